"""Asset style classes: how a style shapes and colours the procedural assets.

The knowledge lives in ``plan/knowledge/styles.yaml``: every style names its
``asset_class``, and ``asset_classes`` says what each class means (its traits, leg
shapes, wood and fabric colours). The assets stage resolves the style once, in the run's
knowledge base (:func:`style_class` with ``kb``), and hands the factories the
:class:`StyleClass` itself, so a class a user's knowledge base adds reaches them with no
knowledge base in force. A factory may also be given a string (a style key such as
"gothic", or an asset class name such as "antique": tools and tests); that is read in
the knowledge base in force; anything else (no style, prose) is the ``plain`` class.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any, TypeAlias

from anyhome.errors import PlanError

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

DEFAULT_CLASS = "plain"
"""The class of no style: random leg shapes, every wood tone."""
TRAITS = frozenset({"antique", "modern", "industrial", "rustic", "eastern"})
"""The broad looks factories choose forms by."""
LEG_SHAPES = frozenset({"straight", "tapered", "turned", "metal"})
"""Leg shapes ``Builder.legs`` draws."""
_HEX = re.compile(r"#[0-9a-fA-F]{6}")
_FILE = "styles.yaml"


@dataclass(frozen=True)
class StyleClass:
    """One asset style class of ``styles.yaml``'s ``asset_classes``."""

    name: str
    traits: frozenset[str]
    legs: tuple[str, ...]
    woods: tuple[str, ...]
    fabrics: tuple[str, ...]


Style: TypeAlias = "str | StyleClass"
"""What a factory's ``style`` is: a resolved :class:`StyleClass` (the assets stage), or a
style key or class name (read in the knowledge base in force)."""


def _bad(key: str, what: str) -> PlanError:
    return PlanError(f"{_FILE}: {key}: {what}")


def _colours(key: str, value: Any) -> tuple[str, ...]:
    if not isinstance(value, list) or not value or not all(isinstance(c, str) and _HEX.fullmatch(c) for c in value):
        raise _bad(key, "must be a non-empty list of #rrggbb colours")
    return tuple(value)


def _parse_class(name: str, entry: Any) -> StyleClass:
    where = f"asset_classes.{name}"
    if not isinstance(entry, dict):
        raise _bad(where, "must be a mapping with traits, legs, woods and fabrics")
    unknown = sorted(set(entry) - {"traits", "legs", "woods", "fabrics"})
    if unknown:
        raise _bad(f"{where}.{unknown[0]}", "unknown field (known: traits, legs, woods, fabrics)")
    traits = entry.get("traits", [])
    if not isinstance(traits, list) or not set(traits) <= TRAITS:
        raise _bad(f"{where}.traits", f"must be a list of {', '.join(sorted(TRAITS))}")
    legs = entry.get("legs")
    if not isinstance(legs, list) or not legs or not set(legs) <= LEG_SHAPES:
        raise _bad(f"{where}.legs", f"must be a non-empty list of {', '.join(sorted(LEG_SHAPES))}")
    return StyleClass(name, frozenset(traits), tuple(legs), _colours(f"{where}.woods", entry.get("woods")),
                      _colours(f"{where}.fabrics", entry.get("fabrics")))


@lru_cache(maxsize=8)
def _tables(kb: KnowledgeBase) -> tuple[dict[str, StyleClass], dict[str, str]]:
    data = kb.raw("styles")
    raw = data.get("asset_classes")
    if not isinstance(raw, dict) or DEFAULT_CLASS not in raw:
        raise _bad("asset_classes", f"must be a mapping that holds the {DEFAULT_CLASS!r} class")
    classes = {str(k): _parse_class(str(k), v) for k, v in raw.items()}
    of_style: dict[str, str] = {}
    for key, entry in data.get("styles", {}).items():
        cls = entry.get("asset_class") if isinstance(entry, dict) else None
        if cls is None:
            raise _bad(f"styles.{key}.asset_class", f"missing (write {DEFAULT_CLASS} for no particular look)")
        if cls not in classes:
            raise _bad(f"styles.{key}.asset_class", f"unknown class {cls!r} (known: {', '.join(sorted(classes))})")
        if key in classes and cls != key:
            raise _bad(f"styles.{key}.asset_class", f"a style named like the class {key!r} must use it")
        of_style[str(key)] = str(cls)
    return classes, of_style


def asset_classes(kb: KnowledgeBase | None = None) -> dict[str, StyleClass]:
    """Every asset style class by name (of ``kb``; None: the knowledge base in force)."""
    return dict(_tables(_kb(kb))[0])


def class_name(style: Style | Sequence[str], kb: KnowledgeBase | None = None) -> str:
    """The asset class name of a style key, an asset class name, or a list of style keys
    (the first one known leads); :data:`DEFAULT_CLASS` when none is known. A
    :class:`StyleClass` is its own name (no knowledge base is read)."""
    if isinstance(style, StyleClass):
        return style.name
    classes, of_style = _tables(_kb(kb))
    for key in [style] if isinstance(style, str) else style:
        k = str(key).strip().lower().replace(" ", "_").replace("-", "_")
        if k in of_style:
            return of_style[k]
        if k in classes:
            return k
    return DEFAULT_CLASS


def style_class(style: Style | Sequence[str], kb: KnowledgeBase | None = None) -> StyleClass:
    """The :class:`StyleClass` of a style (see :func:`class_name`) in ``kb``; a
    :class:`StyleClass` is returned as it is (no knowledge base is read)."""
    if isinstance(style, StyleClass):
        return style
    kb = _kb(kb)
    return _tables(kb)[0][class_name(style, kb)]


def _kb(kb: KnowledgeBase | None) -> KnowledgeBase:
    """``kb``, else the knowledge base in force: the explicit default for a caller that
    names a style by a string and passes no knowledge base (tools, tests, the knob
    ranges of :mod:`anyhome.house`); the assets stage always passes its own."""
    from anyhome.plan.kbview import default

    return kb if kb is not None else default()
