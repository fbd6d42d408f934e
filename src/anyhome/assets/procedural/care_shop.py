"""Care, salon, shop and workroom: hospital_bed, massage_table, salon_chair, mannequin,
clothes_rack, coat_rack, sewing_machine, espresso_machine."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    FABRICS,
    METAL,
    TEXTILE_WHITE,
    Builder,
    about,
    corners,
    darker,
    lengthwise,
    lighter,
    make_params,
    rot_x,
    rot_y,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

CHROME = tint("#c9ccd0", "metal")
LEATHERS = tint([BLACK, "#2b2b2b", "#7a1f2b", "#e8e6e0", "#5c3b26", "#2f4a5a"], "leather")
SKIN_TONES = tint(["#e8e4dc", "#f0ede6", "#2b2b2b", "#d9c3a0", "#b08a66"], "plastic")
GARMENTS = FABRICS + ["#c0392b", "#e8e6e0", "#2e4a8b", "#d9a32a", "#3f6b4a", "#ec7fa9"]


# ----------------------------------------------------------------- hospital bed
def sample_hospital_bed(rng, size, style):
    return make_params("hospital_bed", rng, size, style, ["#e8e6e0", "#d0d8e0", "#c9c1b4"],
                       ["#f4f6f8", "#dfe9f0", "#e6efe6"], ["#7fa8c8", "#9ab8a0", "#c9ccd0"],
                       raised=float(rng.uniform(0.35, 0.7)), rails=bool(rng.random() < 0.85))


def build_hospital_bed(p):
    """Head at -y (against the wall) raised; wheels, side rails, head and foot boards."""
    w, d, h = p.size
    b = Builder()
    wheel = min(0.08, 0.15 * h)
    frame_z = 0.45 * h
    top = 0.72 * h
    b.box((-w / 2 + 0.06, -d / 2 + 0.08, frame_z - 0.06), (w / 2 - 0.06, d / 2 - 0.06, frame_z), DARK_METAL)
    for x, y in corners(w, d, 0.1):
        b.box((x - 0.025, y - 0.025, wheel), (x + 0.025, y + 0.025, frame_z - 0.06), CHROME)
        b.rod((x - 0.02, y, wheel / 2), (x + 0.02, y, wheel / 2), wheel / 2, BLACK, sections=10)
    b.box((-0.15 * w, -0.2 * d, wheel + 0.05), (0.15 * w, 0.2 * d, frame_z - 0.06), tint("#9a9da3", "metal"))  # lift column
    hinge = -d / 2 + 0.4 * d
    b.box((-w / 2 + 0.05, hinge, frame_z), (w / 2 - 0.05, d / 2 - 0.07, top), p.secondary)  # mattress
    tilt = about(rot_x(-p.raised), (0, hinge, frame_z))
    b.box((-w / 2 + 0.05, -d / 2 + 0.09, frame_z), (w / 2 - 0.05, hinge, top), p.secondary, transform=tilt)
    b.box((-0.3 * w, -d / 2 + 0.12, top), (0.3 * w, -d / 2 + 0.3, top + 0.08), TEXTILE_WHITE, transform=tilt)
    b.box((-w / 2 + 0.04, hinge + 0.05 * d, top - 0.04), (w / 2 - 0.04, d / 2 - 0.08, top + 0.015), p.accent)
    for y0, y1, zt in ((-d / 2, -d / 2 + 0.05, h), (d / 2 - 0.05, d / 2, top + 0.16)):
        b.box((-w / 2, y0, frame_z - 0.1), (w / 2, y1, zt), p.primary)
        b.box((-w / 2 + 0.06, y0 - 0.003, zt - 0.12), (w / 2 - 0.06, y1 + 0.003, zt - 0.05), lighter(p.accent, 0.3))
    if p.rails:
        for sx in (-1, 1):
            x = sx * (w / 2 - 0.015)
            b.box((x - 0.015, hinge - 0.1 * d, top + 0.02), (x + 0.015, hinge + 0.3 * d, top + 0.2), p.primary)
            b.box((x - 0.016, hinge - 0.08 * d, top + 0.06), (x + 0.016, hinge + 0.28 * d, top + 0.16), p.accent)
    b.cyl(w / 2 - 0.05, -d / 2 + 0.1, frame_z, h, 0.012, CHROME, sections=6)  # IV pole
    b.rod((w / 2 - 0.1, -d / 2 + 0.1, h - 0.02), (w / 2, -d / 2 + 0.1, h - 0.02), 0.008, CHROME, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- massage / examination table
def sample_massage_table(rng, size, style):
    metal = style_is(style, "modern", "industrial") or rng.random() < 0.3
    return make_params("massage_table", rng, size, style, [METAL, CHROME] if metal else wood_tones(style),
                       ["#e8e6e0", BLACK, "#5f6b7a", "#7d8c74", "#a6896b", "#2f4a5a"], "#f4f1ea",
                       cradle=bool(rng.random() < 0.7), towel=bool(rng.random() < 0.5))


def _draw_massage(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x; the face cradle at +x."""
    cradle = 0.22 * L if p.cradle else 0.0
    x1 = L / 2 - cradle
    pad = 0.08
    top = H - (0.06 * H if p.cradle else 0.12 * H)
    x0 = -L / 2 if p.cradle else -L / 2 + 0.3 * L  # an examination couch raises its head end
    b.box((x0, -B / 2, top - pad), (x1, B / 2, top), p.secondary)
    b.box((-L / 2 + 0.01, -B / 2 + 0.01, top - pad - 0.04), (x1 - 0.01, B / 2 - 0.01, top - pad), p.primary)
    for x in (-L / 2 + 0.12, x1 - 0.12):
        for sy in (-1, 1):
            b.rod((x, sy * (B / 2 - 0.06), top - pad - 0.04), (x, sy * (B / 2 - 0.08), 0.0), 0.025, p.primary,
                  sections=8)
        b.rod((x, -B / 2 + 0.06, 0.2 * top), (x, B / 2 - 0.06, 0.2 * top), 0.012, p.primary, sections=6)
    b.rod((-L / 2 + 0.12, 0, 0.25 * top), (x1 - 0.12, 0, 0.25 * top), 0.01, p.primary, sections=6)
    if p.cradle:
        cx = x1 + cradle * 0.55
        for sy in (-1, 1):
            b.rod((x1 - 0.02, sy * 0.08, top - pad - 0.02), (cx, sy * 0.08, top + 0.01), 0.01, CHROME, sections=6)
        b.torus((cx, 0, top + 0.02), 1.0, 0.05, p.secondary, sections=20, minor_sections=6,
                transform=about(np.diag([cradle * 0.4, 0.13, 1.0, 1.0]), (cx, 0, top + 0.02)))
    else:
        b.box((-L / 2, -B / 2, top - pad), (x0, B / 2, top), p.secondary,
              transform=about(rot_y(0.45), (x0, 0, top - pad)))
        b.rod((L / 2 - 0.04, -0.4 * B, top), (L / 2 - 0.04, 0.4 * B, top), 0.04, tint("#f8f8f6", "paint"), sections=12)
        b.box((x0 + 0.02, -0.35 * B, top), (L / 2 - 0.04, 0.35 * B, top + 0.003), tint("#f8f8f6", "paper"))  # paper sheet
    if p.towel:
        b.box((-0.1 * L, -B / 2 - 0.005, top - 0.02), (0.15 * L, B / 2 + 0.005, top + 0.01), p.accent)


def build_massage_table(p):
    """A padded table on legs with a face cradle at one end (or, without one, an
    examination couch with a paper roll), along the longer side of the box."""
    return lengthwise(p.size, lambda b, L, B, H: _draw_massage(b, L, B, H, p))


# ----------------------------------------------------------------- salon / barber chair
def sample_salon_chair(rng, size, style):
    barber = style_is(style, "antique", "rustic") or rng.random() < 0.35
    return make_params("salon_chair", rng, size, style, LEATHERS, CHROME, ["#c9a54a", CHROME],
                       kind="barber" if barber else "styling")


def build_salon_chair(p):
    """A padded chair on a round hydraulic base, footrest at the front (+y)."""
    w, d, h = p.size
    b = Builder()
    R = min(w, d) * 0.38
    b.cyl(0, -0.05 * d, 0, 0.04, R, p.secondary, r_top=R * 0.95, sections=28)
    b.cyl(0, -0.05 * d, 0.04, 0.34 * h, 0.05, p.secondary, sections=14)
    b.cyl(0, -0.05 * d, 0.2 * h, 0.3 * h, 0.08, DARK_METAL, sections=14)
    seat = 0.5 * h
    b.box((-0.35 * w, -0.35 * d, 0.34 * h), (0.35 * w, 0.25 * d, seat - 0.08), p.secondary)  # seat pan
    b.box((-0.38 * w, -0.38 * d, seat - 0.1), (0.38 * w, 0.3 * d, seat), p.primary)
    back_top = h - (0.16 * h if p.kind == "barber" else 0.06 * h)
    b.box((-0.36 * w, -0.4 * d, seat - 0.05), (0.36 * w, -0.28 * d, back_top), p.primary,
          transform=about(rot_x(0.15), (0, -0.34 * d, seat)))
    if p.kind == "barber":
        b.box((-0.16 * w, -0.44 * d, back_top + 0.02), (0.16 * w, -0.34 * d, h - 0.02), p.primary,
              transform=about(rot_x(0.15), (0, -0.34 * d, seat)))
        b.cyl(0, -0.2 * d, 0.04, 0.1, R * 0.3, p.accent, sections=10)  # pump pedal
    for sx in (-1, 1):
        x = sx * (w / 2 - 0.05)
        b.rod((x, -0.2 * d, seat - 0.05), (x, -0.2 * d, 0.72 * h - 0.03), 0.015, p.secondary, sections=8)
        b.rod((x, 0.2 * d, seat - 0.05), (x, 0.2 * d, 0.72 * h - 0.03), 0.015, p.secondary, sections=8)
        b.box((x - 0.05, -0.3 * d, 0.72 * h - 0.04), (x + 0.05, 0.3 * d, 0.72 * h + 0.01), p.primary)
    b.rod((0, 0.3 * d, seat - 0.1), (0, d / 2 - 0.04, 0.2 * h), 0.015, p.secondary, sections=8)
    b.box((-0.3 * w, d / 2 - 0.1, 0.18 * h), (0.3 * w, d / 2, 0.2 * h + 0.01), p.secondary)  # footrest
    return b.mesh(p.size)


# ----------------------------------------------------------------- mannequin
def sample_mannequin(rng, size, style):
    return make_params("mannequin", rng, size, style, SKIN_TONES, GARMENTS, [DARK_METAL, CHROME, "#8a6a4a"],
                       kind=str(rng.choice(["full", "full", "dress_form"])), dressed=bool(rng.random() < 0.6),
                       skirt=bool(rng.random() < 0.4))


def build_mannequin(p):
    """A figure on a round stand (or a headless dress form on a pole), facing +y."""
    w, d, h = p.size
    b = Builder()
    H = h
    sw = w / 2
    b.cyl(0, 0, 0, 0.025, min(sw, d / 2) * 0.9, p.accent, r_top=min(sw, d / 2) * 0.85, sections=24)
    if p.kind == "dress_form":
        b.cyl(0, 0, 0.02, 0.55 * H, 0.015, p.accent, sections=8)
        for i in range(3):
            a = 2 * np.pi * i / 3
            b.rod((0, 0, 0.12 * H), (0.8 * sw * np.cos(a), 0.8 * d / 2 * np.sin(a), 0.03), 0.01, p.accent, sections=6)
        torso_lo, torso_hi = 0.55 * H, 0.95 * H
    else:
        b.cyl(0, -0.05 * d, 0.02, 0.25 * H, 0.012, p.accent, sections=8)
        torso_lo, torso_hi = 0.5 * H, 0.82 * H
    th = torso_hi - torso_lo
    body = p.primary
    top_col = p.secondary if p.dressed else body
    b.sphere((0, 0, torso_lo + 0.12 * th), (0.62 * sw, 0.5 * d / 2, 0.2 * th), p.secondary if (p.dressed and p.skirt)
             else body)  # hips
    b.sphere((0, 0, torso_lo + 0.45 * th), (0.5 * sw, 0.42 * d / 2, 0.3 * th), top_col)  # waist
    b.sphere((0, 0, torso_lo + 0.75 * th), (0.7 * sw, 0.5 * d / 2, 0.28 * th), top_col)  # chest
    b.cyl(0, 0, torso_hi - 0.04 * th, torso_hi + 0.16 * th, 0.04, body, sections=10)  # neck
    if p.kind == "dress_form":
        b.cyl(0, 0, torso_hi + 0.06 * th, H, 0.03, p.accent, r_top=0.045, sections=10)
        if p.dressed and p.skirt:
            b.cyl(0, 0, 0.3 * H, torso_lo + 0.12 * th, 0.75 * sw, p.secondary, r_top=0.55 * sw, sections=20)
        return b.mesh(p.size)
    head_r = 0.095 * H * 0.6
    b.sphere((0, 0.01, H - head_r * 1.25), (head_r, head_r * 1.05, head_r * 1.25), body)
    k = H / 1.8  # limbs scale with the height
    for sx in (-1, 1):  # legs and arms
        hip = (sx * 0.3 * sw, 0.0, torso_lo + 0.1 * th)
        knee = (sx * 0.3 * sw, 0.02, 0.27 * H)
        foot = (sx * 0.3 * sw, 0.0, 0.04)
        leg_col = p.secondary if (p.dressed and not p.skirt) else body
        b.rod(hip, knee, 0.06 * k, leg_col, sections=8)
        b.rod(knee, foot, 0.045 * k, leg_col, sections=8)
        b.sphere((sx * 0.3 * sw, 0.04, 0.03), (0.04 * k, 0.08 * k, 0.03), body)
        shoulder = (sx * 0.72 * sw, 0.0, torso_lo + 0.85 * th)
        elbow = (sx * 0.85 * sw, 0.02, torso_lo + 0.35 * th)
        hand = (sx * 0.9 * sw, 0.08, torso_lo - 0.02 * th)
        b.rod(shoulder, elbow, 0.038 * k, top_col, sections=8)
        b.rod(elbow, hand, 0.03 * k, body, sections=8)
    if p.dressed and p.skirt:
        b.cyl(0, 0, 0.3 * H, torso_lo + 0.12 * th, 0.8 * sw, p.secondary, r_top=0.6 * sw, sections=20)
    return b.mesh(p.size)


# ----------------------------------------------------------------- clothes rack
def sample_clothes_rack(rng, size, style):
    wood = style_is(style, "rustic", "antique")
    return make_params("clothes_rack", rng, size, style, wood_tones(style) if wood else [CHROME, BLACK, DARK_METAL],
                       GARMENTS[0], GARMENTS[1], garments=int(rng.integers(5, 12)), shelf=bool(rng.random() < 0.5))


def build_clothes_rack(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    rail = h - 0.03
    for sx in (-1, 1):
        x = sx * (w / 2 - 0.03)
        b.box((x - 0.02, -d / 2, 0.05), (x + 0.02, d / 2, 0.08), p.primary)  # foot
        b.cyl(x, 0, 0.08, rail, 0.015, p.primary, sections=8)
        for y in (-d / 2 + 0.04, d / 2 - 0.04):
            b.sphere((x, y, 0.03), 0.03, BLACK, subdivisions=0)
    b.rod((-w / 2 + 0.01, 0, rail), (w / 2 - 0.01, 0, rail), 0.015, p.primary, sections=8)
    if p.shelf:
        b.box((-w / 2 + 0.05, -d / 2 + 0.06, 0.16), (w / 2 - 0.05, d / 2 - 0.06, 0.18), p.primary)
        for i in range(int(w / 0.35)):
            x = -w / 2 + 0.2 + i * 0.35
            if x > w / 2 - 0.2:
                break
            b.box((x - 0.06, -0.1, 0.18), (x + 0.06, 0.05, 0.28), GARMENTS[(i * 5) % len(GARMENTS)], role="fabric")  # shoes / boxes
    n = p.garments
    span = w - 0.2
    for i in range(n):
        x = -span / 2 + (i + 0.5) * span / n
        col = GARMENTS[int(rng.integers(len(GARMENTS)))]
        length = rng.uniform(0.35, 0.75) * (rail - 0.3)
        gw = min(0.45 * d + 0.1, 0.42)
        b.rod((x, 0, rail), (x, 0, rail - 0.06), 0.004, CHROME, sections=4)  # hook
        b.hull([(x - 0.012, -gw / 2, rail - 0.07), (x + 0.012, -gw / 2, rail - 0.07),
                (x - 0.012, gw / 2, rail - 0.07), (x + 0.012, gw / 2, rail - 0.07),
                (x - 0.03, -gw / 2 - 0.03, rail - 0.07 - length), (x + 0.03, -gw / 2 - 0.03, rail - 0.07 - length),
                (x - 0.03, gw / 2 + 0.03, rail - 0.07 - length), (x + 0.03, gw / 2 + 0.03, rail - 0.07 - length)],
               col, role="plastic")
    return b.mesh(p.size)


# ----------------------------------------------------------------- coat rack
def sample_coat_rack(rng, size, style):
    metal = style_is(style, "modern", "industrial") and rng.random() < 0.6
    return make_params("coat_rack", rng, size, style, [BLACK, CHROME] if metal else wood_tones(style),
                       GARMENTS[0], ["#5c3b26", "#2b2b2b", "#a6896b"], hooks=int(rng.integers(4, 7)),
                       coats=int(rng.integers(0, 3)), base=str(rng.choice(["tripod", "disc"])))


def build_coat_rack(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    R = min(w, d) / 2
    if p.base == "tripod":
        for i in range(3):
            a = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0, 0, 0.25 * h), (0.95 * R * np.cos(a), 0.95 * R * np.sin(a), 0.0), 0.018, p.primary, sections=8)
    else:
        b.cyl(0, 0, 0, 0.04, 0.7 * R, p.primary, r_top=0.6 * R, sections=24)
    b.cyl(0, 0, 0, h - 0.04, 0.022, p.primary, r_top=0.018, sections=10)
    b.sphere((0, 0, h - 0.03), (0.035, 0.035, 0.03), p.primary, subdivisions=1)
    top = h - 0.12
    for i in range(p.hooks):
        a = 2 * np.pi * i / p.hooks
        tip = (0.7 * R * np.cos(a), 0.7 * R * np.sin(a), top + 0.08)
        b.rod((0, 0, top - 0.06), tip, 0.01, p.primary, sections=6)
        b.sphere(tip, 0.02, p.primary, subdivisions=0)
    for k in range(p.coats):  # coats hang from hooks: narrow shoulders, wider hem
        a = 2 * np.pi * int(rng.integers(p.hooks)) / p.hooks + 0.3 * k
        c, s = np.cos(a), np.sin(a)
        col = GARMENTS[int(rng.integers(len(GARMENTS)))] if k else p.secondary
        z0, z1 = top + 0.02, top - 0.5 * h
        r0, r1 = 0.3 * R, 0.6 * R

        def at(r, t, z, c=c, s=s):  # r out from the pole, t across, z up
            return (r * c - t * s, r * s + t * c, z)

        b.hull([at(r0 - 0.04, -0.09, z0), at(r0 - 0.04, 0.09, z0), at(r0 + 0.05, -0.09, z0),
                at(r0 + 0.05, 0.09, z0), at(r1 - 0.06, -0.17, z1), at(r1 - 0.06, 0.17, z1),
                at(r1 + 0.08, -0.17, z1), at(r1 + 0.08, 0.17, z1)], col, role="fabric")
    if p.coats and rng.random() < 0.5:
        b.cyl(0.2 * R, 0, top + 0.06, top + 0.12, 0.12, p.accent, r_top=0.08, sections=14)  # a hat
    return b.mesh(p.size)


# ----------------------------------------------------------------- sewing machine
def sample_sewing_machine(rng, size, style):
    treadle = style_is(style, "antique", "rustic") or (not style_is(style, "modern") and rng.random() < 0.4)
    return make_params("sewing_machine", rng, size, style, wood_tones(style),
                       BLACK if treadle else str(rng.choice(["#f0ede6", "#e8e6e0", "#d0d8e0"])),
                       ["#c9a54a", "#c0392b", "#2e86c1"], kind="treadle" if treadle else "table")


def _machine(b: Builder, x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, body: str,
             accent: str) -> None:
    """The machine itself: bed, pillar at +x, arm over to the needle head at -x, hand wheel."""
    L, D, H = x1 - x0, y1 - y0, z1 - z0
    yc = (y0 + y1) / 2
    b.box((x0, y0, z0), (x1, y1, z0 + 0.2 * H), body)  # bed
    b.box((x1 - 0.28 * L, yc - 0.3 * D, z0 + 0.2 * H), (x1 - 0.05 * L, yc + 0.3 * D, z1 - 0.05 * H), body)
    b.box((x0 + 0.08 * L, yc - 0.25 * D, z1 - 0.32 * H), (x1 - 0.05 * L, yc + 0.25 * D, z1), body)  # arm
    b.box((x0 + 0.04 * L, yc - 0.28 * D, z0 + 0.45 * H), (x0 + 0.2 * L, yc + 0.28 * D, z1), body)  # head
    b.rod((x0 + 0.12 * L, yc + 0.05 * D, z0 + 0.45 * H), (x0 + 0.12 * L, yc + 0.05 * D, z0 + 0.24 * H), 0.004,
          METAL, sections=4)  # needle
    b.rod((x1 - 0.05 * L, yc, z0 + 0.62 * H), (x1, yc, z0 + 0.62 * H), 0.22 * H, darker(body, 0.2),
          sections=20)  # hand wheel
    b.cyl(x0 + 0.5 * L, yc, z1, z1 + 0.03, 0.015, accent, sections=10)  # spool
    b.box((x0 + 0.3 * L, yc + 0.25 * D, z1 - 0.25 * H), (x0 + 0.55 * L, yc + 0.251 * D + 0.002, z1 - 0.12 * H),
          tint("#c9a54a", "metal"))  # decal


def build_sewing_machine(p):
    """A sewing machine on its table (a cast-iron treadle stand or plain legs); in a box
    lower than 0.6 m, the machine alone."""
    w, d, h = p.size
    b = Builder()
    if h < 0.6:
        _machine(b, -w / 2, w / 2 - 0.1 * w, -d / 2, d / 2, 0, h, p.secondary, p.accent)
        return b.mesh(p.size)
    mh = min(0.35, 0.33 * h)
    top = h - mh
    b.box((-w / 2, -d / 2, top - 0.04), (w / 2, d / 2, top), p.primary)
    if p.kind == "treadle":
        for sx in (-1, 1):
            x = sx * (w / 2 - 0.08)
            b.hull([(x - 0.015, -d / 2 + 0.03, 0), (x + 0.015, -d / 2 + 0.03, 0), (x - 0.015, d / 2 - 0.03, 0),
                    (x + 0.015, d / 2 - 0.03, 0), (x - 0.015, -0.15 * d, top - 0.04), (x + 0.015, -0.15 * d, top - 0.04),
                    (x - 0.015, 0.15 * d, top - 0.04), (x + 0.015, 0.15 * d, top - 0.04)], BLACK)
        b.box((-w / 2 + 0.1, -0.05 * d, 0.06), (w / 2 - 0.1, 0.05 * d, 0.09), BLACK)
        b.box((-0.2 * w, -0.05 * d, 0.06), (0.2 * w, 0.35 * d, 0.09), DARK_METAL)  # treadle plate
        b.rod((w / 2 - 0.13, -0.1, 0.35 * top), (w / 2 - 0.12, 0.1, 0.35 * top), 0.18 * top, BLACK, sections=16)
        b.box((-w / 2 + 0.1, -d / 2 + 0.05, top - 0.18), (-w / 2 + 0.35, d / 2 - 0.05, top - 0.04), p.primary)
    else:
        b.legs(corners(w, d, 0.04), 0, top - 0.04, 0.025, "straight", p.primary)
        b.box((w / 2 - 0.4, -d / 2 + 0.03, top - 0.2), (w / 2 - 0.04, d / 2 - 0.03, top - 0.04), p.primary)
    mw = min(0.5, 0.55 * w)
    _machine(b, -mw / 2 - 0.05 * w, mw / 2 - 0.05 * w, -0.35 * d, 0.3 * d, top, h, p.secondary, p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- espresso machine
def sample_espresso_machine(rng, size, style):
    w, _, _ = size
    return make_params("espresso_machine", rng, size, style, [CHROME, "#b8322a", BLACK, "#e8e6e0", "#2b2b2b"],
                       CHROME, BLACK, groups=int(np.clip(round(w / 0.3), 1, 3)), cups=int(rng.integers(2, 6)))


def build_espresso_machine(p):
    """Body with group heads and portafilters towards +y, drip tray, steam wand, cups on top."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    top = h - 0.06
    yb, yf = -d / 2, d / 2 - 0.12 * d
    head_z = 0.45 * h  # underside of the overhanging head that carries the groups
    recess = yf - 0.3 * d
    b.extrude_x([(yb, 0), (recess, 0), (recess, head_z), (yf, head_z), (yf, top), (yb, top)], -w / 2, w / 2,
                p.primary)
    b.box((-w / 2 + 0.02, yb + 0.02, top), (w / 2 - 0.02, yf - 0.02, top + 0.008), CHROME)  # cup warmer
    rail = [(-w / 2 + 0.02, yb + 0.02), (w / 2 - 0.02, yb + 0.02), (w / 2 - 0.02, yf - 0.02),
            (-w / 2 + 0.02, yf - 0.02)]
    for i in range(4):
        (x0, y0), (x1, y1) = rail[i], rail[(i + 1) % 4]
        b.rod((x0, y0, h - 0.006), (x1, y1, h - 0.006), 0.006, CHROME, sections=6)
    b.box((-w / 2 + 0.03, recess, 0.0), (w / 2 - 0.03, d / 2, 0.06), CHROME)  # drip tray
    b.box((-w / 2, yf, head_z + 0.08 * h), (w / 2, yf + 0.004, head_z + 0.14 * h), darker(p.primary, 0.2))
    n = p.groups
    for i in range(n):
        x = -w / 2 + (i + 0.5) * w / n if n > 1 else 0.0
        yg = yf - 0.1 * d
        b.cyl(x, yg, head_z - 0.05 * h, head_z, 0.045, CHROME, sections=14)
        b.cyl(x, yg, head_z - 0.11 * h, head_z - 0.05 * h, 0.035, DARK_METAL, sections=14)  # portafilter
        b.rod((x, yg + 0.02, head_z - 0.08 * h), (x, d / 2, head_z - 0.1 * h), 0.012,
              p.secondary if p.secondary != CHROME else BLACK, sections=8)
        b.cyl(x, yg, 0.06, 0.16, 0.03, tint("#f4f1ea", "paint"), sections=10)  # a cup under it
        b.rod((x, yf, 0.72 * h), (x, yf + 0.006, 0.72 * h), 0.035, tint("#f4f1ea", "paint"), sections=14)  # gauge
    for sx in (-1, 1):  # steam wand and hot water tap
        x = sx * (w / 2 - 0.05)
        b.rod((x, yf - 0.05, head_z), (x, yf, head_z - 0.05 * h), 0.008, CHROME, sections=6)
        b.rod((x, yf, head_z - 0.05 * h), (x, yf, 0.12 * h), 0.006, CHROME, sections=6)
        b.cyl(x, yf - 0.02, head_z + 0.15 * h, head_z + 0.22 * h, 0.02, BLACK, sections=8)
    for _ in range(p.cups):
        mx, my = min(0.06, w / 4), min(0.06, (yf - yb) / 4)
        x = rng.uniform(-w / 2 + mx, w / 2 - mx)
        y = rng.uniform(yb + my, yf - my)
        b.cyl(x, y, top + 0.008, h, 0.03, tint("#f4f1ea", "paint"), r_top=0.035, sections=10)
    return b.mesh(p.size)


slot_roles("hospital_bed", "paint", "fabric", {"": "plastic", "#c9ccd0": "metal"})
register("hospital_bed", sample_hospital_bed, build_hospital_bed)
slot_roles("massage_table", {"": "wood", CHROME: "metal", METAL: "metal"}, "leather", "fabric")
register("massage_table", sample_massage_table, build_massage_table)
slot_roles("salon_chair", "leather", "metal", "metal")
register("salon_chair", sample_salon_chair, build_salon_chair)
slot_roles("mannequin", "plastic", "fabric", "metal")
register("mannequin", sample_mannequin, build_mannequin)
slot_roles("clothes_rack", {"": "wood", CHROME: "metal", DARK_METAL: "metal"}, "fabric", "fabric")
register("clothes_rack", sample_clothes_rack, build_clothes_rack)
slot_roles("coat_rack", {"": "wood", CHROME: "metal"}, "fabric", "wood")
register("coat_rack", sample_coat_rack, build_coat_rack)
slot_roles("sewing_machine", "wood", "paint", {"": "paint", "#c9a54a": "metal"})
register("sewing_machine", sample_sewing_machine, build_sewing_machine)
slot_roles("espresso_machine", "metal", "metal", "plastic")
register("espresso_machine", sample_espresso_machine, build_espresso_machine)
