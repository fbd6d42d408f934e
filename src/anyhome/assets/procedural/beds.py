"""Beds: bed, floor_futon, bunk_bed, crib."""

from __future__ import annotations

import numpy as np
import trimesh

from anyhome.assets.procedural._parts import (
    TEXTILE_WHITE,
    Builder,
    Params,
    Size,
    corners,
    darker,
    fabric_tones,
    leg_style,
    lighter,
    make_params,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register
from anyhome.assets.styles import Style

MATTRESS_TOP_M = (0.45, 0.62)
"""Height range of a bed's mattress top; the bed's box reaches up to its headboard."""
BEDDING = tint(["#e9e4da", "#d7dde6", "#c8b8a6", "#9fb2a0", "#b9a2b8", "#d9c3a0", "#8a9bb0"], "fabric")


def sample_bed(rng: np.random.Generator, size: Size, style: Style) -> Params:
    return make_params(
        "bed", rng, size, style, wood_tones(style), TEXTILE_WHITE, BEDDING + fabric_tones(style),
        legs=leg_style(rng, style),
        headboard="upholstered" if rng.random() < 0.35 and not style_is(style, "rustic") else "panel",
        footboard=bool(rng.random() < (0.6 if style_is(style, "antique") else 0.25)),
        mattress_top=float(rng.uniform(0.48, 0.58)),
        pillows=int(rng.integers(1, 3)),
    )


def build_bed(p: Params) -> trimesh.Trimesh:
    w, d, h = p.size
    h = max(h, 0.3)
    b = Builder()
    # the box holds the headboard: the mattress top stays at a sitting height whatever the box
    top = min(float(np.clip(p.mattress_top * h, MATTRESS_TOP_M[0], MATTRESS_TOP_M[1])), h - 0.05)
    rail = top * 0.55
    leg = rail * 0.45
    # frame and legs
    b.box((-w / 2, -d / 2 + 0.06, leg), (w / 2, d / 2, rail), p.primary)
    b.legs(corners(w, d, 0.05), 0, leg, 0.035, p.legs, p.primary)
    # headboard
    hb = p.secondary if p.headboard == "upholstered" else p.primary
    b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + 0.06, h * 0.97), darker(p.primary, 0.1))
    if p.headboard == "upholstered":
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, top * 0.9), (w / 2 - 0.05, -d / 2 + 0.1, h), lighter(p.accent, 0.3))
    else:
        b.box((-w / 2 - 0.0, -d / 2, h * 0.97), (w / 2, -d / 2 + 0.07, h), hb)
    if p.footboard:
        b.box((-w / 2, d / 2 - 0.05, 0), (w / 2, d / 2, top + 0.12), p.primary)
    # mattress, duvet, pillows
    m = 0.03
    b.box((-w / 2 + m, -d / 2 + 0.07, rail), (w / 2 - m, d / 2 - m, top), TEXTILE_WHITE)
    b.box((-w / 2 + m - 0.01, -d / 2 + 0.07 + 0.32 * d, top - 0.12),
          (w / 2 - m + 0.01, d / 2 - m + 0.005, top + 0.025), p.accent)
    b.box((-w / 2 + m - 0.011, -d / 2 + 0.07 + 0.3 * d, top - 0.02),
          (w / 2 - m + 0.011, -d / 2 + 0.07 + 0.38 * d, top + 0.03), lighter(p.accent, 0.5))
    n = 2 if w > 1.1 else 1
    n = max(n, p.pillows if w > 1.1 else 1)
    pw = (w - 2 * m - 0.1) / n
    for i in range(n):
        cx = -w / 2 + m + 0.05 + pw * (i + 0.5)
        b.sphere((cx, -d / 2 + 0.2, top + 0.05), (pw * 0.45, 0.14, 0.07), lighter(p.secondary, 0.2))
    return b.mesh(p.size)


def sample_floor_futon(rng: np.random.Generator, size: Size, style: Style) -> Params:
    return make_params("floor_futon", rng, size, style, ["#efe8da", "#e6dccb", "#f2efe8"], TEXTILE_WHITE,
                       BEDDING + fabric_tones(style), fold=float(rng.uniform(0.0, 0.25)))


def build_floor_futon(p: Params) -> trimesh.Trimesh:
    """A Japanese futon laid on the floor: a thin mattress (shikibuton), a quilt
    (kakebuton) over most of it, turned back by ``fold``, and one small pillow."""
    w, d, h = p.size
    h = min(max(h, 0.08), 0.25)
    b = Builder()
    mat = h * 0.55
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, mat), p.primary)
    quilt_y0 = -d / 2 + 0.3 * d + p.fold * d * 0.5
    b.box((-w / 2 - 0.01, quilt_y0, mat), (w / 2 + 0.01, d / 2 + 0.005, h * 0.85), p.accent)
    b.box((-w / 2 - 0.011, quilt_y0, h * 0.8), (w / 2 + 0.011, quilt_y0 + 0.1, h), lighter(p.accent, 0.25))
    b.sphere((0, -d / 2 + 0.17, mat + 0.04), (min(0.25, w * 0.3), 0.11, 0.05), lighter(p.secondary, 0.2))
    return b.mesh(p.size)


def sample_bunk_bed(rng: np.random.Generator, size: Size, style: Style) -> Params:
    return make_params("bunk_bed", rng, size, style, wood_tones(style) + ["#e8e6e0", "#3a3b3e"],
                       TEXTILE_WHITE, BEDDING, ladder_right=bool(rng.random() < 0.5))


def build_bunk_bed(p: Params) -> trimesh.Trimesh:
    w, d, h = p.size
    b = Builder()
    post = 0.04
    for x, y in corners(w, d, post):
        b.box((x - post, y - post, 0), (x + post, y + post, h), p.primary)
    for z in (0.18 * h, 0.6 * h):
        b.box((-w / 2, -d / 2, z - 0.08), (w / 2, d / 2, z), p.primary)
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, z), (w / 2 - 0.05, d / 2 - 0.05, z + 0.14), TEXTILE_WHITE)
        b.box((-w / 2 + 0.045, -d / 2 + 0.3 * d, z + 0.1), (w / 2 - 0.045, d / 2 - 0.045, z + 0.16), p.accent)
        b.sphere((0, -d / 2 + 0.22, z + 0.18), (w * 0.3, 0.12, 0.05), lighter(p.secondary, 0.2))
    # guard rails on the top bunk
    for y in (-d / 2 + 0.02, d / 2 - 0.02):
        b.box((-w / 2, y - 0.02, h - 0.06), (w / 2, y + 0.02, h - 0.02), p.primary)
    # ladder on the front (+y) side
    lx = w / 2 - 0.3 if p.ladder_right else -w / 2 + 0.3
    for dx in (-0.17, 0.17):
        b.box((lx + dx - 0.02, d / 2 - 0.04, 0), (lx + dx + 0.02, d / 2, 0.92 * h), p.primary)
    for z in np.linspace(0.15 * h, 0.85 * h, 5):
        b.rod((lx - 0.17, d / 2 - 0.02, z), (lx + 0.17, d / 2 - 0.02, z), 0.015, darker(p.primary, 0.2))
    return b.mesh(p.size)


def sample_crib(rng: np.random.Generator, size: Size, style: Style) -> Params:
    return make_params("crib", rng, size, style, ["#f2efe8", "#e8dccb", "#d8bf98", "#c9d6df", "#f0d9dd"],
                       TEXTILE_WHITE, ["#f4c7d0", "#bcd6ea", "#f3e3a6", "#c9e3c4"],
                       slats=int(rng.integers(9, 15)))


def build_crib(p: Params) -> trimesh.Trimesh:
    w, d, h = p.size
    b = Builder()
    post = 0.03
    for x, y in corners(w, d, post):
        b.box((x - post, y - post, 0), (x + post, y + post, h), p.primary)
    base = 0.35 * h
    b.box((-w / 2, -d / 2, base - 0.05), (w / 2, d / 2, base), p.primary)
    b.box((-w / 2 + 0.05, -d / 2 + 0.05, base), (w / 2 - 0.05, d / 2 - 0.05, base + 0.1), p.accent)
    for y in (-d / 2 + 0.02, d / 2 - 0.02):
        b.box((-w / 2, y - 0.02, h - 0.04), (w / 2, y + 0.02, h), p.primary)
        b.box((-w / 2, y - 0.02, base - 0.04), (w / 2, y + 0.02, base), p.primary)
        for x in np.linspace(-w / 2 + 0.08, w / 2 - 0.08, p.slats):
            b.box((x - 0.012, y - 0.012, base), (x + 0.012, y + 0.012, h - 0.04), p.primary)
    for x in (-w / 2 + 0.02, w / 2 - 0.02):
        b.box((x - 0.02, -d / 2, h - 0.04), (x + 0.02, d / 2, h), p.primary)
        for y in np.linspace(-d / 2 + 0.08, d / 2 - 0.08, max(3, p.slats // 2)):
            b.box((x - 0.012, y - 0.012, base), (x + 0.012, y + 0.012, h - 0.04), p.primary)
    return b.mesh(p.size)


slot_roles("bed", "wood", "fabric", "fabric")
register("bed", sample_bed, build_bed)
slot_roles("floor_futon", "fabric", "fabric", "fabric")
register("floor_futon", sample_floor_futon, build_floor_futon)
slot_roles("bunk_bed", "wood", "fabric", "fabric")
register("bunk_bed", sample_bunk_bed, build_bunk_bed)
slot_roles("crib", "wood", "fabric", "fabric")
register("crib", sample_crib, build_crib)
