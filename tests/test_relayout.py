"""relayout: some rooms of an existing house laid out again, every other room kept."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import anyhome
from anyhome.errors import AnyHomeError
from anyhome.evaluate import evaluate_house
from anyhome.house import House

TEXT = "A two-bedroom apartment with a kitchen, a living room with a sofa and a dining table."


@pytest.fixture(scope="module")
def house() -> House:
    return anyhome.generate(TEXT, seed=0)


def _objects(h: House, rooms: set[str], inside: bool) -> list[str]:
    """The house.json text of the objects in (or outside) ``rooms``, in order."""
    data = json.loads(h.to_json())
    return [json.dumps(o, sort_keys=True) for o in data["objects"] if (o["room"] in rooms) == inside]


def _check(before: House, after: House, rooms: set[str]) -> None:
    assert _objects(after, rooms, inside=False) == _objects(before, rooms, inside=False)
    ids = [o.id for o in after.objects]
    assert len(ids) == len(set(ids))
    report = evaluate_house(after)
    assert report.ok, report.violations
    kept_dropped = [d for d in before.dropped if d.room not in rooms]
    assert [d for d in after.dropped if d.room not in rooms] == kept_dropped
    for key in ("rooms", "doors", "windows", "connections", "plan", "prompt", "style", "warnings"):
        assert getattr(after, key) == getattr(before, key), key


def test_one_room_again_keeps_every_other_room_byte_identical(house: House) -> None:
    before = house.to_json()
    room = max(house.rooms, key=lambda r: len(house.objects_in(r.id))).id
    again = anyhome.relayout(house, [room], seed=7)
    assert house.to_json() == before  # the input is not modified
    _check(house, again, {room})
    assert _objects(again, {room}, inside=True) != _objects(house, {room}, inside=True)
    assert again.objects_in(room)
    assert set(again.timings_s) == {"layout", "refine", "assets"}


def test_every_room_with_the_house_seed_gives_the_house_back(house: House) -> None:
    assert anyhome.relayout(house, seed=house.seed).to_json() == house.to_json()
    assert anyhome.relayout(house, [r.id for r in house.rooms], seed=house.seed).to_json() == house.to_json()


def test_a_saved_and_loaded_house(house: House, tmp_path) -> None:
    house.save(tmp_path)
    loaded = anyhome.load(tmp_path)
    room = house.rooms[0].id
    _check(loaded, anyhome.relayout(loaded, room, seed=3), {room})  # one id as a string


@settings(max_examples=8, deadline=None)
@given(data=st.data(), seed=st.integers(0, 2**32 - 1))
def test_any_rooms_any_seed(house: House, data, seed: int) -> None:
    rooms = data.draw(st.sets(st.sampled_from([r.id for r in house.rooms]), min_size=1))
    _check(house, anyhome.relayout(house, sorted(rooms), seed=seed), rooms)


def test_new_ids_never_clash_with_kept_ones(house: House) -> None:
    """A hand-edited house whose other room holds an id the relaid room will make again."""
    room = max(house.rooms, key=lambda r: len(house.objects_in(r.id))).id
    other = next(r.id for r in house.rooms if r.id != room and house.objects_in(r.id))
    taken = house.objects_in(room)[0].id
    data = json.loads(house.to_json())
    victim = next(o for o in data["objects"] if o["room"] == other and o["support"] == "floor"
                  and not any(o["id"] in (x["support"], x["anchor"]) for x in data["objects"]))
    for o in data["objects"]:
        if o["id"] == taken:
            o["id"] = f"{taken}-old"
            for x in data["objects"]:
                x["support"] = f"{taken}-old" if x["support"] == taken else x["support"]
                x["anchor"] = f"{taken}-old" if x["anchor"] == taken else x["anchor"]
    victim["id"] = taken
    edited = House.model_validate(data)
    again = anyhome.relayout(edited, [room], seed=edited.seed)
    _check(edited, again, {room})
    assert again.object(taken).room == other
    mine = {o.id for o in again.objects_in(room)}
    assert f"{taken}-1" in mine  # the same layout as before, the clashing id renamed
    for o in again.objects_in(room):
        assert o.support in mine | {"floor", "wall"} and (o.anchor is None or o.anchor in mine)


@pytest.mark.parametrize("rooms", [["attic"], ["kitchen", "attic"], [3], "attic\x1b[31m"])
def test_an_unknown_room_is_one_line(house: House, rooms) -> None:
    with pytest.raises(AnyHomeError) as e:
        anyhome.relayout(house, rooms)
    msg = str(e.value)
    assert msg.startswith("unknown room ") and "\n" not in msg and "\x1b" not in msg
    assert "(rooms: " + ", ".join(r.id for r in house.rooms) + ")" in msg


def test_a_house_without_a_plan(house: House) -> None:
    with pytest.raises(AnyHomeError, match=r"holds no plan .*cannot be laid out again"):
        anyhome.relayout(house.model_copy(update={"plan": None}))


def test_a_room_missing_from_the_plan(house: House) -> None:
    plan = {**house.plan, "rooms": house.plan["rooms"][:-1],
            "connections": [c for c in house.plan["connections"] if house.plan["rooms"][-1]["id"] not in c]}
    gone = house.plan["rooms"][-1]["id"]
    with pytest.raises(AnyHomeError, match=f"room '{gone}' is not in the house's plan"):
        anyhome.relayout(house.model_copy(update={"plan": plan}), [gone])


def test_a_broken_plan_is_one_line(house: House) -> None:
    with pytest.raises(AnyHomeError, match=r"^the house's plan is not a valid plan: rooms: "):
        anyhome.relayout(house.model_copy(update={"plan": {**house.plan, "rooms": []}}))
