"""Scoring and checking candidate poses: rank by preference, spacing, windows and noise;
verify the best with the contract's exact geometry; the room a whole group needs."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import shapely

from anyhome.geometry import boxes_collide, footprint_polygon, inside
from anyhome.house import HouseObject
from anyhome.layout.rules import REGISTRY, Cands
from anyhome.layout.rules.base import Extent
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import GroupSpec
from anyhome.space import rect_corners


def rank(st: RoomState, c: Cands, size: Sequence[float], kind: str, noise: float, spacing: bool,
         layer: bool = False) -> np.ndarray:
    """Indices of the valid candidates, best first (``layer``: a rug, see RoomSpace.valid)."""
    if not len(c):
        return np.zeros(0, dtype=int)
    o = st.options
    corners = rect_corners(c.xy, size[:2], c.yaw)
    mask = st.space.valid(corners, c.z, c.z + size[2], floor=kind == "floor", doors=kind != "top", layer=layer)
    idx = np.nonzero(mask)[0]
    if not idx.size:
        return idx
    score = c.pref[idx] + noise * st.rng.random(idx.size)
    if spacing and kind == "floor":
        score += o.spacing_weight * st.space.clearance(corners[idx], o.spacing_cap_m) / o.spacing_cap_m
    if kind == "floor" and st.zone is not None:
        score += o.zone_bonus * shapely.contains_xy(st.zone, c.xy[idx, 0], c.xy[idx, 1])
    if kind == "floor" and size[2] > o.tall_m:
        score -= o.window_penalty * st.space.window_penalty(corners[idx])
    return idx[np.argsort(-score, kind="stable")]


def verified(st: RoomState, c: Cands, order: np.ndarray, size: Sequence[float], kind: str,
             supporter: HouseObject | None, k: int = 1, min_sep_m: float = 0.0) -> list[Choice]:
    """Up to ``k`` candidates from ``order`` that pass the exact geometry checks."""
    out: list[Choice] = []
    for i in order[: st.options.verify_factor * k]:
        ch = Choice(c.xy[i].copy(), float(c.yaw[i]), float(c.z[i]))
        if min_sep_m and any(
            np.linalg.norm(o.xy - ch.xy) < min_sep_m and abs(math.cos(o.yaw - ch.yaw) - 1) < 1e-6
            for o in out
        ):
            continue
        if exact_ok(st, ch, size, kind, supporter):
            out.append(ch)
            if len(out) >= k:
                break
    return out


def exact_ok(st: RoomState, ch: Choice, size: Sequence[float], kind: str, supporter: HouseObject | None) -> bool:
    """The contract's own checks (anyhome.geometry), as the evaluator runs them."""
    pos = (ch.xy[0], ch.xy[1], ch.z)
    fp = footprint_polygon(pos, size, ch.yaw)
    if not st.space.outline.contains(fp):
        return False
    if supporter is not None:
        sfp = footprint_polygon(supporter.position, supporter.size, supporter.yaw)
        if not inside(sfp, fp):
            return False
    if kind != "top":
        for zone in st.space.zone_polys:
            if fp.intersects(zone) and fp.intersection(zone).area > 1e-6:
                return False
    lo, hi = np.min(fp.exterior.coords, 0), np.max(fp.exterior.coords, 0)
    for p in st.space.near(lo, hi):
        o = p.obj
        if boxes_collide(pos, size, ch.yaw, o.position, o.size, o.yaw):
            return False
    return True


def pick_one(st: RoomState, c: Cands, size: Sequence[float], kind: str, noise: float, spacing: bool = False,
             supporter: HouseObject | None = None) -> Choice | None:
    got = verified(st, c, rank(st, c, size, kind, noise, spacing), size, kind, supporter)
    return got[0] if got else None


def no_fit_reason(st: RoomState, size: Sequence[float], what: str = "") -> str:
    ext = st.space.bmax - st.space.bmin
    if size[2] > st.space.height:
        return f"taller ({size[2]:.2f} m) than the room ({st.space.height:.2f} m)"
    w, d = size[0], size[1]
    if not ((w <= ext[0] and d <= ext[1]) or (w <= ext[1] and d <= ext[0])):
        return f"larger ({size[0]:.2f} x {size[1]:.2f} m) than the room"
    return what or "no free spot that keeps doors and walkways clear"


def group_extent(g: GroupSpec, near_m: float | None = None) -> Extent:
    """Extent (x0, x1, y0, y1) of a group copy in its anchor's frame, each member's rule
    growing it; with ``near_m``, members placed further in front (a TV) are left out."""
    w, d = g.anchor.size_m[0], g.anchor.size_m[1]
    box: Extent = (-w / 2, w / 2, -d / 2, d / 2)
    for m in g.members:
        if m.target not in (None, g.anchor.name):
            continue
        rule = REGISTRY[m.rule]
        box = rule.extent(box, g.anchor.size_m, m.size_m, rule.parse(m.params), m.count, near_m)
    return box


def group_room_bonus(st: RoomState, g: GroupSpec, c: Cands) -> Cands:
    """Prefer anchor poses where the whole group's extent (members included) is free."""
    o = st.options
    x0, x1, y0, y1 = group_extent(g, near_m=o.near_m)
    w, d = g.anchor.size_m[0], g.anchor.size_m[1]
    if x1 - x0 <= w + 1e-6 and y1 - y0 <= d + 1e-6:
        return c
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    cos, sin = np.cos(c.yaw), np.sin(c.yaw)
    xy = c.xy + np.stack([cx * cos - cy * sin, cx * sin + cy * cos], 1)
    corners = rect_corners(xy, (x1 - x0, y1 - y0), c.yaw)
    ok = st.space.valid(corners, 0.0, min(o.group_room_height_m, g.anchor.size_m[2]), floor=True)
    return Cands(c.xy, c.yaw, c.z, c.pref + o.group_room_bonus * ok)
