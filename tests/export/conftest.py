from __future__ import annotations

import pytest

from anyhome.house import Door, House, HouseObject, Room, Window


@pytest.fixture
def small_house() -> House:
    """Two rooms side by side, a door between, an entrance, a window, a few objects
    (one on top of another, one on a wall)."""
    rooms = [
        Room(id="living", name="living room", type="living_room", polygon=[(0, 0), (5, 0), (5, 4), (0, 4)],
             materials={"floor": "white oak", "walls": "sage green paint"}),
        Room(id="bed", name="bedroom", type="bedroom", polygon=[(5, 0), (9, 0), (9, 4), (5, 4)],
             materials={"floor": "dark walnut", "walls": "pink"}),
    ]
    doors = [Door(id="d1", rooms=("living", "bed"), segment=((5, 1.5), (5, 2.4))),
             Door(id="d0", rooms=("living", "outside"), segment=((1, 0), (2, 0)))]
    windows = [Window(id="w1", room="bed", segment=((9, 1.2), (9, 2.8)), sill=0.9, height=1.2)]
    objs = [
        HouseObject(id="sofa1", room="living", name="grey sofa", category="sofa", position=(2.5, 3.5, 0),
                    size=(2.0, 0.9, 0.85), yaw=3.141592653589793, material="grey linen"),
        HouseObject(id="ct", room="living", name="coffee table", category="coffee_table",
                    position=(2.5, 2.2, 0), size=(1.1, 0.6, 0.42)),
        HouseObject(id="vase1", room="living", name="vase", category="vase", position=(2.5, 2.2, 0.42),
                    size=(0.2, 0.2, 0.4), support="ct"),
        HouseObject(id="art", room="living", name="painting", category="wall_art", position=(0.02, 2.0, 1.3),
                    size=(1.0, 0.04, 0.7), yaw=-1.5707963267948966, support="wall"),
        HouseObject(id="bed1", room="bed", name="double bed", category="bed", position=(7.0, 1.05, 0),
                    size=(1.6, 2.1, 1.1), material="dark walnut"),
        HouseObject(id="ns", room="bed", name="nightstand", category="nightstand", position=(8.2, 0.25, 0),
                    size=(0.5, 0.4, 0.55)),
    ]
    return House(prompt="a small test house", seed=0, rooms=rooms, doors=doors, windows=windows,
                 objects=objs, connections=[("living", "bed"), ("living", "outside")])
