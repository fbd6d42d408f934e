"""Tileable noise and pattern helpers for the procedural textures.

Every field here is periodic over the unit square: texel ``(row, col)`` of an
``n x n`` field sits at ``u = (col + 0.5) / n``, ``v = (row + 0.5) / n``, and the
field wraps at the edges, so a texture built from them tiles.

Value noise is a random periodic lattice interpolated separably (smoothstep weights)
to the texel grid: two gathers and blends per octave.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

FLOAT = np.float32
"""Texels are computed in single precision (plenty for 8-bit images, twice as fast)."""
JITTER = 0.8
"""How far (in cells) a jittered-grid Voronoi point may move from its cell centre."""


def coords(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Texel centres: ``u`` of shape (1, n) (columns), ``v`` of shape (n, 1) (rows)."""
    t = ((np.arange(n) + 0.5) / n).astype(FLOAT)
    return t[None, :], t[:, None]


def smoothstep(e0: float, e1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


@lru_cache(maxsize=64)
def _lerp_weights(n: int, period: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For n texels over a periodic lattice of ``period`` cells: the lower and upper
    lattice index of each texel and the smoothstep weight of the upper one."""
    x = (np.arange(n) + 0.5) * period / n
    i0 = np.floor(x).astype(int)
    f = x - i0
    w = (f * f * (3.0 - 2.0 * f)).astype(FLOAT)
    return i0 % period, (i0 + 1) % period, w


def upsample(lattice: np.ndarray, n: int) -> np.ndarray:
    """(n, n) smooth periodic interpolation of a (rows, cols) lattice over the unit square.

    Separable, with gathers instead of matrix products (no BLAS threads for small work).
    """
    r0, r1, wr = _lerp_weights(n, lattice.shape[0])
    c0, c1, wc = _lerp_weights(n, lattice.shape[1])
    rows = lattice[r0] * (1.0 - wr)[:, None] + lattice[r1] * wr[:, None]
    return rows[:, c0] * (1.0 - wc) + rows[:, c1] * wc


def value_noise(rng: np.random.Generator, n: int, period_u: int, period_v: int | None = None
                ) -> np.ndarray:
    """(n, n) tileable value noise in [0, 1] with ``period_u`` x ``period_v`` lattice cells."""
    pv = period_u if period_v is None else period_v
    return upsample(rng.random((pv, period_u), dtype=FLOAT), n)


def fbm(rng: np.random.Generator, n: int, period: int, octaves: int = 4, gain: float = 0.5,
        aspect: int = 1) -> np.ndarray:
    """(n, n) fractal value noise in about [-1, 1], tileable.

    ``period`` is the lattice size of the first octave along u; ``aspect`` multiplies it
    along v (streaks along u for ``aspect > 1``). Octaves past the texel resolution are
    skipped.
    """
    out = np.zeros((n, n), dtype=FLOAT)
    amp, total = 1.0, 0.0
    for _ in range(octaves):
        if period > n or period * aspect > n:
            break
        out += amp * (value_noise(rng, n, period, period * aspect) - 0.5)
        total += amp
        amp *= gain
        period *= 2
    return out * (2.0 / max(total, 1e-9))


def white(rng: np.random.Generator, n: int) -> np.ndarray:
    """(n, n) independent uniform texels in [-1, 1]."""
    return rng.random((n, n), dtype=FLOAT) * 2.0 - 1.0


def blur(field: np.ndarray, axis: int | None = None, passes: int = 1) -> np.ndarray:
    """Wrap-around [1, 2, 1] blur along ``axis`` (both if None)."""
    axes = (0, 1) if axis is None else (axis,)
    for _ in range(passes):
        for ax in axes:
            field = 0.25 * np.roll(field, 1, ax) + 0.5 * field + 0.25 * np.roll(field, -1, ax)
    return field


def voronoi(rng: np.random.Generator, n: int, cells: int, cells_v: int | None = None
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tileable jittered-grid Voronoi on a ``cells`` x ``cells_v`` grid.

    Returns
    -------
    f1 : (n, n) float, distance to the nearest point, in cells
    f2 : (n, n) float, distance to the second nearest point
    cell : (n, n) int, index of the nearest point (``row * cells + col``)
    """
    cu, cv = cells, cells if cells_v is None else cells_v
    jitter = ((rng.random((cv, cu, 2)) - 0.5) * JITTER).astype(FLOAT)
    u, v = coords(n)
    x = np.broadcast_to(u * cu, (n, n))
    y = np.broadcast_to(v * cv, (n, n))
    ix, iy = np.floor(x).astype(int), np.floor(y).astype(int)
    f1 = np.full((n, n), np.inf, dtype=FLOAT)
    f2 = np.full((n, n), np.inf, dtype=FLOAT)
    cell = np.zeros((n, n), dtype=int)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            gx, gy = ix + dx, iy + dy
            wx, wy = gx % cu, gy % cv
            px = gx + 0.5 + jitter[wy, wx, 0]
            py = gy + 0.5 + jitter[wy, wx, 1]
            d = (px - x) ** 2 + (py - y) ** 2
            closer = d < f1
            f2 = np.where(closer, f1, np.minimum(f2, d))
            f1 = np.where(closer, d, f1)
            cell = np.where(closer, wy * cu + wx, cell)
    return np.sqrt(f1), np.sqrt(f2), cell


def grid_cells(n: int, cols: int, rows: int, stagger: np.ndarray | float = 0.0
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A running-bond grid of ``cols`` x ``rows`` rectangles over the unit square.

    ``stagger`` shifts each row along u by that fraction of a cell (a scalar shifts
    every odd row, an array of length ``rows`` gives each row its own shift).

    Returns
    -------
    fu, fv : (n, n) position inside the cell, each in [0, 1)
    col, row : (n, n) int cell indices (``col`` wraps at ``cols``)
    """
    u, v = coords(n)
    y = np.broadcast_to(v * rows, (n, n))
    row = np.floor(y).astype(int)
    if np.ndim(stagger) == 0:
        shift = np.where(row % 2 == 1, float(stagger), 0.0)
    else:
        shift = np.asarray(stagger, dtype=float)[row % rows]
    x = u * cols + shift
    col = np.floor(x).astype(int) % cols
    return x - np.floor(x), y - row, col, row % rows


def edge_distance(fu: np.ndarray, fv: np.ndarray, aspect: float = 1.0) -> np.ndarray:
    """Distance from a point inside a cell to the cell's nearest edge, in cell heights
    (``aspect`` is the cell's width / height)."""
    du = np.minimum(fu, 1.0 - fu) * aspect
    dv = np.minimum(fv, 1.0 - fv)
    return np.minimum(du, dv)


def normal_map(height: np.ndarray, strength: float) -> np.ndarray:
    """(n, n, 3) tangent-space normals in [-1, 1] from a height field (finite differences,
    wrapping). +x right, +y up in the image (the glTF / OpenGL convention); ``strength``
    scales the slope, in height units per texture width."""
    n = height.shape[0]
    dx = (np.roll(height, -1, 1) - np.roll(height, 1, 1)) * 0.5 * n
    dy = (np.roll(height, 1, 0) - np.roll(height, -1, 0)) * 0.5 * n  # row 0 is the top
    nrm = np.stack([-dx * strength, -dy * strength, np.ones_like(height)], axis=-1)
    return nrm / np.linalg.norm(nrm, axis=-1, keepdims=True)


# ----------------------------------------------------------------- colour helpers
Pattern = tuple[np.ndarray, np.ndarray, np.ndarray]
"""What a pattern generator returns: colour (n, n, 3) sRGB, height (n, n), roughness (n, n)."""


def tinted(tint: np.ndarray, factor: np.ndarray) -> np.ndarray:
    """(n, n, 3): the (3,) ``tint`` scaled per texel by ``factor`` (n, n)."""
    return tint[None, None, :] * factor[..., None]


def blend(a: np.ndarray, b: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Per-texel mix of two colours (each (3,) or (n, n, 3)) by ``t`` (n, n) in [0, 1]."""
    return a + (b - a) * t[..., None]


def luminance(rgb: np.ndarray) -> float:
    return float(np.dot(np.asarray(rgb, dtype=float)[:3], (0.2126, 0.7152, 0.0722)))


def contrast_color(tint: np.ndarray, amount: float = 0.45) -> np.ndarray:
    """A colour that reads against ``tint``: darker for light tints, lighter for dark."""
    if luminance(tint) > 0.45:
        return tint * (1.0 - amount)
    return tint + (1.0 - tint) * amount
