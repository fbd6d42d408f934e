"""A converted building is what it became (programs.yaml ``conversions``), and a room
named as what it was is the room it is now (issue 15, words read in context)."""

from __future__ import annotations

import pytest
from planned import names_of, plan_of

from anyhome.plan.parse import parse

CHURCH_THINGS = ("pew", "altar", "lectern", "hymn", "religious statue")


def _program(text: str) -> str | None:
    from anyhome.plan.knowledge import knowledge_base

    p = parse(text)
    return None if p.building is None else knowledge_base().raw("programs")["buildings"][p.building]["program"]


@pytest.mark.parametrize("text", ["a converted chapel home", "a converted church", "a church conversion with two bedrooms",
                                  "a former Methodist chapel, now a family home", "a deconsecrated church turned into a house"])
def test_a_converted_church_is_a_home_with_its_stained_glass_not_its_pews(text):
    spec = plan_of(text, 0)
    assert spec.building == "home"
    names = [n for r in spec.rooms for n in names_of(r)]
    assert not any(n.startswith(CHURCH_THINGS) for n in names), names
    assert not any("chapel" in r.name or "church" in r.name or "nave" in r.name for r in spec.rooms)
    living = next(r for r in spec.rooms if r.type == "living_room")
    assert "stained glass window" in names_of(living)


@pytest.mark.parametrize("text, program", [
    ("a former school turned into flats", "apartment"),
    ("an old school converted into apartments", "apartment"),
    ("a barn conversion with three bedrooms", "home"),
    ("Converted stone barn in the Cotswolds with a great room", "home"),
    ("a disused fire station, now a loft home", "apartment"),
    ("a former post office", "home"),
])
def test_a_conversion_is_the_building_it_became(text, program):
    assert _program(text) == program


def test_a_building_housed_in_a_former_one_keeps_its_own_program():
    assert _program("A boutique hotel in a former bank") == "hotel"
    assert _program("Community music school in a converted chapel") == "music_school"


def test_a_plain_old_building_or_a_home_is_no_conversion():
    assert _program("an old school with six classrooms") == "school"
    assert parse("a converted farmhouse with a big kitchen").former is None
    assert parse("a chapel with pews").former is None


def test_a_converted_barn_looks_like_a_farmhouse_and_has_no_stalls():
    spec = plan_of("Converted stone barn: a great room, a farmhouse kitchen and three bedrooms.", 0)
    assert "farmhouse" in spec.styles
    names = [n for r in spec.rooms for n in names_of(r)]
    assert not any(w in n for n in names for w in ("hay", "manger", "trough", "saddle"))
    assert sum(r.type == "bedroom" for r in spec.rooms) == 3


def test_a_room_named_as_what_it_was_is_the_room_it_is_now():
    p = parse("The old engine bay is the living room, with a big sectional; "
              "upstairs the former crew dormitory is now the primary bedroom.")
    assert [m.name for m in p.rooms] == ["living room", "primary bedroom"]
    assert p.objects[0].name == "sectional" and p.rooms[p.objects[0].room].name == "living room"
    # no former use said: the den and the playroom stay two rooms
    assert [m.name for m in parse("The den is a playroom for the kids").rooms] == ["den", "playroom"]


def test_a_room_named_again_in_brackets_or_described_after_a_colon_is_one_room():
    p = parse("a Turkish bath (hammam) with a marble slab, and a sauna")
    assert [m.name for m in p.rooms] == ["turkish bath", "sauna"]
    p = parse("the cabinet of curiosities: a wood-panelled room lined with display cases")
    assert [m.name for m in p.rooms] == ["cabinet of curiosities"]
    assert p.objects and p.objects[0].room == 0
