"""Ceiling fixtures and stairs: chandelier, ceiling_fan, staircase, spiral_staircase, ship_ladder.

A ``staircase`` box wide enough for two flights side by side is built as a dog-leg stair
(:mod:`anyhome.floorplan.stairs`: the frame, risers and goings the floorplan sized it
for); a narrower one as a straight flight.

Ceiling fixtures hang from the top of their box (z = height is the ceiling mount).
"""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    METAL,
    Builder,
    about,
    darker,
    lighter,
    make_params,
    rot_x,
    rot_z,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register
from anyhome.floorplan.stairs import (
    LADDER_RISER_MAX_M,
    LADDER_TOP_M,
    WELL_GAP_M,
    dogleg_in_box,
    is_dogleg_box,
)

BRASS = tint("#c9a54a", "metal")
BULB = tint("#fff1c4", "light")
CANDLE = tint("#f4f1e6", "paint")
FLAME = tint("#ffb030", "light")
RISER_M = 0.18
"""Target rise of one stair step."""
PENDANT_WIDTH_M = 0.55
"""A chandelier box narrower than this holds a single pendant lamp."""


# ----------------------------------------------------------------- chandelier / pendant
def sample_chandelier(rng, size, style):
    candles = style_is(style, "antique") or (not style_is(style, "modern", "industrial") and rng.random() < 0.5)
    return make_params("chandelier", rng, size, style, [BRASS, BLACK, "#c9ccd0", "#8a6a3a"],
                       ["#f4f1e6", "#e8e2d4", BLACK, "#c9a54a", "#8a9aa8"], GLASS,
                       arms=int(rng.integers(5, 9)), candles=candles, crystals=bool(candles and rng.random() < 0.5),
                       tiers=int(rng.integers(1, 3)))


def _pendant(b: Builder, w: float, h: float, p) -> None:
    R = w / 2
    b.cyl(0, 0, h - 0.02, h, 0.06, p.primary, sections=14)
    shade_h = min(0.4 * h, 1.2 * R)
    b.cyl(0, 0, shade_h * 0.9, h - 0.02, 0.006, BLACK, sections=4)  # cord
    if p.candles:  # a glass lantern
        b.cyl(0, 0, 0, shade_h, 0.9 * R, GLASS, r_top=0.7 * R, sections=8, alpha=110)
        b.cyl(0, 0, shade_h, shade_h + 0.04, 0.75 * R, p.primary, r_top=0.2 * R, sections=8)
        b.cyl(0, 0, -0.0, 0.02, 0.92 * R, p.primary, sections=8)
    else:
        b.lathe([[0, shade_h], [0.12 * R, shade_h], [0.2 * R, 0.85 * shade_h], [R, 0.05 * shade_h], [R * 0.97, 0],
                 [0.18 * R, 0.8 * shade_h], [0, 0.8 * shade_h]], p.secondary, sections=28)
    b.sphere((0, 0, 0.35 * shade_h), 0.25 * R, BULB, subdivisions=1)


def _chandelier(b: Builder, w: float, d: float, h: float, p) -> None:
    R = w / 2
    b.cyl(0, 0, h - 0.03, h, 0.08, p.primary, sections=16)  # ceiling canopy
    body_top = h - 0.3 * h
    b.cyl(0, 0, body_top, h - 0.03, 0.01, p.primary, sections=6)  # chain rod
    b.lathe([[0, 0], [0.04, 0], [0.06, 0.1 * h], [0.03, 0.25 * h], [0.07, 0.4 * h], [0.04, 0.55 * h],
             [0.02, body_top], [0, body_top]], p.primary, sections=16)
    for tier in range(p.tiers):
        n = p.arms if tier == 0 else max(3, p.arms - 3)
        reach = R * (0.92 if tier == 0 else 0.55)
        z_arm = 0.28 * h + tier * 0.22 * h
        for i in range(n):
            a = 2 * np.pi * (i + 0.5 * tier) / n
            c, s = np.cos(a), np.sin(a)
            elbow = (0.55 * reach * c, 0.55 * reach * s, z_arm - 0.06 * h)
            cup = (reach * c * 0.95, reach * s * 0.95, z_arm + 0.05 * h)
            b.rod((0, 0, z_arm + 0.04 * h), elbow, 0.008, p.primary, sections=6)
            b.rod(elbow, cup, 0.008, p.primary, sections=6)
            b.cyl(cup[0], cup[1], cup[2], cup[2] + 0.02, 0.035, p.primary, r_top=0.045, sections=10)
            if p.candles:
                b.cyl(cup[0], cup[1], cup[2] + 0.02, cup[2] + 0.11, 0.012, CANDLE, sections=8)
                b.sphere((cup[0], cup[1], cup[2] + 0.125), (0.008, 0.008, 0.016), FLAME, subdivisions=0)
            else:
                b.cyl(cup[0], cup[1], cup[2] + 0.02, cup[2] + 0.12, 0.035, p.secondary, r_top=0.055, sections=10,
                      alpha=230)
            if p.crystals:
                b.sphere((elbow[0], elbow[1], elbow[2] - 0.05), (0.012, 0.012, 0.025), GLASS, subdivisions=0,
                         alpha=180)
    b.sphere((0, 0, 0.03), (0.04, 0.04, 0.03), p.primary, subdivisions=1)  # finial


def build_chandelier(p):
    w, d, h = p.size
    b = Builder()
    if w < PENDANT_WIDTH_M:
        _pendant(b, w, h, p)
    else:
        _chandelier(b, w, d, h, p)
    return b.mesh(p.size)


# ----------------------------------------------------------------- ceiling fan
def sample_ceiling_fan(rng, size, style):
    return make_params("ceiling_fan", rng, size, style, [BLACK, "#e8e6e0", "#9a9da3", BRASS, DARK_METAL],
                       wood_tones(style) + ["#e8e6e0", BLACK], "#f4f1e6", blades=int(rng.choice([3, 4, 5])),
                       light=bool(rng.random() < 0.6))


def build_ceiling_fan(p):
    w, d, h = p.size
    b = Builder()
    R = w / 2
    b.cyl(0, 0, h - 0.05, h, 0.07, p.primary, r_top=0.08, sections=16)  # canopy
    motor_top = 0.55 * h if p.light else 0.45 * h
    b.cyl(0, 0, motor_top, h - 0.05, 0.012, p.primary, sections=8)  # downrod
    mz0 = motor_top - 0.3 * h
    b.lathe([[0, mz0], [0.1, mz0], [0.12, mz0 + 0.1 * h], [0.1, motor_top], [0, motor_top]], p.primary, sections=20)
    blade_z = mz0 + 0.1 * h
    for i in range(p.blades):
        a = 2 * np.pi * i / p.blades
        m = rot_z(a)
        b.box((0.08, -0.012, blade_z - 0.004), (0.2, 0.012, blade_z + 0.004), p.primary, transform=m)  # iron
        pitch = about(rot_x(0.15), (0, 0, blade_z))
        b.box((0.18, -0.065, blade_z - 0.006), (R, 0.065, blade_z + 0.006), p.secondary, transform=m @ pitch)
    if p.light:
        b.lathe([[0, 0], [0.09, 0.02], [0.12, 0.08 * h], [0.09, mz0], [0, mz0]], p.accent, sections=20)
    return b.mesh(p.size)


# ----------------------------------------------------------------- straight staircase
def sample_staircase(rng, size, style):
    kind = "open" if style_is(style, "modern", "industrial") else str(rng.choice(["closed", "open"]))
    return make_params("staircase", rng, size, style, wood_tones(style) + ["#e8e6e0", "#9a958c"],
                       wood_tones(style) + [BLACK, METAL], ["#e8e6e0", BLACK, METAL],
                       kind=kind, rails=str(rng.choice(["both", "one", "one"])),
                       turn="dogleg" if is_dogleg_box(size[0], size[1]) else "straight")


def _draw_stairs(b: Builder, L: float, B: float, H: float, p) -> None:
    """Rising along -x (the foot at +x) to a top tread at H; the railing stops where it
    would rise above the box (the floor above has its own guard)."""
    rail_h = min(0.9, 0.4 * H)
    n = max(2, int(round(H / RISER_M)))
    rise = H / n
    run = L / n
    post = 0.04

    def along(x: float) -> float:
        return -x

    for k in range(n):
        x0, x1 = sorted((along(-L / 2 + k * run), along(-L / 2 + (k + 1) * run)))
        z1 = (k + 1) * rise
        if p.kind == "closed":
            b.box((x0, -B / 2, 0), (x1, B / 2, z1 - 0.03), p.primary if k % 2 else lighter(p.primary, 0.05))
            b.box((x0, -B / 2, z1 - 0.03), (x1, B / 2, z1), p.secondary)  # tread
        else:
            b.box((x0, -B / 2 + 0.06, z1 - 0.045), (x1, B / 2 - 0.06, z1), p.secondary)
    if p.kind == "open":  # two stringers
        for sy in (-1, 1):
            y = sy * (B / 2 - 0.03)
            x_lo, x_hi = along(-L / 2), along(L / 2)
            b.hull([(x_lo, y - 0.03, 0), (x_lo, y + 0.03, 0), (along(-L / 2 + run), y - 0.03, 0),
                    (along(-L / 2 + run), y + 0.03, 0), (x_hi, y - 0.03, H - 0.045), (x_hi, y + 0.03, H - 0.045),
                    (x_hi, y - 0.03, H - 0.3), (x_hi, y + 0.03, H - 0.3)], p.primary)
    sides = (-1, 1) if p.rails == "both" else (1,)
    last = max(0, min(n - 1, int((H - rail_h) / rise) - 1))  # the last step the railing can guard
    for sy in sides:
        y = sy * (B / 2 - post)
        for k in range(last + 1):
            xc = along(-L / 2 + (k + 0.5) * run)
            z = (k + 1) * rise
            b.cyl(xc, y, z, z + rail_h, 0.012 if p.kind == "open" else 0.018, p.accent, sections=6)
        x_first, x_last = along(-L / 2 + 0.5 * run), along(-L / 2 + (last + 0.5) * run)
        b.rod((x_first, y, rise + rail_h), (x_last, y, (last + 1) * rise + rail_h), 0.025, p.secondary, sections=8)
        b.box((x_first - post, y - post, 0), (x_first + post, y + post, rise + rail_h + 0.05), p.secondary)  # newel


def _draw_dogleg(b: Builder, L: float, B: float, H: float, p) -> None:
    """A dog-leg stair in the frame of :mod:`anyhome.floorplan.stairs`: the first flight
    on the -y half from its foot at +x, a half landing at -x, the second flight on the
    +y half back up to H at +x; a handrail on the well side of each flight as far as it
    stays inside the box."""
    d = dogleg_in_box(L, B, H)
    r, g = d.riser_m, d.going_m
    wf = (B - WELL_GAP_M) / 2
    land_x = -L / 2 + d.landing_m  # where the half landing ends

    def step(x0: float, x1: float, y0: float, y1: float, z: float, k: int) -> None:
        if p.kind == "closed":
            b.box((x0, y0, 0), (x1, y1, z - 0.03), p.primary if k % 2 else lighter(p.primary, 0.05))
            b.box((x0, y0, z - 0.03), (x1, y1, z), p.secondary)
        else:
            b.box((x0, y0 + 0.04, z - 0.045), (x1, y1 - 0.04, z), p.secondary)

    for k in range(d.first_risers - 1):  # first flight, toward -x
        step(L / 2 - (k + 1) * g, L / 2 - k * g, -B / 2, -B / 2 + wf, (k + 1) * r, k)
    z_land = d.first_risers * r
    step(-L / 2, land_x, -B / 2, B / 2, z_land, 0)
    for j in range(d.second_risers - 1):  # second flight, back toward +x
        step(land_x + j * g, land_x + (j + 1) * g, B / 2 - wf, B / 2, z_land + (j + 1) * r, j)
    top_x = land_x + (d.second_risers - 1) * g
    b.box((min(top_x, L / 2 - 0.05), B / 2 - wf, H - 0.045), (L / 2, B / 2, H), darker(p.secondary, 0.08))  # top nosing
    if p.kind == "open":  # a stringer under each flight's outer edge, a post under the landing
        b.hull([(L / 2, -B / 2, 0), (L / 2, -B / 2 + 0.05, 0), (land_x, -B / 2, z_land - 0.045),
                (land_x, -B / 2 + 0.05, z_land - 0.045), (land_x, -B / 2, z_land - 0.3),
                (land_x, -B / 2 + 0.05, z_land - 0.3), (L / 2 - g, -B / 2, 0), (L / 2 - g, -B / 2 + 0.05, 0)], p.primary)
        b.box((-L / 2, -0.05, 0), (-L / 2 + 0.1, 0.05, z_land - 0.045), p.primary)
        b.hull([(land_x, B / 2, z_land - 0.3), (land_x, B / 2 - 0.05, z_land - 0.3), (land_x, B / 2, z_land),
                (land_x, B / 2 - 0.05, z_land), (L / 2, B / 2, H - 0.045), (L / 2, B / 2 - 0.05, H - 0.045),
                (L / 2, B / 2, H - 0.3), (L / 2, B / 2 - 0.05, H - 0.3)], p.primary)
    rail_h = min(0.9, 0.4 * H)
    roof = H - 0.03  # rails stay inside the box (the floor above has its own guard)
    for y, xs, z0 in ((-WELL_GAP_M / 2, (L / 2 - 0.5 * g, land_x), 0.0), (WELL_GAP_M / 2, (land_x, L / 2), z_land)):
        x_a, x_b = xs
        z_a = min(roof, z0 + r + rail_h)
        z_end = (z_land if z0 == 0 else H) + rail_h
        frac = max(0.0, min(1.0, (roof - z_a) / max(1e-6, z_end - z_a))) if z_end > roof else 1.0
        x_b, z_b = x_a + frac * (x_b - x_a), z_a + frac * (z_end - z_a)
        b.box((x_a - 0.04, y - 0.04, z0), (x_a + 0.04, y + 0.04, z_a), p.secondary)  # newel
        if abs(x_b - x_a) > 0.05:
            b.rod((x_a, y, z_a), (x_b, y, z_b), 0.025, p.secondary, sections=8)


def build_staircase(p):
    """A dog-leg stair (a box wide enough for two flights: ``turn``) or a straight
    flight along the longer side of the box, railings up to the box top."""
    w, d, h = p.size
    b = Builder()
    if getattr(p, "turn", "straight") == "dogleg":
        _draw_dogleg(b, w, d, h, p)
        return b.mesh(p.size)
    if w >= d:
        _draw_stairs(b, w, d, h, p)
        return b.mesh(p.size)
    _draw_stairs(b, d, w, h, p)
    turned = Builder()
    turned.extend(b, rot_z(np.pi / 2))
    return turned.mesh(p.size)


# ----------------------------------------------------------------- spiral staircase
def sample_spiral_staircase(rng, size, style):
    return make_params("spiral_staircase", rng, size, style, [BLACK, DARK_METAL, "#e8e6e0", METAL],
                       wood_tones(style) + [BLACK, "#9a9da3"], wood_tones(style) + [BLACK],
                       turn=float(rng.uniform(1.5 * np.pi, 2.0 * np.pi)), clockwise=bool(rng.random() < 0.5))


def build_spiral_staircase(p):
    """Wedge treads round a central pole up to a landing at the top of the box; balusters
    and a helical handrail as far as they stay inside the box."""
    w, d, h = p.size
    b = Builder()
    R = min(w, d) / 2
    rail_h = min(0.85, 0.35 * h)
    n = max(6, int(round(h / RISER_M)))
    rise = h / n
    step = p.turn / n * (-1 if p.clockwise else 1)
    hub = min(0.05, 0.3 * R)
    b.cyl(0, 0, 0, h, 1.2 * hub, p.primary, sections=14)
    prev = None
    for k in range(n - 1):
        a0 = k * step
        a1 = a0 + step * 1.08
        z = (k + 1) * rise
        pts = []
        for a in (a0, a1):
            pts += [(hub * np.cos(a), hub * np.sin(a), z), (R * np.cos(a), R * np.sin(a), z)]
        pts += [(x, y, z - 0.04) for x, y, _ in pts]
        b.hull(pts, p.secondary if k % 2 else lighter(p.secondary, 0.06))
        if z + rail_h > h:
            continue
        am = (a0 + a1) / 2
        bx, by = 0.95 * R * np.cos(am), 0.95 * R * np.sin(am)
        b.cyl(bx, by, z, z + rail_h, 0.01, p.primary, sections=6)
        cur = (bx, by, z + rail_h)
        if prev is not None:
            b.rod(prev, cur, 0.02, p.accent, sections=8)
        prev = cur
    a_end = (n - 1) * step  # a quarter-circle landing at the top
    arc = [a_end + t * np.pi / 2 * np.sign(step) for t in np.linspace(0, 1, 5)]
    land = [(0.0, 0.0, h)] + [(R * np.cos(a), R * np.sin(a), h) for a in arc]
    b.hull(land + [(x, y, z - 0.04) for x, y, z in land], darker(p.secondary, 0.1))
    return b.mesh(p.size)


# ----------------------------------------------------------------- ship's ladder
def sample_ship_ladder(rng, size, style):
    return make_params("ship_ladder", rng, size, style, wood_tones(style) + [BLACK, DARK_METAL],
                       wood_tones(style), [BLACK, METAL] + wood_tones(style))


def build_ship_ladder(p):
    """A ship's ladder (alternating-tread stair): two steep stringers rising from the foot
    at +x toward -x to the floor at the top end (the last ``LADDER_TOP_M`` of the box
    stays open: the floor above), half-width treads alternating left and right, and a
    handrail on each stringer as far as it stays inside the box."""
    w, d, h = p.size
    b = Builder()
    run = max(0.3, w - LADDER_TOP_M)
    x_foot, x_top = w / 2, w / 2 - run
    n = max(3, int(np.ceil(h / LADDER_RISER_MAX_M - 1e-9)))
    rise = h / n
    s_t = 0.035  # stringer thickness
    for sy in (-1, 1):
        y = sy * (d / 2 - s_t / 2)
        b.hull([(x_foot, y - s_t / 2, 0), (x_foot, y + s_t / 2, 0), (x_foot - 0.12, y - s_t / 2, 0),
                (x_foot - 0.12, y + s_t / 2, 0), (x_top, y - s_t / 2, h), (x_top, y + s_t / 2, h),
                (x_top + 0.12, y - s_t / 2, h), (x_top + 0.12, y + s_t / 2, h)], p.primary)
    go = run / n
    for k in range(n - 1):  # treads, alternating halves
        z = (k + 1) * rise
        x1 = x_foot - (k + 1) * go
        y0, y1 = (-d / 2 + s_t, 0.0) if k % 2 == 0 else (0.0, d / 2 - s_t)
        b.box((x1 - 0.02, y0, z - 0.035), (x1 + 0.2, y1, z), p.secondary if k % 2 else lighter(p.secondary, 0.05))
    rail_h = min(0.85, 0.35 * h)
    roof = h - 0.03
    for sy in (-1, 1):  # a handrail above each stringer, cut where it would leave the box
        y = sy * (d / 2 - s_t / 2)
        frac = max(0.0, min(1.0, (roof - rail_h) / h))
        a = (x_foot - 0.2, y, rail_h)
        e = (x_foot - 0.2 - frac * run, y, rail_h + frac * h)
        b.rod(a, (e[0], y, min(e[2], roof)), 0.018, p.accent, sections=8)
        b.box((x_foot - 0.22, y - 0.015, 0.0), (x_foot - 0.18, y + 0.015, rail_h), p.accent)
    return b.mesh(p.size)


slot_roles("chandelier", "metal", {"": "fabric", "#c9a54a": "metal"}, "glass")
register("chandelier", sample_chandelier, build_chandelier)
slot_roles("ceiling_fan", "metal", "wood", "glass")
register("ceiling_fan", sample_ceiling_fan, build_ceiling_fan)
slot_roles("staircase", "wood", {"": "wood", METAL: "metal"}, {"": "paint", METAL: "metal"})
register("staircase", sample_staircase, build_staircase)
slot_roles("spiral_staircase", "metal", {"": "wood", "#9a9da3": "metal"}, "wood")
register("spiral_staircase", sample_spiral_staircase, build_spiral_staircase)
slot_roles("ship_ladder", {"": "wood", BLACK: "metal", DARK_METAL: "metal"}, "wood", {"": "wood", BLACK: "metal", METAL: "metal"})
register("ship_ladder", sample_ship_ladder, build_ship_ladder)
