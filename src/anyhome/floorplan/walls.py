"""Walls of a grown grid: shared and exterior wall runs, room outlines, shape checks.

A *wall run* is a maximal straight piece of wall with the same room on each side. Runs
are kept in cell units until :func:`run_segment` turns them into meters.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

FOUR = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], dtype=bool)


@dataclass(frozen=True)
class Run:
    """A straight wall piece between room ``a`` and room ``b`` (or
    :data:`anyhome.floorplan.grid.OUTSIDE`).

    ``axis`` 0 is a vertical wall ``x = line``, spanning ``y`` in ``[t0, t1]``; axis 1 a
    horizontal wall ``y = line`` spanning ``x``; all in cells (unpadded frame).
    """

    a: int
    b: int
    axis: int
    line: int
    t0: int
    t1: int

    @property
    def length(self) -> int:
        return self.t1 - self.t0

    def touches(self, k: int) -> bool:
        return k in (self.a, self.b)


def wall_runs(owner: np.ndarray) -> list[Run]:
    """Every wall run of a fully grown padded owner array."""
    runs: list[Run] = []
    for axis in (0, 1):
        grid = owner if axis == 0 else owner.T
        lo, hi = grid[:-1, 1:-1], grid[1:, 1:-1]  # cells before / after each line
        for line in np.flatnonzero(np.any(lo != hi, axis=1)).tolist():
            runs.extend(_line_runs(lo[line], hi[line], axis, line))
    return runs


def _line_runs(lo: np.ndarray, hi: np.ndarray, axis: int, line: int) -> list[Run]:
    key = lo.astype(np.int64) * 4096 + hi
    breaks = np.flatnonzero(np.diff(key)) + 1
    starts = np.concatenate([[0], breaks])
    ends = np.concatenate([breaks, [len(key)]])
    return [
        Run(int(lo[s]), int(hi[s]), axis, line, int(s), int(e))
        for s, e in zip(starts.tolist(), ends.tolist())
        if lo[s] != hi[s]
    ]


def runs_between(runs: list[Run], a: int, b: int) -> list[Run]:
    return [r for r in runs if {r.a, r.b} == {a, b}]


def run_segment(run: Run, t0: float, t1: float, cell_m: float) -> tuple[tuple[float, float], ...]:
    """Meters segment of the part ``[t0, t1]`` (cells, may be fractional) of a run."""
    c = round(run.line * cell_m, 4)
    a, b = round(t0 * cell_m, 4), round(t1 * cell_m, 4)
    return ((c, a), (c, b)) if run.axis == 0 else ((a, c), (b, c))


def room_outline(mask: np.ndarray, cell_m: float) -> list[tuple[float, float]]:
    """CCW rectilinear outline of a simply connected padded cell mask, in meters."""
    edges: dict[tuple[int, int], tuple[int, int]] = {}
    inner = mask[1:-1, 1:-1] & mask[:-2, 1:-1] & mask[2:, 1:-1] & mask[1:-1, :-2] & mask[1:-1, 2:]
    edge_cells = mask.copy()
    edge_cells[1:-1, 1:-1] &= ~inner  # cells with a side on the outline, in the same order
    xs, ys = np.nonzero(edge_cells)
    for x, y in zip(xs.tolist(), ys.tolist()):
        x0, y0 = x - 1, y - 1  # unpadded corner
        if not mask[x, y - 1]:
            edges[(x0, y0)] = (x0 + 1, y0)
        if not mask[x + 1, y]:
            edges[(x0 + 1, y0)] = (x0 + 1, y0 + 1)
        if not mask[x, y + 1]:
            edges[(x0 + 1, y0 + 1)] = (x0, y0 + 1)
        if not mask[x - 1, y]:
            edges[(x0, y0 + 1)] = (x0, y0)
    start = min(edges)
    loop, p = [start], edges[start]
    while p != start:
        loop.append(p)
        p = edges[p]
    corners = [q for i, q in enumerate(loop) if not _collinear(loop[i - 1], q, loop[(i + 1) % len(loop)])]
    return [(round(x * cell_m, 4), round(y * cell_m, 4)) for x, y in corners]


def _collinear(p, q, r) -> bool:
    return (q[0] - p[0]) * (r[1] - q[1]) == (q[1] - p[1]) * (r[0] - q[0])


def simply_connected(mask: np.ndarray) -> bool:
    """One 4-connected piece whose outline is a simple polygon (no holes, no pinches).

    ``mask`` must be padded (its border ring False): the complement is then one
    4-connected piece exactly when the outline is a simple closed curve.
    """
    _, pieces = ndimage.label(mask, structure=FOUR)
    if pieces != 1:
        return False
    _, outside = ndimage.label(~mask, structure=FOUR)
    return outside == 1


def narrow_share(mask: np.ndarray, min_side_cells: int) -> float:
    """Share of a room's cells that no ``min_side`` square inside the room covers."""
    opened = ndimage.binary_opening(mask, structure=np.ones((min_side_cells, min_side_cells)))
    return 1.0 - opened.sum() / max(1, mask.sum())


def bbox_aspect(mask: np.ndarray) -> float:
    xs, ys = np.nonzero(mask)
    w, h = xs.max() - xs.min() + 1, ys.max() - ys.min() + 1
    return max(w, h) / min(w, h)

