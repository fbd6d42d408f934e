"""Material words -> a material spec (texture kind, colour, roughness, metallic, scale).

The knowledge lives in ``plan/knowledge/materials.yaml`` (one entry per material word,
extendable by a user's knowledge folder); the tables here are built from the knowledge
base each function is given as ``kb`` (None: the knowledge base in force, the explicit
default of an export of a house file). A phrase is split into
clauses ("oak and matte black metal" -> "oak", "matte black metal"); the first clause
that names a material decides, and inside it the highest-ranked word wins, ties going
to the last word (the head noun). The surface then adapts the kind (wood on a floor is
planks) and per-surface overrides apply. Colours come from
:func:`anyhome.assets.colors.material_color`, else the kind's default.

>>> surface_material("dark walnut", "floor").kind
'planks'
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from anyhome.assets.colors import material_color, shade, to_hex, to_rgba
from anyhome.materials.textures import DEFAULT_SIZE_PX, GENERATORS, VARIANTS
from anyhome.sanitize import clean_text

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

SURFACES: tuple[str, ...] = ("floor", "walls", "ceiling", "furniture")
TEXTURE_PX_ENV = "ANYHOME_TEXTURE_PX"
"""Environment variable that sets the texture size in texels (default 256)."""
MIN_ROUGHNESS = 0.06
"""Finish words never make a surface smoother than this."""
_OVERRIDABLE = ("roughness", "metallic", "tile_m", "alpha", "color")
_JOINERS = ("and", "with", "on", "in", "over", "plus")
"""Words that split a phrase into clauses (unless they stand inside a material word:
"tongue and groove")."""


@dataclass(frozen=True)
class MaterialSpec:
    """How one surface looks; hashable, so equal specs share one texture set.

    kind : a texture kind (``anyhome.materials.textures.kinds()``), or "plain" / "glass"
    variant : the kind's pattern variant ("" for its default)
    color : ``"#rrggbb"`` base colour
    roughness, metallic : PBR factors in [0, 1]
    tile_m : meters one texture repeat covers (UV = meters / tile_m)
    alpha : opacity (< 1 is drawn blended)
    size_px : texture size in texels
    weathered : drawn aged (stains, worn patches, flaked finish): the words hold a
        weathering word (materials.yaml ``weathering``: peeling, dusty, rusty...)
    """

    kind: str
    variant: str = ""
    color: str = "#b0aaa0"
    roughness: float = 0.6
    metallic: float = 0.0
    tile_m: float = 1.0
    alpha: float = 1.0
    size_px: int = DEFAULT_SIZE_PX
    weathered: bool = False

    @property
    def textured(self) -> bool:
        return self.kind in GENERATORS

    @property
    def name(self) -> str:
        kind = f"{self.kind}/{self.variant}" if self.variant else self.kind
        return f"{kind} {self.color}"


@dataclass(frozen=True)
class _Tables:
    data: dict[str, Any]
    lexicon: dict[tuple[str, ...], tuple[int, dict[str, Any]]]
    """words of a material word (with a kind) -> (rank, entry)"""
    longest: int
    split: re.Pattern[str]


def _kb(kb: KnowledgeBase | None) -> KnowledgeBase:
    from anyhome.plan.kbview import resolve

    return resolve(kb)


@lru_cache(maxsize=8)
def _tables_of(kb: KnowledgeBase) -> _Tables:
    from anyhome.plan.kb import RANKS, material_words

    data = kb.raw("materials")
    lex: dict[tuple[str, ...], tuple[int, dict[str, Any]]] = {}
    for word, e in kb.materials.words.items():
        if e.kind is not None:
            entry = e.model_dump(exclude_none=True, exclude={"rank", "goes_on"})
            lex[tuple(material_words(word))] = (RANKS[e.rank], entry)
    return _Tables(data, lex, max((len(w) for w in lex), default=1), _splitter([" ".join(w) for w in lex]))


def _splitter(words: list[str]) -> re.Pattern[str]:
    """The clause splitter: commas, semicolons, slashes and the joiner words, except a
    joiner inside a material word ("tongue and groove" stays one clause)."""
    alts = []
    for j in _JOINERS:
        guards = "".join(rf"(?!(?<=\b{re.escape(w.split(f' {j} ', 1)[0])} ){j} {re.escape(w.split(f' {j} ', 1)[1])}\b)"
                         for w in words if f" {j} " in w)
        alts.append(rf"\b{guards}{j}\b")
    return re.compile(rf"\s*(?:,|;|/|{'|'.join(alts)})\s*")


def _tables(kb: KnowledgeBase | None) -> _Tables:
    return _tables_of(_kb(kb))


def _data(kb: KnowledgeBase | None) -> dict[str, Any]:
    """materials.yaml of ``kb`` (None: the knowledge base in force; merged with the
    user's overlay)."""
    return _tables(kb).data


MIN_TEXTURE_PX = 8
MAX_TEXTURE_PX = 2048
"""Texture sizes allowed (a 100,000 px texture asked numpy for 37 GiB)."""


def texture_size_px(size_px: int | None = None) -> int:
    """The texture size to use: ``size_px``, else ``$ANYHOME_TEXTURE_PX``, else 256.

    Raises ExportError (one line) for a size that is not an integer from
    :data:`MIN_TEXTURE_PX` to :data:`MAX_TEXTURE_PX`."""
    from anyhome.errors import ExportError

    if size_px is None:
        env = os.environ.get(TEXTURE_PX_ENV, "").strip()
        if not env:
            return DEFAULT_SIZE_PX
        where, value = f"${TEXTURE_PX_ENV}", env
    else:
        where, value = "the texture size", str(size_px)
    if not value.isdigit() or not MIN_TEXTURE_PX <= int(value) <= MAX_TEXTURE_PX:
        raise ExportError(f"{where} must be an integer from {MIN_TEXTURE_PX} to {MAX_TEXTURE_PX}, "
                          f"got {clean_text(value)[:40]!r}")
    return int(value)


def _words(text: str) -> list[str]:
    from anyhome.plan.kb import material_words

    return material_words(text)


def _winner(clause: str, t: _Tables) -> tuple[tuple[str, ...], dict[str, Any]] | None:
    """The winning material word of one clause and its entry, or None (the longest
    material word at each place: "white oak" before "oak"; the highest rank wins, ties
    going to the later word)."""
    lex = t.lexicon
    words = _words(clause)
    best: tuple[int, tuple[str, ...], dict[str, Any]] | None = None
    i = 0
    while i < len(words):
        n = next((n for n in range(min(t.longest, len(words) - i), 0, -1) if tuple(words[i:i + n]) in lex), 0)
        if n:
            key = tuple(words[i:i + n])
            rank, entry = lex[key]
            if best is None or rank >= best[0]:
                best = (rank, key, entry)  # ties: the later word wins
        i += max(n, 1)
    return None if best is None else (best[1], best[2])


def _match(clause: str, t: _Tables) -> tuple[dict[str, Any], list[str]] | None:
    """The winning entry of one clause and the clause's words, or None (:func:`_winner`)."""
    won = _winner(clause, t)
    return None if won is None else (won[1], _words(clause))


def clause_heads(words: str, kb: KnowledgeBase | None = None) -> list[str]:
    """The material word that decides each clause of ``words`` that names one, in order
    ("warm oak linen and brass" -> ["linen", "brass"]: "oak" there is a colour)."""
    t = _tables(kb)
    return [" ".join(won[0]) for c in clauses(words, kb) if (won := _winner(c, t)) is not None]


def clauses(words: str, kb: KnowledgeBase | None = None) -> list[str]:
    """The clauses of a material phrase, in order."""
    return [c for c in _tables(kb).split.split(words.lower()) if c.strip()]


def material_clauses(words: str, kb: KnowledgeBase | None = None) -> list[tuple[dict[str, Any], list[str]]]:
    """(entry, words) for each clause of ``words`` that names a material in ``kb``, in order
    (the entries are the lexicon's own: read them, do not change them)."""
    return [(entry, list(ws)) for entry, ws in _material_clauses(words, _kb(kb))]


@lru_cache(maxsize=4096)
def _material_clauses(words: str, kb: KnowledgeBase) -> tuple[tuple[dict[str, Any], tuple[str, ...]], ...]:
    t = _tables(kb)
    return tuple((m[0], tuple(m[1])) for c in clauses(words, kb) if (m := _match(c, t)) is not None)


def _kind_defaults(kind: str, variant: str, kb: KnowledgeBase | None) -> dict[str, Any]:
    base = dict(_data(kb)["kinds"][kind])
    variants = base.pop("variants", {}) or {}
    base.update(variants.get(variant, {}))
    return base


def _finish(words: list[str], kb: KnowledgeBase | None) -> tuple[float, float]:
    """(roughness shift, colour tone factor) named by finish and tone words."""
    data = _data(kb)
    finish, tone = data.get("finish") or {}, data.get("tone") or {}
    dr = sum(float(finish[w]) for w in words if w in finish)
    factor = 1.0
    for w in words:
        if w in tone:
            factor *= float(tone[w])
    return dr, factor


def spec_from_entry(entry: dict[str, Any], surface: str, words: list[str], color: str | None,
                    size_px: int | None = None, kb: KnowledgeBase | None = None) -> MaterialSpec:
    """Resolve a lexicon entry for a surface into a spec.

    The kind first becomes the surface's kind (``surfaces.<surface>.becomes``), then the
    entry's own override for the surface applies; kind defaults fill what is left.
    """
    if surface not in SURFACES:
        raise ValueError(f"surface must be one of {', '.join(SURFACES)}, got {surface!r}")
    own = entry.get(surface) or {}
    kind = str(entry["kind"])
    kind = str(own.get("kind", _data(kb)["surfaces"][surface]["becomes"].get(kind, kind)))
    variant = str(own.get("variant", entry.get("variant", "") if kind == entry["kind"] else ""))
    if variant not in _known_variants(kind, kb):
        variant = ""
    d = _kind_defaults(kind, variant, kb)
    d.update({k: v for k, v in {**entry, **own}.items() if k in _OVERRIDABLE})
    dr, tone = _finish(words, kb)
    base = color or d.get("color", "#b0aaa0")
    if tone != 1.0:
        base = to_hex(shade(to_rgba(base)[:3].astype(float), tone))
    return MaterialSpec(
        kind=kind,
        variant=variant,
        color=str(base),
        roughness=round(min(1.0, max(MIN_ROUGHNESS, float(d.get("roughness", 0.6)) + dr)), 3),
        metallic=float(d.get("metallic", 0.0)),
        tile_m=float(d.get("tile_m", 1.0)),
        alpha=float(d.get("alpha", 1.0)),
        size_px=texture_size_px(size_px),
        weathered=weathered(words, kb),
    )


STRUCTURE_CEILING = "white plaster"
"""The ceiling between beams or coffers when its words name nothing else for it."""


def find_structure(words: str, kb: KnowledgeBase | None = None) -> tuple[str, str, str] | None:
    """(phrase, structure, rest) of the first ceiling-structure phrase in ``words``
    (materials.yaml ``ceiling_structure``, the longest first): the phrase as found,
    "beams" or "coffers", and the words around it; None without one."""
    table = _data(kb).get("ceiling_structure") or {}
    ws = _words(words)
    for phrase in sorted(table, key=lambda p: -len(p.split())):
        pw = _words(phrase)
        for i in range(len(ws) - len(pw) + 1):
            if ws[i:i + len(pw)] == pw:
                return " ".join(pw), str(table[phrase]), " ".join(ws[:i] + ws[i + len(pw):])
    return None


def ceiling_structure(words: str, kb: KnowledgeBase | None = None) -> tuple[str | None, str]:
    """(structure, rest): the geometry a ceiling's words ask for ("beams", "coffers" or
    None) and the words left for the ceiling surface itself ("exposed oak beams" ->
    ("beams", "exposed"): "oak beams" is the structure's phrase)."""
    found = find_structure(words, kb)
    return (found[1], found[2]) if found else (None, words)


def ceiling_materials(words: str, size_px: int | None = None, kb: KnowledgeBase | None = None
                      ) -> tuple[MaterialSpec, str | None, MaterialSpec | None]:
    """(ceiling, structure, structure's material) of a ceiling's words. Without a
    structure word: the ceiling as :func:`surface_material` makes it, None, None. With
    one, the beams take the wood (the words as furniture: "exposed oak beams" are oak)
    and the ceiling between them keeps the other material clauses, else
    :data:`STRUCTURE_CEILING`; coffers are of the ceiling's own material."""
    structure, rest = ceiling_structure(words, kb)
    if structure is None:
        return surface_material(words, "ceiling", size_px, kb=kb), None, None
    kept = [c for c in clauses(rest, kb)
            if (found := material_clauses(c, kb)) and not any(e.get("kind") in ("wood", "planks") for e, _ in found)]
    ceiling = surface_material(" ".join(kept) or STRUCTURE_CEILING, "ceiling", size_px, kb=kb)
    own = surface_material(words, "furniture", size_px, kb=kb) if structure == "beams" else ceiling
    return ceiling, structure, own


def weathered(words: list[str] | str, kb: KnowledgeBase | None = None) -> bool:
    """Whether material words say the surface is aged (materials.yaml ``weathering``)."""
    ws = _words(words) if isinstance(words, str) else words
    return bool(set(ws) & set(_data(kb).get("weathering") or ()))


def _known_variants(kind: str, kb: KnowledgeBase | None) -> set[str]:
    return set((_data(kb)["kinds"].get(kind) or {}).get("variants", {}) or {}) | set(VARIANTS.get(kind, ()))


def surface_material(words: str, surface: str, size_px: int | None = None,
                     color: str | None = None, kb: KnowledgeBase | None = None) -> MaterialSpec:
    """The material a surface made of ``words`` gets.

    Parameters
    ----------
    words : material words ("dark walnut planks", "blue velvet"); may be empty
    surface : "floor", "walls", "ceiling" or "furniture"
    size_px : texture size (default: :func:`texture_size_px`)
    color : base colour to use instead of the one the words name
    kb : the knowledge base the words are read in (None: the one in force)
    """
    if surface not in SURFACES:
        raise ValueError(f"surface must be one of {', '.join(SURFACES)}, got {surface!r}")
    return _surface_material(words or "", surface, texture_size_px(size_px), color, _kb(kb))


@lru_cache(maxsize=4096)
def _surface_material(words: str, surface: str, size_px: int, color: str | None, kb: KnowledgeBase) -> MaterialSpec:
    """:func:`surface_material` once per phrase, surface, size, colour and knowledge base
    (an export asks for the same few phrases hundreds of times; the spec is frozen)."""
    found = material_clauses(words, kb)
    if found:
        entry, clause_words = found[0]
    else:
        default = _data(kb)["surfaces"][surface]["default"] or ""
        hit = material_clauses(default, kb)
        entry, clause_words = hit[0] if hit else ({"kind": "plain"}, [])
        color = color or material_color(words, kb) or material_color(default, kb)
    color = color or material_color(" ".join(clause_words), kb) or material_color(words, kb)
    spec = spec_from_entry(entry, surface, clause_words, color, size_px, kb)
    if not spec.weathered and weathered(words, kb):  # "dusty, dark oak": the whole phrase ages it
        spec = replace(spec, weathered=True)
    return spec

