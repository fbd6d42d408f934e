"""The validity primitives of SCENE_FORMAT.md."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from anyhome import geometry as g


def test_footprint_front_faces_plus_y_at_yaw_zero():
    c = g.footprint_corners((0, 0, 0), (2, 1, 1), 0.0)
    assert np.allclose(c, [[-1, -0.5], [1, -0.5], [1, 0.5], [-1, 0.5]])
    # yaw 90 deg CCW: front faces -x, back edge on +x side
    back = g.back_edge((0, 0, 0), (2, 1, 1), np.pi / 2)
    assert np.allclose(back[:, 0], 0.5)


@settings(max_examples=60, deadline=None)
@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(0, 6.3))
def test_collision_is_symmetric_and_detects_self(x, y, yaw):
    a = ((0.0, 0.0, 0.0), (1.0, 0.6, 0.8), 0.3)
    b = ((x, y, 0.0), (0.8, 0.8, 0.5), yaw)
    assert g.boxes_collide(*a, *b) == g.boxes_collide(*b, *a)
    assert g.boxes_collide(*a, *a)


def test_touching_and_stacked_boxes_do_not_collide():
    assert not g.boxes_collide((0, 0, 0), (1, 1, 1), 0, (1.0, 0, 0), (1, 1, 1), 0)
    # lamp on a nightstand: z ranges touch at the top
    assert not g.boxes_collide((0, 0, 0), (0.5, 0.5, 0.6), 0, (0, 0, 0.6), (0.2, 0.2, 0.4), 0)
    assert g.boxes_collide((0, 0, 0), (1, 1, 1), 0, (0.9, 0, 0), (1, 1, 1), 0.0)


def test_opening_zone_spans_both_sides():
    zone = g.opening_zone(((0, 0), (1, 0)))
    assert zone.area == np.float64(1.6) or abs(zone.area - 1.6) < 1e-9
    assert zone.contains(Polygon([(0.4, 0.7), (0.6, 0.7), (0.6, -0.7), (0.4, -0.7)]))


def test_on_boundary():
    sq = Polygon([(0, 0), (4, 0), (4, 4), (0, 4)])
    assert g.on_boundary(sq, ((4, 1), (4, 2)))
    assert not g.on_boundary(sq, ((3.9, 1), (3.9, 2)))


def two_rooms():
    rooms = [("a", [(0, 0), (4, 0), (4, 4), (0, 4)]), ("b", [(4, 0), (8, 0), (8, 4), (4, 4)])]
    doors = [("d0", ("a", "outside"), ((1, 0), (2, 0))), ("d1", ("a", "b"), ((4, 1.5), (4, 2.5)))]
    return rooms, doors


def test_navigability_through_doors_only():
    rooms, doors = two_rooms()
    assert g.navigability(rooms, doors, []).ok
    res = g.navigability(rooms, doors[:1], [])
    assert res.unreachable_rooms == ("b",)


def test_navigability_blocked_by_objects():
    rooms, doors = two_rooms()
    wall_of_stuff = Polygon([(2.9, 0), (3.5, 0), (3.5, 4), (2.9, 4)])
    res = g.navigability(rooms, doors, [wall_of_stuff])
    assert "b" in res.unreachable_rooms and "d1" in res.unreachable_doors
    narrow_gap = [Polygon([(2.5, 0), (3.0, 0), (3.0, 3.6), (2.5, 3.6)])]  # 0.4 m < 2 * 0.25
    assert not g.navigability(rooms, doors, narrow_gap).ok
    wide_gap = [Polygon([(2.5, 0), (3.0, 0), (3.0, 3.3), (2.5, 3.3)])]  # 0.7 m gap
    assert g.navigability(rooms, doors, wide_gap).ok


def test_rugs_and_stacked_things_do_not_block():
    assert not g.blocks_navigation("rug", 0.01, "floor")
    assert not g.blocks_navigation("lamp", 0.5, "nightstand-1")
    assert g.blocks_navigation("sofa", 0.8, "floor")
