"""A stairwell wider than its stair gives the band beyond it to the room across (floorplan.wells)."""

from __future__ import annotations

from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.wells import wells_doors_to_strip, wells_end_trimmed, wells_trimmed
from anyhome.house import Door, Floorplan, Level, Room, Window


def _plan(door_on_shared_wall: bool) -> Floorplan:
    well = Room(id="stairwell", name="stairwell", type="stairwell", polygon=[(0, 0), (3.6, 0), (3.6, 3.2), (0, 3.2)])
    living = Room(id="living_room", name="living room", type="living_room",
                  polygon=[(0, 3.2), (3.6, 3.2), (3.6, 7.2), (0, 7.2)])
    doors = [Door(id="door-0", rooms=("stairwell", "outside"), segment=((3.6, 0.2), (3.6, 1.2)))]
    if door_on_shared_wall:
        doors.append(Door(id="door-1", rooms=("stairwell", "living_room"), segment=((2.65, 3.2), (3.55, 3.2))))
    windows = [Window(id="win-0", room="living_room", segment=((0.0, 4.0), (0.0, 5.0)), height=1.2, sill=0.9)]
    return Floorplan(rooms=[well, living], doors=doors, windows=windows, connections=[("stairwell", "outside")],
                     levels=[Level(level=0, elevation_m=0.0, height_m=2.9), Level(level=1, elevation_m=2.9, height_m=2.9)])


def test_the_band_beyond_the_stair_goes_to_the_room_across():
    out = wells_trimmed(_plan(False), 0.0, {0: "stairwell"}, FloorplanOptions())  # the stair on y 0-1.75
    ys = [p[1] for p in out.room("stairwell").polygon]
    assert max(ys) == 1.75
    living = out.room("living_room")
    assert min(p[1] for p in living.polygon) == 1.75 and len(living.polygon) == 4


def test_a_door_on_the_moved_wall_keeps_a_landing_and_moves_with_it():
    out = wells_trimmed(_plan(True), 0.0, {0: "stairwell"}, FloorplanOptions())
    top = max(p[1] for p in out.room("stairwell").polygon)
    assert top == 2.65  # the stair's 1.75 m and a 0.9 m landing before the door
    door = next(d for d in out.doors if d.id == "door-1")
    assert {p[1] for p in door.segment} == {2.65}


def test_no_room_across_the_whole_wall_leaves_the_stairwell_as_it_is():
    plan = _plan(False)
    short = plan.room("living_room").model_copy(update={"polygon": [(0, 3.2), (2.0, 3.2), (2.0, 7.2), (0, 7.2)]})
    plan = plan.model_copy(update={"rooms": [plan.room("stairwell"), short]})
    out = wells_trimmed(plan, 0.0, {0: "stairwell"}, FloorplanOptions())
    assert out.room("stairwell").polygon == plan.room("stairwell").polygon


def test_a_band_on_an_outside_wall_goes_to_the_outside_with_its_door():
    plan = _plan(False)
    well = plan.room("stairwell")
    door = Door(id="door-0", rooms=("stairwell", "outside"), segment=((2.65, 3.2), (3.55, 3.2)))  # the front door
    plan = plan.model_copy(update={"rooms": [well], "doors": [door], "connections": [("stairwell", "outside")],
                                   "windows": []})
    out = wells_trimmed(plan, 0.0, {0: "stairwell"}, FloorplanOptions())
    assert max(p[1] for p in out.room("stairwell").polygon) == 2.65  # a landing before the door
    assert {p[1] for p in out.doors[0].segment} == {2.65}


def test_a_door_onto_the_strip_at_the_stairs_foot_needs_no_landing_beside_the_stair():
    # the box on x 0-2.6 (its foot at 2.6), the door at x 2.65-3.55 opens onto the strip
    out = wells_trimmed(_plan(True), 0.0, {0: "stairwell"}, FloorplanOptions(), boxes={0: (0.0, 2.6)})
    assert max(p[1] for p in out.room("stairwell").polygon) == 1.75
    door = next(d for d in out.doors if d.id == "door-1")
    assert {p[1] for p in door.segment} == {1.75}


def test_the_end_beyond_the_strip_goes_to_the_room_across_the_end_wall():
    well = Room(id="stairwell", name="stairwell", type="stairwell", polygon=[(0, 0), (4.8, 0), (4.8, 1.75), (0, 1.75)])
    study = Room(id="study", name="study", type="study", polygon=[(4.8, 0), (7.8, 0), (7.8, 3.0), (4.8, 3.0)])
    door = Door(id="door-0", rooms=("stairwell", "study"), segment=((4.8, 0.4), (4.8, 1.3)))
    plan = Floorplan(rooms=[well, study], doors=[door], windows=[], connections=[("stairwell", "study")],
                     levels=[Level(level=0, elevation_m=0.0, height_m=2.9), Level(level=1, elevation_m=2.9, height_m=2.9)])
    # the foot at x 2.6 facing east: the box on x 0-2.6, the strip to 3.6
    out = wells_end_trimmed(plan, (2.6, 0.0, 0.0), {0: 2.6}, {0: "stairwell"}, FloorplanOptions())
    assert max(p[0] for p in out.room("stairwell").polygon) == 3.6
    assert min(p[0] for p in out.room("study").polygon) == 3.6 and len(out.room("study").polygon) == 6
    assert {p[0] for p in out.doors[0].segment} == {3.6}  # the door moved with its wall


def test_the_end_behind_the_box_keeps_its_door():
    well = Room(id="stairwell", name="stairwell", type="stairwell", polygon=[(0, 0), (4.8, 0), (4.8, 1.75), (0, 1.75)])
    study = Room(id="study", name="study", type="study", polygon=[(-3.0, 0), (0, 0), (0, 3.0), (-3.0, 3.0)])
    door = Door(id="door-0", rooms=("stairwell", "study"), segment=((0.0, 0.4), (0.0, 1.3)))
    plan = Floorplan(rooms=[well, study], doors=[door], windows=[], connections=[("stairwell", "study")],
                     levels=[Level(level=0, elevation_m=0.0, height_m=2.9), Level(level=1, elevation_m=2.9, height_m=2.9)])
    out = wells_end_trimmed(plan, (3.8, 0.0, 0.0), {0: 2.6}, {0: "stairwell"}, FloorplanOptions())  # box 1.2-3.8
    assert min(p[0] for p in out.room("stairwell").polygon) == 0.0


def _door_beside_the_stair(x0: float) -> Floorplan:
    """The stair on x 0-2.6 (its foot at 2.6, the strip on 2.6-3.6), y 0-1.75; a door
    onto the living room in the north wall at x ``x0``."""
    plan = _plan(False)
    door = Door(id="door-1", rooms=("stairwell", "living_room"), segment=((x0, 3.2), (x0 + 0.9, 3.2)))
    return plan.model_copy(update={"doors": [*plan.doors, door]})


def test_a_door_beside_the_stair_slides_onto_the_strip_and_the_landing_goes():
    plan = wells_doors_to_strip(_door_beside_the_stair(0.8), (2.6, 0.0, 0.0), {0: "stairwell"})
    door = next(d for d in plan.doors if d.id == "door-1")
    xs = sorted(p[0] for p in door.segment)
    assert xs[0] >= 2.6 + 0.03 - 1e-9 and xs[1] <= 3.6 + 1e-9  # on the strip, clear of the stair's box
    assert {p[1] for p in door.segment} == {3.2}
    out = wells_trimmed(plan, 0.0, {0: "stairwell"}, FloorplanOptions(), boxes={0: (0.0, 2.6)})
    assert max(p[1] for p in out.room("stairwell").polygon) == 1.75  # no landing beside the stair
    assert {p[1] for p in next(d for d in out.doors if d.id == "door-1").segment} == {1.75}


def test_a_door_on_the_strip_and_an_outside_door_stay():
    plan = _door_beside_the_stair(2.65)
    assert wells_doors_to_strip(plan, (2.6, 0.0, 0.0), {0: "stairwell"}).doors == plan.doors


def test_a_wall_whose_door_finds_no_place_on_the_strip_keeps_it():
    plan = _door_beside_the_stair(0.8)
    narrow = plan.room("living_room").model_copy(update={"polygon": [(0, 3.2), (2.4, 3.2), (2.4, 7.2), (0, 7.2)]})
    plan = plan.model_copy(update={"rooms": [plan.room("stairwell"), narrow]})  # the living room ends before the strip
    assert wells_doors_to_strip(plan, (2.6, 0.0, 0.0), {0: "stairwell"}).doors == plan.doors
