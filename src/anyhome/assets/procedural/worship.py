"""Worship and speaking: lectern (also pulpit and music stand), pew, altar."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    TEXTILE_WHITE,
    Builder,
    about,
    darker,
    fabric_tones,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

BRASS = tint("#c9a54a", "metal")
ALTAR_FRONTALS = tint(["#7a1f2b", "#4a2a6a", "#2f5a3a", "#c9a54a", "#e8e2d4"], "fabric")


# ----------------------------------------------------------------- lectern / pulpit / music stand
def sample_lectern(rng, size, style):
    w, d, h = size
    antique = style_is(style, "antique")
    kind = "pulpit" if w >= 0.9 else str(rng.choice(["panel", "pedestal", "stand"], p=[0.55, 0.3, 0.15]))
    if kind == "pedestal" and not antique and rng.random() < 0.5:
        kind = "panel"
    return make_params("lectern", rng, size, style, wood_tones(style) + (["#2b2b2b", "#e8e6e0"] if not antique else []),
                       ["#7a1f2b", "#2a2a44", BRASS], BRASS, kind=kind, emblem=bool(rng.random() < 0.5),
                       mic=bool(kind == "panel" and rng.random() < 0.5))


def _desk(b: Builder, w: float, y0: float, y1: float, z_low: float, z_high: float, color: str) -> None:
    """Sloping reading desk: low edge at y0 (the reader), high edge at y1."""
    t = 0.03
    b.hull([(-w / 2, y0, z_low), (w / 2, y0, z_low), (-w / 2, y1, z_high), (w / 2, y1, z_high),
            (-w / 2, y0, z_low - t), (w / 2, y0, z_low - t), (-w / 2, y1, z_high - t), (w / 2, y1, z_high - t)],
           color)
    b.box((-w / 2, y0 - 0.015, z_low - 0.01), (w / 2, y0, z_low + 0.03), darker(color, 0.15))  # book lip


def build_lectern(p):
    """The reader stands at -y; the audience sees the front (+y)."""
    w, d, h = p.size
    b = Builder()
    slope = min(0.12, 0.25 * d)
    if p.kind == "stand":
        R = 0.45 * min(w, d)
        for i in range(3):
            a = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0, 0, 0.15 * h), (R * np.cos(a), R * np.sin(a), 0.0), 0.01, BLACK, sections=6)
        b.cyl(0, 0, 0.1 * h, h - 0.35 * d, 0.012, BLACK, sections=8)
        _desk(b, w, -d / 2, d / 2, h - slope - 0.25 * d, h, BLACK)
        return b.mesh(p.size)
    if p.kind == "pulpit":
        z_floor = min(0.3, 0.2 * h)
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, z_floor), darker(p.primary, 0.15))  # raised floor
        b.box((-w / 2, -d / 2 + 0.2 * d, z_floor), (w / 2, d / 2, h - slope - 0.03), p.primary)
        for i in range(3):  # raised front panels
            x = -w / 2 + (i + 0.5) * w / 3
            b.cbox((x, d / 2 + 0.005, (z_floor + h - slope) / 2), (w / 3 - 0.1, 0.02, 0.55 * (h - slope - z_floor)),
                   lighter(p.primary, 0.08))
        b.box((-w / 2, -d / 2 + 0.2 * d, h - slope - 0.04), (w / 2, d / 2, h - slope), darker(p.primary, 0.2))
        _desk(b, 0.6 * w, 0.1 * d, d / 2 - 0.02, h - slope, h, p.primary)
        for k in range(2):  # steps at the back
            b.box((-0.3 * w, -d / 2 + k * 0.1 * d, 0), (0.3 * w, -d / 2 + (k + 1) * 0.1 * d, z_floor * (1 - 0.4 * k)),
                  p.primary)
        if p.emblem:
            b.cbox((0, d / 2 + 0.02, 0.62 * h), (0.04, 0.02, 0.28 * h), p.accent)
            b.cbox((0, d / 2 + 0.02, 0.68 * h), (0.18, 0.02, 0.04), p.accent)
        return b.mesh(p.size)
    if p.kind == "pedestal":
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, 0), (w / 2 - 0.05, d / 2 - 0.05, 0.06), p.primary)
        b.cyl(0, 0, 0.06, h - slope - 0.1, 0.07, p.primary, r_top=0.05, sections=16)
        b.sphere((0, 0, 0.3 * h), (0.1, 0.1, 0.08), p.primary)
        b.box((-0.35 * w, -0.35 * d, h - slope - 0.12), (0.35 * w, 0.35 * d, h - slope - 0.02), p.primary)
        _desk(b, w, -d / 2, d / 2, h - slope, h, p.primary)
        return b.mesh(p.size)
    # panel podium, wider at the top
    top = h - slope
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.02, 0.06), darker(p.primary, 0.2))
    b.hull([(-0.38 * w, -0.3 * d, 0.06), (0.38 * w, -0.3 * d, 0.06), (-0.38 * w, 0.4 * d, 0.06),
            (0.38 * w, 0.4 * d, 0.06), (-0.46 * w, -0.3 * d, top), (0.46 * w, -0.3 * d, top),
            (-0.46 * w, 0.45 * d, top), (0.46 * w, 0.45 * d, top)], p.primary)
    _desk(b, w, -d / 2, d / 2 - 0.01, top, h, lighter(p.primary, 0.05))
    if p.emblem:
        b.rod((0, 0.43 * d, 0.62 * h), (0, 0.43 * d + 0.02, 0.62 * h), 0.1 * w, p.secondary, sections=20)
        b.rod((0, 0.43 * d + 0.02, 0.62 * h), (0, 0.43 * d + 0.025, 0.62 * h), 0.06 * w, p.accent, sections=20)
    if p.mic:
        b.rod((0.3 * w, 0.2 * d, h - 0.01), (0.15 * w, -0.2 * d, h), 0.006, BLACK, sections=4)
    return b.mesh(p.size)


# ----------------------------------------------------------------- pew
def sample_pew(rng, size, style):
    antique = style_is(style, "antique")
    return make_params("pew", rng, size, style, wood_tones(style), fabric_tones(style), BRASS,
                       cushion=bool(rng.random() < 0.5), finial=bool(antique or rng.random() < 0.3),
                       kneeler=bool(rng.random() < 0.6))


def build_pew(p):
    """A long bench with a tall back; the sitters face +y, the kneeler and book rack of the
    row behind hang on the back (-y)."""
    w, d, h = p.size
    b = Builder()
    seat = min(0.45, 0.48 * h)
    yb = -d / 2 + (0.2 * d if p.kneeler else 0.04)
    end = 0.05
    b.box((-w / 2 + end, yb, seat - 0.05), (w / 2 - end, d / 2 - 0.03, seat), p.primary)
    if p.cushion:
        b.box((-w / 2 + end, yb + 0.05, seat), (w / 2 - end, d / 2 - 0.05, seat + 0.04), p.secondary)
    recline = 0.12
    b.box((-w / 2 + end, yb, seat), (w / 2 - end, yb + 0.035, h - 0.04), p.primary,
          transform=about(rot_x(recline), (0, yb, seat)))
    b.box((-w / 2 + end, yb - 0.02, h - 0.06), (w / 2 - end, yb + 0.07, h - 0.02), darker(p.primary, 0.1),
          transform=about(rot_x(recline), (0, yb, seat)))
    b.box((-w / 2 + end, -0.05 * d, 0.06), (w / 2 - end, 0.0, 0.12), darker(p.primary, 0.2))  # stretcher
    for sx in (-1, 1):  # shaped end panels
        x0, x1 = (sx * w / 2, sx * (w / 2 - end))
        lo, hi = min(x0, x1), max(x0, x1)
        top = 0.86 * h if p.finial else h - 0.06
        b.box((lo, -d / 2 + 0.02, 0), (hi, d / 2, seat + 0.12), p.primary)
        b.box((lo, yb - 0.03, 0), (hi, yb + 0.22 * d, top), p.primary)
        b.rod((lo, yb + 0.22 * d, seat + 0.12), (hi, yb + 0.22 * d, seat + 0.12), min(0.2 * d, 0.35 * d), p.primary,
              sections=16)
        if p.finial:
            b.sphere(((lo + hi) / 2, yb + 0.1 * d, top + 0.05), (end * 0.9, 0.06, 0.06), p.primary)
            b.cyl((lo + hi) / 2, yb + 0.1 * d, top - 0.02, h - 0.1, end * 0.45, p.primary, sections=8)
            b.sphere(((lo + hi) / 2, yb + 0.1 * d, h - 0.05), (end * 0.7, 0.05, 0.05), p.primary)
    if p.kneeler:
        b.box((-w / 2 + end, -d / 2, 0.08), (w / 2 - end, -d / 2 + 0.15 * d, 0.16), p.secondary)
        b.box((-w / 2 + end, yb - 0.1, 0.62 * h), (w / 2 - end, yb - 0.005, 0.66 * h), darker(p.primary, 0.1))
    return b.mesh(p.size)


# ----------------------------------------------------------------- altar
def sample_altar(rng, size, style):
    antique = style_is(style, "antique")
    stone = ["#d8d0c0", "#c9c1b0", "#e8e2d4"]
    return make_params("altar", rng, size, style, stone if antique else wood_tones(style) + stone, TEXTILE_WHITE,
                       ALTAR_FRONTALS, candles=int(rng.choice([2, 2, 4])), cross=bool(rng.random() < 0.6))


def build_altar(p):
    """A table under a white cloth with a coloured frontal, candlesticks and a cross or book."""
    w, d, h = p.size
    b = Builder()
    table = 0.72 * h
    b.box((-w / 2 + 0.04, -d / 2 + 0.04, 0), (w / 2 - 0.04, d / 2 - 0.04, table - 0.02), p.primary)
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.02, 0.08), darker(p.primary, 0.15))
    b.box((-w / 2, -d / 2, table - 0.02), (w / 2, d / 2, table), p.secondary)  # cloth
    drop = 0.25 * table
    for sx in (-1, 1):
        b.box((sx * w / 2 - 0.01 * (sx < 0), -d / 2, table - drop), (sx * w / 2 + 0.01 * (sx > 0), d / 2, table),
              p.secondary)
    b.box((-w / 2, d / 2, table - drop), (w / 2, d / 2 + 0.01, table), p.secondary)
    fw = 0.5 * w
    b.box((-fw / 2, d / 2 + 0.01, 0.15 * table), (fw / 2, d / 2 + 0.02, table - 0.01), p.accent)  # frontal
    b.box((-fw / 2, d / 2 + 0.02, table - drop * 0.6), (fw / 2, d / 2 + 0.025, table - drop * 0.5), BRASS)
    b.box((-0.02, d / 2 + 0.02, 0.3 * table), (0.02, d / 2 + 0.025, 0.8 * table), BRASS)
    b.box((-0.08, d / 2 + 0.02, 0.62 * table), (0.08, d / 2 + 0.025, 0.66 * table), BRASS)
    n = p.candles
    stick = 0.6 * (h - table)
    for i in range(n):
        x = (-0.38 + 0.76 * i / (n - 1)) * w if n > 1 else 0.3 * w
        if abs(x) < 0.12 * w:
            continue
        b.lathe([[0, table], [0.05, table], [0.015, table + 0.05 * stick], [0.012, table + 0.55 * stick],
                 [0.03, table + 0.6 * stick], [0, table + 0.6 * stick]], BRASS, x=x, y=-0.1 * d, sections=12)
        b.cyl(x, -0.1 * d, table + 0.6 * stick, table + stick, 0.015, tint("#f4f1e6", "paint"), sections=10)
        b.sphere((x, -0.1 * d, table + stick + 0.015), (0.008, 0.008, 0.018), tint("#ffb030", "light"), subdivisions=0)
    if p.cross:
        b.box((-0.015, -0.2 * d - 0.015, table), (0.015, -0.2 * d + 0.015, h), BRASS)
        b.box((-0.09, -0.2 * d - 0.015, table + 0.65 * (h - table)), (0.09, -0.2 * d + 0.015,
                                                                       table + 0.73 * (h - table)), BRASS)
        b.cbox((0, -0.2 * d, table + 0.02), (0.1, 0.08, 0.04), BRASS)
    else:
        b.box((-0.12, -0.1 * d, table), (0.12, 0.05 * d + 0.05, table + 0.05), tint("#7a1f2b", "paper"))  # a book
        b.box((-0.11, -0.1 * d + 0.01, table + 0.05), (0.11, 0.05 * d + 0.04, table + 0.055), tint("#f4f1e6", "paint"))
        b.cyl(0, -0.2 * d, table, h, 0.01, BRASS, sections=8)  # and a tall processional candle
        b.sphere((0, -0.2 * d, h - 0.02), 0.02, tint("#ffb030", "light"), subdivisions=0)
    return b.mesh(p.size)


slot_roles("lectern", "wood", {"": "fabric", BRASS: "metal"}, "metal")
register("lectern", sample_lectern, build_lectern)
slot_roles("pew", "wood", "fabric", "metal")
register("pew", sample_pew, build_pew)
slot_roles("altar", "wood", "fabric", "fabric")
register("altar", sample_altar, build_altar)
