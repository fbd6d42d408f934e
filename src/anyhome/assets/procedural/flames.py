"""Things with a flame: candle, candlestick, candelabra, lantern, wood_stove, sauna_stove."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import BRASS, CHROME, COPPER, path, ring_y, vent_lines
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    METAL,
    Builder,
    darker,
    lighter,
    make_params,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

WAX = ["#f4efe1", "#efe6cf", "#e8d8b0", "#b0302a", "#7a2030", "#f2e2c4"]
"""Candle wax colours: ivory, cream, honey, red, burgundy, natural."""
FLAME = tint("#ffc850", "light")
"""A candle flame."""
PEWTER = "#8e9094"
IRON = "#2a2a2c"
HOLDER_METALS = [BRASS, CHROME, PEWTER, IRON]
"""Candlestick and candelabra metals: brass, silver, pewter, wrought iron."""
STOVE_BODIES = [IRON, "#3a3b3e", "#6a1f1f", "#2f4a3a", "#1f2a44"]
"""Cast iron: black, graphite, and the enamelled reds, greens and blues."""
HEARTH_STONES = ["#4a4d52", "#8a4a3a", "#b5a58a", "#6b6e73"]
"""Slate, brick, sandstone, granite."""
SAUNA_STONES = ["#6b6e73", "#5a5c60", "#7d7b76"]


def _flame(b: Builder, x: float, y: float, z0: float, z1: float, r: float) -> None:
    """A wick and a teardrop flame from z0 (the wax top) to z1."""
    b.cyl(x, y, z0, z0 + 0.15 * (z1 - z0), 0.15 * r, tint(IRON, "paint"), sections=6)
    b.cyl(x, y, z0 + 0.1 * (z1 - z0), z1, r, FLAME, r_top=0.0, sections=10)
    b.sphere((x, y, z0 + 0.35 * (z1 - z0)), (r, r, 0.3 * (z1 - z0)), FLAME)


# ----------------------------------------------------------------- candle
def sample_candle(rng, size, style):
    return make_params("candle", rng, size, style, WAX, ["#f4f1ea", "#2b2b2b", BRASS, "#8a6a4a"], FLAME,
                       count=int(rng.choice([1, 1, 3])))


def build_candle(p):
    """Pillar candles (one, or three of stepped heights) on a low dish, each lit."""
    w, d, h = p.size
    b = Builder()
    r_out = min(w, d) / 2
    plate = 0.06 * h
    b.cyl(0, 0, 0, plate, w / 2, p.secondary, r_top=0.95 * w / 2, sections=24, ry=d / 2)
    flame_h = 0.16 * h
    if p.count == 3:
        spots = [(-0.35 * w, -0.15 * d, 1.0), (0.33 * w, -0.2 * d, 0.78), (0.0, 0.3 * d, 0.6)]
        r = 0.25 * min(w, d)
    else:
        spots = [(0.0, 0.0, 1.0)]
        r = 0.62 * r_out
    for x, y, f in spots:
        top = plate + f * (h - plate - flame_h)
        b.cyl(x, y, plate, top, r, p.primary, sections=20)
        b.cyl(x, y, top - 0.02 * h, top, r * 0.85, lighter(p.primary, 0.12), sections=20)  # the melted well
        _flame(b, x, y, top, top + flame_h, 0.12 * r + 0.002)
    return b.mesh(p.size)


# ----------------------------------------------------------------- candlestick
def sample_candlestick(rng, size, style):
    return make_params("candlestick", rng, size, style, HOLDER_METALS, WAX, FLAME,
                       turned=bool(rng.random() < 0.6))


def build_candlestick(p):
    """A taper candle in a metal candlestick: a domed foot, a stem (turned with knops, or
    a plain column), a drip cup."""
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    stem_top = 0.5 * h
    b.lathe([[0, 0], [r, 0], [r * 0.95, 0.03 * h], [r * 0.45, 0.08 * h], [r * 0.2, 0.11 * h], [0, 0.11 * h]],
            p.primary)
    if p.turned:
        b.lathe([[0, 0.1 * h], [r * 0.16, 0.1 * h], [r * 0.35, 0.18 * h], [r * 0.14, 0.26 * h],
                 [r * 0.12, 0.38 * h], [r * 0.3, 0.43 * h], [r * 0.14, stem_top - 0.03 * h], [0, stem_top]],
                p.primary)
    else:
        b.cyl(0, 0, 0.1 * h, stem_top, r * 0.13, p.primary, sections=12)
    b.cyl(0, 0, stem_top - 0.03 * h, stem_top, r * 0.45, p.primary, r_top=r * 0.6, sections=20)  # drip cup
    taper_top = h - 0.12 * h
    b.cyl(0, 0, stem_top, taper_top, r * 0.22, p.secondary, r_top=r * 0.19, sections=12)
    _flame(b, 0, 0, taper_top, h, r * 0.12 + 0.002)
    return b.mesh(p.size)


# ----------------------------------------------------------------- candelabra
def sample_candelabra(rng, size, style):
    return make_params("candelabra", rng, size, style, HOLDER_METALS, WAX, FLAME,
                       arms=int(rng.choice([2, 4])))


def build_candelabra(p):
    """A branched candlestick: a foot, a central stem with a candle, and curved arms
    rising to cups of their own (in a row along x, or all round when the box is square)."""
    w, d, h = p.size
    b = Builder()
    r_foot = 0.3 * min(w, d) if d < 0.6 * w else 0.22 * min(w, d)
    b.lathe([[0, 0], [r_foot, 0], [r_foot * 0.9, 0.03 * h], [r_foot * 0.3, 0.08 * h], [0, 0.08 * h]], p.primary)
    arm_z = 0.4 * h
    cup_z = 0.58 * h
    b.cyl(0, 0, 0.08 * h, cup_z + 0.06 * h, 0.025 * min(w, d) + 0.004, p.primary, sections=10)
    b.sphere((0, 0, arm_z), (0.05 * min(w, d) + 0.006,) * 2 + (0.03 * h,), p.primary)
    radial = d >= 0.6 * w
    if radial:
        angles = [np.pi * 2 * k / p.arms + np.pi / 4 for k in range(p.arms)]
        reach = [(0.42 * w * np.cos(a), 0.42 * d * np.sin(a)) for a in angles]
    else:
        xs = [0.42, 0.22] if p.arms == 4 else [0.42]
        reach = [(s * x * w, 0.0) for x in xs for s in (-1, 1)]
    cup_r = 0.06 * min(w, d) + 0.006 if radial else 0.12 * d + 0.004
    candle_r = 0.6 * cup_r
    flame_h = 0.1 * h
    candle_top = h - flame_h
    tops = [(0.0, 0.0, cup_z + 0.06 * h)]
    for x, y in reach:
        z = cup_z - (0.06 * h if abs(x) < 0.3 * w and not radial else 0.0)
        pts = [(0, 0, arm_z), (0.55 * x, 0.55 * y, arm_z - 0.04 * h), (0.95 * x, 0.95 * y, arm_z + 0.02 * h),
               (x, y, z - 0.02 * h)]
        path(b, pts, 0.012 * min(w, h) + 0.002, p.primary, sections=6)
        tops.append((x, y, z + 0.02 * h))
    for x, y, z in tops:
        b.cyl(x, y, z - 0.03 * h, z, 0.6 * cup_r, p.primary, r_top=cup_r, sections=14)
        top = candle_top - (0.0 if (x, y) == (0.0, 0.0) else 0.04 * h)
        b.cyl(x, y, z, top, candle_r, p.secondary, sections=10)
        _flame(b, x, y, top, top + flame_h * (1.0 if (x, y) == (0.0, 0.0) else 0.9), 0.5 * candle_r)
    return b.mesh(p.size)


# ----------------------------------------------------------------- lantern
def sample_lantern(rng, size, style):
    kinds = ["carriage", "hurricane"] if not style_is(style, "eastern") else ["carriage"]
    return make_params("lantern", rng, size, style, [IRON, BLACK, BRASS, COPPER, DARK_METAL], GLASS,
                       tint(["#ffcf6a", "#ffe2a0"], "light"), kind=str(rng.choice(kinds)))


def build_lantern(p):
    """A carriage lantern (a square glazed box with a pyramid roof and a hanging ring) or
    a hurricane lantern (a glass chimney in a wire frame with a bail handle), lit."""
    w, d, h = p.size
    b = Builder()
    glow = p.accent
    if p.kind == "hurricane":
        r = min(w, d) / 2
        b.cyl(0, 0, 0, 0.22 * h, 0.85 * r, p.primary, r_top=0.75 * r, sections=20)  # fuel tank
        b.cyl(0, 0, 0.22 * h, 0.25 * h, 0.6 * r, p.primary, sections=16)
        b.lathe([[0.3 * r, 0.25 * h], [0.62 * r, 0.38 * h], [0.55 * r, 0.58 * h], [0.35 * r, 0.7 * h],
                 [0.28 * r, 0.72 * h]], p.secondary, sections=20)
        b.sphere((0, 0, 0.36 * h), (0.14 * r, 0.14 * r, 0.05 * h), glow)
        b.cyl(0, 0, 0.7 * h, 0.76 * h, 0.4 * r, p.primary, r_top=0.3 * r, sections=16)  # cap
        for k in range(4):  # wire guards
            a = np.pi / 4 + k * np.pi / 2
            path(b, [(0.8 * r * np.cos(a), 0.8 * r * np.sin(a), 0.22 * h),
                     (0.72 * r * np.cos(a), 0.72 * r * np.sin(a), 0.5 * h),
                     (0.35 * r * np.cos(a), 0.35 * r * np.sin(a), 0.72 * h)], 0.02 * r + 0.001, p.primary,
                 sections=5, joints=False)
        handle = [(-0.85 * r, 0, 0.24 * h)] + [(-0.85 * r * np.cos(t), 0, 0.76 * h + 0.24 * h * np.sin(t))
                                               for t in np.linspace(0, np.pi, 9)] + [(0.85 * r, 0, 0.24 * h)]
        path(b, handle, 0.025 * r + 0.001, p.primary, sections=5)
        return b.mesh(p.size)
    fx, fy = 0.4 * w, 0.4 * d
    bar = 0.06 * min(w, d) + 0.002
    b.box((-0.45 * w, -0.45 * d, 0), (0.45 * w, 0.45 * d, 0.08 * h), p.primary)  # base
    top = 0.7 * h
    for sx in (-1, 1):
        for sy in (-1, 1):
            b.box((sx * fx - bar / 2, sy * fy - bar / 2, 0.08 * h), (sx * fx + bar / 2, sy * fy + bar / 2, top),
                  p.primary)
    b.box((-fx, -fy, 0.08 * h), (fx, fy, top), p.secondary, alpha=110)  # glazing
    b.cyl(0, 0, 0.08 * h, 0.3 * h, 0.08 * min(w, d), tint("#f4efe1", "paint"), sections=10)  # the candle inside
    b.sphere((0, 0, 0.36 * h), (0.08 * min(w, d), 0.08 * min(w, d), 0.07 * h), glow)
    b.box((-0.48 * w, -0.48 * d, top), (0.48 * w, 0.48 * d, top + 0.04 * h), p.primary)
    b.hull([(-0.48 * w, -0.48 * d, top + 0.04 * h), (0.48 * w, -0.48 * d, top + 0.04 * h),
            (0.48 * w, 0.48 * d, top + 0.04 * h), (-0.48 * w, 0.48 * d, top + 0.04 * h),
            (-0.08 * w, -0.08 * d, 0.88 * h), (0.08 * w, -0.08 * d, 0.88 * h), (0.08 * w, 0.08 * d, 0.88 * h),
            (-0.08 * w, 0.08 * d, 0.88 * h)], p.primary)
    b.cyl(0, 0, 0.86 * h, 0.9 * h, 0.05 * min(w, d) + 0.002, p.primary, sections=8)
    ring_y(b, (0, 0, 0.9 * h + 0.045 * h), 0.045 * h, 0.008 * h + 0.001, p.primary, sections=16)  # hanging ring
    return b.mesh(p.size)


# ----------------------------------------------------------------- wood stove
def sample_wood_stove(rng, size, style):
    return make_params("wood_stove", rng, size, style, STOVE_BODIES, HEARTH_STONES, tint("#f08a2a", "light"),
                       hearth=bool(rng.random() < 0.6), window=bool(rng.random() < 0.75),
                       round_body=bool(rng.random() < (0.45 if style_is(style, "antique", "rustic") else 0.15)))


def build_wood_stove(p):
    """A cast-iron wood stove on short legs, a door at the front (+y) with a glass window
    showing the fire, a flue pipe rising from the top; on a stone hearth slab or not.
    ``round_body``: a pot-belly stove."""
    w, d, h = p.size
    b = Builder()
    z0 = 0.0
    if p.hearth:
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.03 * h), p.secondary)
        z0 = 0.03 * h
    bw, bd = 0.78 * w, 0.72 * d
    leg_top = z0 + 0.07 * h
    body_top = z0 + 0.55 * h
    y_back = -d / 2 + 0.06 * d
    yc = y_back + bd / 2
    spread = 0.28 * min(bw, bd) if p.round_body else 0.4 * bw
    for sx in (-1, 1):
        for sy in (-1, 1):
            b.cyl(sx * spread, yc + sy * (spread if p.round_body else 0.4 * bd), z0, leg_top, 0.03 * min(w, d) + 0.004, p.primary,
                  r_top=0.02 * min(w, d) + 0.004, sections=8)
    door_y = yc + bd / 2
    if p.round_body:
        r = min(bw, bd) / 2
        b.lathe([[0, leg_top], [0.55 * r, leg_top], [0.9 * r, leg_top + 0.15 * (body_top - leg_top)],
                 [r, leg_top + 0.45 * (body_top - leg_top)], [0.9 * r, leg_top + 0.75 * (body_top - leg_top)],
                 [0.6 * r, body_top], [0, body_top]], p.primary,
                y=yc, sections=24)
        door_y = yc + 0.95 * r
        dw = 0.55 * r
    else:
        b.box((-bw / 2, yc - bd / 2, leg_top), (bw / 2, yc + bd / 2, body_top), p.primary)
        b.box((-bw / 2 - 0.02 * w, yc - bd / 2 - 0.02 * d, body_top), (bw / 2 + 0.02 * w, yc + bd / 2 + 0.02 * d,
                                                                          body_top + 0.025 * h),
              darker(p.primary, 0.2))  # top plate
        dw = 0.36 * bw
    dz0, dz1 = leg_top + 0.2 * (body_top - leg_top), leg_top + 0.78 * (body_top - leg_top)
    b.box((-dw, door_y, dz0), (dw, door_y + 0.025 * d, dz1), darker(p.primary, 0.25))
    if p.window:
        b.box((-0.75 * dw, door_y + 0.02 * d, dz0 + 0.15 * (dz1 - dz0)),
              (0.75 * dw, door_y + 0.03 * d, dz1 - 0.15 * (dz1 - dz0)), p.accent)
        b.box((-0.55 * dw, door_y + 0.031 * d, dz0 + 0.2 * (dz1 - dz0)),
              (0.55 * dw, door_y + 0.034 * d, dz0 + 0.45 * (dz1 - dz0)), tint("#ffd060", "light"))
    else:
        vent_lines(b, -0.6 * dw, 0.6 * dw, dz0 + 0.1 * (dz1 - dz0), dz0 + 0.3 * (dz1 - dz0), door_y + 0.025 * d, 3,
                   color=p.accent, depth=0.004)
    b.rod((dw * 0.9, door_y + 0.03 * d, (dz0 + dz1) / 2), (dw * 0.9, door_y + 0.08 * d, (dz0 + dz1) / 2),
          0.012 * min(w, d) + 0.002, CHROME if p.primary == IRON else METAL, sections=6)  # handle
    b.box((-0.6 * dw, door_y, leg_top + 0.05 * (body_top - leg_top)),
          (0.6 * dw, door_y + 0.02 * d, leg_top + 0.14 * (body_top - leg_top)), darker(p.primary, 0.25))  # ash drawer
    pipe_r = 0.1 * min(w, d) + 0.01
    py = yc - 0.15 * bd
    b.cyl(0, py, body_top, body_top + 0.06 * h, pipe_r * 1.3, darker(p.primary, 0.2), r_top=pipe_r, sections=16)
    b.cyl(0, py, body_top + 0.06 * h, h, pipe_r, tint(IRON, "metal"), sections=16)
    b.cyl(0, py, 0.8 * h, 0.82 * h, pipe_r * 1.12, tint(IRON, "metal"), sections=16)  # damper collar
    return b.mesh(p.size)


# ----------------------------------------------------------------- sauna stove
def sample_sauna_stove(rng, size, style):
    return make_params("sauna_stove", rng, size, style, [DARK_METAL, "#55585d", "#8e9094", IRON], SAUNA_STONES,
                       wood_tones(style) + ["#c9a77c", "#b98b5a"], round_body=bool(rng.random() < 0.35),
                       guard=bool(rng.random() < 0.5))


def build_sauna_stove(p):
    """A sauna stove (kiuas): a steel heater, louvred at the front (+y), carrying a heap of
    grey stones in a wire basket on top; a wooden guard rail round it or not."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    inset = 0.12 if p.guard else 0.0
    bw, bd = (1 - 2 * inset) * w, (1 - 2 * inset) * d
    body_top = 0.62 * h
    if p.round_body:
        r = min(bw, bd) / 2
        b.cyl(0, 0, 0.04 * h, body_top, r, p.primary, sections=24)
        b.cyl(0, 0, 0, 0.04 * h, 0.8 * r, darker(p.primary, 0.3), sections=16)
        vent_lines(b, -0.45 * r, 0.45 * r, 0.15 * h, 0.45 * h, r * 0.98, 5, color=darker(p.primary, 0.4))
        sr_x, sr_y = 0.95 * r, 0.95 * r
    else:
        b.box((-bw / 2, -bd / 2, 0.04 * h), (bw / 2, bd / 2, body_top), p.primary)
        for sx in (-1, 1):
            for sy in (-1, 1):
                b.box((sx * 0.42 * bw - 0.02 * w, sy * 0.42 * bd - 0.02 * d, 0),
                      (sx * 0.42 * bw + 0.02 * w, sy * 0.42 * bd + 0.02 * d, 0.04 * h), darker(p.primary, 0.3))
        vent_lines(b, -0.35 * bw, 0.35 * bw, 0.12 * h, 0.5 * h, bd / 2, 6, color=darker(p.primary, 0.45))
        b.box((-0.12 * bw, bd / 2, 0.52 * h), (0.12 * bw, bd / 2 + 0.01 * d, 0.57 * h), BLACK)  # control knob plate
        sr_x, sr_y = bw / 2, bd / 2
    stone_top = h if not p.guard else 0.97 * h
    cage = 0.82
    for k in range(8):  # basket bars
        a = 2 * np.pi * k / 8
        x, y = cage * sr_x * np.cos(a), cage * sr_y * np.sin(a)
        b.rod((x, y, body_top), (x * 1.05, y * 1.05, body_top + 0.22 * (stone_top - body_top)),
              0.01 * min(w, d) + 0.002, DARK_METAL, sections=5)
    n = 28
    for i in range(n):
        t = i / n
        rad = np.sqrt(rng.uniform(0, 1)) * (1 - 0.55 * t)
        a = rng.uniform(0, 2 * np.pi)
        x, y = rad * 0.82 * sr_x * np.cos(a), rad * 0.82 * sr_y * np.sin(a)
        rs = float(rng.uniform(0.09, 0.14)) * min(sr_x, sr_y)
        z = body_top + rs * 0.7 + t * (stone_top - body_top - 1.6 * rs)
        shade = p.secondary if i % 3 else darker(p.secondary, 0.25)
        b.sphere((x, y, z), (rs * 1.2, rs, rs * 0.8), shade, subdivisions=1)
    if p.guard:
        post = 0.03 * min(w, d) + 0.005
        xs = ((-w / 2, -w / 2 + post), (w / 2 - post, w / 2))
        ys = ((-d / 2, -d / 2 + post), (d / 2 - post, d / 2))
        for x0, x1 in xs:
            for y0, y1 in ys:
                b.box((x0, y0, 0), (x1, y1, 0.75 * h), p.accent)
        for z in (0.3 * h, 0.55 * h, 0.71 * h):  # the rails
            for y0, y1 in ys:
                b.box((-w / 2, y0, z), (w / 2, y1, z + 0.04 * h), p.accent)
            for x0, x1 in xs:
                b.box((x0, -d / 2, z), (x1, d / 2, z + 0.04 * h), p.accent)
    return b.mesh(p.size)


slot_roles("candle", "paint", {"": "ceramic", BRASS: "metal"}, "light")
register("candle", sample_candle, build_candle)
slot_roles("candlestick", "metal", "paint", "light")
register("candlestick", sample_candlestick, build_candlestick)
slot_roles("candelabra", "metal", "paint", "light")
register("candelabra", sample_candelabra, build_candelabra)
slot_roles("lantern", "metal", "glass", "light")
register("lantern", sample_lantern, build_lantern)
slot_roles("wood_stove", "metal", "stone", "light")
register("wood_stove", sample_wood_stove, build_wood_stove)
slot_roles("sauna_stove", "metal", "stone", "wood")
register("sauna_stove", sample_sauna_stove, build_sauna_stove)
