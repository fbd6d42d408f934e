"""A room of a house of several storeys: the doors, windows and stairs of the other storeys
(:class:`anyhome.space.RoomSpace`, the refiner)."""

from __future__ import annotations

import numpy as np

from anyhome.floorplan.levels import stair_zones, stairs_objects
from anyhome.house import Door, Floorplan, HouseObject, Level, Room, Window
from anyhome.refine.refiner import refine_objects
from anyhome.space import STAIR_FLOOR_ZONE_TOP_M, RoomSpace, rect_corners


def _plan() -> Floorplan:
    """Two storeys of a 3.6 x 7.2 house: a stairwell and a living room below, a stairwell
    and a bedroom above; the living room's door to the garden lies under the bedroom."""
    box = [(0, 0), (3.6, 0), (3.6, 3.2), (0, 3.2)]
    back = [(0, 3.2), (3.6, 3.2), (3.6, 7.2), (0, 7.2)]
    rooms = [Room(id="stairwell", name="stairwell", type="stairwell", polygon=box),
             Room(id="living_room", name="living room", type="living_room", polygon=back),
             Room(id="stairwell_2", name="landing", type="stairwell", polygon=box, level=1),
             Room(id="bedroom", name="bedroom", type="bedroom", polygon=back, level=1)]
    doors = [Door(id="door-0", rooms=("stairwell", "outside"), segment=((3.6, 0.2), (3.6, 1.2))),
             Door(id="door-1", rooms=("stairwell", "living_room"), segment=((2.65, 3.2), (3.55, 3.2))),
             Door(id="door-2", rooms=("living_room", "outside"), segment=((1.0, 7.2), (2.0, 7.2))),
             Door(id="door-3", rooms=("stairwell_2", "bedroom"), segment=((2.65, 3.2), (3.55, 3.2)))]
    windows = [Window(id="win-0", room="living_room", segment=((0.0, 4.0), (0.0, 5.0))),
               Window(id="win-1", room="bedroom", segment=((3.6, 5.0), (3.6, 6.0)))]
    return Floorplan(rooms=rooms, doors=doors, windows=windows,
                     connections=[("stairwell", "outside"), ("stairwell", "living_room"),
                                  ("living_room", "outside"), ("stairwell_2", "bedroom")],
                     levels=[Level(level=0, elevation_m=0.0, height_m=2.9),
                             Level(level=1, elevation_m=2.9, height_m=2.9)])


def _fits(space: RoomSpace, xy: tuple[float, float], size: tuple[float, float, float], z: float,
          floor: bool) -> bool:
    corners = rect_corners(np.asarray([xy]), size[:2], [0.0])
    return bool(space.valid(corners, z, z + size[2], floor=floor)[0])


def test_a_door_of_the_storey_below_is_no_obstacle_upstairs():
    plan = _plan()
    below = RoomSpace(plan, plan.room("living_room"))
    above = RoomSpace(plan, plan.room("bedroom"))
    where, size = (1.5, 6.9), (1.0, 0.5, 0.8)  # in front of the garden door, storey 0
    assert not _fits(below, where, size, 0.0, floor=True)
    assert _fits(above, where, size, 0.0, floor=True)
    assert len(below.door_zones) == 2 and len(above.door_zones) == 1  # its own door, the landing's

    def openings(space: RoomSpace, x0: float, y0: float, x1: float, y1: float) -> list:
        return [op for w in space.walls for op in w.openings
                if np.allclose(w.a, (x0, y0)) and np.allclose(w.b, (x1, y1))]

    assert len(openings(below, 3.6, 7.2, 0.0, 7.2)) == 1 and not openings(above, 3.6, 7.2, 0.0, 7.2)  # the door
    assert not openings(below, 3.6, 3.2, 3.6, 7.2) and len(openings(above, 3.6, 3.2, 3.6, 7.2)) == 1  # the window


def test_the_refiner_keeps_what_stands_over_a_door_of_another_storey():
    plan = _plan()
    chest = HouseObject(id="bedroom-chest-0", room="bedroom", name="chest", category="cabinet",
                        position=(1.5, 6.95, 0.0), size=(1.0, 0.5, 0.8), yaw=np.pi, support="floor")
    out = refine_objects(plan, [chest], np.random.default_rng(0))
    assert [o.id for o in out] == [chest.id]
    assert np.allclose(out[0].position, chest.position, atol=0.06)


def test_a_painting_may_hang_over_the_well_but_nothing_stands_in_it():
    plan = _plan()
    (flight,) = stairs_objects(plan)
    assert flight.room == "stairwell"
    (zone,) = stair_zones(plan)["stairwell_2"]
    space = RoomSpace(plan, plan.room("stairwell_2"))
    lo, hi = zone.min(0), zone.max(0)
    # against the wall y = 0, over the well
    x = float(lo[0] + hi[0]) / 2
    assert not _fits(space, (x, 0.3), (0.6, 0.5, 0.8), 0.0, floor=True)
    assert not _fits(space, (x, 0.02), (0.8, 0.04, 0.6), STAIR_FLOOR_ZONE_TOP_M - 0.3, floor=False)
    assert _fits(space, (x, 0.02), (0.8, 0.04, 0.6), STAIR_FLOOR_ZONE_TOP_M + 0.4, floor=False)


def test_nothing_hangs_over_the_flight_itself():
    plan = _plan()
    (flight,) = stairs_objects(plan)
    space = RoomSpace(plan, plan.room("stairwell"))
    corners = rect_corners(np.asarray([flight.position[:2]]), flight.size[:2], [flight.yaw])[0]
    lo, hi = corners.min(0), corners.max(0)
    x = float(lo[0] + hi[0]) / 2
    y = float(lo[1]) + 0.02 if lo[1] < 0.1 else float(hi[1]) - 0.02
    assert not _fits(space, (x, y), (0.8, 0.04, 0.6), 1.5, floor=False)
