"""Benchmark of the offline planner (issue "open-vocabulary text").

    .venv/bin/python benchmarks/planner.py [--seeds 0,1,2] [--no-write]

For each prompt set (the public ../shared/eval/prompts.jsonl, and benchmarks/prompts/
dev.jsonl, heldout_a.jsonl, heldout_b.jsonl) and each seed it generates the house
in-process (plan, floorplan, layout, refine, assets; no files written) and reports
prompt coverage (``anyhome.evaluate``), validity violations, objects per habitable room
and how many distinct room programs the seeds give. It then times planning alone for
every prompt with each installed embedding backend, after the model is loaded (the
load, including embedding the concept tables, is timed separately), and compares the
backends on benchmarks/mapping_cases.yaml (see mapping.py). Results go between the
``planner`` and ``mapping`` markers of benchmarks/README.md.

The held-out sets were written by someone who had not read the knowledge base, and the
planner was not tuned on them when they were first measured. heldout_a and heldout_b were
measured at the end of the first open-vocabulary session and their failures were studied in
the second; heldout_c was written at the start of the second session and first run at its
end, so it is the clean number for that session.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from collections import Counter
from pathlib import Path

import numpy as np
import yaml

from anyhome.evaluate import evaluate_house, load_expectations
from anyhome.house import is_habitable
from anyhome.pipeline import generate
from anyhome.plan import concepts, get_planner
from anyhome.plan.embed import ENV_BACKEND, available_backends, get_embedder

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import mapping  # noqa: E402

SETS = {
    "public": HERE.parent.parent / "shared" / "eval" / "prompts.jsonl",
    "dev": HERE / "prompts" / "dev.jsonl",
    "heldout_a": HERE / "prompts" / "heldout_a.jsonl",
    "heldout_b": HERE / "prompts" / "heldout_b.jsonl",
    "heldout_c": HERE / "prompts" / "heldout_c.jsonl",
}


def run_set(path: Path, seeds: list[int]) -> dict:
    table = load_expectations(str(path))
    cov, viol, rooms_hab, objs_hab, fails, programs = [], 0, 0, 0, [], []
    worst: list[tuple[float, str]] = []
    for pid, entry in table.items():
        progs = set()
        scores = []
        for seed in seeds:
            try:
                house = generate(entry["prompt"], seed=seed)
            except Exception as e:  # an honest benchmark counts failures, it does not stop
                fails.append(f"{pid} seed {seed}: {e}")
                cov.append(0.0)
                scores.append(0.0)
                continue
            rep = evaluate_house(house, entry.get("expect"))
            viol += len(rep.violations)
            cov.append(rep.coverage.score)
            scores.append(rep.coverage.score)
            for r in house.rooms:
                if is_habitable(r.type):
                    rooms_hab += 1
                    objs_hab += sum(o.room == r.id for o in house.objects)
            progs.add(tuple(sorted(Counter(r.type for r in house.rooms).items())))
        programs.append(len(progs))
        worst.append((statistics.mean(scores), pid))
    return {
        "prompts": len(table), "houses": len(cov), "coverage": statistics.mean(cov),
        "violations": viol, "objects_per_habitable_room": objs_hab / max(1, rooms_hab),
        "distinct_programs_mean": statistics.mean(programs), "failures": fails,
        "weakest": [f"{p} {s:.0%}" for s, p in sorted(worst)[:5]],
    }  # fmt: skip


def plan_times(backend: str, prompts: list[str]) -> dict:
    emb = get_embedder(backend)  # its load_s is timed inside, at its first load
    concepts._index.cache_clear()  # the sets above built the default backend's tables already
    concepts._query_vector.cache_clear()
    t0 = time.perf_counter()
    for kind in concepts.KINDS:  # the tables the planner will use (built once per process)
        concepts.index(kind, backend)
    load_s = emb.load_s + time.perf_counter() - t0
    os.environ[ENV_BACKEND] = backend  # the planner asks get_embedder() for its backend
    planner = get_planner("offline")
    times = []
    for text in prompts:
        t = time.perf_counter()
        planner.plan(text, np.random.default_rng(0))
        times.append(time.perf_counter() - t)
    del os.environ[ENV_BACKEND]
    return {"backend": backend, "model_load_s": emb.load_s, "load_with_concepts_s": load_s,
            "median_ms": statistics.median(times) * 1000, "p90_ms": float(np.percentile(times, 90)) * 1000,
            "max_ms": max(times) * 1000, "prompts": len(times)}  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--no-write", action="store_true")
    args = ap.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")]
    results = {}
    for name, path in SETS.items():
        if not path.exists():
            print(f"skipping {name}: {path} not found", file=sys.stderr)
            continue
        results[name] = run_set(path, seeds)
        print(name, json.dumps(results[name]), flush=True)
    all_prompts = [e["prompt"] for p in SETS.values() if p.exists() for e in load_expectations(str(p)).values()]
    timing = [plan_times(b, all_prompts) for b in available_backends()]
    for t in timing:
        print(json.dumps(t), flush=True)
    cases = yaml.safe_load(mapping.CASES.read_text(encoding="utf-8"))
    maprows = [r for b in available_backends() for r in mapping.evaluate(b, cases, sweep=False)]
    if not args.no_write:
        (HERE / "results").mkdir(exist_ok=True)
        (HERE / "results" / "planner.json").write_text(json.dumps({"sets": results, "timing": timing, "mapping": maprows}, indent=1))
        _write(results, timing, seeds, maprows)
    return 0


def _replace(text: str, tag: str, lines: list[str]) -> str:
    a, b = f"<!-- {tag}:begin -->", f"<!-- {tag}:end -->"
    block = "\n".join([a, *lines, b])
    if a in text:
        return text[: text.index(a)] + block + text[text.index(b) + len(b) :]
    return text.rstrip() + "\n\n" + block + "\n"


def _write(results: dict, timing: list[dict], seeds: list[int], maprows: list[dict]) -> None:
    lines = [
        f"Seeds {', '.join(map(str, seeds))}; default embedding backend ({get_embedder().name}).",
        "",
        "| prompt set | prompts | houses | coverage | violations | objects / habitable room | distinct programs (of 3 seeds) | failures | weakest prompts |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, r in results.items():
        lines.append(
            f"| {name} | {r['prompts']} | {r['houses']} | {r['coverage'] * 100:.1f} % | {r['violations']} | "
            f"{r['objects_per_habitable_room']:.1f} | {r['distinct_programs_mean']:.2f} | {len(r['failures'])} | "
            f"{', '.join(r['weakest'])} |")
    lines += [
        "",
        f"Planning time per prompt ({timing[0]['prompts']} prompts of all sets, model already loaded):",
        "",
        "| backend | model load s | load + concept tables s | median ms | p90 ms | max ms |",
        "|---|---|---|---|---|---|",
    ]
    for t in timing:
        lines.append(f"| {t['backend']} | {t['model_load_s']:.2f} | {t['load_with_concepts_s']:.2f} | "
                     f"{t['median_ms']:.1f} | {t['p90_ms']:.1f} | {t['max_ms']:.1f} |")
    mlines = [
        "| backend | table | cases | listed | top-1 | easy | hard | threshold | accepted | precision | right & accepted | nonsense accepted | ms/query |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in maprows:
        mlines.append(
            f"| {r['backend']} | {r['table']} | {r['cases']} | {r['listed']} | {r['top1']:.0%} | {r['top1_easy']:.0%} | "
            f"{r['top1_hard']:.0%} | {r['threshold']:.2f} | {r['accepted']:.0%} | {r['precision']:.0%} | "
            f"{r['right_and_accepted']:.0%} | {r['nonsense_accepted']:.0%} | {r['ms_per_query']} |")
    readme = HERE / "README.md"
    text = _replace(readme.read_text(), "planner", lines)
    text = _replace(text, "mapping", mlines)
    readme.write_text(text)


if __name__ == "__main__":
    raise SystemExit(main())
