"""Seeded, tileable procedural textures in numpy.

``generate(kind, size, tint, ...)`` returns a :class:`Texture`: a base colour (sRGB in
[0, 1]), a roughness map and a tangent-space normal map made from the pattern's height
field by finite differences. Every texture wraps at its edges; the same arguments give
identical arrays.

>>> tex = generate("planks", 64, "#a0714a")
>>> tex.color.shape, tex.normal.shape, tex.roughness.shape
((64, 64, 3), (64, 64, 3), (64, 64))
"""

from __future__ import annotations

import zlib
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from anyhome.assets.colors import to_rgba
from anyhome.materials.noise import FLOAT, Pattern, normal_map
from anyhome.materials.patterns import finish, masonry, textile, wood

Generator = Callable[[np.random.Generator, int, np.ndarray, float, str], Pattern]

GENERATORS: dict[str, Generator] = {
    "wood": wood.wood,
    "planks": wood.planks,
    "tile": masonry.tile,
    "marble": masonry.marble,
    "brick": masonry.brick,
    "stone": masonry.stone,
    "concrete": masonry.concrete,
    "plaster": finish.plaster,
    "metal": finish.metal,
    "fabric": textile.fabric,
    "carpet": textile.carpet,
    "wallpaper": textile.wallpaper,
    "tatami": textile.tatami,
}
"""Texture kind -> pattern generator."""

VARIANTS: dict[str, tuple[str, ...]] = {
    "planks": ("planks", "parquet", "shiplap", "logs"),
    "tile": ("square", "subway", "zellige", "terracotta"),
    "stone": ("flags", "rubble"),
    "concrete": ("concrete", "polished", "terrazzo"),
    "plaster": ("plaster", "paint", "whitewash", "smooth"),
    "fabric": ("weave", "velvet", "leather"),
    "wallpaper": ("stripes", "damask", "dots", "shoji"),
}
"""The named variants of each kind (the first is the default; others have one look)."""

BUMP: dict[str, float] = {
    "wood": 0.004, "planks": 0.012, "tile": 0.007, "marble": 0.004, "brick": 0.025,
    "stone": 0.03, "concrete": 0.006, "plaster": 0.012, "metal": 0.002, "fabric": 0.008,
    "carpet": 0.008, "wallpaper": 0.004, "tatami": 0.01,
}
"""Normal-map strength per kind: slope per unit of height per texture width."""

DEFAULT_SIZE_PX = 256


@dataclass(frozen=True, eq=False)
class Texture:
    """One generated texture set.

    color : (n, n, 3) float, sRGB in [0, 1]
    roughness : (n, n) float in [0, 1]
    normal : (n, n, 3) float, unit tangent-space normals (+x right, +y up, +z out)
    height : (n, n) float, the relief the normals were made from
    """

    color: np.ndarray
    roughness: np.ndarray
    normal: np.ndarray
    height: np.ndarray


def kinds() -> list[str]:
    """Every texture kind, sorted."""
    return sorted(GENERATORS)


def texture_seed(kind: str, variant: str = "", seed: int = 0) -> int:
    """A stable seed for a kind and variant (so equal materials share their maps)."""
    return zlib.crc32(f"{kind}/{variant}/{seed}".encode()) & 0x7FFFFFFF


def generate(kind: str, size: int = DEFAULT_SIZE_PX, tint: str = "#808080", roughness: float = 0.6,
             variant: str = "", seed: int = 0) -> Texture:
    """Generate a tileable texture.

    Parameters
    ----------
    kind : one of :func:`kinds`
    size : texels along each side
    tint : ``"#rrggbb"``, the colour the pattern is built around
    roughness : the base roughness the pattern varies around
    variant : a pattern variant of the kind (see :data:`VARIANTS`), "" for the default
    seed : varies the random layout; the same arguments give the same arrays
    """
    if kind not in GENERATORS:
        raise KeyError(f"unknown texture kind {kind!r} (known: {', '.join(kinds())})")
    n = int(size)
    if n < 8:
        raise ValueError(f"texture size must be at least 8 texels, got {size}")
    rng = np.random.default_rng(texture_seed(kind, variant, seed))
    rgb = (to_rgba(tint)[:3] / 255.0).astype(FLOAT)
    color, height, rough = GENERATORS[kind](rng, n, rgb, float(roughness), variant)
    color = np.clip(np.broadcast_to(color, (n, n, 3)), 0.0, 1.0).astype(FLOAT)
    rough = np.clip(np.broadcast_to(rough, (n, n)), 0.02, 1.0).astype(FLOAT)
    height = np.asarray(height, dtype=FLOAT)
    return Texture(color=color, roughness=rough, normal=normal_map(height, BUMP[kind]), height=height)
