"""The defect catalogue: one valid generated house, many injected defects, each caught.

The house is generated once per test session (``anyhome.generate`` on a short prompt,
seed 0) and checked valid first. Each defect kind is a small function that edits a deep
copy of it; ``evaluate_house`` must then report a violation (``report.ok`` False) of one
of the expected codes. Edits build elements with ``model_copy(update=...)``, which does
not validate, so NaN, infinite and non-positive numbers reach the evaluator as they can
from Python code. A handful run through the real CLI (``python -m anyhome eval DIR
--strict``): exit 1, or, for defects that ``anyhome.house.load`` may refuse, exit 2 with
one ``error:`` line.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass

import pytest

from anyhome import generate
from anyhome.evaluate import evaluate_house
from anyhome.house import House, HouseObject, Room

PROMPT = "a two-bedroom apartment"
NAN, INF = float("nan"), float("inf")


@pytest.fixture(scope="session")
def valid_house() -> House:
    house = generate(PROMPT, seed=0)
    report = evaluate_house(house)
    assert report.ok, [str(v) for v in report.violations]
    return house


# ------------------------------------------------------------------ helpers
def room(h: House, pred: Callable[[Room], bool] = lambda r: True) -> Room:
    return next(r for r in h.rooms if pred(r))


def bedroom(h: House) -> Room:
    return room(h, lambda r: r.type == "bedroom")


def bounds(r: Room) -> tuple[float, float, float, float]:
    xs, ys = [p[0] for p in r.polygon], [p[1] for p in r.polygon]
    return min(xs), min(ys), max(xs), max(ys)


def centre(r: Room) -> tuple[float, float]:
    x0, y0, x1, y1 = bounds(r)
    return (x0 + x1) / 2, (y0 + y1) / 2


def find(h: House, pred: Callable[[HouseObject], bool]) -> int:
    return next(k for k, o in enumerate(h.objects) if pred(o))


def edit_object(h: House, pred: Callable[[HouseObject], bool], **changes) -> None:
    k = find(h, pred)
    h.objects[k] = h.objects[k].model_copy(update=changes)


def on_floor(o: HouseObject) -> bool:
    return o.support == "floor" and o.size[2] > 0.3


def on_object(o: HouseObject) -> bool:
    return o.support not in ("floor", "wall", "ceiling")


def on_wall(o: HouseObject) -> bool:
    return o.support == "wall"


def add_object(h: House, oid: str, r: Room, position, size, support="floor", **kw) -> None:
    h.objects.append(HouseObject(id=oid, room=r.id, name=oid, category=oid,
                                 position=tuple(position), size=tuple(size), support=support,
                                 **kw))


def edit_room(h: House, pred: Callable[[Room], bool], **changes) -> None:
    k = next(i for i, r in enumerate(h.rooms) if pred(r))
    h.rooms[k] = h.rooms[k].model_copy(update=changes)


def interior_door(h: House) -> int:
    return next(k for k, d in enumerate(h.doors) if "outside" not in d.rooms)


def entrance(h: House) -> int:
    return next(k for k, d in enumerate(h.doors) if "outside" in d.rooms)


def edit_door(h: House, k: int, **changes) -> None:
    h.doors[k] = h.doors[k].model_copy(update=changes)


def edit_window(h: House, pred, **changes) -> None:
    k = next(i for i, w in enumerate(h.windows) if pred(w))
    h.windows[k] = h.windows[k].model_copy(update=changes)


def door_normal_point(seg, depth: float) -> tuple[float, float]:
    (x1, y1), (x2, y2) = seg
    length = math.hypot(x2 - x1, y2 - y1)
    nx, ny = -(y2 - y1) / length, (x2 - x1) / length
    return (x1 + x2) / 2 + nx * depth, (y1 + y2) / 2 + ny * depth


# ------------------------------------------------------------------ defects
def out_of_bounds(h):
    k = find(h, on_floor)
    x0, _, x1, _ = bounds(room(h, lambda r: r.id == h.objects[k].room))
    o = h.objects[k]
    h.objects[k] = o.model_copy(update={"position": (x1 + 0.5, o.position[1], 0.0)})


def collision(h):
    o = h.objects[find(h, on_floor)]
    h.objects.append(o.model_copy(update={"id": o.id + "-twin"}))


def floating(h):
    edit_object(h, on_floor, position=(*h.objects[find(h, on_floor)].position[:2], 0.3))


def sunk_into_floor(h):
    edit_object(h, on_floor, position=(*h.objects[find(h, on_floor)].position[:2], -0.2))


def ceiling_object_off_ceiling(h):
    r = bedroom(h)
    add_object(h, "pendant", r, (*centre(r), 1.5), (0.4, 0.4, 0.3), support="ceiling")


def wall_object_off_wall(h):
    o = h.objects[find(h, on_wall)]
    cx, cy = centre(room(h, lambda r: r.id == o.room))
    x, y = o.position[0] + (cx - o.position[0]) / 2, o.position[1] + (cy - o.position[1]) / 2
    edit_object(h, on_wall, position=(x, y, o.position[2]))


def wall_object_covers_window(h):
    r = bedroom(h)
    w = next(w for w in h.windows if w.room == r.id)
    (x1, y1), (x2, y2) = w.segment
    length = math.hypot(x2 - x1, y2 - y1)
    yaw = math.atan2(y2 - y1, x2 - x1)  # local x along the window
    fx, fy = -math.sin(yaw), math.cos(yaw)  # the front
    cx, cy = centre(r)
    mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    if (cx - mx) * fx + (cy - my) * fy < 0:  # face into the room
        yaw, fx, fy = yaw + math.pi, -fx, -fy
    depth = 0.05
    add_object(h, "mirror", r, (mx + fx * depth / 2, my + fy * depth / 2, w.sill + 0.1),
               (min(1.0, length), depth, 0.5), support="wall", yaw=yaw)


def door_blocked(h):
    d = h.doors[interior_door(h)]
    a, b = d.rooms
    spots = [(door_normal_point(d.segment, depth), r) for depth in (0.45, -0.45)
             for r in h.rooms if r.id in (a, b)]
    (x, y), r = next(((x, y), r) for (x, y), r in spots if _contains(r, x, y))
    add_object(h, "chair", r, (x, y, 0), (0.4, 0.4, 0.9))


def _contains(r: Room, x: float, y: float) -> bool:
    from shapely.geometry import Point, Polygon

    return Polygon(r.polygon).contains(Point(x, y))


def missing_supporter(h):
    edit_object(h, on_object, support="ghost-table")


def self_supported(h):
    o = h.objects[find(h, on_object)]
    edit_object(h, on_object, support=o.id)


def off_supporter(h):
    o = h.objects[find(h, on_object)]
    edit_object(h, on_object, position=(o.position[0] + 1.5, o.position[1], o.position[2]))


def supporter_gap(h):
    o = h.objects[find(h, on_object)]
    edit_object(h, on_object, position=(*o.position[:2], o.position[2] + 0.3))


def unknown_support_word(h):
    edit_object(h, on_floor, support="air")


def object_in_unknown_room(h):
    edit_object(h, on_floor, room="attic")


def object_taller_than_room(h):
    """A floor object with nothing above or beside it made 4 m tall (a bookshelf under
    a 2.7 m ceiling): the only defect is its height."""
    from anyhome.geometry import footprint_polygon

    def alone(o: HouseObject) -> bool:
        fp = footprint_polygon(o.position, o.size, o.yaw).buffer(0.02)
        return not any(x.id != o.id and fp.intersects(
            footprint_polygon(x.position, x.size, x.yaw)) for x in h.objects)

    o = h.objects[find(h, lambda o: on_floor(o) and alone(o))]
    edit_object(h, lambda x: x.id == o.id, size=(*o.size[:2], 4.0))


def object_on_supporter_above_ceiling(h):
    edit_object(h, on_object, size=(0.2, 0.2, 3.0))


def wall_object_above_ceiling(h):
    o = h.objects[find(h, on_wall)]
    height = room(h, lambda r: r.id == o.room).height
    edit_object(h, on_wall, position=(*o.position[:2], height - 0.1))


def zero_size(h):
    edit_object(h, on_floor, size=(0.0, 0.5, 0.5))


def negative_size(h):
    edit_object(h, on_floor, size=(0.5, 0.5, -0.8))


def nan_position(h):
    edit_object(h, on_floor, position=(NAN, 1.0, 0.0))


def infinite_size(h):
    edit_object(h, on_floor, size=(INF, 0.5, 0.5))


def nan_yaw(h):
    edit_object(h, on_floor, yaw=NAN)


def dangling_anchor(h):
    edit_object(h, on_floor, anchor="no-such-object")


def duplicate_object_id(h):
    o = h.objects[find(h, on_floor)]
    k = find(h, lambda x: x.id != o.id and on_floor(x))
    h.objects[k] = h.objects[k].model_copy(update={"id": o.id})


def unsafe_id(h):
    edit_object(h, on_floor, id='x" onmouseover="alert(1)')


def overlapping_rooms(h):
    r = bedroom(h)
    x0, y0, x1, y1 = bounds(r)
    h.rooms.append(Room(id="annex", name="annex", type="storage",
                        polygon=[(x1 - 1, y0 + 1), (x1 + 2, y0 + 1), (x1 + 2, y0 + 3),
                                 (x1 - 1, y0 + 3)],
                        materials={"floor": "oak", "walls": "paint"}))


def clockwise_room(h):
    edit_room(h, lambda r: r.id == bedroom(h).id, polygon=list(reversed(bedroom(h).polygon)))


def bow_tie_room(h):
    x0, y0, x1, y1 = bounds(bedroom(h))
    edit_room(h, lambda r: r.id == bedroom(h).id,
              polygon=[(x0, y0), (x1, y1), (x1, y0), (x0, y1)])


def two_point_room(h):
    x0, y0, x1, y1 = bounds(bedroom(h))
    edit_room(h, lambda r: r.id == bedroom(h).id, polygon=[(x0, y0), (x1, y1)])


def repeated_closing_point(h):
    p = bedroom(h).polygon
    edit_room(h, lambda r: r.id == bedroom(h).id, polygon=[*p, p[0]])


def room_height(value):
    def defect(h):
        edit_room(h, lambda r: r.id == bedroom(h).id, height=value)
    defect.__name__ = f"room_height_{value}"
    return defect


def kilometre_room(h):
    x0, y0, _, _ = bounds(bedroom(h))
    edit_room(h, lambda r: r.id == bedroom(h).id,
              polygon=[(x0, y0 - 1000), (x0 + 1000, y0 - 1000), (x0 + 1000, y0), (x0, y0)])


def unknown_room_type(h):
    edit_room(h, lambda r: r.id == bedroom(h).id, type="spaceship_bridge")


def missing_materials(h):
    edit_room(h, lambda r: r.id == bedroom(h).id, materials={})


def duplicate_room_id(h):
    a = h.rooms[0]
    h.rooms[1] = h.rooms[1].model_copy(update={"id": a.id})


def no_rooms(h):
    h.rooms, h.doors, h.windows, h.objects, h.connections = [], [], [], [], []


def door_off_shared_wall(h):
    k = interior_door(h)
    (x1, y1), (x2, y2) = h.doors[k].segment
    dx, dy = door_normal_point(((x1, y1), (x2, y2)), 0.5)
    mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    sx, sy = dx - mx, dy - my
    edit_door(h, k, segment=((x1 + sx, y1 + sy), (x2 + sx, y2 + sy)))


def entrance_on_interior_wall(h):
    k, inner = entrance(h), h.doors[interior_door(h)]
    room_id = next(r for r in h.doors[k].rooms if r != "outside")
    other = next(r for r in inner.rooms if r != room_id)
    edit_door(h, k, rooms=(other, "outside"), segment=inner.segment)


def no_entrance(h):
    k = entrance(h)
    pair = set(h.doors[k].rooms)
    del h.doors[k]
    h.connections = [c for c in h.connections if set(c) != pair]


def disconnected_room(h):
    rid = bedroom(h).id
    h.doors = [d for d in h.doors if rid not in d.rooms]
    h.connections = [c for c in h.connections if rid not in c]


def connection_without_door(h):
    a = bedroom(h).id
    doored = {r for d in h.doors if a in d.rooms for r in d.rooms}
    b = room(h, lambda r: r.id not in doored).id  # a room no door joins to the bedroom
    h.connections.append((a, b))


def connection_to_unknown_room(h):
    h.connections.append((bedroom(h).id, "attic"))


def door_to_unknown_room(h):
    k = interior_door(h)
    edit_door(h, k, rooms=(h.doors[k].rooms[0], "attic"))


def degenerate_door(h):
    k = interior_door(h)
    p = h.doors[k].segment[0]
    edit_door(h, k, segment=(p, p))


def door_taller_than_room(h):
    edit_door(h, interior_door(h), height=3.5)


def door_zero_height(h):
    edit_door(h, interior_door(h), height=0.0)


def door_nan_segment(h):
    edit_door(h, interior_door(h), segment=((NAN, 0.0), (1.0, 0.0)))


def window_on_interior_wall(h):
    rid = bedroom(h).id
    d = next(d for d in h.doors if rid in d.rooms and "outside" not in d.rooms)
    edit_window(h, lambda w: w.room == rid, segment=d.segment)


def habitable_without_window(h):
    rid = bedroom(h).id
    h.windows = [w for w in h.windows if w.room != rid]


def window_sill_above_ceiling(h):
    edit_window(h, lambda w: w.room == bedroom(h).id, sill=3.0)


def window_top_above_ceiling(h):
    edit_window(h, lambda w: w.room == bedroom(h).id, sill=1.5, height=1.5)


def window_negative_sill(h):
    edit_window(h, lambda w: w.room == bedroom(h).id, sill=-0.5)


def window_unknown_room(h):
    edit_window(h, lambda w: w.room == bedroom(h).id, room="attic")


def window_infinite_height(h):
    edit_window(h, lambda w: w.room == bedroom(h).id, height=INF)


def unreachable_area(h):
    """A floor-to-wall block across the hallway: rooms behind it cannot be walked to."""
    hall = room(h, lambda r: r.type == "hallway")
    x0, y0, x1, y1 = bounds(hall)
    ent = h.doors[entrance(h)]
    ey = (ent.segment[0][1] + ent.segment[1][1]) / 2
    y = ey + 1.5 if ey - y0 < y1 - ey else ey - 1.5  # 1.5 m into the hallway from the entrance
    add_object(h, "partition", hall, ((x0 + x1) / 2, y, 0), (x1 - x0 - 0.02, 0.2, 1.0))


@dataclass(frozen=True)
class Defect:
    edit: Callable[[House], None]
    codes: frozenset[str]
    """At least one of these codes must be reported."""
    load_may_refuse: bool = False
    """``anyhome.house.load`` (with its validation) may refuse the saved file."""

    @property
    def name(self) -> str:
        return self.edit.__name__


def D(edit, *codes, refuse=False):  # noqa: N802
    return Defect(edit, frozenset(codes), refuse)


DEFECTS = [
    D(out_of_bounds, "out_of_bounds"),
    D(collision, "collision"),
    D(floating, "floating"),
    D(sunk_into_floor, "below_floor"),
    D(ceiling_object_off_ceiling, "floating"),
    D(wall_object_off_wall, "wall_object_off_wall"),
    D(wall_object_covers_window, "covers_opening"),
    D(door_blocked, "door_blocked"),
    D(missing_supporter, "missing_supporter", refuse=True),
    D(self_supported, "missing_supporter", refuse=True),
    D(off_supporter, "off_supporter"),
    D(supporter_gap, "supporter_gap"),
    D(unknown_support_word, "floating", refuse=True),
    D(object_in_unknown_room, "unknown_room", refuse=True),
    D(object_taller_than_room, "taller_than_room"),
    D(object_on_supporter_above_ceiling, "taller_than_room"),
    D(wall_object_above_ceiling, "taller_than_room"),
    D(zero_size, "bad_size", refuse=True),
    D(negative_size, "bad_size", refuse=True),
    D(nan_position, "non_finite", refuse=True),
    D(infinite_size, "non_finite", refuse=True),
    D(nan_yaw, "non_finite", refuse=True),
    D(dangling_anchor, "unknown_anchor", refuse=True),
    D(duplicate_object_id, "duplicate_id", refuse=True),
    D(unsafe_id, "unsafe_id", refuse=True),
    D(overlapping_rooms, "room_overlap"),
    D(clockwise_room, "polygon_not_ccw"),
    D(bow_tie_room, "invalid_polygon", refuse=True),
    D(two_point_room, "invalid_polygon", refuse=True),
    D(repeated_closing_point, "repeated_point", refuse=True),
    D(room_height(-2.7), "room_height", refuse=True),
    D(room_height(0.5), "room_height", refuse=True),
    D(room_height(INF), "non_finite", refuse=True),
    D(room_height(NAN), "non_finite", refuse=True),
    D(kilometre_room, "room_too_large", refuse=True),
    D(unknown_room_type, "unknown_room_type", refuse=True),
    D(missing_materials, "missing_materials", refuse=True),
    D(duplicate_room_id, "duplicate_id", refuse=True),
    D(no_rooms, "no_rooms", refuse=True),
    D(door_off_shared_wall, "door_off_boundary"),
    D(entrance_on_interior_wall, "door_off_boundary"),
    D(no_entrance, "no_entrance"),
    D(disconnected_room, "disconnected_room"),
    D(connection_without_door, "connection_missing"),
    D(connection_to_unknown_room, "bad_connection", refuse=True),
    D(door_to_unknown_room, "bad_door_rooms", refuse=True),
    D(degenerate_door, "door_off_boundary", refuse=True),
    D(door_taller_than_room, "door_too_tall"),
    D(door_zero_height, "bad_opening", refuse=True),
    D(door_nan_segment, "non_finite", refuse=True),
    D(window_on_interior_wall, "window_off_boundary"),
    D(habitable_without_window, "habitable_without_window"),
    D(window_sill_above_ceiling, "window_above_ceiling"),
    D(window_top_above_ceiling, "window_above_ceiling"),
    D(window_negative_sill, "bad_opening", refuse=True),
    D(window_unknown_room, "bad_window_room", refuse=True),
    D(window_infinite_height, "non_finite", refuse=True),
    D(unreachable_area, "unreachable_room", "unreachable_door"),
]

CLI_DEFECTS = ["object_taller_than_room", "window_sill_above_ceiling", "door_taller_than_room",
               "room_height_0.5", "dangling_anchor", "no_rooms", "nan_position",
               "collision"]


def test_catalogue_is_large_and_distinct():
    names = [d.name for d in DEFECTS]
    assert len(names) == len(set(names)) >= 42
    assert set(CLI_DEFECTS) <= set(names)


def injected(valid_house: House, defect: Defect) -> House:
    house = valid_house.model_copy(deep=True)
    defect.edit(house)
    return house


@pytest.mark.parametrize("defect", DEFECTS, ids=lambda d: d.name)
def test_injected_defect_is_reported(valid_house, defect):
    house = injected(valid_house, defect)
    report = evaluate_house(house)
    assert not report.ok, f"{defect.name}: no violation"
    assert report.codes() & defect.codes, (defect.name, sorted(report.codes()))
    assert all("\n" not in line for line in report.summary_lines())


@pytest.mark.parametrize("name", CLI_DEFECTS)
def test_injected_defect_through_the_cli(valid_house, tmp_path, name):
    defect = next(d for d in DEFECTS if d.name == name)
    house = injected(valid_house, defect)
    # written as plain JSON (bare NaN tokens included), not through House.to_json, which
    # refuses to save a house that load would refuse
    (tmp_path / "house.json").write_text(json.dumps(house.model_dump(mode="json")), encoding="utf-8")
    proc = subprocess.run([sys.executable, "-m", "anyhome", "eval", str(tmp_path), "--strict"],
                          capture_output=True, text=True, timeout=60)
    assert "Traceback" not in proc.stderr
    if proc.returncode == 2 and defect.load_may_refuse:
        lines = proc.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("error:"), proc.stderr
    else:
        assert proc.returncode == 1, (proc.returncode, proc.stdout, proc.stderr)
        assert "INVALID" in proc.stdout
        assert any(code in proc.stdout for code in defect.codes), proc.stdout


def test_the_valid_house_passes_the_cli(valid_house, tmp_path):
    (tmp_path / "house.json").write_text(valid_house.to_json(), encoding="utf-8")
    proc = subprocess.run([sys.executable, "-m", "anyhome", "eval", str(tmp_path), "--strict"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
