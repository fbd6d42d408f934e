"""Stairs (fixtures.py): a box wide enough for two flights is built as a dog-leg stair
whose steps match the floorplan's riser and going bounds."""

from __future__ import annotations

import numpy as np
import pytest
from procedural_helpers import fresh_mesh

from anyhome.assets.registry import get
from anyhome.floorplan.stairs import dogleg


def _tread_heights(mesh, x_lo: float, x_hi: float, y_lo: float, y_hi: float) -> np.ndarray:
    """Distinct heights of upward faces whose centres lie in the given strip of the box."""
    c = mesh.triangles_center
    up = mesh.face_normals[:, 2] > 0.99
    inside = (c[:, 0] > x_lo) & (c[:, 0] < x_hi) & (c[:, 1] > y_lo) & (c[:, 1] < y_hi)
    return np.unique(np.round(c[up & inside, 2], 3))


@pytest.mark.parametrize("rise", [2.9, 3.2, 4.7])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_dogleg_box_builds_two_flights_within_riser_and_going_bounds(rise, seed):
    d = dogleg(rise)
    size = (d.length_m, d.width_m, rise)
    params = get("staircase").sample(np.random.default_rng(seed), size, "modern" if seed % 2 else "rustic")
    assert params.turn == "dogleg"
    mesh = fresh_mesh("staircase", seed, size, "modern" if seed % 2 else "rustic")
    lo, hi = mesh.bounds
    assert np.allclose(hi - lo, size, atol=1e-6)  # fills its box exactly
    length, width = size[0], size[1]
    first = _tread_heights(mesh, -length / 2 + d.landing_m + 0.01, length / 2, -width / 2, -0.05)
    second = _tread_heights(mesh, -length / 2 + d.landing_m + 0.01, length / 2, 0.05, width / 2)
    for treads in (first, second):  # each flight climbs in steps no higher than a riser
        steps = np.diff(treads)
        assert len(treads) >= d.first_risers - 2
        assert steps.max() <= d.riser_m + 0.05  # a tread top and its nosing sit a few cm apart
    assert first.max() < second.max()  # the second flight climbs on from the half landing
    assert second.max() == pytest.approx(rise, abs=0.01)  # and reaches the floor above


def test_a_narrow_box_stays_a_straight_flight():
    params = get("staircase").sample(np.random.default_rng(0), (3.2, 1.0, 2.5), "")
    assert params.turn == "straight"
