"""Floorplans of several storeys: one solve per storey, stairwells stacked, stairs objects.

A plan whose rooms all sit on level 0 goes straight to :func:`solve_floorplan` (the same
floorplan, byte for byte). Otherwise every storey is solved as a house of its own (an
upper storey or a basement gets a stand-in entrance through its stairwell, dropped
afterwards), until its stairwell comes out as a rectangle that holds its dog-leg stair
(:mod:`anyhome.floorplan.stairs`: two flights side by side, the half landing at one end,
as long as the taller of the storeys it joins needs) and the strip of floor at the
stair's foot (:func:`stairwell_min_m`; the solver is asked for that long side, and the
stairwell's doors in the stair's way are slid along their wall clear of it, :func:`_doors_cleared`).
Each storey is then turned (a quarter turn when needed) so its stairwell's long side
runs east-west, and placed on (a basement: under) the storey next to it toward the
ground with a corner of its stairwell on the same corner of that one's, where the
stairwells of all storeys overlap so that every flight fits with its foot at one place,
clear of their doors (:func:`stack_box`): storey over storey, as in a real stairwell
(the flight above runs a storey over the one below). Each flight is a ``stairs`` object
in the lower storey's stairwell (:func:`stairs_objects`). The place of the stairs is
recorded on the storeys (:attr:`~anyhome.house.Level.stairs_at`). A stairwell opening
onto one room only, a living room, a dining room or a hall, a top storey's one
habitable room (a mezzanine or attic bedroom), or a basement's cellar or laundry, is merged into that room, which the
stair rises in or arrives in, with no landing of its own (:func:`stairs_opened`); the
layout keeps the flights and the floor at their feet clear (:func:`stair_zones`); a storey
whose stairwell opens onto one such room only is searched with the stairwell carved from
that room's corner (:mod:`anyhome.floorplan.carve`), so it merges back as the room's own
rectangle. Storeys that will not stack
are tried again with roomier stairwells, then laid out on one storey.

Work is saved between tries: a storey's search asks each valid layout for its stair as
it finds it (:func:`~anyhome.floorplan.solver.floorplan_candidates` ``accept``; one
that fails is a failed attempt) and stops at the first that holds it
(``storey_wanted_candidates``); an upper storey chooses for the least
overhang among the layouts of separate searches (one search's layouts differ too
little: with them the storey houses' hallways grew); the sixteen places of a storey on the one below
are ranked by overhang (one union of its floor, moved) and the stair, the costly test,
is looked for in that order only until it fits; a stairwell's doors are slid clear of
the stair, and the stair's box tested against the doors, at every place at once. An
upper storey placed as well as its floor allows (:func:`_least_hang_m2`) is not searched
again, and every search of the house together makes at most ``levels_max_attempts``
layout attempts (:mod:`anyhome.floorplan.budget`): past them, one FloorplanError line.

The narrow interface (:func:`solve_levels`, :func:`stairs_objects`) is what the pipeline
sees; a solver that takes a footprint and a fixed stairwell rectangle can replace the
per-storey solve without changing it. Storeys are not solved inside the floor below: of a
few layouts of each, mirrored and with its stairwell on any corner of the one below, the
one hanging least over nothing is kept (:func:`overhang_m2`; an upper storey may still
overhang).

A room much taller than the other rooms of its storey (a double-height living room, a
nave: :data:`THROUGH_FACTOR`) rises through the storey above (:func:`through_rooms`): the
storey is as high as its other rooms, the storey above (a mezzanine, a gallery) is placed
beside it, over the other rooms, and its ceiling stops at that storey's ceiling. Where no
placement keeps off it, the house is stacked as before (the storey above over its top).
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable, Iterable
from contextvars import ContextVar
from typing import TYPE_CHECKING

import numpy as np

from anyhome.errors import FloorplanError
from anyhome.floorplan.budget import ATTEMPT_BUDGET, AttemptBudget, AttemptsSpent
from anyhome.floorplan.doors import DOOR_WIDTH_M, ENTRANCE_WIDTH_M
from anyhome.floorplan.grid import SNAP_M
from anyhome.floorplan.merge import merge_open_plan
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.solver import OPENING_HEADROOM_M, floorplan_candidates, solve_floorplan
from anyhome.floorplan.stairs import (
    DOGLEG,
    HALL_DOOR_M,
    HALL_DOORS,
    LADDER,
    LADDER_NAME,
    PASSAGE_M,
    SPIRAL,
    SPIRAL_NAME,
    STAIR_CLEAR_M,
    STAIR_WIDTH,
    STAIR_WIDTH_M,
    STRIP_M,
    dogleg,
    doors_joined,
    flight_rect,
    is_dogleg_box,
    is_stairwell,
    ladder_risers,
    says_stair,
    spiral_risers,
    stair_hall_min_doors,
    stair_kind,
    stair_length_m,
    stair_width_m,
    well_width_m,
)
from anyhome.floorplan.wells import wells_doors_to_strip, wells_end_trimmed, wells_trimmed
from anyhome.geometry import DOOR_CLEARANCE_M, opening_zone
from anyhome.house import Door, Floorplan, HouseObject, Level, Room, Window
from anyhome.plan.spec import HouseSpec

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

SLAB_M = 0.2
"""Floor structure between a storey's ceiling and the next storey's floor."""
STAIRS_CATEGORY = "stairs"


def stair_room(spec: HouseSpec, level: int) -> str:
    """The id of the stairwell of ``level``: its room named or id'd like a stair."""
    for r in spec.rooms:
        if r.level == level and is_stairwell(r):
            return r.id
    raise FloorplanError(f"level {level} has no stairwell room (a room named 'stairwell')")


THROUGH_FACTOR = 1.6
"""A room of storey ``k`` (ground or above) under a storey ``k`` + 1 is at least this many
times as high as the storey's other rooms' tallest: it rises through the storey above (a
double-height room open to a mezzanine or gallery beside it), :func:`through_rooms`."""
THROUGH_OVERLAP_OK_M2 = 0.05
"""Floor of a storey that may lie over a room rising through it (m2): snapping slivers."""

_AS_ORDINARY: ContextVar[bool] = ContextVar("anyhome_through_as_ordinary", default=False)
"""Set while a house whose upper storey would not sit beside its through rooms is laid
out as before (through rooms as ordinary ones: the storey above over their ceilings)."""
_NARROW_HALLS: ContextVar[set[int] | None] = ContextVar("anyhome_narrow_halls", default=None)
"""The storeys, in the :func:`solve_levels` call under way, whose stair hall the solver
could not lay out as wide as :func:`stair_hall_width_m` asks (asked once, not again)."""
_UNCARVED: ContextVar[set[int] | None] = ContextVar("anyhome_uncarved", default=None)
"""The storeys, in the :func:`solve_levels` call under way, whose carve search
(:func:`_carved_storey`) found no layout once: not searched again (measured on dev_storeys
and dev_storeys2: of 779 such searches after a storey's first failed one, 5 found one)."""
_UNSLICED: ContextVar[set[int] | None] = ContextVar("anyhome_unsliced", default=None)
"""The storeys, in the :func:`solve_levels` call under way, one of whose searches spent
all its slicing attempts (``slicing_attempts``) without a layout: their later searches go
to the spine at once (measured on dev_storeys and dev_storeys2: a third of the storeys'
searches found their layout only in the spine, after 15 slicing attempts)."""


def _through_ids(rooms: Iterable[tuple[str, int, float, bool]]) -> set[str]:
    """Ids of the rooms rising through the storey above, of ``rooms``: (id, level, height,
    is a stairwell). On storey ``k`` >= 0 with a storey ``k`` + 1, a room (never the
    stairwell) at least :data:`THROUGH_FACTOR` times as high as the tallest of the
    storey's rooms that do not rise through (found by shrinking the set of tall rooms
    until it holds still; the lowest room always stays)."""
    rooms = list(rooms)
    numbers = {lv for _, lv, _, _ in rooms}
    out: set[str] = set()
    for k in numbers:
        if k < 0 or k + 1 not in numbers:
            continue
        here = [r for r in rooms if r[1] == k]
        low = min(h for _, _, h, _ in here)
        tall = {i for i, _, h, stair in here if not stair and h > low}
        while tall:
            ordinary = max(h for i, _, h, _ in here if i not in tall)
            keep = {i for i, _, h, _ in here if i in tall and h >= THROUGH_FACTOR * ordinary - 1e-9}
            if keep == tall:
                break
            tall = keep
        out |= tall
    return out


def through_rooms(spec: HouseSpec) -> set[str]:
    """Ids of the rooms of ``spec`` that rise through the storey above theirs (see
    :data:`THROUGH_FACTOR`): the storey's height leaves them out, the storey above is
    laid out beside them, not over them, and their ceiling stays under its ceiling."""
    if _AS_ORDINARY.get():
        return set()
    return _through_ids((r.id, r.level, r.height_m, is_stairwell(r)) for r in spec.rooms)


def storey_heights_m(spec: HouseSpec) -> dict[int, float]:
    """Floor-to-floor height of every storey of ``spec``: its tallest room that does not
    rise through the storey above (:func:`through_rooms`) and the slab."""
    through = through_rooms(spec)
    return {k: max(r.height_m for r in spec.rooms if r.level == k and r.id not in through) + SLAB_M
            for k in {r.level for r in spec.rooms}}


def house_stair_kind(spec: HouseSpec) -> str:
    """The kind of stairs of ``spec`` (:func:`~anyhome.floorplan.stairs.stair_kind`: a
    spiral for a small house) from the floor its rooms, stairwells left out, plan."""
    return stair_kind(sum(r.area_m2 for r in spec.rooms if not is_stairwell(r)))


def plan_stair_kind(plan: Floorplan) -> str:
    """The kind of stairs of a laid-out ``plan``, as recorded on its storeys
    (:attr:`~anyhome.house.Level.stairs_kind`; none recorded: a dog-leg)."""
    return next((lv.stairs_kind for lv in plan.levels if lv.stairs_kind in (SPIRAL, LADDER)), DOGLEG)



def flight_length_m(heights: dict[int, float], k: int, kind: str = DOGLEG) -> float:
    """Length of the stair box the stairwell of storey ``k`` holds: the longer of the
    flights of ``kind`` that start or arrive there (their rises: the storeys' heights)."""
    rises = [heights[j] for j in (k - 1, k) if j in heights and j + 1 in heights]
    return max(stair_length_m(kind, r) for r in rises or [heights[k]])


def stairwell_min_m(spec: HouseSpec, k: int) -> tuple[float, float]:
    """(long, short) sides the stairwell of storey ``k`` needs: its stair box
    (:func:`flight_length_m`) and the strip of floor at the stair's foot (where a flight
    starts and the one below arrives), by the two flights' width; a stair hall with more
    than :data:`~anyhome.floorplan.stairs.HALL_DOORS` doors is longer by
    :data:`~anyhome.floorplan.stairs.HALL_DOOR_M` per door. (How wide it is beyond the
    stair, for a landing beside it, is the planned area's say.)"""
    extra_m = HALL_DOOR_M * max(0, _stair_doors(spec, k) - HALL_DOORS)
    if k == 0 and any(stair_room(spec, 0) in c and "outside" in c for c in spec.connections):
        extra_m += ENTRANCE_WIDTH_M - DOOR_WIDTH_M  # the front door, wider, in the strip's long wall
    kind = house_stair_kind(spec)
    return (round(flight_length_m(storey_heights_m(spec), k, kind) + STRIP_M + extra_m, 4), well_width_m(kind))


def stair_hall_width_m(spec: HouseSpec, k: int) -> float:
    """Narrowest side the solver is asked to give the stairwell of storey ``k``: a stair
    hall (:func:`~anyhome.floorplan.stairs.stair_hall_min_doors` or more) holds its stair and a landing beside it
    (:data:`~anyhome.floorplan.stairs.PASSAGE_M`) that the doors across from the stair
    open onto; a plain stairwell, the stair's width. (A hall narrower than that comes out
    with its flight cutting it in two and is refused, :func:`~anyhome.floorplan.stairs.doors_joined`: measured, a
    townhouse's five-door ground floor was laid out 40 times over, 10-20 s.)"""
    kind = house_stair_kind(spec)
    plain = well_width_m(kind)
    if _stair_doors(spec, k) >= stair_hall_min_doors(kind):
        return round(max(plain, stair_width_m(kind) + PASSAGE_M), 4)
    return plain


def _stair_doors(spec: HouseSpec, k: int) -> int:
    """Doors the plan gives the stairwell of storey ``k`` (its connections)."""
    stair = stair_room(spec, k)
    return sum(stair in c for c in spec.connections)


def solve_levels(spec: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None = None) -> Floorplan:
    """Lay out every storey of ``spec`` (see the module doc); one storey: solve_floorplan."""
    numbers = sorted({r.level for r in spec.rooms})
    if numbers == [0]:
        return merge_open_plan(solve_floorplan(spec, rng, options), spec, rng, options)
    if 0 not in numbers:
        raise FloorplanError("a house of several storeys needs rooms on the ground floor (level 0)")
    opts = options or FloorplanOptions()
    roomy = dataclasses.replace(opts, stairwell_spare_m=opts.stairwell_spare_m + opts.stairwell_roomy_m)
    token = _NARROW_HALLS.set(set())
    uncarved = _UNCARVED.set(set())
    unsliced = _UNSLICED.set(set())
    spent = ATTEMPT_BUDGET.set(AttemptBudget(opts.levels_max_attempts))  # every search of the house, together
    try:
        return _levels_tried(spec, numbers, rng, opts, roomy, options)
    except AttemptsSpent:
        raise FloorplanError(f"could not lay out the {len(numbers)} storeys in {opts.levels_max_attempts} layout "
                             f"attempts (FloorplanOptions.levels_max_attempts)") from None
    finally:
        ATTEMPT_BUDGET.reset(spent)
        _UNCARVED.reset(uncarved)
        _UNSLICED.reset(unsliced)
        _NARROW_HALLS.reset(token)


def _levels_tried(spec: HouseSpec, numbers: list[int], rng: np.random.Generator, opts: FloorplanOptions,
                  roomy: FloorplanOptions, options: FloorplanOptions | None) -> Floorplan:
    why = ""
    i = 0
    while i < opts.level_attempts:  # the later half with roomier stairwells (a squarer room holds the stair)
        half = opts.level_attempts // 2
        try:
            return _stacked(spec, numbers, rng, opts if i < half else roomy)  # the stairs placed, or FloorplanError
        except _Unsolvable as e:  # a storey the solver cannot lay out at all: roomier, then one storey
            why = str(e)
            i = half if i < half else opts.level_attempts
        except FloorplanError as e:
            why = str(e)
            i += 1
    return _one_storey(spec, rng, options, why)


def _stacked(spec: HouseSpec, numbers: list[int], rng: np.random.Generator, options: FloorplanOptions | None) -> Floorplan:
    opts = options or FloorplanOptions()
    plans: dict[int, Floorplan] = {0: _solve_storey(spec, 0, rng, options)}
    outward = [n for n in numbers if n > 0] + sorted((n for n in numbers if n < 0), reverse=True)
    for k in outward:  # each storey on (or under) the one next to it toward the ground
        ref = k - 1 if k > 0 else k + 1
        best, why, blocked = _placed_storey(spec, plans, k, ref, rng, options, opts.storey_wanted_candidates)
        if best is None and blocked and through_rooms(spec) and opts.wanted_candidates > opts.storey_wanted_candidates:
            best, why, blocked = _placed_storey(spec, plans, k, ref, rng, options, opts.wanted_candidates)  # the tight fit beside a tall room: the best of more layouts
        if best is None:
            if blocked and through_rooms(spec):  # as before: through rooms as ordinary ones
                token = _AS_ORDINARY.set(True)
                try:
                    return _stacked(spec, numbers, rng, options)
                finally:
                    _AS_ORDINARY.reset(token)
            raise FloorplanError(why)
        plans[k] = best[1]
    heights = storey_heights_m(spec)
    elevation = {0: 0.0}
    for k in (n for n in numbers if n > 0):
        elevation[k] = elevation[k - 1] + heights[k - 1]
    for k in sorted((n for n in numbers if n < 0), reverse=True):
        elevation[k] = elevation[k + 1] - heights[k]
    levels = [Level(level=k, elevation_m=round(elevation[k], 4), height_m=round(heights[k], 4)) for k in numbers]
    plan = _stairs_recorded(_under_above(_joined(spec, plans, levels), through_rooms(spec)), house_stair_kind(spec))
    kind = house_stair_kind(spec)
    wells = {k: stair_room(spec, k) for k in numbers}
    foot, ya, yaw = _stairs_place(plan)
    lengths = {k: flight_length_m(heights, k, kind) for k in numbers}
    boxes = {k: (foot - n, foot) if abs(yaw) < 0.1 else (foot, foot + n) for k, n in lengths.items()}

    def trimmed_opened(slid: dict[int, str]) -> Floorplan:
        out = wells_doors_to_strip(plan, (foot, ya, yaw), slid) if slid else plan
        out = wells_trimmed(out, ya, wells, opts, kind, boxes if opts.well_end_trim else None)
        if opts.well_end_trim:
            out = wells_end_trimmed(out, (foot, ya, yaw), lengths, wells, opts)
        return stairs_opened(out, opts)

    opened = trimmed_opened({})
    kept = {k: w for k, w in wells.items() if any(r.id == w for r in opened.rooms)}  # not merged into a room
    if opts.well_doors_to_strip and kept:  # their doors onto the strip (a merge, where one is made, saves more)
        opened = trimmed_opened(kept)
    return opened


def _placed_storey(spec: HouseSpec, plans: dict[int, Floorplan], k: int, ref: int, rng: np.random.Generator,
                   options: FloorplanOptions | None, wanted: int) -> tuple[tuple[float, Floorplan] | None, str, bool]:
    """Storey ``k`` placed on (under) storey ``ref`` of ``plans``: of the layouts of a few
    separate searches (``storey_candidates``; each the best of ``wanted`` that hold the
    stair, :func:`_solve_storey`), the one hanging least over nothing, with its overhang
    (None: none placed); why the last try failed; whether every try failed only for want
    of a place beside a room rising through it."""
    opts = options or FloorplanOptions()
    best: tuple[float, Floorplan] | None = None
    why = ""
    blocked = True
    for _ in range(opts.storey_candidates):
        try:
            layout = _solve_storey(spec, k, rng, options, wanted)
        except _Unsolvable:
            raise
        except FloorplanError as e:
            why, blocked = str(e), False
            continue
        try:
            hang, placed = _best_placed(spec, plans, layout, k, ref)
        except _ThroughBlocked as e:
            why = str(e)
            continue
        except FloorplanError as e:
            why, blocked = str(e), False
            continue
        if best is None or hang < best[0] - 1e-6:
            best = (hang, placed)
        if hang <= opts.overhang_ok_m2 + _least_hang_m2(spec, plans[ref], layout, k):
            break
    return best, why, blocked


def _least_hang_m2(spec: HouseSpec, below: Floorplan, layout: Floorplan, k: int) -> float:
    """The least any place of storey ``k`` (``layout``) on the storey ``below`` can hang
    over nothing (m2): its floor less the floor that can hold it up (a room rising
    through holds none up), where more. A layout placed within ``overhang_ok_m2`` of
    that is kept without searching the storey again (another search's layout could
    still be smaller; measured on dev_storeys and dev_storeys2, 9 of 108 plans changed,
    dev_storeys2's CPU median 214 -> 195 ms)."""
    from shapely.geometry import Polygon

    through = through_rooms(spec) if k > 0 else set()
    floor_m2 = sum(Polygon(r.polygon).area for r in layout.rooms)
    held_m2 = sum(Polygon(r.polygon).area for r in below.rooms if r.id not in through)
    return max(0.0, floor_m2 - held_m2)


def _stairs_recorded(plan: Floorplan, kind: str = DOGLEG) -> Floorplan:
    """``plan`` with the place of its stairs of ``kind`` (:func:`stack_box`) recorded on
    every storey a flight rises from (:attr:`~anyhome.house.Level.stairs_at`, and
    ``stairs_kind`` for a spiral), so it stays where it is when a stairwell is merged
    into a room (:func:`stairs_opened`)."""
    numbers = sorted(lv.level for lv in plan.levels)
    if len(numbers) < 2:
        return plan
    marked = {"stairs_kind": kind} if kind in (SPIRAL, LADDER) else {}
    plan = plan.model_copy(update={"levels": [
        lv.model_copy(update=marked) if lv.level < numbers[-1] else lv for lv in plan.levels]})
    found = _stairs_place(plan)
    return plan.model_copy(update={"levels": [
        lv.model_copy(update={"stairs_at": found}) if lv.level < numbers[-1] else lv for lv in plan.levels]})


def _stairs_place(plan: Floorplan) -> tuple[float, float, float]:
    """(foot_x, y0, yaw) of the stairs of ``plan`` (two storeys or more): as recorded on
    its storeys, else found in its stairwells (:func:`stack_box`)."""
    found = next((lv.stairs_at for lv in plan.levels if lv.stairs_at is not None), None)
    found = found or stack_box([(lv.level, plan) for lv in plan.levels], {lv.level: lv.height_m for lv in plan.levels},
                               plan_stair_kind(plan))
    if found is None:
        names = ", ".join(repr(_stairwell(plan, lv.level).id) for lv in sorted(plan.levels, key=lambda lv: lv.level))
        raise FloorplanError(f"no room for the stairs in {names}")
    foot, ya, yaw = found
    return foot, ya, 0.0 if abs(yaw) < 0.1 else math.pi  # a yaw read back from house.json is rounded


def stairs_opened(plan: Floorplan, opts: FloorplanOptions | None = None) -> Floorplan:
    """``plan`` with every stairwell that opens onto one room only merged into that room,
    where the stair may rise in it (:func:`_stair_opened`): the open stair of a cottage's
    living room, of a loft's mezzanine bedroom, of an attic room."""
    opts = opts or FloorplanOptions()
    numbers = sorted(lv.level for lv in plan.levels)
    for k in numbers if len(numbers) >= 2 else ():
        plan = _stair_opened(plan, k, numbers[-1], opts, numbers[0])
    return plan


def _stair_opened(plan: Floorplan, k: int, top: int, opts: FloorplanOptions, bottom: int = 0) -> Floorplan:
    """``plan`` with storey ``k``'s stairwell merged into a room, so the stair rises in,
    or arrives in, that room instead of a landing of its own: a stairwell of one or two
    doors (none to the outside), into a room it opens onto or shares a wall with
    (as long as a door needs, ``shared_wall_min_m``), those it opens onto first, where that room is

    - of a type an open stair may rise in (``open_plan.yaml`` ``open_stair``: a living
      room, a dining room, a hall; people pass through it to the next storey), and the
      stairwell's other door, if any, led to no bedroom (:data:`NOT_THROUGH`: it now
      opens off that room);
    - or, on the top storey ``top``, the storey's only room people stay in (a mezzanine
      or attic bedroom; a bathroom or closet the stairwell opened onto opens off it);
    - or, on a basement that is the lowest storey ``bottom``, a room of a type its stair
      may rise from in the open (``open_plan.yaml`` ``basement_stair``: a cellar, a
      laundry, a playroom), the other door, if any, to no bedroom.

    The room keeps its name, type and ceiling and holds the stairwell
    (:attr:`~anyhome.house.Room.merged`) and takes the taller of the two heights; below
    the top storey a room rising through the storey above is refused
    (:func:`_rises_through`: the stairwell above would stand on its open ceiling), a room
    a little taller or lower than the stairwell is not.
    The floor over a flight stays open (:func:`anyhome.scene.stair_openings`) and the
    layout keeps every flight and the strip at its foot clear (:func:`stair_zones`).
    Refused where the room is open-air or merged already, and where
    :func:`_merged_well` refuses."""
    from anyhome.house import is_habitable

    well = next((r for r in plan.rooms if r.level == k and is_stairwell(r)), None)
    if well is None or well.merged:
        return plan
    doors = [d for d in plan.doors if well.id in d.rooms]
    if not doors or len(doors) > 2 or any("outside" in d.rooms for d in doors):
        return plan
    through = [plan.room(next(x for x in d.rooms if x != well.id)) for d in doors]
    beside = [r for r in plan.rooms if r.level == k and r not in through and r.id != well.id
              and _shared_wall_m(r, well) >= opts.shared_wall_min_m]
    for room in [*sorted(through, key=lambda r: not is_habitable(r.type)), *beside]:
        if room.open_air or room.merged or is_stairwell(room):
            continue
        others = [r for r in through if r.id != room.id]  # the rooms the stairwell's other door led to
        if k == top and is_habitable(room.type) and not any(
                is_habitable(r.type) for r in plan.rooms if r.level == k and r.id not in (room.id, well.id)):
            pass  # a top storey's one room (its bathroom then opens off it)
        elif room.type not in _open_stair_types(k, bottom) or any(r.type in NOT_THROUGH for r in others):
            continue
        if k != top and _rises_through(plan, k, room):
            continue
        opened = _merged_well(plan, k, room, well, opts)
        if opened is not None:
            return opened
    return plan


def _open_stair_types(k: int, bottom: int) -> frozenset[str]:
    """Room types an open stair may rise in on storey ``k`` (``bottom``: the lowest):
    ``open_plan.yaml`` ``open_stair`` and ``stair_hall``, and on a basement at the bottom
    ``basement_stair``."""
    from anyhome.floorplan.merge import open_plan_data

    data = open_plan_data()
    types = data.open_stair | data.stair_hall
    return types | data.basement_stair if k == bottom < 0 else types


def _rises_through(plan: Floorplan, k: int, room: Room) -> bool:
    """Whether ``room`` of storey ``k`` is taller than its storey's ceiling (a room rising
    through the storey above, :func:`through_rooms`): the stairwell above would stand on
    its open ceiling. A room a little taller or lower than the stairwell is not."""
    storey = next((lv for lv in plan.levels if lv.level == k), None)
    return storey is not None and room.height > storey.height_m - SLAB_M + 1e-6


NOT_THROUGH = frozenset({"bedroom"})
"""Room types that may not be reached through a room an open stair rises in, where the
stairwell opened onto them too."""


def _shared_wall_m(a: Room, b: Room) -> float:
    from shapely.geometry import Polygon

    return float(Polygon(a.polygon).boundary.intersection(Polygon(b.polygon).boundary).length)


def _merged_well(plan: Floorplan, k: int, room: Room, well: Room, opts: FloorplanOptions) -> Floorplan | None:
    """``plan`` with ``well`` merged into ``room`` (:func:`_stair_opened`), or None where
    their union is not one outline of at most ``open_stair_max_corners`` corners within
    ``open_stair_max_aspect_ratio`` (bounding box over widest disc), or a
    flight (at the place recorded on the storeys, :func:`_stairs_recorded`) would not
    stand in, or arrive in, the room."""
    from shapely.geometry import Polygon

    from anyhome.floorplan.merge import l_aspect_over, merge_rooms, union_outline

    if not (Polygon(room.polygon).is_valid and Polygon(well.polygon).is_valid):
        return None
    outline = union_outline(room.polygon, well.polygon, tuple(range(4, opts.open_stair_max_corners + 1, 2)))
    if outline is None or l_aspect_over(outline, opts.open_stair_max_aspect_ratio + 1e-9):
        return None
    if len(outline) > 6 and (_shared_wall_m(room, well) < opts.shared_wall_min_m - 1e-6  # an alcove wide enough to walk into
                             or not (_strip_off(plan, room) or _alcove_passage(plan, room, well, k))):
        return None
    opened = merge_rooms(plan, room.id, well.id, name=room.name, outline=outline)
    if well.height > room.height:  # the storey stays as high as its tallest room
        opened = opened.model_copy(update={"rooms": [
            r.model_copy(update={"height": well.height}) if r.id == room.id else r for r in opened.rooms]})
    if _door_beside_flight(opened, room.id, k):
        return None
    levels = {r.id: r.level for r in opened.rooms}
    for o in stairs_objects(opened):  # at the place recorded before the merge  # the flight from storey k stands in the room, the one from below arrives in it
        if (levels[o.room] == k and o.room != room.id) or (
                levels[o.room] == k - 1 and (link := stair_link(opened, o)) is not None and link[1] != room.id):
            return None
    return opened


def _strip_off(plan: Floorplan, room: Room) -> bool:
    """Whether ``room`` borders the strip of floor at the stairs' foot (recorded on the
    storeys) over a door's width: a stairwell that is an alcove off part of its wall (a T
    or Z) is walked into there, not past the flight (measured: a country house's snug
    whose alcove met it beside the flight left the stair's foot reached only through the
    boot room, and the furnished snug cut off three rooms)."""
    from shapely.geometry import Polygon

    strip = _foot_strip(plan)
    return float(Polygon(room.polygon).boundary.intersection(strip.boundary).length) >= DOOR_WIDTH_M - 1e-6


def _foot_strip(plan: Floorplan):
    """The strip of floor at the stairs' foot (recorded on the storeys), as a shapely box
    :data:`~anyhome.floorplan.stairs.STRIP_M` deep and as wide as the stair."""
    from shapely.geometry import box

    foot, ya, yaw = _stairs_place(plan)
    width = stair_width_m(plan_stair_kind(plan))
    return box(foot, ya, foot + STRIP_M, ya + width) if yaw == 0.0 else box(foot - STRIP_M, ya, foot, ya + width)


def _alcove_passage(plan: Floorplan, room: Room, well: Room, k: int) -> bool:
    """Whether ``well`` (storey ``k``) leaves a passage at least
    :data:`~anyhome.floorplan.stairs.PASSAGE_M` wide, clear of every flight standing in it
    or rising through it from below, from its wall shared with ``room`` (over a door's
    width) to the strip at the stairs' foot: an alcove walked into in front of its flight
    (measured on the dev storey sets: a duplex's 11.5 m2 stairwell, opening onto the
    living room only, was kept as a hall because the living room met it along the flight,
    not at its foot). :func:`stair_zones` keeps that passage clear of furniture."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    wpoly = Polygon(well.polygon)
    flights = [b for b in _flight_boxes(plan, (k, k - 1)) if b.intersection(wpoly).area > 1e-6]
    free = wpoly.difference(unary_union(flights)) if flights else wpoly
    r = PASSAGE_M / 2 - 1e-3
    reach = free.buffer(-r, join_style=2).buffer(r, join_style=2)  # where a walker of PASSAGE_M's width goes
    strip = _foot_strip(plan)
    width = stair_width_m(plan_stair_kind(plan))
    shared = Polygon(room.polygon).boundary.intersection(wpoly.boundary).buffer(1e-3)
    return any(part.intersection(strip).area >= PASSAGE_M * min(width, STRIP_M) - 1e-3
               and part.boundary.intersection(shared).length >= DOOR_WIDTH_M - 1e-6
               for part in getattr(reach, "geoms", [reach]))


def _flight_boxes(plan: Floorplan, levels: tuple[int, ...]):
    """The boxes (shapely) of the stairs standing on the storeys ``levels``."""
    level_of = {r.id: r.level for r in plan.rooms}
    return [_flight_box(o) for o in stairs_objects(plan) if level_of.get(o.room) in levels]


def _flight_box(o: HouseObject):
    """The box (shapely) of a ``stairs`` object (its long side east-west: yaw 0 or pi)."""
    from shapely.geometry import box

    x, y, _ = o.position
    return box(x - o.size[0] / 2, y - o.size[1] / 2, x + o.size[0] / 2, y + o.size[1] / 2)


def _door_beside_flight(plan: Floorplan, room_id: str, k: int) -> bool:
    """Whether a door of ``room_id`` (storey ``k``, the stair rising in it) opens beside
    the stair, between a flight and the room's walls behind it, where the passage it
    leads along may be furnished shut (measured: a den's armchair cut a garage off); the
    floor beyond the strip at the stair's foot, where the stair is come to, may hold doors."""
    from shapely.geometry import Polygon, box

    room = plan.room(room_id)
    foot, ya, yaw = _stairs_place(plan)
    poly = Polygon(room.polygon)
    x0, _, x1, _ = poly.bounds
    kind = plan_stair_kind(plan)
    length_m = stair_length_m(kind, next(lv.height_m for lv in plan.levels if lv.level == k))  # the flight rising from it
    width = stair_width_m(kind)
    flight = flight_rect(foot, ya, length_m, width, yaw)
    behind = box(x0, ya, foot, ya + width) if yaw == 0.0 else box(foot, ya, x1, ya + width)  # the flight's side of its foot
    beside = poly.intersection(behind).difference(flight)
    return any(opening_zone(dr.segment).intersection(beside).area > 0.05 for dr in plan.doors if room_id in dr.rooms)


class _Unsolvable(FloorplanError):
    """A storey of the house that the solver could not lay out in all its attempts."""


class _ThroughBlocked(FloorplanError):
    """No placement of a storey keeps it off the rooms rising through it from below."""


def _under_above(plan: Floorplan, through: set[str]) -> Floorplan:
    """``plan`` with the ceiling of each room in ``through`` (rising from storey ``k``
    through ``k`` + 1) at most that of storey ``k`` + 1 (its elevation and height, less
    the slab over it), and its windows' tops kept under the ceiling."""
    if not through:
        return plan
    levels = {lv.level: lv for lv in plan.levels}
    tops: dict[str, float] = {}
    rooms = []
    for r in plan.rooms:
        up, here = levels.get(r.level + 1), levels.get(r.level)
        if r.id in through and up is not None and here is not None:
            top = round(up.elevation_m + up.height_m - SLAB_M - here.elevation_m, 4)
            if r.height > top + 1e-9:
                tops[r.id] = top
                r = r.model_copy(update={"height": top})
        rooms.append(r)
    if not tops:
        return plan
    windows = [w.model_copy(update={"height": min(w.height, tops[w.room] - OPENING_HEADROOM_M - w.sill)})
               if w.room in tops else w for w in plan.windows]
    return plan.model_copy(update={"rooms": rooms, "windows": windows})


MIRRORS = ((False, False), (True, False), (False, True), (True, True))
"""The four mirror images of a storey: as laid out, flipped east-west, north-south, both."""


def _mirrored(plan: Floorplan, stair: str, flip_x: bool, flip_y: bool) -> Floorplan:
    """``plan`` mirrored about its stairwell's centre lines, so the stairwell stays put
    (outlines are reversed to stay counter-clockwise)."""
    if not (flip_x or flip_y):
        return plan
    x0, y0, w, h = _rect(plan.room(stair))
    cx, cy = x0 + w / 2, y0 + h / 2
    out = _map(plan, lambda p: (round(2 * cx - p[0], 6) if flip_x else p[0], round(2 * cy - p[1], 6) if flip_y else p[1]))
    if flip_x != flip_y:  # one reflection turns outlines clockwise
        out = out.model_copy(update={"rooms": [r.model_copy(update={"polygon": list(reversed(r.polygon))}) for r in out.rooms]})
    return out


def _best_placed(spec: HouseSpec, plans: dict[int, Floorplan], plan: Floorplan, k: int,
                 ref: int) -> tuple[float, Floorplan]:
    """Storey ``k`` (``plan``) placed on (a basement: under) storey ``ref``: of its four mirror
    images (:data:`MIRRORS`), each with a corner of its stairwell on the same corner of
    the stairwell of ``ref``, the one whose floor lies most over (under) ``ref``'s, among
    those where the stair fits in the stairwells of every storey placed so far, clear of
    their doors (:func:`stack_box`); with the area of its floor outside ``ref``'s (m2)."""
    stair, ref_stair = stair_room(spec, k), stair_room(spec, ref)
    rx, ry, rw, rh = _rect(plans[ref].room(ref_stair))
    through = through_rooms(spec) if k > 0 else set()  # a basement lies under every room
    below = [r.polygon for r in plans[ref].rooms if r.id not in through]
    rising = [r.polygon for r in plans[ref].rooms if r.id in through]
    heights = storey_heights_m(spec)
    from shapely import affinity

    floor = _union([r.polygon for r in plan.rooms])  # the storey's floor, once: each place moves it
    under = _union(below).buffer(1e-6)
    through_floor = _union(rising) if rising else None
    x0, y0, w, h = _rect(plan.room(stair))
    places: list[tuple[float, bool, bool, bool, float, float]] = []  # (hang, over a room rising through, mirrors, shift)
    for fx, fy in MIRRORS:
        mirrored = affinity.scale(floor, -1.0 if fx else 1.0, -1.0 if fy else 1.0, origin=(x0 + w / 2, y0 + h / 2))
        for cx, cy in ((0, 0), (1, 0), (0, 1), (1, 1)):  # south-west, south-east, north-west, north-east
            dx, dy = rx + cx * rw - (x0 + cx * w), ry + cy * rh - (y0 + cy * h)  # the stairwell stays put when mirrored
            moved = affinity.translate(mirrored, dx, dy)
            over = through_floor is not None and float(moved.intersection(through_floor).area) > THROUGH_OVERLAP_OK_M2
            places.append((float(moved.difference(under).area), over, fx, fy, dx, dy))
    # the stair is looked for (the costly test) in order of hang, the first place it fits wins
    for hang, over, fx, fy, dx, dy in sorted(places, key=lambda t: (t[1], round(t[0], 6))):
        cand = _moved(_mirrored(plan, stair, fx, fy), dx, dy)
        if stack_box([*plans.items(), (k, cand)], heights, house_stair_kind(spec)) is None:
            continue
        if over:
            raise _ThroughBlocked(f"every place for level {k} lies over a room rising through it from level {ref}")
        return hang, cand
    raise FloorplanError(f"no room for a flight of stairs between {ref_stair!r} and {stair!r}")


def _union(outlines: Iterable):
    """The union of the polygons ``outlines`` (shapely)."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    return unary_union([Polygon(p).buffer(0) for p in outlines])


def _outside_m2(outlines: Iterable, below: Iterable) -> float:
    """Area of the union of ``outlines`` that lies outside the union of ``below``."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    floor = unary_union([Polygon(p).buffer(0) for p in outlines])
    return float(floor.difference(unary_union([Polygon(p).buffer(0) for p in below]).buffer(1e-6)).area)


def overhang_m2(rooms: Iterable) -> float:
    """Area of the rooms of each storey above the ground floor that lies over no room of
    the storey below (floor hanging in the air); a room rising through the storey above
    (:data:`THROUGH_FACTOR`, when the rooms have an ``id``, ``name`` and ``height``) holds
    no floor up. ``rooms``: objects with ``polygon`` and ``level`` (a missing level is 0)."""
    rooms = list(rooms)
    through: set[str] = set()
    if all(hasattr(r, "id") and hasattr(r, "name") and hasattr(r, "height") for r in rooms):
        through = _through_ids((r.id, getattr(r, "level", 0) or 0, r.height, is_stairwell(r)) for r in rooms)
    by_level: dict[int, list] = {}
    holding: dict[int, list] = {}
    for r in rooms:
        k = getattr(r, "level", 0) or 0
        by_level.setdefault(k, []).append(r.polygon)
        if not through or r.id not in through:
            holding.setdefault(k, []).append(r.polygon)
    return sum((_outside_m2(by_level[k], holding.get(k - 1, [])) for k in by_level if k > 0), 0.0)


def _storey_spec(spec: HouseSpec, k: int, opts: FloorplanOptions) -> HouseSpec:
    """Storey ``k`` of ``spec`` as a house of its own: an upper storey or a basement gets a
    stand-in entrance through its stairwell (the stairs come in there; dropped after)."""
    ids = {r.id for r in spec.rooms if r.level == k}
    links = [c for c in spec.connections if c[0] in ids and (c[1] in ids or (k == 0 and c[1] == "outside"))]
    stair = stair_room(spec, k)
    if k != 0:
        links.append((stair, "outside"))
    long_m = stairwell_min_m(spec, k)[0]
    spare_m = opts.stairwell_spare_m if house_stair_kind(spec) != LADDER else 0.0  # a ladder's well: as narrow as planned
    least_m2 = round(long_m * (stair_hall_width_m(spec, k) + spare_m), 2)  # a tall storey's stair needs a longer well
    rooms = [r.model_copy(update={"area_m2": max(r.area_m2, least_m2)}) if r.id == stair else r
             for r in spec.rooms if r.level == k]
    return spec.model_copy(update={"rooms": rooms, "connections": links})


ONE_STOREY_NOTE = "could not stack the storeys"
"""Start of the floorplan's note when a house of several storeys was laid out on one."""


def _one_storey(spec: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None, why: str) -> Floorplan:
    """Every room on the ground floor, each stairwell joined to the one above it by a
    door: a valid house where the storeys would not stack (the pipeline warns)."""
    rooms = [r.model_copy(update={"level": 0}) for r in spec.rooms]
    numbers = sorted({r.level for r in spec.rooms})
    links = list(spec.connections)
    links += [(stair_room(spec, a), stair_room(spec, b)) for a, b in zip(numbers, numbers[1:])]
    flat = spec.model_copy(update={"rooms": rooms, "connections": links})
    plan = solve_floorplan(flat, rng, options)
    return plan.model_copy(update={"warnings": [*plan.warnings, f"{ONE_STOREY_NOTE} ({why}); every room is on the ground floor"]})


def _solve_storey(spec: HouseSpec, k: int, rng: np.random.Generator, options: FloorplanOptions | None,
                  wanted: int | None = None) -> Floorplan:
    """Storey ``k`` of ``spec`` laid out on its own: the best-scoring layout of one solver
    search whose stairwell holds the stair (:func:`_stair_fitted`, asked of each valid
    layout as the search finds it: one that fails is a failed attempt and the search goes
    on; ``wanted`` of them, None: ``storey_wanted_candidates``; 1 measured on dev_storeys,
    CPU median 1093 -> 428 ms with circulation and overhang as with the best of three
    valid layouts, the stair tested after; three that hold it: a five-storey house 5 ->
    15 s); the search is run again (at most ``level_attempts`` times) while none does.
    (An upper storey finding no place beside a room rising through it is searched again
    with ``wanted_candidates``, :func:`_stacked`.)"""
    stair = stair_room(spec, k)
    opts = options or FloorplanOptions()
    sub = _storey_spec(spec, k, opts)
    heights = storey_heights_m(spec)
    kind = house_stair_kind(spec)
    long_m, short_m = stairwell_min_m(spec, k)
    why = f"its stairwell never came out as a rectangle of at least {long_m:g} x {short_m:g} m for the stair"
    attempts = opts.level_attempts
    search = dataclasses.replace(opts, wanted_candidates=min(opts.wanted_candidates, wanted or opts.storey_wanted_candidates))
    search = _storey_search(search)
    narrow = _NARROW_HALLS.get()
    wide_m = short_m if narrow is not None and k in narrow else stair_hall_width_m(spec, k)
    refused = [0]

    def fitted(plan: Floorplan) -> Floorplan | None:
        out = _stair_fitted(plan, stair, k, heights, long_m, short_m, kind)
        refused[0] += out is None
        return out

    carved_found = _carved_storey(spec, k, sub, rng, search, heights, long_m, short_m, kind, opts)
    if carved_found is not None:
        return carved_found
    unsliced = _UNSLICED.get()
    for _ in range(attempts):
        refused[0] = 0
        sliced = 0 if unsliced is not None and k in unsliced else min(search.slicing_attempts, opts.storey_slicing_attempts)
        plain = dataclasses.replace(search, slicing_attempts=sliced)
        budget = ATTEMPT_BUDGET.get()
        used = budget.used if budget is not None else 0
        try:
            found = _candidates(sub, rng, plain, min_length_m={stair: long_m}, min_side_m={stair: wide_m},
                                stair_m={stair: flight_length_m(heights, k, kind)}, accept=fitted,
                                width_m=stair_width_m(kind))
        except FloorplanError as e:  # its own bounded tries all failed: trying again rarely helps
            if refused[0]:  # it did lay the storey out, the stair did not fit: search again
                continue
            if wide_m <= short_m:
                raise _Unsolvable(f"could not lay out level {k} ({e})") from None
            wide_m = short_m  # a hall as narrow as the stair, its doors where the flight leaves them reachable
            if narrow is not None:
                narrow.add(k)
            continue
        finally:
            if unsliced is not None and _slicing_spent(plain, budget, used):
                unsliced.add(k)
        return found[0]
    raise FloorplanError(f"could not lay out level {k} in {attempts} attempts ({why})")


def _slicing_spent(search: FloorplanOptions, budget: AttemptBudget | None, used: int) -> bool:
    """Whether a search with ``search`` options, begun when ``budget`` had ``used``
    attempts spent, went past its slicing attempts (found no layout in them)."""
    return budget is not None and search.slicing_attempts > 0 and budget.used - used > search.slicing_attempts


def _storey_search(opts: FloorplanOptions) -> FloorplanOptions:
    """``opts`` for a storey's search: the annealing and the force layout of the seeds
    stop once they no longer progress (``storey_anneal_patience_frac``,
    ``storey_seed_settled_cells``; one-storey houses keep the whole schedules)."""
    return dataclasses.replace(opts, anneal_patience_frac=min(opts.anneal_patience_frac, opts.storey_anneal_patience_frac),
                               seed_settled_cells=max(opts.seed_settled_cells, opts.storey_seed_settled_cells))


def _carved_storey(spec: HouseSpec, k: int, sub: HouseSpec, rng: np.random.Generator, search: FloorplanOptions,
                   heights: dict[int, float], long_m: float, short_m: float, kind: str,
                   opts: FloorplanOptions) -> Floorplan | None:
    """Storey ``k`` laid out with its stairwell carved from a corner of the one room it
    opens onto (:mod:`anyhome.floorplan.carve`), the stair fitted as :func:`_stair_fitted`
    fits it; None where the storey's stairwell opens onto no such room, or
    ``stair_carve_attempts`` searches found no layout that holds it (the caller then lays
    the storey out with a stairwell of its own)."""
    from anyhome.floorplan.carve import carve_room, carved, carved_spec

    uncarved = _UNCARVED.get()
    if opts.stair_carve_attempts == 0 or (uncarved is not None and k in uncarved):
        return None
    stair = stair_room(spec, k)
    bottom = min(r.level for r in spec.rooms)
    room = carve_room(sub, stair, _open_stair_types(k, bottom), stand_in=k != 0)
    if room is None or room in through_rooms(spec):
        return None
    well = next(r for r in spec.rooms if r.id == stair)
    carved_sub = carved_spec(sub, stair, room, _carved_m2(sub, room, long_m, short_m, opts))
    if _carve_hopeless(carved_sub, room, long_m, short_m, opts):
        return None

    def fitted(plan: Floorplan) -> Floorplan | None:
        for cand in carved(plan, well, room, long_m, short_m, opts.stair_carve_left_m):
            out = _stair_fitted(cand, stair, k, heights, long_m, short_m, kind)
            if out is not None:
                return out
        return None

    search = dataclasses.replace(search, max_attempts=min(search.max_attempts, opts.stair_carve_max_attempts))
    for _ in range(opts.stair_carve_attempts):
        try:
            return _candidates(carved_sub, rng, search, min_length_m={room: long_m},
                               min_side_m={room: short_m + opts.stair_carve_left_m}, accept=fitted,
                               width_m=stair_width_m(kind))[0]
        except FloorplanError:
            continue
    if uncarved is not None:
        uncarved.add(k)
    return None


def _carve_hopeless(carved_sub: HouseSpec, room: str, long_m: float, short_m: float, opts: FloorplanOptions) -> bool:
    """Whether the carve search of a storey (``carved_sub``, its stairwell of ``long_m`` x
    ``short_m`` in ``room``) is known to fail before it is run: a hallway only the spine
    lays out (:func:`_spine_hall`), a hallway with too many doors for the passage left
    beside the stair (:func:`~anyhome.floorplan.carve_fit.crowded_hall`), two rooms no
    rectangle cut once holds (:func:`~anyhome.floorplan.carve_fit.two_rooms_unfit`).
    ``stair_carve_hopeless_test`` 0: only the first (as before)."""
    if _spine_hall(carved_sub, room, opts):
        return True
    if not opts.stair_carve_hopeless_test:
        return False
    from anyhome.floorplan.carve_fit import crowded_hall, two_rooms_unfit

    return crowded_hall(carved_sub, room, opts) or two_rooms_unfit(carved_sub, room, long_m, short_m + opts.stair_carve_left_m, opts)


def _spine_hall(carved_sub: HouseSpec, room: str, opts: FloorplanOptions) -> bool:
    """Whether the carve search of a storey (``carved_sub``, its stairwell in ``room``) is
    known to fail: ``room`` is a hallway and the storey has more rooms than
    ``slicing_max_rooms``, so only the spine lays it out, which draws a hallway as deep as
    ``spine_hallway_min_m`` or its area over its length, not as wide as the stair and the
    passage beside it (measured on dev_storeys and dev_storeys2: 129 such searches, none
    found a layout, every attempt 'too narrow')."""
    r = next((x for x in carved_sub.rooms if x.id == room), None)
    return r is not None and r.type == "hallway" and len(carved_sub.rooms) > opts.slicing_max_rooms


def _carved_m2(sub: HouseSpec, room: str, long_m: float, short_m: float, opts: FloorplanOptions) -> float:
    """Floor the room ``room`` of the storey ``sub`` is planned larger by when its stairwell
    (``long_m`` x ``short_m``) is carved from it: the stairwell's; for a stair hall
    (``open_plan.yaml`` ``stair_hall``: an entry, a hallway) only what the stair and the
    passage kept beside it (``stair_carve_left_m``) need beyond the room's own area, as
    the hall doubles as the stairwell (measured: a maisonette's 11.7 m2 entrance hall
    beside a 6.5-11.5 m2 stairwell that opened onto it alone)."""
    from anyhome.floorplan.merge import open_plan_data

    r = next(x for x in sub.rooms if x.id == room)
    if r.type in open_plan_data().stair_hall:
        return round(max(0.0, long_m * (short_m + opts.stair_carve_left_m) - r.area_m2), 2)
    return round(long_m * short_m, 2)


def _candidates(sub: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None,
                width_m: float, **kw) -> list[Floorplan]:
    """:func:`~anyhome.floorplan.solver.floorplan_candidates` of the storey ``sub`` whose
    stair's box is ``width_m`` wide (the solver's door checks,
    :data:`~anyhome.floorplan.stairs.STAIR_WIDTH`)."""
    token = STAIR_WIDTH.set(width_m)
    try:
        return floorplan_candidates(sub, rng, options, **kw)
    finally:
        STAIR_WIDTH.reset(token)


def _stair_fitted(plan: Floorplan, stair: str, k: int, heights: dict[int, float], long_m: float,
                  short_m: float, kind: str = DOGLEG) -> Floorplan | None:
    """Storey ``k`` (``plan``, as the solver laid it out on its own) turned so its
    stairwell ``stair`` runs east-west, its stand-in entrance dropped (above or below the
    ground), with its stairwell's doors slid clear of the stair where needed
    (:func:`_doors_cleared`); None where the stairwell is not a rectangle of at least
    ``long_m`` x ``short_m`` or its stair has no place (:func:`stack_box`)."""
    if k != 0:
        plan = plan.model_copy(update={"doors": [d for d in plan.doors if "outside" not in d.rooms]})
    x0, y0, w, h = _rect(plan.room(stair))
    if w < h:
        plan = _turned(plan)
        x0, y0, w, h = _rect(plan.room(stair))
    if w < long_m - 1e-6 or h < short_m - 1e-6:
        return None
    if stack_box([(k, plan)], heights, kind) is not None:
        return plan
    for slid in _doors_cleared(plan, stair, flight_length_m(heights, k, kind), stair_width_m(kind)):  # only where the doors as laid out are in the way
        if stack_box([(k, slid)], heights, kind) is not None:
            return slid
    return None


def _doors_cleared(plan: Floorplan, stair: str, length_m: float, width_m: float = STAIR_WIDTH_M) -> list[Floorplan]:
    """Ways of ``plan`` whose stairwell ``stair`` (running east-west) holds a stair box
    ``length_m`` long by the stair's width against its far end wall, with the strip at
    its foot: for each of the four such boxes (against the south or the north wall, its
    foot toward the east or the west), the doors of the stairwell whose swing meets the
    box slid along their wall to the nearest place clear of it, where the wall is still
    shared with the same room and no other door is near. The boxes for which every door
    could be cleared, those needing the fewest moves first."""
    from shapely.geometry import Polygon, box

    x0, y0, w, h = _rect(plan.room(stair))
    if w < length_m + STRIP_M - 1e-6 or h < width_m - 1e-6:
        return []
    walls: dict[str, object] = {}  # room id -> its outline, buffered (built when a door of it is slid)

    def wall(room_id: str):
        if room_id not in walls:
            room = next((r for r in plan.rooms if r.id == room_id), None)
            walls[room_id] = None if room is None else Polygon(room.polygon).exterior.buffer(1e-6)
        return walls[room_id]

    out: list[tuple[int, Floorplan]] = []
    for ya in (y0, y0 + h - width_m):
        for xa in (x0, x0 + w - length_m):  # the box against the west (foot east) or the east end wall
            stair_box = box(xa, ya, xa + length_m, ya + width_m).buffer(STAIR_CLEAR_M)
            doors = list(plan.doors)
            moved = 0
            for i, d in enumerate(doors):
                if stair not in d.rooms or not _meets(d.segment, stair_box):
                    continue
                other = next((x for x in d.rooms if x != stair), "outside")
                seg = _clear_spot(d.segment, stair_box, (wall(stair), wall(other)), [e.segment for j, e in enumerate(doors) if j != i])
                if seg is None:
                    break
                doors[i] = d.model_copy(update={"segment": seg})
                moved += 1
            else:
                out.append((moved, plan.model_copy(update={"doors": doors})))
    return [p for _, p in sorted(out, key=lambda t: t[0])]


def _meets(segment, stair_box) -> bool:
    return bool(_door_zone(tuple(map(tuple, segment))).intersects(stair_box))


DOOR_SLIDE_M = 3.0
"""Farthest a stairwell's door is slid along its wall to clear the stair."""


def _clear_spot(segment, stair_box, walls: tuple, near: list) -> tuple | None:
    """``segment`` (a door) slid along its own line to the nearest place (5 cm steps, at
    most :data:`DOOR_SLIDE_M`) where its swing clears ``stair_box``, it still lies on both
    ``walls`` (the two rooms' outlines, buffered; None: outside, not moved) and no door
    of ``near`` is within 0.1 m; None: no such place. Every place is tested at once
    (shapely's array functions), each test only on the places the tests before it
    passed (:func:`~anyhome.floorplan.carve.first_passing`), the nearest that passes wins."""
    import shapely

    from anyhome.floorplan.carve import first_passing

    if any(w is None for w in walls):
        return None
    (ax, ay), (bx, by) = segment
    ux, uy = (1.0, 0.0) if abs(ay - by) < 1e-6 else (0.0, 1.0)
    shifts = [sign * i * SNAP_M for i in range(1, int(DOOR_SLIDE_M / SNAP_M) + 1) for sign in (1, -1)]
    segs = [((round(ax + ux * t, 6), round(ay + uy * t, 6)), (round(bx + ux * t, 6), round(by + uy * t, 6))) for t in shifts]
    ends = np.asarray(segs, dtype=float)  # (place, end, xy)
    lines = shapely.linestrings(ends)
    alive = np.arange(len(segs))

    def on(wall) -> Callable[[np.ndarray], np.ndarray]:
        return lambda idx: shapely.contains(wall, lines[idx])

    def clear_of(e) -> Callable[[np.ndarray], np.ndarray]:
        line = shapely.linestrings(np.asarray(e, dtype=float))
        return lambda idx: shapely.distance(line, lines[idx]) >= 0.1

    tests = [*(on(w) for w in walls), lambda idx: ~shapely.intersects(lines[idx], stair_box),
             lambda idx: ~shapely.intersects(_opening_zones(ends[idx]), stair_box), *(clear_of(e) for e in near)]
    first = first_passing(alive, tests)
    return None if first is None else segs[first]


def _opening_zones(ends: np.ndarray):
    """:func:`~anyhome.geometry.opening_zone` of every segment of ``ends`` (n, 2, 2), as
    an array of polygons (the same corners, computed the same way)."""
    import shapely

    from anyhome.geometry import segment_normal

    corners = np.empty((len(ends), 4, 2))
    for i, (a, b) in enumerate(ends):
        n = segment_normal((a, b)) * DOOR_CLEARANCE_M
        corners[i] = (a - n, b - n, b + n, a + n)
    return shapely.polygons(corners)


def _rect(room: Room) -> tuple[float, float, float, float]:
    """(x0, y0, width, height) of a room that is a rectangle; zeros if it is not."""
    xs = [p[0] for p in room.polygon]
    ys = [p[1] for p in room.polygon]
    if len(room.polygon) != 4:
        return (min(xs), min(ys), 0.0, 0.0)
    return (min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys))


def _map(plan: Floorplan, f) -> Floorplan:
    rooms = [r.model_copy(update={"polygon": [f(p) for p in r.polygon]}) for r in plan.rooms]
    doors = [d.model_copy(update={"segment": (f(d.segment[0]), f(d.segment[1]))}) for d in plan.doors]
    windows = [w.model_copy(update={"segment": (f(w.segment[0]), f(w.segment[1]))}) for w in plan.windows]
    return plan.model_copy(update={"rooms": rooms, "doors": doors, "windows": windows})


def _turned(plan: Floorplan) -> Floorplan:
    """A quarter turn counter-clockwise (outlines stay counter-clockwise)."""
    return _map(plan, lambda p: (-p[1], p[0]))


def _moved(plan: Floorplan, dx: float, dy: float) -> Floorplan:
    return _map(plan, lambda p: (p[0] + dx, p[1] + dy))


def _stairwells(plans: list[tuple[int, Floorplan]]) -> list[tuple[int, Room, list[Door]]]:
    """The stairwell of every storey ``k`` of ``plans`` (laid out in one frame: the first
    room of that storey named like a stair, as :func:`stair_room`) with its doors."""
    out = []
    for k, plan in plans:
        r = next((r for r in plan.rooms if is_stairwell(r) and (r.level == k or not any(x.level for x in plan.rooms))), None)
        if r is not None:
            out.append((k, r, [dr for dr in plan.doors if r.id in dr.rooms]))
    return out


def stack_box(plans: list[tuple[int, Floorplan]], heights: dict[int, float],
              kind: str = DOGLEG) -> tuple[float, float, float] | None:
    """(foot_x, y0, yaw) of the stairs: every flight stands against one long wall of
    every stairwell, on the strip ``y0`` to ``y0`` + the flights' width, its foot end (local
    +x, turned by ``yaw``) at ``foot_x``, with the strip of floor at the foot
    (:data:`~anyhome.floorplan.stairs.STRIP_M`) beyond it; the stairwell of storey ``k``
    (``plans``: (k, its storey laid out in one frame)) holds the box of the flights that
    start or arrive there (:func:`flight_length_m` of stairs of ``kind``, ``heights``:
    each storey's floor-to-floor height) and that strip, the box touching no door of it nor its swing
    (:data:`~anyhome.floorplan.stairs.STAIR_CLEAR_M` apart). Feet are tried on the 5 cm
    grid from the walls in; None: no place."""
    from shapely.geometry import LineString

    wells = _stairwells(plans)
    if not wells:
        return None
    rects = {k: _rect(r) for k, r, _ in wells}
    if any(w <= 0 for _, _, w, _ in rects.values()):
        return None
    width = stair_width_m(kind)
    lengths = {k: flight_length_m(heights, k, kind) for k in rects}
    y0, y1 = max(r[1] for r in rects.values()), min(r[1] + r[3] for r in rects.values())
    if y1 - y0 < width - 1e-6:
        return None
    zones = {k: [_door_zone(dr.segment) for dr in doors] for k, _, doors in wells}
    east_lo = max(r[0] + lengths[k] for k, r in rects.items())  # foot toward +x: the box west of it
    east_hi = min(r[0] + r[2] for r in rects.values()) - STRIP_M
    west_lo = max(r[0] for r in rects.values()) + STRIP_M  # foot toward -x: the box east of it
    west_hi = min(r[0] + r[2] - lengths[k] for k, r in rects.items())
    tries = [(east_lo + i * SNAP_M, 0.0) for i in range(int((east_hi - east_lo) / SNAP_M + 1e-6) + 1)] if east_hi >= east_lo - 1e-6 else []
    tries += [(west_hi - i * SNAP_M, math.pi) for i in range(int((west_hi - west_lo) / SNAP_M + 1e-6) + 1)] if west_hi >= west_lo - 1e-6 else []
    door_segments = {k: [LineString(dr.segment) for dr in doors] for k, _, doors in wells}
    for ya in (y0, y1 - width):
        clear = _clear_of_doors(tries, ya, width, lengths, zones)  # the cheap test, every foot at once
        for i, (foot, yaw) in enumerate(tries):
            if clear[i] and all(doors_joined(rects[k], flight_rect(foot, ya, lengths[k], width, yaw), door_segments[k])
                                for k in rects):
                return (round(foot, 6), round(ya, 6), yaw)
    return None


@functools.lru_cache(maxsize=4096)
def _door_zone(segment: tuple) -> BaseGeometry:
    """A door's swing and its line (:func:`~anyhome.geometry.opening_zone`), as
    :func:`stack_box` tests the stair's box against it: built once per door segment (the
    storeys below are tested again at every place of the storey above)."""
    from shapely.geometry import LineString

    return opening_zone(segment).union(LineString(segment))


def _clear_of_doors(tries: list[tuple[float, float]], ya: float, width: float, lengths: dict[int, float],
                    zones: dict[int, list]) -> np.ndarray:
    """For each (foot, yaw) of ``tries``: whether the flight box of every storey ``k``
    (``lengths[k]`` long, on the strip ``ya`` to ``ya`` + ``width``), grown by
    :data:`~anyhome.floorplan.stairs.STAIR_CLEAR_M`, meets none of that storey's door
    ``zones`` (:func:`stack_box`'s first test, as :func:`flight_rect` draws the box). The
    rounded grown box is built only where the box grown square (which holds it) meets a
    zone: the same answer, without most of the buffers."""
    import shapely

    ok = np.ones(len(tries), dtype=bool)
    if not tries:
        return ok
    foot = np.array([f for f, _ in tries])
    east = np.array([abs(yaw) < 1e-9 for _, yaw in tries])  # yaw 0: the foot toward +x, the box west of it
    for k, length in lengths.items():
        if not zones.get(k):
            continue
        x0 = np.where(east, foot - length, foot)
        x1 = np.where(east, foot, foot + length)
        reach = STAIR_CLEAR_M + 1e-9  # the grown box lies inside the box grown square by this
        near = np.zeros(len(tries), dtype=bool)
        for z in zones[k]:
            near |= shapely.intersects(shapely.box(x0 - reach, ya - reach, x1 + reach, ya + width + reach), z)
        idx = np.flatnonzero(near & ok)  # only these can meet a zone: their rounded boxes are built and tested
        if not len(idx):
            continue
        grown = shapely.buffer(shapely.box(x0[idx], ya, x1[idx], ya + width), STAIR_CLEAR_M, quad_segs=16)
        for z in zones[k]:
            ok[idx] &= ~shapely.intersects(grown, z)
    return ok


def _joined(spec: HouseSpec, plans: dict[int, Floorplan], levels: list[Level]) -> Floorplan:
    by_id = {r.id: r for p in plans.values() for r in p.rooms}
    rooms = [by_id[r.id].model_copy(update={"level": r.level}) for r in spec.rooms]
    doors: list[Door] = []
    windows: list[Window] = []
    for k in sorted(plans):
        doors += [d.model_copy(update={"id": f"door-{len(doors) + i}"}) for i, d in enumerate(plans[k].doors)]
        windows += [w.model_copy(update={"id": f"win-{len(windows) + i}"}) for i, w in enumerate(plans[k].windows)]
    return Floorplan(rooms=rooms, doors=doors, windows=windows, connections=list(spec.connections), levels=levels)


def stairs_objects(plan: Floorplan) -> list[HouseObject]:
    """One stair per pair of storeys, in the lower stairwell, rising to the upper
    storey's floor (its height is the difference of the two elevations); all of them
    with their foot at the same place (:func:`stack_box`), storey over storey: a dog-leg,
    or in a small house (:func:`plan_stair_kind`) a spiral stair of one full turn named
    :data:`~anyhome.floorplan.stairs.SPIRAL_NAME` in a square box. Its ``position`` is,
    as for every object, relative to its room's floor."""
    if not plan.levels:
        return []
    numbers = [lv.level for lv in plan.levels]
    if len(numbers) < 2:
        return []
    elev = {lv.level: lv.elevation_m for lv in plan.levels}
    foot, ya, yaw = _stairs_place(plan)
    kind = plan_stair_kind(plan)
    width = stair_width_m(kind)
    out = []
    for lo, hi in zip(numbers, numbers[1:]):
        low = _stairwell(plan, lo)
        rise_m = elev[hi] - elev[lo]
        xa, _, xb, _ = flight_rect(foot, ya, stair_length_m(kind, rise_m), width, yaw).bounds
        if kind == LADDER:
            n = ladder_risers(rise_m)
            name, text = LADDER_NAME, (f"a ship's ladder (alternating treads) from level {lo} up to level {hi}: "
                                       f"{n} risers of {rise_m / n:.3f} m, arriving at its far end")
        elif kind == SPIRAL:
            n = spiral_risers(rise_m)
            name, text = SPIRAL_NAME, (f"a spiral stair from level {lo} up to level {hi}: one full turn in "
                                       f"{n} risers of {rise_m / n:.3f} m, arriving over its foot")
        else:
            d = dogleg(rise_m)
            name, text = "stairs", (f"a dog-leg stair from level {lo} up to level {hi}: {d.risers} risers of "
                                    f"{d.riser_m:.3f} m, goings of {d.going_m:.2f} m, a half landing")
        out.append(HouseObject(
            id=f"{low.id}-stairs", room=low.id, name=name, category=STAIRS_CATEGORY,
            description=text,
            position=(round((xa + xb) / 2, 4), round(ya + width / 2, 4), 0.0),
            size=(round(xb - xa, 4), width, round(rise_m, 4)),
            yaw=yaw, rule="place_wall", tags=["equipment"],
        ))
    return out


def stair_zones(plan: Floorplan) -> dict[str, list[np.ndarray]]:
    """Room id -> the floor the stairs keep: every flight's box with the strip at its foot
    (:data:`~anyhome.floorplan.stairs.STRIP_M`, where it starts and the flight below
    arrives), as 4 corners, in the room the flight stands in and in every room of the
    storey above over it (the open well it climbs through, the floor it arrives on).
    The layout keeps its objects off them as off a door's swing (about 0.5 ms a call
    for a townhouse: asked once per room, not memoised)."""
    out: dict[str, list[np.ndarray]] = {}
    if len(plan.levels) >= 2:
        from shapely.geometry import Polygon, box

        by_id = {r.id: r for r in plan.rooms}
        for o in stairs_objects(plan):
            x0, y0, x1, y1 = _flight_box(o).bounds
            if o.yaw == 0.0:  # the foot end at +x, turned by the yaw (0 or pi: stack_box)
                zone = box(x0, y0, x1 + STRIP_M, y1)
            else:
                zone = box(x0 - STRIP_M, y0, x1, y1)
            corners = np.asarray(zone.exterior.coords)[:4]
            level = by_id[o.room].level
            for r in plan.rooms:
                if r.id == o.room or (r.level == level + 1 and Polygon(r.polygon).intersection(zone).area > 1e-6):
                    out.setdefault(r.id, []).append(corners)
            own = by_id[o.room]
            if len(own.polygon) > 6 and any(says_stair(m) for m in own.merged):  # a stair in an alcove
                out[own.id].extend(_passage_bands(own, zone))
    return out


def _passage_bands(room: Room, zone) -> list[np.ndarray]:
    """The bands :data:`~anyhome.floorplan.stairs.PASSAGE_M` deep along either long side
    of ``zone`` (a flight and the strip at its foot) that lie in ``room``: the way into an
    alcove holding a stair, walked in front of the flight to its foot
    (:func:`_alcove_passage`)."""
    from shapely.geometry import Polygon, box

    poly = Polygon(room.polygon)
    x0, y0, x1, y1 = zone.bounds
    bands = (box(x0, y1, x1, y1 + PASSAGE_M), box(x0, y0 - PASSAGE_M, x1, y0))
    return [np.asarray(b.exterior.coords)[:4] for b in bands if poly.intersection(b).area >= 0.95 * b.area]


def _stairwell(plan: Floorplan, level: int) -> Room:
    """The room of storey ``level`` the stairs stand in: its stairwell, or the room a
    stairwell was merged into (:func:`stairs_opened`)."""
    for r in plan.rooms:
        if r.level == level and (is_stairwell(r) or any(says_stair(m) for m in r.merged)):
            return r
    raise FloorplanError(f"level {level} has no stairwell room")


def stair_link(plan: Floorplan, obj: HouseObject) -> tuple[str, str] | None:
    """The two rooms a ``stairs`` object joins: its own and the room of the next storey
    up over its top end (None: not stairs, or nothing above)."""
    if obj.category != STAIRS_CATEGORY:
        return None
    from shapely.geometry import Point, Polygon

    here = next((r for r in plan.rooms if r.id == obj.room), None)
    if here is None:
        return None
    above = sorted(lv.level for lv in plan.levels if lv.level > here.level)
    if not above:
        return None
    x, y, _ = obj.position
    c, s = math.cos(obj.yaw), math.sin(obj.yaw)
    if obj.name == SPIRAL_NAME:  # a spiral turns once round: it ends over its foot end
        lx, ly = obj.size[0] / 2 - 0.1, 0.0
    elif obj.name == LADDER_NAME:  # a ladder rises toward its local -x, onto the floor at its top end
        lx, ly = -(obj.size[0] / 2 - 0.1), 0.0
    elif is_dogleg_box(obj.size[0], obj.size[1]):  # a dog-leg ends at its foot end, on its +y half
        lx, ly = obj.size[0] / 2 - 0.1, obj.size[1] / 4
    else:  # a straight flight rises toward its local -x
        lx, ly = -(obj.size[0] / 2 - 0.1), 0.0
    top = Point(x + c * lx - s * ly, y + s * lx + c * ly)
    for r in plan.rooms:
        if r.level == above[0] and Polygon(r.polygon).buffer(1e-6).contains(top):
            return (here.id, r.id)
    return None


def level_view(house, level: int):
    """The storey ``level`` of ``house`` as a house of its own: its rooms, the doors and
    windows of those rooms, their objects (the checks of one storey run on it)."""
    ids = {r.id for r in house.rooms if r.level == level}
    return house.model_copy(update={
        "rooms": [r for r in house.rooms if r.id in ids],
        "doors": [d for d in house.doors if all(x in ids or x == "outside" for x in d.rooms)],
        "windows": [w for w in house.windows if w.room in ids],
        "objects": [o for o in house.objects if o.room in ids],
        "connections": [c for c in house.connections if all(x in ids or x == "outside" for x in c)],
    })


def reachable_rooms(house) -> set[str]:
    """Rooms reachable from the outside through doors and stairs (:func:`stair_link`)."""
    adj: dict[str, set[str]] = {}
    links = [tuple(d.rooms) for d in house.doors]
    links += [lk for o in house.objects if (lk := stair_link(house.floorplan, o)) is not None]
    for a, b in links:
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    seen = {"outside"}
    todo = ["outside"]
    while todo:
        for nxt in adj.get(todo.pop(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen - {"outside"}
