"""``place_on_wall``: hung on the wall behind the target, above it; with no target, on
any free wall."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from pydantic import Field

from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    Cands,
    Kind,
    PlacementRule,
    RuleContext,
    RuleParams,
    front_dir,
    on_wall,
    right_dir,
    wall_positions,
)
from anyhome.space import RoomSpace

BEHIND_TARGET_M = 0.15
"""A target whose back is this close to a wall stands against it."""
BEHIND_PREF = 1.0
"""Preference added right behind the target, less :data:`BEHIND_PER_M` per metre away along the wall."""
BEHIND_PER_M = 1.0
"""Steep enough that a member's noise moves a centred item (a painting over a bed) by
no more than a few centimetres."""


class Params(RuleParams):
    elevation_m: float = Field(default=1.4, ge=0.0, le=12.0)
    """Bottom of the object above the floor, in metres; above a target, at least its top
    plus a gap unless given."""


CENTRED_TOL_M = 0.05
"""A wall item within this of the middle of its target's back is centred behind it."""


def centred_behind(obj: HouseObject, target: HouseObject) -> bool:
    """Whether wall item ``obj`` hangs centred behind ``target`` when it hangs on the
    wall behind it (True when it hangs on another wall: nothing to centre on there)."""
    tb = np.asarray(target.position[:2]) - front_dir(target.yaw) * target.size[1] / 2
    ob = np.asarray(obj.position[:2]) - front_dir(obj.yaw) * obj.size[1] / 2
    rel = ob - tb
    if abs(float(np.cos(obj.yaw - target.yaw)) - 1.0) > 1e-6 or abs(float(rel @ front_dir(target.yaw))) > BEHIND_TARGET_M:
        return True
    return abs(float(rel @ right_dir(target.yaw))) <= CENTRED_TOL_M


def wall_z(params: Params, size: Sequence[float], ref: HouseObject | None, height: float,
           gap_m: float, ceiling_gap_m: float) -> float | None:
    """Bottom height of a wall item, kept under the ceiling; None: it does not fit."""
    z = params.elevation_m
    if ref is not None and "elevation_m" not in params.model_fields_set:
        z = max(z, ref.position[2] + ref.size[2] + gap_m)
    top = height - ceiling_gap_m - 1e-6
    if z + size[2] > top:
        z = top - size[2]
    return z if z >= 0 else None


def place_on_wall(space: RoomSpace, size: Sequence[float], z: float, target: HouseObject | None = None) -> Cands:
    """Back on a wall at height ``z``; behind ``target`` when it stands against a wall."""
    w, d, h = size
    out: list[Cands] = []
    tb = None
    if target is not None:
        tb = np.asarray(target.position[:2]) - front_dir(target.yaw) * target.size[1] / 2
    for wall in space.walls:
        t = wall_positions(wall, w)
        if not t.size:
            continue
        if tb is not None:  # the pose centred behind the target, off the grid
            tt = float((tb - wall.a) @ wall.u)
            if abs(float((tb - wall.a) @ wall.n)) < BEHIND_TARGET_M and w / 2 <= tt <= wall.length - w / 2:
                t = np.append(t, tt)
        t = t[space.wall_clear(wall, t - w / 2, t + w / 2, z, z + h)]
        if not t.size:
            continue
        xy = on_wall(wall, t, d)
        pref = 0.5 + 0.2 * (1.0 - np.abs(t - wall.length / 2) / max(wall.length / 2, 1e-6))
        if tb is not None:
            dist = abs(float((tb - wall.a) @ wall.n))
            tt = float((tb - wall.a) @ wall.u)
            if dist < BEHIND_TARGET_M:
                pref = pref + BEHIND_PREF - BEHIND_PER_M * np.abs(t - tt)
        out.append(Cands(xy, np.full(len(t), wall.yaw), np.full(len(t), z), pref))
    return Cands.join(out)


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    assert isinstance(ctx.params, Params)
    z = wall_z(ctx.params, ctx.size, ctx.ref, ctx.space.height, ctx.options.wall_item_gap_m,
               ctx.options.ceiling_gap_m)
    if z is None:
        return Cands.empty(), "wall"
    return place_on_wall(ctx.space, ctx.size, z, ctx.ref), "wall"


RULE = PlacementRule("place_on_wall", Params, candidates, __doc__ or "", relative=True, against_wall=True,
                     kind="wall")
