"""Wood: continuous grain (furniture) and boards (floors, walls, ceilings).

Grain runs along u. Board variants: ``planks`` (staggered joints), ``parquet``
(herringbone), ``shiplap`` (painted horizontal boards), ``logs`` (round logs).
"""

from __future__ import annotations

import numpy as np

from anyhome.materials.noise import (
    Pattern,
    blend,
    coords,
    edge_distance,
    fbm,
    grid_cells,
    smoothstep,
    tinted,
    white,
)

RINGS_PER_TILE = 9
"""Grain lines across one wood texture (an integer, so the grain wraps)."""
BOARDS_PER_TILE = 8
"""Rows of floor boards in one planks texture."""
PARQUET_BOARD_RATIO = 4
"""Herringbone block length in block widths."""
SHIPLAP_BOARDS = 6
LOG_ROWS = 4
GAP_PX = 1.2
"""Width of the dark joint between boards, in texels."""


def _ring(t: np.ndarray) -> np.ndarray:
    """Dark latewood band of a grain ring from the ring phase ``t``."""
    f = t - np.floor(t)
    return smoothstep(0.45, 0.92, f) * (1.0 - smoothstep(0.92, 1.0, f))


def _grain(rng: np.random.Generator, n: int, across: np.ndarray, rings: float,
           figure: float = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """(late, pores): latewood bands along u from a cross-grain coordinate, plus fine pores;
    ``figure`` is how far the rings wander."""
    warp = fbm(rng, n, 2, 3, aspect=3)
    pores = fbm(rng, n, 4, 3, gain=0.7, aspect=24)
    late = _ring((across + 0.06 * warp) * rings + figure * warp)
    return late, pores


def wood(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    """Continuous grain for furniture."""
    _, v = coords(n)
    late, pores = _grain(rng, n, np.broadcast_to(v, (n, n)), RINGS_PER_TILE, figure=0.3)
    tone = fbm(rng, n, 2, 2)
    color = tinted(tint, 1.06 - 0.24 * late + 0.08 * pores + 0.05 * tone)
    height = 0.5 - 0.35 * late + 0.15 * pores
    return color, height, roughness + 0.08 * late


def _boards(rng, n, tint, roughness, fu, fv, board, count, aspect, board_px, rings=3.0) -> Pattern:
    """Shade boards given each texel's in-board position (``fu`` along, ``fv`` across, both
    in [0, 1)), its board id (< ``count``), the boards' length / width (``aspect``) and
    their width in texels (``board_px``)."""
    phase = rng.random(count)
    tone = 1.0 + 0.16 * (rng.random(count) - 0.5)
    late, pores = _grain(rng, n, fv + phase[board], rings, figure=0.25)
    d = edge_distance(fu, fv, aspect)
    gap = 1.0 - smoothstep(0.0, GAP_PX / board_px, d)
    shade = tone[board] * (1.05 - 0.2 * late + 0.07 * pores) * (1.0 - 0.6 * gap)
    height = 0.8 - 0.2 * late + 0.06 * pores - 0.8 * gap
    return tinted(tint, shade), height, roughness + 0.06 * late + 0.25 * gap


def planks(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    if variant == "parquet":
        return _parquet(rng, n, tint, roughness)
    if variant == "shiplap":
        return _shiplap(rng, n, tint, roughness)
    if variant == "logs":
        return _logs(rng, n, tint, roughness)
    rows = BOARDS_PER_TILE
    stagger = rng.random(rows)
    fu, fv, _, row = grid_cells(n, 1, rows, stagger)
    return _boards(rng, n, tint, roughness, fu, fv, row, rows, float(rows), n / rows)


def _parquet(rng, n, tint, roughness) -> Pattern:
    """Herringbone of 1 x k blocks at 45 degrees; the square texture holds k block pairs."""
    k = PARQUET_BOARD_RATIO
    side = k * np.sqrt(2.0)  # texture side in block widths
    u, v = coords(n)
    big_x, big_y = np.broadcast_to(u * side, (n, n)), np.broadcast_to(v * side, (n, n))
    x, y = (big_x + big_y) / np.sqrt(2.0), (big_x - big_y) / np.sqrt(2.0)
    board = np.full((n, n), -1)
    along = np.zeros((n, n))
    across = np.zeros((n, n))
    for m in range(-2, 3):
        xs, ys = x - m * k, y + m * k
        kh = np.floor(ys)
        a = xs - kh
        hit = (a >= 0) & (a < k) & (board < 0)
        board[hit] = (2 * (kh.astype(int) % k))[hit]
        along[hit], across[hit] = a[hit] / k, (ys - kh)[hit]
        kv = np.floor(xs)
        b = ys - kv - 1
        hit = (b >= 0) & (b < k) & (board < 0)
        board[hit] = (2 * (kv.astype(int) % k) + 1)[hit]
        along[hit], across[hit] = b[hit] / k, (xs - kv)[hit]
    board = np.maximum(board, 0)
    return _boards(rng, n, tint, roughness, along, across, board, 2 * k, float(k), n / side,
                   rings=2.0)


def _shiplap(rng, n, tint, roughness) -> Pattern:
    """Painted horizontal boards: flat colour, a shadow line under each board."""
    rows = SHIPLAP_BOARDS
    _, v = coords(n)
    fv = np.broadcast_to(v * rows, (n, n)) % 1.0
    shadow = 1.0 - smoothstep(0.0, 2.5 * rows / n, fv)
    grain = fbm(rng, n, 2, 3, aspect=16)
    shade = (1.0 + 0.015 * grain) * (1.0 - 0.45 * shadow)
    height = 0.9 - 0.9 * shadow + 0.01 * grain
    return tinted(tint, shade), height, roughness + 0.2 * shadow


def _logs(rng, n, tint, roughness) -> Pattern:
    """Round logs stacked along v with light chinking between them."""
    rows = LOG_ROWS
    _, v = coords(n)
    y = np.broadcast_to(v * rows, (n, n))
    row = np.floor(y).astype(int) % rows
    fv = y - np.floor(y)
    profile = np.sqrt(np.clip(1.0 - (2.0 * fv - 1.0) ** 2, 0.0, 1.0))
    late, pores = _grain(rng, n, fv * 0.3 + rng.random(rows)[row], 4.0)
    tone = 1.0 + 0.14 * (rng.random(rows)[row] - 0.5)
    chink = 1.0 - smoothstep(0.05, 0.2, profile)
    wood_c = tinted(tint, tone * (0.7 + 0.35 * profile) * (1.04 - 0.25 * late + 0.08 * pores))
    color = blend(wood_c, np.array([0.78, 0.74, 0.66]), chink)
    height = 0.3 + 0.7 * profile - 0.05 * late + 0.03 * white(rng, n)
    return color, height, roughness + 0.1 * chink
