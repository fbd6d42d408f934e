"""``place_next_wall``: back against a wall, side by side with the group's previous wall
object (a run of kitchen counters, cases "along the walls"); falls back to ``place_wall``."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from anyhome.geometry import footprint_corners, footprint_polygon, joined_to_first
from anyhome.house import HouseObject
from anyhome.layout.rules.base import (
    Cands,
    Kind,
    NoParams,
    PlacementRule,
    RuleContext,
    footprint_gaps,
    front_dir,
    on_wall,
)
from anyhome.layout.rules.place_wall import place_wall
from anyhome.space import RoomSpace

EARLIER_PIECE_PREF = -0.3
"""Preference shift of a pose beside an earlier piece of the run than the last."""
CORNER_REACH_M = 0.3
"""The run turns a corner onto a wall the previous piece stands at most this much further
from than the new piece is deep (the two then touch or nearly so)."""
JOIN_GAP_M = 0.3
"""A piece of a run further than this from every earlier piece jumped (a compromise)."""
NEAR_TARGET_PER_M = 0.5
"""With a target and no run: preference lost per metre between the footprints."""


def place_next_wall(space: RoomSpace, size: Sequence[float], prev: HouseObject | None) -> Cands:
    """Side by side with ``prev`` (a placed wall object) on its wall, or around the corner."""
    if prev is None:
        return Cands.empty()
    w, d = size[0], size[1]
    pw, pd = prev.size[0], prev.size[1]
    pxy = np.asarray(prev.position[:2])
    back = pxy - front_dir(prev.yaw) * pd / 2
    out: list[Cands] = []
    corners = footprint_corners(prev.position, prev.size, prev.yaw)  # made once, for every wall
    for wall in space.walls:
        t_prev = float((back - wall.a) @ wall.u)
        dist = abs(float((back - wall.a) @ wall.n))
        along = abs(abs(float(np.cos(prev.yaw - wall.yaw))) - 1.0) < 1e-3
        if dist < 0.02 and along:
            ts = np.array([t_prev - pw / 2 - w / 2, t_prev + pw / 2 + w / 2])
            ts = np.concatenate([ts, ts + [-0.02, 0.02]])
            pref = np.array([1.0, 1.0, 0.9, 0.9])
            ok = (ts >= w / 2 - 1e-9) & (ts <= wall.length - w / 2 + 1e-9)  # on this wall, not past its end
            out.append(Cands(on_wall(wall, ts[ok], d), np.full(int(ok.sum()), wall.yaw), np.zeros(int(ok.sum())),
                              pref[ok]))
        else:
            # perpendicular wall: continue the run around a corner
            rel = list(corners - wall.a)  # each corner's dot products as a vector's (not a matrix product's)
            dmin = min(float(r @ wall.n) for r in rel)
            if not -0.02 <= dmin <= d + CORNER_REACH_M:  # too far from this wall, or beyond its line
                continue
            along_t = [float(r @ wall.u) for r in rel]
            tmin, tmax = min(along_t), max(along_t)
            ts = np.array([tmax + w / 2, tmin - w / 2])
            ok = (ts >= w / 2 - 1e-9) & (ts <= wall.length - w / 2 + 1e-9)
            ts = ts[ok]
            if ts.size:
                out.append(Cands(on_wall(wall, ts, d), np.full(len(ts), wall.yaw), np.zeros(len(ts)),
                                  np.full(len(ts), 0.8)))
    return Cands.join(out)


def jumps(pieces: Sequence[HouseObject]) -> int:
    """How many of ``pieces`` (a run, first piece first) are not joined to the first
    through pieces each at most :data:`JOIN_GAP_M` from the next: the run jumped before
    them (a piece after a jump counts too, as it stands apart from the run's start)."""
    polys = [footprint_polygon(p.position, p.size, p.yaw) for p in pieces]
    return len(polys) - len(joined_to_first(polys, JOIN_GAP_M))


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    """Relaxed in this order: beside the previous wall object of the run (on its wall,
    then round a corner); beside an earlier piece of the run; any wall pose, the nearer
    the run the better. With no run to continue but a target (a sideboard by a table
    standing free): the wall poses nearest the target first (:data:`NEAR_TARGET_PER_M`)."""
    near = place_next_wall(ctx.space, ctx.size, ctx.prev_wall)
    for piece in ctx.run:
        if piece is not ctx.prev_wall:
            near = near + place_next_wall(ctx.space, ctx.size, piece).shifted_pref(EARLIER_PIECE_PREF)
    fb = place_wall(ctx.space, ctx.size)
    pieces = [p for p in [*ctx.run, ctx.prev_wall] if p is not None]
    if pieces and len(fb):
        d = np.min([np.linalg.norm(fb.xy - np.asarray(p.position[:2])[None], axis=1) for p in pieces], axis=0)
        fb.pref = ctx.options.next_wall_fallback_pref - ctx.options.next_wall_fallback_per_m * d
    elif ctx.ref is not None and len(fb):
        fb.pref = fb.pref - NEAR_TARGET_PER_M * footprint_gaps(fb.xy, ctx.size, fb.yaw, ctx.ref)
    return near + fb, "floor"


RULE = PlacementRule("place_next_wall", NoParams, candidates, __doc__ or "", against_wall=True, continues=True)
