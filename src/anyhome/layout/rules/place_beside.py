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
    front_dir,
    right_dir,
)

BESIDE_GAPS_M = (0.03, 0.08, 0.15, 0.25)
"""Gaps tried between an object and the one it stands beside (first is preferred)."""
GAP_PREF_STEP = 0.15
"""Preference lost per wider gap."""


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


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    return place_beside(ctx.ref, ctx.size, ctx.params.side), "floor"


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
