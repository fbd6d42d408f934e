"""render_house: a bird's-eye image of the whole house and one eye-level view per room."""

from __future__ import annotations

import json
import logging
import os
import re
import time
from pathlib import Path
from typing import Any, cast

import numpy as np
import trimesh

from anyhome.errors import RenderError
from anyhome.house import House
from anyhome.render.cameras import Camera, birdseye_camera, door_leaf_boxes, room_camera
from anyhome.render.gl import import_moderngl
from anyhome.render.images import write_bytes, write_npy, write_png
from anyhome.render.lights import room_lights
from anyhome.render.meshes import scene_meshes
from anyhome.render.renderer import SUPERSAMPLE, Frame, Renderer

log = logging.getLogger(__name__)

BIRDSEYE_NAME = "birdseye"
"""Stem of the bird's-eye files."""
VIEWS_DIR = "views"
"""Folder of the per-room views."""
META_FILE = "render.json"
"""Cameras and instance legend of the written images."""
MAX_IMAGE_PX = 4096
"""Largest side of an image, in pixels."""
MAX_SUPERSAMPLE = 4
"""Largest anti-aliasing factor per axis."""
MAX_TARGET_PX = 8192
"""Largest side of the supersampled frame (image side x supersample), in pixels."""


def check_image_sizes(
    size_px: object,
    view_size_px: object,
    supersample: object = SUPERSAMPLE,
    names: tuple[str, str] = ("size_px", "view_size_px"),
) -> None:
    """Raise RenderError, before any work, unless the image sizes are integers from 1 to
    :data:`MAX_IMAGE_PX`, the supersample factor one from 1 to :data:`MAX_SUPERSAMPLE`,
    and every supersampled frame fits in :data:`MAX_TARGET_PX`. ``names`` are the names
    used in the message (the CLI passes its flags)."""
    for name, value in ((names[0], size_px), (names[1], view_size_px), ("supersample", supersample)):
        top = MAX_SUPERSAMPLE if name == "supersample" else MAX_IMAGE_PX
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 1 <= value <= top:
            raise RenderError(f"{name} must be an integer from 1 to {top}, got {value!r}")
    for name, value in ((names[0], size_px), (names[1], view_size_px)):
        if cast(int, value) * cast(int, supersample) > MAX_TARGET_PX:  # both checked above
            raise RenderError(f"{name} {value} x supersample {supersample} is more than {MAX_TARGET_PX} px")


def _stem(room_id: str) -> str:
    """A file-name-safe stem for a room id."""
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", room_id).strip("._") or "room"


def _write_frame(out: Path, rel_stem: str, frame: Frame, files: list[Path]) -> None:
    files.append(write_png(out / f"{rel_stem}.png", frame.color))
    if frame.depth is not None:
        files.append(write_npy(out / f"{rel_stem}.depth.npy", frame.depth))
    if frame.ids is not None:
        files.append(write_npy(out / f"{rel_stem}.ids.npy", frame.ids))


def render_house(
    house: House,
    out_dir: str | os.PathLike[str],
    size_px: int = 1024,
    view_size_px: int = 512,
    views: bool = True,
    depth: bool = False,
    ids: bool = False,
    scene: trimesh.Scene | None = None,
    supersample: int = SUPERSAMPLE,
) -> dict[str, Any]:
    """Render a house headlessly (OpenGL on EGL; software Mesa works) into ``out_dir``.

    Writes ``birdseye.png`` (the whole house from above, ceilings hidden), and with
    ``views`` one ``views/<room id>.png`` per room (eye height, ceilings on). With
    ``depth`` each image gets ``<stem>.depth.npy`` ((h, w) float32, meters along the
    optical axis, inf where nothing is drawn); with ``ids`` a ``<stem>.ids.npy`` ((h, w)
    int32 index into ``instances`` of ``render.json``, -1 for sky and ground; indices
    below ``len(house.objects)`` are the object's index in ``house.objects``).
    A house of several storeys is rendered storey by storey, each as a house of its own:
    ``birdseye.png`` is the ground floor, ``birdseye-1.png``... the storeys above and
    ``birdseye-b1.png``... basements (named as the floorplan SVGs); each view record
    carries its ``level``, and ``instances_by_level`` in ``render.json`` holds each
    storey's legend (an index below the storey's object count is the index in that
    storey's objects, in house order).
    ``render.json`` holds each image's camera (intrinsics, world-to-camera in the plan
    frame, OpenGL convention) and the instance legend.

    Parameters
    ----------
    house : the house to render
    out_dir : folder to write into (created); files already there are overwritten, not
        removed (``anyhome render`` renders into a new folder and swaps it in, see
        ``anyhome.pipeline.write_renders``)
    size_px : side of the square bird's-eye image (1 to MAX_IMAGE_PX)
    view_size_px : side of the square per-room views (1 to MAX_IMAGE_PX)
    views : render the per-room views
    depth, ids : also write depth and instance maps
    scene : the house's trimesh Scene; built with ``anyhome.scene.build_scene`` if None
    supersample : anti-aliasing factor per axis (1 is fastest, without anti-aliasing)

    Returns
    -------
    dict with ``files`` (list of Path), ``images`` (name -> camera record),
    ``n_triangles`` and ``timings_s`` (scene, upload, birdseye, views, write, total).

    Raises
    ------
    RenderError
        if a size is out of range (before any work), moderngl or a headless OpenGL
        context is missing, or a file cannot be written.
    """
    check_image_sizes(size_px, view_size_px, supersample)
    import_moderngl()  # fail fast, before building the scene
    t_start = time.perf_counter()
    timings: dict[str, float] = {}
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise RenderError(f"could not create {out}: {e.strerror}") from None
    files: list[Path] = []
    records: dict[str, Any] = {}
    legends: dict[int, list[Any]] = {}
    storeys = house.level_numbers() or [0]
    for k in storeys:
        if len(storeys) > 1:  # each storey on its own, as a one-storey house
            from anyhome.floorplan.levels import level_view

            part, part_scene, suffix = level_view(house, k), None, level_suffix(k)
        else:
            part, part_scene, suffix = house, scene, ""
        legends[k] = _render_storey(part, out, size_px, view_size_px, views, depth, ids, part_scene, supersample,
                                    suffix, files, records, timings)
    write_s = timings.pop("write_frames", 0.0)
    timings["write"] = write_s
    meta = {"frame": "plan (x east, y north, z up, meters); cameras look down -z, y up",
            "depth": "meters along the optical axis; inf where nothing is drawn",
            "instances": legends[0] if 0 in legends else legends[storeys[0]], "images": records}
    if len(legends) > 1:  # several storeys: each storey's images index its own storey's legend
        meta["instances_by_level"] = {str(k): v for k, v in legends.items()}
        for rec in records.values():
            if "room" in rec:
                rec["level"] = house.room_level(rec["room"])
    t = time.perf_counter()
    meta_path = out / META_FILE
    write_bytes(meta_path, (json.dumps(meta, indent=1) + "\n").encode("utf-8"))
    files.append(meta_path)
    timings["write"] += time.perf_counter() - t
    timings["total"] = time.perf_counter() - t_start
    log.debug("rendered %d images in %.2f s", len(records), timings["total"])
    n_triangles = timings.pop("n_triangles")
    return {"files": files, "images": records, "n_triangles": int(n_triangles), "timings_s": timings}


def level_suffix(level: int) -> str:
    """The file-name suffix of a storey's bird's-eye: "" (ground), "-1"..., "-b1"... (basements),
    as the floorplan SVGs are named."""
    return "" if level == 0 else f"-{level}" if level > 0 else f"-b{-level}"


def _render_storey(house: House, out: Path, size_px: int, view_size_px: int, views: bool, depth: bool, ids: bool,
                   scene: trimesh.Scene | None, supersample: int, suffix: str, files: list[Path],
                   records: dict[str, Any], timings: dict[str, float]) -> list[Any]:
    """Render one storey (or a one-storey house): its bird's-eye ``birdseye<suffix>`` and
    its rooms' views; add to ``files``, ``records`` and ``timings``; return its instance legend."""
    def add(key: str, value: float) -> None:
        timings[key] = timings.get(key, 0.0) + value

    t = time.perf_counter()
    if scene is None:
        from anyhome.scene import build_scene

        scene = build_scene(house)
    meshes = scene_meshes(house, scene)
    add("scene", time.perf_counter() - t)
    add("n_triangles", meshes.n_triangles)
    t = time.perf_counter()
    with Renderer(meshes, room_lights(house, meshes.fixtures), supersample) as renderer:
        add("upload", time.perf_counter() - t)

        def shoot(name: str, camera: Camera, ceilings: bool) -> float:
            t0 = time.perf_counter()
            frame = renderer.render(camera, ceilings=ceilings, depth=depth, ids=ids)
            t1 = time.perf_counter()
            _write_frame(out, name, frame, files)
            add("write_frames", time.perf_counter() - t1)
            records[name] = {"file": f"{name}.png", **camera.to_record()}
            return t1 - t0

        add("birdseye", shoot(BIRDSEYE_NAME + suffix, birdseye_camera(house, size_px), ceilings=False))
        add("views", 0.0)
        if views:
            leaves = door_leaf_boxes(house)
            used = {Path(n).name for n in records if n.startswith(f"{VIEWS_DIR}/")}
            for room in house.rooms:
                stem = _stem(room.id)
                while stem in used:  # two ids that sanitize alike
                    stem += "_"
                used.add(stem)
                name = f"{VIEWS_DIR}/{stem}"
                camera = room_camera(house, room, view_size_px, leaves)
                add("views", shoot(name, camera, ceilings=True))
                records[name]["room"] = room.id
    return list(meshes.instances)
