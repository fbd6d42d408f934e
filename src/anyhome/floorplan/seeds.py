"""Seed positions of the rooms: a small force-directed layout of the bubble diagram.

Connected rooms attract, all rooms repel by their size, rooms that need an exterior
wall (habitable ones, the entrance room) are pulled to the footprint's edge and hub
rooms (hallways, entries, service rooms) to its middle.
"""

from __future__ import annotations

import math

import numpy as np

from anyhome.floorplan.grid import FREE, Grid
from anyhome.floorplan.options import FloorplanOptions


def seed_positions(
    grid: Grid,
    areas_m2: np.ndarray,
    edges: list[tuple[int, int]],
    exterior: np.ndarray,
    hub: np.ndarray,
    rng: np.random.Generator,
    opts: FloorplanOptions,
) -> np.ndarray:
    """Position per room, in padded cell units, inside the footprint.

    Parameters
    ----------
    areas_m2 : (n,) float
    edges : index pairs of connected rooms
    exterior : (n,) bool, rooms that need an exterior wall
    hub : (n,) bool, rooms pulled to the middle
    opts : the force layout's gains and step count
    """
    free = np.argwhere(grid.owner == FREE).astype(float) + 0.5  # padded cell centres
    radius = np.sqrt(areas_m2) / grid.cell_m / 2.0
    pos = free[rng.choice(len(free), size=len(areas_m2), replace=len(free) < len(areas_m2))]
    pos = pos + rng.uniform(-opts.seed_jitter_cells, opts.seed_jitter_cells, size=pos.shape)
    forces = _Forces(radius, edges, exterior, _border_cells(grid), opts)
    center = free.mean(axis=0)
    pull = hub[:, None] * opts.seed_center_gain
    inside = grid.owner == FREE
    lo, hi = free.min(axis=0), free.max(axis=0)
    layout = _scalar_layout if len(areas_m2) <= opts.seed_scalar_max_rooms else _array_layout
    return layout(pos, forces, center, pull, free, inside, lo, hi, opts)


def _array_layout(pos: np.ndarray, forces: _Forces, center: np.ndarray, pull: np.ndarray, free: np.ndarray,
                  inside: np.ndarray, lo: np.ndarray, hi: np.ndarray, opts: FloorplanOptions) -> np.ndarray:
    """The force layout's steps from ``pos`` (the rooms' first places), on arrays: each
    room repelled, attracted and pulled to the edge (``forces``) and to ``center``
    (``pull``: each room's gain), then snapped inside the footprint (``free`` cell
    centres, the ``inside`` mask, their least and greatest centres ``lo``, ``hi``), until
    ``seed_force_iterations`` steps or no seed moves more than ``seed_settled_cells``."""
    for _ in range(opts.seed_force_iterations):
        before = pos
        pos = pos + forces.repel(pos) + forces.attract(pos)
        pos = pos + forces.to_edge(pos) + pull * (center - pos)
        pos = _snap_inside(pos, free, inside, lo, hi)
        if float(np.abs(pos - before).max()) <= opts.seed_settled_cells:  # settled: further steps barely move a seed
            break
    return pos


def _scalar_layout(pos: np.ndarray, forces: _Forces, center: np.ndarray, pull: np.ndarray, free: np.ndarray,
                   inside: np.ndarray, lo: np.ndarray, hi: np.ndarray, opts: FloorplanOptions) -> np.ndarray:
    """:func:`_array_layout` in Python floats: the same operations, in the same order,
    on the same doubles (each force of :class:`_Forces`, the pull to the middle,
    :func:`_snap_inside`), so the same positions (tests/floorplan/test_seeds.py compares
    the two); the pull to the edge and the connections' lengths still on arrays."""
    p = pos.tolist()
    n = len(p)
    reach = forces.reach_sum.tolist()
    repel_gain, attract_gain = opts.seed_repel_gain * 0.5, opts.seed_attract_gain * 0.5
    links = list(zip(forces.edges, forces.rest.tolist()))
    cx, cy = center.tolist()
    gains = pull[:, 0].tolist()
    (lo_x, lo_y), (hi_x, hi_y) = lo.tolist(), hi.tolist()
    rows = inside.tolist()
    settled = opts.seed_settled_cells
    for _ in range(opts.seed_force_iterations):
        before = p
        moves = [[0.0, 0.0] for _ in range(n)]
        deltas = [(p[j][0] - p[i][0], p[j][1] - p[i][1]) for (i, j), _ in links]
        dists = _link_lengths(deltas) if deltas else []
        for ((i, j), rest), (dx, dy), dist in zip(links, deltas, dists):  # attraction, in the connections' order
            excess = dist - rest
            if excess > 0:
                pulled = attract_gain * excess
                sx, sy = pulled * dx / dist, pulled * dy / dist
                mi, mj = moves[i], moves[j]
                mi[0] += sx
                mi[1] += sy
                mj[0] -= sx
                mj[1] -= sy
        pushed = []
        for i, (x, y) in enumerate(p):
            rx = ry = 0.0  # repulsion, summed over the other rooms in order
            reach_i = reach[i]
            for j, (xj, yj) in enumerate(p):
                dx, dy = x - xj, y - yj
                dist = math.sqrt(dx * dx + dy * dy) + 1e-6
                over = reach_i[j] - dist if j != i else 0.0
                share = (over if over > 0.0 else 0.0) / dist
                rx, ry = (share * dx, share * dy) if j == 0 else (rx + share * dx, ry + share * dy)
            pushed.append([x + repel_gain * rx + moves[i][0], y + repel_gain * ry + moves[i][1]])
        edge = forces.to_edge(np.array(pushed)).tolist() if len(forces.rooms) else None
        out = []
        for i, (x, y) in enumerate(pushed):
            g = gains[i]
            if edge is None:
                x, y = x + g * (cx - x), y + g * (cy - y)
            else:  # the pull to the middle from where the rooms were pushed, as the arrays' sum
                x, y = x + edge[i][0] + g * (cx - x), y + edge[i][1] + g * (cy - y)
            x = hi_x if (x if x > lo_x else lo_x) > hi_x else (x if x > lo_x else lo_x)
            y = hi_y if (y if y > lo_y else lo_y) > hi_y else (y if y > lo_y else lo_y)
            if not rows[int(x)][int(y)]:
                x, y = free[int(np.argmin(np.linalg.norm(free - np.array([x, y]), axis=1)))].tolist()
            out.append([x, y])
        p = out
        if max(max(abs(a[0] - b[0]), abs(a[1] - b[1])) for a, b in zip(p, before)) <= settled:
            break
    return np.array(p)


def _link_lengths(deltas: list[tuple[float, float]]) -> list[float]:
    """Length (+ 1e-6) of each vector of ``deltas`` as :meth:`_Forces.attract` works it
    out (``np.vecdot``, whose sum of two products is not always Python's)."""
    delta = np.array(deltas)
    return (np.sqrt(np.vecdot(delta, delta)) + 1e-6).tolist()


class _Forces:
    """The force layout's three forces, with what does not change between its steps
    worked out once. Each gives the same floats as the force computed step by step with
    ``np.linalg.norm`` (of one vector: the dot product, ``np.vecdot``; along an axis: the
    sum of squares) and each connection's pull added in the connections' order."""

    def __init__(self, radius: np.ndarray, edges: list[tuple[int, int]], exterior: np.ndarray,
                 border: np.ndarray, opts: FloorplanOptions) -> None:
        n = len(radius)
        self.n, self.opts, self.border = n, opts, border
        self.reach_sum = radius[:, None] + radius[None, :]
        self.diagonal = np.arange(n)
        ij = np.asarray(edges, dtype=np.intp).reshape(-1, 2)
        self.i, self.j = ij[:, 0], ij[:, 1]
        self.rest = opts.seed_rest_distance_frac * (radius[self.i] + radius[self.j])
        self.edges = ij.tolist()
        self.rooms = np.flatnonzero(exterior)
        self.reach = opts.seed_edge_reach_frac * radius[self.rooms]
        self.rows = np.arange(len(self.rooms))

    def repel(self, pos: np.ndarray) -> np.ndarray:
        delta = pos[:, None, :] - pos[None, :, :]
        dist = np.sqrt(np.add.reduce(delta * delta, axis=2)) + 1e-6
        overlap = np.clip(self.reach_sum - dist, 0.0, None)
        overlap[self.diagonal, self.diagonal] = 0.0
        return self.opts.seed_repel_gain * 0.5 * np.sum((overlap / dist)[:, :, None] * delta, axis=1)

    def attract(self, pos: np.ndarray) -> np.ndarray:
        if not len(self.i):
            return np.zeros_like(pos)
        delta = pos[self.j] - pos[self.i]
        dist = np.sqrt(np.vecdot(delta, delta)) + 1e-6
        excess = dist - self.rest
        step = (self.opts.seed_attract_gain * 0.5 * excess)[:, None] * delta / dist[:, None]
        move = [[0.0, 0.0] for _ in range(self.n)]
        for (i, j), pulled, (sx, sy) in zip(self.edges, (excess > 0).tolist(), step.tolist()):
            if pulled:  # added in the connections' order, as Python floats: the same sums
                mi, mj = move[i], move[j]
                mi[0] += sx
                mi[1] += sy
                mj[0] -= sx
                mj[1] -= sy
        return np.array(move)

    def to_edge(self, pos: np.ndarray) -> np.ndarray:
        move = np.zeros_like(pos)
        if not len(self.rooms):
            return move
        gap = self.border[None, :, :] - pos[self.rooms][:, None, :]
        dists = np.sqrt(np.add.reduce(gap * gap, axis=2))  # every room at once
        k = np.argmin(dists, axis=1)
        d = dists[self.rows, k]
        far = d > self.reach
        if far.any():
            i, k, d, reach = self.rooms[far], k[far], d[far], self.reach[far]
            move[i] = self.opts.seed_edge_gain * (self.border[k] - pos[i]) * (1.0 - reach / d)[:, None]
        return move


def _border_cells(grid: Grid) -> np.ndarray:
    """Centres of free cells with a non-footprint 4-neighbour."""
    inside = grid.owner == FREE
    edge = np.zeros_like(inside)
    edge[1:-1, 1:-1] = inside[1:-1, 1:-1] & ~(
        inside[:-2, 1:-1] & inside[2:, 1:-1] & inside[1:-1, :-2] & inside[1:-1, 2:]
    )
    return np.argwhere(edge).astype(float) + 0.5


def _snap_inside(pos: np.ndarray, free: np.ndarray, inside: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Move positions outside the footprint to the nearest free cell centre (``lo``,
    ``hi``: the free cells' least and greatest centres)."""
    pos = np.clip(pos, lo, hi)
    idx = pos.astype(int)  # >= 0.5: the floor
    for i in np.flatnonzero(~inside[idx[:, 0], idx[:, 1]]):
        pos[i] = free[int(np.argmin(np.linalg.norm(free - pos[i], axis=1)))]
    return pos
