"""Furnishing as a designer would (issue 14): rugs under their group, the TV stand on the
wall across from the sofa with its sightline kept clear, key groups kept by making room,
curtains beside windows, ornaments set down on the floor when no top is free."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon

from anyhome.geometry import footprint_polygon
from anyhome.layout import layout_house
from anyhome.layout.groups import sightline as sightline_corners
from anyhome.layout.layers import LAYER_HEIGHT_M
from tests.layout.helpers import check_valid, front, group, house_spec, item, rect, single_room

SOFA = item("sofa", "sofa", (2.1, 0.9, 0.85), "place_wall", params={"wall": "longest"}, tags=["seat"])
COFFEE = item("coffee table", "coffee_table", (1.1, 0.6, 0.45), "place_front", params={"distance_m": 0.45},
              tags=["table"])
TV_STAND = item("tv stand", "tv_stand", (1.6, 0.45, 0.5), "place_front",
                params={"distance_m": 2.2, "facing": "toward", "to_wall": True}, tags=["storage", "surface"])
RUG = item("rug", "rug", (2.0, 1.4, 0.01), "place_center", tags=["floor_layer"])
ARMCHAIR = item("armchair", "armchair", (0.85, 0.85, 0.9), "place_center", tags=["seat"])
"""Drawn to the middle of the room, where the sightline runs."""


def _lounge(polygon=rect(0, 0, 5.5, 4.2), door=((0.3, 0.0), (1.2, 0.0)), extra=(), seed=0):
    fp = single_room(polygon, door=door)
    groups = [group("lounge", SOFA, [COFFEE, TV_STAND], priority=0),
              group("rug", RUG, priority=6), *extra]
    res = layout_house(house_spec({"r1": groups}), fp, np.random.default_rng(seed))
    return fp, res


def _one(res, name):
    objs = [o for o in res.objects if o.name == name]
    assert len(objs) == 1, (name, res.dropped)
    return objs[0]


@pytest.mark.parametrize("seed", range(4))
def test_rug_lies_under_the_seating_group(seed):
    fp, res = _lounge(seed=seed)
    assert check_valid(fp, res.objects) == []
    rug, sofa, table = _one(res, "rug"), _one(res, "sofa"), _one(res, "coffee table")
    assert rug.size[2] == pytest.approx(LAYER_HEIGHT_M)
    under = footprint_polygon(rug.position, rug.size, rug.yaw)
    # under the coffee table and the sofa's front legs, not out in the room
    assert under.contains(footprint_polygon(table.position, table.size, table.yaw).centroid)
    assert under.intersects(footprint_polygon(sofa.position, sofa.size, sofa.yaw))
    assert rug.anchor == sofa.id


def test_rug_is_not_an_obstacle_for_furniture_placed_later():
    """Furniture may stand on a laid rug (it overlaps it by at most the 1 cm tolerance),
    but a second rug may not overlap the first."""
    fp, res = _lounge(extra=[group("rug2", RUG.model_copy(update={"name": "second rug"}), priority=7)])
    assert check_valid(fp, res.objects) == []
    rugs = [o for o in res.objects if "floor_layer" in o.tags]
    assert len(rugs) == 2
    a, b = (footprint_polygon(o.position, o.size, o.yaw) for o in rugs)
    assert a.intersection(b).area < 1e-6


@pytest.mark.parametrize("seed", range(4))
def test_tv_stand_stands_on_the_wall_across_from_the_sofa(seed):
    fp, res = _lounge(seed=seed)
    sofa, tv = _one(res, "sofa"), _one(res, "tv stand")
    room = Polygon(fp.rooms[0].polygon)
    back = np.asarray(tv.position[:2]) - front(tv.yaw) * tv.size[1] / 2
    assert room.exterior.distance(Point(back)) < 0.02
    assert float(front(tv.yaw) @ front(sofa.yaw)) < -0.99  # they face each other


def test_armchairs_stay_out_of_the_sightline():
    chairs = group("armchairs", ARMCHAIR, repeat=3, priority=2)
    for seed in range(4):
        fp, res = _lounge(polygon=rect(0, 0, 6.5, 5.0), extra=[chairs], seed=seed)
        assert check_valid(fp, res.objects) == []
        sofa, tv = _one(res, "sofa"), _one(res, "tv stand")
        a = np.asarray(sofa.position[:2]) + front(sofa.yaw) * sofa.size[1] / 2
        b = np.asarray(tv.position[:2]) + front(tv.yaw) * tv.size[1] / 2
        strip = LineString([a, b]).buffer(min(sofa.size[0], tv.size[0]) / 2, cap_style="flat")
        chairs_placed = [o for o in res.objects if o.name == "armchair"]
        assert chairs_placed
        for o in chairs_placed:
            assert footprint_polygon(o.position, o.size, o.yaw).intersection(strip).area < 0.01


def test_key_group_is_kept_by_making_room():
    """A bed the room can hold is kept even when optional groups, placed first, would
    have taken its place: the room is furnished again, key groups first."""
    fp = single_room(rect(0, 0, 3.2, 3.0), door=((0.2, 0.0), (1.1, 0.0)))
    shelves = group("shelves", item("bookshelf", "shelf", (1.0, 0.4, 2.0), "place_wall"), repeat=4,
                    priority=-1, arrangement="along_walls")
    bed = group("bed", item("bed", "bed", (1.6, 2.0, 0.5), "place_wall", tags=["bed"]), priority=0, required=True)
    res = layout_house(house_spec({"r1": [shelves, bed]}), fp, np.random.default_rng(0))
    assert check_valid(fp, res.objects) == []
    assert any(o.name == "bed" for o in res.objects), res.dropped
    assert all(not d.key for d in res.dropped)


@pytest.mark.parametrize("seed", range(3))
def test_members_of_other_key_groups_give_way_to_a_key_anchor(seed):
    """A cloakroom too small for its bench, the bench's coat rack and the boot shelf keeps
    the shelf (what the room is for) and leaves the coat rack out, saying why."""
    fp = single_room(rect(0, 0, 1.7, 1.4), door=((0.1, 0.0), (1.0, 0.0)))
    rack = item("coat rack", "shelf", (0.8, 0.3, 1.8), "place_beside", params={"side": "left"}, tags=["storage"])
    bench = group("bench", item("bench", "bench", (1.1, 0.4, 0.45), "place_wall", tags=["seat"]), [rack], priority=0)
    shelf = group("shelf", item("boot shelf", "shelf", (1.0, 0.35, 1.2), "place_wall", tags=["storage"]), priority=0)
    res = layout_house(house_spec({"r1": [bench, shelf]}), fp, np.random.default_rng(seed))
    assert check_valid(fp, res.objects) == []
    assert sorted(o.name for o in res.objects) == ["bench", "boot shelf"]
    assert [(d.name, d.key) for d in res.dropped] == [("coat rack", False)]
    assert "make room" in res.dropped[0].reason


def test_key_item_that_cannot_fit_is_marked():
    fp = single_room(rect(0, 0, 1.6, 1.6), door=((0.2, 0.0), (1.1, 0.0)))  # shorter than the narrowest bed
    bed = group("bed", item("bed", "bed", (1.8, 2.1, 0.5), "place_wall", tags=["bed"]), priority=0)
    res = layout_house(house_spec({"r1": [bed]}), fp, np.random.default_rng(0))
    assert [d.key for d in res.dropped if d.name == "bed"] == [True]


def test_a_key_anchor_too_big_for_the_room_is_placed_narrower_last():
    """A 1.8 m wide bed in a 2 x 2 m room fits at none of the shrink scales: it is placed
    at NARROW_SCALES (1.08 m wide, 1.68 m long) rather than dropped."""
    from anyhome.layout.solver import NARROW_SCALES

    fp = single_room(rect(0, 0, 2.0, 2.0), door=((0.2, 0.0), (1.1, 0.0)))
    bed = group("bed", item("bed", "bed", (1.8, 2.1, 0.5), "place_wall", tags=["bed"]), priority=0)
    res = layout_house(house_spec({"r1": [bed]}), fp, np.random.default_rng(0))
    assert not res.dropped
    (got,) = res.objects
    assert got.size[:2] == pytest.approx((1.8 * NARROW_SCALES[0], 2.1 * NARROW_SCALES[1]))
    assert check_valid(fp, res.objects) == []


def test_curtain_hangs_beside_a_window():
    win = ((1.5, 3.0), (3.0, 3.0))
    fp = single_room(rect(0, 0, 4.0, 3.0), windows=[win])
    curtain = item("curtain", "curtain", (1.4, 0.08, 2.3), "place_on_wall", params={"elevation_m": 0.1})
    res = layout_house(house_spec({"r1": []}, ornaments={"r1": [curtain]}), fp, np.random.default_rng(0))
    assert check_valid(fp, res.objects) == []
    c = _one(res, "curtain")
    assert c.support == "wall" and abs(c.position[1] - 3.0) < 0.1
    x0, x1 = c.position[0] - c.size[0] / 2, c.position[0] + c.size[0] / 2
    assert min(abs(x1 - 1.5), abs(x0 - 3.0)) < 0.1  # right at the window's edge


def test_plant_goes_on_the_floor_when_no_top_is_free():
    fp = single_room(rect(0, 0, 3.0, 3.0))
    plant = item("small plant", "plant", (0.25, 0.25, 0.35), "place_top")
    res = layout_house(house_spec({"r1": []}, ornaments={"r1": [plant]}), fp, np.random.default_rng(0))
    assert check_valid(fp, res.objects) == []
    assert _one(res, "small plant").support == "floor"


def test_a_tv_stand_of_its_own_faces_the_sofa_and_keeps_its_view_clear():
    """A TV group placed after the lounge (place_front to_wall, target sofa): on the wall
    across from the sofa, and an armchair placed later stays out of the sightline."""
    stand = TV_STAND.model_copy(update={"target": "sofa"})
    chair = ARMCHAIR.model_copy(update={"size_m": (0.85, 0.85, 0.9)})
    for seed in range(3):
        fp = single_room(rect(0, 0, 5.5, 4.2), door=((0.3, 0.0), (1.2, 0.0)))
        groups = [group("lounge", SOFA, [COFFEE], priority=0), group("tv", stand, priority=1),
                  group("armchairs", chair, priority=2)]
        res = layout_house(house_spec({"r1": groups}), fp, np.random.default_rng(seed))
        assert check_valid(fp, res.objects) == []
        sofa, tv = _one(res, "sofa"), _one(res, "tv stand")
        assert float(front(sofa.yaw) @ front(tv.yaw)) < -0.99  # face each other
        strip = Polygon(sightline_corners(sofa, tv))
        arm = _one(res, "armchair")
        assert not strip.intersects(footprint_polygon(arm.position, arm.size, arm.yaw))


def test_a_tv_stand_with_no_sofa_stands_against_a_wall():
    stand = TV_STAND.model_copy(update={"target": "sofa"})
    fp = single_room(rect(0, 0, 4.0, 3.5))
    res = layout_house(house_spec({"r1": [group("tv", stand)]}), fp, np.random.default_rng(0))
    tv = _one(res, "tv stand")
    back = np.asarray(tv.position[:2]) - front(tv.yaw) * tv.size[1] / 2
    assert Polygon(fp.rooms[0].polygon).exterior.distance(Point(back)) < 0.05


def test_a_dresser_with_a_mirror_keeps_off_the_windows():
    """A dresser (0.85 m, low enough to stand under a window) with a mirror to hang behind
    it stands on a wall without a window, so the mirror hangs over it, not on another wall."""
    dresser = item("dresser", "dresser", (1.2, 0.5, 0.85), "place_wall", tags=["storage"])
    mirror = item("dresser mirror", "mirror", (0.6, 0.03, 0.8), "place_on_wall", params={"elevation_m": 1.0})
    wins = [((0.3, 4.0), (3.7, 4.0)), ((4.0, 0.5), (4.0, 3.5))]  # north and east walls
    for seed in range(5):
        fp = single_room(rect(0, 0, 4.0, 4.0), door=((0.3, 0.0), (1.2, 0.0)), windows=wins)
        res = layout_house(house_spec({"r1": [group("dresser", dresser, [mirror])]}), fp, np.random.default_rng(seed))
        d, m = _one(res, "dresser"), _one(res, "dresser mirror")
        assert float(front(d.yaw) @ front(m.yaw)) > 0.99, seed  # on the wall behind the dresser
        assert np.linalg.norm(np.subtract(d.position[:2], m.position[:2])) < 0.6, seed


def test_a_runner_narrows_to_lie_between_the_door_zones_of_a_narrow_hallway():
    """A 1.3 m hallway with doors on both long walls and both ends: its door zones leave
    only a strip under 0.6 m along one wall; the runner narrows to lie there."""
    from anyhome.house import Door, Floorplan, Room

    hall = Room(id="h", name="hallway", type="hallway", polygon=rect(0, 0, 3.6, 1.3))
    segs = {"outside": ((3.6, 0.25), (3.6, 1.15)), "a": ((0.15, 0.0), (1.05, 0.0)),
            "b": ((0.95, 1.3), (1.85, 1.3)), "c": ((2.15, 1.3), (3.05, 1.3)), "d": ((0.0, 0.25), (0.0, 1.15))}
    others = {"a": rect(0, -3, 1.8, 0), "b": rect(0.5, 1.3, 2.0, 4), "c": rect(2.0, 1.3, 3.6, 4), "d": rect(-3, 0, 0, 1.3)}
    rooms = [hall] + [Room(id=k, name=k, type="bedroom", polygon=p) for k, p in others.items()]
    doors = [Door(id=f"d-{k}", rooms=("h", k), segment=s) for k, s in segs.items()]
    fp = Floorplan(rooms=rooms, doors=doors, windows=[], connections=[("h", k) for k in segs])
    runner = item("runner rug", "rug", (2.4, 0.8, 0.01), "place_center", tags=["floor_layer"])
    res = layout_house(house_spec({"h": [group("runner", runner)]}), fp, np.random.default_rng(0))
    rug = _one(res, "runner rug")
    assert check_valid(fp, res.objects) == []
    assert 0.44 <= min(rug.size[:2]) < 0.6 and max(rug.size[:2]) >= 1.0
