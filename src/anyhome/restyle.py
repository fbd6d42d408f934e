"""Restyling an existing house: new materials and assets, nothing moved.

:func:`restyle` re-derives what a style decides, as the planner and the assets stage
do: every room's floor, walls and ceiling words, every object's material words and
its asset record (``assign_asset``). Geometry is never touched: object ids,
positions, sizes, yaws, supports and rooms, room polygons, doors and windows stay as
they were.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from anyhome.errors import AnyHomeError
from anyhome.house import House, HouseObject

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

RESTYLE_STREAM = 7
"""Child stream of the house seed the new material words draw from; assets draw from
the pipeline's own assets stream, so restyling a house twice gives the same house."""


def _keys(style: str | Sequence[str], kb: KnowledgeBase) -> list[str]:
    from anyhome.plan.appearance import style_keys

    known = kb.raw("styles")["styles"]
    if isinstance(style, str):
        keys = style_keys(style, open_vocab=True, kb=kb) if style.strip() else []
    else:
        keys = [str(k).strip().lower().replace(" ", "_").replace("-", "_") for k in style]
        if any(k not in known for k in keys):
            keys = []
    if not keys:
        shown = style if isinstance(style, str) else ", ".join(map(str, style))
        raise AnyHomeError(f"unknown style {shown[:80]!r}; known styles include {', '.join(list(known)[:10])}")
    return list(dict.fromkeys(keys))


def restyle(house: House, style: str | Sequence[str], knowledge: KnowledgeBase | None = None) -> House:
    """A copy of ``house`` in another style.

    ``style`` is a style key of plan/knowledge/styles.yaml ("gothic"), a list of keys
    (the first leads), or free text the planner understands ("a dark gothic look",
    "craftsman"). Room materials, object materials and asset records are derived
    again (an object built from the user's asset library keeps its model; its procedural
    fallback is drawn again); the palette and the style fields follow. An unknown style raises
    :class:`AnyHomeError`. ``knowledge``: the knowledge base the styles come from
    (None: the one in force).
    """
    from anyhome.assets import assign_asset
    from anyhome.assets.library import SOURCE as LIBRARY_SOURCE
    from anyhome.assets.sets import matched_record, set_key
    from anyhome.pipeline import STAGES, _knowledge
    from anyhome.plan.appearance import item_material, look_for, room_materials

    kb = _knowledge(knowledge)
    keys = _keys(style, kb)
    look = look_for(keys, kb=kb)
    streams = np.random.SeedSequence(int(house.seed)).spawn(len(STAGES))
    asset_rng = np.random.default_rng(streams[STAGES.index("assets")])
    material_rng = np.random.default_rng([int(house.seed), RESTYLE_STREAM])
    rooms = [r.model_copy(update={"style": look.describe, "materials": {**r.materials, **room_materials(look, r.type, kb)}})
             for r in house.rooms]
    objects = []
    first: dict[tuple[str, str, str], HouseObject] = {}  # a set keeps one look (anyhome.assets.sets)
    for obj in house.objects:
        key = set_key(obj)
        if key is not None and key in first:
            new = obj.model_copy(update={"material": first[key].material})
            new.asset = matched_record(first[key].asset or {}, new)
        else:
            new = obj.model_copy(update={"material": item_material(obj.category, look, look.furniture, material_rng, kb)})
            new.asset = assign_asset(new, asset_rng, keys, kb)
            if key is not None:
                first[key] = new
        mine = obj.asset or {}
        if mine.get("source") == LIBRARY_SOURCE and new.asset is not None:
            # the user's own model stays; only its procedural fallback takes the new style
            new.asset = {**mine, "fallback": new.asset.get("fallback", new.asset)}
        objects.append(new)
    data = house.model_dump()
    data.update(style=look.describe, styles=keys, palette=look.palette,
                rooms=[r.model_dump() for r in rooms], objects=[o.model_dump() for o in objects])
    if house.plan is not None:
        data["plan"] = _restyled_plan(house.plan, look, {r.id: r.materials for r in rooms})
    return House.model_validate(data)


def _restyled_plan(plan: dict[str, Any], look: Any, materials: dict[str, dict[str, str]]) -> dict[str, Any]:
    """The house's plan with the new style, palette and room materials (its items keep
    their words: the objects carry the new ones)."""
    rooms = [{**r, "style": look.describe, "styles": [], "materials": materials.get(r.get("id", ""), r.get("materials", {}))}
             if isinstance(r, dict) else r for r in plan.get("rooms", [])]
    return {**plan, "style": look.describe, "styles": list(look.styles), "palette": list(look.palette), "rooms": rooms}
