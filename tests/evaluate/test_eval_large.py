"""Large houses: 12 rooms with 200 and 500 objects evaluate without false violations.

Evaluation speed is measured in benchmarks/run.py (eval_s), never asserted in tests."""

from __future__ import annotations

import pytest
from eval_houses import obj

from anyhome.evaluate import evaluate_house
from anyhome.house import Door, House, Room, Window

ROOM_M = 5.0


def grid_house(n_objects: int, cols: int = 4, rows: int = 3) -> House:
    """``cols x rows`` 5 m rooms joined by doors, an entrance, a window per room, and
    objects in a regular grid clear of the door zones."""
    rooms, doors, windows, connections = [], [], [], []
    for r in range(rows):
        for c in range(cols):
            x, y = c * ROOM_M, r * ROOM_M
            rid = f"r{r}{c}"
            rooms.append(Room(id=rid, name=f"room {rid}", type="office",
                              polygon=[(x, y), (x + ROOM_M, y), (x + ROOM_M, y + ROOM_M),
                                       (x, y + ROOM_M)],
                              materials={"floor": "carpet", "walls": "white paint"}))
            if c > 0:
                doors.append(Door(id=f"dx{r}{c}", rooms=(f"r{r}{c - 1}", rid),
                                  segment=((x, y + 2), (x, y + 3))))
                connections.append((f"r{r}{c - 1}", rid))
            if r > 0:
                doors.append(Door(id=f"dy{r}{c}", rooms=(f"r{r - 1}{c}", rid),
                                  segment=((x + 2, y), (x + 3, y))))
                connections.append((f"r{r - 1}{c}", rid))
    doors.append(Door(id="entrance", rooms=("r00", "outside"), segment=((0, 2), (0, 3))))
    connections.append(("r00", "outside"))
    for r in range(rows):
        for c in range(cols):
            x, y = c * ROOM_M, r * ROOM_M
            if r == rows - 1:
                seg = ((x + 2, y + ROOM_M), (x + 3, y + ROOM_M))
            elif r == 0:
                seg = ((x + 3, y), (x + 2, y))
            elif c == cols - 1:
                seg = ((x + ROOM_M, y + 2), (x + ROOM_M, y + 3))
            else:
                seg = ((x, y + 1), (x, y + 1.8))  # interior wall: breaks the window rule
            windows.append(Window(id=f"w{r}{c}", room=f"r{r}{c}", segment=seg))
    spots = [(1.0 + 0.75 * i, 1.0 + 0.75 * j) for i in range(5) for j in range(5)
             if not (1 <= i <= 3 and 1 <= j <= 3)]  # a ring of 16 spots per room
    objects = []
    k = 0
    while len(objects) < n_objects:
        room = rooms[k % len(rooms)]
        sx, sy = spots[(k // len(rooms)) % len(spots)]
        x0, y0 = room.polygon[0]
        objects.append(obj(f"o{k}", room.id, "box", (x0 + sx, y0 + sy, 0), (0.5, 0.5, 0.8)))
        k += 1
    return House(prompt="grid", seed=0, rooms=rooms, doors=doors, windows=windows,
                 connections=connections, objects=objects)


@pytest.mark.parametrize("n_objects", [200, 500])
def test_large_house_metrics(n_objects):
    report = evaluate_house(grid_house(n_objects))
    assert report.metrics["n_rooms"] == 12 and report.metrics["n_objects"] == n_objects
    assert report.metrics["connections_realized"] == 1.0
    assert report.metrics["nav_rooms_reachable_fraction"] == 1.0
