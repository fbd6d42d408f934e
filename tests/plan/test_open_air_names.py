"""Rooms whose name says they are open to the sky are built open (issue 13): the words
are rooms.yaml's ``open_air`` section, not a list in code."""

from __future__ import annotations

import copy

import pytest

from anyhome.errors import KnowledgeError
from anyhome.plan import get_planner
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.knowledge import KNOWLEDGE_FILES, knowledge_base, load
from anyhome.plan.program import open_air_word
from anyhome.stages import stage_rngs

KB = knowledge_base()
PLANNER = get_planner("offline")


def plan(text: str, seed: int = 0):
    return PLANNER.plan(text, stage_rngs(seed)["plan"])


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("rooftop garden", "roof_terrace"),
        ("roman atrium", "courtyard"),
        ("shaded loggia", "terrace"),
        ("wraparound verandah", "porch"),
        ("peristyle", "courtyard"),
        ("porch", "porch"),
        ("garden room", None),
        ("winter garden", None),
        ("screened porch", None),
        ("pool house", None),
        ("conservatory", None),
        ("kitchen", None),
    ],
)
def test_a_name_says_whether_a_room_is_open_air(name, expected):
    assert open_air_word(KB, name) == expected


@pytest.mark.parametrize("seed", [0, 1])
def test_an_atrium_is_open_to_the_sky(seed):
    spec = plan("A Roman atrium house with an atrium and a peristyle garden", seed)
    atria = [r for r in spec.rooms if "atrium" in r.name]
    assert atria
    assert all(r.open_air for r in atria), [(r.name, r.type, r.open_air) for r in atria]


def test_enclosed_garden_words_keep_their_ceiling():
    spec = plan("A Victorian house with a conservatory, a winter garden and a garden room")
    named = {r.name: r for r in spec.rooms}
    for name in ("winter garden", "garden room"):
        assert name in named, list(named)
        assert not named[name].open_air


def test_a_habitable_room_named_open_air_keeps_its_type_and_loses_its_ceiling():
    from anyhome.plan.program import Slot, open_air_by_name

    cafe = Slot("courtyard cafe", "cafe", "cafe", (30.0, 40.0))
    store = Slot("terrace store", "storage", "storage", (4.0, 6.0))
    open_air_by_name(KB, [cafe, store])
    assert (cafe.type, cafe.open_air) == ("cafe", True)
    assert store.type == "terrace"


def test_an_open_air_word_must_name_an_open_air_type():
    raw = copy.deepcopy({name: load(name) for name in KNOWLEDGE_FILES})
    raw["rooms"]["open_air"]["words"]["sun lounge"] = "living_room"
    with pytest.raises(KnowledgeError) as e:
        KnowledgeBase(raw, lambda name, loc: f"{name}.yaml")
    assert "sun lounge" in str(e.value)
