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
    void_sides: int = 2
    """Outline sides the cut-away part touches: 2 for a corner (an L), 1 for a notch in
    the middle of one side (a U)."""

    @property
    def shape(self) -> tuple[int, int]:
        return self.owner.shape[0] - 2, self.owner.shape[1] - 2


def cell_size_m(total_area_m2: float, opts: FloorplanOptions) -> float:
    """Cell side for a footprint of ``total_area_m2``: about ``opts.footprint_target_cells`` cells."""
    raw = math.sqrt(total_area_m2 / opts.footprint_target_cells)
    snapped = round(raw / SNAP_M) * SNAP_M
    return round(min(opts.cell_max_m, max(opts.cell_min_m, snapped)), 4)


def make_footprint(total_area_m2: float, n_rooms: int, rng: np.random.Generator, opts: FloorplanOptions,
                   allow_u: bool = True, min_long_m: float = 0.0) -> Grid:
    """Draw a rectangular, L-shaped (a corner cut away) or U-shaped (a notch in the middle
    of one side; only where ``allow_u``) footprint holding ``total_area_m2``, its long
    side at least ``min_long_m`` (a stairwell's stair runs along it)."""
    cell = cell_size_m(total_area_m2, opts)
    n_cells = total_area_m2 / cell**2
    l_shape = n_rooms >= opts.l_shape_min_rooms and rng.random() < opts.l_shape_probability
    u_shape = allow_u and not l_shape and n_rooms >= opts.u_shape_min_rooms and rng.random() < opts.u_shape_probability
    cut = rng.uniform(opts.l_cut_min_frac, opts.l_cut_max_frac) if l_shape or u_shape else 0.0
    aspect = rng.uniform(opts.footprint_aspect_min, opts.footprint_aspect_max)
    long_side = math.sqrt(n_cells / (1.0 - cut) * aspect)
    nx = max(1, round(long_side), math.ceil(min_long_m / cell - 1e-9))
    ny = max(1, round(n_cells / (1.0 - cut) / nx))
    if rng.random() < 0.5:
        nx, ny = ny, nx
    owner = np.full((nx + 2, ny + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    if l_shape:
        _cut_corner(owner, nx, ny, cut, rng, opts)
    if u_shape and _cut_notch(owner, nx, ny, cut, rng, opts):
        return Grid(cell_m=cell, owner=owner, void_sides=1)
    return Grid(cell_m=cell, owner=owner)


def _cut_notch(owner: np.ndarray, nx: int, ny: int, cut: float, rng: np.random.Generator, opts: FloorplanOptions) -> bool:
    """Mark a block of about ``cut`` of the rectangle in the middle of one of its sides as
    outside (a U), its arms on either side at least ``opts.u_arm_min_frac`` of that side;
    False (nothing cut) where the rectangle is too small for one."""
    along_x = rng.random() < 0.5  # the notch opens in a side running along x (south or north)
    n_along, n_across = (nx, ny) if along_x else (ny, nx)
    width = round(n_along * rng.uniform(opts.u_notch_min_frac, opts.u_notch_max_frac))
    depth = min(round(n_across * cut * n_along / max(width, 1)), n_across - 2)
    arm = (n_along - width) // 2
    if width < 1 or depth < 1 or arm < max(1, round(opts.u_arm_min_frac * n_along)):
        return False
    span = slice(1 + arm, 1 + arm + width)
    across = slice(1, 1 + depth) if rng.random() < 0.5 else slice(n_across + 1 - depth, n_across + 1)
    if along_x:
        owner[span, across] = OUTSIDE
    else:
        owner[across, span] = OUTSIDE
    return True


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
