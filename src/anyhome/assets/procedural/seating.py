"""Seating: sofa, armchair, chair, office_chair, stool, bench, dental_chair, weight_bench."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    about,
    corners,
    darker,
    fabric_tones,
    leg_style,
    lighter,
    make_params,
    rot_x,
    rot_z,
    slot_roles,
    wood_tones,
)
from anyhome.assets.registry import register


def _sofa_params(name, rng, size, style):
    return make_params(name, rng, size, style, fabric_tones(style), wood_tones(style),
                       ["#d9c3a0", "#9fb2a0", "#b9a2b8", "#c8b8a6", "#e3ddd2", "#7a5a30"],
                       legs=leg_style(rng, style), arm=float(rng.uniform(0.1, 0.18)),
                       seat=float(rng.uniform(0.42, 0.5)), throw_pillows=int(rng.integers(0, 3)),
                       rolled_arms=bool(rng.random() < 0.3))


def _upholstered(b: Builder, p, w, d, h, cushions: int) -> None:
    leg = min(0.12, 0.15 * h)
    seat = p.seat * h
    arm_w = min(p.arm, w * 0.2)
    arm_h = min(0.68 * h, seat + 0.22)
    back_d = 0.22 * d
    b.legs(corners(w, d, 0.06), 0, leg, 0.025, p.legs, p.secondary)
    b.box((-w / 2, -d / 2, leg), (w / 2, d / 2, seat - 0.1), p.primary)  # base
    b.box((-w / 2 + arm_w * 0.5, -d / 2, leg), (w / 2 - arm_w * 0.5, -d / 2 + back_d, h * 0.97), p.primary)
    for s in (-1, 1):  # arms
        x0 = s * (w / 2 - arm_w)
        b.box((min(x0, s * w / 2), -d / 2, leg), (max(x0, s * w / 2), d / 2, arm_h), p.primary)
        if p.rolled_arms:
            b.rod((s * (w / 2 - arm_w / 2), -d / 2, arm_h), (s * (w / 2 - arm_w / 2), d / 2, arm_h),
                  arm_w / 2, p.primary)
    inner = w - 2 * arm_w
    cw = inner / cushions
    ccol = lighter(p.primary, 0.12)
    for i in range(cushions):
        x0 = -w / 2 + arm_w + i * cw
        b.box((x0 + 0.005, -d / 2 + back_d, seat - 0.1), (x0 + cw - 0.005, d / 2 - 0.01, seat), ccol)
        b.box((x0 + 0.01, -d / 2 + back_d - 0.12, seat), (x0 + cw - 0.01, -d / 2 + back_d, h * 0.9), ccol,
              transform=about(rot_x(-0.12), (0, -d / 2 + back_d, seat)))
    for i in range(p.throw_pillows):
        s = -1 if i == 0 else 1
        b.cbox((s * (inner / 2 - 0.2), -d / 2 + back_d + 0.05, seat + 0.2), (0.4, 0.12, 0.38), p.accent,
               transform=about(rot_z(s * 0.2) @ rot_x(-0.25), (s * (inner / 2 - 0.2), -d / 2 + back_d + 0.05, seat + 0.2)))


def sample_sofa(rng, size, style):
    return _sofa_params("sofa", rng, size, style)


def build_sofa(p):
    w, d, h = p.size
    b = Builder()
    cushions = max(1, min(4, int(round((w - 0.4) / 0.65))))
    _upholstered(b, p, w, d, h, cushions)
    return b.mesh(p.size)


def sample_armchair(rng, size, style):
    return _sofa_params("armchair", rng, size, style)


def build_armchair(p):
    w, d, h = p.size
    b = Builder()
    _upholstered(b, p, w, d, h, 1)
    return b.mesh(p.size)


def sample_chair(rng, size, style):
    return make_params("chair", rng, size, style, wood_tones(style), fabric_tones(style), "#e3ddd2",
                       legs=leg_style(rng, style), back=str(rng.choice(["slats", "panel", "spindles"])),
                       seat=float(rng.uniform(0.44, 0.5)), cushion=bool(rng.random() < 0.5))


def build_chair(p):
    w, d, h = p.size
    b = Builder()
    seat = min(p.seat * h if h > 0.6 else 0.6 * h, h - 0.1)
    t = 0.04
    r = 0.022
    b.legs(corners(w, d, r + 0.01), 0, seat - t, r, p.legs, p.primary)
    b.box((-w / 2, -d / 2, seat - t), (w / 2, d / 2, seat), p.primary)
    if p.cushion:
        b.box((-w / 2 + 0.02, -d / 2 + 0.04, seat), (w / 2 - 0.02, d / 2 - 0.02, seat + 0.03), p.secondary)
    y0 = -d / 2
    for s in (-1, 1):  # back posts
        x = s * (w / 2 - r - 0.01)
        b.box((x - r, y0, seat), (x + r, y0 + 2 * r, h), p.primary)
    if p.back == "panel":
        b.box((-w / 2 + 0.04, y0 + 0.005, seat + 0.3 * (h - seat)), (w / 2 - 0.04, y0 + 0.035, h - 0.02),
              p.secondary if p.cushion else p.primary)
    elif p.back == "slats":
        for z in np.linspace(seat + 0.35 * (h - seat), h - 0.04, 3):
            b.box((-w / 2 + 0.03, y0 + 0.005, z - 0.03), (w / 2 - 0.03, y0 + 0.035, z + 0.03), p.primary)
    else:
        b.box((-w / 2 + 0.03, y0, h - 0.07), (w / 2 - 0.03, y0 + 0.04, h), p.primary)
        for x in np.linspace(-w / 2 + 0.1, w / 2 - 0.1, 4):
            b.cyl(x, y0 + 0.02, seat, h - 0.07, 0.01, p.primary, sections=8)
    return b.mesh(p.size)


def sample_office_chair(rng, size, style):
    return make_params("office_chair", rng, size, style, [BLACK, "#3f4a5a", "#5f6b7a", "#8c8f94", "#6e2233"],
                       DARK_METAL, METAL, arms=bool(rng.random() < 0.7), mesh_back=bool(rng.random() < 0.5))


def build_office_chair(p):
    w, d, h = p.size
    b = Builder()
    seat = min(0.5, 0.48 * h)
    rad = min(w, d) / 2
    for k in range(5):
        a = 2 * np.pi * k / 5 + np.pi / 2
        end = np.array([np.cos(a), np.sin(a)]) * (rad - 0.03)
        b.rod((0, 0, 0.06), (end[0], end[1], 0.05), 0.018, p.secondary, sections=8)
        b.sphere((end[0], end[1], 0.03), 0.03, BLACK)
    b.cyl(0, 0, 0.05, seat - 0.08, 0.025, p.accent)
    b.cyl(0, 0, 0.05, 0.2, 0.04, p.secondary)
    b.box((-0.12, -0.12, seat - 0.1), (0.12, 0.12, seat - 0.06), p.secondary)
    b.box((-w / 2 + 0.05, -d / 2 + 0.08, seat - 0.07), (w / 2 - 0.05, d / 2 - 0.02, seat), p.primary)
    b.box((-0.03, -d / 2 + 0.03, seat - 0.07), (0.03, -d / 2 + 0.08, seat + 0.25), p.secondary)
    back = p.primary if not p.mesh_back else darker(p.primary, 0.2)
    b.box((-w / 2 + 0.08, -d / 2, seat + 0.08), (w / 2 - 0.08, -d / 2 + 0.06, h - 0.02), back,
          transform=about(rot_x(-0.1), (0, -d / 2, seat)))
    b.box((-w / 2 + 0.12, -d / 2 - 0.0, h - 0.14), (w / 2 - 0.12, -d / 2 + 0.07, h), p.primary,
          transform=about(rot_x(-0.1), (0, -d / 2, seat)))
    if p.arms:
        for s in (-1, 1):
            x = s * (w / 2 - 0.04)
            b.box((x - 0.015, -0.05, seat - 0.05), (x + 0.015, 0.0, seat + 0.2), p.secondary)
            b.box((x - 0.035, -0.15, seat + 0.2), (x + 0.035, 0.12, seat + 0.23), BLACK)
    return b.mesh(p.size)


def sample_stool(rng, size, style):
    return make_params("stool", rng, size, style, wood_tones(style) + [BLACK, METAL], fabric_tones(style),
                       DARK_METAL, legs=leg_style(rng, style), padded=bool(rng.random() < 0.5),
                       n_legs=int(rng.choice([3, 4])))


def build_stool(p):
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    if h < 0.35 or (p.padded and h < 0.5):  # ottoman / pouf
        b.cyl(0, 0, 0, h * 0.85, r, p.secondary, ry=d / 2 * 0.98, r_top=r * 0.98)
        b.cyl(0, 0, h * 0.85, h, r * 0.95, lighter(p.secondary, 0.15), ry=d / 2 * 0.93)
        return b.mesh(p.size)
    t = 0.04
    for k in range(p.n_legs):
        a = 2 * np.pi * k / p.n_legs + np.pi / 4
        fx, fy = np.cos(a) * (w / 2 - 0.03), np.sin(a) * (d / 2 - 0.03)
        tx, ty = fx * 0.6, fy * 0.6
        b.rod((fx, fy, 0), (tx, ty, h - t), 0.018, p.primary, sections=8)
    b.cyl(0, 0, h * 0.3, h * 0.32, (w / 2) * 0.75, p.accent, ry=(d / 2) * 0.75)
    b.cyl(0, 0, h * 0.3 - 0.01, h * 0.3 + 0.01, (w / 2) * 0.77, p.accent, ry=(d / 2) * 0.77)
    b.cyl(0, 0, h - t, h, r, p.secondary if p.padded else p.primary, ry=d / 2)
    return b.mesh(p.size)


def sample_bench(rng, size, style):
    return make_params("bench", rng, size, style, wood_tones(style), fabric_tones(style), DARK_METAL,
                       legs=leg_style(rng, style), backrest=bool(rng.random() < 0.3),
                       padded=bool(rng.random() < 0.4))


def build_bench(p):
    w, d, h = p.size
    b = Builder()
    has_back = p.backrest and h > 0.7
    seat = min(0.46, 0.9 * h) if has_back else h
    t = 0.05
    n = 4 if w < 1.6 else 6
    xs = np.linspace(-w / 2 + 0.06, w / 2 - 0.06, n // 2)
    b.legs([(x, y) for x in xs for y in (-d / 2 + 0.05, d / 2 - 0.05)], 0, seat - t, 0.025, p.legs, p.primary)
    b.box((-w / 2, -d / 2, seat - t), (w / 2, d / 2, seat), p.primary)
    if p.padded:
        b.box((-w / 2 + 0.02, -d / 2 + 0.02, seat), (w / 2 - 0.02, d / 2 - 0.02, seat + 0.04), p.secondary)
    if has_back:
        for x in xs:
            b.box((x - 0.025, -d / 2, seat), (x + 0.025, -d / 2 + 0.04, h), p.primary)
        for z in (seat + 0.5 * (h - seat), h - 0.05):
            b.box((-w / 2, -d / 2, z - 0.05), (w / 2, -d / 2 + 0.04, z + 0.05 if z < h - 0.05 else h), p.primary)
    return b.mesh(p.size)


def sample_dental_chair(rng, size, style):
    return make_params("dental_chair", rng, size, style, ["#5fa8b8", "#e8e6e0", "#3f6f9a", "#6aa874"],
                       "#e8e6e0", METAL)


def build_dental_chair(p):
    w, d, h = p.size
    b = Builder()
    seat = 0.5 * h
    b.box((-0.3 * w, -0.3 * d, 0), (0.3 * w, 0.2 * d, 0.05), p.secondary)
    b.cyl(0, -0.05 * d, 0.05, seat - 0.08, 0.1, p.secondary)
    cw = min(w * 0.7, 0.65)
    b.box((-cw / 2, -0.2 * d, seat - 0.1), (cw / 2, 0.15 * d, seat), p.primary)  # seat
    b.box((-cw / 2, -0.5 * d, seat - 0.05), (cw / 2, -0.5 * d + 0.12, h * 0.9), p.primary,
          transform=about(rot_x(-0.55), (0, -0.2 * d, seat)))  # reclined back
    b.box((-cw / 2, 0.15 * d, seat - 0.25), (cw / 2, d / 2, seat - 0.15), p.primary,
          transform=about(rot_x(-0.35), (0, 0.15 * d, seat - 0.1)))  # leg rest
    for s in (-1, 1):
        b.box((s * cw / 2 - 0.04, -0.15 * d, seat + 0.15), (s * cw / 2 + 0.04, 0.12 * d, seat + 0.2), p.primary)
    # lamp arm and tray
    b.cyl(w / 2 - 0.06, -0.3 * d, 0, h * 0.95, 0.03, p.accent)
    b.rod((w / 2 - 0.06, -0.3 * d, h * 0.95), (0.0, -0.05 * d, h * 0.97), 0.02, p.accent)
    b.sphere((0.0, -0.05 * d, h * 0.95), (0.1, 0.06, 0.05), p.secondary)
    b.box((-w / 2, 0.0, seat + 0.15), (-w / 2 + 0.35, 0.25 * d, seat + 0.18), p.accent)
    return b.mesh(p.size)


def sample_weight_bench(rng, size, style):
    return make_params("weight_bench", rng, size, style, [BLACK, "#6e2233", "#2e4a8b"], DARK_METAL, METAL)


def build_weight_bench(p):
    w, d, h = p.size
    b = Builder()
    pad = 0.45
    for y in (-d / 2 + 0.1, d / 2 - 0.1):
        b.box((-0.2, y - 0.03, 0), (0.2, y + 0.03, 0.05), p.secondary)
        b.box((-0.03, y - 0.03, 0.05), (0.03, y + 0.03, pad - 0.06), p.secondary)
    b.box((-0.03, -d / 2 + 0.1, pad - 0.09), (0.03, d / 2 - 0.1, pad - 0.06), p.secondary)
    b.box((-0.15, -d / 2 + 0.05, pad - 0.06), (0.15, d / 2 - 0.05, pad), p.primary)
    if h > pad + 0.3:  # the rack spans the box (otherwise the fit would stretch the bench)
        y = -d / 2 + 0.05
        for s in (-1, 1):
            b.box((s * 0.3 - 0.03, y - 0.05, 0), (s * 0.3 + 0.03, y + 0.05, h * 0.85), p.secondary)
        b.rod((-w / 2, y, h * 0.85), (w / 2, y, h * 0.85), 0.015, p.accent)
        for s in (-1, 1):
            b.rod((s * (w / 2 - 0.12), y, h * 0.85), (s * (w / 2 - 0.06), y, h * 0.85), min(0.2, h * 0.15), BLACK,
                  sections=20)
    return b.mesh(p.size)


slot_roles("sofa", "fabric", "wood", "fabric")
register("sofa", sample_sofa, build_sofa)
slot_roles("armchair", "fabric", "wood", "fabric")
register("armchair", sample_armchair, build_armchair)
slot_roles("chair", "wood", "fabric", "fabric")
register("chair", sample_chair, build_chair)
slot_roles("office_chair", "fabric", "metal", "metal")
register("office_chair", sample_office_chair, build_office_chair)
slot_roles("stool", {"": "wood", METAL: "metal"}, "fabric", "metal")
register("stool", sample_stool, build_stool)
slot_roles("bench", "wood", "fabric", "metal")
register("bench", sample_bench, build_bench)
slot_roles("dental_chair", "leather", "plastic", "metal")
register("dental_chair", sample_dental_chair, build_dental_chair)
slot_roles("weight_bench", "leather", "metal", "metal")
register("weight_bench", sample_weight_bench, build_weight_bench)
