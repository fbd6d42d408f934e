"""Benchmark: every public prompt x seeds, timings per stage, validity and coverage.

Usage: .venv/bin/python benchmarks/run.py [--prompts FILE] [--seeds 0,1,2] [--no-write]

Writes benchmarks/results/latest.json and the table between the markers in
benchmarks/README.md. Each house is generated in-process and written (house.json,
house.glb, floorplan.svg) to a temporary folder, so the time includes the exports.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from anyhome.evaluate import evaluate_house, load_expectations
from anyhome.pipeline import generate, write_outputs

HERE = Path(__file__).resolve().parent
DEFAULT_PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"
MARK_BEGIN = "<!-- results:begin -->"
MARK_END = "<!-- results:end -->"
TWELVE_ROOMS = (
    "A large house with six bedrooms, three bathrooms, a kitchen, a living room, "
    "a dining room and a study."
)


def run_one(prompt: str, seed: int, tmp: Path) -> dict:
    t0 = time.perf_counter()
    house = generate(prompt, seed=seed)
    timings = dict(house.timings_s)
    write_outputs(house, tmp / f"h{seed}", timings=timings)
    total = time.perf_counter() - t0
    return {"house": house, "timings": timings, "total_s": total}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--prompts", default=str(DEFAULT_PROMPTS))
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--no-write", action="store_true", help="print only, leave README alone")
    args = ap.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")]
    table = load_expectations(args.prompts)
    rows, totals, stage_times = [], [], {}
    violations_total, cov_scores = 0, []
    with tempfile.TemporaryDirectory() as td:
        for pid, entry in table.items():
            per_seed = []
            for seed in seeds:
                r = run_one(entry["prompt"], seed, Path(td) / pid)
                te = time.perf_counter()
                rep = evaluate_house(r["house"], entry.get("expect"))
                stage_times.setdefault("eval", []).append(time.perf_counter() - te)
                n_viol = len(rep.violations)
                violations_total += n_viol
                cov = rep.coverage.score if rep.coverage is not None else float("nan")
                cov_scores.append(cov)
                totals.append(r["total_s"])
                for k, v in r["timings"].items():
                    stage_times.setdefault(k, []).append(v)
                per_seed.append((r, rep, n_viol, cov))
                print(f"{pid:<18} seed {seed}: {r['total_s']:.2f}s  rooms "
                      f"{len(r['house'].rooms):2d} objects {len(r['house'].objects):3d} "
                      f"violations {n_viol}  coverage {cov:.2f}", flush=True)
            fps = {json.dumps([rm.polygon for rm in r["house"].rooms]) for r, *_ in per_seed}
            rows.append({
                "id": pid,
                "rooms": statistics.mean(len(r["house"].rooms) for r, *_ in per_seed),
                "objects": statistics.mean(len(r["house"].objects) for r, *_ in per_seed),
                "dropped": statistics.mean(len(r["house"].dropped) for r, *_ in per_seed),
                "violations": sum(v for _, _, v, _ in per_seed),
                "coverage": statistics.mean(c for *_, c in per_seed),
                "median_s": statistics.median(r["total_s"] for r, *_ in per_seed),
                "distinct_floorplans": len(fps),
            })
        big = []
        for seed in seeds:
            r = run_one(TWELVE_ROOMS, seed, Path(td) / "twelve")
            big.append((len(r["house"].rooms), r["total_s"]))
    summary = {
        "houses": len(totals),
        "median_total_s": statistics.median(totals),
        "p90_total_s": float(np.percentile(totals, 90)),
        "max_total_s": max(totals),
        "median_stage_s": {k: statistics.median(v) for k, v in stage_times.items()},
        "violations": violations_total,
        "coverage_mean": statistics.mean(cov_scores),
        "twelve_room": [{"rooms": n, "total_s": t} for n, t in big],
        "machine": f"{platform.processor() or platform.machine()}, python {platform.python_version()}",
    }
    print(json.dumps(summary, indent=1))
    if not args.no_write:
        (HERE / "results").mkdir(exist_ok=True)
        (HERE / "results" / "latest.json").write_text(
            json.dumps({"summary": summary, "rows": rows}, indent=1))
        _write_readme(summary, rows)
    return 0


def _write_readme(summary: dict, rows: list[dict]) -> None:
    st = summary["median_stage_s"]
    lines = [
        MARK_BEGIN,
        f"Houses: {summary['houses']} (public prompts x seeds). "
        f"Median time per house {summary['median_total_s']:.2f} s, p90 "
        f"{summary['p90_total_s']:.2f} s, max {summary['max_total_s']:.2f} s "
        "(generate + write house.json, GLB, SVG).",
        "",
        "Median per stage: " + ", ".join(f"{k} {v * 1000:.0f} ms" for k, v in st.items()),
        "",
        "12-room program: " + ", ".join(
            f"{b['rooms']} rooms in {b['total_s']:.2f} s" for b in summary["twelve_room"]),
        "",
        f"Validity violations (SCENE_FORMAT rules 1-6 + windows): **{summary['violations']}**. "
        f"Mean prompt coverage: **{summary['coverage_mean'] * 100:.1f} %**.",
        "",
        "| prompt | rooms | objects | dropped | violations | coverage | median s | distinct floorplans |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['id']} | {r['rooms']:.1f} | {r['objects']:.1f} | {r['dropped']:.1f} | "
            f"{r['violations']} | {r['coverage'] * 100:.0f} % | {r['median_s']:.2f} | "
            f"{r['distinct_floorplans']} |")
    lines.append(MARK_END)
    readme = HERE / "README.md"
    text = readme.read_text()
    a, b = text.index(MARK_BEGIN), text.index(MARK_END) + len(MARK_END)
    readme.write_text(text[:a] + "\n".join(lines) + text[b:])


if __name__ == "__main__":
    sys.exit(main())
