"""Clinic and hospital equipment: wheelchair, medical_cart, xray_machine, medical_scanner."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    SCREEN,
    arc,
    caster,
    extrude_x,
    path,
    ring_x,
    wheel_x,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    darker,
    lengthwise,
    lighter,
    make_params,
    slot_roles,
    tint,
)
from anyhome.assets.registry import register

CART_COLORS = tint(["#c0392b", "#2d6fb0", "#9a9da3", "#e8e6e0", "#3f8a4a"], "paint")
DRAWER_FRONTS = tint(["#e8e6e0", "#f4f4f2", "#c9ccd0"], "plastic")
MEDICAL_WHITE = tint(["#f4f4f2", "#eceae4", "#e6ebee"], "paint")
MEDICAL_ACCENTS = tint(["#2d6fb0", "#4ab0c0", "#7fa8c8", "#5f6b7a", "#3f8a8a"], "plastic")


# ----------------------------------------------------------------- wheelchair
def sample_wheelchair(rng, size, style):
    return make_params("wheelchair", rng, size, style, [CHROME, BLACK, "#b8322a", "#2d4f8a", "#9a9da3"],
                       [BLACK, "#2b2b2b", "#2d4f8a", "#5f6b7a"], "#3a3b3e", spokes=int(rng.choice([8, 12])))


def build_wheelchair(p):
    """A manual wheelchair facing +y: big spoked rear wheels with push rims, small front
    castors, a sling seat and back, armrests, push handles and footrests."""
    w, d, h = p.size
    b = Builder()
    R = min(0.32 * h, 0.3 * d)
    wy = -0.18 * d
    tyre = min(0.035, 0.06 * w)
    for s in (-1, 1):
        x = s * (w / 2 - tyre / 2 - 0.035 * w)
        wheel_x(b, x, wy, R, R, tyre, tint(BLACK, "rubber"), p.primary if p.primary != BLACK else METAL, spokes=p.spokes // 2)
        ring_x(b, (s * (w / 2 - 0.012 * w), wy, R), 0.85 * R, 0.008, CHROME, sections=24)  # push rim
    seat_z = 0.5 * h
    fx = w / 2 - tyre - 0.1 * w
    cr = 0.06 * h
    for s in (-1, 1):
        x = s * fx
        caster(b, x, 0.38 * d, cr / 1.3, BLACK, p.primary)
        path(b, [(x, 0.38 * d, 2.6 * cr / 1.3), (x, 0.3 * d, seat_z), (x, -0.25 * d, seat_z), (x, wy, R),
                 (x, 0.3 * d, 2.6 * cr / 1.3 + 0.05)], 0.012, p.primary, sections=6, joints=False)
        path(b, [(x, -0.25 * d, seat_z), (x, -0.33 * d, h - 0.08 * h), (x, -0.42 * d, h - 0.05 * h)], 0.013,
             p.primary, sections=6)  # back post and handle
        b.rod((x, -0.42 * d, h - 0.05 * h), (x, -0.5 * d, h - 0.05 * h), 0.018, BLACK, sections=8)
        b.box((x - 0.03, -0.2 * d, 0.7 * h), (x + 0.03, 0.12 * d, 0.73 * h), p.secondary)  # armrest
        b.rod((x, -0.15 * d, seat_z), (x, -0.15 * d, 0.7 * h), 0.01, p.primary, sections=6)
        b.rod((x, 0.08 * d, seat_z), (x, 0.08 * d, 0.7 * h), 0.01, p.primary, sections=6)
        path(b, [(x, 0.28 * d, seat_z), (x * 0.8, 0.44 * d, 0.14 * h)], 0.012, p.primary, sections=6)
        b.box((x * 0.8 - 0.1 * w * (1 if s > 0 else -1), 0.4 * d, 0.12 * h), (x * 0.8, 0.5 * d, 0.14 * h),
              DARK_METAL)  # footplate
    b.box((-fx, -0.25 * d, seat_z - 0.02), (fx, 0.28 * d, seat_z + 0.02), p.secondary)  # seat
    b.hull([(-fx, -0.26 * d, seat_z + 0.02), (fx, -0.26 * d, seat_z + 0.02), (-fx, -0.24 * d, seat_z + 0.02),
            (fx, -0.24 * d, seat_z + 0.02), (-fx, -0.34 * d, h - 0.1 * h), (fx, -0.34 * d, h - 0.1 * h),
            (-fx, -0.32 * d, h - 0.1 * h), (fx, -0.32 * d, h - 0.1 * h)], p.secondary)  # back
    return b.mesh(p.size)


# ----------------------------------------------------------------- medical cart
def sample_medical_cart(rng, size, style):
    return make_params("medical_cart", rng, size, style, CART_COLORS, DRAWER_FRONTS, "#f1c40f",
                       drawers=int(rng.integers(4, 7)), monitor=bool(rng.random() < 0.4))


def build_medical_cart(p):
    """A crash cart on castors: a cabinet of drawers with pull handles, a top with a
    raised rim, a push handle on the side, a sharps box, and sometimes a defibrillator."""
    w, d, h = p.size
    b = Builder()
    cr = min(0.03, 0.05 * h)
    for x in (-0.4 * w, 0.4 * w):
        for y in (-0.38 * d, 0.38 * d):
            caster(b, x, y, cr)
    z0 = 2.6 * cr
    top = 0.86 * h if p.monitor else 0.95 * h
    b.box((-0.45 * w, -0.45 * d, z0), (0.45 * w, 0.45 * d, top), p.primary)
    n = p.drawers
    dz = (top - z0 - 0.04 * h) / n
    for k in range(n):
        za = z0 + 0.02 * h + k * dz
        b.box((-0.42 * w, 0.45 * d, za + 0.005), (0.42 * w, 0.47 * d, za + dz - 0.005),
              p.secondary if p.primary != p.secondary else lighter(p.primary, 0.3))
        b.box((-0.15 * w, 0.47 * d, za + dz - 0.4 * dz), (0.15 * w, 0.49 * d, za + dz - 0.25 * dz), DARK_METAL)
    b.box((-w / 2 + 0.0, -d / 2 + 0.04 * d, top), (w / 2, d / 2 - 0.04 * d, top + 0.015 * h), lighter(p.primary, 0.2))
    for lo, hi in (((-w / 2, -d / 2 + 0.04 * d), (w / 2, -d / 2 + 0.07 * d)), ((-w / 2, d / 2 - 0.07 * d),
                                                                             (w / 2, d / 2 - 0.04 * d))):
        b.box((lo[0], lo[1], top), (hi[0], hi[1], top + 0.04 * h), lighter(p.primary, 0.2))
    path(b, [(w / 2 - 0.05 * w, -0.3 * d, 0.7 * h), (w / 2, -0.3 * d, 0.72 * h), (w / 2, 0.3 * d, 0.72 * h),
             (w / 2 - 0.05 * w, 0.3 * d, 0.7 * h)], 0.012, CHROME, sections=6)
    b.box((-w / 2, -0.2 * d, 0.55 * h), (-0.45 * w, 0.1 * d, 0.72 * h), p.accent)  # sharps box
    b.box((-w / 2 - 0.0, -0.18 * d, 0.72 * h), (-0.45 * w, 0.08 * d, 0.74 * h), tint("#c0392b", "paint"))
    if p.monitor:
        b.box((-0.3 * w, -0.3 * d, top + 0.015 * h), (0.3 * w, 0.2 * d, h - 0.01 * h), tint("#e8e6e0", "paint"))
        b.box((-0.25 * w, 0.2 * d, top + 0.04 * h), (0.05 * w, 0.202 * d, h - 0.03 * h), SCREEN)
        b.box((0.1 * w, 0.2 * d, top + 0.05 * h), (0.2 * w, 0.205 * d, top + 0.09 * h), tint("#c0392b", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- x-ray machine
def sample_xray_machine(rng, size, style):
    return make_params("xray_machine", rng, size, style, MEDICAL_WHITE, MEDICAL_ACCENTS, "#3a3b3e",
                       wall_stand=bool(rng.random() < 0.6))


def _draw_xray(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the patient table on its pedestal, a floor column at -x carrying the arm
    with the tube head and collimator over the table, a wall detector stand at +x."""
    tz = 0.38 * H
    tx0, tx1 = -0.35 * L, 0.3 * L
    b.box((-0.15 * L, -0.2 * B, 0), (0.15 * L, 0.2 * B, 0.05 * H), p.primary)
    b.box((-0.08 * L, -0.12 * B, 0.05 * H), (0.08 * L, 0.12 * B, tz - 0.05 * H), p.primary)
    b.box((tx0, -0.3 * B, tz - 0.05 * H), (tx1, 0.3 * B, tz), p.primary)
    b.box((tx0 + 0.02 * L, -0.27 * B, tz), (tx1 - 0.02 * L, 0.27 * B, tz + 0.03 * H), p.secondary)  # pad
    b.box((tx0 + 0.02 * L, -0.22 * B, tz + 0.03 * H), (tx0 + 0.14 * L, 0.22 * B, tz + 0.05 * H), tint("#f4f4f2", "paint"))
    cx, cy = -0.46 * L, -0.38 * B
    b.box((cx - 0.04 * L, cy - 0.1 * B, 0), (cx + 0.04 * L, cy + 0.1 * B, 0.04 * H), darker(p.primary, 0.1))
    b.box((cx - 0.025 * L, cy - 0.06 * B, 0.04 * H), (cx + 0.025 * L, cy + 0.06 * B, H), p.primary)  # column
    az = 0.78 * H
    b.box((cx, cy - 0.05 * B, az - 0.04 * H), (-0.05 * L, cy + 0.08 * B, az + 0.02 * H), p.primary)  # arm
    b.box((-0.1 * L, cy, az - 0.05 * H), (0.0, 0.05 * B, az + 0.02 * H), p.primary)
    b.rod((-0.12 * L, 0.0, az - 0.05 * H), (0.02 * L, 0.0, az - 0.05 * H), 0.08 * H, p.secondary, sections=14)  # tube
    b.box((-0.08 * L, -0.1 * B, az - 0.2 * H), (0.0, 0.1 * B, az - 0.1 * H), p.primary)  # collimator
    b.box((-0.07 * L, -0.08 * B, az - 0.21 * H), (-0.01 * L, 0.08 * B, az - 0.2 * H), p.accent)
    b.box((0.0, 0.1 * B, az - 0.17 * H), (0.02 * L, 0.14 * B, az - 0.12 * H), DARK_METAL)  # handle
    if p.wall_stand:
        sx = 0.45 * L
        b.box((sx - 0.04 * L, -0.2 * B, 0), (sx + 0.04 * L, 0.2 * B, 0.04 * H), darker(p.primary, 0.1))
        b.box((sx - 0.02 * L, -0.06 * B, 0.04 * H), (sx + 0.02 * L, 0.06 * B, 0.95 * H), p.primary)
        b.box((sx - 0.05 * L, -0.25 * B, 0.45 * H), (sx - 0.02 * L, 0.25 * B, 0.85 * H), p.secondary)  # detector
        b.box((sx - 0.055 * L, -0.18 * B, 0.5 * H), (sx - 0.05 * L, 0.18 * B, 0.8 * H), lighter(p.secondary, 0.3))


def build_xray_machine(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_xray(b, L, B, H, p))


# ----------------------------------------------------------------- medical scanner (MRI / CT)
def sample_medical_scanner(rng, size, style):
    return make_params("medical_scanner", rng, size, style, MEDICAL_WHITE, MEDICAL_ACCENTS, "#3a3b3e",
                       kind=str(rng.choice(["mri", "ct"])))


def _draw_scanner(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the gantry at -x, a big rounded block (MRI) or a ring (CT) with a round
    bore, and the patient table sliding into it from +x."""
    deep = 0.42 * L if p.kind == "mri" else 0.16 * L
    gx0 = -L / 2
    gx1 = gx0 + deep
    r_c = 0.18 * min(B, H)
    prof = [(-B / 2, 0.0), (B / 2, 0.0)] + arc(B / 2 - r_c, H - r_c, r_c, 0, np.pi / 2, 5) + \
        arc(-B / 2 + r_c, H - r_c, r_c, np.pi / 2, np.pi, 5)
    if p.kind == "ct":
        prof = [(-B / 2, 0.0), (B / 2, 0.0)] + arc(0, 0.5 * H, 0.5 * min(B, H), -0.3, np.pi + 0.3, 16)
        prof = [(y, max(z, 0.0)) for y, z in prof]
    bz = 0.5 * H
    br = 0.22 * min(B, H) if p.kind == "mri" else 0.25 * min(B, H)
    hole = [(br * np.cos(a), bz + br * np.sin(a)) for a in np.linspace(0, 2 * np.pi, 24, endpoint=False)]
    extrude_x(b, prof, gx0, gx1, p.primary, holes=[hole[::-1]])
    ring_x(b, (gx1 + 0.003, 0.0, bz), br * 1.25, 0.03 * br + 0.01, p.secondary, sections=28)
    b.box((gx1, 0.25 * B, 0.65 * H), (gx1 + 0.01, 0.38 * B, 0.75 * H), SCREEN)
    tz = bz - 0.55 * br
    b.box((gx1 + 0.05 * L, -0.15 * B, 0), (L / 2 - 0.05 * L, 0.15 * B, tz - 0.06 * H), lighter(p.primary, 0.05))
    b.box((gx0 + 0.05 * L, -0.5 * br, tz - 0.05 * H), (L / 2, 0.5 * br, tz), p.primary)  # table
    b.box((gx1 - 0.02 * L, -0.45 * br, tz), (L / 2 - 0.02 * L, 0.45 * br, tz + 0.03 * H), p.secondary)
    b.box((L / 2 - 0.14 * L, -0.3 * br, tz + 0.03 * H), (L / 2 - 0.04 * L, 0.3 * br, tz + 0.06 * H), tint("#f4f4f2", "paint"))


def build_medical_scanner(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_scanner(b, L, B, H, p))


slot_roles("wheelchair", "metal", "fabric", "plastic")
register("wheelchair", sample_wheelchair, build_wheelchair)
slot_roles("medical_cart", "paint", "paint", "plastic")
register("medical_cart", sample_medical_cart, build_medical_cart)
slot_roles("xray_machine", "paint", "paint", "paint")
register("xray_machine", sample_xray_machine, build_xray_machine)
slot_roles("medical_scanner", "plastic", "plastic", "plastic")
register("medical_scanner", sample_medical_scanner, build_medical_scanner)
