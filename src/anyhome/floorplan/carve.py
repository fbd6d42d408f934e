"""Stairwells carved from a corner of the room their stair opens onto.

A storey whose stairwell opens onto one room only, of a type an open stair may rise in
(``open_plan.yaml`` ``open_stair``: a living room, a dining room, a hall; on a basement at
the bottom also ``basement_stair``), is laid out without it: that room is planned as large
as both, at least as long as the stair needs (:func:`carved_spec`). Each layout's room
then gives up a corner, a rectangle of the stairwell's least size (its stair's box and the
strip at its foot, by the stair's width) along one of its walls, clear of its doors, with
a door onto what is left of the room at the end away from the corner (:func:`carved`).
The stairwell is so flush with two walls of the room, and merges back into it as the
room's own rectangle (:func:`anyhome.floorplan.levels.stairs_opened`): a stair rising in
the corner of a cottage's living room, instead of a well beside the room whose union with
it is a Z, a T or an L too long for a room (the storeys' wells were merged only in about
half of such houses before).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np
from shapely.geometry import LineString, Polygon, box
from shapely.geometry.polygon import orient

from anyhome.floorplan.doors import DOOR_WIDTH_M
from anyhome.floorplan.grid import SNAP_M
from anyhome.floorplan.stairs import DOOR_CORNER_M
from anyhome.house import Door, Floorplan, Room, Window
from anyhome.plan.spec import HouseSpec, RoomSpec


def carve_room(spec: HouseSpec, well: str, open_types: frozenset[str], stand_in: bool = False) -> str | None:
    """The id of the room the stairwell ``well`` of ``spec`` is carved from: its only
    connection, when that room is of ``open_types`` and has a roof; None: none.
    ``stand_in``: ``spec`` is a storey above or below the ground, whose stairwell's link
    to the outside is the stand-in entrance (:func:`carved_spec` gives it to the room),
    not a door (before, every such storey was refused for it)."""
    links = [c for c in spec.connections if well in c and not (stand_in and "outside" in c)]
    if len(links) != 1 or "outside" in links[0]:
        return None
    other = next(x for x in links[0] if x != well)
    room = next((r for r in spec.rooms if r.id == other), None)
    if room is None or room.type not in open_types or room.open_air:
        return None
    return room.id


def carved_spec(sub: HouseSpec, well: str, room: str, well_m2: float) -> HouseSpec:
    """The storey ``sub`` (a house of its own) without its stairwell ``well``: ``room``
    planned ``well_m2`` larger, taking the stairwell's stand-in entrance, if any."""
    rooms = [r.model_copy(update={"area_m2": round(r.area_m2 + well_m2, 2)}) if r.id == room else r
             for r in sub.rooms if r.id != well]
    links = [c for c in sub.connections if well not in c]
    if (well, "outside") in sub.connections:
        links.append((room, "outside"))
    return sub.model_copy(update={"rooms": rooms, "connections": links})


def carved(plan: Floorplan, well: RoomSpec, room: str, long_m: float, short_m: float,
           left_m: float) -> Iterator[Floorplan]:
    """``plan`` with the stairwell ``well`` (``long_m`` x ``short_m``) cut from a corner of
    the rectangle of ``room``, its long side along one of the room's walls: every corner
    and both ways where the room is long enough and keeps ``left_m`` beside it (a passage); a
    door of the room on the walls it takes slid along its wall off them (none: the
    corner is refused), no window crossing their ends (those on them go to the
    stairwell). The stairwell's door
    opens onto the room at the end of its inner long wall away from the corner."""
    r = plan.room(room)
    if len(r.polygon) != 4:
        return
    xs, ys = [p[0] for p in r.polygon], [p[1] for p in r.polygon]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    for along_x in (x1 - x0 >= y1 - y0, x1 - x0 < y1 - y0):  # the well's long side along the room's longer side first
        span, across = (x1 - x0, y1 - y0) if along_x else (y1 - y0, x1 - x0)
        if span < long_m - 1e-6 or not (across >= short_m + left_m - 1e-6):
            continue
        for cx in (0, 1):
            for cy in (0, 1):
                w, h = (long_m, short_m) if along_x else (short_m, long_m)
                ax, bx = (x0, round(x0 + w, 4)) if cx == 0 else (round(x1 - w, 4), x1)  # flush with the walls, exactly
                ay, by = (y0, round(y0 + h, 4)) if cy == 0 else (round(y1 - h, 4), y1)
                cut = box(ax, ay, bx, by)
                out = _cut(plan, well, r, cut, along_x, cx, cy)
                if out is not None:
                    yield out


def _cut(plan: Floorplan, well: RoomSpec, r: Room, cut, along_x: bool, cx: int, cy: int) -> Floorplan | None:
    outline = Polygon(r.polygon)
    rest = outline.difference(cut)
    if not isinstance(rest, Polygon) or rest.is_empty:
        return None
    walls = cut.exterior.intersection(outline.exterior)  # the room's walls the stairwell takes
    ax, ay, bx, by = cut.bounds
    rest_wall = rest.exterior.buffer(1e-6)
    neighbours = {x.id: x for x in plan.rooms if x.level == r.level and x.id != r.id}
    outlines: dict[str, object] = {}  # room id -> its outline, buffered: built once a door in the way needs them

    def others() -> dict[str, object]:
        if not outlines:
            outlines.update({i: Polygon(x.polygon).exterior.buffer(1e-6) for i, x in neighbours.items()})
        return outlines

    def in_way(seg) -> bool:
        return bool(LineString(seg).intersection(walls).length > 1e-6)

    from shapely.ops import unary_union

    doors = list(plan.doors)
    for i, d in enumerate(doors):
        if r.id not in d.rooms or not in_way(d.segment):
            continue
        other = next(x for x in d.rooms if x != r.id)
        if other != "outside" and other not in neighbours:
            return None
        near = [e.segment for j, e in enumerate(doors) if j != i] + [w.segment for w in plan.windows]
        on = others()[other] if other != "outside" else None
        off = unary_union(list(others().values())) if other == "outside" else None  # an outside door stays off them
        seg = _slid(d.segment, walls, rest_wall, near, on, off)
        if seg is None:
            return None  # a door of the room that no place along its wall clears
        doors[i] = d.model_copy(update={"segment": seg})
    windows: list[Window] = []
    for w in plan.windows:
        if w.room == r.id and LineString(w.segment).intersection(walls).length > 1e-6:
            if not walls.buffer(1e-6).contains(LineString(w.segment)):
                return None
            w = w.model_copy(update={"room": well.id})
        windows.append(w)
    if along_x:  # the inner long wall, the door at its end away from the corner
        y = by if cy == 0 else ay
        x = bx - DOOR_CORNER_M if cx == 0 else ax + DOOR_CORNER_M + DOOR_WIDTH_M
        seg = ((round(x - DOOR_WIDTH_M, 4), round(y, 4)), (round(x, 4), round(y, 4)))
    else:
        x = bx if cx == 0 else ax
        y = by - DOOR_CORNER_M if cy == 0 else ay + DOOR_CORNER_M + DOOR_WIDTH_M
        seg = ((round(x, 4), round(y - DOOR_WIDTH_M, 4)), (round(x, 4), round(y, 4)))
    if not rest_wall.contains(LineString(seg)):
        return None
    from anyhome.floorplan.merge import union_outline

    pts = [(round(x, 4), round(y, 4)) for x, y in rest.exterior.coords[:-1]]
    rest_pts = union_outline(pts, pts, (4, 6)) if Polygon(pts).is_valid else None  # corners tidied
    if rest_pts is None:
        return None  # not a clean rectangle or L (a sliver left by the cut)
    corners = [(round(x, 4), round(y, 4)) for x, y in orient(cut, 1.0).exterior.coords[:-1]]
    start = corners.index(min(corners))
    height = min(2.1, min(r.height, well.height_m) - 0.1)
    stair = Room(id=well.id, name=well.name, type=well.type, height=well.height_m, style=well.style,
                 open_air=False, ceiling=well.ceiling, materials=dict(well.materials),
                 polygon=corners[start:] + corners[:start])
    rooms = [r.model_copy(update={"polygon": rest_pts}) if x.id == r.id else x for x in plan.rooms] + [stair]
    doors.append(Door(id=f"door-{len(plan.doors)}", rooms=(well.id, r.id), segment=seg, height=height))
    return plan.model_copy(update={"rooms": rooms, "doors": doors, "windows": windows})


def _slid(segment, walls, rest_wall, near: list, on, off) -> tuple | None:
    """``segment`` (a door of the room) moved along its own line to the nearest place
    (:data:`SNAP_M` steps, at most :data:`~anyhome.floorplan.levels.DOOR_SLIDE_M`) off ``walls`` (those the
    stairwell takes), on ``rest_wall`` (what is left of the
    room's outline), :data:`~anyhome.floorplan.stairs.DOOR_CORNER_M` twice from every segment of ``near``, on ``on`` (the other
    room's outline, buffered) or off ``off`` (an outside door: every other room's
    outline); None: no such place. Every place is tested at once (shapely's arrays),
    each test only on the places every test before it passed (:func:`first_passing`)."""
    import shapely

    from anyhome.floorplan.levels import DOOR_SLIDE_M

    (ax, ay), (bx, by) = segment
    ux, uy = (1.0, 0.0) if abs(ay - by) < 1e-6 else (0.0, 1.0)
    shifts = [sign * i * SNAP_M for i in range(1, int(DOOR_SLIDE_M / SNAP_M) + 1) for sign in (1, -1)]
    segs = [((round(ax + ux * t, 4), round(ay + uy * t, 4)), (round(bx + ux * t, 4), round(by + uy * t, 4))) for t in shifts]
    lines = shapely.linestrings(np.asarray(segs, dtype=float))
    def clear_of(e) -> Callable[[np.ndarray], np.ndarray]:
        line = shapely.linestrings(np.asarray(e, dtype=float))
        return lambda ls: shapely.distance(line, ls) >= 2 * DOOR_CORNER_M

    tests: list[Callable[[np.ndarray], np.ndarray]] = [
        lambda ls: shapely.contains(rest_wall, ls), lambda ls: shapely.length(shapely.intersection(ls, walls)) <= 1e-6]
    tests += [clear_of(e) for e in near]
    if on is not None:
        tests.append(lambda ls: shapely.contains(on, ls))
    if off is not None:
        tests.append(lambda ls: shapely.length(shapely.intersection(ls, off)) <= 1e-6)
    first = first_passing(lines, tests)
    return None if first is None else segs[first]


def first_passing(items: np.ndarray, tests: list) -> int | None:
    """Index of the first of ``items`` that every one of ``tests`` (an array of items ->
    an array of bools) passes, or None: each test is run only on the items that passed
    the ones before it (the same answer as every test on every item, for less work:
    most places of a slid door fail the first test)."""
    alive = np.arange(len(items))
    for test in tests:
        if not len(alive):
            return None
        alive = alive[np.asarray(test(items[alive]), dtype=bool)]
    return int(alive[0]) if len(alive) else None
