"""The relation checker says "met" for a right placement and "not met" for a wrong one, per kind."""

from __future__ import annotations

import math

import pytest

from anyhome.evaluate import relations as rel
from anyhome.house import HouseObject
from anyhome.plan.spec import GroupSpec, ItemSpec

ROOM = [(0.0, 0.0), (6.0, 0.0), (6.0, 5.0), (0.0, 5.0)]
"""A 6 x 5 m room: walls at x = 0, x = 6, y = 0, y = 5."""
NORTH_WALL_YAW = math.pi
"""Yaw of an object with its back on the north wall (y = 5), facing south."""


def obj(oid, name, xy, size, yaw=0.0, anchor="a", group="g-0", rule="place_center", z=0.0, support="floor"):
    return HouseObject(id=oid, room="r1", name=name, category=name, position=(xy[0], xy[1], z), size=size,
                       yaw=yaw, group=group, anchor=anchor, rule=rule, support=support)


def item(name, rule, size=(0.5, 0.5, 0.5), **kw):
    return ItemSpec(name=name, category=name, size_m=size, rule=rule, **kw)


SOFA = obj("a", "sofa", (3.0, 0.45), (2.0, 0.9, 0.85), anchor=None, rule="place_wall")
"""A sofa with its back on the south wall, facing north (+y)."""


def kinds(group, objects, kind):
    return [r for r in rel.room_relations([group], objects, ROOM) if r.kind == kind]


def sofa_group(*members):
    return GroupSpec(name="g", anchor=item("sofa", "place_wall", (2.0, 0.9, 0.85)), members=list(members))


@pytest.mark.parametrize("xy,yaw,met", [
    ((3.0, 1.6), math.pi, True),   # 0.4 m ahead, centred, facing the sofa
    ((3.0, 3.6), math.pi, False),  # far beyond distance_m
    ((5.0, 1.6), math.pi, False),  # off to the side of the sofa
    ((3.0, -0.5), math.pi, False),  # behind it
])
def test_front(xy, yaw, met):
    g = sofa_group(item("coffee table", "place_front", (1.0, 0.5, 0.4), params={"distance_m": 0.4}))
    table = obj("t", "coffee table", xy, (1.0, 0.5, 0.4), yaw)
    got = kinds(g, [SOFA, table], rel.FRONT)
    assert len(got) == 1 and got[0].met is met


def test_front_to_wall_needs_the_wall_ahead():
    g = sofa_group(item("tv stand", "place_front", (1.6, 0.45, 0.5), params={"distance_m": 2.0, "to_wall": True}))
    on_wall = obj("t", "tv stand", (3.0, 5.0 - 0.225), (1.6, 0.45, 0.5), NORTH_WALL_YAW)
    mid_room = obj("t", "tv stand", (3.0, 3.5), (1.6, 0.45, 0.5), NORTH_WALL_YAW)
    assert kinds(g, [SOFA, on_wall], rel.FRONT)[0].met
    assert not kinds(g, [SOFA, mid_room], rel.FRONT)[0].met


@pytest.mark.parametrize("yaw,met", [(math.pi, True), (math.pi - math.radians(30), True),
                                     (math.pi / 2, False), (0.0, False)])
def test_facing(yaw, met):
    g = sofa_group(item("coffee table", "place_front", (1.0, 0.5, 0.4), params={"distance_m": 0.4}))
    table = obj("t", "coffee table", (3.0, 1.6), (1.0, 0.5, 0.4), yaw)
    assert kinds(g, [SOFA, table], rel.FACING)[0].met is met


@pytest.mark.parametrize("x,met", [(3.0, True), (3.08, True), (3.4, False)])
def test_aligned_front(x, met):
    g = sofa_group(item("coffee table", "place_front", (1.0, 0.5, 0.4), params={"distance_m": 0.4}))
    table = obj("t", "coffee table", (x, 1.6), (1.0, 0.5, 0.4), math.pi)
    assert kinds(g, [SOFA, table], rel.ALIGNED)[0].met is met


@pytest.mark.parametrize("x,met", [(3.0, True), (3.6, False)])
def test_aligned_wall_item_over_its_target(x, met):
    g = sofa_group(item("painting", "place_on_wall", (0.9, 0.04, 0.6)))
    painting = obj("p", "painting", (x, 0.02), (0.9, 0.04, 0.6), 0.0, z=1.4, support="wall")
    assert kinds(g, [SOFA, painting], rel.ALIGNED)[0].met is met


@pytest.mark.parametrize("x,met", [(1.2, True), (2.4, True), (3.3, False), (0.2, False)])
def test_wall_cabinets_lie_over_the_counter_run_not_centred_on_a_piece(x, met):
    """Two counters (0.6 m, side by side from x = 0.9 to 2.7) and wall cabinets over them:
    a cabinet is aligned when its span lies over the run, wherever along it."""
    run = GroupSpec(name="k", anchor=item("counter", "place_wall", (0.6, 0.6, 0.9)),
                    members=[item("counter", "place_next_wall", (0.6, 0.6, 0.9)),
                             item("wall cabinet", "place_on_wall", (0.6, 0.35, 0.7), target="counter", count=2)])
    c1 = obj("a", "counter", (1.2, 0.3), (0.6, 0.6, 0.9), anchor=None, group="k-0", rule="place_wall")
    c2 = obj("c2", "counter", (1.8, 0.3), (0.6, 0.6, 0.9), group="k-0", rule="place_next_wall")
    c3 = obj("c3", "counter", (2.4, 0.3), (0.6, 0.6, 0.9), group="k-0", rule="place_next_wall")
    cab = [obj("w1", "wall cabinet", (x, 0.175), (0.6, 0.35, 0.7), group="k-0", z=1.45, support="wall"),
           obj("w2", "wall cabinet", (1.8, 0.175), (0.6, 0.35, 0.7), group="k-0", z=1.45, support="wall")]
    got = {r.item: r.met for r in rel.room_relations([run], [c1, c2, c3, *cab], ROOM) if r.kind == rel.ALIGNED}
    assert got["w1"] is met and got["w2"] is True


def test_rows_of_anchors_state_no_run():
    """Beds set out in rows (a nap room) are placed by the arrangement, not as a run along a wall."""
    g = GroupSpec(name="n", anchor=item("cot", "place_next_wall", (0.7, 1.4, 0.35)), arrangement="rows", repeat=3)
    cots = [obj(f"c{i}", "cot", (1.0 + 1.5 * i, 2.5), (0.7, 1.4, 0.35), anchor=None, group=f"n-{i}") for i in range(3)]
    assert rel.room_relations([g], cots, ROOM) == []


@pytest.mark.parametrize("xy,yaw,side,met", [
    ((4.3, 0.25), 0.0, "right", True),    # right of the sofa, backs aligned
    ((1.7, 0.25), 0.0, "left", True),
    ((1.7, 0.25), 0.0, "right", False),   # wrong side
    ((4.9, 0.25), 0.0, "right", False),   # too far off
    ((4.3, 1.25), 0.0, "right", False),   # backs not aligned
    ((4.3, 0.25), math.pi, "right", False),  # facing the other way
])
def test_beside(xy, yaw, side, met):
    g = sofa_group(item("side table", "place_beside", params={"side": side}))
    t = obj("s", "side table", xy, (0.5, 0.5, 0.5), yaw)
    assert kinds(g, [SOFA, t], rel.BESIDE)[0].met is met


@pytest.mark.parametrize("x_left,x_right,met", [(1.7, 4.3, True), (1.5, 4.3, False), (1.7, 4.9, False)])
def test_symmetric_pair(x_left, x_right, met):
    g = sofa_group(item("side table", "place_beside", count=2))
    a = obj("s0", "side table", (x_left, 0.25), (0.5, 0.5, 0.5))
    b = obj("s1", "side table", (x_right, 0.25), (0.5, 0.5, 0.5))
    got = kinds(g, [SOFA, a, b], rel.SYMMETRIC)
    assert len(got) == 1 and got[0].met is met


def test_symmetric_pair_needs_both_sides():
    g = sofa_group(item("side table", "place_beside", count=2))
    a = obj("s0", "side table", (4.3, 0.25), (0.5, 0.5, 0.5))
    b = obj("s1", "side table", (4.9, 0.25), (0.5, 0.5, 0.5))
    assert not kinds(g, [SOFA, a, b], rel.SYMMETRIC)[0].met


TABLE = obj("a", "table", (3.0, 2.5), (1.6, 0.9, 0.75), anchor=None)


@pytest.mark.parametrize("xy,yaw,met", [
    ((3.0, 3.25), math.pi, True),       # north side, facing the table
    ((3.0, 1.75), 0.0, True),           # south side
    ((4.1, 2.5), math.pi / 2, True),    # east end, facing west
    ((3.0, 3.25), 0.0, False),          # facing away
    ((3.0, 3.9), math.pi, False),       # too far out
    ((4.2, 3.3), math.pi, False),       # off the corner
])
def test_around(xy, yaw, met):
    g = GroupSpec(name="g", anchor=item("table", "place_center", (1.6, 0.9, 0.75)),
                  members=[item("chair", "place_around", (0.45, 0.5, 0.9))])
    chair = obj("c", "chair", xy, (0.45, 0.5, 0.9), yaw)
    assert kinds(g, [TABLE, chair], rel.AROUND)[0].met is met


@pytest.mark.parametrize("xy,met", [((5.75, 2.5), True), ((2.0, 1.0), False)])
def test_far(xy, met):
    g = GroupSpec(name="g", anchor=item("table", "place_center", (1.6, 0.9, 0.75)),
                  members=[item("bin", "place_wall", params={"far_m": 1.5})])
    b = obj("b", "bin", xy, (0.5, 0.5, 0.5), -math.pi / 2 if xy[0] > 3 else math.pi / 2)
    assert kinds(g, [TABLE, b], rel.FAR)[0].met is met


@pytest.mark.parametrize("xy,yaw,met", [
    ((3.0, 0.25), 0.0, True),          # on the south wall, straight below the table
    ((5.75, 0.6), -math.pi / 2, False),  # on a wall, but far round the room
    ((3.0, 1.2), 0.0, False),           # near, but off the wall
])
def test_near_a_free_standing_target_against_a_wall(xy, yaw, met):
    table = obj("a", "table", (3.0, 1.8), (1.6, 0.9, 0.75), anchor=None)
    g = GroupSpec(name="g", anchor=item("table", "place_center", (1.6, 0.9, 0.75)),
                  members=[item("sideboard", "place_next_wall", (1.4, 0.45, 0.85))])
    s = obj("s", "sideboard", xy, (1.4, 0.45, 0.85), yaw)
    assert kinds(g, [table, s], rel.NEAR)[0].met is met


@pytest.mark.parametrize("x2,met", [(1.6, True), (2.5, False)])
def test_near_copies(x2, met):
    g = GroupSpec(name="g", anchor=item("easel", "place_next"), repeat=2)
    a = obj("e0", "easel", (1.0, 2.0), (0.5, 0.5, 1.5), anchor=None, group="g-0")
    b = obj("e1", "easel", (x2, 2.0), (0.5, 0.5, 1.5), anchor=None, group="g-1")
    assert all(r.met is met for r in kinds(g, [a, b], rel.NEAR))


@pytest.mark.parametrize("x2,met", [(1.85, True), (3.5, False)])
def test_run_continues_along_the_wall(x2, met):
    g = GroupSpec(name="g", anchor=item("shelf", "place_next_wall", (0.9, 0.35, 1.9)), repeat=2)
    a = obj("s0", "shelf", (0.95, 0.175), (0.9, 0.35, 1.9), anchor=None, group="g-0")
    b = obj("s1", "shelf", (x2, 0.175), (0.9, 0.35, 1.9), anchor=None, group="g-1")
    got = kinds(g, [a, b], rel.RUN)
    assert len(got) == 1 and got[0].met is met


def test_run_piece_off_the_wall_is_not_met():
    g = GroupSpec(name="g", anchor=item("counter", "place_wall", (1.2, 0.6, 0.9)),
                  members=[item("stove", "place_next_wall", (0.6, 0.6, 0.9))])
    counter = obj("c", "counter", (3.0, 0.3), (1.2, 0.6, 0.9), anchor=None, rule="place_wall")
    on = obj("s", "stove", (3.9, 0.3), (0.6, 0.6, 0.9), rule="place_next_wall", anchor="c")
    off = obj("s", "stove", (3.9, 1.0), (0.6, 0.6, 0.9), rule="place_next_wall", anchor="c")
    assert kinds(g, [counter, on], rel.RUN)[0].met
    assert not kinds(g, [counter, off], rel.RUN)[0].met


def test_unplaced_target_states_nothing():
    g = sofa_group(item("coffee table", "place_front", (1.0, 0.5, 0.4)))
    table = obj("t", "coffee table", (3.0, 1.6), (1.0, 0.5, 0.4), math.pi)
    assert rel.room_relations([g], [table], ROOM) == []


def test_a_generated_house_reports_the_relations_its_plan_states():
    from anyhome.evaluate.furnish_metrics import furnish_metrics
    from anyhome.pipeline import generate

    house = generate("a bedroom with a double bed, two nightstands and a desk", seed=0)
    got = rel.house_relations(house)
    assert got, "a bed with nightstands states relations"
    assert {r.kind for r in got} >= {rel.BESIDE}
    per_room = []
    for room in house.rooms:
        spec = next(r for r in house.plan["rooms"] if r["id"] == room.id)
        groups = [GroupSpec.model_validate(g) for g in spec["groups"]]
        per_room += rel.room_relations(groups, [o for o in house.objects if o.room == room.id], room.polygon)
    assert got == per_room
    m = furnish_metrics(house)
    assert m.relations == {k: list(v) for k, v in rel.met_by_kind(got).items()}
    assert any(line.strip().startswith("relations met") for line in m.summary_lines())
