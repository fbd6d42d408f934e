"""Household and building utilities: radiator, water_heater, air_conditioner, generator,
trash_can, ironing_board, towel_rack, urinal, ladder, coat_hook, mailbox, wall_sconce,
room_divider, safe, acoustic_panel."""

from __future__ import annotations

import numpy as np
import trimesh

from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    COPPER,
    GLOW_GREEN,
    STEEL,
    WHITE_PLASTIC,
    disc_x,
    disc_y,
    path,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    FABRICS,
    GLASS,
    METAL,
    Builder,
    about,
    darker,
    lengthwise,
    lighter,
    make_params,
    move,
    rot_x,
    rot_z,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

TOWELS = tint(["#f4f1ea", "#c6e0f4", "#e8dcc0", "#5f6b7a", "#d9a0a0", "#7d8c74", "#2d4f8a"], "fabric")
PAPER = tint("#f4efe0", "paper")
FLAME = tint("#ffb030", "light")
BULB = tint("#fff1c4", "light")


# ----------------------------------------------------------------- radiator
def sample_radiator(rng, size, style):
    panel = style_is(style, "modern") and rng.random() < 0.6
    iron = style_is(style, "antique", "rustic", "industrial")
    return make_params("radiator", rng, size, style, ["#4a4c50", "#2b2b2b", "#8a7a6a"] if iron else
                       [WHITE_PLASTIC, "#f4f4f2", "#3a3b3e", "#e8e6e0"], CHROME, BRASS if iron else CHROME,
                       kind="panel" if panel else "column")


def build_radiator(p):
    """A column radiator (a row of rounded sections joined top and bottom, on feet, with
    a valve at one end) or a flat panel radiator with a grille on top."""
    w, d, h = p.size
    b = Builder()
    foot = 0.1 * h
    if p.kind == "panel":
        b.box((-w / 2, -d / 2 + 0.2 * d, foot), (w / 2, d / 2, h - 0.02 * h), p.primary)
        fins = int(min(60, max(4, w / 0.05)))
        for k in range(fins):
            x = -w / 2 + (k + 0.5) * w / fins
            b.box((x - 0.004, d / 2, foot + 0.02 * h), (x + 0.004, d / 2 + 0.003, h - 0.04 * h), darker(p.primary, 0.06))
        b.box((-w / 2 + 0.01, -d / 2 + 0.2 * d, h - 0.02 * h), (w / 2 - 0.01, d / 2 - 0.01, h), darker(p.primary, 0.3))
        for x in (-0.4 * w, 0.4 * w):
            b.box((x - 0.02, -d / 2, 0.6 * h), (x + 0.02, -d / 2 + 0.2 * d, 0.7 * h), DARK_METAL)
        b.cyl(w / 2 - 0.03, 0, 0, foot, 0.012, p.secondary, sections=8)
        return b.mesh(p.size)
    n = min(40, max(4, int(w / 0.055)))
    sw = w / n
    for k in range(n):
        x = -w / 2 + (k + 0.5) * sw
        for y in (-0.22 * d, 0.22 * d):
            b.cyl(x, y, foot + 0.03 * h, h - 0.05 * h, 0.38 * sw, p.primary, ry=0.25 * d, sections=8)
            b.cyl(x, y, h - 0.05 * h, h, 0.38 * sw, p.primary, ry=0.25 * d, r_top=0.2 * sw, sections=8)
            b.cyl(x, y, foot, foot + 0.03 * h, 0.2 * sw, p.primary, ry=0.13 * d, r_top=0.38 * sw, sections=8)
    for z in (foot + 0.06 * h, h - 0.1 * h):  # headers
        disc_x(b, -w / 2 + 0.2 * sw, w / 2 - 0.2 * sw, 0, z, 0.3 * d, darker(p.primary, 0.1), sections=10)
    for x in (-w / 2 + 1.5 * sw, w / 2 - 1.5 * sw):  # feet
        b.box((x - 0.3 * sw, -0.45 * d, 0), (x + 0.3 * sw, 0.45 * d, foot + 0.04 * h), p.primary)
    disc_x(b, w / 2 - 0.2 * sw, w / 2, 0, foot + 0.06 * h, 0.15 * d, p.secondary, sections=8)  # valve
    b.cyl(w / 2 - 0.1 * sw, 0, foot + 0.06 * h, foot + 0.16 * h, 0.2 * d, p.accent, sections=8)
    b.cyl(w / 2 - 0.1 * sw, 0, 0, foot + 0.06 * h, 0.1 * d, p.secondary, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- water heater
def sample_water_heater(rng, size, style):
    return make_params("water_heater", rng, size, style, [WHITE_PLASTIC, "#e8e6e0", "#c9ccd0", "#5f7fa0", "#d9d3c7"],
                       COPPER, "#e0b030", gas=bool(rng.random() < 0.5))


def build_water_heater(p):
    """A hot water tank: a tall white cylinder on little feet with copper pipes (cold,
    hot) rising from its top, a relief valve and drain pipe, the thermostat at the bottom
    and, on a gas heater, the flue with its draft hood."""
    w, d, h = p.size
    b = Builder()
    R = 0.45 * min(w, d)
    top = 0.82 * h
    for a in (0.5, 2.6, 4.7):
        b.cyl(0.7 * R * np.cos(a), 0.7 * R * np.sin(a), 0, 0.03 * h, 0.03, DARK_METAL, sections=6)
    b.cyl(0, 0, 0.03 * h, top, R, p.primary, sections=24)
    b.lathe([[0, top], [R, top], [0.9 * R, top + 0.04 * h], [0.5 * R, top + 0.06 * h], [0, top + 0.06 * h]],
            p.primary, sections=24)
    b.cyl(0, 0, 0.03 * h, 0.05 * h, 1.01 * R, darker(p.primary, 0.2), sections=24)
    b.box((-0.18 * R, 0.93 * R, 0.45 * h), (0.18 * R, R + 0.005, 0.6 * h), p.accent)  # label
    b.box((-0.2 * R, 0.9 * R, 0.1 * h), (0.2 * R, R + 0.06, 0.2 * h), BLACK)  # thermostat
    disc_y(b, 0, R + 0.06, R + 0.08, 0.15 * h, 0.06, tint("#c0392b", "paint"), sections=10)
    for x, col in ((-0.45 * R, "#2e74c8"), (0.45 * R, "#d63a2a")):
        b.cyl(x, 0.1 * R, top + 0.02 * h, h, 0.025, p.secondary, sections=8)
        disc_x(b, x - 0.04, x + 0.04, 0.1 * R, top + 0.12 * h, 0.03, col, sections=8, role="plastic")
    b.rod((0.95 * R, -0.2 * R, top - 0.05 * h), (R + 0.05, -0.2 * R, top - 0.05 * h), 0.02, CHROME, sections=6)
    b.rod((R + 0.05, -0.2 * R, top - 0.05 * h), (R + 0.05, -0.2 * R, 0.1 * h), 0.012, p.secondary, sections=6)
    if p.gas:
        b.cyl(0, -0.2 * R, top + 0.06 * h, top + 0.1 * h, 0.3 * R, DARK_METAL, r_top=0.15 * R, sections=12)
        b.cyl(0, -0.2 * R, top + 0.1 * h, h, 0.12 * R, tint("#9a9da3", "metal"), sections=12)
    else:
        b.box((-0.25 * R, 0.92 * R, 0.68 * h), (0.25 * R, R + 0.005, 0.76 * h), lighter(p.primary, 0.2))
    return b.mesh(p.size)


# ----------------------------------------------------------------- air conditioner
def sample_air_conditioner(rng, size, style):
    return make_params("air_conditioner", rng, size, style, [WHITE_PLASTIC, "#f4f4f2", "#e8e6e0", "#2b2b2b",
                                                            "#c9ccd0"], "#9a9da3", [GLOW_GREEN, "#4ab0e0"],
                       flap=float(rng.uniform(0.2, 0.7)))


def build_air_conditioner(p):
    """A wall-mounted split unit: a long body rounded at the front, an air outlet along
    the bottom with its louvre flap, a small display."""
    w, d, h = p.size
    b = Builder()
    prof = [(-d / 2, 0.2 * h), (-d / 2, h), (0.15 * d, h)]
    prof += [(0.15 * d + 0.35 * d * np.sin(a), 0.5 * h + 0.5 * h * np.cos(a)) for a in np.linspace(0.3, 2.3, 8)]
    prof += [(0.1 * d, 0.02 * h), (-0.2 * d, 0.05 * h)]
    prof = [(min(y, d / 2), max(min(z, h), 0.0)) for y, z in prof]
    b.extrude_x(prof, -w / 2, w / 2, p.primary)
    b.extrude_x(prof, -w / 2 - 0.005, -w / 2 + 0.0, darker(p.primary, 0.08))
    b.box((-0.45 * w, -0.1 * d, 0.04 * h), (0.45 * w, 0.2 * d, 0.2 * h), tint("#3a3b3e", "paint"))  # outlet
    hinge = (0, 0.2 * d, 0.12 * h)
    b.box((-0.44 * w, 0.2 * d, 0.1 * h), (0.44 * w, 0.45 * d, 0.13 * h), lighter(p.primary, 0.05),
          transform=about(rot_x(-p.flap), hinge))
    b.box((0.25 * w, 0.4 * d, 0.55 * h), (0.35 * w, 0.48 * d, 0.65 * h), BLACK)
    b.box((0.27 * w, 0.47 * d, 0.58 * h), (0.3 * w, 0.5 * d, 0.62 * h), p.accent)
    b.box((-0.45 * w, -d / 2, 0.85 * h), (0.45 * w, 0.1 * d, 0.86 * h), darker(p.primary, 0.1))  # intake seam
    return b.mesh(p.size)


# ----------------------------------------------------------------- generator
def sample_generator(rng, size, style):
    return make_params("generator", rng, size, style, ["#e0b030", "#c0392b", "#e8702a", "#2d6fb0", "#3f8a4a"],
                       [BLACK, "#2b2b2b"], DARK_METAL, wheels=bool(rng.random() < 0.7))


def build_generator(p):
    """A portable generator in its tube cage: engine with its pull starter, the alternator,
    a bright fuel tank on top with a cap, a panel of outlets, and wheels and a handle."""
    w, d, h = p.size
    b = Builder()
    r = min(0.025, 0.03 * min(w, h))
    wr = 0.17 * h if p.wheels else 0.0
    z0 = max(wr * 0.6, 0.04 * h)
    x0, x1, y0, y1 = -w / 2 + r, w / 2 - r, -d / 2 + r, d / 2 - r
    zt = h - r
    for y in (y0, y1):  # cage loops
        path(b, [(x0, y, z0), (x0, y, zt), (x1, y, zt), (x1, y, z0), (x0, y, z0)], r, p.secondary, sections=8)
    for x in (x0, x1):
        for z in (z0, zt):
            b.rod((x, y0, z), (x, y1, z), r, p.secondary, sections=8)
    b.box((-0.4 * w, -0.35 * d, z0), (0.05 * w, 0.3 * d, 0.62 * h), p.accent)  # engine
    for k in range(4):
        z = 0.35 * h + k * 0.06 * h
        b.box((-0.42 * w, -0.3 * d, z), (-0.38 * w, 0.25 * d, z + 0.025 * h), darker(p.accent, 0.3))
    disc_x(b, -0.44 * w, -0.4 * w, 0.0, 0.45 * h, 0.14 * h, p.primary, sections=16)  # recoil starter
    b.box((-0.46 * w, -0.02, 0.55 * h), (-0.44 * w, 0.02, 0.6 * h), BLACK)
    disc_x(b, 0.05 * w, 0.4 * w, -0.05 * d, 0.4 * h, 0.2 * h, p.primary, sections=18)  # alternator
    b.box((0.05 * w, 0.3 * d, 0.25 * h), (0.38 * w, y1, 0.6 * h), BLACK)  # control panel
    for i in range(2):
        disc_y(b, 0.14 * w + i * 0.14 * w, y1, y1 + 0.01, 0.38 * h, 0.035 * h, tint("#e8e6e0", "paint"), sections=10)
    b.box((0.12 * w, y1, 0.5 * h), (0.18 * w, y1 + 0.01, 0.55 * h), tint("#c0392b", "paint"))
    b.hull([(-0.42 * w, -0.38 * d, 0.64 * h), (0.42 * w, -0.38 * d, 0.64 * h), (-0.42 * w, 0.38 * d, 0.64 * h),
            (0.42 * w, 0.38 * d, 0.64 * h), (-0.38 * w, -0.34 * d, zt - r), (0.38 * w, -0.34 * d, zt - r),
            (-0.38 * w, 0.34 * d, zt - r), (0.38 * w, 0.34 * d, zt - r)], p.primary)  # fuel tank
    b.cyl(0.15 * w, 0.0, zt - r, zt + 0.3 * r, 0.05 * h, BLACK, sections=12)
    b.rod((0.1 * w, -d / 2 + 0.05, 0.3 * h), (0.3 * w, -d / 2 + 0.05, 0.3 * h), 0.05 * h, tint("#9a9da3", "metal"))  # muffler
    if p.wheels:
        for y in (y0 - 0.01, y1 + 0.01):
            disc_y(b, x0 + 0.1 * w, y - 0.04, y + 0.04, wr, wr, BLACK, sections=16)
            disc_y(b, x0 + 0.1 * w, y - 0.045, y + 0.045, wr, 0.5 * wr, tint("#9a9da3", "metal"), sections=12)
    return b.mesh(p.size)


# ----------------------------------------------------------------- trash can
def sample_trash_can(rng, size, style):
    w, d, h = size
    kinds = ["pedal", "swing", "basket"] if h < 0.95 else ["wheelie", "pedal"]
    return make_params("trash_can", rng, size, style, [STEEL, BLACK, WHITE_PLASTIC, "#3f8a4a", "#2d6fb0", "#5f6b7a"],
                       [BLACK, "#2b2b2b", "#9a9da3"], "#3a3b3e", kind=str(rng.choice(kinds)))


def build_trash_can(p):
    """A bin: a round pedal bin with a domed lid, a square swing-top bin, an open
    wastebasket with a liner, or (in a tall box) a wheelie bin."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "pedal":
        R = 0.45 * min(w, d)
        sy = 0.45 * d / R
        sc = np.diag([0.45 * w / R, sy, 1.0, 1.0])
        b.cyl(0, 0, 0.02 * h, 0.9 * h, 0.95 * R, p.primary, r_top=R, sections=24, transform=sc)
        b.cyl(0, 0, 0, 0.04 * h, 0.9 * R, p.secondary, sections=24, transform=sc)
        b.lathe([[0, 0.9 * h], [1.02 * R, 0.9 * h], [0.98 * R, 0.94 * h], [0.6 * R, h], [0, h]], p.primary,
                sections=24, transform=sc)
        b.cyl(0, 0, 0.9 * h, 0.91 * h, 1.03 * R, p.secondary, sections=24, transform=sc)
        b.box((-0.2 * R, 0.9 * R * sy, 0.0), (0.2 * R, d / 2, 0.04 * h), p.secondary)  # pedal
        return b.mesh(p.size)
    if p.kind == "swing":
        b.hull([(-0.42 * w, -0.42 * d, 0), (0.42 * w, -0.42 * d, 0), (-0.42 * w, 0.42 * d, 0), (0.42 * w, 0.42 * d, 0),
                (-w / 2, -d / 2, 0.78 * h), (w / 2, -d / 2, 0.78 * h), (-w / 2, d / 2, 0.78 * h),
                (w / 2, d / 2, 0.78 * h)], p.primary)
        b.hull([(-w / 2, -d / 2, 0.78 * h), (w / 2, -d / 2, 0.78 * h), (-w / 2, d / 2, 0.78 * h),
                (w / 2, d / 2, 0.78 * h), (-0.45 * w, -0.2 * d, h), (0.45 * w, -0.2 * d, h),
                (-0.45 * w, 0.1 * d, h), (0.45 * w, 0.1 * d, h)], p.secondary)
        b.box((-0.35 * w, 0.1 * d, 0.82 * h), (0.35 * w, 0.15 * d + 0.01, 0.97 * h), darker(p.secondary, 0.4))
        return b.mesh(p.size)
    if p.kind == "wheelie":
        b.hull([(-0.42 * w, -0.35 * d, 0.05 * h), (0.42 * w, -0.35 * d, 0.05 * h), (-0.42 * w, 0.42 * d, 0.05 * h),
                (0.42 * w, 0.42 * d, 0.05 * h), (-w / 2, -0.42 * d, 0.9 * h), (w / 2, -0.42 * d, 0.9 * h),
                (-w / 2, d / 2, 0.9 * h), (w / 2, d / 2, 0.9 * h)], p.primary)
        b.box((-w / 2, -d / 2, 0.9 * h), (w / 2, d / 2, h - 0.04 * h), p.primary)
        b.box((-w / 2, -0.42 * d, h - 0.05 * h), (w / 2, d / 2 + 0.0, h), darker(p.primary, 0.15))  # lid
        b.rod((-0.45 * w, -d / 2 + 0.02, 0.9 * h), (0.45 * w, -d / 2 + 0.02, 0.9 * h), 0.02, BLACK, sections=8)
        for x in (-0.4 * w, 0.4 * w):
            disc_x(b, x - 0.03, x + 0.03, -0.35 * d, 0.1 * h, 0.1 * h, BLACK, sections=14)
        return b.mesh(p.size)
    R = 0.48 * min(w, d)  # open wastebasket with a liner
    sc = np.diag([0.48 * w / R, 0.48 * d / R, 1.0, 1.0])
    b.lathe([[0, 0], [0.78 * R, 0], [R, 0.94 * h], [0.96 * R, 0.94 * h], [0.75 * R, 0.04 * h], [0, 0.04 * h]],
            p.primary, sections=24, transform=sc)
    b.cyl(0, 0, 0.93 * h, h, 1.01 * R, p.accent, r_top=1.04 * R, sections=24, transform=sc)
    return b.mesh(p.size)


# ----------------------------------------------------------------- ironing board
def sample_ironing_board(rng, size, style):
    return make_params("ironing_board", rng, size, style, ["#c6e0f4", "#e8dcc0", "#d9a0a0", "#7d8c74", "#5f6b7a",
                                                          "#f4f1ea"], [CHROME, WHITE_PLASTIC, BLACK],
                       ["#2d6fb0", "#e8e6e0", "#c0392b"], iron=bool(rng.random() < 0.7))


def _draw_ironing_board(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the board (square end at -x, pointed nose at +x) with its cover, crossed
    legs, a wire iron rest at the square end and an iron on it."""
    top = H - (0.12 * H if p.iron else 0.0)
    th = min(0.03, 0.05 * H)
    x0, x1 = -0.36 * L, L / 2
    outline = [(x0, -0.42 * B), (0.15 * L, -0.42 * B), (0.35 * L, -0.3 * B), (0.46 * L, -0.12 * B), (x1, 0.0),
               (0.46 * L, 0.12 * B), (0.35 * L, 0.3 * B), (0.15 * L, 0.42 * B), (x0, 0.42 * B)]
    b.hull([(x, y, top - th) for x, y in outline] + [(x, y, top - 0.4 * th) for x, y in outline], p.secondary)
    b.hull([(x * 0.99, y * 1.02, top - 0.5 * th) for x, y in outline] + [(x * 0.99, y * 1.02, top) for x, y in outline],
           p.primary)
    for y in (-0.3 * B, 0.3 * B):  # crossed legs
        b.rod((-0.2 * L, y, top - th), (0.25 * L, y, 0.02), 0.012, p.secondary, sections=6)
        b.rod((0.25 * L, y, top - th), (-0.2 * L, y, 0.02), 0.012, p.secondary, sections=6)
    for x in (-0.2 * L, 0.25 * L):
        b.rod((x, -0.42 * B, 0.015), (x, 0.42 * B, 0.015), 0.015, BLACK, sections=6)
    b.rod((0.025 * L, -0.32 * B, 0.42 * top), (0.025 * L, 0.32 * B, 0.42 * top), 0.008, p.secondary, sections=6)
    path(b, [(x0, -0.35 * B, top - th), (-L / 2, -0.35 * B, top - th), (-L / 2, 0.35 * B, top - th),
             (x0, 0.35 * B, top - th)], 0.006, p.secondary, sections=5)  # iron rest
    if p.iron:
        ix = -0.43 * L
        b.hull([(ix - 0.07 * L, -0.12 * B, top - th), (ix + 0.05 * L, -0.12 * B, top - th),
                (ix - 0.07 * L, 0.12 * B, top - th), (ix + 0.05 * L, 0.12 * B, top - th),
                (ix + 0.07 * L, 0.0, top - th), (ix - 0.06 * L, -0.1 * B, top - th + 0.05 * H),
                (ix + 0.04 * L, -0.1 * B, top - th + 0.05 * H), (ix - 0.06 * L, 0.1 * B, top - th + 0.05 * H),
                (ix + 0.04 * L, 0.1 * B, top - th + 0.05 * H)], p.accent)
        path(b, [(ix - 0.05 * L, 0, top - th + 0.05 * H), (ix - 0.04 * L, 0, H), (ix + 0.03 * L, 0, H),
                 (ix + 0.03 * L, 0, top - th + 0.05 * H)], 0.012, BLACK, sections=6)


def build_ironing_board(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_ironing_board(b, L, B, H, p))


# ----------------------------------------------------------------- towel rack
def sample_towel_rack(rng, size, style):
    return make_params("towel_rack", rng, size, style, [CHROME, WHITE_PLASTIC, BLACK, BRASS], TOWELS, TOWELS,
                       kind=str(rng.choice(["rail", "ladder"])))


def build_towel_rack(p):
    """A towel rail on wall brackets with a towel folded over it, or a heated towel ladder
    (two stiles and many rungs) with a towel over one rung."""
    w, d, h = p.size
    b = Builder()
    r = min(0.012, 0.1 * d, 0.03 * h)
    fy = d / 2 - 2.5 * r
    if p.kind == "ladder":
        for x in (-w / 2 + 2 * r, w / 2 - 2 * r):
            b.cyl(x, fy, 0, h, 2 * r, p.primary, sections=10)
            for z in (0.15 * h, 0.85 * h):
                b.rod((x, -d / 2, z), (x, fy, z), r, p.primary, sections=6)
        n = max(4, int(h / 0.07))
        for k in range(n):
            z = 0.05 * h + k * 0.9 * h / (n - 1)
            b.rod((-w / 2 + 2 * r, fy, z), (w / 2 - 2 * r, fy, z), r, p.primary, sections=8)
        tz = 0.9 * h - 0.9 * h / (n - 1) * 2
        tw = 0.7 * w
        b.box((-tw / 2, fy + 1.2 * r, 0.45 * h), (tw / 2, fy + 2.2 * r, tz + r), p.secondary)
        b.box((-tw / 2, fy - 2.2 * r, 0.55 * h), (tw / 2, fy - 1.2 * r, tz + r), p.secondary)
        b.rod((-tw / 2, fy, tz + 1.5 * r), (tw / 2, fy, tz + 1.5 * r), 2.2 * r, p.secondary, sections=10)
        return b.mesh(p.size)
    bars = (h - 3 * r, 0.55 * h)
    for x in (-w / 2 + 0.05 * w, w / 2 - 0.05 * w):
        disc_y(b, x, -d / 2, -d / 2 + 0.008, h - 0.15 * h, 0.03, p.primary, sections=12)
        for z in bars:
            b.rod((x, -d / 2, min(z + 0.1 * h, h - 0.02)), (x, fy, z), r, p.primary, sections=6)
    for z in bars:
        b.rod((-w / 2 + 0.05 * w - r, fy, z), (w / 2 - 0.05 * w + r, fy, z), r, p.primary, sections=8)
    tw = 0.55 * w
    z = bars[0]
    b.rod((-tw / 2, fy, z + 1.5 * r), (tw / 2, fy, z + 1.5 * r), 2.5 * r, p.secondary, sections=10)
    b.box((-tw / 2, fy + 1.5 * r, 0.0), (tw / 2, fy + 3 * r, z + r), p.secondary)  # hanging in front
    b.box((-tw / 2, fy - 3 * r, 0.15 * h), (tw / 2, fy - 1.5 * r, z + r), darker(p.secondary, 0.08))
    b.box((-tw / 2, fy + 3 * r, 0.05 * h), (tw / 2, fy + 3 * r + 0.002, 0.09 * h), p.accent)  # woven band
    return b.mesh(p.size)


# ----------------------------------------------------------------- urinal
def sample_urinal(rng, size, style):
    return make_params("urinal", rng, size, style, ["#f4f4f2", "#eceae4", WHITE_PLASTIC], CHROME, "#b8c0c4",
                       valve=bool(rng.random() < 0.8))


def build_urinal(p):
    """A wall-hung urinal: a rounded white bowl against the wall with its open front
    hollow, a drain, and a chrome flush valve and pipe above."""
    w, d, h = p.size
    b = Builder()
    z1 = 0.8 * h if p.valve else h
    sph = trimesh.creation.icosphere(subdivisions=3)
    zc = 0.52 * z1
    v = np.asarray(sph.vertices) * np.array([0.5 * w, d, 0.5 * z1]) + np.array([0.0, -d / 2, zc])
    v[:, 1] = np.maximum(v[:, 1], -d / 2)  # a half shell with its flat back on the wall
    bulge = 0.45 + 0.55 * np.exp(-(((v[:, 2] - 0.32 * z1) / (0.28 * z1)) ** 2))  # the bowl juts out low down
    v[:, 1] = -d / 2 + (v[:, 1] + d / 2) * bulge
    v[:, 0] *= 0.8 + 0.2 * bulge
    v[:, 2] = np.minimum(v[:, 2], 0.94 * z1)  # a flat top under the flush pipe
    v[:, 2] = np.maximum(v[:, 2], 0.08 * h)
    b.add(v, sph.faces, p.primary)
    c = (0, d / 2 - 0.16 * d, 0.45 * z1)  # the open hollow on the front
    b.sphere(c, (0.3 * w, 0.12 * d, 0.3 * z1), p.accent, subdivisions=2, transform=about(rot_x(-0.5), c))
    b.torus((0, 0, 0), 1.0, 0.06, lighter(p.primary, 0.3), sections=24, minor_sections=4,
            transform=about(rot_x(-0.5 + np.pi / 2), c) @ move(c) @ np.diag([0.31 * w, 0.31 * z1, 0.12 * d, 1.0]))
    if p.valve:
        b.cyl(0, -d / 2 + 0.12 * d, z1 - 0.02 * h, h - 0.12 * h, 0.02, p.secondary, sections=8)
        b.cyl(0, -d / 2 + 0.12 * d, h - 0.12 * h, h, 0.04, p.secondary, sections=10)
        b.rod((0, -d / 2 + 0.12 * d, h - 0.06 * h), (0, -d / 2 + 0.3 * d, h - 0.04 * h), 0.008, p.secondary,
              sections=6)
        b.rod((0, -d / 2 + 0.12 * d, h - 0.06 * h), (0, -d / 2, h - 0.06 * h), 0.02, p.secondary, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- ladder
def sample_ladder(rng, size, style):
    w, d, h = size
    step = d > 0.3 * h
    wood = style_is(style, "antique", "rustic") or rng.random() < 0.4
    return make_params("ladder", rng, size, style, wood_tones(style) if wood else [METAL, "#b8bcc0", "#e0b030"],
                       [BLACK, "#c0392b", "#e8702a", BRASS], METAL, kind="step" if step else "leaning",
                       rolling=bool(wood and not step and rng.random() < 0.5))


def build_ladder(p):
    """A ladder leaning against the wall (a library ladder hooks onto a rail and rolls on
    wheels) or, in a deep box, an A-frame stepladder with a top cap and spreaders."""
    w, d, h = p.size
    b = Builder()
    t = min(0.035, 0.08 * w)
    if p.kind == "step":
        fy0, fy1 = d / 2 - t, -d / 2 + t
        top = h - 0.03 * h
        for x in (-w / 2 + t, w / 2 - t):
            b.rod((x * 0.98, d / 2 - t, 0), (x * 0.85, -0.05 * d, top), t, p.primary, sections=6)
            b.rod((x * 0.98, -d / 2 + t, 0), (x * 0.85, -0.15 * d, top), 0.8 * t, p.primary, sections=6)
            b.box((x - t, d / 2 - 2 * t, 0), (x + t, d / 2, 0.02), p.secondary)
        n = max(3, int(h / 0.28))
        for k in range(1, n):
            f = k / n
            y = fy0 + f * (-0.05 * d - fy0)
            b.box((-w / 2 * (1 - 0.15 * f) + t, y - 0.06, f * top - 0.02), (w / 2 * (1 - 0.15 * f) - t, y + 0.03,
                                                                              f * top), p.primary)
        b.box((-0.45 * w, -0.2 * d, top), (0.45 * w, 0.0, h), p.secondary)  # top cap
        for s in (-1, 1):
            b.rod((s * 0.4 * w, fy0 * 0.4, 0.45 * h), (s * 0.4 * w, fy1 * 0.5, 0.45 * h), 0.006, METAL, sections=4)
        return b.mesh(p.size)
    ya, yb = d / 2 - t, -d / 2 + t
    za = 0.06 * h if p.rolling else 0.0
    for x in (-w / 2 + t, w / 2 - t):
        b.box((x - t, ya - t, za), (x + t, ya + t, za + 0.02), p.primary)
        b.hull([(x - t, ya - t, za), (x + t, ya - t, za), (x - t, ya + t, za), (x + t, ya + t, za),
                (x - t, yb - t, h - 0.04 * h), (x + t, yb - t, h - 0.04 * h), (x - t, yb + t, h - 0.04 * h),
                (x + t, yb + t, h - 0.04 * h)], p.primary)
        if p.rolling:
            disc_x(b, x - 0.02, x + 0.02, ya, za, za, BLACK, sections=12)
            path(b, [(x, yb, h - 0.04 * h), (x, yb - 0.5 * t, h), (x, -d / 2, h - 0.03 * h)], 0.008, p.secondary,
                 sections=5)
    if p.rolling:
        b.rod((-w / 2, -d / 2 + 0.006, h - 0.015 * h), (w / 2, -d / 2 + 0.006, h - 0.015 * h), 0.006,
              p.secondary, sections=6)
    n = max(4, int(h / 0.28))
    for k in range(1, n):
        f = k / n
        y = ya + f * (yb - ya)
        z = za + f * (h - 0.04 * h - za)
        if p.rolling:
            b.box((-w / 2 + 2 * t, y - 0.05, z - 0.02), (w / 2 - 2 * t, y + 0.05, z), p.primary)
        else:
            b.rod((-w / 2 + 2 * t, y, z), (w / 2 - 2 * t, y, z), 0.6 * t, p.primary, sections=8)
    return b.mesh(p.size)


# ----------------------------------------------------------------- coat hook
def sample_coat_hook(rng, size, style):
    pegs = style_is(style, "rustic", "modern") and rng.random() < 0.6
    return make_params("coat_hook", rng, size, style, wood_tones(style) + ["#e8e6e0"], [BLACK, BRASS, CHROME, DARK_METAL],
                       FABRICS, kind="pegs" if pegs else "hooks", scarf=bool(rng.random() < 0.4))


def build_coat_hook(p):
    """A hook board: a wooden rail on the wall with a row of double coat hooks (or Shaker
    pegs), sometimes a scarf hanging from one."""
    w, d, h = p.size
    b = Builder()
    bt = 0.25 * d
    b.box((-w / 2, -d / 2, 0.2 * h), (w / 2, -d / 2 + bt, h), p.primary)
    b.box((-w / 2, -d / 2 + bt, h - 0.1 * h), (w / 2, -d / 2 + bt + 0.05 * d, h), darker(p.primary, 0.1))
    n = max(2, int(w / 0.16))
    xs = [-w / 2 + (k + 0.5) * w / n for k in range(n)]
    y0 = -d / 2 + bt
    zc = 0.6 * h
    for x in xs:
        if p.kind == "pegs":
            b.rod((x, y0, zc), (x, d / 2 - 0.15 * d, zc + 0.05 * h), 0.12 * h, p.primary, sections=10)
            b.sphere((x, d / 2 - 0.15 * d, zc + 0.05 * h), (0.15 * h, 0.15 * d, 0.15 * h), p.primary, subdivisions=1)
        else:
            b.box((x - 0.1 * h, y0, zc - 0.1 * h), (x + 0.1 * h, y0 + 0.01, zc + 0.25 * h), p.secondary)
            path(b, [(x, y0, zc), (x, d / 2 - 0.05 * d, zc - 0.15 * h), (x, d / 2 - 0.05 * d, zc + 0.05 * h)],
                 0.03 * h, p.secondary, sections=6)
            path(b, [(x, y0, zc + 0.15 * h), (x, 0.3 * d, zc + 0.3 * h), (x, 0.3 * d, zc + 0.4 * h)], 0.025 * h,
                 p.secondary, sections=6)
            b.sphere((x, d / 2 - 0.05 * d, zc + 0.05 * h), 0.04 * h, p.secondary, subdivisions=0)
    if p.scarf:  # a scarf hanging from the last hook
        x = xs[-1]
        b.box((x - 0.035, 0.1 * d, 0.0), (x + 0.035, 0.3 * d, zc), p.accent)
        b.box((x - 0.035, 0.1 * d, 0.05 * h), (x + 0.035, 0.32 * d, 0.08 * h), darker(p.accent, 0.3))
    return b.mesh(p.size)


# ----------------------------------------------------------------- mailbox
def sample_mailbox(rng, size, style):
    w, d, h = size
    return make_params("mailbox", rng, size, style, [BLACK, "#3f6b4a", "#b8322a", STEEL, "#2d4f8a", "#5c3b26"],
                       [BRASS, CHROME, "#e8e6e0"], PAPER, kind="pigeonholes" if w > 0.65 else "letterbox")


def build_mailbox(p):
    """A wall letterbox (a box with a sloping hinged lid, the letter slot, a name plate
    and a lock, post showing at the top) or, in a wide box, a grid of pigeonholes with
    letters in them."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    if p.kind == "pigeonholes":
        t = 0.02
        cols = max(2, int(round(w / 0.25)))
        rows = max(2, int(round(h / 0.2)))
        b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + t, h), p.primary)
        for i in range(cols + 1):
            x = -w / 2 + i * (w - t) / cols
            b.box((x, -d / 2, 0), (x + t, d / 2, h), p.primary)
        for j in range(rows + 1):
            z = j * (h - t) / rows
            b.box((-w / 2, -d / 2, z), (w / 2, d / 2, z + t), p.primary)
        for i in range(cols):
            for j in range(rows):
                if rng.random() < 0.55:
                    x0 = -w / 2 + i * (w - t) / cols + t
                    z0 = j * (h - t) / rows + t
                    cw = (w - t) / cols - t
                    b.box((x0 + 0.1 * cw, -0.3 * d, z0), (x0 + 0.9 * cw, 0.2 * d, z0 + 0.02), p.accent)
                    b.box((x0 + 0.05 * cw, d / 2 - 0.005, z0 + 0.02), (x0 + 0.25 * cw, d / 2, z0 + 0.04), p.secondary)
        return b.mesh(p.size)
    lid_z = 0.72 * h
    b.box((-w / 2, -d / 2, 0.05 * h), (w / 2, d / 2, lid_z), p.primary)
    b.box((-w / 2 + 0.02 * w, -d / 2, 0), (w / 2 - 0.02 * w, d / 2 - 0.02 * d, 0.05 * h), darker(p.primary, 0.2))
    b.hull([(-w / 2 - 0.01, -d / 2, lid_z), (w / 2 + 0.01, -d / 2, lid_z), (-w / 2 - 0.01, d / 2 + 0.0, lid_z),
            (w / 2 + 0.01, d / 2, lid_z), (-w / 2 - 0.01, -d / 2, h), (w / 2 + 0.01, -d / 2, h),
            (-w / 2 - 0.01, d / 2, lid_z + 0.06 * h), (w / 2 + 0.01, d / 2, lid_z + 0.06 * h)], darker(p.primary, 0.1))
    b.box((-0.3 * w, d / 2 - 0.01, lid_z - 0.12 * h), (0.3 * w, d / 2 + 0.003, lid_z - 0.04 * h), BLACK)  # slot
    b.box((-0.32 * w, d / 2, lid_z - 0.05 * h), (0.32 * w, d / 2 + 0.01, lid_z - 0.035 * h), p.secondary)
    b.box((-0.18 * w, d / 2, 0.3 * h), (0.18 * w, d / 2 + 0.004, 0.4 * h), p.secondary)  # name plate
    disc_y(b, 0.3 * w, d / 2, d / 2 + 0.01, 0.2 * h, 0.025 * w + 0.003, p.secondary, sections=8)
    b.hull([(-0.2 * w, -0.1 * d, lid_z), (0.15 * w, -0.1 * d, lid_z), (-0.2 * w, 0.1 * d, lid_z),
            (0.15 * w, 0.1 * d, lid_z), (-0.2 * w, -0.05 * d, h + 0.05 * h), (0.15 * w, -0.05 * d, h + 0.05 * h),
            (-0.2 * w, -0.04 * d, h + 0.05 * h), (0.15 * w, -0.04 * d, h + 0.05 * h)], p.accent)  # post
    return b.mesh(p.size)


# ----------------------------------------------------------------- wall sconce
def sample_wall_sconce(rng, size, style):
    if style_is(style, "antique"):
        kind = "candle"
    elif style_is(style, "rustic"):
        kind = str(rng.choice(["torch", "candle"]))
    elif style_is(style, "modern"):
        kind = "cylinder"
    else:
        u = rng.random()
        kind = "shade" if u < 0.4 else "candle" if u < 0.65 else "cylinder" if u < 0.9 else "torch"
    return make_params("wall_sconce", rng, size, style, [BRASS, BLACK, CHROME, DARK_METAL, "#e8e6e0"],
                       ["#f4f1e6", "#e8dcc0", "#f0e6d0", GLASS], BULB, kind=kind)


def build_wall_sconce(p):
    """A wall light: a backplate with an arm holding a fabric shade, a candle with its
    drip cup, a glass cylinder, or an iron torch holder with a flame."""
    w, d, h = p.size
    b = Builder()
    bp = 0.08 * d
    b.box((-0.18 * w, -d / 2, 0.28 * h), (0.18 * w, -d / 2 + bp, 0.72 * h), p.primary)
    disc_y(b, 0, -d / 2 + bp, -d / 2 + 1.5 * bp, 0.5 * h, 0.12 * w, darker(p.primary, 0.15), sections=12)
    cy = 0.1 * d
    R = 0.45 * min(w, d)
    if p.kind == "torch":
        b.rod((0, -d / 2 + bp, 0.3 * h), (0, cy, 0.42 * h), 0.025 * w + 0.004, p.primary, sections=6)
        b.cyl(0, cy, 0.05 * h, 0.62 * h, 0.07 * w, tint("#6b4330", "wood"), r_top=0.11 * w, sections=8)  # the torch
        b.cyl(0, cy, 0.45 * h, 0.62 * h, 0.2 * w, p.primary, r_top=0.26 * w, sections=8)  # iron cup
        b.cyl(0, cy, 0.6 * h, h, 0.22 * w, tint("#e8602a", "light"), r_top=0.0, sections=10)  # flame
        b.cyl(0, cy + 0.02 * d, 0.6 * h, 0.88 * h, 0.15 * w, FLAME, r_top=0.0, sections=10)
        b.cyl(0, cy + 0.04 * d, 0.6 * h, 0.75 * h, 0.08 * w, tint("#fff1a0", "light"), r_top=0.0, sections=8)
        return b.mesh(p.size)
    if p.kind == "candle":
        path(b, [(0, -d / 2 + bp, 0.4 * h), (0, 0.0, 0.3 * h), (0, cy, 0.45 * h)], 0.02 * w + 0.003, p.primary,
             sections=6)
        b.cyl(0, cy, 0.45 * h, 0.5 * h, 0.35 * w, p.primary, r_top=0.4 * w, sections=14)
        b.cyl(0, cy, 0.5 * h, 0.85 * h, 0.1 * w, tint("#f4f1e6", "paint"), sections=10)
        b.sphere((0, cy, 0.9 * h), (0.06 * w, 0.06 * w, 0.07 * h), FLAME, subdivisions=1)
        b.cyl(0, cy, 0.97 * h, h, 0.01 * w, FLAME, sections=4)
        return b.mesh(p.size)
    if p.kind == "cylinder":
        b.rod((0, -d / 2 + bp, 0.5 * h), (0, cy, 0.5 * h), 0.06 * w, p.primary, sections=8)
        b.cyl(0, cy, 0.0, h, R, p.secondary, sections=20, alpha=200)
        b.cyl(0, cy, 0.35 * h, 0.65 * h, 0.35 * R, p.accent, sections=12)
        for z in (0.0, h - 0.03 * h):
            b.cyl(0, cy, z, z + 0.03 * h, 1.02 * R, p.primary, sections=20)
        return b.mesh(p.size)
    path(b, [(0, -d / 2 + bp, 0.35 * h), (0, -0.1 * d, 0.3 * h), (0, cy, 0.4 * h)], 0.02 * w + 0.003, p.primary,
         sections=6)
    b.cyl(0, cy, 0.4 * h, 0.5 * h, 0.12 * w, p.primary, sections=10)
    b.cyl(0, cy, 0.5 * h, h, R, p.secondary, r_top=0.65 * R, sections=20)  # shade
    return b.mesh(p.size)


# ----------------------------------------------------------------- room divider
def sample_room_divider(rng, size, style):
    if style_is(style, "eastern"):
        kind = "shoji"
    elif style_is(style, "antique"):
        kind = "lattice"
    else:
        kind = str(rng.choice(["fabric", "shoji", "lattice", "fabric"]))
    return make_params("room_divider", rng, size, style, wood_tones(style), FABRICS + [PAPER, "#e8dcc0"],
                       [PAPER, "#f4f1ea"], kind=kind, panels=int(rng.choice([3, 4, 4, 5])))


def build_room_divider(p):
    """A folding screen: panels hinged in a zigzag, each a wooden frame filled with
    fabric, a shoji paper grid, or a lattice."""
    w, d, h = p.size
    b = Builder()
    n = p.panels
    depth = 0.85 * d
    a = np.arctan2(depth, w / n)
    pw = float(np.hypot(depth, w / n))
    t = min(0.03, 0.06 * pw)
    th = min(0.025, 0.3 * d)
    x = -w / 2
    for k in range(n):
        turn = a if k % 2 == 0 else -a
        y0 = -depth / 2 if k % 2 == 0 else depth / 2
        m = Builder()
        m.box((0, -th / 2, 0.04 * h), (pw, th / 2, h), p.primary)  # frame as a slab
        if p.kind == "fabric":
            m.box((t, -th / 2 - 0.002, 0.04 * h + t + 0.05 * h), (pw - t, th / 2 + 0.002, h - t), p.secondary)
        elif p.kind == "shoji":
            m.box((t, -th / 2 - 0.002, 0.04 * h + t + 0.05 * h), (pw - t, th / 2 + 0.002, h - t), p.accent)
            for i in range(1, 3):
                xx = t + i * (pw - 2 * t) / 3
                m.box((xx - 0.006, -th / 2 - 0.004, 0.04 * h + t + 0.05 * h), (xx + 0.006, th / 2 + 0.004, h - t),
                      p.primary)
            for j in range(1, 6):
                zz = 0.04 * h + t + 0.05 * h + j * (h - t - 0.09 * h - t) / 6
                m.box((t, -th / 2 - 0.004, zz - 0.006), (pw - t, th / 2 + 0.004, zz + 0.006), p.primary)
        else:
            m.box((t, -th / 2 - 0.001, 0.04 * h + t + 0.05 * h), (pw - t, th / 2 + 0.001, h - t),
                  darker(p.primary, 0.4))
            for i in range(-6, 12):
                za = 0.1 * h + i * 0.12 * h
                for s in (1, -1):
                    pa = np.array([t, 0, za])
                    pb = np.array([pw - t, 0, za + s * (pw - 2 * t)])
                    lo_z, hi_z = 0.09 * h + t, h - t
                    # clip the lattice bar to the panel
                    ts = np.linspace(0, 1, 20)
                    pts = [pa + (pb - pa) * u for u in ts if lo_z <= (pa + (pb - pa) * u)[2] <= hi_z]
                    if len(pts) >= 2:
                        m.rod(pts[0], pts[-1], 0.006, lighter(p.primary, 0.1), sections=4)
        m.box((0, -th / 2, 0), (0.03, th / 2, 0.04 * h), darker(p.primary, 0.2))
        m.box((pw - 0.03, -th / 2, 0), (pw, th / 2, 0.04 * h), darker(p.primary, 0.2))
        b.extend(m, move((x, y0, 0)) @ rot_z(turn))
        x += w / n
    return b.mesh(p.size)


# ----------------------------------------------------------------- safe
def sample_safe(rng, size, style):
    old = style_is(style, "antique", "rustic") or (not style_is(style, "modern") and rng.random() < 0.4)
    return make_params("safe", rng, size, style, ["#2f4a3a", "#3a2a26", BLACK] if old else
                       [DARK_METAL, "#2b2b2b", "#5f6b7a", "#8a8d92"], BRASS if old else CHROME, "#c9a54a",
                       lock="dial" if old else str(rng.choice(["dial", "keypad"])))


def build_safe(p):
    """A steel safe: a heavy body on a plinth, a thick door with hinges, a combination
    dial (or a keypad) and a spoked handle."""
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2 + 0.03 * w, -d / 2 + 0.03 * d, 0), (w / 2 - 0.03 * w, d / 2 - 0.05 * d, 0.06 * h),
          darker(p.primary, 0.3))
    fy = d / 2 - 0.05 * d
    b.box((-w / 2, -d / 2, 0.06 * h), (w / 2, fy, h), p.primary)
    m = 0.08 * w
    b.box((-w / 2 + m, fy, 0.06 * h + m), (w / 2 - m, d / 2, h - m), lighter(p.primary, 0.08))  # door
    b.box((-w / 2 + 1.6 * m, d / 2, 0.06 * h + 1.6 * m), (w / 2 - 1.6 * m, d / 2 + 0.003, h - 1.6 * m),
          darker(p.primary, 0.05))
    if p.primary in ("#2f4a3a", "#3a2a26", BLACK):
        for lo, hi in (((-w / 2 + 1.8 * m, h - 1.9 * m), (w / 2 - 1.8 * m, h - 1.8 * m)),
                       ((-w / 2 + 1.8 * m, 0.06 * h + 1.8 * m), (w / 2 - 1.8 * m, 0.06 * h + 1.9 * m))):
            b.box((lo[0], d / 2 + 0.003, lo[1]), (hi[0], d / 2 + 0.004, hi[1]), p.accent)  # gilt lines
    for z in (0.25 * h, 0.8 * h):  # hinges on the left
        b.cyl(-w / 2 + m, fy + 0.01, z - 0.05 * h, z + 0.05 * h, 0.03, p.secondary, sections=10)
    cz = 0.66 * h
    if p.lock == "dial":
        disc_y(b, 0, d / 2, d / 2 + 0.02, cz, 0.13 * w, p.secondary, sections=20)
        disc_y(b, 0, d / 2 + 0.02, d / 2 + 0.04, cz, 0.09 * w, darker(p.secondary, 0.3), sections=16)
        for k in range(12):
            a = 2 * np.pi * k / 12
            b.cbox((0.15 * w * np.cos(a), d / 2 + 0.004, cz + 0.15 * w * np.sin(a)), (0.008, 0.004, 0.008),
                   p.secondary)
    else:
        b.box((-0.12 * w, d / 2, cz - 0.1 * h), (0.12 * w, d / 2 + 0.015, cz + 0.08 * h), BLACK)
        b.box((-0.09 * w, d / 2 + 0.015, cz + 0.03 * h), (0.09 * w, d / 2 + 0.017, cz + 0.06 * h), GLOW_GREEN)
        for i in range(3):
            for j in range(3):
                b.cbox((-0.06 * w + 0.06 * w * i, d / 2 + 0.016, cz - 0.07 * h + 0.03 * h * j),
                       (0.035 * w, 0.004, 0.018 * h), tint("#9a9da3", "metal"))
    hx, hz = 0.0, 0.4 * h
    disc_y(b, hx, d / 2, d / 2 + 0.05, hz, 0.04 * w, p.secondary, sections=12)
    for k in range(4 if p.lock == "dial" else 3):
        a = 2 * np.pi * k / (4 if p.lock == "dial" else 3) + 0.4
        tip = (hx + 0.16 * w * np.cos(a), d / 2 + 0.045, hz + 0.16 * w * np.sin(a))
        b.rod((hx, d / 2 + 0.045, hz), tip, 0.012, p.secondary, sections=6)
        b.sphere(tip, 0.022, p.secondary, subdivisions=1)
    return b.mesh(p.size)


# ----------------------------------------------------------------- acoustic panel
def sample_acoustic_panel(rng, size, style):
    u = rng.random()
    kind = "slats" if style_is(style, "modern", "rustic") and u < 0.6 else \
        "foam" if u < 0.55 else "slats" if u < 0.8 else "fabric"
    return make_params("acoustic_panel", rng, size, style, ["#2b2b2b", "#3a3b3e", "#2d4f8a", "#8a1f2b", "#5f6b7a",
                                                           "#7d8c74"], wood_tones(style), BLACK, kind=kind)


def build_acoustic_panel(p):
    """A sound-absorbing wall panel: a grid of foam pyramids, vertical wooden slats on a
    black felt backing, or bevelled fabric tiles in a few shades."""
    w, d, h = p.size
    b = Builder()
    base = 0.3 * d
    if p.kind == "foam":
        b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + base, h), p.primary)
        nx = int(min(24, max(2, round(w / 0.1))))
        nz = int(min(24, max(2, round(h / 0.1))))
        sx, sz = w / nx, h / nz
        for i in range(nx):
            for j in range(nz):
                x, z = -w / 2 + (i + 0.5) * sx, (j + 0.5) * sz
                col = p.primary if (i + j) % 2 else darker(p.primary, 0.12)
                b.hull([(x - sx / 2, -d / 2 + base, z - sz / 2), (x + sx / 2, -d / 2 + base, z - sz / 2),
                        (x - sx / 2, -d / 2 + base, z + sz / 2), (x + sx / 2, -d / 2 + base, z + sz / 2),
                        (x, d / 2, z)], col)
        return b.mesh(p.size)
    if p.kind == "slats":
        b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + 0.4 * d, h), p.accent)
        n = int(min(60, max(3, round(w / 0.045))))
        sw = w / n
        for i in range(n):
            x = -w / 2 + i * sw
            b.box((x + 0.2 * sw, -d / 2 + 0.4 * d, 0.01 * h), (x + 0.8 * sw, d / 2, h - 0.01 * h), p.secondary)
        return b.mesh(p.size)
    cols = max(1, int(round(w / 0.6)))
    rows = max(1, int(round(h / 0.6)))
    gap = 0.02 * min(w, h)
    tw, th = (w - (cols - 1) * gap) / cols, (h - (rows - 1) * gap) / rows
    m = 0.08 * min(tw, th)
    tones = [p.primary, lighter(p.primary, 0.2), darker(p.primary, 0.2)]
    for i in range(cols):
        for j in range(rows):
            x0, z0 = -w / 2 + i * (tw + gap), j * (th + gap)
            b.hull([(x0, -d / 2, z0), (x0 + tw, -d / 2, z0), (x0, -d / 2, z0 + th), (x0 + tw, -d / 2, z0 + th),
                    (x0 + m, d / 2, z0 + m), (x0 + tw - m, d / 2, z0 + m), (x0 + m, d / 2, z0 + th - m),
                    (x0 + tw - m, d / 2, z0 + th - m)], tones[(i + 2 * j) % 3])
    return b.mesh(p.size)


slot_roles("radiator", "metal", "metal", "metal")
register("radiator", sample_radiator, build_radiator)
slot_roles("water_heater", "metal", "metal", "plastic")
register("water_heater", sample_water_heater, build_water_heater)
slot_roles("air_conditioner", {"": "plastic", "#c9ccd0": "metal"}, "metal", "light")
register("air_conditioner", sample_air_conditioner, build_air_conditioner)
slot_roles("generator", "paint", "plastic", "metal")
register("generator", sample_generator, build_generator)
slot_roles("trash_can", "metal", {"": "plastic", "#9a9da3": "metal"}, "plastic")
register("trash_can", sample_trash_can, build_trash_can)
slot_roles("ironing_board", "fabric", "metal", "plastic")
register("ironing_board", sample_ironing_board, build_ironing_board)
slot_roles("towel_rack", "metal", "fabric", "fabric")
register("towel_rack", sample_towel_rack, build_towel_rack)
slot_roles("urinal", "ceramic", "metal", "metal")
register("urinal", sample_urinal, build_urinal)
slot_roles("ladder", {"": "wood", METAL: "metal", "#b8bcc0": "metal"}, {"": "plastic", BRASS: "metal"}, "metal")
register("ladder", sample_ladder, build_ladder)
slot_roles("coat_hook", "wood", "metal", "fabric")
register("coat_hook", sample_coat_hook, build_coat_hook)
slot_roles("mailbox", "metal", "metal", "paper")
register("mailbox", sample_mailbox, build_mailbox)
slot_roles("wall_sconce", "metal", {"": "fabric", GLASS: "glass"}, "light")
register("wall_sconce", sample_wall_sconce, build_wall_sconce)
slot_roles("room_divider", "wood", "fabric", "paper")
register("room_divider", sample_room_divider, build_room_divider)
slot_roles("safe", {"": "paint", DARK_METAL: "metal"}, "metal", "metal")
register("safe", sample_safe, build_safe)
slot_roles("acoustic_panel", "fabric", "wood", "plastic")
register("acoustic_panel", sample_acoustic_panel, build_acoustic_panel)
