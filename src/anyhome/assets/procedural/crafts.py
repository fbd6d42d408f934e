"""Crafts and trades: kiln, forge, anvil, pottery_wheel, printing_press, loom,
spinning_wheel, pegboard."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    GLOW_RED,
    SCREEN,
    STEEL,
    arc,
    disc_x,
    disc_y,
    extrude_y,
    path,
    ring_y,
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
    rot_y,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

BRICK = tint(["#a0472e", "#8a3a28", "#b0583a"], "stone")
FIREBRICK = tint("#d9c3a0", "stone")
EMBER = tint(["#ff7a1a", "#e8402a", "#ffb030", "#c0301a"], "light")
CLAY = tint(["#b5754a", "#a0643c", "#9a8a7a", "#c98a5a"], "ceramic")
YARNS = tint(["#c0392b", "#2e4a8b", "#d9a32a", "#3f6b4a", "#8e44ad", "#e8e6e0", "#d35400", "#5f6b7a"], "fabric")
TOOL_HANDLES = tint(["#c0392b", "#f1c40f", "#2e86c1", BLACK, "#27ae60", "#e67e22"], "plastic")


# ----------------------------------------------------------------- kiln
def sample_kiln(rng, size, style):
    brick = style_is(style, "antique", "rustic") and rng.random() < 0.7
    return make_params("kiln", rng, size, style, [STEEL, "#9a9da3", "#c9ccd0"] if not brick else BRICK,
                       [DARK_METAL, BLACK], EMBER[0], kind="brick" if brick else "electric")


def build_kiln(p):
    """An electric kiln (an octagonal steel drum on a stand with banding, a lid and a
    control box) or a brick kiln with an arched glowing door and a chimney."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "brick":
        top = 0.72 * h
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.02, top), p.primary)
        for k in range(int(max(2, top / 0.09))):
            z = (k + 1) * top / int(max(2, top / 0.09) + 1)
            b.box((-w / 2 - 0.002, -d / 2 - 0.002, z), (w / 2 + 0.002, d / 2 - 0.018, z + 0.008), FIREBRICK)
        for x in (-w / 2, w / 2 - 0.04):
            b.box((x, d / 2 - 0.04, 0), (x + 0.04, d / 2, top), p.secondary)
        b.hull([(-w / 2, -d / 2, top), (w / 2, -d / 2, top), (-w / 2, d / 2 - 0.02, top), (w / 2, d / 2 - 0.02, top),
                (-0.15 * w, -0.1 * d, top + 0.12 * h), (0.15 * w, -0.1 * d, top + 0.12 * h),
                (-0.15 * w, 0.1 * d, top + 0.12 * h), (0.15 * w, 0.1 * d, top + 0.12 * h)], darker(p.primary, 0.15))
        b.box((-0.1 * w, -0.1 * d, top), (0.1 * w, 0.08 * d, h), p.primary)  # chimney
        r = 0.3 * w
        zs = 0.12 * h
        prof = [(-r, zs), (r, zs), (r, zs + 0.3 * top)] + arc(0, zs + 0.3 * top, r, 0, np.pi, 10)[1:-1] + \
            [(-r, zs + 0.3 * top)]
        extrude_y(b, [(x, min(z, top - 0.05 * h)) for x, z in prof], d / 2 - 0.021, d / 2 - 0.01, tint("#3a1a10", "paint"))
        inner = [(x * 0.75, zs + (z - zs) * 0.75) for x, z in prof]
        extrude_y(b, inner, d / 2 - 0.012, d / 2 - 0.006, p.accent)
        return b.mesh(p.size)
    R = 0.45 * min(w, d)
    leg = 0.16 * h
    for a in (np.pi / 4, 3 * np.pi / 4, 5 * np.pi / 4, 7 * np.pi / 4):
        b.box((0.7 * R * np.cos(a) - 0.02, 0.7 * R * np.sin(a) - 0.02, 0), (0.7 * R * np.cos(a) + 0.02,
                                                                            0.7 * R * np.sin(a) + 0.02, leg),
              p.secondary)
    b.cyl(0, -0.05 * d, leg - 0.02 * h, leg, 0.95 * R, p.secondary, sections=8)
    top = 0.86 * h
    b.cyl(0, -0.05 * d, leg, top, R, p.primary, sections=8)
    for z in np.linspace(leg + 0.08 * h, top - 0.06 * h, 4):
        b.cyl(0, -0.05 * d, z, z + 0.012, R * 1.02, darker(p.primary, 0.15), sections=8)
    b.cyl(0, -0.05 * d, top, top + 0.02 * h, 1.04 * R, darker(p.primary, 0.3), sections=8)  # lid rim
    b.cyl(0, -0.05 * d, top + 0.02 * h, h - 0.02 * h, 1.02 * R, p.primary, r_top=0.98 * R, sections=8)
    b.box((-0.15 * R, 0.9 * R - 0.05 * d, h - 0.05 * h), (0.15 * R, 1.1 * R - 0.05 * d, h), p.secondary)
    b.cyl(0, -0.05 * d, h - 0.02 * h, h, 0.08 * R, BLACK, sections=8)  # vent plug
    cy = -0.05 * d + R * 0.93
    b.box((-0.28 * R, cy, 0.45 * h), (0.28 * R, d / 2, 0.7 * h), p.secondary)  # controller
    b.box((-0.2 * R, d / 2, 0.6 * h), (0.2 * R, d / 2 + 0.002, 0.67 * h), SCREEN)
    b.box((-0.12 * R, d / 2 + 0.001, 0.63 * h), (0.05 * R, d / 2 + 0.003, 0.65 * h), GLOW_RED)
    for z in (0.33 * h, 0.75 * h):
        disc_y(b, 0.45 * R, cy - 0.03, cy + 0.02, z, 0.04 * R + 0.01, BLACK, sections=8)  # peepholes
    return b.mesh(p.size)


# ----------------------------------------------------------------- forge
def sample_forge(rng, size, style):
    return make_params("forge", rng, size, style, [DARK_METAL, "#3a3b3e", "#4a3a30"] + BRICK[:1], BLACK, EMBER,
                       blower=bool(rng.random() < 0.6))


def build_forge(p):
    """A blacksmith's coal forge: a hearth table with glowing coals in the firepot, the
    smoke hood above it and its chimney, and a hand-cranked blower at the side."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    tz = 0.52 * h
    for x in (-0.42 * w, 0.42 * w):
        for y in (-0.38 * d, 0.38 * d):
            b.box((x - 0.03, y - 0.03, 0), (x + 0.03, y + 0.03, tz - 0.08 * h), p.primary)
    b.box((-0.45 * w, -0.4 * d, 0.12 * h), (0.45 * w, 0.4 * d, 0.14 * h), p.primary)  # shelf
    b.box((-w / 2, -d / 2 + 0.1 * d, tz - 0.08 * h), (w / 2, d / 2, tz), p.primary)
    b.box((-w / 2 + 0.04, -d / 2 + 0.14 * d, tz), (w / 2 - 0.04, d / 2 - 0.04, tz + 0.01), tint("#2a2522", "paint"))
    for sx in (-1, 1):
        b.box((sx * w / 2 - (0.04 if sx > 0 else 0), -d / 2 + 0.1 * d, tz), (sx * w / 2 + (0.04 if sx < 0 else 0),
                                                                            d / 2, tz + 0.05 * h), p.primary)
    b.box((-w / 2, d / 2 - 0.04, tz), (w / 2, d / 2, tz + 0.05 * h), p.primary)
    cx, cy, cr = 0.0, 0.1 * d, 0.22 * min(w, d)
    for _ in range(36):  # coals heaped in the firepot
        a, r = rng.uniform(0, 2 * np.pi), cr * np.sqrt(rng.random())
        z = tz + 0.01 + 0.06 * h * (1 - r / cr) * rng.uniform(0.5, 1)
        col = EMBER[int(rng.integers(len(EMBER)))] if r < 0.75 * cr else "#2a2522"
        b.sphere((cx + r * np.cos(a), cy + r * np.sin(a), z), 0.03 + 0.02 * rng.random(), col, subdivisions=0, role="light")
    hz0, hz1 = 0.72 * h, 0.86 * h
    b.hull([(-0.45 * w, -0.45 * d, hz0), (0.45 * w, -0.45 * d, hz0), (-0.45 * w, 0.35 * d, hz0),
            (0.45 * w, 0.35 * d, hz0), (-0.12 * w, -0.3 * d, hz1), (0.12 * w, -0.3 * d, hz1),
            (-0.12 * w, -0.05 * d, hz1), (0.12 * w, -0.05 * d, hz1)], p.secondary)
    b.cyl(0, -0.18 * d, hz1 - 0.01, h, 0.1 * w, p.secondary, sections=12)  # chimney
    for x in (-0.44 * w, 0.44 * w):
        b.box((x - 0.015, -0.44 * d, tz), (x + 0.015, -0.41 * d, hz0), p.secondary)
    if p.blower:
        bx = w / 2 - 0.08 * w
        disc_x(b, bx - 0.04, bx + 0.04, -0.3 * d, tz - 0.18 * h, 0.12 * h, DARK_METAL, sections=16)
        b.rod((bx + 0.04, -0.3 * d, tz - 0.18 * h), (bx + 0.06, -0.3 * d + 0.1 * h, tz - 0.1 * h), 0.01, METAL)
        b.rod((bx, -0.3 * d, tz - 0.1 * h), (0.1 * w, cy - 0.1 * d, tz - 0.04 * h), 0.03, DARK_METAL, sections=8)
    b.rod((-0.46 * w, d / 2 - 0.05, tz + 0.04 * h), (-0.2 * w, 0.15 * d, tz + 0.05), 0.008, METAL, sections=5)  # tongs
    b.rod((-0.46 * w, d / 2 - 0.07, tz + 0.04 * h), (-0.19 * w, 0.12 * d, tz + 0.05), 0.008, METAL, sections=5)
    return b.mesh(p.size)


# ----------------------------------------------------------------- anvil
def sample_anvil(rng, size, style):
    return make_params("anvil", rng, size, style, [DARK_METAL, "#2b2b2b", "#4a4c50"], wood_tones("rustic"),
                       METAL, stump=bool(rng.random() < 0.85))


def _draw_anvil(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the horn at +x, the heel at -x, on a banded wooden stump."""
    z0 = 0.5 * H if p.stump else 0.0
    if p.stump:
        R = min(0.48 * B, 0.3 * L)
        b.cyl(0, 0, 0, z0, R, p.secondary, sections=16)
        for z in (0.1 * z0, 0.85 * z0):
            b.cyl(0, 0, z, z + 0.03, 1.02 * R, DARK_METAL, sections=16)
        b.cyl(0, 0, z0 - 0.005, z0, 0.95 * R, lighter(p.secondary, 0.2), sections=16)
    ah = H - z0
    wB = 0.62 * B
    b.hull([(-0.3 * L, -wB / 2, z0), (0.25 * L, -wB / 2, z0), (-0.3 * L, wB / 2, z0), (0.25 * L, wB / 2, z0),
            (-0.2 * L, -0.3 * wB, z0 + 0.22 * ah), (0.15 * L, -0.3 * wB, z0 + 0.22 * ah),
            (-0.2 * L, 0.3 * wB, z0 + 0.22 * ah), (0.15 * L, 0.3 * wB, z0 + 0.22 * ah)], p.primary)  # feet
    b.box((-0.16 * L, -0.22 * wB, z0 + 0.2 * ah), (0.12 * L, 0.22 * wB, z0 + 0.6 * ah), p.primary)  # waist
    b.hull([(-0.2 * L, -0.22 * wB, z0 + 0.58 * ah), (0.15 * L, -0.22 * wB, z0 + 0.58 * ah),
            (-0.2 * L, 0.22 * wB, z0 + 0.58 * ah), (0.15 * L, 0.22 * wB, z0 + 0.58 * ah),
            (-0.35 * L, -0.35 * wB, z0 + 0.72 * ah), (0.22 * L, -0.35 * wB, z0 + 0.72 * ah),
            (-0.35 * L, 0.35 * wB, z0 + 0.72 * ah), (0.22 * L, 0.35 * wB, z0 + 0.72 * ah)], p.primary)
    b.box((-L / 2, -0.35 * wB, z0 + 0.72 * ah), (0.22 * L, 0.35 * wB, H - 0.02 * ah), p.primary)  # body & heel
    b.box((-L / 2, -0.35 * wB, H - 0.02 * ah), (0.18 * L, 0.35 * wB, H), p.accent)  # face
    b.box((-0.42 * L, -0.06 * wB, H), (-0.38 * L, 0.06 * wB, H + 0.001), BLACK)  # hardy hole
    pts = []
    for t in np.linspace(0, 1, 6):  # the horn: a cone drooping to a point
        x = 0.22 * L + t * 0.28 * L
        r = 0.33 * wB * (1 - t) + 0.01
        zc = H - 0.25 * ah - t * 0.15 * ah
        rz = 0.25 * ah * (1 - t) + 0.01
        for a in np.linspace(0, 2 * np.pi, 10, endpoint=False):
            pts.append((x, r * np.cos(a), min(H, zc + rz * np.sin(a))))
    b.hull(pts, p.primary)


def build_anvil(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_anvil(b, L, B, H, p))


# ----------------------------------------------------------------- pottery wheel
def sample_pottery_wheel(rng, size, style):
    return make_params("pottery_wheel", rng, size, style, ["#d9dadc", "#5f7fa0", "#3a3b3e", "#e8e6e0", "#6f8f7a"],
                       CLAY, wood_tones(style), seat=bool(rng.random() < 0.7))


def build_pottery_wheel(p):
    """A potter's wheel: body with a splash pan around the turning wheel head and a pot
    of wet clay on it, a foot pedal, and a low stool at the back."""
    w, d, h = p.size
    b = Builder()
    cy = 0.12 * d if p.seat else 0.0
    R = min(0.45 * w, 0.3 * d)
    top = 0.62 * h
    b.box((-0.35 * w, cy - 0.55 * R, 0.06 * h), (0.35 * w, cy + 0.55 * R, top - 0.1 * h), p.primary)
    for x in (-0.3 * w, 0.3 * w):
        for y in (cy - 0.45 * R, cy + 0.45 * R):
            b.cyl(x, y, 0, 0.06 * h, 0.02, BLACK, sections=6)
    b.lathe([[0.6 * R, top - 0.1 * h], [R, top - 0.1 * h], [R, top], [0.94 * R, top], [0.94 * R, top - 0.07 * h],
             [0.6 * R, top - 0.07 * h]], lighter(p.primary, 0.15), x=0, y=cy, sections=28)  # splash pan
    b.cyl(0, cy, top - 0.1 * h, top - 0.02 * h, 0.12 * R, DARK_METAL, sections=10)
    b.cyl(0, cy, top - 0.03 * h, top - 0.005 * h, 0.62 * R, CHROME, sections=24)  # wheel head
    ph = h - top
    b.lathe([[0, top - 0.005 * h], [0.35 * R, top - 0.005 * h], [0.42 * R, top + 0.3 * ph], [0.3 * R, top + 0.7 * ph],
             [0.34 * R, h], [0.3 * R, h], [0.24 * R, top + 0.7 * ph], [0.3 * R, top + 0.35 * ph],
             [0, top + 0.1 * ph]], p.secondary, x=0, y=cy, sections=20)
    b.hull([(0.3 * w, cy + 0.6 * R, 0), (0.45 * w, cy + 0.6 * R, 0), (0.3 * w, cy + 0.95 * R, 0),
            (0.45 * w, cy + 0.95 * R, 0), (0.3 * w, cy + 0.6 * R, 0.08 * h), (0.45 * w, cy + 0.6 * R, 0.08 * h)],
           BLACK)  # pedal
    b.box((-0.5 * w, cy - 0.3 * R, top - 0.12 * h), (-0.35 * w, cy + 0.3 * R, top - 0.1 * h), p.primary)  # tray
    if p.seat:
        sy = -d / 2 + 0.15 * d
        sr = min(0.15 * d, 0.35 * w)
        b.cyl(0, sy, 0.42 * h, 0.5 * h, sr, p.accent, sections=16)
        for a in (0.3, 2.4, 4.5):
            b.rod((0.7 * sr * np.cos(a), sy + 0.7 * sr * np.sin(a), 0.42 * h),
                  (0.95 * sr * np.cos(a), sy + 0.95 * sr * np.sin(a), 0), 0.015, p.accent, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- printing press
def sample_printing_press(rng, size, style):
    iron = style_is(style, "modern") or rng.random() < 0.3
    return make_params("printing_press", rng, size, style, wood_tones("antique") if not iron else
                       [DARK_METAL, "#2b2b2b", "#3a4a3a"], [DARK_METAL, BLACK], ["#f4f1e6", "#e8dcc0"],
                       kind="iron" if iron else "wooden")


def _draw_press(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the frame across the middle, the bed running through it on its rails, the
    tympan raised at +x and the bar of the screw sticking out to the front."""
    post = 0.06 * L
    for y in (-0.42 * B, 0.42 * B):  # cheeks
        b.box((-post, y - 0.05 * B, 0), (post, y + 0.05 * B, H - 0.06 * H), p.primary)
        b.box((-1.6 * post, y - 0.1 * B, 0), (1.6 * post, y + 0.1 * B, 0.06 * H), p.primary)
    b.box((-1.3 * post, -0.5 * B, H - 0.16 * H), (1.3 * post, 0.5 * B, H), p.primary)  # head
    b.box((-post, -0.47 * B, 0.62 * H), (post, 0.47 * B, 0.68 * H), p.primary)  # winter
    rail_z = 0.42 * H
    for y in (-0.22 * B, 0.22 * B):  # ribs
        b.box((-L / 2, y - 0.04 * B, rail_z - 0.05 * H), (L / 2, y + 0.04 * B, rail_z), p.primary)
    for x in (-L / 2 + 0.03 * L, L / 2 - 0.03 * L):
        for y in (-0.22 * B, 0.22 * B):
            b.box((x - 0.02 * L, y - 0.04 * B, 0), (x + 0.02 * L, y + 0.04 * B, rail_z - 0.05 * H), p.primary)
    b.box((-0.35 * L, -0.3 * B, rail_z), (0.1 * L, 0.3 * B, rail_z + 0.05 * H), darker(p.primary, 0.2))  # coffin
    b.box((-0.33 * L, -0.27 * B, rail_z + 0.05 * H), (0.08 * L, 0.27 * B, rail_z + 0.06 * H), tint("#2a2522", "paint"))  # forme
    hinge = (0.1 * L, 0, rail_z + 0.05 * H)
    tilt = about(rot_y(0.75), hinge)  # tympan swung up at +x
    b.box((0.1 * L, -0.28 * B, rail_z + 0.04 * H), (0.42 * L, 0.28 * B, rail_z + 0.06 * H), p.accent,
          transform=tilt)
    b.box((0.1 * L, -0.3 * B, rail_z + 0.035 * H), (0.43 * L, -0.26 * B, rail_z + 0.065 * H), p.primary,
          transform=tilt)
    b.box((0.1 * L, 0.26 * B, rail_z + 0.035 * H), (0.43 * L, 0.3 * B, rail_z + 0.065 * H), p.primary,
          transform=tilt)
    plat = 0.55 * H
    b.box((-1.2 * post, -0.3 * B, plat - 0.05 * H), (1.2 * post, 0.3 * B, plat), p.secondary)  # platen
    b.cyl(0, 0, plat, H - 0.16 * H, 0.03 * L, p.secondary, sections=12)  # screw
    for k in range(5):
        z = plat + 0.05 * H + k * 0.04 * H
        b.cyl(0, 0, z, z + 0.015 * H, 0.036 * L, darker(p.secondary, 0.3), sections=12)
    b.rod((0, 0, 0.72 * H), (0.12 * L, 0.62 * B, 0.74 * H), 0.012 * L, p.secondary, sections=8)  # the bar
    b.rod((0.12 * L, 0.62 * B, 0.74 * H), (0.13 * L, 0.66 * B, 0.74 * H), 0.016 * L, p.primary, sections=8)
    if p.kind == "iron":
        disc_y(b, -0.45 * L, 0.3 * B, 0.36 * B, rail_z, 0.12 * H, p.secondary, sections=16)  # rounce wheel


def build_printing_press(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_press(b, L, B, H, p))


# ----------------------------------------------------------------- loom
def sample_loom(rng, size, style):
    return make_params("loom", rng, size, style, wood_tones(style), "#efe6d0", YARNS,
                       harnesses=int(rng.integers(2, 5)))


def build_loom(p):
    """A floor loom: a frame with the breast beam at the front, the castle with its
    harness frames in the middle, cream warp threads running back to front, the woven
    cloth in stripes near the weaver, and treadles on the floor."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    wz = 0.62 * h
    t = min(0.04, 0.05 * w)
    for x in (-w / 2 + t, w / 2 - t):
        for y in (-d / 2 + t, d / 2 - t):
            b.box((x - t, y - t, 0), (x + t, y + t, wz + 0.03 * h), p.primary)
        b.box((x - t, -d / 2, 0.12 * h), (x + t, d / 2, 0.12 * h + 2 * t), p.primary)
        b.box((x - t, -d / 2, wz - 0.05 * h), (x + t, d / 2, wz - 0.05 * h + 2 * t), p.primary)
        b.box((x - t, -0.05 * d - t, wz), (x + t, -0.05 * d + t, h), p.primary)  # castle posts
    b.box((-w / 2, -0.05 * d - t, h - 2 * t), (w / 2, -0.05 * d + t, h), p.primary)
    for y in (-d / 2 + t, d / 2 - t):  # back and breast beams
        disc_x(b, -w / 2 + 2 * t, w / 2 - 2 * t, y, wz + 0.02 * h, 1.3 * t, lighter(p.primary, 0.1), sections=10)
    n = max(8, int((w - 4 * t) / 0.035))
    x0, x1 = -w / 2 + 3 * t, w / 2 - 3 * t
    for k in range(n):  # warp threads
        x = x0 + (k + 0.5) * (x1 - x0) / n
        b.box((x - 0.003, -d / 2 + t, wz + 0.02 * h + 1.2 * t), (x + 0.003, 0.2 * d, wz + 0.02 * h + 1.3 * t),
              p.secondary)
    cols = [YARNS[int(rng.integers(len(YARNS)))] for _ in range(3)]
    stripes = 7
    for k in range(stripes):  # woven cloth
        ya = 0.2 * d + k * (d / 2 - t - 0.2 * d) / stripes
        yb = 0.2 * d + (k + 1) * (d / 2 - t - 0.2 * d) / stripes
        b.box((x0, ya, wz + 0.02 * h + 1.1 * t), (x1, yb, wz + 0.02 * h + 1.4 * t), cols[k % 3])
    disc_x(b, x0, x1, d / 2 - 2.5 * t, 0.3 * h, 2.2 * t, cols[0], sections=12)  # cloth beam
    hz0, hz1 = wz - 0.05 * h, h - 0.12 * h
    for k in range(p.harnesses):  # harness frames hanging in the castle
        y = -0.1 * d + k * 0.035
        b.box((x0, y, hz1 - 0.02 * h), (x1, y + 0.015, hz1), lighter(p.primary, 0.15))
        b.box((x0, y, hz0 + 0.12 * h), (x1, y + 0.015, hz0 + 0.14 * h), lighter(p.primary, 0.15))
        for x in np.linspace(x0 + 0.02, x1 - 0.02, 12):
            b.box((x - 0.002, y + 0.005, hz0 + 0.14 * h), (x + 0.002, y + 0.01, hz1 - 0.02 * h), tint("#9a9da3", "metal"))
    by = 0.12 * d  # the beater
    for x in (x0 - t, x1 + t):
        b.box((x - t / 2, by - t / 2, 0.15 * h), (x + t / 2, by + t / 2, hz1 - 0.1 * h), p.primary)
    b.box((x0 - t, by - t, wz + 0.02 * h), (x1 + t, by + t, wz + 0.02 * h + 2 * t), p.primary)
    for k in range(4):  # treadles
        x = -0.2 * w + k * 0.13 * w
        b.box((x - 0.025, -0.3 * d, 0.01), (x + 0.025, 0.4 * d, 0.04), darker(p.primary, 0.15))
    return b.mesh(p.size)


# ----------------------------------------------------------------- spinning wheel
def sample_spinning_wheel(rng, size, style):
    return make_params("spinning_wheel", rng, size, style, wood_tones(style), "#efe6d0", wood_tones(style),
                       spokes=int(rng.choice([8, 10, 12])))


def _draw_spinning_wheel(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: the big wheel at -x on its uprights, the flyer and bobbin at +x, all on a
    slanted bench with three splayed legs and a treadle."""
    bench_z0, bench_z1 = 0.3 * H, 0.4 * H
    t = 0.025
    b.hull([(-0.45 * L, -0.3 * B, bench_z0), (0.45 * L, -0.3 * B, bench_z1), (-0.45 * L, 0.3 * B, bench_z0),
            (0.45 * L, 0.3 * B, bench_z1), (-0.45 * L, -0.3 * B, bench_z0 + 0.05), (0.45 * L, -0.3 * B, bench_z1 + 0.05),
            (-0.45 * L, 0.3 * B, bench_z0 + 0.05), (0.45 * L, 0.3 * B, bench_z1 + 0.05)], p.primary)
    for x, y in ((-0.38 * L, -0.2 * B), (-0.38 * L, 0.2 * B), (0.4 * L, 0.0)):
        zt = bench_z0 + (x + 0.45 * L) / (0.9 * L) * (bench_z1 - bench_z0)
        b.rod((x, y, zt), (x + np.sign(x) * 0.08 * L, y * 2.2, 0), 0.018, p.primary, sections=8)
    R = min(0.3 * H, 0.32 * L)
    cx, cz = -0.18 * L, H - R - 0.01
    for y in (-0.1 * B, 0.1 * B):
        b.box((cx - t, y - t / 2, bench_z0), (cx + t, y + t / 2, cz + 0.04), p.primary)
    ring_y(b, (cx, 0, cz), R * 0.96, 0.035 * R, p.accent, sections=32)
    ring_y(b, (cx, 0, cz), R * 0.99, 0.012, darker(p.accent, 0.3), sections=32)
    for k in range(p.spokes):
        a = 2 * np.pi * k / p.spokes
        b.rod((cx, 0, cz), (cx + 0.93 * R * np.cos(a), 0, cz + 0.93 * R * np.sin(a)), 0.008, p.accent, sections=5)
    disc_y(b, cx, -0.12 * B, 0.12 * B, cz, 0.07 * R, p.primary, sections=10)
    mx = 0.32 * L  # mother-of-all: a post, maidens and the flyer
    mz = bench_z1 - 0.02 + 0.1 * H
    b.box((mx - t, -t, bench_z1 - 0.02), (mx + t, t, mz), p.primary)
    b.box((mx - 0.12 * L, -t, mz), (mx + 0.08 * L, t, mz + 0.04), p.primary)
    fz = mz + 0.1 * H
    for x in (mx - 0.1 * L, mx + 0.06 * L):
        b.box((x - t / 2, -t / 2, mz + 0.04), (x + t / 2, t / 2, fz + 0.04), p.primary)
    b.rod((mx - 0.1 * L, 0, fz), (mx + 0.06 * L, 0, fz), 0.008, METAL, sections=6)
    disc_x(b, mx - 0.06 * L, mx + 0.02 * L, 0, fz, 0.045, p.secondary, sections=12)  # bobbin with yarn
    for s in (-1, 1):
        b.rod((mx - 0.08 * L, 0, fz), (mx - 0.08 * L, s * 0.06, fz + 0.03), 0.006, p.primary, sections=5)
        b.rod((mx - 0.08 * L, s * 0.06, fz + 0.03), (mx + 0.04 * L, s * 0.06, fz + 0.03), 0.006, p.primary,
              sections=5)
    b.rod((cx, 0, cz), (mx - 0.04 * L, 0, fz), 0.002, tint("#e8dcc0", "fabric"), sections=4)  # drive band
    b.rod((cx, 0, cz - R), (mx - 0.04 * L, 0, fz), 0.002, tint("#e8dcc0", "fabric"), sections=4)
    b.box((-0.3 * L, 0.1 * B, 0.02), (0.1 * L, 0.35 * B, 0.05), p.primary)  # treadle
    b.rod((-0.1 * L, 0.22 * B, 0.05), (cx + 0.1 * R, 0.12 * B, cz - 0.1 * R), 0.008, p.primary, sections=5)


def build_spinning_wheel(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_spinning_wheel(b, L, B, H, p))


# ----------------------------------------------------------------- pegboard
def sample_pegboard(rng, size, style):
    return make_params("pegboard", rng, size, style, ["#c9a77c", "#e8e6e0", "#5f6b7a", "#3f6b4a", "#2b2b2b"],
                       TOOL_HANDLES, METAL, spacing=float(rng.choice([0.05, 0.06, 0.075])))


def build_pegboard(p):
    """A perforated board on the wall with hand tools hanging from it: hammer, wrenches,
    screwdrivers, pliers, a saw and a tape measure."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    bt = 0.35 * d
    y0 = -d / 2
    fy = y0 + bt
    b.box((-w / 2, y0, 0), (w / 2, fy, h), p.primary)
    frame = min(0.03, 0.04 * w)
    for lo, hi in (((-w / 2, fy, 0), (w / 2, fy + 0.1 * d, frame)), ((-w / 2, fy, h - frame), (w / 2, fy + 0.1 * d, h)),
                   ((-w / 2, fy, 0), (-w / 2 + frame, fy + 0.1 * d, h)), ((w / 2 - frame, fy, 0), (w / 2, fy + 0.1 * d, h))):
        b.box(lo, hi, darker(p.primary, 0.2))
    s = max(p.spacing, w / 30, h / 30)
    hole = darker(p.primary, 0.55)
    for x in np.arange(-w / 2 + frame + s / 2, w / 2 - frame, s):
        for z in np.arange(frame + s / 2, h - frame, s):
            b.box((x - 0.004, fy, z - 0.004), (x + 0.004, fy + 0.002, z + 0.004), hole)
    ty = fy + 0.1 * d
    td = d / 2 - ty

    def handle() -> str:
        return TOOL_HANDLES[int(rng.integers(len(TOOL_HANDLES)))]

    slots = np.linspace(-w / 2 + 0.1 * w, w / 2 - 0.1 * w, 6)
    u = h / 0.9
    # hammer
    x = slots[0]
    b.box((x - 0.012 * u, ty, 0.25 * h), (x + 0.012 * u, ty + td * 0.6, 0.7 * h), handle())
    b.box((x - 0.06 * u, ty, 0.7 * h), (x + 0.06 * u, ty + td, 0.76 * h), p.accent)
    # wrenches, longest first
    x = slots[1]
    for k, ln in enumerate((0.32, 0.27, 0.22)):
        xx = x - 0.04 * u + k * 0.04 * u
        b.box((xx - 0.008 * u, ty, 0.75 * h - ln * h), (xx + 0.008 * u, ty + td * 0.5, 0.75 * h), p.accent)
        b.box((xx - 0.016 * u, ty, 0.75 * h), (xx + 0.016 * u, ty + td * 0.5, 0.79 * h), p.accent)
    # screwdrivers
    x = slots[2]
    for k in range(3):
        xx = x - 0.04 * u + k * 0.04 * u
        b.cyl(xx, ty + td * 0.5, 0.4 * h, 0.6 * h, 0.004 * u, p.accent, sections=6)
        b.cyl(xx, ty + td * 0.5, 0.6 * h, 0.72 * h, 0.013 * u, handle(), sections=8)
    # pliers
    x = slots[3]
    c = handle()
    b.rod((x - 0.03 * u, ty + td * 0.5, 0.35 * h), (x + 0.01 * u, ty + td * 0.5, 0.62 * h), 0.01 * u, c, sections=6)
    b.rod((x + 0.03 * u, ty + td * 0.5, 0.35 * h), (x - 0.01 * u, ty + td * 0.5, 0.62 * h), 0.01 * u, c, sections=6)
    b.box((x - 0.015 * u, ty, 0.62 * h), (x + 0.015 * u, ty + td * 0.6, 0.72 * h), p.accent)
    # a saw
    x = slots[4]
    b.hull([(x - 0.06 * u, ty, 0.75 * h), (x + 0.06 * u, ty, 0.75 * h), (x - 0.02 * u, ty, 0.25 * h),
            (x + 0.04 * u, ty, 0.25 * h), (x - 0.06 * u, ty + td * 0.2, 0.75 * h), (x + 0.06 * u, ty + td * 0.2, 0.75 * h),
            (x - 0.02 * u, ty + td * 0.2, 0.25 * h), (x + 0.04 * u, ty + td * 0.2, 0.25 * h)], CHROME)
    b.box((x - 0.05 * u, ty, 0.75 * h), (x + 0.07 * u, ty + td * 0.5, 0.85 * h), handle())
    # tape measure and a coil of cord
    x = slots[5]
    disc_y(b, x, ty, ty + td * 0.8, 0.68 * h, 0.05 * u, tint("#f1c40f", "paint"), sections=14)
    ring_y(b, (x, ty + td * 0.3, 0.35 * h), 0.06 * u, 0.012 * u, handle(), sections=16)
    for xx in np.linspace(-w / 2 + 0.15 * w, w / 2 - 0.15 * w, 5):  # hooks along the bottom
        path(b, [(xx, fy, 0.15 * h), (xx, ty + td * 0.8, 0.15 * h), (xx, ty + td * 0.8, 0.18 * h)], 0.003, METAL,
             sections=4, joints=False)
    return b.mesh(p.size)


slot_roles("kiln", "metal", "metal", "light")
register("kiln", sample_kiln, build_kiln)
slot_roles("forge", "metal", "metal", "light")
register("forge", sample_forge, build_forge)
slot_roles("anvil", "metal", "wood", "metal")
register("anvil", sample_anvil, build_anvil)
slot_roles("pottery_wheel", "paint", "ceramic", "wood")
register("pottery_wheel", sample_pottery_wheel, build_pottery_wheel)
slot_roles("printing_press", {"": "wood", DARK_METAL: "metal"}, "metal", "paper")
register("printing_press", sample_printing_press, build_printing_press)
slot_roles("loom", "wood", "fabric", "fabric")
register("loom", sample_loom, build_loom)
slot_roles("spinning_wheel", "wood", "fabric", "wood")
register("spinning_wheel", sample_spinning_wheel, build_spinning_wheel)
slot_roles("pegboard", "paint", "wood", "metal")
register("pegboard", sample_pegboard, build_pegboard)
