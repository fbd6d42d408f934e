"""Seed positions of the rooms: a small force-directed layout of the bubble diagram.

Connected rooms attract, all rooms repel by their size, rooms that need an exterior
wall (habitable ones, the entrance room) are pulled to the footprint's edge and hub
rooms (hallways, entries, service rooms) to its middle.
"""

from __future__ import annotations

import numpy as np

from anyhome.floorplan.grid import FREE, Grid
from anyhome.floorplan.options import FloorplanOptions


def seed_positions(
    grid: Grid,
    areas_m2: np.ndarray,
    edges: list[tuple[int, int]],
    exterior: np.ndarray,
    hub: np.ndarray,
    rng: np.random.Generator,
    opts: FloorplanOptions,
) -> np.ndarray:
    """Position per room, in padded cell units, inside the footprint.

    Parameters
    ----------
    areas_m2 : (n,) float
    edges : index pairs of connected rooms
    exterior : (n,) bool, rooms that need an exterior wall
    hub : (n,) bool, rooms pulled to the middle
    opts : the force layout's gains and step count
    """
    free = np.argwhere(grid.owner == FREE).astype(float) + 0.5  # padded cell centres
    radius = np.sqrt(areas_m2) / grid.cell_m / 2.0
    pos = free[rng.choice(len(free), size=len(areas_m2), replace=len(free) < len(areas_m2))]
    pos = pos + rng.uniform(-opts.seed_jitter_cells, opts.seed_jitter_cells, size=pos.shape)
    border = _border_cells(grid)
    center = free.mean(axis=0)
    inside = grid.owner == FREE
    for _ in range(opts.seed_force_iterations):
        before = pos
        pos = pos + _repel(pos, radius, opts) + _attract(pos, radius, edges, opts)
        pos = pos + _to_edge(pos, radius, exterior, border, opts) + hub[:, None] * opts.seed_center_gain * (center - pos)
        pos = _snap_inside(pos, free, inside)
        if float(np.abs(pos - before).max()) <= opts.seed_settled_cells:  # settled: further steps barely move a seed
            break
    return pos


def _repel(pos: np.ndarray, radius: np.ndarray, opts: FloorplanOptions) -> np.ndarray:
    delta = pos[:, None, :] - pos[None, :, :]
    dist = np.linalg.norm(delta, axis=2) + 1e-6
    overlap = np.clip(radius[:, None] + radius[None, :] - dist, 0.0, None)
    np.fill_diagonal(overlap, 0.0)
    return opts.seed_repel_gain * 0.5 * np.sum((overlap / dist)[:, :, None] * delta, axis=1)


def _attract(pos: np.ndarray, radius: np.ndarray, edges: list[tuple[int, int]], opts: FloorplanOptions) -> np.ndarray:
    move = np.zeros_like(pos)
    for i, j in edges:
        delta = pos[j] - pos[i]
        dist = float(np.linalg.norm(delta)) + 1e-6
        excess = dist - opts.seed_rest_distance_frac * (radius[i] + radius[j])
        if excess > 0:
            step = opts.seed_attract_gain * 0.5 * excess * delta / dist
            move[i] += step
            move[j] -= step
    return move


def _to_edge(pos: np.ndarray, radius: np.ndarray, exterior: np.ndarray, border: np.ndarray, opts: FloorplanOptions) -> np.ndarray:
    move = np.zeros_like(pos)
    rooms = np.flatnonzero(exterior)
    dists = np.linalg.norm(border[None, :, :] - pos[rooms][:, None, :], axis=2)  # every room at once, the same numbers
    for i, d in zip(rooms, dists):
        k = int(np.argmin(d))
        reach = opts.seed_edge_reach_frac
        if d[k] > reach * radius[i]:
            move[i] = opts.seed_edge_gain * (border[k] - pos[i]) * (1.0 - reach * radius[i] / d[k])
    return move


def _border_cells(grid: Grid) -> np.ndarray:
    """Centres of free cells with a non-footprint 4-neighbour."""
    inside = grid.owner == FREE
    edge = np.zeros_like(inside)
    edge[1:-1, 1:-1] = inside[1:-1, 1:-1] & ~(
        inside[:-2, 1:-1] & inside[2:, 1:-1] & inside[1:-1, :-2] & inside[1:-1, 2:]
    )
    return np.argwhere(edge).astype(float) + 0.5


def _snap_inside(pos: np.ndarray, free: np.ndarray, inside: np.ndarray) -> np.ndarray:
    """Move positions outside the footprint to the nearest free cell centre."""
    pos = np.clip(pos, free.min(axis=0), free.max(axis=0))
    idx = np.floor(pos).astype(int)
    for i in np.flatnonzero(~inside[idx[:, 0], idx[:, 1]]):
        pos[i] = free[int(np.argmin(np.linalg.norm(free - pos[i], axis=1)))]
    return pos
