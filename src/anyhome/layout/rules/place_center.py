"""``place_center``: in the middle region of the room, clear of the walls."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

import numpy as np
from pydantic import Field

from anyhome.layout.rules.base import (
    GRID_STEP_M,
    HALF_PI,
    Cands,
    Kind,
    PlacementRule,
    RuleContext,
    RuleParams,
    prefer_far,
    yaw_facing,
)
from anyhome.layout.rules.place_wall import cached_poses
from anyhome.space import RoomSpace

MAX_CENTER_CANDIDATES = 1200
"""The centre grid is coarsened so it holds at most about this many positions."""
ALIGNED_PREF = 0.15
"""Preference added to poses whose long side runs along the room's long side."""


class Params(RuleParams):
    facing: Literal["door", "wall", "any"] = "any"
    """Face the nearest door, the nearest wall, or any of the four axis directions."""
    far_m: float = Field(default=0.0, ge=0.0, le=50.0)
    """At least this far (metres, footprint to footprint) from the target (the item's
    ``target``, else its group's anchor); 0: no such wish."""


def place_center(space: RoomSpace, size: Sequence[float], facing: str = "any") -> Cands:
    """Poses on a grid over the room's bounding box (about :data:`MAX_CENTER_CANDIDATES`
    positions), the nearer its centre the better; read-only arrays, shared between calls
    (as :func:`~.place_wall.place_wall`'s: they depend on the room and the size alone)."""
    return cached_poses(space, size, f"center-{facing}", lambda: _place_center(space, size, facing))


def _place_center(space: RoomSpace, size: Sequence[float], facing: str) -> Cands:
    w, d = size[0], size[1]
    lo, hi = space.bmin, space.bmax
    step = max(GRID_STEP_M, float(np.sqrt(space.area / MAX_CENTER_CANDIDATES)))
    xs = np.arange(lo[0] + step / 2, hi[0], step)
    ys = np.arange(lo[1] + step / 2, hi[1], step)
    # always include the exact centre
    gx, gy = np.meshgrid(np.append(xs, space.centre[0]), np.append(ys, space.centre[1]))
    xy = np.stack([gx.ravel(), gy.ravel()], 1)
    diag = float(np.linalg.norm(hi - lo)) or 1.0
    dist = np.linalg.norm(xy - space.centre[None], axis=1)
    base = 1.0 - dist / diag
    extent = hi - lo
    long_x = extent[0] >= extent[1]
    out: list[Cands] = []
    if facing == "door" and len(space.door_points):
        nearest = space.door_points[np.argmin(np.linalg.norm(xy[:, None] - space.door_points[None], axis=-1), 1)]
        v = nearest - xy
        ang = np.arctan2(-v[:, 0], v[:, 1])
        yaws = np.round(ang / HALF_PI) * HALF_PI
        return Cands(xy, yaws, np.zeros(len(xy)), base)
    if facing == "wall" and space.walls:
        # face the nearest wall: front along -n of the closest wall
        best = np.full(len(xy), np.inf)
        yaws = np.zeros(len(xy))
        for wall in space.walls:
            rel = xy - wall.a[None]
            t = rel @ wall.u
            dd = rel @ wall.n
            inside = (t >= 0) & (t <= wall.length) & (dd > 0)
            closer = inside & (dd < best)
            best[closer] = dd[closer]
            yaws[closer] = yaw_facing(-wall.n)
        return Cands(xy, yaws, np.zeros(len(xy)), base)
    for yaw in (0.0, HALF_PI, np.pi, -HALF_PI):
        along_x = abs(np.cos(yaw)) > 0.5  # local width runs along world x
        aligned = (w >= d) == (along_x == long_x) or abs(w - d) < 0.05
        out.append(Cands(xy, np.full(len(xy), yaw), np.zeros(len(xy)), base + (ALIGNED_PREF if aligned else 0.0)))
    return Cands.join(out)


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    assert isinstance(ctx.params, Params)
    c = place_center(ctx.space, ctx.size, ctx.params.facing)
    return prefer_far(c, ctx.size, ctx.ref, ctx.params.far_m), "floor"


RULE = PlacementRule("place_center", Params, candidates, __doc__ or "")
