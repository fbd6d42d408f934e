"""Zones offered to rooms (anyhome.plan.furnish.zone_groups) and their place in the plan."""

from __future__ import annotations

import numpy as np

from anyhome.plan import get_planner
from anyhome.plan.furnish import ZONE_PRIORITY, furnish_room, zone_groups
from anyhome.plan.knowledge import knowledge_base


def test_zones_come_from_the_set_and_skip_what_the_room_has():
    kb = knowledge_base()
    rng = np.random.default_rng(0)
    groups, _, _ = furnish_room(kb, "living_room", "living_room", 30.0, rng)
    zones = zone_groups(kb, "living_room", "living_room", 30.0, groups, rng)
    offered = [e["group"] for e in kb.raw("furniture")["zones"]["living_room"]]
    have = {g["name"] for g in groups}
    assert [z["name"] for z in zones] == [k for k in offered if k not in have]
    assert all(z["fill"] and z["priority"] == ZONE_PRIORITY and not z["required"] for z in zones)


def test_a_type_without_zones_gets_none():
    kb = knowledge_base()
    assert zone_groups(kb, "bathroom", "bathroom", 40.0, [], np.random.default_rng(0)) == []


def test_planned_zones_are_fill_groups_after_the_rooms_own():
    spec = get_planner("offline").plan("a large living room with a sofa", np.random.default_rng(1))
    room = next(r for r in spec.rooms if r.type == "living_room")
    fill = [g for g in room.groups if g.fill]
    assert fill, [g.name for g in room.groups]
    assert all(not g.key for g in fill)
    assert max(g.priority for g in room.groups if not g.fill) < min(g.priority for g in fill)


def test_a_ruled_out_object_is_not_offered_as_a_zone():
    """'no armchairs': the conversation and reading corners (armchairs) are not offered."""
    spec = get_planner("offline").plan("a large living room with a sofa and no armchairs", np.random.default_rng(1))
    room = next(r for r in spec.rooms if r.type == "living_room")
    names = [it.name for g in room.groups for it in [g.anchor, *g.members]]
    assert not any("armchair" in n or "club chair" in n or "lounge chair" in n for n in names), names


def test_a_tv_asked_for_joins_the_sofa_group():
    """'a sofa and a TV': the TV stand goes with the lounge group (placed across from the
    sofa, which is posed so the wall ahead can take it), not as a group of its own."""
    for seed in range(6):
        spec = get_planner("offline").plan("a living room with a sofa and a big TV", np.random.default_rng(seed))
        room = next(r for r in spec.rooms if r.type == "living_room")
        assert "tv" not in [g.name for g in room.groups]
        lounge = next(g for g in room.groups if g.name == "lounge")
        stands = [m for m in lounge.members if m.category == "tv_stand"]
        assert len(stands) == 1
        assert stands[0].rule == "place_front" and stands[0].params.get("to_wall")
        assert stands[0].target in (None, lounge.anchor.name)


def test_join_groups_keeps_a_group_with_no_host():
    kb = knowledge_base()
    rng = np.random.default_rng(0)
    from anyhome.plan.furnish import build_group, group_def, join_groups

    tv = build_group(kb, group_def(kb, {"group": "tv"}), 12.0, rng)
    bed = build_group(kb, group_def(kb, {"group": "bed"}), 12.0, rng)
    groups = [bed, tv]
    join_groups(kb, groups)
    assert [g["name"] for g in groups] == ["bed", "tv"]
    lounge = build_group(kb, group_def(kb, {"group": "lounge", "members": [{}, {"prob": 0.0}]}), 12.0, rng)
    groups = [lounge, tv]
    join_groups(kb, groups)
    assert [g["name"] for g in groups] == ["lounge"]
    assert [m["target"] for m in lounge["members"] if m["category"] == "tv_stand"] == [lounge["anchor"]["name"]]


def test_a_set_listing_its_own_zones_gets_only_those():
    """A home cinema (type living_room) lists its own: no living-room reading corner; a
    prayer hall lists none; a set that lists nothing gets its type's."""
    kb = knowledge_base()
    rng = np.random.default_rng(0)
    cinema = {z["name"] for z in zone_groups(kb, "home_cinema", "living_room", 40.0, [], rng)}
    assert cinema and "reading_chair" not in cinema and "conversation" not in cinema
    assert zone_groups(kb, "prayer_hall", "hall", 80.0, [], rng) == []
    assert "pub" not in kb.raw("furniture")["zones"]
    assert {z["name"] for z in zone_groups(kb, "pub", "living_room", 40.0, [], rng)} == {
        z["name"] for z in zone_groups(kb, "living_room", "living_room", 40.0, [], rng)}


def test_a_room_is_planned_high_enough_for_what_it_holds():
    """A fire engine (2.5-2.7 m tall) gets a bay with headroom over it, whatever the
    garage's usual height."""
    from anyhome.plan.offline import HEADROOM_M

    for seed in range(3):
        spec = get_planner("offline").plan("a fire station with an apparatus bay for a fire engine",
                                           np.random.default_rng(seed))
        for r in spec.rooms:
            floor = [it for g in r.groups for it in [g.anchor, *g.members]
                     if it.rule not in ("place_top", "place_on_wall")]
            if not r.open_air and floor:
                assert r.height_m >= max(it.size_m[2] for it in floor) + HEADROOM_M - 1e-6, r.id


def test_three_barber_chairs_are_three_stations_each_chair_facing_its_own():
    from anyhome.pipeline import generate

    h = generate("a barbershop with three barber chairs", seed=0)
    chairs = [o for o in h.objects if o.category == "salon_chair"]
    stations = {o.id: o for o in h.objects if o.group and o.group.startswith("salon_station") and o.anchor is None}
    assert len(chairs) == 3 and len(stations) == 3
    for c in chairs:
        s = stations[c.anchor]
        face = np.array([-np.sin(c.yaw), np.cos(c.yaw)])
        to_station = np.subtract(s.position[:2], c.position[:2])
        assert face @ to_station / np.linalg.norm(to_station) > 0.9  # the chair faces its station and mirror


def test_an_island_asked_for_is_the_island_not_the_kitchen_runs_counter():
    """'a kitchen with an island': 'island' is a word for a counter, but the island template
    is named by it; the kitchen run keeps its counters, and the island is laid out after
    the run, across an aisle from it."""
    from anyhome.pipeline import generate

    for seed in range(3):
        spec = get_planner("offline").plan("a house with a kitchen with an island", np.random.default_rng(seed))
        kitchen = next(r for r in spec.rooms if r.type == "kitchen")
        names = {g.name: g for g in kitchen.groups}
        assert "island" in names and names["island"].required
        assert names["kitchen_run"].anchor.name != "island"
    h = generate("a house with a kitchen with an island", seed=0)
    kitchen = [o for o in h.objects if o.room.startswith("kitchen") and o.support == "floor"]
    groups = [o.group for o in kitchen]
    assert max(i for i, g in enumerate(groups) if g.startswith("kitchen_run")) < groups.index("island-0")


def test_a_runner_rug_is_planned_long_and_narrow():
    """'a runner rug in the hallway' (and 'a hall runner') is a runner, not an area rug of
    2.0 x 1.4 m that no 1.2 m hallway can hold."""
    for text in ("a house with a runner rug in the hallway", "a house with a hall runner in the hallway"):
        spec = get_planner("offline").plan(text, np.random.default_rng(0))
        rugs = [g.anchor for r in spec.rooms if r.type == "hallway" for g in r.groups if g.anchor.category == "rug"]
        assert rugs, text
        w, d = rugs[0].size_m[:2]
        assert max(w, d) >= 2 * min(w, d) and min(w, d) <= 0.9, (text, rugs[0].size_m)
