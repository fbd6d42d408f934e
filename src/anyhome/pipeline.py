"""Runs the stages: plan -> floorplan -> layout -> refine -> assets, and writes outputs.

Every stage gets its own child RNG spawned from the seed, so a change inside one stage
does not shift the random draws of the others, and a run is reproducible: the same
text, seed, planner and options give a byte-identical house.json.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from anyhome.errors import AnyHomeError, ExportError, PlanError
from anyhome.house import HOUSE_FILE, House

if TYPE_CHECKING:
    from anyhome.plan import Planner

log = logging.getLogger(__name__)

STAGES: tuple[str, ...] = ("plan", "floorplan", "layout", "refine", "assets")
"""The generation stages in order (exports are timed separately by write_outputs)."""
OUTPUTS: tuple[str, ...] = ("house.json", "house.glb", "floorplan.svg")
"""Files ``write_outputs`` writes by default (plus the manifest, see anyhome.outdir)."""

Progress = Callable[[str, str, float], None]
"""progress(stage, event, seconds): event is "start" or "done" (seconds then set)."""


def _quiet(stage: str, event: str, seconds: float) -> None:
    return None


@contextmanager
def _stage(name: str, timings: dict[str, float], progress: Progress) -> Iterator[None]:
    progress(name, "start", 0.0)
    t0 = time.perf_counter()
    yield
    timings[name] = time.perf_counter() - t0
    progress(name, "done", timings[name])


def check_text(text: object) -> None:
    """Raise PlanError unless ``text`` is a string that is valid Unicode (a command line
    with invalid UTF-8 bytes arrives as a string with lone surrogates)."""
    if not isinstance(text, str):
        raise PlanError(f"the text must be a string, got {type(text).__name__}")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as e:
        ch = ord(text[e.start])
        what = f"byte 0x{ch - 0xDC00:02x}" if 0xDC80 <= ch <= 0xDCFF else f"U+{ch:04X}"
        raise PlanError(f"the text is not valid UTF-8 ({what} at character {e.start + 1})") from None


def generate(
    text: str,
    seed: int = 0,
    planner: str | Planner = "offline",
    progress: Progress | None = None,
) -> House:
    """Generate a house from text.

    Parameters
    ----------
    text : the description, free-form
    seed : reproduces the house with the same text and planner
    planner : "offline" (default, embedded), "llm" (configured from the environment and
        the config file, see anyhome.plan.llm.config), or a Planner instance
    progress : optional callback, see :data:`Progress`

    Returns
    -------
    House, with ``house.timings_s`` holding seconds per stage.
    """
    from anyhome.assets import assign_asset
    from anyhome.floorplan import solve_floorplan
    from anyhome.layout import layout_house
    from anyhome.plan import get_planner
    from anyhome.refine import refine_objects

    progress = progress or _quiet
    check_text(text)
    if not isinstance(seed, (int, np.integer)) or seed < 0:
        raise AnyHomeError(f"seed must be a non-negative integer, got {seed!r}")
    rngs = dict(
        zip(STAGES, (np.random.default_rng(s) for s in np.random.SeedSequence(int(seed)).spawn(5)))
    )
    timings: dict[str, float] = {}
    planner = get_planner(planner) if isinstance(planner, str) else planner
    with _stage("plan", timings, progress):
        spec = planner.plan(text, rngs["plan"])
    with _stage("floorplan", timings, progress):
        floorplan = solve_floorplan(spec, rngs["floorplan"])
    with _stage("layout", timings, progress):
        result = layout_house(spec, floorplan, rngs["layout"])
    with _stage("refine", timings, progress):
        objects = refine_objects(floorplan, result.objects, rngs["refine"])
    with _stage("assets", timings, progress):
        for obj in objects:
            obj.asset = assign_asset(obj, rngs["assets"], spec.styles_for(obj.room))
    house = House(
        prompt=text,
        seed=int(seed),
        style=spec.style,
        styles=spec.styles,
        building=spec.building,
        palette=spec.palette,
        planner=planner.name,
        rooms=floorplan.rooms,
        connections=floorplan.connections,
        doors=floorplan.doors,
        windows=floorplan.windows,
        objects=objects,
        dropped=result.dropped,
        warnings=spec.warnings,
        plan=spec.model_dump(mode="json", exclude={"provenance"}),
        provenance=spec.provenance,
    )
    house._timings_s.update(timings)
    return house


def write_outputs(
    house: House,
    out_dir: str | os.PathLike[str],
    glb: bool = True,
    svg: bool = True,
    timings: dict[str, float] | None = None,
    extra: Callable[[Path], list[Path]] | None = None,
    progress: Progress | None = None,
) -> list[Path]:
    """Write house.json (+ house.glb, floorplan.svg) into ``out_dir``, all or nothing.

    Files are written into a temporary sibling folder first, with ``extra(folder)`` (for
    example the renders) and a manifest of what was written; only then does that folder
    replace ``out_dir`` (see :mod:`anyhome.outdir`). A failure or a kill leaves an
    existing ``out_dir`` untouched. A folder holding anything AnyHome did not write is
    refused with an ExportError, before anything is written.

    ``progress`` gets the stages ``"write"`` and, with ``extra``, ``"render"``. Returns
    the paths of the written files inside ``out_dir``.
    """
    from anyhome.export import write_glb, write_svg
    from anyhome.outdir import Staging, write_file

    progress = progress or _quiet
    timings = timings if timings is not None else {}
    with Staging(out_dir) as stage:
        tmp = stage.path
        progress("write", "start", 0.0)
        t_write = time.perf_counter()
        written = [write_file(tmp / HOUSE_FILE, house.to_json().encode("utf-8"))]
        timings["write_json"] = time.perf_counter() - t_write
        if glb:
            t0 = time.perf_counter()
            written.append(write_glb(house, tmp / "house.glb"))
            timings["write_glb"] = time.perf_counter() - t0
        if svg:
            t0 = time.perf_counter()
            written.append(write_svg(house, tmp / "floorplan.svg"))
            timings["write_svg"] = time.perf_counter() - t0
        progress("write", "done", time.perf_counter() - t_write)
        if extra is not None:
            progress("render", "start", 0.0)
            t0 = time.perf_counter()
            written += extra(tmp)
            timings["render"] = time.perf_counter() - t0
            progress("render", "done", timings["render"])
        stage.commit()
    return [stage.dest / Path(p).relative_to(tmp) for p in written]


def write_renders(
    house_dir: str | os.PathLike[str] | None,
    out_dir: str | os.PathLike[str],
    render: Callable[[Path], list[Path]],
) -> list[Path]:
    """Render into ``out_dir``, all or nothing: ``render(folder)`` writes the images into
    a temporary folder that then replaces ``out_dir`` (same rules as write_outputs).

    When ``out_dir`` is the house's own folder ``house_dir``, the new folder also holds
    the house's own files (hard links: house.json, house.glb, floorplan.svg) and none of
    the old renders, so no image of a room that no longer exists stays behind.
    """
    from anyhome import outdir

    with outdir.Staging(out_dir) as stage:
        if house_dir is not None and os.path.realpath(house_dir) == str(stage.dest) and stage.dest.is_dir():
            for rel in outdir.walk_files(stage.dest):
                name = Path(rel).name
                if rel == outdir.MANIFEST_FILE or outdir.is_render_output(rel) or outdir.is_stale_temp(name):
                    continue
                try:
                    outdir.link_or_copy(stage.dest / rel, stage.path / rel)
                except OSError as e:
                    raise ExportError(f"could not copy {stage.dest / rel}: {e.strerror}") from None
        files = render(stage.path)
        stage.commit()
    return [stage.dest / Path(p).relative_to(stage.path) for p in files]


def write_exports(house: House, out_dir: str | os.PathLike[str], formats: list[str]) -> list[Path]:
    """Write house.glb and/or floorplan.svg (``formats``: "glb", "svg") into ``out_dir``.

    The files are written one by one, atomically, into the folder (it is not replaced).
    A folder AnyHome wrote (or a new or empty one) gets them listed in its manifest,
    first, so a kill never leaves a file the manifest does not know. In any other
    folder an existing house.glb or floorplan.svg is never overwritten: ExportError.
    """
    from anyhome.export import write_glb, write_svg
    from anyhome.outdir import check_out, is_ours, write_manifest

    writers = {"glb": ("house.glb", write_glb), "svg": ("floorplan.svg", write_svg)}
    for fmt in formats:
        if fmt not in writers:
            raise AnyHomeError(f"unknown export format {fmt!r} (available: glb, svg)")
    out = check_out(out_dir, replace=False)
    names = [writers[f][0] for f in dict.fromkeys(formats)]
    if is_ours(out):
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise ExportError(f"could not create {out}: {e.strerror}") from None
        write_manifest(out, extra=set(names))
    else:
        for name in names:
            if os.path.lexists(out / name):
                raise ExportError(f"{out} is not a folder AnyHome wrote and already holds {name}; "
                                  "choose another --out (nothing was changed)")
    return [writers[f][1](house, out / writers[f][0]) for f in dict.fromkeys(formats)]
