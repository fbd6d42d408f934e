"""Cameras in the plan frame: a bird's-eye view of the whole house and one eye-level
view per room.

A camera follows OpenGL's convention: it looks down its local -z with +y up; the
view matrix maps plan coordinates to camera coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from shapely.geometry import LineString, MultiPoint, Point, Polygon

from anyhome.geometry import footprint_polygon
from anyhome.house import CEILING_RISE, House, Room

BIRDSEYE_FOV_DEG = 30.0
"""Vertical field of view of the bird's-eye camera."""
BIRDSEYE_ELEVATION_DEG = 65.0
"""Bird's-eye camera elevation above the horizon (90 looks straight down)."""
BIRDSEYE_AZIMUTH_DEG = -25.0
"""Bird's-eye camera bearing seen from the house, clockwise from south (negative: west of south)."""
BIRDSEYE_MARGIN = 0.05
"""Share of the half-frame left free around the house."""
EYE_HEIGHT_M = 1.6
"""Eye-level camera height above the floor."""
VIEW_FOV_DEG = 75.0
"""Horizontal (= vertical, images are square) field of view of the eye-level cameras."""
LOOK_AT_HEIGHT_M = 1.0
"""Height of the point the eye-level camera aims at in the far corner, in a room of
:data:`REFERENCE_HEIGHT_M`."""
REFERENCE_HEIGHT_M = 2.7
"""The room height the eye-level framing is tuned for; in a taller room the camera aims
higher by :data:`LOOK_UP_SHARE` of the difference (a double-height hall shows its
height), in an open-air room level at eye height (the sky fills the top of the view)."""
LOOK_UP_SHARE = 0.5
WALL_INSET_M = 0.4
"""How far from the walls an eye-level camera stands."""
MIN_INSET_M = 0.15
"""Smallest inset tried for narrow rooms."""
HEAD_CLEARANCE_M = 0.25
"""No object reaching eye height may be this close to the camera."""
BLOCKER_TOP_M = 1.3
"""Objects taller than this close in front of the camera block its view."""
BLOCKER_REACH_M = 1.5
"""How far ahead of the camera (inside its field of view) a blocker counts."""
BLOCKER_PENALTY_M = 2.0
"""Score lost (in meters of view length) per blocking object."""
NEAR_M = 0.05
"""Near clipping plane of the eye-level cameras."""


@dataclass(frozen=True)
class Camera:
    """A pinhole camera in the plan frame."""

    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    fov_y_deg: float
    width_px: int
    height_px: int
    near_m: float = NEAR_M
    far_m: float = 200.0
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)

    def view_matrix(self) -> np.ndarray:
        """(4, 4) plan -> camera (OpenGL convention)."""
        eye, target = np.asarray(self.eye, float), np.asarray(self.target, float)
        f = target - eye
        f /= np.linalg.norm(f)
        up = np.asarray(self.up, float)
        if abs(f @ up) > 0.999:
            up = np.array([0.0, 1.0, 0.0])
        r = np.cross(f, up)
        r /= np.linalg.norm(r)
        u = np.cross(r, f)
        m = np.eye(4)
        m[0, :3], m[1, :3], m[2, :3] = r, u, -f
        m[:3, 3] = -m[:3, :3] @ eye
        return m

    def projection_matrix(self) -> np.ndarray:
        """(4, 4) OpenGL perspective projection."""
        t = 1.0 / np.tan(np.radians(self.fov_y_deg) / 2)
        aspect = self.width_px / self.height_px
        n, f = self.near_m, self.far_m
        return np.array([
            [t / aspect, 0, 0, 0], [0, t, 0, 0],
            [0, 0, (f + n) / (n - f), 2 * f * n / (n - f)], [0, 0, -1, 0],
        ])

    def intrinsics(self) -> np.ndarray:
        """(3, 3) pixel intrinsics K (OpenCV style: x right, y down, origin top-left corner)."""
        fy = self.height_px / 2 / np.tan(np.radians(self.fov_y_deg) / 2)
        return np.array([[fy, 0, self.width_px / 2], [0, fy, self.height_px / 2], [0, 0, 1.0]])

    def project(self, points: np.ndarray) -> np.ndarray:
        """(n, 3) plan points -> (n, 2) pixel coordinates (x right, y down)."""
        p = np.column_stack([points, np.ones(len(points))]) @ (self.projection_matrix() @ self.view_matrix()).T
        ndc = p[:, :2] / p[:, 3:4]
        return np.column_stack([(ndc[:, 0] + 1) / 2 * self.width_px, (1 - ndc[:, 1]) / 2 * self.height_px])

    def to_record(self) -> dict:
        """JSON-ready description (matrices row-major)."""
        view = self.view_matrix()
        return {
            "eye": [float(x) for x in self.eye], "target": [float(x) for x in self.target],
            "fov_y_deg": self.fov_y_deg, "width_px": self.width_px, "height_px": self.height_px,
            "near_m": self.near_m, "far_m": self.far_m,
            "world_to_camera": np.round(view, 6).tolist(),
            "camera_to_world": np.round(np.linalg.inv(view), 6).tolist(),
            "projection": np.round(self.projection_matrix(), 6).tolist(),
            "intrinsics": np.round(self.intrinsics(), 4).tolist(),
        }


def look_at_height(room: Room) -> float:
    """Height the eye-level camera of ``room`` aims at (see :data:`REFERENCE_HEIGHT_M`)."""
    if room.open_air:
        return EYE_HEIGHT_M
    return LOOK_AT_HEIGHT_M + LOOK_UP_SHARE * max(0.0, room.height - REFERENCE_HEIGHT_M)


def top_height(room: Room) -> float:
    """Highest point of a room's ceiling (its ridge or crown when sloped)."""
    if room.open_air or room.ceiling == "flat":
        return room.height
    xs = [p[0] for p in room.polygon]
    ys = [p[1] for p in room.polygon]
    short = min(max(xs) - min(xs), max(ys) - min(ys))
    return room.height + CEILING_RISE.get(room.ceiling, 0.0) * short


def house_points(house: House) -> np.ndarray:
    """(n, 3) corners of every room at floor and ceiling (ridge) height."""
    pts = [(x, y, z) for r in house.rooms for x, y in r.polygon for z in (0.0, top_height(r))]
    return np.asarray(pts, dtype=float).reshape(-1, 3)


def birdseye_camera(house: House, size_px: int, elevation_deg: float = BIRDSEYE_ELEVATION_DEG,
                    azimuth_deg: float = BIRDSEYE_AZIMUTH_DEG) -> Camera:
    """A camera that frames the whole house from above at ``elevation_deg``."""
    pts = house_points(house)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    centre = (lo + hi) / 2
    centre[2] = 0.0
    el, az = np.radians(elevation_deg), np.radians(azimuth_deg)
    back = np.array([np.cos(el) * np.sin(az), -np.cos(el) * np.cos(az), np.sin(el)])
    if elevation_deg >= 89.9:
        back = np.array([0.0, -1e-3, 1.0])
        back /= np.linalg.norm(back)
    probe = Camera(tuple(centre + back), tuple(centre), BIRDSEYE_FOV_DEG, size_px, size_px)
    rot = probe.view_matrix()[:3, :3]
    rel = (pts - centre) @ rot.T  # camera-frame offsets for a camera at distance 0
    half = np.tan(np.radians(BIRDSEYE_FOV_DEG) / 2) * (1 - BIRDSEYE_MARGIN)
    # a point is in frame when |x|, |y| <= half * (distance - z_rel)
    dist = float(np.max(np.maximum(np.abs(rel[:, 0]), np.abs(rel[:, 1])) / half + rel[:, 2]))
    dist = max(dist, 1.0)
    eye = centre + back * dist
    radius = float(np.linalg.norm(hi - lo))
    return Camera(tuple(eye), tuple(centre), BIRDSEYE_FOV_DEG, size_px, size_px,
                  near_m=max(0.1, (dist - radius) / 2), far_m=dist + 2 * radius + 60.0)


def _inner(poly: Polygon) -> Polygon:
    for inset in (WALL_INSET_M, (WALL_INSET_M + MIN_INSET_M) / 2, MIN_INSET_M):
        inner = poly.buffer(-inset, join_style="mitre")
        if not inner.is_empty:
            if inner.geom_type != "Polygon":
                inner = max(inner.geoms, key=lambda g: g.area)
            return inner
    return Polygon()


def _candidates(house: House, room: Room, poly: Polygon, inner: Polygon) -> list[np.ndarray]:
    """Camera spots: the inset room's corners and a spot inside each door of the room."""
    if inner.is_empty:
        return [np.asarray(poly.representative_point().coords[0])]
    pts = [np.asarray(p) for p in inner.exterior.coords[:-1]]
    for door in house.doors:
        if room.id in door.rooms:
            mid = Point(np.mean(np.asarray(door.segment, dtype=float), axis=0))
            near = inner.exterior.interpolate(inner.exterior.project(mid))
            pts.append(np.asarray(near.coords[0]))
    return pts


def _head_blocked(spot: np.ndarray, boxes: list[tuple[Polygon, float, float]]) -> bool:
    p = Point(spot)
    return any(z0 < EYE_HEIGHT_M + 0.2 and z1 > EYE_HEIGHT_M - 0.3
               and fp.distance(p) < HEAD_CLEARANCE_M for fp, z0, z1 in boxes)


def _blockers(spot: np.ndarray, target: np.ndarray, boxes: list[tuple[Polygon, float, float]]) -> int:
    """Tall objects in the near part of the view cone from ``spot`` towards ``target``."""
    d = target - spot
    heading = np.arctan2(d[1], d[0])
    half = np.radians(VIEW_FOV_DEG) / 2
    fan = [spot] + [spot + BLOCKER_REACH_M * np.array([np.cos(a), np.sin(a)])
                    for a in np.linspace(heading - half, heading + half, 5)]
    cone = Polygon(fan)
    return sum(1 for fp, _, z1 in boxes if z1 > BLOCKER_TOP_M and fp.intersects(cone))


def door_leaf_boxes(house: House) -> list[tuple[Polygon, float, float]]:
    """Footprints and heights of the open door leaves (a camera must not stand in one)."""
    from anyhome.export.architecture import architecture_meshes

    out = []
    for _, mesh, meta in architecture_meshes(house):
        if meta.get("category") == "door_leaf":
            v = np.asarray(mesh.vertices)
            out.append((MultiPoint(v[:, :2]).convex_hull.buffer(0.05), float(v[:, 2].min()), float(v[:, 2].max())))
    return out


def room_camera(house: House, room: Room, size_px: int,
                leaves: list[tuple[Polygon, float, float]] | None = None) -> Camera:
    """An eye-level camera standing near a corner or door of ``room``, looking across
    the room towards the farthest visible corner (the longest diagonal); ``leaves``
    (:func:`door_leaf_boxes`) keep it out of open doors."""
    poly = Polygon(room.polygon).buffer(0)
    inner = _inner(poly)
    boxes = [(footprint_polygon(o.position, o.size, o.yaw), o.position[2], o.position[2] + o.size[2])
             for o in house.objects_in(room.id)]
    boxes += [b for b in (leaves or []) if b[0].intersects(poly)]
    corners = [np.asarray(p, dtype=float) for p in room.polygon]
    sight = poly.buffer(0.01)
    best, best_score = None, -np.inf
    for spot in _candidates(house, room, poly, inner):
        if _head_blocked(spot, boxes):
            continue
        for corner in corners:
            length = float(np.linalg.norm(corner - spot))
            if length < 0.5 or not sight.contains(LineString([spot, corner])):
                continue
            score = length - BLOCKER_PENALTY_M * _blockers(spot, corner, boxes)
            if score > best_score:
                best, best_score = (spot, corner), score
    if best is None:  # nowhere clear: stand at the middle and look along the longest side
        spot = np.asarray(poly.representative_point().coords[0])
        far = max(corners, key=lambda c: float(np.linalg.norm(c - spot)))
        best = (spot, far)
    spot, corner = best
    eye = (float(spot[0]), float(spot[1]), min(EYE_HEIGHT_M, room.height - 0.3))
    target = (float(corner[0]), float(corner[1]), look_at_height(room))
    far_m = float(np.linalg.norm(np.ptp(house_points(house), axis=0))) + 80.0
    return Camera(eye, target, VIEW_FOV_DEG, size_px, size_px, near_m=NEAR_M, far_m=far_m)
