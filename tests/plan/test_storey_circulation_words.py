"""Words of several-storey homes read as their storeys and rooms (h-circ2): the fixes that
kept storey homes from planning floors, stairs and halls they do not have."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.plan import plan_house
from anyhome.plan.parse import parse


def _spec(text: str, seed: int = 0):
    return plan_house(text, np.random.default_rng(seed))


def _levels(text: str, seed: int = 0) -> dict[str, int]:
    return {r.id: r.level for r in _spec(text, seed).rooms}


BUNGALOW = ("Single-storey bungalow with a full basement underneath: upstairs the kitchen, living room, two "
            "bedrooms and a bathroom; in the basement a games room, the laundry and a guest bedroom with a shower.")


@pytest.mark.parametrize("seed", [0, 1])
def test_a_single_storey_house_over_a_basement_has_its_upstairs_on_the_ground_floor(seed):
    levels = _levels(BUNGALOW, seed)
    assert set(levels.values()) == {-1, 0}
    assert levels["kitchen"] == levels["living_room"] == 0
    assert levels["games_room"] == -1


def test_upstairs_still_adds_a_storey_where_no_storey_count_is_given():
    assert parse("A family home with a basement laundry and three bedrooms upstairs").storeys == 2


@pytest.mark.parametrize("seed", [0, 1])
def test_a_list_after_another_storeys_words_goes_up_whole(seed):
    levels = _levels("Upside-down beach house: three bedrooms and two bathrooms on the ground floor, and the "
                     "kitchen, dining and living space upstairs to catch the sea view.", seed)
    assert levels["kitchen"] == levels["living_space"] == 1
    assert levels.get("dining_room", 1) == 1  # (a seed may plan the dining in the living space)
    assert all(v == 0 for k, v in levels.items() if k.startswith(("bedroom", "master_bedroom", "bathroom")))


def test_a_floor_named_without_its_noun_after_named_floors_is_a_storey():
    text = ("Narrow townhouse on four storeys: a garage on the ground floor, a kitchen on the first floor, "
            "a study on the second, and a bedroom on the third floor.")
    assert [w for _, _, w in parse(text).floor_words] == ["ground", "first", "second", "third"]
    assert _levels(text)["study"] == 2


def test_rooms_underneath_the_ones_named_upstairs_are_on_the_ground_floor():
    text = "A two-storey cabin with two bedrooms upstairs; underneath them a kitchen and a shower room."
    levels = _levels(text)
    assert levels["kitchen"] == levels["shower_room"] == 0
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k)


WHEELS = ("A tiny house on wheels with two sleeping lofts at either end, one reached by a ladder and one by a "
          "storage staircase; underneath them a kitchenette, a compact shower room with a composting toilet and "
          "a built-in sofa.")


def test_a_room_word_naming_a_kind_of_stair_is_no_room():
    assert [m.name for m in parse(WHEELS).rooms if m.kind == "room"] == ["sleeping loft", "kitchenette", "shower room"]


def test_a_sofa_listed_after_a_shower_room_is_not_put_in_it():
    spec = _spec(WHEELS)
    shower = next(r for r in spec.rooms if r.id == "shower_room")
    assert not any(g.anchor.category == "sofa" for g in shower.groups)
    assert any(g.anchor.category == "sofa" for r in spec.rooms for g in r.groups)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_tiny_house_with_sleeping_lofts_is_planned_tiny(seed):
    spec = _spec(WHEELS, seed)
    assert sum(r.area_m2 for r in spec.rooms) <= 45.0
    studio = next(r for r in spec.rooms if r.type == "living_room")
    assert not any(g.anchor.category == "bed" for g in studio.groups)  # the lofts hold the beds
    assert sum(r.type == "bedroom" for r in spec.rooms) == 2


def test_a_studio_with_no_bedroom_beside_it_keeps_its_bed():
    spec = _spec("A studio apartment with a kitchenette and a shower room")
    studio = next(r for r in spec.rooms if r.type == "living_room")
    assert any(g.anchor.category == "bed" for g in studio.groups)
