"""``place_around``: around the target, each copy facing it (chairs around a table)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    HALF_PI,
    Cands,
    Extent,
    Kind,
    PlacementRule,
    RuleContext,
    RuleParams,
    front_dir,
    right_dir,
    wrap,
)

AROUND_GAP_M = 0.05
"""Gap between a table edge and the chairs around it."""
AROUND_SPACING_M = 0.08
"""Gap between neighbouring chairs around a table."""
SEAT_GAPS = ((0.0, 1.0), (0.1, 0.8), (0.2, 0.6))
"""Extra distances (m) a chair may stand out from its slot, with their preferences."""
SEAT_SHIFTS = ((0.0, 0.0), (0.05, -0.05), (-0.05, -0.05))
"""Sideways shifts (m) of a chair from its slot, with their preference changes."""

Side = tuple[str, float, np.ndarray, np.ndarray, float, float, int]


class Params(RuleParams):
    sides: Literal["all", "long", "front"] = "all"
    """Which sides of the target: all four, the two long ones, or its front only."""


def around_slots(target: HouseObject, size: Sequence[float], sides: str = "all") -> list[Side]:
    """The sides of ``target`` chairs can stand at, long sides first.

    Each side is ``(key, length, outward normal, along, chair yaw, target extent across,
    capacity)``; :func:`around_allocation` picks how many chairs each side gets and
    :func:`around_positions` spaces them evenly.
    """
    tw, td = target.size[0], target.size[1]
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    cw = size[0]
    spec = {
        "+y": (tw, f, r, target.yaw + np.pi, td),
        "-y": (tw, -f, r, target.yaw, td),
        "+x": (td, r, f, target.yaw + HALF_PI, tw),
        "-x": (td, -r, f, target.yaw - HALF_PI, tw),
    }
    order = ["+y", "-y", "+x", "-x"] if tw >= td else ["+x", "-x", "+y", "-y"]
    if sides == "long":
        order = order[:2]
    elif sides == "front":
        order = ["+y"]
    out = []
    for key in order:
        length, normal, along, yaw, across = spec[key]
        cap = max(1, int(np.floor((length + AROUND_SPACING_M) / (cw + AROUND_SPACING_M))))
        out.append((key, length, normal, along, wrap(yaw), across, cap))
    return out


def around_positions(target: HouseObject, size: Sequence[float], side: Side, k: int,
                     gap: float = AROUND_GAP_M) -> list[tuple[np.ndarray, float]]:
    _, length, normal, along, yaw, across, _ = side
    txy = np.asarray(target.position[:2])
    s = -length / 2 + length * (np.arange(k) + 0.5) / k
    base = txy + normal * (across / 2 + gap + size[1] / 2)
    return [(base + along * si, yaw) for si in s]


def around_allocation(sides: Sequence[Side], count: int) -> list[int]:
    """How many chairs each side gets: long sides alternately to capacity, then the ends."""
    alloc = [0] * len(sides)
    caps = [s[-1] for s in sides]
    groups = [[0, 1], [2, 3]]
    left = count
    for grp in groups:
        grp = [g for g in grp if g < len(sides)]
        while left > 0 and any(alloc[g] < caps[g] for g in grp):
            for g in grp:
                if left > 0 and alloc[g] < caps[g]:
                    alloc[g] += 1
                    left -= 1
    return alloc


def seat_candidates(slots: Sequence[tuple[np.ndarray, float]]) -> Cands:
    """Poses for one chair at any of ``slots``: the slot itself, a little out or aside."""
    xy, yaw, pref = [], [], []
    for pos, y in slots:
        f = -front_dir(y)  # outward from the table
        for gap, p in SEAT_GAPS:
            for lat, q in SEAT_SHIFTS:
                xy.append(pos + f * gap + right_dir(y) * lat)
                yaw.append(y)
                pref.append(p + q)
    return Cands(np.asarray(xy), np.asarray(yaw), np.zeros(len(xy)), np.asarray(pref))


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Every slot of every side at capacity (one object placed around a target)."""
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    pts: list[np.ndarray] = []
    yaw: list[float] = []
    for s in around_slots(ctx.ref, ctx.size, ctx.params.sides):
        for pos, y in around_positions(ctx.ref, ctx.size, s, s[-1]):
            pts.append(pos)
            yaw.append(y)
    xy = np.asarray(pts).reshape(-1, 2)
    return Cands(xy, np.asarray(yaw), np.zeros(len(xy)), np.ones(len(xy))), "floor"


def extent(box: Extent, anchor_size: Sequence[float], size: Sequence[float], params: Any, count: int,
           near_m: float | None) -> Extent:
    x0, x1, y0, y1 = box
    w, d = anchor_size[0], anchor_size[1]
    ext = AROUND_GAP_M + size[1]
    y1 = max(y1, d / 2 + ext)
    if params.sides != "front":
        y0 = min(y0, -d / 2 - ext)
    if params.sides == "all":
        x0, x1 = min(x0, -w / 2 - ext), max(x1, w / 2 + ext)
    return x0, x1, y0, y1


RULE = PlacementRule("place_around", Params, candidates, __doc__ or "", relative=True, needs_target=True,
                     placement="around", extent=extent)
