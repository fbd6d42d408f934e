"""What a house of several storeys remembers between the searches of one
``solve_levels`` call (floorplan.levels): a storey whose carve search found nothing, or
whose slicing found nothing, is not searched that way again; and the per-room lists the
slicing and tuning scores read."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from anyhome.floorplan import budget, levels, solver
from anyhome.floorplan.options import FloorplanOptions, FloorplanOptionsError
from anyhome.floorplan.slicing import SliceRooms
from anyhome.floorplan.tune import TuneRooms
from anyhome.plan.spec import HouseSpec, RoomSpec


@pytest.fixture(scope="module")
def cottage():
    from anyhome.plan import get_planner
    from anyhome.plan.knowledge import knowledge_base
    from anyhome.stages import stage_rngs

    return get_planner("offline", knowledge_base()).plan("a cozy cottage with an attic bedroom", stage_rngs(1)["plan"])


def _in_one_call(memo, fn):
    """``fn()`` with the memo ContextVar ``memo`` set to a fresh set (None: unset) and a
    budget, as inside one solve_levels call; the set afterwards."""
    seen = set()
    token = memo.set(seen) if memo is not None else None
    spent = budget.ATTEMPT_BUDGET.set(budget.AttemptBudget(10_000))
    try:
        fn()
    finally:
        budget.ATTEMPT_BUDGET.reset(spent)
        if token is not None:
            memo.reset(token)
    return seen


def test_a_storey_whose_carve_search_failed_is_not_carved_again(cottage, monkeypatch):
    from anyhome.floorplan import carve

    k = next(k for k in sorted({r.level for r in cottage.rooms}) if carve.carve_room(
        levels._storey_spec(cottage, k, FloorplanOptions()), levels.stair_room(cottage, k),
        levels._open_stair_types(k, 0), stand_in=k != 0) is not None)
    monkeypatch.setattr(carve, "carved", lambda *_a, **_k: iter(()))  # no corner ever holds the stair: the carve fails
    searches = []
    real = levels._candidates

    def counted(sub, *a, **kw):
        searches.append(not any(levels.is_stairwell(r) for r in sub.rooms))  # a carve search: the well is cut later
        return real(sub, *a, **kw)

    monkeypatch.setattr(levels, "_candidates", counted)

    def twice():
        for seed in (0, 1):
            levels._solve_storey(cottage, k, np.random.default_rng(seed), None)

    assert _in_one_call(levels._UNCARVED, twice) == {k}
    assert searches.count(True) == 1  # the second solve went straight to a stairwell of its own
    searches.clear()
    _in_one_call(None, twice)
    assert searches.count(True) == 2  # without the memo: searched each time


def test_a_storey_whose_slicing_found_nothing_goes_to_the_spine_at_once(cottage, monkeypatch):
    attempts = []

    def failed(prog, *_a, **_k):
        attempts.append(1)
        return "room too narrow"

    monkeypatch.setattr(solver, "_attempt", failed)  # every slicing attempt fails; the spine still lays it out
    opts = FloorplanOptions(stair_carve_attempts=0)
    counts = []

    def twice():
        for seed in (0, 1):
            attempts.clear()
            levels._solve_storey(cottage, 0, np.random.default_rng(seed), opts)
            counts.append(len(attempts))

    assert _in_one_call(levels._UNSLICED, twice) == {0}
    assert counts == [opts.storey_slicing_attempts, 0]


def test_slicing_spent_counts_the_search_s_attempts():
    b = budget.AttemptBudget(100)
    search = FloorplanOptions(slicing_attempts=5)
    for _ in range(5):
        b.spend()
    assert not levels._slicing_spent(search, b, 0)  # five attempts: the fifth may have found it
    b.spend()
    assert levels._slicing_spent(search, b, 0)  # a sixth: the spine was reached
    assert not levels._slicing_spent(search, b, 1)
    assert not levels._slicing_spent(dataclasses.replace(search, slicing_attempts=0), b, 0)  # spine only already
    assert not levels._slicing_spent(search, None, 0)


def test_storey_slicing_attempts_is_range_checked():
    with pytest.raises(FloorplanOptionsError):
        FloorplanOptions(storey_slicing_attempts=-1)


def test_a_hallway_of_a_spine_storey_is_not_carved():
    def storey(n: int, hall_type: str) -> HouseSpec:
        rooms = [RoomSpec(id="hall", name="landing", type=hall_type, area_m2=8.0, level=1)]
        rooms += [RoomSpec(id=f"bed{i}", name="bedroom", type="bedroom", area_m2=12.0, level=1) for i in range(n - 1)]
        return HouseSpec(prompt="a storey", rooms=rooms, connections=[("hall", "outside")] + [("hall", f"bed{i}") for i in range(n - 1)])

    opts = FloorplanOptions()
    n = opts.slicing_max_rooms
    assert levels._spine_hall(storey(n + 1, "hallway"), "hall", opts)
    assert not levels._spine_hall(storey(n, "hallway"), "hall", opts)  # sliced: it may be carved
    assert not levels._spine_hall(storey(n + 1, "living_room"), "hall", opts)
    assert not levels._spine_hall(storey(n + 1, "hallway"), "bed0", opts)


def test_score_lists_hold_the_arrays_numbers():
    opts = FloorplanOptions()
    n = 3
    tune = TuneRooms(target_cells=np.array([25.0, 12.5, 40.0]), min_side_m=np.array([2.4, 1.2, 3.0]),
                     corridor=np.array([False, True, False]), exterior=np.array([True, False, True]), void=None,
                     edges=((0, 1),), cell_m=0.3, opts=opts, max_aspect=np.array([2.0, np.inf, 2.5]),
                     min_long_m=np.array([0.0, 3.4, 0.0]))
    lists = tune.lists
    assert lists.target_cells == [25.0, 12.5, 40.0] and lists.min_side_m == [2.4, 1.2, 3.0]
    assert lists.corridor == [False, True, False] and lists.exterior == [0, 2]
    assert lists.max_aspect == [2.0, float("inf"), 2.5] and lists.min_long_m == [0.0, 3.4, 0.0]
    assert dataclasses.replace(tune, min_long_m=None).lists.min_long_m is None
    pos = np.array([[1.5, 2.5], [3.0, 0.5], [0.5, 0.5]])
    sliced = SliceRooms(cells=np.array([25.0, 12.5, 40.0]), min_side=np.array([2.4, 1.2, 3.0]),
                        corridor=np.array([False, True, False]), exterior=np.array([True, False, True]), void=None,
                        pos=pos, edges=frozenset({(0, 1)}), cell_m=0.3, opts=opts,
                        max_aspect=np.array([2.0, np.inf, 2.5]))
    assert sliced.lists.pos == [[1.5, 2.5], [3.0, 0.5], [0.5, 0.5]] and sliced.lists.exterior == [True, False, True]
    assert sliced.lists.min_long is None and sliced.lists.min_side == [2.4, 1.2, 3.0] and len(sliced.lists.corridor) == n
