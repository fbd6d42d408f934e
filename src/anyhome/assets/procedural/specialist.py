"""Specialist objects that used to stand in as something else: cash_register,
floor_cushion, loft_bed, suit_of_armour, exam_lamp, dog_wash_tub, composting_toilet."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    RUBBER,
    SCREEN,
    STEEL,
    WHITE_PLASTIC,
    caster,
    path,
    ring_y,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    TEXTILE_WHITE,
    Builder,
    about,
    darker,
    fabric_tones,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

TILL_BODIES = ["#1f1f22", "#d8d2c4", "#3a3b3e", "#eceae4"]
"""Cash register housings: black, beige, graphite, white."""
CUSHION_FABRICS = ["#2f3a5a", "#7a2f2a", "#3f5a3f", "#c9a86a", "#6d5a6e", "#1f1f22", "#b9b2a6", "#a6896b"]
"""Zabuton and zafu covers: indigo, madder red, green, mustard, plum, black, natural."""
LOFT_FRAMES = ["#f0eee8", DARK_METAL]
"""Painted white and black steel loft-bed frames (besides the style's woods)."""
ARMOUR_STEELS = [STEEL, "#9a9da3", "#5a5c60"]
"""Polished, grey and blackened steel."""
ZAFU_MIN_H_M = 0.2
"""A floor cushion this tall or taller may carry a round zafu on its zabuton."""
PLUMES = tint(["#b0302a", "#2d4f8a", "#f4f1ea", "#2f6a3a"], "fabric")


# ----------------------------------------------------------------- cash register
def sample_cash_register(rng, size, style):
    return make_params("cash_register", rng, size, style, wood_tones(style) + ["#e8e6e0", "#3a3b3e"],
                       ["#2b2b2b", "#d8d2c4", "#6b6e73", "#b5a58a"], TILL_BODIES,
                       belt=bool(rng.random() < 0.5))


def _till(b: Builder, x: float, y: float, z: float, tw: float, td: float, th: float, body: str) -> None:
    """A cash register standing at (x, y, z), a tw x td x th box, facing +y: the cash
    drawer below, a sloping keypad, a customer display on a post, a receipt printer."""
    b.box((x - tw / 2, y - td / 2, z), (x + tw / 2, y + td / 2, z + 0.28 * th), body)  # drawer housing
    b.box((x - 0.4 * tw, y + td / 2 - 0.004, z + 0.06 * th), (x + 0.4 * tw, y + td / 2, z + 0.22 * th),
          darker(body, 0.15))
    b.box((x - 0.08 * tw, y + td / 2, z + 0.12 * th), (x + 0.08 * tw, y + td / 2 + 0.006, z + 0.16 * th), METAL)
    kz = z + 0.28 * th
    b.hull([(x - 0.45 * tw, y + 0.45 * td, kz), (x + 0.45 * tw, y + 0.45 * td, kz),
            (x - 0.45 * tw, y - 0.3 * td, kz), (x + 0.45 * tw, y - 0.3 * td, kz),
            (x - 0.45 * tw, y - 0.3 * td, kz + 0.28 * th), (x + 0.45 * tw, y - 0.3 * td, kz + 0.28 * th),
            (x - 0.45 * tw, y + 0.45 * td, kz + 0.06 * th), (x + 0.45 * tw, y + 0.45 * td, kz + 0.06 * th)], body)
    slope = np.arctan2(0.22 * th, 0.75 * td)
    tilt = about(rot_x(slope), (x, y + 0.45 * td, kz + 0.06 * th))
    panel = (x - 0.4 * tw, x + 0.0 * tw, y - 0.25 * td, y + 0.42 * td)
    b.box((panel[0], panel[2], kz + 0.06 * th), (panel[1], panel[3], kz + 0.065 * th), darker(body, 0.3),
          transform=tilt)
    keys = tint("#c9ccd0", "plastic")
    for i in range(4):
        for j in range(4):
            kx = panel[0] + (i + 0.5) * (panel[1] - panel[0]) / 4
            ky = panel[2] + (j + 0.5) * (panel[3] - panel[2]) / 4
            b.cbox((kx, ky, kz + 0.07 * th), (0.07 * tw, 0.1 * td, 0.01 * th), keys, transform=tilt)
    b.box((x + 0.05 * tw, y - 0.25 * td, kz + 0.2 * th), (x + 0.4 * tw, y - 0.05 * td, kz + 0.34 * th),
          darker(body, 0.2))  # receipt printer
    b.box((x + 0.1 * tw, y - 0.2 * td, kz + 0.34 * th), (x + 0.35 * tw, y - 0.19 * td, kz + 0.42 * th),
          tint("#f4f1ea", "paper"))
    b.cyl(x - 0.2 * tw, y - 0.3 * td, kz + 0.2 * th, z + 0.85 * th, 0.03 * tw + 0.003, body, sections=8)
    b.box((x - 0.42 * tw, y - 0.36 * td, z + 0.82 * th), (x + 0.02 * tw, y - 0.24 * td, z + th), body)
    b.box((x - 0.39 * tw, y - 0.24 * td, z + 0.85 * th), (x - 0.01 * tw, y - 0.235 * td, z + 0.97 * th),
          tint("#3ad07a", "light"))  # the display, lit


def build_cash_register(p):
    """A checkout counter (its top at 0.75 of the box) with a cash register at one end
    and a belt or a bag shelf at the other; in a box under 0.5 m tall, the cash register
    alone."""
    w, d, h = p.size
    b = Builder()
    if h < 0.5:
        _till(b, 0, 0, 0, w, d, h, p.accent)
        return b.mesh(p.size)
    top = 0.75 * h
    b.box((-w / 2, -d / 2 + 0.02 * d, 0.04 * h), (w / 2, d / 2 - 0.04 * d, top - 0.04 * h), p.primary)
    b.box((-w / 2 + 0.02 * w, -d / 2 + 0.05 * d, 0), (w / 2 - 0.02 * w, d / 2 - 0.08 * d, 0.04 * h),
          darker(p.primary, 0.35))  # kick plate
    b.box((-w / 2, -d / 2, top - 0.04 * h), (w / 2, d / 2, top), p.secondary)  # worktop
    for k in range(3):  # front panels
        x0 = -w / 2 + (k + 0.1) * w / 3
        b.box((x0, d / 2 - 0.04 * d, 0.12 * h), (x0 + 0.8 * w / 3, d / 2 - 0.035 * d, top - 0.1 * h),
              lighter(p.primary, 0.08))
    tw, td = min(0.5, 0.36 * w), 0.75 * d
    _till(b, w / 2 - 0.55 * tw - 0.02 * w, -0.05 * d, top, tw, td, h - top, p.accent)
    if p.belt:  # a conveyor belt with a divider bar
        b.box((-w / 2 + 0.04 * w, -0.3 * d, top), (0.05 * w, 0.3 * d, top + 0.02 * h), RUBBER)
        for y in (-0.32 * d, 0.3 * d):
            b.box((-w / 2 + 0.03 * w, y, top), (0.06 * w, y + 0.02 * d, top + 0.035 * h), tint("#b4b8bd", "metal"))
        b.box((-0.3 * w, -0.25 * d, top + 0.02 * h), (-0.3 * w + 0.03 * w, 0.25 * d, top + 0.05 * h),
              tint("#e8402a", "plastic"))
    else:  # a flush scanner glass and a card terminal on a stalk
        b.box((-0.1 * w, -0.2 * d, top), (0.05 * w, 0.2 * d, top + 0.004 * h), tint("#2a3a3a", "glass"))
    cx = -0.2 * w
    b.cyl(cx, 0.3 * d, top, top + 0.12 * h, 0.015 * w + 0.004, BLACK, sections=8)
    b.box((cx - 0.05 * w, 0.24 * d, top + 0.12 * h), (cx + 0.05 * w, 0.36 * d, top + 0.2 * h), BLACK,
          transform=about(rot_x(-0.5), (cx, 0.3 * d, top + 0.12 * h)))
    return b.mesh(p.size)


# ----------------------------------------------------------------- floor cushion
def sample_floor_cushion(rng, size, style):
    return make_params("floor_cushion", rng, size, style, CUSHION_FABRICS + fabric_tones(style),
                       CUSHION_FABRICS, ["#c9a54a", "#f4f1ea", "#2b2b2b"],
                       zafu=bool(rng.random() < (0.5 if style_is(style, "eastern") else 0.25)) and size[2] >= ZAFU_MIN_H_M,
                       tufts=int(rng.choice([1, 4, 5])))


def _pad(b: Builder, w: float, d: float, z0: float, z1: float, color: str) -> None:
    """A flat cushion with rounded (chamfered) edges filling w x d from z0 to z1."""
    t = z1 - z0
    e = min(0.35 * t, 0.08 * min(w, d))
    pts = []
    for z, inset in ((z0, e), (z0 + 0.3 * t, 0), (z0 + 0.7 * t, 0), (z1, e)):
        pts += [(sx * (w / 2 - inset), sy * (d / 2 - inset), z) for sx in (-1, 1) for sy in (-1, 1)]
    b.hull(pts, color)


def build_floor_cushion(p):
    """A zabuton: a square flat floor cushion with tufted buttons and a corded edge; with
    ``zafu``, a round pleated meditation cushion sits on it."""
    w, d, h = p.size
    b = Builder()
    pad_h = 0.45 * h if p.zafu else h
    _pad(b, w, d, 0, 0.8 * pad_h, p.primary)
    b.sphere((0, 0, 0.55 * pad_h), (0.47 * w, 0.47 * d, 0.45 * pad_h), p.primary, subdivisions=2)  # the puffed top
    for sy in (-1, 1):  # corded edge along the seams
        b.rod((-0.49 * w, sy * 0.49 * d, 0.5 * pad_h), (0.49 * w, sy * 0.49 * d, 0.5 * pad_h),
              0.06 * pad_h + 0.001, darker(p.primary, 0.2), sections=6)
    for sx in (-1, 1):
        b.rod((sx * 0.49 * w, -0.49 * d, 0.5 * pad_h), (sx * 0.49 * w, 0.49 * d, 0.5 * pad_h),
              0.06 * pad_h + 0.001, darker(p.primary, 0.2), sections=6)
    if p.zafu:
        r = 0.33 * min(w, d)
        z0 = pad_h * 0.96
        b.lathe([[0, z0], [0.9 * r, z0], [r, z0 + 0.2 * (h - z0)], [r, z0 + 0.65 * (h - z0)],
                 [0.85 * r, 0.97 * h], [0, h]], p.secondary, sections=28)
        for k in range(14):  # pleats
            a = 2 * np.pi * k / 14
            b.rod((r * np.cos(a), r * np.sin(a), z0 + 0.15 * (h - z0)), (r * np.cos(a), r * np.sin(a), z0 + 0.75 * (h - z0)),
                  0.04 * r + 0.001, darker(p.secondary, 0.15), sections=4)
        b.sphere((0, 0, h - 0.02 * h), (0.1 * r, 0.1 * r, 0.03 * h), p.accent)
        return b.mesh(p.size)
    spots = [(0.0, 0.0)] if p.tufts == 1 else [(sx * 0.22 * w, sy * 0.22 * d) for sx in (-1, 1) for sy in (-1, 1)]
    if p.tufts == 5:
        spots.append((0.0, 0.0))
    for x, y in spots:
        b.sphere((x, y, pad_h), (0.04 * min(w, d), 0.04 * min(w, d), 0.08 * pad_h), p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- loft bed
def sample_loft_bed(rng, size, style):
    return make_params("loft_bed", rng, size, style, wood_tones(style) + LOFT_FRAMES, fabric_tones(style),
                       ["#f4c7d0", "#bcd6ea", "#f3e3a6", "#c9e3c4", "#b9b2a6"],
                       under=str(rng.choice(["desk", "desk", "sofa", "open"])), ladder_right=bool(rng.random() < 0.5))


def build_loft_bed(p):
    """A bed raised on four tall posts (the mattress at 0.7 of the box, head at -y), guard
    rails round it, a ladder at the foot (+y) end, and a desk or a small sofa, or nothing,
    in the space under it."""
    w, d, h = p.size
    b = Builder()
    post = 0.045 * min(w, d) + 0.01
    deck = 0.68 * h
    for sx in (-1, 1):
        for sy in (-1, 1):
            x = sx * (w / 2 - post)
            y = sy * (d / 2 - post)
            b.box((x - post, y - post, 0), (x + post, y + post, h), p.primary)
    for sy in (-1, 1):
        b.box((-w / 2, sy * (d / 2 - post) - post, deck - 0.06 * h), (w / 2, sy * (d / 2 - post) + post, deck),
              p.primary)
    for sx in (-1, 1):
        b.box((sx * (w / 2 - post) - post, -d / 2, deck - 0.06 * h), (sx * (w / 2 - post) + post, d / 2, deck),
              p.primary)
    b.box((-w / 2 + 2 * post, -d / 2 + 2 * post, deck - 0.02 * h), (w / 2 - 2 * post, d / 2 - 2 * post, deck),
          darker(p.primary, 0.15))  # slats
    mz = deck + 0.08 * h
    b.box((-w / 2 + 2 * post, -d / 2 + 2 * post, deck), (w / 2 - 2 * post, d / 2 - 2 * post, mz), TEXTILE_WHITE)
    b.box((-w / 2 + 2 * post - 0.005, -d / 2 + 0.3 * d, mz - 0.02 * h), (w / 2 - 2 * post + 0.005, d / 2 - 2 * post,
                                                                          mz + 0.015 * h), p.secondary)  # duvet
    b.sphere((0, -d / 2 + 2 * post + 0.12 * d, mz + 0.02 * h), (0.3 * w, 0.08 * d, 0.03 * h), p.accent)
    rail_z = (h - 0.04 * h, h)
    for sx in (-1, 1):  # side rails
        b.box((sx * (w / 2 - post) - post / 2, -d / 2, rail_z[0]), (sx * (w / 2 - post) + post / 2, d / 2, rail_z[1]),
              p.primary)
    b.box((-w / 2, -d / 2, mz), (w / 2, -d / 2 + post, h), p.primary)  # head board
    lx = (w / 2 - 0.28 * w) if p.ladder_right else (-w / 2 + 0.28 * w)
    gap = 0.2 * w
    if lx - gap > -w / 2:  # foot rails either side of the ladder
        b.box((-w / 2, d / 2 - post, rail_z[0]), (lx - gap, d / 2, rail_z[1]), p.primary)
    if lx + gap < w / 2:
        b.box((lx + gap, d / 2 - post, rail_z[0]), (w / 2, d / 2, rail_z[1]), p.primary)
    for dx in (-gap, gap):  # ladder at the foot
        b.box((lx + dx - post / 2, d / 2 - post, 0), (lx + dx + post / 2, d / 2, h), p.primary)
    for z in np.linspace(0.12 * h, deck - 0.05 * h, 5):
        b.rod((lx - gap, d / 2 - post / 2, z), (lx + gap, d / 2 - post / 2, z), 0.35 * post, darker(p.primary, 0.2),
              sections=8)
    if p.under == "desk":
        dz = min(0.75, 0.42 * h)
        b.box((-w / 2 + 2 * post, -d / 2 + 2 * post, dz - 0.03 * h), (w / 2 - 2 * post, -d / 2 + 0.55 * d, dz),
              lighter(p.primary, 0.1))
        b.box((-w / 2 + 2 * post, -d / 2 + 2 * post, 0), (-w / 2 + 0.4 * w, -d / 2 + 0.5 * d, dz - 0.03 * h),
              darker(p.primary, 0.1))  # drawers
        b.box((-0.1 * w, -d / 2 + 2 * post, dz), (0.2 * w, -d / 2 + 2 * post + 0.02 * d, dz + 0.14 * h), SCREEN)
    elif p.under == "sofa":
        sz = 0.22 * h
        b.box((-w / 2 + 2 * post, -0.35 * d, 0), (w / 2 - 2 * post, 0.25 * d, sz), p.secondary)
        b.box((-w / 2 + 2 * post, -0.35 * d, sz), (-w / 2 + 0.3 * w, 0.25 * d, sz + 0.15 * h), p.secondary)
        for y in (-0.25 * d, 0.05 * d):
            b.box((-w / 2 + 0.3 * w, y, sz), (0.0, y + 0.2 * d, sz + 0.05 * h), lighter(p.secondary, 0.15))
    return b.mesh(p.size)


# ----------------------------------------------------------------- suit of armour
def sample_suit_of_armour(rng, size, style):
    return make_params("suit_of_armour", rng, size, style, ARMOUR_STEELS, ["#5c3b26", "#3a2a20", "#6b6e73"], PLUMES,
                       weapon=str(rng.choice(["halberd", "sword", "none"])), plume=bool(rng.random() < 0.6))


def build_suit_of_armour(p):
    """A standing suit of plate armour facing +y on a low plinth: sabatons, greaves, tassets,
    a breastplate, round pauldrons, arms with gauntlets, a great helm with a visor slit
    (and a plume), holding a halberd or a sword planted at its side, or nothing."""
    w, d, h = p.size
    b = Builder()
    steel = p.primary
    dark = darker(steel, 0.35)
    plinth = 0.05 * h
    b.box((-w / 2 + 0.05 * w, -d / 2, 0), (w / 2 - 0.05 * w, d / 2, plinth), p.secondary)
    s = min(0.4 * w, 0.5 * d)  # body half-width
    zf = plinth
    for sx in (-1, 1):  # legs
        x = sx * 0.32 * s
        b.hull([(x - 0.12 * s, -0.15 * d, zf), (x + 0.12 * s, -0.15 * d, zf), (x - 0.1 * s, 0.3 * d, zf),
                (x + 0.1 * s, 0.3 * d, zf), (x - 0.1 * s, -0.1 * d, zf + 0.05 * h),
                (x + 0.1 * s, -0.1 * d, zf + 0.05 * h), (x, 0.25 * d, zf + 0.02 * h)], steel)  # sabaton
        b.cyl(x, 0, zf + 0.04 * h, zf + 0.24 * h, 0.12 * s, steel, r_top=0.16 * s, sections=12)  # greave
        b.sphere((x, 0.02 * d, zf + 0.26 * h), (0.17 * s, 0.17 * s, 0.035 * h), dark)  # poleyn (knee)
        b.cyl(x, 0, zf + 0.27 * h, zf + 0.45 * h, 0.17 * s, steel, r_top=0.2 * s, sections=12)  # cuisse
    hip = zf + 0.45 * h
    b.cyl(0, 0, hip - 0.08 * h, hip + 0.02 * h, 0.55 * s, dark, r_top=0.5 * s, ry=0.4 * s, sections=16)  # tassets
    chest_top = hip + 0.3 * h
    b.lathe([[0, hip], [0.5 * s, hip], [0.56 * s, hip + 0.1 * h], [0.62 * s, hip + 0.22 * h],
             [0.5 * s, chest_top], [0, chest_top]], steel, sections=20)
    b.rod((0, 0.3 * s, hip + 0.04 * h), (0, 0.4 * s, hip + 0.24 * h), 0.025 * s + 0.002, lighter(steel, 0.2),
          sections=6)  # the breastplate's ridge
    for sx in (-1, 1):
        sh = (sx * 0.62 * s, 0, chest_top - 0.03 * h)
        b.sphere(sh, (0.3 * s, 0.3 * s, 0.06 * h), steel)  # pauldron
        elbow = (sx * 0.78 * s, 0.05 * d, chest_top - 0.2 * h)
        hand = (sx * 0.72 * s, 0.22 * d, chest_top - 0.33 * h)
        b.rod(sh, elbow, 0.13 * s, steel, sections=10)
        b.sphere(elbow, 0.16 * s, dark)
        b.rod(elbow, hand, 0.12 * s, steel, sections=10)
        b.sphere(hand, (0.14 * s, 0.16 * s, 0.04 * h), dark)  # gauntlet
    b.cyl(0, 0, chest_top, chest_top + 0.03 * h, 0.25 * s, dark, sections=12)  # gorget
    hz = chest_top + 0.03 * h
    helm_top = h - (0.06 * h if p.plume else 0.0)
    b.lathe([[0, hz], [0.3 * s, hz], [0.34 * s, hz + 0.4 * (helm_top - hz)], [0.3 * s, hz + 0.8 * (helm_top - hz)],
             [0.15 * s, helm_top - 0.01 * h], [0, helm_top]], steel, sections=20)
    b.box((-0.22 * s, 0.28 * s, hz + 0.5 * (helm_top - hz)), (0.22 * s, 0.35 * s, hz + 0.56 * (helm_top - hz)),
          tint("#111114", "paint"))  # visor slit
    if p.plume:
        b.sphere((0, -0.1 * s, helm_top + 0.03 * h), (0.08 * s, 0.25 * s, 0.04 * h), p.accent)
        b.cyl(0, 0, helm_top - 0.01 * h, helm_top + 0.02 * h, 0.04 * s, dark, sections=6)
    if p.weapon != "none":
        gx = 1.0 * s
        gy = 0.2 * d
        if p.weapon == "halberd":
            b.cyl(gx, gy, plinth, h, 0.05 * s + 0.003, tint("#5c3b26", "wood"), sections=8)
            b.hull([(gx, gy - 0.02 * d, 0.8 * h), (gx, gy + 0.02 * d, 0.8 * h), (gx + 0.22 * s, gy, 0.78 * h),
                    (gx + 0.22 * s, gy, 0.95 * h), (gx, gy - 0.02 * d, 0.93 * h), (gx, gy + 0.02 * d, 0.93 * h)],
                   lighter(steel, 0.15))  # axe blade
            b.hull([(gx, gy - 0.01 * d, 0.84 * h), (gx, gy + 0.01 * d, 0.84 * h), (gx - 0.15 * s, gy, 0.86 * h),
                    (gx, gy - 0.01 * d, 0.88 * h), (gx, gy + 0.01 * d, 0.88 * h)], lighter(steel, 0.15))  # back spike
            b.cyl(gx, gy, 0.96 * h, h, 0.03 * s + 0.002, lighter(steel, 0.15), r_top=0.0, sections=6)
        else:
            gx = 0.8 * s
            hilt = chest_top - 0.33 * h
            b.hull([(gx, gy - 0.06 * s, plinth + 0.06 * h), (gx, gy + 0.06 * s, plinth + 0.06 * h),
                    (gx, gy, plinth), (gx - 0.01 * s, gy - 0.06 * s, hilt - 0.1 * h),
                    (gx + 0.01 * s, gy + 0.06 * s, hilt - 0.1 * h)], lighter(steel, 0.25))  # blade, point down
            b.box((gx - 0.03 * s, gy - 0.25 * s, hilt - 0.11 * h), (gx + 0.03 * s, gy + 0.25 * s, hilt - 0.095 * h),
                  dark)  # crossguard
            b.cyl(gx, gy, hilt - 0.095 * h, hilt, 0.04 * s + 0.002, tint("#3a2a20", "leather"), sections=8)
    return b.mesh(p.size)


# ----------------------------------------------------------------- exam lamp
def sample_exam_lamp(rng, size, style):
    return make_params("exam_lamp", rng, size, style, [WHITE_PLASTIC, "#d8dde2", "#c9d6df"], "#fff6d8", CHROME,
                       reach=float(rng.uniform(0.55, 0.8)))


def build_exam_lamp(p):
    """A medical examination lamp: a heavy round base (on castors when floor-standing, a
    box over 1 m tall), a post, a gooseneck arching to the front (+y) and a dish head
    looking down with its lens lit."""
    w, d, h = p.size
    b = Builder()
    floor = h > 1.0
    r = 0.45 * min(w, d)
    y0 = -d / 2 + r
    if floor:
        cr = 0.03 * h / 2.6
        for k in range(5):
            a = 2 * np.pi * k / 5 + np.pi / 2
            x, y = 0.9 * r * np.cos(a), y0 + 0.9 * r * np.sin(a)
            b.rod((0, y0, 2.6 * cr + 0.01 * h), (x, y, 2.6 * cr + 0.005 * h), 0.02 * min(w, d) + 0.004, p.accent,
                  sections=6)
            caster(b, x, y, cr)
        base_top = 2.6 * cr + 0.02 * h
        b.cyl(0, y0, 2.6 * cr, base_top, 0.2 * r, p.primary, sections=12)
    else:
        base_top = 0.06 * h
        b.cyl(0, y0, 0, base_top, r, p.primary, r_top=0.9 * r, sections=24)
    post_top = 0.55 * h
    b.cyl(0, y0, base_top, post_top, 0.05 * r + 0.003, p.accent, sections=10)
    reach = p.reach * (d / 2 - y0 - 0.1 * d)
    head_y = y0 + reach + 0.08 * d
    hr = min(0.35 * w, 0.12 * d + 0.02)
    head_z = h - 0.06 * h
    pts = [(0, y0, post_top)] + [(0, y0 + (head_y - y0) * (1 - np.cos(t)) , post_top + (head_z - post_top) *
                                  np.sin(t) + 0.06 * h * np.sin(2 * t)) for t in np.linspace(0.2, np.pi / 2, 8)]
    path(b, pts, 0.03 * r + 0.003, DARK_METAL, sections=8)
    b.cyl(0, head_y, head_z - 0.09 * h, head_z, hr, p.primary, r_top=0.45 * hr, sections=24)  # dish head
    b.cyl(0, head_y, head_z - 0.095 * h, head_z - 0.09 * h, 0.85 * hr, p.secondary, sections=24)  # the lens, lit
    b.cyl(0, head_y, head_z, h, 0.2 * hr, p.accent, sections=10)
    ring_y(b, (0, head_y + hr, head_z - 0.05 * h), 0.08 * hr + 0.01, 0.015 * hr + 0.002, p.accent, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dog wash tub
def sample_dog_wash_tub(rng, size, style):
    return make_params("dog_wash_tub", rng, size, style, [STEEL, "#c9ccd0", WHITE_PLASTIC], RUBBER, CHROME,
                       ramp=bool(rng.random() < 0.5), door=bool(rng.random() < 0.6))


def build_dog_wash_tub(p):
    """A raised dog-washing tub: a deep open steel basin on legs with a rubber mat in its
    bottom, a splash back with a mixer tap and a hand shower on a hose, a restraint arm
    with a loop; a side door or a ramp (off the -x end) to walk the dog in."""
    w, d, h = p.size
    b = Builder()
    ramp_w = 0.3 * w if p.ramp else 0.0
    x0, x1 = -w / 2 + ramp_w, w / 2
    tub_z0, tub_z1 = 0.35 * h, 0.72 * h
    t = 0.02 * min(w, d) + 0.004
    yb = -d / 2 + 0.08 * d  # back wall of the basin (the splash back stands behind it)
    for sx in (x0 + 0.04 * w, x1 - 0.04 * w):
        for sy in (yb + 0.06 * d, d / 2 - 0.06 * d):
            b.cyl(sx, sy, 0, tub_z0, 0.025 * min(w, d) + 0.006, p.primary, sections=10)
    b.box((x0 + 0.04 * w, yb + 0.06 * d, 0.1 * h), (x1 - 0.04 * w, d / 2 - 0.06 * d, 0.11 * h), p.primary)  # shelf
    b.box((x0, yb, tub_z0), (x1, d / 2, tub_z0 + t), p.primary)  # floor of the basin
    b.box((x0 + t, yb + t, tub_z0 + t), (x1 - t, d / 2 - t, tub_z0 + t + 0.01 * h), p.secondary)  # mat
    b.box((x0, yb, tub_z0), (x1, yb + t, tub_z1), p.primary)
    b.box((x0, d / 2 - t, tub_z0), (x1, d / 2, tub_z1), p.primary)
    b.box((x1 - t, yb, tub_z0), (x1, d / 2, tub_z1), p.primary)
    if p.door:  # the -x end wall is a door, lower than the rim, with a latch
        b.box((x0, yb, tub_z0), (x0 + t, d / 2, 0.5 * (tub_z0 + tub_z1) + 0.1 * (tub_z1 - tub_z0)), p.primary)
        b.box((x0 - 0.004, 0.1 * d, tub_z0 + 0.2 * (tub_z1 - tub_z0)), (x0, 0.2 * d, tub_z0 + 0.35 * (tub_z1 - tub_z0)),
              p.accent)
    else:
        b.box((x0, yb, tub_z0), (x0 + t, d / 2, tub_z1), p.primary)
    for y in (yb, d / 2 - t):  # rolled rims
        b.rod((x0, y + t / 2, tub_z1), (x1, y + t / 2, tub_z1), 0.6 * t, p.primary, sections=8)
    b.box((x0, -d / 2, tub_z0), (x1, yb, h), p.primary)  # splash back
    tx = 0.2 * (x1 - x0) + x0 + 0.3 * (x1 - x0)
    b.box((tx - 0.06 * w, yb, 0.8 * h), (tx + 0.06 * w, yb + 0.05 * d, 0.84 * h), p.accent)  # mixer
    b.rod((tx, yb + 0.03 * d, 0.82 * h), (tx, yb + 0.1 * d, 0.76 * h), 0.012 * min(w, d) + 0.003, p.accent)
    hx = tx + 0.18 * w
    b.rod((hx, yb + 0.01 * d, 0.9 * h), (hx, yb + 0.03 * d, 0.9 * h), 0.02 * min(w, d) + 0.004, p.accent)
    b.rod((hx, yb + 0.03 * d, 0.82 * h), (hx, yb + 0.06 * d, 0.95 * h), 0.015 * min(w, d) + 0.004, BLACK)  # shower head
    path(b, [(tx + 0.04 * w, yb + 0.04 * d, 0.8 * h), (tx + 0.08 * w, yb + 0.06 * d, 0.75 * h),
             (hx, yb + 0.05 * d, 0.8 * h)], 0.006 * min(w, d) + 0.002, DARK_METAL, sections=5)
    ax = x1 - 0.12 * (x1 - x0)
    path(b, [(ax, yb, 0.88 * h), (ax, yb, h - 0.02 * h), (ax, yb + 0.35 * d, h - 0.02 * h)], 0.012 * min(w, d) + 0.003,
         p.accent, sections=6)  # restraint arm...
    path(b, [(ax, yb + 0.35 * d, h - 0.02 * h), (ax, yb + 0.36 * d, 0.86 * h)], 0.005 * min(w, d) + 0.002,
         tint("#c0392b", "fabric"), sections=5)  # ...and its leash loop
    if p.ramp:
        b.hull([(-w / 2, yb + 0.1 * d, 0), (-w / 2, d / 2 - 0.1 * d, 0), (x0, yb + 0.1 * d, tub_z0 + t),
                (x0, d / 2 - 0.1 * d, tub_z0 + t), (x0, yb + 0.1 * d, 0), (x0, d / 2 - 0.1 * d, 0)], p.primary)
        for k in range(4):
            fx = -w / 2 + (k + 0.5) * ramp_w / 4
            fz = (fx + w / 2) / ramp_w * (tub_z0 + t) + 0.004
            b.box((fx - 0.01 * w, yb + 0.12 * d, fz - 0.004), (fx + 0.01 * w, d / 2 - 0.12 * d, fz + 0.006), RUBBER)
    return b.mesh(p.size)


# ----------------------------------------------------------------- composting toilet
def sample_composting_toilet(rng, size, style):
    kind = str(rng.choice(["box", "box", "unit"]))
    return make_params("composting_toilet", rng, size, style, wood_tones(style) + [WHITE_PLASTIC, "#d8d2c4"],
                       [WHITE_PLASTIC, "#e8dcc4", "#2b2b2b"], [BLACK, "#6b6e73"], kind=kind,
                       bucket=bool(rng.random() < 0.5))


def build_composting_toilet(p):
    """A composting toilet: a wooden box (or a moulded unit) with a seat and lid on top,
    an access hatch at the front (+y), and a vent pipe rising from the back to the top of
    the box; a sawdust bucket with a scoop on the box's side ledge or not."""
    w, d, h = p.size
    b = Builder()
    seat_z = 0.45 * h
    body_w = 0.78 * w if p.bucket else w
    bx = -w / 2 + body_w / 2
    y0 = -d / 2 + 0.1 * d
    if p.kind == "unit":
        b.lathe([[0, 0], [0.42 * body_w, 0], [0.48 * body_w, 0.4 * seat_z], [0.46 * body_w, seat_z - 0.03 * h],
                 [0, seat_z - 0.03 * h]], p.primary, x=bx, y=y0 + 0.55 * (d / 2 - y0), sections=24)
        b.box((bx - 0.35 * body_w, y0, 0.02 * h), (bx + 0.35 * body_w, y0 + 0.5 * (d / 2 - y0), seat_z - 0.05 * h),
              p.primary)
        b.cyl(bx + 0.52 * body_w, y0 + 0.55 * (d / 2 - y0), 0.2 * seat_z, 0.3 * seat_z, 0.02 * w + 0.004, p.accent,
              sections=8)  # agitator crank hub
        b.rod((bx + 0.5 * body_w, y0 + 0.55 * (d / 2 - y0), 0.25 * seat_z),
              (bx + 0.5 * body_w, y0 + 0.55 * (d / 2 - y0) + 0.12 * d, 0.25 * seat_z), 0.012 * w + 0.002, p.accent)
    else:
        b.box((bx - body_w / 2, y0, 0), (bx + body_w / 2, d / 2, seat_z - 0.03 * h), p.primary)
        b.box((bx - body_w / 2 - 0.01 * w, y0 - 0.01 * d, seat_z - 0.04 * h),
              (bx + body_w / 2, d / 2 + 0.0, seat_z - 0.02 * h), darker(p.primary, 0.1))  # top board
        b.box((bx - 0.35 * body_w, d / 2, 0.08 * h), (bx + 0.35 * body_w, d / 2 + 0.0, 0.34 * h), p.primary)
        b.box((bx - 0.33 * body_w, d / 2 - 0.005 * d, 0.09 * h), (bx + 0.33 * body_w, d / 2, 0.33 * h),
              darker(p.primary, 0.25))  # hatch outline
        b.box((bx - 0.3 * body_w, d / 2 - 0.004 * d, 0.1 * h), (bx + 0.3 * body_w, d / 2 + 0.0 * d, 0.32 * h),
              lighter(p.primary, 0.06))
        b.box((bx - 0.05 * body_w, d / 2, 0.28 * h), (bx + 0.05 * body_w, d / 2 + 0.01 * d, 0.3 * h), p.accent)
    sy = y0 + 0.55 * (d / 2 - y0)
    sr = min(0.36 * body_w, 0.3 * (d / 2 - y0))
    b.cyl(bx, sy, seat_z - 0.02 * h, seat_z, sr, p.secondary, ry=1.2 * sr, sections=24)  # seat ring
    b.cyl(bx, sy, seat_z, seat_z + 0.004 * h, 0.55 * sr, tint("#2a2522", "paint"), ry=0.7 * sr, sections=20)
    lid_y = y0 + 0.02 * d
    b.box((bx - sr, lid_y, seat_z - 0.02 * h), (bx + sr, lid_y + 0.03 * d, seat_z + 0.3 * h), p.secondary,
          transform=about(rot_x(-0.15), (bx, lid_y, seat_z)))  # lid, raised
    pr = 0.05 * min(w, d) + 0.008
    px = bx + 0.3 * body_w
    b.cyl(px, -d / 2 + pr, 0.2 * h, h - 0.04 * h, pr, p.accent, sections=12)  # vent pipe
    b.cyl(px, -d / 2 + pr, h - 0.04 * h, h, pr * 1.5, p.accent, sections=12)  # cowl
    b.box((px - pr, -d / 2 + pr, 0.25 * h), (px + pr, y0 + 0.01 * d, 0.3 * h), p.accent)  # its bracket
    if p.bucket:
        cx = w / 2 - 0.11 * w
        br = min(0.1 * w, 0.18 * d)
        b.cyl(cx, 0.2 * d, 0, 0.3 * h, 0.85 * br, tint("#6b8a5a", "plastic"), r_top=br, sections=16)
        b.cyl(cx, 0.2 * d, 0.28 * h, 0.29 * h, 0.9 * br, tint("#c9a77c", "wood"), sections=16)  # sawdust
        b.rod((cx, 0.2 * d, 0.29 * h), (cx + 0.3 * br, 0.2 * d + 0.3 * br, 0.38 * h), 0.1 * br, BLACK, sections=6)
    return b.mesh(p.size)


slot_roles("cash_register", {"": "wood", "#e8e6e0": "paint", "#3a3b3e": "paint"}, "stone", "plastic")
register("cash_register", sample_cash_register, build_cash_register)
slot_roles("floor_cushion", "fabric", "fabric", "fabric")
register("floor_cushion", sample_floor_cushion, build_floor_cushion)
slot_roles("loft_bed", {"": "wood", "#f0eee8": "paint", DARK_METAL: "metal"}, "fabric", "fabric")
register("loft_bed", sample_loft_bed, build_loft_bed)
slot_roles("suit_of_armour", "metal", "wood", "fabric")
register("suit_of_armour", sample_suit_of_armour, build_suit_of_armour)
slot_roles("exam_lamp", "plastic", "light", "metal")
register("exam_lamp", sample_exam_lamp, build_exam_lamp)
slot_roles("dog_wash_tub", {"": "metal", WHITE_PLASTIC: "plastic"}, "rubber", "metal")
register("dog_wash_tub", sample_dog_wash_tub, build_dog_wash_tub)
slot_roles("composting_toilet", {"": "wood", WHITE_PLASTIC: "plastic", "#d8d2c4": "plastic"},
           {"": "plastic"}, "plastic")
register("composting_toilet", sample_composting_toilet, build_composting_toilet)
