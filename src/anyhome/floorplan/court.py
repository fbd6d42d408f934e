"""Courtyard plans: a ring of rooms around an open court (riad, atrium house, cloister).

The bubble diagram is read as a tree rooted at the court (the program's enclosed
open-air room, rooms.yaml ``enclosed``). Every room joined to the court heads a
*block*: a row of *columns* along one side of the court, each column's rooms stacked
from the court outwards, so the head opens onto the court and the outermost room of a
column has an outside wall. A head that is a hallway, or has more than two sub-rooms,
is a *gallery*: a strip along the court with its sub-rooms in a row between it and the
outside, or in two rows (one between it and the court).

The blocks are dealt to the court's four sides (three for a U of wings, the fourth
side of the court left open), each side a *wing* whose depth makes its length match the
court's side: the west and east wings run the full height, the north and south ones fit
between them, so the outline is a rectangle (or a U) and every room keeps its area. Of
``court_trials`` random deals, mirrorings and court proportions, the one with the fewest
faults (a room out of proportion or too narrow, a door wall too short, a habitable room
without a wall for a window) is drawn on the cell grid; the whole plan is then rotated
or mirrored at random.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from anyhome.floorplan.grid import OUTSIDE, min_side_cells
from anyhome.floorplan.program import CORRIDOR_TYPES, Program
from anyhome.floorplan.slicing import Rect, shared_wall_cells  # Rect: (x0, y0, x1, y1) in cells
from anyhome.floorplan.spine import random_symmetry, rasterize

# Here the court's south-west corner is cell (0, 0).
NORTH, SOUTH, EAST, WEST = range(4)


@dataclass(frozen=True)
class Segment:
    """A piece of a wing along the court: a column of rooms (``column``, from the court
    outwards), or a gallery ``hall`` with its sub-rooms in ``rooms`` (a row each way
    from a gallery room, kept together)."""

    column: tuple[int, ...] = ()
    hall: int | None = None
    rooms: tuple[tuple[int, ...], ...] = ()


Block = list[Segment]


def court_owner(prog: Program, rng: np.random.Generator, open_side: bool = False) -> np.ndarray | str:
    """Padded owner array (``[x, y]``, cells of ``prog.options.spine_cell_m``) of one
    courtyard plan, or the reason none was found; ``open_side``: wings on three sides of
    the court only (a U)."""
    court = next((k for k in range(prog.n) if prog.enclosed and prog.enclosed[k]), None)
    if court is None:
        return "no enclosed courtyard"
    children = _tree(prog, court, rng)
    if isinstance(children, str):
        return children
    blocks = []
    for head in children[court]:
        block = _block(head, children, prog)
        if isinstance(block, str):
            return block
        blocks.append(block)
    opts = prog.options
    if len(blocks) < (3 if open_side else 4):
        return f"the courtyard opens onto {len(blocks)} rooms, too few to wrap it"
    best: tuple[tuple[int, float], dict[int, Rect], str] | None = None
    for _ in range(opts.court_trials):
        rects = _trial(prog, court, blocks, open_side, rng)
        if rects is None:
            continue
        faults, soft, reason = _score(prog, court, rects)
        if best is None or (faults, soft) < best[0]:
            best = ((faults, soft), rects, reason)
    if best is None:
        return "no courtyard ring fits the rooms"
    if best[0][0]:
        return best[2]
    return random_symmetry(rasterize(best[1]), rng)


# ------------------------------------------------------------------ the tree
def _tree(prog: Program, court: int, rng: np.random.Generator) -> list[list[int]] | str:
    """Children of every room in a breadth-first tree of the bubble diagram from the court."""
    children = prog.tree(court, rng)
    return "the bubble diagram is not connected" if children is None else children


def _block(head: int, children: list[list[int]], prog: Program) -> Block | str:
    """The segments of ``head``'s subtree, ``head`` touching the court."""
    if _is_gallery(head, children, prog):
        return _gallery(head, children, prog)
    column, rest = _stack(head, children[head], children, prog)
    if len(rest) > 2:
        return f"room {prog.ids[head]!r} has more than two sub-rooms"
    sides = []
    for j in rest:
        chain = _chain(j, children, prog)
        if isinstance(chain, str):
            return chain
        sides.append(chain)
    right = sides[0] if sides else []
    left = _mirrored(sides[1]) if len(sides) > 1 else []
    return [*left, Segment(column=column), *right]


def _is_gallery(k: int, children: list[list[int]], prog: Program) -> bool:
    return bool(children[k]) and (prog.types[k] in CORRIDOR_TYPES or len(children[k]) > 2)


def _gallery(hall: int, children: list[list[int]], prog: Program) -> Block | str:
    rows = []
    for j in children[hall]:
        row = _row(j, children, prog)
        if isinstance(row, str):
            return row
        rows.append(tuple(row))
    return [Segment(hall=hall, rooms=tuple(rows))]


def _stack(k: int, kids: list[int], children: list[list[int]], prog: Program) -> tuple[tuple[int, ...], list[int]]:
    """``k``'s column: ``k`` and outwards of it one childless service room of its kids
    (a bathroom off a bedroom); the kids left over."""
    for j in kids:
        if not children[j] and not prog.habitable(j) and prog.types[j] not in CORRIDOR_TYPES:
            return (k, j), [i for i in kids if i != j]
    return (k,), list(kids)


def _chain(j: int, children: list[list[int]], prog: Program) -> Block | str:
    """Segments of ``j``'s subtree going outwards from its parent's segment."""
    if _is_gallery(j, children, prog):
        return _gallery(j, children, prog)
    column, rest = _stack(j, children[j], children, prog)
    if len(rest) > 1:
        return f"room {prog.ids[j]!r} has two sub-rooms that cannot share its column"
    tail = _chain(rest[0], children, prog) if rest else []
    if isinstance(tail, str):
        return tail
    return [Segment(column=column), *tail]


def _row(j: int, children: list[list[int]], prog: Program) -> list[int] | str:
    """A gallery room and its subtree in one row: its sub-rooms on either side of it."""
    kids = children[j]
    if len(kids) > 2:
        return f"room {prog.ids[j]!r} has more than two sub-rooms"
    sides = []
    for i in kids:
        side = _row(i, children, prog)
        if isinstance(side, str):
            return side
        if len(children[i]) > 1:
            return f"room {prog.ids[i]!r} has two sub-rooms off a gallery"
        sides.append(side)
    right = sides[0] if sides else []
    left = sides[1][::-1] if len(sides) > 1 else []
    return [*left, j, *right]


# ---------------------------------------------------------------- one trial
@dataclass(frozen=True)
class _Wing:
    """One wing's segments, with each gallery's rooms split between the row beside the
    court (``inner``) and the row beyond the hall."""

    segments: list[Segment]
    inner: dict[int, tuple[int, ...]]
    outer: dict[int, tuple[int, ...]]


def _trial(prog: Program, court: int, blocks: list[Block], open_side: bool, rng) -> dict[int, Rect] | None:
    """The rooms' rectangles of one random deal of the blocks, or None if it breaks apart."""
    opts = prog.options
    sides = [NORTH, EAST, WEST] if open_side else [NORTH, SOUTH, EAST, WEST]
    dealt = _greedy_deal(blocks, sides, prog, rng)
    onto = frozenset(a if b == court else b for a, b in prog.edges if court in (a, b))
    wings = {s: _wing(_ends_outward(_wide_ends(dealt[s], prog), onto), rng) for s in sides}
    cell = opts.spine_cell_m
    hall_m = max(opts.spine_hallway_min_m, opts.shared_wall_min_m)
    depth = {s: 0.0 for s in range(4)}
    widths: dict[int, list[float]] = {}
    ring_m = _ring_depth(prog, court, open_side)
    pull = 0.0 if open_side else rng.uniform(0.0, opts.court_depth_pull_max)
    for s in sides:
        natural = _natural_depth(wings[s], hall_m, prog) * rng.uniform(opts.spine_depth_jitter_min, opts.spine_depth_jitter_max)
        depth[s] = natural ** (1.0 - pull) * ring_m**pull
        widths[s] = _widths(wings[s], depth[s], hall_m, prog)
    for pair in ((NORTH, SOUTH), (EAST, WEST)):  # opposite wings of one length: the shorter shallower
        if all(s in wings for s in pair):
            short, long_ = sorted(pair, key=lambda s: sum(widths[s]))
            for _ in range(2):
                floor_m = _least_depth(wings[short], hall_m, prog)
                ratio = sum(widths[short]) / sum(widths[long_])
                depth[short] = max(floor_m, depth[short] * ratio)
                widths[short] = _widths(wings[short], depth[short], hall_m, prog)
    D = {s: round(depth[s] / cell) for s in range(4)}
    hall = max(1, round(hall_m / cell))
    if any(D[s] <= hall for s in sides):
        return None
    court_min = min_side_cells(prog.min_side_m(court), cell, opts)
    if open_side:
        frame = _u_frame(prog, court, widths, D, court_min, rng)
    else:
        frame = _ring_frame(wings, widths, depth, D, court_min, rng, prog, onto)
    if frame is None:
        return None
    court_rect, lengths, frames = frame
    rects: dict[int, Rect] = {court: court_rect}
    for s in sides:
        caps = _caps(wings[s], widths[s], depth[s], prog)
        stretched = _stretched(widths[s], caps, lengths[s] * cell)
        for k, (t0, t1, s0, s1) in _lay(wings[s], stretched, lengths[s], D[s], hall, prog).items():
            rects[k] = frames[s](t0, t1, s0, s1)
    if any(r[2] <= r[0] or r[3] <= r[1] for r in rects.values()):
        return None
    return rects


Frame = tuple[Rect, dict[int, int], dict[int, Callable[[int, int, int, int], Rect]]]
"""The court's rectangle, each wing's length (cells) and its map from (t0, t1, s0, s1)
(along the court side, outwards from it) to a plan rectangle."""


def _ring_frame(wings: dict[int, _Wing], widths: dict[int, list[float]], depth: dict[int, float], D: dict[int, int],
                court_min: int, rng, prog: Program, onto: frozenset[int]) -> Frame | None:
    """A closed ring: the court as long as the longer of each pair of opposite wings."""
    opts = prog.options
    cell = opts.spine_cell_m
    # each corner square goes to one of its wings: spread along it, or (in a share of the
    # trials) whole to the room at that end
    grow_ends = rng.random() < opts.court_corner_room_probability
    corner = _corners(wings, widths, depth, prog, onto, grow_ends)
    ext = {s: 0 for s in range(4)}
    for (ns, ew), owner in corner.items():
        ext[owner] += D[ew] if owner == ns else D[ns]
        if grow_ends:  # the segment at that end of the wing takes the whole corner square
            end = 0 if (owner == ns and ew == WEST) or (owner == ew and ns == SOUTH) else -1
            widths[owner][end] += (D[ew] if owner == ns else D[ns]) * cell
    natural = {s: round(sum(widths[s]) / cell) for s in wings}
    CW = max(natural[NORTH] - ext[NORTH], natural[SOUTH] - ext[SOUTH], court_min)
    CH = max(natural[EAST] - ext[EAST], natural[WEST] - ext[WEST], court_min)
    # a court no longer than court_max_aspect times its width: the shorter side grows
    CW, CH = max(CW, math.ceil(CH / opts.court_max_aspect)), max(CH, math.ceil(CW / opts.court_max_aspect))
    start = {  # where each wing's run begins (x for north/south, y for east/west)
        NORTH: -D[WEST] if corner[(NORTH, WEST)] == NORTH else 0,
        SOUTH: -D[WEST] if corner[(SOUTH, WEST)] == SOUTH else 0,
        EAST: -D[SOUTH] if corner[(SOUTH, EAST)] == EAST else 0,
        WEST: -D[SOUTH] if corner[(SOUTH, WEST)] == WEST else 0,
    }
    frames = {
        NORTH: lambda t0, t1, s0, s1: (start[NORTH] + t0, CH + s0, start[NORTH] + t1, CH + s1),
        SOUTH: lambda t0, t1, s0, s1: (start[SOUTH] + t0, -s1, start[SOUTH] + t1, -s0),
        EAST: lambda t0, t1, s0, s1: (CW + s0, start[EAST] + t0, CW + s1, start[EAST] + t1),
        WEST: lambda t0, t1, s0, s1: (-s1, start[WEST] + t0, -s0, start[WEST] + t1),
    }
    lengths = {s: (CW if s in (NORTH, SOUTH) else CH) + ext[s] for s in wings}
    return (0, 0, CW, CH), lengths, frames


def _u_frame(prog: Program, court: int, widths: dict[int, list[float]], D: dict[int, int], court_min: int,
             rng) -> Frame | None:
    """A U: a north wing across the full width, east and west wings (legs of one length)
    reaching from it past the court where their rooms need the length; the court at its
    planned area, no wider than deep (the U opens on its shorter side), or (at random) as
    deep as the legs."""
    opts = prog.options
    cell = opts.spine_cell_m
    area = prog.areas_m2[court] / cell**2
    aspect = rng.uniform(1.0 / opts.court_max_aspect, 1.0)
    across = D[EAST] + D[WEST]  # the north wing's length past the court
    natural = {s: round(sum(widths[s]) / cell) for s in (NORTH, EAST, WEST)}
    CW = max(round(math.sqrt(area * aspect)), natural[NORTH] - across, court_min)
    CH = max(round(area / CW), CW, court_min)
    leg = max(natural[EAST], natural[WEST], CH)
    if rng.random() < opts.court_u_deep_probability:  # every room along the legs opens onto the court
        CH = leg
    frames = {
        NORTH: lambda t0, t1, s0, s1: (t0 - D[WEST], CH + s0, t1 - D[WEST], CH + s1),
        EAST: lambda t0, t1, s0, s1: (CW + s0, CH - leg + t0, CW + s1, CH - leg + t1),
        WEST: lambda t0, t1, s0, s1: (-s1, CH - leg + t0, -s0, CH - leg + t1),
    }
    lengths = {NORTH: CW + across, EAST: leg, WEST: leg}
    return (0, 0, CW, CH), lengths, frames


def _corners(wings: dict[int, _Wing], widths: dict[int, list[float]], depth: dict[int, float], prog: Program,
             onto: frozenset[int], grow: bool) -> dict[tuple[int, int], int]:
    """The wing each corner square goes to (keyed by its north/south and east/west wings):
    the one whose segment at that end keeps a door's width along the court (a segment
    that needs no door onto the court always does), then the squarer room if the
    segment takes the whole corner (``grow``), else the east or west wing."""
    opts = prog.options

    def cost(side: int, at_start: bool, corner_m: float) -> float:
        seg = wings[side].segments[0 if at_start else -1]
        w = widths[side][0 if at_start else -1]
        reach = w if grow else w - corner_m
        short = 10.0 + opts.exterior_wall_min_m - reach if _needs_court(seg, onto) and reach < opts.exterior_wall_min_m else 0.0
        if not grow or seg.hall is not None:
            return short
        head = float(prog.areas_m2[seg.column[0]]) / float(prog.areas_m2[list(seg.column)].sum())
        h = depth[side] * head
        return short + max(w + corner_m, h) / min(w + corner_m, h)

    out = {}
    for ns in (NORTH, SOUTH):
        for ew in (EAST, WEST):
            by_ew = cost(ew, ns == SOUTH, depth[ns])
            by_ns = cost(ns, ew == WEST, depth[ew])
            out[(ns, ew)] = ns if by_ns < by_ew else ew
    return out


def _caps(wing: _Wing, widths: list[float], depth_m: float, prog: Program) -> list[float]:
    """The widest each segment may grow before a room in it is out of proportion or grows
    past ``court_room_max_area_ratio`` of its planned area."""
    out = []
    for s, w in zip(wing.segments, widths):
        if s.hall is None and all(math.isfinite(prog.max_aspect(k)) for k in s.column):
            col_area = float(prog.areas_m2[list(s.column)].sum())
            aspect_m = min(0.98 * prog.max_aspect(k) * depth_m * float(prog.areas_m2[k]) / col_area for k in s.column)
            area_m = 0.95 * prog.options.court_room_max_area_ratio * col_area / depth_m
            out.append(max(w, min(aspect_m, area_m)))
        else:
            out.append(w * 1.5)
    return out


def _stretched(widths: list[float], caps: list[float], length_m: float) -> list[float]:
    """``widths`` grown to add up to ``length_m`` by one factor (every room grows by the
    same share of its area), each held to its cap while others can take the growth;
    beyond all caps in proportion to the caps."""
    if length_m <= sum(widths):
        return widths
    if sum(caps) <= length_m:
        return [c * length_m / sum(caps) for c in caps]
    lo, hi = 1.0, max(c / w for w, c in zip(widths, caps))
    for _ in range(40):
        f = (lo + hi) / 2
        if sum(min(w * f, c) for w, c in zip(widths, caps)) < length_m:
            lo = f
        else:
            hi = f
    return [min(w * hi, c) for w, c in zip(widths, caps)]


def _greedy_deal(blocks: list[Block], sides: list[int], prog: Program, rng) -> dict[int, list[Block]]:
    """Blocks, largest first (their areas jittered, so trials differ), each to the side furthest below its share
    of the rooms' area: wings of one typical depth around a square court, the east and
    west ones (or a U's north one) running past the corners; then single moves of a
    block that bring the sides nearer their shares."""
    opts = prog.options
    noise = opts.court_deal_noise_frac
    areas = [_area(b, prog) * rng.uniform(1.0 - noise, 1.0 + noise) for b in blocks]
    total = sum(areas)
    d = float(np.clip(math.sqrt(float(np.median(prog.areas_m2))), opts.spine_block_depth_min_m,
                      opts.spine_block_depth_max_m)) * rng.uniform(opts.spine_depth_jitter_min, opts.spine_depth_jitter_max)
    long_sides = (NORTH,) if len(sides) == 3 else (EAST, WEST)
    n_long = len(long_sides)
    c = max(1.0, (total / d - 2 * d * n_long) / len(sides))  # the court's side
    target = {s: d * (c + 2 * d if s in long_sides else c) for s in sides}
    order = sorted(range(len(blocks)), key=lambda i: (-areas[i], rng.random()))
    side_of: dict[int, int] = {}
    load = {s: 0.0 for s in sides}
    for i in order:
        side = max(sides, key=lambda s: (target[s] - load[s], rng.random()))
        side_of[i] = side
        load[side] += areas[i]

    def cost(ld: dict[int, float]) -> float:
        return sum((ld[s] - target[s]) ** 2 for s in sides)

    for _ in range(len(blocks)):
        best = None
        for i, s0 in side_of.items():
            if sum(1 for j in side_of if side_of[j] == s0) == 1:
                continue
            for s1 in sides:
                if s1 == s0:
                    continue
                moved = dict(load)
                moved[s0] -= areas[i]
                moved[s1] += areas[i]
                gain = cost(load) - cost(moved)
                if gain > 1e-9 and (best is None or gain > best[0]):
                    best = (gain, i, s1)
        if best is None:
            break
        _, i, s1 = best
        load[side_of[i]] -= areas[i]
        load[s1] += areas[i]
        side_of[i] = s1
    dealt: dict[int, list[Block]] = {s: [] for s in sides}
    for i in rng.permutation(len(blocks)).tolist():
        dealt[side_of[i]].append(blocks[i] if rng.random() < 0.5 else _mirrored(blocks[i]))
    if any(not v for v in dealt.values()):
        return _sorted_deal(blocks, sides, prog, rng)
    return dealt


def _sorted_deal(blocks: list[Block], sides: list[int], prog: Program, rng) -> dict[int, list[Block]]:
    """Blocks sorted by the size of their head room and cut into one run per side at
    random (rooms of a size share a wing): every side gets one."""
    def head_area(block: Block) -> float:
        return max(float(prog.areas_m2[s.column[0]]) if s.hall is None else 0.0 for s in block)

    order = sorted(range(len(blocks)), key=lambda i: (head_area(blocks[i]), rng.random()))
    cuts = sorted(rng.choice(np.arange(1, len(blocks)), size=len(sides) - 1, replace=False).tolist())
    runs = [order[i:j] for i, j in zip([0, *cuts], [*cuts, len(blocks)])]
    side_order = rng.permutation(sides).tolist()
    dealt: dict[int, list[Block]] = {}
    for side, run in zip(side_order, runs):
        picked = [blocks[i] if rng.random() < 0.5 else _mirrored(blocks[i]) for i in rng.permutation(run).tolist()]
        dealt[int(side)] = picked
    return dealt


def _wide_ends(blocks: list[Block], prog: Program) -> list[Block]:
    """The wing's blocks with the two of the most floor area in their end segments at its
    ends: the corners take a wing's ends, and a wide segment there still reaches the court."""
    if len(blocks) < 3:
        return blocks

    def end_area(block: Block) -> float:
        return max(_area([block[0]], prog), _area([block[-1]], prog))

    ranked = sorted(range(len(blocks)), key=lambda i: -end_area(blocks[i]))
    first, last = ranked[0], ranked[1]
    middle = [blocks[i] for i in range(len(blocks)) if i not in (first, last)]
    return [blocks[first], *middle, blocks[last]]


def _needs_court(seg: Segment, onto: frozenset[int]) -> bool:
    return (seg.column[:1] or (seg.hall,))[0] in onto


def _ends_outward(blocks: list[Block], onto: frozenset[int]) -> list[Block]:
    """The wing's blocks with the first and last mirrored where that puts a segment that
    needs no door onto the court at the wing's ends (the corners)."""
    out = list(blocks)
    if out and _needs_court(out[0][0], onto) and not _needs_court(out[0][-1], onto):
        out[0] = _mirrored(out[0])
    if out and _needs_court(out[-1][-1], onto) and not _needs_court(out[-1][0], onto):
        out[-1] = _mirrored(out[-1])
    return out


def _mirrored(block: Block) -> Block:
    return [Segment(column=s.column, hall=s.hall, rooms=tuple(r[::-1] for r in s.rooms[::-1])) for s in block[::-1]]


def _area(block: Block, prog: Program) -> float:
    rooms = [k for s in block for k in (*s.column, *(i for r in s.rooms for i in r))]
    return float(sum(prog.areas_m2[k] for k in rooms))


def _wing(blocks: list[Block], rng) -> _Wing:
    segments = [s for b in blocks for s in b]
    inner, outer = {}, {}
    for s in segments:
        if s.hall is None:
            continue
        rows = list(s.rooms)
        n_in = int(rng.integers(len(rows))) if len(rows) > 1 else 0
        inner[s.hall] = tuple(k for r in rows[:n_in] for k in r)
        outer[s.hall] = tuple(k for r in rows[n_in:] for k in r)
    return _Wing(segments, inner, outer)


def _ring_depth(prog: Program, court: int, open_side: bool) -> float:
    """The one wing depth (m) at which the rooms, at their areas, wrap a square court of
    its planned area: ``d * (4 c + 4 d)`` of floor around a ring, ``d * (3 c + 2 d)`` in a U."""
    c = math.sqrt(float(prog.areas_m2[court]))
    rooms = float(prog.areas_m2.sum()) - c * c
    if open_side:
        return (-3 * c + math.sqrt(9 * c * c + 8 * rooms)) / 4
    return (-c + math.sqrt(c * c + rooms)) / 2


def _natural_depth(wing: _Wing, hall_m: float, prog: Program) -> float:
    """The depth (m) at which the wing's rooms come out squarest: the area-weighted mean
    of each segment's own (a column's rooms square to its width, a gallery's rows of
    square rooms beside its hall), within the spine's block depths."""
    areas = prog.areas_m2
    total, weighted = 0.0, 0.0
    for s in wing.segments:
        if s.hall is None:
            head = float(areas[s.column[0]])
            d = sum(float(areas[k]) for k in s.column) / math.sqrt(head)
            a = float(areas[list(s.column)].sum())
        else:
            rows = [r for r in (wing.inner[s.hall], wing.outer[s.hall]) if r]
            d = hall_m + sum(math.sqrt(float(np.median(areas[list(r)]))) for r in rows)
            a = float(sum(areas[k] for r in rows for k in r))
        total += a
        weighted += a * d
    opts = prog.options
    return float(np.clip(weighted / total, opts.spine_block_depth_min_m, opts.spine_block_depth_max_m))


def _least_depth(wing: _Wing, hall_m: float, prog: Program) -> float:
    """The shallowest the wing may be: each column's rooms at their least sides, each
    gallery's hall and a row of rooms at their least side."""
    out = 0.0
    for s in wing.segments:
        if s.hall is None:
            out = max(out, sum(prog.min_side_m(k) for k in s.column))
        else:
            out = max(out, hall_m + max(prog.min_side_m(k) for r in s.rooms for k in r))
    return out + prog.options.spine_cell_m


def _room_width(k: int, area_m2: float, depth_m: float, prog: Program) -> float:
    """A room's width in a row of depth ``depth_m``: its area over the depth, within its
    least side and its greatest aspect."""
    w = max(area_m2 / depth_m, prog.min_side_m(k))
    if math.isfinite(prog.max_aspect(k)):
        w = max(w, 1.02 * depth_m / prog.max_aspect(k))
        w = min(w, 0.98 * depth_m * prog.max_aspect(k))
    return w


def _widths(wing: _Wing, depth_m: float, hall_m: float, prog: Program) -> list[float]:
    """Each segment's natural width (m) in a wing ``depth_m`` deep."""
    areas = prog.areas_m2
    out = []
    for s in wing.segments:
        if s.hall is None:
            col_area = float(areas[list(s.column)].sum())
            out.append(max(_room_width(k, col_area, depth_m, prog) for k in s.column[:1]) if len(s.column) == 1
                       else max(col_area / depth_m, *(prog.min_side_m(k) for k in s.column)))
            continue
        rows = [r for r in (wing.inner[s.hall], wing.outer[s.hall]) if r]
        row_area = [float(sum(areas[k] for k in r)) for r in rows]
        free_m = depth_m - hall_m
        lengths = []
        for r, a in zip(rows, row_area):
            d = free_m * a / sum(row_area)
            lengths.append(sum(_room_width(k, float(areas[k]), d, prog) for k in r))
        out.append(max(lengths))
    return out


def _lay(wing: _Wing, widths: list[float], length: int, D: int, hall: int, prog: Program) -> dict[int, Rect]:
    """Rooms of a wing as (t0, t1, s0, s1) cells: ``t`` along the court side (``length``
    cells, the segments stretched to it from their ``widths``), ``s`` outwards from the
    court (``D`` cells)."""
    areas = prog.areas_m2
    edges = _cuts(widths, length)
    out: dict[int, Rect] = {}
    for s, t0, t1 in zip(wing.segments, edges[:-1], edges[1:]):
        if s.hall is None:
            cuts = _cuts([float(areas[k]) for k in s.column], D)
            for k, s0, s1 in zip(s.column, cuts[:-1], cuts[1:]):
                out[k] = (t0, t1, s0, s1)
            last = s.column[-1]
            s0, s1 = out[last][2:]
            if math.isfinite(prog.max_aspect(last)) and (t1 - t0) > prog.max_aspect(last) * (s1 - s0):
                # a room too wide for the wing's depth reaches out past it (a bay)
                out[last] = (t0, t1, s0, s0 + math.ceil((t1 - t0) / (0.98 * prog.max_aspect(last))))
            continue
        inner, outer = wing.inner[s.hall], wing.outer[s.hall]
        cell = prog.options.spine_cell_m

        def least(row: tuple[int, ...]) -> int:
            return max((min_side_cells(prog.min_side_m(k), cell, prog.options) for k in row), default=0)

        if inner and least(inner) + least(outer) > D - hall:  # no room for two rows: one
            inner, outer = (), outer + inner
        a_in = float(sum(areas[k] for k in inner))
        a_all = a_in + float(sum(areas[k] for k in outer))
        d_in = min(max(round((D - hall) * a_in / a_all), least(inner)), D - hall - least(outer)) if inner else 0
        out[s.hall] = (t0, t1, d_in, d_in + hall)
        for row, s0, s1 in ((inner, 0, d_in), (outer, d_in + hall, D)):
            if not row:
                continue
            row_w = [_room_width(k, float(areas[k]), max(s1 - s0, 1) * prog.options.spine_cell_m, prog) for k in row]
            cuts = _cuts(row_w, t1 - t0)
            for k, c0, c1 in zip(row, cuts[:-1], cuts[1:]):
                out[k] = (t0 + c0, t0 + c1, s0, s1)
    return out


def _cuts(weights: list[float], total: int) -> list[int]:
    """Integer boundaries splitting ``total`` cells in proportion to ``weights``."""
    acc = np.concatenate([[0.0], np.cumsum(weights)])
    return [int(round(total * a / acc[-1])) for a in acc]


# ---------------------------------------------------------------- the score
def _score(prog: Program, court: int, rects: dict[int, Rect]) -> tuple[int, float, str]:
    """(faults, soft cost, the first fault's reason) of a ring's rectangles."""
    opts = prog.options
    cell = opts.spine_cell_m
    faults, soft, reason = 0, 0.0, ""

    def fault(why: str) -> None:
        nonlocal faults, reason
        faults += 1
        reason = reason or why

    shared = {(a, b): shared_wall_cells(rects[a], rects[b]) * cell for a in rects for b in rects if a < b}

    def wall(a: int, b: int) -> float:
        return shared[(min(a, b), max(a, b))]

    for k in range(prog.n):
        x0, y0, x1, y1 = rects[k]
        w, h = x1 - x0, y1 - y0
        if min(w, h) < min_side_cells(prog.min_side_m(k), cell, opts):
            fault(f"room {prog.ids[k]!r} too narrow")
        aspect = max(w, h) / min(w, h)
        if aspect > prog.max_aspect(k):
            fault(f"room {prog.ids[k]!r} too elongated")
        if k != court:
            ratio = w * h * cell * cell / prog.areas_m2[k]
            soft += abs(ratio - 1.0)
            if ratio > opts.court_room_max_area_ratio and prog.types[k] not in CORRIDOR_TYPES:
                fault(f"room {prog.ids[k]!r} grew too large")
            if math.isfinite(prog.max_aspect(k)):
                soft += opts.score_aspect_weight * max(0.0, aspect - opts.score_aspect_free_ratio)
        if prog.habitable(k):
            open_m = 2 * (w + h) * cell - sum(wall(k, j) for j in rects if j not in (k, court))
            if open_m < opts.exterior_wall_min_m:
                fault(f"habitable room {prog.ids[k]!r} has no exterior wall for a window")
    x0, y0, x1, y1 = rects[court]
    court_ratio = (x1 - x0) * (y1 - y0) * cell * cell / prog.areas_m2[court]
    soft += abs(court_ratio - 1.0)
    if court_ratio > opts.court_max_area_ratio:
        fault(f"the courtyard {prog.ids[court]!r} grew too large")
    for a, b in prog.links:
        if b == OUTSIDE:
            x0, y0, x1, y1 = rects[a]
            if 2 * (x1 - x0 + y1 - y0) * cell - sum(wall(a, j) for j in rects if j != a) < opts.exterior_wall_min_m:
                fault(f"the entrance room {prog.ids[a]!r} has no outside wall")
        elif wall(a, b) < opts.shared_wall_min_m:
            fault(f"connection {prog.ids[a]}-{prog.ids[b]} has no shared wall long enough")
    return faults, soft, reason
