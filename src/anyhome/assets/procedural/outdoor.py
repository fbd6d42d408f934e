"""Garden and patio things: fountain, well, hot_tub, fire_pit, grill, patio_umbrella, potted_tree."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    about,
    darker,
    lighter,
    make_params,
    move,
    rot_y,
    rot_z,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

STONES = tint(["#c9c1b0", "#b3ab9c", "#d8d0c0", "#9d978c", "#bfb3a0"], "stone")
WATER = tint(["#5f9fc0", "#6fb0c8", "#4f8fb0"], "glass")
FOLIAGE = tint(["#4f7a3a", "#5d8a45", "#3f6b35", "#6b8f4e"], "plant")
FLAME = tint("#f08a2a", "light")
FLAME_CORE = tint("#ffd060", "light")
TYRE = tint("#1c1c1e", "rubber")


# ----------------------------------------------------------------- fountain
def sample_fountain(rng, size, style):
    w, _, h = size
    tall = h > 1.2 * w  # a bird bath or font on a pedestal, no ground pool
    return make_params("fountain", rng, size, style, STONES, WATER, lighter(WATER[0], 0.5),
                       pool=not tall, tiers=int(rng.integers(1, 3 if h < 1.2 else 4)),
                       finial=str(rng.choice(["ball", "urn", "jet"])))


def _basin(b: Builder, r: float, z0: float, z1: float, stone: str, water: str) -> float:
    """A round stone bowl from z0 to z1 holding water; returns the water level."""
    dz = z1 - z0
    floor = z0 + 0.35 * dz
    b.lathe([[0, z0], [0.8 * r, z0], [r, z1], [0.9 * r, z1], [0.78 * r, floor], [0, floor]], stone, sections=28)
    level = z0 + 0.75 * dz
    b.cyl(0, 0, floor - 0.005, level, 0.84 * r, water, sections=28)
    return level


def build_fountain(p):
    w, d, h = p.size
    b = Builder()
    R = w / 2
    if p.pool:
        ph = min(0.45, 0.25 * h)
        _basin(b, R, 0, ph, p.primary, p.secondary)
        radii = [0.55 * R, 0.36 * R, 0.22 * R][: p.tiers]
        z_lo = ph
    else:  # pedestal: foot, shaft, then the bowls
        b.cyl(0, 0, 0, 0.06 * h, 0.55 * R, darker(p.primary, 0.1), r_top=0.5 * R, sections=24)
        radii = [R, 0.55 * R, 0.33 * R][: p.tiers]
        z_lo = 0.06 * h
    top = h * (0.8 if p.finial == "jet" else 0.88)
    span = top - z_lo
    bowl_h = min(0.22, 0.45 * span / len(radii)) if p.pool else min(0.25 * h, 0.6 * span / len(radii))
    gaps = (span - bowl_h * len(radii)) / len(radii)
    z = z_lo
    for i, r in enumerate(radii):
        shaft_r = max(0.04, 0.12 * r) if i == 0 else max(0.03, 0.1 * r)
        z_b = z + gaps
        b.cyl(0, 0, z - 0.01, z_b + 0.01, shaft_r * 1.3, p.primary, r_top=shaft_r, sections=16)
        b.sphere((0, 0, z + 0.55 * gaps), (shaft_r * 1.7, shaft_r * 1.7, 0.12 * gaps), p.primary)
        level = _basin(b, r, z_b, z_b + bowl_h, p.primary, p.secondary)
        z = level
    if p.finial == "jet":
        b.cyl(0, 0, z, h, max(0.015, 0.02 * R), p.accent, r_top=0.6 * max(0.015, 0.02 * R), sections=10,
              alpha=200)
        b.sphere((0, 0, h - 0.05 * (h - z)), (0.08 * R, 0.08 * R, 0.05 * (h - z)), p.accent, alpha=200)
    elif p.finial == "urn":
        b.lathe([[0, z], [0.06 * R, z], [0.04 * R, z + 0.3 * (h - z)], [0.1 * R, z + 0.7 * (h - z)],
                 [0.05 * R, h], [0, h]], p.primary, sections=16)
    else:
        b.cyl(0, 0, z, z + 0.6 * (h - z), 0.03 * R + 0.02, p.primary, sections=12)
        b.sphere((0, 0, h - 0.4 * (h - z) / 2), (0.08 * R + 0.02, 0.08 * R + 0.02, 0.4 * (h - z) / 2),
                 p.primary)
    return b.mesh(p.size)


# ----------------------------------------------------------------- well
def sample_well(rng, size, style):
    return make_params("well", rng, size, style, STONES, wood_tones(style), ["#3a4a58", "#2e3d48"],
                       frame=str(rng.choice(["posts", "roof", "none"], p=[0.45, 0.35, 0.2])),
                       bucket=bool(rng.random() < 0.8))


def build_well(p):
    """A draw well: a round wall of stone courses round dark water, and, on most, two posts
    with a winch beam (a little roof on some) and a bucket on the rim."""
    w, d, h = p.size
    b = Builder()
    R = min(w, d) / 2
    wall_h = min(0.85, 0.75 * h) if p.frame != "none" else h
    t = min(0.16, 0.22 * R)
    courses = 4
    for i in range(courses):  # stone courses, each a little darker or lighter
        z0, z1 = wall_h * i / courses, wall_h * (i + 1) / courses
        col = darker(p.primary, 0.06) if i % 2 else p.primary
        b.lathe([[R - t, z0], [R, z0], [R, z1], [R - t, z1]], col, sections=28)
    b.lathe([[R - t - 0.01, wall_h], [R + 0.02, wall_h], [R + 0.02, wall_h + 0.05], [R - t - 0.01, wall_h + 0.05]],
            lighter(p.primary, 0.15), sections=28)
    b.cyl(0, 0, 0.02, wall_h - 0.35, R - t - 0.02, p.accent, sections=28)  # the water, well down the shaft
    if p.frame != "none":
        post = max(0.04, 0.05 * R + 0.02)
        for sx in (-1, 1):
            b.box((sx * (R - t / 2) - post, -post, wall_h), (sx * (R - t / 2) + post, post, h - 0.12 * h), p.secondary)
        beam_z = h - 0.2 * h
        b.rod((-(R - t / 2), 0, beam_z), (R - t / 2, 0, beam_z), post * 0.7, darker(p.secondary, 0.1), sections=10,
              role="wood")
        b.rod((0, 0, beam_z), (0, 0, wall_h + 0.3 * (beam_z - wall_h)), 0.006, DARK_METAL, sections=6)
        if p.frame == "roof":
            top, eave = h, h - 0.14 * h
            for sy in (-1, 1):
                b.hull([(-R - 0.05, 0, top), (R + 0.05, 0, top), (-R - 0.05, sy * (R * 0.8), eave),
                        (R + 0.05, sy * (R * 0.8), eave), (-R - 0.05, sy * (R * 0.8), eave - 0.03),
                        (R + 0.05, sy * (R * 0.8), eave - 0.03)], darker(p.secondary, 0.2))
    if p.bucket:
        br = min(0.13, 0.25 * R)
        bx = R - t / 2
        b.cyl(bx * 0.7, bx * 0.7, wall_h + 0.05, wall_h + 0.05 + 1.3 * br, br * 0.8, p.secondary, r_top=br,
              sections=14)
    return b.mesh(p.size)


# ----------------------------------------------------------------- hot tub / pools
def sample_hot_tub(rng, size, style):
    w, d, h = size
    shallow = h < 0.2 * min(w, d)  # a swimming or plunge pool more than a tub
    round_ok = abs(w - d) < 0.1 * max(w, d) and not shallow
    cladding = ["#8a6a4a", "#6b5040", "#7a7a78", "#4a4a4c", "#a88a66"] if not shallow else STONES
    return make_params("hot_tub", rng, size, style, cladding, ["#e8eef0", "#dfe7ea", "#c8d8de"], WATER,
                       round=bool(round_ok and rng.random() < 0.35), shallow=bool(shallow),
                       ladder=bool(shallow and rng.random() < 0.8), lid=bool(not shallow and rng.random() < 0.3))


def build_hot_tub(p):
    w, d, h = p.size
    b = Builder()
    rim = min(0.12, 0.08 * min(w, d)) if not p.shallow else min(0.3, 0.06 * min(w, d))
    level = h - (0.12 * h if not p.shallow else 0.25 * h)
    if p.round:
        r = w / 2
        b.lathe([[0, 0], [r, 0], [r, h], [r - rim, h], [r - rim, 0.25 * h], [0, 0.25 * h]], p.primary, sections=32)
        b.torus((0, 0, h), r - rim / 2, rim * 0.55, lighter(p.primary, 0.25), sections=32, minor_sections=6)
        b.cyl(0, 0, 0.25 * h, level, r - rim - 0.005, p.accent, sections=32, alpha=230)
    else:
        floor = 0.25 * h if not p.shallow else 0.02
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, floor), p.primary)
        for lo, hi in (((-w / 2, -d / 2), (w / 2, -d / 2 + rim)), ((-w / 2, d / 2 - rim), (w / 2, d / 2)),
                       ((-w / 2, -d / 2), (-w / 2 + rim, d / 2)), ((w / 2 - rim, -d / 2), (w / 2, d / 2))):
            b.box((*lo, 0), (*hi, h - 0.03 * h), p.primary)
            b.box((lo[0], lo[1], h - 0.03 * h), (*hi, h), lighter(p.primary, 0.3))
        inner = rim + 0.005
        b.box((-w / 2 + inner, -d / 2 + inner, floor), (w / 2 - inner, d / 2 - inner, level - 0.02), p.secondary)
        b.box((-w / 2 + inner, -d / 2 + inner, level - 0.02), (w / 2 - inner, d / 2 - inner, level), p.accent,
              alpha=230)
        if not p.shallow:  # vertical cladding boards and pillows in two corners
            n = max(4, int(w / 0.12))
            for i in range(1, n):
                x = -w / 2 + i * w / n
                b.box((x - 0.004, d / 2, 0.02), (x + 0.004, d / 2 + 0.004, h - 0.05), darker(p.primary, 0.2))
            for sx in (-1, 1):
                b.cbox((sx * (w / 2 - rim - 0.12), -d / 2 + rim + 0.04, h - 0.06), (0.22, 0.07, 0.12), DARK_METAL)
        if p.ladder:
            x = w / 2 - rim - 0.25
            for dx in (-0.22, 0.22):
                b.rod((x + dx, d / 2 - rim - 0.1, level - 0.3 * h), (x + dx, d / 2 - rim - 0.1, h), 0.02,
                      METAL, sections=8)
                b.rod((x + dx, d / 2 - rim - 0.1, h), (x + dx, d / 2 - rim / 2, h), 0.02, METAL, sections=8)
    if p.lid:  # a folded cover on the back edge
        b.box((-w / 2 + 0.02, -d / 2, h), (w / 2 - 0.02, -d / 2 + 0.25 * d, h + 0.06), tint("#5a5550", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- fire pit
def sample_fire_pit(rng, size, style):
    if style_is(style, "modern", "industrial"):
        kind = "bowl"
    elif style_is(style, "rustic", "antique"):
        kind = "stone"
    else:
        kind = str(rng.choice(["stone", "stone", "bowl"]))
    return make_params("fire_pit", rng, size, style, STONES if kind == "stone" else [DARK_METAL, "#5a3a2a"],
                       "#6b4a30", FLAME, kind=kind, lit=bool(rng.random() < 0.75))


def build_fire_pit(p):
    w, d, h = p.size
    b = Builder()
    R = w / 2
    if p.kind == "stone":
        rim_h = 0.75 * h
        n = 14
        for i in range(n):
            a = 2 * np.pi * i / n
            m = rot_z(a)
            shade = p.primary if i % 2 else darker(p.primary, 0.12)
            b.box((0.72 * R, -0.22 * R, 0), (R, 0.22 * R, rim_h * 0.5), shade, transform=m)
            m2 = rot_z(a + np.pi / n)
            b.box((0.72 * R, -0.22 * R, rim_h * 0.5), (R, 0.22 * R, rim_h), lighter(shade, 0.08), transform=m2)
        b.cyl(0, 0, 0, 0.15 * h, 0.8 * R, tint("#2a2420", "paint"), sections=20)
        fire_z = 0.15 * h
    else:  # a steel bowl on three legs
        bowl_z = 0.3 * h
        b.lathe([[0, bowl_z], [0.5 * R, bowl_z], [R, 0.9 * h], [0.96 * R, 0.9 * h], [0.47 * R, bowl_z + 0.03],
                 [0, bowl_z + 0.03]], p.primary, sections=28)
        for i in range(3):
            a = 2 * np.pi * i / 3
            b.rod((0.35 * R * np.cos(a), 0.35 * R * np.sin(a), bowl_z + 0.02),
                  (0.75 * R * np.cos(a), 0.75 * R * np.sin(a), 0), 0.02, p.primary, sections=8)
        fire_z = bowl_z + 0.15 * h
    for k in range(3):  # crossed logs
        a = np.pi * k / 3
        c, s = np.cos(a) * 0.45 * R, np.sin(a) * 0.45 * R
        b.rod((-c, -s, fire_z + 0.04), (c, s, fire_z + 0.04 + 0.02 * k), 0.05 * R + 0.02, p.secondary, sections=8)
    if p.lit:
        top = h if p.kind == "stone" else h
        b.cyl(0, 0, fire_z + 0.04, top, 0.35 * R, p.accent, r_top=0.02, sections=9)
        b.cyl(0.12 * R, 0.05 * R, fire_z + 0.04, fire_z + 0.7 * (top - fire_z), 0.2 * R, FLAME_CORE, r_top=0.01,
              sections=7)
    return b.mesh(p.size)


# ----------------------------------------------------------------- grill
def sample_grill(rng, size, style):
    w, d, _ = size
    kind = "kettle" if w < 1.35 * d else "cart"
    return make_params("grill", rng, size, style, [BLACK, "#2b2b2b", "#8a2a22", "#3a4a5a", "#9a9da3"],
                       METAL, wood_tones(style), kind=kind, burners=int(rng.integers(2, 5)))


def build_grill(p):
    w, d, h = p.size
    b = Builder()
    if p.kind == "kettle":
        R = min(w, d) / 2
        cz = 0.62 * h
        b.sphere((0, 0, cz), (R, R, 0.4 * R), p.primary, subdivisions=2)  # bowl and dome lid
        b.torus((0, 0, cz), R * 0.99, 0.012, p.secondary, sections=28, minor_sections=4)
        b.cyl(0, 0, cz + 0.38 * R, cz + 0.45 * R, 0.04, p.secondary, sections=10)
        b.rod((-0.1, 0, cz + 0.5 * R), (0.1, 0, cz + 0.5 * R), 0.015, BLACK, sections=8)
        for i in range(3):
            a = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0.6 * R * np.cos(a), 0.6 * R * np.sin(a), cz - 0.2 * R),
                  (0.85 * R * np.cos(a), 0.85 * R * np.sin(a), 0), 0.015, p.secondary, sections=8)
        b.cbox((0, 0, 0.3 * h), (1.2 * R, 0.02, 0.02), p.secondary)
        b.rod((-R, -0.1 * R, 0.04), (-R, 0.1 * R, 0.04), 0.05, BLACK, sections=12)
        b.cyl(0, 0, cz + 0.4 * R, h, 0.04, p.secondary, r_top=0.02, sections=8)  # vent knob
        return b.mesh(p.size)
    # gas cart: cabinet, firebox with a rounded lid, side shelves
    body = 0.55 * w
    top = 0.6 * h
    b.box((-body / 2, -d / 2 + 0.05, 0.1), (body / 2, d / 2 - 0.05, top - 0.12), p.primary)
    b.box((-body / 2 + 0.03, d / 2 - 0.05, 0.15), (-0.01, d / 2 - 0.04, top - 0.17), darker(p.primary, 0.15))
    b.box((0.01, d / 2 - 0.05, 0.15), (body / 2 - 0.03, d / 2 - 0.04, top - 0.17), darker(p.primary, 0.15))
    for x in (-body / 2 + 0.05, body / 2 - 0.05):
        b.rod((x, -d / 2 + 0.08, 0.05), (x, -d / 2 + 0.08, 0.1), 0.05, TYRE, sections=10)
        b.cyl(x, d / 2 - 0.1, 0, 0.1, 0.03, TYRE, sections=8)
    b.box((-body / 2, -d / 2, top - 0.12), (body / 2, d / 2, top), p.secondary)  # control front and firebox
    for i in range(p.burners):
        x = -body / 2 + (i + 0.5) * body / p.burners
        b.rod((x, d / 2, top - 0.06), (x, d / 2 + 0.03, top - 0.06), 0.02, BLACK, sections=10)
    lid_r = d / 2
    lid = about(rot_y(np.pi / 2), (0, 0, 0))
    b.cyl(0, 0, -body / 2, body / 2, lid_r * 0.95, p.primary, ry=lid_r * 0.55, sections=20,
          transform=move((0, -0.02 * d, top)) @ lid)
    b.rod((-body * 0.35, d / 2 - 0.02, top + 0.25 * lid_r), (body * 0.35, d / 2 - 0.02, top + 0.25 * lid_r),
          0.015, p.secondary, sections=8)
    for s in (-1, 1):  # side shelves and the bottom of the cart
        b.box((s * body / 2, -d / 2 + 0.05, top - 0.04), (s * w / 2, d / 2 - 0.05, top - 0.01), p.accent)
        b.rod((s * (w / 2 - 0.02), d / 2 - 0.07, top - 0.04), (s * (w / 2 - 0.02), d / 2 - 0.07, top - 0.1), 0.008,
              p.secondary, sections=6)
    b.cyl(-body / 2 + 0.12, -d / 2 + 0.2, 0.12, 0.42 * h, 0.1, tint("#e8e6e0", "paint"), sections=14)  # gas bottle
    top_cap = 0.47 * h
    b.cyl(-body / 2 + 0.12, -d / 2 + 0.2, 0.42 * h, top_cap, 0.05, METAL, sections=10)
    b.box((-0.01, -d / 2 + 0.05, top), (0.01, -d / 2 + 0.1, h), p.primary)  # lid hinge stop
    return b.mesh(p.size)


# ----------------------------------------------------------------- patio umbrella
def sample_patio_umbrella(rng, size, style):
    return make_params("patio_umbrella", rng, size, style,
                       ["#e8e2d4", "#2f4a6a", "#b8322a", "#3f6b4a", "#d9a32a", "#c9c1b4"],
                       ["#f4f1ea", "#e8e2d4"], wood_tones(style) + [METAL], panels=int(rng.choice([6, 8])),
                       striped=bool(rng.random() < 0.35))


def build_patio_umbrella(p):
    w, d, h = p.size
    b = Builder()
    R = w / 2
    b.cyl(0, 0, 0, 0.08, min(0.3, 0.25 * R), DARK_METAL, r_top=min(0.25, 0.2 * R), sections=20)
    b.cyl(0, 0, 0.05, h - 0.05, 0.022, p.accent, sections=10)
    rim = h - 0.28 * R * 0.6 - 0.08
    apex = h - 0.06
    n = p.panels
    for i in range(n):
        a0, a1 = 2 * np.pi * i / n, 2 * np.pi * (i + 1) / n
        col = p.secondary if (p.striped and i % 2) else p.primary
        pts = [(0, 0, apex), (0, 0, apex - 0.02)]
        for a in (a0, a1):
            pts += [(R * np.cos(a), R * np.sin(a), rim), (R * np.cos(a), R * np.sin(a), rim - 0.02)]
        b.hull(pts, col)
        am = (a0 + a1) / 2  # a valance flap
        c0 = (R * np.cos(a0), R * np.sin(a0))
        c1 = (R * np.cos(a1), R * np.sin(a1))
        b.hull([(*c0, rim), (*c1, rim), (*c0, rim - 0.1), (*c1, rim - 0.1),
                (0.97 * R * np.cos(am), 0.97 * R * np.sin(am), rim - 0.05)], darker(col, 0.1))
        b.rod((0, 0, rim - 0.35 * (apex - rim)), (0.55 * R * np.cos(a0), 0.55 * R * np.sin(a0), rim + 0.5 * (apex - rim)),
              0.008, p.accent, sections=6)
    b.cyl(0, 0, apex - 0.01, h, 0.03, p.accent, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- potted tree
def sample_potted_tree(rng, size, style):
    return make_params("potted_tree", rng, size, style,
                       ["#b5643c", "#e8e6e0", "#3a3a3c", "#8a8f94", "#c9b28e"], FOLIAGE, ["#e8c53a", "#e8e6e0"],
                       kind=str(rng.choice(["olive", "fig", "lemon", "ball"])), square_pot=bool(rng.random() < 0.4),
                       clusters=int(rng.integers(9, 15)))


def build_potted_tree(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    R = min(w, d) / 2
    pot_r = 0.42 * R
    pot_h = min(0.55, 0.2 * h)
    if p.square_pot:
        b.box((-pot_r, -pot_r, 0), (pot_r, pot_r, pot_h), p.primary)
        b.box((-pot_r * 0.92, -pot_r * 0.92, pot_h), (pot_r * 0.92, pot_r * 0.92, pot_h + 0.005), tint("#4a3526", "paint"))
    else:
        b.cyl(0, 0, 0, pot_h, pot_r * 0.75, p.primary, r_top=pot_r, sections=20)
        b.cyl(0, 0, pot_h - 0.04, pot_h, pot_r * 1.05, darker(p.primary, 0.1), sections=20)
        b.cyl(0, 0, pot_h - 0.03, pot_h + 0.005, pot_r * 0.95, tint("#4a3526", "paint"), sections=20)
    crown_z = pot_h + (0.55 if p.kind != "fig" else 0.35) * (h - pot_h)
    bark = "#6b5238" if p.kind != "olive" else "#7a7266"
    lean = rng.uniform(-0.15, 0.15, 2) * R
    mid = (lean[0] * 0.5, lean[1] * 0.5, pot_h + 0.5 * (crown_z - pot_h))
    b.rod((0, 0, pot_h - 0.02), mid, 0.045 * R + 0.02, bark, sections=8, role="wood")
    b.rod(mid, (lean[0], lean[1], crown_z), 0.035 * R + 0.015, bark, sections=8, role="wood")
    crown_c = np.array([lean[0], lean[1], crown_z + 0.45 * (h - crown_z)])
    crown_r = np.array([R, R, 0.5 * (h - crown_z)])
    for _ in range(3):  # branches
        end = crown_c + rng.uniform(-0.6, 0.6, 3) * crown_r * np.array([1, 1, 0.5])
        b.rod((lean[0], lean[1], crown_z), end, 0.02 * R + 0.01, bark, sections=6, role="wood")
    if p.kind == "ball":
        b.sphere(crown_c, crown_r * 0.98, p.secondary, subdivisions=2)
    else:
        for i in range(p.clusters):
            u = rng.normal(size=3)
            u /= np.linalg.norm(u)
            s = rng.uniform(0.3, 0.42) if p.kind != "fig" else rng.uniform(0.35, 0.5)
            c = crown_c + u * crown_r * (1 - s) * np.array([1, 1, 1])
            col = p.secondary if i % 3 else FOLIAGE[i % len(FOLIAGE)]
            b.sphere(c, crown_r * s, col, subdivisions=1)
    if p.kind == "lemon":
        for _ in range(7):
            u = rng.normal(size=3)
            u[2] = abs(u[2]) * 0.3
            u /= np.linalg.norm(u)
            b.sphere(crown_c + u * crown_r * 0.85, 0.05 * R + 0.015, p.accent, subdivisions=0)
    return b.mesh(p.size)


slot_roles("fountain", "stone", "glass", "glass")
register("fountain", sample_fountain, build_fountain)
slot_roles("well", "stone", "wood", "glass")
register("well", sample_well, build_well)
slot_roles("hot_tub", "wood", "plastic", "glass")
register("hot_tub", sample_hot_tub, build_hot_tub)
slot_roles("fire_pit", {"": "stone", DARK_METAL: "metal"}, "wood", "light")
register("fire_pit", sample_fire_pit, build_fire_pit)
slot_roles("grill", {"": "paint", "#9a9da3": "metal"}, "metal", "wood")
register("grill", sample_grill, build_grill)
slot_roles("patio_umbrella", "fabric", "fabric", {"": "wood", METAL: "metal"})
register("patio_umbrella", sample_patio_umbrella, build_patio_umbrella)
slot_roles("potted_tree", "ceramic", "plant", "plant")
register("potted_tree", sample_potted_tree, build_potted_tree)
