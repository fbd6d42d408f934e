"""Hard surfaces: tile, brick, stone, concrete, marble.

Tile variants: ``square`` (default), ``subway`` (2:1 running bond), ``zellige`` (small
hand-made squares, uneven colour), ``terracotta`` (large matte squares). Stone
variants: ``flags`` (flat slabs) and ``rubble`` (rounded stones, deep joints).
Concrete variants: ``concrete``, ``polished``, ``terrazzo``.
"""

from __future__ import annotations

import numpy as np

from anyhome.materials.noise import (
    Pattern,
    blend,
    contrast_color,
    coords,
    edge_distance,
    fbm,
    grid_cells,
    smoothstep,
    tinted,
    voronoi,
    white,
)

GROUT = np.array([0.66, 0.65, 0.62])
"""Grout and mortar grey (mixed with the tint)."""
TILE_GRID = {"square": (4, 4, 0.0, 0.03, 0.03), "subway": (4, 8, 0.5, 0.025, 0.02),
             "zellige": (6, 6, 0.0, 0.04, 0.14), "terracotta": (3, 3, 0.0, 0.025, 0.08)}
"""variant -> (columns, rows, row stagger, grout half-width in cell heights, tone spread)."""
BRICK_COLS, BRICK_ROWS = 4, 12
"""One brick texture: 4 x 12 bricks of 225 x 75 mm (with joints) = 0.9 m square."""
MORTAR_HALF = 0.075
"""Half the mortar joint, in brick heights."""
STONE_CELLS = {"flags": 4, "rubble": 6}
TERRAZZO_CHIPS = np.array([[0.95, 0.94, 0.9], [0.35, 0.35, 0.36], [0.7, 0.68, 0.64],
                           [0.72, 0.5, 0.38], [0.55, 0.6, 0.58]])
"""Chip colours of terrazzo (white, charcoal, grey, rust, green-grey)."""


def tile(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    cols, rows, stagger, half, spread = TILE_GRID.get(variant, TILE_GRID["square"])
    fu, fv, col, row = grid_cells(n, cols, rows, stagger)
    cid = row * cols + col
    tone = 1.0 + spread * (rng.random(cols * rows) - 0.5) * 2.0
    d = edge_distance(fu, fv, rows / cols)
    px = rows / n  # one texel in cell heights
    grout = 1.0 - smoothstep(half, half + 1.5 * px, d)
    bevel = smoothstep(half, half + 3 * px, d)
    wobble = fbm(rng, n, 8, 3)
    mottle = fbm(rng, n, 4, 4)
    glaze = 0.35 if variant == "zellige" else 0.06 if variant == "terracotta" else 0.02
    surf = tinted(tint, tone[cid] * (1.0 + glaze * 0.4 * mottle))
    color = blend(surf, 0.45 * tint + 0.55 * GROUT, grout)
    height = 0.2 + 0.8 * bevel + glaze * 0.25 * wobble
    rough = np.where(grout > 0.5, 0.9, roughness + 0.05 * mottle)
    return color, height, rough


def brick(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    fu, fv, col, row = grid_cells(n, BRICK_COLS, BRICK_ROWS, 0.5)
    cid = row * BRICK_COLS + col
    count = BRICK_COLS * BRICK_ROWS
    tone = 1.0 + 0.22 * (rng.random(count) - 0.5)
    burnt = rng.random(count) < 0.15
    tone = np.where(burnt, tone * 0.72, tone)
    rough_edge = fbm(rng, n, 16, 3) * 0.04
    d = edge_distance(fu, fv, BRICK_ROWS / BRICK_COLS) + rough_edge
    mortar = 1.0 - smoothstep(MORTAR_HALF, MORTAR_HALF + 1.5 * BRICK_ROWS / n, d)
    grit = fbm(rng, n, 16, 3) * 0.08 + white(rng, n) * 0.05
    face = tinted(tint, tone[cid] * (1.0 + grit))
    mortar_c = 0.25 * tint + 0.75 * GROUT * 1.1
    color = blend(face, mortar_c * (1.0 + 0.5 * grit[..., None]), mortar)
    height = 0.35 + 0.65 * smoothstep(MORTAR_HALF, MORTAR_HALF + 0.12, d) + 0.3 * grit
    return color, height, np.clip(roughness + 0.05 * (1.0 - mortar), 0, 1)


def stone(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    rubble = variant == "rubble"
    cells = STONE_CELLS["rubble" if rubble else "flags"]
    f1, f2, cell = voronoi(rng, n, cells)
    count = cells * cells
    tone = 1.0 + 0.3 * (rng.random(count) - 0.5)
    hue = 1.0 + 0.05 * (rng.random((count, 3)) - 0.5)
    gap = f2 - f1 + fbm(rng, n, 12, 3) * 0.06
    joint_w = 0.12 if rubble else 0.05
    joint = 1.0 - smoothstep(joint_w, joint_w + 2.0 * cells / n, gap)
    grain = fbm(rng, n, 6, 5)
    face = tint[None, None, :] * hue[cell] * (tone[cell] * (1.0 + 0.12 * grain))[..., None]
    color = blend(face, 0.3 * tint + 0.7 * GROUT * 0.85, joint)
    dome = smoothstep(0.0, 0.45 if rubble else 0.12, gap)
    height = 0.15 + 0.75 * dome + 0.12 * grain
    return color, height, np.clip(roughness + 0.05 * joint + 0.04 * grain, 0, 1)


def concrete(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    cloud = fbm(rng, n, 3, 6, gain=0.55)
    speck = white(rng, n)
    pores = smoothstep(0.985, 1.0, rng.random((n, n)))
    shade = 1.0 + 0.07 * cloud + 0.025 * speck - 0.35 * pores
    color = tinted(tint, shade)
    height = 0.5 + 0.1 * cloud + 0.05 * speck - 0.5 * pores
    if variant == "terrazzo":
        f1, _, cell = voronoi(rng, n, 18)
        size = 0.18 + 0.22 * rng.random(18 * 18)
        pick = rng.integers(len(TERRAZZO_CHIPS), size=18 * 18)
        chip = 1.0 - smoothstep(size[cell] - 18.0 / n, size[cell], f1)
        color = blend(color, TERRAZZO_CHIPS[pick[cell]], chip)
        height = height + 0.05 * chip
    rough = roughness + 0.08 * cloud + 0.3 * pores
    return color, height, np.clip(rough, 0, 1)


def marble(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    """Diagonal veins (a warped sine band with a soft halo) over ridged fine veining."""
    u, v = coords(n)
    warp = fbm(rng, n, 2, 6, gain=0.55)
    band = np.abs(np.sin(np.pi * (u + v) + 3.0 * warp))
    main = (1.0 - smoothstep(0.0, 0.05, band)) * 0.8 + (1.0 - smoothstep(0.0, 0.35, band)) * 0.25
    ridge = 1.0 - np.abs(fbm(rng, n, 3, 5, gain=0.45))
    fine = smoothstep(0.93, 0.99, ridge) * 0.5
    strength = 0.5 + 0.5 * smoothstep(-0.4, 0.4, fbm(rng, n, 2, 3))
    vein = np.clip((main + fine) * strength, 0.0, 1.0)
    cloud = fbm(rng, n, 2, 4)
    base = tinted(tint, 1.0 + 0.04 * cloud)
    color = blend(base, contrast_color(tint, 0.45), vein)
    height = 0.5 - 0.03 * vein
    return color, height, np.clip(roughness + 0.06 * vein, 0, 1)
