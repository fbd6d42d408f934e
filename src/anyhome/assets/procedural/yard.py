"""Garden and yard: pergola, sun_lounger, surfboard, beehive, chicken_coop, lawn_mower,
wheelbarrow."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    disc_x,
    disc_y,
    extrude_x,
    extrude_y,
    wheel_x,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    about,
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

LEAF = tint(["#3f7a3a", "#4a8a3a", "#2f6a2f", "#5a9a4a"], "plant")
BOARD_COLORS = tint(["#f4f1ea", "#4ab0c0", "#f08a2a", "#e8c53a", "#2d6fb0", "#e05a47", "#7fc8a8"], "plastic")
STRAW = tint("#d9b870", "plant")
HIVE_PAINT = tint(["#f4f1ea", "#f1e0a0", "#c6e0c6", "#c6d8f0", "#e8d8b0"], "paint")
MOWER = tint(["#c0392b", "#3f8a4a", "#e8702a", "#e0b030", "#2d6fb0"], "paint")


# ----------------------------------------------------------------- pergola
def sample_pergola(rng, size, style):
    return make_params("pergola", rng, size, style, wood_tones(style) + ["#f4f1ea", "#2b2b2b"], LEAF, "#e8dcc0",
                       vines=bool(rng.random() < 0.5), canopy=bool(rng.random() < 0.25))


def build_pergola(p):
    """A pergola: four posts carrying two beams with shaped ends, rafters across them and
    thin battens on top; climbing vines on one side or a shade cloth."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = min(0.14, 0.06 * min(w, d))
    inset = 0.12 * min(w, d)
    beam_z0 = h - 0.18 * h
    for x in (-w / 2 + inset, w / 2 - inset - t):
        for y in (-d / 2 + inset, d / 2 - inset - t):
            b.box((x, y, 0), (x + t, y + t, beam_z0), p.primary)
            b.box((x - 0.2 * t, y - 0.2 * t, 0), (x + 1.2 * t, y + 1.2 * t, 0.04 * h), darker(p.primary, 0.2))
    for y in (-d / 2 + inset, d / 2 - inset - t):  # beams
        prof = [(-w / 2, beam_z0 + 0.04 * h), (-w / 2 + 0.05 * w, beam_z0), (w / 2 - 0.05 * w, beam_z0),
                (w / 2, beam_z0 + 0.04 * h), (w / 2, beam_z0 + 0.09 * h), (-w / 2, beam_z0 + 0.09 * h)]
        extrude_y(b, prof, y, y + t, p.primary)
    rz = beam_z0 + 0.09 * h
    n = max(4, int(w / 0.35))
    for k in range(n):
        x = -w / 2 + 0.06 * w + k * (0.88 * w) / (n - 1)
        prof = [(-d / 2, rz + 0.04 * h), (-d / 2 + 0.04 * d, rz), (d / 2 - 0.04 * d, rz), (d / 2, rz + 0.04 * h),
                (d / 2, rz + 0.07 * h), (-d / 2, rz + 0.07 * h)]
        extrude_x(b, prof, x - 0.3 * t, x + 0.3 * t, lighter(p.primary, 0.05))
    for k in range(max(3, int(d / 0.5))):
        y = -d / 2 + 0.1 * d + k * 0.8 * d / max(2, int(d / 0.5) - 1)
        b.box((-w / 2 + 0.03 * w, y - 0.2 * t, rz + 0.07 * h), (w / 2 - 0.03 * w, y + 0.2 * t, h), p.primary)
    if p.canopy:
        b.box((-w / 2 + inset, -d / 2 + inset, rz + 0.07 * h - 0.01), (w / 2 - inset, d / 2 - inset, rz + 0.07 * h),
              p.accent, alpha=220)
    if p.vines:
        x = -w / 2 + inset + t / 2
        for y in (-d / 2 + inset + t / 2, d / 2 - inset - t / 2):
            for k in range(8):
                z = (k + 0.5) * beam_z0 / 8
                b.sphere((x + rng.uniform(-0.05, 0.05), y + rng.uniform(-0.05, 0.05), z), 0.12 + 0.05 * rng.random(),
                         p.secondary, subdivisions=0)
        for _ in range(14):
            yy = rng.uniform(-d / 2 + inset, d / 2 - inset)
            b.sphere((x + rng.uniform(-0.1, 0.3), yy, rz + 0.08 * h), (0.18, 0.18, 0.08), LEAF[int(rng.integers(4))],
                     subdivisions=0)
    return b.mesh(p.size)


# ----------------------------------------------------------------- sun lounger
def sample_sun_lounger(rng, size, style):
    return make_params("sun_lounger", rng, size, style, wood_tones(style)[:3] + ["#f4f1ea", "#9a9da3"],
                       ["#f4f1ea", "#2d6fb0", "#e8c53a", "#5f6b7a", "#e05a47", "#4ab0c0"], ["#f4f1ea", "#2d6fb0"],
                       cushion=bool(rng.random() < 0.6), back=float(rng.uniform(0.5, 0.9)))


def _draw_lounger(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the head end at -x with its raised backrest, legs (wheels at the head),
    slats or a cushion on the flat part."""
    fz = 0.42 * H
    hinge_x = -0.15 * L
    for y in (-0.44 * B, 0.44 * B):
        b.box((-L / 2, y - 0.03 * B, fz - 0.12 * H), (L / 2, y + 0.03 * B, fz), p.primary)
    for x in (-0.42 * L, 0.42 * L):
        for y in (-0.4 * B, 0.4 * B):
            if x < 0:
                disc_y(b, x, y - 0.02, y + 0.02, 0.12 * H, 0.12 * H, BLACK, sections=12)
            else:
                b.box((x - 0.02 * L, y - 0.03 * B, 0), (x + 0.02 * L, y + 0.03 * B, fz), p.primary)
    top = fz + (0.1 * H if p.cushion else 0.0)
    if p.cushion:
        b.box((hinge_x, -0.42 * B, fz), (L / 2 - 0.01 * L, 0.42 * B, top), p.secondary)
    else:
        n = max(4, int((L / 2 - hinge_x) / 0.08))
        for k in range(n):
            x = hinge_x + (k + 0.2) * (L / 2 - hinge_x) / n
            b.box((x, -0.42 * B, fz - 0.03 * H), (x + 0.6 * (L / 2 - hinge_x) / n, 0.42 * B, fz), p.primary)
    back = about(rot_y(p.back * 0.9), (hinge_x, 0, top))
    length = hinge_x + L / 2
    sub = Builder()
    if p.cushion:
        sub.box((hinge_x - length, -0.42 * B, top - 0.1 * H), (hinge_x, 0.42 * B, top), p.secondary)
        sub.box((hinge_x - length, -0.3 * B, top), (hinge_x - length + 0.18 * L, 0.3 * B, top + 0.12 * H), p.accent)
    else:
        for k in range(max(3, int(length / 0.08))):
            x = hinge_x - length + (k + 0.2) * length / max(3, int(length / 0.08))
            sub.box((x, -0.42 * B, top - 0.03 * H), (x + 0.6 * length / max(3, int(length / 0.08)), 0.42 * B, top),
                    p.primary)
    for y in (-0.44 * B, 0.44 * B):
        sub.box((hinge_x - length, y - 0.03 * B, top - 0.12 * H), (hinge_x, y + 0.03 * B, top - 0.04 * H), p.primary)
    b.extend(sub, back)


def build_sun_lounger(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_lounger(b, L, B, H, p))


# ----------------------------------------------------------------- surfboard
def sample_surfboard(rng, size, style):
    return make_params("surfboard", rng, size, style, BOARD_COLORS, BOARD_COLORS, "#2b2b2b",
                       nose=float(rng.uniform(0.3, 1.0)), stripe=bool(rng.random() < 0.7))


def build_surfboard(p):
    """A surfboard standing on its tail against the wall, nose up: the outline pointed
    (or rounded) at the nose, a stripe, the stringer and a fin at the back."""
    w, d, h = p.size
    b = Builder()
    n = 16
    th = 0.45 * d
    lean = about(rot_x(-0.06), (0, 0, 0))
    sub = Builder()
    prev = None
    for k in range(n + 1):
        t = k / n
        hw = 0.5 * w * (np.sin(np.pi * min(1.0, t * 1.05)) ** (0.5 + 0.3 * p.nose) if t < 0.95 else
                        0.5 * w * 0.25 * (1 - p.nose) + 0.01)
        hw = max(hw, 0.18 * w * (1 - t) if t < 0.1 else 0.02)
        z = t * h
        ring = [(hw * np.cos(a), 0.5 * th * np.sin(a) * (0.6 + 0.4 * np.sin(np.pi * t)), z)
                for a in np.linspace(0, 2 * np.pi, 10, endpoint=False)]
        if prev is not None:
            col = p.secondary if p.stripe and 0.55 < t <= 0.75 else p.primary
            sub.hull(prev + ring, col)
        prev = ring
    sub.box((-0.004, th / 2 * 0.85, 0.02 * h), (0.004, th / 2 * 0.95, 0.97 * h), lighter(p.primary, 0.3)
            if p.primary != tint("#f4f1ea", "paint") else tint("#c9a06a", "paint"))  # stringer
    sub.hull([(0, -0.3 * th, 0.04 * h), (0, -0.3 * th, 0.16 * h), (0, -d / 2 - 0.2 * d, 0.06 * h),
              (0.005, -0.3 * th, 0.1 * h), (-0.005, -0.3 * th, 0.1 * h)], p.accent)  # fin
    b.extend(sub, lean)
    return b.mesh(p.size)


# ----------------------------------------------------------------- beehive
def sample_beehive(rng, size, style):
    skep = style_is(style, "rustic", "antique") and rng.random() < 0.6
    return make_params("beehive", rng, size, style, HIVE_PAINT, wood_tones("rustic"), "#b8bcc0",
                       kind="skep" if skep else "boxes", boxes=int(rng.integers(2, 5)))


def build_beehive(p):
    """A beehive: a stack of painted boxes with hand-hold slots under a metal-topped lid,
    on a stand, its entrance slot over a landing board and a few bees; or a straw skep
    on a wooden stand."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    stand = 0.18 * h
    for x in (-0.4 * w, 0.4 * w):
        for y in (-0.4 * d, 0.4 * d):
            b.box((x - 0.03, y - 0.03, 0), (x + 0.03, y + 0.03, stand), p.secondary)
    b.box((-0.45 * w, -0.45 * d, stand - 0.03 * h), (0.45 * w, 0.45 * d, stand), p.secondary)
    if p.kind == "skep":
        R = 0.44 * min(w, d)
        rings = 9
        for k in range(rings):
            t0, t1 = k / rings, (k + 1) / rings
            r0 = R * np.cos(t0 * np.pi / 2) ** 0.7
            r1 = R * np.cos(t1 * np.pi / 2) ** 0.7
            z0 = stand + t0 * (h - stand)
            z1 = stand + t1 * (h - stand)
            b.cyl(0, 0, z0, z1, max(r0, 0.02), STRAW if k % 2 else darker(STRAW, 0.1), r_top=max(r1, 0.01), sections=20)
        b.box((-0.12 * w, R * 0.85, stand), (0.12 * w, R * 1.02, stand + 0.06 * h), tint("#2a2018", "paint"))
        return b.mesh(p.size)
    y0, y1 = -0.42 * d, 0.4 * d
    b.box((-0.42 * w, y0, stand), (0.42 * w, y1 + 0.05 * d, stand + 0.03 * h), p.secondary)
    b.hull([(-0.3 * w, y1, stand), (0.3 * w, y1, stand), (-0.3 * w, y1, stand + 0.03 * h), (0.3 * w, y1, stand + 0.03 * h),
            (-0.3 * w, d / 2, stand - 0.04 * h), (0.3 * w, d / 2, stand - 0.04 * h), (-0.3 * w, d / 2, stand - 0.03 * h),
            (0.3 * w, d / 2, stand - 0.03 * h)], p.secondary)  # landing board
    z = stand + 0.03 * h
    lid = 0.1 * h
    box_h = (h - lid - z) / p.boxes
    for k in range(p.boxes):
        col = p.primary if k % 2 == 0 else lighter(p.primary, 0.2)
        b.box((-0.42 * w, y0, z), (0.42 * w, y1, z + box_h - 0.005), col)
        for x0, x1 in ((-0.43 * w, -0.42 * w), (0.42 * w, 0.43 * w)):
            b.box((x0, -0.1 * d, z + 0.55 * box_h), (x1, 0.1 * d, z + 0.7 * box_h), tint("#5a4a3a", "paint"))
        z += box_h
    b.box((-0.25 * w, y1, stand + 0.035 * h), (0.25 * w, y1 + 0.004, stand + 0.05 * h), tint("#2a2018", "paint"))  # entrance
    b.box((-w / 2, -d / 2, z), (w / 2, d / 2, z + 0.7 * lid), p.primary)
    b.box((-w / 2, -d / 2, z + 0.7 * lid), (w / 2, d / 2, h), p.accent)
    b.cbox((0, y0 - 0.005, z - 0.5 * box_h), (0.1 * w, 0.01, 0.03 * h), tint("#5a4a3a", "paint"))
    for _ in range(6):  # bees by the entrance
        c = (rng.uniform(-0.3, 0.3) * w, d / 2 - rng.uniform(0, 0.15) * d, stand + rng.uniform(0.05, 0.2) * h)
        b.sphere(c, (0.012, 0.008, 0.008), tint("#e0b030", "paint"), subdivisions=0)
        b.sphere((c[0] + 0.01, c[1], c[2]), 0.006, BLACK, subdivisions=0)
    return b.mesh(p.size)


# ----------------------------------------------------------------- chicken coop
def sample_chicken_coop(rng, size, style):
    return make_params("chicken_coop", rng, size, style, ["#a0472e", "#c9a77c", "#6b8a5a", "#e8e6e0", "#8a5a3a"],
                       ["#5c3b26", "#3a3b3e", "#7a3a2a"], "#f4f1ea", hens=int(rng.integers(1, 4)))


def build_chicken_coop(p):
    """A chicken coop: a henhouse on legs with a gable roof, a nesting box on the side and
    a ramp down from its little door, and a wire run beside it with hens in it."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    hx0, hx1 = -w / 2, -w / 2 + 0.48 * w
    fz = 0.38 * h
    eave = 0.75 * h
    for x in (hx0 + 0.03, hx1 - 0.06):
        for y in (-d / 2 + 0.03, d / 2 - 0.06):
            b.box((x, y, 0), (x + 0.05, y + 0.05, fz), p.secondary)
    b.box((hx0, -d / 2 + 0.02, fz), (hx1, d / 2 - 0.02, eave), p.primary)
    for k in range(1, 6):  # siding
        z = fz + k * (eave - fz) / 6
        b.box((hx0 - 0.003, -d / 2 + 0.017, z), (hx1 + 0.003, d / 2 - 0.017, z + 0.006), darker(p.primary, 0.15))
    dx = (hx0 + hx1) / 2
    b.box((dx - 0.1, d / 2 - 0.02, fz + 0.02), (dx + 0.1, d / 2 - 0.01, fz + 0.25), tint("#2a2018", "paint"))  # pop door
    b.hull([(dx - 0.1, d / 2 - 0.01, fz), (dx + 0.1, d / 2 - 0.01, fz), (dx - 0.1, d / 2 - 0.01, fz - 0.02),
            (dx + 0.1, d / 2 - 0.01, fz - 0.02), (dx - 0.1, d / 2 + 0.0, 0.0), (dx + 0.1, d / 2, 0.0),
            (dx - 0.1, d / 2 - 0.02, 0.0), (dx + 0.1, d / 2 - 0.02, 0.0)], p.secondary)  # ramp
    b.box((hx0 + 0.1 * w, -d / 2, fz + 0.1 * h), (hx1 - 0.1 * w, -d / 2 + 0.02, eave - 0.1 * h), darker(p.primary, 0.1))
    b.box((hx0 + 0.05 * w, d / 2 - 0.02, eave - 0.12 * h), (hx0 + 0.12 * w, d / 2, eave - 0.05 * h), tint("#9ac4e0", "glass"))
    ridge = h
    extrude_x(b, [(-d / 2 + 0.02, eave), (d / 2 - 0.02, eave), (0.0, ridge - 0.03 * h)], hx0, hx1, p.primary)
    for s in (-1, 1):
        b.hull([(hx0 - 0.03, s * d / 2, eave - 0.03 * h), (hx1 + 0.03, s * d / 2, eave - 0.03 * h),
                (hx0 - 0.03, 0, ridge - 0.02 * h), (hx1 + 0.03, 0, ridge - 0.02 * h), (hx0 - 0.03, 0, ridge),
                (hx1 + 0.03, 0, ridge), (hx0 - 0.03, s * d / 2, eave - 0.01 * h), (hx1 + 0.03, s * d / 2, eave - 0.01 * h)],
               p.secondary)
    rx0, rx1 = hx1, w / 2  # the run
    rt = 0.04
    run_h = 0.7 * h
    for x in (rx0 + 0.02, rx1 - rt):
        for y in (-d / 2 + 0.02, d / 2 - rt):
            b.box((x, y, 0), (x + rt, y + rt, run_h), p.secondary)
    for z in (0.0, run_h - rt):
        b.box((rx0, -d / 2 + 0.02, z), (rx1, -d / 2 + 0.02 + rt, z + rt), p.secondary)
        b.box((rx0, d / 2 - rt, z), (rx1, d / 2, z + rt), p.secondary)
        b.box((rx1 - rt, -d / 2, z), (rx1, d / 2, z + rt), p.secondary)
    for lo, hi in (((rx0, d / 2 - 0.01), (rx1, d / 2 - 0.005)), ((rx1 - 0.01, -d / 2 + 0.02), (rx1 - 0.005, d / 2)),
                   ((rx0, -d / 2 + 0.02), (rx1, -d / 2 + 0.025))):  # wire mesh
        b.box((lo[0], lo[1], rt), (hi[0], hi[1], run_h - rt), tint("#9a9da3", "metal"), alpha=90)
    b.box((rx0, -d / 2 + 0.02, run_h - 0.01), (rx1, d / 2, run_h), tint("#9a9da3", "metal"), alpha=90)
    for k in range(p.hens):
        cx = rx0 + (k + 0.6) * (rx1 - rx0) / (p.hens + 0.5)
        cy = rng.uniform(-0.2, 0.2) * d
        col = ["#f4f1ea", "#a0643c", "#2b2b2b"][int(rng.integers(3))]
        b.sphere((cx, cy, 0.12), (0.14, 0.09, 0.1), col, subdivisions=1, role="paint")
        b.sphere((cx + 0.12, cy, 0.24), 0.055, col, subdivisions=1, role="paint")
        b.sphere((cx + 0.12, cy, 0.3), (0.03, 0.01, 0.025), tint("#d63a2a", "paint"), subdivisions=0)
        b.cyl(cx + 0.18, cy, 0.23, 0.245, 0.02, tint("#e0b030", "paint"), r_top=0.0, sections=6, transform=about(rot_y(1.4),
                                                                                                  (cx + 0.18, cy, 0.24)))
        b.box((cx - 0.2, cy - 0.04, 0.14), (cx - 0.1, cy + 0.04, 0.24), col, role="paint")  # tail
    return b.mesh(p.size)


# ----------------------------------------------------------------- lawn mower
def sample_lawn_mower(rng, size, style):
    w, d, h = size
    return make_params("lawn_mower", rng, size, style, MOWER, [BLACK, "#2b2b2b"], ["#3a5a3a", "#2b2b2b", "#5f6b7a"],
                       bag=bool(rng.random() < 0.7), kind="ride_on" if w > 0.85 and d > 1.2 else "push")


def build_lawn_mower(p):
    """A push mower (the deck at the front with four wheels, the engine on top, a grass
    bag at the back and the handle rising over it) or a ride-on mower."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "ride_on":
        R = 0.2 * h
        for y, r in ((-0.3 * d, R), (0.32 * d, 0.7 * R)):
            for s in (-1, 1):
                wheel_x(b, s * (w / 2 - 0.06 * w), y, r, r, 0.12 * w, tint(BLACK, "rubber"), tint("#e0b030", "paint"))
        b.box((-0.38 * w, -0.45 * d, 0.15 * h), (0.38 * w, 0.45 * d, 0.35 * h), p.primary)
        b.box((-0.45 * w, -0.05 * d, 0.05 * h), (0.45 * w, 0.3 * d, 0.15 * h), DARK_METAL)  # deck
        b.hull([(-0.35 * w, 0.05 * d, 0.35 * h), (0.35 * w, 0.05 * d, 0.35 * h), (-0.35 * w, 0.48 * d, 0.35 * h),
                (0.35 * w, 0.48 * d, 0.35 * h), (-0.3 * w, 0.1 * d, 0.55 * h), (0.3 * w, 0.1 * d, 0.55 * h),
                (-0.3 * w, 0.45 * d, 0.45 * h), (0.3 * w, 0.45 * d, 0.45 * h)], p.primary)  # hood
        b.box((-0.3 * w, -0.35 * d, 0.35 * h), (0.3 * w, -0.1 * d, 0.45 * h), p.secondary)  # seat
        b.box((-0.3 * w, -0.38 * d, 0.45 * h), (0.3 * w, -0.32 * d, 0.7 * h), p.secondary)
        b.rod((0, 0.1 * d, 0.5 * h), (0, 0.0, 0.8 * h), 0.02, BLACK, sections=6)
        b.torus((0, -0.02 * d, 0.82 * h), 0.12, 0.015, BLACK, sections=16, minor_sections=4)
        return b.mesh(p.size)
    deck_y0, deck_y1 = 0.0, d / 2
    R = 0.12 * h
    for y in (deck_y0 + 0.05 * d, deck_y1 - 0.05 * d):
        for s in (-1, 1):
            wheel_x(b, s * (w / 2 - 0.04 * w), y, R, R, 0.08 * w, tint(BLACK, "rubber"), METAL)
    b.hull([(-0.44 * w, deck_y0, 0.06 * h), (0.44 * w, deck_y0, 0.06 * h), (-0.44 * w, deck_y1 - 0.02, 0.06 * h),
            (0.44 * w, deck_y1 - 0.02, 0.06 * h), (-0.4 * w, deck_y0 + 0.02, 0.24 * h), (0.4 * w, deck_y0 + 0.02, 0.24 * h),
            (-0.4 * w, deck_y1 - 0.06, 0.22 * h), (0.4 * w, deck_y1 - 0.06, 0.22 * h)], p.primary)  # deck
    ey = (deck_y0 + deck_y1) / 2
    b.cyl(0, ey, 0.24 * h, 0.34 * h, 0.3 * w, DARK_METAL, sections=14)  # engine
    b.cyl(0, ey, 0.34 * h, 0.4 * h, 0.24 * w, p.primary, r_top=0.18 * w, sections=14)
    b.box((0.12 * w, ey - 0.05 * d, 0.3 * h), (0.32 * w, ey + 0.06 * d, 0.4 * h), BLACK)  # air filter
    b.cyl(-0.15 * w, ey + 0.06 * d, 0.38 * h, 0.43 * h, 0.04 * w, BLACK, sections=8)  # fuel cap
    hy = -d / 2 + 0.04 * d
    for s in (-1, 1):  # handle
        b.rod((s * 0.4 * w, deck_y0 + 0.02, 0.2 * h), (s * 0.38 * w, hy, h - 0.02 * h), 0.012, p.secondary, sections=6)
    b.rod((-0.38 * w, hy, h - 0.02 * h), (0.38 * w, hy, h - 0.02 * h), 0.015, p.secondary, sections=8)
    b.rod((-0.34 * w, hy + 0.05 * d, h - 0.08 * h), (0.34 * w, hy + 0.05 * d, h - 0.08 * h), 0.008, tint("#c9ccd0", "metal"),
          sections=6)  # bail lever
    b.rod((-0.1 * w, ey, 0.36 * h), (-0.3 * w, hy + 0.2 * d, 0.6 * h), 0.004, tint("#c9ccd0", "metal"), sections=4)  # pull cord
    if p.bag:
        b.hull([(-0.35 * w, deck_y0, 0.1 * h), (0.35 * w, deck_y0, 0.1 * h), (-0.35 * w, deck_y0, 0.4 * h),
                (0.35 * w, deck_y0, 0.4 * h), (-0.38 * w, -0.35 * d, 0.12 * h), (0.38 * w, -0.35 * d, 0.12 * h),
                (-0.38 * w, -0.33 * d, 0.48 * h), (0.38 * w, -0.33 * d, 0.48 * h)], p.accent)
        b.box((-0.36 * w, -0.36 * d, 0.46 * h), (0.36 * w, -0.3 * d, 0.5 * h), BLACK)
    return b.mesh(p.size)


# ----------------------------------------------------------------- wheelbarrow
def sample_wheelbarrow(rng, size, style):
    return make_params("wheelbarrow", rng, size, style, ["#3f8a4a", "#c0392b", "#2d6fb0", "#9a9da3", "#e0b030"],
                       wood_tones("rustic")[:2] + [BLACK], ["#6b4a30", "#8a7a6a", "#4a6a3a"], load=bool(rng.random() < 0.4))


def build_wheelbarrow(p):
    """A wheelbarrow along y: the wheel at the front, the deep tray on the frame, two legs
    at the back and long handles with grips."""
    w, d, h = p.size
    b = Builder()
    R = 0.28 * h
    wy = d / 2 - R
    wheel_x(b, 0, wy, R, R, 0.1 * w, tint(BLACK, "rubber"), METAL, spokes=0)
    tz0, tz1 = 0.35 * h, h
    pts = [(-0.2 * w, -0.05 * d, tz0), (0.2 * w, -0.05 * d, tz0), (-0.2 * w, 0.25 * d, tz0), (0.2 * w, 0.25 * d, tz0),
           (-w / 2, -0.28 * d, tz1), (w / 2, -0.28 * d, tz1), (-0.35 * w, 0.42 * d, tz1), (0.35 * w, 0.42 * d, tz1)]
    b.hull(pts, p.primary)
    inner = [(x * 0.9, y * 0.92 + 0.0, tz1 - 0.005) for x, y, _ in pts[4:]]
    b.hull(inner + [(x * 0.9, y * 0.92, tz1 - 0.004) for x, y, _ in pts[4:]] +
           [(0.0, 0.08 * d, tz1 - 0.005), (0.0, 0.08 * d, tz1 - 0.004)], darker(p.primary, 0.45))
    if p.load:
        b.sphere((0, 0.05 * d, tz1), (0.34 * w, 0.26 * d, 0.1 * h), p.accent, subdivisions=1)
    for s in (-1, 1):
        x = s * 0.22 * w
        b.rod((s * 0.04 * w, wy, R), (x, -0.1 * d, tz0 - 0.02 * h), 0.018, p.secondary, sections=6)
        b.rod((x, -0.1 * d, tz0 - 0.02 * h), (s * 0.3 * w, -d / 2 + 0.03 * d, 0.62 * h), 0.018, p.secondary,
              sections=6)
        b.rod((s * 0.3 * w, -d / 2 + 0.12 * d, 0.6 * h), (s * 0.31 * w, -d / 2, 0.64 * h), 0.025, BLACK, sections=8)
        b.rod((x, -0.12 * d, tz0 - 0.02 * h), (x, -0.18 * d, 0.0), 0.015, p.secondary, sections=6)  # leg
    disc_x(b, -0.05 * w, 0.05 * w, wy, R, 0.02, METAL, sections=6)
    return b.mesh(p.size)


slot_roles("pergola", "wood", "plant", "fabric")
register("pergola", sample_pergola, build_pergola)
slot_roles("sun_lounger", {"": "wood", "#9a9da3": "metal"}, "fabric", "fabric")
register("sun_lounger", sample_sun_lounger, build_sun_lounger)
slot_roles("surfboard", "plastic", "plastic", "plastic")
register("surfboard", sample_surfboard, build_surfboard)
slot_roles("beehive", "wood", "wood", "metal")
register("beehive", sample_beehive, build_beehive)
slot_roles("chicken_coop", "wood", "wood", "fabric")
register("chicken_coop", sample_chicken_coop, build_chicken_coop)
slot_roles("lawn_mower", "paint", "plastic", "plastic")
register("lawn_mower", sample_lawn_mower, build_lawn_mower)
slot_roles("wheelbarrow", "metal", "wood", "metal")
register("wheelbarrow", sample_wheelbarrow, build_wheelbarrow)
