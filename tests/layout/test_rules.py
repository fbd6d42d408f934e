"""Each placement rule, alone in a simple room."""

from __future__ import annotations

import math

import numpy as np
import pytest
from shapely.geometry import Polygon

from anyhome.geometry import back_edge, footprint_polygon, on_boundary
from anyhome.layout import LayoutResult, layout_house

from .helpers import check_valid, front, group, house_spec, item, l_shape, rect, single_room

ROOM = rect(0, 0, 5, 4)


def run(groups, polygon=ROOM, seed=0, ornaments=None, **fp_kw):
    fp = single_room(polygon, **fp_kw)
    spec = house_spec({"r1": groups}, ornaments={"r1": ornaments or []})
    res = layout_house(spec, fp, np.random.default_rng(seed))
    assert isinstance(res, LayoutResult)
    assert check_valid(fp, res.objects) == []
    return fp, res


def named(res, name):
    return [o for o in res.objects if o.name == name]


def walls_touched(o, polygon, tol=0.011):
    poly = footprint_polygon(o.position, o.size, o.yaw)
    edges = Polygon(polygon).exterior
    n = 0
    pts = list(edges.coords)
    from shapely.geometry import LineString

    for a, b in zip(pts[:-1], pts[1:]):
        if LineString([a, b]).distance(poly) < tol and poly.intersection(LineString([a, b]).buffer(tol)).length > 0.05:
            n += 1
    return n


def faces(o, target):
    """o's front points towards target's centre (within 45 degrees)."""
    v = np.asarray(target.position[:2]) - np.asarray(o.position[:2])
    return float(front(o.yaw) @ v) / np.linalg.norm(v) > math.cos(math.pi / 4)


@pytest.mark.parametrize("seed", range(4))
def test_place_corner_touches_two_walls(seed):
    _, res = run([group("g", item("wardrobe", "wardrobe", (1.2, 0.6, 2.0), "place_corner"))], seed=seed)
    (o,) = res.objects
    assert o.rule == "place_corner"
    assert on_boundary(Polygon(ROOM), back_edge(o.position, o.size, o.yaw))
    assert walls_touched(o, ROOM) == 2


def test_place_wall_back_on_wall_facing_room():
    _, res = run([group("g", item("bed", "bed", (1.6, 2.0, 0.6), "place_wall"))])
    (o,) = res.objects
    assert on_boundary(Polygon(ROOM), back_edge(o.position, o.size, o.yaw))
    centre = np.array([2.5, 2.0])
    assert float(front(o.yaw) @ (centre - np.asarray(o.position[:2]))) > 0


def test_place_wall_longest():
    for seed in range(3):
        _, res = run([group("g", item("sofa", "sofa", (1.8, 0.9, 0.8), "place_wall", params={"wall": "longest"}))], seed=seed)
        (o,) = res.objects
        assert abs(math.cos(o.yaw)) > 0.99  # back on a 5 m (horizontal) wall


def test_place_next_wall_forms_a_run():
    counter = item("counter", "counter", (0.6, 0.6, 0.9), "place_wall")
    members = [item("sink", "sink", (0.8, 0.6, 0.9), "place_next_wall"),
               item("stove", "stove", (0.6, 0.6, 0.9), "place_next_wall")]
    _, res = run([group("kitchen", counter, members)])
    objs = {o.name: o for o in res.objects}
    assert set(objs) == {"counter", "sink", "stove"}
    for o in objs.values():
        assert on_boundary(Polygon(ROOM), back_edge(o.position, o.size, o.yaw))
    # sink touches the counter side by side
    a, b = objs["counter"], objs["sink"]
    gap = footprint_polygon(a.position, a.size, a.yaw).distance(footprint_polygon(b.position, b.size, b.yaw))
    assert gap < 0.05


def test_along_walls_runs():
    case = item("display case", "cabinet", (1.0, 0.5, 1.8), "place_wall")
    _, res = run([group("cases", case, arrangement="along_walls", repeat=4)], polygon=rect(0, 0, 7, 5),
                 door=((3.0, 0.0), (4.0, 0.0)))
    assert len(res.objects) == 4
    for o in res.objects:
        assert on_boundary(Polygon(rect(0, 0, 7, 5)), back_edge(o.position, o.size, o.yaw))


@pytest.mark.parametrize("seed", range(3))
def test_place_center_clear_of_walls(seed):
    _, res = run([group("g", item("table", "table", (1.2, 0.8, 0.75), "place_center"))], polygon=rect(0, 0, 6, 5), seed=seed)
    (o,) = res.objects
    poly = footprint_polygon(o.position, o.size, o.yaw)
    assert Polygon(rect(0, 0, 6, 5)).exterior.distance(poly) >= 0.39
    assert np.linalg.norm(np.asarray(o.position[:2]) - [3.0, 2.5]) < 1.5


def test_place_next_side_by_side_same_facing():
    anchor = item("table", "table", (1.0, 0.6, 0.75), "place_center")
    _, res = run([group("g", anchor, arrangement="free", repeat=1,
                        members=[item("bench", "bench", (1.0, 0.4, 0.45), "place_next", count=2)])],
                 polygon=rect(0, 0, 6, 5))
    b = named(res, "bench")
    assert len(b) == 2
    assert abs(math.cos(b[0].yaw - b[1].yaw) - 1) < 1e-6
    d = footprint_polygon(b[0].position, b[0].size, b[0].yaw).distance(
        footprint_polygon(b[1].position, b[1].size, b[1].yaw))
    assert d < 0.35


def test_place_beside_both_sides_backs_aligned():
    bed = item("bed", "bed", (1.6, 2.0, 0.6), "place_wall")
    ns = item("nightstand", "nightstand", (0.45, 0.4, 0.55), "place_beside", count=2)
    _, res = run([group("bed", bed, [ns])])
    b = named(res, "bed")[0]
    n = named(res, "nightstand")
    assert len(n) == 2
    r = np.array([math.cos(b.yaw), math.sin(b.yaw)])
    sides = sorted(np.sign((np.asarray(x.position[:2]) - b.position[:2]) @ r) for x in n)
    assert sides == [-1, 1]
    bb = back_edge(b.position, b.size, b.yaw).mean(0) @ front(b.yaw)
    for x in n:
        assert abs(back_edge(x.position, x.size, x.yaw).mean(0) @ front(x.yaw) - bb) < 1e-6
        assert abs(math.cos(x.yaw - b.yaw) - 1) < 1e-6


@pytest.mark.parametrize("count", [2, 4, 6])
def test_place_around_chairs_face_table(count):
    table = item("dining table", "table", (1.6, 0.9, 0.75), "place_center")
    chair = item("chair", "chair", (0.45, 0.5, 0.9), "place_around", count=count)
    _, res = run([group("dining", table, [chair])], polygon=rect(0, 0, 6, 5))
    t = named(res, "dining table")[0]
    chairs = named(res, "chair")
    assert len(chairs) == count
    for c in chairs:
        assert faces(c, t)
        assert c.anchor == t.id and c.group == "dining-0"


def test_place_front_chair_faces_desk():
    desk = item("desk", "desk", (1.2, 0.6, 0.75), "place_wall")
    chair = item("chair", "chair", (0.5, 0.5, 0.9), "place_front", params={"distance_m": 0.1})
    _, res = run([group("desk", desk, [chair])])
    d, c = named(res, "desk")[0], named(res, "chair")[0]
    assert faces(c, d)
    # in front of the desk
    assert float(front(d.yaw) @ (np.asarray(c.position[:2]) - d.position[:2])) > d.size[1] / 2


def test_sofa_faces_tv():
    sofa = item("sofa", "sofa", (2.0, 0.9, 0.85), "place_wall", params={"wall": "longest"})
    tv = item("tv stand", "tv_stand", (1.4, 0.45, 0.5), "place_front", params={"distance_m": 2.0})
    _, res = run([group("living", sofa, [tv])], polygon=rect(0, 0, 5, 4.5))
    s, t = named(res, "sofa")[0], named(res, "tv stand")[0]
    assert faces(s, t) and faces(t, s)


def test_place_top_z_equals_top():
    desk = item("desk", "desk", (1.2, 0.6, 0.75), "place_wall")
    lamp = item("lamp", "lamp", (0.3, 0.3, 0.5), "place_top")
    _, res = run([group("desk", desk, [lamp])])
    d, lp = named(res, "desk")[0], named(res, "lamp")[0]
    assert lp.support == d.id
    assert lp.position[2] == pytest.approx(d.position[2] + d.size[2])
    assert footprint_polygon(d.position, d.size, d.yaw).contains(footprint_polygon(lp.position, lp.size, lp.yaw))


def test_place_top_shrinks_or_drops():
    stand = item("nightstand", "nightstand", (0.4, 0.4, 0.55), "place_wall")
    big = item("big lamp", "lamp", (0.6, 0.5, 0.8), "place_top")
    huge = item("tv", "tv", (2.0, 0.5, 1.0), "place_top")
    _, res = run([group("g", stand, [big, huge])])
    lamp = named(res, "big lamp")[0]
    assert lamp.size[0] < 0.6 and lamp.size[0] / lamp.size[2] == pytest.approx(0.6 / 0.8)
    assert [d.name for d in res.dropped] == ["tv"]


def test_place_on_wall_not_over_door_or_window():
    door = ((1.0, 0.0), (2.0, 0.0))
    windows = [((5.0, 1.0), (5.0, 3.0)), ((0.0, 0.5), (0.0, 3.5))]
    art = item("painting", "painting", (1.0, 0.04, 0.7), "place_on_wall")
    orn = [item("clock", "clock", (0.4, 0.05, 0.4), "place_on_wall", count=3)]
    for seed in range(5):
        _, res = run([group("art", art)], door=door, windows=windows, ornaments=orn, seed=seed)
        assert len(res.objects) == 4
        for o in res.objects:
            assert o.support == "wall"
            assert o.position[2] + o.size[2] <= 2.7 - 0.05 + 1e-9
            be = back_edge(o.position, o.size, o.yaw)
            # never over the door span of the south wall
            if np.all(np.abs(be[:, 1]) < 1e-6):
                assert be[:, 0].max() <= 1.0 or be[:, 0].min() >= 2.0


def test_place_on_wall_behind_target():
    bed = item("bed", "bed", (1.6, 2.0, 0.6), "place_wall")
    art = item("painting", "painting", (1.0, 0.04, 0.6), "place_on_wall")
    _, res = run([group("bed", bed, [art])])
    b, p = named(res, "bed")[0], named(res, "painting")[0]
    assert abs(math.cos(b.yaw - p.yaw) - 1) < 1e-6
    assert np.linalg.norm(back_edge(b.position, b.size, b.yaw).mean(0) - back_edge(p.position, p.size, p.yaw).mean(0)) < 0.5
    assert p.position[2] >= b.size[2]


def test_rows_arrangement_two_rows_facing_board():
    board = item("whiteboard", "whiteboard", (2.0, 0.05, 1.0), "place_on_wall", params={"elevation_m": 0.9})
    desk = item("desk", "desk", (1.0, 0.5, 0.75), "place_center")
    chair = item("chair", "chair", (0.45, 0.45, 0.85), "place_front", params={"distance_m": 0.1})
    fp, res = run([group("board", board), group("desks", desk, [chair], arrangement="rows", repeat=8, priority=1)],
                  polygon=rect(0, 0, 8, 7), door=((0.5, 0.0), (1.4, 0.0)))
    desks, chairs = named(res, "desk"), named(res, "chair")
    assert len(desks) == 8 and len(chairs) == 8
    b = named(res, "whiteboard")[0]
    nb = front(b.yaw)  # into the room
    rows = {round(float(np.asarray(d.position[:2]) @ nb), 2) for d in desks}
    assert len(rows) >= 2
    assert len({round(d.yaw, 6) for d in desks}) == 1
    for c in chairs:  # students look at the board
        assert float(front(c.yaw) @ nb) < -0.99


def test_l_shaped_room_valid():
    poly = l_shape(6, 5, 2.5, 2)
    groups = [
        group("bed", item("bed", "bed", (1.6, 2.0, 0.6), "place_wall"),
              [item("nightstand", "nightstand", (0.45, 0.4, 0.55), "place_beside", count=2)]),
        group("desk", item("desk", "desk", (1.2, 0.6, 0.75), "place_corner"),
              [item("chair", "chair", (0.5, 0.5, 0.9), "place_front")]),
        group("table", item("table", "table", (1.0, 1.0, 0.75), "place_center"),
              [item("stool", "stool", (0.4, 0.4, 0.45), "place_around", count=4)]),
    ]
    for seed in range(3):
        _, res = run(groups, polygon=poly, seed=seed)
        assert len(res.objects) >= 8


def test_oversize_is_dropped_with_reason():
    groups = [
        group("huge", item("pool table", "table", (6.0, 5.0, 0.8), "place_center"),
              [item("cue rack", "rack", (0.5, 0.1, 1.0), "place_on_wall")]),
        group("tall", item("tower", "shelf", (0.5, 0.5, 3.5), "place_wall")),
    ]
    _, res = run(groups)
    assert res.objects == []
    reasons = {d.name: d.reason for d in res.dropped}
    assert "larger" in reasons["pool table"]
    assert "taller" in reasons["tower"]
    assert "anchor" in reasons["cue rack"]


def test_ornaments_on_surfaces_and_walls():
    groups = [group("desk", item("desk", "desk", (1.2, 0.6, 0.75), "place_wall")),
              group("shelf", item("bookshelf", "shelf", (0.8, 0.35, 1.0), "place_wall"))]
    orn = [item("vase", "vase", (0.15, 0.15, 0.3), "place_top", count=2),
           item("book stack", "books", (0.2, 0.15, 0.1), "place_top", target="bookshelf"),
           item("poster", "poster", (0.6, 0.02, 0.8), "place_on_wall")]
    _, res = run(groups, ornaments=orn)
    by = {o.name: o for o in res.objects}
    assert by["book stack"].support == by["bookshelf"].id
    assert named(res, "vase")[0].support in {by["desk"].id, by["bookshelf"].id}
    assert by["poster"].support == "wall" and by["poster"].group is None and by["poster"].anchor is None


def test_doors_kept_clear_and_ids_readable():
    groups = [group("g", item("cabinet", "cabinet", (0.8, 0.5, 1.2), "place_wall"), repeat=6)]
    fp, res = run(groups, door=((0.0, 1.0), (0.0, 2.0)))
    ids = [o.id for o in res.objects]
    assert len(set(ids)) == len(ids)
    assert all(i.startswith("r1-cabinet-") for i in ids)


def _gap(a, b):
    return footprint_polygon(a.position, a.size, a.yaw).distance(footprint_polygon(b.position, b.size, b.yaw))


@pytest.mark.parametrize("seed", range(4))
def test_far_m_keeps_away_from_its_target(seed):
    room = rect(0, 0, 7, 4)
    tree = item("cat tree", "cat_tree", (0.6, 0.6, 1.5), "place_corner")
    box = item("litter box", "box", (0.5, 0.4, 0.4), "place_wall", params={"far_m": 4.0})
    _, res = run([group("pets", tree, [box])], polygon=room, seed=seed, door=((3.0, 0.0), (3.9, 0.0)))
    assert _gap(named(res, "cat tree")[0], named(res, "litter box")[0]) >= 4.0 - 0.01


def test_far_m_out_of_reach_is_relaxed_not_dropped():
    tree = item("cat tree", "cat_tree", (0.6, 0.6, 1.5), "place_corner")
    box = item("litter box", "box", (0.5, 0.4, 0.4), "place_center", params={"far_m": 30.0})
    _, res = run([group("pets", tree, [box])])
    assert not res.dropped
    # the furthest free pose: well beyond half the room's length
    assert _gap(named(res, "cat tree")[0], named(res, "litter box")[0]) > 2.5


@pytest.mark.parametrize("seed", range(6))
def test_place_next_wall_near_a_free_standing_target(seed):
    from anyhome.evaluate.relations import NEAR, room_relations

    room = rect(0, 0, 9, 4)
    table = item("dining table", "table", (1.6, 0.9, 0.75), "place_center")
    g = group("dining", table, [item("sideboard", "cabinet", (1.4, 0.45, 0.85), "place_next_wall")])
    _, res = run([g], polygon=room, seed=seed, door=((0.5, 0.0), (1.4, 0.0)))
    near = [r for r in room_relations([g], res.objects, room) if r.kind == NEAR]
    assert len(near) == 1 and near[0].met, near


def test_place_next_wall_keeps_to_its_wall_past_an_inner_corner():
    from anyhome.layout.rules.place_next_wall import place_next_wall
    from anyhome.layout.state import RoomState
    from anyhome.plan.spec import RoomSpec

    poly = l_shape(6.5, 4.5, 3.1, 2.2)  # inner corner at (3.4, 2.3)
    fp = single_room(poly)
    st = RoomState(fp, fp.rooms[0], RoomSpec(id="r1", name="r", type="other", area_m2=20.0),
                   np.random.default_rng(0), __import__("anyhome.layout.options", fromlist=["x"]).DEFAULT_OPTIONS)
    size = (0.9, 0.35, 1.9)
    # a bookcase with its back on the wall y = 2.3, its left side at the inner corner
    prev = res_obj("bookcase", (3.85, 2.3 - 0.175), size, math.pi)
    c = place_next_wall(st.space, size, prev)
    assert len(c)
    for xy, yaw in zip(c.xy, c.yaw):
        assert on_boundary(Polygon(poly), back_edge((xy[0], xy[1], 0.0), size, yaw))


def res_obj(name, xy, size, yaw):
    from anyhome.house import HouseObject

    return HouseObject(id=name, room="r1", name=name, category=name, position=(xy[0], xy[1], 0.0), size=size, yaw=yaw)


def test_place_beside_relaxed_to_a_wall_rather_than_dropped():
    room = rect(0, 0, 1.8, 4.5)  # the bed fills the short wall: no side is free
    bed = item("bed", "bed", (1.6, 2.0, 0.6), "place_wall")
    stand = item("nightstand", "nightstand", (0.45, 0.4, 0.55), "place_beside", count=2)
    _, res = run([group("bed", bed, [stand])], polygon=room, door=((0.45, 0.0), (1.35, 0.0)))
    b = named(res, "bed")[0]
    stands = named(res, "nightstand")
    assert len(stands) == 2 and not res.dropped
    for s in stands:
        assert on_boundary(Polygon(room), back_edge(s.position, s.size, s.yaw))
        assert _gap(s, b) <= 1.5 + 0.01


def test_run_of_anchors_continues_rather_than_jumps():
    from anyhome.evaluate.relations import RUN, room_relations

    room = rect(0, 0, 6, 5)
    g = group("shelves", item("bookcase", "shelf", (0.9, 0.35, 1.9), "place_next_wall"), repeat=4)
    for seed in range(4):
        _, res = run([g], polygon=room, seed=seed, door=((2.5, 0.0), (3.4, 0.0)))
        runs = [r for r in room_relations([g], res.objects, room) if r.kind == RUN]
        assert len(runs) == 3 and all(r.met for r in runs), (seed, runs)


def test_footprint_gaps_match_shapely():
    import shapely

    from anyhome.layout.rules.base import HALF_PI, footprint_gaps
    from anyhome.space import rect_corners

    rng = np.random.default_rng(0)
    for t in range(60):
        turn = 0.0 if t % 3 else float(rng.uniform(-1, 1))  # some refs not axis-aligned
        ref = res_obj("ref", (rng.uniform(0, 5), rng.uniform(0, 5)), (rng.uniform(0.2, 2), rng.uniform(0.2, 2), 1.0),
                      float(rng.integers(-2, 3)) * HALF_PI + turn)
        xy = rng.uniform(0, 6, (40, 2))
        yaw = rng.integers(-2, 3, 40) * HALF_PI + np.where(rng.random(40) < 0.2, rng.uniform(-1, 1, 40), 0.0)
        size = (rng.uniform(0.2, 2), rng.uniform(0.2, 2), 1.0)
        want = shapely.distance(shapely.polygons(rect_corners(xy, size[:2], yaw)),
                                footprint_polygon(ref.position, ref.size, ref.yaw))
        assert np.allclose(footprint_gaps(xy, size, yaw, ref), want, atol=1e-9)


def test_run_jumps_count_every_piece_cut_off_from_the_start():
    from anyhome.layout.rules.place_next_wall import jumps

    first = res_obj("a", (0.45, 0.175), (0.9, 0.35, 1.9), 0.0)
    joined = res_obj("b", (1.35, 0.175), (0.9, 0.35, 1.9), 0.0)
    far = res_obj("c", (4.45, 0.175), (0.9, 0.35, 1.9), 0.0)
    next_to_far = res_obj("d", (5.35, 0.175), (0.9, 0.35, 1.9), 0.0)
    assert jumps([first, joined]) == 0
    # the run jumped once, but two pieces stand apart from its start (as the benchmark judges)
    assert jumps([first, joined, far, next_to_far]) == 2


def test_place_wall_poses_are_shared_and_read_only():
    from anyhome.layout.rules.place_wall import place_wall
    from anyhome.space import RoomSpace

    fp = single_room(rect(0, 0, 4, 3))
    space = RoomSpace(fp, fp.rooms[0])
    a = place_wall(space, (0.9, 0.35, 1.9))
    b = place_wall(space, (0.9, 0.35, 1.9))
    assert a is not b and a.xy is b.xy  # one set of arrays, a new Cands per call
    with pytest.raises(ValueError):
        a.pref[0] = 5.0
    a.pref = a.pref + 1.0  # a caller changing preferences makes its own array
    assert np.array_equal(place_wall(space, (0.9, 0.35, 1.9)).pref, b.pref)
    other = RoomSpace(single_room(rect(0, 0, 6, 3)), single_room(rect(0, 0, 6, 3)).rooms[0])
    assert len(place_wall(other, (0.9, 0.35, 1.9))) > len(a)  # per room


def test_place_beside_side_and_pair():
    from anyhome.layout.rules.place_beside import pair_matches, side_of

    bed = res_obj("bed", (2.0, 1.0), (1.6, 2.0, 0.6), 0.0)
    left = res_obj("l", (2.0 - 0.8 - 0.03 - 0.225, 0.2), (0.45, 0.4, 0.55), 0.0)
    right = res_obj("r", (2.0 + 0.8 + 0.03 + 0.225, 0.2), (0.45, 0.4, 0.55), 0.0)
    right_far = res_obj("rf", (2.0 + 0.8 + 0.25 + 0.225, 0.2), (0.45, 0.4, 0.55), 0.0)
    assert side_of(left, bed) == "left" and side_of(right, bed) == "right"
    assert pair_matches(left, right, bed)
    assert not pair_matches(left, right_far, bed)  # both beside, gaps 0.22 m apart
    assert not pair_matches(right, right_far, bed)  # one side


def test_place_front_off_centre():
    from anyhome.layout.rules.place_front import off_centre_m

    sofa = res_obj("sofa", (2.0, 0.45), (2.0, 0.9, 0.85), np.pi / 2)  # front toward -x
    table = res_obj("t", (0.9, 2.3), (1.1, 0.6, 0.45), -np.pi / 2)
    assert off_centre_m([table], sofa) == pytest.approx(1.85)
    chairs = [res_obj("c0", (0.9, 0.0), (0.5, 0.5, 0.9), 0.0), res_obj("c1", (0.9, 0.9), (0.5, 0.5, 0.9), 0.0)]
    assert off_centre_m(chairs, sofa) == pytest.approx(0.0)


@pytest.mark.parametrize("seed", range(3))
def test_rows_keep_an_aisle_behind_the_teachers_chair(seed):
    """The first row stands clear of everything at the front (a teacher's desk and the
    chair behind it), not only of the wall: 24 desks facing a 10 m wall whose teacher's
    chair once closed the only aisle between the two sides of the rows."""
    teacher = item("teacher's desk", "desk", (1.52, 0.65, 0.74), "place_wall", tags=["work_surface", "front_of_room"])
    tchair = item("teacher chair", "chair", (0.46, 0.5, 0.93), "place_front", params={"distance_m": 0.15, "facing": "toward"})
    desk = item("student desk", "desk", (0.64, 0.53, 0.76), "place_center", tags=["work_surface"])
    chair = item("student chair", "chair", (0.43, 0.45, 0.76), "place_front", params={"distance_m": 0.05, "facing": "toward"})
    fp, res = run([group("teacher", teacher, [tchair]),
                   group("desks", desk, [chair], arrangement="rows", repeat=24)],
                  polygon=rect(0, 0, 10.15, 7.7), door=((10.15, 3.35), (10.15, 4.35)), seed=seed)
    t = named(res, "teacher chair")[0]
    tc = footprint_polygon(t.position, t.size, t.yaw)
    students = [footprint_polygon(o.position, o.size, o.yaw) for o in res.objects if o.name.startswith("student")]
    assert len(students) == 48
    assert min(tc.distance(s) for s in students) >= 0.75

def test_centre_grid_is_kept_per_room_read_only_and_the_same_as_made_afresh():
    from anyhome.layout.rules.place_center import _place_center, place_center
    from anyhome.space import RoomSpace

    fp = single_room(l_shape(6, 5, 2.5, 2))
    sp = RoomSpace(fp, fp.rooms[0])
    for facing in ("any", "door", "wall"):
        a, b = place_center(sp, (1.2, 0.6, 0.8), facing), place_center(sp, (1.2, 0.6, 0.8), facing)
        assert a is not b and a.xy is b.xy  # a new wrapper round the arrays kept
        assert not a.pref.flags.writeable
        fresh = _place_center(sp, (1.2, 0.6, 0.8), facing)
        for got, want in ((a.xy, fresh.xy), (a.yaw, fresh.yaw), (a.z, fresh.z), (a.pref, fresh.pref)):
            assert np.array_equal(got, want)
    assert place_center(sp, (0.6, 0.6, 0.8)).xy is not a.xy  # another size: its own


def test_front_poses_are_every_distance_with_every_sideways_shift():
    from anyhome.house import HouseObject
    from anyhome.layout.rules import front_dir, right_dir
    from anyhome.layout.rules.place_front import (
        DISTANCE_FACTORS,
        LATERAL_PER_M,
        LATERAL_SHIFTS_M,
        place_front,
    )
    from anyhome.space import RoomSpace

    fp = single_room(rect(0, 0, 5, 4))
    sp = RoomSpace(fp, fp.rooms[0])
    sofa = HouseObject(id="r1-sofa-0", room="r1", name="sofa", category="sofa", position=(2.5, 0.45, 0.0),
                       size=(2.0, 0.9, 0.85), yaw=0.3)
    c = place_front(sp, sofa, (1.1, 0.6, 0.45), 0.4, lateral=0.2)
    txy, f, r = np.asarray(sofa.position[:2]), front_dir(sofa.yaw), right_dir(sofa.yaw)
    k = 0
    for j, m in enumerate(DISTANCE_FACTORS):
        for lo in LATERAL_SHIFTS_M:  # as one pose at a time makes them
            want = txy + f * (sofa.size[1] / 2 + 0.4 * m + 0.6 / 2) + r * (0.2 + lo)
            assert np.array_equal(c.xy[k], want) and c.pref[k] == (1.0 - 0.08 * j) - LATERAL_PER_M * abs(lo)
            k += 1
    assert len(c) >= k
