"""Benchmark of open-plan L rooms (issue 13): which houses get one, and what the layout
places in them, against the same houses with every room a rectangle.

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/open_plan.py --sets dev --seeds 0,1,2

Each prompt and seed is generated twice in-process (offline planner, no export): with
the default floorplan options and with ``FloorplanOptions(open_plan_max_rooms=0)``.
The merge is the floorplan stage's last step and draws nothing the other stages read,
so the two houses differ only in the merged rooms. For every house that gets an L
room it prints the objects and dropped copies of the planned rooms the L room holds,
merged and unmerged, and the validity violations of the merged house.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

import numpy as np

from anyhome.errors import AnyHomeError
from anyhome.evaluate import evaluate_house
from anyhome.floorplan.levels import solve_levels
from anyhome.floorplan.options import FloorplanOptions
from anyhome.pipeline import generate
from anyhome.plan.knowledge import knowledge_base
from anyhome.stages import Stages

sys.path.insert(0, str(__import__("pathlib").Path(__file__).resolve().parent))
from floorplans import SETS, load_prompts  # noqa: E402

RECTANGLES = FloorplanOptions(open_plan_max_rooms=0)


def _rectangles(spec: Any, rng: np.random.Generator) -> Any:
    return solve_levels(spec, rng, RECTANGLES)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sets", default="dev")
    ap.add_argument("--seeds", default="0,1,2")
    args = ap.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")]
    kb = knowledge_base()
    flat = Stages(floorplan=_rectangles)
    totals = {"houses": 0, "with_l": 0, "l_rooms": 0, "objects_l": 0, "objects_rect": 0,
              "dropped_l": 0, "dropped_rect": 0, "violations": 0, "failed": 0}
    for name in args.sets.split(","):
        for pid, prompt in load_prompts(SETS[name]):
            for seed in seeds:
                try:
                    house = generate(prompt, seed=seed, knowledge=kb)
                except AnyHomeError as e:
                    print(f"{name} {pid} seed {seed}: FAILED {e}")
                    totals["failed"] += 1
                    continue
                totals["houses"] += 1
                merged = [r for r in house.rooms if r.merged]
                if not merged:
                    continue
                rect = generate(prompt, seed=seed, knowledge=kb, stages=flat)
                ids = {r.id for r in merged} | {h for r in merged for h in r.merged}
                obj_l = sum(o.room in ids for o in house.objects)
                obj_r = sum(o.room in ids for o in rect.objects)
                drop_l = sum(d.room in ids for d in house.dropped)
                drop_r = sum(d.room in ids for d in rect.dropped)
                viol = len(evaluate_house(house, kb=kb).violations)
                totals["with_l"] += 1
                totals["l_rooms"] += len(merged)
                for key, v in (("objects_l", obj_l), ("objects_rect", obj_r), ("dropped_l", drop_l),
                               ("dropped_rect", drop_r), ("violations", viol)):
                    totals[key] += v
                rooms = ", ".join(f"{r.id}+{'+'.join(r.merged)}" for r in merged)
                print(f"{name} {pid:<28} seed {seed}: L {rooms}: objects {obj_l} (rectangles {obj_r}), "
                      f"dropped {drop_l} (rectangles {drop_r}), violations {viol}", flush=True)
    print(" ".join(f"{k}={v}" for k, v in totals.items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
