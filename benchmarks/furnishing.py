"""Benchmark of furnishing (issue 14): furnishing metrics per prompt set, seeds, in one table.

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/furnishing.py \\
        --sets public,heldout_c,heldout_furnish --seeds 0,1,2 --out benchmarks/results/furnishing.md

Every house is generated in-process (``anyhome.generate``, offline planner; no export,
no render) and measured with :func:`anyhome.evaluate.evaluate_house` (its ``furnish``
figures, :mod:`anyhome.evaluate.furnish_metrics`, and the validity metrics
``n_floor_objects_reached`` / ``n_floor_objects``: furniture on the ground floor an
agent of 0.25 m radius can walk up to). The layout stage is timed per room: the run's
:class:`anyhome.stages.Stages` holds ``layout_house`` wrapped in a timer, and each room's
time is recorded with its object count.

``heldout_furnish`` was written by a helper who had not read the knowledge base, at the
start of the first furnishing session, before any furnishing change: measure on it,
never tune on it.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from anyhome.evaluate import evaluate_house
from anyhome.layout import solver as layout_solver
from anyhome.pipeline import generate
from anyhome.plan.knowledge import knowledge_base
from anyhome.stages import Stages

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floorplans import SETS as PLAN_SETS  # noqa: E402
from floorplans import add_common_args, chosen, emit, line_logger, load_prompts, pct  # noqa: E402

HERE = Path(__file__).resolve().parent
SETS = {**PLAN_SETS, "heldout_furnish": HERE / "prompts" / "heldout_furnish.jsonl"}


class RoomTimer:
    """``layout_solver.furnish_room`` wrapped: (objects placed, seconds) per room."""

    def __init__(self) -> None:
        self.rooms: list[tuple[int, float]] = []
        self._inner = layout_solver.furnish_room

    def __enter__(self) -> RoomTimer:
        def timed(st: Any) -> None:
            t0 = time.perf_counter()
            try:
                self._inner(st)
            finally:
                self.rooms.append((len(st.space.placed), time.perf_counter() - t0))

        layout_solver.furnish_room = timed
        return self

    def __exit__(self, *exc: object) -> None:
        layout_solver.furnish_room = self._inner


def run_set(name: str, prompts: list[tuple[str, str]], seeds: list[int],
            log: Callable[[str], None]) -> dict[str, Any]:
    kb = knowledge_base()
    tot: dict[str, Any] = {"set": name, "houses": 0, "violations": 0, "key_dropped": [],
                           "mismatched": [], "coverage": [], "relations": {}}
    keys = ("n_planned", "n_dropped", "n_key", "n_layers_planned", "n_layers_placed", "n_tv_stands",
            "n_tv_against_wall", "n_tv_with_seat", "n_tv_facing_seat", "n_tv_view_blocked", "n_sets",
            "n_kitchens", "n_kitchen_work_run", "n_kitchen_wall_cabinets")
    for k in keys + ("n_floor_objects", "n_floor_objects_reached"):
        tot[k] = 0
    with RoomTimer() as timer:
        for pid, text in prompts:
            for seed in seeds:
                house = generate(text, seed=seed, stages=Stages(), knowledge=kb)
                rep = evaluate_house(house, kb=kb)
                f = rep.furnish
                assert f is not None
                tot["houses"] += 1
                tot["violations"] += len(rep.violations)
                for k in keys:
                    tot[k] += getattr(f, k)
                tot["n_floor_objects"] += int(rep.metrics.get("n_floor_objects", 0))
                tot["n_floor_objects_reached"] += int(rep.metrics.get("n_floor_objects_reached", 0))
                tot["key_dropped"] += [f"{pid}/s{seed}/{k}" for k in f.key_dropped]
                tot["mismatched"] += [f"{pid}/s{seed}/{k}" for k in f.mismatched_sets]
                tot["coverage"] += list(f.coverage.values())
                for k, (met, n) in f.relations.items():
                    tot["relations"].setdefault(k, [0, 0])
                    tot["relations"][k][0] += met
                    tot["relations"][k][1] += n
                log(f"{name:16s} {pid[:28]:28s} s{seed} drop {f.n_dropped}/{f.n_planned} "
                    f"key {len(f.key_dropped)} rugs {f.n_layers_placed}/{f.n_layers_planned} "
                    f"tv {f.n_tv_against_wall}/{f.n_tv_stands} sets {len(f.mismatched_sets)}/{f.n_sets} "
                    f"low {f.n_low_coverage}/{len(f.coverage)} v={len(rep.violations)}")
    tot["rooms"] = timer.rooms
    return tot


def _frac(n: int, d: int) -> str:
    return f"{100 * n / d:.1f} % ({n}/{d})" if d else "-"


def _ms_by_count(rooms: list[tuple[int, float]]) -> str:
    bands = [(0, 9), (10, 19), (20, 29), (30, 10_000)]
    out = []
    for lo, hi in bands:
        ts = [t for n, t in rooms if lo <= n <= hi]
        if ts:
            out.append(f"{lo}-{hi if hi < 10_000 else '+'}: {1000 * statistics.median(ts):.0f}")
    return ", ".join(out)


def table(results: list[dict[str, Any]], seeds: list[int]) -> str:
    head = f"| figure (seeds {','.join(map(str, seeds))}) | bar | " + " | ".join(r["set"] for r in results) + " |"
    lines = [head, "|---|---|" + "---|" * len(results)]

    def row(label: str, bar: str, fmt: Callable[[dict[str, Any]], str]) -> None:
        lines.append(f"| {label} | {bar} | " + " | ".join(fmt(r) for r in results) + " |")

    row("houses", "", lambda r: str(r["houses"]))
    row("validity violations", "0", lambda r: str(r["violations"]))
    row("rugs and mats kept", ">= 90 %", lambda r: _frac(r["n_layers_placed"], r["n_layers_planned"]))
    row("items dropped", "<= 3 %", lambda r: _frac(r["n_dropped"], r["n_planned"]))
    row("key items dropped (named, room-defining)", "0", lambda r: f"{len(r['key_dropped'])} of {r['n_key']}")
    row("floor TV stands against a wall", "100 %", lambda r: _frac(r["n_tv_against_wall"], r["n_tv_stands"]))
    row("... facing the room's main seat (rooms with one)", "", lambda r: _frac(r["n_tv_facing_seat"], r["n_tv_with_seat"]))
    row("... view from it blocked", "", lambda r: str(r["n_tv_view_blocked"]))
    row("mismatched sets", "0", lambda r: f"{len(r['mismatched'])} of {r['n_sets']}")
    row("habitable rooms with floor coverage < 15 %", "<= 5 %",
        lambda r: _frac(sum(c < 0.15 for c in r["coverage"]), len(r["coverage"])))
    row("floor coverage of habitable rooms: median / p90", "20-50 %",
        lambda r: f"{100 * pct(r['coverage'], 50):.0f} % / {100 * pct(r['coverage'], 90):.0f} %" if r["coverage"] else "-")
    row("kitchens with sink, cooktop and fridge in counter runs", "", lambda r: _frac(r["n_kitchen_work_run"], r["n_kitchens"]))
    row("kitchens with wall cabinets over the counters", "", lambda r: _frac(r["n_kitchen_wall_cabinets"], r["n_kitchens"]))
    row("furniture reachable (ground floor, 0.25 m agent)", ">= 95 %",
        lambda r: _frac(r["n_floor_objects_reached"], r["n_floor_objects"]))
    row("relations the plans state, met", "", lambda r: _frac(sum(v[0] for v in r["relations"].values()),
                                                              sum(v[1] for v in r["relations"].values())))
    row("... kinds met below 95 %", "", lambda r: ", ".join(
        f"{k} {100 * v[0] / v[1]:.0f} % ({v[0]}/{v[1]})" for k, v in r["relations"].items()
        if v[1] and v[0] < 0.95 * v[1]) or "none")
    row("layout ms per room, median by objects placed", "30 objects <= 50", lambda r: _ms_by_count(r["rooms"]))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_common_args(ap, "public,heldout_c,heldout_furnish")
    ap.add_argument("--list", action="store_true", help="list the key items dropped and the mismatched sets")
    args = ap.parse_args(argv)
    picked = chosen(args, SETS)
    if picked is None:
        return 2
    seeds, names = picked
    t0 = time.perf_counter()
    results = [run_set(n, load_prompts(SETS[n]), seeds, line_logger(args)) for n in names]
    md = table(results, seeds) + f"\n\nWall time of the run: {time.perf_counter() - t0:.0f} s\n"
    if args.list:
        for r in results:
            md += f"\n{r['set']}: key items dropped: {', '.join(r['key_dropped']) or 'none'}\n"
            md += f"{r['set']}: mismatched sets: {', '.join(r['mismatched'][:40]) or 'none'}\n"
    emit(md, args.out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
