"""A hand-built valid two-room house that the rule tests mutate one thing at a time.

Plan (meters)::

    y=4 +-----------w_l-----------+-----------------------+
        | living (L)              |  bedroom (B)           |
        | painting on west wall   d_lb               w_b (east wall)
        | sofa against north wall |  bed against south     |
    y=0 +---d_out-----------------+-----------------------+
        x=0                      x=6                     x=10
"""

from __future__ import annotations

import math

from anyhome.house import Door, House, HouseObject, Room, Window


def obj(oid: str, room: str, name: str, position, size, yaw: float = 0.0,
        support: str = "floor", category: str | None = None, **kw) -> HouseObject:
    return HouseObject(id=oid, room=room, name=name, category=category or name.replace(" ", "_"),
                       position=tuple(position), size=tuple(size), yaw=yaw, support=support, **kw)


def make_valid_house() -> House:
    rooms = [
        Room(id="L", name="living room", type="living_room",
             polygon=[(0, 0), (6, 0), (6, 4), (0, 4)], style="gothic",
             materials={"floor": "dark walnut planks", "walls": "burgundy damask wallpaper"}),
        Room(id="B", name="master bedroom", type="bedroom",
             polygon=[(6, 0), (10, 0), (10, 4), (6, 4)], style="gothic",
             materials={"floor": "oak", "walls": "grey plaster"}),
    ]
    doors = [
        Door(id="d_out", rooms=("L", "outside"), segment=((1, 0), (2, 0))),
        Door(id="d_lb", rooms=("L", "B"), segment=((6, 1.5), (6, 2.5))),
    ]
    windows = [
        Window(id="w_l", room="L", segment=((2, 4), (4, 4))),
        Window(id="w_b", room="B", segment=((10, 1.5), (10, 2.5))),
    ]
    objects = [
        obj("sofa", "L", "sofa", (3, 3.55, 0), (2, 0.9, 0.8), yaw=math.pi, material="velvet"),
        obj("rug", "L", "rug", (3, 2.2, 0), (2, 1.5, 0.008)),
        obj("table", "L", "coffee table", (3, 2.2, 0), (1.0, 0.5, 0.45)),
        obj("painting", "L", "painting", (0.05, 2, 1.2), (1.0, 0.1, 0.7), yaw=-math.pi / 2,
            support="wall"),
        obj("pendant", "L", "pendant lamp", (3, 2, 2.4), (0.5, 0.5, 0.3), support="ceiling"),
        obj("bed", "B", "bed", (8, 1.0, 0), (1.6, 2.0, 0.5), description="antique bed"),
        obj("ns", "B", "bedside table", (9.3, 0.25, 0), (0.5, 0.5, 0.55)),
        obj("lamp", "B", "table lamp", (9.3, 0.25, 0.55), (0.3, 0.3, 0.4), support="ns"),
    ]
    return House(prompt="test house", seed=0, style="gothic", rooms=rooms,
                 connections=[("L", "outside"), ("L", "B")], doors=doors, windows=windows,
                 objects=objects)
