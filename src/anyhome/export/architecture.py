"""Architecture pieces for the GLB: door frames and open leaves, window frames with glass
and sill, skirting boards and one ceiling light per room.

Every piece is a handful of boxes in the PLAN frame (meters, x east, y north, z up), so
an exporter hangs it under its root node with an identity transform. Walls are centred
on the room boundary and ``WALL_THICKNESS_M`` thick (see :mod:`anyhome.export.walls`).

A door leaf is shown open: hinged at the jamb nearest a corner of the room it swings
into and turned about 85 degrees into that room, so it stands by the side wall and the
way stays clear; where that would cut the room's walkway in two (a door in the middle of
a corridor's long side) it folds flat against the wall beside the opening instead. The swing is chosen, per door, among both rooms (only the inside for an
entrance), both hinge ends and ``OPEN_ANGLES_DEG``; a leaf must lie inside the room's
inner wall face (or the opening itself) and is kept off furniture, off earlier leaves,
off windows and out of the doorways of other doors.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any, cast

import numpy as np
import trimesh
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon
from shapely.ops import unary_union

from anyhome.export.ceilings import ceiling_height_at
from anyhome.export.walls import ON_LINE_TOL_M, WALL_THICKNESS_M, WallPiece, wall_pieces
from anyhome.geometry import blocks_navigation, footprint_polygon, opening_zone
from anyhome.house import Door, House, Room, Window

# ------------------------------------------------------------------ tunables
OUTSIDE = "outside"
"""The pseudo-room on the far side of an entrance door (house.json's ``doors[].rooms``)."""
JAMB_WIDTH_M = 0.05
"""Width of a door jamb and head, inside the opening."""
FRAME_PROUD_M = 0.015
"""How far door jambs stand out of each wall face."""
CASING_WIDTH_M = 0.07
"""Width of the door casing (architrave) on each wall face, measured from the jamb's inner edge."""
CASING_THICKNESS_M = 0.015
"""How far the casing stands out of the wall face."""
LEAF_THICKNESS_M = 0.04
"""Thickness of a door leaf."""
LEAF_FLOOR_GAP_M = 0.01
"""Gap under a door leaf."""
LEAF_HEAD_GAP_M = 0.003
"""Gap between the leaf's top and the frame head."""
FLAT_OPEN_DEG = 180.0
"""The opening angle of a leaf folded flat against the wall, in front of the casing."""
OPEN_ANGLES_DEG = (85.0, 75.0, FLAT_OPEN_DEG, 60.0, 45.0, 30.0)
"""Opening angles tried for a leaf, in order of preference (0, closed, is the fallback)."""
LEAF_WALKWAY_M = 0.6
"""Width of way a leaf must leave open: it may not split the room's floor, shrunk by half
this from the walls, into more pieces than the floor has without it."""
DOORWAY_KEEP_CLEAR_M = 0.6
"""A leaf stays out of this depth in front of every other door's opening."""
SWING_AVOID_TYPES = frozenset({"hallway", "entry", "balcony", "garage", "terrace", "deck", "patio", "porch",
                               "courtyard", "garden", "roof_terrace"})
"""Room types a door leaf swings into only when the other side cannot take it."""

WINDOW_FRAME_WIDTH_M = 0.05
"""Width of the window frame's border (and mullion)."""
WINDOW_FRAME_DEPTH_M = 0.07
"""Depth of the window frame across the wall."""
MULLION_MIN_WIDTH_M = 1.2
"""Windows at least this wide get a vertical mullion in the middle."""
GLASS_THICKNESS_M = 0.008
"""Thickness of the glass pane."""
SILL_THICKNESS_M = 0.03
"""Thickness of the window sill board."""
SILL_RISE_M = 0.01
"""How far the sill's top stands above the opening's bottom (no face level with the wall's)."""
SILL_PROJECTION_M = 0.04
"""How far the sill stands out of each wall face."""
SILL_OVERHANG_M = 0.05
"""How far the sill runs past each end of the opening."""

SKIRTING_HEIGHT_M = 0.08
"""Height of the skirting boards."""
SKIRTING_THICKNESS_M = 0.012
"""Thickness of the skirting boards, from the wall's inner face."""

LIGHT_WALL_MARGIN_M = 0.5
"""A room's centroid is used for its light only if it is this far inside the polygon."""
CEILING_GAP_M = 0.001
"""Lights stop this far below the ceiling (no coplanar faces)."""
DISC_RADIUS_M = 0.18
"""Radius of a flush ceiling disc."""
DISC_HEIGHT_M = 0.05
"""Height of a flush ceiling disc."""
PENDANT_TYPES = frozenset(
    {"dining_room", "kitchen", "living_room", "cafe", "restaurant", "bar", "hall", "library"}
)
"""Room types that get a pendant; the others get a flush disc."""
LANTERN_BOTTOM_M = 1.75
"""Bottom of an open-air room's wall lantern (it has no ceiling to hang a light from)."""
LANTERN_SIZE_M = (0.2, 0.15, 0.3)
"""Width along the wall, depth out of it and height of the wall lantern."""
PENDANT_BOTTOM_M = 2.1
"""Height above the floor of a pendant shade's bottom rim (at least this low headroom)."""
PENDANT_RADIUS_M = 0.2
"""Radius of a pendant's shade at its rim."""
PENDANT_SHADE_HEIGHT_M = 0.22
"""Height of a pendant's conical shade."""
LIGHT_SECTIONS = 16
"""Facets around a light's round parts."""


@dataclass(frozen=True)
class Finish:
    """A material: its words (for metadata) and its glTF PBR factors."""

    words: str
    rgba: tuple[float, float, float, float]
    metallic: float = 0.0
    roughness: float = 0.6
    emissive: tuple[float, float, float] | None = None
    blend: bool = False


FINISHES: dict[str, Finish] = {
    "door_frame": Finish("white painted wood", (0.93, 0.92, 0.89, 1.0), roughness=0.5),
    "door_leaf": Finish("white oak", (0.80, 0.68, 0.52, 1.0), roughness=0.55),
    "entrance_leaf": Finish("dark stained oak", (0.36, 0.24, 0.15, 1.0), roughness=0.5),
    "window_frame": Finish("white painted wood", (0.95, 0.95, 0.93, 1.0), roughness=0.45),
    "window_glass": Finish("clear glass", (0.78, 0.88, 0.92, 0.3), roughness=0.05, blend=True),
    "skirting": Finish("white painted wood", (0.93, 0.92, 0.89, 1.0), roughness=0.5),
    "disc_light": Finish("opal glass, warm white light", (1.0, 0.97, 0.9, 1.0), roughness=0.3,
                         emissive=(1.0, 0.9, 0.72)),
    "pendant_light": Finish("brass, warm white light", (0.78, 0.62, 0.34, 1.0), metallic=0.8,
                            roughness=0.35, emissive=(1.0, 0.85, 0.6)),
    "wall_lantern": Finish("black metal and frosted glass, warm white light", (0.95, 0.9, 0.8, 1.0),
                           roughness=0.4, emissive=(1.0, 0.85, 0.6)),
}
"""Finish of every piece kind."""

Piece = tuple[str, trimesh.Trimesh, dict]


# ------------------------------------------------------------------ public API
def architecture_meshes(house: House) -> list[Piece]:
    """Every architecture piece of a house.

    Returns
    -------
    pieces : list of (node name, mesh, metadata)
        node names ``door:<id>:frame``, ``door:<id>:leaf`` (not for ``kind="open"``),
        ``window:<id>:frame``, ``window:<id>:glass``, ``room:<id>:skirting`` and
        ``room:<id>:light`` (a ceiling light; in an open-air room a wall lantern on a
        full-height wall it shares with an enclosed room, or none); meshes in plan coordinates with a PBR material; metadata
        with ``category``, ``room`` or ``rooms``, ``material`` and ``name``.
    """
    pieces: list[Piece] = []
    placed: dict[str, list[Polygon]] = {}
    for door in house.doors:
        pieces.append(door_frame(door))
        if door.kind == "door":
            pieces.append(door_leaf(house, door, placed))
    for window in house.windows:
        pieces.extend(window_pieces(window))
    shared = None
    for room in house.rooms:
        pieces.append(skirting(house, room))
        if not room.open_air:
            pieces.append(ceiling_light(room))
            continue
        if shared is None:
            shared = [p for p in wall_pieces(house) if not p.railing]
        if (lantern := wall_lantern(room, shared)) is not None:
            pieces.append(lantern)
    return pieces


@dataclass(frozen=True)
class LeafPlacement:
    """Where a door leaf swings: into ``room``, hinged at segment end ``hinge`` (0 or 1)."""

    room: str
    hinge: int
    angle_deg: float
    corners: np.ndarray
    """(4, 2) float: the leaf's footprint in the plan."""


def door_frame(door: Door) -> Piece:
    """Jambs and head inside the opening, casing on both wall faces."""
    a, u, n, width = _segment_frame(door.segment)
    h, j, t = door.height, JAMB_WIDTH_M, WALL_THICKNESS_M / 2
    boxes = [
        _box(a, u, n, (0.0, j), (-t - FRAME_PROUD_M, t + FRAME_PROUD_M), (0.0, h)),
        _box(a, u, n, (width - j, width), (-t - FRAME_PROUD_M, t + FRAME_PROUD_M), (0.0, h)),
        _box(a, u, n, (j, width - j), (-t - FRAME_PROUD_M, t + FRAME_PROUD_M), (h - j, h)),
    ]
    c0, c1 = j - CASING_WIDTH_M, width - j + CASING_WIDTH_M
    for face in (-1.0, 1.0):
        depth = tuple(sorted((face * t, face * (t + CASING_THICKNESS_M))))
        boxes += [
            _box(a, u, n, (c0, j), depth, (0.0, h - j)),
            _box(a, u, n, (width - j, c1), depth, (0.0, h - j)),
            _box(a, u, n, (c0, c1), depth, (h - j, h - j + CASING_WIDTH_M)),
        ]
    finish = FINISHES["door_frame"]
    meta = {"category": "door_frame", "id": door.id, "rooms": list(door.rooms),
            "kind": door.kind, "material": finish.words, "name": f"door frame {door.id}"}
    return f"door:{door.id}:frame", _finished(boxes, finish), meta


def door_leaf(house: House, door: Door, placed: dict[str, list[Polygon]] | None = None) -> Piece:
    """The door's leaf, open (see :func:`place_leaf`); ``placed`` collects leaf footprints
    per room so that later leaves keep off earlier ones."""
    placed = {} if placed is None else placed
    where = place_leaf(house, door, placed.get(door.rooms[0], []) + placed.get(door.rooms[1], []))
    placed.setdefault(where.room, []).append(Polygon(where.corners))
    top = door.height - JAMB_WIDTH_M - LEAF_HEAD_GAP_M
    mesh_box = _prism(where.corners, LEAF_FLOOR_GAP_M, top)
    finish = FINISHES["entrance_leaf" if OUTSIDE in door.rooms else "door_leaf"]
    hinge = np.asarray(door.segment[where.hinge], dtype=float)
    meta = {"category": "door_leaf", "id": door.id, "rooms": list(door.rooms),
            "swing_room": where.room, "hinge": [float(x) for x in hinge],
            "open_angle_deg": where.angle_deg, "material": finish.words,
            "name": f"door leaf {door.id}"}
    return f"door:{door.id}:leaf", _finished([mesh_box], finish), meta


def place_leaf(house: House, door: Door, avoid: Sequence[Polygon] = ()) -> LeafPlacement:
    """Choose the swing room, hinge end and opening angle of a door's leaf.

    Candidates must lie inside the room's inner wall face or the opening. They are ranked
    by: free of furniture, windows, ``avoid`` and other doorways; not splitting the room's
    walkway (see ``LEAF_WALKWAY_M``); swinging into a room not in
    ``SWING_AVOID_TYPES``; the order of ``OPEN_ANGLES_DEG``; into the smaller room; free
    edge nearest a wall. With no candidate at all the leaf is shown closed, in the opening.
    """
    a, u, _, width = _segment_frame(door.segment)
    leaf_w = max(width - 2 * JAMB_WIDTH_M, LEAF_THICKNESS_M)
    best: tuple | None = None
    for room_id in door.rooms:
        if room_id == OUTSIDE:
            continue
        room = house.room(room_id)
        n = _into(room, door.segment)
        inner = _room_poly(room).buffer(-WALL_THICKNESS_M / 2, join_style="mitre")
        allowed = inner.union(_rect(a, u, n, (0.0, width), (-WALL_THICKNESS_M / 2,
                                                            WALL_THICKNESS_M / 2)))
        allowed = allowed.buffer(1e-6, join_style="mitre")
        blocked = _obstacles(house, room, door) + list(avoid)
        avoid_rank = int(room.type in SWING_AVOID_TYPES)
        walkway = inner.buffer(-LEAF_WALKWAY_M / 2, join_style="mitre")
        pieces = _count_parts(walkway)
        for hinge in (0, 1):
            for rank, angle in enumerate(OPEN_ANGLES_DEG):
                corners, tip, _ = _leaf_geometry(a, u, n, width, leaf_w, hinge, angle)
                leaf = Polygon(corners)
                if not allowed.contains(leaf):
                    continue
                hits = sum(leaf.intersects(b) for b in blocked)
                blocks = _count_parts(walkway.difference(leaf.buffer(LEAF_WALKWAY_M / 2))) > pieces
                score = (hits, blocks, avoid_rank, rank, round(inner.area, 3),
                         round(inner.exterior.distance(ShapelyPoint(tip)), 4), hinge)
                if best is None or score < best[0]:
                    best = (score, LeafPlacement(room_id, hinge, angle, corners))
    if best is not None:
        return best[1]
    room_id = next(r for r in door.rooms if r != OUTSIDE)
    n = _into(house.room(room_id), door.segment)
    return LeafPlacement(room_id, 0, 0.0, _leaf_geometry(a, u, n, width, leaf_w, 0, 0.0)[0])


def window_pieces(window: Window) -> list[Piece]:
    """The window's frame (border, mullion if wide, sill board) and its glass pane."""
    a, u, n, width = _segment_frame(window.segment)
    z0, z1 = window.sill, window.sill + window.height
    f, d = WINDOW_FRAME_WIDTH_M, WINDOW_FRAME_DEPTH_M / 2
    boxes = [
        _box(a, u, n, (0.0, f), (-d, d), (z0, z1)),
        _box(a, u, n, (width - f, width), (-d, d), (z0, z1)),
        _box(a, u, n, (f, width - f), (-d, d), (z0, z0 + f)),
        _box(a, u, n, (f, width - f), (-d, d), (z1 - f, z1)),
    ]
    if width >= MULLION_MIN_WIDTH_M:
        boxes.append(_box(a, u, n, ((width - f) / 2, (width + f) / 2), (-d * 0.9, d * 0.9),
                          (z0 + f, z1 - f)))
    sill_n = WALL_THICKNESS_M / 2 + SILL_PROJECTION_M
    boxes.append(_box(a, u, n, (-SILL_OVERHANG_M, width + SILL_OVERHANG_M), (-sill_n, sill_n),
                      (z0 + SILL_RISE_M - SILL_THICKNESS_M, z0 + SILL_RISE_M)))
    frame_finish, glass_finish = FINISHES["window_frame"], FINISHES["window_glass"]
    g = GLASS_THICKNESS_M / 2
    glass = _box(a, u, n, (f, width - f), (-g, g), (z0 + f, z1 - f))
    base = {"id": window.id, "room": window.room, "rooms": [window.room]}
    return [
        (f"window:{window.id}:frame", _finished(boxes, frame_finish),
         {**base, "category": "window_frame", "material": frame_finish.words,
          "name": f"window frame {window.id}"}),
        (f"window:{window.id}:glass", _finished([glass], glass_finish),
         {**base, "category": "window_glass", "material": glass_finish.words,
          "name": f"window glass {window.id}"}),
    ]


def skirting(house: House, room: Room) -> Piece:
    """A strip along the room's inner wall faces, cut at door casings and low windows."""
    inner = _room_poly(room).buffer(-WALL_THICKNESS_M / 2, join_style="mitre")
    strip = inner.difference(inner.buffer(-SKIRTING_THICKNESS_M, join_style="mitre"))
    reach = WALL_THICKNESS_M / 2 + SKIRTING_THICKNESS_M + 0.01
    cuts = []
    openings: list[tuple[Sequence, float]] = [
        (d.segment, CASING_WIDTH_M - JAMB_WIDTH_M) for d in house.doors if room.id in d.rooms]
    openings += [(w.segment, 0.0) for w in house.windows
                 if w.room == room.id and w.sill < SKIRTING_HEIGHT_M]
    for seg, extend in openings:
        a, u, n, width = _segment_frame(seg)
        cuts.append(_rect(a, u, n, (-extend, width + extend), (-reach, reach)))
    if cuts:
        strip = strip.difference(unary_union(cuts))
    parts = [trimesh.creation.extrude_polygon(p, SKIRTING_HEIGHT_M)
             for p in getattr(strip, "geoms", [strip]) if isinstance(p, Polygon) and p.area > 1e-8]
    finish = FINISHES["skirting"]
    meta = {"category": "skirting", "room": room.id, "material": finish.words,
            "name": f"{room.name} skirting"}
    return f"room:{room.id}:skirting", _finished(parts, finish), meta


def ceiling_light(room: Room) -> Piece:
    """A pendant (``PENDANT_TYPES``) or a flush disc at the room's light position."""
    x, y = light_position(room)
    top = ceiling_height_at(room, x, y) - CEILING_GAP_M  # under a pitched or vaulted ceiling: higher
    if room.type in PENDANT_TYPES and top - PENDANT_BOTTOM_M > PENDANT_SHADE_HEIGHT_M + 0.05:
        finish, style = FINISHES["pendant_light"], "pendant"
        shade = trimesh.creation.cone(PENDANT_RADIUS_M, PENDANT_SHADE_HEIGHT_M, sections=LIGHT_SECTIONS)
        shade.apply_translation((x, y, PENDANT_BOTTOM_M))
        canopy = _cylinder(x, y, top - 0.02, top, 0.06)
        cord = _cylinder(x, y, PENDANT_BOTTOM_M + PENDANT_SHADE_HEIGHT_M * 0.8, top - 0.02, 0.006)
        parts = [shade, canopy, cord]
    else:
        finish, style = FINISHES["disc_light"], "flush disc"
        parts = [_cylinder(x, y, top - DISC_HEIGHT_M, top, DISC_RADIUS_M)]
    meta = {"category": "ceiling_light", "room": room.id, "style": style,
            "material": finish.words, "name": f"{room.name} ceiling light"}
    return f"room:{room.id}:light", _finished(parts, finish), meta


def wall_lantern(room: Room, walls: list[WallPiece]) -> Piece | None:
    """A lantern on the longest full-height wall an open-air room shares with an
    enclosed room, at :data:`LANTERN_BOTTOM_M`, where no opening is; None: no such wall."""
    poly = _room_poly(room)
    best = None
    for piece in walls:
        if room.id not in piece.rooms or piece.height < LANTERN_BOTTOM_M + LANTERN_SIZE_M[2] + 0.05:
            continue
        half = LANTERN_SIZE_M[0] / 2 + 0.15
        blocked = [(o[0] - half, o[1] + half) for o in piece.openings
                   if o[2] < LANTERN_BOTTOM_M + LANTERN_SIZE_M[2] and o[3] > LANTERN_BOTTOM_M]
        for t in np.linspace(half, piece.length - half, 9) if piece.length > 2 * half else []:
            if any(a <= t <= b for a, b in blocked):
                continue
            clear = min([t, piece.length - t, *[min(abs(t - a), abs(t - b)) for a, b in blocked]])
            if best is None or clear > best[0]:
                best = (clear, piece, float(t))
    if best is None:
        return None
    _, piece, t = best
    u = piece.direction
    n = np.array([-u[1], u[0]])
    mid = piece.a + u * t
    if not poly.contains(ShapelyPoint(*(mid + n * 0.2))):
        n = -n
    w, d, h = LANTERN_SIZE_M
    wall = WALL_THICKNESS_M / 2
    body = _box(mid, u, n, (-w / 2, w / 2), (wall, wall + d), (LANTERN_BOTTOM_M, LANTERN_BOTTOM_M + h))
    finish = FINISHES["wall_lantern"]
    meta = {"category": "wall_light", "room": room.id, "style": "wall lantern",
            "material": finish.words, "name": f"{room.name} wall lantern"}
    return f"room:{room.id}:light", _finished([body], finish), meta


def light_position(room: Room) -> tuple[float, float]:
    """The polygon centroid if well inside, else the centre of its largest rectangle."""
    poly = _room_poly(room)
    c = poly.centroid
    if poly.buffer(-LIGHT_WALL_MARGIN_M).contains(c):
        return float(c.x), float(c.y)
    return largest_rectangle_centre(room.polygon)


def largest_rectangle_centre(polygon: Sequence[Sequence[float]]) -> tuple[float, float]:
    """Centre of the largest axis-aligned rectangle inside a rectilinear polygon.

    Searched on the grid of the polygon's own x and y coordinates (exact for
    rectilinear shapes; a fair guess for others).
    """
    poly = _room_poly_from(polygon)
    xs = np.unique(np.round([p[0] for p in polygon], 6))
    ys = np.unique(np.round([p[1] for p in polygon], 6))
    inside = np.array([[poly.contains(ShapelyPoint((xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2))
                        for j in range(len(ys) - 1)] for i in range(len(xs) - 1)], dtype=bool)
    best, centre = 0.0, poly.representative_point().coords[0]
    for i0 in range(len(xs) - 1):
        for i1 in range(i0, len(xs) - 1):
            for j0 in range(len(ys) - 1):
                for j1 in range(j0, len(ys) - 1):
                    area = (xs[i1 + 1] - xs[i0]) * (ys[j1 + 1] - ys[j0])
                    if area > best and inside[i0:i1 + 1, j0:j1 + 1].all():
                        best = area
                        centre = ((xs[i0] + xs[i1 + 1]) / 2, (ys[j0] + ys[j1 + 1]) / 2)
    return float(centre[0]), float(centre[1])


# ------------------------------------------------------------------ helpers
def _room_poly(room: Room) -> Polygon:
    return _room_poly_from(room.polygon)


def _room_poly_from(polygon: Sequence[Sequence[float]]) -> Polygon:
    poly = Polygon(polygon)
    return poly if poly.is_valid else poly.buffer(0)


def _segment_frame(segment) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """(start point, unit direction, unit left normal, length) of a plan segment."""
    a = np.asarray(segment[0], dtype=float)
    v = np.asarray(segment[1], dtype=float) - a
    length = float(np.linalg.norm(v))
    u = v / max(length, 1e-12)
    return a, u, np.array([-u[1], u[0]]), length


def _into(room: Room, segment) -> np.ndarray:
    """Unit normal of the segment pointing into the room."""
    a, u, n, width = _segment_frame(segment)
    mid = a + u * width / 2
    poly = _room_poly(room)
    probe = max(2 * ON_LINE_TOL_M, 0.05)
    return n if poly.contains(ShapelyPoint(mid + n * probe)) else -n


def _leaf_geometry(a, u, n, width, leaf_w, hinge, angle_deg):
    """A leaf hinged at segment end ``hinge`` and turned ``angle_deg`` towards ``n``.

    The closed leaf is centred in the wall; it turns about its edge on the ``n`` face, so
    opened it stands just past the jamb, off the wall and out of the jamb. At
    ``FLAT_OPEN_DEG`` it lies flat on the wall face beside the opening, clear of the casing.

    Returns
    -------
    corners : (4, 2) float
        the leaf's footprint
    tip : (2,) float
        the middle of its free edge
    along : (2,) float
        unit direction from the hinge to the free edge
    """
    s = u if hinge == 0 else -u
    end = a if hinge == 0 else a + u * width
    if angle_deg >= FLAT_OPEN_DEG - 1e-9:
        off = WALL_THICKNESS_M / 2 + CASING_THICKNESS_M + 0.001
        corners = _quad(end, s, n, (JAMB_WIDTH_M - leaf_w, JAMB_WIDTH_M), (off, off + LEAF_THICKNESS_M))
        tip = end + s * (JAMB_WIDTH_M - leaf_w) + n * (off + LEAF_THICKNESS_M / 2)
        return corners, tip, -s
    pivot = end + s * JAMB_WIDTH_M + n * LEAF_THICKNESS_M / 2
    th = np.radians(angle_deg)
    along = np.cos(th) * s + np.sin(th) * n
    across = -np.sin(th) * s + np.cos(th) * n
    local = np.array([[0.0, 0.0], [leaf_w, 0.0], [leaf_w, -LEAF_THICKNESS_M], [0.0, -LEAF_THICKNESS_M]])
    corners = pivot + local[:, :1] * along + local[:, 1:] * across
    return corners, pivot + along * leaf_w - across * LEAF_THICKNESS_M / 2, along


def _count_parts(region) -> int:
    """Pieces of a (multi)polygon, ignoring slivers."""
    return sum(1 for p in getattr(region, "geoms", [region]) if p.area > 1e-3)


def _obstacles(house: House, room: Room, door: Door) -> list[Polygon]:
    """What a leaf swinging into ``room`` must keep off: furniture, other doorways, windows."""
    out = []
    for obj in house.objects_in(room.id):
        if obj.position[2] < door.height and blocks_navigation(obj.category, obj.size[2], obj.support):
            out.append(footprint_polygon(obj.position, obj.size, obj.yaw).buffer(-0.005))
    for other in house.doors:
        if other.id != door.id and room.id in other.rooms:
            out.append(opening_zone(other.segment, DOORWAY_KEEP_CLEAR_M))
    for window in house.windows:
        if window.room == room.id:
            out.append(opening_zone(window.segment, WALL_THICKNESS_M / 2 + SILL_PROJECTION_M + 0.01))
    return [p for p in out if not p.is_empty]


def _rect(a, u, n, t: Sequence[float], w: Sequence[float]) -> Polygon:
    return Polygon(_quad(a, u, n, t, w))


def _quad(a, u, n, t: Sequence[float], w: Sequence[float]) -> np.ndarray:
    """(4, 2) corners of the rectangle t along ``u`` and w along ``n`` from ``a``."""
    return np.array([a + u * t[0] + n * w[0], a + u * t[1] + n * w[0],
                     a + u * t[1] + n * w[1], a + u * t[0] + n * w[1]])


_PRISM_FACES = np.array(
    [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
     [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
)


def _prism(corners: np.ndarray, z0: float, z1: float) -> trimesh.Trimesh:
    """A box from a (4, 2) convex footprint between two heights, faces outward."""
    q = np.asarray(corners, dtype=float)
    x, y = q[:, 0], q[:, 1]
    if np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y) < 0:
        q = q[::-1]
    verts = np.vstack([np.column_stack([q, np.full(4, z0)]), np.column_stack([q, np.full(4, z1)])])
    return trimesh.Trimesh(vertices=verts, faces=_PRISM_FACES, process=False)


def _box(a, u, n, t, w, z) -> trimesh.Trimesh:
    return _prism(_quad(a, u, n, t, w), z[0], z[1])


def _cylinder(x: float, y: float, z0: float, z1: float, radius: float) -> trimesh.Trimesh:
    mesh = trimesh.creation.cylinder(radius=radius, height=z1 - z0, sections=LIGHT_SECTIONS)
    mesh.apply_translation((x, y, (z0 + z1) / 2))
    return mesh


def _finished(parts: Iterable[trimesh.Trimesh], finish: Finish) -> trimesh.Trimesh:
    """Concatenate parts into one mesh wearing the finish's PBR material."""
    # trimesh types concatenate's result as its Geometry base; of meshes it is a Trimesh
    mesh = cast(trimesh.Trimesh, trimesh.util.concatenate(list(parts)))
    mesh.visual = trimesh.visual.TextureVisuals(material=_material(finish))
    return mesh


def _material(finish: Finish) -> trimesh.visual.material.PBRMaterial:
    kwargs: dict[str, Any] = {}
    if finish.emissive is not None:
        kwargs["emissiveFactor"] = list(finish.emissive)
    if finish.blend:
        kwargs["alphaMode"] = "BLEND"
    return trimesh.visual.material.PBRMaterial(
        name=finish.words, baseColorFactor=list(finish.rgba), metallicFactor=finish.metallic,
        roughnessFactor=finish.roughness, doubleSided=finish.blend, **kwargs)
