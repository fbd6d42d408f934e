"""Scoring and checking candidate poses: rank by preference, spacing, windows and noise;
verify the best with the contract's exact geometry; the room a whole group needs."""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Iterator, Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon

from anyhome.geometry import boxes_collide, footprint_corners, footprint_polygon, inside
from anyhome.house import HouseObject
from anyhome.layout.rules import REGISTRY, Cands
from anyhome.layout.rules.base import Extent
from anyhome.layout.rules.place_beside import BESIDE_GAPS_M
from anyhome.layout.rules.place_beside import Params as BesideParams
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import GroupSpec, ItemSpec
from anyhome.space import NO_COLLISION_M, rect_corners, sat_overlap

FIRST_CHUNK = 48
"""Candidates checked first by a :class:`Ranking` (those with the highest bound on their score)..."""
CHUNK_GROWTH = 4
"""...and how many times more each next batch checks, while the best are not settled."""


def rank(st: RoomState, c: Cands, size: Sequence[float], kind: str, noise: float, spacing: bool,
         layer: bool = False, avoid_windows: bool = False, bonus: Callable[[Cands], Cands] | None = None,
         bonus_max: float = 0.0) -> Ranking:
    """The valid candidates, best first, found as they are asked for (:class:`Ranking`;
    ``layer``: a rug, see RoomSpace.valid; ``avoid_windows``: keep off windows as tall
    objects do, for an anchor with something to hang on the wall behind it, a dresser's
    mirror; ``bonus``: the valid candidates with their preferences raised, as
    :func:`group_room_bonus` does, by at most ``bonus_max``, asked only of those)."""
    return Ranking(st, c, size, kind, noise, spacing, layer, avoid_windows, bonus, bonus_max)


class Ranking:
    """Indices of the valid candidates of ``c``, best first, by score: preference (raised
    by ``bonus``), ``noise`` times a seeded draw per candidate (one draw over all of them,
    so that a candidate's noise does not depend on which others are valid), free space
    around a floor pose (``spacing``), the group's zone, windows. Found lazily: candidates
    are checked (validity, then the terms asked of valid poses only: ``bonus``, spacing)
    in batches by a bound on their score, highest first, and a candidate is handed out
    once its score beats every bound left; the order is the one checking all at once
    gives (ties by index). The room must be the same whenever one is asked for."""

    def __init__(self, st: RoomState, c: Cands, size: Sequence[float], kind: str, noise: float, spacing: bool,
                 layer: bool = False, avoid_windows: bool = False, bonus: Callable[[Cands], Cands] | None = None,
                 bonus_max: float = 0.0) -> None:
        o = st.options
        self.st, self.c, self.size, self.kind, self.layer, self.bonus = st, c, size, kind, layer, bonus
        n = len(c)
        base = c.pref.astype(float, copy=True)
        if n and noise:
            base += noise * st.rng.random(n)
        floor = kind == "floor"
        if floor and st.zone is not None and n:
            base += o.zone_bonus * shapely.contains_xy(st.zone, c.xy[:, 0], c.xy[:, 1])
        self._windows = floor and (size[2] > o.tall_m or avoid_windows)
        """Poses in front of a window score less (asked of valid poses only)."""
        self._spacing: tuple[float, float] | None = None
        if spacing and floor:
            self._spacing = (o.zone_spacing_weight, o.zone_spacing_cap_m) if st.spread else (o.spacing_weight,
                                                                                             o.spacing_cap_m)
        self._base = base
        """The terms of the score asked of every candidate."""
        self._bound = base + (bonus_max if bonus is not None else 0.0) + (self._spacing[0] if self._spacing else 0.0)
        """The highest score each candidate may have."""
        self._rest = np.arange(n)
        """Candidates not checked yet..."""
        self._top = float(self._bound.max()) if n else -np.inf
        """...and the highest bound among them."""
        self._chunk = FIRST_CHUNK
        self._heap: list[tuple[float, int]] = []
        """(-score, index) of the valid candidates checked and not handed out yet."""
        self.found: list[int] = []
        """The valid candidates handed out so far, best first."""

    def get(self, pos: int) -> int | None:
        """Index of the ``pos``-th best valid candidate; None when fewer are valid."""
        while len(self.found) <= pos:
            if not self._next():
                return None
        return self.found[pos]

    def all(self) -> np.ndarray:
        """The whole order (every candidate checked)."""
        while self._next():
            pass
        return np.asarray(self.found, dtype=int)

    def _next(self) -> bool:
        """Hand out the next best valid candidate, checking more where the bounds ask to;
        False when none is left."""
        heap = self._heap
        while True:
            if heap and -heap[0][0] > self._top:
                self.found.append(heapq.heappop(heap)[1])
                return True
            if not len(self._rest):
                if not heap:
                    return False
                self.found.append(heapq.heappop(heap)[1])
                return True
            self._check(self._take())

    def _take(self) -> np.ndarray:
        """The next batch: the unchecked candidates of the highest bounds."""
        rest, k = self._rest, self._chunk
        self._chunk *= CHUNK_GROWTH
        if len(rest) <= k:
            self._rest, self._top = rest[:0], -np.inf
            return rest
        part = np.argpartition(-self._bound[rest], k - 1)
        self._rest = rest[part[k:]]
        self._top = float(self._bound[self._rest].max())
        return rest[part[:k]]

    def _check(self, idx: np.ndarray) -> None:
        """Validity, then the scores of the valid ones of ``idx``."""
        st, c, size, kind = self.st, self.c, self.size, self.kind
        corners = rect_corners(c.xy[idx], size[:2], c.yaw[idx])
        z = c.z[idx]
        ok = st.space.valid(corners, z, z + size[2], floor=kind == "floor", doors=kind != "top", layer=self.layer)
        idx = idx[ok]
        if not idx.size:
            return
        score = self._base[idx].copy()
        if self.bonus is not None:
            sub = Cands(c.xy[idx], c.yaw[idx], c.z[idx], c.pref[idx])
            score += self.bonus(sub).pref - sub.pref
        if self._spacing is not None:
            weight, cap = self._spacing
            score += weight * st.space.clearance(corners[ok], cap) / cap
        if self._windows:
            score -= st.options.window_penalty * st.space.window_penalty(corners[ok])
        for sc, i in zip((-score).tolist(), idx.tolist(), strict=True):
            heapq.heappush(self._heap, (sc, i))


def verified(st: RoomState, c: Cands, order: Ranking, size: Sequence[float], kind: str,
             supporter: HouseObject | None, k: int = 1, min_sep_m: float = 0.0) -> list[Choice]:
    """Up to ``k`` candidates from ``order`` that pass the exact geometry checks."""
    return list(verified_lazily(st, c, order, size, kind, supporter, k, min_sep_m))


def verified_lazily(st: RoomState, c: Cands, order: Ranking, size: Sequence[float], kind: str,
                    supporter: HouseObject | None, k: int = 1, min_sep_m: float = 0.0) -> Iterator[Choice]:
    """:func:`verified`'s choices, each checked when asked for (the same choices as long as
    the room is the same whenever one is asked for)."""
    return Verifier(st, c, order, size, kind, supporter, min_sep_m).upto(k)


class Verifier:
    """The candidates of ``order`` that pass the exact geometry checks, checked as they are
    asked for and kept: asking for more (:meth:`upto` with a larger ``k``) goes on where
    the last ask stopped rather than checking the first ones again. The choices are those
    of :func:`verified` as long as the room is the same whenever one is checked."""

    def __init__(self, st: RoomState, c: Cands, order: Ranking, size: Sequence[float], kind: str,
                 supporter: HouseObject | None, min_sep_m: float = 0.0) -> None:
        self.st, self.c, self.order, self.size, self.kind = st, c, order, size, kind
        self.supporter, self.min_sep_m = supporter, min_sep_m
        self.found: list[Choice] = []
        """The choices found so far, in order."""
        self._next = 0
        """Position in ``order`` of the next candidate to check."""

    def upto(self, k: int) -> Iterator[Choice]:
        """The first ``k`` choices among the first ``verify_factor * k`` candidates of
        ``order``, each found when asked for."""
        end = self.st.options.verify_factor * k
        for i in range(k):
            if i >= len(self.found) and not self._find(end):
                return
            yield self.found[i]

    def list(self, k: int) -> list[Choice]:
        """:meth:`upto` all at once."""
        return list(self.upto(k))

    def _find(self, end: int) -> bool:
        """Check candidates up to position ``end`` of ``order`` until one passes."""
        c, out, sep = self.c, self.found, self.min_sep_m
        while self._next < end:
            i = self.order.get(self._next)
            if i is None:
                return False
            self._next += 1
            ch = Choice(c.xy[i].copy(), float(c.yaw[i]), float(c.z[i]))
            if sep and any(
                math.hypot(float(o.xy[0] - ch.xy[0]), float(o.xy[1] - ch.xy[1])) < sep
                and abs(math.cos(o.yaw - ch.yaw) - 1) < 1e-6
                for o in out
            ):
                continue
            if exact_ok(self.st, ch, self.size, self.kind, self.supporter):
                out.append(ch)
                return True
        return False


def exact_ok(st: RoomState, ch: Choice, size: Sequence[float], kind: str, supporter: HouseObject | None) -> bool:
    """The contract's own checks (anyhome.geometry), as the evaluator runs them (shapely asked
    only where coordinates do not settle them: a rectangular room, boxes apart)."""
    pos = (ch.xy[0], ch.xy[1], ch.z)
    sp = st.space
    corners = footprint_corners(pos, size, ch.yaw)
    lo, hi = corners.min(0), corners.max(0)
    fp: Polygon | None = None
    inside_box = sp.in_outline_box(lo, hi)
    if inside_box is None:
        fp = Polygon(corners)
        if not sp.outline.contains(fp):
            return False
    elif not inside_box:
        return False
    if supporter is not None:
        fp = Polygon(corners) if fp is None else fp
        sfp = footprint_polygon(supporter.position, supporter.size, supporter.yaw)
        if not inside(sfp, fp):
            return False
    if kind != "top" and sp.zone_polys:
        meet = ~((sp.zone_lo > hi).any(1) | (sp.zone_hi < lo).any(1))  # bounding boxes apart: no intersection
        for z in meet.nonzero()[0].tolist():
            if ch.z >= sp.zone_tops[z]:  # hung over a stair well or a flight's foot
                continue
            zone = sp.zone_polys[z]
            fp = Polygon(corners) if fp is None else fp
            if fp.intersects(zone) and fp.intersection(zone).area > 1e-6:
                return False
    near = sp.near(lo, hi)
    if near:
        # footprints a clear gap apart cannot collide (their shrunk polygons are further apart)
        gap = sat_overlap(corners[None], np.stack([p.corners for p in near]))[0]
        for p, g in zip(near, gap, strict=True):
            o = p.obj
            if g < NO_COLLISION_M:  # apart, or overlapping too little to collide
                continue
            if boxes_collide(pos, size, ch.yaw, o.position, o.size, o.yaw):
                return False
    return True


def pick_one(st: RoomState, c: Cands, size: Sequence[float], kind: str, noise: float, spacing: bool = False,
             supporter: HouseObject | None = None) -> Choice | None:
    got = verified(st, c, rank(st, c, size, kind, noise, spacing), size, kind, supporter)
    return got[0] if got else None


def no_fit_reason(st: RoomState, size: Sequence[float], what: str = "") -> str:
    ext = st.space.bmax - st.space.bmin
    if size[2] > st.space.height:
        return f"taller ({size[2]:.2f} m) than the room ({st.space.height:.2f} m)"
    w, d = size[0], size[1]
    if not ((w <= ext[0] and d <= ext[1]) or (w <= ext[1] and d <= ext[0])):
        return f"larger ({size[0]:.2f} x {size[1]:.2f} m) than the room"
    return what or "no free spot that keeps doors and walkways clear"


def group_extent(g: GroupSpec, near_m: float | None = None) -> Extent:
    """Extent (x0, x1, y0, y1) of a group copy in its anchor's frame, each member's rule
    growing it; with ``near_m``, members placed further in front (a TV) are left out."""
    w, d = g.anchor.size_m[0], g.anchor.size_m[1]
    box: Extent = (-w / 2, w / 2, -d / 2, d / 2)
    for m in g.members:
        if m.target not in (None, g.anchor.name):
            continue
        rule = REGISTRY[m.rule]
        box = rule.extent(box, g.anchor.size_m, m.size_m, rule.parse(m.params), m.count, near_m)
    return box


def bonus_max(st: RoomState, g: GroupSpec, rule: str, first: bool) -> float:
    """The most :func:`group_room_bonus` then :func:`run_room_bonus` add to a preference."""
    o = st.options
    group = o.group_room_bonus + o.beside_lane_bonus if g.members else 0.0
    return group + (o.group_room_bonus if run_length(g, rule, first)[0] > 0 else 0.0)


def group_room_bonus(st: RoomState, g: GroupSpec, c: Cands) -> Cands:
    """Prefer anchor poses where the whole group's extent (members included) is free
    (:func:`group_room_free`), and with free lanes beside it (:func:`beside_lanes_free`)."""
    return anchor_bonus(st, g, c, None, False)


def anchor_bonus(st: RoomState, g: GroupSpec, c: Cands, rule: str | None, first: bool) -> Cands:
    """:func:`group_room_bonus` (when ``g`` has members) then, with ``rule``, :func:`run_room_bonus`
    of the anchor poses ``c``, every box they test asked of :meth:`~anyhome.space.RoomSpace.valid`
    at once."""
    o = st.options
    group = _group_boxes(st, g, c) if g.members and len(c) else None
    run = _run_boxes(g, c, rule, first) if rule is not None else []
    boxes = [*(group or []), *run]
    if not boxes:
        return c
    free = _free_each(st, g, boxes)
    pref = c.pref
    if group is not None:
        pref = pref + o.group_room_bonus * free[0] + o.beside_lane_bonus * _all_of(free[1:len(group)], len(c))
    if run:
        pref = pref + o.group_room_bonus * (free[-2] | free[-1])
    return Cands(c.xy, c.yaw, c.z, pref)


def _free_each(st: RoomState, g: GroupSpec, boxes: list[np.ndarray]) -> list[np.ndarray]:
    """Masks of the footprints of each of ``boxes`` (corners (n, 4, 2)) free up to the group's
    height, asked at once (``valid`` tests each pose alone)."""
    top = min(st.options.group_room_height_m, g.anchor.size_m[2])
    ok = st.space.valid(np.concatenate(boxes) if len(boxes) > 1 else boxes[0], 0.0, top, floor=True)
    return np.split(ok, np.cumsum([len(b) for b in boxes])[:-1])


def _all_of(masks: list[np.ndarray], n: int) -> np.ndarray:
    """Poses free in every one of ``masks`` (all True when there are none)."""
    ok = np.ones(n, dtype=bool)
    for m in masks:
        ok &= m
    return ok


def _group_boxes(st: RoomState, g: GroupSpec, c: Cands) -> list[np.ndarray] | None:
    """Footprints :func:`group_room_bonus` tests: the group's extent, then the lanes beside
    the anchor (:func:`beside_lanes_free`); None when the members add nothing to the anchor's
    own footprint."""
    extent = _extent_box(st, g, c)
    return None if extent is None else [extent, *_lane_boxes(st, g, c)]


def group_room_free(st: RoomState, g: GroupSpec, c: Cands) -> np.ndarray | None:
    """Mask of anchor poses ``c`` where the whole group's extent (members included) is
    free; None when the members add nothing to the anchor's own footprint."""
    box = _extent_box(st, g, c)
    return None if box is None else _free_each(st, g, [box])[0]


def _extent_box(st: RoomState, g: GroupSpec, c: Cands) -> np.ndarray | None:
    """Footprints of the group's extent at the anchor poses ``c`` (:func:`group_room_free`)."""
    o = st.options
    x0, x1, y0, y1 = group_extent(g, near_m=o.near_m)
    w, d = g.anchor.size_m[0], g.anchor.size_m[1]
    if x1 - x0 <= w + 1e-6 and y1 - y0 <= d + 1e-6:
        return None
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    cos, sin = np.cos(c.yaw), np.sin(c.yaw)
    xy = c.xy + np.stack([cx * cos - cy * sin, cx * sin + cy * cos], 1)
    return rect_corners(xy, (x1 - x0, y1 - y0), c.yaw)


def _beside_members(g: GroupSpec) -> list[tuple[float, ItemSpec]]:
    """(side sign: -1 left, +1 right; member) for every side a member placed beside the
    anchor (``place_beside``) may take."""
    out = []
    for m in g.members:
        if m.rule != "place_beside" or m.target not in (None, g.anchor.name):
            continue
        side = BesideParams.model_validate(m.params).side
        out += [(sgn, m) for sgn in {"left": (-1.0,), "right": (1.0,)}.get(side, (-1.0, 1.0))]
    return out


def _side_boxes(g: GroupSpec, c: Cands, boxes: dict[float, tuple[float, float, float, float]]) -> list[np.ndarray]:
    """Footprints of every box (side sign -> width, depth, offset to the right of the
    anchor's side, offset to the front) at the anchor poses ``c``."""
    cos, sin = np.cos(c.yaw), np.sin(c.yaw)
    right, front = np.stack([cos, sin], 1), np.stack([-sin, cos], 1)
    out = []
    for sgn, (bw, bd, out_m, fwd_m) in boxes.items():
        xy = c.xy + right * (sgn * (g.anchor.size_m[0] / 2 + out_m + bw / 2)) + front * fwd_m
        out.append(rect_corners(xy, (bw, bd), c.yaw))
    return out


def _free_boxes(st: RoomState, g: GroupSpec, c: Cands, boxes: dict[float, tuple[float, float, float, float]]) -> np.ndarray:
    """Mask of anchor poses ``c`` where every box (side sign -> width, depth, offset to the
    right of the anchor's side, offset to the front) is free up to the group's height."""
    sides = _side_boxes(g, c, boxes)
    return _all_of(_free_each(st, g, sides) if sides else [], len(c))


def _lane_boxes(st: RoomState, g: GroupSpec, c: Cands) -> list[np.ndarray]:
    """Footprints of the lanes :func:`beside_lanes_free` tests (none when no member stands
    beside the anchor)."""
    o = st.options
    widths: dict[float, float] = {}
    for sgn, m in _beside_members(g):
        widths[sgn] = max(widths.get(sgn, 0.0), o.beside_lane_m, m.size_m[0] + BESIDE_GAPS_M[0])
    if not widths or not len(c):
        return []
    depth = g.anchor.size_m[1] + o.beside_lane_front_m
    return _side_boxes(g, c, {sgn: (w, depth, 0.0, o.beside_lane_front_m / 2) for sgn, w in widths.items()})


def beside_lanes_free(st: RoomState, g: GroupSpec, c: Cands) -> np.ndarray:
    """Mask of anchor poses ``c`` with a free lane along each side of the anchor that a
    member stands beside (``place_beside``): :attr:`~.options.LayoutOptions.beside_lane_m`
    wide (or the member's width, if wider), from the anchor's back to
    :attr:`~.options.LayoutOptions.beside_lane_front_m` beyond its front, so that a
    nightstand or side table there is still walked up to once the anchor stands; all
    True when no member stands beside it."""
    lanes = _lane_boxes(st, g, c)
    return _all_of(_free_each(st, g, lanes) if lanes else [], len(c))


def beside_spots_free(st: RoomState, g: GroupSpec, c: Cands) -> np.ndarray | None:
    """Mask of anchor poses ``c`` where every spot a member beside the anchor is asked
    for (``place_beside``, each side it may take, at the preferred gap) is free; None
    when no member stands beside the anchor."""
    sizes: dict[float, tuple[float, float]] = {}
    for sgn, m in _beside_members(g):
        w0, d0 = sizes.get(sgn, (0.0, 0.0))
        sizes[sgn] = (max(w0, m.size_m[0]), max(d0, m.size_m[1]))
    if not sizes:
        return None
    d = g.anchor.size_m[1]
    return _free_boxes(st, g, c, {sgn: (mw, md, BESIDE_GAPS_M[0], (md - d) / 2) for sgn, (mw, md) in sizes.items()})


def run_length(g: GroupSpec, rule: str, first: bool) -> tuple[float, float]:
    """(length, depth) of the run along the walls that follows ``g``'s anchor (placed by
    ``rule``): its members continuing it and, for the first copy of a run of anchors,
    the later copies; (0, 0) when none follows."""
    if not REGISTRY[rule].runs_along_wall:
        return 0.0, 0.0
    pieces = [(m.size_m, m.count) for m in g.members
              if REGISTRY[m.rule].continues and REGISTRY[m.rule].runs_along_wall]
    if first and (REGISTRY[g.anchor.rule].continues or g.arrangement == "along_walls"):
        pieces.append((g.anchor.size_m, g.repeat - 1))
    length = sum(s[0] * n for s, n in pieces)
    depth = max((s[1] for s, n in pieces if n), default=0.0)
    return length, depth


def run_room_bonus(st: RoomState, g: GroupSpec, c: Cands, rule: str, first: bool) -> Cands:
    """Prefer anchor poses with free wall beside them (on either side) for the run that
    follows (:func:`run_length`), so that it continues rather than jumps."""
    run = _run_boxes(g, c, rule, first)
    if not run:
        return c
    free = _free_each(st, g, run)
    return Cands(c.xy, c.yaw, c.z, c.pref + st.options.group_room_bonus * (free[0] | free[1]))


def _run_boxes(g: GroupSpec, c: Cands, rule: str, first: bool) -> list[np.ndarray]:
    """Footprints :func:`run_room_bonus` tests: the run beside the anchor on its right, then
    on its left (none when no run follows)."""
    length, depth = run_length(g, rule, first)
    if length <= 0 or not len(c):
        return []
    w, d = g.anchor.size_m[0], g.anchor.size_m[1]
    cos, sin = np.cos(c.yaw), np.sin(c.yaw)
    right = np.stack([cos, sin], 1)
    front = np.stack([-sin, cos], 1)
    back = c.xy - front * (d / 2)  # middle of the anchor's back, on the wall
    out = []
    for sgn in (1.0, -1.0):
        xy = back + right * (sgn * (w / 2 + length / 2)) + front * (depth / 2)
        out.append(rect_corners(xy, (length, depth), c.yaw))
    return out
