"""``place_top``: on the target's top surface (z = its top; ``support`` = its id),
shrunk to fit when the top is smaller."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    HALF_PI,
    Cands,
    Kind,
    NoParams,
    PlacementRule,
    RuleContext,
    front_dir,
    right_dir,
    wrap,
)

TOP_MARGIN_M = 0.015
"""Margin kept between an on-top object and the edge of its supporter's top."""
MIN_SCALE = 0.5
"""An object is shrunk to fit a top at most to this fraction of its size."""
TOP_GRID_M = 0.05
"""Spacing of the candidate positions on a top."""


def fit_on_top(target: HouseObject, size: Sequence[float]) -> tuple[tuple[float, float, float], bool] | None:
    """Size (possibly shrunk) of an object on ``target``'s top and whether it is turned 90°."""
    tw = target.size[0] - 2 * TOP_MARGIN_M
    td = target.size[1] - 2 * TOP_MARGIN_M
    if tw <= 0.02 or td <= 0.02:
        return None
    best: tuple[float, bool] | None = None
    for turned in (False, True):
        w, d = (size[1], size[0]) if turned else (size[0], size[1])
        s = min(1.0, tw / w, td / d)
        if best is None or s > best[0] + 1e-9:
            best = (s, turned)
    assert best is not None  # the loop ran
    s, turned = best
    if s < MIN_SCALE:
        return None
    return (size[0] * s, size[1] * s, size[2] * s), turned


def place_top(target: HouseObject, size: Sequence[float], turned: bool, rng: np.random.Generator) -> Cands:
    txy = np.asarray(target.position[:2])
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    w, d = (size[1], size[0]) if turned else (size[0], size[1])
    fx = max(0.0, (target.size[0] - 2 * TOP_MARGIN_M - w) / 2)
    fy = max(0.0, (target.size[1] - 2 * TOP_MARGIN_M - d) / 2)
    u = np.linspace(-fx, fx, max(1, int(2 * fx / TOP_GRID_M) + 1))
    v = np.linspace(-fy, fy, max(1, int(2 * fy / TOP_GRID_M) + 1))
    grid_u, grid_v = np.meshgrid(u, v)
    gu, gv = grid_u.ravel(), grid_v.ravel()
    xy = txy[None] + gu[:, None] * r[None] + gv[:, None] * f[None]
    yaw = wrap(target.yaw + (HALF_PI if turned else 0.0))
    z = target.position[2] + target.size[2]
    pref = 0.5 + 0.3 * rng.random(len(xy))
    return Cands(xy, np.full(len(xy), yaw), np.full(len(xy), z), pref)


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Poses on the target's top for the object as it fits there (see :func:`fit_on_top`:
    the layout places the shrunk size it returns)."""
    assert ctx.ref is not None and ctx.rng is not None
    fit = fit_on_top(ctx.ref, ctx.size)
    if fit is None:
        return Cands.empty(), "top"
    size, turned = fit
    return place_top(ctx.ref, size, turned, ctx.rng), "top"


RULE = PlacementRule("place_top", NoParams, candidates, __doc__ or "", relative=True, needs_target=True,
                     kind="top", placement="top")
