"""Recursive slicing of the footprint into room rectangles, guided by seed positions.

Each step cuts a rectangle in two along x or y; the rooms on each side are a prefix
and suffix of the rooms sorted by their seed position along that axis, the cut sits
where the two sides' target areas put it. Of all cuts the one with the best score is
taken: squarish single rooms, few bubble-diagram edges across the cut, enough
exterior wall for the rooms that need one; a little noise keeps layouts diverse.
An L-shaped footprint is a rectangle whose *void* pseudo-room must land in a corner.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

CUT_EDGE_COST = 0.6
"""Score per bubble-diagram edge crossing a cut."""
INFEASIBLE_COST = 10.0
"""Score of a part that breaks a hard rule (too thin, no exterior wall...)."""
EXTERIOR_PER_ROOM_M = 2.2
"""Exterior wall a part needs per room that must touch the outside."""
SPLIT_NOISE = 0.35
"""Scale of the random score noise that varies layouts across seeds."""
ROOM_ASPECT_SOFT = 1.5
"""Aspect above which a single room's shape starts to cost."""
ROOM_ASPECT_MAX = 2.5
"""Aspect above which a room (not a corridor) is infeasible."""
PART_ASPECT_SOFT = 3.0
"""Aspect above which a multi-room part starts to cost."""

Rect = tuple[int, int, int, int]
"""(x0, y0, x1, y1) in cells, unpadded."""
Ext = tuple[bool, bool, bool, bool]
"""Whether a part's (left, right, bottom, top) side is on the footprint's exterior."""


@dataclass(frozen=True)
class SliceRooms:
    """What the slicer knows about the rooms (index ``n`` may be the void)."""

    cells: np.ndarray
    min_side: np.ndarray
    corridor: np.ndarray
    exterior: np.ndarray
    void: int | None
    pos: np.ndarray
    edges: frozenset[tuple[int, int]]
    cell_m: float


def slice_footprint(rect: Rect, rooms: SliceRooms, rng: np.random.Generator) -> dict[int, Rect]:
    """Rectangle per room (and the void) tiling ``rect``."""
    out: dict[int, Rect] = {}
    _slice(rect, list(range(len(rooms.cells))), (True, True, True, True), rooms, rng, out)
    return out


def _slice(rect: Rect, ids: list[int], ext: Ext, rooms: SliceRooms, rng, out: dict[int, Rect]) -> None:
    if len(ids) == 1:
        out[ids[0]] = rect
        return
    best, best_score = None, np.inf
    for axis in (0, 1):
        order = sorted(ids, key=lambda k: rooms.pos[k, axis])
        for i in range(1, len(order)):
            cut = _cut(rect, order[:i], order, axis, rooms)
            if cut is None:
                continue
            parts = _parts(rect, ext, axis, cut, order[:i], order[i:])
            score = _cut_score(parts, rooms) + SPLIT_NOISE * rng.random()
            if score < best_score:
                best, best_score = parts, score
    if best is None:
        best = _parts(rect, ext, 0, rect[0] + 1, ids[:1], ids[1:])  # degenerate: let checks reject
    for part_rect, part_ids, part_ext in best:
        _slice(part_rect, part_ids, part_ext, rooms, rng, out)


def _cut(rect: Rect, first: list[int], ids: list[int], axis: int, rooms: SliceRooms) -> int | None:
    lo, hi = (rect[0], rect[2]) if axis == 0 else (rect[1], rect[3])
    frac = rooms.cells[first].sum() / rooms.cells[ids].sum()
    cut = lo + int(round(frac * (hi - lo)))
    return cut if lo < cut < hi else None


def _parts(rect: Rect, ext: Ext, axis: int, cut: int, a: list[int], b: list[int]):
    x0, y0, x1, y1 = rect
    left, right, bottom, top = ext
    if axis == 0:
        return ((x0, y0, cut, y1), a, (left, False, bottom, top)), ((cut, y0, x1, y1), b, (False, right, bottom, top))
    return ((x0, y0, x1, cut), a, (left, right, bottom, False)), ((x0, cut, x1, y1), b, (left, right, False, top))


def _cut_score(parts, rooms: SliceRooms) -> float:
    a_ids, b_ids = set(parts[0][1]), set(parts[1][1])
    crossing = sum(1 for i, j in rooms.edges if (i in a_ids and j in b_ids) or (i in b_ids and j in a_ids))
    return CUT_EDGE_COST * crossing + sum(_part_score(r, ids, ext, rooms) for r, ids, ext in parts)


def _part_score(rect: Rect, ids: list[int], ext: Ext, rooms: SliceRooms) -> float:
    w_m = (rect[2] - rect[0]) * rooms.cell_m
    h_m = (rect[3] - rect[1]) * rooms.cell_m
    short, long_ = min(w_m, h_m), max(w_m, h_m)
    score = _exterior_score(ids, ext, w_m, h_m, rooms)
    if len(ids) == 1:
        return score + _room_shape_score(ids[0], short, long_, ext, rooms)
    if short < rooms.min_side[ids].min() - 1e-6:
        score += INFEASIBLE_COST
    return score + 0.3 * max(0.0, long_ / short - PART_ASPECT_SOFT)


def _room_shape_score(k: int, short: float, long_: float, ext: Ext, rooms: SliceRooms) -> float:
    if k == rooms.void:
        corner = (ext[0] or ext[1]) and (ext[2] or ext[3])
        return 0.0 if corner else INFEASIBLE_COST
    score = INFEASIBLE_COST if short < rooms.min_side[k] - 1e-6 else 0.0
    if rooms.corridor[k]:
        return score
    aspect = long_ / short
    if aspect > ROOM_ASPECT_MAX:
        score += INFEASIBLE_COST
    return score + max(0.0, aspect - ROOM_ASPECT_SOFT)


def _exterior_score(ids: list[int], ext: Ext, w_m: float, h_m: float, rooms: SliceRooms) -> float:
    need = int(rooms.exterior[ids].sum())
    if need == 0:
        return 0.0
    have = (ext[0] + ext[1]) * h_m + (ext[2] + ext[3]) * w_m
    if have == 0:
        return INFEASIBLE_COST * need
    return 2.0 * max(0.0, need * EXTERIOR_PER_ROOM_M - have) / EXTERIOR_PER_ROOM_M
