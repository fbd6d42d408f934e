"""The cell grid a floorplan is grown on: cell size, footprint mask and labels.

Rooms are sets of square cells of side ``cell_m`` (a multiple of :data:`SNAP_M`), so
every wall lands on the 5 cm snapping grid. The owner array is padded with one ring of
:data:`OUTSIDE` cells so neighbour look-ups never fall off the array.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from anyhome.floorplan.options import FloorplanOptions

SNAP_M = 0.05
"""Every coordinate of the floorplan is a multiple of this."""

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


def cell_size_m(total_area_m2: float, opts: FloorplanOptions) -> float:
    """Cell side for a footprint of ``total_area_m2``: about ``opts.footprint_target_cells`` cells."""
    raw = math.sqrt(total_area_m2 / opts.footprint_target_cells)
    snapped = round(raw / SNAP_M) * SNAP_M
    return round(min(opts.cell_max_m, max(opts.cell_min_m, snapped)), 4)


def make_footprint(total_area_m2: float, n_rooms: int, rng: np.random.Generator, opts: FloorplanOptions) -> Grid:
    """Draw a rectangular or L-shaped footprint holding ``total_area_m2``."""
    cell = cell_size_m(total_area_m2, opts)
    n_cells = total_area_m2 / cell**2
    l_shape = n_rooms >= opts.l_shape_min_rooms and rng.random() < opts.l_shape_probability
    cut = rng.uniform(opts.l_cut_min_frac, opts.l_cut_max_frac) if l_shape else 0.0
    aspect = rng.uniform(opts.footprint_aspect_min, opts.footprint_aspect_max)
    long_side = math.sqrt(n_cells / (1.0 - cut) * aspect)
    nx = max(1, round(long_side))
    ny = max(1, round(n_cells / (1.0 - cut) / nx))
    if rng.random() < 0.5:
        nx, ny = ny, nx
    owner = np.full((nx + 2, ny + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    if l_shape:
        _cut_corner(owner, nx, ny, cut, rng, opts)
    return Grid(cell_m=cell, owner=owner)


def _cut_corner(owner: np.ndarray, nx: int, ny: int, cut: float, rng: np.random.Generator, opts: FloorplanOptions) -> None:
    """Mark one corner block of about ``cut`` of the rectangle as outside."""
    fx = rng.uniform(opts.l_corner_x_min_frac, opts.l_corner_x_max_frac)
    cx = max(1, round(nx * fx))
    cy = max(1, round(ny * cut / fx))
    cx, cy = min(cx, nx - 2), min(cy, ny - 2)
    if cx < 1 or cy < 1:
        return
    xs = slice(1, 1 + cx) if rng.random() < 0.5 else slice(nx + 1 - cx, nx + 1)
    ys = slice(1, 1 + cy) if rng.random() < 0.5 else slice(ny + 1 - cy, ny + 1)
    owner[xs, ys] = OUTSIDE


def min_side_cells(min_side_m: float, cell_m: float, opts: FloorplanOptions) -> int:
    """Cells a room must span to be about ``min_side_m`` wide (``opts.min_side_leeway_cells`` leeway)."""
    return max(2, math.ceil(min_side_m / cell_m - opts.min_side_leeway_cells))
