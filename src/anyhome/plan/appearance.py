"""Styles, palettes and material words for the offline planner (``knowledge/styles.yaml``)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from anyhome.plan.knowledge import load
from anyhome.plan.parse import Parsed

WOOD_WORDS = ("wood", "wooden", "oak", "walnut", "pine", "bamboo", "teak", "mahogany", "birch", "ebony")
"""Materials that read as planks when put on a floor."""


@dataclass
class Look:
    """The chosen appearance of the house."""

    styles: list[str]
    describe: str
    palette: list[str]
    floor: str
    walls: str
    ceiling: str
    furniture: str
    room_overrides: dict[int, dict[str, str]] = field(default_factory=dict)  # mention idx -> surface -> words
    notes: list[str] = field(default_factory=list)
    user_surfaces: set[str] = field(default_factory=set)  # house-wide surfaces the text set


def choose_look(parsed: Parsed, implied: list[str], building: str, rng: np.random.Generator) -> Look:
    data = load("styles")
    styles = data["styles"]
    keys = [k for k in [*parsed.styles, *implied] if k in styles]
    keys = list(dict.fromkeys(keys))
    if not keys:
        pool = data["defaults"].get(building) or data["defaults"]["*"]
        keys = [str(pool[int(rng.integers(len(pool)))])]
    lead = styles[keys[0]]
    describe = "; ".join(styles[k]["describe"] for k in keys)
    own = [w for w in parsed.style_words if w not in describe]
    if own:  # the user's own words lead ("moroccan: mediterranean, terracotta...")
        describe = ", ".join(own) + ": " + describe
    palette = list(dict.fromkeys([*parsed.colours, *lead["palette"], *(c for k in keys[1:] for c in styles[k]["palette"][:1])]))
    look = Look(keys, describe, palette, lead["floor"], lead["walls"], lead["ceiling"], lead["furniture"])
    furniture_words: list[str] = []
    for mm in parsed.materials:
        for surface in mm.surfaces:
            words = mm.phrase
            if surface == "floor" and mm.material in WOOD_WORDS or surface == "floor" and any(w in mm.material for w in WOOD_WORDS) and "plank" not in words:
                words = f"{mm.phrase} planks" if not mm.phrase.endswith(("floor", "floors", "planks")) else mm.phrase
            if mm.room is not None:
                look.room_overrides.setdefault(mm.room, {})[surface] = words
            elif surface == "furniture":
                furniture_words.append(mm.phrase)
            else:
                setattr(look, surface, words)
                if mm.explicit:
                    look.user_surfaces.add(surface)
        look.notes.append(mm.phrase)
    if furniture_words:
        look.furniture = ", ".join(dict.fromkeys(furniture_words))
    if look.notes:
        look.describe += "; " + ", ".join(dict.fromkeys(look.notes))
    if parsed.colours:
        look.describe += "; accents of " + ", ".join(parsed.colours)
    return look


def item_material(category: str, look: Look, furniture: str, rng: np.random.Generator) -> str:
    pattern = load("styles")["category_materials"].get(category, "{furniture}")
    colour = look.palette[int(rng.integers(len(look.palette)))] if look.palette else "neutral"
    return str(pattern).format(furniture=furniture, colour=colour)
