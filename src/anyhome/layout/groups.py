"""Group placement: an anchor by its rule (or its arrangement's), then every member
relative to it; a few anchor poses are tried when members do not fit."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

import numpy as np

from anyhome.house import Dropped, HouseObject
from anyhome.layout import arrangements, placement, scoring
from anyhome.layout.rules import REGISTRY, Cands, front_dir, right_dir
from anyhome.layout.rules import place_around as around_rule
from anyhome.layout.rules import place_beside as beside_rule
from anyhome.layout.rules import place_front as front_rule
from anyhome.layout.rules import place_next_wall as next_wall_rule
from anyhome.layout.rules import place_on_wall as on_wall_rule
from anyhome.layout.rules.place_around import (
    around_allocation,
    around_positions,
    around_slots,
    seat_candidates,
)
from anyhome.layout.state import Choice, Outcome, RoomState, Snapshot
from anyhome.plan.spec import GroupSpec, ItemSpec
from anyhome.space import rect_corners


def place_group_copy(st: RoomState, g: GroupSpec, copy: int, prev: HouseObject | None) -> HouseObject | None:
    """Copy ``copy`` of group ``g`` (``prev``: the previous copy's anchor); its anchor or None."""
    label = f"{g.name}-{copy}"
    item = g.anchor
    size = item.size_m
    if REGISTRY[item.rule].placement == "top" and g.arrangement not in ("along_walls", "center"):
        obj = placement.place_on_some_top(st, item, None, label, None)
        if obj is None:
            drop_group(st, g, "no surface to stand on")
            return None
        st.dropped.extend(place_members(st, g, label, obj) or [])
        return obj
    c, kind, rule, ref = arrangements.anchor_candidates(st, g, prev)
    o = st.options
    tries = o.anchor_tries_required if g.required else o.anchor_tries

    def bonus(cands: Cands) -> Cands:  # room for the group and its run, asked of valid poses only
        return scoring.anchor_bonus(st, g, cands, rule, prev is None)

    run_on = prev is not None and REGISTRY[rule].continues  # the copy continues a run: no jump
    hangs = bool(anchored(g, "place_on_wall"))
    order = scoring.rank(st, c, size, kind, o.member_noise if run_on else o.noise, spacing=not run_on,
                         avoid_windows=hangs, bonus=bonus if kind == "floor" else None,
                         bonus_max=scoring.bonus_max(st, g, rule, prev is None))
    poses = scoring.Verifier(st, c, order, size, kind, None, min_sep_m=o.anchor_min_sep_m)
    memo: dict[int, int] = {}

    def bound(ch: Choice) -> int:  # with the room as it was: asked before a choice is tried
        got = memo.get(id(ch))
        if got is None:
            got = memo[id(ch)] = least_compromises(st, g, ch)
        return got

    guess = _bounded(g)
    choices = poses.upto(tries)  # checked as tried: the first pose most often keeps the group
    if guess:
        choices = promising_first(choices, bound)

    def more() -> list[Choice]:
        return poses.list(tries + o.anchor_reach_retries)

    anchor = try_choices(st, g, label, choices, kind, rule, more, nudge=kind == "floor", bound=bound if guess else None)
    if anchor is not None and ref is not None and rule == "place_front" and item.params.get("to_wall"):
        st.space.keep_clear.append(sightline(ref, anchor))  # a TV of its own, across from the sofa
    return anchor


def promising_first(choices: Iterator[Choice], bound: Callable[[Choice], int]) -> Iterator[Choice]:
    """``choices`` with the first where every member may stand where its rule asks
    (``bound``, :func:`least_compromises`, 0) moved ahead of those before it, the rest in
    their order; when none is bound to 0 (none can keep the whole group as its rules ask:
    every one is tried), all of them by their bound, the least first (in their order among
    equals). Each is taken from ``choices`` with the room as it was (nothing is committed
    while looking)."""
    held: list[Choice] = []
    for ch in choices:
        if not bound(ch):
            yield ch
            break
        held.append(ch)
    else:
        held.sort(key=bound)
    yield from held
    yield from choices


def _bounded(g: GroupSpec) -> bool:
    """Whether :func:`least_compromises` looks at any member of ``g``."""
    front = anchored(g, "place_front")
    return bool(anchored(g, "place_beside")) or any(m.params.get("to_wall") for m in g.members if m.name in front)


BESIDE_SPOT_GAPS_M = np.arange(-0.01, beside_rule.BESIDE_GAPS_M[-1] + 0.015, 0.01)
"""Side gaps at which a spot beside an anchor is looked for by :func:`least_compromises`:
every gap at which :func:`~.rules.place_beside.stands_beside` holds, 1 cm apart."""


def least_compromises(st: RoomState, g: GroupSpec, ch: Choice) -> int:
    """A lower bound, with the room as it is, on the compromises (:func:`compromises`) of a
    copy of ``g`` with its anchor at ``ch`` once its members are placed (a member dropped
    instead counts as a drop, which weighs more): for each member beside the anchor, its
    copies beyond the sides it may take where a spot beside the anchor is free (one copy
    stands beside each side at most); for each ``to_wall`` member (a TV stand),
    :data:`OFF_WALL_AHEAD_COST` when none of its rule's poses facing the anchor straight is
    free, else 1 when none of those centred on the anchor is. Poses taken now stay taken
    as the copy is placed; the bound holds for the poses the rules offer (a beside spot is
    looked for every 1 cm of gap)."""
    a = g.anchor
    yaw = ch.yaw
    f, r = front_dir(yaw), right_dir(yaw)
    space = st.space
    bent = 0
    for m in g.members:
        if m.target not in (None, a.name):
            continue
        w, d, h = m.size_m
        if m.rule == "place_beside":
            side = beside_rule.Params.model_validate(m.params).side
            sides = {"left": (-1.0,), "right": (1.0,)}.get(side, (-1.0, 1.0))
            if m.count <= 0:
                continue
            lat = (a.size_m[0] + w) / 2 + BESIDE_SPOT_GAPS_M
            offs = np.concatenate([sgn * lat for sgn in sides])
            xy = ch.xy[None] + offs[:, None] * r[None] + f[None] * ((d - a.size_m[1]) / 2)
            ok = space.valid(rect_corners(xy, (w, d), np.full(len(xy), yaw)), ch.z, ch.z + h, floor=True)
            free = sum(bool(part.any()) for part in np.split(ok, len(sides)))
            bent += max(0, m.count - free)
        elif m.rule == "place_front" and m.params.get("to_wall") and m.count == 1:
            p = front_rule.Params.model_validate(m.params)
            c = front_rule.front_to_wall_at(space, ch.xy, yaw, a.size_m[1], m.size_m, p.distance_m)
            straight = (-np.sin(c.yaw) * f[0] + np.cos(c.yaw) * f[1]) <= -0.99
            centred = straight & (np.abs((c.xy - ch.xy[None]) @ r) <= front_rule.CENTRED_TOL_M)
            for cost, mask in ((1, centred), (OFF_WALL_AHEAD_COST - 1, straight & ~centred)):  # the centred first
                if mask.any() and space.valid(rect_corners(c.xy[mask], (w, d), c.yaw[mask]), 0.0, h, floor=True).any():
                    break
                bent += cost
    return bent


def try_choices(st: RoomState, g: GroupSpec, label: str, choices: Iterable[Choice], kind: str,
                rule: str, more: Callable[[], list[Choice]] | None = None, nudge: bool = False,
                bound: Callable[[Choice], int] | None = None) -> HouseObject | None:
    """The anchor at the first of ``choices`` where every member fits and every object stays
    reachable, else where the fewest are dropped, then left out of reach, then the fewest
    members are placed by a fallback (:func:`compromises`); when the best so far leaves
    some out of reach, among ``more()`` too (a longer list starting with ``choices``);
    when it places some by a fallback and ``nudge`` is set, among the best pose shifted
    sideways too (:func:`nudged`: a bed moved off a door so that both nightstands fit);
    None (all dropped) when no choice keeps the walkways open. ``choices`` may be checked
    lazily (:class:`~.scoring.Verifier`): each is taken with the room as it was. ``bound``:
    a lower bound on a choice's compromises (:func:`least_compromises`), asked with the room
    as it was; a choice it shows cannot beat the best (no drops, all reached) is not tried."""
    item = g.anchor
    todo = iter(choices)
    first = next(todo, None)
    if first is None:
        drop_group(st, g, scoring.no_fit_reason(st, item.size_m))
        return None
    support = "wall" if kind == "wall" else "floor"
    snap = st.snapshot()
    best: tuple[int, int, int, int] | None = None  # (drops, objects out of reach, compromises, choice index)
    kept: tuple[Outcome, HouseObject, list[Dropped]] | None = None  # the room with the best, come back to at the end
    pool = [first]
    taken = 1  # choices taken from ``choices`` and ``more()`` (the rest of the pool: nudged poses)
    nudged_at: set[int] = set()  # poses of the pool whose nudges were added
    k = 0
    while k < len(pool):  # grows while being walked
        ch = pool[k]
        skip = best is not None and bound is not None and not best[0] and not best[1] and bound(ch) >= best[2]
        got = None if skip else st.commit_checked(item, item.size_m, ch, support, rule, label, None, check=kind != "top")
        if got is not None:  # else it closed a walkway (and was taken back)
            anchor = got[0]
            worse = None if best is None else _no_better(st, g, label, anchor, snap, best[:3])
            drops = place_members(st, g, label, anchor, worse)
            if drops is not None:
                bent = compromises(st, g, label, anchor)
                unreached = st.unreached_since(snap)
                if not drops and not bent and not unreached:
                    return anchor
                if best is None or (len(drops), unreached, bent) < best[:3]:
                    best = (len(drops), unreached, bent, k)
                    kept = (st.outcome(), anchor, drops)
            st.restore(snap)
        if best is not None and best[2] and best[3] == k and k not in nudged_at and nudge:  # first its nudges
            nudged_at.add(k)
            pool[k + 1:k + 1] = nudged(st, g, ch, kind)
        if k == len(pool) - 1:  # the next choice, checked with the room as it was
            pool += [ch for ch in [next(todo, None)] if ch is not None]
            taken += len(pool) - k - 1
        if best is not None and k == len(pool) - 1 and more is not None and best[1]:
            extra = more()[taken:]
            pool += extra
            taken += len(extra)
            more = None
        if best is not None and k == len(pool) - 1 and nudge and best[2] and best[3] not in nudged_at:
            nudged_at.add(best[3])
            pool += nudged(st, g, pool[best[3]], kind)
        k += 1
    if best is None:
        drop_group(st, g, "would block a walkway or a door")
        return None
    assert kept is not None
    outcome, anchor, drops = kept
    st.resume(outcome)  # the anchor and its members where they stood when it was judged best
    st.dropped.extend(drops)
    return anchor


def _no_better(st: RoomState, g: GroupSpec, label: str, anchor: HouseObject, snap: Snapshot,
               best: tuple[int, int, int]) -> Callable[[list[Dropped]], bool]:
    """Whether a copy of ``g`` whose members are placed in part (``drops`` so far) can no
    longer beat ``best`` (drops, objects out of reach, compromises) in :func:`try_choices`:
    drops and objects out of reach only grow as members are placed, and so do the
    compromises of the members placed (a run's jumps left out: a later piece may join it)."""

    def no_better(drops: list[Dropped]) -> bool:
        head = (len(drops), st.unreached_since(snap))
        if head != best[:2]:
            return head > best[:2]
        return compromises(st, g, label, anchor, runs=False) >= best[2]

    return no_better


NUDGES_M = tuple(s * 0.05 * k for k in range(1, 11) for s in (1, -1))
"""Sideways shifts (m, along the anchor's width) of its best pose tried when members
are placed by a fallback there: finer than the poses the anchor's rule offers apart."""
NUDGE_TRIES = 4
"""Most nudged poses tried."""


def nudged(st: RoomState, g: GroupSpec, ch: Choice, kind: str) -> list[Choice]:
    """``g``'s anchor pose ``ch``, where a spot beside the anchor is taken, shifted along
    its width by :data:`NUDGES_M`: the poses that leave the spots beside it free
    (:func:`~.scoring.beside_spots_free`) and pass the exact checks, the nearest first
    (up to :data:`NUDGE_TRIES`); none when ``ch`` leaves them free already."""
    size = g.anchor.size_m
    here = scoring.beside_spots_free(st, g, Cands(ch.xy[None], np.array([ch.yaw]), np.array([ch.z]), np.zeros(1)))
    if here is None or here[0]:  # nothing beside it, or its spots already free: shifting it frees none
        return []
    right = right_dir(ch.yaw)
    xy = ch.xy[None] + np.asarray(NUDGES_M)[:, None] * right[None]
    c = Cands(xy, np.full(len(xy), ch.yaw), np.full(len(xy), ch.z), -np.abs(np.asarray(NUDGES_M)))
    free = scoring.beside_spots_free(st, g, c)
    assert free is not None
    c = Cands(c.xy[free], c.yaw[free], c.z[free], c.pref[free])
    order = scoring.rank(st, c, size, kind, 0.0, spacing=False)
    return scoring.verified(st, c, order, size, kind, None, k=NUDGE_TRIES)


OFF_WALL_AHEAD_COST = 3
"""Compromises counted for a ``to_wall`` item (a TV stand) not on the wall straight ahead
of its anchor: the relations in front and centred broken, and the seat no longer faces it
(worse than a TV stand off centre on the wall ahead, or a coffee table off centre)."""


def compromises(st: RoomState, g: GroupSpec, label: str, anchor: HouseObject, runs: bool = True) -> int:
    """How far this copy's members stand from where their rules ask, counted as the
    relations they break: a ``to_wall`` item (a TV stand) not on the wall straight ahead
    of the anchor, facing it (:data:`OFF_WALL_AHEAD_COST`), else off the anchor's axis (1);
    copies in front of the anchor off its axis (1, :data:`~.rules.place_front.CENTRED_TOL_M`);
    members beside it where ``place_beside`` does not put them (:func:`beside_compromises`);
    a wall item not centred behind an anchor that stands against a wall (a window in the
    way); each piece of a run along the walls cut off from its start
    (:func:`~.rules.place_next_wall.jumps`; ``runs`` False: not counted)."""
    front = anchored(g, "place_front")
    walls = {m.name for m in g.members if m.name in front and m.params.get("to_wall")}
    beside = anchored(g, "place_beside")
    over = anchored(g, "place_on_wall")
    runs = runs and REGISTRY[anchor.rule].runs_along_wall and any(m.rule == "place_next_wall" for m in g.members)
    if not front and not beside and not over and not runs:
        return 0
    back = front_dir(anchor.yaw)
    mine = [o for o in st.space.objects if o.group == label]
    bent = 0
    for name in front:
        objs = [o for o in mine if o.name == name]
        if name in walls and any(float(front_dir(o.yaw) @ back) > -0.99 for o in objs):
            bent += OFF_WALL_AHEAD_COST
        elif objs and front_rule.off_centre_m(objs, anchor) > front_rule.CENTRED_TOL_M:
            bent += 1
    return (bent + beside_compromises(g, [o for o in mine if o.name in beside], anchor)
            + sum(1 for o in mine if o.name in over and not on_wall_rule.centred_behind(o, anchor))
            + (next_wall_rule.jumps([anchor, *(o for o in mine if o.rule == "place_next_wall")]) if runs else 0))


def beside_compromises(g: GroupSpec, objs: list[HouseObject], anchor: HouseObject) -> int:
    """Relations broken by the copies of ``g``'s members beside ``anchor`` (``objs``): one per
    copy placed by the last relaxation of ``place_beside`` or on the other side than the
    one asked for, and one for two copies on ``both`` sides that are not a symmetric pair
    (:func:`~.rules.place_beside.pair_matches`)."""
    bent = 0
    for m in g.members:
        if m.rule != "place_beside" or m.target not in (None, g.anchor.name):
            continue
        mine = [o for o in objs if o.name == m.name]
        side = beside_rule.Params.model_validate(m.params).side
        bent += sum(1 for o in mine if not beside_rule.stands_beside(o, anchor)
                    or (side != "both" and beside_rule.side_of(o, anchor) != side))
        if side == "both" and len(mine) == 2:
            bent += int(not beside_rule.pair_matches(mine[0], mine[1], anchor))
    return bent


def anchored(g: GroupSpec, rule: str) -> set[str]:
    """Names of the members of ``g`` placed by ``rule`` relative to its anchor."""
    return {m.name for m in g.members if m.rule == rule and m.target in (None, g.anchor.name)}


def drop_group(st: RoomState, g: GroupSpec, reason: str) -> None:
    st.drop(g.anchor.name, reason)
    for m in g.members:
        st.drop(m.name, f"its anchor {g.anchor.name!r} was not placed", m.count)


def place_members(st: RoomState, g: GroupSpec, label: str, anchor: HouseObject,
                  stop: Callable[[list[Dropped]], bool] | None = None) -> list[Dropped] | None:
    """Every member of ``g`` around ``anchor``, each after its target; what was dropped.
    ``stop``: asked after each member with what was dropped so far; when it says so, the
    rest are left unplaced and None is returned (the caller takes the copy back)."""
    placed: dict[str, list[HouseObject]] = {g.anchor.name: [anchor]}
    drops: list[Dropped] = []
    pending = list(g.members)
    run: list[HouseObject] = [anchor] if REGISTRY[anchor.rule].against_wall else []  # grown by the copies
    names = {m.name for m in g.members} | {g.anchor.name}
    if stop is not None and pending and stop(drops):
        return None
    while pending:
        ready = [m for m in pending if (m.target or g.anchor.name) in placed or (m.target or "") not in names]
        if not ready:
            for m in pending:
                drops += [st.dropped_entry(m.name, f"target {m.target!r} was not placed")] * m.count
            break
        m = ready[0]
        pending.remove(m)
        tname = m.target or g.anchor.name
        refs = placed.get(tname)
        if refs is None:  # target names something outside the group
            refs = st.match(tname) or [anchor]
        objs, d = place_item_copies(st, m, refs, label, anchor.id, run[-1] if run else None, run)
        placed.setdefault(m.name, []).extend(objs)
        drops += d
        if stop is not None and pending and stop(drops):
            return None
    return drops


def place_item_copies(st: RoomState, m: ItemSpec, refs: list[HouseObject], label: str | None,
                      anchor_id: str | None, prev_wall: HouseObject | None,
                      run: list[HouseObject] | None = None) -> tuple[list[HouseObject], list[Dropped]]:
    """The ``count`` copies of member ``m`` against ``refs`` (its target's copies, in turn);
    ``run``: the group's pieces against a wall so far (grown as copies join it)."""
    run = [] if run is None else run
    rule = REGISTRY[m.rule]
    objs: list[HouseObject] = []
    drops: list[Dropped] = []
    if not refs and rule.relative:
        return [], [st.dropped_entry(m.name, f"target {m.target!r} was not placed")] * m.count
    if rule.placement == "around":
        return place_around(st, m, refs, label, anchor_id)
    prev_same = None
    for i in range(m.count):
        ref = refs[i % len(refs)] if refs else None
        if rule.placement == "top":
            obj = placement.place_on_some_top(st, m, [ref] if ref is not None else None, label, anchor_id)
            reason = "does not fit on top of its target"
        else:
            params = rule.copy_params(dict(m.params), i, m.count)
            obj = placement.place_single(st, m, params, ref, prev_same, prev_wall, label, anchor_id, i, run)
            reason = scoring.no_fit_reason(st, m.size_m)
        if obj is None:
            drops.append(st.dropped_entry(m.name, reason))
            continue
        if ref is not None and m.rule == "place_front" and m.params.get("to_wall"):
            st.space.keep_clear.append(sightline(ref, obj))
        objs.append(obj)
        prev_same = obj
        if REGISTRY[obj.rule].runs_along_wall:
            prev_wall = obj
            run.append(obj)
    return objs, drops


def sightline(seat: HouseObject, screen: HouseObject) -> np.ndarray:
    """Corners of the strip between ``seat``'s front and ``screen``'s, as wide as the narrower."""
    a, b = np.asarray(seat.position[:2]), np.asarray(screen.position[:2])
    a = a + front_dir(seat.yaw) * seat.size[1] / 2
    b = b + front_dir(screen.yaw) * screen.size[1] / 2
    v = b - a
    length = float(np.linalg.norm(v))
    yaw = float(np.arctan2(-v[0], v[1])) if length > 1e-6 else seat.yaw
    width = min(seat.size[0], screen.size[0])
    return rect_corners(((a + b) / 2)[None], (width, max(length, 1e-3)), [yaw])[0]


def place_around(st: RoomState, m: ItemSpec, refs: list[HouseObject], label: str | None,
                 anchor_id: str | None) -> tuple[list[HouseObject], list[Dropped]]:
    """Copies of ``m`` spread over the sides of ``refs`` (long sides first), then anywhere free."""
    objs: list[HouseObject] = []
    size = m.size_m
    sides = around_rule.Params.model_validate(m.params).sides
    counts = [m.count // len(refs) + (1 if i < m.count % len(refs) else 0) for i in range(len(refs))]
    missing = 0
    for ref, n in zip(refs, counts):
        slots = around_slots(ref, size, sides)
        alloc = around_allocation(slots, n)
        left = n - sum(alloc)
        for s, k in zip(slots, alloc):
            if k == 0:
                continue
            for pos, yaw in around_positions(ref, size, s, k):
                obj = _around_one(st, m, [(pos, yaw)], label, anchor_id)
                if obj is None:
                    left += 1
                else:
                    objs.append(obj)
        # leftovers: any slot at capacity on any side
        if left:
            spare = []
            for s in slots:
                spare += around_positions(ref, size, s, s[-1])
            while left:
                obj = _around_one(st, m, spare, label, anchor_id)
                if obj is None:
                    break
                objs.append(obj)
                left -= 1
        missing += left
    drops = [st.dropped_entry(m.name, "no free seat around its target")] * missing
    return objs, drops


def _around_one(st: RoomState, m: ItemSpec, slots: list, label: str | None, anchor_id: str | None) -> HouseObject | None:
    size = m.size_m
    c = seat_candidates(slots)
    order = scoring.rank(st, c, size, "floor", st.options.member_noise, spacing=False)
    choices = scoring.verified_lazily(st, c, order, size, "floor", None, k=st.options.member_nav_retries)
    return st.commit_if_walkable(m, size, choices, "floor", "place_around", label, anchor_id)
