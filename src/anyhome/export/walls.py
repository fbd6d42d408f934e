"""Wall geometry shared by the exporters: one wall piece per stretch of room boundary
(walls shared by two rooms drawn once), with door and window openings cut out.

All in the plan frame (meters, z up).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from anyhome.house import House, Room

WALL_THICKNESS_M = 0.1
"""Wall thickness; walls are centred on the room boundary."""
RAILING_HEIGHT_M = 1.05
"""Height of the parapet an open-air room (``Room.open_air``) has on the sides it shares
with no enclosed room (guarding heights of 1.0-1.1 m: UK Approved Document K, the
International Building Code's 42 in)."""
ON_LINE_TOL_M = 0.01
"""How far an opening may lie from a wall line and still be cut into it."""
_KEY_DECIMALS = 3


@dataclass
class WallPiece:
    """A straight stretch of wall between two points, owned by one room."""

    room: str
    a: np.ndarray
    b: np.ndarray
    height: float
    rooms: set[str] = field(default_factory=set)
    openings: list[tuple[float, float, float, float, str]] = field(default_factory=list)
    """(t0, t1, z0, z1, id) along the piece, in meters from ``a``."""
    railing: bool = False
    """Only open-air rooms border it: a low parapet (:data:`RAILING_HEIGHT_M`)."""

    @property
    def length(self) -> float:
        return float(np.linalg.norm(self.b - self.a))

    @property
    def direction(self) -> np.ndarray:
        return (self.b - self.a) / max(self.length, 1e-12)


def _key(a: np.ndarray, b: np.ndarray) -> tuple:
    pa = tuple(np.round(a, _KEY_DECIMALS) + 0.0)
    pb = tuple(np.round(b, _KEY_DECIMALS) + 0.0)
    return (pa, pb) if pa <= pb else (pb, pa)


def _split_points(a: np.ndarray, b: np.ndarray, vertices: np.ndarray) -> list[float]:
    v = b - a
    length = float(np.linalg.norm(v))
    u = v / length
    rel = vertices - a
    t = rel @ u
    dist = np.abs(rel @ np.array([-u[1], u[0]]))
    inner = (dist < 1e-4) & (t > 1e-4) & (t < length - 1e-4)
    return sorted({0.0, length, *np.round(t[inner], 6).tolist()})


def wall_height(room: Room) -> float:
    """The height a room raises its walls to: its ceiling, or for an open-air room the
    parapet (a wall shared with an enclosed room takes the higher)."""
    return min(RAILING_HEIGHT_M, room.height) if room.open_air else room.height


def wall_pieces(house: House) -> list[WallPiece]:
    """Every wall stretch of the house, once, with its openings. A stretch only
    open-air rooms border is a low parapet (``railing``)."""
    vertices = np.array([p for r in house.rooms for p in r.polygon], dtype=float).reshape(-1, 2)
    pieces: dict[tuple, WallPiece] = {}
    for room in house.rooms:
        pts = [np.asarray(p, dtype=float) for p in room.polygon]
        for i in range(len(pts)):
            a, b = pts[i], pts[(i + 1) % len(pts)]
            length = float(np.linalg.norm(b - a))
            if length < 1e-6:
                continue
            u = (b - a) / length
            ts = _split_points(a, b, vertices)
            for t0, t1 in zip(ts[:-1], ts[1:], strict=True):
                pa, pb = a + u * t0, a + u * t1
                k = _key(pa, pb)
                if k in pieces:
                    pieces[k].height = max(pieces[k].height, wall_height(room))
                    pieces[k].rooms.add(room.id)
                    pieces[k].railing = pieces[k].railing and room.open_air
                else:
                    pieces[k] = WallPiece(room.id, pa, pb, wall_height(room), {room.id}, railing=room.open_air)
    out = list(pieces.values())
    openings = [(d.id, d.segment, 0.0, d.height) for d in house.doors]
    openings += [(w.id, w.segment, w.sill, w.sill + w.height) for w in house.windows]
    for piece in out:
        u, length = piece.direction, piece.length
        nrm = np.array([-u[1], u[0]])
        for oid, seg, z0, z1 in openings:
            s = np.asarray(seg, dtype=float) - piece.a
            if np.abs(s @ nrm).max() > ON_LINE_TOL_M:
                continue
            t0, t1 = sorted((float(s[0] @ u), float(s[1] @ u)))
            t0, t1 = max(t0, 0.0), min(t1, length)
            if t1 - t0 > 1e-3:
                piece.openings.append((t0, t1, z0, z1, oid))
    return out


def solid_blocks(piece: WallPiece) -> list[tuple[float, float, float, float]]:
    """(t0, t1, z0, z1) blocks that make up a wall piece around its openings."""
    length, height = piece.length, piece.height
    cuts = sorted({0.0, length, *[o[0] for o in piece.openings], *[o[1] for o in piece.openings]})
    blocks = []
    for t0, t1 in zip(cuts[:-1], cuts[1:], strict=True):
        if t1 - t0 < 1e-6:
            continue
        mid = (t0 + t1) / 2
        holes = sorted((o[2], o[3]) for o in piece.openings if o[0] <= mid <= o[1])
        z = 0.0
        for z0, z1 in holes:
            if z0 > z + 1e-6:
                blocks.append((t0, t1, z, min(z0, height)))
            z = max(z, z1)
        if z < height - 1e-6:
            blocks.append((t0, t1, z, height))
    return blocks
