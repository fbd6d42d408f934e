"""Decor: lamp, floor_lamp, rug, plant, wall_art, mirror, clock, curtain, tapestry,
yoga_mat, vase, book, statue, barrel."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    about,
    darker,
    fabric_tones,
    lighter,
    make_params,
    rot_y,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

SHADES = tint(["#f1ead8", "#e9e4da", "#d9c3a0", "#f4efe6", "#c8b8a6"], "fabric")
RUGS = tint(["#8b3a3a", "#3a4f7a", "#b59b72", "#6f7f5f", "#c9b8a0", "#5a3a5e", "#d8cfc0", "#7a5a30"], "fabric")
FOLIAGE = tint(["#3e7a3a", "#2f6b35", "#4f8a3f", "#5b9450", "#356b4a"], "plant")
POTS = tint(["#b5654a", "#e8e6e0", "#2b2b2b", "#8c8f94", "#c9a77c", "#3f6f7a"], "ceramic")
ART = tint(["#c0392b", "#2e86c1", "#f1c40f", "#27ae60", "#8e44ad", "#e67e22", "#1abc9c", "#34495e", "#ecf0f1"], "paint")


def sample_lamp(rng, size, style):
    return make_params("lamp", rng, size, style, ["#e8e6e0", "#c9a54a", "#2b2b2b", "#b5654a", "#3f6f7a", METAL],
                       SHADES, METAL, base=str(rng.choice(["urn", "column", "disc"])))


def build_lamp(p):
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    shade_h = 0.38 * h
    if p.base == "urn":
        b.lathe([[0, 0], [r * 0.45, 0], [r * 0.55, 0.05 * h], [r * 0.6, 0.22 * h], [r * 0.3, 0.4 * h],
                 [r * 0.12, 0.45 * h], [0, 0.45 * h]], p.primary)
    elif p.base == "column":
        b.cyl(0, 0, 0, 0.03 * h, r * 0.5, p.primary)
        b.cyl(0, 0, 0.03 * h, 0.45 * h, r * 0.18, p.primary)
    else:
        b.cyl(0, 0, 0, 0.04 * h, r * 0.55, p.primary)
        b.sphere((0, 0, 0.22 * h), (r * 0.45, r * 0.45, 0.18 * h), p.primary)
    b.cyl(0, 0, 0.4 * h, h - shade_h * 0.6, 0.008, p.accent, sections=8)
    b.sphere((0, 0, h - shade_h * 0.55), r * 0.15, tint("#fff6d8", "light"))
    b.cyl(0, 0, h - shade_h, h, r, p.secondary, r_top=r * 0.7, sections=24, alpha=235)
    return b.mesh(p.size)


def sample_floor_lamp(rng, size, style):
    return make_params("floor_lamp", rng, size, style, [BLACK, "#c9a54a", METAL, "#e8e6e0"], SHADES, METAL,
                       tripod=bool(rng.random() < 0.3))


def build_floor_lamp(p):
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    shade_h = min(0.35, 0.2 * h)
    if p.tripod:
        for k in range(3):
            a = 2 * np.pi * k / 3 + np.pi / 2
            b.rod((np.cos(a) * r * 0.8, np.sin(a) * r * 0.8, 0), (0, 0, h * 0.55), 0.012, p.primary, sections=8)
    else:
        b.cyl(0, 0, 0, 0.03, r * 0.7, p.primary, sections=24)
    b.cyl(0, 0, 0.03, h - shade_h * 0.5, 0.012, p.primary, sections=8)
    b.sphere((0, 0, h - shade_h * 0.55), 0.04, tint("#fff6d8", "light"))
    b.cyl(0, 0, h - shade_h, h, r, p.secondary, r_top=r * 0.75, sections=24)
    return b.mesh(p.size)


def sample_rug(rng, size, style):
    return make_params("rug", rng, size, style, RUGS, ["#e8dcc4", "#2b2b2b", "#c9a54a", "#f0ede6"], RUGS,
                       pattern=str(rng.choice(["border", "stripes", "medallion", "plain"])),
                       fringe=bool(rng.random() < 0.4))


def build_rug(p):
    w, d, h = p.size
    b = Builder()
    h = max(h, 0.005)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, h * 0.8), p.primary)
    top = h * 0.8
    eps = h * 0.2
    if p.pattern == "border":
        m = min(w, d) * 0.08
        for x0, y0, x1, y1 in ((-w / 2 + m, -d / 2 + m, w / 2 - m, -d / 2 + 2 * m),
                               (-w / 2 + m, d / 2 - 2 * m, w / 2 - m, d / 2 - m),
                               (-w / 2 + m, -d / 2 + m, -w / 2 + 2 * m, d / 2 - m),
                               (w / 2 - 2 * m, -d / 2 + m, w / 2 - m, d / 2 - m)):
            b.box((x0, y0, top), (x1, y1, top + eps), p.secondary)
    elif p.pattern == "stripes":
        for k, y in enumerate(np.linspace(-d / 2 + d / 12, d / 2 - d / 12, 6)):
            b.box((-w / 2 + 0.02, y - d / 30, top), (w / 2 - 0.02, y + d / 30, top + eps),
                  p.secondary if k % 2 else p.accent)
    elif p.pattern == "medallion":
        b.cyl(0, 0, top, top + eps, w * 0.25, p.secondary, ry=d * 0.25, sections=24)
        b.cyl(0, 0, top, top + eps * 1.01, w * 0.12, p.accent, ry=d * 0.12, sections=24)
    else:
        b.box((-w / 2 + 0.04, -d / 2 + 0.04, top), (w / 2 - 0.04, d / 2 - 0.04, top + eps), lighter(p.primary, 0.08))
    if p.fringe:
        for y in (-d / 2, d / 2 - 0.03):
            b.box((-w / 2 + 0.02, y, 0), (w / 2 - 0.02, y + 0.03, h * 0.4), tint("#eee8da", "fabric"))
    return b.mesh(p.size)


def sample_plant(rng, size, style):
    return make_params("plant", rng, size, style, POTS, FOLIAGE, ["#e05a8a", "#f2c12e", "#ffffff", "#e07a3a"],
                       kind=str(rng.choice(["bush", "tree", "tall", "flowering"])),
                       leaves=int(rng.integers(6, 14)))


def build_plant(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    r = min(w, d) / 2
    pot_h = min(0.35 * h, max(0.12, 0.5 * r * 2))
    pr = r * 0.55
    b.cyl(0, 0, 0, pot_h, pr * 0.75, p.primary, r_top=pr, sections=20)
    b.cyl(0, 0, pot_h - 0.02, pot_h, pr * 1.05, darker(p.primary, 0.1), sections=20)
    b.cyl(0, 0, pot_h - 0.02, pot_h - 0.005, pr * 0.95, tint("#4a3526", "paint"), sections=20)
    if p.kind in ("tree", "tall"):
        trunk_top = h * (0.55 if p.kind == "tree" else 0.35)
        b.cyl(0, 0, pot_h - 0.02, trunk_top, 0.02, tint("#6b4a30", "paint"), r_top=0.012, sections=8)
        c0, c1, rad = trunk_top, h, r
    else:
        c0, c1, rad = pot_h, h, r
    for i in range(p.leaves):
        t = i / max(1, p.leaves - 1)
        z = c0 + (c1 - c0) * (0.25 + 0.5 * t) if p.kind != "tall" else c0 + (c1 - c0) * t
        a = rng.uniform(0, 2 * np.pi)
        rr = rng.uniform(0.1, 0.6) * rad * (1 - 0.5 * t if p.kind == "tall" else 1)
        sr = rng.uniform(0.25, 0.45) * rad
        col = p.secondary if rng.random() < 0.6 else FOLIAGE[int(rng.integers(len(FOLIAGE)))]
        b.sphere((np.cos(a) * rr, np.sin(a) * rr, z), (sr, sr, sr * 0.8), col)
    top_z = c1 - 0.15 * (c1 - c0)
    b.sphere((0, 0, top_z), (rad * 0.55, rad * 0.55, 0.15 * (c1 - c0)), p.secondary)
    if p.kind == "flowering":
        for _ in range(5):
            a = rng.uniform(0, 2 * np.pi)
            b.sphere((np.cos(a) * rad * 0.4, np.sin(a) * rad * 0.4, top_z + rng.uniform(0, 0.1) * (c1 - c0)),
                     rad * 0.1, p.accent, subdivisions=0)
    return b.mesh(p.size)


def sample_wall_art(rng, size, style):
    frame = ["#c9a54a", "#5c3b26"] if style_is(style, "antique") else \
        ["#2b2b2b", "#f0ede6", "#c9a77c", "#c9a54a"]
    return make_params("wall_art", rng, size, style, frame, "#f4f1ea", ART,
                       motif=str(rng.choice(["abstract", "landscape", "blocks"])), mat=bool(rng.random() < 0.5))


def build_wall_art(p):
    """Hung art: the picture plane is local x-z, the back (local -y) against the wall."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    f = min(0.05, 0.08 * min(w, h))
    y0, y1 = -d / 2, d / 2
    b.box((-w / 2, y0, 0), (w / 2, y0 + 0.6 * d, h), p.secondary)  # canvas backing
    for x0, z0, x1, z1 in ((-w / 2, 0, w / 2, f), (-w / 2, h - f, w / 2, h), (-w / 2, 0, -w / 2 + f, h),
                           (w / 2 - f, 0, w / 2, h)):
        b.box((x0, y0, z0), (x1, y1, z1), p.primary)
    m = f + (0.06 * min(w, h) if p.mat else 0.0)
    ix0, ix1, iz0, iz1 = -w / 2 + m, w / 2 - m, m, h - m
    yc = y0 + 0.6 * d
    if p.motif == "landscape":
        b.box((ix0, yc, iz0), (ix1, yc + 0.002, iz0 + 0.55 * (iz1 - iz0)), tint("#6f9a5a", "paint"))
        b.box((ix0, yc, iz0 + 0.55 * (iz1 - iz0)), (ix1, yc + 0.002, iz1), tint("#9cc3e0", "paint"))
        b.box((ix0 + 0.2 * (ix1 - ix0), yc + 0.002, iz0 + 0.45 * (iz1 - iz0)),
              (ix0 + 0.55 * (ix1 - ix0), yc + 0.004, iz0 + 0.7 * (iz1 - iz0)), tint("#5a6a7a", "paint"))
        b.sphere((ix0 + 0.8 * (ix1 - ix0), yc + 0.003, iz0 + 0.82 * (iz1 - iz0)),
                 (0.06 * (ix1 - ix0), 0.001, 0.06 * (ix1 - ix0)), tint("#f5d36a", "paint"), subdivisions=1)
    else:
        b.box((ix0, yc, iz0), (ix1, yc + 0.002, iz1), lighter(p.accent, 0.6))
        for _ in range(6 if p.motif == "abstract" else 4):
            cx, cz = rng.uniform(ix0, ix1), rng.uniform(iz0, iz1)
            sw = rng.uniform(0.1, 0.35) * (ix1 - ix0)
            sh = rng.uniform(0.1, 0.35) * (iz1 - iz0)
            c = ART[int(rng.integers(len(ART)))]
            x0c, x1c = max(ix0, cx - sw / 2), min(ix1, cx + sw / 2)
            z0c, z1c = max(iz0, cz - sh / 2), min(iz1, cz + sh / 2)
            if p.motif == "blocks":
                b.box((x0c, yc + 0.002, z0c), (x1c, yc + 0.004, z1c), c)
            else:
                b.sphere(((x0c + x1c) / 2, yc + 0.003, (z0c + z1c) / 2), ((x1c - x0c) / 2, 0.001, (z1c - z0c) / 2), c)
    return b.mesh(p.size)


def sample_mirror(rng, size, style):
    return make_params("mirror", rng, size, style, ["#c9a54a", "#2b2b2b", "#e8e6e0", "#5c3b26", METAL], "#d6e2e8",
                       METAL, oval=bool(rng.random() < 0.35))


def build_mirror(p):
    w, d, h = p.size
    b = Builder()
    if p.oval:
        b.rod((0, -d / 2, h / 2), (0, d / 2 - 0.005, h / 2), 1.0, p.primary, sections=32)
        b.rod((0, d / 2 - 0.01, h / 2), (0, d / 2, h / 2), 0.9, p.secondary, sections=32)
        m = b.mesh(p.size)
        return m
    f = min(0.04, 0.08 * min(w, h))
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.005, h), p.primary)
    b.box((-w / 2 + f, d / 2 - 0.01, f), (w / 2 - f, d / 2, h - f), p.secondary)
    return b.mesh(p.size)


def sample_clock(rng, size, style):
    return make_params("clock", rng, size, style, wood_tones(style) + [BLACK, "#e8e6e0", "#c9a54a"], "#f4f1ea",
                       BLACK)


def build_clock(p):
    w, d, h = p.size
    b = Builder()
    tall = h > 1.6 * w and h > 0.8
    if tall:  # a standing (grandfather) clock: case with the dial at the top
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.08 * h), darker(p.primary, 0.1))
        b.box((-w / 2 + 0.03, -d / 2, 0.08 * h), (w / 2 - 0.03, d / 2 - 0.02, 0.75 * h), p.primary)
        b.box((-w / 2 + 0.08, d / 2 - 0.02, 0.15 * h), (w / 2 - 0.08, d / 2 - 0.01, 0.7 * h), tint("#3a3530", "paint"), alpha=200)
        b.rod((0, d / 2 - 0.03, 0.65 * h), (0, d / 2 - 0.03, 0.35 * h), 0.008, tint("#c9a54a", "metal"))
        b.rod((0, d / 2 - 0.04, 0.33 * h), (0, d / 2 - 0.02, 0.33 * h), 0.05, tint("#c9a54a", "metal"))
        b.box((-w / 2, -d / 2, 0.75 * h), (w / 2, d / 2, h), p.primary)
        cz, r, fy = 0.87 * h, min(w, 0.25 * h) * 0.38, d / 2
    else:
        cz, r, fy = h / 2, min(w, h) / 2, d / 2
        b.rod((0, -d / 2, cz), (0, fy - 0.004, cz), r, p.primary, sections=32)
    b.rod((0, fy - 0.006, cz), (0, fy - 0.002, cz), r * 0.88, p.secondary, sections=32)
    for k in range(12):
        a = 2 * np.pi * k / 12
        b.cbox((np.sin(a) * r * 0.75, fy - 0.002, cz + np.cos(a) * r * 0.75), (r * 0.04, 0.002, r * 0.12),
               p.accent, transform=about(rot_y(a), (np.sin(a) * r * 0.75, fy, cz + np.cos(a) * r * 0.75)))
    b.box((-r * 0.03, fy - 0.002, cz), (r * 0.03, fy + 0.001, cz + r * 0.45), p.accent,
          transform=about(rot_y(0.9), (0, fy, cz)))
    b.box((-r * 0.02, fy - 0.002, cz), (r * 0.02, fy + 0.002, cz + r * 0.7), p.accent,
          transform=about(rot_y(-2.2), (0, fy, cz)))
    return b.mesh(p.size)


def sample_curtain(rng, size, style):
    return make_params("curtain", rng, size, style, fabric_tones(style) + ["#f0ebe0", "#d9c3a0"], METAL, "#e8e6e0",
                       folds=int(rng.integers(6, 12)), open=bool(rng.random() < 0.6))


def build_curtain(p):
    w, d, h = p.size
    b = Builder()
    rod_r = min(0.02, d / 3)
    b.rod((-w / 2, 0, h - rod_r), (w / 2, 0, h - rod_r), rod_r, p.secondary)
    for s in (-1, 1):
        b.sphere((s * (w / 2 - rod_r), 0, h - rod_r), rod_r * 1.6, p.secondary)
    panels = [(-w / 2, -w / 2 + 0.25 * w), (w / 2 - 0.25 * w, w / 2)] if p.open else [(-w / 2, 0), (0, w / 2)]
    for x0, x1 in panels:
        n = p.folds if not p.open else max(3, p.folds // 2)
        fw = (x1 - x0) / n
        for i in range(n):
            cx = x0 + (i + 0.5) * fw
            b.cyl(cx, 0, 0.0, h - 2 * rod_r, fw * 0.6, p.primary if i % 2 == 0 else darker(p.primary, 0.12),
                  ry=min(d / 2, fw * 0.6), sections=10)
    return b.mesh(p.size)


def sample_tapestry(rng, size, style):
    return make_params("tapestry", rng, size, style, RUGS, ["#c9a54a", "#e8dcc4"], RUGS, bands=int(rng.integers(3, 7)))


def build_tapestry(p):
    w, d, h = p.size
    b = Builder()
    rod = min(0.02, d / 2)
    b.rod((-w / 2, 0, h - rod), (w / 2, 0, h - rod), rod, tint("#5c3b26", "paint"))
    b.box((-w / 2 + 0.03, -d / 2, 0.06 * h), (w / 2 - 0.03, -d / 2 + 0.4 * d, h - 2 * rod), p.primary)
    for k, z in enumerate(np.linspace(0.12 * h, h - 0.1 * h, p.bands)):
        b.box((-w / 2 + 0.06, -d / 2 + 0.4 * d, z - 0.02 * h), (w / 2 - 0.06, -d / 2 + 0.45 * d, z + 0.02 * h),
              p.secondary if k % 2 else p.accent)
    b.sphere((0, -d / 2 + 0.42 * d, 0.5 * h), (0.18 * w, 0.01, 0.15 * h), p.secondary)
    for x in np.linspace(-w / 2 + 0.05, w / 2 - 0.05, 9):
        b.box((x - 0.005, -d / 2, 0), (x + 0.005, -d / 2 + 0.2 * d, 0.07 * h), p.secondary)
    return b.mesh(p.size)


def sample_yoga_mat(rng, size, style):
    return make_params("yoga_mat", rng, size, style, ["#7fa8c9", "#9b7fc9", "#7fc99b", "#c97f9b", "#3f4a5a"],
                       "#e8e6e0", BLACK, rolled_end=bool(rng.random() < 0.5))


def build_yoga_mat(p):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.006), p.primary)
    if p.rolled_end:
        r = max(h, 0.01) / 2
        b.rod((-w / 2, -d / 2 + r, r), (w / 2, -d / 2 + r, r), r, darker(p.primary, 0.1), sections=16)
    else:
        b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0.006), (w / 2 - 0.02, -d / 2 + 0.03, max(h, 0.007)), p.secondary)
    return b.mesh(p.size)


def sample_vase(rng, size, style):
    return make_params("vase", rng, size, style, ["#3f6f9a", "#e8e6e0", "#b5654a", "#2b2b2b", "#c9a54a", "#6f9a8a"],
                       ["#e05a8a", "#f2c12e", "#ffffff", "#e07a3a"], "#3e7a3a",
                       flowers=bool(rng.random() < 0.5), neck=float(rng.uniform(0.25, 0.6)))


def build_vase(p):
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    vh = h * (0.6 if p.flowers else 1.0)
    n = p.neck
    b.lathe([[0, 0], [r * 0.5, 0], [r * 0.95, 0.35 * vh], [r * n, 0.8 * vh], [r * n * 0.9, 0.92 * vh],
             [r * (n + 0.15), vh], [r * n * 0.8, vh], [0, 0.95 * vh]], p.primary)
    if p.flowers:
        rng = np.random.default_rng(p.seed)
        for _ in range(7):
            a = rng.uniform(0, 2 * np.pi)
            tip = (np.cos(a) * r * 0.8, np.sin(a) * r * 0.8, h * rng.uniform(0.85, 0.95))
            b.rod((0, 0, vh * 0.8), tip, 0.004, p.accent, sections=6)
            b.sphere(tip, r * 0.18, p.secondary, subdivisions=0)
    return b.mesh(p.size)


def sample_book(rng, size, style):
    return make_params("book", rng, size, style, ["#8b2e2e", "#2e4a8b", "#2f6b45", "#c8a24a", "#5a3a6e", "#1f1f22"],
                       "#f2ede0", "#c9a54a")


def build_book(p):
    """A book lying flat if it is lower than it is wide, else standing; spine on local -x."""
    w, d, h = p.size
    b = Builder()
    c = min(0.004, 0.08 * min(w, d, h))
    if h <= w:
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, c), p.primary)
        b.box((-w / 2, -d / 2, h - c), (w / 2, d / 2, h), p.primary)
        b.box((-w / 2, -d / 2, 0), (-w / 2 + c, d / 2, h), p.primary)
        b.box((-w / 2 + c, -d / 2 + c, c), (w / 2 - c, d / 2 - c, h - c), p.secondary)
        b.box((-w / 2, -d / 2 + 0.2 * d, h * 0.3), (-w / 2 - 0.001, -d / 2 + 0.25 * d, h * 0.7), p.accent)
    else:
        b.box((-w / 2, -d / 2, 0), (-w / 2 + c, d / 2, h), p.primary)
        b.box((w / 2 - c, -d / 2, 0), (w / 2, d / 2, h), p.primary)
        b.box((-w / 2, d / 2 - c, 0), (w / 2, d / 2, h), p.primary)
        b.box((-w / 2 + c, -d / 2 + c, c), (w / 2 - c, d / 2 - c, h - c), p.secondary)
        b.box((-w / 2 + c, d / 2, 0.7 * h), (w / 2 - c, d / 2 + 0.001, 0.75 * h), p.accent)
    return b.mesh(p.size)


def sample_statue(rng, size, style):
    return make_params("statue", rng, size, style, ["#e6e2d8", "#8a6a3a", "#9a9da3", "#b5a58a", "#3a3a3c"],
                       "#cfcac0", "#cfcac0", plinth=bool(rng.random() < 0.6), pose=float(rng.uniform(-0.4, 0.4)))


def build_statue(p):
    w, d, h = p.size
    b = Builder()
    z = 0.0
    if p.plinth:
        z = 0.18 * h
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, z), p.secondary)
        b.box((-w / 2 * 0.9, -d / 2 * 0.9, z), (w / 2 * 0.9, d / 2 * 0.9, z + 0.02 * h), darker(p.secondary, 0.1))
        z += 0.02 * h
    fh = h - z
    s = min(w, d) / 2
    c = p.primary
    b.cyl(0, 0, z, z + 0.05 * fh, s * 0.6, c, ry=s * 0.5)
    for sx in (-1, 1):  # legs
        b.rod((sx * s * 0.2, 0, z + 0.05 * fh), (sx * s * 0.25, 0, z + 0.45 * fh), s * 0.14, c)
    b.sphere((0, 0, z + 0.62 * fh), (s * 0.45, s * 0.3, 0.2 * fh), c)  # torso
    b.sphere((0, 0, z + 0.9 * fh), (s * 0.18, s * 0.18, 0.1 * fh), c)  # head
    b.rod((0, 0, z + 0.78 * fh), (0, 0, z + 0.84 * fh), s * 0.08, c)
    b.rod((-s * 0.42, 0, z + 0.75 * fh), (-s * 0.7, s * 0.2, z + 0.45 * fh), s * 0.08, c)
    b.rod((s * 0.42, 0, z + 0.75 * fh), (s * 0.75, s * 0.2 * np.sign(p.pose + 1e-9), z + 0.75 * fh + p.pose * fh * 0.4),
          s * 0.08, c)
    return b.mesh(p.size)


def sample_barrel(rng, size, style):
    return make_params("barrel", rng, size, style, ["#8f6642", "#a0714a", "#6b4330", "#3f6f9a"], DARK_METAL,
                       "#5c3b26", hoops=int(rng.integers(2, 4)))


def build_barrel(p):
    w, d, h = p.size
    b = Builder()
    r = min(w, d) / 2
    prof = [[0, 0]] + [[r * (0.86 + 0.14 * np.sin(np.pi * t)), h * t] for t in np.linspace(0, 1, 9)] + [[0, h]]
    b.lathe(prof, p.primary, sections=24)
    for t in np.linspace(0.12, 0.88, p.hoops * 2 - 1 if p.hoops > 2 else 3):
        rr = r * (0.86 + 0.14 * np.sin(np.pi * t)) + 0.004
        b.cyl(0, 0, h * t - 0.02, h * t + 0.02, rr, p.secondary, sections=24)
    b.cyl(0, 0, h - 0.001, h + 0.002, r * 0.8, darker(p.primary, 0.25), sections=24)
    return b.mesh(p.size)


slot_roles("lamp", {"": "ceramic", METAL: "metal", "#c9a54a": "metal"}, "fabric", "metal")
register("lamp", sample_lamp, build_lamp)
slot_roles("floor_lamp", "metal", "fabric", "metal")
register("floor_lamp", sample_floor_lamp, build_floor_lamp)
slot_roles("rug", "fabric", "fabric", "fabric")
register("rug", sample_rug, build_rug)
slot_roles("plant", "ceramic", "plant", "plant")
register("plant", sample_plant, build_plant)
slot_roles("wall_art", "wood", "paper", "paint")
register("wall_art", sample_wall_art, build_wall_art)
slot_roles("mirror", {"": "paint", METAL: "metal", "#c9a54a": "metal"}, "glass", "metal")
register("mirror", sample_mirror, build_mirror)
slot_roles("clock", {"": "wood", "#c9a54a": "metal"}, "paper", "plastic")
register("clock", sample_clock, build_clock)
slot_roles("curtain", "fabric", "metal", "plastic")
register("curtain", sample_curtain, build_curtain)
slot_roles("tapestry", "fabric", "metal", "fabric")
register("tapestry", sample_tapestry, build_tapestry)
slot_roles("yoga_mat", "rubber", "rubber", "plastic")
register("yoga_mat", sample_yoga_mat, build_yoga_mat)
slot_roles("vase", {"": "ceramic", "#c9a54a": "metal"}, "plant", "plant")
register("vase", sample_vase, build_vase)
slot_roles("book", "paper", "paper", "metal")
register("book", sample_book, build_book)
slot_roles("statue", {"": "stone", "#9a9da3": "metal"}, "stone", "stone")
register("statue", sample_statue, build_statue)
slot_roles("barrel", "wood", "metal", "wood")
register("barrel", sample_barrel, build_barrel)
