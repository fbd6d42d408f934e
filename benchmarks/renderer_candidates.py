"""Benchmark: headless renderer candidates on one scene, measured on this machine.

Usage:
    .venv/bin/python benchmarks/renderer_candidates.py \\
        --pyrender2-python /work/venvs/pyrender2/bin/python \\
        --bpy-python /work/venvs/bpy/bin/python [--prompt-id wine-bar] [--seed 0]
        [--frames 60] [--bpy-frames 1] [--repeats 2] [--images DIR] [--out FILE]

The candidates need separate virtual environments (bpy pins numpy < 2), e.g.:
    python3.11 -m venv /work/venvs/pyrender2 && /work/venvs/pyrender2/bin/pip install pyrender2
    python3.11 -m venv /work/venvs/bpy && /work/venvs/bpy/bin/pip install bpy==5.0.1

The scene is built once with the project (``anyhome generate PROMPT --seed S --out DIR``,
which writes ``house.glb`` and ``house.json``). The eye-level camera of the fullest room
(:func:`anyhome.render.room_camera`), the sun direction and one point light per room
(:func:`anyhome.render.lights.room_lights`) are written to ``DIR/view.json`` in the plan
frame, with the GLB root node's plan -> glTF matrix, so that every candidate renders
the same view of the same geometry. Each candidate then runs in a subprocess with its
own interpreter (this file, ``--worker NAME``), which needs only numpy and the
candidate, not anyhome (except ``moderngl``, the project's own renderer, which runs in
the project's environment and draws the house from ``house.json``):

* ``moderngl``: :class:`anyhome.render.Renderer` on EGL, frames per second at the
  frame size, colour only and colour + depth + object ids, without (``ss1``) and with
  render_house's default 2 x 2 supersampling (``ss2``).
* ``pyrender2``: ``pyrender.OffscreenRenderer`` with ``PYOPENGL_PLATFORM=egl`` on the
  GLB (``trimesh.load`` -> ``pyrender.Scene.from_trimesh_scene``), a directional light
  and the point lights; colour + depth (one pass: pyrender always reads both back,
  through its fixed 4x MSAA buffer), the same with directional shadows, and colour +
  depth + ids (ids need a second ``RenderFlags.SEG`` pass).
* ``bpy``: ``bpy.ops.import_scene.gltf`` of the GLB, a sun, the point lights and the
  camera; seconds per frame with Eevee (``--eevee-samples``, default 1 and 16) and with
  Cycles on the CPU (``--cycles-samples``, default 16, no denoising), after one warm-up
  frame per engine.

Every candidate runs ``--repeats`` times, the candidates taking turns (the machine is
shared: the 1-minute load average before and after each run is recorded). The table
shows each mode's best run and every run's figure; the JSON
(``benchmarks/results/renderer_candidates.json``) keeps every run. A candidate that
cannot be imported or fails is reported with its error line. Install size is ``du -sk``
of the candidate's environment, and the installed files of the candidate's
distributions with their dependencies, in all and beyond anyhome's own dependencies.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT_PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"
DEFAULT_OUT = HERE / "results" / "renderer_candidates.json"
CANDIDATES = ("moderngl", "pyrender2", "bpy")
DISTS = {"moderngl": ["moderngl"], "pyrender2": ["pyrender2"], "bpy": ["bpy"]}
"""Distributions whose installed files (with their dependencies) make a candidate."""
RESULT_TAG = "RENDERER-CANDIDATE-RESULT "
"""Prefix of the worker's one JSON line on stdout (bpy prints its own lines there)."""
WORKER_TIMEOUT_S = 1800
SKY_RGB = (0.55, 0.62, 0.72)
"""Background colour of the Blender world (the project's sky ambient)."""


# ------------------------------------------------------------------ shared helpers
def look_at(eye, target, up=(0.0, 0.0, 1.0)):
    """(4, 4) camera/light -> world pose looking down its local -z with +y up (OpenGL)."""
    import numpy as np

    eye, target = np.asarray(eye, float), np.asarray(target, float)
    f = target - eye
    f /= np.linalg.norm(f)
    up = np.asarray(up, float)
    if abs(f @ up) > 0.999:
        up = np.array([0.0, 1.0, 0.0])
    r = np.cross(f, up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    pose = np.eye(4)
    pose[:3, 0], pose[:3, 1], pose[:3, 2], pose[:3, 3] = r, u, -f, eye
    return pose


def dist_size(names: list[str], exclude: list[str] = ()) -> dict:
    """Installed bytes of the distributions ``names`` and everything they require
    (extras left out), as seen by the running interpreter; ``extra_bytes`` leaves out
    the distributions named in ``exclude`` (the project's own dependencies)."""
    from importlib import metadata

    seen: dict[str, int] = {}
    todo = list(names)
    while todo:
        name = re.sub(r"[-_.]+", "-", todo.pop()).lower()
        if name in seen:
            continue
        try:
            dist = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            continue
        size = 0
        for f in dist.files or []:
            p = Path(dist.locate_file(f))
            if p.is_file():
                size += p.stat().st_size
        seen[name] = size
        for req in dist.requires or []:
            if "extra ==" in req:
                continue
            m = re.match(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)", req)
            if m:
                todo.append(m.group(1))
    skip = {re.sub(r"[-_.]+", "-", n).lower() for n in exclude}
    extra = sorted(n for n in seen if n not in skip)
    return {"bytes": sum(seen.values()), "dists": sorted(seen),
            "extra_bytes": sum(seen[n] for n in extra), "extra_dists": extra}


def numpy_pin(dist: str) -> str | None:
    """The numpy requirement of ``dist`` (e.g. ``numpy<2.0,>=1.26``), or None."""
    from importlib import metadata

    for req in metadata.requires(dist) or []:
        if re.match(r"\s*numpy\b", req) and "extra ==" not in req:
            return req.strip()
    return None


def timed(fn, frames: int, warmup: bool = True) -> dict:
    """Mean seconds per call of ``fn`` over ``frames`` calls, after a timed warm-up call
    (left out, ``first_frame_s`` None, when ``warmup`` is False)."""
    first = None
    if warmup:
        t0 = time.perf_counter()
        fn()
        first = time.perf_counter() - t0
    t0 = time.perf_counter()
    for _ in range(frames):
        fn()
    per = (time.perf_counter() - t0) / frames
    return {"first_frame_s": first, "seconds_per_frame": per, "fps": 1.0 / per, "frames": frames}


# ------------------------------------------------------------------ workers
def worker_moderngl(scene: Path, view: dict, args: argparse.Namespace) -> dict:
    import moderngl

    from anyhome.house import load
    from anyhome.render import Renderer, room_camera
    from anyhome.render.images import write_png
    from anyhome.render.lights import room_lights
    from anyhome.render.meshes import scene_meshes
    from anyhome.scene import build_scene

    t0 = time.perf_counter()
    house = load(scene)
    meshes = scene_meshes(house, build_scene(house))
    camera = room_camera(house, house.room(view["room"]), args.size)
    lights = room_lights(house, meshes.fixtures)
    out = {"version": moderngl.__version__, "triangles": meshes.n_triangles, "modes": {},
           "dist_size": dist_size(["moderngl"], args.exclude_dists),
           "numpy_pin": numpy_pin("moderngl")}
    for ss in (1, 2):
        with Renderer(meshes, lights, supersample=ss) as r:
            if ss == 1:
                out["setup_s"] = time.perf_counter() - t0
                out["gl_renderer"] = r.ctx.info.get("GL_RENDERER")
            for label, extra in (("colour", False), ("colour+depth+ids", True)):
                out["modes"][f"{label}, ss{ss}"] = timed(
                    lambda extra=extra: r.render(camera, depth=extra, ids=extra), args.frames)
            if args.image and ss == 1:
                write_png(Path(args.image), r.render(camera).color)
    out["notes"] = ("project renderer; house drawn from house.json (the scene the GLB is written "
                    "from, plus a ground plane); sun shadow map computed once and cached; "
                    "ss2 = render_house's default 2x2 supersampling")
    return out


def worker_pyrender2(scene: Path, view: dict, args: argparse.Namespace) -> dict:
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")
    from importlib import metadata

    import numpy as np
    import pyrender
    import trimesh

    t0 = time.perf_counter()
    tm = trimesh.load(scene / "house.glb")
    ps = pyrender.Scene.from_trimesh_scene(tm, bg_color=[0.74, 0.83, 0.92, 1.0],
                                           ambient_light=[0.3, 0.3, 0.3])
    to_gltf = np.asarray(view["plan_to_gltf"])
    cam = pyrender.PerspectiveCamera(yfov=np.radians(view["fov_y_deg"]), aspectRatio=1.0,
                                     znear=view["near_m"], zfar=view["far_m"])
    ps.add(cam, pose=to_gltf @ look_at(view["eye"], view["target"]))
    sun = np.asarray(view["sun_dir"])
    ps.add(pyrender.DirectionalLight(color=[1.0, 0.95, 0.85], intensity=3.0),
           pose=to_gltf @ look_at(sun * 10.0, [0.0, 0.0, 0.0]))
    for pos in view["point_lights"]:
        light_pose = np.eye(4)
        light_pose[:3, 3] = pos
        ps.add(pyrender.PointLight(color=[1.0, 0.86, 0.68], intensity=8.0),
               pose=to_gltf @ light_pose)
    mesh_nodes = list(ps.mesh_nodes)
    triangles = sum(len(p.indices) if p.indices is not None else len(p.positions) // 3
                    for n in mesh_nodes for p in n.mesh.primitives)
    rng = np.random.default_rng(0)
    seg_map = {n: rng.integers(1, 255, 3) for n in mesh_nodes}
    r = pyrender.OffscreenRenderer(args.size, args.size)
    flags = pyrender.RenderFlags
    r.render(ps)
    setup = time.perf_counter() - t0
    from OpenGL.GL import GL_RENDERER, glGetString

    r._platform.make_current()
    gl_renderer = glGetString(GL_RENDERER).decode()
    modes = {
        "colour+depth": timed(lambda: r.render(ps), args.frames),
        "colour+depth, directional shadows": timed(
            lambda: r.render(ps, flags.SHADOWS_DIRECTIONAL), args.frames),
        "ids (SEG pass) alone": timed(lambda: r.render(ps, flags.SEG, seg_map), args.frames),
        "colour+depth+ids (2 passes)": timed(
            lambda: (r.render(ps), r.render(ps, flags.SEG, seg_map)), args.frames),
    }
    if args.image:
        from PIL import Image

        Image.fromarray(r.render(ps)[0]).save(args.image)
    r.delete()
    return {"version": metadata.version("pyrender2"), "triangles": int(triangles),
            "setup_s": setup, "gl_renderer": gl_renderer, "modes": modes,
            "dist_size": dist_size(["pyrender2"], args.exclude_dists),
            "numpy_pin": numpy_pin("pyrender2"),
            "notes": ("GLB via trimesh.load -> Scene.from_trimesh_scene; same camera; "
                      "1 directional + 1 point light per room, ambient 0.3; pyrender always "
                      "reads colour and depth back and draws into a fixed 4x MSAA buffer; "
                      "object ids need a second RenderFlags.SEG pass")}


def worker_bpy(scene: Path, view: dict, args: argparse.Namespace) -> dict:
    import bpy
    import numpy as np
    from mathutils import Matrix

    t0 = time.perf_counter()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=str(scene / "house.glb"))
    import_s = time.perf_counter() - t0
    sc = bpy.context.scene
    # plan -> Blender world: the GLB root's plan -> glTF matrix, then the importer's
    # glTF (+Y up) -> Blender (+Z up) axis change (x, y, z) -> (x, -z, y)
    to_blender = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], float)
    to_world = to_blender @ np.asarray(view["plan_to_gltf"])
    notes = []
    root = bpy.data.objects.get("house")
    expected = to_blender @ np.asarray(view["plan_to_gltf"]) @ to_blender.T
    if root is None or not np.allclose(np.array(root.matrix_world), expected, atol=1e-5):
        notes.append("the imported root node is not where the axis change puts it")
    world = bpy.data.worlds.new("bench_sky")
    world.color = SKY_RGB
    sc.world = world

    def place(obj, pose):
        obj.matrix_world = Matrix((to_world @ pose).tolist())

    cam_data = bpy.data.cameras.new("bench_camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = float(np.radians(view["fov_y_deg"]))
    cam_data.clip_start, cam_data.clip_end = view["near_m"], view["far_m"]
    cam = bpy.data.objects.new("bench_camera", cam_data)
    sc.collection.objects.link(cam)
    place(cam, look_at(view["eye"], view["target"]))
    sc.camera = cam
    sun = bpy.data.objects.new("bench_sun", bpy.data.lights.new("bench_sun", "SUN"))
    sun.data.energy = 3.0
    sc.collection.objects.link(sun)
    place(sun, look_at(np.asarray(view["sun_dir"]) * 10.0, [0.0, 0.0, 0.0]))
    for i, pos in enumerate(view["point_lights"]):
        lamp = bpy.data.objects.new(f"bench_point_{i}", bpy.data.lights.new(f"p{i}", "POINT"))
        lamp.data.energy = 200.0
        sc.collection.objects.link(lamp)
        pose = np.eye(4)
        pose[:3, 3] = pos
        place(lamp, pose)
    triangles = 0
    for obj in sc.objects:
        if obj.type == "MESH":
            obj.data.calc_loop_triangles()
            triangles += len(obj.data.loop_triangles)
    sc.render.resolution_x = sc.render.resolution_y = args.size
    sc.render.resolution_percentage = 100
    engine_prop = bpy.types.RenderSettings.bl_rna.properties["engine"]
    engines = [e.identifier for e in engine_prop.enum_items]
    eevee = next((e for e in ("BLENDER_EEVEE_NEXT", "BLENDER_EEVEE") if e in engines), None)
    modes, errors = {}, {}

    def render():
        bpy.ops.render.render(write_still=False)

    runs = []
    if eevee:
        runs += [(f"eevee ({eevee}), {n} sample{'s' * (n != 1)}", eevee, n)
                 for n in args.eevee_samples]
    else:
        errors["eevee"] = f"no Eevee engine among {engines}"
    n = args.cycles_samples
    runs.append((f"cycles CPU, {n} sample{'s' * (n != 1)}, no denoising", "CYCLES", n))
    warm = set()
    for label, engine, samples in runs:
        sc.render.engine = engine
        if engine == "CYCLES":
            sc.cycles.device = "CPU"
            sc.cycles.samples = samples
            sc.cycles.use_denoising = False
        else:
            sc.eevee.taa_render_samples = samples
        try:
            modes[label] = timed(render, args.bpy_frames, warmup=engine not in warm)
        except Exception as e:  # a render engine that cannot start (no GPU context...)
            errors[label] = f"{type(e).__name__}: {str(e).strip().splitlines()[0]}"
            continue
        warm.add(engine)
        if args.image:
            stem = Path(args.image)
            bpy.data.images["Render Result"].save_render(
                str(stem.with_name(f"{stem.stem}-{engine.lower()}-{samples}{stem.suffix}")))
    gpu_renderer = None
    try:
        import gpu

        gpu_renderer = gpu.platform.renderer_get()
    except Exception as e:  # no GPU module context in background mode
        gpu_renderer = f"unavailable ({type(e).__name__})"
    notes.append("GLB via bpy.ops.import_scene.gltf; same camera; 1 sun + 1 point light per "
                 "room; seconds per frame of bpy.ops.render.render (no read-back of pixels "
                 "into Python); Cycles on the CPU threads of this machine")
    return {"version": bpy.app.version_string, "triangles": triangles, "setup_s": import_s,
            "gl_renderer": gpu_renderer, "modes": modes, "errors": errors,
            "dist_size": dist_size(["bpy"], args.exclude_dists), "numpy_pin": numpy_pin("bpy"),
            "threads": sc.render.threads, "notes": "; ".join(notes)}


WORKERS = {"moderngl": worker_moderngl, "pyrender2": worker_pyrender2, "bpy": worker_bpy}


def run_worker(args: argparse.Namespace) -> int:
    scene = Path(args.scene)
    view = json.loads((scene / "view.json").read_text(encoding="utf-8"))
    out = WORKERS[args.worker](scene, view, args)
    import numpy

    out.update(python=platform.python_version(), numpy=numpy.__version__, prefix=sys.prefix)
    sys.stdout.write(RESULT_TAG + json.dumps(out) + "\n")
    sys.stdout.flush()
    return 0


# ------------------------------------------------------------------ orchestrator
def build_scene_dir(prompt: str, seed: int, out: Path) -> dict:
    """``anyhome generate`` into ``out``, then the shared view (``out/view.json``)."""
    import numpy as np
    import trimesh

    from anyhome.house import load
    from anyhome.render import room_camera
    from anyhome.render.lights import room_lights, sun_direction
    from anyhome.render.meshes import scene_meshes
    from anyhome.scene import ROOT_NODE, build_scene

    exe = Path(sys.executable).parent / "anyhome"
    cmd = [str(exe), "generate", prompt, "--seed", str(seed), "--out", str(out), "-q", "--no-svg"]
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    gen_s = time.perf_counter() - t0
    house = load(out)
    room = max(house.rooms, key=lambda r: len(house.objects_in(r.id)))
    camera = room_camera(house, room, 512)
    meshes = scene_meshes(house, build_scene(house))
    glb = trimesh.load(out / "house.glb")
    glb_triangles = sum(len(glb.geometry[glb.graph[n][1]].faces) for n in glb.graph.nodes_geometry)
    view = {
        "room": room.id, "eye": list(camera.eye), "target": list(camera.target),
        "fov_y_deg": camera.fov_y_deg, "near_m": camera.near_m, "far_m": camera.far_m,
        "sun_dir": sun_direction().tolist(),
        "point_lights": [list(light.position) for light in room_lights(house, meshes.fixtures)],
        "plan_to_gltf": np.asarray(glb.graph.get(ROOT_NODE)[0]).tolist(),
    }
    (out / "view.json").write_text(json.dumps(view, indent=1), encoding="utf-8")
    return {"prompt": prompt, "seed": seed, "generate_cmd": " ".join(cmd[1:]), "generate_s": gen_s,
            "glb_bytes": (out / "house.glb").stat().st_size, "glb_triangles": glb_triangles,
            "rooms": len(house.rooms), "objects": len(house.objects), "view": view}


def _error_line(text: str) -> str:
    """The last line of a traceback or error output that says what went wrong."""
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    for ln in reversed(lines):
        if re.match(r"^[A-Za-z_][\w.]*(Error|Exception|Exit)\b", ln) or "rror" in ln:
            return ln
    return lines[-1] if lines else "no output"


def env_size_kb(python: str) -> dict:
    """``du -sk`` of the environment ``python`` runs in."""
    try:
        prefix = subprocess.run([python, "-c", "import sys; print(sys.prefix)"], check=True,
                                capture_output=True, text=True).stdout.strip()
        du = subprocess.run(["du", "-sk", prefix], check=True, capture_output=True, text=True)
        return {"prefix": prefix, "kb": int(du.stdout.split()[0])}
    except (OSError, subprocess.CalledProcessError) as e:
        return {"error": str(e)}


def run_candidate(name: str, python: str, scene: Path, args: argparse.Namespace,
                  image: Path | None) -> dict:
    cmd = [python, str(Path(__file__).resolve()), "--worker", name, "--scene", str(scene),
           "--size", str(args.size), "--frames", str(args.frames),
           "--bpy-frames", str(args.bpy_frames), "--cycles-samples", str(args.cycles_samples),
           "--eevee-samples", ",".join(map(str, args.eevee_samples)),
           "--exclude-dists", ",".join(args.exclude_dists)]
    if image is not None:
        cmd += ["--image", str(image)]
    env = dict(os.environ, PYOPENGL_PLATFORM="egl")
    load = {"loadavg_before": os.getloadavg()[0]}
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=WORKER_TIMEOUT_S)
    except (OSError, subprocess.TimeoutExpired) as e:
        return {"ok": False, "error": f"{type(e).__name__}: {e}"}
    wall = time.perf_counter() - t0
    load["loadavg_after"] = os.getloadavg()[0]
    for line in reversed(p.stdout.splitlines()):
        if line.startswith(RESULT_TAG):
            return {"ok": True, "wall_s": wall, **load, **json.loads(line[len(RESULT_TAG):])}
    return {"ok": False, "wall_s": wall, **load, "returncode": p.returncode,
            "error": _error_line(p.stderr or p.stdout), "stderr_tail": p.stderr[-2000:]}


def _mb(n_bytes: float) -> str:
    return f"{n_bytes / 1e6:.0f} MB" if n_bytes < 1e9 else f"{n_bytes / 1e9:.2f} GB"


def best_modes(runs: list[dict]) -> dict[str, dict]:
    """Mode -> the fastest measurement of that mode over the successful ``runs``, with
    ``all_s``: seconds per frame of every run that measured it, in run order."""
    out: dict[str, dict] = {}
    for run in runs:
        for mode, m in run.get("modes", {}).items() if run.get("ok") else ():
            best = out.setdefault(mode, {**m, "all_s": []})
            best["all_s"].append(m["seconds_per_frame"])
            if m["seconds_per_frame"] < best["seconds_per_frame"]:
                best.update(m)
    return out


def _speed(seconds: float) -> str:
    return f"{1.0 / seconds:.1f} fps" if seconds < 1.0 else f"{seconds:.1f} s"


def print_table(result: dict) -> None:
    sc = result["scene"]
    print(f"Machine: {result['machine']}. Scene: {sc['prompt']!r} (seed {sc['seed']}), "
          f"{sc['glb_triangles']} triangles in house.glb; {result['size']}² frames; "
          f"{result['repeats']} runs per candidate.")
    print()
    print("| candidate | version | numpy | triangles | frame | mode | best run | all runs "
          "| first frame | install size | notes |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, cand in result["candidates"].items():
        runs = cand["runs"]
        ok = [r for r in runs if r.get("ok")]
        env = cand.get("env_size", {})
        env_size = f"env {_mb(env['kb'] * 1024)}" if "kb" in env else ""
        if not ok:
            errors = "; ".join(sorted({r.get("error", "?") for r in runs}))
            print(f"| {name} | - | - | - | - | - | failed | | | {env_size} | {errors} |")
            continue
        ref = ok[0]
        ds = ref["dist_size"]
        size = f"{_mb(ds['bytes'])} with deps, {_mb(ds['extra_bytes'])} beyond anyhome's"
        if cand.get("separate_env") and env_size:
            size += f"; {env_size}"
        notes = ref.get("notes", "")
        errs = {k: v for r in ok for k, v in (r.get("errors") or {}).items()}
        errs.update({"run": r["error"] for r in runs if not r.get("ok")})
        if errs:
            notes += "; failed: " + "; ".join(f"{k}: {v}" for k, v in errs.items())
        for i, (mode, m) in enumerate(best_modes(runs).items()):
            pin = ref.get("numpy_pin") or "no numpy requirement"
            head = (f"| {name} | {ref['version']} | {ref['numpy']} ({pin}) "
                    f"| {ref['triangles']} | {result['size']}² |") if i == 0 else "| | | | | |"
            tail = f" {size} | {notes} |" if i == 0 else " | |"
            first = "-" if m["first_frame_s"] is None else f"{m['first_frame_s']:.2f} s"
            every = " / ".join(_speed(x) for x in m["all_s"])
            print(f"{head} {mode} | {_speed(m['seconds_per_frame'])} | {every} | {first} |{tail}")
    print()
    for name, cand in result["candidates"].items():
        ok = [r for r in cand["runs"] if r.get("ok")]
        if ok:
            loads = ", ".join(f"{r['loadavg_before']:.1f}-{r['loadavg_after']:.1f}" for r in ok)
            print(f"{name}: renderer {ok[0].get('gl_renderer')}; setup (load + upload) "
                  f"{min(r['setup_s'] for r in ok):.2f} s; python {ok[0]['python']}; "
                  f"1-min load average before-after each run: {loads}")


def _ints(text: str) -> list[int]:
    return [int(x) for x in text.split(",") if x.strip()]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--prompts", default=str(DEFAULT_PROMPTS))
    ap.add_argument("--prompt-id", default="wine-bar",
                    help="public prompt to build (default wine-bar, the most triangles)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--size", type=int, default=512, help="frame side in pixels")
    ap.add_argument("--frames", type=int, default=60, help="timed frames per OpenGL mode")
    ap.add_argument("--bpy-frames", type=int, default=1,
                    help="timed frames per Blender mode (after a warm-up frame per engine)")
    ap.add_argument("--eevee-samples", type=_ints, default=[1, 16],
                    help="comma list of Eevee sample counts (default 1,16)")
    ap.add_argument("--cycles-samples", type=int, default=16)
    ap.add_argument("--repeats", type=int, default=2, help="runs of each candidate")
    ap.add_argument("--moderngl-python", default=sys.executable)
    ap.add_argument("--pyrender2-python", help="python of an environment with pyrender2")
    ap.add_argument("--bpy-python", help="python of an environment with bpy")
    ap.add_argument("--only", help="comma list of candidates to run (default all)")
    ap.add_argument("--images", help="write one colour frame per candidate here")
    ap.add_argument("--out", default=str(DEFAULT_OUT), help="JSON results file")
    ap.add_argument("--worker", choices=CANDIDATES, help=argparse.SUPPRESS)
    ap.add_argument("--scene", help=argparse.SUPPRESS)
    ap.add_argument("--image", help=argparse.SUPPRESS)
    ap.add_argument("--exclude-dists", type=lambda t: [x for x in t.split(",") if x],
                    default=[], help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.worker:
        return run_worker(args)
    args.exclude_dists = dist_size(["anyhome"])["dists"]

    prompts = {}
    for line in Path(args.prompts).read_text(encoding="utf-8").splitlines():
        if line.strip():
            entry = json.loads(line)
            prompts[entry["id"]] = entry["prompt"]
    pythons = {"moderngl": args.moderngl_python, "pyrender2": args.pyrender2_python,
               "bpy": args.bpy_python}
    names = args.only.split(",") if args.only else list(CANDIDATES)
    result = {"machine": f"{platform.machine()}, {os.cpu_count()} CPUs, {platform.system()}",
              "size": args.size, "repeats": args.repeats, "frames": args.frames,
              "bpy_frames": args.bpy_frames, "eevee_samples": args.eevee_samples,
              "cycles_samples": args.cycles_samples,
              "command": " ".join([Path(sys.executable).name, *sys.argv]), "candidates": {}}
    images = Path(args.images) if args.images else None
    if images:
        images.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as td:
        scene = Path(td) / "scene"
        result["scene"] = build_scene_dir(prompts[args.prompt_id], args.seed, scene)
        print(f"scene: {result['scene']['glb_triangles']} triangles, view of "
              f"{result['scene']['view']['room']}", file=sys.stderr, flush=True)
        for name in names:
            cand = {"python": pythons[name], "separate_env": name != "moderngl", "runs": []}
            result["candidates"][name] = cand
            if not pythons[name]:
                cand["runs"].append({"ok": False, "error": f"not run: no --{name}-python given"})
            else:
                cand["env_size"] = env_size_kb(pythons[name])
        for i in range(args.repeats):  # candidates take turns, so load from other jobs hits all
            for name in names:
                if not pythons[name]:
                    continue
                image = images / f"{name}.png" if images and i == 0 else None
                run = run_candidate(name, pythons[name], scene, args, image)
                result["candidates"][name]["runs"].append(run)
                state = "ok" if run.get("ok") else f"failed: {run.get('error')}"
                print(f"{name} run {i + 1}: {state}", file=sys.stderr, flush=True)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    print_table(result)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
