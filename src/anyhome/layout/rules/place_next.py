"""``place_next``: side by side with (same facing as) the previous copy of the item or,
for the first one, like ``place_center``."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    Cands,
    Kind,
    NoParams,
    PlacementRule,
    RuleContext,
    front_dir,
    right_dir,
)
from anyhome.layout.rules.place_center import place_center
from anyhome.space import RoomSpace

NEXT_GAPS_M = ((0.05, 1.0), (0.15, 0.9), (0.3, 0.8))
"""Gaps tried beside the previous copy, with their preferences."""


def place_next(space: RoomSpace, size: Sequence[float], prev: HouseObject | None) -> Cands:
    """Side by side with the previous copy ``prev``, same facing."""
    if prev is None:
        return place_center(space, size)
    w = size[0]
    pxy = np.asarray(prev.position[:2])
    r = right_dir(prev.yaw)
    f = front_dir(prev.yaw)
    back_shift = (size[1] - prev.size[1]) / 2
    out = []
    pref = []
    for gap, p in NEXT_GAPS_M:
        for sgn in (1.0, -1.0):
            out.append(pxy + sgn * r * (prev.size[0] / 2 + w / 2 + gap) + f * back_shift)
            pref.append(p)
    xy = np.asarray(out)
    near = Cands(xy, np.full(len(xy), prev.yaw), np.zeros(len(xy)), np.asarray(pref))
    fallback = place_center(space, size)
    dist = np.linalg.norm(fallback.xy - pxy[None], axis=1)
    fallback.pref = 0.5 - 0.1 * dist
    return near + fallback


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    return place_next(ctx.space, ctx.size, ctx.prev_same), "floor"


RULE = PlacementRule("place_next", NoParams, candidates, __doc__ or "", continues=True)
