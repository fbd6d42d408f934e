"""Styles, palettes and material words for the offline planner (``knowledge/styles.yaml``).

A plan carries its style as keys of ``styles.yaml`` (``HouseSpec.styles``); the words
(``Look.describe``) are for display. :func:`style_keys` reads keys from free text,
:func:`look_for` makes the look of given keys, :func:`room_materials` dresses a room.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import resolve, vocabulary
from anyhome.plan.knowledge import normalize
from anyhome.plan.parse import Parsed

WOOD_WORDS = ("wood", "wooden", "oak", "walnut", "pine", "bamboo", "teak", "mahogany", "birch", "ebony")
"""Materials that read as planks when put on a floor."""

KEEP_DEFAULT_SURFACES = frozenset({"bathroom", "laundry", "changing_room", "balcony", "garage"})
"""Room types whose floor and walls keep their own materials unless the text names them
(open-air types, rooms.yaml ``open_air``, too: their outdoor floors)."""


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


def choose_look(kb: KnowledgeBase, parsed: Parsed, implied: list[str], building: str, rng: np.random.Generator) -> Look:
    data = kb.raw("styles")
    styles = data["styles"]
    keys = [k for k in [*parsed.styles, *implied] if k in styles]
    keys = list(dict.fromkeys(keys))
    if not keys:
        pool = data["defaults"].get(building) or data["defaults"]["*"]
        keys = [str(pool[int(rng.integers(len(pool)))])]
    look = look_for(keys, parsed.colours, kb)
    own = [w for w in parsed.style_words if w not in look.describe]
    if own:  # the user's own words lead ("moroccan: mediterranean, terracotta...")
        look.describe = ", ".join(own) + ": " + look.describe
    furniture_words: list[str] = []
    objects_words = [(m.start - len(" ".join(m.words)) - 1, m.start) for m in parsed.objects if m.words and not m.negated]
    for mm in parsed.materials:
        if mm.surfaces == ["furniture"] and any(a <= mm.start < b for a, b in objects_words):
            continue  # "an orange tartan sofa": the sofa's own material (plan.furnish.apply_mention), not the house's
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
    for surface, aged in parsed.aged.items():  # "dusty floors": the style's floor, dusty
        if surface in ("floor", "walls", "ceiling", "furniture"):
            setattr(look, surface, " ".join(aged) + " " + getattr(look, surface))
            look.notes.append(" ".join(aged) + " " + surface)
    if look.notes:
        look.describe += "; " + ", ".join(dict.fromkeys(look.notes))
    if parsed.colours:
        look.describe += "; accents of " + ", ".join(parsed.colours)
    return look


def style_keys(text: str, open_vocab: bool = False, kb: KnowledgeBase | None = None) -> list[str]:
    """The style keys ``text`` names, in order: a key itself ("art_deco"), the words of
    the styles ("gothic revival", "scandi"), and with ``open_vocab`` the nearest style by
    meaning of each other word ("craftsman", "spooky")."""
    kb = resolve(kb)
    styles = kb.raw("styles")["styles"]
    norm = normalize(text)
    if norm.replace(" ", "_") in styles:
        return [norm.replace(" ", "_")]
    voc = vocabulary(kb)
    keys = [voc.style_forms[m.group()] for m in voc.style_regex.finditer(norm)]
    if open_vocab and not keys:
        from anyhome.plan import openvocab as ov

        for word in norm.split():
            match = ov.map_style(word, kb)
            if match is not None:
                keys.append(match.key)
    return list(dict.fromkeys(keys))


def look_for(keys: list[str], palette: list[str] | None = None, kb: KnowledgeBase | None = None) -> Look:
    """The look of the style ``keys`` (the first leads), as :func:`choose_look` makes it
    for a text naming just these styles; ``palette`` leads the palette when given."""
    styles = resolve(kb).raw("styles")["styles"]
    lead = styles[keys[0]]
    palette = list(dict.fromkeys([*(palette or []), *lead["palette"], *(styles[k]["palette"][0] for k in keys[1:])]))
    describe = "; ".join(styles[k]["describe"] for k in keys)
    return Look(list(keys), describe, palette, lead["floor"], lead["walls"], lead["ceiling"], lead["furniture"])


def room_materials(look: Look, room_type: str, kb: KnowledgeBase | None = None) -> dict[str, str]:
    """Floor, walls and ceiling words of a room of ``room_type`` in ``look``: wet rooms and
    the types of :data:`KEEP_DEFAULT_SURFACES` keep their own floor and walls unless the
    text named them (``look.user_surfaces``)."""
    types = resolve(kb).raw("rooms")["types"]
    defaults = types.get(room_type, types["other"])["materials"]
    materials = {"floor": look.floor, "walls": look.walls, "ceiling": look.ceiling}
    info = types.get(room_type, {})
    keep = room_type in KEEP_DEFAULT_SURFACES or bool(info.get("wet")) or bool(info.get("open_air"))
    if keep:
        for surface in ("floor", "walls"):
            if surface not in look.user_surfaces:
                materials[surface] = defaults[surface]
    if info.get("open_air"):  # outdoor floor and walls (decking, pavers); no ceiling
        materials["ceiling"] = ""
    return materials


def item_material(category: str, look: Look, furniture: str, rng: np.random.Generator,
                  kb: KnowledgeBase | None = None) -> str:
    pattern = resolve(kb).raw("styles")["category_materials"].get(category, "{furniture}")
    colour = look.palette[int(rng.integers(len(look.palette)))] if look.palette else "neutral"
    return str(pattern).format(furniture=furniture, colour=colour)
