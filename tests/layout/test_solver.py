"""Whole-room and whole-house properties of the layout solver."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from anyhome.house import Door, Floorplan, Room, Window
from anyhome.layout import layout_house

from .helpers import check_valid, group, house_spec, item, l_shape, rect, two_rooms

CATALOGUE = [
    ("bed", "bed", (1.6, 2.0, 0.6), "place_wall", {}),
    ("wardrobe", "wardrobe", (1.2, 0.6, 2.0), "place_corner", {}),
    ("desk", "desk", (1.2, 0.6, 0.75), "place_wall", {}),
    ("sofa", "sofa", (2.0, 0.9, 0.85), "place_wall", {"wall": "longest"}),
    ("table", "table", (1.4, 0.8, 0.75), "place_center", {}),
    ("counter", "counter", (0.6, 0.6, 0.9), "place_next_wall", {}),
    ("plant", "plant", (0.4, 0.4, 1.2), "place_corner", {}),
    ("armchair", "armchair", (0.8, 0.8, 0.9), "place_next", {}),
    ("rug", "rug", (2.0, 1.4, 0.01), "place_center", {}),
    ("bookshelf", "shelf", (0.9, 0.35, 1.9), "place_wall", {"wall": "opposite_door"}),
]
MEMBERS = [
    ("chair", "chair", (0.45, 0.5, 0.9), "place_around", {}),
    ("chair", "chair", (0.5, 0.5, 0.9), "place_front", {"distance_m": 0.2}),
    ("nightstand", "nightstand", (0.45, 0.4, 0.55), "place_beside", {}),
    ("lamp", "lamp", (0.3, 0.3, 0.5), "place_top", {}),
    ("painting", "painting", (0.8, 0.04, 0.6), "place_on_wall", {}),
    ("side table", "table", (0.5, 0.5, 0.5), "place_beside", {"side": "right"}),
    ("tv stand", "tv_stand", (1.4, 0.45, 0.5), "place_front", {"distance_m": 2.0}),
    ("stove", "stove", (0.6, 0.6, 0.9), "place_next_wall", {}),
]
ORNAMENTS = [
    ("vase", "vase", (0.15, 0.15, 0.3), "place_top", {}),
    ("clock", "clock", (0.4, 0.05, 0.4), "place_on_wall", {}),
    ("books", "books", (0.25, 0.2, 0.15), "place_top", {}),
]


def _item(entry, count=1):
    name, cat, size, rule, params = entry
    return item(name, cat, size, rule, params=dict(params), count=count)


@st.composite
def rooms(draw):
    w = draw(st.floats(2.2, 8.0))
    h = draw(st.floats(2.2, 7.0))
    if draw(st.booleans()) and w > 3.5 and h > 3.5:
        poly = l_shape(w, h, draw(st.floats(1.0, w - 2.0)), draw(st.floats(1.0, h - 2.0)))
    else:
        poly = rect(0, 0, w, h)
    edges = [(np.asarray(poly[i], float), np.asarray(poly[(i + 1) % len(poly)], float)) for i in range(len(poly))]
    long_edges = [e for e in edges if np.linalg.norm(e[1] - e[0]) >= 1.2]
    doors, windows = [], []
    n_doors = draw(st.integers(1, 2))
    for k in range(n_doors):
        a, b = long_edges[draw(st.integers(0, len(long_edges) - 1))]
        length = np.linalg.norm(b - a)
        t = draw(st.floats(0.1, length - 1.0))
        u = (b - a) / length
        seg = (tuple(a + u * t), tuple(a + u * (t + 0.9)))
        doors.append(Door(id=f"d{k}", rooms=("r1", "outside"), segment=seg))
    for k in range(draw(st.integers(0, 2))):
        a, b = long_edges[draw(st.integers(0, len(long_edges) - 1))]
        length = np.linalg.norm(b - a)
        t = draw(st.floats(0.05, max(0.05, length - 1.1)))
        u = (b - a) / length
        windows.append(Window(id=f"w{k}", room="r1", segment=(tuple(a + u * t), tuple(a + u * (t + 1.0)))))
    room = Room(id="r1", name="room", type="other", polygon=poly)
    return Floorplan(rooms=[room], doors=doors, windows=windows, connections=[("r1", "outside")])


@st.composite
def furniture(draw):
    groups = []
    for g in range(draw(st.integers(1, 5))):
        anchor = _item(CATALOGUE[draw(st.integers(0, len(CATALOGUE) - 1))])
        members = []
        for _ in range(draw(st.integers(0, 3))):
            members.append(_item(MEMBERS[draw(st.integers(0, len(MEMBERS) - 1))], count=draw(st.integers(1, 4))))
        arrangement = draw(st.sampled_from(["free", "free", "rows", "along_walls", "center", "symmetric"]))
        groups.append(group(f"g{g}", anchor, members, arrangement=arrangement,
                            repeat=draw(st.integers(1, 4)), priority=draw(st.integers(0, 3))))
    orn = [_item(ORNAMENTS[draw(st.integers(0, len(ORNAMENTS) - 1))], count=draw(st.integers(1, 3)))
           for _ in range(draw(st.integers(0, 3)))]
    return groups, orn


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(fp=rooms(), furn=furniture(), seed=st.integers(0, 2**16))
def test_random_layouts_are_valid(fp, furn, seed):
    groups, orn = furn
    spec = house_spec({"r1": groups}, ornaments={"r1": orn})
    res = layout_house(spec, fp, np.random.default_rng(seed))
    assert check_valid(fp, res.objects) == []
    # everything planned is either placed or reported
    planned = sum(g.repeat * (1 + sum(m.count for m in g.members)) for g in groups) + sum(o.count for o in orn)
    assert len(res.objects) + len(res.dropped) == planned
    for o in res.objects:
        assert o.asset is None
        if o.anchor is not None:
            assert o.anchor in {x.id for x in res.objects}


def _house():
    fp = two_rooms()
    sofa = group("sofa_group", item("sofa", "sofa", (2.0, 0.9, 0.85), "place_wall", params={"wall": "longest"}), [
        item("coffee table", "table", (1.0, 0.5, 0.45), "place_front"),
        item("tv stand", "tv_stand", (1.4, 0.45, 0.5), "place_front", params={"distance_m": 2.2})])
    dining = group("dining", item("dining table", "table", (1.4, 0.8, 0.75), "place_center"),
                   [item("chair", "chair", (0.45, 0.5, 0.9), "place_around", count=4)], priority=2)
    bed = group("bed_group", item("bed", "bed", (1.6, 2.1, 0.6), "place_wall"), [
        item("nightstand", "nightstand", (0.45, 0.4, 0.55), "place_beside", count=2),
        item("lamp", "lamp", (0.25, 0.25, 0.45), "place_top", target="nightstand", count=2)])
    spec = house_spec({"living": [sofa, dining], "bed": [bed]},
                      connections=[("living", "outside"), ("living", "bed")],
                      ornaments={"living": [item("vase", "vase", (0.2, 0.2, 0.3), "place_top")]})
    return fp, spec


def test_house_valid_and_deterministic():
    fp, spec = _house()
    a = layout_house(spec, fp, np.random.default_rng(7))
    b = layout_house(spec, fp, np.random.default_rng(7))
    assert [o.model_dump() for o in a.objects] == [o.model_dump() for o in b.objects]
    assert a.dropped == b.dropped
    assert check_valid(fp, a.objects) == []
    assert {o.room for o in a.objects} == {"living", "bed"}
    lamps = [o for o in a.objects if o.name == "lamp"]
    assert len(lamps) == 2 and len({o.support for o in lamps}) == 2


def test_seeds_differ():
    fp, spec = _house()
    layouts = {tuple(o.position for o in layout_house(spec, fp, np.random.default_rng(s)).objects) for s in range(6)}
    assert len(layouts) > 1


def test_missing_room_is_reported():
    fp = two_rooms()
    spec = house_spec({"attic": [group("g", item("box", "box", (0.5, 0.5, 0.5), "place_wall"))]},
                      connections=[("attic", "outside")])
    res = layout_house(spec, fp, np.random.default_rng(0))
    assert res.objects == [] and res.dropped[0].room == "attic"


def test_five_furnished_rooms():
    """A furnished five-room house stays valid (its speed is measured in benchmarks/)."""
    rooms_ = [Room(id=f"r{i}", name=f"r{i}", type="bedroom", polygon=rect(4.5 * i, 0, 4.5 * i + 4.5, 4.0))
              for i in range(5)]
    doors = [Door(id="d0", rooms=("r0", "outside"), segment=((1.0, 0.0), (1.9, 0.0)))]
    doors += [Door(id=f"d{i}", rooms=(f"r{i - 1}", f"r{i}"), segment=((4.5 * i, 1.5), (4.5 * i, 2.4))) for i in range(1, 5)]
    fp = Floorplan(rooms=rooms_, doors=doors, connections=[("r0", "outside")])
    _, spec1 = _house()
    living, bedroom = spec1.rooms[0].groups, spec1.rooms[1].groups
    wardrobe = group("wardrobe", item("wardrobe", "wardrobe", (1.2, 0.6, 2.0), "place_corner"))
    office = [group("desk", item("desk", "desk", (1.2, 0.6, 0.75), "place_wall"),
                    [item("chair", "chair", (0.5, 0.5, 0.9), "place_front"),
                     item("lamp", "lamp", (0.3, 0.3, 0.5), "place_top")]),
              group("shelves", item("bookshelf", "shelf", (0.9, 0.35, 1.9), "place_wall"), repeat=3,
                    arrangement="along_walls")]
    plan = {"r0": living, "r1": bedroom + [wardrobe], "r2": office, "r3": bedroom + [wardrobe], "r4": living}
    orn = [item("vase", "vase", (0.15, 0.15, 0.3), "place_top"), item("clock", "clock", (0.4, 0.05, 0.4), "place_on_wall")]
    spec = house_spec(plan, connections=[("r0", "outside")] + [(f"r{i - 1}", f"r{i}") for i in range(1, 5)],
                      ornaments={k: orn for k in plan})
    res = layout_house(spec, fp, np.random.default_rng(1))
    assert check_valid(fp, res.objects) == []
    assert len(res.objects) >= 40, res.dropped


def test_real_pipeline():
    """Planner + floorplan + layout on real prompts: valid, with rows in the classroom."""
    from anyhome.floorplan import solve_floorplan
    from anyhome.plan import plan_house

    for text in ("A one-bedroom apartment with a living room and a kitchen.",
                 "A classroom with desks and chairs arranged in neat rows facing a whiteboard."):
        spec = plan_house(text, np.random.default_rng(0))
        fp = solve_floorplan(spec, np.random.default_rng(0))
        res = layout_house(spec, fp, np.random.default_rng(0))
        assert check_valid(fp, res.objects) == []
        assert res.objects
