"""sha1 of every house of a prompt set (house.json less provenance and timings), to show
that a change leaves those houses as they were.

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/house_hashes.py --out /tmp/before.json
    (change the code)
    PYTHONPATH=src .venv/bin/python benchmarks/house_hashes.py --out /tmp/after.json --compare /tmp/before.json

Defaults: the 30 public prompts (tests/data/public_prompts.jsonl), seeds 0-2.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path

from anyhome.pipeline import generate
from anyhome.plan.knowledge import knowledge_base

HERE = Path(__file__).resolve().parent


def house_hash(house) -> str:
    data = json.loads(house.model_dump_json())
    data.pop("provenance", None)
    data.pop("timings", None)
    return hashlib.sha1(json.dumps(data, sort_keys=True).encode()).hexdigest()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--prompts", default=str(HERE.parent / "tests" / "data" / "public_prompts.jsonl"))
    ap.add_argument("--seeds", default="0,1,2")
    ap.add_argument("--out", required=True)
    ap.add_argument("--compare", help="an earlier --out: print the houses that differ")
    args = ap.parse_args(argv)
    kb = knowledge_base()
    out = {}
    for line in Path(args.prompts).read_text(encoding="utf-8").splitlines():
        if line.strip():
            d = json.loads(line)
            for seed in map(int, args.seeds.split(",")):
                out[f"{d['id']}:{seed}"] = house_hash(generate(d["prompt"], seed=seed, knowledge=kb))
    Path(args.out).write_text(json.dumps(out, indent=1, sort_keys=True))
    print(f"{len(out)} houses")
    if args.compare:
        before = json.loads(Path(args.compare).read_text())
        differ = sorted(k for k in set(before) | set(out) if before.get(k) != out.get(k))
        print(f"{len(differ)} differ" + (": " + ", ".join(differ) if differ else ""))
        return 1 if differ else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
