"""Ornaments: small objects on furniture tops and on the walls, placed after the groups."""

from __future__ import annotations

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout import placement, scoring
from anyhome.layout.rules import REGISTRY, Cands
from anyhome.layout.state import RoomState
from anyhome.plan.spec import ItemSpec

FLOOR_OK_CATEGORIES = frozenset({"plant", "box", "basket", "vase", "statue", "crate", "lantern"})
"""Ornament families that may stand on the floor (a potted plant, a basket) when no top is free."""
FLOOR_RULES = ("place_corner", "place_wall")
"""Rules tried, in turn, for an ornament set down on the floor."""


def place_ornament(st: RoomState, item: ItemSpec, prev: HouseObject | None) -> HouseObject | None:
    """One copy of ornament ``item`` (``prev``: its previous copy); None (dropped) if nothing fits.

    An ornament for a top goes on its target's top; when none is free, on any free top;
    then, a family that may (:data:`FLOOR_OK_CATEGORIES`), on the floor by a wall."""
    rule = REGISTRY[item.rule]
    if rule.placement == "top":
        obj = placement.place_on_some_top(st, item, None, None, None)
        if obj is None and item.target:
            obj = placement.place_on_some_top(st, item, placement.supporters(st, None), None, None)
        if obj is None and item.category in FLOOR_OK_CATEGORIES:
            for name in FLOOR_RULES:
                floor_item = item.model_copy(update={"rule": name, "target": None, "params": {}})
                obj = placement.place_single(st, floor_item, {}, None, None, None, None, None, 0)
                if obj is not None:
                    break
        if obj is None:
            st.drop(item.name, "no free surface to stand on")
        return obj
    if item.category in WINDOW_CATEGORIES and rule.kind == "wall" and st.room_windows():
        obj = _beside_window(st, item)
        if obj is not None:
            return obj
    ref = None
    if rule.relative:
        refs = st.match(item.target)
        ref = refs[0] if refs else None
    obj = placement.place_single(st, item, dict(item.params), ref, prev, None, None, None, 0)
    if obj is None:
        st.drop(item.name, scoring.no_fit_reason(st, item.size_m, "no free spot on the floor or walls"))
    return obj


WINDOW_CATEGORIES = frozenset({"curtain"})
"""Wall ornaments that hang beside a window of their room, when it has one."""
CURTAIN_PANEL_M = 0.5
"""Width of a curtain panel drawn to the side of a window."""
CURTAIN_GAP_M = 0.06
"""Gap between a panel and its window's edge (the contract's opening margin and more)."""


def _beside_window(st: RoomState, item: ItemSpec) -> HouseObject | None:
    """A curtain panel beside one of the room's windows (the side with the most room first)."""
    z = float(item.params.get("elevation_m", 0.1))
    h = min(item.size_m[2], st.space.height - st.options.ceiling_gap_m - z - 1e-6)
    if h <= 0.5:
        return None
    w = min(item.size_m[0], CURTAIN_PANEL_M)
    size = (w, item.size_m[1], h)
    pts, yaws = [], []
    for wall in st.space.walls:
        for t0, t1, _, _, is_door in wall.openings:
            if is_door:
                continue
            for t in (t0 - CURTAIN_GAP_M - w / 2, t1 + CURTAIN_GAP_M + w / 2):
                if w / 2 <= t <= wall.length - w / 2:
                    pts.append(wall.a + wall.u * t + wall.n * (size[1] / 2))
                    yaws.append(wall.yaw)
    if not pts:
        return None
    n = len(pts)
    c = Cands(np.asarray(pts), np.asarray(yaws), np.full(n, z), np.linspace(1.0, 0.9, n))
    order = scoring.rank(st, c, size, "wall", st.options.member_noise, spacing=False)
    choices = scoring.verified_lazily(st, c, order, size, "wall", None, k=st.options.member_nav_retries)
    panel = item.model_copy(update={"size_m": size})
    return st.commit_if_walkable(panel, size, choices, "wall", item.rule, None, None)


def place_ornaments(st: RoomState) -> None:
    """Every copy of every ornament of the room, in plan order."""
    for item in st.spec.ornaments:
        prev = None
        for _ in range(item.count):
            prev = place_ornament(st, item, prev) or prev
