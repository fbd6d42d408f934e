"""Benchmark of material words (issue 15): how many of the plan's material words show in the GLB?

    PYTHONPATH=src .venv/bin/python benchmarks/material_words.py [--sets public,heldout_context,heldout_c] [--seeds 0,1,2] [--list] [--out FILE]

Each prompt and seed is generated in-process (offline planner), its house.glb written to
a temporary folder and read back, and scored with
:func:`anyhome.evaluate.material_words.material_words` (the figure ``anyhome eval``
prints for a house folder with its GLB): each (surface, phrase, word) of the house once,
realised when every node that carries it shows it (module doc). Printed: the share
realised, by kind of word (texture, weathering, ceiling structure), and with ``--list``
the words most often not shown.

The prompt sets are those of benchmarks/context.py (public: ../shared/eval/prompts.jsonl)
plus benchmarks/prompts/heldout_c.jsonl; measured, never tuned on.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

from anyhome.evaluate.expectations import load_prompt_records
from anyhome.evaluate.material_words import material_words
from anyhome.pipeline import generate, write_exports

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from context import SETS as CONTEXT_SETS  # noqa: E402

SETS = {**CONTEXT_SETS, "heldout_c": HERE / "prompts" / "heldout_c.jsonl"}
KINDS = ("texture", "weathering", "structure")


def run_set(path: Path, seeds: list[int]) -> dict[str, Any]:
    tot: dict[str, Any] = {"houses": 0, "n": 0, "met": 0, "by_kind": {k: [0, 0] for k in KINDS},
                           "misses": Counter(), "failures": []}
    with tempfile.TemporaryDirectory() as tmp:
        for rec in load_prompt_records(path):
            for seed in seeds:
                try:
                    house = generate(rec["prompt"], seed=seed)
                    out = Path(tmp) / f"{rec['id']}-{seed}"
                    write_exports(house, out, ["glb"])
                    rep = material_words(house, out / "house.glb")
                except Exception as e:  # an honest benchmark counts failures, it does not stop
                    tot["failures"].append(f"{rec['id']} seed {seed}: {e}")
                    continue
                tot["houses"] += 1
                tot["n"] += rep.n_words
                tot["met"] += rep.n_realised
                for k, (met, n) in rep.by_kind.items():
                    tot["by_kind"][k][0] += met
                    tot["by_kind"][k][1] += n
                tot["misses"].update(m.split(": ")[-1] + " on " + m.split(" ")[0] for m in rep.misses)
                (out / "house.glb").unlink()
    return tot


def _pct(met: int, n: int) -> str:
    return f"{100 * met / n:.1f} % ({met}/{n})" if n else "-"


def table(results: dict[str, dict[str, Any]], seeds: list[int]) -> str:
    names = list(results)
    out = [f"| figure (seeds {','.join(map(str, seeds))}) | bar | " + " | ".join(names) + " |",
           "|---|---|" + "---|" * len(names)]
    out.append("| houses (failed) |  | " + " | ".join(f"{r['houses']} ({len(r['failures'])})" for r in results.values()) + " |")
    out.append("| **material words shown in the GLB** | >= 90 % | "
               + " | ".join(_pct(r["met"], r["n"]) for r in results.values()) + " |")
    for k in KINDS:
        out.append(f"| ... {k} words |  | " + " | ".join(_pct(*r["by_kind"][k]) for r in results.values()) + " |")
    out.append("| words most often not shown |  | " + " | ".join(
        ", ".join(f"{w} ({n})" for w, n in r["misses"].most_common(4)) or "-" for r in results.values()) + " |")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sets", default="public,heldout_context,heldout_c")
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--list", action="store_true", help="print every word not shown, with its count")
    ap.add_argument("--out", help="also write the table to this file")
    args = ap.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")]
    results = {name: run_set(SETS[name], seeds) for name in args.sets.split(",")}
    text = table(results, seeds)
    if args.list:
        text += "\n\n" + "\n".join(f"- {n}: {w} x{c}" for n, r in results.items() for w, c in r["misses"].most_common())
        text += "\n" + "\n".join(f"- {n}: FAILED {f}" for n, r in results.items() for f in r["failures"])
    print(text)
    if args.out:
        Path(args.out).write_text(text + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
