"""Local moves on a slicing tree: nudge cuts until connections share enough wall.

The cost adds up what the hard checks later reject (shared walls shorter than a door
needs, rooms off their area, too thin or too long, exterior walls too short for a
window), all computed on the leaf rectangles, so a move costs microseconds. Hill
climbing takes the best single-cut nudge per round, for a bounded number of rounds.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.slicing import Cut, Rect, shared_wall_cells, tree_cuts, tree_rects


@dataclass(frozen=True)
class TuneRooms:
    """Per leaf index: target cells, min side and flags (the void has target 0); the
    search's options (the cost's weights and thresholds)."""

    target_cells: np.ndarray
    min_side_m: np.ndarray
    corridor: np.ndarray
    exterior: np.ndarray
    void: int | None
    edges: tuple[tuple[int, int], ...]
    cell_m: float
    opts: FloorplanOptions
    max_aspect: np.ndarray
    """Longest/shortest side each room may have (inf for corridors and the void)."""
    min_long_m: np.ndarray | None = None
    """Shortest long side each room may have (0: any; a stairwell holds its stair)."""
    void_sides: int = 2
    """Outline sides the void must touch: 2 (a corner: free, the slicing placed it) or 1
    (the notch of a U: a void touching another number of sides costs)."""

    @functools.cached_property
    def room_costs(self) -> dict[tuple[int, Rect], float]:
        """(room, rectangle) -> :func:`_room_cost`, worked out once: the annealing and the
        nudges come back to the same rectangles of most rooms at every move."""
        return {}

    @functools.cached_property
    def lists(self) -> _RoomLists:
        """The per-room arrays as Python lists (the costs read them per room, per move:
        a list is read faster than an array, and the numbers are the same)."""
        return _RoomLists(
            self.target_cells.tolist(), self.min_side_m.tolist(), self.corridor.tolist(), self.max_aspect.tolist(),
            None if self.min_long_m is None else self.min_long_m.tolist(), np.flatnonzero(self.exterior).tolist())


@dataclass(frozen=True)
class _RoomLists:
    """:class:`TuneRooms`' per-room arrays as lists; ``exterior``: the indices of the
    rooms that need an exterior wall."""

    target_cells: list[float]
    min_side_m: list[float]
    corridor: list[bool]
    max_aspect: list[float]
    min_long_m: list[float] | None
    exterior: list[int]


def tune_tree(tree: Cut | int, rect: Rect, rooms: TuneRooms) -> float:
    """Improve the tree's cut positions in place; return the final cost."""
    opts = rooms.opts
    nudges = [d for d in range(-opts.tune_nudge_max_cells, opts.tune_nudge_max_cells + 1) if d]
    cost = layout_cost(tree_rects(tree, rect), rect, rooms)
    for _ in range(opts.tune_rounds):
        if cost < 1e-9:
            break
        best = None
        for cut in tree_cuts(tree):
            start = cut.at
            for d in nudges:
                cut.at = start + d
                c = layout_cost(tree_rects(tree, rect), rect, rooms)
                if c < cost - 1e-9:
                    cost, best = c, (cut, start + d)
            cut.at = start
        if best is None:
            break
        best[0].at = best[1]
    return cost


def layout_cost(rects: dict[int, Rect], outer: Rect, rooms: TuneRooms) -> float:
    """Hard-rule violations of the leaf rectangles (0 when none)."""
    opts = rooms.opts
    cost = 0.0
    known = rooms.room_costs
    for k, r in rects.items():
        if r[2] <= r[0] or r[3] <= r[1]:
            return np.inf
        if k != rooms.void:
            c = known.get((k, r))
            if c is None:
                c = known[(k, r)] = _room_cost(k, r, rooms)
            cost += c
    for i, j in rooms.edges:
        shared = shared_wall_cells(rects[i], rects[j]) * rooms.cell_m
        if shared < opts.shared_wall_min_m:
            cost += opts.tune_violation_weight * (opts.shared_wall_min_m - shared) + opts.tune_gap_weight * _gap(rects[i], rects[j]) * rooms.cell_m
    if rooms.void is not None and rooms.void_sides == 1:
        v = rects[rooms.void]
        sides = (v[0] == outer[0]) + (v[2] == outer[2]) + (v[1] == outer[1]) + (v[3] == outer[3])
        cost += opts.tune_violation_weight * abs(int(sides) - 1)
    for k in rooms.lists.exterior:
        ext = _exterior(rects[k], outer, rects.get(rooms.void) if rooms.void is not None else None) * rooms.cell_m
        cost += opts.tune_violation_weight * max(0.0, opts.exterior_wall_min_m - ext)
    return cost


def _room_cost(k: int, r: Rect, rooms: TuneRooms) -> float:
    opts = rooms.opts
    lists = rooms.lists
    w, h = (r[2] - r[0]) * rooms.cell_m, (r[3] - r[1]) * rooms.cell_m
    err = abs((r[2] - r[0]) * (r[3] - r[1]) / lists.target_cells[k] - 1.0)
    cost = opts.tune_violation_weight * max(0.0, err - opts.tune_area_slack_frac)
    cost += opts.tune_violation_weight * max(0.0, lists.min_side_m[k] - min(w, h))
    if lists.min_long_m is not None:
        cost += opts.tune_violation_weight * max(0.0, lists.min_long_m[k] - max(w, h))
    if not lists.corridor[k]:
        cost += opts.tune_aspect_weight * max(0.0, max(w, h) / min(w, h) - lists.max_aspect[k])
    return cost


def _gap(a: Rect, b: Rect) -> int:
    """Manhattan gap (cells) between two rectangles (0 if they touch)."""
    return max(0, a[0] - b[2], b[0] - a[2]) + max(0, a[1] - b[3], b[1] - a[3])


def _exterior(r: Rect, outer: Rect, void: Rect | None) -> int:
    """Length (cells) of a rectangle's walls on the footprint's outline."""
    w, h = r[2] - r[0], r[3] - r[1]
    length = (r[0] == outer[0]) * h + (r[2] == outer[2]) * h
    length += (r[1] == outer[1]) * w + (r[3] == outer[3]) * w
    return length + (shared_wall_cells(r, void) if void is not None else 0)
