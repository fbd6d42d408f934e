"""A tiny home of several storeys fits a tiny home's total (issue 13): the size word is
read past the storey words, a tiny house of one main room keeps its word's total as a
ceiling, its rooms' norms shrink by the word's ``least`` factor (never below a square
of the type's min_width_m), its stairwells are sized for the stairs the fitted total
calls for, and its rooms keep only their first furniture when the total is tight."""

from __future__ import annotations

import pytest
from shapely.geometry import Polygon

from anyhome.floorplan.levels import solve_levels
from anyhome.plan import get_planner
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.parse import parse
from anyhome.plan.program import HELD_KEYS, Slot, choose_program, norm_area_m2, sizing
from anyhome.stages import stage_rngs

PLANNER = get_planner("offline", floorplan=solve_levels)
KB = knowledge_base()
TYPES = KB.raw("rooms")["types"]

COTTAGE = "A tiny two-storey cottage: a kitchen and sitting room downstairs, one bedroom and a bathroom upstairs."
TOWER = ("a tiny three storey tower house with one room per floor - kitchen/diner at the bottom, sitting room "
         "and a wc in the middle, bedroom with a shower at the top")


def plan(text: str, seed: int = 0):
    return PLANNER.plan(text, stage_rngs(seed)["plan"])


@pytest.mark.parametrize("text", [
    "a tiny three storey tower house", "a tiny two-storey cottage", "a tiny 2 storey cabin", "a grand three-storey townhouse",
])
def test_a_size_word_is_read_past_the_storey_words(text):
    assert parse(text, KB).size_words == [text.split()[1]]


def test_a_number_not_of_storeys_still_ends_the_size_words():
    assert parse("a large 2 bedroom flat", KB).size_words == []  # as before: the count ends the phrase


def test_places_without_a_storey_word_name_storeys_in_a_tower():
    levels = {r.name: r.level for r in plan(TOWER).rooms}
    assert levels["kitchen diner"] == 0  # "one room per floor - kitchen/diner": the dash ends "floor"
    assert levels["sitting room"] == levels["wc"] == 1
    assert max(levels.values()) == 2


def test_places_without_a_storey_word_leave_a_one_storey_home_alone():
    p = parse("a kitchen with an island in the middle and a shelf at the top", KB)
    assert p.storeys == 1 and not p.floor_words


def test_a_tiny_house_of_one_main_room_keeps_its_word_total_as_a_ceiling():
    p = parse("a tiny house with a mezzanine bedroom", KB)
    program, _ = choose_program(KB, p)
    sz = sizing(KB, p, program)
    tiny = KB.raw("programs")["sizes"]["words"]["tiny"]
    assert sz.band == (0.0, float(tiny["total_m2"][1]))
    assert sz.least_scale == tiny["least"] < 1.0


@pytest.mark.parametrize("room_type", ["bedroom", "living_room", "kitchen", "bathroom", "dining_room"])
def test_a_tiny_homes_norm_is_smaller_but_never_below_a_square_of_the_min_width(room_type):
    info = TYPES[room_type]
    full = Slot("x", room_type, room_type, (1.0, 99.0))
    tiny = Slot("x", room_type, room_type, (1.0, 99.0), least_scale=0.5)
    assert norm_area_m2(KB, full) == info["min_area_m2"]
    assert norm_area_m2(KB, tiny) <= info["min_area_m2"]
    assert norm_area_m2(KB, tiny) >= min(info["min_area_m2"], info["min_width_m"] ** 2) - 1e-9


@pytest.mark.parametrize("text", [COTTAGE, TOWER, "A tiny house with a mezzanine bedroom over a compact kitchen, a bathroom and a small lounge."])
def test_a_tiny_home_of_several_storeys_is_built_within_a_tiny_total(text):
    for seed in (0, 1):
        spec = plan(text, seed)
        assert len({r.level for r in spec.rooms}) >= 2
        built = solve_levels(spec, stage_rngs(seed)["floorplan"])
        area = sum(Polygon(r.polygon).area for r in built.rooms)
        assert area <= 45.0, (seed, area, [(r.name, r.level, r.area_m2) for r in spec.rooms])
        for r in built.rooms:  # the bars on widths still hold
            if r.type in ("bedroom", "living_room"):
                b = Polygon(r.polygon).bounds
                assert min(b[2] - b[0], b[3] - b[1]) >= {"bedroom": 2.4, "living_room": 3.0}[r.type], (seed, r.name, b)


def test_a_tiny_home_gets_compact_stairs_and_its_stairwells_are_sized_for_them():
    spec = plan(COTTAGE)
    wells = [r for r in spec.rooms if r.type == "stairwell"]
    assert wells and all(r.area_m2 <= 4.5 for r in wells)  # a ladder's well (3.5 m2), not a dog-leg's (8.5)
    assert HELD_KEYS


def test_a_tight_tiny_bedroom_keeps_its_bed_not_its_reading_chair():
    spec = plan(COTTAGE)
    bedroom = next(r for r in spec.rooms if r.type == "bedroom")
    names = {g.name for g in bedroom.groups}
    assert "bed" in names
    assert all(g.priority == 0 or g.required for g in bedroom.groups), names
