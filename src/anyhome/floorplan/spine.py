"""Constructive floorplans: a spine of hub rooms with room blocks on both sides.

Used for programs the slicing search cannot lay out reliably (many rooms, busy hubs).
The bubble diagram is read as a tree rooted at the entrance room. The *spine* is the
chain of branching rooms from the root (entrance hall -> living room -> hallway ...),
laid east-west; when the root has two branching children the chain runs both ways
from it (its outside gap keeps an exterior wall for the entrance door). Every other child of a spine room becomes a *block* north or south of
it: full-depth columns, the child's column touching the spine, the child's own
children in columns beside it (so they share a wall with it), a second grandchild
stacked inside its parent's column. Every column reaches the outer edge, so every
habitable room gets an exterior wall, and every tree edge is a shared wall by
construction. Sides of different lengths leave L-shaped notches. The whole plan is
then rotated or mirrored at random.
"""

from __future__ import annotations

import numpy as np

from anyhome.floorplan.grid import FREE, OUTSIDE, min_side_cells
from anyhome.floorplan.program import CORRIDOR_TYPES, Program

Column = list[int]  # rooms stacked from the spine side outwards


def spine_owner(prog: Program, rng: np.random.Generator) -> np.ndarray | str:
    """Padded owner array (``[x, y]``) of one spine layout, or a reason it cannot be built
    (cells of ``prog.options.spine_cell_m``; sizes from ``prog.options``)."""
    tree = _tree(prog, rng)
    if isinstance(tree, str):
        return tree
    root, children = tree
    top, children = _spine_root(root, children, prog)
    spine = _spine(top, children)
    blocks: dict[int, list[list[Column]]] = {}
    for s in spine:
        blocks[s] = []
        for c in children[s]:
            if c in spine:
                continue
            cols = _block(c, children, prog, rng)
            if isinstance(cols, str):
                return cols
            blocks[s].append(cols)
    depth = _block_depth(prog, spine, rng)
    for s in spine:
        for block in blocks[s]:
            for col in block:
                depth = max(depth, sum(_min_side(prog, k) for k in col))
    rects: dict[int, tuple[int, int, int, int]] = {}
    x = 0
    for s in spine:
        sides = _split_sides(blocks[s], prog, rng)
        side_depth, widths = _sized(sides, s, depth, prog)
        end = None
        if s == spine[-1]:
            end, sides, side_depth, widths = _shortest_hall(s, root, spine, blocks[s], sides, depth, children, prog, rng)
        over, over_start = None, s == spine[0]
        if prog.stacked:  # a storey keeps the spine its stairs and the storeys above were found with
            use_over = over_start and len(spine) > 1 and not prog.habitable(s)
        else:
            use_over = not end and (over_start or s == spine[-1])
        if use_over:
            over = _overhang(s, sides, widths, children, prog, rng, at_start=over_start)
            if over:
                sides, widths = over[1], over[2]
        lengths = [sum(sum(bw) for bw in side) for side in widths]
        own_len = end[0] if end else over[0] if over else _spine_length(prog, s, max(lengths), rng)
        seg_len = own_len if over else max(own_len, *lengths)
        # a hall whose end wall is outside takes the entrance there: no stretch kept free
        entrance_end = s == root and not prog.habitable(s) and (s == spine[0] or (s == spine[-1] and not end))
        # a room whose blocks reach out past its free end has an outside wall there
        window_gap = not over and (prog.habitable(s) or (s == root and not entrance_end)) and all(lengths)
        if window_gap:  # both sides taken: leave an outside stretch for its windows
            seg_len = max(seg_len, max(lengths) + _cells(prog.options.spine_window_gap_m, prog))
        d = _hall_width(prog) if end else _spine_depth(prog, s, seg_len)
        if s != spine[0] and (s != spine[-1] or end):  # entered through both end walls
            d = max(d, _beside_stair(prog, s))
        y0 = -(d // 2)
        rects[s] = (x, y0, x + (own_len if end else seg_len), y0 + d)
        align_end = (rng.random() < 0.5 and not end) or bool(over and over_start)
        if over and not over_start:
            align_end = False
        for side_i, (side, side_w) in enumerate(zip(sides, widths)):
            slack = seg_len - lengths[side_i]  # negative where the blocks reach out past its start
            if not window_gap and not end and not over:
                align_end = rng.random() < 0.5
            cx = x + (slack if align_end else 0)
            for block_cols, block_w in zip(side, side_w):
                for col, w in zip(block_cols, block_w):
                    _place_column(col, w, cx, y0, d, side_depth[side_i], side_i, prog, rects)
                    cx += w
        if end:  # the last column's first room closes the hall's end: it grows across the
            # hall's width, or (were it then out of proportion) its column moves in by as much
            col, grow = end[1], end[4]
            for i, k in enumerate(col):
                x0, ry0, x1, ry1 = rects[k]
                north = ry0 >= y0 + d
                if grow:
                    rects[k] = (x0, y0, x1, ry1) if north else (x0, ry0, x1, y0 + d)
                    break
                rects[k] = (x0, ry0 - d, x1, ry1 - d) if north else (x0, ry0 + d, x1, ry1 + d)
        x += seg_len
    return random_symmetry(rasterize(rects), rng)


# ------------------------------------------------------------------ the tree
def _tree(prog: Program, rng: np.random.Generator) -> tuple[int, list[list[int]]] | str:
    entrances = [a for a, b in prog.links if b == OUTSIDE]
    if not entrances:
        return "no entrance room"
    root = entrances[0]
    children = prog.tree(root)
    if children is None:
        return "the bubble diagram is not connected"
    for k in range(prog.n):
        rng.shuffle(children[k])
    return root, children


def _fits(root: int, children: list[list[int]], prog: Program) -> bool:
    """True if every room off the spine through ``root`` fits in a block beside it."""
    spine = _spine(root, children)
    return all(not isinstance(_block(c, children, prog, None), str)
               for s in spine for c in children[s] if c not in spine)


def _rerooted(children: list[list[int]], old_root: int, root: int) -> list[list[int]]:
    """The same tree hung from ``root``: each room's children in their old order, its old
    parent (where it is not the new one) last."""
    parent = {c: k for k, cs in enumerate(children) for c in cs}
    out: list[list[int]] = [[] for _ in children]
    order, seen = [root], {root}
    for k in order:
        nbrs = list(children[k]) + ([parent[k]] if k != old_root else [])
        for j in nbrs:
            if j not in seen:
                seen.add(j)
                out[k].append(j)
                order.append(j)
    return out


def _spine_root(root: int, children: list[list[int]], prog: Program) -> tuple[int, list[list[int]]]:
    """Where the spine is built from: the entrance room, or, where a spine through it
    leaves a room with more than two sub-rooms in a block (a hallway with both a
    corridor and a living room of four rooms behind it), the nearest room (breadth
    first) from which every such room lies on the spine. The entrance then sits in a
    block, whose column reaches the outer edge for its door."""
    if _fits(root, children, prog):
        return root, children
    order = [root]
    for k in order:
        order.extend(children[k])
    for k in order[1:]:
        tree = _rerooted(children, root, k)
        if _fits(k, tree, prog):
            return k, tree
    return root, children


def _subtree_size(k: int, children: list[list[int]]) -> int:
    return 1 + sum(_subtree_size(c, children) for c in children[k])


def _must_join(k: int, children: list[list[int]]) -> bool:
    """True if room ``k`` or one of its descendants has more than two sub-rooms (a block
    beside the spine holds at most two): the spine must run through it."""
    return len(children[k]) > 2 or any(_must_join(c, children) for c in children[k])


def _chain_from(start: int, children: list[list[int]]) -> list[int]:
    chain, cur = [start], start
    while True:
        branching = [c for c in children[cur] if len(children[c]) >= 2 or _must_join(c, children)]
        if not branching:
            return chain
        cur = max(branching, key=lambda c: (_must_join(c, children), _subtree_size(c, children)))
        chain.append(cur)


def _spine(root: int, children: list[list[int]]) -> list[int]:
    """The chain of branching rooms through the root: the root's biggest branching
    child leads east; a second branching child of the root leads west."""
    east = _chain_from(root, children)
    branching = [c for c in children[root] if (len(children[c]) >= 2 or _must_join(c, children)) and c not in east]
    if not branching:
        return east
    west = _chain_from(max(branching, key=lambda c: (_must_join(c, children), _subtree_size(c, children))), children)
    return list(reversed(west)) + east


# ---------------------------------------------------------------- the blocks
def _block(c: int, children: list[list[int]], prog: Program, rng) -> list[Column] | str:
    """Columns of child ``c``'s subtree, ``c``'s own column full depth."""
    kids = children[c]
    if len(kids) > 2:
        return f"room {prog.ids[c]!r} has more than two sub-rooms"
    right = _chain(kids[0], children, prog) if kids else []
    left = _chain(kids[1], children, prog) if len(kids) > 1 else []
    if isinstance(right, str):
        return right
    if isinstance(left, str):
        return left
    return list(reversed(left)) + [[c]] + right


def _chain(n: int, children: list[list[int]], prog: Program) -> list[Column] | str:
    """Columns of ``n``'s subtree going outwards from its parent's column."""
    kids = children[n]
    if len(kids) > 2:
        return f"room {prog.ids[n]!r} has more than two sub-rooms"
    column: Column = [n]
    if len(kids) == 2:
        fits = [k for k in kids if not children[k] and not (prog.habitable(k) and prog.habitable(n))]
        if not fits:
            return f"room {prog.ids[n]!r} has two sub-rooms that cannot share its column"
        stacked = min(fits, key=lambda k: prog.habitable(k))
        kids = [k for k in kids if k != stacked]
        column = [stacked, n] if not prog.habitable(stacked) else [n, stacked]
    rest = _chain(kids[0], children, prog) if kids else []
    if isinstance(rest, str):
        return rest
    return [column] + rest


def _split_sides(
    blocks: list[list[Column]], prog: Program, rng
) -> tuple[list[list[Column]], list[list[Column]]]:
    """Blocks north (0) and south (1) of their spine room, balancing area."""
    def area(b: list[Column]) -> float:
        return float(sum(prog.areas_m2[k] for col in b for k in col))

    order = sorted(range(len(blocks)), key=lambda i: (-area(blocks[i]), rng.random()))
    sides: tuple[list[list[Column]], list[list[Column]]] = ([], [])
    totals = [0.0, 0.0]
    first = int(rng.integers(2))
    for i in order:
        side = int(np.argmin(totals)) if totals[0] != totals[1] else first
        sides[side].append(blocks[i])
        totals[side] += area(blocks[i])
    return sides


# ------------------------------------------------------------ the hall's end
Sides = tuple[list[list[Column]], list[list[Column]]]


def _sized(sides: Sides, s: int, depth: int, prog: Program) -> tuple[list[int], list[list[list[int]]]]:
    """Depth of each side of spine room ``s`` and the widths of its blocks' columns."""
    base_depth = [max([depth, *(_deep_enough(col, prog) for b in side for col in b)]) for side in sides]
    cap = _segment_cap(prog, s)
    side_depth = [_pick_depth(side, base_depth[i], cap, prog) for i, side in enumerate(sides)]
    widths = [[[_column_width(c, side_depth[i], prog) for c in b] for b in side] for i, side in enumerate(sides)]
    return side_depth, widths


def _shortest_hall(
    s: int, root: int, spine: list[int], blocks: list[list[Column]], sides: Sides, depth: int,
    children: list[list[int]], prog: Program, rng: np.random.Generator,
) -> tuple[tuple[int, Column, Sides, list[list[list[int]]], bool] | None, Sides, list[int], list[list[list[int]]]]:
    """The end of the spine: the split of its blocks between the two sides (the drawn
    one first, then others, up to ``spine_hall_splits``, for halls of at most
    ``spine_hall_split_max_blocks`` blocks) whose hall, closed by an end room
    (:func:`_end_room`), is shortest; the drawn split unchanged when none closes."""
    side_depth, widths = _sized(sides, s, depth, prog)
    best = _end_room(s, root, spine, sides, widths, side_depth, children, prog)
    out = (best, best[2], side_depth, best[3]) if best else (None, sides, side_depth, widths)
    soft = _cells(prog.options.spine_corridor_soft_length_m, prog)
    if prog.types[s] not in CORRIDOR_TYPES or len(blocks) < 2 or (best and best[0] <= soft):
        return out
    if len(blocks) > prog.options.spine_hall_split_max_blocks:
        return out
    masks = rng.permutation(np.arange(1, 2 ** len(blocks) - 1)).tolist()
    for mask in masks[: prog.options.spine_hall_splits]:
        if out[0] is not None and out[0][0] <= soft:
            break
        split: Sides = ([b for i, b in enumerate(blocks) if mask >> i & 1], [b for i, b in enumerate(blocks) if not mask >> i & 1])
        sd, ws = _sized(split, s, depth, prog)
        end = _end_room(s, root, spine, split, ws, sd, children, prog)
        if end and (out[0] is None or end[0] < out[0][0]):
            out = (end, end[2], sd, end[3])
    return out


def _door_col(block: list[Column], s: int, children: list[list[int]]) -> int:
    """Index of the block's column whose room has its door on spine room ``s``."""
    return next((i for i, col in enumerate(block) if any(k in children[s] for k in col)), 0)


def _packed(
    blocks: list[list[Column]], widths: list[list[int]], s: int, children: list[list[int]], need: int,
    last: int | None = None,
) -> tuple[list[list[Column]], list[list[int]], int]:
    """One side's blocks in the order (each mirrored where that helps) that brings the
    latest door on spine room ``s`` nearest the side's start, the block ``last`` kept at
    the end as it is; and where that door's ``need`` of wall ends (a door in the last
    column of the block ``last`` excepted: it opens in the hall's end wall)."""
    items = []
    for i, (b, w) in enumerate(zip(blocks, widths)):
        if i == last:
            continue
        k = _door_col(b, s, children)
        items.append((b[::-1], w[::-1]) if sum(w[:k]) > sum(w[k + 1:]) else (b, w))
    items.sort(key=lambda bw: sum(bw[1]) - sum(bw[1][: _door_col(bw[0], s, children)]))
    if last is not None:
        items.append((blocks[last], widths[last]))
    reach, start = 0, 0
    for bi, (block, bw) in enumerate(items):
        k = _door_col(block, s, children)
        if not (last is not None and bi == len(items) - 1 and k == len(block) - 1):
            reach = max(reach, start + sum(bw[:k]) + need)
        start += sum(bw)
    return [b for b, _ in items], [w for _, w in items], reach


def _overhang(
    s: int, sides: Sides, widths: list[list[list[int]]], children: list[list[int]], prog: Program, rng,
    at_start: bool = True,
) -> tuple[int, Sides, list[list[list[int]]]] | None:
    """The first spine room (nothing lies beyond its start) kept to its own length, its
    blocks reaching out past its start: (its length, sides, widths), each side's blocks
    ordered and mirrored so their doors on it come at its far end; None where that is
    no shorter than the length its blocks would stretch it to. ``at_start`` False: the
    last spine room, its blocks reaching out past its end, their doors at its start.
    (A hub stretched to its blocks' length would be as deep as that length over its
    greatest aspect: a 27 m2 family room drawn 15.5 m by 8 m.)"""
    need = _cells(prog.options.shared_wall_min_m, prog)
    out_sides: list[list[list[Column]]] = [[], []]
    out_widths: list[list[list[int]]] = [[], []]
    reach = need
    for i in (0, 1):
        blocks, bws, r = _packed(sides[i], widths[i], s, children, need)
        out_sides[i] = [b[::-1] for b in reversed(blocks)] if at_start else blocks
        out_widths[i] = [w[::-1] for w in reversed(bws)] if at_start else bws
        reach = max(reach, r)
    natural = need if prog.types[s] in CORRIDOR_TYPES else _spine_length(prog, s, 0, rng)
    own = max(reach, natural)
    if own >= max(sum(map(sum, w)) for w in widths):
        return None
    return own, (out_sides[0], out_sides[1]), out_widths


def _end_room(
    s: int, root: int, spine: list[int], sides: Sides,
    widths: list[list[list[int]]], depth: list[int], children: list[list[int]], prog: Program,
) -> tuple[int, Column, Sides, list[list[list[int]]], bool] | None:
    """A hall only as long as its doors need: (hall length, room, sides, widths) where the
    room, in the last column of one side, closes the hall's far end (it grows across the
    hall's width, keeping its type's proportions) and every other room with a door on the
    hall keeps ``shared_wall_min_m`` of wall along it; the sides' blocks come back reordered
    (and mirrored) so that the hall is shortest. None where the spine room is not a hallway,
    is the root in the middle of the spine, or no room fits."""
    if prog.types[s] not in CORRIDOR_TYPES or (s == root and s != spine[0]):
        return None  # a root in the middle keeps its outside stretch for the entrance
    need = _cells(prog.options.shared_wall_min_m, prog)

    def packed(side_i: int, last: int | None) -> tuple[list[list[Column]], list[list[int]], int]:
        return _packed(sides[side_i], widths[side_i], s, children, need, last)

    best = None
    for side_i in (0, 1):
        other = 1 - side_i
        o_blocks, o_widths, o_reach = packed(other, None)
        for last in range(len(sides[side_i])):
            blocks, bws, reach = packed(side_i, last)
            end_col, w_end = blocks[-1][-1], bws[-1][-1]
            if sum(map(sum, bws)) - w_end == 0 and not o_blocks:
                continue
            hall = sum(map(sum, bws)) - w_end
            if max(reach, o_reach) > hall:
                continue
            d = _hall_width(prog)
            k = end_col[0]
            h = _column_heights(end_col, depth[side_i], prog)[0] + d
            if d < need:
                continue
            grow = not _aspect_fault(k, w_end, h, prog)
            if best is None or hall < best[0]:
                new_sides: list[list[list[Column]]] = [[], []]
                new_widths: list[list[list[int]]] = [[], []]
                new_sides[side_i], new_widths[side_i] = blocks, bws
                new_sides[other], new_widths[other] = o_blocks, o_widths
                best = (hall, end_col, (new_sides[0], new_sides[1]), new_widths, grow)
    return best


# ----------------------------------------------------------------- the sizes
def _cells(m: float, prog: Program) -> int:
    return int(round(m / prog.options.spine_cell_m))


def _min_side(prog: Program, k: int) -> int:
    """Cells room ``k`` must span (as the shape check counts them)."""
    return min_side_cells(prog.min_side_m(k), prog.options.spine_cell_m, prog.options)


def _block_depth(prog: Program, spine: list[int], rng) -> int:
    opts = prog.options
    others = [k for k in range(prog.n) if k not in spine]
    if not others:
        return _cells(opts.spine_block_depth_min_m, prog)
    typical = float(np.sqrt(np.median([prog.areas_m2[k] for k in others])))
    jitter = rng.uniform(opts.spine_depth_jitter_min, opts.spine_depth_jitter_max)
    depth_m = np.clip(typical * jitter, opts.spine_block_depth_min_m, opts.spine_block_depth_max_m)
    return _cells(float(depth_m), prog)


def _deep_enough(col: Column, prog: Program) -> int:
    """Depth a one-room column needs to stay within ``spine_big_room_aspect`` (an auditorium
    beside a foyer must not become a 50 m strip); 0 for stacked columns."""
    if len(col) != 1:
        return 0
    opts = prog.options
    return min(
        _cells(float(np.sqrt(prog.areas_m2[col[0]] / opts.spine_big_room_aspect)), prog),
        _cells(opts.spine_big_depth_max_m, prog),
    )


def _segment_cap(prog: Program, s: int) -> int:
    """Longest a spine room's segment should grow: a hallway's soft length, else the
    length at which the room, at its target area, reaches its greatest aspect."""
    opts = prog.options
    if not np.isfinite(prog.max_aspect(s)):
        return _cells(opts.spine_corridor_soft_length_m, prog)
    return int(np.sqrt(prog.areas_m2[s] * prog.max_aspect(s)) / opts.spine_cell_m)


def _pick_depth(side: list[list[Column]], base: int, cap: int, prog: Program) -> int:
    """Depth of one side of a spine segment: the least of ``base`` and deeper steps that
    keeps the side within ``cap`` and every column room within its aspect; else the one
    with the fewest aspect faults, then the shortest."""
    if not side:
        return base
    opts = prog.options
    best: tuple[tuple[int, int], int] | None = None
    for step in range(opts.spine_depth_steps + 1):
        depth = int(round(base * (1 + step * opts.spine_depth_step_frac)))
        if depth * opts.spine_cell_m > opts.spine_big_depth_max_m and step:
            break
        length, faults = 0, 0
        for block in side:
            for col in block:
                w = _column_width(col, depth, prog)
                length += w
                faults += sum(_aspect_fault(k, w, h, prog) for k, h in zip(col, _column_heights(col, depth, prog)))
        if faults == 0 and length <= cap:
            return depth
        key = (faults, length)
        if best is None or key < best[0]:
            best = (key, depth)
    assert best is not None
    return best[1]


def _aspect_fault(k: int, w: int, h: int, prog: Program) -> bool:
    return min(w, h) < _min_side(prog, k) or max(w, h) / min(w, h) > prog.max_aspect(k)


def _column_heights(col: Column, depth: int, prog: Program) -> list[int]:
    total = sum(prog.areas_m2[k] for k in col)
    heights = [max(int(round(depth * prog.areas_m2[k] / total)), _min_side(prog, k)) for k in col]
    heights[-1] = depth - sum(heights[:-1])
    return heights


def _column_width(col: Column, depth: int, prog: Program) -> int:
    area_cells = sum(prog.areas_m2[k] for k in col) / prog.options.spine_cell_m**2
    width = max(int(np.ceil(area_cells / depth)), *(_min_side(prog, k) for k in col))
    if len(col) == 1 and np.isfinite(prog.max_aspect(col[0])):  # a small room in a deep row: wider, not a strip
        width = max(width, int(np.ceil(depth / prog.max_aspect(col[0]))))
    if len(col) == 1 and prog.min_length_m and depth * prog.options.spine_cell_m < prog.min_length_m[col[0]] - 1e-6:
        width = max(width, int(np.ceil(prog.min_length_m[col[0]] / prog.options.spine_cell_m - 1e-9)))  # a stairwell's stair runs along the spine
    return width


def _spine_length(prog: Program, s: int, blocks_len: int, rng) -> int:
    """The spine room's own length: its blocks' length, or its natural proportions."""
    opts = prog.options
    area = prog.areas_m2[s] / opts.spine_cell_m**2
    natural = int(round(np.sqrt(area * rng.uniform(opts.spine_aspect_min, opts.spine_aspect_max))))
    if prog.types[s] == "hallway" and blocks_len:
        return blocks_len
    return max(natural, _min_side(prog, s), _min_long(prog, s))


def _min_long(prog: Program, k: int) -> int:
    """Cells room ``k``'s long side must span (``Program.min_length_m``: a stairwell's
    stair and the strip at its foot), 0 for none: a stairwell on the spine is laid out
    that long at once instead of failing the length check after it is built."""
    least_m = prog.min_length_m[k] if prog.min_length_m else 0.0
    return int(np.ceil(least_m / prog.options.spine_cell_m - 1e-9)) if least_m > 0 else 0


def _beside_stair(prog: Program, k: int) -> int:
    """Cells deep a stairwell on the spine (room ``k``, ``Program.stair_m``) entered
    through both its end walls must be: its stair's box against one end wall leaves the
    door there room beside it (:data:`~anyhome.floorplan.stairs.STAIR_WIDTH`, the clearance,
    a door and its corner margin); 0 for any other room. (As deep as the planned area
    makes it, 2.2 m for a dog-leg, no such door ever cleared the stair: measured, a
    brownstone's ground floor refused 1280 spine layouts, 45 s CPU.)"""
    if not _min_long(prog, k) or not prog.stair_m or prog.stair_m[k] <= 0:
        return 0
    from anyhome.floorplan.doors import DOOR_WIDTH_M
    from anyhome.floorplan.stairs import DOOR_CORNER_M, STAIR_CLEAR_M, STAIR_WIDTH

    least_m = STAIR_WIDTH.get() + STAIR_CLEAR_M + DOOR_WIDTH_M + DOOR_CORNER_M
    return int(np.ceil(least_m / prog.options.spine_cell_m - 1e-9))


def _hall_width(prog: Program) -> int:
    """Width of a hall closed by an end room: the narrowest spine hallway, and wide
    enough for the end room's door in its end wall."""
    return max(_cells(prog.options.spine_hallway_min_m, prog), _cells(prog.options.shared_wall_min_m, prog))


def _spine_depth(prog: Program, s: int, length: int) -> int:
    """A spine room's depth: its area over its length, never narrower than its type
    allows nor so shallow that it becomes a strip (its greatest aspect)."""
    area = prog.areas_m2[s] / prog.options.spine_cell_m**2
    floor_m = prog.options.spine_hallway_min_m if prog.types[s] == "hallway" else prog.min_side_m(s)
    depth = max(int(round(area / length)), _cells(floor_m, prog))
    if np.isfinite(prog.max_aspect(s)):
        depth = max(depth, int(np.ceil(length / prog.max_aspect(s))))
    return depth


def _place_column(col, w, cx, y0, d, depth, side, prog, rects) -> None:
    """Stack ``col``'s rooms outward from the spine, north (side 0) or south (side 1)."""
    heights = (_column_heights(col, depth, prog) if len(col) > 1 or prog.stacked
               else [_column_depth(col[0], w, depth, prog)])
    offset = 0
    for k, h in zip(col, heights):
        if side == 0:
            rects[k] = (cx, y0 + d + offset, cx + w, y0 + d + offset + h)
        else:
            rects[k] = (cx, y0 - offset - h, cx + w, y0 - offset)
        offset += h


def _column_depth(k: int, w: int, depth: int, prog: Program) -> int:
    """Depth of room ``k``'s one-room column of width ``w`` on a side ``depth`` deep: the
    side's depth, or, where that would make the room more than ``spine_column_fill_max``
    times its area, the depth that gives it its area (never below its least side, nor
    twice ``shared_wall_min_m``, room for its doors on the columns beside it, nor past its
    greatest aspect; a room with a least length, a stairwell, keeps the side's)."""
    area_cells = prog.areas_m2[k] / prog.options.spine_cell_m**2
    if w * depth <= prog.options.spine_column_fill_max * area_cells or (prog.min_length_m and prog.min_length_m[k] > 0):
        return depth
    short = max(int(np.ceil(area_cells / w)), _min_side(prog, k), 2 * _cells(prog.options.shared_wall_min_m, prog))
    if np.isfinite(prog.max_aspect(k)):
        short = max(short, int(np.ceil(w / prog.max_aspect(k))))
    return min(depth, short)


def rasterize(rects: dict[int, tuple[int, int, int, int]]) -> np.ndarray:
    """Padded owner array (``[x, y]``) of room rectangles in cells (index -> (x0, y0, x1, y1)),
    outside everywhere else."""
    xs0 = min(r[0] for r in rects.values())
    ys0 = min(r[1] for r in rects.values())
    xs1 = max(r[2] for r in rects.values())
    ys1 = max(r[3] for r in rects.values())
    owner = np.full((xs1 - xs0 + 2, ys1 - ys0 + 2), OUTSIDE, dtype=np.int32)
    for k, (x0, y0, x1, y1) in rects.items():
        owner[x0 - xs0 + 1 : x1 - xs0 + 1, y0 - ys0 + 1 : y1 - ys0 + 1] = k
    assert not np.any(owner == FREE)
    return owner


def random_symmetry(owner: np.ndarray, rng) -> np.ndarray:
    """``owner`` turned by a random quarter turn and mirrored half the time."""
    owner = np.rot90(owner, int(rng.integers(4)))
    if rng.random() < 0.5:
        owner = owner[::-1, :]
    return np.ascontiguousarray(owner)
