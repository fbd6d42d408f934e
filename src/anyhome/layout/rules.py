"""The ten placement rules as candidate-pose generators.

Each function returns :class:`Cands`, every pose the rule allows (on a ~0.1 m grid)
with a preference in [0, 1] (higher is better). Validity is not checked here; the
solver filters with :meth:`RoomSpace.valid` and picks among what is left.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from anyhome.space import RoomSpace, Wall

GRID_STEP_M = 0.1
"""Spacing of candidate positions along walls and over the room."""
MAX_CENTER_CANDIDATES = 1200
"""The centre grid is coarsened so it holds at most about this many positions."""
BESIDE_GAPS_M = (0.03, 0.08, 0.15, 0.25)
"""Gaps tried between an object and the one it stands beside (first is preferred)."""
AROUND_GAP_M = 0.05
"""Gap between a table edge and the chairs around it."""
AROUND_SPACING_M = 0.08
"""Gap between neighbouring chairs around a table."""
TOP_MARGIN_M = 0.015
"""Margin kept between an on-top object and the edge of its supporter's top."""
WALL_ITEM_ELEVATION_M = 1.4
"""Default bottom height of wall-mounted objects."""
HALF_PI = np.pi / 2


@dataclass
class Cands:
    """Candidate poses: centre of the bottom face (x, y), yaw, z and preference."""

    xy: np.ndarray
    yaw: np.ndarray
    z: np.ndarray
    pref: np.ndarray

    @staticmethod
    def empty() -> Cands:
        return Cands(np.zeros((0, 2)), np.zeros(0), np.zeros(0), np.zeros(0))

    def __len__(self) -> int:
        return len(self.xy)

    def __add__(self, other: Cands) -> Cands:
        return Cands(
            np.concatenate([self.xy, other.xy]),
            np.concatenate([self.yaw, other.yaw]),
            np.concatenate([self.z, other.z]),
            np.concatenate([self.pref, other.pref]),
        )

    def shifted_pref(self, delta: float) -> Cands:
        return Cands(self.xy, self.yaw, self.z, self.pref + delta)


def front_dir(yaw: float) -> np.ndarray:
    return np.array([-np.sin(yaw), np.cos(yaw)])


def right_dir(yaw: float) -> np.ndarray:
    return np.array([np.cos(yaw), np.sin(yaw)])


def yaw_facing(direction: np.ndarray) -> float:
    """Yaw whose front (+y local) points along ``direction``."""
    return float(np.arctan2(-direction[0], direction[1]))


def wrap(yaw: float) -> float:
    return float((yaw + np.pi) % (2 * np.pi) - np.pi)


def _wall_positions(wall: Wall, width: float, step: float = GRID_STEP_M) -> np.ndarray:
    if wall.length < width - 1e-9:
        return np.zeros(0)
    lo, hi = width / 2, wall.length - width / 2
    t = np.arange(lo, hi + 1e-9, step)
    if hi - t[-1] > 1e-6:
        t = np.append(t, hi)
    return t


def _on_wall(wall: Wall, t: np.ndarray, depth: float) -> np.ndarray:
    return wall.a[None] + wall.u[None] * t[:, None] + wall.n[None] * (depth / 2)


# ------------------------------------------------------------------ absolute
def place_wall(space: RoomSpace, size, which: str = "any") -> Cands:
    w, d = size[0], size[1]
    longest = max((wl.length for wl in space.walls), default=0.0)
    out = Cands.empty()
    diag = float(np.linalg.norm(space.bmax - space.bmin)) or 1.0
    for wall in space.walls:
        t = _wall_positions(wall, w)
        if not t.size:
            continue
        xy = _on_wall(wall, t, d)
        centred = 1.0 - np.abs(t - wall.length / 2) / max(wall.length / 2, 1e-6)
        pref = 0.5 + 0.2 * centred
        if which == "longest":
            pref = pref + (0.5 if wall.length >= longest - 0.05 else 0.0)
        elif which == "opposite_door" and len(space.door_points):
            dist = np.min(np.linalg.norm(xy[:, None] - space.door_points[None], axis=-1), 1)
            pref = pref + 0.6 * dist / diag
        out = out + Cands(xy, np.full(len(t), wall.yaw), np.zeros(len(t)), pref)
    return out


def _convex(space: RoomSpace, i: int, j: int) -> bool:
    """The corner where wall i ends and wall j starts is convex (seen from inside)."""
    ui, uj = space.walls[i].u, space.walls[j].u
    return float(ui[0] * uj[1] - ui[1] * uj[0]) > 1e-6


def place_corner(space: RoomSpace, size) -> Cands:
    w, d = size[0], size[1]
    out = Cands.empty()
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
            out = out + Cands(_on_wall(wall, t, d), np.full(len(t), wall.yaw), np.zeros(len(t)), np.ones(len(t)))
    return out


def place_next_wall(space: RoomSpace, size, prev) -> Cands:
    """Side by side with ``prev`` (a placed wall object) on its wall, or around the corner."""
    if prev is None:
        return Cands.empty()
    w, d = size[0], size[1]
    pw, pd = prev.size[0], prev.size[1]
    pxy = np.asarray(prev.position[:2])
    back = pxy - front_dir(prev.yaw) * pd / 2
    out = Cands.empty()
    for wall in space.walls:
        t_prev = float((back - wall.a) @ wall.u)
        dist = abs(float((back - wall.a) @ wall.n))
        along = abs(abs(float(np.cos(prev.yaw - wall.yaw))) - 1.0) < 1e-3
        if dist < 0.02 and along:
            ts = np.array([t_prev - pw / 2 - w / 2, t_prev + pw / 2 + w / 2])
            ts = np.concatenate([ts, ts + [-0.02, 0.02]])
            pref = np.array([1.0, 1.0, 0.9, 0.9])
            out = out + Cands(_on_wall(wall, ts, d), np.full(4, wall.yaw), np.zeros(4), pref)
        else:
            # perpendicular wall: continue the run around a corner
            corners = prev_corners(prev)
            tmin = min(float((c - wall.a) @ wall.u) for c in corners)
            tmax = max(float((c - wall.a) @ wall.u) for c in corners)
            dmin = min(float((c - wall.a) @ wall.n) for c in corners)
            if dmin > 0.02:
                continue
            ts = np.array([tmax + w / 2, tmin - w / 2])
            ok = (ts >= w / 2 - 1e-9) & (ts <= wall.length - w / 2 + 1e-9)
            ts = ts[ok]
            if ts.size:
                out = out + Cands(_on_wall(wall, ts, d), np.full(len(ts), wall.yaw), np.zeros(len(ts)), np.full(len(ts), 0.8))
    return out


def prev_corners(obj) -> np.ndarray:
    from anyhome.geometry import footprint_corners

    return footprint_corners(obj.position, obj.size, obj.yaw)


def place_center(space: RoomSpace, size, facing: str = "any") -> Cands:
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
    out = Cands.empty()
    if facing == "door" and len(space.door_points):
        yaws = None
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
        out = out + Cands(xy, np.full(len(xy), yaw), np.zeros(len(xy)), base + (0.15 if aligned else 0.0))
    return out


def place_next(space: RoomSpace, size, prev) -> Cands:
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
    for gap, p in ((0.05, 1.0), (0.15, 0.9), (0.3, 0.8)):
        for sgn in (1.0, -1.0):
            out.append(pxy + sgn * r * (prev.size[0] / 2 + w / 2 + gap) + f * back_shift)
            pref.append(p)
    xy = np.asarray(out)
    near = Cands(xy, np.full(len(xy), prev.yaw), np.zeros(len(xy)), np.asarray(pref))
    fallback = place_center(space, size)
    dist = np.linalg.norm(fallback.xy - pxy[None], axis=1)
    fallback.pref = 0.5 - 0.1 * dist
    return near + fallback


# ------------------------------------------------------------------ relative
def place_beside(target, size, side: str = "both") -> Cands:
    txy = np.asarray(target.position[:2])
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    back_shift = (size[1] - target.size[1]) / 2
    pts: list[np.ndarray] = []
    pref: list[float] = []
    sides = {"left": (-1.0,), "right": (1.0,)}.get(side, (-1.0, 1.0))
    for k, gap in enumerate(BESIDE_GAPS_M):
        for sgn in sides:
            pts.append(txy + sgn * r * (target.size[0] / 2 + size[0] / 2 + gap) + f * back_shift)
            pref.append(1.0 - 0.15 * k)
    xy = np.asarray(pts)
    return Cands(xy, np.full(len(xy), target.yaw), np.full(len(xy), target.position[2]), np.asarray(pref))


def around_slots(target, size, sides: str = "all") -> list[tuple]:
    """The sides of ``target`` chairs can stand at, long sides first.

    Each side is ``(key, length, outward normal, along, chair yaw, target extent across,
    capacity)``; :func:`around_allocation` picks how many chairs each side gets and
    :func:`around_positions` spaces them evenly.
    """
    tw, td = target.size[0], target.size[1]
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    cw = size[0]
    spec = {
        "+y": (tw, f, r, target.yaw + np.pi, td),
        "-y": (tw, -f, r, target.yaw, td),
        "+x": (td, r, f, target.yaw + HALF_PI, tw),
        "-x": (td, -r, f, target.yaw - HALF_PI, tw),
    }
    order = ["+y", "-y", "+x", "-x"] if tw >= td else ["+x", "-x", "+y", "-y"]
    if sides == "long":
        order = order[:2]
    elif sides == "front":
        order = ["+y"]
    out = []
    for key in order:
        length, normal, along, yaw, across = spec[key]
        cap = max(1, int(np.floor((length + AROUND_SPACING_M) / (cw + AROUND_SPACING_M))))
        out.append((key, length, normal, along, wrap(yaw), across, cap))
    return out


def around_positions(target, size, side, k: int, gap: float = AROUND_GAP_M) -> list[tuple[np.ndarray, float]]:
    _, length, normal, along, yaw, across, _ = side
    txy = np.asarray(target.position[:2])
    s = -length / 2 + length * (np.arange(k) + 0.5) / k
    base = txy + normal * (across / 2 + gap + size[1] / 2)
    return [(base + along * si, yaw) for si in s]


def around_allocation(sides, count: int) -> list[int]:
    """How many chairs each side gets: long sides alternately to capacity, then the ends."""
    alloc = [0] * len(sides)
    caps = [s[-1] for s in sides]
    groups = [[0, 1], [2, 3]]
    left = count
    for grp in groups:
        grp = [g for g in grp if g < len(sides)]
        while left > 0 and any(alloc[g] < caps[g] for g in grp):
            for g in grp:
                if left > 0 and alloc[g] < caps[g]:
                    alloc[g] += 1
                    left -= 1
    return alloc


def place_front(space: RoomSpace, target, size, distance_m: float = 0.4, facing: str = "toward", lateral: float = 0.0) -> Cands:
    txy = np.asarray(target.position[:2])
    f, r = front_dir(target.yaw), right_dir(target.yaw)
    yaw = wrap(target.yaw + np.pi) if facing == "toward" else target.yaw
    dists, prefs = [], []
    for k, m in enumerate((1.0, 0.8, 1.25, 0.6, 1.5, 0.4, 2.0, 0.2, 0.0)):
        dists.append(distance_m * m if distance_m > 0 else 0.1 * k)
        prefs.append(1.0 - 0.08 * k)
    pts: list[np.ndarray] = []
    yaws: list[float] = []
    pref: list[float] = []
    for dd, p in zip(dists, prefs):
        for lk, lo in enumerate((0.0, 0.1, -0.1, 0.2, -0.2, 0.3, -0.3)):
            pts.append(txy + f * (target.size[1] / 2 + dd + size[1] / 2) + r * (lateral + lo))
            yaws.append(yaw)
            pref.append(p - 0.05 * lk)
    # snap flush to a wall straight ahead (a TV stand in front of a sofa)
    for wall in space.walls:
        if float(f @ wall.n) > -0.999:
            continue
        rel = txy - wall.a
        dist_wall = float(rel @ wall.n)
        t = float(rel @ wall.u) + lateral * float(r @ wall.u)
        gap = dist_wall - target.size[1] / 2 - size[1]
        if 0 < gap and 0.5 * distance_m <= gap <= 2.5 * max(distance_m, 0.4) and 0 <= t <= wall.length:
            pts.append(wall.a + wall.u * t + wall.n * (size[1] / 2))
            yaws.append(yaw)
            pref.append(0.95)
    xy = np.asarray(pts)
    return Cands(xy, np.asarray(yaws), np.zeros(len(xy)), np.asarray(pref))


def fit_on_top(target, size) -> tuple[tuple[float, float, float], bool] | None:
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
    if s < 0.5:
        return None
    return (size[0] * s, size[1] * s, size[2] * s), turned


def place_top(target, size, turned: bool, rng: np.random.Generator) -> Cands:
    txy = np.asarray(target.position[:2])
    r, f = right_dir(target.yaw), front_dir(target.yaw)
    w, d = (size[1], size[0]) if turned else (size[0], size[1])
    fx = max(0.0, (target.size[0] - 2 * TOP_MARGIN_M - w) / 2)
    fy = max(0.0, (target.size[1] - 2 * TOP_MARGIN_M - d) / 2)
    u = np.linspace(-fx, fx, max(1, int(2 * fx / 0.05) + 1))
    v = np.linspace(-fy, fy, max(1, int(2 * fy / 0.05) + 1))
    grid_u, grid_v = np.meshgrid(u, v)
    gu, gv = grid_u.ravel(), grid_v.ravel()
    xy = txy[None] + gu[:, None] * r[None] + gv[:, None] * f[None]
    yaw = wrap(target.yaw + (HALF_PI if turned else 0.0))
    z = target.position[2] + target.size[2]
    pref = 0.5 + 0.3 * rng.random(len(xy))
    return Cands(xy, np.full(len(xy), yaw), np.full(len(xy), z), pref)


def place_on_wall(space: RoomSpace, size, z: float, target=None) -> Cands:
    """Back on a wall at height ``z``; behind ``target`` when it stands against a wall."""
    w, d, h = size
    out = Cands.empty()
    tb = None
    if target is not None:
        tb = np.asarray(target.position[:2]) - front_dir(target.yaw) * target.size[1] / 2
    for wall in space.walls:
        t = _wall_positions(wall, w)
        if not t.size:
            continue
        t = t[space.wall_clear(wall, t - w / 2, t + w / 2, z, z + h)]
        if not t.size:
            continue
        xy = _on_wall(wall, t, d)
        pref = 0.5 + 0.2 * (1.0 - np.abs(t - wall.length / 2) / max(wall.length / 2, 1e-6))
        if tb is not None:
            dist = abs(float((tb - wall.a) @ wall.n))
            tt = float((tb - wall.a) @ wall.u)
            if dist < 0.15:
                pref = pref + 1.0 - 0.3 * np.abs(t - tt)
        out = out + Cands(xy, np.full(len(t), wall.yaw), np.full(len(t), z), pref)
    return out
