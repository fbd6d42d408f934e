"""Compare embedding backends on benchmarks/mapping_cases.yaml.

For every case (a phrase the knowledge base does not list, and the concepts a reader
would map it to) the backend ranks the concepts of its table; a case is right when the
best concept is one of ``expect``. Concept phrases equal to the case phrase (from
knowledge/concepts.yaml) are left out, so a phrase never finds itself. A case whose phrase
the knowledge base has since come to list (a room name, an object synonym, a building
word) is no longer an open-vocabulary case: it is skipped and counted in the "listed" column.
Nonsense strings measure how often a backend invents a match above its threshold.

    .venv/bin/python benchmarks/mapping.py [--backend static lexical minilm] [--json out.json]

Prints one table row per backend and table; ``--sweep`` also prints accuracy and
acceptance for a range of thresholds.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np
import yaml

from anyhome.plan import concepts
from anyhome.plan.embed import available_backends, get_embedder
from anyhome.plan.knowledge import knowledge_base, normalize, vocabulary

CASES = Path(__file__).with_name("mapping_cases.yaml")

NONSENSE = [
    "asdf", "qwer zxcv", "blorptang", "xyzzy", "flibbertigibbet", "zorp", "glarb fnord",
    "kzzt", "mumblewump", "qqqq", "snorkelwhistle", "wug", "trabble", "plimsquat", "vorbl",
    "jabberwock", "skronk", "dax", "blicket", "toma",
]  # fmt: skip
"""Strings that name nothing; a match above threshold for them is a false match."""


def _forms(phrase: str) -> frozenset[str]:
    p = normalize(phrase)
    return frozenset({p, p + "s", p.rstrip("s")})


def listed(kind: str, phrase: str) -> bool:
    """Whether the knowledge base now names ``phrase`` itself (so matching it is lexical)."""
    voc = vocabulary()
    table = voc.building_forms if kind == "buildings" else voc.forms
    return any(f in table for f in _forms(phrase))


def evaluate(backend: str, cases: dict, sweep: bool) -> list[dict]:
    emb = get_embedder(backend)
    rows = []
    for kind in [k for k in concepts.KINDS if cases.get(k)]:
        skipped = sum(listed(kind, c["phrase"]) for c in cases[kind])
        open_cases = [c for c in cases[kind] if not listed(kind, c["phrase"])]
        t0 = time.perf_counter()
        idx = concepts.ConceptIndex(kind, emb, knowledge_base())
        build_s = time.perf_counter() - t0
        limit = concepts.THRESHOLDS[backend][kind]
        results = []
        t0 = time.perf_counter()
        for c in open_cases:
            best = idx.rank(c["phrase"], k=1, exclude=_forms(c["phrase"]))[0]
            results.append((best.score, best.key in c["expect"], bool(c.get("hard"))))
        per_case_ms = (time.perf_counter() - t0) / max(1, len(results)) * 1000
        noise = [idx.rank(w, k=1)[0].score for w in NONSENSE]
        sc = np.array([r[0] for r in results])
        ok = np.array([r[1] for r in results])
        hard = np.array([r[2] for r in results])
        acc = ok[sc >= limit]
        row = {
            "backend": backend, "table": kind, "cases": len(results), "listed": skipped,
            "top1": float(ok.mean()), "top1_easy": float(ok[~hard].mean()), "top1_hard": float(ok[hard].mean()),
            "threshold": limit, "accepted": float((sc >= limit).mean()),
            "precision": float(acc.mean()) if len(acc) else 0.0,
            "right_and_accepted": float((ok & (sc >= limit)).mean()),
            "nonsense_accepted": float(np.mean(np.array(noise) >= limit)),
            "index_build_s": round(build_s, 3), "ms_per_query": round(per_case_ms, 2),
        }  # fmt: skip
        rows.append(row)
        if sweep:
            for t in np.arange(0.3, 0.95, 0.05):
                a = sc >= t
                print(f"  {backend:7s} {kind:9s} t={t:.2f} accepted {a.mean():5.1%} precision "
                      f"{(ok[a].mean() if a.any() else 0):5.1%} right&accepted {(ok & a).mean():5.1%} "
                      f"nonsense {np.mean(np.array(noise) >= t):5.1%}")
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--backend", nargs="*", default=None)
    ap.add_argument("--json", default=None)
    ap.add_argument("--sweep", action="store_true")
    args = ap.parse_args(argv)
    cases = yaml.safe_load(CASES.read_text(encoding="utf-8"))
    backends = args.backend or available_backends()
    rows = []
    for b in backends:
        rows.extend(evaluate(b, cases, args.sweep))
        print(f"{b}: model load {get_embedder(b).load_s:.2f} s", file=sys.stderr)
    print("| backend | table | cases | listed | top-1 | easy | hard | threshold | accepted | precision | right & accepted | nonsense accepted | ms/query |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['backend']} | {r['table']} | {r['cases']} | {r['listed']} | {r['top1']:.0%} | {r['top1_easy']:.0%} | "
              f"{r['top1_hard']:.0%} | {r['threshold']:.2f} | {r['accepted']:.0%} | {r['precision']:.0%} | "
              f"{r['right_and_accepted']:.0%} | {r['nonsense_accepted']:.0%} | {r['ms_per_query']} |")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
