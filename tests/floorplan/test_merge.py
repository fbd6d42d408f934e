"""Open-plan L rooms (anyhome.floorplan.merge): the union, the doors, windows and
connections that follow it, when a house gets one, and that merged houses stay valid."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Polygon

import anyhome
from anyhome.evaluate.validity import check_validity
from anyhome.floorplan.merge import (
    asks_open_plan,
    l_aspect,
    l_polygon,
    merge_open_plan,
    merge_rooms,
)
from anyhome.floorplan.options import FloorplanOptions
from anyhome.house import Door, Floorplan, House, Room, Window
from anyhome.plan.spec import HouseSpec, RoomSpec

OPEN_PROMPT = "An open-plan two-bedroom apartment with a living room, a dining room and a kitchen."


def _rect(x0: float, y0: float, x1: float, y1: float) -> list[tuple[float, float]]:
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def _floorplan() -> Floorplan:
    """A living room (5 x 4) with a dining room (2.5 x 3) against part of its east wall
    and a kitchen north of the dining room."""
    walls = {"floor": "oak", "walls": "white paint", "ceiling": "white paint"}
    rooms = [Room(id="living", name="Living Room", type="living_room", polygon=_rect(0, 0, 5, 4), materials=walls),
             Room(id="dining", name="Dining Room", type="dining_room", polygon=_rect(5, 0, 7.5, 3), materials=walls),
             Room(id="kitchen", name="Kitchen", type="kitchen", polygon=_rect(5, 3, 7.5, 6), materials=walls)]
    doors = [Door(id="door-0", rooms=("living", "dining"), segment=((5, 0.5), (5, 2.0)), kind="open"),
             Door(id="door-1", rooms=("dining", "kitchen"), segment=((6, 3), (6.9, 3))),
             Door(id="door-2", rooms=("living", "outside"), segment=((1, 0), (2, 0)))]
    windows = [Window(id="win-0", room="dining", segment=((7.5, 0.8), (7.5, 2.2))),
               Window(id="win-1", room="living", segment=((0, 1), (0, 2.5))),
               Window(id="win-2", room="kitchen", segment=((7.5, 4), (7.5, 5)))]
    conns = [("living", "dining"), ("dining", "kitchen"), ("living", "outside")]
    return Floorplan(rooms=rooms, doors=doors, windows=windows, connections=conns)


def _spec(prompt: str) -> HouseSpec:
    rooms = [RoomSpec(id="living", name="Living Room", type="living_room", area_m2=20),
             RoomSpec(id="dining", name="Dining Room", type="dining_room", area_m2=9),
             RoomSpec(id="kitchen", name="Kitchen", type="kitchen", area_m2=9)]
    return HouseSpec(prompt=prompt, rooms=rooms,
                     connections=[("living", "dining"), ("dining", "kitchen"), ("living", "outside")])


def test_two_rectangles_sharing_part_of_a_wall_make_a_ccw_l() -> None:
    outline = l_polygon(_rect(0, 0, 5, 4), _rect(5, 0, 8, 3))
    assert outline == [(0, 0), (8, 0), (8, 3), (5, 3), (5, 4), (0, 4)]
    assert Polygon(outline).exterior.is_ccw and Polygon(outline).area == pytest.approx(29.0)


@pytest.mark.parametrize("other", [_rect(5, 0, 8, 4), _rect(5, 1, 8, 3), _rect(6, 0, 8, 3)],
                         ids=["whole wall: a rectangle", "both ends offset: a T", "apart"])
def test_other_unions_are_no_l(other: list[tuple[float, float]]) -> None:
    assert l_polygon(_rect(0, 0, 5, 4), other) is None


def test_the_aspect_of_an_l_is_its_long_side_over_its_widest_disc() -> None:
    assert l_aspect(_rect(0, 0, 4, 2)) == pytest.approx(2.0, abs=0.01)
    assert l_aspect([(0, 0), (8, 0), (8, 3), (5, 3), (5, 4), (0, 4)]) == pytest.approx(2.0, abs=0.02)


def test_merging_removes_the_shared_opening_and_renames_the_rest() -> None:
    fp = merge_rooms(_floorplan(), "living", "dining")
    assert [r.id for r in fp.rooms] == ["living", "kitchen"]
    living = fp.room("living")
    assert living.merged == ["dining"] and len(living.polygon) == 6
    assert living.name == "Living Room and Dining Room" and living.type == "living_room"
    assert [(d.id, d.rooms) for d in fp.doors] == [("door-1", ("living", "kitchen")), ("door-2", ("living", "outside"))]
    assert [(w.id, w.room) for w in fp.windows] == [("win-0", "living"), ("win-1", "living"), ("win-2", "kitchen")]
    assert fp.connections == [("living", "kitchen"), ("living", "outside")]
    boundary = Polygon(living.polygon).exterior
    for d in fp.doors:
        assert boundary.distance(LineString(d.segment).centroid) < 1e-6


def test_a_merged_floorplan_passes_the_validity_rules() -> None:
    fp = merge_rooms(_floorplan(), "living", "dining")
    house = House(prompt="test", seed=0, rooms=fp.rooms, doors=fp.doors, windows=fp.windows,
                  connections=fp.connections)
    assert check_validity(house).violations == []
    again = House.from_json(house.to_json())
    assert again.room("living").merged == ["dining"]


def test_open_plan_words_always_merge_and_no_words_follow_the_chance() -> None:
    assert asks_open_plan(_spec("an open-plan flat")) and not asks_open_plan(_spec("a flat with a sleeping loft"))
    merged = merge_open_plan(_floorplan(), _spec("an open-plan flat"), np.random.default_rng(0))
    assert [r.id for r in merged.rooms if r.merged] == ["living"]
    never = FloorplanOptions(open_plan_probability=0.0)
    assert merge_open_plan(_floorplan(), _spec("a flat"), np.random.default_rng(0), never) == _floorplan()
    always = FloorplanOptions(open_plan_probability=1.0)
    assert merge_open_plan(_floorplan(), _spec("a flat"), np.random.default_rng(0), always) != _floorplan()
    off = FloorplanOptions(open_plan_max_rooms=0)
    assert merge_open_plan(_floorplan(), _spec("an open-plan flat"), np.random.default_rng(0), off) == _floorplan()


def test_a_too_long_l_is_refused() -> None:
    fp = _floorplan()
    long_dining = fp.rooms[1].model_copy(update={"polygon": _rect(5, 0, 8, 3)})  # 8 m by 4: aspect 2
    fp = fp.model_copy(update={"rooms": [fp.rooms[0], long_dining, fp.rooms[2]]})
    assert merge_open_plan(fp, _spec("an open-plan flat"), np.random.default_rng(0)) == fp


def test_an_open_plan_house_gets_an_l_room_furnished_for_both_rooms() -> None:
    house = anyhome.generate(OPEN_PROMPT, seed=0)
    (room,) = [r for r in house.rooms if r.merged]
    assert len(room.polygon) == 6 and room.merged == ["dining_room"]
    assert not any(d.reason == "room is missing from the floorplan" for d in house.dropped)
    names = {o.name for o in house.objects_in(room.id)}
    assert "dining table" in names and names & {"sofa", "sectional sofa", "loveseat"}
    assert check_validity(house).violations == []


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000))
def test_any_open_plan_house_is_valid(seed: int) -> None:
    house = anyhome.generate(OPEN_PROMPT, seed=seed)
    assert check_validity(house).violations == []
    for room in house.rooms:
        if room.merged:
            assert len(room.polygon) == 6 and Polygon(room.polygon).exterior.is_ccw
            assert all(d.rooms.count(room.id) < 2 for d in house.doors)


def test_the_aspect_test_answers_as_the_widest_disc_does():
    """``l_aspect_over`` skips the widest-disc search where the bounding box alone is too
    long: its answer is still ``l_aspect(...) > limit`` for rectangles and Ls of every
    proportion, at limits around their aspects."""
    from anyhome.floorplan.merge import l_aspect, l_aspect_over

    rng = np.random.default_rng(3)
    for _ in range(150):
        w, h = (round(float(v), 2) for v in rng.uniform(1.0, 9.0, size=2))
        cx, cy = round(float(rng.uniform(0.2, 0.8)) * w, 2), round(float(rng.uniform(0.2, 0.8)) * h, 2)
        rect = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
        ell = [(0.0, 0.0), (w, 0.0), (w, cy), (cx, cy), (cx, h), (0.0, h)]
        for outline in (rect, ell):
            aspect = l_aspect(outline)
            for limit in (aspect - 1e-6, aspect, aspect + 1e-6, 1.5, 2.0, 3.0):
                assert l_aspect_over(outline, limit) == (aspect > limit)
