"""Material and colour words to base colours.

The word lists live in ``colors.yaml`` next to this module. Colours are sRGB hex
strings (``"#rrggbb"``) everywhere a record stores them, so they survive JSON.
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

_COLORS_FILE = Path(__file__).with_name("colors.yaml")
"""Material words -> base colour (the colour words live in ``plan/knowledge/colours.yaml``)."""

RGB = tuple[int, int, int]


@lru_cache(maxsize=1)
def _material_rgb() -> dict[str, RGB]:
    import yaml

    data = yaml.safe_load(_COLORS_FILE.read_text(encoding="utf-8"))
    return {str(k): (int(v[0]), int(v[1]), int(v[2])) for k, v in data["materials"].items()}


@lru_cache(maxsize=8)
def _colour_tables(kb: Any) -> tuple[dict[tuple[str, ...], RGB], int, dict[str, float], dict[str, float]]:
    """(colour phrase as words -> RGB, most words in a phrase, modifiers, muting) of a
    knowledge base's colours.yaml."""
    c = kb.colours
    phrases = {tuple(_words(k)): (int(v[0]), int(v[1]), int(v[2])) for k, v in c.colours.items()}
    return phrases, max(len(p) for p in phrases), dict(c.modifiers), dict(c.muting)


def _tables() -> tuple[dict[tuple[str, ...], RGB], int, dict[str, RGB], dict[str, float], dict[str, float]]:
    from anyhome.plan.knowledge import knowledge_base

    phrases, longest, modifiers, muting = _colour_tables(knowledge_base())
    return phrases, longest, _material_rgb(), modifiers, muting


def _words(text: str) -> list[str]:
    return re.findall(r"[a-z]+", text.lower())


def material_color(text: str) -> str | None:
    """Base colour named by a material phrase, or None if it names none.

    Colour words (``plan/knowledge/colours.yaml``; the longest phrase: "sky blue") win
    over material words ("pink velvet" is pink); a two-word material
    ("white oak") wins over its parts; the modifiers right before the match shade it
    ("dark") or mute it ("faded": greyer).

    >>> material_color("dark walnut")
    '#392518'
    """
    colors, longest, materials, modifiers, muting = _tables()
    words = _words(text)
    found: tuple[int, int, int] | None = None
    at = -1
    for i in range(len(words) - 1):  # two-word materials first
        pair = f"{words[i]} {words[i + 1]}"
        if pair in materials:
            found, at = materials[pair], i
            break
    if found is None:
        for i in range(len(words)):  # the first colour, its longest phrase ("sky blue")
            n = next((n for n in range(min(longest, len(words) - i), 0, -1) if tuple(words[i:i + n]) in colors), 0)
            if n:
                found, at = colors[tuple(words[i:i + n])], i
                break
    if found is None:
        for i, w in enumerate(words):
            if w in materials:
                found, at = materials[w], i
                break
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
