"""Finishes: plaster and paint, brushed metal.

Plaster variants: ``plaster`` (trowelled, default), ``paint`` (orange peel),
``whitewash`` (brush strokes over a rough wall), ``smooth`` (vinyl, laminate).
"""

from __future__ import annotations

import numpy as np

from anyhome.materials.noise import (
    Pattern,
    blur,
    fbm,
    tinted,
    upsample,
    white,
)

PLASTER_RELIEF = {"plaster": 0.06, "paint": 0.012, "whitewash": 0.09, "smooth": 0.006}
"""Colour variation of each plaster variant."""
STREAK_LENGTH = 6
"""Lattice cells along u of the brushed-metal streaks (fewer = longer streaks)."""


def plaster(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    relief = PLASTER_RELIEF.get(variant, PLASTER_RELIEF["plaster"])
    cloud = fbm(rng, n, 2, 6, gain=0.6)
    trowel = fbm(rng, n, 3, 4, gain=0.5, aspect=2)
    peel = blur(white(rng, n), None, passes=2)
    shade = 1.0 + relief * (0.6 * cloud + 0.5 * trowel) + 0.15 * relief * peel
    if variant == "whitewash":
        strokes = fbm(rng, n, 2, 4, gain=0.7, aspect=12)
        shade = shade + 0.05 * strokes
    height = 0.5 + 0.3 * trowel * relief / 0.06 + 0.2 * peel * min(1.0, relief / 0.03)
    return tinted(tint, shade), height, np.clip(roughness + 0.05 * cloud, 0, 1)


def metal(rng: np.random.Generator, n: int, tint: np.ndarray, roughness: float, variant: str) -> Pattern:
    """Brushed metal: fine streaks along u."""
    rows = max(2, n // 2)
    lattice = rng.random((rows, STREAK_LENGTH)) - 0.5
    streaks = upsample(lattice, n)
    fine = blur(white(rng, n), 1, passes=4)
    cloud = fbm(rng, n, 2, 3)
    shade = 1.0 + 0.08 * streaks + 0.05 * fine + 0.04 * cloud
    height = 0.5 + 0.2 * streaks + 0.1 * fine
    return tinted(tint, shade), height, np.clip(roughness + 0.1 * streaks + 0.05 * cloud, 0, 1)
