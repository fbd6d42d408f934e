"""Ornaments: small objects on furniture tops and on the walls, placed after the groups."""

from __future__ import annotations

from anyhome.house import HouseObject
from anyhome.layout import placement, scoring
from anyhome.layout.rules import REGISTRY
from anyhome.layout.state import RoomState
from anyhome.plan.spec import ItemSpec


def place_ornament(st: RoomState, item: ItemSpec, prev: HouseObject | None) -> HouseObject | None:
    """One copy of ornament ``item`` (``prev``: its previous copy); None (dropped) if nothing fits."""
    rule = REGISTRY[item.rule]
    if rule.placement == "top":
        obj = placement.place_on_some_top(st, item, None, None, None)
        if obj is None:
            st.drop(item.name, "no free surface to stand on")
        return obj
    ref = None
    if rule.relative:
        refs = st.match(item.target)
        ref = refs[0] if refs else None
    obj = placement.place_single(st, item, dict(item.params), ref, prev, None, None, None, 0)
    if obj is None:
        st.drop(item.name, scoring.no_fit_reason(st, item.size_m, "no free spot on the floor or walls"))
    return obj


def place_ornaments(st: RoomState) -> None:
    """Every copy of every ornament of the room, in plan order."""
    for item in st.spec.ornaments:
        prev = None
        for _ in range(item.count):
            prev = place_ornament(st, item, prev) or prev
