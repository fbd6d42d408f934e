"""Brewery, warehouse and factory: fermentation_tank, brew_kettle, pallet, forklift,
conveyor_belt."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    COPPER,
    GLOW_RED,
    STEEL,
    disc_y,
    path,
    wheel_x,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    METAL,
    Builder,
    darker,
    lengthwise,
    lighter,
    make_params,
    slot_roles,
    style_is,
    tint,
)
from anyhome.assets.registry import register

PALLET_WOOD = tint(["#d8bf98", "#c9a77c", "#e0cfae", "#bf9b6e"], "wood")
CARDBOARD = tint(["#c9a06a", "#b88a56", "#d4ac74"], "paper")
FORKLIFT = tint(["#e0b030", "#e8702a", "#c0392b", "#3f8a4a", "#2d6fb0"], "paint")


def _valve(b: Builder, x: float, y: float, z: float, r: float, handle: str = "#c0392b") -> None:
    """A butterfly valve on a pipe along y with a lever handle."""
    disc_y(b, x, y - r, y + r, z, 1.6 * r, STEEL, sections=10)
    b.box((x - 0.3 * r, y - 0.3 * r, z + 1.6 * r), (x + 3 * r, y + 0.3 * r, z + 2 * r), handle)


# ----------------------------------------------------------------- fermentation tank
def sample_fermentation_tank(rng, size, style):
    return make_params("fermentation_tank", rng, size, style, [STEEL, "#c9ccd0", "#b0b4b8"], CHROME, "#c0392b",
                       legs=int(rng.choice([3, 4])), jacket=int(rng.integers(2, 4)))


def build_fermentation_tank(p):
    """A cylindroconical fermenter: a steel cylinder with cooling jacket bands, a dished
    top with its manway and fittings, the cone below on splayed legs, a side manway on the
    cone, valves and the racking arm at the bottom."""
    w, d, h = p.size
    b = Builder()
    R = 0.45 * min(w, d)
    c0, c1 = 0.36 * h, 0.86 * h
    cone0 = 0.12 * h
    b.cyl(0, 0, c0, c1, R, p.primary, sections=28)
    for k in range(p.jacket):
        z = c0 + (k + 0.5) * (c1 - c0) / p.jacket - 0.06 * h
        b.cyl(0, 0, z, z + 0.12 * h, R * 1.01, darker(p.primary, 0.08), sections=28)
    b.cyl(0, 0, cone0, c0, 0.1 * R, p.primary, r_top=R, sections=28)
    b.lathe([[0, c1], [R, c1], [0.92 * R, c1 + 0.05 * h], [0.6 * R, c1 + 0.08 * h], [0, c1 + 0.09 * h]], p.primary,
            sections=28)
    b.cyl(0.3 * R, 0, c1 + 0.05 * h, h - 0.02 * h, 0.16 * R, p.secondary, sections=14)  # top manway
    b.cyl(0.3 * R, 0, h - 0.02 * h, h, 0.2 * R, p.secondary, sections=14)
    b.cyl(-0.35 * R, 0.1 * R, c1 + 0.05 * h, c1 + 0.12 * h, 0.05 * R, p.secondary, sections=8)  # relief valve
    disc_y(b, -0.35 * R, 0.1 * R - 0.05 * R, 0.1 * R + 0.05 * R, c1 + 0.13 * h, 0.1 * R, p.accent, sections=10)
    for k in range(p.legs):
        a = 2 * np.pi * k / p.legs + np.pi / 4
        top = (0.92 * R * np.cos(a), 0.92 * R * np.sin(a), c0 + 0.02 * h)
        foot = (0.98 * R * np.cos(a) * 1.0, 0.98 * R * np.sin(a), 0.0)
        b.rod(top, foot, 0.05 * R, p.primary, sections=10)
        b.cyl(foot[0], foot[1], 0, 0.01 * h, 0.1 * R, DARK_METAL, sections=8)
    ca = 0.55 * (c0 - cone0) + cone0  # side manway on the cone
    rr = 0.1 * R + (R - 0.1 * R) * (ca - cone0) / (c0 - cone0)
    b.rod((0, 0.8 * rr, ca), (0, rr + 0.08 * R, ca + 0.02 * h), 0.2 * R, p.secondary, sections=14)
    b.cyl(0, 0, cone0 - 0.05 * h, cone0, 0.07 * R, p.secondary, sections=10)
    _valve(b, 0, 0.05 * R, cone0 - 0.06 * h, 0.05 * R, p.accent)
    b.rod((0.5 * rr, -0.5 * rr, ca - 0.04 * h), (0.9 * R, -0.9 * R, ca - 0.06 * h), 0.04 * R, p.secondary,
          sections=8)  # racking arm
    disc_y(b, 0.7 * R, 0.7 * R, 0.74 * R, c0 + 0.25 * (c1 - c0), 0.08 * R, tint("#f4f1ea", "paint"), sections=12)  # gauge
    return b.mesh(p.size)


# ----------------------------------------------------------------- brew kettle
def sample_brew_kettle(rng, size, style):
    copper = style_is(style, "antique", "rustic") or rng.random() < 0.45
    return make_params("brew_kettle", rng, size, style, [COPPER, "#c07a40"] if copper else [STEEL, "#c9ccd0"],
                       [BRASS, CHROME] if copper else [CHROME, STEEL], "#c0392b", kind="copper" if copper else "steel")


def build_brew_kettle(p):
    """A brewhouse kettle: a big vessel on a low stand with a domed top, the vapour stack
    rising from it, a manway door with a sight glass, pipes and valves at the bottom; a
    traditional copper kettle or a clad steel one with its agitator motor."""
    w, d, h = p.size
    b = Builder()
    R = 0.45 * min(w, d)
    stand = 0.12 * h
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        b.cyl(0.85 * R * np.cos(a), 0.85 * R * np.sin(a), 0, stand, 0.06 * R, DARK_METAL, sections=8)
    b.cyl(0, 0, stand - 0.02 * h, stand, R * 0.95, DARK_METAL, sections=24)
    top = 0.62 * h
    b.lathe([[0, stand], [0.85 * R, stand], [R, stand + 0.06 * h], [R, top], [0, top]], p.primary, sections=32)
    if p.kind == "steel":
        for z in np.linspace(stand + 0.1 * h, top - 0.05 * h, 4):
            b.cyl(0, 0, z, z + 0.008 * h, 1.01 * R, darker(p.primary, 0.15), sections=32)
    dome_top = top + 0.2 * h
    b.lathe([[0, top], [R, top], [0.95 * R, top + 0.07 * h], [0.7 * R, top + 0.15 * h], [0.3 * R, dome_top],
             [0, dome_top]], p.primary if p.kind == "copper" else lighter(p.primary, 0.1), sections=32)
    b.cyl(0, 0, dome_top - 0.02 * h, h, 0.16 * R, p.primary, sections=16)  # vapour stack
    b.cyl(0, 0, h - 0.03 * h, h, 0.2 * R, p.secondary, sections=16)
    if p.kind == "copper":
        b.cyl(0, 0, top - 0.01 * h, top + 0.01 * h, 1.02 * R, p.secondary, sections=32)  # brass band
        b.cyl(0, 0, dome_top - 0.04 * h, dome_top - 0.02 * h, 0.35 * R, p.secondary, sections=16)
    else:
        b.box((0.2 * R, -0.15 * R, dome_top - 0.05 * h), (0.5 * R, 0.15 * R, dome_top + 0.06 * h), DARK_METAL)
        b.cyl(0.35 * R, 0, dome_top + 0.06 * h, dome_top + 0.1 * h, 0.12 * R, DARK_METAL, sections=10)
    # manway on the dome, facing the front
    mz = top + 0.08 * h
    b.rod((0, 0.7 * R, mz), (0, 0.9 * R, mz + 0.02 * h), 0.25 * R, p.secondary, sections=16)
    b.rod((0, 0.88 * R, mz + 0.02 * h), (0, 0.92 * R, mz + 0.025 * h), 0.18 * R, GLASS, sections=14)
    for x in (-0.45 * R, 0.45 * R):  # outlet pipes and valves
        path(b, [(x, 0.6 * R, stand + 0.04 * h), (x, R * 1.05, stand + 0.04 * h), (x, R * 1.05, 0.02 * h)],
             0.05 * R, p.secondary, sections=10)
        _valve(b, x, 0.95 * R, stand + 0.04 * h, 0.05 * R, p.accent)
    disc_y(b, 0.6 * R, 0.8 * R, 0.84 * R, 0.45 * h, 0.08 * R, tint("#f4f1ea", "paint"), sections=12)  # thermometer
    b.box((-R, -R, 0.3 * h), (-0.8 * R, -0.6 * R, 0.5 * h), tint("#3a3b3e", "paint"))  # control box
    b.box((-1.0 * R, -0.6 * R, 0.44 * h), (-0.95 * R, -0.59 * R, 0.46 * h), GLOW_RED)
    return b.mesh(p.size)


# ----------------------------------------------------------------- pallet
def sample_pallet(rng, size, style):
    return make_params("pallet", rng, size, style, PALLET_WOOD, PALLET_WOOD, "#3a3b3e",
                       boards=int(rng.choice([5, 7])), load=bool(rng.random() < 0.2))


def build_pallet(p):
    """A wooden pallet, or a stack of them when the box is tall: bottom boards, nine
    blocks (stamped), cross boards and a deck of top boards; sometimes a wrapped load of
    boxes on the top one."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    unit = 0.144
    load_h = 0.0
    n = max(1, int(round(h / unit)))
    if p.load and h > 2.5 * unit:
        n = max(1, int(round(0.3 * h / unit)))
        load_h = h - n * unit
    ph = (h - load_h) / n
    t = 0.15 * ph  # board thickness
    for k in range(n):
        z0 = k * ph
        tone = PALLET_WOOD[int(rng.integers(len(PALLET_WOOD)))] if k else p.primary
        for y in (-d / 2, -0.05 * d, d / 2 - 0.1 * d):  # bottom boards
            b.box((-w / 2, y, z0), (w / 2, y + 0.1 * d, z0 + t), tone)
        for x in (-w / 2, -0.06 * w, w / 2 - 0.12 * w):  # blocks
            for y in (-d / 2, -0.06 * d, d / 2 - 0.12 * d):
                b.box((x, y, z0 + t), (x + 0.12 * w, y + 0.12 * d, z0 + ph - 2 * t), darker(tone, 0.12))
                b.box((x + 0.03 * w, y + 0.12 * d, z0 + 0.45 * ph), (x + 0.09 * w, y + 0.12 * d + 0.002,
                                                                    z0 + 0.65 * ph), p.accent)
        for x in (-w / 2, -0.06 * w, w / 2 - 0.12 * w):  # cross boards
            b.box((x, -d / 2, z0 + ph - 2 * t), (x + 0.12 * w, d / 2, z0 + ph - t), tone)
        m = p.boards
        bw = d / m * 0.7
        for i in range(m):  # deck boards
            y = -d / 2 + i * (d - bw) / (m - 1)
            b.box((-w / 2, y, z0 + ph - t), (w / 2, y + bw, z0 + ph), lighter(tone, 0.05) if i % 2 else tone)
    if load_h > 0:
        z0 = h - load_h
        for i in range(2):
            for j in range(2):
                x0, y0 = -w / 2 + i * w / 2, -d / 2 + j * d / 2
                b.box((x0 + 0.01, y0 + 0.01, z0), (x0 + w / 2 - 0.01, y0 + d / 2 - 0.01, h - 0.01),
                      CARDBOARD[(i + j) % 3])
        b.box((-w / 2, -d / 2, z0 + 0.02), (w / 2, d / 2, h), tint("#dfe6ea", "paint"), alpha=90)  # stretch wrap
    return b.mesh(p.size)


# ----------------------------------------------------------------- forklift
def sample_forklift(rng, size, style):
    return make_params("forklift", rng, size, style, FORKLIFT, [BLACK, "#2b2b2b"], DARK_METAL,
                       forks_up=float(rng.uniform(0.0, 0.3)))


def build_forklift(p):
    """A counterbalance forklift facing +y: body with the heavy counterweight at the back,
    big front and small rear wheels, seat and steering wheel under the overhead guard, and
    the mast at the front with the carriage and two fork tines."""
    w, d, h = p.size
    b = Builder()
    Rf, Rr = 0.16 * h, 0.12 * h
    yf, yr = 0.15 * d, -0.32 * d
    for s in (-1, 1):
        wheel_x(b, s * (w / 2 - 0.09 * w), yf, Rf, Rf, 0.18 * w, tint(BLACK, "rubber"), METAL)
        wheel_x(b, s * (w / 2 - 0.1 * w), yr, Rr, Rr, 0.15 * w, tint(BLACK, "rubber"), METAL)
    b.box((-0.4 * w, -0.38 * d, 0.08 * h), (0.4 * w, 0.22 * d, 0.3 * h), p.primary)  # chassis
    b.box((-0.48 * w, 0.02 * d, 0.2 * h), (0.48 * w, 0.25 * d, 0.26 * h), p.primary)  # fenders
    b.box((-0.48 * w, -0.42 * d, 0.2 * h), (0.48 * w, -0.2 * d, 0.27 * h), p.primary)
    b.hull([(-0.45 * w, -0.5 * d, 0.1 * h), (0.45 * w, -0.5 * d, 0.1 * h), (-0.45 * w, -0.3 * d, 0.1 * h),
            (0.45 * w, -0.3 * d, 0.1 * h), (-0.42 * w, -0.48 * d, 0.42 * h), (0.42 * w, -0.48 * d, 0.42 * h),
            (-0.42 * w, -0.28 * d, 0.44 * h), (0.42 * w, -0.28 * d, 0.44 * h)], p.accent)  # counterweight
    b.box((-0.35 * w, -0.3 * d, 0.3 * h), (0.35 * w, 0.05 * d, 0.38 * h), darker(p.primary, 0.15))  # hood
    b.box((-0.25 * w, -0.25 * d, 0.38 * h), (0.25 * w, -0.12 * d, 0.44 * h), p.secondary)  # seat
    b.box((-0.25 * w, -0.28 * d, 0.44 * h), (0.25 * w, -0.25 * d, 0.6 * h), p.secondary)
    b.box((-0.3 * w, 0.05 * d, 0.3 * h), (0.3 * w, 0.15 * d, 0.5 * h), p.primary)  # dash
    b.rod((0, 0.1 * d, 0.5 * h), (0, 0.04 * d, 0.58 * h), 0.02, BLACK, sections=6)
    b.torus((0, 0.04 * d, 0.58 * h), 0.13, 0.015, BLACK, sections=16, minor_sections=4)
    gt = min(0.04, 0.05 * w)
    for x in (-0.42 * w, 0.42 * w):  # overhead guard
        b.rod((x, -0.3 * d, 0.4 * h), (x, -0.28 * d, h - 0.03 * h), gt, DARK_METAL, sections=8)
        b.rod((x, 0.14 * d, 0.45 * h), (x, 0.08 * d, h - 0.03 * h), gt, DARK_METAL, sections=8)
        b.rod((x, -0.28 * d, h - 0.03 * h), (x, 0.08 * d, h - 0.03 * h), gt, DARK_METAL, sections=8)
    for k in range(5):
        y = -0.28 * d + k * 0.36 * d / 4
        b.rod((-0.42 * w, y, h - 0.03 * h), (0.42 * w, y, h - 0.03 * h), 0.6 * gt, DARK_METAL, sections=6)
    b.cyl(0.3 * w, -0.25 * d, h - 0.03 * h, h, 0.04, tint("#f08a2a", "paint"), sections=8)  # beacon
    my = 0.27 * d  # mast
    for x in (-0.32 * w, 0.32 * w):
        b.box((x - 0.04 * w, my - 0.03 * d, 0.05 * h), (x + 0.04 * w, my + 0.03 * d, 0.96 * h), p.accent)
    for z in (0.3 * h, 0.94 * h):
        b.box((-0.36 * w, my - 0.02 * d, z - 0.02 * h), (0.36 * w, my + 0.02 * d, z), p.accent)
    b.cyl(0, my - 0.03 * d, 0.1 * h, 0.8 * h, 0.04, CHROME, sections=8)
    cz = 0.03 * h + p.forks_up * 0.5 * h
    b.box((-0.4 * w, my + 0.03 * d, cz), (0.4 * w, my + 0.05 * d, cz + 0.25 * h), DARK_METAL)  # carriage
    for x in (-0.25 * w, 0.25 * w):
        b.box((x - 0.05 * w, my + 0.05 * d, cz), (x + 0.05 * w, my + 0.07 * d, cz + 0.2 * h), DARK_METAL)
        b.box((x - 0.05 * w, my + 0.05 * d, cz), (x + 0.05 * w, d / 2, cz + 0.02 * h), DARK_METAL)  # tines
    for x in (-0.35 * w, 0.35 * w):
        disc_y(b, x, 0.22 * d, 0.23 * d, 0.45 * h, 0.03, tint("#fff1c4", "light"), sections=8)
    return b.mesh(p.size)


# ----------------------------------------------------------------- conveyor belt
def sample_conveyor_belt(rng, size, style):
    return make_params("conveyor_belt", rng, size, style, [STEEL, "#9a9da3", "#3a5a8a", "#e0b030", "#3f6b4a"],
                       ["#2b2b2b", "#3a3b3e", "#1f1f22"], CARDBOARD, kind=str(rng.choice(["belt", "belt", "rollers"])),
                       boxes=int(rng.integers(1, 5)))


def _draw_conveyor(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: legs with braces, side frames, the belt (or rollers) between end drums,
    a motor under one end and parcels riding on it."""
    rng = np.random.default_rng(p.seed)
    top = 0.82 * H
    fr = 0.08 * H
    n = max(2, int(L / 1.3) + 1)
    for x in np.linspace(-L / 2 + 0.06 * L / n, L / 2 - 0.06 * L / n, n):
        for y in (-0.4 * B, 0.4 * B):
            b.box((x - 0.025, y - 0.025, 0), (x + 0.025, y + 0.025, top - fr), p.primary)
            b.box((x - 0.04, y - 0.04, 0), (x + 0.04, y + 0.04, 0.015), DARK_METAL)
        b.box((x - 0.015, -0.4 * B, 0.25 * top), (x + 0.015, 0.4 * B, 0.25 * top + 0.03), p.primary)
    for y in (-0.46 * B, 0.42 * B):  # side frames
        b.box((-L / 2, y, top - fr), (L / 2, y + 0.04 * B, top + 0.01), p.primary)
    if p.kind == "rollers":
        m = max(6, int(L / 0.1))
        for k in range(m):
            x = -L / 2 + (k + 0.5) * L / m
            b.rod((x, -0.42 * B, top - 0.02), (x, 0.42 * B, top - 0.02), min(0.025, 0.35 * L / m), tint("#c9ccd0", "metal"),
                  sections=8)
    else:
        b.box((-L / 2 + 0.04, -0.42 * B, top - 0.03), (L / 2 - 0.04, 0.42 * B, top), p.secondary)
        for x in (-L / 2 + 0.04, L / 2 - 0.04):
            b.rod((x, -0.42 * B, top - 0.04), (x, 0.42 * B, top - 0.04), 0.04, p.secondary, sections=12)
        b.box((-L / 2 + 0.04, -0.42 * B, top - fr + 0.01), (L / 2 - 0.04, 0.42 * B, top - fr + 0.02), p.secondary)
    for y in (-0.46 * B, 0.46 * B):  # guide rails
        for x in np.linspace(-0.4 * L, 0.4 * L, 4):
            b.box((x - 0.01, y - 0.01, top), (x + 0.01, y + 0.01, H - 0.03 * H), METAL)
        b.rod((-L / 2, y, H - 0.03 * H), (L / 2, y, H - 0.03 * H), 0.015, tint("#c9ccd0", "metal"), sections=6)
    mx = L / 2 - 0.1 * L
    b.box((mx - 0.1, -0.3 * B, top - fr - 0.25 * H), (mx + 0.1, 0.1 * B, top - fr), DARK_METAL)  # motor
    disc_y(b, mx, 0.1 * B, 0.2 * B, top - fr - 0.12 * H, 0.08, tint("#3a5a8a", "paint"), sections=12)
    slots = np.linspace(-0.38 * L, 0.38 * L, max(1, p.boxes))
    for x in slots:
        bw = rng.uniform(0.25, 0.45) * B
        bh = rng.uniform(0.1, 0.18)
        b.box((x - 0.6 * bw, -bw / 2, top), (x + 0.6 * bw, bw / 2, top + bh), CARDBOARD[int(rng.integers(3))])
        b.box((x - 0.6 * bw, -0.03, top + bh), (x + 0.6 * bw, 0.03, top + bh + 0.002), tint("#c9b890", "paint"))  # tape


def build_conveyor_belt(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_conveyor(b, L, B, H, p))


slot_roles("fermentation_tank", "metal", "metal", "paint")
register("fermentation_tank", sample_fermentation_tank, build_fermentation_tank)
slot_roles("brew_kettle", "metal", "metal", "paint")
register("brew_kettle", sample_brew_kettle, build_brew_kettle)
slot_roles("pallet", "wood", "wood", "metal")
register("pallet", sample_pallet, build_pallet)
slot_roles("forklift", "paint", "rubber", "metal")
register("forklift", sample_forklift, build_forklift)
slot_roles("conveyor_belt", "metal", "rubber", "paper")
register("conveyor_belt", sample_conveyor_belt, build_conveyor_belt)
