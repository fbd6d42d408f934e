"""The whole search's attempt limit (anyhome.floorplan.budget) and what it bounds."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.errors import FloorplanError
from anyhome.floorplan import budget, levels
from anyhome.floorplan.options import FloorplanOptions, FloorplanOptionsError


@pytest.fixture(scope="module")
def cottage():
    from anyhome.plan import get_planner
    from anyhome.plan.knowledge import knowledge_base
    from anyhome.stages import stage_rngs

    return get_planner("offline", knowledge_base()).plan("a cozy cottage with an attic bedroom", stage_rngs(1)["plan"])


def test_budget_counts_and_refuses_past_its_limit():
    b = budget.AttemptBudget(2)
    b.spend()
    b.spend()
    with pytest.raises(budget.AttemptsSpent):
        b.spend()
    assert b.used == 2
    budget.spend_attempt()  # no budget set: nothing counted, nothing raised


def test_a_search_that_cannot_succeed_ends_in_one_floorplan_error_line(cottage, monkeypatch):
    """Every storey layout refused (no stair ever fits): every retry, the roomier
    stairwells and the fallback to one storey would search again; with a tiny limit the
    house ends in one FloorplanError line naming the option, after that many attempts."""
    assert len({r.level for r in cottage.rooms}) >= 2
    fitted = []

    def never(plan, *_a, **_k):
        fitted.append(plan)
        return None

    monkeypatch.setattr(levels, "_stair_fitted", never)
    spent = []
    real_spend = budget.AttemptBudget.spend

    def counted(self):
        spent.append(self.used)
        real_spend(self)

    monkeypatch.setattr(budget.AttemptBudget, "spend", counted)
    with pytest.raises(FloorplanError) as e:
        levels.solve_levels(cottage, np.random.default_rng(0), FloorplanOptions(levels_max_attempts=25))
    msg = str(e.value)
    assert "\n" not in msg and "levels_max_attempts" in msg and "25" in msg
    assert len(spent) == 26 and max(spent) == 25  # 25 spent, the 26th refused
    assert fitted  # the searches did run (and were refused) before the limit


def test_the_limit_leaves_a_house_that_lays_out_as_it_was(cottage):
    """A limit the search does not reach changes nothing; the budget is gone afterwards."""
    a = levels.solve_levels(cottage, np.random.default_rng(3))
    b = levels.solve_levels(cottage, np.random.default_rng(3), FloorplanOptions(levels_max_attempts=100_000))
    assert a.model_dump_json() == b.model_dump_json()
    assert budget.ATTEMPT_BUDGET.get() is None


def test_levels_max_attempts_is_range_checked():
    with pytest.raises(FloorplanOptionsError):
        FloorplanOptions(levels_max_attempts=0)


def test_a_stairwell_entered_through_both_end_walls_is_deep_enough_for_a_door_beside_its_stair():
    """The brownstone of dev_storeys2 (seed 1): its ground floor's stairwell lies on the
    spine between the reception and the family room, entered through both end walls. As
    deep as its planned area made it (2.2 m) no door ever cleared the stair, and 1280
    spine layouts were refused (45 s CPU); now the first layouts hold it."""
    from anyhome.plan import get_planner
    from anyhome.plan.knowledge import knowledge_base
    from anyhome.stages import stage_rngs

    prompt = ("Brooklyn brownstone, four floors: garden level with a kitchen and family room opening to the yard, "
              "parlor floor with the living room and dining room, third floor with two kids' bedrooms and a bath, "
              "top floor with the primary suite and an office.")
    spec = get_planner("offline", knowledge_base()).plan(prompt, stage_rngs(1)["plan"])
    token = budget.ATTEMPT_BUDGET.set(budget.AttemptBudget(60))
    try:
        plan = levels._solve_storey(spec, 0, np.random.default_rng(1), None)
    finally:
        budget.ATTEMPT_BUDGET.reset(token)
    heights = levels.storey_heights_m(spec)
    assert levels.stack_box([(0, plan)], heights, levels.house_stair_kind(spec)) is not None


def test_stair_fitter_answers_as_stair_fits_with_the_door_added():
    """The stairwell door placement asks ``stair_fitter(rect, own, L)([opening])`` of every
    opening: the same answer as ``stair_fits(rect, [*own, opening], L)``."""
    from anyhome.floorplan.stairs import stair_fits, stair_fitter

    for rect, own in (((0.0, 0.0, 3.6, 2.4), [((3.6, 0.2), (3.6, 1.1))]), ((0.0, 0.0, 2.4, 3.6), []),
                      ((1.0, 2.0, 3.9, 2.8), [((1.0, 2.9), (1.0, 3.8))])):
        x0, y0, w, h = rect
        fits = stair_fitter(rect, own, 2.6)
        openings = [((x0 + t, y0), (x0 + t + 0.9, y0)) for t in np.arange(0.0, w - 0.85, 0.05)]
        openings += [((x0 + w, y0 + t), (x0 + w, y0 + t + 0.9)) for t in np.arange(0.0, h - 0.85, 0.05)]
        answers = [fits([o]) for o in openings]
        assert answers == [stair_fits(rect, [*own, o], 2.6) for o in openings]
        assert any(answers) and not all(answers)


def test_slicing_that_only_leaves_the_stairwell_too_short_gives_way_to_the_spine(monkeypatch):
    """A storey's slicing attempts that all leave a room short of its least length: after
    ``slicing_short_give_up`` of them the search goes on with the spine at once."""
    from anyhome.floorplan import solver
    from tests.floorplan.programs import family_home

    calls = []

    def too_short(prog, *_a, **_k):
        calls.append(1)
        return f"room {prog.ids[0]!r} {solver.TOO_SHORT}"

    monkeypatch.setattr(solver, "_attempt", too_short)
    spec = family_home()
    for give_up, slicing in ((3, 3), (0, FloorplanOptions().slicing_attempts)):
        calls.clear()
        found = solver.floorplan_candidates(spec, np.random.default_rng(0), FloorplanOptions(slicing_short_give_up=give_up),
                                            min_length_m={"living": 0.5})
        assert found and len(calls) == slicing


def test_least_hang_is_the_floor_no_room_below_can_hold():
    from anyhome.house import Floorplan, Room
    from anyhome.plan.spec import HouseSpec, RoomSpec

    def room(i, x0, x1):
        return Room(id=i, name=i, type="bedroom", polygon=[(x0, 0.0), (x1, 0.0), (x1, 3.0), (x0, 3.0)])

    spec = HouseSpec(prompt="two storeys", rooms=[
        RoomSpec(id="a", name="a", type="bedroom", area_m2=12, level=0),
        RoomSpec(id="b", name="b", type="bedroom", area_m2=18, level=1)], connections=[("a", "outside")])
    below = Floorplan(rooms=[room("a", 0.0, 4.0)], doors=[], windows=[], connections=[])
    above = Floorplan(rooms=[room("b", 0.0, 6.0)], doors=[], windows=[], connections=[])
    assert levels._least_hang_m2(spec, below, above, 1) == pytest.approx(6.0)
    assert levels._least_hang_m2(spec, above, below, 1) == 0.0
