"""Runs the stages: plan -> floorplan -> layout -> refine -> assets, and writes outputs.

Every stage gets its own child RNG spawned from the seed, so a change inside one stage
does not shift the random draws of the others, and a run is reproducible: the same
text, seed, planner and options give a byte-identical house.json.
"""

from __future__ import annotations

import logging
import os
import shutil
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from anyhome.errors import AnyHomeError, ExportError
from anyhome.house import HOUSE_FILE, House

if TYPE_CHECKING:
    from anyhome.plan import Planner

log = logging.getLogger(__name__)

STAGES: tuple[str, ...] = ("plan", "floorplan", "layout", "refine", "assets")
"""The generation stages in order (exports are timed separately by write_outputs)."""
OUTPUTS: tuple[str, ...] = ("house.json", "house.glb", "floorplan.svg")
"""Files ``write_outputs`` writes by default."""

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
            obj.asset = assign_asset(obj, rngs["assets"], spec.style)
    house = House(
        prompt=text,
        seed=int(seed),
        style=spec.style,
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
) -> list[Path]:
    """Write house.json (+ house.glb, floorplan.svg) into ``out_dir``, all or nothing.

    Files are written into a temporary sibling folder first; only when every file is
    written does it replace ``out_dir``. A failure leaves an existing ``out_dir``
    untouched. A non-empty ``out_dir`` that holds no house.json is refused, so a typo
    never overwrites a user's folder.
    """
    from anyhome.export import write_glb, write_svg

    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise ExportError(f"{out} exists and is not a folder")
    if out.is_dir() and any(out.iterdir()) and not (out / HOUSE_FILE).exists():
        raise ExportError(f"{out} is a non-empty folder without a house.json; choose another --out")
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent))
    timings = timings if timings is not None else {}
    try:
        t0 = time.perf_counter()
        house.save(tmp)
        timings["write_json"] = time.perf_counter() - t0
        if glb:
            t0 = time.perf_counter()
            write_glb(house, tmp / "house.glb")
            timings["write_glb"] = time.perf_counter() - t0
        if svg:
            t0 = time.perf_counter()
            write_svg(house, tmp / "floorplan.svg")
            timings["write_svg"] = time.perf_counter() - t0
        if out.exists():
            _replace_dir(tmp, out)
        else:
            os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return sorted(p for p in out.iterdir() if p.is_file())


def _replace_dir(new: Path, old: Path) -> None:
    """Swap ``new`` into ``old``'s place with a rename, then delete the old content."""
    backup = old.with_name(f".{old.name}.old-{os.getpid()}")
    os.replace(old, backup)
    try:
        os.replace(new, old)
    except BaseException:
        os.replace(backup, old)
        raise
    shutil.rmtree(backup, ignore_errors=True)
