"""The offline planner: valid, deterministic, diverse plans; bad input handled."""

import json
import re

import numpy as np
import pytest
from public_prompts import PUBLIC_PROMPTS

from anyhome.errors import PlanError
from anyhome.house import ROOM_TYPES
from anyhome.plan import get_planner
from anyhome.plan.spec import MAX_ROOMS, HouseSpec

PUBLIC = [json.loads(line) for line in PUBLIC_PROMPTS.read_text().splitlines() if line.strip()]
TEXTS = [p["prompt"] for p in PUBLIC]


def plan(text, seed=0):
    return get_planner("offline").plan(text, np.random.default_rng(seed))


def _connected(h: HouseSpec) -> bool:
    adj = {r.id: set() for r in h.rooms}
    for a, b in h.connections:
        if b != "outside":
            adj[a].add(b)
            adj[b].add(a)
    seen, todo = set(), [h.entrance_room]
    while todo:
        r = todo.pop()
        if r not in seen:
            seen.add(r)
            todo.extend(adj[r])
    return seen == set(adj)


@pytest.mark.parametrize("text", TEXTS)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_public_prompts_plan_valid_houses(text, seed):
    h = plan(text, seed)
    HouseSpec.model_validate(h.model_dump())
    assert 1 <= len(h.rooms) <= MAX_ROOMS
    assert sum(b == "outside" for _, b in h.connections) == 1
    assert _connected(h)
    assert all(r.type in ROOM_TYPES for r in h.rooms)
    for r in h.rooms:
        assert set(r.materials) >= {"floor", "walls", "ceiling"}
        assert all(v or (k == "ceiling" and r.open_air) for k, v in r.materials.items())  # open air: no ceiling
        for o in r.ornaments:
            assert o.rule in ("place_top", "place_on_wall")


def _count(text, term):
    return sum(bool(re.search(rf"\b{re.escape(term)}(s|es)?\b", text)) for text in text)


def _objects(h):
    out = []
    for r in h.rooms:
        for g in r.groups:
            for it in [g.anchor, *g.members]:
                out += [f"{it.name} {it.category.replace('_', ' ')}"] * (it.count * g.repeat)
        for o in r.ornaments:
            out += [f"{o.name} {o.category.replace('_', ' ')}"] * o.count
    return out


def test_requested_counts_are_honoured():
    h = plan("A three-bedroom family home with an open kitchen, a dining room and two bathrooms.")
    names = [f"{r.name} {r.type.replace('_', ' ')}" for r in h.rooms]
    assert _count(names, "bedroom") == 3 and _count(names, "bathroom") == 2
    h = plan("A conference room with a long table and twelve chairs.")
    assert _count(_objects(h), "chair") == 12
    h = plan("A small office with four workstations and a meeting room.")
    assert _count(_objects(h), "workstation") == 4


def test_requested_groups_are_required_and_arranged():
    h = plan("A classroom with desks and chairs arranged in neat rows facing a whiteboard.")
    rows = [g for r in h.rooms for g in r.groups if g.arrangement == "rows"]
    assert rows and rows[0].anchor.category == "desk" and rows[0].repeat >= 8 and rows[0].required


def test_style_reaches_rooms_and_items():
    h = plan("A gothic living room with wooden furniture.")
    assert "gothic" in h.style
    assert any("wooden" in it.material for r in h.rooms for g in r.groups for it in [g.anchor, *g.members])


def test_same_seed_same_plan():
    for text in TEXTS[:10]:
        assert plan(text, 7).model_dump() == plan(text, 7).model_dump()


def test_different_seeds_differ():
    for text in ["A house.", "A cat cafe.", "A bedroom."]:
        dumps = {json.dumps(plan(text, s).model_dump(), sort_keys=True) for s in range(4)}
        assert len(dumps) > 1


def test_empty_text_raises():
    for text in ["", "   \n\t"]:
        with pytest.raises(PlanError):
            plan(text)


def test_absurd_counts_are_capped_with_warning():
    h = plan("a house with 200 bedrooms")
    assert len(h.rooms) <= MAX_ROOMS and h.warnings
    assert any("bedroom" in w for w in h.warnings)


@pytest.mark.parametrize(
    "text",
    ["qwxz plorb", "一个有三个卧室的房子", "Ein Haus mit drei Schlafzimmern", "a " * 5000, "bedroom " * 2000,
     "a house with no bathroom", "a house with 0 bedrooms and 99 kitchens"],
)
def test_odd_text_still_plans(text):
    h = plan(text)
    assert h.rooms and _connected(h)


def test_unrecognised_text_warns():
    assert plan("qwxz plorb").warnings


def test_long_text_ok():
    text = ("A cozy cottage with a reading nook and a fireplace. " * 200)[:10000]
    h = plan(text)
    assert h.rooms and any("characters" in w for w in h.warnings)


def test_degrees_are_modest():
    for text in TEXTS:
        h = plan(text)
        deg = {}
        for a, b in h.connections:
            for x in (a, b):
                deg[x] = deg.get(x, 0) + 1
        assert max(v for k, v in deg.items() if k != "outside") <= 7


def test_named_counts_survive_the_room_cap():
    spec = plan("A five-bedroom hacienda with a central courtyard, a tiled kitchen and four bathrooms.")
    types = [r.type for r in spec.rooms]
    assert len(spec.rooms) <= MAX_ROOMS
    assert types.count("bedroom") == 5 and types.count("bathroom") == 4


def test_counted_named_rooms_replace_the_programs_rooms_of_that_type():
    for seed in range(4):
        spec = plan("A clinic with two exam rooms and a waiting room.", seed)
        exam_type = next(r.type for r in spec.rooms if r.name == "exam room")
        assert sorted(r.name for r in spec.rooms if r.type == exam_type) == ["exam room", "exam room 2"]


def test_named_rooms_may_pass_a_types_usual_maximum():
    spec = plan("A music school with five practice rooms, each with an upright piano.")
    practice = [r for r in spec.rooms if "practice room" in r.name]
    assert len(practice) == 5
    assert all(any("piano" in it.name for g in r.groups for it in [g.anchor, *g.members]) for r in practice)


def test_rows_get_room_for_their_aisles():
    spec = plan("An office with twelve desks in two rows.")
    room = next(r for r in spec.rooms if any(g.anchor.name == "desk" and g.repeat == 12 for g in r.groups))
    assert room.area_m2 >= 12 * 1.4 * 0.7 * 3


def test_a_venue_main_room_takes_the_users_name_for_the_building():
    names = [r.name for r in plan("A sushi restaurant with a kitchen.").rooms]
    assert "sushi restaurant" in names


def test_plural_named_rooms_without_a_count_give_two():
    names = [r.name for r in plan("A minimalist Japanese home with tatami rooms.").rooms]
    assert sum("tatami room" in n for n in names) == 2


def test_a_named_room_in_a_small_household_is_kept():
    spec = plan("A house for a couple with twin toddlers: a master bedroom, a nursery with two cribs.")
    nursery = next(r for r in spec.rooms if r.name == "nursery")
    assert any("crib" in g.anchor.name for g in nursery.groups)


def test_many_tvs_hang_on_the_walls():
    spec = plan("A sports bar with twelve TVs along the walls.")
    tvs = [o for r in spec.rooms for o in r.ornaments if o.category == "tv"]
    assert sum(o.count for o in tvs) == 12 and all(o.rule == "place_on_wall" for o in tvs)


def test_a_modifier_does_not_remap_a_known_room():
    spec = plan("A day spa with a eucalyptus steam room.")
    room = next(r for r in spec.rooms if r.name == "eucalyptus steam room")
    assert not any(r.name == "steam room" for r in spec.rooms)
    assert any("sauna" in it.name or "bench" in it.name for g in room.groups for it in [g.anchor, *g.members])


def test_a_programs_room_word_is_read_as_the_building_reads_it():
    """"Three practice rooms" in a music conservatory are music rooms (the program's
    practice rooms), not yoga rooms, and no cap on gyms is reported."""
    h = plan("A music conservatory with a recital hall and three practice rooms, each with an upright piano.")
    practice = [r for r in h.rooms if r.name.startswith("practice room")]
    assert len(practice) == 3
    assert {r.type for r in practice} == {"studio"}
    assert all(any(g.anchor.name == "upright piano" for g in r.groups) for r in practice)
    assert not any("gym" in w for w in h.warnings)


def test_a_nook_is_small_whatever_it_reads_as():
    """"A meditation nook" is furnished as a meditation room but drawn at a nook's size."""
    from anyhome.plan.knowledge import knowledge_base
    from anyhome.plan.parse import parse
    from anyhome.plan.program import plan_rooms

    kb = knowledge_base()
    parsed = parse("A one-bedroom apartment with a meditation nook.", kb)
    slots, _ = plan_rooms(kb, parsed, "apartment", np.random.default_rng(0), [])
    nook = next(s for s in slots if s.name == "meditation nook")
    assert nook.furnish == "meditation_room"
    assert nook.area_range == tuple(kb.raw("rooms")["small_heads"]["nook"])


def test_a_music_schools_practice_rooms_hold_an_instrument_stand_and_chair():
    """A practice room is furnished for practice (the piano, a music stand with its chair,
    a sheet-music shelf), not as a lounge."""
    h = plan("A music school with three practice rooms.")
    practice = [r for r in h.rooms if r.name.startswith("practice room")]
    assert len(practice) == 3
    for r in practice:
        names = {g.anchor.name for g in r.groups}
        assert {"music stand", "sheet music shelf"} <= names
        assert any(g.anchor.category == "piano" for g in r.groups)
        assert "sofa" not in names


def test_a_second_item_of_one_category_keeps_the_first_ones_count():
    """"24 student desks ... and a teacher's desk at the front": the teacher's desk is its
    own group (it had set the student desks back to one), and "the front" is no object."""
    h = plan("A classroom with 24 student desks in rows facing a whiteboard and a teacher's desk at the front.", seed=11)
    groups = {g.anchor.name: g for r in h.rooms for g in r.groups}
    assert groups["student desk"].repeat == 24 and groups["student desk"].arrangement == "rows"
    assert groups["teacher's desk"].repeat == 1
    assert "front" not in groups
