"""Appliances of kitchens, offices and shops: dishwasher, microwave, printer, photocopier,
water_cooler, popcorn_machine, beer_tap, projector, record_player, radio, typewriter,
dough_mixer, coffee_roaster."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    COPPER,
    GLOW_GREEN,
    GLOW_RED,
    SCREEN,
    STEEL,
    WHITE_PLASTIC,
    arc,
    buttons,
    caster,
    disc_x,
    disc_y,
    extrude_y,
    path,
    vent_lines,
    wheel_x,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    Builder,
    darker,
    lighter,
    make_params,
    move,
    rot_x,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register
from anyhome.assets.styles import Style

APPLIANCE_FINISHES = tint([STEEL, WHITE_PLASTIC, "#2b2b2b", "#c9ccd0"], "metal")
OFFICE_GREYS = tint(["#e6e4de", "#d9dadc", "#c9ccd0", "#3a3b3e", "#f2f1ed"], "plastic")
RETRO = tint(["#c9483a", "#7fb8a8", "#e8d9b0", "#3a6fb0", "#2b2b2b", "#e8e6e0"], "paint")
TAP_HANDLES = tint(["#c0392b", "#f1c40f", "#2e86c1", "#27ae60", BLACK, "#e67e22", "#8e44ad", "#e8e6e0"], "plastic")


def _vintage(style: Style, rng, share: float = 0.25) -> bool:
    if style_is(style, "antique", "rustic"):
        return True
    if style_is(style, "modern"):
        return False
    return bool(rng.random() < share)


# ----------------------------------------------------------------- dishwasher
def sample_dishwasher(rng, size, style):
    return make_params("dishwasher", rng, size, style, [STEEL, STEEL, WHITE_PLASTIC, "#c9ccd0", "#2b2b2b"],
                       [BLACK, "#2b2b2b", "#5f6b7a"], [GLOW_GREEN, "#4ab0e0", GLOW_RED],
                       handle=str(rng.choice(["bar", "bar", "bar", "pocket"])))


def build_dishwasher(p):
    """A built-in dishwasher: a plain door under a control strip, a kick plate below."""
    w, d, h = p.size
    b = Builder()
    kick = 0.09 * h
    strip = min(0.1 * h, 0.09)
    fy = d / 2 - 0.03
    b.box((-w / 2 + 0.02, -d / 2, 0), (w / 2 - 0.02, fy - 0.03, kick), BLACK)
    b.box((-w / 2, -d / 2, kick), (w / 2, fy, h), darker(p.primary, 0.15))
    b.box((-w / 2, fy, kick), (w / 2, d / 2 - 0.01, h - strip), p.primary)  # door
    b.box((-w / 2, fy, h - strip), (w / 2, d / 2 - 0.01, h), p.secondary)  # control strip
    b.box((-w / 2 + 0.01, fy - 0.01, h - strip - 0.006), (w / 2 - 0.01, d / 2, h - strip), DARK_METAL)
    buttons(b, 0.05 * w, 0.45 * w, h - 0.75 * strip, h - 0.25 * strip, d / 2 - 0.01, 1, 5, tint("#9a9da3", "metal"), 0.5)
    b.box((-0.35 * w, d / 2 - 0.01, h - 0.72 * strip), (-0.1 * w, d / 2 - 0.005, h - 0.28 * strip), SCREEN)
    b.box((-0.3 * w, d / 2 - 0.006, h - 0.6 * strip), (-0.2 * w, d / 2 - 0.004, h - 0.4 * strip), p.accent)
    hz = h - strip - 0.06 * h
    if p.handle == "bar":
        for x in (-0.38 * w, 0.38 * w):
            b.box((x - 0.01, d / 2 - 0.012, hz - 0.01), (x + 0.01, d / 2 - 0.002, hz + 0.01), CHROME)
        disc_x(b, -0.4 * w, 0.4 * w, d / 2 - 0.006, hz, 0.008, CHROME, sections=8)
    else:
        b.box((-0.3 * w, d / 2 - 0.011, hz - 0.02), (0.3 * w, d / 2 - 0.005, hz + 0.01), DARK_METAL)
    b.box((-w / 2 + 0.03, d / 2 - 0.011, kick + 0.02), (w / 2 - 0.03, d / 2 - 0.008, kick + 0.025),
          darker(p.primary, 0.1))
    return b.mesh(p.size)


# ----------------------------------------------------------------- microwave
def sample_microwave(rng, size, style):
    retro = _vintage(style, rng, 0.2)
    return make_params("microwave", rng, size, style, RETRO if retro else APPLIANCE_FINISHES,
                       [BLACK, "#2b2b2b"], GLOW_GREEN, dials=retro, handle=bool(rng.random() < 0.6))


def build_microwave(p):
    """A box with a door window on the left and a keypad (or two dials) on the right."""
    w, d, h = p.size
    b = Builder()
    foot = 0.04 * h
    for x in (-0.42 * w, 0.42 * w):
        for y in (-0.38 * d, 0.38 * d):
            b.cbox((x, y, foot / 2), (0.04 * w, 0.05 * d, foot), BLACK)
    fy = d / 2 - 0.015
    b.box((-w / 2, -d / 2, foot), (w / 2, fy, h), p.primary)
    split = -w / 2 + 0.7 * w
    b.box((-w / 2 + 0.004, fy, foot + 0.005), (split, d / 2 - 0.004, h - 0.005), p.secondary)  # door
    b.box((-w / 2 + 0.1 * w, d / 2 - 0.005, foot + 0.16 * h), (split - 0.1 * w, d / 2, h - 0.14 * h), tint("#14181c", "paint"))
    b.box((-w / 2 + 0.13 * w, d / 2 - 0.002, h - 0.3 * h), (-w / 2 + 0.3 * w, d / 2, h - 0.18 * h), tint("#3a4450", "paint"))
    b.box((split, fy, foot + 0.005), (w / 2 - 0.004, d / 2 - 0.006, h - 0.005), darker(p.primary, 0.12))
    px0, px1 = split + 0.03 * w, w / 2 - 0.03 * w
    if p.dials:
        for z in (0.68 * h, 0.32 * h):
            disc_y(b, (px0 + px1) / 2, d / 2 - 0.006, d / 2, z, 0.3 * (px1 - px0), CHROME, sections=14)
            b.cbox(((px0 + px1) / 2, d / 2, z + 0.05 * h), (0.02 * w, 0.006, 0.16 * h), BLACK)
    else:
        b.box((px0, d / 2 - 0.006, 0.74 * h), (px1, d / 2, 0.88 * h), SCREEN)
        b.box((px0 + 0.2 * (px1 - px0), d / 2 - 0.003, 0.78 * h), (px1 - 0.2 * (px1 - px0), d / 2, 0.84 * h),
              p.accent)
        buttons(b, px0, px1, 0.26 * h, 0.7 * h, d / 2 - 0.006, 4, 3, lighter(p.secondary, 0.5), 0.65)
        b.box((px0, d / 2 - 0.006, 0.1 * h), (px1, d / 2, 0.22 * h), tint("#3a7a4a", "paint"))  # start
    if p.handle:
        b.box((split - 0.045 * w, d / 2 - 0.004, 0.2 * h), (split - 0.025 * w, d / 2, 0.8 * h), CHROME)
    return b.mesh(p.size)


# ----------------------------------------------------------------- printer
def sample_printer(rng, size, style):
    return make_params("printer", rng, size, style, OFFICE_GREYS, [BLACK, "#3a3b3e", "#9a9da3"], GLOW_GREEN,
                       feeder=bool(rng.random() < 0.5))


def build_printer(p):
    """A desktop printer: body with a paper cassette, an output tray with a printed sheet,
    a scanner lid on top and a small control panel."""
    w, d, h = p.size
    b = Builder()
    tray = 0.22 * d
    fy = d / 2 - tray
    body_top = 0.6 * h if p.feeder else 0.8 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, fy, body_top), p.primary)
    b.box((-w / 2 + 0.01, -d / 2 + 0.005, body_top), (w / 2 - 0.01, fy - 0.01, body_top + 0.12 * h),
          lighter(p.primary, 0.15) if p.primary != tint("#f2f1ed", "paint") else tint("#d9dadc", "paint"))  # scanner lid
    b.box((-0.44 * w, fy, 0.04 * h), (0.44 * w, fy + 0.2 * tray, 0.3 * h), darker(p.primary, 0.08))  # cassette
    b.box((-0.12 * w, fy + 0.2 * tray, 0.14 * h), (0.12 * w, fy + 0.22 * tray, 0.2 * h), p.secondary)
    b.box((-0.4 * w, fy - 0.01, 0.38 * h), (0.4 * w, fy + 0.003, 0.55 * h), BLACK)  # output slot
    b.box((-0.38 * w, fy, 0.36 * h), (0.38 * w, d / 2, 0.38 * h), p.secondary)  # output tray
    b.box((-0.3 * w, fy, 0.385 * h), (0.3 * w, d / 2 - 0.02, 0.395 * h), tint("#fbfbf8", "paper"))  # printed sheet
    b.box((-0.2 * w, fy + 0.2 * tray, 0.392 * h), (0.15 * w, fy + 0.5 * tray, 0.397 * h), tint("#5a6b7a", "paint"))
    pz = body_top
    b.box((0.12 * w, fy - 0.1 * d, pz - 0.02 * h), (0.46 * w, fy + 0.02, pz + 0.05 * h), p.secondary)  # panel
    b.box((0.16 * w, fy - 0.08 * d, pz + 0.05 * h), (0.3 * w, fy - 0.01, pz + 0.055 * h), SCREEN)
    for k in range(3):
        b.cbox((0.35 * w + 0.035 * w * k, fy - 0.04 * d, pz + 0.055 * h), (0.02 * w, 0.02 * d, 0.01 * h),
               p.accent if k == 0 else lighter(p.secondary, 0.4))
    if p.feeder:  # a sheet feeder standing up at the back
        z0 = body_top + 0.1 * h
        b.hull([(-0.35 * w, -d / 2 + 0.12 * d, z0), (0.35 * w, -d / 2 + 0.12 * d, z0), (-0.35 * w, -d / 2 + 0.16 * d, z0),
                (0.35 * w, -d / 2 + 0.16 * d, z0), (-0.35 * w, -d / 2, h), (0.35 * w, -d / 2, h),
                (-0.35 * w, -d / 2 + 0.04 * d, h), (0.35 * w, -d / 2 + 0.04 * d, h)], p.secondary)
        b.hull([(-0.3 * w, -d / 2 + 0.165 * d, z0 + 0.02 * h), (0.3 * w, -d / 2 + 0.165 * d, z0 + 0.02 * h),
                (-0.3 * w, -d / 2 + 0.17 * d, z0 + 0.02 * h), (0.3 * w, -d / 2 + 0.17 * d, z0 + 0.02 * h),
                (-0.3 * w, -d / 2 + 0.05 * d, 0.97 * h), (0.3 * w, -d / 2 + 0.05 * d, 0.97 * h),
                (-0.3 * w, -d / 2 + 0.055 * d, 0.97 * h), (0.3 * w, -d / 2 + 0.055 * d, 0.97 * h)], tint("#fbfbf8", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- photocopier
def sample_photocopier(rng, size, style):
    return make_params("photocopier", rng, size, style, OFFICE_GREYS[:3] + ["#f2f1ed"],
                       ["#3a3b3e", "#5f6b7a", BLACK], "#4ab0e0", drawers=int(rng.integers(2, 5)),
                       finisher=bool(rng.random() < 0.5))


def build_photocopier(p):
    """A floor copier: paper drawers on castors, the print engine, a sheet output tray on
    the left, the scanner glass and document feeder on top and a tilted touch panel."""
    w, d, h = p.size
    b = Builder()
    wheel = 0.025 * h
    side = 0.18 * w
    x0 = -w / 2 + side
    base_top = 0.55 * h
    for x in (x0 + 0.05, w / 2 - 0.05):
        for y in (-d / 2 + 0.05, d / 2 - 0.07):
            caster(b, x, y, wheel / 2.6)
    b.box((x0, -d / 2, wheel), (w / 2, d / 2 - 0.02, base_top), p.primary)
    n = p.drawers
    dz = (base_top - wheel - 0.02) / n
    for k in range(n):
        z0 = wheel + 0.01 + k * dz
        b.box((x0 + 0.01, d / 2 - 0.02, z0 + 0.008), (w / 2 - 0.01, d / 2, z0 + dz - 0.008), lighter(p.primary, 0.1))
        b.box((x0 + 0.3 * (w / 2 - x0), d / 2, z0 + dz - 0.05), (w / 2 - 0.3 * (w / 2 - x0), d / 2 + 0.001,
                                                                  z0 + dz - 0.03), p.secondary)
    top = 0.86 * h
    b.box((x0, -d / 2, base_top), (w / 2, d / 2 - 0.04, top), lighter(p.primary, 0.05))
    b.box((x0, d / 2 - 0.04, base_top + 0.02), (w / 2, d / 2 - 0.03, base_top + 0.05), p.secondary)
    # output tray on the left with a few sheets
    b.box((-w / 2 + 0.01, -0.35 * d, base_top + 0.04 * h), (x0, 0.3 * d, base_top + 0.055 * h), p.secondary)
    b.box((-w / 2 + 0.03, -0.3 * d, base_top + 0.055 * h), (x0, 0.25 * d, base_top + 0.075 * h), tint("#fbfbf8", "paint"))
    if p.finisher:
        b.box((-w / 2, -0.4 * d, wheel), (x0, 0.35 * d, base_top + 0.03 * h), darker(p.primary, 0.06))
    b.box((x0 + 0.01, -d / 2 + 0.01, top), (w / 2 - 0.01, d / 2 - 0.06, top + 0.03 * h), tint("#2a3a44", "glass"))  # glass
    b.box((x0, -d / 2, top + 0.03 * h), (w / 2, d / 2 - 0.08, top + 0.07 * h), p.primary)  # lid
    b.box((x0 + 0.06, -d / 2 + 0.05, top + 0.07 * h), (w / 2 - 0.06, 0.1 * d, h), lighter(p.primary, 0.1))  # feeder
    b.box((x0 + 0.1, 0.1 * d, top + 0.07 * h), (w / 2 - 0.1, 0.3 * d, top + 0.075 * h), tint("#fbfbf8", "paint"))
    # tilted control panel at the front right
    px0, px1 = 0.05 * w, w / 2 - 0.01
    b.hull([(px0, d / 2 - 0.1, top - 0.04 * h), (px1, d / 2 - 0.1, top - 0.04 * h), (px0, d / 2, top - 0.06 * h),
            (px1, d / 2, top - 0.06 * h), (px0, d / 2 - 0.1, top + 0.02 * h), (px1, d / 2 - 0.1, top + 0.02 * h),
            (px0, d / 2, top - 0.03 * h), (px1, d / 2, top - 0.03 * h)], p.secondary)
    b.hull([(px0 + 0.02, d / 2 - 0.08, top + 0.011 * h), (px1 - 0.08, d / 2 - 0.08, top + 0.011 * h),
            (px0 + 0.02, d / 2 - 0.015, top - 0.024 * h), (px1 - 0.08, d / 2 - 0.015, top - 0.024 * h),
            (px0 + 0.02, d / 2 - 0.08, top + 0.021 * h), (px1 - 0.08, d / 2 - 0.08, top + 0.021 * h),
            (px0 + 0.02, d / 2 - 0.015, top - 0.014 * h), (px1 - 0.08, d / 2 - 0.015, top - 0.014 * h)], p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- water cooler
def sample_water_cooler(rng, size, style):
    return make_params("water_cooler", rng, size, style, [WHITE_PLASTIC, "#d9dadc", STEEL, "#3a3b3e"],
                       "#8cc4e8", "#c9ccd0", bottle=bool(rng.random() < 0.8))


def build_water_cooler(p):
    """A slim cabinet with a red and a blue tap in a recess; a big blue bottle upside down on top."""
    w, d, h = p.size
    b = Builder()
    top = 0.66 * h if p.bottle else 0.96 * h
    b.box((-w / 2 + 0.01, -d / 2 + 0.01, 0), (w / 2 - 0.01, d / 2 - 0.01, 0.03 * h), DARK_METAL)
    b.box((-w / 2, -d / 2, 0.03 * h), (w / 2, d / 2 - 0.02, top), p.primary)
    b.box((-w / 2 + 0.015, d / 2 - 0.02, 0.03 * h), (w / 2 - 0.015, d / 2, 0.36 * top), p.primary)
    b.box((-0.38 * w, d / 2 - 0.06, 0.62 * top), (0.38 * w, d / 2 - 0.019, 0.88 * top), tint("#4a4c50", "paint"))  # recess
    b.box((-w / 2 + 0.015, d / 2 - 0.02, 0.88 * top), (w / 2 - 0.015, d / 2, top), p.primary)
    b.box((-0.35 * w, d / 2 - 0.07, 0.6 * top), (0.35 * w, d / 2, 0.63 * top), p.accent)  # drip tray
    for x, col in ((-0.18 * w, "#d63a2a"), (0.18 * w, "#2e74c8")):
        b.box((x - 0.03 * w, d / 2 - 0.06, 0.8 * top), (x + 0.03 * w, d / 2 - 0.01, 0.86 * top), col, role="plastic")
        b.cyl(x, d / 2 - 0.025, 0.74 * top, 0.8 * top, 0.012, col, sections=8, role="plastic")
    b.box((-w / 2 + 0.015, d / 2 - 0.021, 0.36 * top), (w / 2 - 0.015, d / 2, 0.6 * top), lighter(p.primary, 0.1))
    if p.bottle:
        r = 0.45 * min(w, d)
        bz = top + 0.03 * h
        b.cyl(0, 0, top, bz, 0.5 * r, p.accent, sections=16)  # collar
        b.lathe([[0, bz], [0.25 * r, bz], [0.25 * r, bz + 0.05 * h], [r, bz + 0.12 * h], [r, h - 0.04 * h],
                 [0.9 * r, h], [0, h]], p.secondary, sections=20)
        for z in (bz + 0.16 * h, h - 0.1 * h):
            b.cyl(0, 0, z, z + 0.01 * h, r * 1.015, darker(p.secondary, 0.12), sections=20)
    return b.mesh(p.size)


# ----------------------------------------------------------------- popcorn machine
def sample_popcorn_machine(rng, size, style):
    return make_params("popcorn_machine", rng, size, style, ["#c0392b", "#b8322a", "#d63a2a", "#2b2b2b"],
                       "#f1c40f", CHROME)


def build_popcorn_machine(p):
    """A glass kettle cabinet full of popcorn on a red cart with two wheels (a
    countertop machine alone in a low box)."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    cart = h > 1.0
    c0 = 0.55 * h if cart else 0.0
    if cart:
        b.box((-0.42 * w, -0.4 * d, 0.12 * h), (0.42 * w, 0.4 * d, c0 - 0.03 * h), p.primary)
        b.box((-0.42 * w, 0.4 * d - 0.005, 0.25 * h), (0.42 * w, 0.4 * d, 0.4 * h), p.secondary)  # sign band
        b.box((-0.44 * w, -0.42 * d, c0 - 0.03 * h), (0.44 * w, 0.42 * d, c0), darker(p.primary, 0.3))
        r = 0.11 * h
        for x in (-0.44 * w, 0.44 * w):
            wheel_x(b, x + (0.03 * w if x < 0 else -0.03 * w), -0.18 * d, r, r, 0.05 * w, tint(BLACK, "rubber"), p.secondary,
                    spokes=4)
        for x in (-0.3 * w, 0.3 * w):
            b.box((x - 0.02, 0.28 * d, 0), (x + 0.02, 0.32 * d, 0.12 * h), DARK_METAL)
        path(b, [(-0.44 * w, -0.42 * d, c0 - 0.04 * h), (-0.5 * w, -0.5 * d, c0 + 0.05 * h),
                 (0.5 * w, -0.5 * d, c0 + 0.05 * h), (0.44 * w, -0.42 * d, c0 - 0.04 * h)], 0.012, p.accent)
    hb = h - c0
    g0, g1 = c0 + 0.12 * hb, c0 + 0.8 * hb
    x0, x1, y0, y1 = -0.4 * w, 0.4 * w, -0.36 * d, 0.36 * d
    b.box((x0, y0, c0), (x1, y1, g0), p.primary)
    b.box((x0 + 0.05 * w, y1 - 0.002, c0 + 0.02 * hb), (x1 - 0.05 * w, y1, g0 - 0.02 * hb), p.secondary)
    for _ in range(60):  # popcorn heap
        x, y = rng.uniform(0.95 * x0, 0.95 * x1), rng.uniform(0.95 * y0, 0.95 * y1)
        z = g0 + rng.uniform(0, 0.28 * (g1 - g0)) * (1.2 - abs(x) / (x1 + 1e-9))
        b.sphere((x, y, z), 0.018 + 0.01 * rng.random(), tint("#fbf3c8", "light") if rng.random() < 0.8 else tint("#f1d27a", "paint"),
                 subdivisions=0)
    b.box((x0, y0, g0), (x1, y1, g0 + 0.01 * hb), p.primary)
    b.cyl(0, 0, g1 - 0.3 * (g1 - g0), g1 - 0.12 * (g1 - g0), 0.15 * w, CHROME, r_top=0.17 * w, sections=14)
    b.cyl(0, 0, g1 - 0.12 * (g1 - g0), g1, 0.015, CHROME, sections=6)
    for x in (x0, x1):
        for y in (y0, y1):
            b.box((x - 0.012, y - 0.012, g0), (x + 0.012, y + 0.012, g1), p.primary)
    b.box((x0, y0, g0), (x1, y1, g1), GLASS, alpha=70)
    b.box((x0 - 0.01, y0 - 0.01, g1), (x1 + 0.01, y1 + 0.01, g1 + 0.06 * hb), p.primary)
    b.hull([(x0 - 0.01, y0 - 0.01, g1 + 0.06 * hb), (x1 + 0.01, y0 - 0.01, g1 + 0.06 * hb),
            (x0 - 0.01, y1 + 0.01, g1 + 0.06 * hb), (x1 + 0.01, y1 + 0.01, g1 + 0.06 * hb),
            (x0 + 0.2 * w, y0 + 0.2 * d, h - 0.04 * hb), (x1 - 0.2 * w, y0 + 0.2 * d, h - 0.04 * hb),
            (x0 + 0.2 * w, y1 - 0.2 * d, h - 0.04 * hb), (x1 - 0.2 * w, y1 - 0.2 * d, h - 0.04 * hb)], p.primary)
    b.box((x0 + 0.05 * w, y1 - 0.02, g1 + 0.005 * hb), (x1 - 0.05 * w, y1 + 0.012, g1 + 0.055 * hb), p.secondary)
    b.cyl(0, 0, h - 0.04 * hb, h, 0.05 * w, p.secondary, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- beer tap
def sample_beer_tap(rng, size, style):
    return make_params("beer_tap", rng, size, style, [CHROME, BRASS, COPPER, "#2b2b2b"], STEEL,
                       TAP_HANDLES, taps=int(rng.integers(3, 7)), tower=str(rng.choice(["tee", "pillars"])))


def build_beer_tap(p):
    """A draught tower on a drip tray: faucets in a row, tall coloured handles above them."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    n = p.taps
    tray_h = 0.06 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, tray_h), p.secondary)
    for k in range(int(max(3, w / 0.02))):  # drip grate
        x = -w / 2 + 0.01 + (k + 0.5) * (w - 0.02) / int(max(3, w / 0.02))
        b.box((x - 0.003, -d / 2 + 0.01, tray_h), (x + 0.003, d / 2 - 0.01, tray_h + 0.004), darker(p.secondary, 0.3))
    xs = [(-0.5 + (k + 0.5) / n) * 0.88 * w for k in range(n)]
    bar_z = 0.55 * h
    r = min(0.03, 0.25 * w / n, 0.2 * d)
    if p.tower == "tee":
        b.cyl(0, -0.1 * d, tray_h, bar_z, 0.07 * min(w, 1.2), p.primary, sections=16)
        b.rod((-0.47 * w, -0.1 * d, bar_z), (0.47 * w, -0.1 * d, bar_z), 1.3 * r, p.primary, sections=14)
        for s in (-1, 1):
            b.sphere((s * 0.47 * w, -0.1 * d, bar_z), 1.3 * r, p.primary, subdivisions=1)
    else:
        for x in xs:
            b.cyl(x, -0.1 * d, tray_h, bar_z + r, 0.8 * r, p.primary, sections=12)
            b.sphere((x, -0.1 * d, bar_z + r), 0.8 * r, p.primary, subdivisions=1)
    for x in xs:
        b.rod((x, -0.1 * d, bar_z), (x, 0.25 * d, bar_z), 0.5 * r, p.primary, sections=8)
        b.cyl(x, 0.25 * d, bar_z - 0.12 * h, bar_z, 0.45 * r, p.primary, sections=8)  # spout
        hc = TAP_HANDLES[int(rng.integers(len(TAP_HANDLES)))]
        top = h - rng.uniform(0, 0.1) * h
        b.cyl(x, 0.22 * d, bar_z, bar_z + 0.05 * h, 0.45 * r, BLACK, sections=8)
        b.cyl(x, 0.22 * d, bar_z + 0.05 * h, top, 0.55 * r, hc, r_top=0.9 * r, sections=8)
        b.box((x - 0.9 * r, 0.22 * d + 0.5 * r, top - 0.18 * h), (x + 0.9 * r, 0.22 * d + 0.9 * r, top - 0.04 * h),
              lighter(hc, 0.5))
    return b.mesh(p.size)


# ----------------------------------------------------------------- projector
def sample_projector(rng, size, style):
    w, d, h = size
    film = h > 0.45 * max(w, d) and _vintage(style, rng, 0.5)
    return make_params("projector", rng, size, style, ["#e8e6e0", BLACK, "#2b2b2b", "#d9dadc"] if not film
                       else [DARK_METAL, "#3a4a3a", "#5a4a3a"], [BLACK, "#3a3b3e"], "#4ab0e0",
                       kind="film" if film else "video")


def build_projector(p):
    """A video projector (a low body, a big lens at the front left, vents) or, in a
    tall box, a film projector with two reels on arms."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "film":
        body = 0.4 * h
        b.box((-0.3 * w, -0.3 * d, 0), (0.3 * w, 0.3 * d, 0.06 * h), BLACK)
        b.box((-0.22 * w, -0.25 * d, 0.06 * h), (0.22 * w, 0.25 * d, body), p.primary)
        disc_y(b, -0.05 * w, 0.25 * d, d / 2, 0.25 * h, 0.07 * h, p.secondary, sections=16)
        disc_y(b, -0.05 * w, d / 2 - 0.005, d / 2, 0.25 * h, 0.05 * h, tint("#8ab0c8", "paint"), sections=16)
        R = min(0.3 * h, 0.25 * d)
        for y in (-d / 2 + R, d / 2 - R):
            zc = h - R
            b.rod((0.1 * w, 0.5 * y, body), (0.1 * w, y, zc), 0.01, p.primary, sections=6)
            disc_x(b, 0.05 * w, 0.15 * w, y, zc, R, tint("#3a3b3e", "paint"), sections=24)
            disc_x(b, 0.045 * w, 0.155 * w, y, zc, 0.15 * R, CHROME, sections=10)
            for k in range(3):
                a = 2 * np.pi * k / 3
                disc_x(b, 0.04 * w, 0.16 * w, y + 0.55 * R * np.cos(a), zc + 0.55 * R * np.sin(a), 0.2 * R,
                       tint("#15161a", "paint"), sections=10)
        return b.mesh(p.size)
    foot = 0.08 * h
    for x in (-0.35 * w, 0.35 * w):
        b.cyl(x, 0.3 * d, 0, foot, 0.04 * w, BLACK, sections=8)
    b.cyl(0, -0.35 * d, 0, foot, 0.04 * w, BLACK, sections=8)
    b.box((-w / 2, -d / 2, foot), (w / 2, 0.42 * d, h), p.primary)
    b.box((-w / 2 + 0.01, -d / 2 + 0.01, h - 0.01), (w / 2 - 0.01, 0.4 * d, h), lighter(p.primary, 0.1))
    lx, lz, lr = -0.22 * w, (foot + h) / 2, 0.33 * (h - foot)
    disc_y(b, lx, 0.42 * d, d / 2, lz, lr, p.secondary, sections=20)
    disc_y(b, lx, d / 2 - 0.004, d / 2, lz, 0.7 * lr, tint("#2a4a6a", "paint"), sections=20)
    disc_y(b, lx + 0.2 * lr, d / 2 - 0.002, d / 2 + 0.0001, lz + 0.25 * lr, 0.18 * lr, tint("#8ab0c8", "paint"), sections=10)
    vent_lines(b, 0.08 * w, 0.45 * w, foot + 0.2 * h, h - 0.2 * h, 0.42 * d, 4, darker(p.primary, 0.5))
    b.box((0.15 * w, -0.2 * d, h), (0.3 * w, 0.0, h + 0.002), p.secondary)
    b.cbox((0.36 * w, 0.25 * d, h + 0.001), (0.03 * w, 0.04 * d, 0.002), p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- record player
def sample_record_player(rng, size, style):
    w, d, h = size
    gram = h > 0.6 * max(w, d) and _vintage(style, rng, 0.5)
    return make_params("record_player", rng, size, style, wood_tones(style) + [BLACK, "#e8e6e0"],
                       [BLACK, "#15161a"], ["#c0392b", "#f1c40f", "#2e86c1", "#e8e6e0"],
                       kind="gramophone" if gram else "turntable", lid=bool(rng.random() < 0.4))


def _platter(b: Builder, cx: float, cy: float, z: float, R: float, p) -> float:
    b.cyl(cx, cy, z, z + 0.012, R, CHROME, sections=28)
    b.cyl(cx, cy, z + 0.012, z + 0.016, 0.97 * R, p.secondary, sections=28)
    for k in (0.5, 0.75):
        b.cyl(cx, cy, z + 0.016, z + 0.0165, k * R, tint("#2a2a2e", "paint"), r_top=k * R, sections=28)
    b.cyl(cx, cy, z + 0.016, z + 0.017, 0.33 * R, p.accent, sections=16)
    b.cyl(cx, cy, z + 0.017, z + 0.03, 0.02 * R + 0.002, CHROME, sections=6)
    return z + 0.017


def build_record_player(p):
    """A turntable: plinth, platter with a record and its label, a tonearm; or, in a tall
    box, a gramophone with a brass horn."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "gramophone":
        base = 0.3 * h
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, base), p.primary)
        b.box((-w / 2 + 0.01, -d / 2 + 0.01, base), (w / 2 - 0.01, d / 2 - 0.01, base + 0.01), darker(p.primary, 0.2))
        R = 0.4 * min(w, d)
        zt = _platter(b, 0, 0, base + 0.01, R, p)
        disc_x(b, w / 2, w / 2 + 0.001, 0, 0.5 * base, 0.1 * base, BRASS)
        path(b, [(w / 2, 0, 0.5 * base), (w / 2, 0.1 * d, 0.4 * base), (w / 2, 0.1 * d, 0.2 * base)], 0.006, BRASS)
        arm0 = (0.35 * w, -0.35 * d, zt + 0.02)
        path(b, [(0.35 * w, -0.35 * d, base), arm0, (0.1 * w, 0.1 * d, zt + 0.04)], 0.012, BRASS)
        # the horn: a flaring trumpet rising from the arm to a bell facing +y, up
        axis0 = np.array([0.1 * w, 0.1 * d, zt + 0.04])
        bell = np.array([0.0, 0.05 * d, h - 0.42 * min(w, d) * 0.9])
        b.rod(axis0, bell, 0.02, BRASS, sections=10)
        Rb = 0.45 * min(w, d)
        L = h - bell[2]
        b.lathe([[0.02, 0], [0.05 * Rb, 0.2 * L], [0.25 * Rb, 0.6 * L], [Rb, L], [0.96 * Rb, L],
                 [0.2 * Rb, 0.6 * L + 0.01], [0, 0.3 * L]], BRASS, sections=28, transform=move(bell) @ rot_x(-0.35))
        return b.mesh(p.size)
    foot = 0.12 * h
    for x, y in ((-0.42 * w, -0.4 * d), (0.42 * w, -0.4 * d), (-0.42 * w, 0.4 * d), (0.42 * w, 0.4 * d)):
        b.cyl(x, y, 0, foot, 0.035 * w, BLACK, sections=8)
    top = 0.55 * h
    b.box((-w / 2, -d / 2, foot), (w / 2, d / 2, top), p.primary)
    R = min(0.42 * d, 0.32 * w)
    cx = -w / 2 + R + 0.05 * w
    zt = _platter(b, cx, 0.0, top, R, p)
    px, py = w / 2 - 0.12 * w, -d / 2 + 0.15 * d
    b.cyl(px, py, top, zt + 0.03, 0.05 * w, CHROME, sections=12)
    b.rod((px, py + 0.01, zt + 0.03), (px - 0.06 * w, py - 0.12 * d, zt + 0.03), 0.01, DARK_METAL, sections=6)
    tip = (cx + 0.6 * R, 0.35 * R, zt + 0.012)
    b.rod((px, py, zt + 0.03), tip, 0.006, CHROME, sections=6)
    b.cbox(tip, (0.03 * w, 0.05 * d, 0.012), BLACK)
    for k in range(2):
        disc_y(b, w / 2 - 0.08 * w - k * 0.09 * w, d / 2, d / 2 + 0.002, (foot + top) / 2, 0.2 * (top - foot),
               CHROME, sections=10)
    if p.lid:  # a smoked dust cover raised at the back
        b.box((-w / 2, -d / 2, top), (w / 2, -d / 2 + 0.01, h), tint("#3a3f46", "paint"), alpha=120)
    return b.mesh(p.size)


# ----------------------------------------------------------------- radio
def sample_radio(rng, size, style):
    cathedral = _vintage(style, rng, 0.4)
    return make_params("radio", rng, size, style,
                       wood_tones(style) if cathedral else RETRO + [BLACK, "#9a9da3"],
                       ["#c9a878", "#d9c39a", "#b8a27a"] if cathedral else [CHROME, "#3a3b3e", "#e8e6e0"],
                       "#f4e0a0", kind="cathedral" if cathedral else "transistor")


def build_radio(p):
    """A transistor radio (speaker grille, dial window, knobs, a handle and an aerial)
    or an arched wooden cathedral radio with a cloth grille."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "cathedral":
        r = w / 2
        shoulder = max(0.05 * h, h - r)
        prof = [(-w / 2, 0), (w / 2, 0), (w / 2, shoulder)] + arc(0, shoulder, r, 0, np.pi, 16)[1:-1] + \
            [(-w / 2, shoulder)]
        prof = [(x, min(z, h)) for x, z in prof]
        extrude_y(b, prof, -d / 2, d / 2 - 0.01, p.primary)
        gi = 0.72
        gs = 0.3 * h
        gprof = [(-gi * r * 0.8, gs), (gi * r * 0.8, gs), (gi * r * 0.8, max(gs, shoulder))] + \
            arc(0, max(gs, shoulder), gi * r * 0.8, 0, np.pi, 12)[1:-1] + [(-gi * r * 0.8, max(gs, shoulder))]
        gprof = [(x, min(z, 0.92 * h)) for x, z in gprof]
        extrude_y(b, gprof, d / 2 - 0.012, d / 2 - 0.004, p.secondary)
        for k in (-1, 0, 1):  # fretwork bars over the cloth
            b.box((k * 0.22 * r - 0.012, d / 2 - 0.006, gs), (k * 0.22 * r + 0.012, d / 2, 0.8 * h), darker(p.primary))
        disc_y(b, 0, d / 2 - 0.01, d / 2, 0.17 * h, 0.08 * h, p.accent, sections=16)
        for x in (-0.55 * r, 0.55 * r):
            disc_y(b, x, d / 2 - 0.01, d / 2 + 0.002, 0.14 * h, 0.045 * h, darker(p.primary, 0.5), sections=10)
        return b.mesh(p.size)
    foot = 0.0
    top = 0.72 * h
    b.box((-w / 2, -d / 2, foot), (w / 2, d / 2 - 0.01, top), p.primary)
    b.box((-w / 2 + 0.01, d / 2 - 0.012, 0.1 * top), (0.1 * w, d / 2, 0.9 * top), p.secondary)  # grille plate
    for k in range(7):
        z = 0.16 * top + k * 0.1 * top
        b.box((-w / 2 + 0.03, d / 2 - 0.002, z), (0.08 * w, d / 2 + 0.001, z + 0.03 * top), darker(p.secondary, 0.5))
    b.box((0.15 * w, d / 2 - 0.012, 0.5 * top), (w / 2 - 0.03, d / 2, 0.85 * top), p.accent)  # dial window
    for k in range(6):
        x = 0.17 * w + k * (w / 2 - 0.05 - 0.17 * w) / 5
        b.box((x, d / 2, 0.72 * top), (x + 0.003, d / 2 + 0.001, 0.8 * top), BLACK)
    b.box((0.3 * w, d / 2, 0.55 * top), (0.31 * w, d / 2 + 0.002, 0.83 * top), GLOW_RED)
    for x in (0.22 * w, 0.4 * w):
        disc_y(b, x, d / 2 - 0.01, d / 2 + 0.01, 0.27 * top, 0.1 * top, p.secondary, sections=12)
    for x in (-0.38 * w, 0.38 * w):
        b.box((x - 0.02, -0.1 * d, top), (x + 0.02, 0.1 * d, top + 0.12 * h), p.secondary)
    b.box((-0.4 * w, -0.1 * d, top + 0.1 * h), (0.4 * w, 0.1 * d, top + 0.14 * h), p.secondary)  # handle
    b.rod((w / 2 - 0.03, -0.3 * d, top), (w / 2 - 0.01, -0.35 * d, h), 0.004, CHROME, sections=5)  # aerial
    return b.mesh(p.size)


# ----------------------------------------------------------------- typewriter
def sample_typewriter(rng, size, style):
    return make_params("typewriter", rng, size, style, [BLACK, "#2b2b2b", "#7fb8a8", "#c9483a", "#3a6fb0",
                                                        "#e8d9b0"], CHROME, "#fbfbf8", paper=bool(rng.random() < 0.8))


def build_typewriter(p):
    """A typewriter: rows of round keys stepping up to the carriage, a black platen
    roller across the back, a sheet of paper standing in it and the return lever."""
    w, d, h = p.size
    b = Builder()
    top = 0.55 * h if p.paper else 0.85 * h
    back = -d / 2 + 0.3 * d
    b.hull([(-w / 2 + 0.03 * w, d / 2, 0), (w / 2 - 0.03 * w, d / 2, 0), (-w / 2 + 0.03 * w, -d / 2 + 0.05, 0),
            (w / 2 - 0.03 * w, -d / 2 + 0.05, 0), (-w / 2 + 0.03 * w, d / 2, 0.12 * top),
            (w / 2 - 0.03 * w, d / 2, 0.12 * top), (-w / 2 + 0.05 * w, back, 0.75 * top),
            (w / 2 - 0.05 * w, back, 0.75 * top), (-w / 2 + 0.05 * w, -d / 2 + 0.05, 0.75 * top),
            (w / 2 - 0.05 * w, -d / 2 + 0.05, 0.75 * top)], p.primary)
    for row in range(4):
        t = (row + 0.5) / 4.6
        y = d / 2 - 0.06 * d - t * (d / 2 - 0.06 * d - back)
        z = 0.12 * top + t * 0.63 * top + 0.04 * top
        n = 10 - (row % 2)
        for k in range(n):
            x = (-0.5 + (k + 0.5 + 0.3 * (row % 2)) / 10.6) * 0.8 * w
            b.cyl(x, y, z + 0.0 * top, z + 0.05 * top, 0.022 * w + 0.002, BLACK, sections=8)
            b.cyl(x, y, z + 0.05 * top, z + 0.055 * top, 0.018 * w + 0.002, tint("#e8e6e0", "paint"), sections=8)
    b.box((-0.25 * w, d / 2 - 0.05 * d, 0.1 * top), (0.25 * w, d / 2 - 0.01, 0.16 * top), BLACK)  # space bar
    b.cyl(0, back - 0.02, 0.6 * top, 0.8 * top, 0.15 * w, darker(p.primary, 0.4), sections=12)  # type basket
    pr = 0.12 * top + 0.01
    pz = 0.75 * top + pr
    py = back - 0.3 * (back + d / 2)
    disc_x(b, -w / 2 + 0.04 * w, w / 2 - 0.04 * w, py, pz, pr, tint("#15161a", "paint"), sections=16)  # platen
    disc_x(b, -w / 2 + 0.06 * w, w / 2 - 0.06 * w, py + 0.6 * pr, pz - 0.3 * pr, 0.35 * pr, p.secondary, sections=8)
    for s in (-1, 1):
        disc_x(b, s * (w / 2 - 0.04 * w), s * (w / 2), py, pz, 0.8 * pr, BLACK, sections=12)
    b.box((-0.35 * w, py - pr - 0.01, pz - 0.6 * pr), (0.35 * w, py + pr + 0.01, pz - 0.2 * pr), p.primary)
    path(b, [(-w / 2 + 0.06 * w, py + pr, pz + 0.4 * pr), (-w / 2 + 0.05 * w, py + pr + 0.06 * d, pz + 0.8 * pr),
             (-w / 2 + 0.02 * w, py + pr + 0.1 * d, pz + 0.8 * pr)], 0.004, p.secondary)
    if p.paper:
        b.hull([(-0.28 * w, py - 0.3 * pr, pz + 0.9 * pr), (0.28 * w, py - 0.3 * pr, pz + 0.9 * pr),
                (-0.28 * w, py - 0.3 * pr - 0.002, pz + 0.9 * pr), (0.28 * w, py - 0.3 * pr - 0.002, pz + 0.9 * pr),
                (-0.28 * w, -d / 2, h), (0.28 * w, -d / 2, h), (-0.28 * w, -d / 2 + 0.003, h),
                (0.28 * w, -d / 2 + 0.003, h)], p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dough mixer
def sample_dough_mixer(rng, size, style):
    return make_params("dough_mixer", rng, size, style, ["#e8e6e0", "#9a9da3", "#c0392b", "#3a6fb0", "#3f6b4a"],
                       STEEL, "#e8d3a8")


def build_dough_mixer(p):
    """A bakery spiral mixer: pedestal, a steel bowl with dough, the column at the back
    and the head arm reaching over the bowl with its spiral hook."""
    w, d, h = p.size
    b = Builder()
    base = 0.36 * h
    b.box((-0.45 * w, -d / 2, 0.04 * h), (0.45 * w, d / 2, base), p.primary)
    b.box((-0.47 * w, -d / 2, 0), (0.47 * w, d / 2, 0.04 * h), DARK_METAL)
    R = min(0.45 * w, 0.35 * d)
    by = d / 2 - R - 0.02
    bz1 = base + 0.3 * h
    b.cyl(0, by, base, base + 0.03 * h, 0.6 * R, DARK_METAL, sections=20)
    b.lathe([[0, base + 0.03 * h], [0.75 * R, base + 0.03 * h], [R, base + 0.12 * h], [R, bz1], [0.95 * R, bz1],
             [0.95 * R, base + 0.12 * h], [0, base + 0.07 * h]], p.secondary, x=0, y=by, sections=28)
    b.cyl(0, by, base + 0.07 * h, base + 0.2 * h, 0.9 * R, p.accent, r_top=0.75 * R, sections=20)  # dough
    b.sphere((0.2 * R, by + 0.1 * R, base + 0.2 * h), (0.5 * R, 0.45 * R, 0.06 * h), p.accent, subdivisions=1)
    col_y1 = -d / 2 + 0.28 * d
    b.box((-0.4 * w, -d / 2, base), (0.4 * w, col_y1, h - 0.2 * h), p.primary)
    b.box((-0.42 * w, -d / 2, h - 0.22 * h), (0.42 * w, by + 0.35 * R, h - 0.02 * h), p.primary)  # head arm
    b.rod((-0.42 * w, by + 0.35 * R, h - 0.12 * h), (0.42 * w, by + 0.35 * R, h - 0.12 * h), 0.1 * h,
          p.primary, sections=16)
    b.box((-0.3 * w, -d / 2 + 0.03, h - 0.02 * h), (0.3 * w, col_y1, h), lighter(p.primary, 0.2))
    hook = [(0.35 * R * np.cos(t * 3.5 * np.pi), by + 0.35 * R * np.sin(t * 3.5 * np.pi),
             h - 0.22 * h - t * 0.33 * h) for t in np.linspace(0, 1, 14)]
    path(b, [(0, by, h - 0.22 * h)] + hook, 0.015, STEEL)
    b.box((-0.3 * w, col_y1, 0.55 * h), (0.3 * w, col_y1 + 0.01, 0.7 * h), DARK_METAL)  # control panel
    buttons(b, -0.25 * w, 0.15 * w, 0.57 * h, 0.68 * h, col_y1 + 0.01, 2, 3, tint("#e8e6e0", "paint"), 0.5)
    disc_y(b, 0.2 * w, col_y1 + 0.01, col_y1 + 0.04, 0.625 * h, 0.035 * h, GLOW_RED, sections=12)
    return b.mesh(p.size)


# ----------------------------------------------------------------- coffee roaster
def sample_coffee_roaster(rng, size, style):
    return make_params("coffee_roaster", rng, size, style, ["#b8322a", BLACK, "#2b2b2b", "#e8e6e0", "#2f5a4a"],
                       [STEEL, COPPER, BRASS], "#5a3420")


def build_coffee_roaster(p):
    """A drum roaster: cabinet, the drum housing with its round front plate and window,
    a bean hopper on top, a chimney, and the round cooling tray with stirring arms."""
    w, d, h = p.size
    b = Builder()
    cab_x1 = 0.1 * w
    b.box((-w / 2, -d / 2, 0), (cab_x1, d / 2 - 0.12 * d, 0.5 * h), p.primary)
    b.box((-w / 2 - 0.0, -d / 2, 0.5 * h), (cab_x1, d / 2 - 0.12 * d, 0.52 * h), p.secondary)
    dx, dz = -0.2 * w, 0.67 * h
    R = min(0.17 * h, 0.28 * w, 0.35 * d)
    disc_y(b, dx, -d / 2 + 0.05, d / 2 - 0.16 * d, dz, R, p.primary, sections=24)  # drum housing
    b.box((dx - 0.8 * R, -d / 2 + 0.05, 0.5 * h), (dx + 0.8 * R, d / 2 - 0.16 * d, dz), p.primary)
    fy = d / 2 - 0.16 * d
    disc_y(b, dx, fy, fy + 0.04, dz, 1.05 * R, p.secondary, sections=24)
    disc_y(b, dx, fy + 0.04, fy + 0.045, dz, 0.35 * R, tint("#3a2a1a", "glass"), sections=16)  # window
    disc_y(b, dx + 0.55 * R, fy + 0.04, fy + 0.07, dz - 0.5 * R, 0.1 * R, BLACK, sections=8)
    for a in (0.3, 2.2, 4.2):
        disc_y(b, dx + 0.75 * R * np.cos(a), fy + 0.04, fy + 0.05, dz + 0.75 * R * np.sin(a), 0.04 * R, DARK_METAL,
               sections=6)
    hz = dz + R
    b.cyl(dx, 0.0, hz - 0.02, h - 0.15 * h, 0.12 * R, p.secondary, sections=10)
    b.cyl(dx, 0.0, h - 0.15 * h, h, 0.15 * R, p.secondary, r_top=0.7 * R, sections=16)  # hopper
    cx = 0.32 * w
    b.cyl(cx, -d / 2 + 0.1 * d, 0, h, 0.05 * w, DARK_METAL, sections=12)  # chimney
    b.rod((dx, -d / 2 + 0.1 * d, dz + 0.5 * R), (cx, -d / 2 + 0.1 * d, dz + 0.5 * R), 0.04 * w, DARK_METAL,
          sections=10)
    # cooling tray in front of the drum
    tr = min(0.22 * w, 0.3 * d)
    tx, ty, tz = dx + 0.25 * w, d / 2 - tr, 0.44 * h
    b.cyl(tx, ty, 0, tz - 0.03 * h, 0.5 * tr, p.primary, r_top=0.4 * tr, sections=16)
    b.lathe([[0, tz - 0.03 * h], [tr, tz - 0.03 * h], [tr, tz + 0.02 * h], [0.96 * tr, tz + 0.02 * h],
             [0.96 * tr, tz - 0.015 * h], [0, tz - 0.015 * h]], p.secondary, x=tx, y=ty, sections=28)
    b.cyl(tx, ty, tz - 0.015 * h, tz - 0.005 * h, 0.95 * tr, p.accent, sections=24)  # beans
    b.cyl(tx, ty, tz - 0.005 * h, tz + 0.06 * h, 0.03 * tr, DARK_METAL, sections=8)
    for a in (0.0, 2.1, 4.2):
        b.rod((tx, ty, tz + 0.01 * h), (tx + 0.9 * tr * np.cos(a), ty + 0.9 * tr * np.sin(a), tz + 0.0), 0.012,
              DARK_METAL, sections=5)
    b.hull([(dx - 0.3 * R, fy + 0.04, dz - 0.6 * R), (dx + 0.3 * R, fy + 0.04, dz - 0.6 * R),
            (dx - 0.3 * R, fy + 0.1, dz - 0.9 * R), (dx + 0.3 * R, fy + 0.1, dz - 0.9 * R),
            (tx - 0.2 * tr, ty, tz + 0.03 * h), (tx + 0.1 * tr, ty, tz + 0.03 * h)], p.secondary)  # chute
    for k, x in enumerate((-0.4 * w, -0.25 * w)):  # gauges
        disc_y(b, x, d / 2 - 0.12 * d, d / 2 - 0.1 * d, 0.4 * h, 0.04 * h, tint("#f4f1ea", "metal") if k else CHROME, sections=12)
    return b.mesh(p.size)


slot_roles("dishwasher", "metal", "plastic", "light")
register("dishwasher", sample_dishwasher, build_dishwasher)
slot_roles("microwave", "paint", "plastic", "light")
register("microwave", sample_microwave, build_microwave)
slot_roles("printer", "plastic", {"": "plastic", "#9a9da3": "metal"}, "light")
register("printer", sample_printer, build_printer)
slot_roles("photocopier", "plastic", "plastic", "light")
register("photocopier", sample_photocopier, build_photocopier)
slot_roles("water_cooler", {"": "plastic", STEEL: "metal"}, "plastic", {"": "plastic", "#c9ccd0": "metal"})
register("water_cooler", sample_water_cooler, build_water_cooler)
slot_roles("popcorn_machine", "paint", "paint", "metal")
register("popcorn_machine", sample_popcorn_machine, build_popcorn_machine)
slot_roles("beer_tap", "metal", "metal", "plastic")
register("beer_tap", sample_beer_tap, build_beer_tap)
slot_roles("projector", {"": "plastic", DARK_METAL: "metal"}, "plastic", "glass")
register("projector", sample_projector, build_projector)
slot_roles("record_player", "wood", "plastic", "paint")
register("record_player", sample_record_player, build_record_player)
slot_roles("radio", {"": "wood", "#9a9da3": "metal"}, {"": "fabric", CHROME: "metal"}, "paper")
register("radio", sample_radio, build_radio)
slot_roles("typewriter", "paint", "metal", "plastic")
register("typewriter", sample_typewriter, build_typewriter)
slot_roles("dough_mixer", {"": "paint", "#9a9da3": "metal"}, "metal", "ceramic")
register("dough_mixer", sample_dough_mixer, build_dough_mixer)
slot_roles("coffee_roaster", "paint", "metal", "wood")
register("coffee_roaster", sample_coffee_roaster, build_coffee_roaster)
