"""Loading the offline planner's knowledge base (YAML files in ``knowledge/``).

The files are read once per process and cached. ``vocabulary()`` compiles every
phrase of the knowledge base (buildings, rooms, objects, styles, materials) into
lookup tables and regular expressions used by :mod:`anyhome.plan.parse`.
"""

from __future__ import annotations

import functools
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from anyhome.errors import KnowledgeError
from anyhome.plan.kb import SECTIONED, KnowledgeBase, Source

KNOWLEDGE_DIR = Path(__file__).with_name("knowledge")
"""Folder holding the shipped programs.yaml, rooms.yaml, objects.yaml, furniture.yaml,
styles.yaml and concepts.yaml."""

KNOWLEDGE_FILES = ("programs", "rooms", "objects", "furniture", "styles", "concepts", "surfaces", "assets", "colours",
                   "materials", "heights")


def normalize(text: str) -> str:
    """Lower-case, unify quotes and hyphens to spaces (a minus sign before a figure,
    "-3", stays; a dash between words, "a small footprint - kitchen on the bottom floor",
    "a footprint—kitchen", is a comma: it ends a name), collapse whitespace."""
    t = text.lower().replace("\u2019", "'").replace("\u2018", "'")
    t = re.sub(r"\s+[-\u2013\u2014]+\s+|\s*\u2014\s*", ", ", t)
    t = re.sub(r"(?!(?<!\S)-\d)[-\u2010-\u2015_/]+", " ", t)
    return re.sub(r"\s+", " ", t).strip()


ENV_VAR = "ANYHOME_KNOWLEDGE_PATH"
"""Environment variable naming the user's knowledge folders (several separated by
``os.pathsep``; later folders win)."""

_cli_dirs: tuple[str, ...] = ()
"""Folders given with ``--knowledge DIR`` (after those of :data:`ENV_VAR`: they win)."""

_DEPENDENT_CACHES = (("anyhome.plan.concepts", "_index"), ("anyhome.assets.styles", "_tables"))
"""Caches elsewhere computed from the knowledge without an argument that says which:
cleared whenever the overlay changes (the caches here are keyed by it)."""

_last_overlay: tuple[str, ...] | None = None


def use_knowledge(dirs: list[str] | tuple[str, ...] | None) -> None:
    """Add the user's knowledge folders (``--knowledge DIR``) on top of the shipped files
    and :data:`ENV_VAR`'s; ``None`` or ``[]`` drops them again."""
    global _cli_dirs
    _cli_dirs = tuple(str(d) for d in dirs or ())


def overlay() -> tuple[str, ...]:
    """The user's knowledge folders in force, lowest priority first."""
    env = os.environ.get(ENV_VAR, "")
    return tuple(p for p in env.split(os.pathsep) if p.strip()) + _cli_dirs


def _sync() -> tuple[str, ...]:
    """The overlay in force; clears the dependent caches when it changed since the last call."""
    global _last_overlay
    key = overlay()
    if key != _last_overlay:
        if _last_overlay is not None:
            for module, attr in _DEPENDENT_CACHES:
                mod = sys.modules.get(module)
                fn = getattr(mod, attr, None) if mod is not None else None
                if fn is not None and hasattr(fn, "cache_clear"):
                    fn.cache_clear()
        _last_overlay = key
    return key


@functools.lru_cache(maxsize=64)
def _read(path: Path, user: bool) -> dict[str, Any]:
    """One YAML file's top-level mapping (an empty user file is an empty mapping)."""
    try:
        with path.open(encoding="utf-8") as f:
            data = yaml.load(f, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark is not None else "top level"
        what = " ".join(str(getattr(e, "problem", None) or e).split())
        raise KnowledgeError(f"{path}: {where}: invalid YAML: {what}") from None
    except (OSError, UnicodeDecodeError) as e:
        raise KnowledgeError(f"{path}: top level: cannot read: {getattr(e, 'strerror', None) or e}") from None
    if data is None and user:
        return {}
    if not isinstance(data, dict):
        raise KnowledgeError(f"{path}: top level: must be a mapping (key: value lines), got {type(data).__name__}")
    return data


def _user_files(folder: str) -> dict[str, Path]:
    d = Path(folder).expanduser()
    if not d.is_dir():
        raise KnowledgeError(f"{d}: top level: knowledge folder not found (from ${ENV_VAR} or --knowledge)")
    files: dict[str, Path] = {}
    for p in sorted(d.iterdir()):
        if p.suffix.lower() in (".yaml", ".yml"):
            if p.stem not in KNOWLEDGE_FILES or p.suffix != ".yaml":
                raise KnowledgeError(f"{p}: top level: not a knowledge file (known: "
                                     f"{', '.join(n + '.yaml' for n in KNOWLEDGE_FILES)})")
            files[p.stem] = p
    return files


def _merge_entries(base: dict[Any, Any], user: dict[Any, Any], prefix: tuple[Any, ...], path: str,
                   src: dict[tuple[Any, ...], str]) -> None:
    """Entries key by key: a new key adds its entry; a known key whose old and new values
    are both mappings gets the new fields (each field replaced whole); else replaced."""
    for k, v in user.items():
        old = base.get(k)
        if isinstance(old, dict) and isinstance(v, dict):
            base[k] = {**old, **v}
            for f in v:
                src[prefix + (k, f)] = path
        else:
            base[k] = v
            src[prefix + (k,)] = path


def _merge(name: str, base: dict[str, Any], user: dict[str, Any], path: str,
           src: dict[tuple[Any, ...], str]) -> dict[str, Any]:
    out = dict(base)
    if name not in SECTIONED:
        _merge_entries(out, user, (), path, src)
        return out
    for sec, uv in user.items():
        old = out.get(sec)
        src[(sec,)] = path
        if isinstance(old, list) and isinstance(uv, list):
            if sec == "buildings":  # the user's building words come first: they win
                shipped = [src.get((sec, i), "") for i in range(len(old))]
                out[sec] = uv + old
                for i, p in enumerate([path] * len(uv) + shipped):
                    src[(sec, i)] = p
            else:
                out[sec] = old + [x for x in uv if x not in old]
        elif isinstance(old, dict) and isinstance(uv, dict):
            out[sec] = dict(old)
            _merge_entries(out[sec], uv, (sec,), path, src)
        else:
            out[sec] = uv
    return out


@functools.lru_cache(maxsize=8)
def _raw(key: tuple[str, ...]) -> tuple[dict[str, dict[str, Any]], dict[str, dict[tuple[Any, ...], str]]]:
    """Every knowledge file merged with the overlay ``key``, and where each entry came from."""
    data = {name: _read(KNOWLEDGE_DIR / f"{name}.yaml", False) for name in KNOWLEDGE_FILES}
    sources: dict[str, dict[tuple[Any, ...], str]] = {name: {} for name in KNOWLEDGE_FILES}
    for folder in key:
        for name, path in _user_files(folder).items():
            data[name] = _merge(name, data[name], _read(path, True), str(path), sources[name])
    return data, sources


def _source(sources: dict[str, dict[tuple[Any, ...], str]]) -> Source:
    def source(name: str, loc: tuple[Any, ...]) -> str:
        src = sources[name]
        for n in range(len(loc), 0, -1):
            if tuple(loc[:n]) in src:
                return src[tuple(loc[:n])]
        return str(KNOWLEDGE_DIR / f"{name}.yaml")

    return source


@functools.lru_cache(maxsize=8)
def _knowledge_base(key: tuple[str, ...]) -> KnowledgeBase:
    data, sources = _raw(key)
    return KnowledgeBase(data, _source(sources))


def knowledge_base(dirs: list[str] | tuple[str, ...] | None = None) -> KnowledgeBase:
    """The validated knowledge (shipped files and the user's overlay), built once per
    overlay; a bad entry raises :class:`KnowledgeError` (``FILE: KEY: what is wrong``).
    ``dirs``: exactly these user folders on top of the shipped files (no
    :data:`ENV_VAR`, no ``--knowledge``); None: the overlay in force."""
    if dirs is not None:
        return _knowledge_base(tuple(str(d) for d in dirs))
    return _knowledge_base(_sync())


def load(name: str) -> dict[str, Any]:
    """The content of ``knowledge/<name>.yaml`` merged with the user's overlay (see
    :func:`overlay`), as plain mappings; every file is validated (once per overlay) before
    any is handed out."""
    if name not in KNOWLEDGE_FILES:
        raise KeyError(name)
    key = _sync()
    _knowledge_base(key)
    return _raw(key)[0][name]


def _plural_forms(phrase: str) -> list[str]:
    forms = [phrase]
    head = phrase.rsplit(" ", 1)[-1]
    if head.endswith(("s", "x", "ch", "sh")):
        forms.append(phrase + "es")
    elif head.endswith("y") and head[-2:-1] not in "aeiou":
        forms.append(phrase[:-1] + "ies")
    elif head.endswith("f"):
        forms.append(phrase[:-1] + "ves")
        forms.append(phrase + "s")
    else:
        forms.append(phrase + "s")
    # "partners' offices", "teachers' lounges": the plural's possessive is the owners'
    owners = re.compile(r"\b(\w+[^s\W])(?<!men)(?<!children)(?<!people)'s ")
    forms += [owners.sub(r"\1s' ", f) for f in forms[1:] if owners.search(f)]
    return forms


@dataclass(frozen=True)
class Entry:
    """What a phrase in the text means."""

    kind: str  # "building" | "room" | "object"
    key: str  # program key, room phrase key, or object prototype key
    phrase: str  # the normalized phrase (singular)


@dataclass(frozen=True)
class Vocabulary:
    forms: dict[str, tuple[Entry, bool]]  # surface form -> (entry, is_plural)
    regex: re.Pattern[str]
    building_forms: dict[str, int]  # phrase -> index into programs.yaml buildings
    building_regex: re.Pattern[str]
    style_forms: dict[str, str]  # phrase -> style key
    style_regex: re.Pattern[str]
    material_regex: re.Pattern[str]
    colour_regex: re.Pattern[str]
    finish_regex: re.Pattern[str]  # weathering words and the words of ceiling structures ("peeling", "exposed")
    hidden_objects: dict[str, tuple[Entry, bool]] = field(default_factory=dict)  # object forms a room word of the same spelling hides


def _alternation(phrases: list[str]) -> re.Pattern[str]:
    alts = sorted(set(phrases), key=lambda p: (-len(p), p))
    body = "|".join(re.escape(p) for p in alts)
    return re.compile(rf"(?<![\w'])(?:{body})(?![\w])")


def vocabulary() -> Vocabulary:
    """Compile every phrase of the knowledge base into lookup tables (cached per overlay)."""
    return _vocabulary(_sync())


def _vocabulary(overlay_key: tuple[str, ...]) -> Vocabulary:
    from anyhome.plan.kbview import vocabulary as kb_vocabulary

    return kb_vocabulary(_knowledge_base(overlay_key))


def planner_materials(kb: KnowledgeBase) -> dict[str, list[str]]:
    """The planner's material words (materials.yaml words with ``goes_on``) -> the
    surfaces each goes on when the text does not say."""
    return {w: list(e.goes_on) for w, e in kb.materials.words.items() if e.goes_on}


def compile_vocabulary(kb: KnowledgeBase) -> Vocabulary:
    """Every phrase of ``kb`` compiled into lookup tables (use
    :func:`anyhome.plan.kbview.vocabulary`: cached per knowledge base)."""

    def load(name: str) -> dict[str, Any]:
        return kb.raw(name)

    forms: dict[str, tuple[Entry, bool]] = {}
    for key, proto in load("objects").items():
        for phrase in [key, *proto.get("synonyms", [])]:
            p = normalize(phrase)
            for i, f in enumerate(_plural_forms(p)):
                forms.setdefault(f, (Entry("object", key, p), i > 0))
    hidden: dict[str, tuple[Entry, bool]] = {}
    for key in load("rooms")["names"]:
        p = normalize(key)
        for i, f in enumerate(_plural_forms(p)):
            # room words win over object words of the same spelling (kept aside for a
            # room word that names a room in some buildings alone: an archery club's "range")
            if f in forms and forms[f][0].kind == "object":
                hidden[f] = forms[f]
            forms[f] = (Entry("room", key, p), i > 0)
    building_forms: dict[str, int] = {}
    for i, b in enumerate(load("programs")["buildings"]):
        for w in b["words"]:
            for f in _plural_forms(normalize(w))[:1]:
                building_forms.setdefault(f, i)
    styles = load("styles")
    style_forms = {normalize(w): k for k, s in styles["styles"].items() for w in s["words"]}
    mats = [normalize(m) for m in planner_materials(kb)]
    colours = load("colours")
    cols = [normalize(c) for c in [*colours["colours"], *colours.get("modifiers", {})]]
    finish = [normalize(w) for w in load("materials").get("weathering") or []]
    finish += [normalize(w) for phrase in load("materials").get("ceiling_structure") or {} for w in phrase.split()]
    return Vocabulary(
        forms=forms,
        regex=_alternation(list(forms)),
        building_forms=building_forms,
        building_regex=_alternation(list(building_forms)),
        style_forms=style_forms,
        style_regex=_alternation(list(style_forms)),
        material_regex=_alternation(mats),
        colour_regex=_alternation(cols),
        finish_regex=_alternation(finish or ["\x00"]),
        hidden_objects=hidden,
    )
