"""Recursive slicing of the footprint into room rectangles, guided by seed positions.

Each step cuts a rectangle in two along x or y; the rooms on each side are a prefix
and suffix of the rooms sorted by their seed position along that axis, the cut sits
where the two sides' target areas put it. Of all cuts the one with the best score is
taken: squarish single rooms, few bubble-diagram edges across the cut, enough
exterior wall for the rooms that need one; a little noise keeps layouts diverse.
An L-shaped footprint is a rectangle whose *void* pseudo-room must land in a corner; a
U-shaped one a rectangle whose void must touch one side of it only (a notch in its middle).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from anyhome.floorplan.options import FloorplanOptions

Rect = tuple[int, int, int, int]
"""(x0, y0, x1, y1) in cells, unpadded."""
Ext = tuple[bool, bool, bool, bool]
"""Whether a part's (left, right, bottom, top) side is on the footprint's exterior."""
Ports = dict[int, frozenset[int]]
"""Sides (0 left, 1 right, 2 bottom, 3 top) of its part a room must touch for a door."""
Part = tuple[Rect, list[int], Ext, Ports]
"""One side of a cut: its rectangle, rooms, exterior sides and ports."""


@dataclass(frozen=True)
class SliceRooms:
    """What the slicer knows about the rooms (index ``n`` may be the void), and the
    search's options (the score's weights)."""

    cells: np.ndarray
    min_side: np.ndarray
    corridor: np.ndarray
    exterior: np.ndarray
    void: int | None
    pos: np.ndarray
    edges: frozenset[tuple[int, int]]
    cell_m: float
    opts: FloorplanOptions
    max_aspect: np.ndarray
    """Longest/shortest side each room may have (inf for corridors and the void)."""
    void_sides: int = 2
    """Outline sides the void must touch: 2 (a corner, an L) or 1 (a notch, a U)."""
    min_long: np.ndarray | None = None
    """Shortest long side (m) each room may have (0: any; a stairwell: its stair)."""

    @functools.cached_property
    def greedy(self) -> dict[tuple, tuple[tuple[int, Rect], ...]]:
        """A part (rect, rooms, exterior sides, ports in their order) -> its rooms'
        rectangles cut greedily (:func:`_greedy_rects`), in the order found."""
        return {}

    @functools.cached_property
    def lists(self) -> _SliceLists:
        """The per-room arrays as Python lists (the scores read them per room, per cut:
        a list is read faster than an array, and the numbers are the same)."""
        return _SliceLists(self.min_side.tolist(), self.corridor.tolist(), self.exterior.tolist(),
                           self.max_aspect.tolist(), None if self.min_long is None else self.min_long.tolist(),
                           self.pos.tolist())


@dataclass(frozen=True)
class _SliceLists:
    """:class:`SliceRooms`' per-room arrays as lists (``pos``: one [x, y] per room)."""

    min_side: list[float]
    corridor: list[bool]
    exterior: list[bool]
    max_aspect: list[float]
    min_long: list[float] | None
    pos: list[list[float]]


@dataclass
class Cut:
    """An inner node of the slicing tree: a cut at ``at`` cells across ``axis``."""

    axis: int
    at: int
    low: Cut | int
    high: Cut | int


def slice_footprint(rect: Rect, rooms: SliceRooms, rng: np.random.Generator) -> Cut | int:
    """Slicing tree (leaves are room indices, the void included) tiling ``rect``."""
    return _slice(rect, list(range(len(rooms.cells))), (True, True, True, True), {}, rooms, rng)


def tree_rects(tree: Cut | int, rect: Rect, out: dict[int, Rect] | None = None) -> dict[int, Rect]:
    """Rectangle of every leaf; an empty or inverted rectangle means the tree is invalid."""
    out = {} if out is None else out
    if isinstance(tree, int):
        out[tree] = rect
        return out
    x0, y0, x1, y1 = rect
    if tree.axis == 0:
        low, high = (x0, y0, tree.at, y1), (tree.at, y0, x1, y1)
    else:
        low, high = (x0, y0, x1, tree.at), (x0, tree.at, x1, y1)
    tree_rects(tree.low, low, out)
    return tree_rects(tree.high, high, out)


def tree_cuts(tree: Cut | int) -> list[Cut]:
    return [] if isinstance(tree, int) else [tree, *tree_cuts(tree.low), *tree_cuts(tree.high)]


def _slice(rect: Rect, ids: list[int], ext: Ext, ports: Ports, rooms: SliceRooms, rng) -> Cut | int:
    """Cut ``rect`` recursively; ``ports`` maps a room to the sides it must touch.

    The ``opts.slice_lookahead`` best cuts by their immediate score are completed greedily and
    the one whose completed layout scores best (plus noise) is taken.
    """
    if len(ids) == 1:
        return ids[0]
    ranked = _ranked_cuts(rect, ids, ext, ports, rooms, rng)
    if not ranked:  # a part too small to cut: let the room checks reject it
        ranked = [(0.0, _parts(rect, ext, ports, 0, rect[0] + 1, ids[:1], ids[1:], rooms.edges))]
    opts = rooms.opts
    best = min(
        ranked[:opts.slice_lookahead],
        key=lambda c: _completed_cost(c[1], rooms) + opts.slice_noise * rng.random(),
    )[1]
    (rect_a, ids_a, ext_a, ports_a), (rect_b, ids_b, ext_b, ports_b), _ = best
    axis = 0 if rect_a[1] == rect_b[1] and rect_a[3] == rect_b[3] else 1
    return Cut(
        axis,
        rect_a[2] if axis == 0 else rect_a[3],
        _slice(rect_a, ids_a, ext_a, ports_a, rooms, rng),
        _slice(rect_b, ids_b, ext_b, ports_b, rooms, rng),
    )


def _ranked_cuts(rect, ids, ext, ports, rooms: SliceRooms, rng=None) -> list[tuple[float, tuple[Part, Part, int]]]:
    """(immediate score, parts) of every candidate cut, best first."""
    out = []
    for axis, low, high in _splits(ids, rooms):
        cut = _cut(rect, low, low + high, axis, rooms)
        if cut is None:
            continue
        parts = _parts(rect, ext, ports, axis, cut, low, high, rooms.edges)
        noise = rooms.opts.slice_noise * rng.random() if rng is not None else 0.0
        out.append((_cut_score(parts, rooms) + noise, parts))
    out.sort(key=lambda c: c[0])
    return out


def _splits(ids: list[int], rooms: SliceRooms):
    """(axis, low rooms, high rooms): prefixes of the seed order, and graph bipartitions."""
    for axis in (0, 1):
        pos = rooms.lists.pos
        order = sorted(ids, key=lambda k: pos[k][axis])
        for i in range(1, len(order)):
            yield axis, order[:i], order[i:]
    for side_a, side_b in _edge_bipartitions(ids, rooms):
        for axis in (0, 1):
            a_first = rooms.pos[side_a, axis].mean() <= rooms.pos[side_b, axis].mean()
            yield (axis, side_a, side_b) if a_first else (axis, side_b, side_a)


def _edge_bipartitions(ids: list[int], rooms: SliceRooms) -> list[tuple[list[int], list[int]]]:
    """Splits of ``ids`` made by removing one edge of a spanning tree of its subgraph."""
    members = set(ids)
    adj = {k: [j for i, j in rooms.edges if i == k and j in members] for k in ids}
    for i, j in rooms.edges:
        if i in members and j in members:
            adj[j].append(i)
    tree_edges, seen, stack = [], {ids[0]}, [ids[0]]
    while stack:
        k = stack.pop()
        for j in adj[k]:
            if j not in seen:
                seen.add(j)
                tree_edges.append((k, j))
                stack.append(j)
    out = []
    for cut_edge in tree_edges:
        side = _component(cut_edge[1], [e for e in tree_edges if e != cut_edge])
        rest = [k for k in ids if k not in side]
        if rest and len(side) < len(ids):
            out.append((sorted(side), rest))
    return out


def _component(start: int, edges: list[tuple[int, int]]) -> set[int]:
    comp, grew = {start}, True
    while grew:
        grew = False
        for i, j in edges:
            if (i in comp) != (j in comp):
                comp |= {i, j}
                grew = True
    return comp


def _completed_cost(parts, rooms: SliceRooms) -> float:
    """Cost of a cut when both parts are then sliced greedily to single rooms."""
    opts = rooms.opts
    cost = opts.slice_infeasible_cost * parts[2]
    leaves: dict[int, Rect] = {}
    for rect, ids, ext, ports in parts[:2]:
        part: dict[int, Rect] = {}
        _greedy_rects(rect, ids, ext, ports, rooms, part)
        cost += _leaves_cost(part, rect, ext, ports, rooms)
        leaves.update(part)
    for i, j in rooms.edges:
        if i in leaves and j in leaves:
            cost += opts.slice_wall_deficit_weight * max(0.0, opts.shared_wall_min_m - shared_wall_cells(leaves[i], leaves[j]) * rooms.cell_m)
    return cost


def _greedy_rects(rect, ids, ext, ports, rooms: SliceRooms, out: dict[int, Rect]) -> None:
    """``out`` given the rectangle of each of ``ids``, ``rect`` cut greedily (the best
    cut by its immediate score, no noise): the same part comes back for many cuts, so
    each part's rectangles are worked out once per slicing (``SliceRooms.greedy``) and
    added to ``out`` in the order they were found."""
    if len(ids) == 1:
        out[ids[0]] = rect
        return
    key = (rect, tuple(ids), ext, tuple(ports.items()))
    found = rooms.greedy.get(key)
    if found is None:
        part: dict[int, Rect] = {}
        ranked = _ranked_cuts(rect, ids, ext, ports, rooms)
        if not ranked:
            for k in ids:
                part[k] = (rect[0], rect[1], rect[0], rect[1])
        else:
            for sub in ranked[0][1][:2]:
                _greedy_rects(*sub, rooms, part)
        found = rooms.greedy[key] = tuple(part.items())
    out.update(found)


def _leaves_cost(leaves: dict[int, Rect], rect: Rect, ext: Ext, ports: Ports, rooms: SliceRooms) -> float:
    """Hard-rule violations of a completed part: shapes, ports, exterior walls."""
    cell = rooms.cell_m
    opts = rooms.opts
    cost = 0.0
    for k, r in leaves.items():
        w, h = (r[2] - r[0]) * cell, (r[3] - r[1]) * cell
        if w <= 0 or h <= 0:
            cost += opts.slice_infeasible_cost
            continue
        cost += _room_shape_score(k, min(w, h), max(w, h), _leaf_ext(r, rect, ext), rooms)
        cost += sum(_side_deficit(r, rect, side, cell, opts) for side in ports.get(k, ()))
        if rooms.lists.exterior[k]:
            cost += min((_side_deficit(r, rect, side, cell, opts) for side in range(4) if ext[side]), default=opts.slice_infeasible_cost)
    return cost


def _leaf_ext(r: Rect, rect: Rect, ext: Ext) -> Ext:
    return (
        ext[0] and r[0] == rect[0], ext[1] and r[2] == rect[2],
        ext[2] and r[1] == rect[1], ext[3] and r[3] == rect[3],
    )


def _side_deficit(r: Rect, rect: Rect, side: int, cell: float, opts: FloorplanOptions) -> float:
    """Cost of a leaf having less than ``opts.shared_wall_min_m`` of wall on its part's ``side``."""
    on = (r[0] == rect[0], r[2] == rect[2], r[1] == rect[1], r[3] == rect[3])[side]
    length = (r[3] - r[1]) if side < 2 else (r[2] - r[0])
    return opts.slice_wall_deficit_weight * max(0.0, opts.shared_wall_min_m - (length * cell if on else 0.0))


def shared_wall_cells(a: Rect, b: Rect) -> int:
    """Length (cells) of the wall two rectangles share."""
    if a[2] == b[0] or b[2] == a[0]:
        return max(0, min(a[3], b[3]) - max(a[1], b[1]))
    if a[3] == b[1] or b[3] == a[1]:
        return max(0, min(a[2], b[2]) - max(a[0], b[0]))
    return 0


def _cut(rect: Rect, first: list[int], ids: list[int], axis: int, rooms: SliceRooms) -> int | None:
    lo, hi = (rect[0], rect[2]) if axis == 0 else (rect[1], rect[3])
    frac = rooms.cells[first].sum() / rooms.cells[ids].sum()
    cut = lo + int(round(frac * (hi - lo)))
    return cut if lo < cut < hi else None


def _parts(rect: Rect, ext: Ext, ports: Ports, axis: int, cut: int, a: list[int], b: list[int], edges) -> tuple[Part, Part, int]:
    """The two parts of a cut: (rect, rooms, exterior sides, ports) each."""
    x0, y0, x1, y1 = rect
    left, right, bottom, top = ext
    if axis == 0:
        rects = (x0, y0, cut, y1), (cut, y0, x1, y1)
        exts = (left, False, bottom, top), (False, right, bottom, top)
    else:
        rects = (x0, y0, x1, cut), (x0, cut, x1, y1)
        exts = (left, right, bottom, False), (left, right, False, top)
    lost = (1, 0) if axis == 0 else (3, 2)  # side of each part that is now the cut
    a_set, b_set = set(a), set(b)
    port_a = {k: v - {lost[0]} for k, v in ports.items() if k in a_set}
    port_b = {k: v - {lost[1]} for k, v in ports.items() if k in b_set}
    for i, j in edges:
        if i in a_set and j in b_set or i in b_set and j in a_set:
            i, j = (i, j) if i in a_set else (j, i)
            port_a[i] = port_a.get(i, frozenset()) | {lost[0]}
            port_b[j] = port_b.get(j, frozenset()) | {lost[1]}
    broken = sum(1 for k, v in ports.items() if v & {lost[0] if k in a_set else lost[1]})
    return (rects[0], a, exts[0], port_a), (rects[1], b, exts[1], port_b), broken


def _cut_score(parts: tuple[Part, Part, int], rooms: SliceRooms) -> float:
    part_a, part_b, broken = parts
    crossing = sum(len(v) for v in part_a[3].values())
    opts = rooms.opts
    score = opts.slice_cut_edge_cost * crossing + opts.slice_infeasible_cost * broken
    return score + sum(_part_score(*part, rooms) for part in (part_a, part_b))


def _part_score(rect: Rect, ids: list[int], ext: Ext, ports: Ports, rooms: SliceRooms) -> float:
    w_m = (rect[2] - rect[0]) * rooms.cell_m
    h_m = (rect[3] - rect[1]) * rooms.cell_m
    short, long_ = min(w_m, h_m), max(w_m, h_m)
    opts = rooms.opts
    score = _exterior_score(ids, ext, w_m, h_m, rooms) + _port_score(ids, ports, opts)
    if len(ids) == 1:
        return score + _room_shape_score(ids[0], short, long_, ext, rooms)
    min_side = rooms.lists.min_side
    if short < min(min_side[k] for k in ids) - 1e-6:
        score += opts.slice_infeasible_cost
    return score + opts.slice_part_aspect_weight * max(0.0, long_ / short - opts.slice_part_aspect_soft)


def _room_shape_score(k: int, short: float, long_: float, ext: Ext, rooms: SliceRooms) -> float:
    opts = rooms.opts
    if k == rooms.void:
        if rooms.void_sides == 1:
            placed = sum(ext) == 1
        else:
            placed = bool((ext[0] or ext[1]) and (ext[2] or ext[3]))
        return 0.0 if placed else opts.slice_infeasible_cost
    lists = rooms.lists
    score = opts.slice_infeasible_cost if short < lists.min_side[k] - 1e-6 else 0.0
    if lists.min_long is not None and long_ < lists.min_long[k] - 1e-6:
        score += opts.slice_infeasible_cost
    if lists.corridor[k]:
        return score
    aspect = long_ / short
    if aspect > lists.max_aspect[k]:
        score += opts.slice_infeasible_cost
    return score + max(0.0, aspect - opts.slice_room_aspect_soft)


def _exterior_score(ids: list[int], ext: Ext, w_m: float, h_m: float, rooms: SliceRooms) -> float:
    opts = rooms.opts
    exterior = rooms.lists.exterior
    need = sum(1 for k in ids if exterior[k])
    if need == 0:
        return 0.0
    have = (ext[0] + ext[1]) * h_m + (ext[2] + ext[3]) * w_m
    if have == 0:
        return opts.slice_infeasible_cost * need
    per_room = opts.slice_exterior_per_room_m
    return opts.slice_exterior_deficit_weight * max(0.0, need * per_room - have) / per_room


def _port_score(ids: list[int], ports: Ports, opts: FloorplanOptions) -> float:
    """Cost of rooms that must touch opposite sides or crowd one side of a part."""
    score = 0.0
    per_side = [0, 0, 0, 0]
    for k in ids:
        sides = ports.get(k, frozenset())
        if {0, 1} <= sides or {2, 3} <= sides:
            score += opts.slice_opposite_ports_cost
        for side in sides:
            per_side[side] += 1
    crowd = opts.slice_crowded_side_ports
    return score + opts.slice_crowded_side_cost * sum(max(0, c - crowd) for c in per_side)
