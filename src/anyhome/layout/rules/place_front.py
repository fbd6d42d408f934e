"""``place_front``: in front of the target (its +y side), facing it (a coffee table
before a sofa, a TV stand across the room from it)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

import numpy as np
from pydantic import Field

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
    wrap,
)
from anyhome.layout.rules.place_center import place_center
from anyhome.layout.rules.place_wall import place_wall
from anyhome.space import RoomSpace, Wall

DISTANCE_FACTORS = (1.0, 0.8, 1.25, 0.6, 1.5, 0.4, 2.0, 0.2, 0.0)
"""Multiples of ``distance_m`` tried, the first preferred."""
LATERAL_SHIFTS_M = (0.0, 0.1, -0.1, 0.2, -0.2, 0.3, -0.3)
"""Sideways shifts tried at each distance, the first preferred..."""
LATERAL_PER_M = 1.0
"""...losing this much preference per metre off centre (more than a member's noise
per 0.1 m: the object stays centred on its target whenever that pose is free)."""
COPY_GAP_M = 0.1
"""Gap between copies standing side by side in front of one target (chairs at a desk)."""
WALL_SNAP_PREF = 0.95
"""Preference of the pose flush with a wall straight ahead (a TV stand)."""
WALL_SNAP_MIN_M = 0.4
"""The wall snap reaches at least 2.5 times this far (a short ``distance_m`` still snaps)."""
MIN_TO_WALL_M = 1.0
"""With ``to_wall``: the nearest the wall ahead may be to the target's front."""
TO_WALL_PREF = 1.5
"""With ``to_wall``: preference of the pose on the wall ahead, centred on the target..."""
TO_WALL_OFF_PER_M = 0.2
"""...less this much per metre off the distance asked..."""
TO_WALL_LATERAL_PER_M = 1.0
"""...and this much per metre off centre (steep: a member's noise keeps it centred)."""
OTHER_WALL_PREF = 0.6
"""With ``to_wall`` and no wall ahead: preference of another wall's pose facing the target
straight (times the cosine of the angle; poses turned away by more than 60 degrees are not offered)."""
TO_WALL_SHIFTS_M = (0.0, 0.15, -0.15, 0.3, -0.3, 0.5, -0.5, 0.8, -0.8, 1.1, -1.1, 1.5, -1.5)
"""Sideways shifts of the pose on the wall ahead."""


CENTRED_TOL_M = 0.09
"""Copies in front of a target whose centroid lies further than this off the target's
axis are off centre (a compromise the group's anchor pose is tried again for)."""


class Params(RuleParams):
    distance_m: float = Field(default=0.4, ge=0.0, le=20.0)
    """Gap between the target's front and the object, in metres."""
    facing: Literal["toward", "same", "away"] = "toward"
    """Face the target, or look the way it looks."""
    to_wall: bool = False
    """Stand against the wall ahead of the target (a TV stand across from a sofa): poses
    flush with that wall, at least ``MIN_TO_WALL_M`` from the target; else against
    another wall, turned toward the target."""


def place_front(space: RoomSpace, target: HouseObject, size: Sequence[float], distance_m: float = 0.4,
                facing: str = "toward", lateral: float = 0.0) -> Cands:
    txy = np.asarray(target.position[:2])
    f, r = front_dir(target.yaw), right_dir(target.yaw)
    yaw = wrap(target.yaw + np.pi) if facing == "toward" else target.yaw
    dists, prefs = [], []
    for k, m in enumerate(DISTANCE_FACTORS):
        dists.append(distance_m * m if distance_m > 0 else 0.1 * k)
        prefs.append(1.0 - 0.08 * k)
    # every distance with every sideways shift, the shifts of one distance together
    dd = np.repeat(np.asarray(dists), len(LATERAL_SHIFTS_M))
    lo = np.tile(np.asarray(LATERAL_SHIFTS_M), len(dists))
    grid = txy[None] + f[None] * (target.size[1] / 2 + dd + size[1] / 2)[:, None] + r[None] * (lateral + lo)[:, None]
    pts: list[np.ndarray] = list(grid)
    yaws: list[float] = [yaw] * len(grid)
    pref: list[float] = (np.repeat(np.asarray(prefs), len(LATERAL_SHIFTS_M)) - LATERAL_PER_M * np.abs(lo)).tolist()
    # snap flush to a wall straight ahead (a TV stand in front of a sofa)
    for wall in space.walls:
        if float(f @ wall.n) > -0.999:
            continue
        rel = txy - wall.a
        dist_wall = float(rel @ wall.n)
        t = float(rel @ wall.u) + lateral * float(r @ wall.u)
        gap = dist_wall - target.size[1] / 2 - size[1]
        if 0 < gap and 0.5 * distance_m <= gap <= 2.5 * max(distance_m, WALL_SNAP_MIN_M) and 0 <= t <= wall.length:
            pts.append(wall.a + wall.u * t + wall.n * (size[1] / 2))
            yaws.append(yaw)
            pref.append(WALL_SNAP_PREF)
    xy = np.asarray(pts)
    return Cands(xy, np.asarray(yaws), np.zeros(len(xy)), np.asarray(pref))


def front_to_wall(space: RoomSpace, target: HouseObject, size: Sequence[float], distance_m: float) -> Cands:
    """Poses against the wall ahead of ``target`` (``to_wall``), else against another wall turned toward it."""
    return front_to_wall_at(space, np.asarray(target.position[:2]), target.yaw, target.size[1], size, distance_m)


def front_to_wall_at(space: RoomSpace, txy: np.ndarray, yaw: float, depth_m: float, size: Sequence[float],
                     distance_m: float) -> Cands:
    """:func:`front_to_wall` of a target at ``txy`` turned ``yaw``, ``depth_m`` deep."""
    pts: list[np.ndarray] = []
    yaws: list[float] = []
    pref: list[float] = []
    for wall, gap, t0 in walls_ahead(space, txy, yaw, depth_m, size, distance_m):
        for lo in TO_WALL_SHIFTS_M:
            t = t0 + lo
            if size[0] / 2 <= t <= wall.length - size[0] / 2:
                pts.append(wall.a + wall.u * t + wall.n * (size[1] / 2))
                yaws.append(wall.yaw)
                pref.append(TO_WALL_PREF - TO_WALL_OFF_PER_M * abs(gap - distance_m) - TO_WALL_LATERAL_PER_M * abs(lo))
    out = Cands(np.asarray(pts).reshape(-1, 2), np.asarray(yaws), np.zeros(len(pts)), np.asarray(pref))
    others = place_wall(space, size)
    if len(others):
        to_t = txy[None] - others.xy
        cos = np.einsum("nc,nc->n", np.stack([-np.sin(others.yaw), np.cos(others.yaw)], 1), to_t)
        cos = cos / np.maximum(np.linalg.norm(to_t, axis=1), 1e-6)
        keep = cos > 0.5
        out = out + Cands(others.xy[keep], others.yaw[keep], others.z[keep], OTHER_WALL_PREF * cos[keep])
    return out


def walls_ahead(space: RoomSpace, txy: np.ndarray, yaw: float, depth_m: float, size: Sequence[float],
                distance_m: float) -> list[tuple[Wall, float, float]]:
    """(wall, gap, t) of each wall straight ahead of a target at ``txy`` turned ``yaw``,
    ``depth_m`` deep, that a ``to_wall`` object ``size`` may stand against: ``gap`` between
    the target's front and the object's front, ``t`` the target's axis along the wall."""
    f = front_dir(yaw)
    out = []
    for wall in space.walls:
        if float(f @ wall.n) > -0.999:
            continue
        rel = txy - wall.a
        gap = float(rel @ wall.n) - depth_m / 2 - size[1]
        if gap < MIN_TO_WALL_M or gap > 2.5 * max(distance_m, WALL_SNAP_MIN_M):
            continue
        out.append((wall, gap, float(rel @ wall.u)))
    return out


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    if ctx.params.to_wall:
        return front_to_wall(ctx.space, ctx.ref, ctx.size, ctx.params.distance_m), "floor"
    return place_front(ctx.space, ctx.ref, ctx.size, ctx.params.distance_m, ctx.params.facing), "floor"


def copy_candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Several copies stand side by side, centred on the target."""
    if ctx.count <= 1 or (isinstance(ctx.params, Params) and ctx.params.to_wall):
        return candidates(ctx)
    assert isinstance(ctx.params, Params) and ctx.ref is not None
    lat = (ctx.copy - (ctx.count - 1) / 2) * (ctx.size[0] + COPY_GAP_M)
    return place_front(ctx.space, ctx.ref, ctx.size, ctx.params.distance_m, ctx.params.facing, lateral=lat), "floor"


def off_centre_m(objs: Sequence[HouseObject], target: HouseObject) -> float:
    """Sideways distance (m) of the centroid of ``objs`` from ``target``'s axis."""
    c = np.mean([np.asarray(o.position[:2]) for o in objs], axis=0)
    return abs(float((c - np.asarray(target.position[:2])) @ right_dir(target.yaw)))


def extent(box: Extent, anchor_size: Sequence[float], size: Sequence[float], params: Any, count: int,
           near_m: float | None) -> Extent:
    x0, x1, y0, y1 = box
    dist = params.distance_m
    if near_m is not None and dist > near_m:
        return box
    y1 = max(y1, anchor_size[1] / 2 + dist + size[1])
    half = max(size[0], count * (size[0] + COPY_GAP_M)) / 2
    return min(x0, -half), max(x1, half), y0, y1


def untargeted(ctx: RuleContext) -> tuple[Cands, Kind]:
    """With nothing to stand in front of: on a wall when ``to_wall`` (a TV stand with no
    sofa), else about the room centre."""
    assert isinstance(ctx.params, Params)
    return (place_wall(ctx.space, ctx.size) if ctx.params.to_wall else place_center(ctx.space, ctx.size)), "floor"


RULE = PlacementRule("place_front", Params, candidates, __doc__ or "", relative=True, needs_target=True,
                     copy_candidates=copy_candidates, extent=extent, untargeted=untargeted,
                     faces_anchor=lambda params: params.facing == "toward")
