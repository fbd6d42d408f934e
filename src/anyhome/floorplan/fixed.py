"""Floorplans inside a given footprint (``solve_floorplan(..., footprint=...)``).

An upper storey must fill the ground floor's footprint exactly. Supported: an
axis-aligned rectangle whose corners lie on the 5 cm grid; the program's target areas
are scaled to fill it and the slicing search lays the rooms out inside it, with the same
hard checks as a free plan. Rooms at fixed rectangles (``fixed=``, a stairwell at the
same place on every level) are not supported yet: they raise a one-line
:class:`~anyhome.errors.FloorplanError`, as does any other footprint shape.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING

import numpy as np
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from anyhome.errors import FloorplanError
from anyhome.floorplan.grid import FREE, OUTSIDE, SNAP_M, Grid, cell_size_m

if TYPE_CHECKING:
    from anyhome.floorplan.program import Program
    from anyhome.floorplan.solver import Layout


def footprint_rect(footprint: object) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of a rectangular footprint (shapely polygon or list of points)."""
    try:
        poly = footprint if isinstance(footprint, BaseGeometry) else Polygon(footprint)
    except (TypeError, ValueError) as e:
        raise FloorplanError(f"footprint is not a polygon: {e}") from None
    if not isinstance(poly, Polygon) or poly.is_empty or not poly.is_valid:
        raise FloorplanError("footprint must be one valid polygon")
    x0, y0, x1, y1 = poly.bounds
    if abs(poly.area - (x1 - x0) * (y1 - y0)) > 1e-6 or poly.interiors:
        raise FloorplanError("footprint must be an axis-aligned rectangle (other shapes are not supported yet)")
    for v in (x0, y0, x1, y1):
        if abs(v / SNAP_M - round(v / SNAP_M)) > 1e-6:
            raise FloorplanError(f"footprint corner {v} is not on the {SNAP_M} m grid")
    return x0, y0, x1, y1


def rect_grid(width_m: float, depth_m: float, prog: Program) -> Grid:
    """A grid filling a ``width_m`` x ``depth_m`` rectangle exactly: the cell is the
    largest multiple of the 5 cm snap dividing both sides, no larger than a free
    plan's cell of that area."""
    a, b = round(width_m / SNAP_M), round(depth_m / SNAP_M)
    g = math.gcd(a, b)
    most = max(1, int(cell_size_m(width_m * depth_m, prog.options) / SNAP_M + 1e-9))
    d = max(k for k in range(1, min(g, most) + 1) if g % k == 0)
    nx, ny = a // d, b // d
    owner = np.full((nx + 2, ny + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    return Grid(cell_m=round(d * SNAP_M, 4), owner=owner)


def solve_in_footprint(prog: Program, rng: np.random.Generator, footprint: object | None,
                       fixed: dict[str, tuple[float, float, float, float]]) -> Layout:
    """The best valid layout of ``prog`` filling ``footprint`` (see the module doc)."""
    from anyhome.floorplan.solver import _attempt, best_attempt

    if fixed:
        raise FloorplanError(f"rooms at fixed places ({', '.join(sorted(fixed))}) are not supported yet")
    if footprint is None:
        raise FloorplanError("a footprint is needed")
    x0, y0, x1, y1 = footprint_rect(footprint)
    grid = rect_grid(x1 - x0, y1 - y0, prog)
    scale = (x1 - x0) * (y1 - y0) / float(prog.areas_m2.sum())
    scaled = dataclasses.replace(prog, areas_m2=prog.areas_m2 * scale)
    best = best_attempt(lambda _: _attempt(scaled, rng, prog.options, grid), prog.n, prog.options,
                        f" in the {x1 - x0:g} x {y1 - y0:g} m footprint")
    return dataclasses.replace(best, origin=(x0, y0))
