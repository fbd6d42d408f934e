"""Double-height rooms under a mezzanine or gallery (issue 13): a room much taller than the
other rooms of its storey rises through the storey above, which sits one ordinary storey
up, over the ordinary rooms, beside (not over) the tall room."""

from __future__ import annotations

from types import SimpleNamespace as R

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from anyhome.evaluate import evaluate_house
from anyhome.floorplan import levels
from anyhome.floorplan.levels import (
    SLAB_M,
    THROUGH_FACTOR,
    overhang_m2,
    reachable_rooms,
    through_rooms,
)
from anyhome.pipeline import generate

LOFTS = (
    "A loft apartment with a double-height living room, a kitchen, a mezzanine study and a shower room.",
    "a barn conversion with a double-height great room and a mezzanine bedroom",
    "a chapel conversion with a double-height nave living room and a gallery bedroom upstairs",
)


def _spec(text: str, seed: int):
    from anyhome.plan import get_planner
    from anyhome.plan.knowledge import knowledge_base
    from anyhome.stages import stage_rngs

    return get_planner("offline", knowledge_base()).plan(text, stage_rngs(seed)["plan"])


@pytest.mark.parametrize("text", LOFTS)
def test_mezzanine_sits_one_ordinary_storey_up_beside_the_tall_room(text):
    """Seeds 0-2: every house is valid with every room reachable; in at least one of them
    the upper storey sits one ordinary storey up, off the tall room, whose ceiling is not
    above the upper storey's. (A house whose upper storey finds no place beside the tall
    room is laid out as before, over its ceiling: a stair hall in place of the ground
    floor's hallway leaves the loft little ordinary floor to stand on.)"""
    kept = 0
    for seed in (0, 1, 2):
        spec = _spec(text, seed)
        through = through_rooms(spec)
        assert through, "the double-height room rises through the storey above"
        house = generate(text, seed=seed)
        assert house.level_numbers() == [0, 1]
        assert reachable_rooms(house) == {r.id for r in house.rooms}
        report = evaluate_house(house)
        assert report.violations == [] and report.metrics["connections_realized"] == 1.0
        ground = [r for r in house.rooms if r.level == 0]
        ordinary_m = max(r.height for r in ground if r.id not in through)
        tall = [r for r in ground if r.id in through]
        up = house.levels[1]
        if up.elevation_m != pytest.approx(ordinary_m + SLAB_M):  # laid out as before
            assert up.elevation_m == pytest.approx(max(r.height for r in ground) + SLAB_M)
            continue
        kept += 1
        assert tall and all(r.height >= THROUGH_FACTOR * ordinary_m - 1e-9 for r in tall)
        top_m = up.elevation_m + max(r.height for r in house.rooms if r.level == 1)
        for t in tall:
            assert t.height <= top_m + 1e-6  # its ceiling is not above the upper storey's
            for r in (r for r in house.rooms if r.level == 1):
                assert Polygon(r.polygon).intersection(Polygon(t.polygon)).area <= levels.THROUGH_OVERLAP_OK_M2
    assert kept >= 1  # measured: barn 3/3, chapel 3/3, loft 1/3 (its upper storey outgrows the ordinary rooms)


def test_tall_nave_is_cut_to_the_gallery_storeys_ceiling():
    """An 11 m nave under a storey of 2.7 m rooms: its ceiling stops at that storey's."""
    text = LOFTS[2]
    spec = _spec(text, 1)
    nave = next(r for r in spec.rooms if r.id in through_rooms(spec))
    house = generate(text, seed=1)
    up = house.levels[1]
    built = next(r for r in house.rooms if r.id == nave.id)
    assert built.height < nave.height_m
    assert built.height == pytest.approx(up.elevation_m + up.height_m - SLAB_M)
    windows = [w for w in house.windows if w.room == nave.id]
    assert all(w.sill + w.height <= built.height for w in windows)


@pytest.mark.parametrize("text", ["a three-storey townhouse with a kitchen, a living room and four bedrooms",
                                  "a two-storey family house with three bedrooms upstairs",
                                  "a two-storey farmhouse with a big kitchen and a basement"])
def test_house_without_tall_rooms_keeps_its_storey_heights(text):
    """No through room: every storey as high as its tallest room and the slab."""
    spec = _spec(text, 0)
    assert through_rooms(spec) == set()
    house = generate(text, seed=0)
    assert len(house.levels) >= 2
    for lv in house.levels:
        assert lv.height_m == pytest.approx(max(r.height for r in house.rooms if r.level == lv.level) + SLAB_M)


def test_no_place_beside_the_tall_room_lays_the_house_out_as_before(monkeypatch):
    """When no placement of the storey above keeps off the through room (here: none may
    touch it at all), the house is stacked as before: the storey above over the tall
    room's ceiling, not on one storey nor an error."""
    spec = _spec(LOFTS[1], 2)  # a barn whose tall storey stacks at once (others take a minute)
    tall = next(r for r in spec.rooms if r.id in through_rooms(spec))
    monkeypatch.setattr(levels, "THROUGH_OVERLAP_OK_M2", -1.0)
    plan = levels.solve_levels(spec, np.random.default_rng(2))
    assert [lv.level for lv in plan.levels] == [0, 1]
    assert plan.levels[1].elevation_m == pytest.approx(tall.height_m + SLAB_M)
    assert next(r for r in plan.rooms if r.id == tall.id).height == pytest.approx(tall.height_m)
    assert len(levels.stairs_objects(plan)) == 1
    assert through_rooms(spec) == {tall.id}  # the fallback does not leak out


def test_overhang_does_not_count_floor_over_a_through_room():
    ground = R(id="kitchen", name="kitchen", polygon=[(0, 0), (4, 0), (4, 4), (0, 4)], level=0, height=3.0)
    hall = R(id="living", name="living", polygon=[(4, 0), (9, 0), (9, 4), (4, 4)], level=0, height=6.0)
    up = R(id="study", name="study", polygon=[(0, 0), (6, 0), (6, 4), (0, 4)], level=1, height=3.0)
    assert overhang_m2([ground, hall, up]) == pytest.approx(8.0)  # 2 x 4 m over the double-height room
    low_hall = R(**{**vars(hall), "height": 3.2})
    assert overhang_m2([ground, low_hall, up]) == pytest.approx(0.0)
    bare = [R(polygon=r.polygon, level=r.level) for r in (ground, hall, up)]  # no heights: as before
    assert overhang_m2(bare) == pytest.approx(0.0)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.integers(-1, 2), st.floats(2.0, 12.0), st.booleans()), min_size=1, max_size=12))
def test_through_rooms_are_the_tall_rooms_of_a_storey_under_another(rooms):
    rows = [(f"r{i}", k, h, stair) for i, (k, h, stair) in enumerate(rooms)]
    got = levels._through_ids(rows)
    numbers = {k for _, k, _, _ in rows}
    for k in numbers:
        here = [r for r in rows if r[1] == k]
        rest = [h for i, _, h, _ in here if i not in got]
        assert rest, "a storey never rises through entirely"
        for i, _, h, stair in here:
            if i in got:
                assert k >= 0 and k + 1 in numbers and not stair
                assert h >= THROUGH_FACTOR * max(rest) - 1e-9
            elif k >= 0 and k + 1 in numbers and not stair and h > min(rest):
                # an ordinary room: not that much taller than the storey's other ordinary rooms
                others = [x for j, _, x, _ in here if j not in got and j != i]
                assert h < THROUGH_FACTOR * max(others) + 1e-9
