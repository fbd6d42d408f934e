"""Issue 11, the planner's part: counts in any notation, caps with warnings, negation,
and no control characters in a plan."""

import json
import re
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome.plan import get_planner
from anyhome.plan.offline import (
    MAX_HOUSE_OBJECTS,
    MAX_ROOM_AREA_M2,
    MAX_ROOM_OBJECTS,
)
from anyhome.plan.parse import parse, rewrite_numbers
from anyhome.plan.spec import MAX_COUNT, MAX_ROOMS, HouseSpec, ItemSpec, RoomSpec


def plan(text, seed=0):
    return get_planner("offline").plan(text, np.random.default_rng(seed))


def objects_in(room):
    return sum((g.anchor.count + sum(m.count for m in g.members)) * g.repeat for g in room.groups) + sum(
        o.count for o in room.ornaments
    )


def names(h):
    return [f"{r.name} {r.type}" for r in h.rooms]


def items(h):
    return [
        f"{it.name} {it.category}" for r in h.rooms for g in r.groups for it in [g.anchor, *g.members]
    ] + [f"{o.name} {o.category}" for r in h.rooms for o in r.ornaments]


# ------------------------------------------------------------------ numbers


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("10^9 chairs", 10**9), ("10 ** 9 chairs", 10**9), ("1e9 chairs", 10**9), ("1.5e+6 chairs", 1_500_000),
        ("1,000,000 chairs", 10**6), ("a million chairs", 10**6), ("a billion chairs", 10**9),
        ("two hundred and fifty chairs", 250), ("twenty four chairs", 24), ("3 dozen chairs", 36),
        ("-3 chairs", -3), ("2.5 chairs", 3), ("10^99999 chairs", 10**99), ("9" * 400 + " chairs", 10**99),
    ],
)  # fmt: skip
def test_counts_in_any_notation(text, value):
    chair = parse(text).objects[0]
    assert chair.asked == value


def test_single_number_words_stay_words():
    assert rewrite_numbers("one two three") == "one two three"
    assert rewrite_numbers("a twin bed and a pair of lamps") == "a twin bed and a pair of lamps"


@settings(max_examples=60, deadline=None)
@given(st.text(alphabet="0123456789 ^e*.,-+ab", max_size=40))
def test_number_rewriting_never_raises_and_stays_short(text):
    out = rewrite_numbers(text)
    assert len(out) <= len(text) + 200


@pytest.mark.parametrize(
    ("text", "word"),
    [("10^9 rooms", "rooms"), ("1e9 bedrooms", "bedrooms"), ("a billion bedrooms", "bedrooms"),
     ("100 bathrooms", "bathrooms"), ("a hotel with 60 rooms", "60 rooms")],
)  # fmt: skip
def test_too_many_rooms_warn_and_plan_a_full_house(text, word):
    h = plan(text)
    assert len(h.rooms) == MAX_ROOMS
    assert any(word.split()[-1] in w and f"at most {MAX_ROOMS} rooms" in w for w in h.warnings), h.warnings


def test_forty_hotel_rooms_fill_the_house_with_guest_rooms():
    h = plan("a hotel with 40 rooms")  # within MAX_ROOMS (48): planned as asked
    # the 40 are the program's corridor and 39 other rooms; more corridors carry on from
    # it for the guest rooms to open off (program.connect_corridors), on top of the 40 as
    # a house of several storeys gets its stairwells on top of the rooms asked for
    from anyhome.plan.program import CORRIDORS_MAX

    halls = sum(r.type == "hallway" for r in h.rooms)
    assert len(h.rooms) - halls == 39 and 1 <= halls <= CORRIDORS_MAX
    assert not any("at most" in w and "rooms" in w.split("at most")[1][:12] for w in h.warnings)
    assert sum(r.type == "bedroom" for r in h.rooms) >= 30


def test_a_negative_count_warns_and_is_ignored():
    h = plan("-3 bathrooms")  # as if no number was given: "bathrooms", two
    assert [r.type for r in h.rooms] == ["bathroom", "bathroom"]
    assert any("-3" in w and "negative" in w for w in h.warnings)


def test_zero_rooms_of_a_kind_warns_and_plans_a_house_without_them():
    h = plan("0 kitchens")
    assert h.rooms and not any(r.type == "kitchen" for r in h.rooms)
    assert any("kitchen" in w for w in h.warnings)


# ------------------------------------------------------------------ caps


def test_per_room_and_per_house_object_caps_bite_with_warnings():
    h = plan("twelve bedrooms, each with 120 desks, 120 chairs, 120 lamps and 120 clocks")
    per_room = [objects_in(r) for r in h.rooms]
    assert max(per_room) <= MAX_ROOM_OBJECTS and sum(per_room) <= MAX_HOUSE_OBJECTS
    assert any(f"at most {MAX_ROOM_OBJECTS} per room" in w and "120 desks" in w for w in h.warnings), h.warnings
    assert any(f"a house holds at most {MAX_HOUSE_OBJECTS}" in w for w in h.warnings), h.warnings
    assert all(r.area_m2 <= MAX_ROOM_AREA_M2 for r in h.rooms)


def test_equal_asks_stay_equal_under_the_room_cap():
    h = plan("a bedroom with 120 desks, 120 lamps and 120 clocks")
    room = h.rooms[0]
    desks = sum(g.repeat for g in room.groups if g.anchor.category == "desk")
    clocks = sum(o.count for o in room.ornaments if o.category == "clock")
    assert objects_in(room) <= MAX_ROOM_OBJECTS and abs(desks - clocks) <= 1


def test_item_count_cap_warns_with_the_number_asked():
    h = plan("a library with a million books")
    assert any("1e6 books" in w and f"at most {MAX_COUNT}" in w for w in h.warnings)


def test_a_lecture_hall_keeps_its_hundred_and_twenty_seats():
    h = plan("a lecture hall with 120 seats")
    seats = sum(
        g.repeat * it.count for r in h.rooms for g in r.groups for it in [g.anchor, *g.members] if "seat" in it.name
    )
    assert seats == 120 and not any("per room" in w for w in h.warnings)


def test_a_room_grown_past_its_cap_warns():
    h = plan("a game room with 120 pool tables")
    assert h.rooms[0].area_m2 <= MAX_ROOM_AREA_M2
    assert any(f"at most {MAX_ROOM_AREA_M2:.0f} m2" in w for w in h.warnings), h.warnings


# ------------------------------------------------------------------ negation


@pytest.mark.parametrize(
    ("text", "gone"),
    [("a house without a kitchen", "kitchen"), ("a house with a garden and no garage", "garage"),
     ("a house with two bedrooms but no bathroom", "bathroom"), ("a home with no dining room", "dining"),
     ("an apartment that doesn't need a balcony", "balcony"),
     ("a house without a kitchen or a bathroom", "kitchen"), ("a house without a kitchen or a bathroom", "bathroom")],
)  # fmt: skip
def test_negated_rooms_are_not_planned(text, gone):
    for seed in range(3):
        h = plan(text, seed)
        assert not any(gone in n for n in names(h)), (seed, names(h))


def test_negated_room_is_planned_without_a_warning_when_the_house_stays_valid():
    h = plan("a house without a bathroom")
    assert not any(r.type == "bathroom" for r in h.rooms) and not h.warnings


@pytest.mark.parametrize(
    ("text", "gone"),
    [("a bedroom without a tv", "tv"), ("a living room with no rug", "rug"),
     ("a living room with no tv, rug or lamp", "lamp"), ("a house with no rugs", "rug")],
)  # fmt: skip
def test_negated_objects_are_not_planned(text, gone):
    for seed in range(4):
        h = plan(text, seed)
        assert not any(re.search(rf"\b{gone}\b", it) for it in items(h)), (seed, items(h))


def test_negation_does_not_reach_past_a_positive_item():
    h = plan("a house with no garage, a big kitchen and two bedrooms")
    types = [r.type for r in h.rooms]
    assert "garage" not in types and "kitchen" in types and types.count("bedroom") == 2


@pytest.mark.parametrize(
    "text", ["a house with no more than two bedrooms", "a no-frills kitchen", "a house, not too big, with a kitchen"]
)
def test_no_false_negation(text):
    h = plan(text)
    ns = names(h)
    if "bedroom" in text:
        assert sum(r.type == "bedroom" for r in h.rooms) == 2
    else:
        assert any("kitchen" in n for n in ns)


# ------------------------------------------------------------------ control characters

HOSTILE = ["\x1b]0;pwned\x07", "\x1b[31m", "\x00", "\u202e", "\u2066", "\x9b", "\x7f", "\r\n"]
BAD = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def _strings(v):
    if isinstance(v, str):
        yield v
    elif isinstance(v, dict):
        for k, x in v.items():
            yield from _strings(k)
            yield from _strings(x)
    elif isinstance(v, (list, tuple)):
        for x in v:
            yield from _strings(x)


def test_control_characters_in_the_text_never_reach_the_plan():
    text = "a {0}bedroom with a {1}red{1} canopy bed, a {2}nul lamp and a {3}evil{4} flumph {5}{6}{7}".format(*HOSTILE[:8])
    h = plan(text)
    dumped = h.model_dump()
    assert not [s for s in _strings(dumped) if BAD.search(s.replace("\n", ""))]
    assert "pwned" not in json.dumps(dumped)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.sampled_from([*HOSTILE, "bed", " room ", "x", "é"]), min_size=1, max_size=8).map("".join))
def test_spec_models_clean_every_string(s):
    item = {"name": "bed" + s, "category": "bed" + s, "size_m": (1, 2, 0.5), "rule": "place_wall", "material": s,
            "description": s, "target": "x" + s, "params": {"wall": "longest"}}  # fmt: skip
    # (params are typed per rule now: a hostile string there is refused, see test_rule_registry)
    room = RoomSpec(
        id="r" + s, name="room" + s, type="bedroom", area_m2=10, style=s, materials={"floor": s},
        groups=[{"name": "g" + s, "anchor": item}], ornaments=[],
    )  # fmt: skip
    h = HouseSpec(prompt=s, style=s, palette=[s], rooms=[room], connections=[("r" + s, "outside")], warnings=[s],
                  provenance={"model": s})  # fmt: skip
    for v in _strings(h.model_dump()):
        assert not BAD.search(v.replace("\n", "")), repr(v)
    assert re.fullmatch(r"[A-Za-z0-9_][A-Za-z0-9_.:-]{0,127}", h.rooms[0].id)
    assert h.connections[0][0] == h.rooms[0].id


def test_assignment_is_cleaned_too():
    it = ItemSpec(name="bed", category="bed", size_m=(1, 2, 0.5), rule="place_wall")
    it.name = "bed\x1b[2J"
    assert it.name == "bed"


def test_a_name_of_only_control_characters_is_refused():
    with pytest.raises(ValueError):
        ItemSpec(name="\x1b[31m\x00", category="bed", size_m=(1, 2, 0.5), rule="place_wall")


# ------------------------------------------------------------------ the CLI end to end


@pytest.mark.parametrize("text", ["twelve bedrooms, each with 120 desks, 120 chairs, 120 lamps and 120 clocks"])
def test_crowded_prompt_generates_with_warnings(tmp_path, text):
    out = tmp_path / "h"
    r = subprocess.run(
        [sys.executable, "-m", "anyhome", "generate", text, "--out", str(out), "--no-glb"],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert r.returncode == 0, r.stderr[-2000:]
    house = json.loads((out / "house.json").read_text())
    assert len(house["objects"]) <= MAX_HOUSE_OBJECTS
    assert any("per room" in w for w in house["warnings"])


def test_very_long_names_give_ids_that_load():
    """A 300-letter room name and a 200-letter item name: every id stays in house.json's
    alphabet and length, so the house saves and loads (it crashed before the cap)."""
    import anyhome
    from anyhome.house import House

    text = "a " + "super" * 60 + "duper room with a " + "mega" * 50 + "lamp, and a bedroom"
    house = anyhome.generate(text, seed=0)
    assert all(len(o.id) <= 128 for o in house.objects)
    assert House.from_json(house.to_json()).rooms[0].id == house.rooms[0].id
