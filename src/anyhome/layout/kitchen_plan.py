"""Kitchen run plans: the walls a kitchen's counter run follows (one wall, galley, L, U),
chosen by the room's size, and where the fridge, sink and cooktop go along them.

Pure geometry over a :class:`~anyhome.space.RoomSpace`: nothing is placed here
(:mod:`anyhome.layout.kitchens` commits a plan). A run is a list of :class:`Leg`: a
stretch of one wall, the legs of an L or a U joined at a corner, the corner square
belonging to the earlier leg; a galley is two legs on facing walls. Along every leg the
appliances stand in its appliance zone and counters fill every gap, so the run is
continuous; the fridge stands at a run end, the sink under a window when one is on the
run, the cooktop with counter on both sides and away from the window.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from anyhome.layout.rules.base import on_wall
from anyhome.space import RoomSpace, Wall, rect_corners

PROBE_STEP_M = 0.05
"""Step of the probes that find the free stretches of a wall."""
SLIDE_STEP_M = 0.5
"""Step of the start of a capped one-wall run along a free stretch longer than it."""
MIN_LEG_M = 0.9
"""Shortest leg of an L or a U beyond its corner square."""
CORNER_CLEAR_M = 0.3
"""No appliance within this of a corner square (an oven door would hit the other leg)."""
MIN_COUNTER_M = 0.3
"""Narrowest counter piece: gaps between appliances are 0 (at a run end) or at least this."""
LANDING_M = 0.4
"""Counter kept on each side of the cooktop and between any two appliances."""
GALLEY_AISLE_M = (1.0, 1.6)
"""Aisle between the two runs of a galley, least and most, in metres."""
U_AISLE_MIN_M = 1.2
"""Least aisle between the two arms of a U."""
SINK_WINDOW_SCORE = 2.0
"""Score of a sink under a window (less a point per metre off the window's centre)."""
WORK_LEG_M = (1.2, 2.7)
"""Work-triangle leg lengths (centre to centre) a designer aims for, least and most."""
MAX_COUNTER_M = 2.4
"""Longest single counter piece; longer stretches are split into equal pieces."""
GALLEY_MAX_WIDTH_M = 3.2
"""Rooms up to this wide (short side) prefer a galley to an L."""
U_MIN_WIDTH_M = 3.4
"""Rooms at least this wide (short side) prefer a U to an L when no dining spot or island is planned."""


@dataclass(frozen=True)
class Leg:
    """A stretch ``[t0, t1]`` of ``wall`` (metres from its start) the run covers;
    appliances stand within ``[lo, hi]``."""

    wall: Wall
    t0: float
    t1: float
    lo: float
    hi: float


@dataclass(frozen=True)
class RunShape:
    """One way to lay out a kitchen: its shape name and legs (connected in order, except
    a galley's two)."""

    shape: str
    legs: tuple[Leg, ...]

    @property
    def length_m(self) -> float:
        return sum(g.t1 - g.t0 for g in self.legs)


@dataclass(frozen=True)
class Slot:
    """One run piece: ``role`` (counter, fridge, sink, stove) on leg ``leg`` over ``[t0, t1]``."""

    role: str
    leg: int
    t0: float
    t1: float


def free_spans(space: RoomSpace, walls: Sequence[Wall], depth: float, height: float) -> list[list[tuple[float, float]]]:
    """For each of ``walls``, the stretches where a floor piece ``depth`` deep and ``height``
    tall fits (in the room, clear of doors and of what is placed), probed every
    :data:`PROBE_STEP_M` (one ``valid`` call for every wall)."""
    ts = [np.arange(PROBE_STEP_M / 2, w.length, PROBE_STEP_M) for w in walls]
    probes = [rect_corners(on_wall(w, t, depth), (PROBE_STEP_M, depth), np.full(len(t), w.yaw))
              for w, t in zip(walls, ts, strict=True) if t.size]
    ok = space.valid(np.concatenate(probes), 0.0, height, floor=True) if probes else np.zeros(0, dtype=bool)
    out: list[list[tuple[float, float]]] = []
    at = 0
    for w, t in zip(walls, ts, strict=True):
        good = ok[at:at + len(t)]
        at += len(t)
        edges = np.diff(np.concatenate(([False], good, [False])).astype(np.int8))
        starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
        out.append([(max(0.0, float(t[a] - PROBE_STEP_M / 2)), min(w.length, float(t[b] + PROBE_STEP_M / 2)))
                    for a, b in zip(starts.tolist(), ends.tolist(), strict=True)])
    return out


def _convex(a: Wall, b: Wall) -> bool:
    return float(a.u[0] * b.u[1] - a.u[1] * b.u[0]) > 1e-6


def _span_to_end(spans: list[tuple[float, float]], wall: Wall) -> tuple[float, float] | None:
    return next((s for s in spans if s[1] >= wall.length - PROBE_STEP_M), None)


def _span_from_start(spans: list[tuple[float, float]]) -> tuple[float, float] | None:
    return next((s for s in spans if s[0] <= PROBE_STEP_M), None)


def run_shapes(space: RoomSpace, depth: float, deepest: float, height: float, cap_m: float | None) -> list[RunShape]:
    """Every one-wall, L, U and galley run the room's free walls allow for counters
    ``depth`` deep (the corner squares) and pieces up to ``deepest`` deep and ``height``
    tall; ``cap_m``: the run kept to about that length (an open-plan kitchen, a
    kitchenette), no galley or U."""
    walls = space.walls
    k = len(walls)
    spans = free_spans(space, walls, deepest, height)
    out: list[RunShape] = []
    for i, w in enumerate(walls):
        for a, b in spans[i]:
            if b - a < MIN_LEG_M:
                continue
            if cap_m is None:
                out.append(RunShape("one", (Leg(w, a, b, a, b),)))
            else:
                c = min(cap_m, b - a)
                starts = sorted({a, b - c, *np.arange(a + SLIDE_STEP_M, b - c, SLIDE_STEP_M)})
                out += [RunShape("one", (Leg(w, t, t + c, t, t + c),)) for t in starts]
    for i in range(k):
        wa, wb, wc = walls[i], walls[(i + 1) % k], walls[(i + 2) % k]
        if not _convex(wa, wb):
            continue
        sa, sb = _span_to_end(spans[i], wa), _span_from_start(spans[(i + 1) % k])
        if sa is None or sb is None or wa.length - sa[0] < depth + MIN_LEG_M or sb[1] < depth + MIN_LEG_M:
            continue
        a0, b1 = sa[0], sb[1]
        if cap_m is not None:
            a0 = max(a0, wa.length - depth - cap_m / 2)
            b1 = min(b1, depth + cap_m / 2)
        leg_a = Leg(wa, a0, wa.length, a0, wa.length - depth - CORNER_CLEAR_M)
        out.append(RunShape("L", (leg_a, Leg(wb, depth, b1, depth + CORNER_CLEAR_M, b1))))
        if cap_m is not None or k < 4 or not _convex(wb, wc) or wb.length - 2 * depth < U_AISLE_MIN_M:
            continue
        whole_b = sb[1] >= wb.length - PROBE_STEP_M
        sc = _span_from_start(spans[(i + 2) % k])
        if whole_b and sc is not None and sc[1] >= depth + MIN_LEG_M:
            leg_b = Leg(wb, depth, wb.length, depth + CORNER_CLEAR_M, wb.length - depth - CORNER_CLEAR_M)
            out.append(RunShape("U", (leg_a, leg_b, Leg(wc, depth, sc[1], depth + CORNER_CLEAR_M, sc[1]))))
    if cap_m is None:
        out += _galleys(walls, spans, depth)
    return out


def _galleys(walls: list[Wall], spans: list[list[tuple[float, float]]], depth: float) -> list[RunShape]:
    out = []
    for i, wa in enumerate(walls):
        for j in range(i + 1, len(walls)):
            wb = walls[j]
            if float(wa.u @ wb.u) > -0.999:
                continue
            aisle = float((wb.a - wa.a) @ wa.n) - 2 * depth
            if not GALLEY_AISLE_M[0] - 1e-6 <= aisle <= GALLEY_AISLE_M[1]:
                continue
            la = max(spans[i], key=lambda s: s[1] - s[0], default=None)
            lb = max(spans[j], key=lambda s: s[1] - s[0], default=None)
            if la is None or lb is None or min(la[1] - la[0], lb[1] - lb[0]) < MIN_LEG_M:
                continue
            out.append(RunShape("galley", (Leg(wa, la[0], la[1], la[0], la[1]), Leg(wb, lb[0], lb[1], lb[0], lb[1]))))
    return out


def shape_order(short_side_m: float, open_plan: bool, room_for_more: bool) -> tuple[str, ...]:
    """Shapes to try first to last in a room ``short_side_m`` wide (``room_for_more``: a
    dining spot or an island is planned there too)."""
    if open_plan:
        return ("L", "one")
    if short_side_m < 2 * 0.6 + GALLEY_AISLE_M[0]:
        return ("L", "one")
    if short_side_m <= GALLEY_MAX_WIDTH_M:
        return ("galley", "L", "one") if short_side_m < 2.8 else ("L", "galley", "U", "one")
    if short_side_m >= U_MIN_WIDTH_M and not room_for_more:
        return ("U", "L", "galley", "one")
    return ("L", "U", "galley", "one")


def _window_centres(space: RoomSpace, leg: Leg) -> list[float]:
    return [(a + b) / 2 for a, b, _z0, _z1, door in leg.wall.openings if not door and leg.lo <= (a + b) / 2 <= leg.hi]


def _under_window(leg: Leg, t0: float, t1: float) -> bool:
    return any(not door and t1 > a and t0 < b for a, b, _z0, _z1, door in leg.wall.openings)


def _xy(leg: Leg, t: float) -> np.ndarray:
    return leg.wall.a + leg.wall.u * t


def _gaps_ok(leg: Leg, items: list[tuple[str, float, float]], landing_m: float = LANDING_M) -> bool:
    """Pieces on one leg: none overlap, appliances at least ``landing_m`` apart, every gap
    0 (a run end) or a counter of at least MIN_COUNTER_M, ``landing_m`` of counter on both
    sides of a cooktop."""
    items = sorted(items, key=lambda x: x[1])
    edges = [("end", leg.t0, leg.t0), *items, ("end", leg.t1, leg.t1)]
    for (ra, _a0, a1), (rb, b0, _b1) in zip(edges, edges[1:]):
        gap = b0 - a1
        if gap < -1e-6:
            return False
        if ra != "end" and rb != "end" and gap < landing_m - 1e-6:
            return False
        if "stove" in (ra, rb) and gap < landing_m - 1e-6:
            return False
        if 1e-3 < gap < MIN_COUNTER_M - 1e-6:
            return False
    return True


def plan_run(space: RoomSpace, shape: RunShape, widths: dict[str, float],
             landing_m: float = LANDING_M) -> list[Slot] | None:
    """Fridge, sink and cooktop on ``shape`` (``widths``: role -> width; a role left out is
    not placed), ``landing_m`` of counter between them and beside the cooktop, and
    counters in every gap; None when they do not fit."""
    legs = shape.legs
    best: tuple[float, list[tuple[int, str, float, float]]] | None = None
    for fridge in _fridge_options(shape, widths, landing_m):
        sinks = _sink_options(space, shape, widths, fridge, landing_m)
        for s_score, sink in sinks[:6]:
            fixed = [x for x in (fridge, sink) if x is not None]
            for st_score, stove in _stove_options(shape, widths, fixed, landing_m):
                score = s_score + st_score + _triangle(shape, fridge, sink, stove)
                if best is None or score > best[0]:
                    best = (score, [x for x in (*fixed, stove) if x is not None])
    if best is None:
        return None
    slots = [Slot(role, i, t0, t1) for i, role, t0, t1 in best[1]]
    for i, leg in enumerate(legs):
        taken = sorted((s.t0, s.t1) for s in slots if s.leg == i)
        cur = leg.t0
        for a, b in [*taken, (leg.t1, leg.t1)]:
            if a - cur > 1e-3:
                n = math.ceil((a - cur) / MAX_COUNTER_M - 1e-9)
                step = (a - cur) / n
                slots += [Slot("counter", i, cur + j * step, cur + (j + 1) * step) for j in range(n)]
            cur = max(cur, b)
    return slots


Piece = tuple[int, str, float, float]


def _fridge_options(shape: RunShape, widths: dict[str, float], landing_m: float) -> list[Piece | None]:
    """The fridge at each free run end that is not in front of a window."""
    if "fridge" not in widths:
        return [None]
    w = widths["fridge"]
    ends: list[Piece] = []
    legs = shape.legs
    firsts = range(len(legs)) if shape.shape == "galley" else [0]
    lasts = range(len(legs)) if shape.shape == "galley" else [len(legs) - 1]
    ends += [(i, "fridge", legs[i].t0, legs[i].t0 + w) for i in firsts]
    ends += [(i, "fridge", legs[i].t1 - w, legs[i].t1) for i in lasts]
    return [e for e in ends if legs[e[0]].lo - 1e-6 <= e[2] and e[3] <= legs[e[0]].hi + 1e-6
            and not _under_window(legs[e[0]], e[2], e[3]) and _gaps_ok(legs[e[0]], [e[1:]], landing_m)]


def _sink_options(space: RoomSpace, shape: RunShape, widths: dict[str, float],
                  fridge: Piece | None, landing_m: float) -> list[tuple[float, Piece | None]]:
    """Sink poses, best first: centred under a window, else anywhere along the run."""
    if "sink" not in widths:
        return [(0.0, None)]
    w = widths["sink"]
    out: list[tuple[float, Piece]] = []
    for i, leg in enumerate(shape.legs):
        if leg.hi - leg.lo < w:
            continue
        ts = [*(c - w / 2 for c in _window_centres(space, leg)), leg.lo, leg.hi - w,
              *np.arange(leg.lo, leg.hi - w, 0.15)]
        for t0 in ts:
            t0 = min(max(float(t0), leg.lo), leg.hi - w)
            p: Piece = (i, "sink", t0, t0 + w)
            mine = [x[1:] for x in (fridge, p) if x is not None and x[0] == i]
            if not _gaps_ok(leg, mine, landing_m):
                continue
            mid = t0 + w / 2
            off = min((abs(mid - (a + b) / 2) for a, b, _z0, _z1, door in leg.wall.openings if not door), default=None)
            if off is not None and _under_window(leg, mid - 0.05, mid + 0.05):
                score = SINK_WINDOW_SCORE - off  # under the window, centred best
            else:
                score = -0.01 * abs(mid - (leg.t0 + leg.t1) / 2)
            out.append((score, p))
    out.sort(key=lambda x: -x[0])
    return list(out)


def _stove_options(shape: RunShape, widths: dict[str, float], fixed: list[Piece],
                   landing_m: float) -> list[tuple[float, Piece | None]]:
    if "stove" not in widths:
        return [(0.0, None)]
    w = widths["stove"]
    out: list[tuple[float, Piece | None]] = []
    for i, leg in enumerate(shape.legs):
        t0s = np.arange(leg.lo, leg.hi - w + 1e-6, 0.1)
        near = np.zeros(len(t0s), dtype=bool)
        for x in fixed:  # an appliance closer than a landing on either side: _gaps_ok refuses it
            if x[0] == i:
                near |= (x[2] - (t0s + w) < landing_m - 1e-6) & (t0s - x[3] < landing_m - 1e-6)
        for t0 in t0s[~near]:
            p: Piece = (i, "stove", float(t0), float(t0) + w)
            if not _gaps_ok(leg, [x[1:] for x in (*fixed, p) if x[0] == i], landing_m):
                continue
            score = -3.0 if _under_window(leg, p[2], p[3]) else 0.0
            out.append((score, p))
    return out


def _triangle(shape: RunShape, fridge: Piece | None, sink: Piece | None, stove: Piece | None) -> float:
    """Score of the work triangle: legs of designer length, sink and cooktop apart."""
    pts = {}
    for p in (fridge, sink, stove):
        if p is not None:
            leg = shape.legs[p[0]]
            pts[p[1]] = _xy(leg, (p[2] + p[3]) / 2)
    score = 0.0
    for a, b, wgt in (("sink", "stove", 1.0), ("sink", "fridge", 0.5), ("stove", "fridge", 0.5)):
        if a in pts and b in pts:
            d = float(np.linalg.norm(pts[a] - pts[b]))
            lo, hi = WORK_LEG_M
            score += wgt * (1.0 if lo <= d <= hi else -min(abs(d - lo), abs(d - hi)))
    if sink is not None and stove is not None and sink[0] != stove[0]:
        score += 0.3
    return score
