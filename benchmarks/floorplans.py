"""Benchmark of floorplans (issue 13): plan metrics per prompt set, seeds, in one table.

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/floorplans.py \\
        --sets public,heldout_c,heldout_plan --seeds 0,1,2 --out benchmarks/results/floorplans.md

Every house is generated in-process (``anyhome.generate``, offline planner; no export,
no render) and measured with :func:`anyhome.evaluate.plan_metrics.plan_metrics` and
:func:`anyhome.evaluate.evaluate_house`. The floorplan stage is timed directly: the
run's :class:`anyhome.stages.Stages` holds ``solve_floorplan`` wrapped in a timer.

Definitions (see also anyhome/evaluate/plan_metrics.py):

- home: :func:`anyhome.evaluate.plan_metrics.is_home` (``house.building`` a dwelling
  of programs.yaml, a building word whose program is one, or an unknown word with a
  bedroom or a living room);
- reuse: the share of pairs of houses of DIFFERENT prompts (all seeds) whose room-size
  signatures mostly coincide: at least 70 % of the rooms of EACH house match a room of
  the other (short and long side each within 0.5 m, each room matched once). The table
  also gives the looser figure over the smaller house's rooms only (a one-room studio
  whose room matches one of a mansion's counts there), and the same figure for pairs of
  seeds of ONE prompt (how much the seed changes the plan);
- courtyards inside the footprint, footprint shapes: see
  anyhome/evaluate/footprint.py (a courtyard is inside when less than 30 % of its
  perimeter lies on its level's outline: rooms on at least three sides);
- the 40-room timing: a hotel-floor spec of 40 rooms (a corridor, 19 guest rooms,
  19 bathrooms, a linen room) given to the floorplan stage, when HouseSpec accepts it.
"""

from __future__ import annotations

import argparse
import itertools
import json
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from anyhome.errors import AnyHomeError
from anyhome.evaluate import evaluate_house
from anyhome.evaluate.footprint import INSIDE_MAX_SHARE, SHAPES
from anyhome.evaluate.plan_metrics import (
    BLOAT_FACTOR,
    BLOAT_MIN_M2,
    PlanMetrics,
    signatures_share_most,
)
from anyhome.floorplan import solve_floorplan
from anyhome.floorplan.levels import solve_levels
from anyhome.pipeline import generate
from anyhome.plan.knowledge import knowledge_base
from anyhome.stages import Stages

HERE = Path(__file__).resolve().parent
SETS = {
    "public": HERE.parent / "tests" / "data" / "public_prompts.jsonl",
    "heldout_c": HERE / "prompts" / "heldout_c.jsonl",
    "heldout_plan": HERE / "prompts" / "heldout_plan.jsonl",
    "dev": HERE / "prompts" / "dev.jsonl",
    "heldout_storeys": HERE / "prompts" / "heldout_storeys.jsonl",
    "heldout_storeys2": HERE / "prompts" / "heldout_storeys2.jsonl",
    "heldout_storeys3": HERE / "prompts" / "heldout_storeys3.jsonl",
    "heldout_storeys4": HERE / "prompts" / "heldout_storeys4.jsonl",
    "dev_storeys": HERE / "prompts" / "dev_storeys.jsonl",
    "dev_storeys2": HERE / "prompts" / "dev_storeys2.jsonl",
    "dev_storeys3": HERE / "prompts" / "dev_storeys3.jsonl",
    "dev_size": HERE / "prompts" / "dev_size.jsonl",
    "dev_storeys4": HERE / "prompts" / "dev_storeys4.jsonl",
    "dev_size2": HERE / "prompts" / "dev_size2.jsonl",
}
"""``dev``, ``dev_storeys``, ``dev_storeys2``, ``dev_storeys3``, ``dev_storeys4`` (multi-storey homes), ``dev_size`` and
``dev_size2`` (stated totals, grand homes) are the sets to tune on; the held-out sets are for measuring only."""
OVERHANG_TOL_M2 = 1.0
"""An upper storey may hang over nothing by this much (wall thickness, rounding)."""
SMALL_HOME_ROOMS = 8
"""The corridor bar applies to homes of at most this many rooms."""


def load_prompts(path: Path) -> list[tuple[str, str]]:
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.strip():
            d = json.loads(line)
            out.append((d["id"], d["prompt"]))
    return out


def pct(xs: list[float], q: float) -> float:
    return float(np.percentile(xs, q)) if xs else float("nan")


class TimedFloorplan:
    """The default floorplan stage (``floorplan.levels.solve_levels``: one storey is
    ``solve_floorplan`` itself) with its wall time recorded per call."""

    def __init__(self) -> None:
        self.times_s: list[float] = []

    def __call__(self, spec: Any, rng: np.random.Generator) -> Any:
        t0 = time.perf_counter()
        try:
            return solve_levels(spec, rng)
        finally:
            self.times_s.append(time.perf_counter() - t0)


def run_set(name: str, prompts: list[tuple[str, str]], seeds: list[int],
            log: Callable[[str], None]) -> dict[str, Any]:
    kb = knowledge_base()
    timer = TimedFloorplan()
    stages = Stages(floorplan=timer)
    rows: list[tuple[str, int, PlanMetrics, int]] = []
    failures: list[str] = []
    for pid, prompt in prompts:
        for seed in seeds:
            try:
                house = generate(prompt, seed=seed, stages=stages, knowledge=kb)
            except AnyHomeError as e:  # counted, not fatal: the table reports failures
                failures.append(f"{pid} seed {seed}: {e}")
                log(f"{name:<12} {pid:<28} seed {seed}: FAILED {e}")
                continue
            rep = evaluate_house(house, kb=kb)
            assert rep.plan is not None
            rows.append((pid, seed, rep.plan, len(rep.violations)))
            log(f"{name:<12} {pid:<28} seed {seed}: {rep.plan.n_rooms:2d} rooms "
                f"{rep.plan.total_area_m2:6.1f} m2 circ {rep.plan.circulation_share:.2f} "
                f"corr {rep.plan.longest_corridor_m:4.1f} m fp {1000 * timer.times_s[-1]:.0f} ms "
                f"viol {len(rep.violations)}{_size_note(rep.plan)}")
    summary = summarise(name, rows, timer.times_s)
    summary["failures"] = failures
    return summary


def _size_note(p: PlanMetrics) -> str:
    """What the evaluator read of the prompt's size, and its verdicts (empty when none)."""
    parts = []
    if p.size_words:
        parts.append("/".join(p.size_words))
    if p.stated_area_m2 is not None:
        parts.append(f"stated {p.stated_area_m2:g} m2")
    bad = [k for k in ("tiny_ok", "stated_area_ok", "mansion_ok") if getattr(p, k) is False]
    if bad:
        parts.append("MISSED " + ",".join(bad))
    return (" | " + " ".join(parts)) if parts else ""


def summarise(name: str, rows: list[tuple[str, int, PlanMetrics, int]], fp_times: list[float]) -> dict[str, Any]:
    plans = [p for _, _, p, _ in rows]
    homes = [p for p in plans if p.is_home]
    circ = [p.circulation_share for p in homes]
    small_homes = [p for p in homes if p.n_rooms <= SMALL_HOME_ROOMS]
    habitable = sum(p.n_habitable for p in plans)
    strips = sum(p.n_habitable_aspect_over_2 for p in plans)
    verdicts: dict[str, tuple[int, int]] = {}
    for key in ("tiny_ok", "stated_area_ok", "mansion_ok"):
        vs = [getattr(p, key) for p in plans if getattr(p, key) is not None]
        verdicts[key] = (sum(vs), len(vs))
    pairs = [(a, b) for a, b in itertools.combinations(rows, 2) if a[0] != b[0]]
    shared = sum(signatures_share_most(a[2].signature, b[2].signature) for a, b in pairs)
    same = [(a, b) for a, b in itertools.combinations(rows, 2) if a[0] == b[0]]
    same_shared = sum(signatures_share_most(a[2].signature, b[2].signature) for a, b in same)
    shared_small = sum(signatures_share_most(a[2].signature, b[2].signature, of="smaller") for a, b in pairs)
    return {
        "set": name,
        "houses": len(plans),
        "homes": len(homes),
        "circ_median": statistics.median(circ) if circ else float("nan"),
        "circ_p90": pct(circ, 90),
        "small_homes": len(small_homes),
        "longest_corridor_small_home_m": max((p.longest_corridor_m for p in small_homes), default=0.0),
        "small_homes_corridor_over_8m": sum(p.longest_corridor_m > 8.0 for p in small_homes),
        "longest_corridor_m": max((p.longest_corridor_m for p in plans), default=0.0),
        "habitable": habitable,
        "aspect_over_2_share": strips / habitable if habitable else 0.0,
        "bedrooms": sum(p.n_bedrooms for p in plans),
        "bedrooms_narrow": sum(p.n_bedrooms_narrow for p in plans),
        "living": sum(p.n_living_rooms for p in plans),
        "living_narrow": sum(p.n_living_rooms_narrow for p in plans),
        "below_type_norm": sum(p.n_below_type_min_width for p in plans),
        "oversized": sum(p.n_oversized for p in plans),
        "bloated": sum(p.n_bloated for p in plans),
        "worst_area_ratio": max((p.worst_area_ratio for p in plans), default=0.0),
        "planned": sum(p.n_planned for p in plans),
        "rooms": sum(p.n_rooms for p in plans),
        "open_air": sum(p.n_open_air for p in plans),
        "open_air_with_ceiling": sum(p.n_open_air_with_ceiling for p in plans),
        "verdicts": verdicts,
        "pairs": len(pairs),
        "reuse_pairs": shared,
        "reuse_share": shared / len(pairs) if pairs else 0.0,
        "reuse_pairs_smaller": shared_small,
        "seed_pairs": len(same),
        "seed_pairs_shared": same_shared,
        "max_levels": max((p.levels for p in plans), default=1),
        "multi_level": sum(p.levels > 1 for p in plans),
        "overhanging": sum(p.overhang_m2 > OVERHANG_TOL_M2 for p in plans),
        "overhang_m2": sum(p.overhang_m2 for p in plans),
        "all_reachable": sum(p.all_reachable for p in plans),
        "max_rooms": max((p.n_rooms for p in plans), default=0),
        "violations": sum(v for *_, v in rows),
        "houses_with_violations": sum(v > 0 for *_, v in rows),
        "courtyards": sum(len(p.courtyard_shares) for p in plans),
        "courtyards_inside": sum(p.n_courtyards_inside for p in plans),
        "courtyards_enclosed": sum(p.n_courtyards_enclosed for p in plans),
        "shapes": {k: sum(p.footprint == k for p in plans) for k in SHAPES},
        "l_rooms": sum(p.n_l_rooms for p in plans),
        "houses_with_l": sum(p.n_l_rooms > 0 for p in plans),
        "fp_median_ms": 1000 * statistics.median(fp_times),
        "fp_p90_ms": 1000 * pct(fp_times, 90),
        "fp_max_ms": 1000 * max(fp_times),
    }


def forty_rooms() -> str:
    """Time the floorplan stage on a 40-room hotel floor, or say why it cannot run."""
    from pydantic import ValidationError

    from anyhome.plan.spec import HouseSpec, kb_context

    kb = knowledge_base()
    rooms = [{"id": "corridor", "name": "corridor", "type": "hallway", "area_m2": 60.0},
             {"id": "linen", "name": "linen room", "type": "storage", "area_m2": 6.0}]
    conns = [["corridor", "outside"], ["linen", "corridor"]]
    for i in range(19):
        rooms.append({"id": f"guest{i}", "name": "guest room", "type": "bedroom", "area_m2": 14.0})
        rooms.append({"id": f"bath{i}", "name": "bathroom", "type": "bathroom", "area_m2": 4.0})
        conns += [[f"guest{i}", "corridor"], [f"bath{i}", f"guest{i}"]]
    data = {"prompt": "a hotel floor of 40 rooms", "building": "hotel", "rooms": rooms, "connections": conns}
    try:
        spec = HouseSpec.model_validate(data, context=kb_context(kb))
    except ValidationError as e:
        first = e.errors()[0]
        return f"not possible: HouseSpec refuses 40 rooms ({'.'.join(map(str, first['loc']))}: {first['msg']})"
    t0 = time.perf_counter()
    try:
        fp = solve_floorplan(spec, np.random.default_rng(0))
    except AnyHomeError as e:
        return f"failed after {time.perf_counter() - t0:.2f} s: {e}"
    return f"{len(fp.rooms)} rooms in {time.perf_counter() - t0:.2f} s"


def _frac(n: int, d: int) -> str:
    return f"{n}/{d}" if d else "-"


def table(results: list[dict[str, Any]], seeds: list[int]) -> str:
    cols = [r["set"] for r in results]
    lines = [f"| figure (seeds {','.join(map(str, seeds))}) | bar | " + " | ".join(cols) + " |",
             "|---|---|" + "---|" * len(cols)]

    def row(label: str, bar: str, fmt: Callable[[dict[str, Any]], str]) -> None:
        lines.append(f"| {label} | {bar} | " + " | ".join(fmt(r) for r in results) + " |")

    row("houses (homes)", "", lambda r: f"{r['houses']} ({r['homes']})")
    row("prompts x seeds that failed (FloorplanError...)", "0", lambda r: str(len(r["failures"])))
    row("circulation share, homes: median", "<= 0.12", lambda r: f"{r['circ_median']:.3f}")
    row("circulation share, homes: p90", "<= 0.18", lambda r: f"{r['circ_p90']:.3f}")
    row("longest corridor, homes of <= 8 rooms (m)", "<= 8", lambda r: f"{r['longest_corridor_small_home_m']:.1f}")
    row("homes of <= 8 rooms with a corridor > 8 m", "0", lambda r: _frac(r["small_homes_corridor_over_8m"], r["small_homes"]))
    row("longest corridor, any house (m)", "", lambda r: f"{r['longest_corridor_m']:.1f}")
    row("habitable rooms with aspect > 2", "<= 3 %", lambda r: f"{100 * r['aspect_over_2_share']:.1f} % of {r['habitable']}")
    row("bedrooms narrower than 2.4 m", "0", lambda r: _frac(r["bedrooms_narrow"], r["bedrooms"]))
    row("living rooms narrower than 3.0 m", "0", lambda r: _frac(r["living_narrow"], r["living"]))
    row("rooms below their type's min_width_m", "", lambda r: _frac(r["below_type_norm"], r["rooms"]))
    row("rooms drawn at > 2x their planned area", "", lambda r: _frac(r["oversized"], r["planned"]))
    row(f"rooms drawn at > {BLOAT_FACTOR:g}x their planned area and > {BLOAT_MIN_M2:g} m2 (worst ratio)", "",
        lambda r: f"{_frac(r['bloated'], r['planned'])} ({r['worst_area_ratio']:.1f}x)")
    row("open-air rooms with a ceiling", "0", lambda r: _frac(r["open_air_with_ceiling"], r["open_air"]))
    row('"tiny" homes <= 45 m2 (met/asked)', "all", lambda r: _frac(*r["verdicts"]["tiny_ok"]))
    row("stated areas within 15 % (met/asked)", "all", lambda r: _frac(*r["verdicts"]["stated_area_ok"]))
    row('"mansion"/"grand" homes >= 300 m2 (met/asked)', "all", lambda r: _frac(*r["verdicts"]["mansion_ok"]))
    row("pairs of different prompts sharing most room sizes", "<= 3 %",
        lambda r: f"{100 * r['reuse_share']:.1f} % ({r['reuse_pairs']}/{r['pairs']})")
    row("... different prompts, most of the smaller house's room sizes", "",
        lambda r: f"{100 * r['reuse_pairs_smaller'] / max(r['pairs'], 1):.1f} % ({r['reuse_pairs_smaller']}/{r['pairs']})")
    row("pairs of seeds of one prompt sharing most room sizes", "",
        lambda r: _frac(r["seed_pairs_shared"], r["seed_pairs"]))
    row(f"courtyards inside the footprint (< {100 * INSIDE_MAX_SHARE:.0f} % of the perimeter on the outline)", "",
        lambda r: _frac(r["courtyards_inside"], r["courtyards"]))
    row("courtyards with rooms on every side", "", lambda r: _frac(r["courtyards_enclosed"], r["courtyards"]))
    row("footprints: " + " / ".join(SHAPES), "", lambda r: " / ".join(str(r["shapes"][k]) for k in SHAPES))
    row("L-shaped (non-rectangular) rooms (houses with one)", "", lambda r: f"{r['l_rooms']} ({r['houses_with_l']})")
    row("most levels / houses with > 1 level", "", lambda r: f"{r['max_levels']} / {r['multi_level']}")
    row(f"houses with > {OVERHANG_TOL_M2:g} m2 of upper floor over nothing (m2 in all)", "",
        lambda r: f"{_frac(r['overhanging'], r['multi_level'])} ({r['overhang_m2']:.0f})")
    row("houses with every room reachable (doors, stairs)", "all", lambda r: _frac(r["all_reachable"], r["houses"]))
    row("most rooms in a house", "", lambda r: str(r["max_rooms"]))
    row("validity violations (houses with any)", "0", lambda r: f"{r['violations']} ({r['houses_with_violations']})")
    row("floorplan stage median / p90 / max (ms)", "median <= 100",
        lambda r: f"{r['fp_median_ms']:.0f} / {r['fp_p90_ms']:.0f} / {r['fp_max_ms']:.0f}")
    return "\n".join(lines)


def add_common_args(ap: argparse.ArgumentParser, default_sets: str) -> None:
    """The options every per-set benchmark takes: --sets, --seeds, --out, -q."""
    ap.add_argument("--sets", default=default_sets)
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--out", default=None, help="write the markdown table here")
    ap.add_argument("-q", "--quiet", action="store_true", help="no line per house")


def chosen(args: argparse.Namespace, sets: dict[str, Path]) -> tuple[list[int], list[str]] | None:
    """(seeds, set names) from the common options; None (and one error line) for an unknown set."""
    seeds = [int(s) for s in args.seeds.split(",")]
    names = [s.strip() for s in args.sets.split(",") if s.strip()]
    unknown = [n for n in names if n not in sets]
    if unknown:
        print(f"error: unknown set {unknown[0]!r} (known: {', '.join(sets)})", file=sys.stderr)
        return None
    return seeds, names


def line_logger(args: argparse.Namespace) -> Callable[[str], None]:
    def log(line: str) -> None:
        if not args.quiet:
            print(line, flush=True)

    return log


def emit(md: str, out: str | None) -> None:
    """Print the table, and write it to ``out`` when given."""
    print(md)
    if out:
        Path(out).parent.mkdir(parents=True, exist_ok=True)
        Path(out).write_text(md, encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_common_args(ap, "public,heldout_c,heldout_plan")
    args = ap.parse_args(argv)
    picked = chosen(args, SETS)
    if picked is None:
        return 2
    seeds, names = picked
    t0 = time.perf_counter()
    results = [run_set(n, load_prompts(SETS[n]), seeds, line_logger(args)) for n in names]
    big = forty_rooms()
    emit(table(results, seeds) + f"\n\n40-room program, floorplan stage: {big}\n"
         + f"\nWall time of the run: {time.perf_counter() - t0:.0f} s\n", args.out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
