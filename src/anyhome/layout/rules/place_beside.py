"""``place_beside``: left and/or right of the target, backs aligned, same facing."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    Cands,
    Extent,
    Kind,
    PlacementRule,
    RuleContext,
    RuleParams,
    footprint_gaps,
    front_dir,
    right_dir,
)
from anyhome.layout.rules.place_wall import place_wall
from anyhome.space import RoomSpace

BESIDE_GAPS_M = (0.03, 0.08, 0.15, 0.25)
"""Gaps tried between an object and the one it stands beside (first is preferred)."""
GAP_PREF_STEP = 0.15
"""Preference lost per wider gap."""
RELAXED_NEAR_M = 1.5
"""Last relaxation, when neither side of the target is free: against a wall, with at
most this gap to the target..."""
RELAXED_PREF = -1.0
"""...at this preference, less :data:`RELAXED_PER_M` per metre of gap."""
RELAXED_PER_M = 0.3
PAIR_TOL_M = 0.05
"""Side gaps of a symmetric pair (two copies on ``both`` sides) differ by at most this."""


class Params(RuleParams):
    side: Literal["left", "right", "both"] = "both"
    """Which side of the target; ``both``: either, and copies alternate sides."""


def place_beside(target: HouseObject, size: Sequence[float], side: str = "both") -> Cands:
    txy = np.asarray(target.position[:2])
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    back_shift = (size[1] - target.size[1]) / 2
    pts: list[np.ndarray] = []
    pref: list[float] = []
    sides = {"left": (-1.0,), "right": (1.0,)}.get(side, (-1.0, 1.0))
    for k, gap in enumerate(BESIDE_GAPS_M):
        for sgn in sides:
            pts.append(txy + sgn * r * (target.size[0] / 2 + size[0] / 2 + gap) + f * back_shift)
            pref.append(1.0 - GAP_PREF_STEP * k)
    xy = np.asarray(pts)
    return Cands(xy, np.full(len(xy), target.yaw), np.full(len(xy), target.position[2]), np.asarray(pref))


def stands_beside(obj: HouseObject, target: HouseObject) -> bool:
    """Whether ``obj`` stands where :func:`place_beside` puts it (a side of ``target``,
    one of the gaps, backs aligned, same facing), not where a relaxation did."""
    rel = np.asarray(obj.position[:2]) - np.asarray(target.position[:2])
    lat = abs(float(rel @ right_dir(target.yaw)))
    fwd = float(rel @ front_dir(target.yaw))
    side_gap = lat - (target.size[0] + obj.size[0]) / 2
    return (abs(float(np.cos(obj.yaw - target.yaw)) - 1.0) < 1e-6 and -0.01 <= side_gap <= BESIDE_GAPS_M[-1] + 0.01
            and abs(fwd - (obj.size[1] - target.size[1]) / 2) < 0.01)


def side_of(obj: HouseObject, target: HouseObject) -> str:
    """Which side of ``target`` the centre of ``obj`` lies on: ``left`` or ``right``."""
    rel = np.asarray(obj.position[:2]) - np.asarray(target.position[:2])
    return "right" if float(rel @ right_dir(target.yaw)) >= 0 else "left"


def pair_matches(a: HouseObject, b: HouseObject, target: HouseObject) -> bool:
    """Whether ``a`` and ``b`` stand beside ``target`` as a symmetric pair: one each side,
    each where :func:`place_beside` puts it, their side gaps within :data:`PAIR_TOL_M`."""
    if not (stands_beside(a, target) and stands_beside(b, target)) or side_of(a, target) == side_of(b, target):
        return False
    return abs(_side_gap(a, target) - _side_gap(b, target)) <= PAIR_TOL_M


def _side_gap(obj: HouseObject, target: HouseObject) -> float:
    rel = np.asarray(obj.position[:2]) - np.asarray(target.position[:2])
    return abs(float(rel @ right_dir(target.yaw))) - (target.size[0] + obj.size[0]) / 2


def near_on_walls(space: RoomSpace, target: HouseObject, size: Sequence[float]) -> Cands:
    """Wall poses within :data:`RELAXED_NEAR_M` of ``target``, the nearest preferred."""
    c = place_wall(space, size)
    if not len(c) or target.support != "floor":
        return Cands.empty()
    gaps = footprint_gaps(c.xy, size, c.yaw, target)
    keep = gaps <= RELAXED_NEAR_M
    return Cands(c.xy[keep], c.yaw[keep], c.z[keep], RELAXED_PREF - RELAXED_PER_M * gaps[keep])


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Relaxed in this order: the side asked for, at growing gaps; the other side
    (copies, see :func:`copy_candidates`); against a wall near the target
    (:func:`near_on_walls`)."""
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    return place_beside(ctx.ref, ctx.size, ctx.params.side) + near_on_walls(ctx.space, ctx.ref, ctx.size), "floor"


def copy_candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """The side asked for, then the other side, less preferred."""
    c, kind = candidates(ctx)
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    if ctx.params.side in ("left", "right"):
        other = place_beside(ctx.ref, ctx.size, "right" if ctx.params.side == "left" else "left")
        c = c + other.shifted_pref(ctx.options.other_side_pref)
    return c, kind


def copy_params(params: dict[str, Any], copy: int, count: int) -> dict[str, Any]:
    """Copies of an item on ``both`` sides alternate left and right."""
    params = dict(params)
    if params.get("side", "both") == "both":
        params["side"] = ("left", "right")[copy % 2] if count > 1 else "both"
    return params


def extent(box: Extent, anchor_size: Sequence[float], size: Sequence[float], params: Any, count: int,
           near_m: float | None) -> Extent:
    x0, x1, y0, y1 = box
    w = anchor_size[0]
    ext = size[0] + BESIDE_GAPS_M[0]
    if params.side in ("both", "left"):
        x0 = min(x0, -w / 2 - ext)
    if params.side in ("both", "right"):
        x1 = max(x1, w / 2 + ext)
    return x0, x1, y0, y1


RULE = PlacementRule("place_beside", Params, candidates, __doc__ or "", relative=True, needs_target=True,
                     copy_candidates=copy_candidates, copy_params=copy_params, extent=extent)
