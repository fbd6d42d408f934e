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


# ------------------------------------------------------- bounded navigation raster
def reference_navigability(rooms, doors, obstacles, cell_m=g.NAV_CELL_M):
    """The raster of the first version of :func:`g.navigability`: full-grid masks from
    full coordinate arrays (kept here to check the windowed one gives the same cells)."""
    import shapely
    from shapely.geometry import LineString

    polys = {rid: Polygon(p) for rid, p in rooms}
    minx, miny, maxx, maxy = shapely.bounds(shapely.union_all(list(polys.values())))
    pad = 2 * cell_m
    xs = np.arange(minx - pad, maxx + pad, cell_m) + cell_m / 2
    ys = np.arange(miny - pad, maxy + pad, cell_m) + cell_m / 2
    gx, gy = np.meshgrid(xs, ys)
    free = np.zeros(gx.shape, dtype=bool)
    for p in polys.values():
        free |= shapely.contains_xy(p.buffer(-g.WALL_INSET_CELLS * cell_m, join_style="mitre"),
                                    gx, gy)
    for _, _, seg in doors:
        free |= shapely.contains_xy(LineString(seg).buffer(cell_m * 0.75, cap_style="flat"),
                                    gx, gy)
    for ob in obstacles:
        free &= ~shapely.contains_xy(ob, gx, gy)
    from scipy import ndimage

    return int((ndimage.distance_transform_edt(free) * cell_m > g.AGENT_RADIUS_M).sum())


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(0.2, 7.8), st.floats(0.2, 3.8), st.floats(0.1, 1.5),
                          st.floats(0.1, 1.5), st.floats(0, 6.3)), max_size=8))
def test_windowed_raster_equals_the_full_grid_one(boxes):
    rooms, doors = two_rooms()
    obstacles = [g.footprint_polygon((x, y, 0), (w, d, 1), yaw) for x, y, w, d, yaw in boxes]
    res = g.navigability(rooms, doors, obstacles)
    assert res.checked and res.cell_m == g.NAV_CELL_M
    assert res.free_cells == reference_navigability(rooms, doors, obstacles)


def test_huge_house_is_coarsened_or_refused_within_the_cell_bound():
    assert g.nav_cell_size(10, 10) == g.NAV_CELL_M
    step = g.nav_cell_size(150, 150)
    assert g.NAV_CELL_M < step <= g.MAX_NAV_CELL_M
    assert (150 / step + 5) ** 2 <= g.MAX_NAV_CELLS
    big = [("a", [(0, 0), (150, 0), (150, 150), (0, 150)])]
    res = g.navigability(big, [("d0", ("a", "outside"), ((1, 0), (2, 0)))], [])
    assert res.ok and res.cell_m == step and res.free_cells > 0
    km = [("a", [(0, 0), (1000, 0), (1000, 1000), (0, 1000)])]
    res = g.navigability(km, [("d0", ("a", "outside"), ((1, 0), (2, 0)))], [])
    assert not res.checked and not res.ok and "1000 m x 1000 m" in res.skipped
    assert g.nav_cell_size(float("inf"), 1.0) == float("inf")


def test_stacked_geometry_beyond_the_work_bound_is_refused():
    rooms, doors = two_rooms()
    n = int(g.MAX_NAV_WORK_CELLS / (4 / g.NAV_CELL_M + 1) ** 2) + 10
    res = g.navigability(rooms, doors, [Polygon([(0, 0), (4, 0), (4, 4), (0, 4)])] * n)
    assert not res.checked and "overlapping geometry" in res.skipped


def test_floor_coverage_counts_overlaps_once_and_only_inside_the_room():
    from shapely.geometry import box

    room = box(0, 0, 4, 5)
    feet = [box(0, 0, 2, 2), box(1, 1, 3, 3), box(3.5, 4.5, 5, 6)]  # overlapping; one half outside
    assert abs(g.floor_coverage(feet, room) - (4 + 4 - 1 + 0.25) / 20) < 1e-9
    assert g.floor_coverage([], room) == 0.0
