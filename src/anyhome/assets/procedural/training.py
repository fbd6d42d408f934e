"""Gym and gymnastics equipment: rowing_machine, stair_climber, cable_machine, leg_press,
ballet_barre, pommel_horse, parallel_bars, wall_bars, pull_up_bar, dance_pole,
basketball_hoop, trampoline."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    SCREEN,
    disc_x,
    disc_y,
    path,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    about,
    darker,
    lengthwise,
    lighter,
    make_params,
    rot_y,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

FRAMES = tint([BLACK, "#2b2b2b", "#3a3b3e", "#c9ccd0", "#e8e6e0", "#b8322a"], "paint")
PADS = tint([BLACK, "#2b2b2b", "#7a1f2b", "#2d4f8a", "#3a3b3e"], "leather")
GYM_WOOD = tint(["#d8bf98", "#c9a77c", "#e0cfae"], "wood")


# ----------------------------------------------------------------- rowing machine
def sample_rowing_machine(rng, size, style):
    water = rng.random() < 0.3
    return make_params("rowing_machine", rng, size, style, GYM_WOOD + ["#8f6642"] if water else FRAMES[:4],
                       PADS, "#4a90c8", kind="water" if water else "air")


def _draw_rower(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the flywheel (or water tank) at +x, the rail running back to the rear foot."""
    fx = 0.36 * L
    rail_z = 0.36 * H
    if p.kind == "water":
        for y in (-0.22 * B, 0.22 * B):
            b.box((-L / 2, y - 0.04 * B, 0.0), (0.3 * L, y + 0.04 * B, rail_z), p.primary)
        b.box((-L / 2, -0.3 * B, 0), (-0.45 * L, 0.3 * B, rail_z), p.primary)
        R = min(0.45 * B, 0.14 * L)
        b.cyl(fx, 0, 0.05 * H, 0.5 * H, R, tint("#8ac4e8", "paint"), sections=24, alpha=150)  # tank
        b.cyl(fx, 0, 0.05 * H, 0.3 * H, 0.97 * R, p.accent, sections=24)
        b.cyl(fx, 0, 0.0, 0.05 * H, R * 1.02, p.primary, sections=24)
        b.box((0.3 * L, -0.1 * B, 0.0), (L / 2, 0.1 * B, 0.06 * H), p.primary)
        b.box((0.26 * L, -0.35 * B, 0.0), (0.32 * L, 0.35 * B, H - 0.05 * H), p.primary)  # front posts
        disc_x(b, 0.24 * L, 0.34 * L, 0, 0.8 * H, 0.06 * H, tint("#2b2b2b", "paint"), sections=10)
        mon = (0.29 * L, 0, H)
    else:
        b.hull([(-0.46 * L, -0.1 * B, rail_z - 0.08 * H), (-0.46 * L, 0.1 * B, rail_z - 0.08 * H),
                (-0.46 * L, -0.1 * B, rail_z), (-0.46 * L, 0.1 * B, rail_z), (0.28 * L, -0.1 * B, rail_z + 0.1 * H),
                (0.28 * L, 0.1 * B, rail_z + 0.1 * H), (0.28 * L, -0.1 * B, rail_z), (0.28 * L, 0.1 * B, rail_z)],
               p.primary)  # monorail
        b.box((-0.48 * L, -0.45 * B, 0), (-0.42 * L, 0.45 * B, 0.05 * H), p.primary)  # rear foot
        b.box((-0.47 * L, -0.06 * B, 0.04 * H), (-0.43 * L, 0.06 * B, rail_z - 0.06 * H), p.primary)
        R = min(0.34 * H, 0.16 * L)
        fz = max(R + 0.06 * H, 0.42 * H)
        disc_y(b, fx, -0.3 * B, 0.3 * B, fz, R, tint("#2b2b2b", "paint"), sections=24)  # flywheel cage
        for s in (-1, 1):
            disc_y(b, fx, s * 0.3 * B, s * 0.31 * B, fz, 0.7 * R, tint("#5f6b7a", "paint"), sections=20)
        b.box((fx - 0.05 * L, -0.5 * B, 0), (fx + 0.05 * L, 0.5 * B, 0.05 * H), p.primary)  # front foot
        b.box((fx - 0.02 * L, -0.06 * B, 0.04 * H), (fx + 0.02 * L, 0.06 * B, fz), p.primary)
        arm0 = (fx, 0, fz + R)
        mon = (0.2 * L, 0, H - 0.08 * H)
        path(b, [arm0, (fx - 0.02 * L, 0, H - 0.1 * H), mon], 0.015, DARK_METAL)
    b.box((mon[0] - 0.02 * L, -0.2 * B, mon[2] - 0.15 * H), (mon[0] + 0.01 * L, 0.2 * B, mon[2] + 0.05 * H * 0),
          BLACK)
    b.box((mon[0] - 0.025 * L, -0.17 * B, mon[2] - 0.13 * H), (mon[0] - 0.02 * L, 0.17 * B, mon[2] - 0.02 * H),
          SCREEN)
    for s in (-1, 1):  # footrests
        y = s * 0.18 * B
        b.hull([(0.15 * L, y - 0.08 * B, rail_z + 0.02 * H), (0.15 * L, y + 0.08 * B, rail_z + 0.02 * H),
                (0.2 * L, y - 0.08 * B, rail_z + 0.25 * H), (0.2 * L, y + 0.08 * B, rail_z + 0.25 * H),
                (0.17 * L, y - 0.08 * B, rail_z + 0.02 * H), (0.17 * L, y + 0.08 * B, rail_z + 0.02 * H),
                (0.22 * L, y - 0.08 * B, rail_z + 0.25 * H), (0.22 * L, y + 0.08 * B, rail_z + 0.25 * H)],
               darker(p.secondary, 0.1) if p.secondary != BLACK else tint("#3a3b3e", "paint"))
    sx = -0.12 * L
    b.box((sx - 0.05 * L, -0.2 * B, rail_z + 0.02 * H), (sx + 0.05 * L, 0.2 * B, rail_z + 0.12 * H), p.secondary)
    b.rod((0.27 * L, -0.4 * B, 0.55 * H), (0.27 * L, 0.4 * B, 0.55 * H), 0.02, p.secondary, sections=8)  # handle
    b.rod((0.27 * L, 0, 0.55 * H), (fx - 0.1 * L, 0, 0.5 * H), 0.004, METAL, sections=4)


def build_rowing_machine(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_rower(b, L, B, H, p))


# ----------------------------------------------------------------- stair climber
def sample_stair_climber(rng, size, style):
    return make_params("stair_climber", rng, size, style, FRAMES, ["#3a3b3e", "#2b2b2b"], "#c0392b",
                       steps=int(rng.integers(5, 8)))


def build_stair_climber(p):
    """A stepmill: side housings rising to the back, a flight of revolving steps between
    them, handrails on both sides and the console at the top."""
    w, d, h = p.size
    b = Builder()
    sz = 0.5 * h
    side = 0.12 * w
    prof = [(d / 2, 0.0), (-d / 2, 0.0), (-d / 2, sz + 0.05 * h), (-0.2 * d, sz + 0.05 * h), (d / 2, 0.1 * h)]
    for x0 in (-w / 2, w / 2 - side):
        b.extrude_x(prof, x0, x0 + side, p.primary)
    b.box((-w / 2 + side, -d / 2, 0), (w / 2 - side, -d / 2 + 0.1 * d, sz), darker(p.primary, 0.2))
    n = p.steps
    for k in range(n):  # treads rising to the back
        t = k / n
        y0 = d / 2 - 0.08 * d - t * 0.8 * d
        z = 0.1 * h + t * (sz - 0.12 * h)
        b.box((-w / 2 + side, y0 - 0.8 * d / n, z), (w / 2 - side, y0, z + 0.035 * h), p.secondary)
        b.box((-w / 2 + side, y0 - 0.02, z + 0.035 * h), (w / 2 - side, y0, z + 0.04 * h), p.accent)
        b.box((-w / 2 + side, y0 - 0.8 * d / n, 0.05 * h), (w / 2 - side, y0 - 0.8 * d / n + 0.02, z),
              darker(p.secondary, 0.4))
    rail_h = 0.42 * h
    for s in (-1, 1):
        x = s * (w / 2 - side / 2)
        a = (x, d / 2 - 0.1 * d, 0.1 * h + rail_h)
        c = (x, -0.3 * d, sz + rail_h)
        path(b, [(x, d / 2 - 0.1 * d, 0.1 * h), a, c, (x, -0.3 * d, sz)], 0.02, CHROME)
    b.box((-0.15 * w, -d / 2, sz), (0.15 * w, -d / 2 + 0.12 * d, h - 0.12 * h), p.primary)  # console column
    b.hull([(-0.25 * w, -d / 2 + 0.02, h - 0.16 * h), (0.25 * w, -d / 2 + 0.02, h - 0.16 * h),
            (-0.25 * w, -d / 2 + 0.12 * d, h - 0.16 * h), (0.25 * w, -d / 2 + 0.12 * d, h - 0.16 * h),
            (-0.25 * w, -d / 2, h), (0.25 * w, -d / 2, h), (-0.25 * w, -d / 2 + 0.06 * d, h),
            (0.25 * w, -d / 2 + 0.06 * d, h)], p.primary)
    b.hull([(-0.2 * w, -d / 2 + 0.1 * d + 0.002, h - 0.14 * h), (0.2 * w, -d / 2 + 0.1 * d + 0.002, h - 0.14 * h),
            (-0.2 * w, -d / 2 + 0.06 * d + 0.002, h - 0.02 * h), (0.2 * w, -d / 2 + 0.06 * d + 0.002, h - 0.02 * h),
            (-0.2 * w, -d / 2 + 0.1 * d + 0.006, h - 0.14 * h), (0.2 * w, -d / 2 + 0.1 * d + 0.006, h - 0.14 * h),
            (-0.2 * w, -d / 2 + 0.06 * d + 0.006, h - 0.02 * h), (0.2 * w, -d / 2 + 0.06 * d + 0.006, h - 0.02 * h)],
           SCREEN)
    return b.mesh(p.size)


# ----------------------------------------------------------------- cable machine
def sample_cable_machine(rng, size, style):
    return make_params("cable_machine", rng, size, style, FRAMES, [BLACK, "#3a3b3e"], ["#c0392b", "#e0b030", CHROME],
                       shrouds=bool(rng.random() < 0.4))


def build_cable_machine(p):
    """A cable crossover: two towers each with a weight stack on guide rods and an
    adjustable pulley, joined by a top beam with pull-up grips; cables to D-handles."""
    w, d, h = p.size
    b = Builder()
    tw = min(0.28 * w, 0.6)
    t = min(0.04, 0.05 * tw)
    for sx in (-1, 1):
        xc = sx * (w / 2 - tw / 2)
        for x in (xc - tw / 2, xc + tw / 2 - 2 * t):
            for y in (-d / 4, d / 4 - 2 * t):
                b.box((x, y, 0.03 * h), (x + 2 * t, y + 2 * t, h - 0.06 * h), p.primary)
        b.box((xc - tw / 2, -d / 2, 0), (xc + tw / 2, d / 2, 0.03 * h), p.primary)  # foot
        b.box((xc - tw / 2, -d / 4, h - 0.08 * h), (xc + tw / 2, d / 4, h - 0.04 * h), p.primary)
        n = 14
        for k in range(n):  # weight plates
            z = 0.05 * h + k * 0.02 * h
            b.box((xc - 0.3 * tw, -0.12 * d, z), (xc + 0.3 * tw, 0.06 * d, z + 0.018 * h),
                  p.secondary if k % 2 else lighter(p.secondary, 0.15))
        b.box((xc - 0.05 * tw, -0.12 * d, 0.05 * h + n * 0.02 * h), (xc + 0.05 * tw, 0.06 * d, 0.6 * h), CHROME)
        for x in (xc - 0.35 * tw, xc + 0.35 * tw):
            b.cyl(x, -0.03 * d, 0.03 * h, h - 0.08 * h, 0.008, CHROME, sections=6)
        if p.shrouds:
            b.box((xc - 0.42 * tw, 0.06 * d + 0.005, 0.05 * h), (xc + 0.42 * tw, 0.08 * d, 0.7 * h), p.accent)
        px = xc - sx * (tw / 2)
        b.box((px - sx * 0.02, -0.05 * d, 0.55 * h), (px - sx * 0.08, 0.05 * d, 0.63 * h), p.accent)  # carriage
        disc_y(b, px - sx * 0.05, -0.01, 0.01, 0.59 * h, 0.04, DARK_METAL, sections=12)
        disc_y(b, xc, -0.01, 0.01, h - 0.1 * h, 0.05, DARK_METAL, sections=12)
        hand = (px - sx * 0.25 * w * 0.5, 0.15 * d, 0.45 * h)
        b.rod((px - sx * 0.05, 0, 0.59 * h), hand, 0.004, METAL, sections=4)
        b.rod((hand[0] - 0.06, hand[1], hand[2] - 0.02), (hand[0] + 0.06, hand[1], hand[2] - 0.02), 0.015, BLACK,
              sections=6)
    b.box((-w / 2, -0.06 * d, h - 0.06 * h), (w / 2, 0.06 * d, h), p.primary)  # top beam
    for s in (-1, 1):
        b.rod((s * 0.2 * w, 0.06 * d, h - 0.03 * h), (s * 0.25 * w, 0.25 * d, h - 0.05 * h), 0.018, BLACK,
              sections=6)
    b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + 0.06 * d, 0.03 * h), p.primary)  # floor rail
    return b.mesh(p.size)


# ----------------------------------------------------------------- leg press
def sample_leg_press(rng, size, style):
    return make_params("leg_press", rng, size, style, FRAMES, PADS, [BLACK, "#3a3b3e", "#c0392b"],
                       plates=int(rng.integers(2, 5)))


def _draw_leg_press(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the reclined seat at +x, the sled rails rising at 45 degrees to -x with the
    footplate carriage and its weight plates."""
    b.box((-L / 2, -0.42 * B, 0), (L / 2, -0.32 * B, 0.06 * H), p.primary)  # base rails
    b.box((-L / 2, 0.32 * B, 0), (L / 2, 0.42 * B, 0.06 * H), p.primary)
    b.box((-L / 2, -0.42 * B, 0), (-L / 2 + 0.06 * L, 0.42 * B, 0.06 * H), p.primary)
    x_low, z_low = 0.05 * L, 0.3 * H
    x_top, z_top = -L / 2 + 0.04 * L, H - 0.04 * H
    for y in (-0.25 * B, 0.25 * B):  # inclined rails and their uprights
        b.rod((x_low, y, z_low), (x_top, y, z_top), 0.035, p.primary, sections=8)
        b.rod((x_top, y, z_top), (x_top, y, 0.05 * H), 0.035, p.primary, sections=8)
        b.rod((x_low, y, z_low), (x_low, y, 0.05 * H), 0.03, p.primary, sections=8)
    t = 0.45  # the carriage, part way up the rails
    cx, cz = x_low + t * (x_top - x_low), z_low + t * (z_top - z_low)
    ang = np.arctan2(z_top - z_low, x_low - x_top)
    tilt = about(rot_y(ang), (cx, 0, cz))
    b.box((cx - 0.03, -0.35 * B, cz), (cx + 0.25, 0.35 * B, cz + 0.05), p.primary, transform=tilt)
    b.box((cx + 0.22, -0.3 * B, cz - 0.02), (cx + 0.26, 0.3 * B, cz + 0.5), darker(p.primary, 0.2),
          transform=tilt)  # footplate
    for s in (-1, 1):  # weight horns and plates
        y0 = s * 0.35 * B
        b.rod((cx, y0, cz + 0.15), (cx, s * 0.5 * B, cz + 0.15), 0.025, CHROME, sections=8)
        for k in range(p.plates):
            y = y0 + s * (0.02 + k * 0.035)
            disc_y(b, cx, min(y, y + s * 0.03), max(y, y + s * 0.03), cz + 0.15, 0.2 + 0.02 * (k == 0), p.accent,
                   sections=18)
    sx = 0.2 * L  # seat and reclined back pad
    b.box((sx - 0.05 * L, -0.15 * B, 0.06 * H), (sx + 0.05 * L, 0.15 * B, 0.28 * H), p.primary)
    b.box((sx - 0.12 * L, -0.22 * B, 0.28 * H), (sx + 0.06 * L, 0.22 * B, 0.34 * H), p.secondary)
    hinge = (sx + 0.06 * L, 0, 0.3 * H)
    b.box((sx + 0.06 * L, -0.22 * B, 0.3 * H), (L / 2, 0.22 * B, 0.36 * H), p.secondary,
          transform=about(rot_y(-0.75), hinge))
    for s in (-1, 1):
        path(b, [(sx, s * 0.22 * B, 0.3 * H), (sx, s * 0.32 * B, 0.36 * H), (sx - 0.06 * L, s * 0.32 * B, 0.36 * H)],
             0.015, BLACK)


def build_leg_press(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_leg_press(b, L, B, H, p))


# ----------------------------------------------------------------- ballet barre
def sample_ballet_barre(rng, size, style):
    return make_params("ballet_barre", rng, size, style, wood_tones(style)[:3] + GYM_WOOD,
                       [CHROME, BLACK, "#e8e6e0"], METAL, kind=str(rng.choice(["wall", "wall", "free"])))


def _draw_barre(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: two wooden rails at two heights, on wall brackets (at -y) or on
    free-standing uprights with flat feet."""
    r = min(0.022, 0.12 * B, 0.03 * H)
    zs = (0.72 * H, H - r)
    n = max(2, int(L / 1.2) + 1)
    xs = np.linspace(-L / 2 + 0.12 * L / n, L / 2 - 0.12 * L / n, n)
    if p.kind == "wall":
        ry = B / 2 - r
        for x in xs:
            b.box((x - 0.02, -B / 2, 0.62 * H), (x + 0.02, -B / 2 + 0.02, H), p.secondary)  # wall plate
            for z in zs:
                b.rod((x, -B / 2 + 0.02, z - 0.04 * H), (x, ry, z), 0.012, p.secondary, sections=6)
                b.sphere((x, ry, z), 0.02, p.secondary, subdivisions=0)
    else:
        ry = 0.0
        for x in xs:
            b.box((x - 0.02, -B / 2, 0), (x + 0.02, B / 2, 0.03), p.secondary)
            b.cyl(x, 0, 0, H - r, 0.02, p.secondary, sections=8)
    for z in zs:
        b.rod((-L / 2, ry, z), (L / 2, ry, z), r, p.primary, sections=12)


def build_ballet_barre(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_barre(b, L, B, H, p))


# ----------------------------------------------------------------- pommel horse
def sample_pommel_horse(rng, size, style):
    return make_params("pommel_horse", rng, size, style, ["#8a5a3a", "#6b4330", "#2d4f8a", "#3a3b3e", "#b08058"],
                       ["#e8d3a8", "#d8bf98"], [DARK_METAL, "#c9ccd0", "#b8322a"], pommels=bool(rng.random() < 0.8))


def _draw_pommel(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: a leather body with rounded ends, two wooden pommels on top, two legs with
    adjustable posts and feet across."""
    top = H - (0.12 * H if p.pommels else 0.0)
    bh = min(0.3 * H, 0.7 * B)
    z0 = top - bh
    r = min(0.45 * B, 0.9 * bh) * 0.5
    prof = [(-0.3 * B + r, z0), (0.3 * B - r, z0)]
    for cy, cz, a0 in ((0.3 * B - r, z0 + r, -np.pi / 2), (0.3 * B - r, top - r, 0.0),
                       (-0.3 * B + r, top - r, np.pi / 2), (-0.3 * B + r, z0 + r, np.pi)):
        prof += [(cy + r * np.cos(a), cz + r * np.sin(a)) for a in np.linspace(a0, a0 + np.pi / 2, 4)]
    b.extrude_x(prof, -0.46 * L, 0.46 * L, p.primary)
    for s in (-1, 1):  # rounded ends
        b.sphere((s * 0.46 * L, 0, (z0 + top) / 2), (0.04 * L, 0.3 * B, bh / 2), p.primary, subdivisions=2)
    if p.pommels:
        for x in (-0.12 * L, 0.12 * L):
            for y in (-0.15 * B, 0.15 * B):
                b.box((x - 0.015, y - 0.015, top - 0.01), (x + 0.015, y + 0.015, H - 0.03 * H), p.secondary)
            b.rod((x, -0.17 * B, H - 0.03 * H), (x, 0.17 * B, H - 0.03 * H), 0.025, p.secondary, sections=10)
    for x in (-0.3 * L, 0.3 * L):
        b.box((x - 0.03, -0.04, 0.35 * H), (x + 0.03, 0.04, z0), p.accent)
        b.cyl(x, 0, 0.04, 0.4 * H, 0.045, darker(p.accent, 0.1), sections=10)
        b.box((x - 0.05, -B / 2, 0), (x + 0.05, B / 2, 0.04), p.accent)
        for s in (-1, 1):
            b.rod((x, 0, 0.3 * H), (x, s * 0.45 * B, 0.04), 0.015, p.accent, sections=6)


def build_pommel_horse(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_pommel(b, L, B, H, p))


# ----------------------------------------------------------------- parallel bars
def sample_parallel_bars(rng, size, style):
    return make_params("parallel_bars", rng, size, style, GYM_WOOD, [DARK_METAL, "#c9ccd0", "#e8e6e0"],
                       ["#2d4f8a", "#b8322a"], mats=bool(rng.random() < 0.4))


def _draw_parallel(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: two long oval rails on four uprights over a low floor frame."""
    r = min(0.025, 0.05 * B, 0.02 * H)
    ys = (-0.38 * B, 0.38 * B)
    b.box((-0.42 * L, -B / 2, 0), (-0.36 * L, B / 2, 0.04 * H), p.secondary)
    b.box((0.36 * L, -B / 2, 0), (0.42 * L, B / 2, 0.04 * H), p.secondary)
    b.box((-0.4 * L, -0.04 * B, 0), (0.4 * L, 0.04 * B, 0.03 * H), p.secondary)
    for y in ys:
        b.rod((-L / 2, y, H - r), (L / 2, y, H - r), r, p.primary, sections=10)
        for x in (-0.3 * L, 0.3 * L):
            b.cyl(x, y, 0.03 * H, H - 2 * r, 0.025, p.secondary, sections=8)
            b.cyl(x, y, 0.3 * H, 0.75 * H, 0.035, lighter(p.secondary, 0.15), sections=8)
            b.rod((x, y, 0.02 * H), (x + (0.1 * L if x < 0 else -0.1 * L), y, 0.4 * H), 0.015, p.secondary)
        b.rod((-0.39 * L, y, 0.04 * H), (-0.3 * L, y, 0.04 * H), 0.02, p.secondary)
        b.rod((0.3 * L, y, 0.04 * H), (0.39 * L, y, 0.04 * H), 0.02, p.secondary)
    if p.mats:
        b.box((-0.25 * L, -B / 2, 0), (0.25 * L, B / 2, 0.02 * H), p.accent)


def build_parallel_bars(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_parallel(b, L, B, H, p))


# ----------------------------------------------------------------- wall bars
def sample_wall_bars(rng, size, style):
    return make_params("wall_bars", rng, size, style, GYM_WOOD + ["#c9a06a"], GYM_WOOD, METAL,
                       spacing=float(rng.choice([0.14, 0.15, 0.16])))


def build_wall_bars(p):
    """Swedish ladder: two wide stiles against the wall with round rungs all the way up,
    the top rung set forward."""
    w, d, h = p.size
    b = Builder()
    sw = min(0.08, 0.1 * w)
    for x in (-w / 2, w / 2 - sw):
        b.box((x, -d / 2, 0), (x + sw, d / 2 - 0.15 * d, h - 0.06 * h), p.primary)
        b.box((x, -d / 2, h - 0.06 * h), (x + sw, d / 2, h), p.primary)
    r = min(0.017, 0.15 * d, 0.3 * p.spacing)
    n = max(3, int(h / p.spacing))
    for k in range(1, n):
        z = k * (h - 0.08 * h) / n
        b.rod((-w / 2 + sw, 0.05 * d, z), (w / 2 - sw, 0.05 * d, z), r, p.secondary, sections=10)
    b.rod((-w / 2 + sw, d / 2 - r, h - 0.03 * h), (w / 2 - sw, d / 2 - r, h - 0.03 * h), r, p.secondary, sections=10)
    for z in (0.2 * h, 0.8 * h):
        for x in (-w / 2 + sw / 2, w / 2 - sw / 2):
            b.box((x - 0.01, -d / 2 - 0.0, z), (x + 0.01, -d / 2 + 0.02, z + 0.05), p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- pull-up bar
def sample_pull_up_bar(rng, size, style):
    return make_params("pull_up_bar", rng, size, style, [BLACK, "#2b2b2b", CHROME, "#3a3b3e"], BLACK, "#c0392b",
                       grips=bool(rng.random() < 0.5))


def build_pull_up_bar(p):
    """A wall-mounted pull-up bar: two wall plates with arms reaching out and up to a bar
    across, foam grips near its ends (and parallel grips)."""
    w, d, h = p.size
    b = Builder()
    r = min(0.016, 0.06 * h, 0.08 * d)
    by, bz = d / 2 - r, h - r
    for x in (-0.38 * w, 0.38 * w):
        b.box((x - 0.04, -d / 2, 0), (x + 0.04, -d / 2 + 0.012, h * 0.85), p.primary)
        b.hull([(x - 0.02, -d / 2, 0.05 * h), (x + 0.02, -d / 2, 0.05 * h), (x - 0.02, -d / 2, 0.55 * h),
                (x + 0.02, -d / 2, 0.55 * h), (x - 0.02, by, bz - 0.02), (x + 0.02, by, bz - 0.02),
                (x - 0.02, by - 0.03, bz + 0.0), (x + 0.02, by - 0.03, bz)], p.primary)
        for z in (0.15 * h, 0.65 * h):
            disc_y(b, x, -d / 2 + 0.012, -d / 2 + 0.02, z, 0.01, CHROME, sections=6)
    b.rod((-w / 2, by, bz), (w / 2, by, bz), r, p.primary, sections=10)
    for s in (-1, 1):
        b.rod((s * 0.45 * w, by, bz), (s * w / 2, by, bz), r * 1.4, p.secondary, sections=10)
        b.rod((s * 0.2 * w, by, bz), (s * 0.32 * w, by, bz), r * 1.4, p.secondary, sections=10)
    if p.grips:
        for s in (-1, 1):
            path(b, [(s * 0.1 * w, by, bz), (s * 0.1 * w, by - 0.3 * d, bz - 0.3 * h),
                     (s * 0.1 * w, -d / 2 + 0.1 * d, bz - 0.3 * h)], r * 0.8, p.accent, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dance pole
def sample_dance_pole(rng, size, style):
    return make_params("dance_pole", rng, size, style, [CHROME, "#c9a54a", "#b8733a", BLACK], CHROME, BLACK,
                       stage=bool(rng.random() < 0.3))


def build_dance_pole(p):
    """A fitness pole: a chrome pole between a floor base and a ceiling mount (on a low
    round stage, sometimes)."""
    w, d, h = p.size
    b = Builder()
    R = 0.5 * min(w, d)
    base = 0.02 * h
    if p.stage:
        b.cyl(0, 0, 0, 0.06 * h, R, p.accent, sections=24)
        base = 0.06 * h
        r_dome = 0.25 * R
    else:
        r_dome = 0.7 * R
    b.cyl(0, 0, 0, base + 0.01 * h, r_dome, p.secondary, r_top=0.6 * r_dome, sections=20)
    r = min(0.022, 0.2 * R)
    b.cyl(0, 0, base, h - 0.01 * h, r, p.primary, sections=16)
    for z in (0.33 * h, 0.66 * h):
        b.cyl(0, 0, z, z + 0.01 * h, 1.3 * r, p.secondary, sections=12)
    b.cyl(0, 0, h - 0.02 * h, h, 0.5 * r_dome + r, p.secondary, sections=16)
    return b.mesh(p.size)


# ----------------------------------------------------------------- basketball hoop
def sample_basketball_hoop(rng, size, style):
    return make_params("basketball_hoop", rng, size, style, ["#f4f4f2", "#e8e6e0", "#cfe0e6"],
                       ["#c0392b", BLACK, "#2d4f8a"], "#e8702a", ball=bool(rng.random() < 0.3))


def build_basketball_hoop(p):
    """A wall-mounted hoop: backboard with its border and shooting square, an orange rim
    on a bracket, and a net of cords tapering below it."""
    w, d, h = p.size
    b = Builder()
    by = -d / 2 + 0.12 * d
    bz0 = 0.3 * h
    b.box((-0.1 * w, -d / 2, 0.5 * h), (0.1 * w, by, 0.8 * h), DARK_METAL)  # wall bracket
    b.box((-w / 2, by, bz0), (w / 2, by + 0.04 * d, h), p.primary)
    t = 0.03 * w
    for lo, hi in (((-w / 2, bz0), (w / 2, bz0 + t)), ((-w / 2, h - t), (w / 2, h)), ((-w / 2, bz0), (-w / 2 + t, h)),
                   ((w / 2 - t, bz0), (w / 2, h))):
        b.box((lo[0], by + 0.04 * d, lo[1]), (hi[0], by + 0.045 * d, hi[1]), p.secondary)
    sq = 0.27 * w
    rz = bz0 + 0.2 * (h - bz0)
    for lo, hi in (((-sq / 2, rz), (sq / 2, rz + 0.012)), ((-sq / 2, rz + 0.45 * (h - bz0)),
                                                           (sq / 2, rz + 0.45 * (h - bz0) + 0.012)),
                   ((-sq / 2, rz), (-sq / 2 + 0.012, rz + 0.45 * (h - bz0))),
                   ((sq / 2 - 0.012, rz), (sq / 2, rz + 0.45 * (h - bz0)))):
        b.box((lo[0], by + 0.04 * d, lo[1]), (hi[0], by + 0.045 * d, hi[1]), p.secondary)
    R = min(0.22 * w, 0.38 * (d - 0.16 * d))
    cy = by + 0.06 * d + R
    b.box((-0.06 * w, by + 0.04 * d, rz - 0.03), (0.06 * w, cy - R + 0.01, rz), p.accent)
    b.torus((0, cy, rz), R, 0.012, p.accent, sections=24, minor_sections=5)
    n = 12
    bottom = max(0.02 * h, rz - 0.45 * h)
    for k in range(n):
        a = 2 * np.pi * k / n
        a2 = a + np.pi / n
        b.rod((R * np.cos(a), cy + R * np.sin(a), rz), (0.6 * R * np.cos(a2), cy + 0.6 * R * np.sin(a2), bottom),
              0.003, tint("#f4f4f2", "paint"), sections=3)
        b.rod((R * np.cos(a2 + np.pi / n), cy + R * np.sin(a2 + np.pi / n), rz),
              (0.6 * R * np.cos(a2), cy + 0.6 * R * np.sin(a2), bottom), 0.003, tint("#f4f4f2", "paint"), sections=3)
    b.torus((0, cy, (rz + bottom) / 2), 0.8 * R, 0.004, tint("#f4f4f2", "paint"), sections=16, minor_sections=3)
    b.torus((0, cy, bottom), 0.6 * R, 0.004, tint("#f4f4f2", "paint"), sections=16, minor_sections=3)
    if p.ball:
        b.sphere((0.3 * w, by + 0.06 * d + 0.12, 0.12), 0.12, tint("#d9702a", "paint"), subdivisions=2)
    return b.mesh(p.size)


# ----------------------------------------------------------------- trampoline
def sample_trampoline(rng, size, style):
    return make_params("trampoline", rng, size, style, [BLACK, "#2b2b2b"], ["#2d6fb0", "#3f8a4a", "#c0392b",
                                                                            "#e0b030", "#3a3b3e"], CHROME,
                       legs=int(rng.choice([4, 6, 8])))


def build_trampoline(p):
    """A round trampoline: a black mat inside a padded ring over the springs, on W-shaped
    legs."""
    w, d, h = p.size
    b = Builder()
    Rx, Ry = w / 2, d / 2
    top = h
    pad_h = min(0.06, 0.12 * h)
    scale = np.diag([1.0, Ry / Rx, 1.0, 1.0])
    b.lathe([[0.82 * Rx, top - pad_h], [Rx, top - pad_h], [Rx, top - 0.3 * pad_h], [0.97 * Rx, top],
             [0.84 * Rx, top], [0.8 * Rx, top - 0.3 * pad_h]], p.secondary, sections=36, transform=scale)
    b.cyl(0, 0, top - pad_h - 0.02, top - pad_h - 0.005, 0.84 * Rx, p.primary, ry=0.84 * Ry, sections=36)  # mat
    b.torus((0, 0, top - pad_h - 0.02), 0.95 * Rx, 0.02, p.accent, transform=scale, sections=36, minor_sections=4)
    n = p.legs
    for k in range(n):
        a = 2 * np.pi * (k + 0.5) / n
        for da in (-0.12, 0.12):
            x, y = 0.95 * Rx * np.cos(a + da), 0.95 * Ry * np.sin(a + da)
            b.rod((x, y, top - pad_h - 0.02), (x * 0.98, y * 0.98, 0.02), 0.02, p.accent, sections=6)
        x0, y0 = 0.95 * Rx * np.cos(a - 0.12), 0.95 * Ry * np.sin(a - 0.12)
        x1, y1 = 0.95 * Rx * np.cos(a + 0.12), 0.95 * Ry * np.sin(a + 0.12)
        b.rod((x0 * 0.98, y0 * 0.98, 0.02), (x1 * 0.98, y1 * 0.98, 0.02), 0.022, p.accent, sections=6)
    return b.mesh(p.size)


slot_roles("rowing_machine", "metal", "leather", "plastic")
register("rowing_machine", sample_rowing_machine, build_rowing_machine)
slot_roles("stair_climber", "metal", "rubber", "plastic")
register("stair_climber", sample_stair_climber, build_stair_climber)
slot_roles("cable_machine", "metal", "leather", "metal")
register("cable_machine", sample_cable_machine, build_cable_machine)
slot_roles("leg_press", "metal", "leather", "metal")
register("leg_press", sample_leg_press, build_leg_press)
slot_roles("ballet_barre", "wood", "metal", "metal")
register("ballet_barre", sample_ballet_barre, build_ballet_barre)
slot_roles("pommel_horse", "leather", "leather", "metal")
register("pommel_horse", sample_pommel_horse, build_pommel_horse)
slot_roles("parallel_bars", "wood", "metal", "paint")
register("parallel_bars", sample_parallel_bars, build_parallel_bars)
slot_roles("wall_bars", "wood", "wood", "metal")
register("wall_bars", sample_wall_bars, build_wall_bars)
slot_roles("pull_up_bar", "metal", "plastic", "rubber")
register("pull_up_bar", sample_pull_up_bar, build_pull_up_bar)
slot_roles("dance_pole", "metal", "metal", "plastic")
register("dance_pole", sample_dance_pole, build_dance_pole)
slot_roles("basketball_hoop", "plastic", "paint", "rubber")
register("basketball_hoop", sample_basketball_hoop, build_basketball_hoop)
slot_roles("trampoline", "metal", "fabric", "metal")
register("trampoline", sample_trampoline, build_trampoline)
