"""Relations between placed objects (issue 14): does each relation a room's plan states hold?

Measured on the placed geometry only (positions, sizes, yaws, the room outline, and the
``group`` / ``name`` fields of house.json that say which copy of which group an object
is); never on the layout solver's own scores or candidate lists. A relation whose
object or target was not placed is not counted (the items-placed rate says how many
were dropped).

What each rule of a plan states, and the relations it is checked for:

==================  ====================================================================
rule / parameter    relations
==================  ====================================================================
``place_front``     :data:`FRONT`, :data:`FACING` (``facing: toward``), :data:`ALIGNED`
``place_beside``    :data:`BESIDE`; two copies on ``both`` sides: :data:`SYMMETRIC`
``place_around``    :data:`AROUND`, :data:`FACING`
``place_next``      :data:`NEAR` (to another copy of the item)
``place_next_wall`` :data:`RUN` (group anchor against a wall, or copies of an anchor),
                    else :data:`NEAR` (near a free-standing target, against a wall)
``place_on_wall``   :data:`ALIGNED` (target against a wall: hung centred above it)
``far_m`` > 0       :data:`FAR`
==================  ====================================================================

The geometric definitions are the docstrings of the relation names below.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from pydantic import ValidationError
from shapely.geometry import Polygon
from shapely.ops import nearest_points

from anyhome.geometry import (
    footprint_corners,
    footprint_polygon,
    front_dir,
    joined_to_first,
    right_dir,
)
from anyhome.house import House, HouseObject
from anyhome.layout.rules import REGISTRY
from anyhome.layout.rules.place_front import MIN_TO_WALL_M
from anyhome.plan.spec import GroupSpec, ItemSpec

NEAR = "near"
"""Footprints at most :data:`NEAR_GAP_M` apart (``place_next``: to the nearest other copy);
for an object against a wall near a free-standing target: against a wall and at most
:data:`NEAR_SLACK_M` further from the target than the nearest wall allows."""
FAR = "far"
"""Footprints at least ``far_m`` apart (less :data:`TOL_M`)."""
FRONT = "in front"
"""In the target's front half-plane (footprint beyond the target's front edge), centre
within the target's width sideways, gap to its front near ``distance_m`` (within
:data:`FRONT_GAP_TOL_M` or :data:`FRONT_GAP_REL` of it); with ``to_wall``: at least
:data:`TO_WALL_MIN_M` away and back against a wall."""
BESIDE = "beside"
"""Left or right of the target (the side asked for), the gap between their sides at most
:data:`BESIDE_GAP_M`, backs within :data:`BACK_TOL_M` and facing the same way."""
SYMMETRIC = "symmetric pair"
"""Two copies beside one target (``side: both``): one each side, side gaps and backs
within :data:`SYMMETRIC_TOL_M` of each other."""
AROUND = "around"
"""At a side of the target (centre within the side's extent, not off a corner),
footprints at most :data:`AROUND_GAP_M` apart, facing the target."""
FACING = "facing"
"""Front within :data:`FACING_DEG` of the direction to the nearest point of the target's
footprint."""
ALIGNED = "aligned"
"""Centre on the target's axis: ``place_front`` copies' centroid within :data:`ALIGN_TOL_M`
of it sideways; a wall item over a target against a wall on that wall, within
:data:`ALIGN_TOL_M` of its centre along it."""
RUN = "run"
"""Against a wall and joined to the run's first object (the group's anchor or first
copy) through run pieces each at most :data:`RUN_GAP_M` from the next: a run that
continues rather than jumps."""

KINDS: tuple[str, ...] = (NEAR, FAR, FRONT, BESIDE, SYMMETRIC, AROUND, FACING, ALIGNED, RUN)
"""Every relation kind, in table order."""

TOL_M = 0.02
"""Measuring tolerance."""
NEAR_GAP_M = 0.5
"""Largest footprint gap of objects near each other."""
NEAR_SLACK_M = 0.6
"""An object against a wall near a free-standing target may be this much further from
it than the nearest wall is (less the object's depth)."""
FRONT_GAP_TOL_M = 0.3
"""Gap in front of a target may differ from ``distance_m`` by this much..."""
FRONT_GAP_REL = 0.5
"""...or by this fraction of ``distance_m``, whichever is larger."""
TO_WALL_MIN_M = MIN_TO_WALL_M
"""Least gap in front of the target of a ``to_wall`` item (the rule's minimum)."""
WALL_GAP_M = 0.05
"""A back edge whose middle is at most this far from the room outline is against a wall."""
BESIDE_GAP_M = 0.3
"""Largest gap between an object's side and the side of the one it stands beside."""
BACK_TOL_M = 0.15
"""Backs of side-by-side objects are aligned within this."""
SYMMETRIC_TOL_M = 0.1
"""The two halves of a symmetric pair match within this."""
AROUND_GAP_M = 0.35
"""Largest gap between a seat and the table it stands around."""
FACING_DEG = 35.0
"""Largest angle between an object's front and the direction to what it faces."""
ALIGN_TOL_M = 0.1
"""Largest sideways offset of a centre-aligned object."""
RUN_GAP_M = 0.3
"""Largest gap between neighbouring pieces of a run along the walls."""


@dataclass(frozen=True)
class Relation:
    """One stated relation, checked: its kind, object and target ids, whether it holds,
    and the measurement that decided it."""

    kind: str
    item: str
    target: str | None
    met: bool
    detail: str = ""


# ------------------------------------------------------------------ geometry


def _poly(o: HouseObject) -> Polygon:
    return footprint_polygon(o.position, o.size, o.yaw)


def _corners(o: HouseObject) -> np.ndarray:
    return footprint_corners(o.position, o.size, o.yaw)


def _xy(o: HouseObject) -> np.ndarray:
    return np.asarray(o.position[:2], dtype=float)


def gap(a: HouseObject, b: HouseObject) -> float:
    """Distance between the footprints of ``a`` and ``b`` (0 when they touch or overlap)."""
    return float(_poly(a).distance(_poly(b)))


def against_wall(o: HouseObject, outline: Polygon) -> bool:
    """The middle of ``o``'s back edge lies within :data:`WALL_GAP_M` of ``outline``."""
    back = _xy(o) - front_dir(o.yaw) * o.size[1] / 2
    return float(outline.exterior.distance(shapely.Point(back))) <= WALL_GAP_M


def facing_angle_deg(o: HouseObject, target: HouseObject) -> float:
    """Angle between ``o``'s front and the direction to the nearest point of ``target``'s footprint."""
    c = shapely.Point(_xy(o))
    tp = _poly(target)
    if tp.contains(c):
        return 0.0
    near = nearest_points(tp, c)[0]
    v = np.array([near.x, near.y]) - _xy(o)
    n = float(np.linalg.norm(v))
    if n < 1e-9:
        return 0.0
    cos = float(np.clip(front_dir(o.yaw) @ (v / n), -1.0, 1.0))
    return math.degrees(math.acos(cos))


def _local(o: HouseObject, t: HouseObject) -> tuple[np.ndarray, np.ndarray]:
    """``o``'s footprint corners in ``t``'s frame: (sideways, forward) coordinates."""
    rel = _corners(o) - _xy(t)[None]
    return rel @ right_dir(t.yaw), rel @ front_dir(t.yaw)


# ------------------------------------------------------------------ relations
def checkfront_dir(o: HouseObject, t: HouseObject, distance_m: float, to_wall: bool,
                outline: Polygon) -> Relation:
    """:data:`FRONT`."""
    xs, ys = _local(o, t)
    g = float(ys.min()) - t.size[1] / 2
    lat = float((_xy(o) - _xy(t)) @ right_dir(t.yaw))
    sideways_ok = abs(lat) <= t.size[0] / 2 + TOL_M
    if to_wall:
        ok = g >= TO_WALL_MIN_M - TOL_M and sideways_ok and against_wall(o, outline)
    else:
        ok = g >= -TOL_M and sideways_ok and abs(g - distance_m) <= max(FRONT_GAP_TOL_M, FRONT_GAP_REL * distance_m)
    return Relation(FRONT, o.id, t.id, ok, f"gap {g:.2f} m, sideways {lat:.2f} m")


def check_facing(o: HouseObject, t: HouseObject) -> Relation:
    """:data:`FACING`."""
    a = facing_angle_deg(o, t)
    return Relation(FACING, o.id, t.id, a <= FACING_DEG, f"{a:.0f} deg")


def _side_gap(o: HouseObject, t: HouseObject) -> tuple[float, float, float]:
    """(side: -1 left / +1 right, gap between the sides, back offset) of ``o`` beside ``t``."""
    xs, ys = _local(o, t)
    side = 1.0 if float(xs.mean()) >= 0 else -1.0
    g = float((side * xs).min()) - t.size[0] / 2
    back = float(ys.min()) + t.size[1] / 2
    return side, g, back


def check_beside(o: HouseObject, t: HouseObject, side: str) -> Relation:
    """:data:`BESIDE`."""
    s, g, back = _side_gap(o, t)
    same = abs(math.degrees(math.acos(float(np.clip(front_dir(o.yaw) @ front_dir(t.yaw), -1, 1))))) <= FACING_DEG
    side_ok = side == "both" or (side == "left") == (s < 0)
    ok = -TOL_M <= g <= BESIDE_GAP_M and abs(back) <= BACK_TOL_M and same and side_ok
    return Relation(BESIDE, o.id, t.id, ok, f"{'right' if s > 0 else 'left'}, gap {g:.2f} m, back {back:+.2f} m")


def check_symmetric(a: HouseObject, b: HouseObject, t: HouseObject) -> Relation:
    """:data:`SYMMETRIC`."""
    sa, ga, ba = _side_gap(a, t)
    sb, gb, bb = _side_gap(b, t)
    ok = sa != sb and abs(ga - gb) <= SYMMETRIC_TOL_M and abs(ba - bb) <= SYMMETRIC_TOL_M
    return Relation(SYMMETRIC, a.id, t.id, ok, f"sides {sa:+.0f}/{sb:+.0f}, gaps {ga:.2f}/{gb:.2f} m")


def check_around(o: HouseObject, t: HouseObject) -> Relation:
    """:data:`AROUND`."""
    rel = _xy(o) - _xy(t)
    u, v = float(rel @ right_dir(t.yaw)), float(rel @ front_dir(t.yaw))
    at_side = abs(u) <= t.size[0] / 2 + TOL_M or abs(v) <= t.size[1] / 2 + TOL_M
    g = gap(o, t)
    a = facing_angle_deg(o, t)
    ok = at_side and g <= AROUND_GAP_M and a <= FACING_DEG
    return Relation(AROUND, o.id, t.id, ok, f"gap {g:.2f} m, {'side' if at_side else 'corner'}, {a:.0f} deg")


def check_alignedfront_dir(objs: Sequence[HouseObject], t: HouseObject) -> Relation:
    """:data:`ALIGNED` for ``place_front`` copies (their centroid)."""
    c = np.mean([_xy(o) for o in objs], axis=0)
    lat = float((c - _xy(t)) @ right_dir(t.yaw))
    return Relation(ALIGNED, objs[0].id, t.id, abs(lat) <= ALIGN_TOL_M, f"sideways {lat:+.2f} m")


def check_aligned_wall(o: HouseObject, t: HouseObject) -> Relation:
    """:data:`ALIGNED` for a wall item over a target standing against a wall."""
    tb = _xy(t) - front_dir(t.yaw) * t.size[1] / 2
    ob = _xy(o) - front_dir(o.yaw) * o.size[1] / 2
    same_wall = abs(float((ob - tb) @ front_dir(t.yaw))) <= WALL_GAP_M and float(front_dir(o.yaw) @ front_dir(t.yaw)) > 0.99
    lat = float((ob - tb) @ right_dir(t.yaw))
    return Relation(ALIGNED, o.id, t.id, same_wall and abs(lat) <= ALIGN_TOL_M,
                    f"{'same' if same_wall else 'other'} wall, along {lat:+.2f} m")


def check_over_run(o: HouseObject, run: Sequence[HouseObject]) -> Relation:
    """:data:`ALIGNED` for one of several wall items over several targets (wall cabinets
    over a counter run): its footprint lies over the pieces of ``run`` (the targets and
    the other floor pieces of their group: sink, cooktop, round the corner too), to
    :data:`ALIGN_TOL_M`, rather than centred on any one of them."""
    under = shapely.union_all([_poly(t) for t in run]).buffer(ALIGN_TOL_M, join_style="mitre")
    out = _poly(o).difference(under).area
    return Relation(ALIGNED, o.id, run[0].id, out <= 1e-6, f"{out:.3f} m2 of it over no piece of the run")


def check_far(o: HouseObject, t: HouseObject, far_m: float) -> Relation:
    """:data:`FAR`."""
    g = gap(o, t)
    return Relation(FAR, o.id, t.id, g >= far_m - TOL_M, f"gap {g:.2f} m (at least {far_m:.2f})")


def check_near_copies(objs: Sequence[HouseObject]) -> list[Relation]:
    """:data:`NEAR` for each copy of an item to its nearest other copy."""
    out = []
    for i, o in enumerate(objs):
        others = [p for j, p in enumerate(objs) if j != i]
        if not others:
            continue
        g, p = min(((gap(o, p), p) for p in others), key=lambda x: x[0])
        out.append(Relation(NEAR, o.id, p.id, g <= NEAR_GAP_M, f"gap {g:.2f} m"))
    return out


def check_near_wall(o: HouseObject, t: HouseObject, outline: Polygon) -> Relation:
    """:data:`NEAR` for an object against a wall near a (free-standing) target."""
    reach = max(0.0, float(outline.exterior.distance(_poly(t))) - o.size[1])
    g = gap(o, t)
    wall = against_wall(o, outline)
    ok = wall and g <= max(NEAR_GAP_M, reach + NEAR_SLACK_M)
    return Relation(NEAR, o.id, t.id, ok, f"gap {g:.2f} m (nearest wall allows {reach:.2f}), "
                                          f"{'on' if wall else 'off'} a wall")


def check_run(pieces: Sequence[HouseObject], first: HouseObject, outline: Polygon) -> list[Relation]:
    """:data:`RUN` for every piece of ``pieces`` but ``first``."""
    order = [first, *(p for p in pieces if p.id != first.id)]
    joined = {order[k].id for k in joined_to_first([_poly(p) for p in order], RUN_GAP_M)}
    return [Relation(RUN, p.id, first.id, p.id in joined and against_wall(p, outline),
                     f"{'joined' if p.id in joined else 'apart'}, {'on' if against_wall(p, outline) else 'off'} a wall")
            for p in pieces if p.id != first.id]


# ------------------------------------------------------------------ a room
def _copies(g: GroupSpec, objects: Sequence[HouseObject]) -> dict[str, list[HouseObject]]:
    """Group copy label (``name-k``) -> its objects, in placement order."""
    out: dict[str, list[HouseObject]] = {}
    for o in objects:
        if o.group is not None and o.group.rsplit("-", 1)[0] == g.name:
            out.setdefault(o.group, []).append(o)
    return out


def _nearest(o: HouseObject, cands: Sequence[HouseObject]) -> HouseObject:
    return min(cands, key=lambda t: gap(o, t))


def _params(item: ItemSpec) -> Any:
    """``item``'s parameters as its rule reads them, the rule's defaults filled in."""
    return REGISTRY[item.rule].parse(item.params, lenient=True)


def _far_m(item: ItemSpec) -> float:
    return float(getattr(_params(item), "far_m", 0.0))


def item_relations(m: ItemSpec, objs: Sequence[HouseObject], targets: Sequence[HouseObject],
                   outline: Polygon, anchor_on_wall: bool, floor: Sequence[HouseObject] = ()) -> list[Relation]:
    """The relations member ``m`` states, checked on its placed copies ``objs`` against
    its target's placed copies ``targets`` (``floor``: the group copy's floor objects,
    the run that several wall items hang over)."""
    if not objs or not targets:
        return []
    out: list[Relation] = []
    p = _params(m)
    near = {o.id: _nearest(o, targets) for o in objs}
    if m.rule == "place_front":
        for o in objs:
            out.append(checkfront_dir(o, near[o.id], p.distance_m, p.to_wall, outline))
            if p.facing == "toward":
                out.append(check_facing(o, near[o.id]))
        by_target: dict[str, list[HouseObject]] = {}
        for o in objs:
            by_target.setdefault(near[o.id].id, []).append(o)
        tmap = {t.id: t for t in targets}
        out += [check_alignedfront_dir(os_, tmap[tid]) for tid, os_ in by_target.items()]
    elif m.rule == "place_beside":
        side = p.side
        out += [check_beside(o, near[o.id], side) for o in objs]
        if side == "both":
            for t in targets:
                mine = [o for o in objs if near[o.id].id == t.id]
                if len(mine) == 2:
                    out.append(check_symmetric(mine[0], mine[1], t))
    elif m.rule == "place_around":
        for o in objs:
            out.append(check_around(o, near[o.id]))
            out.append(check_facing(o, near[o.id]))
    elif m.rule == "place_next":
        out += check_near_copies(objs)
    elif m.rule == "place_next_wall" and not anchor_on_wall:
        out += [check_near_wall(o, near[o.id], outline) for o in objs]
    elif m.rule == "place_on_wall" and len(objs) > 1 and len(targets) > 1:  # wall cabinets over a counter run
        out += [check_over_run(o, [*targets, *(f for f in floor if f not in targets)]) for o in objs]
    elif m.rule == "place_on_wall":
        out += [check_aligned_wall(o, near[o.id]) for o in objs if against_wall(near[o.id], outline)]
    if _far_m(m) > 0:
        out += [check_far(o, near[o.id], _far_m(m)) for o in objs]
    return out


def group_relations(g: GroupSpec, objects: Sequence[HouseObject], outline: Polygon) -> list[Relation]:
    """The relations group ``g`` states, checked on its placed copies in ``objects``."""
    out: list[Relation] = []
    copies = _copies(g, objects)
    anchors = [o for objs in copies.values() for o in objs if o.anchor is None and o.name == g.anchor.name]
    if g.arrangement == "rows":  # the rows arrangement places the anchors, not their rule
        pass
    elif len(anchors) > 1 and (g.anchor.rule == "place_next_wall" or g.arrangement == "along_walls"):
        out += check_run(anchors, anchors[0], outline)
    elif len(anchors) > 1 and g.anchor.rule == "place_next":
        out += check_near_copies(anchors)
    if _far_m(g.anchor) > 0 and g.anchor.target:
        tg = [o for o in objects if o.name == g.anchor.target]
        out += [check_far(a, _nearest(a, tg), _far_m(g.anchor)) for a in anchors if tg]
    for objs in copies.values():
        anchor = next((o for o in objs if o.anchor is None and o.name == g.anchor.name), None)
        names = {m.name for m in g.members} | {g.anchor.name}
        on_wall = anchor is not None and against_wall(anchor, outline)
        for m in g.members:
            mine = [o for o in objs if o.name == m.name and o.anchor is not None]
            tname = m.target or g.anchor.name
            pool = objs if tname in names else objects
            targets = [o for o in pool if o.name == tname and o not in mine]
            floor = [o for o in objs if o.support == "floor"]
            out += item_relations(m, mine, targets, outline, on_wall, floor)
        run = [o for o in objs if o.rule == "place_next_wall" and o.anchor is not None]
        if on_wall and anchor is not None and run:
            out += check_run([anchor, *run], anchor, outline)
    return out


def room_relations(groups: Sequence[GroupSpec], objects: Sequence[HouseObject],
                   polygon: Sequence[Sequence[float]]) -> list[Relation]:
    """Every relation the room's ``groups`` state, checked on its placed ``objects``
    (the room's polygon ``polygon``)."""
    outline = Polygon(polygon)
    out: list[Relation] = []
    for g in groups:
        out += group_relations(g, objects, outline)
    return out


def met_by_kind(relations: Sequence[Relation]) -> dict[str, tuple[int, int]]:
    """Relation kind -> (met, checked), kinds in :data:`KINDS` order, unchecked kinds left out."""
    out: dict[str, tuple[int, int]] = {}
    for k in KINDS:
        rs = [r for r in relations if r.kind == k]
        if rs:
            out[k] = (sum(r.met for r in rs), len(rs))
    return out


def planned_rooms(plan: Any, host: dict[str, str]) -> dict[str, tuple[list[GroupSpec], list[ItemSpec]]]:
    """Room id -> (groups, ornaments) of a plan dict as house.json records it, each planned
    room under the id of the room holding it (``host``: planned id -> open-plan room id);
    anything the current models refuse (a hand-edited or damaged plan) is left out."""
    out: dict[str, tuple[list[GroupSpec], list[ItemSpec]]] = {}
    rooms = plan.get("rooms") if isinstance(plan, dict) else None
    for rs in rooms if isinstance(rooms, list) else []:
        rid = rs.get("id") if isinstance(rs, dict) else None
        if not isinstance(rid, str):
            continue
        groups, ornaments = out.setdefault(host.get(rid, rid), ([], []))
        groups += [g for g in (_valid(GroupSpec, d) for d in _list(rs.get("groups"))) if isinstance(g, GroupSpec)]
        ornaments += [o for o in (_valid(ItemSpec, d) for d in _list(rs.get("ornaments"))) if isinstance(o, ItemSpec)]
    return out


def _list(v: Any) -> list[Any]:
    return v if isinstance(v, list) else []


def _valid(model: type[GroupSpec] | type[ItemSpec], data: Any) -> GroupSpec | ItemSpec | None:
    try:
        return model.model_validate(data)
    except ValidationError:
        return None


def house_relations(house: House) -> list[Relation]:
    """Every relation the plan recorded in ``house`` (``house.plan``) states, checked room
    by room (an open-plan room with the groups of every planned room it holds); a group
    the plan records in a form the current rules refuse is left out."""
    host = {h: r.id for r in house.rooms for h in r.merged}
    planned = planned_rooms(house.plan, host)
    out: list[Relation] = []
    for r in house.rooms:
        if r.id in planned and planned[r.id][0]:
            objs = [o for o in house.objects if o.room == r.id]
            out += room_relations(planned[r.id][0], objs, r.polygon)
    return out
