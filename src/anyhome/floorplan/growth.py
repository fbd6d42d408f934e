"""Grow rooms from seed cells until they fill the footprint (ProcTHOR-style).

Three phases: rectangles grow a row or column at a time, the room furthest behind its
target first, keeping a square-ish aspect (hallways grow to corridor width, then only
lengthwise); rooms still short of their target then grow L/U arms from runs of free
cells at least a minimum width long; leftover pockets finally go to the neighbouring
room furthest behind its target.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from anyhome.floorplan.grid import FREE, Grid

GROW_ASPECT = 1.5
"""Long/short ratio a rectangle room grows to before it must widen."""
GROW_ASPECT_HARD = 2.2
"""Long/short ratio a rectangle room may reach when widening is blocked."""
ARM_GROW_BELOW = 0.97
"""A room grows L/U arms while it holds less than this share of its target."""
FOUR = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]], dtype=bool)


@dataclass(frozen=True)
class Goal:
    """What one room grows toward.

    Attributes
    ----------
    target_cells : float
    min_side_cells : int
        narrowest arm a room may grow.
    corridor_axis : int or None
        for hallways, the axis (0 = x, 1 = y) they lengthen along.
    """

    target_cells: float
    min_side_cells: int
    corridor_axis: int | None = None


def grow_rooms(
    grid: Grid, seeds: list[tuple[int, int]], goals: list[Goal], rng: np.random.Generator
) -> np.ndarray:
    """Return a copy of ``grid.owner`` with every footprint cell given to a room."""
    owner = grid.owner.copy()
    rects = [[x, x + 1, y, y + 1] for x, y in seeds]
    for k, (x, y) in enumerate(seeds):
        owner[x, y] = k
    order = rng.random(len(seeds))
    _grow_rectangles(owner, rects, goals, order, rng)
    _grow_arms(owner, goals, order, rng)
    _fill_pockets(owner, goals)
    return owner


def _grow_rectangles(owner, rects, goals, order, rng) -> None:
    active = set(range(len(rects)))
    while active:
        k = min(active, key=lambda r: (_rect_area(rects[r]) / goals[r].target_cells, order[r]))
        if _rect_area(rects[k]) >= goals[k].target_cells or not _grow_rect(
            owner, rects[k], k, goals[k], rng
        ):
            active.discard(k)


def _rect_area(rect: list[int]) -> int:
    return (rect[1] - rect[0]) * (rect[3] - rect[2])


def _strip(owner: np.ndarray, rect: list[int], side: int) -> np.ndarray:
    x0, x1, y0, y1 = rect
    return (
        owner[x1, y0:y1],
        owner[x0 - 1, y0:y1],
        owner[x0:x1, y1],
        owner[x0:x1, y0 - 1],
    )[side]


def _side_order(rect: list[int], goal: Goal, rng: np.random.Generator) -> list[tuple[int, float]]:
    """Sides (0: +x, 1: -x, 2: +y, 3: -y) to try, each with the aspect it leads to."""
    w, h = rect[1] - rect[0], rect[3] - rect[2]
    x_sides = [(s, max(w + 1, h) / min(w + 1, h)) for s in rng.permutation([0, 1]).tolist()]
    y_sides = [(s, max(w, h + 1) / min(w, h + 1)) for s in rng.permutation([2, 3]).tolist()]
    if goal.corridor_axis is not None:
        width = w if goal.corridor_axis == 1 else h
        along, across = (x_sides, y_sides) if goal.corridor_axis == 0 else (y_sides, x_sides)
        if width < goal.min_side_cells:
            return [(s, 1.0) for s, _ in across + along]
        return [(s, 1.0) for s, _ in along]
    first, second = (x_sides, y_sides) if w < h or (w == h and rng.random() < 0.5) else (y_sides, x_sides)
    return first + second


def _grow_rect(owner, rect, k, goal, rng) -> bool:
    options = _side_order(rect, goal, rng)
    for limit in (GROW_ASPECT, GROW_ASPECT_HARD):
        for side, aspect in options:
            if aspect <= limit and np.all(_strip(owner, rect, side) == FREE):
                _strip(owner, rect, side)[:] = k
                rect[(1, 0, 3, 2)[side]] += (1, -1, 1, -1)[side]
                return True
    return False


def _grow_arms(owner, goals, order, rng) -> None:
    counts = np.bincount(owner[owner >= 0], minlength=len(goals)).astype(float)
    targets = np.array([g.target_cells for g in goals])
    active = set(range(len(goals)))
    while active:
        k = min(active, key=lambda r: (counts[r] / targets[r], order[r]))
        if counts[k] >= ARM_GROW_BELOW * targets[k]:
            active.discard(k)
            continue
        run = _best_arm(owner, k, goals[k].min_side_cells, rng)
        if run is None:
            active.discard(k)
            continue
        owner[run] = k
        counts[k] += len(run[0])


def _best_arm(owner: np.ndarray, k: int, min_run: int, rng: np.random.Generator):
    """Longest run (>= ``min_run``) of free cells along one side of room ``k``."""
    mine = owner == k
    free = owner == FREE
    best, best_len = None, min_run - 1
    for axis, step in ((0, 1), (0, -1), (1, 1), (1, -1)):
        front = free & np.roll(mine, step, axis=axis)
        for line in np.unique(np.nonzero(front)[axis]):
            cells = np.take(front, line, axis=axis)
            for a, b in _runs(cells):
                length = b - a + rng.random() * 0.5
                if length > best_len:
                    idx = np.arange(a, b)
                    best = (np.full_like(idx, line), idx) if axis == 0 else (idx, np.full_like(idx, line))
                    best_len = length
    return best


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """Half-open index ranges of the True runs of a 1-D bool array."""
    padded = np.concatenate([[False], flags, [False]]).astype(np.int8)
    d = np.diff(padded)
    return list(zip(np.flatnonzero(d == 1).tolist(), np.flatnonzero(d == -1).tolist()))


def _fill_pockets(owner: np.ndarray, goals: list[Goal]) -> None:
    labels, n = ndimage.label(owner == FREE, structure=FOUR)
    if n == 0:
        return
    counts = np.bincount(owner[owner >= 0], minlength=len(goals)).astype(float)
    targets = np.array([g.target_cells for g in goals])
    for lab in range(1, n + 1):
        pocket = labels == lab
        ring = ndimage.binary_dilation(pocket, structure=FOUR) & ~pocket
        near = np.unique(owner[ring & (owner >= 0)])
        if near.size == 0:
            continue
        k = int(near[np.argmax((targets[near] - counts[near]) / targets[near])])
        owner[pocket] = k
        counts[k] += pocket.sum()
