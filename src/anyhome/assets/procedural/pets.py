"""Animals' homes: kennel (a wire crate or a wooden dog house), aquarium, bird_cage."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
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

FISH = tint(["#f08a2a", "#f1c40f", "#e74c3c", "#3498db", "#ecf0f1"], "plastic")
WATER = tint("#6fb8d0", "glass")
WATER_PLANTS = tint(["#3f8a4a", "#5daa5a", "#2f6b3a"], "plant")
BIRDS = tint(["#f1c40f", "#3fae5a", "#3498db", "#e8e6e0"], "plastic")
HOUSE_WIDTH_M = 0.85
"""A kennel box at least this wide (and deep) is built as a wooden dog house, not a crate."""


# ----------------------------------------------------------------- kennel
def sample_kennel(rng, size, style):
    w, d, _ = size
    house = min(w, d) >= HOUSE_WIDTH_M
    return make_params("kennel", rng, size, style,
                       wood_tones(style) + ["#b5643c", "#8a9aa8"] if house else [DARK_METAL, BLACK, "#9a9da3"],
                       ["#7a2a22", "#3a4a5a", "#4a3a2a", "#2f4a3a"] if house else ["#3a3b3e", "#5a4a3a"],
                       ["#c9a06a", "#8c8f94"], kind="house" if house else "crate", bed=bool(rng.random() < 0.6))


def _crate(b: Builder, w: float, d: float, h: float, p) -> None:
    bar = 0.006
    nx, ny = max(1, int(w / 0.06)), max(1, int(d / 0.06))  # bars about 6 cm apart
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04), p.secondary)  # tray
    edges = [((-1, -1), (1, -1)), ((1, -1), (1, 1)), ((1, 1), (-1, 1)), ((-1, 1), (-1, -1))]
    for z in (0.04, h - bar):
        for (ax, ay), (bx, by) in edges:
            b.rod((ax * w / 2, ay * d / 2, z), (bx * w / 2, by * d / 2, z), bar * 1.5, p.primary, sections=4)
    for sx in (-1, 1):  # side walls: vertical bars along y
        for i in range(ny + 1):
            y = -d / 2 + i * d / ny
            b.rod((sx * w / 2, y, 0.04), (sx * w / 2, y, h), bar, p.primary, sections=4)
    for sy in (-1, 1):  # end walls, the door on the front
        for i in range(nx + 1):
            x = -w / 2 + i * w / nx
            b.rod((x, sy * d / 2, 0.04), (x, sy * d / 2, h), bar, p.primary, sections=4)
    for i in range(nx + 1):  # roof: bars along y
        x = -w / 2 + i * w / nx
        b.rod((x, -d / 2, h - bar), (x, d / 2, h - bar), bar, p.primary, sections=4)
    for z in (0.35 * h, 0.7 * h):
        b.rod((-w / 2, d / 2, z), (w / 2, d / 2, z), bar, p.primary, sections=4)
        for sx in (-1, 1):
            b.rod((sx * w / 2, -d / 2, z), (sx * w / 2, d / 2, z), bar, p.primary, sections=4)
    b.box((-0.1 * w, d / 2 - 0.005, 0.45 * h), (0.1 * w, d / 2 + 0.015, 0.55 * h), METAL)  # latch
    if p.bed:
        b.box((-w / 2 + 0.03, -d / 2 + 0.03, 0.04), (w / 2 - 0.03, d / 2 - 0.03, 0.1), p.accent)


def _dog_house(b: Builder, w: float, d: float, h: float, p) -> None:
    eave = 0.55 * h
    b.box((-w / 2 + 0.03, -d / 2 + 0.03, 0), (w / 2 - 0.03, d / 2 - 0.03, 0.06), darker(p.primary, 0.25))
    b.box((-w / 2 + 0.05, -d / 2 + 0.05, 0.06), (w / 2 - 0.05, d / 2 - 0.05, eave), p.primary)
    gable = [(-w / 2 + 0.05, eave), (w / 2 - 0.05, eave), (0, h - 0.05)]
    for y in (d / 2 - 0.05, -d / 2 + 0.05):
        b.hull([(x, y - 0.02, z) for x, z in gable] + [(x, y, z) for x, z in gable], p.primary)
    for sx in (-1, 1):  # roof planes overhang the walls
        b.hull([(0, -d / 2, h - 0.04), (0, d / 2, h - 0.04), (0, -d / 2, h), (0, d / 2, h),
                (sx * w / 2, -d / 2, eave - 0.06), (sx * w / 2, d / 2, eave - 0.06),
                (sx * w / 2, -d / 2, eave - 0.02), (sx * w / 2, d / 2, eave - 0.02)], p.secondary)
    dw, dh = 0.4 * w, 0.6 * eave
    b.box((-dw / 2, d / 2 - 0.06, 0.08), (dw / 2, d / 2 - 0.045, 0.08 + dh - dw / 2), tint("#1c1814", "paint"))  # doorway
    b.rod((0, d / 2 - 0.06, 0.08 + dh - dw / 2), (0, d / 2 - 0.045, 0.08 + dh - dw / 2), dw / 2, tint("#1c1814", "paint"),
          sections=20)
    for k in range(1, int(eave / 0.12)):  # siding boards
        b.box((-w / 2 + 0.05, d / 2 - 0.05, k * 0.12), (w / 2 - 0.05, d / 2 - 0.046, k * 0.12 + 0.008),
              darker(p.primary, 0.15))
    b.cbox((0, d / 2 - 0.03, eave + 0.12 * (h - eave)), (0.25 * w, 0.02, 0.06), lighter(p.accent, 0.2))  # name
    if p.bed:
        b.cyl(0.3 * w, d / 2 - 0.15 * d, 0.0, 0.04, 0.08, tint("#c0392b", "paint"), r_top=0.07, sections=14)  # a bowl


def build_kennel(p):
    w, d, h = p.size
    b = Builder()
    (_dog_house if p.kind == "house" else _crate)(b, w, d, h, p)
    return b.mesh(p.size)


# ----------------------------------------------------------------- aquarium
def sample_aquarium(rng, size, style):
    return make_params("aquarium", rng, size, style, wood_tones(style) + [BLACK, "#e8e6e0"], WATER, BLACK,
                       fish=int(rng.integers(4, 10)), plants=int(rng.integers(3, 7)))


def build_aquarium(p):
    """A glass tank of water with gravel, plants and fish; on a cabinet when the box is tall."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    stand = 0.5 * h if h > 0.9 else 0.0
    if stand:
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, stand), p.primary)
        for sx in (-1, 1):
            b.box((sx * w / 4 - 0.23 * w, d / 2, 0.06), (sx * w / 4 + 0.23 * w, d / 2 + 0.01, stand - 0.04),
                  lighter(p.primary, 0.08))
            b.box((sx * 0.03 - 0.005, d / 2 + 0.01, 0.6 * stand), (sx * 0.03 + 0.005, d / 2 + 0.02, 0.8 * stand),
                  METAL)
    z0 = stand
    lid = min(0.06, 0.08 * (h - z0))
    t0, t1 = z0 + 0.02, h - lid
    inset = 0.01
    b.box((-w / 2 + inset, -d / 2 + inset, z0), (w / 2 - inset, d / 2 - inset, t0 + 0.04), tint("#d9c3a0", "stone"))  # gravel
    b.box((-w / 2 + inset, -d / 2 + inset, t0 + 0.04), (w / 2 - inset, -d / 2 + inset + 0.005, t1), tint("#2f6b8a", "paint"))
    water_top = t1 - 0.04
    for _ in range(p.plants):
        x = rng.uniform(-0.42, 0.42) * w
        y = rng.uniform(-0.35, 0.1) * d
        tall = rng.uniform(0.4, 0.85) * (water_top - t0)
        b.sphere((x, y, t0 + 0.04 + tall / 2), (0.025 + 0.02 * w, 0.02, tall / 2),
                 WATER_PLANTS[int(rng.integers(len(WATER_PLANTS)))], subdivisions=1)
    for _ in range(2):
        b.sphere((rng.uniform(-0.35, 0.35) * w, rng.uniform(-0.2, 0.2) * d, t0 + 0.05),
                 (0.06 + 0.04 * w, 0.05, 0.05), tint("#8a8f94", "paint"), subdivisions=1)
    fl = min(0.05, 0.06 * w)
    for _ in range(p.fish):
        c = np.array([rng.uniform(-0.4, 0.4) * w, rng.uniform(-0.2, 0.35) * d, rng.uniform(0.3, 0.85) * (water_top - t0)
                      + t0])
        s = 1 if rng.random() < 0.5 else -1
        col = FISH[int(rng.integers(len(FISH)))]
        b.sphere(c, (fl, fl * 0.3, fl * 0.5), col, subdivisions=1)
        b.hull([c + (-s * fl * 0.8, 0, 0), c + (-s * fl * 1.5, 0, fl * 0.45), c + (-s * fl * 1.5, 0, -fl * 0.45),
                c + (-s * fl * 1.5, 0.005, 0)], col)
    b.box((-w / 2 + inset, -d / 2 + inset, t0 + 0.04), (w / 2 - inset, d / 2 - inset, water_top), p.secondary,
          alpha=70)  # water
    b.box((-w / 2, -d / 2, t1), (w / 2, d / 2, h), p.accent)  # lid
    for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        b.box((x * w / 2 - 0.012 * (x > 0), y * d / 2 - 0.012 * (y > 0), z0),
              (x * w / 2 + 0.012 * (x < 0), y * d / 2 + 0.012 * (y < 0), t1), p.accent)
    b.box((-w / 2, -d / 2, z0), (w / 2, d / 2, t0), p.accent)
    b.box((-w / 2 + 0.002, d / 2 - 0.004, t0), (w / 2 - 0.002, d / 2, t1), GLASS, alpha=40)  # front glass
    return b.mesh(p.size)


# ----------------------------------------------------------------- bird cage
def sample_bird_cage(rng, size, style):
    return make_params("bird_cage", rng, size, style, ["#c9a54a", "#e8e6e0", BLACK, "#9a9da3", "#5a6b5a"],
                       wood_tones(style), BIRDS, shape=str(rng.choice(["dome", "dome", "box"])),
                       bars=int(rng.integers(18, 28)), bird=bool(rng.random() < 0.8))


def build_bird_cage(p):
    """A cage on a pedestal stand when the box is much taller than wide, else standing alone."""
    w, d, h = p.size
    b = Builder()
    R = min(w, d) / 2
    stand = h > 1.8 * 2 * R
    if stand:
        z0 = h - min(h * 0.55, 2.4 * R * 1.5)
        for i in range(3):
            a = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0, 0, 0.18 * z0), (0.95 * R * np.cos(a), 0.95 * R * np.sin(a), 0.0), 0.015, p.primary, sections=6)
        b.cyl(0, 0, 0, z0, 0.02, p.primary, sections=8)
    else:
        z0 = 0.0
    cr = 0.85 * R
    b.cyl(0, 0, z0, z0 + 0.06, cr * 1.05, p.primary, sections=24)  # tray
    body_top = z0 + 0.72 * (h - z0) if p.shape == "dome" else h - 0.03
    n = p.bars
    for i in range(n):
        a = 2 * np.pi * i / n
        x, y = cr * np.cos(a), cr * np.sin(a)
        if p.shape == "box":
            s = max(abs(np.cos(a)), abs(np.sin(a)))
            x, y = x / s, y / s
            x, y = np.clip(x, -cr, cr), np.clip(y, -cr, cr)
        b.rod((x, y, z0 + 0.06), (x, y, body_top), 0.004, p.primary, sections=4)
        if p.shape == "dome":  # curve over to the top in three steps
            prev = (x, y, body_top)
            for k in range(1, 4):
                t = k / 3
                r = cr * np.cos(t * np.pi / 2)
                nxt = (r * np.cos(a), r * np.sin(a), body_top + (h - 0.05 - body_top) * np.sin(t * np.pi / 2))
                b.rod(prev, nxt, 0.004, p.primary, sections=4)
                prev = nxt
    for z in (z0 + 0.06, z0 + 0.35 * (body_top - z0), body_top):
        if p.shape == "box":
            for (ax, ay), (bx, by) in (((-1, -1), (1, -1)), ((1, -1), (1, 1)), ((1, 1), (-1, 1)), ((-1, 1), (-1, -1))):
                b.rod((ax * cr, ay * cr, z), (bx * cr, by * cr, z), 0.006, p.primary, sections=4)
        else:
            b.torus((0, 0, z), cr, 0.006, p.primary, sections=24, minor_sections=4)
    if p.shape == "box":
        b.box((-cr, -cr, body_top), (cr, cr, body_top + 0.015), p.primary)
    b.torus((0, 0, h - 0.04), 0.035, 0.006, p.primary, sections=12, minor_sections=4)
    b.cyl(0, 0, h - 0.06, h - 0.04, 0.02, p.primary, sections=8)
    perch_z = z0 + 0.4 * (body_top - z0)
    b.rod((-0.8 * cr, 0, perch_z), (0.8 * cr, 0, perch_z), 0.008, p.secondary, sections=6)
    if p.bird:
        b.sphere((0.15 * cr, 0, perch_z + 0.05), (0.035, 0.03, 0.045), p.accent, subdivisions=1)
        b.sphere((0.15 * cr + 0.02, 0.0, perch_z + 0.095), 0.025, p.accent, subdivisions=1)
        b.hull([(0.15 * cr + 0.04, -0.006, perch_z + 0.1), (0.15 * cr + 0.04, 0.006, perch_z + 0.1),
                (0.15 * cr + 0.04, 0, perch_z + 0.088), (0.15 * cr + 0.06, 0, perch_z + 0.092)], tint("#e8a03a", "paint"))
    return b.mesh(p.size)


slot_roles("kennel", {"": "wood", DARK_METAL: "metal", "#9a9da3": "metal"}, "paint", "fabric")
register("kennel", sample_kennel, build_kennel)
slot_roles("aquarium", "wood", "glass", "plastic")
register("aquarium", sample_aquarium, build_aquarium)
slot_roles("bird_cage", "metal", "wood", "paint")
register("bird_cage", sample_bird_cage, build_bird_cage)
