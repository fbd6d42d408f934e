"""Shared geometry: object footprints, opening zones and the navigation raster.

These functions *are* the definitions of SCENE_FORMAT.md's validity rules; the layout
stage uses them to stay valid by construction and ``anyhome.evaluate`` uses them to
check. Meters everywhere.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from scipy import ndimage
from shapely.geometry import LineString, Polygon

from anyhome.tags import is_floor_layer, tags_for

TOLERANCE_M = 0.01
"""Validity tolerance of SCENE_FORMAT.md (1 cm)."""
DOOR_CLEARANCE_M = 0.8
"""Depth of the keep-clear rectangle on each side of a door opening."""
NAV_CELL_M = 0.05
"""Raster step of the navigability check."""
AGENT_RADIUS_M = 0.25
"""Radius the free space is eroded by in the navigability check."""
NAV_IGNORE_HEIGHT_M = 0.03
"""Objects lower than this (and walkable floor layers, tag ``floor_layer``) do not block navigation."""
WALL_INSET_CELLS = 0.75
"""Room interiors are shrunk by this many cells so a shared wall is at least one cell thick."""
MAX_NAV_CELLS = 4_000_000
"""Most cells the navigation raster may hold (about 30 bytes each at the peak, so the
check never needs more than ~120 MB): a 100 m x 100 m house at 5 cm. A larger house is
rasterized at the smallest coarser step that fits, up to ``MAX_NAV_CELL_M``."""
MAX_NAV_WORK_CELLS = 10 * MAX_NAV_CELLS
"""Most cells the rasterized rooms and obstacles may cover together (their windows
overlap when geometry is stacked): bounds the time of the check."""
MAX_NAV_CELL_M = AGENT_RADIUS_M / 2
"""Coarsest raster step the navigability check accepts; a house that would need a
coarser one (e.g. a 1 km room) is not checked (``NavResult.checked`` is False)."""


# --------------------------------------------------------------------- boxes
def wrap_yaw(yaw: float) -> float:
    """``yaw`` in radians brought into [-pi, pi): the one yaw wrap of the project."""
    return float((yaw + math.pi) % (2 * math.pi) - math.pi)


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


def front_dir(yaw: float) -> np.ndarray:
    """Unit vector an object turned by ``yaw`` faces (its +y, the format's front)."""
    return np.array([-np.sin(yaw), np.cos(yaw)])


def right_dir(yaw: float) -> np.ndarray:
    """Unit vector to the right of an object turned by ``yaw`` (its +x)."""
    return np.array([np.cos(yaw), np.sin(yaw)])


def footprint_polygon(position: Sequence[float], size: Sequence[float], yaw: float) -> Polygon:
    return Polygon(footprint_corners(position, size, yaw))


def floor_coverage(feet: Sequence[Polygon], room: Polygon) -> float:
    """Fraction of ``room``'s floor under the footprints ``feet`` (overlaps counted once):
    the furnishing metric's floor coverage, and what the layout's zones aim at."""
    if not feet or room.area <= 0:
        return 0.0
    return float(shapely.union_all(list(feet)).intersection(room).area / room.area)


def joined_to_first(polys: Sequence[Polygon], gap_m: float) -> set[int]:
    """Indices of ``polys`` joined to the first through a chain of neighbours each at most
    ``gap_m`` apart (a run of pieces along the walls, the first piece first)."""
    if not polys:
        return set()
    joined, frontier = {0}, [0]
    while frontier:
        a = frontier.pop()
        for b in range(len(polys)):
            if b not in joined and polys[a].distance(polys[b]) <= gap_m:
                joined.add(b)
                frontier.append(b)
    return joined


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
    edge: Sequence[Sequence[float] | np.ndarray], points: np.ndarray
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
    cell_m: float = NAV_CELL_M
    """The raster step used (coarser than ``NAV_CELL_M`` only for a very large house)."""
    skipped: str = ""
    """Why the check did not run (empty when it ran)."""
    targets_reached: tuple[bool, ...] = ()
    """For each of the ``targets`` given: whether a reachable cell lies within the agent's
    reach (``agent_radius_m`` + 2 cells) of it."""

    @property
    def checked(self) -> bool:
        return not self.skipped

    @property
    def ok(self) -> bool:
        return self.checked and not self.unreachable_rooms and not self.unreachable_doors


def nav_cell_size(width_m: float, height_m: float, cell_m: float = NAV_CELL_M,
                  max_cells: int = MAX_NAV_CELLS) -> float:
    """The raster step for a ``width_m x height_m`` extent: ``cell_m`` when the raster
    (with its padding) holds at most ``max_cells`` cells, else the smallest step that fits
    (may exceed ``MAX_NAV_CELL_M``: the caller refuses then); ``inf`` for a non-finite extent."""
    if not (np.isfinite(width_m) and np.isfinite(height_m)):
        return float("inf")

    def cells(step: float) -> float:
        return (np.ceil(width_m / step) + 5) * (np.ceil(height_m / step) + 5)

    if cells(cell_m) <= max_cells:
        return cell_m
    step = max(cell_m, float(np.sqrt(width_m * height_m / max_cells)))
    while cells(step) > max_cells:
        step *= 1.05
    return step


def blocks_navigation(
    category: str, height_m: float, support: str, tags: Sequence[str] | None = None
) -> bool:
    """Whether an object's footprint counts as an obstacle for the agent.

    A walkable floor layer (tag ``floor_layer``: rugs, mats) never does. ``tags`` are the
    object's semantic tags; when None they are looked up from ``category`` with
    :func:`anyhome.tags.tags_for`.
    """
    if support not in ("floor", "wall"):
        return False  # on top of something: the supporter already blocks
    if height_m < NAV_IGNORE_HEIGHT_M:
        return False
    if tags is None:
        tags = tags_for(category, category)
    return not is_floor_layer(tags)


def walked_up_to(category: str, height_m: float, support: str, tags: Sequence[str] | None = None) -> bool:
    """Whether an agent must be able to walk up to an object: a blocking floor object,
    stairs excepted (what the navigation check counts as furniture)."""
    return support == "floor" and category != "stairs" and blocks_navigation(category, height_m, support, tags)


def navigability(
    rooms: Iterable[tuple[str, Sequence[Sequence[float]]]],
    doors: Iterable[tuple[str, Sequence[str], Sequence[Sequence[float]]]],
    obstacles: Iterable[Polygon],
    cell_m: float = NAV_CELL_M,
    agent_radius_m: float = AGENT_RADIUS_M,
    targets: Sequence[Polygon] = (),
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
    cells is; a door if a reachable cell lies within ``agent_radius_m + 2 cells`` of it,
    and so is each of ``targets`` (object footprints: can the agent get to it?).
    """
    rooms = list(rooms)
    doors = list(doors)
    polys = {rid: Polygon(p) for rid, p in rooms}
    if not polys:
        return NavResult((), (), 0, 0)
    minx, miny, maxx, maxy = shapely.bounds(shapely.union_all(list(polys.values())))
    step = nav_cell_size(maxx - minx, maxy - miny, cell_m)
    if step > max(cell_m, MAX_NAV_CELL_M):
        return NavResult((), (), 0, 0, cell_m=step, skipped=(
            f"the house spans {maxx - minx:.0f} m x {maxy - miny:.0f} m: a navigation raster "
            f"of at most {MAX_NAV_CELLS:,} cells would need {step:.2f} m cells, coarser than "
            f"the {MAX_NAV_CELL_M} m limit"))
    cell_m = step
    obstacles = list(obstacles)
    work = _window_cells([*polys.values(), *obstacles], cell_m)
    if work > MAX_NAV_WORK_CELLS:
        return NavResult((), (), 0, 0, cell_m=cell_m, skipped=(
            f"rooms and obstacles cover {work:,.0f} raster cells in all (at most "
            f"{MAX_NAV_WORK_CELLS:,}): too much overlapping geometry"))
    pad = 2 * cell_m
    xs = np.arange(minx - pad, maxx + pad, cell_m) + cell_m / 2
    ys = np.arange(miny - pad, maxy + pad, cell_m) + cell_m / 2
    shape = (len(ys), len(xs))
    gx, gy = xs[np.newaxis, :], ys[:, np.newaxis]  # broadcast: no full coordinate arrays
    free = np.zeros(shape, dtype=bool)
    room_of = np.full(shape, -1, dtype=np.int32)
    room_ids = list(polys)
    half = cell_m / 2
    for k, rid in enumerate(room_ids):
        inner = polys[rid].buffer(-WALL_INSET_CELLS * cell_m, join_style="mitre")
        if inner.is_empty:
            continue
        win = _raster_window(inner, gx, gy, xs, ys)
        if win is not None:
            where, mask = win
            free[where] |= mask
            room_of[where][mask] = k
    for _, _, seg in doors:
        zone = LineString(seg).buffer(half * 1.5, cap_style="flat")
        win = _raster_window(zone, gx, gy, xs, ys)
        if win is not None:
            free[win[0]] |= win[1]
    for ob in obstacles:
        win = _raster_window(ob, gx, gy, xs, ys)
        if win is not None:
            free[win[0]] &= ~win[1]
    dist = ndimage.distance_transform_edt(free)
    walkable = dist * cell_m > agent_radius_m
    del dist
    labels, _ = ndimage.label(walkable)
    near = agent_radius_m + 2 * cell_m
    entrance_labels: set[int] = set()
    door_labels: dict[str, set[int]] = {}
    for did, sides, seg in doors:
        zone = LineString(seg).buffer(near)
        win = _raster_window(zone, gx, gy, xs, ys)
        lab = set() if win is None else (
            set(np.unique(labels[win[0]][win[1] & walkable[win[0]]]).tolist()) - {0})
        door_labels[did] = lab
        if "outside" in sides:
            entrance_labels |= lab
    reach = np.isin(labels, list(entrance_labels)) if entrance_labels else np.zeros_like(walkable)
    reached = set(np.unique(room_of[reach]).tolist())
    unreachable_rooms = tuple(rid for k, rid in enumerate(room_ids) if k not in reached)
    unreachable_doors = tuple(
        did for did, lab in door_labels.items() if not (lab & entrance_labels)
    )
    reached_targets = []
    for t in targets:
        win = _raster_window(t.buffer(near), gx, gy, xs, ys)
        reached_targets.append(win is not None and bool(np.any(reach[win[0]] & win[1])))
    return NavResult(unreachable_rooms, unreachable_doors, int(walkable.sum()), int(reach.sum()),
                     cell_m=cell_m, targets_reached=tuple(reached_targets))


def _window_cells(geoms: Sequence, cell_m: float) -> float:
    """Cells the raster windows of ``geoms`` hold together (from their bounds)."""
    if not geoms:
        return 0.0
    b = shapely.bounds(np.array(geoms, dtype=object))
    w = np.nan_to_num((b[:, 2] - b[:, 0]) / cell_m + 1, nan=0.0)
    h = np.nan_to_num((b[:, 3] - b[:, 1]) / cell_m + 1, nan=0.0)
    return float(np.sum(w * h))


def _raster_window(geom, gx: np.ndarray, gy: np.ndarray, xs: np.ndarray, ys: np.ndarray):
    """``(window, mask)``: the raster window of ``geom``'s bounds (a pair of slices) and the
    cells in it whose centre lies inside ``geom``; ``None`` when the window is empty.

    ``gx`` is the ``(1, nx)`` row of cell-centre x and ``gy`` the ``(ny, 1)`` column of y.
    """
    if geom.is_empty:
        return None
    x0, y0, x1, y1 = geom.bounds
    i0, i1 = np.searchsorted(ys, [y0, y1])
    j0, j1 = np.searchsorted(xs, [x0, x1])
    if i0 >= i1 or j0 >= j1:
        return None
    where = (slice(i0, i1), slice(j0, j1))
    return where, shapely.contains_xy(geom, gx[:, j0:j1], gy[i0:i1, :])


def raster_mask(geom, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Boolean ``(len(ys), len(xs))`` mask of the raster cells (centres ``xs`` by ``ys``)
    whose centre lies inside ``geom``; only its bounding-box window is tested."""
    gx, gy = xs[None, :], ys[:, None]
    mask = np.zeros((len(ys), len(xs)), dtype=bool)
    win = _raster_window(geom, gx, gy, xs, ys)
    if win is not None:
        mask[win[0]] = win[1]
    return mask
