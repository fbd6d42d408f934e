"""``place_wall``: back against a wall, facing into the room."""

from __future__ import annotations

import weakref
from collections.abc import Callable, Sequence
from typing import Literal

import numpy as np
from pydantic import Field

from anyhome.layout.rules.base import (
    Cands,
    Kind,
    PlacementRule,
    RuleContext,
    RuleParams,
    on_wall,
    prefer_far,
    wall_positions,
)
from anyhome.space import RoomSpace

CENTRED_PREF = 0.2
"""Preference added at the middle of a wall (none at its ends), over a base of 0.5."""
LONGEST_PREF = 0.5
"""Preference added on the longest wall(s) with ``wall: longest``."""
AWAY_FROM_DOOR_PREF = 0.6
"""Preference added per room diagonal of distance from the doors with ``wall: opposite_door``."""


class Params(RuleParams):
    wall: Literal["any", "longest", "opposite_door"] = "any"
    """Which wall: any, the longest, or the one furthest from the doors."""
    far_m: float = Field(default=0.0, ge=0.0, le=50.0)
    """At least this far (metres, footprint to footprint) from the target (the item's
    ``target``, else its group's anchor); 0: no such wish."""


_CACHE: dict[int, tuple[weakref.ref[RoomSpace], dict[tuple[float, float, str], Cands]]] = {}
"""Wall poses by room (its id, while it lives) and (width, depth, which wall): they depend
on the room's outline alone, and every member beside or in front of something asks for
them again (the centre grid of :mod:`.place_center` is kept here too)."""


def room_cache(space: RoomSpace) -> dict[tuple[float, float, str], Cands]:
    """The poses kept for ``space`` while it lives, by (width, depth, what they are)."""
    key = id(space)
    got = _CACHE.get(key)
    if got is None or got[0]() is not space:
        got = (weakref.ref(space, lambda _: _CACHE.pop(key, None)), {})
        _CACHE[key] = got
    return got[1]


def cached_poses(space: RoomSpace, size: Sequence[float], what: str, build: Callable[[], Cands]) -> Cands:
    """``build()``'s poses for a box ``size`` in ``space``, made once per room and kind
    (``what``) and kept as read-only arrays shared between calls (a caller changing a
    preference makes a new array)."""
    key = (float(size[0]), float(size[1]), what)
    per_room = room_cache(space)
    got = per_room.get(key)
    if got is None:
        got = build()
        for a in (got.xy, got.yaw, got.z, got.pref):
            a.flags.writeable = False
        per_room[key] = got
    return Cands(got.xy, got.yaw, got.z, got.pref)


def place_wall(space: RoomSpace, size: Sequence[float], which: str = "any") -> Cands:
    """Every pose with the back of a box ``size`` against a wall of ``space`` (``which``:
    see :class:`Params`); read-only arrays, shared between calls (:func:`cached_poses`)."""
    return cached_poses(space, size, which, lambda: _place_wall(space, size, which))


def _place_wall(space: RoomSpace, size: Sequence[float], which: str) -> Cands:
    w, d = size[0], size[1]
    longest = max((wl.length for wl in space.walls), default=0.0)
    out: list[Cands] = []
    diag = float(np.linalg.norm(space.bmax - space.bmin)) or 1.0
    for wall in space.walls:
        t = wall_positions(wall, w)
        if not t.size:
            continue
        xy = on_wall(wall, t, d)
        centred = 1.0 - np.abs(t - wall.length / 2) / max(wall.length / 2, 1e-6)
        pref = 0.5 + CENTRED_PREF * centred
        if which == "longest":
            pref = pref + (LONGEST_PREF if wall.length >= longest - 0.05 else 0.0)
        elif which == "opposite_door" and len(space.door_points):
            dist = np.min(np.linalg.norm(xy[:, None] - space.door_points[None], axis=-1), 1)
            pref = pref + AWAY_FROM_DOOR_PREF * dist / diag
        out.append(Cands(xy, np.full(len(t), wall.yaw), np.zeros(len(t)), pref))
    return Cands.join(out)


def candidates(ctx: RuleContext) -> tuple[Cands, Kind]:
    assert isinstance(ctx.params, Params)
    return prefer_far(place_wall(ctx.space, ctx.size, ctx.params.wall), ctx.size, ctx.ref, ctx.params.far_m), "floor"


RULE = PlacementRule("place_wall", Params, candidates, __doc__ or "", against_wall=True)
