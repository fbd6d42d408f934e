from __future__ import annotations

import pytest
from two_rooms import two_room_house

from anyhome.house import House, HouseObject


@pytest.fixture
def small_house() -> House:
    """Two rooms side by side, a door between, an entrance, a window, a few objects
    (one on top of another, one on a wall)."""
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
    return two_room_house(objs)
