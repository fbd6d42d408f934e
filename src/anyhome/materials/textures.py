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
from anyhome.materials.noise import FLOAT, Pattern, blur, fbm, normal_map, smoothstep
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
    "fabric": ("weave", "velvet", "leather", "check"),
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


WEATHER_STAIN_DARKEN = 0.45
"""Most a weathered texture's stains darken its colour (fraction)."""
WEATHER_WEAR_FADE = 0.35
"""Most a weathered texture's worn patches fade towards grey-white (fraction)."""
WEATHER_FLAKE_SHARE = 0.12
"""Share of a weathered texture's area where the finish has flaked off (a paler,
rougher underlayer with a raised edge)."""


WEATHER_UNDERLAYER: dict[str, tuple[float, float, float]] = {
    "plaster": (0.86, 0.84, 0.80), "wallpaper": (0.86, 0.84, 0.80), "tile": (0.70, 0.68, 0.64),
    "metal": (0.48, 0.24, 0.12),
}
"""Kinds whose finish comes off where weathered, and the colour beneath (sRGB): paint and
paper flake to plaster, glaze chips to the tile's body, metal rusts."""


def weather(tex: Texture, rng: np.random.Generator, kind: str) -> Texture:
    """The texture aged: dark water stains and grime from low-frequency noise, faded worn
    patches, and flakes where the finish has come off (paler, rougher, with an edge in
    the relief); rougher everywhere. Tileable as its input (the noise wraps)."""
    n = tex.color.shape[0]
    stain = smoothstep(0.1, 0.9, fbm(rng, n, 3, octaves=4) * 0.5 + 0.5)
    wear = smoothstep(0.55, 0.95, fbm(rng, n, 5, octaves=3) * 0.5 + 0.5)
    flake_field = fbm(rng, n, 8, octaves=4) * 0.5 + 0.5
    flakes = (flake_field > np.quantile(flake_field, 1.0 - WEATHER_FLAKE_SHARE)).astype(FLOAT)
    color = tex.color * (1.0 - WEATHER_STAIN_DARKEN * stain[..., None] ** 1.5)
    grey = np.full_like(color, 0.78)
    color = color + (grey - color) * (WEATHER_WEAR_FADE * wear)[..., None]
    under = WEATHER_UNDERLAYER.get(kind)
    if under is None:  # wood, stone, fabric: no finish to flake off, only dust in the worn patches
        flakes = np.zeros_like(flakes)
        color = color + (grey - color) * (0.25 * wear)[..., None]
    else:  # paint and paper flake off to plaster; metal rusts through
        color = color + (np.array(under, FLOAT) - color) * (0.8 * flakes)[..., None]
    rough = np.clip(tex.roughness + 0.25 * stain + 0.3 * flakes, 0.02, 1.0).astype(FLOAT)
    height = tex.height - 0.6 * blur(flakes, passes=1) * float(np.ptp(tex.height) or 1.0)
    return Texture(color=np.clip(color, 0.0, 1.0).astype(FLOAT), roughness=rough,
                   normal=normal_map(height, BUMP[kind]), height=height)


def generate(kind: str, size: int = DEFAULT_SIZE_PX, tint: str = "#808080", roughness: float = 0.6,
             variant: str = "", seed: int = 0, weathered: bool = False) -> Texture:
    """Generate a tileable texture.

    Parameters
    ----------
    kind : one of :func:`kinds`
    size : texels along each side
    tint : ``"#rrggbb"``, the colour the pattern is built around
    roughness : the base roughness the pattern varies around
    variant : a pattern variant of the kind (see :data:`VARIANTS`), "" for the default
    seed : varies the random layout; the same arguments give the same arrays
    weathered : aged by :func:`weather` (stains, worn patches, flaked finish)
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
    tex = Texture(color=color, roughness=rough, normal=normal_map(height, BUMP[kind]), height=height)
    return weather(tex, np.random.default_rng(texture_seed(kind, variant + "/weathered", seed)), kind) if weathered else tex
