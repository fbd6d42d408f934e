"""Seed positions of the force layout: an early stop once the seeds settle."""

from __future__ import annotations

import dataclasses

import numpy as np

from anyhome.floorplan.grid import FREE, make_footprint
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.seeds import seed_positions


def _positions(opts: FloorplanOptions) -> np.ndarray:
    areas = np.array([14.0, 9.0, 5.0, 4.0])
    grid = make_footprint(float(areas.sum()), len(areas), np.random.default_rng(0), opts)
    return seed_positions(grid, areas, [(0, 1), (1, 2), (1, 3)], np.array([True, True, False, False]),
                          np.array([False, True, False, False]), np.random.default_rng(1), opts)


def test_settled_seeds_stop_the_force_layout() -> None:
    base = FloorplanOptions()
    one_step = _positions(dataclasses.replace(base, seed_force_iterations=1))
    settled_at_once = _positions(dataclasses.replace(base, seed_settled_cells=10.0))  # every step counts as settled
    never_settled = _positions(dataclasses.replace(base, seed_settled_cells=0.0))
    np.testing.assert_allclose(settled_at_once, one_step)
    assert not np.allclose(never_settled, one_step)


def test_seeds_stay_inside_the_footprint() -> None:
    opts = FloorplanOptions()
    areas = np.array([14.0, 9.0, 5.0, 4.0])
    grid = make_footprint(float(areas.sum()), len(areas), np.random.default_rng(0), opts)
    pos = _positions(opts)
    idx = np.floor(pos).astype(int)
    assert (grid.owner[idx[:, 0], idx[:, 1]] == FREE).all()
