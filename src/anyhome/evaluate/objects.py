"""Object rules 1-4 of SCENE_FORMAT.md: in bounds, no collisions, grounded, doors clear.

All tests use the definitions of :mod:`anyhome.geometry` with its 1 cm tolerance.

Rule 1 (in bounds)
    An object whose ``support`` is ``floor``, ``wall`` or ``ceiling`` (or anything that is
    not an object id) must have its footprint inside its room polygon
    (:func:`geometry.inside`). An object standing on another one must have its footprint
    inside the supporter's footprint and ``z`` equal to the supporter's top within 1 cm;
    its supporter must exist (``missing_supporter``).
Rule 2 (no collisions)
    :func:`geometry.boxes_collide` on every pair, after an STRtree prefilter on
    footprints and a z-interval prefilter. The supporter exception needs no special case:
    an object resting on its supporter's top has no vertical overlap.
Rule 3 (grounded)
    ``floor`` -> ``z == 0``; ``wall`` -> the footprint's back edge lies on a wall of the
    room (:func:`geometry.on_boundary` of the room polygon) and, projected on that wall, the object's ``[t0, t1] x [z, z + h]``
    rectangle overlaps no door (``[0, height]``) or window (``[sill, sill + height]``)
    opening on that wall by more than 1 cm in both directions; ``ceiling`` ->
    ``z + h == room height``; an object id -> that object exists; anything else floats.
Rule 4 (doors clear)
    No footprint of a ``floor`` object, shrunk by half the tolerance, intersects
    :func:`geometry.opening_zone` of a door (0.8 m on both sides) with positive area.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon

from anyhome import geometry
from anyhome.evaluate.polygons import is_usable, room_polygon
from anyhome.evaluate.report import Violation
from anyhome.house import House, HouseObject, Room

TOL = geometry.TOLERANCE_M
SURFACE_SUPPORTS = frozenset({"floor", "wall", "ceiling"})
"""``support`` values that are not object ids."""
MIN_OVERLAP_AREA_M2 = 1e-9
"""Intersection area above which a shrunk footprint counts as entering a zone."""


@dataclass(frozen=True)
class ObjectIndex:
    """Per-house lookups shared by the object rules (built once per evaluation)."""

    objects: tuple[HouseObject, ...]
    footprints: tuple[Polygon, ...]
    by_id: dict[str, HouseObject]
    fp_by_id: dict[str, Polygon]
    rooms: dict[str, Room]
    room_polys: dict[str, Polygon]

    @classmethod
    def build(cls, house: House) -> ObjectIndex:
        objects = tuple(house.objects)
        footprints = tuple(geometry.footprint_polygon(o.position, o.size, o.yaw) for o in objects)
        return cls(
            objects=objects,
            footprints=footprints,
            by_id={o.id: o for o in objects},
            fp_by_id={o.id: fp for o, fp in zip(objects, footprints)},
            rooms={r.id: r for r in house.rooms},
            room_polys={r.id: room_polygon(r.polygon) for r in house.rooms},
        )


# ------------------------------------------------------------------- rule 1
def check_in_bounds(index: ObjectIndex) -> list[Violation]:
    out: list[Violation] = []
    for obj, fp in zip(index.objects, index.footprints):
        if obj.room not in index.rooms:
            out.append(Violation(1, "unknown_room", f"{obj.id}: room {obj.room!r} does not exist",
                                 (obj.id, obj.room)))
            continue
        room_ok = is_usable(index.room_polys[obj.room])  # else rule 5 reports the room
        if obj.support in SURFACE_SUPPORTS:
            if room_ok and not geometry.inside(index.room_polys[obj.room], fp):
                out.append(Violation(1, "out_of_bounds",
                                     f"{obj.id} ({obj.name}) sticks out of room {obj.room}",
                                     (obj.id, obj.room)))
            continue
        sup = index.by_id.get(obj.support)
        if sup is None or sup.id == obj.id:
            out.append(Violation(1, "missing_supporter",
                                 f"{obj.id} ({obj.name}) stands on {obj.support!r}, "
                                 "which is no other object", (obj.id,)))
            if room_ok and not geometry.inside(index.room_polys[obj.room], fp):
                out.append(Violation(1, "out_of_bounds",
                                     f"{obj.id} ({obj.name}) sticks out of room {obj.room}",
                                     (obj.id, obj.room)))
            continue
        if not geometry.inside(index.fp_by_id[sup.id], fp):
            out.append(Violation(1, "off_supporter",
                                 f"{obj.id} ({obj.name}) overhangs the top of {sup.id} ({sup.name})",
                                 (obj.id, sup.id)))
        top = sup.position[2] + sup.size[2]
        if abs(obj.position[2] - top) > TOL:
            out.append(Violation(1, "supporter_gap",
                                 f"{obj.id} ({obj.name}) at z={obj.position[2]:.3f} m but the top "
                                 f"of {sup.id} is at {top:.3f} m", (obj.id, sup.id)))
    return out


# ------------------------------------------------------------------- rule 2
def colliding_pairs(index: ObjectIndex) -> list[tuple[int, int]]:
    """Index pairs ``(i, j)``, ``i < j``, of objects whose boxes collide (rule 2)."""
    if len(index.objects) < 2:
        return []
    tree = shapely.STRtree(index.footprints)
    left, right = tree.query(index.footprints, predicate="intersects")
    keep = left < right
    left, right = left[keep], right[keep]
    z0 = np.array([o.position[2] for o in index.objects])
    z1 = z0 + np.array([o.size[2] for o in index.objects])
    overlap_z = np.minimum(z1[left], z1[right]) - np.maximum(z0[left], z0[right])
    keep = overlap_z > TOL
    pairs: list[tuple[int, int]] = []
    for i, j in zip(left[keep].tolist(), right[keep].tolist()):
        a, b = index.objects[i], index.objects[j]
        if geometry.boxes_collide(a.position, a.size, a.yaw, b.position, b.size, b.yaw):
            pairs.append((i, j))
    return sorted(pairs)


def check_collisions(index: ObjectIndex) -> list[Violation]:
    out = []
    for i, j in colliding_pairs(index):
        a, b = index.objects[i], index.objects[j]
        out.append(Violation(2, "collision", f"{a.id} ({a.name}) and {b.id} ({b.name}) overlap",
                             (a.id, b.id)))
    return out


# ------------------------------------------------------------------- rule 3
def check_grounded(index: ObjectIndex, house: House) -> list[Violation]:
    out: list[Violation] = []
    for obj in index.objects:
        z, h = obj.position[2], obj.size[2]
        label = f"{obj.id} ({obj.name})"
        if obj.support == "floor":
            if abs(z) > TOL:
                code = "floating" if z > 0 else "below_floor"
                out.append(Violation(3, code, f"{label} stands on the floor but z={z:.3f} m",
                                     (obj.id,)))
        elif obj.support == "ceiling":
            room = index.rooms.get(obj.room)
            if room is not None and abs(z + h - room.height) > TOL:
                code = "floating" if z + h < room.height else "above_ceiling"
                out.append(Violation(3, code, f"{label} hangs from the ceiling but its top is at "
                                     f"{z + h:.3f} m, the ceiling at {room.height:.3f} m",
                                     (obj.id,)))
        elif obj.support == "wall":
            room = index.rooms.get(obj.room)
            if room is not None:
                out.extend(_check_wall_object(obj, room, house))
        elif obj.support not in index.by_id or obj.support == obj.id:
            out.append(Violation(3, "floating", f"{label} has support {obj.support!r}, which is "
                                 "neither floor, wall, ceiling nor another object", (obj.id,)))
    return out


def _check_wall_object(obj: HouseObject, room: Room, house: House) -> list[Violation]:
    """Back edge on the room boundary (:func:`geometry.on_boundary`, so a wall split by a
    collinear vertex still counts as one wall), then the openings along that wall's line."""
    back = geometry.back_edge(obj.position, obj.size, obj.yaw)
    if len(room.polygon) >= 3 and geometry.on_boundary(Polygon(room.polygon), back):
        for a, b in geometry.polygon_edges(room.polygon):
            if float(np.linalg.norm(b - a)) <= TOL:
                continue
            t0, t1, dist = geometry.wall_interval((a, b), back)
            if dist <= TOL:
                return _covered_openings(obj, (a, b), t0, t1, house)
    return [Violation(3, "wall_object_off_wall",
                      f"{obj.id} ({obj.name}) is a wall object whose back is on no wall of "
                      f"room {room.id}", (obj.id, room.id))]


def _covered_openings(
    obj: HouseObject, edge: tuple[np.ndarray, np.ndarray], t0: float, t1: float, house: House
) -> list[Violation]:
    z0, z1 = obj.position[2], obj.position[2] + obj.size[2]
    openings = [(d.id, d.segment, 0.0, d.height) for d in house.doors]
    openings += [(w.id, w.segment, w.sill, w.sill + w.height) for w in house.windows]
    out = []
    for oid, seg, bottom, top in openings:
        s0, s1, dist = geometry.wall_interval(edge, np.asarray(seg, dtype=float))
        if dist > TOL:
            continue
        along = min(t1, s1) - max(t0, s0)
        up = min(z1, top) - max(z0, bottom)
        if along > TOL and up > TOL:
            out.append(Violation(3, "covers_opening",
                                 f"{obj.id} ({obj.name}) covers opening {oid}", (obj.id, oid)))
    return out


# ------------------------------------------------------------------- rule 4
def check_doors_clear(index: ObjectIndex, house: House) -> list[Violation]:
    floor = [(o, fp) for o, fp in zip(index.objects, index.footprints) if o.support == "floor"]
    if not floor or not house.doors:
        return []
    shrunk = [fp.buffer(-TOL / 2, join_style="mitre") for _, fp in floor]
    tree = shapely.STRtree(shrunk)
    out = []
    for door in house.doors:
        zone = geometry.opening_zone(door.segment)
        for k in sorted(tree.query(zone, predicate="intersects").tolist()):
            if shrunk[k].intersection(zone).area > MIN_OVERLAP_AREA_M2:
                obj = floor[k][0]
                out.append(Violation(4, "door_blocked",
                                     f"{obj.id} ({obj.name}) stands in the clearance of door "
                                     f"{door.id}", (obj.id, door.id)))
    return out
