"""The two-room test house shared by the export and render tests (objects differ)."""

from anyhome.house import Door, House, Room, Window


def two_room_house(objects) -> House:
    """A living room and a bedroom side by side, a door between, an entrance and a
    window, holding ``objects``."""
    rooms = [
        Room(id="living", name="living room", type="living_room", polygon=[(0, 0), (5, 0), (5, 4), (0, 4)],
             materials={"floor": "white oak", "walls": "sage green paint"}),
        Room(id="bed", name="bedroom", type="bedroom", polygon=[(5, 0), (9, 0), (9, 4), (5, 4)],
             materials={"floor": "dark walnut", "walls": "pink"}),
    ]
    doors = [Door(id="d1", rooms=("living", "bed"), segment=((5, 1.5), (5, 2.4))),
             Door(id="d0", rooms=("living", "outside"), segment=((1, 0), (2, 0)))]
    windows = [Window(id="w1", room="bed", segment=((9, 1.2), (9, 2.8)), sill=0.9, height=1.2)]
    return House(prompt="a small test house", seed=0, rooms=rooms, doors=doors, windows=windows,
                 objects=list(objects), connections=[("living", "bed"), ("living", "outside")])
