"""A horse barn's things: hay_bale, water_trough, manger (the trough full of hay),
hose_reel, saddle_rack."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import disc_x, ring_x
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    darker,
    lighter,
    make_params,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

HAY = tint(["#d8c07a", "#cdb46a", "#e0c888", "#bfa760"], "plant")
STRAW = tint(["#e6d08e", "#d9c27c"], "plant")
TWINE = tint(["#c0392b", "#2d6fb0", "#f0e8d0", "#3f8a4a"], "fabric")
TROUGH = tint(["#9a9da3", "#5f6b7a", "#2b2b2b", "#3f6a8a"], "metal")
WATER = tint("#4f86a8", "glass")
HOSE = tint(["#3f8a4a", "#e8702a", "#2b2b2b", "#e0b030"], "rubber")
REEL = tint(["#2d6fb0", "#3f8a4a", "#9a9da3", "#c0392b"], "plastic")
LEATHER = tint(["#6b3f22", "#4a2c18", "#8a5a32", "#2b1a10"], "leather")


# ----------------------------------------------------------------- hay bale
def sample_hay_bale(rng, size, style):
    return make_params("hay_bale", rng, size, style, HAY + STRAW, TWINE, TWINE,
                       ties=int(rng.integers(2, 4)), round=bool(rng.random() < 0.15))


def build_hay_bale(p):
    """A small square bale: a block of hay with a few loose wisps on top and two or three
    bands of twine around it; ``round``: a round bale lying on its side (axis along x)."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    if p.round:
        r = 0.5 * min(d, h)
        disc_x(b, -w / 2, w / 2, 0.0, r, r, p.primary, sections=24)
        for k in range(3):
            ring_x(b, (-w / 2 + (k + 1) * w / 4, 0.0, r), r * 1.005, 0.008 * r + 0.004, p.secondary)
        for s in (-1, 1):  # the rolled face shows its spiral as darker rings
            disc_x(b, s * w / 2 - 0.005, s * w / 2 + 0.005, 0.0, r, 0.6 * r, darker(p.primary, 0.12), sections=20)
        return b.mesh(p.size)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.97 * h), p.primary)
    for _ in range(10):  # wisps on the cut top
        x, y = rng.uniform(-0.45 * w, 0.45 * w), rng.uniform(-0.4 * d, 0.4 * d)
        b.box((x - 0.04 * w, y - 0.02 * d, 0.96 * h), (x + 0.04 * w, y + 0.02 * d, h), lighter(p.primary, 0.1))
    t = 0.012 * w + 0.004
    e = 0.006  # the twine lies on the faces, not through the bale
    for k in range(p.ties):
        x = -w / 2 + (k + 1) * w / (p.ties + 1)
        b.box((x - t, -d / 2, 0.97 * h), (x + t, d / 2, 0.97 * h + e), p.secondary)
        for y0, y1 in ((d / 2, d / 2 + e), (-d / 2 - e, -d / 2)):
            b.box((x - t, y0, 0.0), (x + t, y1, 0.97 * h + e), p.secondary)
    return b.mesh(p.size)


# ----------------------------------------------------------------- water trough
def sample_water_trough(rng, size, style):
    return make_params("water_trough", rng, size, style, TROUGH, WATER, HAY,
                       feed=False, legs=bool(rng.random() < 0.5), valve=bool(rng.random() < 0.4))


def build_water_trough(p):
    """A long open trough along x: four walls and a floor with a rolled rim, on short legs
    or a plinth, holding water (or heaped hay when ``feed``: a manger); ``valve``: the
    float-valve box of an automatic waterer at one end."""
    w, d, h = p.size
    b = Builder()
    z0 = 0.18 * h if p.legs else 0.0
    if p.legs:
        for x in (-0.4 * w, 0.4 * w):
            for y in (-0.3 * d, 0.3 * d):
                b.box((x - 0.03 * w, y - 0.04 * d, 0), (x + 0.03 * w, y + 0.04 * d, z0 + 0.02 * h), DARK_METAL)
    else:
        b.box((-0.46 * w, -0.4 * d, 0), (0.46 * w, 0.4 * d, 0.04 * h), darker(p.primary, 0.2))
    top = 0.92 * h
    wall = 0.035 * min(w, d) + 0.01
    for y0, y1 in ((-d / 2, -d / 2 + wall), (d / 2 - wall, d / 2)):  # long sides, open on top
        b.box((-w / 2, y0, z0), (w / 2, y1, top), p.primary)
    for x0, x1 in ((-w / 2, -w / 2 + wall), (w / 2 - wall, w / 2)):
        b.box((x0, -d / 2 + wall, z0), (x1, d / 2 - wall, top), p.primary)
    b.box((-w / 2 + wall, -d / 2 + wall, z0), (w / 2 - wall, d / 2 - wall, z0 + 0.12 * h), darker(p.primary, 0.35))
    if p.feed:  # hay heaped above the rim
        b.box((-w / 2 + wall, -d / 2 + wall, z0 + 0.12 * h), (w / 2 - wall, d / 2 - wall, 0.97 * h), p.accent)
        b.sphere((0.0, 0.0, 0.95 * h), (0.4 * w, 0.35 * d, 0.05 * h), lighter(p.accent, 0.08), subdivisions=1)
    else:
        b.box((-w / 2 + wall, -d / 2 + wall, z0 + 0.12 * h), (w / 2 - wall, d / 2 - wall, 0.8 * h), p.secondary,
              alpha=220)
    for y in (-d / 2, d / 2 - 0.02 * d):  # rolled rim
        b.box((-w / 2, y, top - 0.03 * h), (w / 2, y + 0.02 * d, top + 0.02 * h), lighter(p.primary, 0.1))
    if p.valve and not p.feed:
        b.box((w / 2 - 0.2 * w, -d / 2, top - 0.05 * h), (w / 2, -d / 2 + 0.35 * d, h), METAL)
    return b.mesh(p.size)


def sample_manger(rng, size, style):
    return make_params("manger", rng, size, style, TROUGH + wood_tones(style)[:2], WATER, HAY,
                       feed=True, legs=bool(rng.random() < 0.5), valve=False)


# ----------------------------------------------------------------- hose reel
def sample_hose_reel(rng, size, style):
    return make_params("hose_reel", rng, size, style, REEL, HOSE, ["#e0b030", BLACK],
                       wound=int(rng.integers(4, 8)), cart=bool(rng.random() < 0.5))


def build_hose_reel(p):
    """A hose reel: a drum on an axle between two side frames (on a wall plate, or a cart
    with wheels and a handle), the hose wound round it in ``wound`` turns and its end
    hanging down to a spray nozzle."""
    w, d, h = p.size
    b = Builder()
    cz = 0.55 * h
    R = 0.3 * min(d, h)
    for s in (-1, 1):  # side frames
        x = s * 0.4 * w
        b.box((x - 0.03 * w, -0.08 * d, 0.0 if p.cart else 0.2 * h), (x + 0.03 * w, 0.08 * d, cz + 0.06 * h), p.primary)
        disc_x(b, x - 0.025 * w, x + 0.025 * w, 0.0, cz, R * 1.15, p.primary, sections=16)
    disc_x(b, -0.4 * w, 0.4 * w, 0.0, cz, 0.25 * R, darker(p.primary, 0.3), sections=10)  # drum
    for k in range(p.wound):  # wound hose
        x = -0.34 * w + k * 0.68 * w / max(1, p.wound - 1)
        ring_x(b, (x, 0.0, cz), 0.75 * R, 0.22 * R, p.secondary, sections=16)
    # the free end down to a nozzle on the floor in front
    b.rod((0.2 * w, 0.0, cz - 0.95 * R), (0.15 * w, d / 2 - 0.1 * d, 0.06 * h), 0.045 * min(d, h), p.secondary, sections=8)
    b.box((0.08 * w, d / 2 - 0.12 * d, 0.0), (0.22 * w, d / 2, 0.1 * h), p.accent)
    if p.cart:
        for s in (-1, 1):
            disc_x(b, s * 0.46 * w - 0.04 * w, s * 0.46 * w + 0.04 * w, -0.1 * d, 0.14 * h, 0.14 * h, BLACK,
                   sections=14)
        b.rod((-0.4 * w, -0.1 * d, cz), (-0.4 * w, -d / 2, h), 0.02 * w + 0.005, p.primary, sections=6)
        b.rod((0.4 * w, -0.1 * d, cz), (0.4 * w, -d / 2, h), 0.02 * w + 0.005, p.primary, sections=6)
        b.rod((-0.4 * w, -d / 2, h - 0.01), (0.4 * w, -d / 2, h - 0.01), 0.025 * w + 0.005, BLACK, sections=8)
    else:
        b.box((-0.46 * w, -d / 2, 0.15 * h), (0.46 * w, -d / 2 + 0.06 * d, 0.8 * h), darker(p.primary, 0.15))
    return b.mesh(p.size)


# ----------------------------------------------------------------- saddle rack
def sample_saddle_rack(rng, size, style):
    return make_params("saddle_rack", rng, size, style, wood_tones(style)[:3] + ["#2b2b2b", "#9a9da3"], LEATHER,
                       tint(["#2d6fb0", "#c0392b", "#f4f1ea", "#3f8a4a"], "fabric"),
                       saddle=bool(rng.random() < 0.8), pad=bool(rng.random() < 0.6))


def build_saddle_rack(p):
    """A free-standing saddle stand along y: a ridged top bar like a horse's back on two
    A-frame ends, a shelf rail below; ``saddle``: a saddle on it (seat, cantle, pommel,
    flaps and stirrups), ``pad``: a saddle cloth under it."""
    w, d, h = p.size
    b = Builder()
    ridge = 0.72 * h
    for y in (-0.42 * d, 0.42 * d):  # A-frame ends
        b.hull([(-w / 2, y - 0.03 * d, 0), (w / 2, y - 0.03 * d, 0), (-w / 2, y + 0.03 * d, 0),
                (w / 2, y + 0.03 * d, 0), (-0.08 * w, y - 0.03 * d, ridge), (0.08 * w, y - 0.03 * d, ridge),
                (-0.08 * w, y + 0.03 * d, ridge), (0.08 * w, y + 0.03 * d, ridge)], p.primary)
    b.hull([(-0.12 * w, -d / 2, ridge - 0.05 * h), (0.12 * w, -d / 2, ridge - 0.05 * h), (0.0, -d / 2, ridge + 0.03 * h),
            (-0.12 * w, d / 2, ridge - 0.05 * h), (0.12 * w, d / 2, ridge - 0.05 * h), (0.0, d / 2, ridge + 0.03 * h)],
           lighter(p.primary, 0.08))  # ridged top bar
    for s in (-1, 1):
        b.box((s * 0.35 * w - 0.03 * w, -0.42 * d, 0.2 * h), (s * 0.35 * w + 0.03 * w, 0.42 * d, 0.25 * h), p.primary)
    if not p.saddle:
        return b.mesh(p.size)
    if p.pad:
        b.hull([(-0.5 * w, -0.3 * d, 0.45 * h), (0.5 * w, -0.3 * d, 0.45 * h), (-0.5 * w, 0.3 * d, 0.45 * h),
                (0.5 * w, 0.3 * d, 0.45 * h), (-0.06 * w, -0.32 * d, ridge + 0.05 * h), (0.06 * w, -0.32 * d, ridge + 0.05 * h),
                (-0.06 * w, 0.32 * d, ridge + 0.05 * h), (0.06 * w, 0.32 * d, ridge + 0.05 * h)], p.accent)
    seat = ridge + 0.08 * h
    b.hull([(-0.42 * w, -0.25 * d, 0.5 * h), (0.42 * w, -0.25 * d, 0.5 * h), (-0.42 * w, 0.25 * d, 0.5 * h),
            (0.42 * w, 0.25 * d, 0.5 * h), (-0.12 * w, -0.25 * d, seat), (0.12 * w, -0.25 * d, seat),
            (-0.12 * w, 0.25 * d, seat), (0.12 * w, 0.25 * d, seat)], p.secondary)  # seat and flaps
    b.sphere((0.0, 0.26 * d, seat + 0.04 * h), (0.1 * w, 0.05 * d, 0.07 * h), darker(p.secondary, 0.15))  # pommel
    b.sphere((0.0, -0.26 * d, seat + 0.06 * h), (0.18 * w, 0.05 * d, 0.09 * h), darker(p.secondary, 0.15))  # cantle
    for s in (-1, 1):  # stirrup leathers and irons
        x = s * 0.44 * w
        b.box((x - 0.01 * w, 0.02 * d, 0.3 * h), (x + 0.01 * w, 0.06 * d, 0.55 * h), darker(p.secondary, 0.2))
        b.box((x - 0.03 * w, 0.0, 0.24 * h), (x + 0.03 * w, 0.08 * d, 0.3 * h), METAL)
    return b.mesh(p.size)


slot_roles("hay_bale", "plant", "fabric", "fabric")
register("hay_bale", sample_hay_bale, build_hay_bale)
slot_roles("water_trough", "metal", "glass", "plant")
register("water_trough", sample_water_trough, build_water_trough)
slot_roles("manger", {"": "wood", **{c: "metal" for c in ("#9a9da3", "#5f6b7a", "#2b2b2b", "#3f6a8a")}}, "glass", "plant")
register("manger", sample_manger, build_water_trough)
slot_roles("hose_reel", "plastic", "rubber", "plastic")
register("hose_reel", sample_hose_reel, build_hose_reel)
slot_roles("saddle_rack", {"": "wood", "#2b2b2b": "metal", "#9a9da3": "metal"}, "leather", "fabric")
register("saddle_rack", sample_saddle_rack, build_saddle_rack)
