"""Kitchen figures (anyhome.evaluate.kitchen_metrics) on hand-built rooms: a run, a
scattered kitchen, a shop that is no kitchen, cabinets over or beside the counters."""

from __future__ import annotations

import math

from shapely.geometry import Polygon

from anyhome.evaluate.kitchen_metrics import kitchen_figures
from anyhome.house import HouseObject

ROOM = Polygon([(0, 0), (4, 0), (4, 3), (0, 3)])


def obj(i, cat, x, w, depth=0.6, h=0.9, z=0.0, support="floor", y=None, yaw=0.0):
    """An object with its back on the south wall (y = 0) unless ``y`` and ``yaw`` say otherwise."""
    return HouseObject(id=f"o{i}", room="k", name=cat, category=cat, position=(x, depth / 2 if y is None else y, z),
                       size=(w, depth, h), yaw=yaw, support=support)


def run(gap=0.0):
    """Fridge, counter, sink, counter, stove along the south wall; ``gap`` before the stove."""
    return [obj(0, "refrigerator", 0.4, 0.8, 0.7, 1.8), obj(1, "counter", 1.2, 0.8), obj(2, "sink", 2.0, 0.8),
            obj(3, "counter", 2.7, 0.6), obj(4, "stove", 3.35 + gap, 0.7)]


def test_a_continuous_run_is_a_work_run():
    f = kitchen_figures({"k": ROOM}, {"k": run()})
    assert (f.n_kitchens, f.n_work_run, f.n_wall_cabinets) == (1, 1, 0)


def test_appliances_off_the_run_are_no_work_run():
    objs = run()[:4] + [obj(4, "stove", 2.0, 0.7, y=2.7, yaw=math.pi)]  # the cooktop alone on the north wall
    objs += [obj(5, "refrigerator", 0.5, 0.8, 0.7, 1.8, y=2.65, yaw=math.pi)]
    assert kitchen_figures({"k": ROOM}, {"k": objs[1:]}).n_work_run == 0


def test_a_shop_counter_with_a_fridge_is_no_kitchen():
    objs = [obj(0, "counter", 1.0, 1.8), obj(1, "refrigerator", 3.0, 0.8, 0.7, 1.8)]
    assert kitchen_figures({"k": ROOM}, {"k": objs}).n_kitchens == 0


def test_wall_cabinets_count_only_over_a_counter():
    over = obj(9, "cabinet", 1.2, 0.8, 0.35, 0.7, z=1.45, support="wall", y=0.175)
    beside = obj(9, "cabinet", 2.0, 0.8, 0.35, 0.7, z=1.45, support="wall", y=0.175)  # over the sink only
    assert kitchen_figures({"k": ROOM}, {"k": [*run(), over]}).n_wall_cabinets == 1
    assert kitchen_figures({"k": ROOM}, {"k": [*run(), beside]}).n_wall_cabinets == 0
