"""Kitchens laid out as runs (anyhome.layout.kitchens): shapes by room size, the work
triangle in the run, wall cabinets over the counters, an island only with its aisles."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon

from anyhome.evaluate.kitchen_metrics import kitchen_figures
from anyhome.geometry import footprint_polygon
from anyhome.house import Door, Floorplan, Room, Window
from anyhome.layout import layout_house
from anyhome.layout.kitchens import AISLE_MIN_M, CABINET_ELEVATION_M, is_kitchen_run
from anyhome.plan.spec import HouseSpec, RoomSpec

from .helpers import check_valid, group, item, rect


def kitchen_run():
    return group("kitchen_run", item("kitchen counter", "counter", (1.8, 0.6, 0.9), "place_corner"), [
        item("stove", "stove", (0.7, 0.6, 0.9), "place_next_wall"),
        item("kitchen sink", "sink", (0.8, 0.6, 0.9), "place_next_wall"),
        item("refrigerator", "refrigerator", (0.8, 0.7, 1.8), "place_next_wall"),
        item("wall cabinet", "cabinet", (0.8, 0.35, 0.7), "place_on_wall", params={"elevation_m": 1.45}, count=3),
    ])


def island():
    return group("island", item("kitchen island", "counter", (1.8, 0.9, 0.9), "place_center"),
                 [item("stool", "stool", (0.4, 0.4, 0.75), "place_front", params={"distance_m": 0.1, "facing": "toward"},
                       count=2)], priority=2)


def kitchen(w, h, door, windows=(), groups=None, seed=0):
    room = Room(id="k", name="kitchen", type="kitchen", polygon=rect(0, 0, w, h), height=2.7)
    fp = Floorplan(rooms=[room], doors=[Door(id="d0", rooms=("k", "outside"), segment=door)],
                   windows=[Window(id=f"w{i}", room="k", segment=s) for i, s in enumerate(windows)],
                   connections=[("k", "outside")])
    spec = HouseSpec(prompt="test", rooms=[RoomSpec(id="k", name="kitchen", type="kitchen", area_m2=w * h,
                                                    groups=groups or [kitchen_run()])],
                     connections=[("k", "outside")])
    res = layout_house(spec, fp, np.random.default_rng(seed))
    return fp, res


def _backs_on_walls(objs, poly):
    """Indices of the walls (polygon edges) the objects' backs lie on."""
    pts = list(poly.exterior.coords)
    walls = set()
    for o in objs:
        f = np.array([-np.sin(o.yaw), np.cos(o.yaw)])
        back = shapely.Point(np.asarray(o.position[:2]) - f * o.size[1] / 2)
        for i in range(len(pts) - 1):
            if shapely.LineString([pts[i], pts[i + 1]]).distance(back) < 0.02:
                walls.add(i)
    return walls


RUN = ("counter", "sink", "stove", "refrigerator")


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_3_by_5_kitchen_gets_an_l_or_u_with_the_work_triangle_and_wall_cabinets(seed):
    fp, res = kitchen(3.0, 5.0, ((1.0, 0.0), (1.9, 0.0)), windows=[((3.0, 2.0), (3.0, 3.2))], seed=seed)
    assert check_valid(fp, res.objects) == []
    assert [d.name for d in res.dropped] == []
    poly = Polygon(fp.rooms[0].polygon)
    run = [o for o in res.objects if o.category in RUN]
    assert len(_backs_on_walls(run, poly)) in (2, 3)  # an L or a U
    fig = kitchen_figures({"k": poly}, {"k": res.objects})
    assert (fig.n_kitchens, fig.n_work_run, fig.n_wall_cabinets) == (1, 1, 1)
    cabinets = [o for o in res.objects if o.category == "cabinet"]
    assert cabinets and all(o.support == "wall" and abs(o.position[2] - CABINET_ELEVATION_M) < 1e-6 for o in cabinets)
    stove = next(o for o in res.objects if o.category == "stove")
    over_stove = footprint_polygon(stove.position, stove.size, stove.yaw)
    assert not any(footprint_polygon(c.position, c.size, c.yaw).intersection(over_stove).area > 1e-4
                   for c in cabinets)  # the hood's place stays free


def test_the_sink_stands_under_the_window_and_the_fridge_ends_the_run():
    fp, res = kitchen(3.0, 5.0, ((1.0, 0.0), (1.9, 0.0)), windows=[((3.0, 2.0), (3.0, 3.2))])
    sink = next(o for o in res.objects if o.category == "sink")
    assert abs(sink.position[0] - 2.7) < 0.05 and 2.0 <= sink.position[1] <= 3.2
    fridge = next(o for o in res.objects if o.category == "refrigerator")
    ffp = footprint_polygon(fridge.position, fridge.size, fridge.yaw)
    touching = [o for o in res.objects if o.support == "floor" and o.id != fridge.id
                and footprint_polygon(o.position, o.size, o.yaw).distance(ffp) < 0.02]
    assert len(touching) == 1 and touching[0].category == "counter"  # at the end, counter beside it


@pytest.mark.parametrize("seed", [0, 1])
def test_a_2_2_m_wide_kitchen_gets_a_galley_or_one_run(seed):
    fp, res = kitchen(2.2, 4.5, ((0.6, 0.0), (1.5, 0.0)), seed=seed)
    assert check_valid(fp, res.objects) == []
    poly = Polygon(fp.rooms[0].polygon)
    run = [o for o in res.objects if o.category in RUN]
    assert {o.category for o in run} == set(RUN)
    assert _backs_on_walls(run, poly) <= {1, 3}  # the two long walls (x = 2.2 and x = 0)
    assert kitchen_figures({"k": poly}, {"k": res.objects}).n_work_run == 1


def test_a_large_kitchen_gets_an_island_with_work_aisles():
    fp, res = kitchen(5.0, 6.0, ((2.0, 0.0), (2.9, 0.0)), windows=[((5.0, 2.0), (5.0, 3.2))],
                      groups=[kitchen_run(), island()])
    assert check_valid(fp, res.objects) == []
    isl = next(o for o in res.objects if o.name == "kitchen island")
    ifp = footprint_polygon(isl.position, isl.size, isl.yaw)
    run = [o for o in res.objects if o.category in RUN and o.id != isl.id]
    gap = min(footprint_polygon(o.position, o.size, o.yaw).distance(ifp) for o in run)
    assert gap >= AISLE_MIN_M - 1e-6
    assert sum(o.name == "stool" for o in res.objects) == 2


def test_a_small_kitchen_drops_the_island_with_its_reason():
    fp, res = kitchen(2.6, 3.0, ((1.0, 0.0), (1.9, 0.0)), groups=[kitchen_run(), island()])
    assert check_valid(fp, res.objects) == []
    gone = [d for d in res.dropped if d.name == "kitchen island"]
    assert len(gone) == 1 and "aisles" in gone[0].reason
    assert {o.category for o in res.objects} >= set(RUN)


def test_only_counter_groups_with_kitchen_appliances_are_kitchen_runs():
    assert is_kitchen_run(kitchen_run())
    assert not is_kitchen_run(island())
    desk = group("desk", item("desk", "desk", (1.2, 0.6, 0.75), "place_wall"),
                 [item("sink", "sink", (0.6, 0.45, 0.85), "place_wall"), item("stove", "stove", (0.6, 0.6, 0.9), "place_wall")])
    assert not is_kitchen_run(desk)
