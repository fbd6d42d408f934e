"""Shared geometry: object footprints, opening zones and the navigation raster.

These functions *are* the definitions of SCENE_FORMAT.md's validity rules; the layout
stage uses them to stay valid by construction and ``anyhome.evaluate`` uses them to
check. Meters everywhere.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from scipy import ndimage
from shapely.geometry import LineString, Polygon

TOLERANCE_M = 0.01
"""Validity tolerance of SCENE_FORMAT.md (1 cm)."""
DOOR_CLEARANCE_M = 0.8
"""Depth of the keep-clear rectangle on each side of a door opening."""
NAV_CELL_M = 0.05
"""Raster step of the navigability check."""
AGENT_RADIUS_M = 0.25
"""Radius the free space is eroded by in the navigability check."""
NAV_IGNORE_HEIGHT_M = 0.03
"""Objects lower than this (and rugs) do not block navigation."""
WALL_INSET_CELLS = 0.75
"""Room interiors are shrunk by this many cells so a shared wall is at least one cell thick."""
NAV_IGNORE_CATEGORIES = frozenset({"rug", "carpet", "mat", "yoga_mat", "play_mat"})
"""Flat floor coverings that an agent walks over."""


# --------------------------------------------------------------------- boxes
def footprint_corners(position: Sequence[float], size: Sequence[float], yaw: float) -> np.ndarray:
    """Corners of an object's rotated footprint.

    Returns
    -------
    corners : (4, 2) float
        counter-clockwise: back-left, back-right, front-right, front-left (front is +y local).
    """
    w, d = size[0] / 2.0, size[1] / 2.0
    local = np.array([[-w, -d], [w, -d], [w, d], [-w, d]])
    c, s = np.cos(yaw), np.sin(yaw)
    rot = np.array([[c, -s], [s, c]])
    return local @ rot.T + np.asarray(position[:2], dtype=float)


def footprint_polygon(position: Sequence[float], size: Sequence[float], yaw: float) -> Polygon:
    return Polygon(footprint_corners(position, size, yaw))


def back_edge(position: Sequence[float], size: Sequence[float], yaw: float) -> np.ndarray:
    """(2, 2) endpoints of the footprint's back edge (local -y side)."""
    return footprint_corners(position, size, yaw)[:2]


def boxes_collide(
    pos_a: Sequence[float], size_a: Sequence[float], yaw_a: float,
    pos_b: Sequence[float], size_b: Sequence[float], yaw_b: float,
    tol: float = TOLERANCE_M,
) -> bool:
    """True if two oriented boxes overlap by more than ``tol`` along every axis.

    Vertical overlap is the z-interval intersection; horizontal penetration is tested by
    shrinking both footprints by ``tol / 2`` and asking whether they still intersect.
    """
    z0 = max(pos_a[2], pos_b[2])
    z1 = min(pos_a[2] + size_a[2], pos_b[2] + size_b[2])
    if z1 - z0 <= tol:
        return False
    pa = footprint_polygon(pos_a, size_a, yaw_a).buffer(-tol / 2, join_style="mitre")
    pb = footprint_polygon(pos_b, size_b, yaw_b).buffer(-tol / 2, join_style="mitre")
    if pa.is_empty or pb.is_empty:
        return False
    return pa.intersects(pb) and pa.intersection(pb).area > 1e-9


def inside(poly: Polygon, inner: Polygon, tol: float = TOLERANCE_M) -> bool:
    """``inner`` lies inside ``poly`` up to ``tol``."""
    return poly.buffer(tol, join_style="mitre").contains(inner)


# ------------------------------------------------------------------ openings
def segment_normal(segment: Sequence[Sequence[float]]) -> np.ndarray:
    (x1, y1), (x2, y2) = segment
    v = np.array([x2 - x1, y2 - y1], dtype=float)
    n = np.array([-v[1], v[0]])
    length = np.linalg.norm(n)
    return n / length if length > 0 else n


def opening_zone(segment: Sequence[Sequence[float]], depth_m: float = DOOR_CLEARANCE_M) -> Polygon:
    """The rectangle ``depth_m`` deep on *both* sides of an opening segment."""
    a = np.asarray(segment[0], dtype=float)
    b = np.asarray(segment[1], dtype=float)
    n = segment_normal(segment) * depth_m
    return Polygon([a - n, b - n, b + n, a + n])


def on_boundary(poly: Polygon, segment: Sequence[Sequence[float]], tol: float = TOLERANCE_M) -> bool:
    """The whole segment lies on the polygon's boundary (within ``tol``)."""
    line = LineString(segment)
    return poly.exterior.buffer(tol, join_style="mitre").contains(line)


def wall_interval(
    edge: Sequence[Sequence[float]], points: np.ndarray
) -> tuple[float, float, float]:
    """Project points on an edge: (t_min, t_max) along it in meters and max distance from it."""
    a = np.asarray(edge[0], dtype=float)
    b = np.asarray(edge[1], dtype=float)
    v = b - a
    length = float(np.linalg.norm(v))
    u = v / length
    rel = np.asarray(points, dtype=float) - a
    t = rel @ u
    dist = np.abs(rel @ np.array([-u[1], u[0]]))
    return float(t.min()), float(t.max()), float(dist.max())


def polygon_edges(polygon: Sequence[Sequence[float]]) -> list[tuple[np.ndarray, np.ndarray]]:
    pts = [np.asarray(p, dtype=float) for p in polygon]
    return [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]


# ---------------------------------------------------------------- navigation
@dataclass(frozen=True)
class NavResult:
    """Outcome of the navigability check."""

    unreachable_rooms: tuple[str, ...]
    unreachable_doors: tuple[str, ...]
    free_cells: int
    reachable_cells: int

    @property
    def ok(self) -> bool:
        return not self.unreachable_rooms and not self.unreachable_doors


def blocks_navigation(category: str, height_m: float, support: str) -> bool:
    """Whether an object's footprint counts as an obstacle for the agent."""
    if support not in ("floor", "wall"):
        return False  # on top of something: the supporter already blocks
    if height_m < NAV_IGNORE_HEIGHT_M:
        return False
    return category not in NAV_IGNORE_CATEGORIES


def navigability(
    rooms: Iterable[tuple[str, Sequence[Sequence[float]]]],
    doors: Iterable[tuple[str, Sequence[str], Sequence[Sequence[float]]]],
    obstacles: Iterable[Polygon],
    cell_m: float = NAV_CELL_M,
    agent_radius_m: float = AGENT_RADIUS_M,
) -> NavResult:
    """Rule 6 of SCENE_FORMAT.md.

    Parameters
    ----------
    rooms : (room_id, polygon) pairs
    doors : (door_id, (room_a, room_b or 'outside'), segment) triples
    obstacles : footprints that block the agent (see :func:`blocks_navigation`)

    Every room polygon is rasterized at ``cell_m``; walls (room boundaries) block except
    along door segments; obstacles block; the free space is eroded by the agent radius
    and flood-filled from the entrance door(s). A room is reachable if any of its free
    cells is; a door if a reachable cell lies within ``agent_radius_m + 2 cells`` of it.
    """
    rooms = list(rooms)
    doors = list(doors)
    polys = {rid: Polygon(p) for rid, p in rooms}
    if not polys:
        return NavResult((), (), 0, 0)
    minx, miny, maxx, maxy = shapely.bounds(shapely.union_all(list(polys.values())))
    pad = 2 * cell_m
    xs = np.arange(minx - pad, maxx + pad, cell_m) + cell_m / 2
    ys = np.arange(miny - pad, maxy + pad, cell_m) + cell_m / 2
    gx, gy = np.meshgrid(xs, ys)  # shape (ny, nx)
    free = np.zeros(gx.shape, dtype=bool)
    room_of = np.full(gx.shape, -1, dtype=np.int32)
    room_ids = list(polys)
    half = cell_m / 2
    for k, rid in enumerate(room_ids):
        inner = polys[rid].buffer(-WALL_INSET_CELLS * cell_m, join_style="mitre")
        if inner.is_empty:
            continue
        mask = _raster(inner, gx, gy, xs, ys)
        free |= mask
        room_of[mask] = k
    for _, _, seg in doors:
        zone = LineString(seg).buffer(half * 1.5, cap_style="flat")
        free |= _raster(zone, gx, gy, xs, ys)
    for ob in obstacles:
        free &= ~_raster(ob, gx, gy, xs, ys)
    dist = ndimage.distance_transform_edt(free) * cell_m
    walkable = dist > agent_radius_m
    labels, _ = ndimage.label(walkable)
    near = agent_radius_m + 2 * cell_m
    entrance_labels: set[int] = set()
    door_labels: dict[str, set[int]] = {}
    for did, sides, seg in doors:
        zone = LineString(seg).buffer(near)
        lab = set(np.unique(labels[_raster(zone, gx, gy, xs, ys) & walkable]).tolist()) - {0}
        door_labels[did] = lab
        if "outside" in sides:
            entrance_labels |= lab
    reach = np.isin(labels, list(entrance_labels)) if entrance_labels else np.zeros_like(walkable)
    unreachable_rooms = tuple(
        rid for k, rid in enumerate(room_ids) if not np.any(reach & (room_of == k))
    )
    unreachable_doors = tuple(
        did for did, lab in door_labels.items() if not (lab & entrance_labels)
    )
    return NavResult(unreachable_rooms, unreachable_doors, int(walkable.sum()), int(reach.sum()))


def _raster(geom, gx: np.ndarray, gy: np.ndarray, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Boolean mask of raster cells whose centre lies inside ``geom`` (bbox-windowed)."""
    mask = np.zeros(gx.shape, dtype=bool)
    if geom.is_empty:
        return mask
    x0, y0, x1, y1 = geom.bounds
    i0, i1 = np.searchsorted(ys, [y0, y1])
    j0, j1 = np.searchsorted(xs, [x0, x1])
    if i0 >= i1 or j0 >= j1:
        return mask
    mask[i0:i1, j0:j1] = shapely.contains_xy(geom, gx[i0:i1, j0:j1], gy[i0:i1, j0:j1])
    return mask
