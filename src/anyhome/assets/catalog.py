"""A catalog of the procedural asset families: what each one is, how big, how heavy, and
which object categories of the knowledge base (``plan/knowledge/objects.yaml``) it builds.

    >>> from anyhome.assets.catalog import describe
    >>> next(d for d in describe() if d["name"] == "sofa")["typical_size_m"]
    [2.2, 0.95, 0.85]

Everything :func:`describe` returns is plain JSON (lists, strings, numbers). Every
function reads the knowledge base ``kb`` it is given; None (the catalog command, a
tool): the knowledge base in force.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from anyhome.assets.registry import GENERIC, families, family_for, get, synonyms, typical_size
from anyhome.assets.styles import style_class
from anyhome.plan.kbview import resolve

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

SAMPLES = ((0, ""), (1, "modern"), (2, "victorian"), (3, "industrial"), (4, "rustic"), (5, ""))
"""(seed, style) pairs over which triangle counts are measured."""


def family_names() -> list[str]:
    """Names of every procedural family, sorted."""
    return families()


def triangle_range(name: str, samples: tuple[tuple[int, str], ...] = SAMPLES,
                   kb: KnowledgeBase | None = None) -> tuple[int, int]:
    """Fewest and most triangles of a family at its typical size over (seed, style) ``samples``."""
    kb = resolve(kb)
    fam = get(name)
    size = typical_size(name, kb)
    counts = [len(fam.build(fam.sample(np.random.default_rng(seed), size, style_class(style, kb))).faces)
              for seed, style in samples]
    return min(counts), max(counts)


def knowledge_map(kb: KnowledgeBase | None = None) -> dict[str, dict[str, list[str]]]:
    """Family -> {"categories": [...], "objects": [...]}: the ``objects.yaml`` prototypes
    (and their categories) that are built as it, judged as the planner writes them
    (``family_for(category, name)``). Every family has an entry, possibly empty."""
    kb = resolve(kb)
    cats: dict[str, set[str]] = {name: set() for name in families()}
    objs: dict[str, set[str]] = {name: set() for name in families()}
    for key, proto in kb.raw("objects").items():
        category = str((proto or {}).get("category") or "")
        fam = family_for(category, str(key), kb)
        objs[fam].add(str(key))
        if category:
            cats[fam].add(category)
    return {name: {"categories": sorted(cats[name]), "objects": sorted(objs[name])} for name in families()}


def documented_fallbacks(kb: KnowledgeBase | None = None) -> list[str]:
    """Words sent on purpose to the generic block (things with no family of their own
    yet): :func:`anyhome.assets.registry.synonyms`, from objects.yaml and assets.yaml."""
    return sorted(k for k, v in synonyms(kb).items() if v == GENERIC)


def describe(kb: KnowledgeBase | None = None) -> list[dict[str, Any]]:
    """One JSON-serialisable record per family, sorted by name.

    Keys: ``name``; ``typical_size_m`` (width, depth, height); ``triangles`` ([fewest,
    most] over a few seeds and styles at the typical size); ``categories`` and
    ``objects`` (the ``objects.yaml`` categories and prototypes built as this family);
    ``synonyms`` (the object words that name it: objects.yaml prototypes and
    plan/knowledge/assets.yaml ``words:``).
    """
    kb = resolve(kb)
    known = knowledge_map(kb)
    syn: dict[str, list[str]] = {}
    for word, fam in synonyms(kb).items():
        syn.setdefault(fam, []).append(word)
    records = []
    for name in families():
        lo, hi = triangle_range(name, kb=kb)
        records.append({
            "name": name,
            "typical_size_m": [float(s) for s in typical_size(name, kb)],
            "triangles": [int(lo), int(hi)],
            "categories": known[name]["categories"],
            "objects": known[name]["objects"],
            "synonyms": sorted(syn.get(name, [])),
        })
    return records
