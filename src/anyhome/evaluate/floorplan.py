"""Rule 5 of SCENE_FORMAT.md (floorplan) and the project rule "windows".

Rule 5
    Every room polygon is a valid, counter-clockwise shapely polygon; no two rooms
    overlap by more than ``ROOM_OVERLAP_M2``; a door between two rooms lies on both
    boundaries (:func:`geometry.on_boundary`), an outside door on its room's boundary and
    on no other room's; the house has at least one entrance (a door to ``"outside"``);
    every room is reachable from the outside through the door graph; every planned
    connection has a door (or opening) between the same two rooms.
Windows
    Every window lies on its room's exterior boundary (on the room's boundary and on no
    other enclosed room's: a wall shared with an open-air room, a courtyard the house
    wraps around or a terrace, is an outer wall for a window), and every habitable room
    (:func:`house.is_habitable`) has one.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from anyhome import geometry
from anyhome.evaluate.polygons import is_usable, overlapping_pairs, room_polygon
from anyhome.evaluate.report import Violation
from anyhome.house import House, is_habitable

TOL = geometry.TOLERANCE_M
OUTSIDE = "outside"
ROOM_OVERLAP_M2 = 1e-4
"""Intersection area above which two rooms overlap."""
MAX_ROOM_OVERLAPS = 1000
"""Rule 5 stops after reporting this many overlapping room pairs."""
SHARED_WALL_MIN_M = 2 * TOL
"""A segment shares more than this length with another room's boundary -> not exterior."""


def check_floorplan(house: House) -> list[Violation]:
    polys = {r.id: room_polygon(r.polygon) for r in house.rooms}
    out = _check_polygons(house, polys)
    out += _check_overlaps(house, polys)
    out += _check_doors(house, polys)
    out += _check_reachability(house)
    out += _check_connections(house)
    return out


def connections_realized(house: House) -> float:
    """Fraction of planned connections that have a door; 1.0 when none is planned."""
    if not house.connections:
        return 1.0
    pairs = {frozenset(d.rooms) for d in house.doors}
    return sum(frozenset(c) in pairs for c in house.connections) / len(house.connections)


def on_exterior(polys: dict[str, Polygon], room_id: str, segment: Sequence[Sequence[float]],
                bands: _Bands | None = None, outdoors: frozenset[str] = frozenset()) -> bool:
    """The segment lies on ``room_id``'s boundary and runs along no other room's wall
    (rooms in ``outdoors``, open to the sky, excepted)."""
    if not geometry.on_boundary(polys[room_id], segment):
        return False
    line = LineString(segment)
    bands = bands if bands is not None else _Bands(polys)
    for rid, band in bands.near(line):
        if rid == room_id or rid in outdoors:
            continue
        if line.intersects(band) and line.intersection(band).length > SHARED_WALL_MIN_M:
            return False
    return True


class _Bands:
    """The 1 cm bands around every room's boundary, with an STRtree to find the near ones."""

    def __init__(self, polys: dict[str, Polygon]) -> None:
        self.ids = [rid for rid, p in polys.items() if not p.is_empty]
        self.bands = np.array([polys[rid].exterior.buffer(TOL, join_style="mitre")
                               for rid in self.ids], dtype=object)
        self.tree = shapely.STRtree(self.bands)

    def near(self, line: LineString) -> list[tuple[str, Polygon]]:
        ks = np.sort(self.tree.query(line))
        return [(self.ids[k], self.bands[k]) for k in ks.tolist()]


def _check_polygons(house: House, polys: dict[str, Polygon]) -> list[Violation]:
    out = []
    for room in house.rooms:
        poly = polys[room.id]
        if not is_usable(poly):
            out.append(Violation(5, "invalid_polygon",
                                 f"room {room.id} has an invalid or empty polygon", (room.id,)))
        elif not poly.exterior.is_ccw:
            out.append(Violation(5, "polygon_not_ccw",
                                 f"room {room.id} polygon is not counter-clockwise", (room.id,)))
    return out


def _check_overlaps(house: House, polys: dict[str, Polygon]) -> list[Violation]:
    """Pairs of usable rooms whose intersection area exceeds ``ROOM_OVERLAP_M2``
    (candidates from an STRtree of the room outlines), in house order."""
    rooms = [r for r in house.rooms if is_usable(polys[r.id])]
    if len(rooms) < 2:
        return []
    geoms = np.array([polys[r.id] for r in rooms], dtype=object)
    out = []
    for _, left, right in overlapping_pairs(geoms):
        area = shapely.area(shapely.intersection(geoms[left], geoms[right]))
        for i, j, a in zip(left.tolist(), right.tolist(), area.tolist()):
            if a > ROOM_OVERLAP_M2:
                out.append(Violation(5, "room_overlap",
                                     f"rooms {rooms[i].id} and {rooms[j].id} overlap by "
                                     f"{a:.2f} m2", (rooms[i].id, rooms[j].id)))
        if len(out) >= MAX_ROOM_OVERLAPS:
            out.append(Violation("limits", "overlaps_capped",
                                 f"rule 5 stopped after {len(out)} overlapping room pairs; "
                                 "more may overlap", ()))
            break
    return out


def _check_doors(house: House, polys: dict[str, Polygon]) -> list[Violation]:
    bands = _Bands(polys)
    out = []
    entrances = 0
    for door in house.doors:
        a, b = door.rooms
        unknown = [r for r in (a, b) if r != OUTSIDE and r not in polys]
        if unknown or a == b or (a == OUTSIDE and b == OUTSIDE):
            out.append(Violation(5, "bad_door_rooms",
                                 f"door {door.id} joins {a!r} and {b!r}", (door.id,)))
            continue
        if OUTSIDE in (a, b):
            entrances += 1
            room = b if a == OUTSIDE else a
            ok = not _degenerate(door.segment) and on_exterior(polys, room, door.segment, bands)
        else:
            ok = (not _degenerate(door.segment)
                  and geometry.on_boundary(polys[a], door.segment)
                  and geometry.on_boundary(polys[b], door.segment))
        if not ok:
            where = "the exterior wall of " + (b if a == OUTSIDE else a) if OUTSIDE in (a, b) \
                else f"the wall shared by {a} and {b}"
            out.append(Violation(5, "door_off_boundary", f"door {door.id} is not on {where}",
                                 (door.id,)))
    if house.rooms and entrances == 0:
        out.append(Violation(5, "no_entrance", "the house has no door to the outside", ()))
    return out


def reachable_rooms(house: House) -> set[str]:
    """Rooms reachable from the outside through the door graph."""
    adj: dict[str, set[str]] = {}
    for door in house.doors:
        a, b = door.rooms
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    seen = {OUTSIDE}
    todo = deque([OUTSIDE])
    while todo:
        for nxt in adj.get(todo.popleft(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen - {OUTSIDE}


def _check_reachability(house: House) -> list[Violation]:
    reached = reachable_rooms(house)
    return [
        Violation(5, "disconnected_room",
                  f"room {r.id} cannot be reached from the entrance through doors", (r.id,))
        for r in house.rooms if r.id not in reached
    ]


def _check_connections(house: House) -> list[Violation]:
    pairs = {frozenset(d.rooms) for d in house.doors}
    return [
        Violation(5, "connection_missing",
                  f"planned connection {a} - {b} has no door", (a, b))
        for a, b in house.connections if frozenset((a, b)) not in pairs
    ]


# --------------------------------------------------------------- windows
def check_windows(house: House) -> list[Violation]:
    polys = {r.id: room_polygon(r.polygon) for r in house.rooms}
    bands = _Bands(polys)
    outdoors = frozenset(r.id for r in house.rooms if r.open_air)
    out = []
    lit: set[str] = set()
    for win in house.windows:
        if win.room not in polys:
            out.append(Violation("windows", "bad_window_room",
                                 f"window {win.id} lights unknown room {win.room!r}", (win.id,)))
            continue
        if _degenerate(win.segment) or not on_exterior(polys, win.room, win.segment, bands, outdoors):
            out.append(Violation("windows", "window_off_boundary",
                                 f"window {win.id} is not on an exterior wall of room {win.room}",
                                 (win.id, win.room)))
            continue
        lit.add(win.room)
    for room in house.rooms:
        if is_habitable(room.type) and room.id not in lit:
            out.append(Violation("windows", "habitable_without_window",
                                 f"habitable room {room.id} ({room.name}) has no window",
                                 (room.id,)))
    return out


def _degenerate(segment: Sequence[Sequence[float]]) -> bool:
    (x1, y1), (x2, y2) = segment
    return float(np.hypot(x2 - x1, y2 - y1)) <= TOL
