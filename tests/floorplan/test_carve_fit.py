"""Carve searches known to fail from the storey's program alone (floorplan.carve_fit),
and levels._carved_storey skipping them: a crowded hall, two rooms no rectangle holds."""

from __future__ import annotations

import dataclasses

import numpy as np

from anyhome.floorplan import budget, levels
from anyhome.floorplan.carve_fit import crowded_hall, two_rooms_unfit
from anyhome.floorplan.options import FloorplanOptions
from anyhome.plan.spec import HouseSpec, RoomSpec


def _hall_storey(n_beds: int, hall_type: str = "hallway") -> HouseSpec:
    """A carved upper storey: a hall (its stand-in entrance kept) onto ``n_beds`` bedrooms."""
    rooms = [RoomSpec(id="hall", name="landing", type=hall_type, area_m2=10.6, level=1)]
    rooms += [RoomSpec(id=f"bed{i}", name="bedroom", type="bedroom", area_m2=12.0, level=1) for i in range(n_beds)]
    return HouseSpec(prompt="a storey", rooms=rooms,
                     connections=[("hall", "outside")] + [("hall", f"bed{i}") for i in range(n_beds)])


def test_a_hall_with_too_many_doors_for_its_passage_is_crowded():
    opts = FloorplanOptions()
    most = opts.stair_carve_hall_max_links
    assert crowded_hall(_hall_storey(most - 1), "hall", opts)  # the outside is a link too
    assert not crowded_hall(_hall_storey(most - 2), "hall", opts)
    assert not crowded_hall(_hall_storey(most), "bed0", opts)  # a bedroom holds no stair
    assert not crowded_hall(_hall_storey(most, "living_room"), "hall", opts)


def _cottage_ground(kitchen_m2: float, living_m2: float) -> HouseSpec:
    """A two-room ground floor, its stairwell opening onto the living room only (the
    stairwell is carved from the living room's corner)."""
    rooms = [RoomSpec(id="living", name="living room", type="living_room", area_m2=living_m2),
             RoomSpec(id="kitchen", name="kitchenette", type="kitchen", area_m2=kitchen_m2),
             RoomSpec(id="stair", name="stairwell", type="stairwell", area_m2=4.0),
             RoomSpec(id="bed", name="bedroom", type="bedroom", area_m2=12.0, level=1),
             RoomSpec(id="stair1", name="stairwell", type="stairwell", area_m2=4.0, level=1)]
    return HouseSpec(prompt="a cottage", rooms=rooms,
                     connections=[("living", "outside"), ("living", "kitchen"), ("living", "stair"),
                                  ("stair1", "bed")])


def _carve_of(spec: HouseSpec, opts: FloorplanOptions, seed: int) -> tuple[bool, int]:
    """The ground storey's carve search of ``spec``: (found a layout, attempts spent)."""
    sub = levels._storey_spec(spec, 0, opts)
    long_m, short_m = levels.stairwell_min_m(spec, 0)
    search = levels._storey_search(dataclasses.replace(opts, wanted_candidates=1))
    spent = budget.ATTEMPT_BUDGET.set(budget.AttemptBudget(10_000))
    try:
        out = levels._carved_storey(spec, 0, sub, np.random.default_rng(seed), search, levels.storey_heights_m(spec),
                                    long_m, short_m, levels.house_stair_kind(spec), opts)
        return out is not None, budget.ATTEMPT_BUDGET.get().used
    finally:
        budget.ATTEMPT_BUDGET.reset(spent)


def _carved(spec: HouseSpec, opts: FloorplanOptions) -> tuple[HouseSpec, float, float]:
    from anyhome.floorplan.carve import carved_spec

    sub = levels._storey_spec(spec, 0, opts)
    long_m, short_m = levels.stairwell_min_m(spec, 0)
    return (carved_spec(sub, "stair", "living", levels._carved_m2(sub, "living", long_m, short_m, opts)),
            long_m, short_m + opts.stair_carve_left_m)


def test_two_rooms_no_rectangle_holds_are_told_and_their_search_would_fail():
    opts = FloorplanOptions()
    tight = _cottage_ground(kitchen_m2=5.0, living_m2=11.0)  # a kitchenette too small for a slab of the rectangle
    carved_sub, long_m, side_m = _carved(tight, opts)
    assert two_rooms_unfit(carved_sub, "living", long_m, side_m, opts)
    run_anyway = dataclasses.replace(opts, stair_carve_hopeless_test=0)
    searched = [_carve_of(tight, run_anyway, seed) for seed in range(3)]
    assert [found for found, _ in searched] == [False] * 3  # the search it saves finds nothing
    assert all(spent == opts.stair_carve_max_attempts for _, spent in searched)  # it was run in full
    assert _carve_of(tight, opts, 0) == (False, 0)  # skipped: no attempt spent


def test_two_rooms_a_rectangle_holds_are_searched():
    opts = FloorplanOptions()
    roomy = _cottage_ground(kitchen_m2=12.0, living_m2=20.0)
    carved_sub, long_m, side_m = _carved(roomy, opts)
    assert not two_rooms_unfit(carved_sub, "living", long_m, side_m, opts)
    assert any(_carve_of(roomy, opts, seed)[0] for seed in range(3))
    three = carved_sub.model_copy(update={"rooms": [*carved_sub.rooms, RoomSpec(id="wc", name="wc", type="bathroom", area_m2=2.0)]})
    assert not two_rooms_unfit(three, "living", long_m, side_m, opts)  # only two-room storeys are judged


def test_the_hopeless_test_can_be_switched_off():
    opts = FloorplanOptions()
    hall = _hall_storey(opts.stair_carve_hall_max_links)
    assert levels._carve_hopeless(hall, "hall", 3.6, 1.75, opts)
    assert not levels._carve_hopeless(hall, "hall", 3.6, 1.75, dataclasses.replace(opts, stair_carve_hopeless_test=0))
