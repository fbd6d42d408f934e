"""How a group's copies are laid out: ``free`` (each anchor by its rule), ``along_walls``
(anchors in runs against the walls), ``center`` (around the room centre) and ``rows``
(anchors on a regular grid facing one wall, "desks in neat rows facing a whiteboard")."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from anyhome.house import HouseObject
from anyhome.layout import groups, placement, scoring
from anyhome.layout.rules import REGISTRY, Cands, Kind, front_dir, yaw_facing
from anyhome.layout.rules import place_center as center_rule
from anyhome.layout.rules.place_center import place_center
from anyhome.layout.state import RoomState
from anyhome.plan.spec import GroupSpec
from anyhome.space import Wall


def anchor_candidates(st: RoomState, g: GroupSpec, prev: HouseObject | None) -> tuple[Cands, Kind, str, HouseObject | None]:
    """Candidates for a copy's anchor by the group's arrangement: (cands, kind, rule, ref)."""
    item = g.anchor
    size = item.size_m
    rule = item.rule
    run = run_so_far(st, g)
    if g.arrangement == "along_walls":
        if prev is None:
            rule = rule if rule in ("place_wall", "place_corner") else "place_wall"
        else:
            rule = "place_next_wall"
        c, kind = placement.candidates(st, item, rule, size, None, prev, prev, run=run)
        return c, kind, rule, None
    if g.arrangement == "center":
        params = REGISTRY["place_center"].parse(item.params, lenient=True)
        assert isinstance(params, center_rule.Params)
        c = place_center(st.space, size, params.facing)
        c.pref = c.pref * st.options.center_pref_scale
        return c, "floor", "place_center", None
    ref = None
    if REGISTRY[rule].relative or item.target:  # a target of another rule: far_m, a wall run near it
        refs = st.match(item.target)
        ref = refs[0] if refs else None
    if REGISTRY[rule].placement == "top":
        return Cands.empty(), "top", rule, ref
    c, kind = placement.candidates(st, item, rule, size, ref, prev, prev, run=run)
    return c, kind, rule, ref


def run_so_far(st: RoomState, g: GroupSpec) -> list[HouseObject]:
    """The anchors of ``g``'s copies placed so far that stand against a wall (a run of
    bookcases), oldest first."""
    return [o for o in st.space.objects if o.anchor is None and o.group is not None
            and o.group.rsplit("-", 1)[0] == g.name and o.name == g.anchor.name
            and REGISTRY[o.rule].runs_along_wall]


def board_wall(st: RoomState) -> Wall | None:
    """The wall holding the anchor of an earlier group (a whiteboard, a screen), if any."""
    for o in st.space.objects:
        if o.anchor is not None or o.group is None:
            continue
        back = np.asarray(o.position[:2]) - front_dir(o.yaw) * o.size[1] / 2
        for w in st.space.walls:
            rel = back - w.a
            if abs(float(rel @ w.n)) < 0.05 and -0.05 <= float(rel @ w.u) <= w.length + 0.05:
                return w
    return None


def front_zone_depth(st: RoomState, wall: Wall) -> float:
    """How far from ``wall`` the floor objects standing in its front band reach (a
    teacher's desk and the chair behind it); 0 when none. Objects starting deeper than
    the band (``row_front_clearance_m`` plus a metre) are the rows' business, not the front's;
    one along a side wall counts to the band's edge at most."""
    o = st.options
    band_m = o.row_front_clearance_m + 1.0
    deepest = 0.0
    for p in st.space.placed:
        if not p.floor or p.layer:
            continue
        rel = p.corners - wall.a
        us, vs = rel @ wall.u, rel @ wall.n
        if float(vs.min()) < band_m and float(us.max()) > 0.0 and float(us.min()) < wall.length:
            deepest = max(deepest, min(float(vs.max()), band_m))
    return deepest


@dataclass
class RowsGrid:
    """Capacity and geometry of a rows arrangement facing ``wall``."""

    rows: int
    cols: int
    wall: Wall
    ext: tuple[float, float, float, float]
    cu: float
    cv: float
    cd: float
    u0: float
    u1: float
    v0: float


def rows_grid(st: RoomState, g: GroupSpec, wall: Wall, front_m: float) -> RowsGrid:
    """Capacity (rows, columns) of a rows arrangement facing ``wall`` and its geometry."""
    o = st.options
    x0, x1, y0, y1 = scoring.group_extent(g)
    cw, cd = x1 - x0, y1 - y0
    cu, cv = cw + o.row_aisle_u_m, cd + o.row_aisle_v_m
    rel = st.space.vertices - wall.a
    us, vs = rel @ wall.u, rel @ wall.n
    u0, u1 = us.min() + o.row_side_clearance_m, us.max() - o.row_side_clearance_m
    v0 = max(0.0, vs.min()) + front_m
    v1 = vs.max() - o.row_side_clearance_m
    maxc = max(0, int(np.floor((u1 - u0 + o.row_aisle_u_m) / cu + 1e-9)))
    maxr = max(0, int(np.floor((v1 - v0 + o.row_aisle_v_m) / cv + 1e-9)))
    return RowsGrid(maxr, maxc, wall, (x0, x1, y0, y1), cu, cv, cd, u0, u1, v0)


def place_free(st: RoomState, g: GroupSpec, start: int = 0) -> None:
    """Copies ``start..repeat-1`` of ``g``, each anchor by its rule."""
    prev = None
    for c in range(start, g.repeat):
        prev = groups.place_group_copy(st, g, c, prev) or prev


def place_rows(st: RoomState, g: GroupSpec) -> None:
    """Anchors on a regular grid facing one wall, members attached to each."""
    o = st.options
    item = g.anchor
    n = g.repeat
    board = board_wall(st)
    if board is not None:
        depth = max((x.size[1] for x in st.space.objects if x.anchor is None and x.group is not None),
                    default=0.0)
        front = max(o.row_front_clearance_m + min(depth, 1.0), front_zone_depth(st, board) + o.row_front_aisle_m)
        plans = [rows_grid(st, g, board, front), rows_grid(st, g, board, o.row_side_clearance_m + depth)]
    else:  # face the longest wall, or the one across it when that fits more
        walls = sorted(st.space.walls, key=lambda w: -w.length)
        across = [w for w in walls if abs(float(w.u @ walls[0].u)) < 0.1]
        later = [x.anchor for x in st.spec.groups if x is not g] + list(st.spec.ornaments)
        fronts = [x for x in later if placement.front_item(x)]
        # room in front of the rows for what they face (a board, a 4 m deep stage)
        front = (o.row_front_clearance_m + max((x.size_m[1] for x in fronts), default=0.0) if fronts
                 else o.row_side_clearance_m)
        plans = [rows_grid(st, g, w, f) for w in walls[:1] + across[:1] for f in (front, o.row_side_clearance_m)]
    plans = [p for p in plans if p.rows * p.cols > 0]
    if not plans:
        place_free(st, g)
        return
    geo = next((p for p in plans if p.rows * p.cols >= n), max(plans, key=lambda p: p.rows * p.cols))
    maxr, maxc, wall = geo.rows, geo.cols, geo.wall
    x0, x1, y0, y1 = geo.ext
    st.rows_wall = wall
    nb = wall.n
    faces_member = any(
        m.target in (None, item.name) and REGISTRY[m.rule].faces_anchor(REGISTRY[m.rule].parse(m.params))
        for m in g.members
    )
    yaw = yaw_facing(nb if faces_member else -nb)
    options = []
    for c in range(1, maxc + 1):
        r = math.ceil(n / c)
        if r <= maxr:
            # one long row, or rows of one, read as no rows at all
            lopsided = (r < 2 and n >= 2 and maxr >= 2) or (c < 2 and n >= 4 and maxc >= 2)
            options.append((lopsided, r * c - n, abs(c * geo.cu - r * geo.cv), c))
    cols = min(options)[3] if options else maxc
    rot = np.array([[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]])
    centre_local = rot @ np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    cells = []
    for j in range(maxr):
        for i in range(cols):
            u = (geo.u0 + geo.u1) / 2 + (i - (cols - 1) / 2) * geo.cu
            v = geo.v0 + geo.cd / 2 + j * geo.cv
            cells.append(wall.a + wall.u * u + nb * v - centre_local)
    placed = 0
    shifts = np.asarray(o.row_shifts_m)
    for cell in cells:
        if placed >= n:
            break
        label = f"{g.name}-{placed}"
        xy = cell[None] + shifts[:, None] * wall.u[None]
        cands = Cands(xy, np.full(len(xy), yaw), np.zeros(len(xy)), 1.0 - 0.1 * np.abs(shifts))
        order = scoring.rank(st, cands, item.size_m, "floor", 0.0, spacing=False)
        choices = scoring.verified(st, cands, order, item.size_m, "floor", None, k=2)
        if not choices:
            continue
        snap = st.snapshot()
        anchor = groups.try_choices(st, g, label, choices, "floor", item.rule)
        if anchor is None:
            st.restore(snap)
            continue
        placed += 1
    # copies the grid has no place for are placed freely, else dropped
    place_free(st, g, placed)
