"""Drawn footprints (anyhome.floorplan.grid.make_footprint): rectangles, Ls and Us (a
notch in the middle of one side), and the floorplans solved inside them."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon, box

from anyhome.evaluate.footprint import footprint_shape
from anyhome.floorplan import solve_floorplan
from anyhome.floorplan.grid import OUTSIDE, make_footprint
from anyhome.floorplan.options import FloorplanOptions
from tests.floorplan.test_shapes import check_shapes, one_bed_home
from tests.floorplan.test_solver import check_floorplan

U_ONLY = FloorplanOptions(u_shape_probability=1.0, l_shape_probability=0.0)
L_ONLY = FloorplanOptions(u_shape_probability=0.0, l_shape_probability=1.0)


def _grid_shape(owner: np.ndarray) -> str:
    return footprint_shape([box(x, y, x + 1, y + 1) for x, y in np.argwhere(owner != OUTSIDE)])


@pytest.mark.parametrize("seed", range(6))
def test_a_u_footprint_is_a_rectangle_notched_in_the_middle_of_one_side(seed: int) -> None:
    grid = make_footprint(80.0, 6, np.random.default_rng(seed), U_ONLY)
    assert grid.void_sides == 1
    assert _grid_shape(grid.owner) == "U"
    nx, ny = grid.shape
    assert (grid.owner[1:-1, 1:-1] == OUTSIDE).sum() < 0.3 * nx * ny


def test_an_l_footprint_keeps_a_corner_void() -> None:
    grid = make_footprint(80.0, 6, np.random.default_rng(0), L_ONLY)
    assert grid.void_sides == 2 and _grid_shape(grid.owner) == "L"


def test_small_programs_get_no_u() -> None:
    opts = FloorplanOptions(u_shape_probability=1.0, l_shape_probability=0.0, u_shape_min_rooms=5)
    assert _grid_shape(make_footprint(40.0, 3, np.random.default_rng(0), opts).owner) == "rectangle"


def test_a_home_in_a_u_footprint() -> None:
    """Some seed lays the six-room home out as a U, every hard rule kept."""
    spec = one_bed_home()
    shapes = []
    for seed in range(6):
        fp = solve_floorplan(spec, np.random.default_rng(seed), U_ONLY)
        check_floorplan(spec, fp)
        shapes.append(footprint_shape([Polygon(r.polygon) for r in fp.rooms]))
    assert "U" in shapes, shapes


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), shape=st.sampled_from(["U", "L"]))
def test_floorplans_in_drawn_footprints_pass_the_checks(seed: int, shape: str) -> None:
    spec = one_bed_home()
    fp = solve_floorplan(spec, np.random.default_rng(seed), U_ONLY if shape == "U" else L_ONLY)
    check_floorplan(spec, fp)
    check_shapes(fp)
