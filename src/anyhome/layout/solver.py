"""Algorithm 1 of AnyHome: place each room's furniture groups by their rules.

Per room, groups are taken in priority order; for each of ``repeat`` copies the anchor
is placed by its rule, choosing among all viable candidate poses (scored by rule
preference, spacing and seeded noise), then each member by its rule relative to the
anchor or to its ``target``. A few anchor poses are tried when members do not fit.
After every floor object the room's walkways are re-checked on the 5 cm navigation
raster; what does not fit is dropped and reported, never forced. Ornaments follow.
"""

from __future__ import annotations

import logging
import math
import re
from dataclasses import dataclass, field

import numpy as np

from anyhome.geometry import (
    boxes_collide,
    footprint_polygon,
    inside,
)
from anyhome.house import Dropped, Floorplan, HouseObject, Room
from anyhome.layout import rules as R
from anyhome.plan.spec import WALL_RULES, GroupSpec, HouseSpec, ItemSpec, RoomSpec
from anyhome.space import NavGrid, Placed, RoomSpace, Wall, nav_blocks, rect_corners
from anyhome.tags import is_front_of_room, is_supporter

log = logging.getLogger(__name__)

ANCHOR_TRIES = 6
"""Anchor poses tried per group copy when its members do not all fit."""
ANCHOR_TRIES_REQUIRED = 10
"""Anchor poses tried for groups the text asked for explicitly."""
NOISE = 0.3
"""Weight of the seeded random term in an anchor's score."""
MEMBER_NOISE = 0.05
"""Weight of the seeded random term in a member's score."""
SPACING_WEIGHT = 0.3
"""Weight of the free distance (capped at ``SPACING_CAP_M``) around an anchor."""
SPACING_CAP_M = 0.8
WINDOW_PENALTY = 0.6
"""Score taken from tall floor objects standing in front of a window."""
TALL_M = 1.0
"""Floor objects taller than this avoid windows."""
GROUP_ROOM_BONUS = 0.8
"""Score added to anchor poses that leave room for the whole group around them."""
MEMBER_NAV_RETRIES = 4
"""Next-best poses tried when a member would block a walkway."""
ROW_AISLE_U_M = 0.5
"""Aisle between the columns of a ``rows`` arrangement."""
ROW_AISLE_V_M = 0.5
"""Aisle between the rows of a ``rows`` arrangement."""
ROW_FRONT_CLEARANCE_M = 1.0
"""Free band kept in front of the wall the rows face."""
ROW_SIDE_CLEARANCE_M = 0.3
"""Band kept along the other walls of a ``rows`` arrangement."""
FRONT_WALL_BONUS = 2.0
"""Score added to front-of-room items' poses (tag ``front_of_room``) on the wall the rows face."""
SURFACE_TOP_RANGE_M = (0.4, 1.2)
"""Top heights an ornament without a named target may stand on."""


@dataclass
class LayoutResult:
    """The layout stage's output: placed objects and what could not be placed."""

    objects: list[HouseObject] = field(default_factory=list)
    dropped: list[Dropped] = field(default_factory=list)


def layout_house(spec: HouseSpec, floorplan: Floorplan, rng: np.random.Generator) -> LayoutResult:
    """Place every room's furniture groups and ornaments (Algorithm 1 of AnyHome).

    Parameters
    ----------
    spec : the plan (rooms with groups and ornaments)
    floorplan : rooms, doors and windows the plan was laid out as
    rng : the only source of randomness; same inputs and seed give identical objects

    Returns
    -------
    LayoutResult
        ``objects`` valid by construction (SCENE_FORMAT.md rules 1-4 and 6) and
        ``dropped``, one entry per object copy that found no valid spot.
    """
    result = LayoutResult()
    for rs in spec.rooms:
        try:
            room = floorplan.room(rs.id)
        except KeyError:
            for item in _items(rs):
                result.dropped.append(Dropped(room=rs.id, name=item.name, reason="room is missing from the floorplan"))
            continue
        rl = RoomLayout(floorplan, room, rs, rng)
        rl.furnish()
        result.objects.extend(rl.space.objects)
        result.dropped.extend(rl.dropped)
    return result


def _items(rs: RoomSpec) -> list[ItemSpec]:
    out = []
    for g in rs.groups:
        for _ in range(g.repeat):
            out.append(g.anchor)
            out.extend(g.members)
    return out + list(rs.ornaments)


SLUG_MAX_CHARS = 40
"""Longest name part of an object id (ids are at most 128 characters, see anyhome.sanitize)."""


def slugify(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower())[:SLUG_MAX_CHARS].strip("_") or "object"


@dataclass
class _Snapshot:
    n_placed: int
    counters: dict[str, int]
    n_dropped: int


@dataclass
class _Choice:
    """A chosen pose for one object."""

    xy: np.ndarray
    yaw: float
    z: float


class RoomLayout:
    """Furnishes one room; ``space.objects`` and ``dropped`` hold the outcome."""

    def __init__(self, floorplan: Floorplan, room: Room, spec: RoomSpec, rng: np.random.Generator) -> None:
        self.room = room
        self.spec = spec
        self.rng = rng
        self.space = RoomSpace(floorplan, room)
        self.nav = NavGrid(floorplan, self.space)
        self.dropped: list[Dropped] = []
        self.counters: dict[str, int] = {}
        self.rows_wall: Wall | None = None

    # ------------------------------------------------------------ bookkeeping
    def _snapshot(self) -> _Snapshot:
        return _Snapshot(len(self.space.placed), dict(self.counters), len(self.dropped))

    def _restore(self, snap: _Snapshot) -> None:
        del self.space.placed[snap.n_placed:]
        del self.dropped[snap.n_dropped:]
        self.counters = dict(snap.counters)
        self.nav.set_blocked(self.space.placed)

    def _drop(self, name: str, reason: str) -> None:
        self.dropped.append(Dropped(room=self.room.id, name=name, reason=reason))

    def _new_id(self, name: str) -> str:
        slug = slugify(name)
        k = self.counters.get(slug, 0)
        self.counters[slug] = k + 1
        return f"{self.room.id}-{slug}-{k}"

    def _commit(self, item: ItemSpec, size, ch: _Choice, support: str, rule: str,
                group: str | None, anchor: str | None) -> HouseObject:
        obj = HouseObject(
            id=self._new_id(item.name), room=self.room.id, name=item.name, category=item.category,
            description=item.description,
            position=(float(ch.xy[0]), float(ch.xy[1]), float(ch.z)),
            size=(float(size[0]), float(size[1]), float(size[2])), yaw=R.wrap(ch.yaw),
            support=support, group=group, anchor=anchor, rule=rule, material=item.material,
            tags=list(item.tags),
        )
        corners = rect_corners(ch.xy[None], size[:2], [obj.yaw])[0]
        mask = self.nav.obstacle_mask(corners) if nav_blocks(obj) else None
        self.space.placed.append(Placed(obj, corners, ch.z, ch.z + size[2], support == "floor", mask))
        if mask is not None:
            self.nav.blocked |= mask
        return obj

    # ------------------------------------------------------------ choosing
    def _rank(self, c: R.Cands, size, kind: str, noise: float, spacing: bool) -> np.ndarray:
        """Indices of the valid candidates, best first."""
        if not len(c):
            return np.zeros(0, dtype=int)
        corners = rect_corners(c.xy, size[:2], c.yaw)
        mask = self.space.valid(corners, c.z, c.z + size[2], floor=kind == "floor", doors=kind != "top")
        idx = np.nonzero(mask)[0]
        if not idx.size:
            return idx
        score = c.pref[idx] + noise * self.rng.random(idx.size)
        if spacing and kind == "floor":
            score += SPACING_WEIGHT * self.space.clearance(corners[idx], SPACING_CAP_M) / SPACING_CAP_M
        if kind == "floor" and size[2] > TALL_M:
            score -= WINDOW_PENALTY * self.space.window_penalty(corners[idx])
        return idx[np.argsort(-score, kind="stable")]

    def _verified(self, c: R.Cands, order: np.ndarray, size, kind: str, supporter: HouseObject | None,
                  k: int = 1, min_sep_m: float = 0.0) -> list[_Choice]:
        """Up to ``k`` candidates from ``order`` that pass the exact geometry checks."""
        out: list[_Choice] = []
        for i in order[: 40 * k]:
            ch = _Choice(c.xy[i].copy(), float(c.yaw[i]), float(c.z[i]))
            if min_sep_m and any(
                np.linalg.norm(o.xy - ch.xy) < min_sep_m and abs(math.cos(o.yaw - ch.yaw) - 1) < 1e-6
                for o in out
            ):
                continue
            if self._exact_ok(ch, size, kind, supporter):
                out.append(ch)
                if len(out) >= k:
                    break
        return out

    def _exact_ok(self, ch: _Choice, size, kind: str, supporter: HouseObject | None) -> bool:
        """The contract's own checks (anyhome.geometry), as the evaluator runs them."""
        pos = (ch.xy[0], ch.xy[1], ch.z)
        fp = footprint_polygon(pos, size, ch.yaw)
        if not inside(self.space.poly, fp):
            return False
        if supporter is not None:
            sfp = footprint_polygon(supporter.position, supporter.size, supporter.yaw)
            if not inside(sfp, fp):
                return False
        if kind != "top":
            for zone in self.space.zone_polys:
                if fp.intersects(zone) and fp.intersection(zone).area > 1e-6:
                    return False
        lo, hi = np.min(fp.exterior.coords, 0), np.max(fp.exterior.coords, 0)
        for p in self.space.placed:
            plo, phi = p.corners.min(0), p.corners.max(0)
            if np.any(plo > hi) or np.any(phi < lo):
                continue
            o = p.obj
            if boxes_collide(pos, size, ch.yaw, o.position, o.size, o.yaw):
                return False
        return True

    def _pick_one(self, c: R.Cands, size, kind: str, noise: float, spacing: bool = False,
                  supporter: HouseObject | None = None) -> _Choice | None:
        got = self._verified(c, self._rank(c, size, kind, noise, spacing), size, kind, supporter)
        return got[0] if got else None

    def _no_fit_reason(self, size, what: str = "") -> str:
        ext = self.space.bmax - self.space.bmin
        if size[2] > self.space.height:
            return f"taller ({size[2]:.2f} m) than the room ({self.space.height:.2f} m)"
        w, d = size[0], size[1]
        if not ((w <= ext[0] and d <= ext[1]) or (w <= ext[1] and d <= ext[0])):
            return f"larger ({size[0]:.2f} x {size[1]:.2f} m) than the room"
        return what or "no free spot that keeps doors and walkways clear"

    # ------------------------------------------------------------ rooms
    def furnish(self) -> None:
        groups = sorted(self.spec.groups, key=lambda g: g.priority)
        for g in groups:
            if g.arrangement == "rows":
                self._place_rows(g)
            else:
                prev = None
                for c in range(g.repeat):
                    anchor = self._place_group_copy(g, c, prev)
                    prev = anchor or prev
        for item in self.spec.ornaments:
            prev = None
            for _ in range(item.count):
                obj = self._place_ornament(item, prev)
                prev = obj or prev

    # ------------------------------------------------------------ candidates
    def _match(self, target: str | None, exclude: str | None = None) -> list[HouseObject]:
        """Objects of this room named or categorised as ``target``, best match first."""
        if not target:
            return []
        t = target.lower().strip()
        objs = [o for o in self.space.objects if o.id != exclude]
        tiers = [
            [o for o in objs if o.name.lower() == t],
            [o for o in objs if t in o.name.lower()],
            [o for o in objs if o.category.lower() == t or t in o.category.lower()],
            [o for o in objs if o.category.lower() in t],
        ]
        seen, out = set(), []
        for tier in tiers:
            for o in tier:
                if o.id not in seen:
                    seen.add(o.id)
                    out.append(o)
        return out

    def _wall_z(self, item: ItemSpec, size, ref: HouseObject | None) -> float | None:
        z = float(item.params.get("elevation_m", R.WALL_ITEM_ELEVATION_M))
        if ref is not None and "elevation_m" not in item.params:
            z = max(z, ref.position[2] + ref.size[2] + 0.1)
        top = self.space.height - 0.05 - 1e-6
        if z + size[2] > top:
            z = top - size[2]
        return z if z >= 0 else None

    def _cands(self, item: ItemSpec, rule: str, size, ref: HouseObject | None,
               prev_same: HouseObject | None, prev_wall: HouseObject | None) -> tuple[R.Cands, str]:
        """Candidates for one copy of ``item`` by ``rule``; returns (cands, kind)."""
        c, kind = self._rule_cands(item, rule, size, ref, prev_same, prev_wall)
        w = self.rows_wall
        if w is not None and len(c) and rule in WALL_RULES and _front_item(item):
            rel = c.xy - w.a[None]
            t, d = rel @ w.u, rel @ w.n
            on = (np.abs(d - size[1] / 2) < 0.01) & (t >= -0.01) & (t <= w.length + 0.01)
            c = R.Cands(c.xy, c.yaw, c.z, c.pref + FRONT_WALL_BONUS * on)
        return c, kind

    def _rule_cands(self, item: ItemSpec, rule: str, size, ref: HouseObject | None,
                    prev_same: HouseObject | None, prev_wall: HouseObject | None) -> tuple[R.Cands, str]:
        p = item.params
        if rule == "place_corner":
            return R.place_corner(self.space, size) + R.place_wall(self.space, size).shifted_pref(-1.0), "floor"
        if rule == "place_wall":
            return R.place_wall(self.space, size, str(p.get("wall", "any"))), "floor"
        if rule == "place_next_wall":
            near = R.place_next_wall(self.space, size, prev_wall)
            fb = R.place_wall(self.space, size)
            if prev_wall is not None and len(fb):
                d = np.linalg.norm(fb.xy - np.asarray(prev_wall.position[:2])[None], axis=1)
                fb.pref = -0.5 - 0.1 * d
            return near + fb, "floor"
        if rule == "place_center":
            return R.place_center(self.space, size, str(p.get("facing", "any"))), "floor"
        if rule == "place_next":
            return R.place_next(self.space, size, prev_same), "floor"
        if rule == "place_on_wall":
            z = self._wall_z(item, size, ref)
            if z is None:
                return R.Cands.empty(), "wall"
            return R.place_on_wall(self.space, size, z, ref), "wall"
        if ref is None:  # relative rule with nothing to relate to
            return R.place_center(self.space, size), "floor"
        if rule == "place_beside":
            return R.place_beside(ref, size, str(p.get("side", "both"))), "floor"
        if rule == "place_front":
            return R.place_front(self.space, ref, size, float(p.get("distance_m", 0.4)),
                                 str(p.get("facing", "toward"))), "floor"
        if rule == "place_around":
            slots = R.around_slots(ref, size, str(p.get("sides", "all")))
            pts: list[np.ndarray] = []
            yaw: list[float] = []
            for s in slots:
                for pos, y in R.around_positions(ref, size, s, s[-1]):
                    pts.append(pos)
                    yaw.append(y)
            xy = np.asarray(pts).reshape(-1, 2)
            return R.Cands(xy, np.asarray(yaw), np.zeros(len(xy)), np.ones(len(xy))), "floor"
        return R.place_center(self.space, size), "floor"

    # ------------------------------------------------------------ groups
    def _anchor_cands(self, g: GroupSpec, prev: HouseObject | None) -> tuple[R.Cands, str, str, HouseObject | None]:
        item = g.anchor
        size = item.size_m
        rule = item.rule
        if g.arrangement == "along_walls":
            if prev is None:
                rule = rule if rule in ("place_wall", "place_corner") else "place_wall"
            else:
                rule = "place_next_wall"
            c, kind = self._cands(item, rule, size, None, prev, prev)
            return c, kind, rule, None
        if g.arrangement == "center":
            c = R.place_center(self.space, size, str(item.params.get("facing", "any")))
            c.pref = c.pref * 3.0
            return c, "floor", "place_center", None
        ref = None
        if rule in ("place_beside", "place_around", "place_front", "place_top", "place_on_wall"):
            refs = self._match(item.target)
            ref = refs[0] if refs else None
        if rule == "place_top":
            return R.Cands.empty(), "top", rule, ref
        c, kind = self._cands(item, rule, size, ref, prev, prev)
        return c, kind, rule, ref

    def _place_group_copy(self, g: GroupSpec, copy: int, prev: HouseObject | None) -> HouseObject | None:
        label = f"{g.name}-{copy}"
        item = g.anchor
        size = item.size_m
        if item.rule == "place_top" and g.arrangement not in ("along_walls", "center"):
            obj = self._place_on_some_top(item, None, label, None)
            if obj is None:
                self._drop_group(g, "no surface to stand on")
                return None
            drops = self._place_members(g, label, obj)
            self.dropped.extend(drops)
            return obj
        c, kind, rule, ref = self._anchor_cands(g, prev)
        tries = ANCHOR_TRIES_REQUIRED if g.required else ANCHOR_TRIES
        if kind == "floor" and g.members and len(c):
            c = self._group_room_bonus(g, c)
        order = self._rank(c, size, kind, NOISE, spacing=True)
        choices = self._verified(c, order, size, kind, None, k=tries, min_sep_m=0.5)
        return self._try_choices(g, label, choices, kind, rule)

    def _group_room_bonus(self, g: GroupSpec, c: R.Cands) -> R.Cands:
        """Prefer anchor poses where the whole group's extent (members included) is free."""
        x0, x1, y0, y1 = self._group_extent(g, far=False)
        w, d = g.anchor.size_m[0], g.anchor.size_m[1]
        if x1 - x0 <= w + 1e-6 and y1 - y0 <= d + 1e-6:
            return c
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        cos, sin = np.cos(c.yaw), np.sin(c.yaw)
        xy = c.xy + np.stack([cx * cos - cy * sin, cx * sin + cy * cos], 1)
        corners = rect_corners(xy, (x1 - x0, y1 - y0), c.yaw)
        ok = self.space.valid(corners, 0.0, min(0.9, g.anchor.size_m[2]), floor=True)
        return R.Cands(c.xy, c.yaw, c.z, c.pref + GROUP_ROOM_BONUS * ok)

    def _try_choices(self, g: GroupSpec, label: str, choices: list[_Choice], kind: str, rule: str) -> HouseObject | None:
        item = g.anchor
        if not choices:
            self._drop_group(g, self._no_fit_reason(item.size_m))
            return None
        snap = self._snapshot()
        best: tuple[int, int] | None = None  # (number of drops, choice index)
        for k, ch in enumerate(choices):
            support = "wall" if kind == "wall" else "floor"
            anchor = self._commit(item, item.size_m, ch, support, rule, label, None)
            if kind != "top" and not self.nav.ok():
                self._restore(snap)
                continue
            drops = self._place_members(g, label, anchor)
            if not drops:
                return anchor
            if best is None or len(drops) < best[0]:
                best = (len(drops), k)
            self._restore(snap)
        if best is None:
            self._drop_group(g, "would block a walkway or a door")
            return None
        ch = choices[best[1]]
        anchor = self._commit(item, item.size_m, ch, "wall" if kind == "wall" else "floor", rule, label, None)
        self.dropped.extend(self._place_members(g, label, anchor))
        return anchor

    def _drop_group(self, g: GroupSpec, reason: str) -> None:
        self._drop(g.anchor.name, reason)
        for m in g.members:
            for _ in range(m.count):
                self._drop(m.name, f"its anchor {g.anchor.name!r} was not placed")

    # ------------------------------------------------------------ members
    def _place_members(self, g: GroupSpec, label: str, anchor: HouseObject) -> list[Dropped]:
        placed: dict[str, list[HouseObject]] = {g.anchor.name: [anchor]}
        drops: list[Dropped] = []
        pending = list(g.members)
        prev_wall = anchor if anchor.rule in WALL_RULES else None
        names = {m.name for m in g.members} | {g.anchor.name}
        while pending:
            ready = [m for m in pending if (m.target or g.anchor.name) in placed or (m.target or "") not in names]
            if not ready:
                for m in pending:
                    drops += [Dropped(room=self.room.id, name=m.name, reason=f"target {m.target!r} was not placed")] * m.count
                break
            m = ready[0]
            pending.remove(m)
            tname = m.target or g.anchor.name
            refs = placed.get(tname)
            if refs is None:  # target names something outside the group
                refs = self._match(tname) or [anchor]
            objs, d = self._place_item_copies(m, refs, label, anchor.id, prev_wall)
            placed.setdefault(m.name, []).extend(objs)
            for o in objs:
                if o.rule in ("place_wall", "place_corner", "place_next_wall"):
                    prev_wall = o
            drops += d
        return drops

    def _place_item_copies(self, m: ItemSpec, refs: list[HouseObject], label: str | None, anchor_id: str | None,
                           prev_wall: HouseObject | None) -> tuple[list[HouseObject], list[Dropped]]:
        objs: list[HouseObject] = []
        drops: list[Dropped] = []
        if not refs and m.rule in R_REL:
            return [], [Dropped(room=self.room.id, name=m.name, reason=f"target {m.target!r} was not placed")] * m.count
        if m.rule == "place_around":
            return self._place_around(m, refs, label, anchor_id)
        prev_same = None
        for i in range(m.count):
            ref = refs[i % len(refs)] if refs else None
            if m.rule == "place_top":
                obj = self._place_on_some_top(m, [ref] if ref is not None else None, label, anchor_id)
                reason = "does not fit on top of its target"
            else:
                params = dict(m.params)
                if m.rule == "place_beside" and params.get("side", "both") == "both":
                    params["side"] = ("left", "right")[i % 2] if m.count > 1 else "both"
                obj = self._place_single(m, params, ref, prev_same, prev_wall, label, anchor_id, i)
                reason = self._no_fit_reason(m.size_m)
            if obj is None:
                drops.append(Dropped(room=self.room.id, name=m.name, reason=reason))
                continue
            objs.append(obj)
            prev_same = obj
            if obj.rule in ("place_wall", "place_corner", "place_next_wall"):
                prev_wall = obj
        return objs, drops

    def _place_single(self, m: ItemSpec, params: dict, ref: HouseObject | None, prev_same, prev_wall,
                      label: str | None, anchor_id: str | None, copy: int) -> HouseObject | None:
        item = m.model_copy(update={"params": params})
        size = m.size_m
        c, kind = self._cands(item, m.rule, size, ref, prev_same, prev_wall)
        if m.rule == "place_beside" and params.get("side") in ("left", "right") and ref is not None:
            other = R.place_beside(ref, size, "right" if params["side"] == "left" else "left")
            c = c + other.shifted_pref(-0.5)
        if m.rule == "place_front" and ref is not None and m.count > 1:
            lat = (copy - (m.count - 1) / 2) * (size[0] + 0.1)
            c = R.place_front(self.space, ref, size, float(params.get("distance_m", 0.4)),
                              str(params.get("facing", "toward")), lateral=lat)
        order = self._rank(c, size, kind, MEMBER_NOISE, spacing=False)
        choices = self._verified(c, order, size, kind, None, k=MEMBER_NAV_RETRIES)
        support = "wall" if kind == "wall" else "floor"
        for ch in choices:
            snap = self._snapshot()
            obj = self._commit(m, size, ch, support, m.rule, label, anchor_id)
            if not nav_blocks(obj) or self.nav.ok():
                return obj
            self._restore(snap)
        return None

    def _place_around(self, m: ItemSpec, refs: list[HouseObject], label, anchor_id) -> tuple[list[HouseObject], list[Dropped]]:
        objs: list[HouseObject] = []
        size = m.size_m
        sides = str(m.params.get("sides", "all"))
        counts = [m.count // len(refs) + (1 if i < m.count % len(refs) else 0) for i in range(len(refs))]
        missing = 0
        for ref, n in zip(refs, counts):
            slots = R.around_slots(ref, size, sides)
            alloc = R.around_allocation(slots, n)
            left = n - sum(alloc)
            for s, k in zip(slots, alloc):
                if k == 0:
                    continue
                for pos, yaw in R.around_positions(ref, size, s, k):
                    obj = self._around_one(m, ref, s, [(pos, yaw)], label, anchor_id)
                    if obj is None:
                        left += 1
                    else:
                        objs.append(obj)
            # leftovers: any slot at capacity on any side
            if left:
                spare = []
                for s in slots:
                    spare += R.around_positions(ref, size, s, s[-1])
                while left:
                    obj = self._around_one(m, ref, None, spare, label, anchor_id)
                    if obj is None:
                        break
                    objs.append(obj)
                    left -= 1
            missing += left
        drops = [Dropped(room=self.room.id, name=m.name, reason="no free seat around its target")] * missing
        return objs, drops

    def _around_one(self, m, ref, side, slots, label, anchor_id) -> HouseObject | None:
        size = m.size_m
        xy, yaw, pref = [], [], []
        for pos, y in slots:
            f = -R.front_dir(y)  # outward from the table
            for gap, p in ((0.0, 1.0), (0.1, 0.8), (0.2, 0.6)):
                for lat, q in ((0.0, 0.0), (0.05, -0.05), (-0.05, -0.05)):
                    xy.append(pos + f * gap + R.right_dir(y) * lat)
                    yaw.append(y)
                    pref.append(p + q)
        c = R.Cands(np.asarray(xy), np.asarray(yaw), np.zeros(len(xy)), np.asarray(pref))
        order = self._rank(c, size, "floor", MEMBER_NOISE, spacing=False)
        for ch in self._verified(c, order, size, "floor", None, k=MEMBER_NAV_RETRIES):
            snap = self._snapshot()
            obj = self._commit(m, size, ch, "floor", "place_around", label, anchor_id)
            if not nav_blocks(obj) or self.nav.ok():
                return obj
            self._restore(snap)
        return None

    # ------------------------------------------------------------ on top
    def _supporters(self, target: str | None) -> list[HouseObject]:
        if target:
            return self._match(target)
        lo, hi = SURFACE_TOP_RANGE_M
        out = []
        for o in self.space.objects:
            top = o.position[2] + o.size[2]
            if not lo <= top <= hi or o.size[0] * o.size[1] < 0.04:
                continue
            if is_supporter(o.tags):
                out.append(o)
        return out

    def _place_on_some_top(self, item: ItemSpec, refs: list[HouseObject] | None, label, anchor_id) -> HouseObject | None:
        sups = refs if refs is not None else self._supporters(item.target)
        if not sups:
            return None
        load = {o.id: 0 for o in sups}
        for o in self.space.objects:
            if o.support in load:
                load[o.support] += 1
        noise = self.rng.random(len(sups))
        order = sorted(range(len(sups)), key=lambda i: (load[sups[i].id], noise[i]))
        for i in order:
            sup = sups[i]
            fit = R.fit_on_top(sup, item.size_m)
            if fit is None:
                continue
            size, turned = fit
            c = R.place_top(sup, size, turned, self.rng)
            ch = self._pick_one(c, size, "top", MEMBER_NOISE, supporter=sup)
            if ch is not None:
                return self._commit(item, size, ch, sup.id, "place_top", label, anchor_id)
        return None

    # ------------------------------------------------------------ ornaments
    def _place_ornament(self, item: ItemSpec, prev: HouseObject | None) -> HouseObject | None:
        rule = item.rule
        if rule == "place_top":
            obj = self._place_on_some_top(item, None, None, None)
            if obj is None:
                self._drop(item.name, "no free surface to stand on")
            return obj
        ref = None
        if rule in R_REL:
            refs = self._match(item.target)
            ref = refs[0] if refs else None
        obj = self._place_single(item, dict(item.params), ref, prev, None, None, None, 0)
        if obj is None:
            self._drop(item.name, self._no_fit_reason(item.size_m, "no free spot on the floor or walls"))
        return obj

    # ------------------------------------------------------------ rows
    def _board_wall(self) -> Wall | None:
        """The wall holding the anchor of an earlier group (a whiteboard, a screen), if any."""
        for o in self.space.objects:
            if o.anchor is not None or o.group is None:
                continue
            back = np.asarray(o.position[:2]) - R.front_dir(o.yaw) * o.size[1] / 2
            for w in self.space.walls:
                rel = back - w.a
                if abs(float(rel @ w.n)) < 0.05 and -0.05 <= float(rel @ w.u) <= w.length + 0.05:
                    return w
        return None

    def _group_extent(self, g: GroupSpec, far: bool = True) -> tuple[float, float, float, float]:
        """Extent (x0, x1, y0, y1) of a group copy in its anchor's frame.

        With ``far`` False, members placed more than 1 m in front (a TV) are left out.
        """
        w, d = g.anchor.size_m[0], g.anchor.size_m[1]
        x0, x1, y0, y1 = -w / 2, w / 2, -d / 2, d / 2
        for m in g.members:
            if m.target not in (None, g.anchor.name):
                continue
            mw, md = m.size_m[0], m.size_m[1]
            if m.rule == "place_front":
                dist = float(m.params.get("distance_m", 0.4))
                if not far and dist > 1.0:
                    continue
                y1 = max(y1, d / 2 + dist + md)
                half = max(mw, m.count * (mw + 0.1)) / 2
                x0, x1 = min(x0, -half), max(x1, half)
            elif m.rule == "place_beside":
                side = m.params.get("side", "both")
                ext = mw + R.BESIDE_GAPS_M[0]
                if side in ("both", "left"):
                    x0 = min(x0, -w / 2 - ext)
                if side in ("both", "right") or (side == "both" and m.count > 1):
                    x1 = max(x1, w / 2 + ext)
            elif m.rule == "place_around":
                ext = R.AROUND_GAP_M + md
                y1 = max(y1, d / 2 + ext)
                if m.params.get("sides", "all") != "front":
                    y0 = min(y0, -d / 2 - ext)
                if m.params.get("sides", "all") == "all":
                    x0, x1 = min(x0, -w / 2 - ext), max(x1, w / 2 + ext)
        return x0, x1, y0, y1

    def _rows_grid(self, g: GroupSpec, wall: Wall, front_m: float) -> tuple[int, int, dict]:
        """Capacity (rows, columns) of a rows arrangement facing ``wall`` and its geometry."""
        x0, x1, y0, y1 = self._group_extent(g)
        cw, cd = x1 - x0, y1 - y0
        cu, cv = cw + ROW_AISLE_U_M, cd + ROW_AISLE_V_M
        rel = self.space.vertices - wall.a
        us, vs = rel @ wall.u, rel @ wall.n
        u0, u1 = us.min() + ROW_SIDE_CLEARANCE_M, us.max() - ROW_SIDE_CLEARANCE_M
        v0 = max(0.0, vs.min()) + front_m
        v1 = vs.max() - ROW_SIDE_CLEARANCE_M
        maxc = max(0, int(np.floor((u1 - u0 + ROW_AISLE_U_M) / cu + 1e-9)))
        maxr = max(0, int(np.floor((v1 - v0 + ROW_AISLE_V_M) / cv + 1e-9)))
        geo = dict(wall=wall, ext=(x0, x1, y0, y1), cu=cu, cv=cv, cd=cd, u0=u0, u1=u1, v0=v0)
        return maxr, maxc, geo

    def _place_rows(self, g: GroupSpec) -> None:
        """Anchors on a regular grid facing one wall, members attached to each."""
        item = g.anchor
        n = g.repeat
        board = self._board_wall()
        if board is not None:
            depth = max((o.size[1] for o in self.space.objects if o.anchor is None and o.group is not None),
                        default=0.0)
            front = ROW_FRONT_CLEARANCE_M + min(depth, 1.0)
            plans = [self._rows_grid(g, board, front), self._rows_grid(g, board, ROW_SIDE_CLEARANCE_M + depth)]
        else:  # face the longest wall, or the one across it when that fits more
            walls = sorted(self.space.walls, key=lambda w: -w.length)
            across = [w for w in walls if abs(float(w.u @ walls[0].u)) < 0.1]
            later = [x.anchor for x in self.spec.groups if x is not g] + list(self.spec.ornaments)
            fronts = [x for x in later if _front_item(x)]
            # room in front of the rows for what they face (a board, a 4 m deep stage)
            front = ROW_FRONT_CLEARANCE_M + max((x.size_m[1] for x in fronts), default=0.0) if fronts else ROW_SIDE_CLEARANCE_M
            plans = [self._rows_grid(g, w, f) for w in walls[:1] + across[:1] for f in (front, ROW_SIDE_CLEARANCE_M)]
        plans = [p for p in plans if p[0] * p[1] > 0]
        if not plans:
            prev = None
            for c in range(n):
                prev = self._place_group_copy(g, c, prev) or prev
            return
        maxr, maxc, geo = next((p for p in plans if p[0] * p[1] >= n), max(plans, key=lambda p: p[0] * p[1]))
        wall, (x0, x1, y0, y1) = geo["wall"], geo["ext"]
        self.rows_wall = wall
        nb = wall.n
        faces_member = any(
            m.rule == "place_front" and m.target in (None, item.name)
            and m.params.get("facing", "toward") == "toward" for m in g.members
        )
        yaw = R.yaw_facing(nb if faces_member else -nb)
        options = []
        for c in range(1, maxc + 1):
            r = math.ceil(n / c)
            if r <= maxr:
                # one long row, or rows of one, read as no rows at all
                lopsided = (r < 2 and n >= 2 and maxr >= 2) or (c < 2 and n >= 4 and maxc >= 2)
                options.append((lopsided, r * c - n, abs(c * geo["cu"] - r * geo["cv"]), c))
        cols = min(options)[3] if options else maxc
        rot = np.array([[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]])
        centre_local = rot @ np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        cells = []
        for j in range(maxr):
            for i in range(cols):
                u = (geo["u0"] + geo["u1"]) / 2 + (i - (cols - 1) / 2) * geo["cu"]
                v = geo["v0"] + geo["cd"] / 2 + j * geo["cv"]
                cells.append(wall.a + wall.u * u + nb * v - centre_local)
        placed = 0
        for cell in cells:
            if placed >= n:
                break
            label = f"{g.name}-{placed}"
            shifts = np.array([0.0, 0.1, -0.1, 0.2, -0.2])
            xy = cell[None] + shifts[:, None] * wall.u[None]
            cands = R.Cands(xy, np.full(len(xy), yaw), np.zeros(len(xy)), 1.0 - 0.1 * np.abs(shifts))
            order = self._rank(cands, item.size_m, "floor", 0.0, spacing=False)
            choices = self._verified(cands, order, item.size_m, "floor", None, k=2)
            if not choices:
                continue
            snap = self._snapshot()
            anchor = self._try_choices(g, label, choices, "floor", item.rule)
            if anchor is None:
                self._restore(snap)
                continue
            placed += 1
        # copies the grid has no place for are placed freely, else dropped
        prev = None
        for c in range(placed, n):
            prev = self._place_group_copy(g, c, prev) or prev


def _front_item(item: ItemSpec) -> bool:
    """Whether an item belongs at the front of a room set out in rows (a board, a lectern)."""
    return is_front_of_room(item.tags)


R_REL = frozenset({"place_beside", "place_around", "place_front", "place_top", "place_on_wall"})
