"""``place_corner``: back against a wall and one side against the adjacent wall."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from anyhome.layout.rules.base import Cands, Kind, NoParams, PlacementRule, RuleContext, on_wall
from anyhome.layout.rules.place_wall import place_wall
from anyhome.space import RoomSpace


def _convex(space: RoomSpace, i: int, j: int) -> bool:
    """The corner where wall i ends and wall j starts is convex (seen from inside)."""
    ui, uj = space.walls[i].u, space.walls[j].u
    return float(ui[0] * uj[1] - ui[1] * uj[0]) > 1e-6


def place_corner(space: RoomSpace, size: Sequence[float]) -> Cands:
    w, d = size[0], size[1]
    out: list[Cands] = []
    k = len(space.walls)
    for i, wall in enumerate(space.walls):
        if wall.length < w - 1e-9:
            continue
        ts = []
        if _convex(space, (i - 1) % k, i):
            ts.append(w / 2)
        if _convex(space, i, (i + 1) % k):
            ts.append(wall.length - w / 2)
        if ts:
            t = np.asarray(ts)
            out.append(Cands(on_wall(wall, t, d), np.full(len(t), wall.yaw), np.zeros(len(t)), np.ones(len(t))))
    return Cands.join(out)


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Corners first; any wall pose, less preferred, when no corner is free."""
    walls = place_wall(ctx.space, ctx.size).shifted_pref(ctx.options.corner_wall_pref)
    return place_corner(ctx.space, ctx.size) + walls, "floor"


RULE = PlacementRule("place_corner", NoParams, candidates, __doc__ or "", against_wall=True)
