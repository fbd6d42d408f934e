"""A stairwell carved from a corner of the one room it opens onto (floorplan.carve)."""

from __future__ import annotations

from shapely.geometry import LineString, Polygon

from anyhome.floorplan.carve import carve_room, carved, carved_spec
from anyhome.floorplan.merge import union_outline
from anyhome.house import Door, Floorplan, Room
from anyhome.plan.spec import RoomSpec
from tests.floorplan.test_options import _spec

WELL = RoomSpec(id="stairwell", name="stairwell", type="stairwell", area_m2=6.3, height_m=2.7)
LIVING = [(0.0, 0.0), (6.0, 0.0), (6.0, 4.5), (0.0, 4.5)]


def _plan(doors: list[Door]) -> Floorplan:
    living = Room(id="living_room", name="living room", type="living_room", polygon=LIVING)
    kitchen = Room(id="kitchen", name="kitchen", type="kitchen", polygon=[(6.0, 0.0), (9.0, 0.0), (9.0, 4.5), (6.0, 4.5)])
    return Floorplan(rooms=[living, kitchen], doors=doors, windows=[], connections=[("living_room", "kitchen")])


def test_the_stairwell_takes_a_corner_and_opens_onto_the_rest():
    plan = _plan([Door(id="door-0", rooms=("living_room", "kitchen"), segment=((6.0, 3.0), (6.0, 3.9)))])
    cands = list(carved(plan, WELL, "living_room", 3.6, 1.75, 1.2))
    assert cands
    for out in cands:
        well, rest = Polygon(out.room("stairwell").polygon), Polygon(out.room("living_room").polygon)
        assert abs(well.area - 3.6 * 1.75) < 1e-6 and abs(well.area + rest.area - 6.0 * 4.5) < 1e-6
        assert len(out.room("living_room").polygon) == 6  # an L: the stairwell flush with two walls
        assert union_outline(out.room("living_room").polygon, out.room("stairwell").polygon) is not None
        door = next(d for d in out.doors if "stairwell" in d.rooms)
        assert set(door.rooms) == {"stairwell", "living_room"}
        assert rest.exterior.buffer(1e-6).contains(LineString(door.segment))
        for d in out.doors:  # every door of the room still on what is left of it
            if "living_room" in d.rooms:
                assert rest.exterior.buffer(1e-6).contains(LineString(d.segment))


def test_a_door_on_the_walls_taken_slides_along_them():
    door = Door(id="door-0", rooms=("living_room", "kitchen"), segment=((6.0, 0.3), (6.0, 1.2)))  # in the SE corner
    outs = [o for o in carved(_plan([door]), WELL, "living_room", 3.6, 1.75, 1.2)
            if max(p[0] for p in o.room("stairwell").polygon) == 6.0 and min(p[1] for p in o.room("stairwell").polygon) == 0.0]
    assert outs  # the south-east corner is still carved, the door moved
    for out in outs:
        moved = next(d for d in out.doors if d.id == "door-0")
        assert moved.segment != door.segment
        assert LineString(moved.segment).intersection(Polygon(out.room("stairwell").polygon).exterior).length < 1e-6
        assert Polygon(out.room("kitchen").polygon).exterior.buffer(1e-6).contains(LineString(moved.segment))


def test_a_room_too_narrow_for_the_stairwell_and_a_passage_is_not_carved():
    narrow = _plan([]).model_copy(update={"rooms": [
        Room(id="living_room", name="living room", type="living_room", polygon=[(0, 0), (3.6, 0), (3.6, 2.5), (0, 2.5)])]})
    assert list(carved(narrow, WELL, "living_room", 3.6, 1.75, 1.2)) == []


def test_only_a_stairwell_with_one_door_onto_an_open_stair_room_is_carved():
    spec = _spec("a two-storey cottage with a living room and a kitchen downstairs and two bedrooms upstairs")
    wells = [r.id for r in spec.rooms if r.type == "stairwell"]
    for well in wells:
        links = [c for c in spec.connections if well in c]
        room = carve_room(spec, well, frozenset({"living_room", "dining_room"}))
        if room is not None:
            assert len(links) == 1 and room in links[0]
            sub = carved_spec(spec, well, room, 6.3)
            assert well not in {r.id for r in sub.rooms} and not any(well in c for c in sub.connections)
            grown = next(r for r in sub.rooms if r.id == room)
            assert abs(grown.area_m2 - next(r for r in spec.rooms if r.id == room).area_m2 - 6.3) < 0.011
        else:
            assert len(links) != 1 or not any(
                r.type in ("living_room", "dining_room") for r in spec.rooms if r.id in links[0] and r.id != well)


def test_an_upper_storeys_stand_in_entrance_does_not_stop_the_carve():
    spec = _spec("a two-storey cottage with a living room and a kitchen downstairs and two bedrooms upstairs")
    well = next(r for r in spec.rooms if r.type == "stairwell")
    room = next(r for r in spec.rooms if r.type == "living_room")
    sub = spec.model_copy(update={"connections": [(well.id, room.id), (well.id, "outside")]})  # a storey's stand-in
    types = frozenset({"living_room"})
    assert carve_room(sub, well.id, types) is None  # a real door to the outside
    assert carve_room(sub, well.id, types, stand_in=True) == room.id
    carved_sub = carved_spec(sub, well.id, room.id, 6.3)
    assert (room.id, "outside") in carved_sub.connections  # the stand-in goes to the room


def test_a_stair_hall_is_planned_no_larger_than_the_stair_and_its_passage():
    from anyhome.floorplan.levels import _carved_m2
    from anyhome.floorplan.options import FloorplanOptions

    spec = _spec("a two-storey cottage with a living room and a kitchen downstairs and two bedrooms upstairs")
    room = next(r for r in spec.rooms if r.type == "living_room")
    opts = FloorplanOptions()
    assert abs(_carved_m2(spec, room.id, 3.6, 1.75, opts) - 3.6 * 1.75) < 0.011  # a living room: both
    hall = room.model_copy(update={"type": "entry", "area_m2": 4.0})
    sub = spec.model_copy(update={"rooms": [hall if r.id == room.id else r for r in spec.rooms]})
    need = 3.6 * (1.75 + opts.stair_carve_left_m)  # the stair and the passage beside it
    assert abs(_carved_m2(sub, room.id, 3.6, 1.75, opts) - (need - 4.0)) < 0.011
    big = sub.model_copy(update={"rooms": [hall.model_copy(update={"area_m2": 14.0}) if r.id == room.id else r
                                           for r in spec.rooms]})
    assert _carved_m2(big, room.id, 3.6, 1.75, opts) == 0.0  # a hall that holds it already grows no larger


def _slid_all_at_once(segment, walls, rest_wall, near, on, off):
    """``carve._slid`` as it was: every test on every place, the first that passes all."""
    import numpy as np
    import shapely

    from anyhome.floorplan.levels import DOOR_SLIDE_M
    from anyhome.floorplan.stairs import DOOR_CORNER_M

    (ax, ay), (bx, by) = segment
    ux, uy = (1.0, 0.0) if abs(ay - by) < 1e-6 else (0.0, 1.0)
    shifts = [sign * i * 0.05 for i in range(1, int(DOOR_SLIDE_M / 0.05) + 1) for sign in (1, -1)]
    segs = [((round(ax + ux * t, 4), round(ay + uy * t, 4)), (round(bx + ux * t, 4), round(by + uy * t, 4))) for t in shifts]
    lines = shapely.linestrings(np.asarray(segs, dtype=float))
    ok = shapely.contains(rest_wall, lines) & (shapely.length(shapely.intersection(lines, walls)) <= 1e-6)
    for e in near:
        ok &= shapely.distance(shapely.linestrings(np.asarray(e, dtype=float)), lines) >= 2 * DOOR_CORNER_M
    if on is not None:
        ok &= shapely.contains(on, lines)
    if off is not None:
        ok &= shapely.length(shapely.intersection(lines, off)) <= 1e-6
    first = np.flatnonzero(ok)
    return segs[int(first[0])] if len(first) else None


def test_a_door_slid_with_each_test_on_the_survivors_lands_where_every_test_put_it(monkeypatch):
    """A slid door's places are each tested only while they pass (speed only): on rooms
    with doors in every corner and along every wall, every slide lands where testing
    every place with every test put it."""
    from anyhome.floorplan import carve

    slid, calls = carve._slid, []

    def both(*args):
        calls.append(slid(*args))
        assert calls[-1] == _slid_all_at_once(*args)
        return calls[-1]

    monkeypatch.setattr(carve, "_slid", both)
    for i, y in enumerate((0.1, 0.6, 1.3, 2.2, 3.4, 3.6)):  # along the wall shared with the kitchen
        doors = [Door(id="door-0", rooms=("living_room", "kitchen"), segment=((6.0, y), (6.0, y + 0.9))),
                 Door(id="door-1", rooms=("living_room", "outside"), segment=((0.2 + i, 0.0), (1.1 + i, 0.0)))]
        list(carved(_plan(doors), WELL, "living_room", 3.6, 1.75, 1.2))
    assert any(c is not None for c in calls) and any(c is None for c in calls)
