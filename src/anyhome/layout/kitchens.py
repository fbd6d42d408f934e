"""Kitchens as designers lay them out: a kitchen run group (a counter anchor with a sink,
a cooktop or a fridge among its members) becomes one continuous counter run along the
walls (:mod:`anyhome.layout.kitchen_plan`: galley, L, U or one wall by the room's size),
wall cabinets hang above its counters, and an island stands clear of it by a work aisle.

The solver calls :func:`place_kitchen` for such a group (:func:`is_kitchen_run`) and
:func:`place_island` for a free-standing counter group in a room whose run is placed
(:func:`is_island`); what does not fit falls back to the group's own rules or is dropped
with its reason, never forced.
"""

from __future__ import annotations

import numpy as np
import shapely

from anyhome.house import HouseObject
from anyhome.layout import arrangements, groups, scoring
from anyhome.layout.kitchen_plan import RunShape, Slot, plan_run, run_shapes, shape_order
from anyhome.layout.rules import REGISTRY
from anyhome.layout.rules.base import front_dir, on_wall
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import GroupSpec, ItemSpec
from anyhome.space import rect_corners

ROLES = {"refrigerator": "fridge", "sink": "sink", "stove": "stove"}
"""Member category -> its role in the run."""
CABINET_ELEVATION_M = 1.45
"""Bottom of the wall cabinets above the floor."""
CABINET_ABOVE_COUNTER_M = 0.45
"""Least gap between a counter top and the wall cabinets over it (room to work)."""
MIN_CABINET_M = 0.3
"""Narrowest wall cabinet."""
MAX_CABINET_M = 0.9
"""Widest wall cabinet; longer stretches get several of equal width."""
LANDINGS_M = (0.4, 0.0)
"""Counter kept between appliances and beside the cooktop: a designer's landing first,
then none (a small room's run still continuous rather than scattered)."""
MAX_SHAPE_TRIES = 10
"""Run plans tried (best first) before the group falls back to its own rules."""
ISLAND_AISLE_M = 1.1
"""Work aisle between the run's front and the island."""
AISLE_MIN_M = 1.0
"""Least free floor kept around an island (and beyond its seats)."""
ISLAND_SHIFTS_M = (0.0, -0.3, 0.3, -0.6, 0.6, -1.0, 1.0)
"""Offsets along the run tried for the island's centre."""
PENINSULA_STEP_M = 0.1
"""Step along the walls of the peninsula poses tried."""
KITCHEN_ROOM_TYPE = "kitchen"
RUN_WITH_TABLE_M = 5.4
"""Run length kept in a kitchen room that holds a table or an island too (the rest of
its walls left for them)."""
"""A room of this type (not open-plan) gets its walls' full length of run."""


def is_kitchen_run(g: GroupSpec) -> bool:
    """A counter anchor with at least two of sink, cooktop and fridge among its members."""
    cats = {m.category for m in g.members if m.category in ROLES}
    return g.anchor.category == "counter" and len(cats) >= 2


def _run_pieces(st: RoomState) -> list[HouseObject]:
    return [o for o in st.space.objects if o.support == "floor" and o.category in (*ROLES, "counter")
            and o.rule in ("place_corner", "place_wall", "place_next_wall")]


def waits_for_run(g: GroupSpec) -> bool:
    """A free-standing counter (an island): laid out after the kitchen runs of its
    priority, so that it can stand across an aisle from them (:func:`place_island`)."""
    return g.anchor.category == "counter" and g.anchor.rule == "place_center"


def is_island(st: RoomState, g: GroupSpec) -> bool:
    """A counter placed free-standing (``place_center``) in a room whose run stands."""
    return waits_for_run(g) and bool(_run_pieces(st))


def place_kitchen(st: RoomState, g: GroupSpec) -> None:
    """The group's first copy as a kitchen run with wall cabinets; further copies, and
    the whole group when no run plan fits, by the group's own rules."""
    roles: dict[str, ItemSpec] = {}
    rest: list[ItemSpec] = []
    cabinets: list[ItemSpec] = []
    for m in g.members:
        role = ROLES.get(m.category)
        floor = REGISTRY[m.rule].kind == "floor" and m.target in (None, g.anchor.name)
        if role and floor and role not in roles:
            roles[role] = m
        elif m.category == "counter" and floor:
            continue  # its length joins the run's counters
        elif m.category == "cabinet" and m.rule == "place_on_wall":
            cabinets.append(m)
        else:
            rest.append(m)
    label = f"{g.name}-0"
    slots = _place_run(st, g, roles, label)
    if slots is None:
        arrangements.place_free(st, g)
        return
    anchor, pieces = slots
    for role, m in roles.items():  # copies beyond the first of each appliance, and one left out of the run
        n = m.count - sum(1 for p in pieces if p.name == m.name)
        if n > 0:  # beside either end of the run (or any piece of it), not only its last piece
            _place_rest(st, g, [m.model_copy(update={"count": n})], label, anchor, pieces[-1], run=list(pieces))
    for m in cabinets:
        if not _hang_cabinets(st, m, pieces, label, anchor.id):
            st.drop(m.name, "no free wall above the counters", m.count)
    _place_rest(st, g, rest, label, anchor, pieces[-1])
    if g.repeat > 1:
        arrangements.place_free(st, g, 1)


def _place_rest(st: RoomState, g: GroupSpec, items: list[ItemSpec], label: str, anchor: HouseObject,
                last: HouseObject, run: list[HouseObject] | None = None) -> None:
    for m in items:
        refs = st.match(m.target) if m.target not in (None, g.anchor.name) else [anchor]
        _, drops = groups.place_item_copies(st, m, refs or [anchor], label, anchor.id, last, run)
        st.dropped.extend(drops)


def _cap_m(st: RoomState, g: GroupSpec, roles: dict[str, ItemSpec], more: bool) -> float | None:
    """Run length of an open-plan kitchen or a kitchenette (its pieces and a landing), or
    of a kitchen room that holds a table or an island too (``more``); None for a kitchen
    room of its own, whose run takes its walls."""
    counters = [g.anchor.size_m[0], *(m.size_m[0] for m in g.members if m.category == "counter")]
    natural = sum(counters) + sum(m.size_m[0] for m in roles.values()) + 0.4
    if st.room.type == KITCHEN_ROOM_TYPE and not st.room.merged:
        return max(natural, RUN_WITH_TABLE_M) if more else None
    return natural


def _ranked_shapes(st: RoomState, g: GroupSpec, roles: dict[str, ItemSpec]) -> list[RunShape]:
    items = [g.anchor, *roles.values()]
    depth, height = g.anchor.size_m[1], max(m.size_m[2] for m in items)
    more = any(x is not g and x.anchor.rule == "place_center" for x in st.spec.groups)
    cap = _cap_m(st, g, roles, more)
    shapes = run_shapes(st.space, depth, max(m.size_m[1] for m in items), height, cap)
    ext = st.space.bmax - st.space.bmin
    order = shape_order(float(ext.min()), cap is not None, more)

    def score(s: RunShape) -> tuple[int, float]:
        windows = sum(1 for leg in s.legs for a, b, _, _, door in leg.wall.openings
                      if not door and leg.lo <= (a + b) / 2 <= leg.hi)
        zone = 0.0
        if st.zone is not None:
            mids = [leg.wall.a + leg.wall.u * (leg.t0 + leg.t1) / 2 + leg.wall.n * depth for leg in s.legs]
            zone = float(np.mean([shapely.contains_xy(st.zone, p[0], p[1]) for p in mids]))
        return (order.index(s.shape), -(3.0 * zone + 0.5 * min(windows, 1) + 0.1 * s.length_m))

    return sorted((s for s in shapes if s.shape in order), key=score)[:MAX_SHAPE_TRIES]


def _place_run(st: RoomState, g: GroupSpec, roles: dict[str, ItemSpec],
               label: str) -> tuple[HouseObject, list[HouseObject]] | None:
    """The first ranked run plan whose every piece fits and keeps the walkways open, with
    full landings, else with appliances side by side (:data:`LANDINGS_M`), else without
    the fridge (placed after by its own rule):
    (its anchor counter, its pieces in run order); None when none does."""
    widths = {r: m.size_m[0] for r, m in roles.items()}
    shapes = _ranked_shapes(st, g, roles)
    passes = [(landing, widths) for landing in LANDINGS_M]
    if "fridge" in widths and len(widths) > 1:  # the fridge by its own rule, the rest a run
        passes.append((LANDINGS_M[-1], {r: w for r, w in widths.items() if r != "fridge"}))
    for landing, widths in passes:
        for shape in shapes:
            slots = plan_run(st.space, shape, widths, landing)
            if slots is None:
                continue
            snap = st.snapshot()
            got = _commit_run(st, g, roles, shape, slots, label)
            if got is not None and st.nav.ok():
                return got
            st.restore(snap)
    return None


def _commit_run(st: RoomState, g: GroupSpec, roles: dict[str, ItemSpec], shape: RunShape, slots: list[Slot],
                label: str) -> tuple[HouseObject, list[HouseObject]] | None:
    counters = [s for s in slots if s.role == "counter"]
    if not counters:
        return None
    first = max(counters, key=lambda s: s.t1 - s.t0)
    ordered = [first, *sorted((s for s in slots if s is not first), key=lambda s: (s.leg, s.t0))]
    anchor: HouseObject | None = None
    pieces: list[HouseObject] = []
    for s in ordered:
        item = g.anchor if s.role == "counter" else roles[s.role]
        leg = shape.legs[s.leg]
        size = (s.t1 - s.t0, item.size_m[1], item.size_m[2])
        xy = on_wall(leg.wall, np.array([(s.t0 + s.t1) / 2]), size[1])[0]
        ch = Choice(xy, leg.wall.yaw, 0.0)
        corners = rect_corners(xy[None], size[:2], [ch.yaw])
        if not st.space.valid(corners, 0.0, size[2], floor=True)[0] or not scoring.exact_ok(st, ch, size, "floor", None):
            return None
        rule = ("place_corner" if shape.shape in ("L", "U") else "place_wall") if anchor is None else "place_next_wall"
        obj = st.commit(item, size, ch, "floor", rule, label, None if anchor is None else anchor.id)
        anchor = anchor or obj
        pieces.append(obj)
    assert anchor is not None
    return anchor, pieces


def _hang_cabinets(st: RoomState, m: ItemSpec, pieces: list[HouseObject], label: str, anchor_id: str) -> int:
    """Wall cabinets above the run's counters and sink, clear of windows and doors and
    of the cooktop (its hood's place) and fridge; the number hung."""
    w_d, h = m.size_m[1], m.size_m[2]
    z = min(CABINET_ELEVATION_M, st.space.height - st.options.ceiling_gap_m - h)
    tops = [p.position[2] + p.size[2] for p in pieces if p.category in ("counter", "sink")]
    if not tops or z < max(tops) + CABINET_ABOVE_COUNTER_M:
        return 0
    hung = 0
    run_d = max(p.size[1] for p in pieces if p.category == "counter")
    for wall in st.space.walls:
        spans = []
        for p in pieces:
            if p.category not in ("counter", "sink"):
                continue
            back = np.asarray(p.position[:2]) - front_dir(p.yaw) * p.size[1] / 2
            rel = back - wall.a
            if abs(float(rel @ wall.n)) > 0.02 or abs(float(front_dir(p.yaw) @ wall.n) - 1) > 1e-3:
                continue
            t = float(rel @ wall.u)
            spans.append((t - p.size[0] / 2, t + p.size[0] / 2))
        for a, b in _merge(spans):
            a = w_d if abs(a - run_d) < 0.03 else a  # meet the other leg's cabinets in the corner
            b = wall.length - w_d if abs(wall.length - b - run_d) < 0.03 else b
            for c0, c1 in _clear_parts(st, wall, a, b, z, z + h):
                n = int(np.ceil((c1 - c0) / MAX_CABINET_M - 1e-9))
                step = (c1 - c0) / n
                for j in range(n):
                    mid = np.array([c0 + (j + 0.5) * step])
                    size = (step, w_d, h)
                    ch = Choice(on_wall(wall, mid, w_d)[0], wall.yaw, z)
                    corners = rect_corners(ch.xy[None], size[:2], [ch.yaw])
                    if st.space.valid(corners, z, z + h, floor=False)[0] and scoring.exact_ok(st, ch, size, "wall", None):
                        st.commit(m, size, ch, "wall", "place_on_wall", label, anchor_id)
                        hung += 1
    return hung


def _merge(spans: list[tuple[float, float]]) -> list[tuple[float, float]]:
    out: list[list[float]] = []
    for a, b in sorted(spans):
        if out and a <= out[-1][1] + 0.02:
            out[-1][1] = max(out[-1][1], b)
        else:
            out.append([a, b])
    return [(a, b) for a, b in out]


def _clear_parts(st: RoomState, wall, a: float, b: float, z0: float, z1: float) -> list[tuple[float, float]]:
    """Parts of ``[a, b]`` on ``wall`` at least MIN_CABINET_M long that cover no opening."""
    ts = np.arange(a, b, 0.05)
    ok = st.space.wall_clear(wall, ts, np.minimum(ts + 0.05, b), z0, z1)
    parts, start = [], None
    for t, good in zip(ts, ok):
        if good and start is None:
            start = t
        if not good and start is not None:
            parts.append((start, t))
            start = None
    if start is not None:
        parts.append((start, b))
    return [(p, q) for p, q in parts if q - p >= MIN_CABINET_M]


def place_island(st: RoomState, g: GroupSpec) -> None:
    """The island parallel to the run's longest leg, a work aisle in front of it, with
    :data:`AISLE_MIN_M` of floor free round it (beyond its seats); else a peninsula, one
    end against a wall near the run, the same aisles along its sides; when neither has
    room, dropped, or placed by its own rule when the text asked for it."""
    label = f"{g.name}-0"
    choices = _island_choices(st, g) or _peninsula_choices(st, g)
    if not choices:
        if g.key:  # asked for by the text: kept where its own rule finds room
            arrangements.place_free(st, g)
        else:
            groups.drop_group(st, g, "no room for an island or a peninsula with 1.0 m work aisles")
        return
    groups.try_choices(st, g, label, choices[:4], "floor", "place_center")
    if g.repeat > 1:
        arrangements.place_free(st, g, 1)


def _seat_depth_m(g: GroupSpec) -> float:
    return max((m.size_m[1] for m in g.members if m.rule == "place_front"), default=0.0)


def _fits(st: RoomState, ch: Choice, size: tuple[float, float, float], clear_xy: np.ndarray,
          clear_wd: tuple[float, float]) -> bool:
    """``size`` at ``ch`` fits, and the floor ``clear_wd`` round ``clear_xy`` (same yaw) is free."""
    clear = rect_corners(clear_xy[None], clear_wd, [ch.yaw])
    if not st.space.valid(clear, 0.0, size[2], floor=True, doors=False)[0]:
        return False
    corners = rect_corners(ch.xy[None], size[:2], [ch.yaw])
    return bool(st.space.valid(corners, 0.0, size[2], floor=True)[0]) and scoring.exact_ok(st, ch, size, "floor", None)


def _island_choices(st: RoomState, g: GroupSpec) -> list[Choice]:
    w, d, h = g.anchor.size_m
    back_m, front_m = ISLAND_AISLE_M - 0.05, _seat_depth_m(g) + AISLE_MIN_M
    out = []
    for wall, t_mid, depth in _legs_by_length(st):
        off = depth + ISLAND_AISLE_M + d / 2
        for s in ISLAND_SHIFTS_M:
            xy = wall.a + wall.u * (t_mid + s) + wall.n * off
            ch = Choice(xy, wall.yaw, 0.0)  # front (seats) away from the run
            cx = xy + wall.n * (front_m - back_m) / 2
            if _fits(st, ch, (w, d, h), cx, (w + 2 * AISLE_MIN_M, d + back_m + front_m)):
                out.append(ch)
    return out


def _peninsula_choices(st: RoomState, g: GroupSpec) -> list[Choice]:
    """Peninsula poses, one end on a wall and the long side perpendicular to it: its back
    against the end of the run (continuing it), or free-standing with an aisle behind it
    too; seats on the side away from the run; nearest the run first."""
    w, d, h = g.anchor.size_m
    seat = _seat_depth_m(g)
    pieces = _run_pieces(st)
    centres = np.array([p.position[:2] for p in pieces]).reshape(-1, 2)
    out: list[tuple[float, Choice]] = []
    for wall in st.space.walls:
        ends = []
        for p in pieces:  # just past each run piece standing on this wall
            rel = np.asarray(p.position[:2]) - wall.a
            if abs(float(front_dir(p.yaw) @ wall.n) - 1) < 1e-3 and abs(float(rel @ wall.n) - p.size[1] / 2) < 0.02:
                t = float(rel @ wall.u)
                ends += [t - p.size[0] / 2 - d / 2, t + p.size[0] / 2 + d / 2]
        grid = np.arange(d / 2, wall.length - d / 2 + 1e-6, PENINSULA_STEP_M)
        for t in [*ends, *grid]:
            xy = wall.a + wall.u * t + wall.n * (w / 2)
            for side in (1.0, -1.0):  # seats on the side away from the run
                front = wall.u * side
                if len(centres) and float(np.mean((centres - xy) @ front)) > 0:
                    continue
                ch = Choice(xy, float(np.arctan2(-front[0], front[1])), 0.0)
                back = AISLE_MIN_M if t not in ends else 0.0  # a peninsula on the run's end needs none
                # local frame: width along the wall's normal, depth along the wall
                cx = xy + front * (seat + AISLE_MIN_M - back) / 2 + wall.n * AISLE_MIN_M / 2
                if _fits(st, ch, (w, d, h), cx, (w + AISLE_MIN_M, d + seat + AISLE_MIN_M + back)):
                    near = float(np.min(np.linalg.norm(centres - xy, axis=1))) if len(centres) else 0.0
                    out.append((near - (1.0 if back == 0.0 else 0.0), ch))
    out.sort(key=lambda x: x[0])
    return [c for _, c in out]


def _legs_by_length(st: RoomState) -> list[tuple]:
    """(wall, middle of the run along it, run depth) of each wall the run follows, longest first."""
    out = []
    pieces = _run_pieces(st)
    for wall in st.space.walls:
        ts, depth = [], 0.0
        for p in pieces:
            back = np.asarray(p.position[:2]) - front_dir(p.yaw) * p.size[1] / 2
            rel = back - wall.a
            if abs(float(rel @ wall.n)) < 0.02 and abs(float(front_dir(p.yaw) @ wall.n) - 1) < 1e-3:
                t = float(rel @ wall.u)
                ts += [t - p.size[0] / 2, t + p.size[0] / 2]
                depth = max(depth, p.size[1])
        if ts:
            out.append((max(ts) - min(ts), wall, (max(ts) + min(ts)) / 2, depth))
    out.sort(key=lambda x: -x[0])
    return [x[1:] for x in out]
