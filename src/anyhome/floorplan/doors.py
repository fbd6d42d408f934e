"""Doors: one per planned connection on a wall the two rooms share, plus the entrance.

Each door goes near one end of its shared wall run (keeping the rest of the wall free
for furniture) or in its middle, whichever keeps its keep-clear zone away from the
other doors of its rooms. Living, dining and kitchen pairs get a wide opening.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

import numpy as np

from anyhome.floorplan.grid import OUTSIDE
from anyhome.floorplan.openings import Opening, run_bounds_m, snap_down_m, snap_m
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.walls import Run, runs_between
from anyhome.geometry import DOOR_CLEARANCE_M

DOOR_WIDTH_M = 0.9
"""Width of an interior door."""
ENTRANCE_WIDTH_M = 1.0
"""Width of the entrance door."""
OPEN_TYPES = frozenset({"living_room", "dining_room", "kitchen"})
"""Room types whose pairs are joined by a wide opening instead of a door."""


DoorKind = Literal["door", "open"]


@dataclass(frozen=True)
class PlacedDoor:
    """A door between room indices ``rooms`` (the second may be OUTSIDE)."""

    rooms: tuple[int, int]
    opening: Opening
    kind: DoorKind = "door"


def door_kind(type_a: str, type_b: str | None) -> DoorKind:
    return "open" if type_a in OPEN_TYPES and type_b in OPEN_TYPES else "door"


def place_door(
    rooms: tuple[int, int],
    kind: DoorKind,
    runs: list[Run],
    cell_m: float,
    placed: list[PlacedDoor],
    rng: np.random.Generator,
    opts: FloorplanOptions,
    penalty: Callable[[Opening], float] | None = None,
) -> PlacedDoor | None:
    """Best door for ``rooms`` on a run they share, or None if no run fits one
    (margins, gaps and scores from ``opts``)."""
    best, best_score = None, float("inf")
    for run in runs_between(runs, *rooms):
        for opening, this_kind, extra in _candidates(run, kind, rooms[1] == OUTSIDE, cell_m, opts):
            if any(opening.gap_to(d.opening) < opts.door_gap_m for d in placed):
                continue
            score = extra + _zone_score(opening, rooms, placed) + opts.door_noise * rng.random()
            if penalty is not None:
                score += penalty(opening)
            if score < best_score:
                best, best_score = PlacedDoor(rooms, opening, this_kind), score
    return best


def _candidates(run: Run, kind: str, entrance: bool, cell_m: float, opts: FloorplanOptions):
    """(opening, kind, score) candidates on one run: near either end and centred."""
    line, start, end = run_bounds_m(run, cell_m)
    margin = opts.door_end_margin_m
    free = end - start - 2 * margin
    width = ENTRANCE_WIDTH_M if entrance else DOOR_WIDTH_M
    if kind == "open" and free >= opts.open_min_width_m - 1e-9:
        width = min(opts.open_max_width_m, snap_down_m(free))
        lo = snap_m(start + (end - start - width) / 2)
        return [(Opening(run.axis, line, lo, round(lo + width, 4)), "open", 0.0)]
    if free < width - 1e-9:
        return []
    out = []
    for lo, extra in (
        (start + margin, 0.0),
        (end - margin - width, 0.0),
        (snap_m(start + (end - start - width) / 2), 0.0 if entrance else opts.door_center_penalty),
    ):
        lo = round(lo, 4)
        out.append((Opening(run.axis, line, lo, round(lo + width, 4)), "door", extra))
    return out


def _zone_score(opening: Opening, rooms: tuple[int, int], placed: list[PlacedDoor]) -> float:
    """Overlap (m2) of this door's keep-clear zone with those of its rooms' other doors."""
    total = 0.0
    for d in placed:
        if set(d.rooms) & set(rooms) - {OUTSIDE}:
            total += opening.zone_overlap_m2(d.opening, DOOR_CLEARANCE_M)
    return total
