"""Explicit, replaceable stages; generate is the plan stage + generate_from_spec."""

from __future__ import annotations

from dataclasses import fields, replace

import pytest

import anyhome
from anyhome.errors import AnyHomeError, PlanError
from anyhome.floorplan.levels import solve_levels
from anyhome.layout import LayoutResult, layout_house
from anyhome.pipeline import STAGES
from anyhome.plan import HouseSpec, get_planner
from anyhome.refine import refine_objects
from anyhome.stages import Stages, assign_assets, plan_text, stage_rngs

TEXTS = [
    "A one-bedroom, one-bathroom haunted house featuring dark wood and antique furnishings.",
    "A Japanese tea house.",
    "A small cafe with a counter,\nfour tables and a reading corner.\x1b[31m",  # newline and an escape
]


def test_stages_name_today_functions_in_run_order() -> None:
    assert tuple(f.name for f in fields(Stages)) == STAGES
    s = Stages()
    assert (s.plan, s.floorplan, s.layout, s.refine, s.assets) == (
        plan_text, solve_levels, layout_house, refine_objects, assign_assets)
    with pytest.raises(AttributeError):
        s.layout = layout_house  # frozen
    assert anyhome.Stages is Stages


def test_a_stage_that_is_not_a_function_is_refused() -> None:
    with pytest.raises(AnyHomeError, match="stage 'refine' must be a function, got int"):
        Stages(refine=1)


@pytest.mark.parametrize("seed", [0, 3])
@pytest.mark.parametrize("text", TEXTS)
def test_generate_is_plan_then_generate_from_spec(text: str, seed: int) -> None:
    spec = get_planner("offline").plan(text, stage_rngs(seed)["plan"])
    house = anyhome.generate(text, seed=seed)
    assert anyhome.generate_from_spec(spec, seed=seed).to_json() == house.to_json()
    # the house's plan gives the spec back
    again = HouseSpec.model_validate({**house.plan, "provenance": house.provenance})
    assert again == spec.model_copy(update={"provenance": house.provenance})
    assert anyhome.generate_from_spec(again, seed=seed).to_json() == house.to_json()
    # and its JSON works too
    assert anyhome.generate_from_spec(house.plan, seed=seed).to_json() == house.to_json()


def test_generate_from_spec_refuses_what_is_not_a_plan() -> None:
    with pytest.raises(PlanError, match=r"^the spec is not a valid plan: rooms: Field required$"):
        anyhome.generate_from_spec({"prompt": "x"})
    with pytest.raises(PlanError, match="must be a HouseSpec or its JSON object, got str"):
        anyhome.generate_from_spec("a kitchen")
    with pytest.raises(AnyHomeError, match="seed must be a non-negative integer"):
        anyhome.generate_from_spec(anyhome.generate("A kitchen.").plan, seed=-1)


def test_one_replaced_stage_runs_with_the_defaults_of_the_others() -> None:
    text = TEXTS[0]
    base = anyhome.generate(text, seed=2)
    calls = []

    def no_refine(floorplan, objects, rng):
        calls.append((len(floorplan.rooms), len(objects)))
        return [o.model_copy() for o in objects]

    house = anyhome.generate(text, seed=2, stages=Stages(refine=no_refine))
    assert calls == [(len(base.rooms), len(house.objects))]  # called once, on the layout's objects
    # the other stages drew exactly what they drew before (own child RNGs)
    assert [r.model_dump() for r in house.rooms] == [r.model_dump() for r in base.rooms]
    assert house.doors == base.doors
    assert {o.id for o in base.objects} <= {o.id for o in house.objects}  # refine only moves or drops


def test_a_replaced_plan_and_layout_stage() -> None:
    def gothic_plan(text, rng, planner):
        return planner.plan(text, rng).model_copy(update={"style": "gothic"})

    def empty_layout(spec, floorplan, rng):
        return LayoutResult()

    stages = replace(Stages(), plan=gothic_plan, layout=empty_layout)
    house = anyhome.generate(TEXTS[1], stages=stages)
    assert house.style == "gothic" and house.plan["style"] == "gothic"
    assert house.objects == [] and house.dropped == []
    assert [r.id for r in house.rooms] == [r.id for r in anyhome.generate(TEXTS[1]).rooms]


def test_the_planner_meets_a_stated_total_with_the_run_s_floorplan_stage() -> None:
    """The plan stage lays its plan out with the run's floorplan stage (passed in, never
    imported by the planner): a stage that builds 20 % larger houses gets smaller rooms
    planned."""
    calls: list[int] = []

    def larger(spec, rng):
        calls.append(1)
        plan = solve_levels(spec, rng)
        for r in plan.rooms:
            r.polygon = [(1.2 ** 0.5 * x, 1.2 ** 0.5 * y) for x, y in r.polygon]
        return plan

    text = "a 60 m2 two-bedroom apartment"
    spec = get_planner("offline").plan(text, stage_rngs(0)["plan"])
    run = get_planner("offline", floorplan=larger)
    scaled = run.plan(text, stage_rngs(0)["plan"])
    assert calls, "the planner never laid its plan out with the stage it was given"
    # the rooms are planned about 1/1.2 as large (how close the built house lands is
    # tests/plan/test_program_sizes.py's business)
    assert 0.7 < sum(r.area_m2 for r in scaled.rooms) / sum(r.area_m2 for r in spec.rooms) < 0.92
    # the same stage reaches the planner through generate's Stages
    calls.clear()
    anyhome.generate(text, seed=0, stages=Stages(floorplan=larger))
    assert len(calls) > 1  # the plan's probes, then the floorplan stage itself
