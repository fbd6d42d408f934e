"""Ceiling heights and open air in the plan: rooms.yaml ``height_m`` / ``open_air`` per
type, heights.yaml (building kinds and height words), and the room a height word goes to."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.errors import KnowledgeError
from anyhome.plan import get_planner
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.spec import RoomSpec

pytestmark = pytest.mark.usefixtures("no_knowledge_overlay")  # tests/conftest.py


def _plan(text: str, seed: int = 0):
    return get_planner("offline").plan(text, np.random.default_rng(seed))


def test_every_type_has_a_height_and_open_air_types_are_not_habitable() -> None:
    kb = knowledge_base()
    types = kb.rooms.types
    for t in ("balcony", "terrace", "deck", "patio", "porch", "courtyard", "garden", "roof_terrace"):
        assert types[t].open_air and not types[t].habitable
    assert types["hall"].height_m >= 5.0 and types["gym"].height_m >= 4.5
    assert types["classroom"].height_m == 3.0 and types["garage"].height_m < 2.7
    assert not any(rt.open_air for t, rt in types.items() if rt.habitable)


@pytest.mark.parametrize("word, room_type", [
    ("veranda", "porch"), ("roof terrace", "roof_terrace"), ("courtyard", "courtyard"), ("garden", "garden"),
    ("deck", "deck"), ("patio", "patio"), ("terrace", "terrace")])
def test_open_air_room_words(word, room_type) -> None:
    spec = _plan(f"a house with a {word}")
    rooms = [r for r in spec.rooms if r.type == room_type]
    assert rooms and all(r.open_air and r.ceiling == "flat" and r.materials["ceiling"] == "" for r in rooms)
    assert all(not r.open_air for r in spec.rooms if r.type not in {room_type, "balcony"})


def test_height_words_go_to_their_room() -> None:
    spec = _plan("a kitchen, a bedroom and a sunken living room with high ceilings")
    h = {r.type: r.height_m for r in spec.rooms}
    assert h["living_room"] == pytest.approx(round((2.7 * 1.25 + 0.4) / 0.05) * 0.05)
    assert h["kitchen"] == 2.7 and h["bedroom"] == 2.6
    spec = _plan("a kitchen and a double height living room")  # a pre-modifier: the room after it
    h = {r.type: r.height_m for r in spec.rooms}
    assert h["living_room"] == 5.4 and h["kitchen"] == 2.7


def test_house_wide_words_and_building_kinds() -> None:
    low = _plan("a low-ceilinged cottage")
    assert all(r.height_m < 2.6 for r in low.rooms)
    assert min(r.height_m for r in low.rooms) >= 2.3  # the limit keeps doors (2.1 m) under ceilings
    mansion = _plan("a mansion")
    assert {r.type: r.height_m for r in mansion.rooms}["living_room"] > 3.0
    cabin = _plan("a cabin with a pitched ceiling")
    shapes = {r.type: r.ceiling for r in cabin.rooms}
    assert shapes["living_room"] == "pitched" and shapes["bathroom"] == "flat"  # habitable rooms only


def test_llm_rooms_take_their_type_height_and_open_air() -> None:
    r = RoomSpec(id="t", name="terrace", type="terrace", area_m2=12)
    assert r.open_air and r.height_m == 2.7
    r = RoomSpec(id="h", name="ballroom", type="hall", area_m2=60)
    assert not r.open_air and r.height_m >= 5.0
    r = RoomSpec(id="h", name="hall", type="hall", area_m2=60, height_m=3.0)  # a planner's own height stays
    assert r.height_m == 3.0
    assert RoomSpec(id="b", name="b", type="balcony", area_m2=5, ceiling="vaulted").ceiling == "flat"


@pytest.mark.parametrize("files, expected", [
    ({"rooms.yaml": "types:\n  balcony: {height_m: 2.7, open_air: true, min_width_m: 1.2, habitable: true, "
                    "area: [4, 8], tier: 7, max: 2, materials: {floor: a, walls: b, ceiling: ''}}\n"},
     "rooms.yaml: types.balcony: an open_air room cannot be habitable"),
    ({"rooms.yaml": "types:\n  balcony: {height_m: 30}\n"}, "rooms.yaml: types.balcony: height_m: Input should be less than or equal to 12"),
    ({"heights.yaml": "words:\n  domed: {ceiling: domed}\n"}, "heights.yaml: words.domed: ceiling:"),
    ({"heights.yaml": "limits: {min_m: 4.0, max_m: 3.0}\n"}, "heights.yaml: limits: min_m 4.0 is more than max_m 3.0"),
])
def test_bad_height_knowledge_is_one_line(tmp_path, files, expected) -> None:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    with pytest.raises(KnowledgeError) as e:
        knowledge_base([str(tmp_path)])
    assert expected in str(e.value) and "\n" not in str(e.value)
