"""Free space of one room (shared by layout and refine): walls, openings, placed objects,
vectorized validity (the walkways: :mod:`anyhome.navgrid`).

The checks here are *stricter* than the definitions in :mod:`anyhome.geometry` (small
margins everywhere), so a pose accepted here stays valid after house.json rounds it to
0.1 mm and when the evaluator re-checks it with the shapely definitions.
"""

from __future__ import annotations

import functools
import math
import operator
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from anyhome.geometry import TOLERANCE_M, blocks_navigation, opening_zone
from anyhome.house import Door, Floorplan, HouseObject, Room

if TYPE_CHECKING:
    from anyhome.navgrid import Obstacle

EPS_COLLIDE_M = 0.002
"""Two boxes may touch or overlap by at most this much (the contract allows 1 cm)."""
DOOR_MARGIN_M = 0.015
"""Gap kept between a floor object and a door's keep-clear rectangle."""
INSIDE_TOL_M = 0.004
VIEW_CLEAR_M = 0.6
"""Floor objects up to this tall may stand in a sightline (a coffee table); taller ones not."""
"""How far a footprint may poke out of its room polygon (the contract allows 1 cm)."""
WALL_OPENING_MARGIN_M = 0.05
"""Gap kept along a wall between a wall object and a door or window opening."""
CEILING_GAP_M = 0.05
"""Gap kept between the top of a wall or on-top object and the ceiling."""
NO_COLLISION_M = TOLERANCE_M - 1e-6
"""Footprints overlapping by less than this (:func:`sat_overlap`) do not collide as
:func:`anyhome.geometry.boxes_collide` tests them (each shrunk by half the tolerance,
they are apart)."""


@dataclass(frozen=True)
class Wall:
    """One polygon edge of a room, seen from inside (``n`` points into the room)."""

    index: int
    a: np.ndarray
    b: np.ndarray
    u: np.ndarray
    n: np.ndarray
    length: float
    openings: tuple[tuple[float, float, float, float, bool], ...]
    """(t0, t1, z0, z1, is_door) of each door or window on this wall, t in meters from a."""

    @functools.cached_property
    def yaw(self) -> float:
        """Yaw of an object whose back is on this wall and whose front faces the room (made once)."""
        return float(np.arctan2(-self.n[0], self.n[1]))


def rect_corners(xy: npt.ArrayLike, wd: npt.ArrayLike, yaw: npt.ArrayLike) -> np.ndarray:
    """Footprint corners of many boxes, as :func:`anyhome.geometry.footprint_corners`.

    Parameters
    ----------
    xy : (n, 2) float
    wd : (2,) or (n, 2) float, width and depth
    yaw : (n,) float

    Returns
    -------
    corners : (n, 4, 2) float, back-left, back-right, front-right, front-left
    """
    if (isinstance(xy, np.ndarray) and xy.shape == (1, 2) and isinstance(wd, (tuple, list)) and len(wd) == 2
            and isinstance(yaw, (tuple, list)) and len(yaw) == 1):  # one box: on Python floats
        return _rect_corners_one(xy, wd, yaw)
    xy_a = np.asarray(xy, dtype=float).reshape(-1, 2)
    n = len(xy_a)
    yaw_a = np.asarray(yaw, dtype=float).reshape(-1)
    if len(yaw_a) != n:
        yaw_a = np.broadcast_to(yaw_a, (n,))
    if isinstance(wd, (tuple, list)) and len(wd) == 2:  # one size: the same arithmetic on floats
        hw, hd = float(wd[0]) / 2.0, float(wd[1]) / 2.0
        lx = np.array([[-hw], [hw], [hw], [-hw]])  # a sign flip is exact
        ly = np.array([[-hd], [-hd], [hd], [hd]])
    elif (wd_a := np.asarray(wd, dtype=float)).ndim == 1:
        lx = ((wd_a[0] / 2.0) * _SIGN_X)[:, None]  # -hw, hw, hw, -hw (a sign flip is exact)
        ly = ((wd_a[1] / 2.0) * _SIGN_Y)[:, None]
    else:
        wd_a = np.broadcast_to(wd_a, (n, 2))
        lx = _SIGN_X[:, None] * (wd_a[:, 0] / 2.0)[None]
        ly = _SIGN_Y[:, None] * (wd_a[:, 1] / 2.0)[None]
    c, s = np.cos(yaw_a), np.sin(yaw_a)
    # (x or y, corner, pose): each row a scalar times a contiguous vector (faster than (n, 4))
    out = np.empty((2, 4, n))
    x, y = out[0], out[1]
    np.multiply(lx, c, out=x)  # lx * c - ly * s + x0, in place
    x -= ly * s
    x += xy_a[:, 0]
    np.multiply(lx, s, out=y)
    y += ly * c
    y += xy_a[:, 1]
    return out.transpose(2, 1, 0)


def _rect_corners_one(xy: np.ndarray, wd: Sequence[float], yaw: Sequence[float]) -> np.ndarray:
    """:func:`rect_corners` of one box, on Python floats (the same operations, in the same order)."""
    (x0, y0), = xy.tolist()
    hw, hd = float(wd[0]) / 2.0, float(wd[1]) / 2.0
    t = float(yaw[0])
    c, s = math.cos(t), math.sin(t)
    out = np.empty((1, 4, 2))
    out[0] = [((lx * c) - (ly * s) + x0, (lx * s) + (ly * c) + y0)
              for lx, ly in ((-hw, -hd), (hw, -hd), (hw, hd), (-hw, hd))]
    return out


_SIGN_X = np.array([-1.0, 1.0, 1.0, -1.0])
_SIGN_Y = np.array([-1.0, -1.0, 1.0, 1.0])


def _axes(c: np.ndarray) -> np.ndarray:
    e = np.stack([c[:, 1] - c[:, 0], c[:, 3] - c[:, 0]], 1)
    return e / np.maximum(np.sqrt(np.add.reduce(e * e, axis=-1, keepdims=True)), 1e-12)  # as np.linalg.norm


def sat_overlap(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Separating-axis overlap of rectangles.

    Parameters
    ----------
    a : (n, 4, 2) float, b : (m, 4, 2) float

    Returns
    -------
    overlap : (n, m) float, the smallest interval overlap over the separating axes: > 0 is
        the penetration depth, < 0 a separation (the largest gap along one of the axes).
        Pairs of axis-aligned rectangles and pairs whose bounding boxes are more than
        5 cm apart get the (exact, resp. conservative) bounding-box value.
    """
    if len(a) == 0 or len(b) == 0:
        return np.zeros((len(a), len(b)))
    amin, amax = _cmin(a), _cmax(a)
    bmin, bmax = _cmin(b), _cmax(b)
    ox = np.minimum(amax[:, 0, None], bmax[None, :, 0]) - np.maximum(amin[:, 0, None], bmin[None, :, 0])
    oy = np.minimum(amax[:, 1, None], bmax[None, :, 1]) - np.maximum(amin[:, 1, None], bmin[None, :, 1])
    out = np.minimum(ox, oy)
    al_a, al_b = _aligned(a), _aligned(b)
    need = ~(al_a[:, None] & al_b[None]) & (out > -0.05)
    if np.count_nonzero(need):
        i, j = need.nonzero()
        out[i, j] = _sat_pairs(a[i], b[j])
    return out


_BOX_EDGE_M = 1e-9
"""Points this close to an axis-aligned rectangle's outline are left to shapely."""


def _convex(v: np.ndarray) -> bool:
    """Whether the CCW polygon of vertices ``v`` (n, 2) turns left (or goes straight) at every vertex."""
    e = np.roll(v, -1, 0) - v
    f = np.roll(e, -1, 0)
    return bool(np.all(e[:, 0] * f[:, 1] - e[:, 1] * f[:, 0] >= 0.0))


def _axis_box(ring: np.ndarray) -> tuple[float, float, float, float] | None:
    """(x0, y0, x1, y1) of a closed ring (5, 2) that is an axis-aligned rectangle, else None."""
    if len(ring) != 5:
        return None
    x0, y0 = ring.min(0)
    x1, y1 = ring.max(0)
    corners = {(float(x), float(y)) for x, y in ring[:4]}
    if corners != {(x0, y0), (x1, y0), (x1, y1), (x0, y1)}:
        return None
    return float(x0), float(y0), float(x1), float(y1)


_SAT_SLACK_M = 1e-9
"""Rounding allowed for in :func:`overlap_above` (m)."""


def overlap_above(a: np.ndarray, b: np.ndarray, thr: float, inclusive: bool = False,
                  pairs: np.ndarray | None = None) -> np.ndarray:
    """``sat_overlap(a, b) > thr`` (``inclusive``: ``>=``), (n, m) bool, separating axes
    tested only for pairs whose bounding boxes overlap by ``thr`` or more (the overlap
    along a rectangle's own axes is at most that along x or y); pairs further apart are
    False. For a negative ``thr`` (a margin) this can differ from ``sat_overlap``, whose
    edge axes may understate the gap of two turned rectangles: the bounding-box gap is a
    true lower bound of it. ``pairs`` (n, m) bool: only these pairs can be True;
    ``amin``, ``amax``: ``a``'s bounds when known."""
    n, m = len(a), len(b)
    if n == 0 or m == 0:
        return np.zeros((n, m), dtype=bool)
    amin, amax = _cmin(a), _cmax(a)
    bmin, bmax = _cmin(b), _cmax(b)
    ox = np.minimum(amax[:, 0, None], bmax[None, :, 0]) - np.maximum(amin[:, 0, None], bmin[None, :, 0])
    oy = np.minimum(amax[:, 1, None], bmax[None, :, 1]) - np.maximum(amin[:, 1, None], bmin[None, :, 1])
    bb = np.minimum(ox, oy)
    out = bb >= thr if inclusive else bb > thr
    maybe = bb >= thr - _SAT_SLACK_M
    if pairs is not None:
        out &= pairs
        maybe &= pairs
    al_a, al_b = _aligned(a), _aligned(b)
    need = maybe & ~(al_a[:, None] & al_b[None]) & (bb > -0.05)
    if np.count_nonzero(need):
        i, j = need.nonzero()
        ov = _sat_pairs(a[i], b[j])
        out[i, j] = ov >= thr if inclusive else ov > thr
    return out


def _box_in(lo: np.ndarray, hi: np.ndarray, box: tuple[float, float, float, float], e: float, outer: bool = True
            ) -> tuple[np.ndarray, np.ndarray | None]:
    """Whether all corners of footprints of bounds ``lo``, ``hi`` (2, n), or points (``lo`` is
    ``hi``), lie in ``box`` (x0, y0, x1, y1) shrunk by ``e``, and (``outer``, else None) whether
    they lie in it grown by ``e``, (n,) each; the one test of a box in this module."""
    x0, y0, x1, y1 = box
    inner = lo[0] > x0 + e
    inner &= hi[0] < x1 - e
    inner &= lo[1] > y0 + e
    inner &= hi[1] < y1 - e
    if not outer:
        return inner, None
    out = lo[0] > x0 - e
    out &= hi[0] < x1 + e
    out &= lo[1] > y0 - e
    out &= hi[1] < y1 + e
    return inner, out


_ZONE_KIND, _SIGHTLINE, _PLACED = 0, 1, 2
"""Kinds of what a pose may not overlap (:meth:`RoomSpace._blockers`)."""
_PAIR_MARGIN_M = 0.01
"""Bounds further apart than the cap plus this are not compared in :meth:`RoomSpace.clearance` (m)."""
_PAIR_SLACK_M = 1e-6
"""Rounding allowed for when pairs are found by their bounds (:func:`_any_overlap`, m)."""


def _any_overlap(a: np.ndarray, alo: np.ndarray, ahi: np.ndarray, idx: np.ndarray, tab: tuple[np.ndarray, ...],
                 pairs: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None) -> np.ndarray:
    """Whether each pose ``a[idx]`` overlaps some row ``j`` of ``tab`` by more than its ``thr[j]``
    (or as much, ``inclusive[j]``) as :func:`overlap_above` tests it, (len(idx),) bool, computed
    on the pairs whose bounds overlap by ``thr`` less :data:`_PAIR_SLACK_M` or more along x and
    y only (no other overlaps by ``thr``).

    Parameters
    ----------
    a : (n, 4, 2) float, alo, ahi : (2, n) float, its bounds (:func:`_bounds_t`); idx : (k,) int, the
        rows of ``a`` tested
    tab : the rows tested against (:func:`_table`)
    pairs : (rows of ``idx``, rows of ``tab``) -> bool, the pairs that may overlap at all
    """
    b, f, flags = tab
    bmin, bmax, thr, b_aligned, inclusive = f[:, _LO:_LO + 2], f[:, _HI:_HI + 2], f[:, _THR], flags[:, _ALIGNED], flags[:, _INCL]
    nxlo, nxhi, nylo, nyhi = (f[:, k:k + 1] for k in range(_NEAR, _NEAR + 4))
    lox, loy, hix, hiy = alo[0, idx], alo[1, idx], ahi[0, idx], ahi[1, idx]
    near = lox < nxhi  # (m, k): a row of poses per footprint, contiguous
    near &= hix > nxlo
    near &= loy < nyhi
    near &= hiy > nylo
    j, i = near.nonzero()
    if pairs is not None and len(i):
        keep = pairs(i, j)
        i, j = i[keep], j[keep]
    out = np.zeros(len(idx), dtype=bool)
    if not len(i):
        return out
    ox = np.minimum(hix[i], bmax[j, 0]) - np.maximum(lox[i], bmin[j, 0])
    oy = np.minimum(hiy[i], bmax[j, 1]) - np.maximum(loy[i], bmin[j, 1])
    bb = np.minimum(ox, oy)
    t, inc = thr[j], inclusive[j]
    hit = np.where(inc, bb >= t, bb > t)
    k = ((bb >= t - _SAT_SLACK_M) & (bb > -0.05)).nonzero()[0]  # as overlap_above, the axes of these
    if k.size:
        ai = a[idx[i[k]]]
        rot = ~(_aligned(ai) & b_aligned[j[k]])
        k, ai = k[rot], ai[rot]
        if k.size:
            ov = _sat_pairs(ai, b[j[k]])
            hit[k] = np.where(inc[k], ov >= t[k], ov > t[k])
    out[i[hit]] = True
    return out


def _per_pose(z: np.ndarray | float, n: int) -> np.ndarray:
    """``z`` (one value, or one per pose) as (n,) float (an array filled is cheaper than ``np.broadcast_to``)."""
    a = np.asarray(z, dtype=float)
    if a.ndim == 0:
        out = np.empty(n)
        out.fill(float(a))
        return out
    return a if a.shape == (n,) else np.broadcast_to(a, (n,))


def _bounds_t(c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(n, 4, 2) corners -> lower and upper bounds, (2, n) each (x then y, contiguous: fast)."""
    t = np.ascontiguousarray(c.transpose(2, 1, 0))
    return (np.minimum(np.minimum(t[:, 0], t[:, 1]), np.minimum(t[:, 2], t[:, 3])),
            np.maximum(np.maximum(t[:, 0], t[:, 1]), np.maximum(t[:, 2], t[:, 3])))


def _blocker_rows(objs: list[Placed]) -> tuple[np.ndarray, ...]:
    """Rows of placed objects as :meth:`RoomSpace._blockers` stacks them."""
    if len(objs) == 1:  # most often: the object placed last
        return objs[0].rows()
    return tuple(np.concatenate(col) for col in zip(*(p.rows() for p in objs), strict=True))


_LO, _HI, _THR, _Z0, _Z1, _NEAR = 0, 2, 4, 5, 6, 7
"""Float columns of a table of rows (:func:`_table`): lower bounds (x, y), upper bounds
(x, y), the overlap allowed, bottom, top, and from ``_NEAR`` on the bounds (x lower, x upper,
y lower, y upper) a pose's bounds must cross to come near enough to overlap."""
_ALIGNED, _INCL, _ZONE, _SIGHT = 0, 1, 2, 3
"""Flag columns of a table of rows: square to the axes, the overlap allowed may be reached,
a door zone, a sightline."""


def _table(c: np.ndarray, thr: float, inclusive: bool, kind: int, z0: np.ndarray | float, z1: np.ndarray | float
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rows of what a pose may not overlap (read-only), one per footprint of ``c`` (m, 4, 2):
    the corners, floats (m, 11) (:data:`_LO` ...: bounds, the overlap ``thr`` each may have,
    bottom ``z0`` and top ``z1``, NaN: at any height, the bounds a pose must cross to come
    within ``thr``) and flags (m, 4) (:data:`_ALIGNED` ...: square to the axes, ``inclusive``:
    it may have that much, a door zone or a sightline by ``kind``)."""
    m = len(c)
    lo, hi = _cmin(c), _cmax(c)
    g = _PAIR_SLACK_M - thr  # a pair overlapping by thr along x (y) has its bounds this close
    f = np.empty((m, 11))
    f[:, _LO:_LO + 2] = lo
    f[:, _HI:_HI + 2] = hi
    f[:, _THR] = thr
    f[:, _Z0] = z0
    f[:, _Z1] = z1
    f[:, _NEAR] = lo[:, 0] - g
    f[:, _NEAR + 1] = hi[:, 0] + g
    f[:, _NEAR + 2] = lo[:, 1] - g
    f[:, _NEAR + 3] = hi[:, 1] + g
    flags = np.empty((m, 4), dtype=bool)
    flags[:, _ALIGNED] = _aligned(c)
    flags[:, _INCL] = inclusive
    flags[:, _ZONE] = kind == _ZONE_KIND
    flags[:, _SIGHT] = kind == _SIGHTLINE
    f.flags.writeable = flags.flags.writeable = False
    return c, f, flags


def storey_doors(floorplan: Floorplan, level: int) -> list[Door]:
    """The doors of storey ``level``: those of its rooms. A door of another storey, above
    or below, is no obstacle on this one (a door below once kept a top-floor bedroom's bed out)."""
    rooms = {r.id for r in floorplan.rooms if r.level == level}
    return [d for d in floorplan.doors if rooms.intersection(d.rooms)]


STAIR_FLOOR_ZONE_TOP_M = 1.0
"""A stair well (the floor of an upper storey over a flight) and the strip of floor at a
flight's foot keep the floor clear: what hangs on a wall from this height up (a painting, a
mirror) may hang over them, as over a landing."""


def stair_blocks(floorplan: Floorplan, room_id: str) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The stairs' zones of room ``room_id`` (:func:`anyhome.floorplan.levels.stair_zones`), as
    corners (4, 2): (the boxes of the flights standing in it, kept clear at every height; the
    zones, kept clear below :data:`STAIR_FLOOR_ZONE_TOP_M`: the strip at a flight's foot, the
    well of a flight from the storey below)."""
    from anyhome.floorplan.levels import stair_zones, stairs_objects

    flights = [np.asarray(rect_corners(np.asarray([o.position[:2]]), o.size[:2], [o.yaw])[0])
               for o in stairs_objects(floorplan) if o.room == room_id]
    return flights, list(stair_zones(floorplan).get(room_id, []))


def _zone_table(zones: np.ndarray, tops: np.ndarray) -> tuple[np.ndarray, ...]:
    """The rows of door zones (m, 4, 2) as :meth:`RoomSpace._blockers` stacks them: a zone of
    top ``inf`` meets a pose at any height, one of a finite top the poses whose bottom is below it."""
    full = np.isinf(tops)
    if full.all():
        return _table(zones, -DOOR_MARGIN_M, True, _ZONE_KIND, np.nan, np.nan)
    parts = [_table(zones[full], -DOOR_MARGIN_M, True, _ZONE_KIND, np.nan, np.nan),
             _table(zones[~full], -DOOR_MARGIN_M, True, _PLACED, -np.inf, tops[~full])]
    order = np.concatenate([np.flatnonzero(full), np.flatnonzero(~full)])
    back = np.argsort(order)  # the rows in the zones' order
    out = tuple(np.concatenate(cols)[back] for cols in zip(*parts, strict=True))
    for a in out:
        a.flags.writeable = False
    return out


def _own_rows(p: Placed) -> tuple[np.ndarray, ...]:
    """The row of one placed object as :meth:`RoomSpace._blockers` stacks it (read-only)."""
    return _table(p.corners[None], EPS_COLLIDE_M, False, _PLACED, p.z0, p.z1)


def _cmin(c: np.ndarray) -> np.ndarray:
    """(n, 4, 2) corners -> (n, 2) lower bounds (faster than ``min(1)`` on a short axis)."""
    return np.minimum(np.minimum(c[:, 0], c[:, 1]), np.minimum(c[:, 2], c[:, 3]))


def _cmax(c: np.ndarray) -> np.ndarray:
    return np.maximum(np.maximum(c[:, 0], c[:, 1]), np.maximum(c[:, 2], c[:, 3]))


def _aligned(c: np.ndarray) -> np.ndarray:
    e = c[:, 1] - c[:, 0]
    return (np.abs(e[:, 0]) < 1e-9) | (np.abs(e[:, 1]) < 1e-9)


_NO_ROWS = _table(np.zeros((0, 4, 2)), 0.0, False, _PLACED, 0.0, 0.0)
"""A table of no rows."""


def _sat_pairs(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Overlap of rectangle a[k] with b[k], (p, 4, 2) each -> (p,)."""
    axes = np.concatenate([_axes(a), _axes(b)], 1)  # (p, 4, 2)
    pa = np.einsum("pkc,pac->pak", a, axes)
    pb = np.einsum("pkc,pac->pak", b, axes)
    ov = np.minimum(pa.max(-1), pb.max(-1)) - np.maximum(pa.min(-1), pb.min(-1))
    return ov.min(-1)


@dataclass
class Placed:
    obj: HouseObject
    corners: np.ndarray
    z0: float
    z1: float
    floor: bool
    nav: Obstacle | None = None
    """What it does to the room's walkways (:class:`anyhome.navgrid.NavGrid`); None when nothing."""
    layer: bool = False
    """A rug laid under furniture (:mod:`anyhome.layout.layers`): only other layers collide with it."""
    _rows: tuple[np.ndarray, ...] | None = field(default=None, repr=False, compare=False)

    def rows(self) -> tuple[np.ndarray, ...]:
        """Its row of the tables :meth:`RoomSpace._blockers` and :meth:`RoomSpace.near` read
        (:func:`_own_rows`), made once."""
        if self._rows is None:
            self._rows = _own_rows(self)
        return self._rows


def room_polygon(room: Room) -> Polygon:
    return orient(Polygon(room.polygon), 1.0)


def room_walls(poly: Polygon, openings: list[tuple[np.ndarray, np.ndarray, float, float, bool]]) -> list[Wall]:
    """Walls of a CCW polygon with the openings (segment ends, z0, z1, is_door) lying on each."""
    pts = np.asarray(poly.exterior.coords)[:-1]
    walls = []
    for i in range(len(pts)):
        a, b = pts[i], pts[(i + 1) % len(pts)]
        v = b - a
        length = float(np.linalg.norm(v))
        if length < 1e-9:
            continue
        u = v / length
        n = np.array([-u[1], u[0]])
        ops = []
        for p, q, z0, z1, is_door in openings:
            dp, dq = (p - a) @ n, (q - a) @ n
            if abs(dp) > 0.02 or abs(dq) > 0.02:
                continue
            t0, t1 = sorted(((p - a) @ u, (q - a) @ u))
            if t1 < -0.02 or t0 > length + 0.02:
                continue
            ops.append((float(t0), float(t1), z0, z1, is_door))
        walls.append(Wall(i, a, b, u, n, length, tuple(ops)))
    return walls


@dataclass
class RoomSpace:
    """Everything the solver needs to test poses in one room."""

    floorplan: Floorplan
    room: Room
    poly: Polygon = field(init=False)
    placed: list[Placed] = field(default_factory=list)
    keep_clear: list[np.ndarray] = field(default_factory=list)
    """Sightlines (corners (4, 2)): between a seat and the TV across from it; no floor
    object taller than ``VIEW_CLEAR_M`` may enter one."""

    def __post_init__(self) -> None:
        self.poly = room_polygon(self.room)
        self.buf = self.poly.buffer(INSIDE_TOL_M, join_style="mitre")
        shapely.prepare(self.buf)
        self.outline = self.poly.buffer(TOLERANCE_M, join_style="mitre")
        """The room as :func:`anyhome.geometry.inside` tests a footprint against it (prepared)."""
        shapely.prepare(self.outline)
        self.vertices = np.asarray(self.poly.exterior.coords)[:-1]
        self.convex = _convex(self.vertices)
        """A convex room: no room vertex can lie inside a footprint whose corners are in ``buf``."""
        self.buf_box = _axis_box(np.asarray(self.buf.exterior.coords)) if not self.buf.interiors else None
        """``buf``'s (x0, y0, x1, y1) when it is an axis-aligned rectangle, else None."""
        self.outline_box = _axis_box(np.asarray(self.outline.exterior.coords)) if not self.outline.interiors else None
        """``outline``'s (x0, y0, x1, y1) when it is an axis-aligned rectangle, else None."""
        self._tables: dict[object, tuple[list[Placed], tuple[np.ndarray, ...]]] = {}
        """Arrays of rows derived from placed objects (:meth:`_rows`)."""
        self.bmin = self.vertices.min(0)
        self.bmax = self.vertices.max(0)
        self._bounds = (self.bmin - INSIDE_TOL_M, self.bmax + INSIDE_TOL_M)
        """What :meth:`valid` keeps footprints within (the bounding box grown by the tolerance)."""
        self._bounds_in_buf = self.buf_box is not None and bool(
            np.all(np.abs(np.concatenate(self._bounds) - np.asarray(self.buf_box)) < _BOX_EDGE_M / 2))
        """Footprints within ``_bounds`` lie within ``buf_box`` grown by :data:`_BOX_EDGE_M`."""
        self.height = float(self.room.height)
        self.area = float(self.poly.area)
        c = self.poly.centroid
        self.centre = np.array([c.x, c.y]) if self.poly.contains(c) else np.array(
            self.poly.representative_point().coords[0]
        )
        openings = []
        zones = []
        self.doors = []
        for d in storey_doors(self.floorplan, self.room.level):
            seg = np.asarray(d.segment, dtype=float)
            openings.append((seg[0], seg[1], 0.0, float(d.height), True))
            z = np.asarray(opening_zone(d.segment).exterior.coords)[:4]
            zb = (z.min(0), z.max(0))
            if np.all(zb[1] >= self.bmin - 0.05) and np.all(zb[0] <= self.bmax + 0.05):
                zones.append(z)
            if self.room.id in d.rooms:
                self.doors.append(d)
        tops = [math.inf] * len(zones)
        if self.floorplan.levels:  # the stairs' flights and the floor at their feet
            flights, floor_only = stair_blocks(self.floorplan, self.room.id)
            zones += flights + floor_only
            tops += [math.inf] * len(flights) + [STAIR_FLOOR_ZONE_TOP_M] * len(floor_only)
        self.door_zones = np.asarray(zones).reshape(-1, 4, 2)
        self.zone_tops = np.asarray(tops, dtype=float)
        """Per door zone, the height from which a pose may overlap it: infinite (never) but
        for a stair well or the strip at a flight's foot (:func:`stair_blocks`)."""
        self.zone_lo, self.zone_hi = self.door_zones.min(1), self.door_zones.max(1)
        self.zone_aligned = _aligned(self.door_zones)
        self._zone_rows = _zone_table(self.door_zones, self.zone_tops)
        """The door zones as :meth:`_blockers` stacks them, first."""
        self._kc: tuple[list[np.ndarray], tuple[np.ndarray, ...]] = ([], ())
        """The sightlines whose rows :meth:`_blockers` made last, and those rows."""
        self._joined: tuple[tuple[np.ndarray, ...], tuple[np.ndarray, ...], tuple[np.ndarray, ...]] | None = None
        """The last table and sightline rows :meth:`_blockers` joined, and the table joined."""
        self.zone_polys = [Polygon(z) for z in zones]
        wzones = []
        level = {r.id: r.level for r in self.floorplan.rooms}
        for w in self.floorplan.windows:
            if level.get(w.room) != self.room.level:  # a window of another storey
                continue
            seg = np.asarray(w.segment, dtype=float)
            openings.append((seg[0], seg[1], float(w.sill), float(w.sill + w.height), False))
            if w.room == self.room.id:
                wzones.append(np.asarray(opening_zone(w.segment, 0.5).exterior.coords)[:4])
        self.window_zones = np.asarray(wzones).reshape(-1, 4, 2)
        self.walls = room_walls(self.poly, openings)
        self.door_points = np.array(
            [np.mean(np.asarray(d.segment, dtype=float), 0) for d in self.doors]
        ).reshape(-1, 2)

    # ------------------------------------------------------------ objects
    def by_id(self, oid: str) -> Placed | None:
        for p in self.placed:
            if p.obj.id == oid:
                return p
        return None

    @property
    def objects(self) -> list[HouseObject]:
        return [p.obj for p in self.placed]

    def _rows(self, key: object, objs: list[Placed], head: tuple[np.ndarray, ...],
              make: Callable[[list[Placed]], tuple[np.ndarray, ...]]) -> tuple[np.ndarray, ...]:
        """Arrays of rows ``head`` then ``make(objs)``, kept under ``key`` from call to call:
        objects placed since are appended, those taken away cut off (the layout places and
        takes back the last ones)."""
        held, tab = self._tables.get(key, ([], head))
        if len(held) == len(objs) and all(map(operator.is_, held, objs)):
            return tab
        n, k = min(len(held), len(objs)), 0
        while k < n and held[k] is objs[k]:
            k += 1
        if k < len(held):  # objects taken away
            top = len(head[0]) + k
            tab = tuple(a[:top] for a in tab)
        if k < len(objs):
            tab = tuple(np.concatenate([a, r]) for a, r in zip(tab, make(objs[k:]), strict=True))
        self._tables[key] = (list(objs), tab)
        return tab

    def near(self, lo: np.ndarray, hi: np.ndarray) -> list[Placed]:
        """Placed objects whose footprint's bounding box meets the box ``lo``-``hi`` (2,)."""
        if not self.placed:
            return []
        f = self._rows("near", self.placed, _NO_ROWS, _blocker_rows)[1]
        cmin, cmax = f[:, _LO:_LO + 2], f[:, _HI:_HI + 2]
        keep = (cmin[:, 0] <= hi[0]) & (cmin[:, 1] <= hi[1]) & (cmax[:, 0] >= lo[0]) & (cmax[:, 1] >= lo[1])
        return [self.placed[i] for i in keep.nonzero()[0].tolist()]

    # ------------------------------------------------------------ validity
    def valid(
        self, corners: np.ndarray, z0: np.ndarray | float, z1: np.ndarray | float, floor: bool, doors: bool = True,
        layer: bool = False,
    ) -> np.ndarray:
        """Mask of poses that are in bounds, collision-free and (floor/wall) clear of doors;
        ``layer``: a rug laid under furniture, tested against the other layers only."""
        n = len(corners)
        if n == 0:
            return np.ones(0, dtype=bool)
        z0, z1 = _per_pose(z0, n), _per_pose(z1, n)
        lo, hi = _bounds_t(corners)
        (bx0, by0), (bx1, by1) = self._bounds
        ok = lo[0] >= bx0
        ok &= lo[1] >= by0
        ok &= hi[0] <= bx1
        ok &= hi[1] <= by1
        limit = self.height if floor else self.height - CEILING_GAP_M
        ok &= z1 <= limit + 1e-9
        if self.buf_box is not None and self.convex:  # a rectangle: most settled by their bounds
            inner, outer = _box_in(lo, hi, self.buf_box, _BOX_EDGE_M, outer=not self._bounds_in_buf)
            if outer is not None:
                ok &= outer  # a corner outside: out
            idx = (ok & ~inner).nonzero()[0]  # a corner a hair from the outline: as below
        else:
            idx = ok.nonzero()[0]
        if idx.size:
            c = corners[idx]
            pin = self._in_buf(c[..., 0].ravel(), c[..., 1].ravel()).reshape(-1, 4)
            pin = pin[:, 0] & pin[:, 1] & pin[:, 2] & pin[:, 3]
            if self.convex:
                inner = pin
            else:
                sub = pin.nonzero()[0]
                inner = np.zeros(len(idx), dtype=bool)
                if sub.size:
                    inner[sub] = ~self._vertex_inside(c[sub])
            ok[idx] = inner
        idx = ok.nonzero()[0]
        if idx.size:
            tall = z1 > VIEW_CLEAR_M
            sightlines = bool(floor and not layer and np.count_nonzero(tall[idx]))
            tab = self._blockers(layer, doors, sightlines)
            zone, sight, bz0, bz1 = tab[2][:, _ZONE], tab[2][:, _SIGHT], tab[1][:, _Z0], tab[1][:, _Z1]

            def may_meet(i: np.ndarray, j: np.ndarray) -> np.ndarray:
                """Door zones meet any pose, sightlines tall ones, objects those overlapping them in z
                (the others' heights are NaN: no overlap)."""
                ii = idx[i]
                return zone[j] | (sight[j] & tall[ii]) | (
                    np.minimum(z1[ii], bz1[j]) - np.maximum(z0[ii], bz0[j]) > EPS_COLLIDE_M)

            if len(tab[0]):
                ok[idx[_any_overlap(corners, lo, hi, idx, tab, pairs=may_meet)]] = False
        return ok

    def _blockers(self, layer: bool, doors: bool, sightlines: bool) -> tuple[np.ndarray, ...]:
        """What a pose may not overlap, stacked (:func:`_table`): the door zones (``doors``), the
        sightlines (``sightlines``) and the placed objects (``layer``: the layers, else all but them)."""
        got = self._rows(layer, [p for p in self.placed if p.layer == layer], self._zone_rows, _blocker_rows)
        if not doors:
            got = tuple(a[len(self.door_zones):] for a in got)
        if not sightlines or not self.keep_clear:
            return got
        held, more = self._kc
        if len(held) != len(self.keep_clear) or not all(map(operator.is_, held, self.keep_clear)):
            more = _table(np.stack(self.keep_clear), EPS_COLLIDE_M, False, _SIGHTLINE, np.nan, np.nan)
            self._kc = (list(self.keep_clear), more)
        j = self._joined
        if j is None or j[1] is not more or len(j[0]) != len(got) or not all(map(operator.is_, j[0], got)):
            j = (got, more, tuple(np.concatenate([a, m]) for a, m in zip(got, more, strict=True)))
            self._joined = j
        return j[2]

    def _in_buf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """``shapely.contains_xy(self.buf, x, y)``; for an axis-aligned rectangle by comparing
        coordinates, shapely asked only about points within a hair of its outline."""
        if self.buf_box is None:
            return shapely.contains_xy(self.buf, x, y)
        pts = np.stack((x, y))
        out, near = _box_in(pts, pts, self.buf_box, _BOX_EDGE_M)
        assert near is not None
        edge = near & ~out
        if np.count_nonzero(edge):
            out[edge] = shapely.contains_xy(self.buf, x[edge], y[edge])
        return out

    def in_outline_box(self, lo: np.ndarray, hi: np.ndarray) -> bool | None:
        """Whether ``outline`` contains a footprint of bounding box ``lo``-``hi`` (2,), settled by
        coordinates for an axis-aligned rectangular room; None: ask shapely."""
        if self.outline_box is None:
            return None
        inner, outer = _box_in(lo, hi, self.outline_box, _BOX_EDGE_M)
        if inner:
            return True
        return False if not outer else None

    def _vertex_inside(self, c: np.ndarray) -> np.ndarray:
        centre = c.mean(1)
        ex, ey = c[:, 1] - c[:, 0], c[:, 3] - c[:, 0]
        hw = np.sqrt(np.add.reduce(ex * ex, axis=1)) / 2  # as np.linalg.norm
        hd = np.sqrt(np.add.reduce(ey * ey, axis=1)) / 2
        ex = ex / (2 * hw[:, None])
        ey = ey / (2 * hd[:, None])
        d = self.vertices[None] - centre[:, None]
        lx = np.abs(np.einsum("nvc,nc->nv", d, ex))
        ly = np.abs(np.einsum("nvc,nc->nv", d, ey))
        return np.any((lx < hw[:, None] - 0.005) & (ly < hd[:, None] - 0.005), 1)

    def clearance(self, corners: np.ndarray, cap_m: float = 1.0) -> np.ndarray:
        """Approximate free distance from each footprint to floor objects and door zones."""
        n = len(corners)
        out = np.full(n, cap_m)
        floor = [p.corners for p in self.placed if p.floor and not p.layer]
        if not n or not (floor or len(self.door_zones)):
            return out
        b = np.concatenate([np.reshape(floor, (-1, 4, 2)), self.door_zones])
        # as min(cap, max(0, -sat_overlap(corners, b).max(1))), on the pairs whose bounds come
        # within the cap only: the others are further apart than it
        lo, hi = _bounds_t(corners)
        bmin, bmax = _cmin(b), _cmax(b)
        g = cap_m + _PAIR_MARGIN_M
        j, i = np.nonzero((lo[0][None] < (bmax[:, 0] + g)[:, None]) & (hi[0][None] > (bmin[:, 0] - g)[:, None])
                          & (lo[1][None] < (bmax[:, 1] + g)[:, None]) & (hi[1][None] > (bmin[:, 1] - g)[:, None]))
        if not len(i):
            return out
        ov = np.minimum(np.minimum(hi[0, i], bmax[j, 0]) - np.maximum(lo[0, i], bmin[j, 0]),
                        np.minimum(hi[1, i], bmax[j, 1]) - np.maximum(lo[1, i], bmin[j, 1]))
        k = np.nonzero(~(_aligned(corners)[i] & _aligned(b)[j]) & (ov > -0.05))[0]  # squareness per pose, then per pair
        if k.size:
            ov[k] = _sat_pairs(corners[i[k]], b[j[k]])
        most = np.full(n, -np.inf)
        np.maximum.at(most, i, ov)
        got = most > -np.inf
        out[got] = np.minimum(cap_m, np.maximum(0.0, -most[got]))
        return out

    def window_penalty(self, corners: np.ndarray) -> np.ndarray:
        if not len(self.window_zones) or not len(corners):
            return np.zeros(len(corners), dtype=bool)
        return np.any(sat_overlap(corners, self.window_zones) > 0.0, 1)

    def wall_clear(self, wall: Wall, t0: np.ndarray, t1: np.ndarray, z0: float, z1: float) -> np.ndarray:
        """Mask of wall intervals [t0, t1] x [z0, z1] that cover no opening of ``wall``.

        A wall object never overlaps a door interval at any height (its footprint would
        otherwise narrow the doorway in the navigation raster).
        """
        ok = np.ones(len(t0), dtype=bool)
        m = WALL_OPENING_MARGIN_M
        for a, b, oz0, oz1, is_door in wall.openings:
            hit = (t1 > a - m) & (t0 < b + m)
            if not is_door and not (z1 > oz0 - m and z0 < oz1 + m):
                continue
            ok &= ~hit
        return ok


def nav_blocks(obj: HouseObject) -> bool:
    return blocks_navigation(obj.category, obj.size[2], obj.support, obj.tags)


