"""Dog-leg stairs (anyhome.floorplan.stairs): risers, goings and the box of two flights."""

from __future__ import annotations

import pytest

from anyhome.floorplan.stairs import (
    FLIGHT_WIDTH_M,
    GOING_M,
    RISER_MAX_M,
    STRIP_M,
    dogleg,
    dogleg_in_box,
    is_dogleg_box,
)

RISES_M = [2.6, 2.9, 3.0, 3.2, 3.5, 4.2, 4.7]
"""Floor-to-floor heights of storeys (rooms of 2.4 to 4.5 m and a 0.2 m slab)."""


@pytest.mark.parametrize("rise", RISES_M)
def test_risers_at_most_019_and_goings_at_least_025(rise):
    d = dogleg(rise)
    assert d.riser_m <= RISER_MAX_M + 1e-9 and d.riser_m <= 0.19 + 1e-9
    assert d.riser_m >= 0.15  # no more risers than the rise needs
    assert d.going_m >= 0.25 - 1e-9
    assert d.first_risers + d.second_risers == d.risers
    assert abs(d.risers * d.riser_m - rise) < 1e-9


@pytest.mark.parametrize("rise", RISES_M)
def test_box_holds_both_flights_and_the_half_landing(rise):
    d = dogleg(rise)
    assert d.width_m >= 2 * FLIGHT_WIDTH_M
    assert d.length_m >= (d.first_risers - 1) * d.going_m + d.landing_m - 1e-9
    assert d.length_m >= (d.second_risers - 1) * d.going_m + d.landing_m - 1e-9
    assert d.landing_m >= FLIGHT_WIDTH_M  # a half landing as deep as a flight is wide
    assert is_dogleg_box(d.length_m, d.width_m)


def test_a_storey_of_29_m_fits_a_compact_stairwell():
    """A 2.9 m storey: 16 risers of 0.181 m, a box of 2.6 x 1.75 m; with the strip at its
    foot the stairwell needs 3.5 x 1.75 m (6.1 m2), not the 12.5 m2 of a straight flight."""
    d = dogleg(2.9)
    assert d.risers == 16
    assert (d.length_m + STRIP_M) * d.width_m < 6.5


def test_a_longer_box_stretches_the_goings_never_shrinks_them():
    d = dogleg(2.9)
    assert dogleg_in_box(d.length_m, d.width_m, 2.9).going_m == pytest.approx(GOING_M)
    longer = dogleg_in_box(d.length_m + 0.35, d.width_m, 2.9)
    assert longer.going_m > GOING_M and longer.risers == d.risers
    assert dogleg_in_box(d.length_m - 0.3, d.width_m, 2.9).going_m == pytest.approx(GOING_M)


def test_a_narrow_box_is_a_straight_flight():
    assert not is_dogleg_box(3.2, 1.0)  # the objects.yaml staircase
    assert is_dogleg_box(2.6, 1.75)


def test_no_rise_is_refused():
    with pytest.raises(ValueError):
        dogleg(0.0)


def test_a_stairwell_holds_its_stair_only_where_its_doors_leave_it_clear():
    from anyhome.floorplan.stairs import stair_fits

    rect = (0.0, 0.0, 3.6, 2.4)  # a 2.6 m stair box and the 1 m strip at its foot
    end_door = ((3.6, 0.2), (3.6, 1.1))  # in the end wall at the foot: clear
    assert stair_fits(rect, [end_door], 2.6)
    mid_door = ((1.3, 0.0), (2.3, 0.0))  # in a long wall, over the stair, 0.65 m beside it
    assert not stair_fits(rect, [end_door, mid_door], 2.6)
    strip_door = ((2.65, 0.0), (3.55, 0.0))  # in a long wall, in the strip: clear
    assert stair_fits(rect, [end_door, strip_door], 2.6)
    assert stair_fits((0.0, 0.0, 2.4, 3.6), [((0.2, 3.6), (1.1, 3.6))], 2.6)  # turned a quarter
    assert not stair_fits(rect, [], 3.0)  # too short for the box and its strip


def test_stairwell_doors_are_placed_where_the_stair_fits():
    import numpy as np

    from anyhome.floorplan import solve_floorplan
    from anyhome.floorplan.stairs import stair_fits
    from anyhome.plan.spec import HouseSpec, RoomSpec

    rooms = [RoomSpec(id="stairwell", name="stairwell", type="stairwell", area_m2=8.5),
             RoomSpec(id="dining_room", name="dining room", type="dining_room", area_m2=14.0),
             RoomSpec(id="kitchen", name="kitchen", type="kitchen", area_m2=11.0)]
    spec = HouseSpec(prompt="stairwell", rooms=rooms, connections=[("stairwell", "dining_room"), ("dining_room", "kitchen"),
                                               ("stairwell", "outside")])
    fits = 0
    for seed in range(6):
        plan = solve_floorplan(spec, np.random.default_rng(seed), min_length_m={"stairwell": 3.7}, stair_m={"stairwell": 2.6})
        well = plan.room("stairwell")
        xs, ys = [p[0] for p in well.polygon], [p[1] for p in well.polygon]
        rect = (min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys))
        fits += len(well.polygon) == 4 and stair_fits(rect, [d.segment for d in plan.doors if "stairwell" in d.rooms], 2.6)
    assert fits >= 5  # without stair_m: 1 of 4 ground floors of a townhouse, measured


def test_stair_kind_is_a_ladder_for_a_tiny_house_a_spiral_for_a_small_one():
    from anyhome.floorplan.stairs import (
        DOGLEG,
        LADDER,
        LADDER_MAX_FLOOR_M2,
        SPIRAL,
        SPIRAL_MAX_FLOOR_M2,
        stair_kind,
        stair_length_m,
        stair_width_m,
    )

    assert stair_kind(LADDER_MAX_FLOOR_M2) == LADDER
    assert stair_kind(LADDER_MAX_FLOOR_M2 + 1.0) == SPIRAL
    assert stair_kind(SPIRAL_MAX_FLOOR_M2) == SPIRAL
    assert stair_kind(SPIRAL_MAX_FLOOR_M2 + 1.0) == DOGLEG
    assert stair_length_m(SPIRAL, 2.9) < stair_length_m(DOGLEG, 2.9)  # a spiral's stairwell is shorter
    assert stair_width_m(LADDER) < stair_width_m(SPIRAL) == stair_width_m(DOGLEG)


def test_ladder_is_steep_and_short():
    """A ship's ladder of a 2.9 m storey: risers of at most 0.24 m, about 60 degrees, its
    box (run and the floor at its top) well under a dog-leg's length."""
    import math

    from anyhome.floorplan.stairs import (
        LADDER,
        LADDER_GOING_M,
        LADDER_TOP_M,
        ladder_risers,
        stair_length_m,
    )

    n = ladder_risers(2.9)
    assert 2.9 / n <= 0.24 + 1e-9
    assert 55 <= math.degrees(math.atan2(2.9 / n, LADDER_GOING_M)) <= 68
    assert stair_length_m(LADDER, 2.9) == pytest.approx((n - 1) * LADDER_GOING_M + LADDER_TOP_M)
    assert stair_length_m(LADDER, 2.9) < 2.2


def test_small_two_storey_house_gets_a_spiral_stair_that_joins_its_storeys():
    """A small maisonette: a spiral stair (one full turn in a square box), recorded on its
    ground floor, joining the two storeys; every room reachable, no violation; its
    stairwells are planned smaller than a dog-leg's."""
    from anyhome.assets.registry import family_for
    from anyhome.evaluate import evaluate_house
    from anyhome.floorplan.levels import reachable_rooms, stair_link
    from anyhome.floorplan.stairs import SPIRAL, SPIRAL_NAME
    from anyhome.pipeline import generate
    from anyhome.plan.program import SPIRAL_STAIRWELL_AREA_M2, STAIRWELL_AREA_M2

    h = generate("A small maisonette over two floors with a lounge, a kitchen-diner, two bedrooms and a bathroom.", 0)
    stairs = [o for o in h.objects if o.category == "stairs"]
    assert len(stairs) == 1 and stairs[0].name == SPIRAL_NAME
    assert stairs[0].size[0] == pytest.approx(stairs[0].size[1])
    assert h.levels[0].stairs_kind == SPIRAL
    assert family_for(stairs[0].category, stairs[0].name) == "spiral_staircase"
    a, b = stair_link(h.floorplan, stairs[0])
    assert (h.room_level(a), h.room_level(b)) == (0, 1)
    assert reachable_rooms(h) == {r.id for r in h.rooms}
    assert evaluate_house(h).violations == []
    planned = [r["area_m2"] for r in h.plan["rooms"] if r["type"] == "stairwell"]
    assert planned and all(a < STAIRWELL_AREA_M2 for a in planned)
    assert SPIRAL_STAIRWELL_AREA_M2 < STAIRWELL_AREA_M2


def test_tiny_two_storey_house_gets_a_ladder_and_stays_tiny():
    """A tiny two-storey cottage whose rooms fit: a ship's ladder (category stairs, asset
    family ship_ladder) joins its storeys, every room reachable, no violation, the house
    at most 45 m2 (issue 13's bar for "tiny"), its stairwells planned at the ladder's
    3.5 m2."""
    from shapely.geometry import Polygon

    from anyhome.assets.registry import family_for
    from anyhome.evaluate import evaluate_house
    from anyhome.floorplan.levels import STAIRS_CATEGORY, reachable_rooms, stair_link
    from anyhome.floorplan.stairs import LADDER, LADDER_NAME
    from anyhome.pipeline import generate
    from anyhome.plan.program import LADDER_STAIRWELL_AREA_M2, SPIRAL_STAIRWELL_AREA_M2

    h = generate("A tiny two-storey cottage: a kitchen and sitting room downstairs, one bedroom and a bathroom upstairs.", 2)
    stairs = [o for o in h.objects if o.category == STAIRS_CATEGORY]
    assert len(stairs) == 1 and stairs[0].name == LADDER_NAME and stairs[0].category == "stairs"
    assert h.levels[0].stairs_kind == LADDER
    assert family_for(stairs[0].category, stairs[0].name) == "ship_ladder"
    a, b = stair_link(h.floorplan, stairs[0])
    assert (h.room_level(a), h.room_level(b)) == (0, 1)
    assert reachable_rooms(h) == {r.id for r in h.rooms}
    assert evaluate_house(h).violations == []
    assert sum(Polygon(r.polygon).area for r in h.rooms) <= 45.0
    planned = [r["area_m2"] for r in h.plan["rooms"] if r["type"] == "stairwell"]
    assert planned == [LADDER_STAIRWELL_AREA_M2] * 2
    assert LADDER_STAIRWELL_AREA_M2 < SPIRAL_STAIRWELL_AREA_M2


def test_a_downstairs_or_upstairs_room_is_no_stairwell():
    from anyhome.floorplan.stairs import says_stair

    assert says_stair("stairwell_2") and says_stair("spiral stairs") and says_stair("Staircase hall")
    assert not says_stair("downstairs_loo") and not says_stair("upstairs study")


def test_a_semi_with_a_downstairs_loo_keeps_its_two_storeys():
    """The loo's id said "stair": it was taken for the ground floor's stairwell and the
    storeys fell back to one (every seed)."""
    from anyhome.pipeline import generate

    h = generate("a two-storey brick semi with a through lounge, a kitchen-diner and a downstairs loo, "
                 "three bedrooms and a bathroom upstairs", 5)
    assert len(h.levels) == 2 and not h.warnings
    assert next(r for r in h.rooms if "loo" in r.id).type == "bathroom"
