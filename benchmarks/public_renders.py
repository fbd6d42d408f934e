"""Bird's-eye renders of the 30 public prompts (seed 0) on one sheet, to see that styles
differ (haunted: dark wood, muted; Barbie: pink; tea house: tatami, light wood;
industrial loft: brick, metal).

    .venv/bin/python benchmarks/public_renders.py   # -> benchmarks/public_birdseye.png
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

from PIL import Image, ImageDraw

from anyhome.pipeline import generate
from anyhome.render import render_house

HERE = Path(__file__).resolve().parent
PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"
TILE_PX = 256
COLUMNS = 6


def main() -> int:
    recs = [json.loads(line) for line in PROMPTS.read_text().splitlines() if line.strip()]
    tiles = []
    with tempfile.TemporaryDirectory() as tmp:
        for r in recs:
            out = Path(tmp) / r["id"]
            render_house(generate(r["prompt"], seed=0), out, size_px=TILE_PX, views=False)
            im = Image.open(out / "birdseye.png").convert("RGB")
            ImageDraw.Draw(im).text((4, 4), r["id"], fill=(0, 0, 0))
            tiles.append(im)
    rows = -(-len(tiles) // COLUMNS)
    sheet = Image.new("RGB", (TILE_PX * COLUMNS, TILE_PX * rows), "white")
    for i, t in enumerate(tiles):
        sheet.paste(t, ((i % COLUMNS) * TILE_PX, (i // COLUMNS) * TILE_PX))
    sheet.save(HERE / "public_birdseye.png")
    print(HERE / "public_birdseye.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
