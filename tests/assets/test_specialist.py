"""Specialist objects (issue 15): flames, specialist and photo families. Names map to
their families, knobs change the mesh, and every word assets.yaml once listed as a
stand-in is now drawn by a family of its own. (Bounds, determinism, face counts and
roles of every family are checked in test_invariants, test_families and test_part_roles.)"""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps, typical_mesh

from anyhome.assets.procedural._parts import face_roles
from anyhome.assets.registry import family_for, is_stand_in
from anyhome.plan.knowledge import knowledge_base

CASES = [
    ("candle", "candle", "candle"),
    ("", "tea light", "candle"),
    ("candlestick", "candlestick", "candlestick"),
    ("", "candle holder", "candlestick"),
    ("candelabra", "candelabra", "candelabra"),
    ("lantern", "wall lantern", "lantern"),
    ("", "hurricane lamp", "lantern"),
    ("", "wood-burning stove", "wood_stove"),
    ("", "log burner", "wood_stove"),
    ("sauna_stove", "kiuas", "sauna_stove"),
    ("stove", "sauna heater", "sauna_stove"),
    ("", "checkout counter", "cash_register"),
    ("", "zabuton", "floor_cushion"),
    ("", "high sleeper", "loft_bed"),
    ("statue", "suit of armor", "suit_of_armour"),
    ("lamp", "examination lamp", "exam_lamp"),
    ("sink", "dog wash tub", "dog_wash_tub"),
    ("", "dog bath", "dog_wash_tub"),
    ("", "compost toilet", "composting_toilet"),
    ("", "seamless backdrop", "backdrop"),
    ("", "paper backdrop", "backdrop"),
    ("", "softbox", "studio_light"),
    ("", "ring light", "studio_light"),
    ("", "strobe", "studio_light"),
    ("", "tripod", "camera_tripod"),
    ("well", "old stone well", "well"),
    ("", "wellhead", "well"),
    ("archery_target", "straw target", "archery_target"),
    ("", "target boss", "archery_target"),
]

REMOVED_STAND_INS = {
    "sauna_stove": "sauna_stove", "sauna_heater": "sauna_stove", "kiuas": "sauna_stove",
    "candelabra": "candelabra", "candlestick": "candlestick", "candle": "candle", "lantern": "lantern",
    "wood_stove": "wood_stove", "wood_burning_stove": "wood_stove", "woodstove": "wood_stove",
    "suit_of_armour": "suit_of_armour", "suit_of_armor": "suit_of_armour", "cash_register": "cash_register",
    "till": "cash_register", "floor_cushion": "floor_cushion", "zabuton": "floor_cushion",
    "composting_toilet": "composting_toilet", "examination_lamp": "exam_lamp", "exam_lamp": "exam_lamp",
    "dog_wash_tub": "dog_wash_tub", "dog_bath": "dog_wash_tub", "loft_bed": "loft_bed",
}
"""The words assets.yaml `stand_ins` listed before these families -> the family drawing each."""


def test_names_map_to_families() -> None:
    assert_maps(CASES)


def _prototype_category(word: str) -> str:
    """The category the planner gives an object named ``word`` (its prototype's)."""
    from anyhome.plan.kb import word_key

    for key, proto in knowledge_base().objects.items():
        if word in {word_key(w) for w in (key, *proto.synonyms)}:
            return proto.category
    raise AssertionError(f"no prototype names {word!r}")


@pytest.mark.parametrize(("word", "family"), sorted(REMOVED_STAND_INS.items()))
def test_former_stand_ins_are_drawn_by_their_own_family(word: str, family: str) -> None:
    assert word not in knowledge_base().assets.stand_ins
    name = word.replace("_", " ")
    category = _prototype_category(word)
    assert family_for(category, name) == family
    assert not is_stand_in(category, name, family)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("candle", "count", 1, 3),
        ("well", "frame", "roof", "none"),
        ("well", "bucket", True, False),
        ("archery_target", "arrows", 0, 3),
        ("candlestick", "turned", True, False),
        ("candelabra", "arms", 2, 4),
        ("lantern", "kind", "carriage", "hurricane"),
        ("wood_stove", "round_body", True, False),
        ("wood_stove", "window", True, False),
        ("sauna_stove", "guard", True, False),
        ("cash_register", "belt", True, False),
        ("floor_cushion", "tufts", 1, 4),
        ("loft_bed", "under", "desk", "open"),
        ("suit_of_armour", "weapon", "halberd", "none"),
        ("exam_lamp", "reach", 0.55, 0.8),
        ("dog_wash_tub", "ramp", True, False),
        ("composting_toilet", "kind", "box", "unit"),
        ("backdrop", "sweep", 0.55, 0.9),
        ("studio_light", "kind", "softbox", "ring"),
        ("studio_light", "kind", "umbrella", "softbox"),
        ("camera_tripod", "flash", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


@pytest.mark.parametrize(("family", "roles"), [
    ("candle", {"light"}), ("candlestick", {"metal", "light"}), ("candelabra", {"metal", "light"}),
    ("lantern", {"metal", "glass", "light"}), ("wood_stove", {"metal", "light"}), ("sauna_stove", {"metal", "stone"}),
    ("suit_of_armour", {"metal"}), ("exam_lamp", {"light"}), ("backdrop", {"paper", "metal"}),
    ("studio_light", {"metal", "light"}), ("camera_tripod", {"metal", "glass"}),
])
def test_parts_are_what_the_thing_is_made_of(family: str, roles: set[str]) -> None:
    for seed in (0, 7):
        assert roles <= set(face_roles(typical_mesh(family, seed, ""))), family
