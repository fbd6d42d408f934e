"""Open vocabulary: words the knowledge base does not list still shape the plan."""

import numpy as np
import pytest

from anyhome.plan import get_planner
from anyhome.plan.openvocab import find_object_phrases, first_noun_phrase
from anyhome.plan.parse import _tokens, parse, parse_number
from anyhome.plan.spec import MAX_COUNT


def plan(text, seed=0):
    return get_planner("offline").plan(text, np.random.default_rng(seed))


def items(room):
    out = []
    for g in room.groups:
        out.append((g.anchor.name, g.anchor.count * g.repeat))
        out.extend((m.name, m.count * g.repeat) for m in g.members)
    out.extend((o.name, o.count) for o in room.ornaments)
    return out


def _phrases(text):
    return [p for p, *_ in find_object_phrases(text, _tokens(text), [], lambda t: parse_number(t) is not None)]


def test_object_phrases_come_from_lists_only():
    assert _phrases("a cabin with a hammock, a jukebox and two chaise longues") == ["hammock", "jukebox", "chaise longues"]
    assert _phrases("a cabin for a musician") == []  # no list opener
    assert _phrases("a house with lots of character and great views") == []  # non-objects


def test_first_noun_phrase():
    text = "a dojo with tatami mats"
    assert first_noun_phrase(text, _tokens(text))[0] == "dojo"


def test_unknown_objects_keep_name_and_count():
    h = plan("A cabin with two hammocks and a treasure chest.")
    names = {n: c for r in h.rooms for n, c in items(r)}
    assert names.get("hammock") == 2
    assert names.get("treasure chest") == 1


def test_unknown_object_without_match_is_warned_about():
    h = plan("A house with a flumbrixer.")
    assert any("flumbrixer" in w for w in h.warnings)
    assert any(n == "flumbrixer" for r in h.rooms for n, _ in items(r))


@pytest.mark.parametrize(
    ("text", "name", "types"),
    [
        ("A house with a séance room.", "séance room", None),
        ("A house with a boot room.", "boot room", {"entry"}),
        ("A cabin with a home theater and a sauna.", "sauna", {"treatment_room"}),
        ("A cottage with a pottery studio.", "pottery studio", {"studio"}),
    ],
)
def test_unknown_rooms_keep_the_users_name(text, name, types):
    h = plan(text)
    rooms = [r for r in h.rooms if r.name == name]
    assert rooms, [r.name for r in h.rooms]
    if types:
        assert rooms[0].type in types


def test_each_with_gives_every_room_its_own():
    h = plan("A house with three bedrooms, each with a desk and a bunk bed.")
    beds = [r for r in h.rooms if r.type == "bedroom"]
    assert len(beds) == 3
    for r in beds:
        names = [n for n, _ in items(r)]
        assert "desk" in names and "bunk bed" in names


def test_each_with_multiplies_rooms_named_inside():
    h = plan("A hotel with four guest rooms, each with its own bathroom.")
    assert sum(r.type == "bathroom" for r in h.rooms) == 4


def test_bed_bath_in_words():
    p = parse("A two bed, two bath condo")
    assert (p.bedrooms, p.bathrooms) == (2, 2)


def test_head_of_adjacent_building_words_wins():
    assert plan("A boutique hotel with a lobby.").building == "hotel"


def test_unknown_style_word_before_building_is_kept():
    h = plan("A Craftsman bungalow with a porch.")
    assert h.style.startswith("craftsman")


def test_other_scripts_warn_and_plan_a_default():
    h = plan("一个有两间卧室的日式房子")
    assert any("another script" in w for w in h.warnings)
    assert len(h.rooms) >= 1


def test_one_room_contradiction_is_warned_about():
    h = plan("a one-room house with five bedrooms")
    assert sum(r.type == "bedroom" for r in h.rooms) == 5
    assert any("one-room" in w for w in h.warnings)


def test_absurd_object_count_is_capped_with_a_warning():
    h = plan("a hall with 5000 chairs")
    assert any("5000" in w and str(MAX_COUNT) in w for w in h.warnings)


def test_nonsense_is_not_a_style():
    h = plan("asdf qwer zxcv")
    assert "asdf" not in h.style
    assert any("recognised" in w for w in h.warnings)


def test_object_on_a_room_goes_there():
    h = plan("A house with two hammocks on the porch.")
    porch = next(r for r in h.rooms if r.name == "porch")
    assert ("hammock", 2) in items(porch)


def test_a_colon_opens_a_list_as_with_does():
    """"A monastery: twelve cells, a chapel": before, what stood right after the colon
    was read as nothing, so the twelve cells were lost."""
    assert _phrases("a monastery: twelve cells, a chapel") == ["cells", "chapel"]
    cells = [m for m in parse("A small monastery: twelve cells, a chapel and a refectory.").rooms if m.name == "cell"]
    assert cells and cells[0].count == 12


def test_a_closed_compound_on_room_is_a_room():
    """"two courtrooms" was read as two objects named courtroom; "a mushroom" stays
    no room."""
    p = parse("A courthouse with two courtrooms and a mushroom planter.")
    rooms = {m.name: m for m in p.rooms}
    assert "courtroom" in rooms and rooms["courtroom"].count == 2
    assert not any("mushroom" in m.name for m in p.rooms)


def test_a_building_word_weakly_guessed_as_a_home_plans_only_the_named_rooms():
    """"A county courthouse with ...": the embedding matcher's nearest building for
    "courthouse" is a courtyard house (a weak match); with none of a home's rooms named,
    the house has the named rooms and no bedrooms, and the holding cells alone go to the
    basement (before, every room went down and the plan had no entrance)."""
    spec = plan("County courthouse with two courtrooms, judges chambers, a jury deliberation room, "
                "and a few holding cells in the basement.")
    types = [r.type for r in spec.rooms]
    assert "bedroom" not in types and "living_room" not in types
    names = {r.name: r for r in spec.rooms}
    assert {"courtroom", "courtroom 2", "jury deliberation room"} <= set(names)
    assert names["courtroom"].level == 0 and names["holding cell"].level == -1
    by_id = {r.id: r for r in spec.rooms}
    entrances = [by_id[c[0]] for c in spec.connections if c[1] == "outside"]
    assert entrances and all(r.level == 0 for r in entrances)
