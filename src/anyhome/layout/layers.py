"""Floor layers: rugs laid under the group they belong to, after it.

A rug is not an obstacle: it is a walkable layer 1 cm thick (so an object standing on it
overlaps it by no more than the contract's 1 cm tolerance, SCENE_FORMAT rule 2) placed
once the room's furniture stands, under a group and sized to it:

- a seating group (a sofa or a bench and what stands in front of it): from under the
  seat's front legs to past the coffee table, a little wider than the seat;
- a bed: under its lower two thirds, wider than the bed on both sides and past its foot;
- a table with seats around it: under the table and its chairs pulled out.

The rectangle is shrunk (toward the group) until it lies inside the room, out of the
door zones (rule 4) and off every other layer; a rug with no group to lie under, or
whose group leaves no room, is placed as before by its own rule, as a layer. Which
groups take a rug: the item's ``target`` when the plan names one, else the room's
groups in order (:data:`UNDER_ORDER`), each at most one rug.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout import placement, scoring
from anyhome.layout.rules import front_dir, right_dir
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import GroupSpec, ItemSpec
from anyhome.space import rect_corners
from anyhome.tags import is_floor_layer

LAYER_HEIGHT_M = 0.01
"""Thickness of a laid rug: the contract's collision tolerance, so furniture may stand on it."""
LAYER_MAX_PLANNED_M = 0.03
"""A floor layer planned up to this thick is laid as a layer (a crash mat is not)."""
MIN_SIDE_M = 0.6
"""A rug narrower than this (either side) is not laid under a group."""
MIN_SHARE = 0.35
"""...nor one shrunk below this share of the area its group calls for."""
SHRINK_STEPS = (1.0, 0.9, 0.8, 0.7, 0.6, 0.5)
"""Scales of the rug's sides tried, each at several shifts toward the anchor."""
MAX_SIDE_M = 4.5
"""Longest side of a laid rug."""
TABLE_MARGIN_M = 0.15
"""A rug under a table reaches this far past its chairs."""
RUNNER_ASPECT = 2.0
"""A rug whose long side is at least this many times its short side is a runner."""
RUNNER_MIN_SIDE_M = 0.45
"""Narrowest a runner is laid (runners of 45-50 cm are sold) where the door zones of a narrow
hallway leave no wider strip."""
UNDER_ORDER = ("seating", "bed", "table")
"""Kinds of group a rug without a target goes under, first preferred."""


def is_layer_group(g: GroupSpec) -> bool:
    """A group that is just a rug (or mat) laid on the floor: placed after the furniture."""
    a = g.anchor
    return not g.members and is_floor_layer(a.tags) and a.size_m[2] <= LAYER_MAX_PLANNED_M


def _kind(anchor: HouseObject) -> str:
    tags = set(anchor.tags)
    if "bed" in tags:
        return "bed"
    if "seat" in tags and anchor.size[0] >= 1.2:
        return "seating"
    if tags & {"table"}:
        return "table"
    return "other"


def _group_objects(st: RoomState) -> dict[str, list[HouseObject]]:
    """Group label -> its floor objects (anchor first), for groups with a floor anchor."""
    out: dict[str, list[HouseObject]] = {}
    for o in st.space.objects:
        if o.group and o.support == "floor" and not is_floor_layer(o.tags) and o.category != "stairs":
            out.setdefault(o.group, []).append(o)
    return {k: sorted(v, key=lambda o: o.anchor is not None) for k, v in out.items() if v[0].anchor is None}


def _extent(anchor: HouseObject, objs: list[HouseObject]) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) of the rug in the anchor's frame (front +y)."""
    w, d = anchor.size[0], anchor.size[1]
    kind = _kind(anchor)
    if kind == "bed":
        return -w / 2 - 0.5, w / 2 + 0.5, -d / 2 + 0.35 * d, d / 2 + 0.5
    f, r = front_dir(anchor.yaw), right_dir(anchor.yaw)
    c = np.asarray(anchor.position[:2])
    x0, x1, y0, y1 = -w / 2, w / 2, -d / 2, d / 2
    near = [o for o in objs[1:] if o.size[2] < 1.0 and np.linalg.norm(np.asarray(o.position[:2]) - c) < 1.6 + d]
    for o in near:
        corners = rect_corners(np.asarray(o.position[:2])[None], o.size[:2], [o.yaw])[0] - c
        xs, ys = corners @ r, corners @ f
        x0, x1, y0, y1 = min(x0, xs.min()), max(x1, xs.max()), min(y0, ys.min()), max(y1, ys.max())
    if kind == "seating":  # from under the front legs to past the coffee table
        y0 = d / 2 - 0.25
        y1 = max(y1 + 0.3, d / 2 + 1.4)
        x0, x1 = min(x0, -w / 2 - 0.2), max(x1, w / 2 + 0.2)
        return x0, x1, y0, y1
    return x0 - TABLE_MARGIN_M, x1 + TABLE_MARGIN_M, y0 - TABLE_MARGIN_M, y1 + TABLE_MARGIN_M


def _poses(anchor: HouseObject, ext: tuple[float, float, float, float]) -> Iterator[tuple[np.ndarray, float, float, float]]:
    """(centre, yaw, width, depth) of the rug: the whole extent, then smaller, shifted toward the anchor."""
    x0, x1, y0, y1 = ext
    w0, d0 = min(x1 - x0, MAX_SIDE_M), min(y1 - y0, MAX_SIDE_M)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    f, r = front_dir(anchor.yaw), right_dir(anchor.yaw)
    c = np.asarray(anchor.position[:2])
    for s in SHRINK_STEPS:
        w, d = w0 * s, d0 * s
        for sx in (0.0, 0.5, -0.5, 1.0, -1.0):
            for sy in (0.0, -0.5, 0.5, -1.0, 1.0):
                px = cx + sx * (w0 - w) / 2
                py = cy + sy * (d0 - d) / 2
                yield c + r * px + f * py, anchor.yaw, w, d


def _lay(st: RoomState, item: ItemSpec, label: str, anchor: HouseObject, ext: tuple[float, float, float, float]) -> HouseObject | None:
    full = (ext[1] - ext[0]) * (ext[3] - ext[2])
    for xy, yaw, w, d in _poses(anchor, ext):
        if min(w, d) < MIN_SIDE_M or w * d < MIN_SHARE * min(full, MAX_SIDE_M ** 2):
            continue
        size = (w, d, LAYER_HEIGHT_M)
        corners = rect_corners(xy[None], (w, d), [yaw])
        if st.space.valid(corners, 0.0, LAYER_HEIGHT_M, floor=True, layer=True)[0]:
            return st.commit(item, size, Choice(xy, yaw, 0.0), "floor", item.rule, label, anchor.id, layer=True)
    return None


def place_layers(st: RoomState, groups: list[GroupSpec]) -> None:
    """Every rug group of the room under the furniture already placed (see module doc)."""
    taken: set[str] = set()
    for g in groups:
        item = g.anchor.model_copy(update={"size_m": (*g.anchor.size_m[:2], LAYER_HEIGHT_M)})
        for copy in range(g.repeat):
            label = f"{g.name}-{copy}"
            found = _groups_for(st, item, taken)
            obj = None
            for glabel, objs in found:
                obj = _lay(st, item, label, objs[0], _extent(objs[0], objs))
                if obj is not None:
                    taken.add(glabel)
                    break
            if obj is None and not _own_rule(st, item, label):
                st.drop(item.name, scoring.no_fit_reason(st, item.size_m))


def _own_rule(st: RoomState, item: ItemSpec, label: str) -> bool:
    """A rug with nothing to lie under, by its own rule, still a layer: at its planned
    size, else shorter (a runner between two doors); a runner (long side at least
    :data:`RUNNER_ASPECT` times the short one) may also narrow to :data:`RUNNER_MIN_SIDE_M`
    and lie along a wall, where a narrow hallway's door zones leave a strip."""
    for size, rule in _own_sizes(item):
        sized = item.model_copy(update={"size_m": size})
        c, kind = placement.candidates(st, sized, rule, size, None, None, None)
        order = scoring.rank(st, c, size, kind, st.options.noise, spacing=False, layer=True)
        choices = scoring.verified(st, c, order, size, kind, None, k=1)
        if choices:
            st.commit(sized, size, choices[0], "floor", rule, label, None, layer=True)
            return True
    return False


def _own_sizes(item: ItemSpec) -> Iterator[tuple[tuple[float, float, float], str]]:
    """(size, rule) tried by :func:`_own_rule`, first preferred."""
    w, d, h = item.size_m
    long_m, short_m = max(w, d), min(w, d)
    runner = long_m >= RUNNER_ASPECT * short_m
    for s in SHRINK_STEPS:
        size = (w * s, d, h) if w >= d else (w, d * s, h)
        if min(size[:2]) < MIN_SIDE_M and s < 1.0:
            break
        yield size, item.rule
    if not runner or short_m <= RUNNER_MIN_SIDE_M:
        return
    for s in SHRINK_STEPS:
        length = long_m * s
        if length < RUNNER_ASPECT * RUNNER_MIN_SIDE_M:
            break
        for width in (MIN_SIDE_M, RUNNER_MIN_SIDE_M):
            if width < short_m:
                yield (length, width, h), "place_wall"


def _groups_for(st: RoomState, item: ItemSpec, taken: set[str]) -> list[tuple[str, list[HouseObject]]]:
    """Groups the rug may lie under, best first."""
    groups = [(k, v) for k, v in _group_objects(st).items() if k not in taken]
    if item.target:
        named = {o.id for o in st.match(item.target)}
        hits = [(k, v) for k, v in groups if v[0].id in named]
        if hits:
            return hits
    rank = {k: i for i, k in enumerate(UNDER_ORDER)}
    found = [(k, v) for k, v in groups if _kind(v[0]) != "other"]
    return sorted(found, key=lambda kv: (rank[_kind(kv[1][0])], -kv[1][0].size[0] * kv[1][0].size[1]))
