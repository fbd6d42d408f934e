"""The cell grid a floorplan is grown on: cell size, footprint mask and labels.

Rooms are sets of square cells of side ``cell_m`` (a multiple of :data:`SNAP_M`), so
every wall lands on the 5 cm snapping grid. The owner array is padded with one ring of
:data:`OUTSIDE` cells so neighbour look-ups never fall off the array.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

SNAP_M = 0.05
"""Every coordinate of the floorplan is a multiple of this."""
TARGET_CELLS = 600
"""Roughly how many cells the footprint is cut into (sets the cell size)."""
MIN_CELL_M = 0.3
"""Smallest cell side."""
MAX_CELL_M = 1.0
"""Largest cell side."""
ASPECT_RANGE = (1.0, 1.6)
"""Range the footprint's long/short side ratio is drawn from."""
L_SHAPE_PROB = 0.35
"""Chance of an L-shaped footprint (a corner cut away) for programs of 4+ rooms."""
L_CUT_FRACTION = (0.12, 0.25)
"""Share of the bounding rectangle the L-shape's missing corner takes."""
L_MIN_ROOMS = 4
"""Programs with fewer rooms always get a rectangular footprint."""

OUTSIDE = -1
"""Owner value of a cell outside the footprint."""
FREE = -2
"""Owner value of a footprint cell not yet given to a room."""


@dataclass(frozen=True)
class Grid:
    """A footprint on a cell grid.

    Attributes
    ----------
    cell_m : float
        cell side in meters.
    owner : (nx + 2, ny + 2) int
        :data:`OUTSIDE`, :data:`FREE` or a room index; padded by one outside ring, so
        padded cell ``(i, j)`` spans ``x in [(i - 1) * cell_m, i * cell_m]``.
    """

    cell_m: float
    owner: np.ndarray

    @property
    def shape(self) -> tuple[int, int]:
        return self.owner.shape[0] - 2, self.owner.shape[1] - 2


def cell_size_m(total_area_m2: float) -> float:
    """Cell side for a footprint of ``total_area_m2``: about :data:`TARGET_CELLS` cells."""
    raw = math.sqrt(total_area_m2 / TARGET_CELLS)
    snapped = round(raw / SNAP_M) * SNAP_M
    return round(min(MAX_CELL_M, max(MIN_CELL_M, snapped)), 4)


def make_footprint(total_area_m2: float, n_rooms: int, rng: np.random.Generator) -> Grid:
    """Draw a rectangular or L-shaped footprint holding ``total_area_m2``."""
    cell = cell_size_m(total_area_m2)
    n_cells = total_area_m2 / cell**2
    l_shape = n_rooms >= L_MIN_ROOMS and rng.random() < L_SHAPE_PROB
    cut = rng.uniform(*L_CUT_FRACTION) if l_shape else 0.0
    aspect = rng.uniform(*ASPECT_RANGE)
    long_side = math.sqrt(n_cells / (1.0 - cut) * aspect)
    nx = max(1, round(long_side))
    ny = max(1, round(n_cells / (1.0 - cut) / nx))
    if rng.random() < 0.5:
        nx, ny = ny, nx
    owner = np.full((nx + 2, ny + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    if l_shape:
        _cut_corner(owner, nx, ny, cut, rng)
    return Grid(cell_m=cell, owner=owner)


def _cut_corner(owner: np.ndarray, nx: int, ny: int, cut: float, rng: np.random.Generator) -> None:
    """Mark one corner block of about ``cut`` of the rectangle as outside."""
    fx = rng.uniform(0.35, 0.6)
    cx = max(1, round(nx * fx))
    cy = max(1, round(ny * cut / fx))
    cx, cy = min(cx, nx - 2), min(cy, ny - 2)
    if cx < 1 or cy < 1:
        return
    xs = slice(1, 1 + cx) if rng.random() < 0.5 else slice(nx + 1 - cx, nx + 1)
    ys = slice(1, 1 + cy) if rng.random() < 0.5 else slice(ny + 1 - cy, ny + 1)
    owner[xs, ys] = OUTSIDE


def min_side_cells(min_side_m: float, cell_m: float) -> int:
    """Cells a room must span to be about ``min_side_m`` wide (a little leeway)."""
    return max(2, math.ceil(min_side_m / cell_m - 0.2))
