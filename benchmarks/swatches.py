"""Render a labelled sheet of material swatches: every material word of the knowledge
base (materials.yaml ``words`` with a texture kind) on the surface it goes on (its first
``goes_on``, else the surface its kind is made for), or all of them weathered.

    PYTHONPATH=src .venv/bin/python benchmarks/swatches.py [--out benchmarks/swatches.png] [--tile 96] [--weathered]

Each tile is the base-colour texture :func:`anyhome.materials.images.texture_images`
makes for ``surface_material(word, surface)``, shaded by its normal map under one light so relief shows; untextured
kinds (plain, glass) are their flat colour. The label is the word and the kind/variant.
Look at it: two words that should differ (walnut and oak, zellige and subway) must.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from anyhome.assets.colors import to_rgba
from anyhome.materials.catalog import surface_material
from anyhome.materials.images import texture_images
from anyhome.plan.knowledge import knowledge_base

OUT = Path(__file__).with_name("swatches.png")
COLUMNS = 12
LABEL_PX = 22
LIGHT = np.array([-0.4, 0.5, 0.77])
"""Direction towards the light in the texture's tangent space (upper left, in front)."""


KIND_SURFACE = {"planks": "floor", "tile": "floor", "marble": "floor", "stone": "floor", "concrete": "floor",
                "tatami": "floor", "carpet": "floor", "brick": "walls", "plaster": "walls", "wallpaper": "walls"}
"""Where a word without ``goes_on`` is shown: the surface its kind is made for (furniture else)."""


def _tile(word: str, surface: str, px: int, aged: bool) -> Image.Image:
    spec = surface_material(f"weathered {word}" if aged else word, surface, size_px=px)
    if spec.textured:
        base, _, normal = texture_images(spec)
        rgb = np.asarray(base, dtype=float) / 255.0
        n = np.asarray(normal, dtype=float) / 127.5 - 1.0
        shade = np.clip(n @ (LIGHT / np.linalg.norm(LIGHT)), 0.0, 1.0)
        rgb = np.clip(rgb * (0.55 + 0.55 * shade[..., None]), 0.0, 1.0)
        img = Image.fromarray((rgb * 255).astype(np.uint8), "RGB")
    else:
        img = Image.new("RGB", (px, px), tuple(int(c) for c in to_rgba(spec.color)[:3]))
    tile = Image.new("RGB", (px, px + LABEL_PX), (255, 255, 255))
    tile.paste(img.resize((px, px)), (0, 0))
    draw = ImageDraw.Draw(tile)
    font = ImageFont.load_default()
    kind = spec.kind + (f"/{spec.variant}" if spec.variant else "")
    draw.text((2, px), word[:18], fill=(0, 0, 0), font=font)
    draw.text((2, px + 10), kind[:18], fill=(90, 90, 90), font=font)
    return tile


def swatches(px: int = 96, aged: bool = False) -> Image.Image:
    kb = knowledge_base()
    words = [(w, (e.goes_on or [KIND_SURFACE.get(str(e.kind), "furniture")])[0])
             for w, e in kb.materials.words.items() if e.kind is not None]
    rows = -(-len(words) // COLUMNS)
    sheet = Image.new("RGB", (COLUMNS * (px + 4), rows * (px + LABEL_PX + 4)), (236, 238, 241))
    for i, (word, surface) in enumerate(words):
        r, c = divmod(i, COLUMNS)
        sheet.paste(_tile(word, surface, px, aged), (c * (px + 4) + 2, r * (px + LABEL_PX + 4) + 2))
    return sheet


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--tile", type=int, default=96)
    ap.add_argument("--weathered", action="store_true", help="every word weathered")
    args = ap.parse_args(argv)
    swatches(args.tile, args.weathered).save(args.out)
    print(args.out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
