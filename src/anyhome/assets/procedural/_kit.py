"""Small drawing helpers shared by the newer procedural modules: discs and rings facing
an axis, spoked wheels, castors, button grids, polylines, sagging ropes and extrusions
along y. Each draws into a :class:`~anyhome.assets.procedural._parts.Builder`."""

from __future__ import annotations

import numpy as np
import trimesh

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    Role,
    Tint,
    move,
    rot_x,
    rot_y,
)

CHROME = Tint("#c9ccd0", "metal")
BRASS = Tint("#c9a54a", "metal")
COPPER = Tint("#b8733a", "metal")
STEEL = Tint("#b4b8bd", "metal")
RUBBER = Tint("#1c1c1e", "rubber")
GLOW_RED = Tint("#e8402a", "light")
GLOW_GREEN = Tint("#4ad06a", "light")
SCREEN = Tint("#1c2430", "screen")
WHITE_PLASTIC = Tint("#eceae4", "plastic")


def disc_y(b: Builder, x: float, y0: float, y1: float, z: float, r: float, color: str, sections: int = 20, role: Role | None = None) -> None:
    """A round disc (or short cylinder) on an axis along y, from y0 to y1."""
    b.rod((x, y0, z), (x, y1, z), r, color, sections=sections, role=role)


def disc_x(b: Builder, x0: float, x1: float, y: float, z: float, r: float, color: str, sections: int = 20, role: Role | None = None) -> None:
    """A round disc (or short cylinder) on an axis along x, from x0 to x1."""
    b.rod((x0, y, z), (x1, y, z), r, color, sections=sections, role=role)


def ring_y(b: Builder, center, major: float, minor: float, color: str, sections: int = 24, role: Role | None = None) -> None:
    """A ring in the x-z plane (facing y) about ``center``."""
    b.torus((0, 0, 0), major, minor, color, transform=move(center) @ rot_x(np.pi / 2), sections=sections,
            minor_sections=5, role=role)


def ring_x(b: Builder, center, major: float, minor: float, color: str, sections: int = 24, role: Role | None = None) -> None:
    """A ring in the y-z plane (facing x) about ``center``."""
    b.torus((0, 0, 0), major, minor, color, transform=move(center) @ rot_y(np.pi / 2), sections=sections,
            minor_sections=5, role=role)


def wheel_x(b: Builder, x: float, y: float, z: float, r: float, width: float, tyre: str = RUBBER,
            hub: str = METAL, spokes: int = 0) -> None:
    """A wheel rolling along y (axle along x): tyre, hub and optional spokes."""
    w2 = width / 2
    disc_x(b, x - w2, x + w2, y, z, r, tyre, sections=20)
    disc_x(b, x - w2 - 0.002, x + w2 + 0.002, y, z, 0.6 * r if not spokes else 0.25 * r, hub, sections=16)
    if spokes:
        ring_x(b, (x, y, z), 0.82 * r, 0.06 * r, hub, sections=20)
        for k in range(spokes):
            a = np.pi * k / spokes
            dy, dz = np.cos(a) * 0.82 * r, np.sin(a) * 0.82 * r
            b.rod((x, y - dy, z - dz), (x, y + dy, z + dz), 0.035 * r, hub, sections=5)


def wheel_y(b: Builder, x: float, y: float, z: float, r: float, width: float, tyre: str = RUBBER,
            hub: str = METAL, spokes: int = 0) -> None:
    """A wheel rolling along x (axle along y)."""
    w2 = width / 2
    disc_y(b, x, y - w2, y + w2, z, r, tyre, sections=20)
    disc_y(b, x, y - w2 - 0.002, y + w2 + 0.002, z, 0.6 * r if not spokes else 0.25 * r, hub, sections=16)
    if spokes:
        ring_y(b, (x, y, z), 0.82 * r, 0.06 * r, hub, sections=20)
        for k in range(spokes):
            a = np.pi * k / spokes
            dx, dz = np.cos(a) * 0.82 * r, np.sin(a) * 0.82 * r
            b.rod((x - dx, y, z - dz), (x + dx, y, z + dz), 0.035 * r, hub, sections=5)


def caster(b: Builder, x: float, y: float, r: float, color: str = BLACK, fork: str = METAL, role: Role | None = None) -> None:
    """A small swivel castor whose top is at 2.6 r."""
    b.box((x - 0.5 * r, y - 0.5 * r, 1.9 * r), (x + 0.5 * r, y + 0.5 * r, 2.6 * r), fork)
    b.box((x - 0.45 * r, y - 0.15 * r, r), (x + 0.45 * r, y + 0.15 * r, 2.0 * r), fork)
    disc_x(b, x - 0.35 * r, x + 0.35 * r, y, r, r, color, sections=12, role=role)


def buttons(b: Builder, x0: float, x1: float, z0: float, z1: float, y: float, rows: int, cols: int,
            color: str, fill: float = 0.6, depth: float = 0.006, role: Role | None = None) -> None:
    """A grid of small square buttons on a face looking +y at ``y``."""
    rows, cols = max(1, rows), max(1, cols)
    dx, dz = (x1 - x0) / cols, (z1 - z0) / rows
    for i in range(cols):
        for j in range(rows):
            cx, cz = x0 + (i + 0.5) * dx, z0 + (j + 0.5) * dz
            b.cbox((cx, y + depth / 2, cz), (dx * fill, depth, dz * fill), color, role=role)


def path(b: Builder, pts, r: float, color: str, sections: int = 8, joints: bool = True, role: Role | None = None) -> None:
    """Rods along a polyline, with a ball at each inner joint."""
    pts = [np.asarray(p, dtype=float) for p in pts]
    for a, c in zip(pts[:-1], pts[1:], strict=True):
        b.rod(a, c, r, color, sections=sections, role=role)
    if joints:
        for p in pts[1:-1]:
            b.sphere(p, r, color, subdivisions=0, role=role)


def sag(a, c, drop: float, n: int = 8) -> list[np.ndarray]:
    """Points of a rope hanging from ``a`` to ``c`` that sags ``drop`` in the middle."""
    a = np.asarray(a, dtype=float)
    c = np.asarray(c, dtype=float)
    t = np.linspace(0, 1, n + 1)
    pts = a[None, :] + (c - a)[None, :] * t[:, None]
    pts[:, 2] -= drop * 4 * t * (1 - t)
    return list(pts)


def extrude_y(b: Builder, profile, y0: float, y1: float, color: str, alpha: int = 255, holes=None, role: Role | None = None) -> None:
    """A polygon in the (x, z) plane (``profile`` : (n, 2), optional ``holes``) extruded
    from y0 to y1."""
    from shapely.geometry import Polygon

    poly = Polygon(np.asarray(profile, dtype=float), [np.asarray(h, dtype=float) for h in holes or []])
    m = trimesh.creation.extrude_polygon(poly, y1 - y0)
    v = np.asarray(m.vertices)
    # (u, v, t) -> (x = u, y = y0 + t, z = v) swaps two axes: reverse the faces to stay outward
    b.add(np.column_stack([v[:, 0], v[:, 2] + y0, v[:, 1]]), np.asarray(m.faces)[:, ::-1], color, alpha, role=role)


def extrude_x(b: Builder, profile, x0: float, x1: float, color: str, alpha: int = 255, holes=None, role: Role | None = None) -> None:
    """A polygon in the (y, z) plane (``profile`` : (n, 2), optional ``holes``) extruded
    from x0 to x1."""
    from shapely.geometry import Polygon

    poly = Polygon(np.asarray(profile, dtype=float), [np.asarray(h, dtype=float) for h in holes or []])
    m = trimesh.creation.extrude_polygon(poly, x1 - x0)
    v = np.asarray(m.vertices)
    # (u, v, t) -> (x = x0 + t, y = u, z = v): a cyclic permutation keeps faces outward
    b.add(np.column_stack([v[:, 2] + x0, v[:, 0], v[:, 1]]), np.asarray(m.faces), color, alpha, role=role)


def arc(cx: float, cz: float, r: float, a0: float, a1: float, n: int = 12) -> list[tuple[float, float]]:
    """Points (x, z) on a circle arc from angle a0 to a1 (radians, 0 = +x)."""
    return [(cx + r * np.cos(a), cz + r * np.sin(a)) for a in np.linspace(a0, a1, n)]


def sector_y(b: Builder, cx: float, cz: float, y0: float, y1: float, r0: float, r1: float, a0: float, a1: float,
             color: str, n: int = 3, role: Role | None = None) -> None:
    """A ring sector (annulus slice) in the x-z plane from angle a0 to a1, thick from y0 to y1."""
    pts = []
    for a in np.linspace(a0, a1, n + 1):
        for r in (r0, r1):
            for y in (y0, y1):
                pts.append((cx + r * np.cos(a), y, cz + r * np.sin(a)))
    b.hull(pts, color, role=role)


def frame_y(b: Builder, x0: float, x1: float, z0: float, z1: float, y0: float, y1: float, t: float,
            color: str, role: Role | None = None) -> None:
    """A rectangular picture frame of bar width ``t`` in the x-z plane, from y0 to y1."""
    b.box((x0, y0, z0), (x1, y1, z0 + t), color, role=role)
    b.box((x0, y0, z1 - t), (x1, y1, z1), color, role=role)
    b.box((x0, y0, z0), (x0 + t, y1, z1), color, role=role)
    b.box((x1 - t, y0, z0), (x1, y1, z1), color, role=role)


def vent_lines(b: Builder, x0: float, x1: float, z0: float, z1: float, y: float, n: int, color: str = DARK_METAL,
               depth: float = 0.004, role: Role | None = None) -> None:
    """Horizontal louvre slits on a face looking +y."""
    n = max(1, n)
    dz = (z1 - z0) / n
    for k in range(n):
        z = z0 + (k + 0.5) * dz
        b.box((x0, y, z - 0.18 * dz), (x1, y + depth, z + 0.18 * dz), color, role=role)


__all__ = ["BRASS", "CHROME", "COPPER", "GLOW_GREEN", "GLOW_RED", "RUBBER", "SCREEN", "STEEL", "WHITE_PLASTIC",
           "arc", "buttons", "caster", "disc_x", "disc_y", "extrude_x", "extrude_y", "frame_y", "path", "ring_x", "ring_y",
           "sag", "sector_y", "vent_lines", "wheel_x", "wheel_y"]
