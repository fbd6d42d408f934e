"""Runs the stages: plan -> floorplan -> layout -> refine -> assets, and writes outputs.

Entry points: :func:`generate` (text), :func:`generate_from_spec` (a HouseSpec: every
stage after planning) and :func:`relayout` (some rooms of an existing house again). The
stage functions are replaceable (:class:`anyhome.stages.Stages`). Every stage gets its
own child RNG spawned from the seed, so a change inside one stage does not shift the
random draws of the others, and a run is reproducible: the same text, seed, planner and
options give a byte-identical house.json.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from anyhome.errors import AnyHomeError, ExportError, PlanError
from anyhome.house import HOUSE_FILE, Floorplan, House, HouseObject
from anyhome.sanitize import clean_text, is_safe_id

if TYPE_CHECKING:
    from anyhome.plan import HouseSpec, Planner
    from anyhome.plan.kb import KnowledgeBase
    from anyhome.stages import Stages

log = logging.getLogger(__name__)

STAGES: tuple[str, ...] = ("plan", "floorplan", "layout", "refine", "assets")
"""The generation stages in order (exports are timed separately by write_outputs)."""

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


def _check_seed(seed: object) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise AnyHomeError(f"seed must be a non-negative integer, got {seed!r}")
    return int(seed)


def generate(
    text: str,
    seed: int = 0,
    planner: str | Planner = "offline",
    progress: Progress | None = None,
    stages: Stages | None = None,
    knowledge: KnowledgeBase | None = None,
) -> House:
    """Generate a house from text: the plan stage, then :func:`generate_from_spec`.

    Parameters
    ----------
    text : the description, free-form
    seed : reproduces the house with the same text and planner
    planner : "offline" (default, embedded), "llm" (configured from the environment and
        the config file, see anyhome.plan.llm.config), or a Planner instance
    progress : optional callback, see :data:`Progress`
    stages : the stage functions (:class:`anyhome.stages.Stages`); None: the defaults
    knowledge : the run's knowledge base (:class:`anyhome.plan.kb.KnowledgeBase`), passed
        to the planner (a planner named by a string) and the assets stage; None: the one
        in force (shipped files, ``$ANYHOME_KNOWLEDGE_PATH``, ``--knowledge``), loaded once

    Returns
    -------
    House, with ``house.timings_s`` holding seconds per stage.
    """
    from anyhome.plan import get_planner
    from anyhome.stages import Stages, stage_rngs

    progress = progress or _quiet
    check_text(text)
    seed = _check_seed(seed)
    stages = stages or Stages()
    kb = _knowledge(knowledge)
    planner = get_planner(planner, kb, stages.floorplan) if isinstance(planner, str) else planner
    timings: dict[str, float] = {}
    with _stage("plan", timings, progress):
        spec = stages.plan(text, stage_rngs(seed)["plan"], planner)
    house = generate_from_spec(spec, seed, stages, planner=planner.name, progress=progress, knowledge=kb)
    later = dict(house._timings_s)
    house._timings_s.clear()
    house._timings_s.update({**timings, **later})
    return house


def generate_from_spec(
    spec: HouseSpec,
    seed: int = 0,
    stages: Stages | None = None,
    *,
    planner: str | None = None,
    progress: Progress | None = None,
    knowledge: KnowledgeBase | None = None,
) -> House:
    """Run every stage after planning (floorplan, layout, refine, assets) on ``spec``.

    ``generate(text, seed)`` is exactly ``generate_from_spec(plan, seed)`` of the plan it
    made, so the house is byte-identical. The house's ``plan`` holds the spec (without its
    provenance, which is the house's ``provenance``), so
    ``HouseSpec.model_validate(house.plan)`` gives the spec back.

    Parameters
    ----------
    spec : a HouseSpec (or its JSON as a dict)
    seed : the same seed as ``generate``'s gives the same house
    stages : the stage functions; None: the defaults
    planner : the name recorded as the house's planner; None: the spec's provenance
        ``planner`` if it has one, else "offline"
    progress : optional callback, see :data:`Progress`
    knowledge : the knowledge base the assets stage reads; None: the one in force
    """
    from anyhome.plan import HouseSpec
    from anyhome.stages import Stages, stage_rngs

    progress = progress or _quiet
    seed = _check_seed(seed)
    kb = _knowledge(knowledge)
    if not isinstance(spec, HouseSpec):
        spec = _spec_from_json(spec, "the spec", kb)
    stages = stages or Stages()
    rngs = stage_rngs(seed)
    timings: dict[str, float] = {}
    with _stage("floorplan", timings, progress):
        floorplan = stages.floorplan(spec, rngs["floorplan"])
    with _stage("layout", timings, progress):
        result = stages.layout(_stairs_given(spec, floorplan), floorplan, rngs["layout"])
    with _stage("refine", timings, progress):
        objects = _with_stairs(floorplan, stages.refine(floorplan, result.objects, rngs["refine"]))
    with _stage("assets", timings, progress):
        objects = stages.assets(objects, rngs["assets"], spec, kb)
    if planner is None:
        named = (spec.provenance or {}).get("planner")
        planner = named if isinstance(named, str) else "offline"
    house = House(
        prompt=spec.prompt,
        seed=seed,
        style=spec.style,
        styles=spec.styles,
        building=spec.building,
        palette=spec.palette,
        planner=planner,
        rooms=floorplan.rooms,
        connections=floorplan.connections,
        doors=floorplan.doors,
        windows=floorplan.windows,
        objects=objects,
        levels=floorplan.levels,
        dropped=result.dropped,
        warnings=[*spec.warnings, *floorplan.warnings],
        plan=spec.model_dump(mode="json", exclude={"provenance"}),
        provenance=spec.provenance,
    )
    house._timings_s.update(timings)
    return house


STAIR_ITEM_CATEGORIES = frozenset({"staircase", "spiral_staircase"})
"""Categories of planned items that are a house's stairs ("up a steep staircase", "a
grand staircase hall")."""


def _stairs_given(spec: HouseSpec, floorplan: Floorplan) -> HouseSpec:
    """``spec`` for the layout: in a house of several storeys, without the staircases
    the plan asks for (and what stands on them), which the floorplan's flights between
    the storeys are (measured on dev_storeys3: a tiny cottage's "steep staircase" and a
    mansion's "grand staircase" were laid out as furniture beside the stairs, or dropped
    as key items for want of a wall). The plan kept in house.json still says them."""
    if len(floorplan.levels) < 2:
        return spec
    rooms = []
    for r in spec.rooms:
        groups = [g.model_copy(update={"members": [m for m in g.members if m.category not in STAIR_ITEM_CATEGORIES]})
                  for g in r.groups if g.anchor.category not in STAIR_ITEM_CATEGORIES]
        ornaments = [o for o in r.ornaments if o.category not in STAIR_ITEM_CATEGORIES]
        rooms.append(r.model_copy(update={"groups": groups, "ornaments": ornaments}))
    return spec.model_copy(update={"rooms": rooms})


def _with_stairs(floorplan: Floorplan, objects: list[HouseObject]) -> list[HouseObject]:
    """The objects plus a flight of stairs between each pair of storeys; what the layout
    put where a flight runs (and what stands on it) gives way to the stairs."""
    from shapely.geometry import Polygon

    from anyhome.floorplan.levels import stairs_objects
    from anyhome.geometry import footprint_corners

    stairs = stairs_objects(floorplan)
    if not stairs:
        return objects
    runs = {s.room: Polygon(footprint_corners(s.position, s.size, s.yaw)) for s in stairs}
    gone = {o.id for o in objects if o.room in runs and o.support != "ceiling"
            and Polygon(footprint_corners(o.position, o.size, o.yaw)).intersects(runs[o.room])}
    grew = True
    while grew:
        kept = {o.id for o in objects if o.id not in gone and (o.support in gone or o.anchor in gone)}
        grew = bool(kept)
        gone |= kept
    return [o for o in objects if o.id not in gone] + stairs


def _knowledge(knowledge: object) -> KnowledgeBase:
    """The run's knowledge base: the caller's, else the one in force (loaded and
    validated once per overlay)."""
    from anyhome.plan.kb import KnowledgeBase
    from anyhome.plan.knowledge import knowledge_base

    if knowledge is None:
        return knowledge_base()
    if not isinstance(knowledge, KnowledgeBase):
        raise AnyHomeError(f"knowledge must be a KnowledgeBase (anyhome.plan.knowledge.knowledge_base()), "
                           f"got {type(knowledge).__name__}")
    return knowledge


def _spec_from_json(data: object, what: str, kb: KnowledgeBase) -> HouseSpec:
    """``data`` validated as a HouseSpec in the knowledge base ``kb`` (its styles, the tags
    of items without them)."""
    from pydantic import ValidationError

    from anyhome.plan import HouseSpec
    from anyhome.plan.spec import kb_context

    if not isinstance(data, dict):
        raise PlanError(f"{what} must be a HouseSpec or its JSON object, got {type(data).__name__}")
    try:
        return HouseSpec.model_validate(data, context=kb_context(kb))
    except ValidationError as e:
        err = e.errors()[0]
        where = ".".join(str(x) for x in err["loc"]) or "plan"
        raise PlanError(f"{what} is not a valid plan: {where}: {clean_text(err['msg'])}") from None


def relayout(
    house: House,
    rooms: Iterable[str] | str | None = None,
    seed: int = 0,
    stages: Stages | None = None,
    knowledge: KnowledgeBase | None = None,
) -> House:
    """Lay out, refine and furnish the named rooms of ``house`` again.

    The house's floorplan (rooms, doors, windows) and plan (``house.plan``) are used as
    they are; the objects of every other room are kept exactly (same JSON), and the new
    objects' ids are unique in the house. ``house`` is not modified.

    Parameters
    ----------
    house : a generated (or loaded) house that holds its plan
    rooms : room ids (one id as a string is fine); None: every room
    seed : seeds the layout, refine and asset stages (as ``generate`` with that seed:
        relayout of every room with the house's own seed gives the house back)
    stages : the stage functions (layout, refine, assets are used); None: the defaults
    knowledge : the knowledge base the assets stage reads; None: the one in force

    Returns
    -------
    A new House (``timings_s``: layout, refine, assets).

    Raises
    ------
    AnyHomeError
        for an unknown room id, a house without a plan, or a plan that is not valid.
    """
    from anyhome.stages import Stages, stage_rngs

    seed = _check_seed(seed)
    stages = stages or Stages()
    kb = _knowledge(knowledge)
    chosen = _chosen_rooms(house, rooms)
    if house.plan is None:
        raise AnyHomeError("this house holds no plan (house.json has no 'plan'), so its rooms cannot be "
                           "laid out again; generate it again to get one")
    spec = _spec_from_json({**house.plan, "provenance": house.provenance}, "the house's plan", kb)
    unplanned = sorted(chosen - {rs.id for rs in spec.rooms})
    if unplanned:
        raise AnyHomeError(f"room {unplanned[0]!r} is not in the house's plan, so it cannot be laid out again")
    floorplan = house.floorplan
    rngs = stage_rngs(seed)
    timings: dict[str, float] = {}
    held = {h for r in house.rooms if r.id in chosen for h in r.merged}  # an open-plan room's other planned rooms
    sub = spec.model_copy(update={"rooms": [rs for rs in spec.rooms if rs.id in chosen | held]})
    kept = [o for o in house.objects if o.room not in chosen]
    with _stage("layout", timings, _quiet):
        result = stages.layout(_stairs_given(sub, floorplan), floorplan, rngs["layout"])
    new = [o for o in result.objects if o.room in chosen]
    with _stage("refine", timings, _quiet):
        # the other rooms' objects are there as context (the walkways are house-wide);
        # only the chosen rooms' objects are taken from the result
        refined = stages.refine(floorplan, [o.model_copy(deep=True) for o in kept] + new, rngs["refine"])
    new = _unique_ids([o for o in refined if o.room in chosen], {o.id for o in kept})
    with _stage("assets", timings, _quiet):
        new = stages.assets(new, rngs["assets"], spec, kb)
    rank = {rid: i for i, rid in enumerate([rs.id for rs in spec.rooms] + [r.id for r in house.rooms])}

    def order(items: list) -> list:  # grouped by room in plan order, stable inside a room
        return sorted(items, key=lambda x: rank.get(x.room, len(rank)))

    data = house.model_dump()
    data["objects"] = [o.model_dump() for o in order(kept + new)]
    data["dropped"] = [d.model_dump() for d in order([d for d in house.dropped if d.room not in chosen]
                                                     + [d for d in result.dropped if d.room in chosen])]
    out = House.model_validate(data)
    out._timings_s.update(timings)
    return out


def _chosen_rooms(house: House, rooms: Iterable[str] | str | None) -> set[str]:
    ids = [r.id for r in house.rooms]
    if rooms is None:
        return set(ids)
    names = [rooms] if isinstance(rooms, str) else list(rooms)
    for rid in names:
        if not isinstance(rid, str) or rid not in ids:
            shown = clean_text(repr(rid))[:80]
            raise AnyHomeError(f"unknown room {shown} (rooms: {', '.join(ids)})")
    return set(names)


def _unique_ids(objects: list[HouseObject], taken: set[str]) -> list[HouseObject]:
    """``objects`` with ids renamed where they clash with ``taken`` (the kept objects'),
    and the support and anchor references among them following."""
    renames: dict[str, str] = {}
    used = set(taken) | {o.id for o in objects}
    for o in objects:
        if o.id in taken:
            base, k = o.id, 1
            while f"{base}-{k}" in used or not is_safe_id(f"{base}-{k}"):
                if not is_safe_id(f"{base}-{k}"):
                    base = base[:-1]
                else:
                    k += 1
            renames[o.id] = f"{base}-{k}"
            used.add(renames[o.id])
    if not renames:
        return objects
    return [o.model_copy(update={"id": renames.get(o.id, o.id), "support": renames.get(o.support, o.support),
                                 "anchor": renames.get(o.anchor, o.anchor) if o.anchor else o.anchor})
            for o in objects]


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
    from anyhome.export import write_glb
    from anyhome.export.svg import write_level_svgs
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
            written += write_level_svgs(house, tmp)
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
