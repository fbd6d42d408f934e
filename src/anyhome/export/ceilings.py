"""Ceiling geometry of a room: none (open air), a flat slab, or a sloped surface.

``Room.ceiling`` (see :data:`anyhome.house.CEILING_RISE`):

- ``flat``: a slab from ``height`` to ``height + thickness`` over the room's polygon.
- ``pitched``: two planes rising from the two long sides of the room's bounding box to
  a ridge along its long axis, ``CEILING_RISE["pitched"] x`` the short side above
  ``height``.
- ``vaulted``: a segmental barrel vault spanning the short side (its axis along the long
  side), crown ``CEILING_RISE["vaulted"] x`` the short side above ``height``, drawn as
  :data:`VAULT_SEGMENTS` flat strips.

The sloped kinds are one double-sided surface over the room's polygon (cut into strips
along the ridge so each strip is planar), plus the gable ends: an upright face on every
stretch of the room's outline under the sloped part (from ``height`` up to the ceiling),
so the walls reach the ceiling everywhere. The gables belong to the ceiling node (the
walls stay ``height`` high, as house.json says).
"""

from __future__ import annotations

from typing import cast

import numpy as np
import trimesh
from shapely.geometry import Polygon, box

from anyhome.house import CEILING_RISE, Room

VAULT_SEGMENTS = 8
"""Flat strips approximating a barrel vault."""


def _poly(room: Room) -> Polygon:
    poly = Polygon(room.polygon)
    return poly if poly.is_valid else poly.buffer(0)


def profile(room: Room) -> tuple[int, float, np.ndarray, np.ndarray]:
    """The ceiling across the room: (axis, origin, s, z) with ``axis`` the plan axis (0 x,
    1 y) the profile runs along (the short side), ``origin`` where it starts and the
    knots ``(s, z)``; the height at a point is ``np.interp(p[axis] - origin, s, z)``."""
    x0, y0, x1, y1 = _poly(room).bounds
    axis = 1 if (x1 - x0) >= (y1 - y0) else 0
    lo, span = (y0, y1 - y0) if axis == 1 else (x0, x1 - x0)
    h = room.height
    rise = CEILING_RISE.get(room.ceiling, 0.0) * span
    if room.ceiling == "pitched":
        return axis, lo, np.array([0.0, span / 2, span]), np.array([h, h + rise, h])
    if room.ceiling == "vaulted" and rise > 0:
        radius = (span * span / 4 + rise * rise) / (2 * rise)
        s = np.linspace(0.0, span, VAULT_SEGMENTS + 1)
        z = h + np.sqrt(np.maximum(radius * radius - (s - span / 2) ** 2, 0.0)) - (radius - rise)
        return axis, lo, s, z
    return axis, lo, np.array([0.0, span]), np.array([h, h])


BEAM_WIDTH_M = 0.14
BEAM_DEPTH_M = 0.2
"""Cross-section of a ceiling beam (width across it, depth below the ceiling)."""
BEAM_SPACING_M = 1.1
"""Centre-to-centre distance of beams across a room (joists of a beamed ceiling)."""
COFFER_RIB_WIDTH_M = 0.16
COFFER_RIB_DEPTH_M = 0.14
COFFER_SPACING_M = 1.0
"""Ribs of a coffered ceiling: cross-section and the size of the square coffers."""
MIN_STRUCTURE_ROOM_M = 1.2
"""Rooms narrower than this get no beams or coffers (a corridor's ceiling stays plain)."""


def structure_mesh(room: Room, kind: str) -> trimesh.Trimesh | None:
    """Geometry hung under a flat ceiling: ``beams`` (parallel beams spanning the room's
    short side, :data:`BEAM_SPACING_M` apart, one down the long axis on rooms wider than
    4 m) or ``coffers`` (ribs both ways, square coffers of :data:`COFFER_SPACING_M`),
    clipped to the room's polygon; None for a sloped or open ceiling, an unknown kind or
    a room too narrow for them."""
    if room.open_air or room.ceiling != "flat" or kind not in ("beams", "coffers"):
        return None
    poly = _poly(room)
    x0, y0, x1, y1 = poly.bounds
    if min(x1 - x0, y1 - y0) < MIN_STRUCTURE_ROOM_M:
        return None
    width, depth, step = ((BEAM_WIDTH_M, BEAM_DEPTH_M, BEAM_SPACING_M) if kind == "beams"
                          else (COFFER_RIB_WIDTH_M, COFFER_RIB_DEPTH_M, COFFER_SPACING_M))
    long_x = (x1 - x0) >= (y1 - y0)
    strips = []

    def across(axis_x: bool) -> None:
        """Ribs crossing the room at regular spacing along x (``axis_x``) or y."""
        lo, hi = (x0, x1) if axis_x else (y0, y1)
        n = max(1, int((hi - lo) // step))
        margin = ((hi - lo) - (n - 1) * step) / 2 if n > 1 else (hi - lo) / 2
        for k in range(n):
            c = lo + margin + k * step
            strips.append(box(c - width / 2, y0, c + width / 2, y1) if axis_x else box(x0, c - width / 2, x1, c + width / 2))

    across(long_x)  # beams span the short side: they stand at intervals along the long one
    if kind == "coffers":
        across(not long_x)
    elif min(x1 - x0, y1 - y0) > 4.0:  # a wide room: a spine beam carries the joists
        c = (y0 + y1) / 2 if long_x else (x0 + x1) / 2
        strips.append(box(x0, c - width, x1, c + width) if long_x else box(c - width, y0, c + width, y1))
    meshes = []
    for strip in strips:
        part = poly.intersection(strip)
        for p in getattr(part, "geoms", [part]):
            if isinstance(p, Polygon) and p.area > MIN_SLAB_M2:
                m = trimesh.creation.extrude_polygon(p, depth)
                m.apply_translation((0.0, 0.0, room.height - depth))
                meshes.append(m)
    return cast(trimesh.Trimesh, trimesh.util.concatenate(meshes)) if meshes else None


def ceiling_height_at(room: Room, x: float, y: float) -> float:
    """Height of the ceiling above the plan point (x, y) (``room.height`` when flat)."""
    axis, lo, s, z = profile(room)
    return float(np.interp((x, y)[axis] - lo, s, z))


def ceiling_mesh(room: Room, thickness: float, hole: Polygon | None = None) -> trimesh.Trimesh | None:
    """The room's ceiling (see the module doc); None for an open-air room. A flat
    ceiling leaves out ``hole`` (a stair opening: the flight climbs through it)."""
    if room.open_air:
        return None
    if room.ceiling == "flat":
        return slab(_poly(room), room.height, room.height + thickness, hole)
    return _sloped(room)


MIN_SLAB_M2 = 1e-4
"""Pieces of a floor or ceiling cut by a stair opening smaller than this are left out."""


def slab(poly: Polygon, z0: float, z1: float, hole: Polygon | None = None) -> trimesh.Trimesh | None:
    """``poly`` less ``hole`` extruded from ``z0`` to ``z1``; None when nothing is left."""
    if hole is not None:
        poly = poly.difference(hole)
    parts = [p for p in getattr(poly, "geoms", [poly]) if isinstance(p, Polygon) and p.area > MIN_SLAB_M2]
    if not parts:
        return None
    mesh = cast(trimesh.Trimesh, trimesh.util.concatenate([trimesh.creation.extrude_polygon(p, z1 - z0) for p in parts]))
    mesh.apply_translation((0.0, 0.0, z0))
    return mesh


def _sloped(room: Room) -> trimesh.Trimesh:
    poly = _poly(room)
    axis, lo, s, z = profile(room)
    x0, y0, x1, y1 = poly.bounds
    verts: list[np.ndarray] = []
    faces: list[np.ndarray] = []

    def add(v: np.ndarray, f: np.ndarray) -> None:
        base = sum(len(x) for x in verts)
        verts.append(v)
        faces.append(np.vstack([f, f[:, ::-1]]) + base)  # both sides

    for a, b in zip(s[:-1], s[1:], strict=True):
        strip = box(x0 - 1, lo + a, x1 + 1, lo + b) if axis == 1 else box(lo + a, y0 - 1, lo + b, y1 + 1)
        part = poly.intersection(strip)
        for p in getattr(part, "geoms", [part]):
            if not isinstance(p, Polygon) or p.area < 1e-9:
                continue
            v2, f = trimesh.creation.triangulate_polygon(p)
            v2 = np.asarray(v2, dtype=float)
            zz = np.interp(v2[:, axis] - lo, s, z)
            add(np.column_stack([v2, zz]), np.asarray(f)[:, ::-1])
    # gable ends: upright faces from the wall top up to the ceiling along the outline
    ring = np.asarray(poly.exterior.coords, dtype=float)
    h = room.height
    for p, q in zip(ring[:-1], ring[1:], strict=True):
        ts = [0.0, 1.0]
        dp = q[axis] - p[axis]
        if abs(dp) > 1e-9:
            ts += [float(t) for t in (lo + s - p[axis]) / dp if 1e-9 < t < 1 - 1e-9]
        ts = sorted(ts)
        pts = np.array([p + (q - p) * t for t in ts])
        tops = np.interp(pts[:, axis] - lo, s, z)
        for i in range(len(pts) - 1):
            if tops[i] - h < 1e-6 and tops[i + 1] - h < 1e-6:
                continue
            v = np.array([[*pts[i], h], [*pts[i + 1], h], [*pts[i + 1], tops[i + 1]], [*pts[i], tops[i]]])
            add(v, np.array([[0, 1, 2], [0, 2, 3]]))
    return trimesh.Trimesh(vertices=np.vstack(verts), faces=np.vstack(faces), process=False)
