"""Furnishing figures (anyhome.evaluate.furnish_metrics) on a real house, then on the
same house with one defect injected each: each figure moves as its definition says."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.evaluate import evaluate_house
from anyhome.evaluate.furnish_metrics import furnish_metrics
from anyhome.house import Dropped, House
from anyhome.pipeline import generate

TEXT = "a living room with a sofa, a coffee table, a tv and a rug, and a dining table with six dining chairs"


@pytest.fixture(scope="module")
def house() -> House:
    return generate(TEXT, seed=0)


def _edited(house: House, **update) -> House:
    return house.model_copy(deep=True, update=update)


def test_a_generated_living_room_meets_the_figures(house):
    m = evaluate_house(house).furnish
    assert m is not None
    assert m.n_layers_planned >= 1 and m.n_layers_placed == m.n_layers_planned
    assert m.n_tv_stands == 1 and m.n_tv_against_wall == 1 and m.n_tv_facing_seat == 1
    assert m.n_sets >= 1 and m.mismatched_sets == []
    assert m.key_dropped == []
    assert all(0.0 < c < 1.0 for c in m.coverage.values())


def test_tv_stand_moved_off_the_wall_is_counted(house):
    objs = [o.model_copy() for o in house.objects]
    tv = next(o for o in objs if o.category == "tv_stand")
    f = np.array([-np.sin(tv.yaw), np.cos(tv.yaw)])
    tv.position = (tv.position[0] + 0.5 * f[0], tv.position[1] + 0.5 * f[1], 0.0)
    assert furnish_metrics(_edited(house, objects=objs)).n_tv_against_wall == 0


def test_one_odd_chair_makes_a_mismatched_set(house):
    objs = [o.model_copy(deep=True) for o in house.objects]
    chairs = [o for o in objs if o.name == "dining chair"]
    assert len(chairs) >= 2
    chairs[-1].asset["params"]["primary"] = "#ff00ff"
    assert len(furnish_metrics(_edited(house, objects=objs)).mismatched_sets) == 1


def test_dropped_key_item_and_rug_are_counted(house):
    sofa = next(o for o in house.objects if o.category == "sofa")
    rug = next(o for o in house.objects if "floor_layer" in o.tags)
    objs = [o for o in house.objects if o.id != rug.id]
    dropped = [*house.dropped, Dropped(room=sofa.room, name=sofa.name, reason="test"),
               Dropped(room=rug.room, name=rug.name, reason="test")]
    m = furnish_metrics(_edited(house, objects=objs, dropped=dropped))
    assert f"{sofa.room}:{sofa.name}" in m.key_dropped  # the rug too: the text asks for it
    assert m.n_layers_placed == m.n_layers_planned - 1
    assert m.n_dropped == len(house.dropped) + 2


def test_floor_objects_reached_by_the_agent(house):
    rep = evaluate_house(house)
    assert 0 < rep.metrics["n_floor_objects_reached"] <= rep.metrics["n_floor_objects"]


KITCHEN_TEXT = "a small house with a kitchen, a living room and a bedroom"


@pytest.fixture(scope="module")
def kitchen_house() -> House:
    return generate(KITCHEN_TEXT, seed=0)


def test_a_generated_kitchen_has_its_work_run_and_wall_cabinets(kitchen_house):
    m = furnish_metrics(kitchen_house)
    assert m.n_kitchens >= 1
    assert m.n_kitchen_work_run == m.n_kitchens and m.n_kitchen_wall_cabinets == m.n_kitchens


def test_a_fridge_moved_off_the_run_and_cabinets_taken_down_are_counted(kitchen_house):
    before = furnish_metrics(kitchen_house)
    objs = [o.model_copy() for o in kitchen_house.objects]
    fridge = next(o for o in objs if o.category == "refrigerator")
    f = np.array([-np.sin(fridge.yaw), np.cos(fridge.yaw)])
    fridge.position = (fridge.position[0] + 1.0 * f[0], fridge.position[1] + 1.0 * f[1], 0.0)  # out into the room
    moved = furnish_metrics(_edited(kitchen_house, objects=objs))
    assert moved.n_kitchen_work_run == before.n_kitchen_work_run - 1
    bare = [o for o in kitchen_house.objects if not (o.category == "cabinet" and o.support == "wall"
                                                     and o.room == fridge.room)]
    assert furnish_metrics(_edited(kitchen_house, objects=bare)).n_kitchen_wall_cabinets == before.n_kitchen_wall_cabinets - 1
