"""Material and colour words to base colours.

Colour words live in ``plan/knowledge/colours.yaml``, material words (with their base
colour, ``color``) in ``plan/knowledge/materials.yaml``. Colours are sRGB hex
strings (``"#rrggbb"``) everywhere a record stores them, so they survive JSON.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

RGB = tuple[int, int, int]


@lru_cache(maxsize=8)
def _material_rgb(kb: Any) -> dict[str, RGB]:
    """Material word -> its base colour (materials.yaml entries with a ``color``)."""
    out: dict[str, RGB] = {}
    for word, e in kb.materials.words.items():
        if e.color is not None:
            rgb = to_rgba(e.color)
            out[" ".join(_words(word))] = (int(rgb[0]), int(rgb[1]), int(rgb[2]))
    return out


@lru_cache(maxsize=8)
def _colour_tables(kb: Any) -> tuple[dict[tuple[str, ...], RGB], int, dict[str, float], dict[str, float]]:
    """(colour phrase as words -> RGB, most words in a phrase, modifiers, muting) of a
    knowledge base's colours.yaml."""
    c = kb.colours
    phrases = {tuple(_words(k)): (int(v[0]), int(v[1]), int(v[2])) for k, v in c.colours.items()}
    return phrases, max(len(p) for p in phrases), dict(c.modifiers), dict(c.muting)


def _tables(kb: KnowledgeBase | None) -> tuple[dict[tuple[str, ...], RGB], int, dict[str, RGB], dict[str, float],
                                              dict[str, float]]:
    from anyhome.plan.kbview import resolve

    kb = resolve(kb)
    phrases, longest, modifiers, muting = _colour_tables(kb)
    return phrases, longest, _material_rgb(kb), modifiers, muting


def _words(text: str) -> list[str]:
    return re.findall(r"[^\W\d_]+", text.lower())


def material_color(text: str, kb: KnowledgeBase | None = None) -> str | None:
    """Base colour named by a material phrase in ``kb``'s colours and materials (None:
    the knowledge base in force), or None if it names none.

    Colour words (``plan/knowledge/colours.yaml``; the longest phrase: "sky blue") win
    over material words (``plan/knowledge/materials.yaml``: "pink velvet" is pink),
    except a material of several words that starts at or before the colour ("white
    oak"); with no colour word the first material decides, the longest at its place
    ("oak and wrought iron" is oak, "silvered glass" is not glass). The modifiers right
    before the match shade it ("dark") or mute it ("faded": greyer).

    >>> material_color("dark walnut")
    '#392518'
    """
    colors, longest, materials, modifiers, muting = _tables(kb)
    words = _words(text)
    longest_material = max((w.count(" ") + 1 for w in materials), default=1)

    def first(table: dict[Any, RGB], most: int, least: int, key: Any) -> tuple[int, RGB] | None:
        """(place, colour) of the first phrase of ``table`` in the words, the longest there."""
        for i in range(len(words)):
            for n in range(min(most, len(words) - i), least - 1, -1):
                if key(words[i:i + n]) in table:
                    return i, table[key(words[i:i + n])]
        return None

    colour = first(colors, longest, 1, tuple)
    several = first(materials, longest_material, 2, " ".join)
    hit: tuple[int, RGB] | None = first(materials, longest_material, 1, " ".join)
    if colour is not None:
        hit = several if several is not None and several[0] <= colour[0] else colour
    found: RGB | None = None if hit is None else hit[1]
    at = -1 if hit is None else hit[0]
    if found is None:
        return None
    rgb = np.asarray(found, dtype=float)
    for w in words[max(0, at - 2) : at]:
        if w in modifiers:
            rgb = shade(rgb, modifiers[w])
        elif w in muting:
            rgb = desaturate(rgb, muting[w])
    return to_hex(rgb)


def desaturate(rgb: np.ndarray, keep: float) -> np.ndarray:
    """Move an RGB triple towards its own grey (luma), keeping ``keep`` of the colour."""
    rgb = np.asarray(rgb, dtype=float)
    grey = float(rgb @ np.array([0.299, 0.587, 0.114]))
    return grey + (rgb - grey) * keep


def shade(rgb: np.ndarray, factor: float) -> np.ndarray:
    """Darken (factor < 1) or lighten towards white (factor > 1) an RGB triple."""
    rgb = np.asarray(rgb, dtype=float)
    if factor <= 1.0:
        return rgb * factor
    t = min(1.0, factor - 1.0)
    return rgb + (255.0 - rgb) * t


def to_hex(rgb) -> str:
    r, g, b = (int(round(min(255.0, max(0.0, float(c))))) for c in rgb)
    return f"#{r:02x}{g:02x}{b:02x}"


def to_rgba(color: str, alpha: int = 255) -> np.ndarray:
    """``"#rrggbb"`` -> (4,) uint8."""
    c = color.lstrip("#")
    return np.array([int(c[0:2], 16), int(c[2:4], 16), int(c[4:6], 16), alpha], dtype=np.uint8)


def mix(a: str, b: str, t: float) -> str:
    """Blend two hex colours: t=0 gives a, t=1 gives b."""
    ca, cb = to_rgba(a)[:3].astype(float), to_rgba(b)[:3].astype(float)
    return to_hex(ca + (cb - ca) * t)
