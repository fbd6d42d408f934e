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


def _both_layouts(n_rooms: int, seed: int, opts: FloorplanOptions) -> tuple[np.ndarray, np.ndarray]:
    """The force layout of a random ``n_rooms``-room program stepped on arrays and in
    Python floats, from the same first places."""
    from anyhome.floorplan import seeds

    rng = np.random.default_rng(seed)
    areas = rng.uniform(3.0, 25.0, size=n_rooms)
    grid = make_footprint(float(areas.sum()), n_rooms, rng, opts)
    pairs = [(i, j) for i in range(n_rooms) for j in range(i + 1, n_rooms)]
    edges = [pairs[k] for k in rng.permutation(len(pairs))[: rng.integers(0, len(pairs) + 1)]] if pairs else []
    exterior, hub = rng.random(n_rooms) < 0.6, rng.random(n_rooms) < 0.3
    free = np.argwhere(grid.owner == FREE).astype(float) + 0.5
    pos = free[rng.choice(len(free), size=n_rooms)] + rng.uniform(-0.4, 0.4, size=(n_rooms, 2))
    pos[0] = (-5.0, 1e3)  # far outside: snapped back in
    forces = seeds._Forces(np.sqrt(areas) / grid.cell_m / 2.0, edges, exterior, seeds._border_cells(grid), opts)
    args = (free.mean(axis=0), hub[:, None] * opts.seed_center_gain, free, grid.owner == FREE,
            free.min(axis=0), free.max(axis=0), opts)
    return seeds._array_layout(pos.copy(), forces, *args), seeds._scalar_layout(pos.copy(), forces, *args)


def test_python_float_steps_give_the_array_steps_positions_exactly() -> None:
    """The force layout of a few rooms, stepped in Python floats for speed, gives the very
    doubles the array code gives (the floorplans stay as they were)."""
    for settled in (0.0, 0.01):
        opts = dataclasses.replace(FloorplanOptions(), seed_settled_cells=settled)
        for n_rooms in range(1, opts.seed_scalar_max_rooms + 1):
            for seed in range(12):
                array_pos, scalar_pos = _both_layouts(n_rooms, seed, opts)
                assert array_pos.tobytes() == scalar_pos.tobytes(), (n_rooms, seed, settled)
