"""Soft and papered surfaces: fabric, carpet, wallpaper, tatami.

Fabric variants: ``weave`` (plain weave, default), ``velvet``, ``leather``, ``check``
(gingham, plaid, tartan: the weave under crossing bands of a darker shade). Wallpaper
variants: ``stripes`` (default), ``damask``, ``dots``, ``shoji`` (paper panes in a
cedar lattice).
"""

from __future__ import annotations

import numpy as np

from anyhome.materials.noise import (
    Pattern,
    blend,
    blur,
    contrast_color,
    coords,
    fbm,
    grid_cells,
    smoothstep,
    tinted,
    voronoi,
    white,
)

CHECK_BANDS = 4
"""Check repeats across one texture (a check of a few centimetres on a 0.4 m texture)."""
CHECK_DEPTH = 0.45
"""How much darker a check's band is than its ground (where two cross: twice as dark)."""
THREADS = 48
"""Threads per fabric texture along each axis (fewer on small textures)."""
TATAMI_MATS = 2
"""Mats across one tatami texture (each a full mat long along u)."""
TATAMI_STALKS = 96
"""Rush stalks across one tatami texture."""
HERI = np.array([0.13, 0.14, 0.12])
"""Tatami border cloth (dark)."""
HERI_WIDTH = 0.022
"""Border width as a share of the texture (about 4 cm on a 1.8 m texture)."""
CEDAR = np.array([0.71, 0.54, 0.36])
SHOJI_PANES = (3, 4)
"""Shoji panes (columns, rows) per texture."""
SHOJI_BAR = 0.008
"""Half the width of a shoji lattice bar, as a share of the texture."""


def fabric(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    if variant == "velvet":
        return _velvet(rng, n, tint, roughness)
    if variant == "leather":
        return _leather(rng, n, tint, roughness)
    threads = min(THREADS, max(8, n // 4))  # at least 4 texels a thread: no moire
    u, v = coords(n)
    x, y = np.broadcast_to(u * threads, (n, n)), np.broadcast_to(v * threads, (n, n))
    i, j = np.floor(x).astype(int), np.floor(y).astype(int)
    fu, fv = x - i, y - j
    warp_top = (i + j) % 2 == 0
    across = np.where(warp_top, fu, fv)
    along = np.where(warp_top, fv, fu)
    profile = np.sin(np.pi * across) * (0.75 + 0.25 * np.sin(np.pi * along))
    tones = rng.random((2, threads))
    thread_tone = np.where(warp_top, tones[0][i % threads], tones[1][j % threads])
    fibre = blur(white(rng, n))
    slub = fbm(rng, n, 4, 3)
    shade = (0.82 + 0.2 * profile) * (1.0 + 0.06 * (thread_tone - 0.5) + 0.04 * fibre + 0.04 * slub)
    shade = shade * np.where(warp_top, 1.0, 0.96)
    height = 0.2 + 0.8 * profile + 0.05 * fibre
    if variant == "check":  # bands of a darker shade crossing both ways; darker where they cross
        bands = CHECK_BANDS
        bu = (np.floor(np.broadcast_to(u, (n, n)) * bands * 2) % 2 == 0).astype(float)
        bv = (np.floor(np.broadcast_to(v, (n, n)) * bands * 2) % 2 == 0).astype(float)
        shade = shade * (1.0 - CHECK_DEPTH * 0.5 * (bu + bv))
        line = (np.abs(((np.broadcast_to(u, (n, n)) * bands * 2) % 1.0) - 0.5) < 0.06).astype(float)
        shade = shade * (1.0 - 0.25 * line)
    return tinted(tint, shade), height, np.clip(roughness + 0.05 * (1.0 - profile), 0, 1)


def _velvet(rng, n, tint, roughness) -> Pattern:
    sheen = fbm(rng, n, 3, 4, gain=0.6)
    pile = blur(white(rng, n), None)
    shade = 1.0 + 0.12 * sheen + 0.05 * pile
    return tinted(tint, shade), 0.5 + 0.1 * pile + 0.1 * sheen, np.clip(roughness - 0.1 * sheen, 0, 1)


def _leather(rng, n, tint, roughness) -> Pattern:
    f1, f2, _ = voronoi(rng, n, 40)
    pebble = smoothstep(0.0, 0.25, f2 - f1)
    wrinkle = fbm(rng, n, 3, 5, gain=0.6)
    shade = (0.9 + 0.1 * pebble) * (1.0 + 0.1 * wrinkle)
    height = 0.4 + 0.4 * pebble + 0.2 * wrinkle
    return tinted(tint, shade), height, np.clip(roughness + 0.1 * (1.0 - pebble), 0, 1)


def carpet(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    tufts = blur(white(rng, n), None)
    loops = blur(white(rng, n), None, passes=2)
    mottle = fbm(rng, n, 4, 4)
    shade = 0.9 + 0.12 * tufts + 0.08 * loops + 0.06 * mottle
    height = 0.5 + 0.35 * tufts + 0.15 * loops
    return tinted(tint, shade), height, np.clip(roughness + 0.03 * tufts, 0, 1)


def wallpaper(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    paper = 1.0 + 0.02 * fbm(rng, n, 16, 3) + 0.01 * white(rng, n)
    if variant == "shoji":
        return _shoji(rng, n, tint, roughness, paper)
    u, v = coords(n)
    ink = contrast_color(tint, 0.3)
    if variant == "damask":
        motif = _damask(n)
    elif variant == "dots":
        fu, fv, _, _ = grid_cells(n, 6, 6, 0.5)
        motif = 1.0 - smoothstep(0.17, 0.17 + 6.0 / n * 1.5, np.hypot(fu - 0.5, fv - 0.5))
    else:  # stripes, vertical
        x = np.broadcast_to(u * 8, (n, n)) % 1.0
        wide = smoothstep(0.0, 1.5 * 8 / n, x) * (1.0 - smoothstep(0.5, 0.5 + 1.5 * 8 / n, x))
        pin = 1.0 - smoothstep(0.0, 1.2 * 8 / n, np.abs(x - 0.75))
        motif = np.clip(0.7 * wide + 0.9 * pin, 0.0, 1.0)
    color = blend(tinted(tint, paper), ink * paper[..., None], motif)
    height = 0.5 + 0.06 * motif + 0.3 * (paper - 1.0)
    return color, height, np.clip(roughness - 0.1 * motif, 0, 1)


def _damask(n: int) -> np.ndarray:
    """A mirrored ornament on a half-drop grid, in [0, 1] (1 = ink)."""
    fu, fv, _, _ = grid_cells(n, 2, 2, 0.5)
    x, y = np.abs(fu - 0.5) * 2.0, (fv - 0.5) * 2.0  # mirrored about the vertical axis
    r = np.hypot(x, y)
    th = np.arctan2(y, x)
    aa = 8.0 / n  # edge softness: two texels of a cell that spans n / 2 texels over [-1, 1]
    petals = 1.0 - smoothstep(0.0, aa, r - (0.22 + 0.08 * np.cos(6 * th)))
    ring = 1.0 - smoothstep(0.0, aa, np.abs(r - (0.5 + 0.06 * np.cos(8 * th))) - 0.035)
    lx, ly = x - 0.42, np.abs(y) - 0.62
    leaf = 1.0 - smoothstep(0.0, aa, np.hypot(lx * 2.2, ly * 1.0) - 0.3 - 0.08 * np.sin(5 * ly))
    stem = 1.0 - smoothstep(0.0, aa, np.abs(y - 0.5 * np.sin(3 * x)) - 0.025)
    stem = stem * smoothstep(0.55, 0.6, x)
    dot = 1.0 - smoothstep(0.0, aa, np.hypot(x - 0.0, np.abs(y) - 0.85) - 0.06)
    return np.clip(petals + ring + leaf + stem + dot, 0.0, 1.0)


def _shoji(rng, n, tint, roughness, paper) -> Pattern:
    cols, rows = SHOJI_PANES
    fu, fv, _, _ = grid_cells(n, cols, rows)
    d = np.minimum(np.minimum(fu, 1.0 - fu) / cols, np.minimum(fv, 1.0 - fv) / rows)  # texture units
    bar = 1.0 - smoothstep(SHOJI_BAR, SHOJI_BAR + 1.5 / n, d)
    grain = fbm(rng, n, 4, 3, aspect=8)
    wood_c = CEDAR * (1.0 + 0.06 * grain)[..., None]
    color = blend(tinted(tint, paper), wood_c, bar)
    height = 0.3 + 0.7 * bar + 0.3 * (paper - 1.0)
    return color, height, np.clip(roughness + 0.1 * bar, 0, 1)


def tatami(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    """Woven rush running along u, TATAMI_MATS mats stacked along v with dark borders
    along their long edges."""
    u, v = coords(n)
    y = np.broadcast_to(v * TATAMI_STALKS, (n, n))
    stalk = np.floor(y).astype(int) % TATAMI_STALKS
    fs = y - np.floor(y)
    round_ = np.sin(np.pi * fs)
    tone = 1.0 + 0.12 * (rng.random(TATAMI_STALKS)[stalk] - 0.5)
    weave = 0.5 + 0.5 * np.cos(2 * np.pi * (np.broadcast_to(u, (n, n)) * 24 + 0.5 * (stalk % 2)))
    streak = fbm(rng, n, 4, 3, aspect=16)
    shade = tone * (0.8 + 0.18 * round_) * (0.95 + 0.06 * weave) * (1.0 + 0.05 * streak)
    rush = tinted(tint, shade)
    mat_v = np.broadcast_to(v * TATAMI_MATS, (n, n)) % 1.0
    edge = np.minimum(mat_v, 1.0 - mat_v) / TATAMI_MATS
    border = 1.0 - smoothstep(HERI_WIDTH, HERI_WIDTH + 1.5 / n, edge)
    cloth = HERI * (1.0 + 0.1 * blur(white(rng, n)))[..., None]
    color = blend(rush, cloth, border)
    mat_u = np.broadcast_to(u, (n, n))
    seam = 1.0 - smoothstep(0.0, 1.5 / n, np.minimum(mat_u, 1.0 - mat_u))
    color = color * (1.0 - 0.35 * seam)[..., None]
    height = (0.3 + 0.5 * round_ + 0.1 * weave) * (1.0 - border) + 0.95 * border - 0.5 * seam
    return color, height, np.clip(roughness + 0.1 * border, 0, 1)
