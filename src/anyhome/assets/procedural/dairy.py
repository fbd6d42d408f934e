"""A dairy farm's things: milking_point (one cow's place in a milking parlour, with its
milking cluster), cow_cubicle (a lying stall of a cubicle shed) and milk_tank (the
refrigerated bulk tank the milk is kept in)."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import CHROME, GLOW_GREEN, RUBBER, SCREEN, STEEL, disc_x, path
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
    tint,
)
from anyhome.assets.registry import register

GALVANISED = tint(["#a9adb2", "#b4b8bd", "#9a9da3"], "metal")
RAIL_PAINT = tint(["#2d6fb0", "#c0392b", "#3f8a4a", "#e0b030"], "paint")
MATS = tint(["#1c1c1e", "#2b2b2b", "#3a3b3e"], "rubber")
CONCRETE = tint(["#a8a49c", "#b5b1a8", "#9c9890"], "stone")
BEDDING = tint(["#e6d08e", "#d8c07a", "#cdb890"], "plant")
STAINLESS = tint(["#c9ccd0", "#b4b8bd", "#d4d6d8"], "metal")
WHITE_BOX = tint("#eceae4", "plastic")
COPPER_PIPE = tint("#b8733a", "metal")
COOLER = tint(["#e8e6e0", "#2d6fb0", "#3f8a4a", "#9a9da3"], "paint")


# ----------------------------------------------------------------- milking point
def sample_milking_point(rng, size, style):
    return make_params("milking_point", rng, size, style, GALVANISED + RAIL_PAINT, MATS, STEEL,
                       herringbone=bool(rng.random() < 0.7), jar=bool(rng.random() < 0.5))


def build_milking_point(p):
    """One cow's place in a milking parlour, the pit side at +y: a rubber standing mat on
    a kerb, a breast rail and a rump rail on posts (set at a slant for a ``herringbone``
    parlour, square to the pit for a parallel one), and at the pit edge the milking unit:
    a swing arm, a milk meter (a glass recorder ``jar`` or a small electronic meter with a
    screen), the long milk tube and the cluster of four teat cups hanging from its claw."""
    w, d, h = p.size
    b = Builder()
    kerb = 0.12 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, 0.3 * d, kerb), CONCRETE[0])  # the cows' standing kerb
    b.box((-0.46 * w, -0.46 * d, kerb), (0.46 * w, 0.28 * d, kerb + 0.015 * h), p.secondary)
    r = 0.018 * min(w, d) + 0.012
    slant = 0.35 * w if p.herringbone else 0.0
    for s in (-1, 1):  # the two rails a cow stands between, each on two posts
        y = s * 0.4 * d
        x0, x1 = -w / 2 + r + (slant if s > 0 else 0.0), w / 2 - r - (slant if s < 0 else 0.0)
        for x in (x0, x1):
            b.cyl(x, y, kerb, 0.72 * h, r, p.primary, sections=10)
        b.rod((x0, y, 0.7 * h), (x1, y, 0.7 * h), r, p.primary, sections=10)
        b.rod((x0, y, 0.45 * h), (x1, y, 0.45 * h), 0.8 * r, p.primary, sections=10)
    # the pit-edge post and swing arm the unit hangs from
    px, py = 0.38 * w, d / 2 - 0.05 * d
    b.cyl(px, py, 0.0, h, 1.2 * r, DARK_METAL, sections=10)
    b.rod((px, py, 0.96 * h), (-0.1 * w, py - 0.02 * d, 0.96 * h), r, DARK_METAL, sections=8)
    if p.jar:  # a glass recorder jar with a steel cap
        b.cyl(px - 0.12 * w, py, 0.62 * h, 0.9 * h, 0.07 * w + 0.02, GLASS, alpha=200, sections=14)
        b.cyl(px - 0.12 * w, py, 0.9 * h, 0.93 * h, 0.075 * w + 0.02, p.accent, sections=14)
    else:  # an electronic meter with a screen and a green lamp
        b.box((px - 0.2 * w, py - 0.04 * d, 0.72 * h), (px - 0.05 * w, py + 0.02 * d, 0.86 * h), WHITE_BOX)
        b.box((px - 0.18 * w, py + 0.02 * d, 0.76 * h), (px - 0.07 * w, py + 0.025 * d, 0.83 * h), SCREEN)
        b.sphere((px - 0.12 * w, py + 0.025 * d, 0.85 * h), 0.012, GLOW_GREEN)
    # the cluster: claw bowl, four teat cups on short tubes, the long milk tube up to the meter
    cx, cy, cz = -0.05 * w, 0.25 * d, 0.3 * h
    b.sphere((cx, cy, cz), (0.05 * w + 0.01, 0.05 * w + 0.01, 0.03 * h), p.accent)
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        tx, ty = cx + 0.08 * w * np.cos(a), cy + 0.08 * w * np.sin(a)
        b.rod((cx, cy, cz), (tx, ty, cz + 0.1 * h), 0.006, RUBBER, sections=6)
        b.cyl(tx, ty, cz + 0.1 * h, cz + 0.19 * h, 0.018, p.accent, sections=10)
    path(b, [(cx, cy, cz), (0.1 * w, py - 0.06 * d, 0.45 * h), (px - 0.12 * w, py, 0.62 * h)], 0.01, RUBBER, sections=6)
    return b.mesh(p.size)



# ----------------------------------------------------------------- cow cubicle
def sample_cow_cubicle(rng, size, style):
    return make_params("cow_cubicle", rng, size, style, GALVANISED, MATS, BEDDING,
                       loop=bool(rng.random() < 0.6), bedding=bool(rng.random() < 0.6))


def build_cow_cubicle(p):
    """One cow's lying stall, the head end at -y: a raised concrete bed with a rubber
    mattress (strewn with sawdust or straw when ``bedding``), a brisket board across it,
    a neck rail over it, and on one side the steel divider, a bent ``loop`` (a Dutch
    comfort loop down to the kerb) or a straight cantilevered rail."""
    w, d, h = p.size
    b = Builder()
    bed = 0.18 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, bed), CONCRETE[0])  # the raised bed and its kerb
    b.box((-0.47 * w, -0.47 * d, bed), (0.47 * w, 0.4 * d, bed + 0.03 * h), p.secondary)  # mattress
    if p.bedding:
        b.box((-0.44 * w, -0.3 * d, bed + 0.03 * h), (0.44 * w, 0.35 * d, bed + 0.045 * h), p.accent)
    b.box((-0.45 * w, -0.3 * d, bed), (0.45 * w, -0.27 * d, bed + 0.12 * h), darker(CONCRETE[0], 0.2))  # brisket board
    r = 0.02 * min(w, d) + 0.01
    sx = -w / 2 + r  # the divider stands on the -x side; the next cubicle's divider is this one's +x side
    b.cyl(sx, -0.46 * d, 0.0, h - r, 1.3 * r, p.primary, sections=10)  # head-end post
    if p.loop:
        pts = [(sx, -0.46 * d, h - r), (sx, -0.05 * d, h - r), (sx, 0.2 * d, 0.85 * h), (sx, 0.3 * d, 0.5 * h),
               (sx, 0.2 * d, bed + 0.15 * h), (sx, -0.3 * d, bed + 0.2 * h), (sx, -0.46 * d, bed + 0.2 * h)]
        path(b, pts, r, p.primary, sections=8)
    else:
        b.rod((sx, -0.46 * d, h - r), (sx, 0.35 * d, 0.85 * h), r, p.primary, sections=8)
        b.rod((sx, -0.46 * d, 0.55 * h), (sx, 0.2 * d, 0.5 * h), r, p.primary, sections=8)
    b.rod((-w / 2, -0.15 * d, h - 0.05 * h), (w / 2, -0.15 * d, h - 0.05 * h), 0.8 * r, lighter(p.primary, 0.1),
          sections=8)  # neck rail
    return b.mesh(p.size)


# ----------------------------------------------------------------- milk tank
def sample_milk_tank(rng, size, style):
    return make_params("milk_tank", rng, size, style, STAINLESS, COOLER, BLACK,
                       upright=bool(rng.random() < 0.25), cooler=bool(rng.random() < 0.7))


def build_milk_tank(p):
    """A refrigerated bulk milk tank in stainless steel on adjustable legs: a long
    rounded vat along x (or an ``upright`` round silo tank), a hinged manhole lid with
    the agitator's motor on top, a ladder step, an outlet valve low at one end, a control
    box with a display and, when ``cooler``, the refrigeration condensing unit beside it."""
    w, d, h = p.size
    b = Builder()
    legs = 0.22 * h
    body_w = 0.78 * w if p.cooler else w
    x0 = -w / 2
    xc = x0 + body_w / 2
    top = 0.9 * h
    r = min(0.5 * d, 0.5 * (top - legs))
    if p.upright:
        b.cyl(xc, 0.0, legs, top - 0.08 * h, 0.45 * min(body_w, d), p.primary, sections=24)
        b.cyl(xc, 0.0, top - 0.08 * h, top, 0.45 * min(body_w, d), p.primary, r_top=0.2 * min(body_w, d), sections=24)
    else:  # a vat with rounded ends: a long cylinder along x, squashed to the box
        zc = legs + r
        disc_x(b, x0 + r, x0 + body_w - r, 0.0, zc, r, p.primary, sections=24)
        for s in (-1, 1):
            b.sphere((xc + s * (body_w / 2 - r), 0.0, zc), (r, r, r), p.primary, subdivisions=2)
        b.box((x0 + 0.1 * body_w, -0.3 * d, zc), (x0 + 0.9 * body_w, 0.3 * d, top - 0.04 * h), p.primary)
    for lx in (x0 + 0.15 * body_w, x0 + 0.85 * body_w):  # legs with pad feet
        for ly in (-0.35 * d, 0.35 * d):
            b.cyl(lx, ly, 0.02 * h, legs + 0.05 * h, 0.025 * min(w, d) + 0.01, METAL, sections=8)
            b.cyl(lx, ly, 0.0, 0.02 * h, 0.045 * min(w, d) + 0.015, DARK_METAL, sections=8)
    # manhole lid and agitator motor on top
    b.cyl(xc - 0.15 * body_w, 0.0, top - 0.03 * h, top + 0.01 * h, 0.12 * min(body_w, d) + 0.05, lighter(p.primary, 0.1),
          sections=16)
    b.box((xc + 0.05 * body_w, -0.08 * d, top - 0.02 * h), (xc + 0.18 * body_w, 0.08 * d, h), DARK_METAL)
    # outlet valve at the low end and a control box on the front
    b.rod((x0, 0.0, legs + 0.08 * h), (x0 + 0.1 * body_w, 0.0, legs + 0.08 * h), 0.03 * h, CHROME, sections=10)
    b.box((xc - 0.1 * body_w, d / 2 - 0.06 * d, 0.45 * h), (xc + 0.08 * body_w, d / 2, 0.62 * h), WHITE_BOX)
    b.box((xc - 0.07 * body_w, d / 2 - 0.002, 0.5 * h), (xc + 0.05 * body_w, d / 2, 0.58 * h), SCREEN)
    if p.cooler:  # the condensing unit: a box with a fan grille
        cx0 = x0 + body_w + 0.02 * w
        b.box((cx0, -0.35 * d, 0.0), (w / 2, 0.35 * d, 0.55 * h), p.secondary)
        disc_x(b, w / 2 - 0.002, w / 2 + 0.004, 0.0, 0.3 * h, 0.4 * min(w / 2 - cx0, 0.5 * h) + 0.02, p.accent,
               sections=16)
        b.rod((cx0, 0.0, 0.5 * h), (x0 + body_w - 0.05 * w, 0.0, legs + 0.1 * h), 0.015, COPPER_PIPE, sections=6)
    return b.mesh(p.size)


slot_roles("milking_point", {"": "paint", **{c: "metal" for c in ("#a9adb2", "#b4b8bd", "#9a9da3")}}, "rubber", "metal")
register("milking_point", sample_milking_point, build_milking_point)
slot_roles("cow_cubicle", "metal", "rubber", "plant")
register("cow_cubicle", sample_cow_cubicle, build_cow_cubicle)
slot_roles("milk_tank", "metal", {"": "paint", "#9a9da3": "metal"}, "plastic")
register("milk_tank", sample_milk_tank, build_milk_tank)
