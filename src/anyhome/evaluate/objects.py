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
    footprints and a z-interval prefilter, evaluated on arrays (:func:`colliding_pairs`).
    The supporter exception needs no special case: an object resting on its supporter's
    top has no vertical overlap. The work is bounded: at most ``MAX_COLLISIONS`` pairs are
    reported and at most ``MAX_CANDIDATE_PAIRS`` footprint-box pairs examined; when a
    bound is hit a ``limits`` violation says so (the house is then not certified valid).
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

from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from anyhome import geometry
from anyhome.evaluate.polygons import CHUNK_PAIRS, is_usable, overlapping_pairs, room_polygon
from anyhome.evaluate.report import Violation
from anyhome.house import House, HouseObject, Room

TOL = geometry.TOLERANCE_M
SURFACE_SUPPORTS = frozenset({"floor", "wall", "ceiling"})
"""``support`` values that are not object ids."""
MIN_OVERLAP_AREA_M2 = 1e-9
"""Intersection area above which a shrunk footprint counts as entering a zone."""
MAX_COLLISIONS = 1000
"""Rule 2 stops after reporting this many colliding pairs."""
MAX_CANDIDATE_PAIRS = 5_000_000
"""Rule 2 stops after examining this many pairs of overlapping footprint boxes."""
EXACT_BATCH = 2048
"""Candidate pairs given to the exact (shapely) test at once."""


@dataclass(frozen=True)
class ObjectIndex:
    """Per-house lookups shared by the object rules (built once per evaluation)."""

    objects: tuple[HouseObject, ...]
    footprints: tuple[Polygon, ...]
    by_id: dict[str, HouseObject]
    fp_by_id: dict[str, Polygon]
    rooms: dict[str, Room]
    room_polys: dict[str, Polygon]
    position_of: dict[str, int] = field(default_factory=dict)
    fp_array: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=object))
    notes: list[Violation] = field(default_factory=list)
    """``limits`` violations: a rule that stopped at its bound."""

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
            position_of={o.id: k for k, o in enumerate(objects)},
            fp_array=np.array(footprints, dtype=object),
        )


def _inside_many(container: Polygon, inner: np.ndarray) -> np.ndarray:
    """:func:`geometry.inside` of every geometry of ``inner`` in one container."""
    return shapely.contains(container.buffer(TOL, join_style="mitre"), inner)


# ------------------------------------------------------------------- rule 1
def check_in_bounds(index: ObjectIndex) -> list[Violation]:
    objs, fps = index.objects, index.fp_array
    n = len(objs)
    inside_room = np.ones(n, dtype=bool)
    by_room: dict[str, list[int]] = {}
    for k, o in enumerate(objs):
        if o.room in index.rooms and (o.support in SURFACE_SUPPORTS
                                      or o.support not in index.by_id or o.support == o.id):
            by_room.setdefault(o.room, []).append(k)
    for rid, ks in by_room.items():
        poly = index.room_polys[rid]
        if is_usable(poly):  # else rule 5 reports the room
            inside_room[ks] = _inside_many(poly, fps[ks])
    on_obj = [k for k, o in enumerate(objs) if o.room in index.rooms
              and o.support not in SURFACE_SUPPORTS and o.support in index.by_id
              and o.support != o.id]
    inside_sup = np.ones(n, dtype=bool)
    if on_obj:
        sup_at = [index.position_of[objs[k].support] for k in on_obj]
        buffered = shapely.buffer(fps[sup_at], TOL, join_style="mitre")
        inside_sup[on_obj] = shapely.contains(buffered, fps[on_obj])

    out: list[Violation] = []
    for k, obj in enumerate(objs):
        if obj.room not in index.rooms:
            out.append(Violation(1, "unknown_room", f"{obj.id}: room {obj.room!r} does not exist",
                                 (obj.id, obj.room)))
            continue
        oob = Violation(1, "out_of_bounds", f"{obj.id} ({obj.name}) sticks out of room {obj.room}",
                        (obj.id, obj.room))
        if obj.support in SURFACE_SUPPORTS:
            if not inside_room[k]:
                out.append(oob)
            continue
        sup = index.by_id.get(obj.support)
        if sup is None or sup.id == obj.id:
            out.append(Violation(1, "missing_supporter",
                                 f"{obj.id} ({obj.name}) stands on {obj.support!r}, "
                                 "which is no other object", (obj.id,)))
            if not inside_room[k]:
                out.append(oob)
            continue
        if not inside_sup[k]:
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
def colliding_pairs(index: ObjectIndex, max_pairs: int = MAX_COLLISIONS,
                    max_candidates: int = MAX_CANDIDATE_PAIRS,
                    chunk_pairs: int = CHUNK_PAIRS) -> list[tuple[int, int]]:
    """Index pairs ``(i, j)``, ``i < j``, of objects whose boxes collide (rule 2).

    The same test as :func:`geometry.boxes_collide` on arrays: footprint boxes that
    overlap (STRtree), z-intervals that overlap by more than 1 cm, then footprints shrunk
    by half the tolerance whose intersection has an area above 1e-9 m^2. Objects are
    taken in house order, in chunks; the search stops once ``max_pairs`` pairs are found
    or ``max_candidates`` footprint-box pairs were examined, and then appends a
    ``limits`` violation to ``index.notes``.
    """
    n = len(index.objects)
    if n < 2:
        return []
    fps = index.fp_array
    z0 = np.array([o.position[2] for o in index.objects], dtype=float)
    z1 = z0 + np.array([o.size[2] for o in index.objects], dtype=float)
    shrunk = shapely.buffer(fps, -TOL / 2, join_style="mitre")
    pairs: list[tuple[int, int]] = []
    examined = 0
    for stop, left, right in overlapping_pairs(fps, chunk_pairs):
        examined += len(left)
        overlap_z = np.minimum(z1[left], z1[right]) - np.maximum(z0[left], z0[right])
        keep = overlap_z > TOL
        left, right = left[keep], right[keep]
        for b in range(0, len(left), EXACT_BATCH):  # exact tests, stopping at max_pairs
            bl, br = left[b:b + EXACT_BATCH], right[b:b + EXACT_BATCH]
            area = shapely.area(shapely.intersection(shrunk[bl], shrunk[br]))
            hit = area > MIN_OVERLAP_AREA_M2
            pairs.extend(zip(bl[hit].tolist(), br[hit].tolist()))
            if len(pairs) >= max_pairs:
                break
        if len(pairs) >= max_pairs:
            del pairs[max_pairs:]
            index.notes.append(Violation(
                "limits", "collisions_capped",
                f"rule 2 stopped after {max_pairs} colliding pairs (objects up to "
                f"{index.objects[pairs[-1][0]].id}); more pairs collide than are listed", ()))
            break
        if examined >= max_candidates and stop < n:
            index.notes.append(Violation(
                "limits", "collisions_unchecked",
                f"rule 2 stopped after examining {examined:,} pairs of overlapping footprints "
                f"(bound {max_candidates:,}): objects {index.objects[stop].id} and later "
                f"({n - stop} of {n}) were not checked for collisions", ()))
            break
    return pairs


def check_collisions(index: ObjectIndex) -> list[Violation]:
    out = []
    for i, j in colliding_pairs(index):
        a, b = index.objects[i], index.objects[j]
        out.append(Violation(2, "collision", f"{a.id} ({a.name}) and {b.id} ({b.name}) overlap",
                             (a.id, b.id)))
    return out


# ------------------------------------------------------------------- rule 3
@dataclass
class _Openings:
    ids: list[str]
    segments: np.ndarray  # (k, 2, 2)
    bottom: np.ndarray
    top: np.ndarray

    @classmethod
    def of(cls, house: House) -> _Openings:
        items = [(d.id, d.segment, 0.0, d.height) for d in house.doors]
        items += [(w.id, w.segment, w.sill, w.sill + w.height) for w in house.windows]
        return cls([i[0] for i in items],
                   np.array([i[1] for i in items], dtype=float).reshape(-1, 2, 2),
                   np.array([i[2] for i in items], dtype=float),
                   np.array([i[3] for i in items], dtype=float))


def check_grounded(index: ObjectIndex, house: House) -> list[Violation]:
    out: list[Violation] = []
    openings = _Openings.of(house)
    bands: dict[str, Polygon | None] = {}
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
                if room.id not in bands:
                    bands[room.id] = (Polygon(room.polygon).exterior.buffer(TOL, join_style="mitre")
                                      if len(room.polygon) >= 3 else None)
                out.extend(_check_wall_object(obj, room, bands[room.id], openings))
        elif obj.support not in index.by_id or obj.support == obj.id:
            out.append(Violation(3, "floating", f"{label} has support {obj.support!r}, which is "
                                 "neither floor, wall, ceiling nor another object", (obj.id,)))
    return out


def _check_wall_object(obj: HouseObject, room: Room, band: Polygon | None,
                       openings: _Openings) -> list[Violation]:
    """Back edge on the room boundary (:func:`geometry.on_boundary`, so a wall split by a
    collinear vertex still counts as one wall), then the openings along that wall's line."""
    back = geometry.back_edge(obj.position, obj.size, obj.yaw)
    if band is not None and band.contains(LineString(back)):
        for a, b in geometry.polygon_edges(room.polygon):
            if float(np.linalg.norm(b - a)) <= TOL:
                continue
            t0, t1, dist = geometry.wall_interval((a, b), back)
            if dist <= TOL:
                return _covered_openings(obj, (a, b), t0, t1, openings)
    return [Violation(3, "wall_object_off_wall",
                      f"{obj.id} ({obj.name}) is a wall object whose back is on no wall of "
                      f"room {room.id}", (obj.id, room.id))]


def _covered_openings(
    obj: HouseObject, edge: tuple[np.ndarray, np.ndarray], t0: float, t1: float,
    openings: _Openings,
) -> list[Violation]:
    """:func:`geometry.wall_interval` of every opening at once, then the overlap test."""
    if not openings.ids:
        return []
    z0, z1 = obj.position[2], obj.position[2] + obj.size[2]
    a = np.asarray(edge[0], dtype=float)
    v = np.asarray(edge[1], dtype=float) - a
    u = v / float(np.linalg.norm(v))
    rel = openings.segments - a  # (k, 2, 2)
    t = rel @ u
    dist = np.abs(rel @ np.array([-u[1], u[0]])).max(axis=1)
    s0, s1 = t.min(axis=1), t.max(axis=1)
    along = np.minimum(t1, s1) - np.maximum(t0, s0)
    up = np.minimum(z1, openings.top) - np.maximum(z0, openings.bottom)
    hit = (dist <= TOL) & (along > TOL) & (up > TOL)
    return [Violation(3, "covers_opening", f"{obj.id} ({obj.name}) covers opening {oid}",
                      (obj.id, oid))
            for oid, h in zip(openings.ids, hit) if h]


# ------------------------------------------------------------------- rule 4
def check_doors_clear(index: ObjectIndex, house: House) -> list[Violation]:
    floor = [k for k, o in enumerate(index.objects) if o.support == "floor"]
    if not floor or not house.doors:
        return []
    shrunk = shapely.buffer(index.fp_array[floor], -TOL / 2, join_style="mitre")
    tree = shapely.STRtree(shrunk)
    out = []
    for door in house.doors:
        zone = geometry.opening_zone(door.segment)
        ks = np.sort(tree.query(zone, predicate="intersects"))
        if not len(ks):
            continue
        area = shapely.area(shapely.intersection(shrunk[ks], zone))
        for k in ks[area > MIN_OVERLAP_AREA_M2].tolist():
            obj = index.objects[floor[k]]
            out.append(Violation(4, "door_blocked",
                                 f"{obj.id} ({obj.name}) stands in the clearance of door "
                                 f"{door.id}", (obj.id, door.id)))
    return out
