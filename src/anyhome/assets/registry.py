"""The registry of procedural asset families, name matching and asset records.

A family is a pair of functions ``sample(rng, size, style) -> Params`` and
``build(params) -> trimesh.Trimesh``; the mesh lies in the object's local frame
(centred on x/y, bottom at z = 0, front facing +y) and fills the box exactly.
"""

from __future__ import annotations

import re
import zlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np
import trimesh

from anyhome.assets.colors import material_color
from anyhome.assets.library import SOURCE as LIBRARY_SOURCE
from anyhome.assets.procedural._parts import Params, Size
from anyhome.assets.styles import Style, style_class
from anyhome.house import HouseObject

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

GENERIC = "generic"
"""Family of objects whose name matches nothing: a composed block that still reads as a thing."""
SOURCE = "procedural"
BROAD_FAMILIES = frozenset({"table", "chair", "bench", "cabinet", "shelf", "box", "bed", "counter", "desk", "stool"})
"""Families a category may name loosely; a one-word name that is a family of its own
(a "pew" of category bench) is built as that family instead."""


@dataclass(frozen=True)
class Family:
    name: str
    sample: Callable[[np.random.Generator, Size, Style], Params]
    build: Callable[[Params], trimesh.Trimesh]


_REGISTRY: dict[str, Family] = {}


def register(name: str, sample: Callable[..., Params], build: Callable[[Params], trimesh.Trimesh]) -> None:
    """Add a family (later registrations of the same name replace earlier ones)."""
    _REGISTRY[name] = Family(name, sample, build)


@lru_cache(maxsize=1)
def _loaded() -> dict[str, Family]:
    import importlib

    from anyhome.assets.procedural import MODULES

    for module in MODULES:  # each registers its families on import
        importlib.import_module(f"anyhome.assets.procedural.{module}")
    return _REGISTRY


def families() -> list[str]:
    return sorted(_loaded())


def get(name: str) -> Family:
    fams = _loaded()
    if name not in fams:
        raise KeyError(f"unknown asset family {name!r}")
    return fams[name]


@dataclass(frozen=True)
class _Words:
    """The word tables of one knowledge base (see :func:`_words`)."""

    protos: dict[str, str]  # prototype word (key or synonym) -> the prototype's family, or "" if none
    categories: dict[str, str]  # assets.yaml categories: category -> family
    words: dict[str, str]  # assets.yaml words: word -> family
    sizes: dict[str, tuple[float, float, float]]  # family -> typical box
    stand_ins: frozenset[str]  # assets.yaml stand_ins: words no family draws as itself


def _kb(kb: KnowledgeBase | None) -> KnowledgeBase:
    """``kb``, else the knowledge base in force: the explicit default of the catalog tools
    and of a caller outside the stages; the assets stage passes its own."""
    from anyhome.plan.kbview import resolve

    return resolve(kb)


@lru_cache(maxsize=8)
def _tables(kb: Any) -> _Words:
    """The knowledge base's object words and sizes as the asset side reads them: a word a
    prototype names (its key or a synonym) is built as the prototype's family (its key
    when that is a family, else its category, through assets.yaml ``categories:``);
    other words come from assets.yaml ``words:``. A family's typical size is the size of
    the prototype whose key, else whose category, is the family; else assets.yaml
    ``sizes:``."""
    from anyhome.plan.kb import word_key

    fams = _loaded()
    cats = dict(kb.assets.categories)
    protos: dict[str, str] = {}
    sizes: dict[str, tuple[float, float, float]] = {}
    for key, o in kb.objects.items():
        k = word_key(key)
        fam = k if k in fams else o.category if o.category in fams else cats.get(o.category, "")
        for w in (key, *o.synonyms):
            protos.setdefault(word_key(w), fam)
        if k in fams:
            sizes[k] = tuple(o.size)
    for o in kb.objects.values():
        sizes.setdefault(o.category, tuple(o.size))
    for f, size in kb.assets.sizes.items():
        sizes.setdefault(f, tuple(size))
    return _Words(protos, cats, dict(kb.assets.words), sizes, frozenset(kb.assets.stand_ins))


def synonyms(kb: KnowledgeBase | None = None) -> dict[str, str]:
    """Every object word -> the family it names: the prototypes' words (objects.yaml) and
    assets.yaml ``words:`` (the family names themselves are not listed), in ``kb``."""
    t = _tables(_kb(kb))
    return {**{w: f for w, f in t.protos.items() if f}, **t.words}


def typical_size(family: str, kb: KnowledgeBase | None = None) -> tuple[float, float, float]:
    """A typical box (width, depth, height) in meters for a family: the size of the object
    prototype that is the family (its key, else its category), else assets.yaml
    ``sizes:``, else the generic block's."""
    sizes = _tables(_kb(kb)).sizes
    return sizes.get(family) or sizes[GENERIC]


def _norm(text: str) -> str:
    return "_".join(re.findall(r"[a-z0-9]+", text.lower()))


def _lookup(key: str, t: _Words, use_synonyms: bool = True) -> str | None:
    fams = _loaded()
    for k in (key, key[:-1] if key.endswith("s") else None, key[:-2] if key.endswith("es") else None):
        if not k:
            continue
        if k in fams:
            return k
        if not use_synonyms:
            continue
        for table in (t.protos, t.categories, t.words):
            if table.get(k) in fams:
                return table[k]
    return None


def _specific_name(name: str, category: str, t: _Words) -> str | None:
    """The family a name asks for by itself, when it should overrule the category: a
    name of two or more words that is a family or a synonym ("pool table", "billiard
    table"), or a one-word family name ("pew") given with a broad category ("bench").
    Other single words are too loose ("chest", "mat", a "bench" of category weight_bench)."""
    key = _norm(name)
    if not key:
        return None
    if "_" in key:
        hit = _lookup(key, t)
        if hit in BROAD_FAMILIES and key in t.protos and _lookup(_norm(category), t) not in (None, GENERIC, hit):
            return None  # a loose prototype word ("long table") never overrules a specific category
        return hit if hit != GENERIC else None  # a known fallback never overrules a category
    hit = _lookup(key, t, use_synonyms=False)
    return hit if hit and _lookup(_norm(category), t) in BROAD_FAMILIES else None


def family_for(category: str, name: str = "", kb: KnowledgeBase | None = None) -> str:
    """The family to build an object as: the family a name asks for by itself (see
    ``_specific_name``), else the category if it is a family, else the best match of the
    category or name (whole, word pairs, then single words, last word first, through the
    prototypes' words and assets.yaml of ``kb``, see :func:`_tables`), else ``"generic"``."""
    t = _tables(_kb(kb))
    if hit := _specific_name(name, category, t):
        return hit
    for text in (category, name):
        key = _norm(text)
        if key and (hit := _lookup(key, t)):
            return hit
    for text in (category, name):
        words = _norm(text).split("_")
        for i in range(len(words) - 2, -1, -1):
            if hit := _lookup(f"{words[i]}_{words[i + 1]}", t):
                return hit
        for w in reversed(words):
            if w and (hit := _lookup(w, t)):
                return hit
    return GENERIC


def is_stand_in(category: str, name: str, family: str, kb: KnowledgeBase | None = None) -> bool:
    """Whether the family an object is built as draws something else: the generic block,
    or a name or category that assets.yaml ``stand_ins`` lists (the whole name, or its
    last words: "old sauna heater")."""
    if family == GENERIC:
        return True
    listed = _tables(_kb(kb)).stand_ins
    words = _norm(name).split("_")
    tails = {"_".join(words[-n:]) for n in range(1, len(words) + 1)}
    return _norm(category) in listed or bool(tails & listed)


def object_rng(obj: HouseObject) -> np.random.Generator:
    """A generator seeded from a stable hash of the object id."""
    return np.random.default_rng(zlib.crc32(obj.id.encode("utf-8")))


def assign_asset(obj: HouseObject, rng: np.random.Generator, style: Style | Sequence[str] = "",
                 kb: KnowledgeBase | None = None) -> dict[str, Any]:
    """Choose and parametrise the procedural asset for an object.

    ``style`` is the house's (or room's) style keys of plan/knowledge/styles.yaml, the
    lead first, or one key or asset class name; the lead's asset style class shapes and
    colours the asset, and the record's ``params.style`` names that class (see
    :mod:`anyhome.assets.styles`). Returns the JSON-serialisable record to store in
    ``HouseObject.asset``; the object's material words (else its description's) set the
    main colour. Everything is read in ``kb`` (None: the knowledge base in force): the
    family, the style class (resolved here, once, and handed to the factory) and colours.
    """
    kb = _kb(kb)
    name = family_for(obj.category, obj.name, kb)
    fam = get(name)
    params = fam.sample(rng, obj.size, style_class(style, kb))
    color = material_color(obj.material, kb) or material_color(obj.description, kb)
    if color:
        params = replace(params, primary=color)
    record: dict[str, Any] = {"source": SOURCE, "family": name, "params": params.to_record()}
    if is_stand_in(obj.category, obj.name, name, kb):
        record["approximate"] = True  # said in the summary and by anyhome eval, never silent
    return record


def procedural_record(obj: HouseObject, record: dict[str, Any] | None,
                      kb: KnowledgeBase | None = None) -> dict[str, Any]:
    """``record`` if it is a usable procedural record, else one sampled from a generator
    seeded by the object id (in ``kb``)."""
    if not record or record.get("source") != SOURCE or record.get("family") not in _loaded():
        return assign_asset(obj, object_rng(obj), "", kb)
    return record


def params_from_record(record: dict[str, Any]) -> Params:
    return Params.from_record(record["family"], record["params"])


def build_object_mesh(obj: HouseObject, kb: KnowledgeBase | None = None) -> trimesh.Trimesh:
    """The object's mesh in its local frame (see module doc), rebuilt from ``obj.asset``.

    A library record (``source`` ``library``, :mod:`anyhome.assets.library`) gives the
    model file's geometry (its parts joined) fitted to the box; when its file is missing
    or changed, its ``fallback`` procedural record is built (with a logged warning).
    Without a procedural record an asset is sampled from a generator seeded by the
    object id (its family and colours read in ``kb``; None: the knowledge base in force).
    The mesh is fitted to ``obj.size`` (so a resized object keeps its look).
    """
    record = obj.asset
    if record and record.get("source") == LIBRARY_SOURCE:
        from anyhome.assets.library import library_mesh

        mesh = library_mesh(record, obj.size)
        if mesh is not None:
            return mesh
        record = record.get("fallback")
    record = procedural_record(obj, record, kb)
    params = params_from_record(record)
    size = (float(obj.size[0]), float(obj.size[1]), float(obj.size[2]))
    if size != params.size:
        params = replace(params, size=size)
    return get(params.family).build(params)
