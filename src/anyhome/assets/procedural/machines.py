"""Workshop and laboratory machines: lathe, drill_press, bandsaw, laser_cutter,
cnc_machine, 3d_printer, microscope, bunsen_burner, centrifuge."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    GLOW_GREEN,
    GLOW_RED,
    SCREEN,
    STEEL,
    WHITE_PLASTIC,
    buttons,
    caster,
    disc_x,
    disc_y,
    ring_x,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    Builder,
    about,
    darker,
    lengthwise,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    tint,
)
from anyhome.assets.registry import register

MACHINE_PAINTS = tint(["#4a6a5a", "#6f7f86", "#3a5a8a", "#d8d0b8", "#5a6b5a", "#8a4a3a", "#e0b030"], "paint")
HANDLES = tint(["#c0392b", BLACK, "#e0b030"], "plastic")
FILAMENTS = tint(["#e67e22", "#2e86c1", "#27ae60", "#c0392b", "#f1c40f", "#8e44ad", "#e8e6e0"], "plastic")


def _handwheel(b: Builder, x: float, y: float, z: float, r: float, color: str) -> None:
    """A handwheel facing +y with three spokes and a knob."""
    from anyhome.assets.procedural._kit import ring_y

    ring_y(b, (x, y, z), r, 0.12 * r, color, sections=16)
    for k in range(3):
        a = 2 * np.pi * k / 3 + 0.3
        b.rod((x, y, z), (x + r * np.cos(a), y, z + r * np.sin(a)), 0.08 * r, color, sections=5)
    b.rod((x + r * np.cos(0.3), y, z + r * np.sin(0.3)), (x + r * np.cos(0.3), y + 0.8 * r, z + r * np.sin(0.3)),
          0.12 * r, BLACK, sections=6)


# ----------------------------------------------------------------- lathe
def sample_lathe(rng, size, style):
    return make_params("lathe", rng, size, style, MACHINE_PAINTS, STEEL, HANDLES,
                       work=str(rng.choice(["wood", "metal"])))


def _draw_lathe(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: headstock and chuck at -x, tailstock at +x, the carriage between."""
    bed_z = 0.68 * H
    yb0, yb1 = -0.35 * B, 0.3 * B
    for x0, x1 in ((-L / 2, -L / 2 + 0.22 * L), (L / 2 - 0.16 * L, L / 2)):  # pedestals
        b.box((x0, yb0, 0), (x1, yb1, bed_z - 0.1 * H), p.primary)
        b.box((x0 + 0.02 * L, yb1, 0.1 * H), (x1 - 0.02 * L, yb1 + 0.01, bed_z - 0.16 * H), darker(p.primary, 0.1))
    b.box((-L / 2 + 0.02 * L, -0.45 * B, bed_z - 0.1 * H), (L / 2 - 0.02 * L, 0.45 * B, bed_z - 0.07 * H),
          darker(p.primary, 0.25))  # chip pan
    for y in (-0.15 * B, 0.12 * B):  # bed ways
        b.box((-L / 2 + 0.04 * L, y - 0.06 * B, bed_z - 0.07 * H), (L / 2 - 0.04 * L, y + 0.06 * B, bed_z),
              p.primary)
        b.box((-L / 2 + 0.04 * L, y - 0.05 * B, bed_z), (L / 2 - 0.04 * L, y + 0.05 * B, bed_z + 0.005),
              p.secondary)
    zc = bed_z + 0.14 * H
    hx1 = -L / 2 + 0.24 * L
    b.box((-L / 2, -0.35 * B, bed_z), (hx1, 0.25 * B, zc + 0.12 * H), p.primary)  # headstock
    b.box((-L / 2 + 0.02 * L, 0.25 * B, bed_z + 0.03 * H), (hx1 - 0.02 * L, 0.26 * B, zc + 0.1 * H),
          lighter(p.primary, 0.15))
    for k in range(3):
        b.rod((-L / 2 + (0.06 + 0.06 * k) * L, 0.26 * B, zc), (-L / 2 + (0.06 + 0.06 * k) * L, 0.38 * B, zc),
              0.01, p.accent if k == 1 else BLACK, sections=6)
    r_ch = 0.09 * H
    disc_x(b, hx1, hx1 + 0.04 * L, 0, zc, r_ch, p.secondary, sections=18)  # chuck
    for k in range(3):
        a = 2 * np.pi * k / 3
        b.cbox((hx1 + 0.045 * L, 0.6 * r_ch * np.cos(a), zc + 0.6 * r_ch * np.sin(a)), (0.02 * L, 0.02, 0.02),
               DARK_METAL)
    tx0 = L / 2 - 0.2 * L
    work_r = 0.045 * H if p.work == "wood" else 0.03 * H
    disc_x(b, hx1 + 0.04 * L, tx0 - 0.03 * L, 0, zc, work_r, tint("#c9a06a", "wood") if p.work == "wood" else CHROME,
           sections=14)
    b.box((tx0, -0.18 * B, bed_z), (tx0 + 0.09 * L, 0.15 * B, zc + 0.05 * H), p.primary)  # tailstock
    disc_x(b, tx0 - 0.03 * L, tx0, 0, zc, 0.025 * H, p.secondary, sections=10)
    disc_x(b, tx0 + 0.09 * L, tx0 + 0.12 * L, 0, zc, 0.02 * H, p.secondary, sections=8)
    ring_x(b, (tx0 + 0.125 * L, 0, zc), 0.06 * H, 0.007 * H, p.secondary, sections=14)
    cx = -L / 2 + 0.52 * L  # carriage: saddle, apron with handwheel, tool post
    b.box((cx - 0.07 * L, -0.25 * B, bed_z), (cx + 0.07 * L, 0.22 * B, bed_z + 0.05 * H), p.primary)
    b.box((cx - 0.08 * L, 0.22 * B, bed_z - 0.16 * H), (cx + 0.08 * L, 0.3 * B, bed_z + 0.05 * H), p.primary)
    _handwheel(b, cx - 0.04 * L, 0.3 * B, bed_z - 0.07 * H, 0.05 * H, p.secondary)
    b.box((cx - 0.03 * L, -0.02 * B, bed_z + 0.05 * H), (cx + 0.03 * L, 0.15 * B, zc - 0.02 * H), DARK_METAL)
    b.box((cx - 0.01 * L, -0.1 * B, zc - 0.03 * H), (cx + 0.01 * L, 0.1 * B, zc - 0.015 * H), CHROME)  # tool
    b.rod((-L / 2 + 0.22 * L, 0.3 * B, bed_z - 0.1 * H), (L / 2 - 0.16 * L, 0.3 * B, bed_z - 0.1 * H), 0.008,
          p.secondary, sections=6)  # lead screw


def build_lathe(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_lathe(b, L, B, H, p))


# ----------------------------------------------------------------- drill press
def sample_drill_press(rng, size, style):
    return make_params("drill_press", rng, size, style, MACHINE_PAINTS, STEEL, HANDLES,
                       table=str(rng.choice(["round", "square"])))


def build_drill_press(p):
    """A floor drill press: base plate, column at the back, the work table, and the head
    with motor, belt cover, chuck and three feed handles."""
    w, d, h = p.size
    b = Builder()
    cy = -0.3 * d
    r_col = min(0.04, 0.08 * w, 0.06 * d)
    b.box((-0.45 * w, -d / 2, 0), (0.45 * w, 0.25 * d, 0.05 * h), p.primary)
    b.box((-0.3 * w, -d / 2 + 0.02, 0.05 * h), (0.3 * w, -0.15 * d, 0.07 * h), p.primary)
    b.cyl(0, cy, 0.05 * h, 0.9 * h, r_col, p.secondary, sections=14)
    tz = 0.45 * h
    b.box((-1.4 * r_col, cy - 1.4 * r_col, tz - 0.08 * h), (1.4 * r_col, cy + 1.4 * r_col, tz - 0.01 * h),
          p.primary)  # collar
    b.box((-0.4 * r_col, cy, tz - 0.05 * h), (0.4 * r_col, 0.05 * d, tz - 0.01 * h), p.primary)  # arm
    tr = min(0.38 * w, 0.28 * d)
    if p.table == "round":
        b.cyl(0, 0.1 * d, tz - 0.01 * h, tz, tr, p.primary, sections=24)
    else:
        b.box((-tr, 0.1 * d - tr, tz - 0.01 * h), (tr, 0.1 * d + tr, tz), p.primary)
    b.box((-0.15 * tr, 0.1 * d - tr * 0.9, tz), (0.15 * tr, 0.1 * d + tr * 0.9, tz + 0.002), DARK_METAL)
    hz0, hz1 = 0.68 * h, 0.86 * h
    b.box((-0.28 * w, cy - 0.1 * d, hz0), (0.28 * w, 0.08 * d, hz1), p.primary)  # head
    b.cyl(0, 0.08 * d, hz0, hz1, 0.28 * w, p.primary, sections=20)
    b.box((-0.3 * w, cy - 0.12 * d, hz1), (0.3 * w, 0.12 * d, 0.95 * h), lighter(p.primary, 0.1))  # belt cover
    b.cyl(0, 0.12 * d, hz1, 0.95 * h, 0.3 * w, lighter(p.primary, 0.1), sections=20)
    b.cyl(0, cy - 0.12 * d, hz1, 0.95 * h, 0.3 * w, lighter(p.primary, 0.1), sections=20)
    b.cyl(0, 0.0, 0.95 * h, h, 0.05 * w, p.secondary, sections=8)
    b.rod((0, cy - 0.1 * d, 0.77 * h), (0, -d / 2, 0.77 * h), min(0.16 * w, 0.09 * h), darker(p.primary, 0.2),
          sections=16)  # motor
    qy = 0.12 * d
    b.cyl(0, qy, 0.6 * h, hz0, 0.06 * w, p.secondary, sections=12)  # quill
    b.cyl(0, qy, 0.56 * h, 0.6 * h, 0.025 * w, p.secondary, r_top=0.055 * w, sections=12)  # chuck
    b.cyl(0, qy, 0.5 * h, 0.56 * h, 0.008, CHROME, sections=6)  # bit
    hx, hz = 0.3 * w, 0.76 * h
    b.rod((0.28 * w, 0, hz), (0.34 * w, 0, hz), 0.03 * w, p.secondary, sections=10)
    for k in range(3):
        a = 2 * np.pi * k / 3 + 0.5
        tip = (hx + 0.06 * w, 0.3 * d * np.cos(a), hz + 0.16 * h * np.sin(a))
        b.rod((hx + 0.04 * w, 0, hz), tip, 0.008, CHROME, sections=6)
        b.sphere(tip, 0.02, p.accent, subdivisions=1)
    b.box((-0.1 * w, 0.08 * d + 0.27 * w * 0.9, 0.8 * h), (0.1 * w, 0.08 * d + 0.3 * w, 0.84 * h), BLACK)
    return b.mesh(p.size)


# ----------------------------------------------------------------- bandsaw
def sample_bandsaw(rng, size, style):
    return make_params("bandsaw", rng, size, style, MACHINE_PAINTS, STEEL, HANDLES,
                       stand=str(rng.choice(["cabinet", "legs"])))


def build_bandsaw(p):
    """A floor bandsaw: stand, a C-frame with the spine on the left, upper and lower wheel
    housings, the square table with the blade running through it."""
    w, d, h = p.size
    b = Builder()
    sz = 0.42 * h
    if p.stand == "cabinet":
        b.box((-0.4 * w, -0.4 * d, 0), (0.4 * w, 0.4 * d, sz), darker(p.primary, 0.2))
        b.box((-0.3 * w, 0.4 * d, 0.08 * h), (0.3 * w, 0.41 * d, sz - 0.04 * h), darker(p.primary, 0.1))
    else:
        for x in (-0.38 * w, 0.38 * w):
            for y in (-0.38 * d, 0.38 * d):
                b.rod((x * 0.8, y * 0.8, sz), (x, y, 0), 0.02, DARK_METAL, sections=6)
        b.box((-0.34 * w, -0.34 * d, sz - 0.02 * h), (0.34 * w, 0.34 * d, sz), DARK_METAL)
    R = min(0.3 * w, 0.12 * h)
    y0, y1 = -0.22 * d, 0.18 * d
    lz = sz + R * 0.9
    uz = h - R * 1.05
    x_w = -0.02 * w
    disc_y(b, x_w, y0, y1, lz, R, p.primary, sections=24)  # lower housing
    b.box((x_w - R, y0, sz), (x_w + R, y1, lz), p.primary)
    disc_y(b, x_w, y0, y1, uz, R, p.primary, sections=24)  # upper housing
    b.box((-0.45 * w, y0 + 0.05 * d, lz), (-0.45 * w + 0.14 * w, y1 - 0.05 * d, uz), p.primary)  # spine
    for z in (lz, uz):
        disc_y(b, x_w, y1, y1 + 0.01, z, 0.2 * R, p.secondary, sections=10)
        b.box((x_w - 0.6 * R, y1, z - 0.05 * R), (x_w - 0.4 * R, y1 + 0.02, z + 0.05 * R), BLACK)
    blade_x = x_w + 0.95 * R
    tz = lz + R + 0.04 * h
    tw = min(0.5 * w, 0.45 * d)
    b.box((blade_x - tw, -tw, tz - 0.02 * h), (blade_x + 0.6 * tw, tw, tz), p.secondary)  # table
    b.box((blade_x - 0.06 * w, -0.05 * d, lz), (blade_x + 0.02 * w, 0.05 * d, tz - 0.02 * h), p.primary)  # trunnion
    b.box((blade_x + 0.3 * tw, -tw, tz), (blade_x + 0.36 * tw, tw, tz + 0.03 * h), DARK_METAL)  # fence
    guide_z = tz + 0.12 * h
    b.box((blade_x - 0.003, -0.004, tz), (blade_x + 0.003, 0.004, guide_z), CHROME)  # blade
    b.box((blade_x - 0.03 * w, -0.05 * d, guide_z), (blade_x + 0.03 * w, 0.04 * d, uz), p.primary)  # guard post
    b.box((blade_x - 0.035 * w, -0.06 * d, guide_z - 0.02 * h), (blade_x + 0.035 * w, 0.05 * d, guide_z),
          DARK_METAL)
    b.cbox((-0.28 * w, y1 + 0.01, sz + 0.08 * h), (0.08 * w, 0.02, 0.06 * h), BLACK)
    b.cbox((-0.28 * w, y1 + 0.02, sz + 0.09 * h), (0.04 * w, 0.01, 0.02 * h), p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- laser cutter
def sample_laser_cutter(rng, size, style):
    return make_params("laser_cutter", rng, size, style, [WHITE_PLASTIC, "#2b2b2b", "#3a5a8a", "#d9dadc"],
                       ["#e8732a", "#d9502a", "#c9402a"], [BLACK, "#3a3b3e"])


def build_laser_cutter(p):
    """A laser cutter on its stand: the work box with a sloping lid holding a large
    tinted window, a side control panel with a screen and an emergency stop."""
    w, d, h = p.size
    b = Builder()
    sz = 0.5 * h
    for x in (-0.45 * w, 0.45 * w):
        for y in (-0.42 * d, 0.42 * d):
            caster(b, x, y, min(0.02, 0.02 * h))
    b.box((-0.48 * w, -0.46 * d, 0.06 * h), (0.48 * w, 0.46 * d, sz), p.accent)
    for x0, x1 in ((-0.46 * w, -0.01 * w), (0.01 * w, 0.46 * w)):
        b.box((x0, 0.46 * d, 0.09 * h), (x1, 0.47 * d, sz - 0.03 * h), lighter(p.accent, 0.12))
    bz = 0.78 * h
    panel_x = w / 2 - 0.2 * w
    b.box((-w / 2, -d / 2, sz), (w / 2, d / 2, bz), p.primary)
    b.box((-w / 2 + 0.03, d / 2, sz + 0.03 * h), (panel_x - 0.03, d / 2 + 0.001, bz - 0.04 * h),
          darker(p.primary, 0.08))
    # the lid: higher at the back, its window tinted
    pts = [(-w / 2, d / 2, bz), (panel_x, d / 2, bz), (-w / 2, -d / 2, bz), (panel_x, -d / 2, bz),
           (-w / 2, d / 2, bz + 0.06 * h), (panel_x, d / 2, bz + 0.06 * h), (-w / 2, -d / 2, h),
           (panel_x, -d / 2, h)]
    b.hull(pts, p.primary)
    inset = 0.06
    s0 = (bz + 0.06 * h, d / 2 - inset)
    s1 = (h, -d / 2 + inset)

    def on_lid(y):
        t = (d / 2 - y) / d
        return bz + 0.06 * h + t * (h - bz - 0.06 * h)

    wy0, wy1 = s1[1], s0[1]
    wpts = []
    for x in (-w / 2 + inset, panel_x - inset):
        for y in (wy0, wy1):
            for dz in (0.0, 0.004):
                wpts.append((x, y, on_lid(y) + dz))
    b.hull(wpts, p.secondary, alpha=235)
    b.box((-w / 2 + 0.2 * w, d / 2 - 0.03, bz + 0.055 * h), (panel_x - 0.2 * w, d / 2 + 0.005, bz + 0.075 * h),
          CHROME)  # lid handle
    b.box((panel_x, -d / 2, bz), (w / 2, d / 2, bz + 0.12 * h), darker(p.primary, 0.12))
    b.box((panel_x + 0.03, d / 2 - 0.005, bz + 0.04 * h), (w / 2 - 0.03, d / 2 + 0.001, bz + 0.1 * h), SCREEN)
    buttons(b, panel_x + 0.03, w / 2 - 0.03, sz + 0.06 * h, bz - 0.06 * h, d / 2, 3, 3, tint("#9a9da3", "metal"), 0.5)
    b.cyl(w / 2 - 0.1 * w, d / 2 - 0.12 * d, bz + 0.12 * h, bz + 0.15 * h, 0.035, GLOW_RED, sections=12)
    b.cyl(-0.3 * w, -d / 2 + 0.08 * d, bz, h, 0.05, tint("#b0b3b8", "metal"), sections=12)  # exhaust duct
    return b.mesh(p.size)


# ----------------------------------------------------------------- cnc machine
def sample_cnc_machine(rng, size, style):
    return make_params("cnc_machine", rng, size, style, ["#e8e6e0", "#3a5a8a", "#6f7f86", "#e0b030", "#2b2b2b"],
                       STEEL, ["#c9a06a", "#d8bf98"], kind="router" if rng.random() < 0.7 else "mill")


def build_cnc_machine(p):
    """A CNC router (a slatted bed on legs, the gantry bridge with its spindle over a
    plywood sheet) or an enclosed CNC mill with a windowed door."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "mill":
        b.box((-w / 2, -d / 2, 0), (w / 2 - 0.2 * w, d / 2 - 0.05 * d, 0.3 * h), darker(p.primary, 0.2))
        b.box((-w / 2, -d / 2, 0.3 * h), (w / 2 - 0.2 * w, d / 2 - 0.05 * d, h), p.primary)
        for x0, x1 in ((-w / 2 + 0.04 * w, -0.08 * w), (-0.08 * w, w / 2 - 0.24 * w)):
            b.box((x0, d / 2 - 0.05 * d, 0.34 * h), (x1, d / 2 - 0.03 * d, 0.92 * h), lighter(p.primary, 0.1))
            b.box((x0 + 0.04 * w, d / 2 - 0.03 * d, 0.5 * h), (x1 - 0.04 * w, d / 2 - 0.025 * d, 0.86 * h), GLASS,
                  alpha=170)
        b.box((-0.1 * w, d / 2 - 0.03 * d, 0.55 * h), (-0.08 * w, d / 2, 0.75 * h), CHROME)
        b.cyl(-0.12 * w, -0.05 * d, 0.62 * h, 0.82 * h, 0.06 * w, p.secondary, sections=12)  # spindle inside
        b.box((-w / 2 + 0.1 * w, -0.3 * d, 0.36 * h), (w / 2 - 0.3 * w, 0.2 * d, 0.42 * h), DARK_METAL)
        b.box((w / 2 - 0.2 * w, -0.1 * d, 0.45 * h), (w / 2, d / 2, 0.85 * h), darker(p.primary, 0.1))  # panel
        b.box((w / 2 - 0.18 * w, d / 2, 0.68 * h), (w / 2 - 0.02 * w, d / 2 + 0.001, 0.82 * h), SCREEN)
        buttons(b, w / 2 - 0.18 * w, w / 2 - 0.02 * w, 0.48 * h, 0.66 * h, d / 2, 4, 3, tint("#9a9da3", "metal"), 0.55)
        b.cyl(w / 2 - 0.05 * w, 0.2 * d, h - 0.08 * h, h, 0.03 * w, GLOW_GREEN, sections=8)  # signal tower
        return b.mesh(p.size)
    bed = 0.58 * h
    for x in (-0.44 * w, 0.44 * w):
        for y in (-0.42 * d, 0.42 * d):
            b.box((x - 0.025 * w, y - 0.025 * d, 0), (x + 0.025 * w, y + 0.025 * d, bed - 0.06 * h), DARK_METAL)
        b.box((x - 0.02 * w, -0.42 * d, 0.15 * h), (x + 0.02 * w, 0.42 * d, 0.19 * h), DARK_METAL)
    b.box((-0.47 * w, -0.46 * d, bed - 0.06 * h), (0.47 * w, 0.46 * d, bed), p.primary)
    for k in range(9):
        x = -0.44 * w + k * 0.11 * w
        b.box((x, -0.44 * d, bed), (x + 0.05 * w, 0.44 * d, bed + 0.01 * h), darker(p.secondary, 0.2))
    b.box((-0.35 * w, -0.3 * d, bed + 0.01 * h), (0.35 * w, 0.3 * d, bed + 0.025 * h), p.accent)  # sheet
    for x in (-0.49 * w, 0.49 * w):  # side rails
        b.box((x - 0.02 * w, -0.48 * d, bed - 0.04 * h), (x + 0.02 * w, 0.48 * d, bed + 0.02 * h), p.secondary)
    gy = 0.05 * d
    for x in (-w / 2, w / 2 - 0.06 * w):
        b.box((x, gy - 0.08 * d, bed - 0.04 * h), (x + 0.06 * w, gy + 0.08 * d, 0.92 * h), p.primary)
    b.box((-w / 2, gy - 0.05 * d, 0.78 * h), (w / 2, gy + 0.06 * d, 0.92 * h), p.primary)  # beam
    b.box((-w / 2 + 0.06 * w, gy + 0.06 * d, 0.8 * h), (w / 2 - 0.06 * w, gy + 0.07 * d, 0.82 * h), p.secondary)
    sx = 0.1 * w
    b.box((sx - 0.08 * w, gy + 0.06 * d, 0.72 * h), (sx + 0.08 * w, gy + 0.14 * d, h), darker(p.primary, 0.1))
    b.cyl(sx, gy + 0.2 * d, 0.7 * h, 0.95 * h, 0.05 * w, tint("#e8e6e0", "paint"), sections=14)  # spindle motor
    b.box((sx - 0.02 * w, gy + 0.14 * d, 0.85 * h), (sx + 0.02 * w, gy + 0.2 * d, 0.9 * h), p.secondary)
    b.cyl(sx, gy + 0.2 * d, 0.64 * h, 0.7 * h, 0.02 * w, CHROME, r_top=0.04 * w, sections=10)
    b.cyl(sx, gy + 0.2 * d, bed + 0.03 * h, 0.64 * h, 0.004, CHROME, sections=5)
    b.box((-w / 2 - 0.0, -0.48 * d, 0.3 * h), (-w / 2 + 0.05 * w, -0.2 * d, 0.5 * h), BLACK)  # controller box
    return b.mesh(p.size)


# ----------------------------------------------------------------- 3d printer
def sample_3d_printer(rng, size, style):
    return make_params("3d_printer", rng, size, style, [BLACK, "#2b2b2b", "#e8e6e0", "#3a3b3e"],
                       ["#e8732a", BLACK, "#c0392b", "#2e86c1"], FILAMENTS,
                       kind="open" if rng.random() < 0.7 else "enclosed")


def build_3d_printer(p):
    """An open-frame printer (bed on the base, the upright frame and gantry with the
    print head, a filament spool on top) or an enclosed box printer with a window door."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    part = FILAMENTS[int(rng.integers(len(FILAMENTS)))]
    if p.kind == "enclosed":
        spool = 0.2 * h
        top = h - spool
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.12 * top), p.primary)
        b.box((-w / 2, -d / 2, top - 0.1 * top), (w / 2, d / 2, top), p.primary)
        for x in (-w / 2, w / 2 - 0.04 * w):
            for y in (-d / 2, d / 2 - 0.04 * d):
                b.box((x, y, 0.12 * top), (x + 0.04 * w, y + 0.04 * d, top), p.primary)
        b.box((-w / 2 + 0.04 * w, -d / 2, 0.12 * top), (w / 2 - 0.04 * w, -d / 2 + 0.02, top), darker(p.primary))
        b.box((-0.35 * w, -0.35 * d, 0.2 * top), (0.35 * w, 0.35 * d, 0.22 * top), DARK_METAL)
        b.box((-0.1 * w, -0.1 * d, 0.22 * top), (0.1 * w, 0.1 * d, 0.45 * top), part)
        b.box((-0.1 * w, -0.05 * d, 0.6 * top), (0.1 * w, 0.08 * d, 0.7 * top), p.secondary)
        b.box((-w / 2, -d / 2, 0.12 * top), (w / 2, d / 2, top - 0.1 * top), GLASS, alpha=80)
        b.box((0.1 * w, d / 2, 0.03 * top), (0.4 * w, d / 2 + 0.002, 0.1 * top), SCREEN)
        disc_y(b, 0, -0.2 * d, 0.2 * d, top + 0.5 * spool, 0.5 * spool, p.accent, sections=20)
        disc_y(b, 0, -0.21 * d, 0.21 * d, top + 0.5 * spool, 0.15 * spool, DARK_METAL, sections=10)
        return b.mesh(p.size)
    base = 0.12 * h
    b.box((-w / 2, -d / 2 + 0.1 * d, 0), (w / 2, d / 2, base), p.primary)
    b.hull([(0.05 * w, d / 2, 0.02 * h), (0.4 * w, d / 2, 0.02 * h), (0.05 * w, d / 2 - 0.06 * d, base),
            (0.4 * w, d / 2 - 0.06 * d, base), (0.05 * w, d / 2 + 0.0, base * 0.7), (0.4 * w, d / 2, base * 0.7)],
           BLACK)
    b.box((0.08 * w, d / 2 - 0.0005, 0.04 * h), (0.37 * w, d / 2, 0.1 * h), tint("#3a6ab0", "paint"))
    bz = base + 0.06 * h
    b.box((-0.38 * w, -0.38 * d + 0.1 * d, bz - 0.02 * h), (0.38 * w, 0.38 * d + 0.05 * d, bz), DARK_METAL)  # bed
    b.cyl(0.05 * w, 0.05 * d, bz, bz + 0.12 * h, 0.08 * w, part, r_top=0.04 * w, sections=8)  # print
    fy = -0.05 * d
    top = 0.78 * h
    for x in (-0.44 * w, 0.44 * w):
        b.box((x - 0.04 * w, fy - 0.05 * d, base), (x + 0.04 * w, fy + 0.05 * d, top), p.primary)
    b.box((-0.48 * w, fy - 0.05 * d, top - 0.05 * h), (0.48 * w, fy + 0.05 * d, top), p.primary)
    gz = bz + 0.3 * h
    for dz in (-0.025 * h, 0.025 * h):
        b.rod((-0.42 * w, fy + 0.06 * d, gz + dz), (0.42 * w, fy + 0.06 * d, gz + dz), 0.006, CHROME, sections=6)
    hx = -0.05 * w
    b.box((hx - 0.08 * w, fy + 0.06 * d, gz - 0.06 * h), (hx + 0.08 * w, fy + 0.2 * d, gz + 0.05 * h), p.secondary)
    b.box((hx - 0.05 * w, fy + 0.2 * d, gz - 0.05 * h), (hx + 0.05 * w, fy + 0.23 * d, gz + 0.03 * h), BLACK)
    b.cyl(hx, fy + 0.13 * d, gz - 0.1 * h, gz - 0.06 * h, 0.008, CHROME, r_top=0.02, sections=6)
    R = 0.22 * h / 2 + 0.01
    sy = fy
    b.rod((0, sy, top), (0, sy, h - R), 0.01, DARK_METAL, sections=6)
    disc_x(b, -0.1 * w, 0.1 * w, sy, h - R, R, p.accent, sections=20)  # spool
    disc_x(b, -0.11 * w, 0.11 * w, sy, h - R, 0.35 * R, DARK_METAL, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- microscope
def sample_microscope(rng, size, style):
    return make_params("microscope", rng, size, style, [WHITE_PLASTIC, BLACK, "#d9dadc", "#2b3a4a"],
                       [BLACK, "#3a3b3e", CHROME], "#c9ccd0")


def build_microscope(p):
    """A compound microscope: foot, the curved arm at the back, stage with a slide,
    revolving nosepiece with objectives and the binocular head tilted to the front."""
    w, d, h = p.size
    b = Builder()
    b.box((-0.42 * w, -0.48 * d, 0), (0.42 * w, 0.3 * d, 0.1 * h), p.primary)
    b.cyl(0, 0.3 * d, 0, 0.1 * h, 0.42 * w, p.primary, sections=16)
    b.cyl(0, 0.15 * d, 0.1 * h, 0.14 * h, 0.12 * w, tint("#f4f1c4", "light"), sections=12)  # lamp
    ay = -0.3 * d
    b.box((-0.14 * w, ay - 0.12 * d, 0.1 * h), (0.14 * w, ay + 0.08 * d, 0.72 * h), p.primary)  # arm
    b.hull([(-0.14 * w, ay - 0.12 * d, 0.6 * h), (0.14 * w, ay - 0.12 * d, 0.6 * h), (-0.14 * w, ay + 0.08 * d, 0.6 * h),
            (0.14 * w, ay + 0.08 * d, 0.6 * h), (-0.14 * w, ay - 0.1 * d, 0.86 * h), (0.14 * w, ay - 0.1 * d, 0.86 * h),
            (-0.14 * w, 0.12 * d, 0.86 * h), (0.14 * w, 0.12 * d, 0.86 * h), (-0.14 * w, 0.12 * d, 0.74 * h),
            (0.14 * w, 0.12 * d, 0.74 * h)], p.primary)
    for s in (-1, 1):  # focus knobs
        disc_x(b, s * 0.14 * w, s * 0.32 * w, ay - 0.02 * d, 0.3 * h, 0.09 * h, p.secondary, sections=14)
        disc_x(b, s * 0.32 * w, s * 0.4 * w, ay - 0.02 * d, 0.3 * h, 0.05 * h, p.secondary, sections=10)
    sz = 0.38 * h
    b.box((-0.38 * w, ay + 0.08 * d, sz - 0.03 * h), (0.38 * w, 0.36 * d, sz), p.secondary)  # stage
    b.box((-0.28 * w, 0.0, sz), (0.28 * w, 0.14 * d, sz + 0.005), GLASS)
    ny = 0.12 * d
    b.cyl(0, ny, 0.66 * h, 0.74 * h, 0.2 * w, p.accent, r_top=0.14 * w, sections=14)  # nosepiece
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        ox, oy = 0.1 * w * np.cos(a), ny + 0.06 * d * np.sin(a)
        b.cyl(ox, oy, 0.5 * h + 0.03 * h * k, 0.66 * h, 0.035 * w + 0.003, CHROME, sections=8)
    b.box((-0.16 * w, -0.05 * d, 0.86 * h), (0.16 * w, 0.16 * d, 0.9 * h), p.primary)  # head
    for s in (-1, 1):  # eyepieces tilted towards the viewer
        b.rod((s * 0.07 * w, 0.08 * d, 0.88 * h), (s * 0.1 * w, 0.42 * d, h - 0.03 * h), 0.05 * w, p.secondary,
              sections=10)
        b.rod((s * 0.1 * w, 0.42 * d, h - 0.03 * h), (s * 0.105 * w, 0.48 * d, h), 0.055 * w, BLACK, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- bunsen burner
def sample_bunsen_burner(rng, size, style):
    return make_params("bunsen_burner", rng, size, style, [CHROME, "#b0b3b8", "#c9a54a"], [BLACK, "#2b3a4a"],
                       "#d9702a", flame=bool(rng.random() < 0.85))


def build_bunsen_burner(p):
    """A burner: round base, the barrel with its air collar, a gas hose, a blue flame."""
    w, d, h = p.size
    b = Builder()
    R = 0.45 * min(w, d)
    tube_top = 0.58 * h if p.flame else h
    b.cyl(0, 0, 0, 0.06 * h, R, p.secondary, r_top=0.9 * R, sections=18)
    b.cyl(0, 0, 0.06 * h, 0.1 * h, 0.5 * R, p.primary, r_top=0.3 * R, sections=12)
    b.cyl(0, 0, 0.1 * h, tube_top, 0.2 * R, p.primary, r_top=0.22 * R, sections=12)
    b.cyl(0, 0, 0.16 * h, 0.28 * h, 0.28 * R, darker(p.primary, 0.2), sections=12)  # air collar
    b.rod((0, 0, 0.12 * h), (R * 0.95, -0.2 * R, 0.1 * h), 0.07 * R, p.primary, sections=8)  # gas inlet
    b.rod((0.95 * R, -0.2 * R, 0.1 * h), (0.97 * R, -0.9 * R, 0.03 * h), 0.1 * R, p.accent, sections=8)  # hose
    if p.flame:
        b.cyl(0, 0, tube_top, h, 0.18 * R, tint("#6aa8f0", "paint"), r_top=0.0, sections=12, alpha=170)
        b.cyl(0, 0, tube_top, tube_top + 0.45 * (h - tube_top), 0.12 * R, tint("#2a5ad0", "paint"), r_top=0.0, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- centrifuge
def sample_centrifuge(rng, size, style):
    return make_params("centrifuge", rng, size, style, [WHITE_PLASTIC, "#d9dadc", "#c9d4dc"],
                       ["#3a5a8a", "#5f6b7a", "#2b2b2b"], ["#e8c53a", "#4ab0e0", "#c0392b"],
                       open=bool(rng.random() < 0.5))


def build_centrifuge(p):
    """A benchtop centrifuge: a rounded body, a sloping control panel at the front, a round
    lid with a window (or raised at the back over the rotor and its tubes)."""
    w, d, h = p.size
    b = Builder()
    body = 0.62 * h if p.open else 0.78 * h
    R = 0.42 * min(w, d * 0.85)
    cy = -0.08 * d
    b.cyl(0, cy, 0, body, 0.5 * w, p.primary, ry=0.42 * d, sections=24)
    b.hull([(-0.4 * w, 0.2 * d, 0), (0.4 * w, 0.2 * d, 0), (-0.4 * w, d / 2, 0), (0.4 * w, d / 2, 0),
            (-0.4 * w, 0.2 * d, 0.8 * body), (0.4 * w, 0.2 * d, 0.8 * body), (-0.4 * w, d / 2, 0.4 * body),
            (0.4 * w, d / 2, 0.4 * body)], p.primary)
    b.hull([(-0.3 * w, 0.25 * d, 0.72 * body), (0.3 * w, 0.25 * d, 0.72 * body), (-0.3 * w, 0.45 * d, 0.46 * body),
            (0.3 * w, 0.45 * d, 0.46 * body), (-0.3 * w, 0.25 * d, 0.74 * body), (0.3 * w, 0.25 * d, 0.74 * body),
            (-0.3 * w, 0.46 * d, 0.48 * body), (0.3 * w, 0.46 * d, 0.48 * body)], p.secondary)
    b.hull([(-0.2 * w, 0.28 * d, 0.7 * body), (0.0, 0.28 * d, 0.7 * body), (-0.2 * w, 0.36 * d, 0.6 * body),
            (0.0, 0.36 * d, 0.6 * body), (-0.2 * w, 0.28 * d, 0.75 * body), (0.0, 0.28 * d, 0.75 * body),
            (-0.2 * w, 0.36 * d, 0.65 * body), (0.0, 0.36 * d, 0.65 * body)], GLOW_GREEN)
    b.cyl(0, cy, body, body + 0.01, 1.02 * R, darker(p.primary, 0.15), sections=28)
    if not p.open:
        b.lathe([[0, body], [R, body], [R, body + 0.05 * h], [0.8 * R, h - 0.02 * h], [0, h]], p.primary,
                x=0, y=cy, sections=28)
        b.cyl(0, cy, h - 0.02 * h, h, 0.45 * R, tint("#3a4a5a", "paint"), sections=20, alpha=200)
        return b.mesh(p.size)
    b.cyl(0, cy, body - 0.01, body + 0.012, 0.9 * R, tint("#4a4c50", "paint"), sections=24)
    b.cyl(0, cy, body + 0.012, body + 0.03, 0.7 * R, CHROME, r_top=0.5 * R, sections=20)  # rotor
    for k in range(8):
        a = 2 * np.pi * k / 8
        x, y = 0.55 * R * np.cos(a), cy + 0.55 * R * np.sin(a)
        b.cyl(x, y, body + 0.02, body + 0.06, 0.07 * R, p.accent, sections=8)
    hinge = (0, cy - R, body + 0.01)
    lid = about(rot_x(1.75), hinge)  # swung open past upright
    b.lathe([[0, body], [R, body], [R, body + 0.05 * h], [0.8 * R, body + 0.1 * h], [0, body + 0.1 * h]],
            p.primary, x=0, y=cy, sections=28, transform=lid)
    return b.mesh(p.size)


slot_roles("lathe", "paint", "metal", "plastic")
register("lathe", sample_lathe, build_lathe)
slot_roles("drill_press", "paint", "metal", "plastic")
register("drill_press", sample_drill_press, build_drill_press)
slot_roles("bandsaw", "paint", "metal", "plastic")
register("bandsaw", sample_bandsaw, build_bandsaw)
slot_roles("laser_cutter", "plastic", "plastic", "plastic")
register("laser_cutter", sample_laser_cutter, build_laser_cutter)
slot_roles("cnc_machine", "paint", "metal", "wood")
register("cnc_machine", sample_cnc_machine, build_cnc_machine)
slot_roles("3d_printer", "plastic", "plastic", "plastic")
register("3d_printer", sample_3d_printer, build_3d_printer)
slot_roles("microscope", "plastic", {"": "plastic", CHROME: "metal"}, "metal")
register("microscope", sample_microscope, build_microscope)
slot_roles("bunsen_burner", "metal", "rubber", "light")
register("bunsen_burner", sample_bunsen_burner, build_bunsen_burner)
slot_roles("centrifuge", "plastic", "plastic", "plastic")
register("centrifuge", sample_centrifuge, build_centrifuge)

