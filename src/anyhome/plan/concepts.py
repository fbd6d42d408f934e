"""Nearest known concept for a phrase the knowledge base does not list.

Three concept tables are built from the knowledge files:

* ``rooms``: furnishing sets (``furniture.yaml`` ``sets``), described by their key, every
  room name of ``rooms.yaml`` that uses the set, and the phrases of ``concepts.yaml``;
* ``objects``: object prototypes (``objects.yaml``), described by key, synonyms, category;
* ``buildings``: building programs (``programs.yaml``), described by key and their words;
* ``styles``: styles (``styles.yaml``), described by their words and description.

A phrase is embedded whole or, for rooms and buildings with a generic head word,
as its modifier alone ("séance room" -> "séance"); its score for a concept is the best cosine similarity to
any of the concept's phrases. A match is kept only above the backend's threshold
(``THRESHOLDS``, chosen on benchmarks/mapping_cases.yaml); below it the caller falls back
to a neutral default and keeps the user's words as the name.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

import numpy as np

from anyhome.house import ROOM_TYPES
from anyhome.plan.embed import Embedder, get_embedder
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import resolve
from anyhome.plan.knowledge import normalize

KINDS = ("rooms", "objects", "buildings", "styles")

GENERIC_HEADS = frozenset(
    "room rooms area space spaces corner nook zone chamber suite quarters hall den lounge "
    "studio shop house center centre place spot bay".split()
)
"""Head words that say little about a room's function ("séance room" -> "séance")."""

THRESHOLDS: dict[str, dict[str, float]] = {
    "hybrid": {"rooms": 0.45, "objects": 0.45, "buildings": 0.45, "styles": 0.5},
    "static": {"rooms": 0.65, "objects": 0.65, "buildings": 0.65, "styles": 0.7},
    "minilm": {"rooms": 0.45, "objects": 0.5, "buildings": 0.45, "styles": 0.5},
    "lexical": {"rooms": 0.45, "objects": 0.5, "buildings": 0.45, "styles": 0.5},
}
"""Least cosine similarity a match needs, per backend and table."""


MAX_PHRASE_CHARS = 60
"""Longer phrases are not words but run-on text; they match nothing."""


@dataclass(frozen=True)
class Match:
    key: str  # concept key (furnishing set, object prototype or program)
    score: float
    via: str  # the concept phrase that matched best


def _room_phrases(kb: KnowledgeBase) -> dict[str, list[str]]:
    sets = kb.raw("furniture")["sets"]
    names = kb.raw("rooms")["names"]
    # a set only rooms of one kind of building use ("side_room" of a hospital ward) is no
    # reading of an unknown room elsewhere: a siheyuan's "west side room" is no ward
    free = {i.get("furnish") or i.get("type") for i in names.values() if not i.get("only_within")}
    bound = {i.get("furnish") or i.get("type") for i in names.values() if i.get("only_within")} - free
    out: dict[str, list[str]] = {k: [k.replace("_", " ")] for k in sets if k != "other" and k not in bound}
    for name, info in names.items():
        furnish = info.get("furnish") or info.get("type")
        if furnish in out and not info.get("only_within"):  # "stall" is a loose box in a stable alone
            out[furnish].append(normalize(name))
    return out


def _object_phrases(kb: KnowledgeBase) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for key, proto in kb.raw("objects").items():
        out[key] = [normalize(key), *(normalize(s) for s in proto.get("synonyms", []))]
        cat = proto.get("category", "").replace("_", " ")
        if cat and cat not in out[key]:
            out[key].append(cat)
    return out


def _building_phrases(kb: KnowledgeBase) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for b in kb.raw("programs")["buildings"]:
        out.setdefault(b["program"], [b["program"].replace("_", " ")])
        out[b["program"]].extend(normalize(w) for w in b["words"])
    return out


def _style_phrases(kb: KnowledgeBase) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for key, st in kb.raw("styles")["styles"].items():
        out[key] = [normalize(w) for w in st["words"]] + [normalize(st["describe"])]
    return out


_PHRASES = {"rooms": _room_phrases, "objects": _object_phrases, "buildings": _building_phrases, "styles": _style_phrases}


def concept_phrases(kind: str, kb: KnowledgeBase | None = None) -> dict[str, list[str]]:
    """Every concept of ``kind`` with its phrases: from the knowledge files, plus those
    that ``concepts.yaml`` adds for existing concepts."""
    kb = resolve(kb)
    out = _PHRASES[kind](kb)
    for key, phrases in (kb.raw("concepts").get(kind) or {}).items():
        if key in out:
            out[key].extend(normalize(p) for p in phrases)
    return out


class ConceptIndex:
    """Embedded concept phrases of one table, for one backend."""

    def __init__(self, kind: str, embedder: Embedder, kb: KnowledgeBase) -> None:
        self.kind = kind
        self.embedder = embedder
        table = concept_phrases(kind, kb)
        self.keys = list(table)
        self.phrases: list[str] = []
        owner: list[int] = []
        for i, k in enumerate(self.keys):
            for p in dict.fromkeys(table[k]):
                self.phrases.append(p)
                owner.append(i)
        self.owner = np.array(owner)
        self.matrix = embedder.encode(self.phrases)

    def rank(self, phrase: str, k: int = 3, exclude: frozenset[str] = frozenset()) -> list[Match]:
        """The ``k`` best concepts for ``phrase`` (no threshold); concept phrases in
        ``exclude`` are ignored (leave-one-out measurement)."""
        queries = query_forms(phrase, self.kind)
        q = np.stack([_query_vector(self.embedder.name, t) for t in queries])
        sim = q @ self.matrix.T  # (forms, phrases)
        best_phrase = sim.max(axis=0)
        if exclude:
            best_phrase = np.where([p in exclude for p in self.phrases], -1.0, best_phrase)
        per_key: dict[int, tuple[float, int]] = {}
        for j, s in enumerate(best_phrase):
            o = int(self.owner[j])
            if o not in per_key or s > per_key[o][0]:
                per_key[o] = (float(s), j)
        ranked = sorted(per_key.items(), key=lambda kv: -kv[1][0])[:k]
        return [Match(self.keys[o], round(s, 4), self.phrases[j]) for o, (s, j) in ranked]


@functools.lru_cache(maxsize=4096)
def _query_vector(backend: str, text: str) -> np.ndarray:
    """One query's embedding, cached: a phrase is looked up in several tables (a list
    phrase is tried as a room and as an object), and texts repeat across seeds."""
    return get_embedder(backend).encode([text])[0]


def query_forms(phrase: str, kind: str) -> list[str]:
    """What is embedded for ``phrase``: for rooms and buildings with a generic head word,
    the modifier alone ("séance room" -> "séance"; measured better than the whole phrase
    or the best of both on benchmarks/mapping_cases.yaml), else the phrase."""
    p = normalize(phrase)
    forms = [p]
    words = p.split()
    if kind in ("rooms", "buildings") and len(words) >= 2 and words[-1] in GENERIC_HEADS:
        return [" ".join(words[:-1])]
    return forms


def index(kind: str, backend: str | None = None, kb: KnowledgeBase | None = None) -> ConceptIndex:
    """The cached concept index of ``kind`` in ``kb`` for the backend (default: ``get_embedder()``)."""
    return _index(kind, get_embedder(backend).name, resolve(kb))


@functools.lru_cache(maxsize=32)
def _index(kind: str, backend: str, kb: KnowledgeBase) -> ConceptIndex:
    return ConceptIndex(kind, get_embedder(backend), kb)


def threshold(kind: str, backend: str | None = None, kb: KnowledgeBase | None = None) -> float:
    """The least score a match of ``kind`` needs with this backend."""
    name = index(kind, backend, kb).embedder.name
    return THRESHOLDS.get(name, THRESHOLDS["lexical"])[kind]


def nearest(kind: str, phrase: str, backend: str | None = None, with_score: bool = False,
            kb: KnowledgeBase | None = None) -> Match | None:
    """Best concept for ``phrase`` if it clears the backend's threshold, else None
    (``with_score``: the best concept whatever its score)."""
    if not re.search(r"[a-z]", normalize(phrase)) or len(phrase) > MAX_PHRASE_CHARS:
        return None  # the packaged concepts are English; other scripts match nothing
    idx = index(kind, backend, kb)
    best = idx.rank(phrase, k=1)
    if not best:
        return None
    return best[0] if with_score or best[0].score >= threshold(kind, backend, kb) else None


def furnish_type(furnish: str, kb: KnowledgeBase | None = None) -> str:
    """The functional room type of a furnishing set (``other`` when none says)."""
    if furnish in ROOM_TYPES:
        return furnish
    for info in resolve(kb).raw("rooms")["names"].values():
        if info.get("furnish") == furnish and info.get("type") in ROOM_TYPES:
            return str(info["type"])
    return "other"
