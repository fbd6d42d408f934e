"""One object copy by its rule: candidates through the rule registry, then the best pose
that passes the exact checks and keeps every walkway open; objects on tops."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout import scoring
from anyhome.layout.rules import REGISTRY, Cands, Kind, RuleContext
from anyhome.layout.rules.place_center import place_center
from anyhome.layout.rules.place_top import fit_on_top, place_top
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import ItemSpec
from anyhome.tags import is_front_of_room, is_supporter


def front_item(item: ItemSpec) -> bool:
    """Whether an item belongs at the front of a room set out in rows (a board, a lectern)."""
    return is_front_of_room(item.tags)


def candidates(st: RoomState, item: ItemSpec, rule_name: str, size: Sequence[float], ref: HouseObject | None,
               prev_same: HouseObject | None, prev_wall: HouseObject | None, params: dict[str, Any] | None = None,
               copy: int | None = None, run: Sequence[HouseObject] = ()) -> tuple[Cands, Kind]:
    """Candidates for one copy of ``item`` by the rule ``rule_name`` (not always the item's
    own: an arrangement may place it by another); returns (cands, kind).

    ``copy`` set: a member's or ornament's copy (the rule's ``copy_candidates``); ``run``:
    the pieces of the run along the walls it continues (:attr:`RuleContext.run`)."""
    rule = REGISTRY[rule_name]
    raw = item.params if params is None else params
    ctx = RuleContext(st.space, size, rule.parse(raw, lenient=True), st.options, ref, prev_same, prev_wall,
                      copy=copy or 0, count=item.count, rng=st.rng, run=run)
    kind: Kind
    if rule.needs_target and ref is None:  # relative rule with nothing to relate to
        c, kind = rule.untargeted(ctx) if rule.untargeted is not None else (place_center(st.space, size), "floor")
    elif copy is not None and rule.copy_candidates is not None:
        c, kind = rule.copy_candidates(ctx)
    else:
        c, kind = rule.candidates(ctx)
    w = st.rows_wall
    if w is not None and len(c) and rule.against_wall and front_item(item):
        rel = c.xy - w.a[None]
        t, d = rel @ w.u, rel @ w.n
        on = (np.abs(d - size[1] / 2) < 0.01) & (t >= -0.01) & (t <= w.length + 0.01)
        c = Cands(c.xy, c.yaw, c.z, c.pref + st.options.front_wall_bonus * on)
    return c, kind


def place_single(st: RoomState, m: ItemSpec, params: dict[str, Any], ref: HouseObject | None,
                 prev_same: HouseObject | None, prev_wall: HouseObject | None, label: str | None,
                 anchor_id: str | None, copy: int, run: Sequence[HouseObject] = ()) -> HouseObject | None:
    """Copy ``copy`` of a member or ornament by its own rule; None if nothing fits."""
    size = m.size_m
    c, kind = candidates(st, m, m.rule, size, ref, prev_same, prev_wall, params=params, copy=copy, run=run)
    order = scoring.rank(st, c, size, kind, st.options.member_noise, spacing=False)
    k = st.options.member_nav_retries
    poses = scoring.Verifier(st, c, order, size, kind, None)
    choices = poses.upto(k)
    support = "wall" if kind == "wall" else "floor"

    def more() -> list[Choice]:  # the first k again (not checked again), then more
        return poses.list(k + st.options.reach_retries)

    return st.commit_if_walkable(m, size, choices, support, m.rule, label, anchor_id, more=more)


def supporters(st: RoomState, target: str | None) -> list[HouseObject]:
    """What an object may stand on: objects matching ``target`` or, without one, any
    supporting surface at table height."""
    if target:
        return st.match(target)
    lo, hi = st.options.surface_top_range_m
    out = []
    for o in st.space.objects:
        top = o.position[2] + o.size[2]
        if not lo <= top <= hi or o.size[0] * o.size[1] < st.options.min_surface_m2:
            continue
        if is_supporter(o.tags):
            out.append(o)
    return out


def place_on_some_top(st: RoomState, item: ItemSpec, refs: list[HouseObject] | None, label: str | None,
                      anchor_id: str | None) -> HouseObject | None:
    """``item`` on the least loaded of ``refs`` (None: of its target's matches), shrunk to fit."""
    sups = refs if refs is not None else supporters(st, item.target)
    if not sups:
        return None
    load = {o.id: 0 for o in sups}
    for o in st.space.objects:
        if o.support in load:
            load[o.support] += 1
    noise = st.rng.random(len(sups))
    order = sorted(range(len(sups)), key=lambda i: (load[sups[i].id], noise[i]))
    for i in order:
        sup = sups[i]
        fit = fit_on_top(sup, item.size_m)
        if fit is None:
            continue
        size, turned = fit
        c = place_top(sup, size, turned, st.rng)
        ch = scoring.pick_one(st, c, size, "top", st.options.member_noise, supporter=sup)
        if ch is not None:
            return st.commit(item, size, ch, sup.id, "place_top", label, anchor_id)
    return None
