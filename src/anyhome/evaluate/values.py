"""Project rules "values", "heights" and the reference part of "ids", plus screening.

A House built in Python is not checked by ``anyhome.house.load``: it may hold NaN or
infinite numbers, sizes <= 0, unknown references. :func:`screen` reports every such
element and returns a copy of the house without the elements the geometric rules cannot
run on, so that rules 1-6 never see a non-finite number.

Values
    ``no_rooms``: the house has no room. ``non_finite``: a number of a room (polygon,
    height), door or window (segment, height, sill) or object (position, size, yaw) is NaN,
    infinite or beyond ``MAX_COORD_M`` in size; the element is left out of the geometric
    rules. ``bad_size``: an object size <= 0 (left out too). ``bad_opening``: a door or
    window height <= 0 or a window sill < 0. ``room_too_large``: a room's bounding box
    has a side over ``MAX_ROOM_SIDE_M``. ``unknown_room_type``: not in
    :data:`anyhome.house.ROOM_TYPES`. ``repeated_point``: a polygon repeats a point
    (the closing point included). ``missing_materials``: a room's materials lack
    ``floor`` or ``walls``.
Heights
    ``room_height``: a finite room height outside ``ROOM_HEIGHT_RANGE_M``.
    ``taller_than_room``: an object's top (``z + sz``; on a supporter or on a wall alike)
    is above its room's ceiling by more than 1 cm (ceiling objects: rule 3).
    ``door_too_tall``: a door higher than the lower of the rooms it joins.
    ``window_above_ceiling``: a window whose top (``sill + height``) is above its room's
    ceiling.
Ids (references)
    ``unknown_anchor``: an object's ``anchor`` names no object. ``bad_connection``: a
    planned connection names an unknown room. ``unsafe_id``: an id outside the safe
    alphabet of :func:`anyhome.sanitize.is_safe_id`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

from anyhome import geometry
from anyhome.evaluate.report import Violation
from anyhome.house import ROOM_TYPES, House
from anyhome.sanitize import ID_PATTERN, is_safe_id

TOL = geometry.TOLERANCE_M
ROOM_HEIGHT_RANGE_M = (2.0, 40.0)
"""Plausible floor-to-ceiling heights. The generator writes 2.7 m (offline planner) and
2.0-12.0 m (``RoomSpec.height_m``, LLM planner); 40 m leaves room for a hand-built
cathedral nave or hangar."""
MAX_ROOM_SIDE_M = 200.0
"""Largest plausible side of a room's bounding box (the load limit of house.json too)."""
MAX_COORD_M = 1e6
"""Numbers beyond this (a thousand kilometres) are treated like non-finite ones."""
OUTSIDE = "outside"


@dataclass(frozen=True)
class Screened:
    house: House
    """A copy holding only the elements the geometric rules can run on."""
    violations: list[Violation]


def _ok(values: Iterable[float]) -> bool:
    try:
        return all(math.isfinite(v) and abs(v) <= MAX_COORD_M for v in values)
    except TypeError:
        return False


def _flat(points) -> list[float]:
    return [float(c) for p in points for c in p]


def screen(house: House) -> Screened:
    out: list[Violation] = []
    if not house.rooms:
        out.append(Violation("values", "no_rooms", "the house has no rooms", ()))

    rooms, heights = [], {}
    for r in house.rooms:
        if not _ok(_flat(r.polygon)):
            out.append(Violation("values", "non_finite", f"room {r.id} has a non-finite or "
                                 "out-of-range polygon coordinate", (r.id,)))
            rooms.append(r.model_copy(update={"polygon": []}))  # rule 5: invalid_polygon
        else:
            rooms.append(r)
            if r.polygon:
                xs, ys = [p[0] for p in r.polygon], [p[1] for p in r.polygon]
                side = max(max(xs) - min(xs), max(ys) - min(ys))
                if side > MAX_ROOM_SIDE_M:
                    out.append(Violation("values", "room_too_large",
                                         f"room {r.id} is {side:.0f} m across (at most "
                                         f"{MAX_ROOM_SIDE_M:.0f} m is plausible)", (r.id,)))
            pts = [tuple(p) for p in r.polygon]
            if any(pts[k] == pts[(k + 1) % len(pts)] for k in range(len(pts))) and len(pts) > 1:
                out.append(Violation("values", "repeated_point",
                                     f"room {r.id} polygon repeats a point (a closing point "
                                     "or a duplicate vertex)", (r.id,)))
        if not _ok([r.height]):
            out.append(Violation("values", "non_finite",
                                 f"room {r.id} height {r.height!r} is not a finite number", (r.id,)))
        else:
            heights[r.id] = r.height
            lo, hi = ROOM_HEIGHT_RANGE_M
            if not lo <= r.height <= hi:
                out.append(Violation("heights", "room_height",
                                     f"room {r.id} is {r.height:.2f} m high (plausible: "
                                     f"{lo:g} to {hi:g} m)", (r.id,)))
        if r.type not in ROOM_TYPES:
            out.append(Violation("values", "unknown_room_type",
                                 f"room {r.id} has the unknown type {r.type!r}", (r.id,)))
        missing = [k for k in ("floor", "walls") if k not in r.materials]
        if missing:
            out.append(Violation("values", "missing_materials",
                                 f"room {r.id} names no {' or '.join(missing)} material", (r.id,)))

    doors = []
    for d in house.doors:
        if not _ok([*_flat(d.segment), d.height]):
            out.append(Violation("values", "non_finite",
                                 f"door {d.id} has a non-finite number", (d.id,)))
            continue
        doors.append(d)
        if d.height <= 0:
            out.append(Violation("values", "bad_opening",
                                 f"door {d.id} height {d.height:.2f} m is not positive", (d.id,)))
        known = [heights[r] for r in d.rooms if r in heights]
        if known and d.height > min(known) + TOL:
            out.append(Violation("heights", "door_too_tall",
                                 f"door {d.id} is {d.height:.2f} m high, its room is "
                                 f"{min(known):.2f} m high", (d.id,)))

    windows = []
    for w in house.windows:
        if not _ok([*_flat(w.segment), w.height, w.sill]):
            out.append(Violation("values", "non_finite",
                                 f"window {w.id} has a non-finite number", (w.id,)))
            continue
        windows.append(w)
        if w.height <= 0 or w.sill < 0:
            out.append(Violation("values", "bad_opening",
                                 f"window {w.id} has height {w.height:.2f} m and sill "
                                 f"{w.sill:.2f} m (need height > 0, sill >= 0)", (w.id,)))
        h = heights.get(w.room)
        if h is not None and w.sill + w.height > h + TOL:
            out.append(Violation("heights", "window_above_ceiling",
                                 f"window {w.id} reaches {w.sill + w.height:.2f} m, above the "
                                 f"{h:.2f} m ceiling of room {w.room}", (w.id, w.room)))

    objects = []
    ids = {o.id for o in house.objects}
    for o in house.objects:
        label = f"{o.id} ({o.name})"
        if not _ok([*o.position, *o.size, o.yaw]) or len(o.position) != 3 or len(o.size) != 3:
            out.append(Violation("values", "non_finite",
                                 f"{label} has a non-finite or out-of-range position, size "
                                 "or yaw", (o.id,)))
            continue
        if min(o.size) <= 0:
            out.append(Violation("values", "bad_size", f"{label} has size "
                                 f"{tuple(round(s, 3) for s in o.size)}: every side must be "
                                 "> 0", (o.id,)))
            continue
        objects.append(o)
        h = heights.get(o.room)
        top = o.position[2] + o.size[2]
        if h is not None and o.support != "ceiling" and top > h + TOL:
            out.append(Violation("heights", "taller_than_room",
                                 f"{label} reaches {top:.2f} m, above the {h:.2f} m ceiling of "
                                 f"room {o.room}", (o.id, o.room)))
        if o.anchor is not None and o.anchor not in ids:
            out.append(Violation("ids", "unknown_anchor",
                                 f"{label} has the anchor {o.anchor!r}, which is no object",
                                 (o.id,)))

    room_ids = {r.id for r in house.rooms}
    for a, b in house.connections:
        bad = [x for x in (a, b) if x != OUTSIDE and x not in room_ids]
        if bad or a == b:
            out.append(Violation(5, "bad_connection",
                                 f"planned connection {a!r} - {b!r} names an unknown room"
                                 if bad else f"planned connection joins {a!r} to itself",
                                 (a, b)))
    for kind, items in (("room", house.rooms), ("door", house.doors),
                        ("window", house.windows), ("object", house.objects)):
        for x in items:
            if not is_safe_id(x.id):
                out.append(Violation("ids", "unsafe_id", f"{kind} id {x.id!r} is not a safe id "
                                     f"(pattern {ID_PATTERN})", (x.id,)))
    clean = house.model_copy(update={"rooms": rooms, "doors": doors, "windows": windows,
                                     "objects": objects})
    return Screened(clean, out)
