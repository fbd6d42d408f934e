"""Loading the offline planner's knowledge base (YAML files in ``knowledge/``).

The files are read once per process and cached. ``vocabulary()`` compiles every
phrase of the knowledge base (buildings, rooms, objects, styles, materials) into
lookup tables and regular expressions used by :mod:`anyhome.plan.parse`.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from anyhome.errors import PlanError

KNOWLEDGE_DIR = Path(__file__).with_name("knowledge")
"""Folder holding programs.yaml, rooms.yaml, objects.yaml, furniture.yaml, styles.yaml."""

KNOWLEDGE_FILES = ("programs", "rooms", "objects", "furniture", "styles", "concepts")


def normalize(text: str) -> str:
    """Lower-case, unify quotes and hyphens to spaces (a minus sign before a figure,
    "-3", stays), collapse whitespace."""
    t = text.lower().replace("\u2019", "'").replace("\u2018", "'")
    t = re.sub(r"(?!(?<!\S)-\d)[-\u2010-\u2015_/]+", " ", t)
    return re.sub(r"\s+", " ", t).strip()


@functools.lru_cache(maxsize=None)
def load(name: str) -> dict[str, Any]:
    """Return the parsed content of ``knowledge/<name>.yaml`` (cached)."""
    path = KNOWLEDGE_DIR / f"{name}.yaml"
    try:
        with path.open(encoding="utf-8") as f:
            data = yaml.load(f, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except (OSError, yaml.YAMLError) as e:
        raise PlanError(f"cannot read knowledge file {path}: {e}") from None
    if not isinstance(data, dict):
        raise PlanError(f"knowledge file {path} must hold a mapping")
    return data


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


def _alternation(phrases: list[str]) -> re.Pattern[str]:
    alts = sorted(set(phrases), key=lambda p: (-len(p), p))
    body = "|".join(re.escape(p) for p in alts)
    return re.compile(rf"(?<![\w'])(?:{body})(?![\w])")


@functools.lru_cache(maxsize=None)
def vocabulary() -> Vocabulary:
    """Compile every phrase of the knowledge base into lookup tables (cached)."""
    forms: dict[str, tuple[Entry, bool]] = {}
    for key, proto in load("objects").items():
        for phrase in [key, *proto.get("synonyms", [])]:
            p = normalize(phrase)
            for i, f in enumerate(_plural_forms(p)):
                forms.setdefault(f, (Entry("object", key, p), i > 0))
    for key in load("rooms")["names"]:
        p = normalize(key)
        for i, f in enumerate(_plural_forms(p)):
            # room words win over object words of the same spelling
            forms[f] = (Entry("room", key, p), i > 0)
    building_forms: dict[str, int] = {}
    for i, b in enumerate(load("programs")["buildings"]):
        for w in b["words"]:
            for f in _plural_forms(normalize(w))[:1]:
                building_forms.setdefault(f, i)
    styles = load("styles")
    style_forms = {normalize(w): k for k, s in styles["styles"].items() for w in s["words"]}
    mats = [normalize(m) for m in styles["materials"]]
    cols = [normalize(c) for c in styles["colours"]]
    return Vocabulary(
        forms=forms,
        regex=_alternation(list(forms)),
        building_forms=building_forms,
        building_regex=_alternation(list(building_forms)),
        style_forms=style_forms,
        style_regex=_alternation(list(style_forms)),
        material_regex=_alternation(mats),
        colour_regex=_alternation(cols),
    )
