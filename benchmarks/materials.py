"""Benchmark: procedural texture generation per kind, and GLB size and time per house.

Usage: .venv/bin/python benchmarks/materials.py [--prompts FILE] [--seed 0] [--sizes 256,512]
       [--repeat 5]

Prints markdown tables: milliseconds per texture kind and size (median of ``--repeat``
runs, CPU time of one process), then for every public prompt the GLB size and the time
of ``write_glb`` with cold texture caches (as in a one-house CLI run) and warm ones (as
in a long-running process), at each texture size. Nothing is written to the repository.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

from anyhome.export import write_glb
from anyhome.materials.gltf import read_glb
from anyhome.materials.images import clear_caches
from anyhome.materials.textures import VARIANTS, generate, kinds
from anyhome.pipeline import generate as generate_house

HERE = Path(__file__).resolve().parent
DEFAULT_PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"
TINT = "#a0714a"


def texture_table(sizes: list[int], repeat: int) -> list[str]:
    rows = ["| kind | variant | " + " | ".join(f"{s} px ms" for s in sizes) + " |",
            "|---|---|" + "---|" * len(sizes)]
    worst = dict.fromkeys(sizes, 0.0)
    for kind in kinds():
        for variant in VARIANTS.get(kind, ("",)):
            cells = []
            for size in sizes:
                times = []
                for _ in range(repeat):
                    t0 = time.process_time()
                    generate(kind, size, TINT, 0.5, variant)
                    times.append(time.process_time() - t0)
                ms = statistics.median(times) * 1000
                worst[size] = max(worst[size], ms)
                cells.append(f"{ms:.1f}")
            rows.append(f"| {kind} | {variant or '-'} | " + " | ".join(cells) + " |")
    rows.append("| **slowest** | | " + " | ".join(f"**{worst[s]:.1f}**" for s in sizes) + " |")
    return rows


def glb_stats(path: Path) -> dict:
    tree, _ = read_glb(path.read_bytes())
    mats = tree.get("materials", [])
    textured = sum("normalTexture" in m for m in mats)
    return {"materials": len(mats), "textured": textured, "images": len(tree.get("images", []))}


def house_table(prompts: Path, seed: int, sizes: list[int]) -> list[str]:
    head = "| prompt | rooms | objects | materials (textured) | images |"
    head += "".join(f" {s} px MB | {s} px cold s | {s} px warm s |" for s in sizes)
    rows = [head, "|---|---|---|---|---|" + "---|---|---|" * len(sizes)]
    totals: dict[int, dict[str, list[float]]] = {s: {"mb": [], "cold": [], "warm": []} for s in sizes}
    entries = [json.loads(line) for line in prompts.read_text(encoding="utf-8").splitlines() if line.strip()]
    with tempfile.TemporaryDirectory() as td:
        for entry in entries:
            house = generate_house(entry["prompt"], seed=seed)
            cells, stats = [], {}
            for size in sizes:
                clear_caches()
                t0 = time.perf_counter()
                path = write_glb(house, Path(td) / f"{entry['id']}-{size}.glb", texture_px=size)
                cold = time.perf_counter() - t0
                t0 = time.perf_counter()
                write_glb(house, path, texture_px=size)
                warm = time.perf_counter() - t0
                mb = path.stat().st_size / 2**20
                stats = glb_stats(path)
                for key, value in (("mb", mb), ("cold", cold), ("warm", warm)):
                    totals[size][key].append(value)
                cells.append(f" {mb:.2f} | {cold:.2f} | {warm:.2f} |")
            rows.append(f"| {entry['id']} | {len(house.rooms)} | {len(house.objects)} | "
                        f"{stats['materials']} ({stats['textured']}) | {stats['images']} |" + "".join(cells))
    summary = "| **median** | | | | |"
    summary += "".join(f" **{statistics.median(totals[s]['mb']):.2f}** | **{statistics.median(totals[s]['cold']):.2f}**"
                       f" | **{statistics.median(totals[s]['warm']):.2f}** |" for s in sizes)
    summary_max = "| **max** | | | | |"
    summary_max += "".join(f" {max(totals[s]['mb']):.2f} | {max(totals[s]['cold']):.2f}"
                           f" | {max(totals[s]['warm']):.2f} |" for s in sizes)
    return [*rows, summary, summary_max]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--prompts", default=str(DEFAULT_PROMPTS))
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--sizes", default="256,512")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")]
    print("## Texture generation (CPU ms per texture, median)\n")
    print("\n".join(texture_table(sizes, args.repeat)))
    print(f"\n## GLB per public prompt (seed {args.seed})\n")
    print("\n".join(house_table(Path(args.prompts), args.seed, sizes)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
