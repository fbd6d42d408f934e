"""Benchmark: headless renders of every public prompt (seed 0).

Usage: .venv/bin/python benchmarks/render.py [--prompts FILE] [--seed 0] [--size 1024]
       [--view-size 512] [--fps-frames 60] [--keep DIR]

For each prompt it times ``generate``, then ``render_house`` (a bird's-eye image at
``--size`` squared and one ``--view-size`` view per room; the target is at most 15 s
per house, generation included), and prints a markdown table. Then it measures frames
per second at 512 x 512 on the house with the most triangles: colour only, and colour
with depth and instance read-back, without anti-aliasing and with render_house's default
2 x 2 supersampling. Renders go to a temporary folder unless ``--keep``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import tempfile
import time
from pathlib import Path

from anyhome.pipeline import generate
from anyhome.render import Renderer, render_house, room_camera
from anyhome.render.lights import room_lights
from anyhome.render.meshes import scene_meshes
from anyhome.scene import build_scene

HERE = Path(__file__).resolve().parent
DEFAULT_PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"
TARGET_S = 15.0
"""Target seconds per house: generate + bird's-eye + one view per room."""
FPS_SIZE_PX = 512


def _prompts(path: str) -> list[tuple[str, str]]:
    rows = []
    for line in Path(path).read_text(encoding="utf-8").splitlines():
        if line.strip():
            entry = json.loads(line)
            rows.append((entry["id"], entry["prompt"]))
    return rows


def measure_fps(house, frames: int) -> dict[str, float]:
    """Frames per second at 512 x 512 from the fullest room's camera (after a warm-up),
    without anti-aliasing (``supersample=1``) and with the default 2 x 2 supersampling."""
    meshes = scene_meshes(house, build_scene(house))
    room = max(house.rooms, key=lambda r: len(house.objects_in(r.id)))
    camera = room_camera(house, room, FPS_SIZE_PX)
    out: dict[str, float] = {"triangles": meshes.n_triangles}
    for supersample in (1, 2):
        with Renderer(meshes, room_lights(house, meshes.fixtures), supersample=supersample) as r:
            for label, extra in (("colour", False), ("colour+depth+ids", True)):
                r.render(camera, depth=extra, ids=extra)  # warm-up: shadow map, buffers
                t0 = time.perf_counter()
                for _ in range(frames):
                    r.render(camera, depth=extra, ids=extra)
                out[f"{label} ss{supersample}"] = frames / (time.perf_counter() - t0)
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--prompts", default=str(DEFAULT_PROMPTS))
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--size", type=int, default=1024, help="bird's-eye side in pixels")
    ap.add_argument("--view-size", type=int, default=512, help="per-room view side in pixels")
    ap.add_argument("--fps-frames", type=int, default=60)
    ap.add_argument("--keep", help="write the renders here instead of a temporary folder")
    args = ap.parse_args(argv)
    rows = []
    largest = None
    with tempfile.TemporaryDirectory() as td:
        root = Path(args.keep) if args.keep else Path(td)
        for pid, prompt in _prompts(args.prompts):
            t0 = time.perf_counter()
            house = generate(prompt, seed=args.seed)
            gen_s = time.perf_counter() - t0
            r = render_house(house, root / pid, size_px=args.size, view_size_px=args.view_size)
            total = time.perf_counter() - t0
            t = r["timings_s"]
            rows.append({"id": pid, "rooms": len(house.rooms), "triangles": r["n_triangles"],
                         "generate": gen_s, **{k: t[k] for k in ("scene", "upload", "birdseye",
                                                                  "views", "write")},
                         "render": t["total"], "total": total})
            print(f"{pid:<20} {total:6.2f} s", flush=True)
            if largest is None or r["n_triangles"] > largest[0]:
                largest = (r["n_triangles"], pid, house)
    fps = measure_fps(largest[2], args.fps_frames)
    cpus = os.cpu_count()
    print()
    print(f"Machine: {platform.machine()}, {cpus} CPUs, python {platform.python_version()}; "
          f"bird's-eye {args.size} px, views {args.view_size} px, seed {args.seed}.")
    print()
    print("| prompt | rooms | triangles | generate s | scene s | GL setup s | bird's-eye s "
          "| views s | write s | render s | total s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        flag = " **over**" if r["total"] > TARGET_S else ""
        print(f"| {r['id']} | {r['rooms']} | {r['triangles']} | {r['generate']:.2f} | "
              f"{r['scene']:.2f} | {r['upload']:.2f} | {r['birdseye']:.2f} | {r['views']:.2f} | "
              f"{r['write']:.2f} | {r['render']:.2f} | {r['total']:.2f}{flag} |")
    totals = [r["total"] for r in rows]
    print(f"| **all {len(rows)}** | {sum(r['rooms'] for r in rows)} | "
          f"{sum(r['triangles'] for r in rows)} | {sum(r['generate'] for r in rows):.2f} | "
          f"{sum(r['scene'] for r in rows):.2f} | {sum(r['upload'] for r in rows):.2f} | "
          f"{sum(r['birdseye'] for r in rows):.2f} | {sum(r['views'] for r in rows):.2f} | "
          f"{sum(r['write'] for r in rows):.2f} | {sum(r['render'] for r in rows):.2f} | "
          f"{sum(totals):.2f} |")
    print()
    print(f"Per house: median {statistics.median(totals):.2f} s, max {max(totals):.2f} s "
          f"(target <= {TARGET_S:.0f} s); {sum(t > TARGET_S for t in totals)} over.")
    print(f"FPS at {FPS_SIZE_PX}x{FPS_SIZE_PX} on {largest[1]} ({fps['triangles']} triangles), "
          f"{args.fps_frames} frames each:")
    print()
    print("| anti-aliasing | colour | colour + depth + ids |")
    print("|---|---|---|")
    for ss, label in ((1, "none"), (2, "2x2 supersampling (render_house default)")):
        print(f"| {label} | {fps[f'colour ss{ss}']:.1f} fps | {fps[f'colour+depth+ids ss{ss}']:.1f} fps |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
