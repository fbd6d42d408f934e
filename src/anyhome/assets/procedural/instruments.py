"""Instruments and stage and chapel fittings: harp, marimba, pipe_organ, gong,
stage_light, votive_stand."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    disc_x,
    disc_y,
    path,
    ring_y,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    Builder,
    about,
    darker,
    lengthwise,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

GOLD = tint("#d4af37", "metal")
PIPE_METALS = tint(["#c9ccd0", "#d8dade", GOLD, "#b8a070"], "metal")
STRING = tint("#efe6d0", "metal")
ROSEWOOD = tint(["#7a3b22", "#8a4a2a", "#6b3320", "#9a5a34"], "wood")
FLAME = tint("#ffb030", "light")
VOTIVE_GLASS = tint(["#b8202a", "#c0392b", "#f4f1e6", "#d9a32a"], "glass")


# ----------------------------------------------------------------- harp
def sample_harp(rng, size, style):
    gilt = style_is(style, "antique") or (not style_is(style, "modern") and rng.random() < 0.5)
    return make_params("harp", rng, size, style, [GOLD, "#c9a54a"] if gilt else wood_tones(style),
                       wood_tones(style), "#b8202a", strings=int(rng.integers(26, 40)))


def build_harp(p):
    """A pedal harp in the x-z plane: the upright pillar with its crown, the soundbox
    slanting up from the base, the curved neck joining their tops, and the strings
    (every seventh red) running down from the neck to the soundbox."""
    w, d, h = p.size
    b = Builder()
    px = -0.4 * w
    b.box((-0.42 * w, -0.35 * d, 0), (0.2 * w, 0.35 * d, 0.06 * h), p.secondary)  # base
    for x in (-0.38 * w, 0.15 * w):
        for y in (-0.3 * d, 0.3 * d):
            b.sphere((x, y, 0.01 * h), (0.03 * w, 0.04 * d, 0.015 * h), p.secondary, subdivisions=0)
    b.cyl(px, 0, 0.06 * h, 0.88 * h, 0.05 * w, p.primary, r_top=0.045 * w, sections=12)  # pillar
    b.cyl(px, 0, 0.06 * h, 0.16 * h, 0.08 * w, p.primary, r_top=0.05 * w, sections=12)
    b.cyl(px, 0, 0.86 * h, 0.92 * h, 0.05 * w, p.primary, r_top=0.09 * w, sections=12)  # crown
    b.cyl(px, 0, 0.92 * h, h, 0.09 * w, p.primary, r_top=0.04 * w, sections=12)
    sb0 = np.array([-0.25 * w, 0.0, 0.06 * h])
    sb1 = np.array([0.42 * w, 0.0, 0.82 * h])
    b.hull([sb0 + (-0.08 * w, -0.3 * d, 0), sb0 + (0.1 * w, -0.3 * d, 0), sb0 + (-0.08 * w, 0.3 * d, 0),
            sb0 + (0.1 * w, 0.3 * d, 0), sb1 + (-0.05 * w, -0.12 * d, 0), sb1 + (0.05 * w, -0.12 * d, 0),
            sb1 + (-0.05 * w, 0.12 * d, 0), sb1 + (0.05 * w, 0.12 * d, 0)], p.secondary)  # soundbox
    b.hull([sb0 + (-0.07 * w, -0.06 * d, 0.02 * h), sb0 + (-0.07 * w, 0.06 * d, 0.02 * h),
            sb1 + (-0.052 * w, -0.03 * d, 0), sb1 + (-0.052 * w, 0.03 * d, 0),
            sb0 + (-0.09 * w, -0.06 * d, 0.02 * h), sb0 + (-0.09 * w, 0.06 * d, 0.02 * h),
            sb1 + (-0.06 * w, -0.03 * d, 0), sb1 + (-0.06 * w, 0.03 * d, 0)], lighter(p.secondary, 0.25))

    def neck_z(x: float) -> float:
        t = (x - px) / (sb1[0] - px)
        return 0.9 * h - 0.1 * h * np.sin(np.pi * t) + (0.86 * h - 0.9 * h) * t

    xs = np.linspace(px, sb1[0] + 0.05 * w, 10)
    pts = [(x, 0.0, neck_z(x)) for x in xs]
    for a, c in zip(pts[:-1], pts[1:], strict=True):  # the neck
        b.hull([(a[0], -0.06 * d, a[2] - 0.04 * h), (a[0], 0.06 * d, a[2] - 0.04 * h), (a[0], -0.06 * d, a[2] + 0.03 * h),
                (a[0], 0.06 * d, a[2] + 0.03 * h), (c[0], -0.06 * d, c[2] - 0.04 * h), (c[0], 0.06 * d, c[2] - 0.04 * h),
                (c[0], -0.06 * d, c[2] + 0.03 * h), (c[0], 0.06 * d, c[2] + 0.03 * h)], p.primary)
    n = p.strings
    for k in range(n):
        t = (k + 0.5) / n
        x = px + 0.08 * w + t * (sb1[0] - px - 0.12 * w)
        zb = sb0[2] + (x - (sb0[0] - 0.08 * w)) / (sb1[0] - sb0[0] + 0.08 * w) * (sb1[2] - sb0[2])
        zt = neck_z(x) - 0.04 * h
        if zt > zb + 0.02:
            b.box((x - 0.0015, -0.0015, zb), (x + 0.0015, 0.0015, zt), p.accent if k % 7 == 0 else STRING)
    for k in range(7):  # pedals
        x = -0.3 * w + k * 0.06 * w
        b.box((x - 0.01, 0.35 * d, 0.02 * h), (x + 0.01, 0.5 * d, 0.035 * h), BRASS)
    return b.mesh(p.size)


# ----------------------------------------------------------------- marimba
def sample_marimba(rng, size, style):
    return make_params("marimba", rng, size, style, ROSEWOOD, [BLACK, DARK_METAL, "#5c3b26"], [GOLD, BLACK, CHROME],
                       octaves=int(rng.integers(3, 6)))


def _draw_marimba(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x (low notes at -x): two rows of graduated bars, naturals in front and
    sharps behind, over resonator tubes that shorten to the right, on an end-framed stand."""
    n = 7 * p.octaves
    top = H - 0.02 * H
    x0, x1 = -0.44 * L, 0.44 * L
    step = (x1 - x0) / n
    for sx in (-1, 1):  # end frames on wheels
        x = sx * 0.47 * L
        b.box((x - 0.02 * L, -0.45 * B, 0.1 * H), (x + 0.02 * L, 0.45 * B, top - 0.1 * H), p.secondary)
        for y in (-0.4 * B, 0.4 * B):
            b.cyl(x, y, 0, 0.1 * H, 0.05 * H, BLACK, sections=10)
    for y in (-0.35 * B, 0.35 * B):
        b.box((-0.47 * L, y - 0.015, top - 0.12 * H), (0.47 * L, y + 0.015, top - 0.08 * H), p.secondary)
    for k in range(n):  # naturals
        t = k / max(1, n - 1)
        x = x0 + (k + 0.5) * step
        ln = (0.5 - 0.25 * t) * B
        b.box((x - 0.4 * step, 0.05 * B, top - 0.06 * H), (x + 0.4 * step, 0.05 * B + ln, top - 0.03 * H),
              p.primary if k % 2 else lighter(p.primary, 0.06))
        tube = (0.55 - 0.45 * t) * H
        b.cyl(x, 0.05 * B + ln / 2, top - 0.08 * H - tube, top - 0.08 * H, 0.35 * step, p.accent, sections=8)
    for k in range(n - 1):  # sharps over the gaps, in groups of two and three
        if k % 7 in (2, 6):
            continue
        t = k / max(1, n - 1)
        x = x0 + (k + 1) * step
        ln = (0.4 - 0.2 * t) * B
        b.box((x - 0.35 * step, -0.05 * B - ln, top - 0.03 * H), (x + 0.35 * step, -0.05 * B, top),
              darker(p.primary, 0.1))
        tube = (0.5 - 0.42 * t) * H
        b.cyl(x, -0.05 * B - ln / 2, top - 0.08 * H - tube, top - 0.08 * H, 0.3 * step, p.accent, sections=8)
    for y in (0.05 * B, -0.05 * B):  # bar rails
        b.box((x0, y - 0.01, top - 0.09 * H), (x1, y + 0.01, top - 0.06 * H), p.secondary)
    for s in (-1, 1):  # mallets lying on the bars
        b.rod((0.1 * L * s, 0.3 * B, top - 0.02 * H), (0.1 * L * s + 0.12 * L, 0.4 * B, top - 0.02 * H), 0.006,
              tint("#c9a06a", "wood"), sections=5)
        b.sphere((0.1 * L * s, 0.3 * B, top - 0.02 * H), 0.02, tint("#e8dcc0", "fabric"), subdivisions=1)


def build_marimba(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_marimba(b, L, B, H, p))


# ----------------------------------------------------------------- pipe organ
def sample_pipe_organ(rng, size, style):
    return make_params("pipe_organ", rng, size, style, wood_tones("antique") + wood_tones("")[4:6], PIPE_METALS,
                       [GOLD, "#c9a54a"], manuals=int(rng.integers(2, 4)), towers=int(rng.choice([3, 5])))


def build_pipe_organ(p):
    """A pipe organ: a wooden case at the back with a facade of metal pipes in towers
    (tallest in the middle) and flats, each pipe with its mouth and conical foot; in front
    the console with stacked keyboards, stop knobs, a music rack, bench and pedalboard."""
    w, d, h = p.size
    b = Builder()
    case_d = 0.45 * d
    cy0, cy1 = -d / 2, -d / 2 + case_d
    imp = 0.3 * h  # impost: the pipes stand on it
    b.box((-w / 2, cy0, 0), (w / 2, cy1, imp), p.primary)
    b.box((-w / 2 - 0.0, cy0, imp), (w / 2, cy1 - 0.1 * case_d, h - 0.05 * h), darker(p.primary, 0.25))
    b.box((-w / 2, cy0, imp - 0.03 * h), (w / 2, cy1 + 0.02, imp), lighter(p.primary, 0.1))
    groups = p.towers
    gx = np.linspace(-w / 2, w / 2, groups + 1)
    for g in range(groups):
        centre = abs(g - (groups - 1) / 2) / ((groups - 1) / 2)  # 0 in the middle, 1 at the ends
        tower = g % 2 == 0
        top = h - 0.04 * h - 0.25 * (h - imp) * centre * (0.6 if tower else 1.0) - (0.0 if tower else 0.12 * h)
        xa, xb = gx[g] + 0.01 * w, gx[g + 1] - 0.01 * w
        n = max(3, int((xb - xa) / 0.12))
        r = 0.42 * (xb - xa) / n
        for k in range(n):
            x = xa + (k + 0.5) * (xb - xa) / n
            u = abs((k + 0.5) / n - 0.5) * 2
            ptop = top - (0.18 * (h - imp) * u if tower else -0.1 * (h - imp) * u + 0.1 * (h - imp))
            ptop = min(ptop, h - 0.01)
            y = cy1 - r - (0.0 if tower else 0.08 * case_d)
            foot = imp + 0.1 * (ptop - imp)
            b.cyl(x, y, imp, foot, 0.25 * r, p.secondary, r_top=r, sections=10)
            b.cyl(x, y, foot, ptop, r, p.secondary if k % 2 else lighter(p.secondary, 0.12), sections=10)
            b.box((x - 0.5 * r, y + 0.8 * r, foot + 0.02 * h), (x + 0.5 * r, y + 1.02 * r, foot + 0.05 * h),
                  tint("#2a2a2e", "paint"))
        if tower:
            b.box((xa - 0.01, cy1 - 0.2 * case_d, top + 0.01), (xb + 0.01, cy1, top + 0.04 * h), p.primary)
            b.box((xa, cy1 - 0.2 * case_d, top + 0.04 * h), (xb, cy1, min(h, top + 0.06 * h)), p.accent)
    cw = min(0.45 * w, 1.6)  # console
    kz = 0.38 * h
    b.box((-cw / 2, cy1, 0), (cw / 2, cy1 + 0.35 * d, kz), p.primary)
    for s in (-1, 1):
        b.box((s * cw / 2 - (0.05 if s > 0 else 0), cy1, kz), (s * cw / 2 + (0.05 if s < 0 else 0), cy1 + 0.3 * d,
                                                               kz + 0.12 * h), p.primary)
        for i in range(3):
            for j in range(4):
                x = s * (cw / 2 - 0.12 - 0.05 * i)
                disc_y(b, x, cy1 + 0.02, cy1 + 0.05, kz + 0.05 * h + 0.03 * h * j, 0.012,
                       [tint("#f4f1e6", "paint"), tint("#c0392b", "paint"), BLACK][(i + j) % 3], sections=6)
    for m in range(p.manuals):
        z = kz + m * 0.035 * h
        y1 = cy1 + 0.33 * d - m * 0.05 * d
        b.box((-cw / 2 + 0.05, y1 - 0.12 * d, z), (cw / 2 - 0.05, y1, z + 0.015 * h), tint("#f4f1ea", "paint"))
        nkeys = max(8, int((cw - 0.1) / 0.03))
        for k in range(nkeys):
            if k % 7 in (2, 6):
                continue
            x = -cw / 2 + 0.05 + (k + 1) * (cw - 0.1) / (nkeys + 1)
            b.box((x - 0.006, y1 - 0.12 * d, z + 0.015 * h), (x + 0.006, y1 - 0.05 * d, z + 0.022 * h), BLACK)
    b.box((-cw / 2 + 0.05, cy1, kz + p.manuals * 0.035 * h), (cw / 2 - 0.05, cy1 + 0.06, kz + 0.2 * h), p.primary)
    b.box((-0.2 * cw, cy1 + 0.06, kz + p.manuals * 0.035 * h + 0.02), (0.2 * cw, cy1 + 0.08, kz + 0.18 * h), tint("#f4f1ea", "paint"))
    b.box((-cw / 2, d / 2 - 0.12 * d, 0.18 * h), (cw / 2, d / 2, 0.21 * h), p.primary)  # bench
    for x in (-cw / 2 + 0.04, cw / 2 - 0.04):
        b.box((x - 0.03, d / 2 - 0.12 * d, 0), (x + 0.03, d / 2, 0.18 * h), p.primary)
    for k in range(12):  # pedalboard
        x = -0.4 * cw + k * 0.8 * cw / 11
        b.box((x - 0.015, cy1 + 0.35 * d, 0.01), (x + 0.015, d / 2 - 0.14 * d, 0.03), tint("#e8dcc0", "paint") if k % 3 else BLACK)
    return b.mesh(p.size)


# ----------------------------------------------------------------- gong
def sample_gong(rng, size, style):
    return make_params("gong", rng, size, style, ["#8a1f1f", "#5c3b26", BLACK, "#3e2a1e"], ["#c9993a", "#b8862a",
                                                                                           "#d4a94a"], GOLD,
                       boss=bool(rng.random() < 0.6))


def build_gong(p):
    """A gong on its stand: two posts on wide feet, a top beam with upturned ends, the
    bronze disc (with a central boss and rings) hanging on cords, a mallet."""
    w, d, h = p.size
    b = Builder()
    t = min(0.05, 0.06 * w)
    for x in (-0.42 * w, 0.42 * w):
        b.box((x - t, -t, 0.05 * h), (x + t, t, h - 0.1 * h), p.primary)
        b.box((x - 1.5 * t, -d / 2, 0), (x + 1.5 * t, d / 2, 0.05 * h), p.primary)
        b.cyl(x, 0, h - 0.1 * h, h - 0.08 * h, 1.4 * t, p.accent, sections=8)
    b.hull([(-0.45 * w, -t, h - 0.1 * h), (0.45 * w, -t, h - 0.1 * h), (-0.45 * w, t, h - 0.1 * h),
            (0.45 * w, t, h - 0.1 * h), (-0.45 * w, -t, h - 0.04 * h), (0.45 * w, -t, h - 0.04 * h),
            (-0.45 * w, t, h - 0.04 * h), (0.45 * w, t, h - 0.04 * h)], p.primary)
    for s in (-1, 1):  # upturned ends
        b.hull([(s * 0.45 * w, -t, h - 0.1 * h), (s * 0.45 * w, t, h - 0.1 * h), (s * 0.45 * w, -t, h - 0.04 * h),
                (s * 0.45 * w, t, h - 0.04 * h), (s * w / 2, -t, h), (s * w / 2, t, h), (s * w / 2, -t, h - 0.03 * h),
                (s * w / 2, t, h - 0.03 * h)], p.primary)
    b.box((-0.42 * w, -0.7 * t, 0.15 * h), (0.42 * w, 0.7 * t, 0.15 * h + 2 * t), p.primary)
    R = min(0.36 * w, 0.34 * (h - 0.1 * h))
    cz = h - 0.14 * h - R
    disc_y(b, 0, -0.03, 0.0, cz, R, p.secondary, sections=32)
    ring_y(b, (0, 0.002, cz), 0.97 * R, 0.02 * R, darker(p.secondary, 0.2), sections=32)
    ring_y(b, (0, 0.002, cz), 0.6 * R, 0.01 * R, darker(p.secondary, 0.15), sections=28)
    if p.boss:
        b.sphere((0, 0.0, cz), (0.2 * R, 0.08 * R, 0.2 * R), lighter(p.secondary, 0.2), subdivisions=2)
    else:
        disc_y(b, 0, 0.0, 0.004, cz, 0.3 * R, lighter(p.secondary, 0.15), sections=20)
    for s in (-1, 1):
        b.rod((s * 0.5 * R, -0.015, cz + 0.86 * R), (s * 0.3 * w, 0, h - 0.1 * h), 0.006, tint("#c0392b", "fabric"), sections=4)
    b.rod((0.38 * w, 0.4 * d, 0.05 * h), (0.36 * w, 0.1 * d, 0.55 * h), 0.012, tint("#c9a06a", "wood"), sections=6)  # mallet
    b.sphere((0.36 * w, 0.1 * d, 0.55 * h), (0.06 * w, 0.06 * w, 0.05 * h), tint("#e8dcc0", "fabric"), subdivisions=1)
    return b.mesh(p.size)


# ----------------------------------------------------------------- stage light
def sample_stage_light(rng, size, style):
    return make_params("stage_light", rng, size, style, [BLACK, "#2b2b2b", "#3a3b3e", CHROME],
                       ["#fff1c4", "#8ac4ff", "#ff8ac4", "#ffd27a"], DARK_METAL,
                       kind=str(rng.choice(["par", "fresnel", "moving"])), tilt=float(rng.uniform(0.3, 0.8)))


def build_stage_light(p):
    """A stage light: a PAR can or a fresnel with barn doors tilting in a yoke on a clamp
    plate, or a moving head (a base box, a turning yoke, a round head)."""
    w, d, h = p.size
    b = Builder()
    R = 0.36 * min(w, d)
    b.box((-0.3 * w, -0.3 * d, 0), (0.3 * w, 0.3 * d, 0.05 * h), p.accent)  # mounting plate
    if p.kind == "moving":
        b.box((-0.42 * w, -0.42 * d, 0.05 * h), (0.42 * w, 0.42 * d, 0.3 * h), p.primary)
        b.box((-0.2 * w, 0.42 * d - 0.01, 0.12 * h), (0.2 * w, 0.42 * d, 0.22 * h), tint("#1c2430", "paint"))
        arm = 0.08 * w
        for s in (-1, 1):
            b.box((s * 0.4 * w - arm / 2, -0.1 * d, 0.3 * h), (s * 0.4 * w + arm / 2, 0.1 * d, 0.8 * h), p.primary)
        c = (0, 0, 0.68 * h)
        b.sphere(c, (0.34 * w, 0.34 * d, 0.26 * h), p.primary, subdivisions=2)
        disc_y(b, 0, 0.2 * d, 0.36 * d, c[2], 0.2 * min(w, h), p.secondary, sections=16)
        return b.mesh(p.size)
    zc = 0.58 * h
    for s in (-1, 1):  # the yoke
        b.box((s * (R + 0.05 * w) - 0.02 * w, -0.04 * d, 0.12 * h), (s * (R + 0.05 * w) + 0.02 * w, 0.04 * d, zc),
              p.accent)
        disc_x(b, s * (R + 0.03 * w), s * (R + 0.08 * w), 0, zc, 0.05 * h, p.accent, sections=10)
    b.box((-(R + 0.07 * w), -0.04 * d, 0.08 * h), (R + 0.07 * w, 0.04 * d, 0.12 * h), p.accent)
    b.cyl(0, 0, 0.05 * h, 0.08 * h, 0.06 * w, p.accent, sections=8)
    tilt = about(rot_x(-p.tilt), (0, 0, zc))
    L = 0.9 * min(d, h)
    sub = Builder()
    if p.kind == "fresnel":
        sub.box((-R, -0.4 * L, zc - R), (R, 0.3 * L, zc + R), p.primary)
        sub.rod((0, 0.3 * L, zc), (0, 0.33 * L, zc), 0.8 * R, p.secondary, sections=16)
        for z0, z1 in ((zc + R, zc + R + 0.02 * h), (zc - R - 0.02 * h, zc - R)):  # barn doors
            sub.box((-R, 0.3 * L, z0), (R, 0.3 * L + 0.5 * R, z1), p.primary)
        for x0, x1 in ((-R - 0.02 * w, -R), (R, R + 0.02 * w)):
            sub.box((x0, 0.3 * L, zc - 0.8 * R), (x1, 0.3 * L + 0.4 * R, zc + 0.8 * R), p.primary)
        sub.rod((0, -0.4 * L, zc), (0, -0.5 * L, zc), 0.3 * R, p.primary, sections=8)
    else:
        sub.rod((0, -0.45 * L, zc), (0, 0.4 * L, zc), R, p.primary, sections=18)
        sub.rod((0, 0.4 * L, zc), (0, 0.42 * L, zc), 1.05 * R, p.primary, sections=18)
        sub.rod((0, 0.41 * L, zc), (0, 0.425 * L, zc), 0.85 * R, p.secondary, sections=18)
        sub.rod((0, -0.5 * L, zc), (0, -0.45 * L, zc), 0.6 * R, darker(p.primary, 0.2), sections=12)
    b.extend(sub, tilt)
    return b.mesh(p.size)


# ----------------------------------------------------------------- votive stand
def sample_votive_stand(rng, size, style):
    return make_params("votive_stand", rng, size, style, [BLACK, DARK_METAL, BRASS, "#5c3b26"], VOTIVE_GLASS,
                       BRASS, tiers=int(rng.integers(3, 5)))


def build_votive_stand(p):
    """A votive candle stand: stepped tiers of red and clear glass cups with little flames
    on a metal frame with legs, an offering box in front."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    n = p.tiers
    base = 0.45 * h
    top = h - 0.12 * h
    for x in (-0.46 * w, 0.46 * w):
        for y in (-0.42 * d, 0.4 * d):
            b.box((x - 0.015, y - 0.015, 0), (x + 0.015, y + 0.015, base + (top - base) * (0.0 if y > 0 else 1.0)),
                  p.primary)
    b.box((-0.46 * w, -0.42 * d, 0.1 * h), (0.46 * w, 0.4 * d, 0.12 * h), p.primary)
    cups = max(4, int(w / 0.075))
    for k in range(n):
        t = k / max(1, n - 1)
        y1 = 0.45 * d - k * 0.85 * d / n
        y0 = y1 - 0.85 * d / n
        z = base + t * (top - base - 0.12 * h) if n > 1 else base
        b.box((-w / 2, y0, z - 0.02), (w / 2, y1, z), p.primary)
        b.box((-w / 2, y1 - 0.01, z), (w / 2, y1, z + 0.02), p.accent)
        for i in range(cups):
            x = -w / 2 + (i + 0.5) * w / cups
            yc = (y0 + y1) / 2
            cr = min(0.3 * w / cups, 0.3 * (y1 - y0))
            col = p.secondary if rng.random() < 0.6 else VOTIVE_GLASS[int(rng.integers(len(VOTIVE_GLASS)))]
            b.cyl(x, yc, z, z + 2.2 * cr, cr, col, r_top=1.05 * cr, sections=8)
            if rng.random() < 0.7:
                b.sphere((x, yc, z + 2.8 * cr), (0.35 * cr, 0.35 * cr, 0.8 * cr), FLAME, subdivisions=0)
    b.box((-0.15 * w, 0.2 * d, 0.12 * h), (0.15 * w, 0.45 * d, 0.3 * h), p.primary if p.primary != BRASS else
          DARK_METAL)  # offering box
    b.box((-0.06 * w, 0.2 * d, 0.3 * h), (0.06 * w, 0.35 * d, 0.302 * h), BLACK)
    b.cyl(0, -0.3 * d, top, h - 0.02 * h, 0.01, p.accent, sections=6)  # a small cross on top
    b.box((-0.04 * w, -0.3 * d - 0.008, h - 0.07 * h), (0.04 * w, -0.3 * d + 0.008, h - 0.055 * h), p.accent)
    path(b, [(0.4 * w, 0.4 * d, 0.12 * h), (0.42 * w, 0.42 * d, 0.5 * h)], 0.004, tint("#c9a06a", "paint"), sections=4)
    return b.mesh(p.size)


slot_roles("harp", {"": "wood", GOLD: "metal", "#c9a54a": "metal"}, "wood", "fabric")
register("harp", sample_harp, build_harp)
slot_roles("marimba", "wood", "metal", "metal")
register("marimba", sample_marimba, build_marimba)
slot_roles("pipe_organ", "wood", "metal", "metal")
register("pipe_organ", sample_pipe_organ, build_pipe_organ)
slot_roles("gong", "wood", "metal", "metal")
register("gong", sample_gong, build_gong)
slot_roles("stage_light", "metal", "light", "metal")
register("stage_light", sample_stage_light, build_stage_light)
slot_roles("votive_stand", "metal", "glass", "metal")
register("votive_stand", sample_votive_stand, build_votive_stand)

