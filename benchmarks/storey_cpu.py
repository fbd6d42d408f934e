"""CPU time (process_time) of the storey stage, ``floorplan.levels.solve_levels``, on the
specs the offline planner gives for a prompt set, with the layout attempts it spent.

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/storey_cpu.py --sets dev_storeys,dev_storeys2 \\
        [--seeds 0,1,2] [--profile /tmp/storeys.prof] [--out /tmp/storeys.json]

(``PYTHONPATH`` may point at an older checkout's src to time the code before a change.)

Each house: its spec planned first (not timed), then ``solve_levels`` with the
floorplan stage's own generator (``stage_rngs(seed)["floorplan"]``), timed alone; a
line per house (ms, attempts, a hash of the floorplan), then per set the median, p90
and max. ``--profile``: cProfile of the timed calls only.
"""

from __future__ import annotations

import argparse
import cProfile
import hashlib
import json
import statistics
import sys
import time
from pathlib import Path

from anyhome.errors import AnyHomeError
from anyhome.floorplan.levels import solve_levels
from anyhome.plan import get_planner
from anyhome.plan.knowledge import knowledge_base
from anyhome.stages import stage_rngs

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floorplans import SETS, load_prompts  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sets", default="dev_storeys,dev_storeys2")
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--profile")
    ap.add_argument("--out")
    args = ap.parse_args(argv)
    planner = get_planner("offline", knowledge_base(), solve_levels)
    spent = [0]
    try:  # counted where the code has a whole-search budget (not before it: 0)
        from anyhome.floorplan import budget

        real_spend = budget.AttemptBudget.spend

        def counted(self: budget.AttemptBudget) -> None:
            spent[0] += 1
            real_spend(self)

        budget.AttemptBudget.spend = counted  # type: ignore[method-assign]
    except ImportError:
        pass
    prof = cProfile.Profile() if args.profile else None
    res: dict[str, dict] = {}
    for name in args.sets.split(","):
        for pid, prompt in load_prompts(SETS[name]):
            for seed in map(int, args.seeds.split(",")):
                spec = planner.plan(prompt, stage_rngs(seed)["plan"])
                spent[0] = 0
                t0 = time.process_time()
                if prof:
                    prof.enable()
                try:
                    h = hashlib.sha1(solve_levels(spec, stage_rngs(seed)["floorplan"]).model_dump_json().encode()).hexdigest()[:12]
                except AnyHomeError as e:
                    h = f"FAILED {e}"
                if prof:
                    prof.disable()
                ms = 1000 * (time.process_time() - t0)
                res[f"{name}:{pid}:{seed}"] = {"ms": round(ms, 1), "attempts": spent[0], "hash": h}
                print(f"{name:<14} {pid:<40} {seed} {ms:8.0f} ms {spent[0]:4d} attempts {h}", flush=True)
        ms_all = sorted(v["ms"] for k, v in res.items() if k.startswith(name + ":"))
        print(f"{name}: {len(ms_all)} houses, CPU median {statistics.median(ms_all):.0f} ms, "
              f"p90 {ms_all[int(0.9 * (len(ms_all) - 1))]:.0f}, max {ms_all[-1]:.0f}, sum {sum(ms_all) / 1000:.1f} s")
    if args.out:
        Path(args.out).write_text(json.dumps(res, indent=1))
    if prof:
        prof.dump_stats(args.profile)
    return 0


if __name__ == "__main__":
    sys.exit(main())
