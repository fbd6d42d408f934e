"""Exhibits, curiosities and wall features: plinth, model_ship, sarcophagus, rope_barrier,
cannon, spinner_rack, mounted_antlers, barber_pole, dartboard, archery_target."""

from __future__ import annotations

import numpy as np
import trimesh

from anyhome.assets.colors import to_rgba
from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    disc_y,
    extrude_y,
    path,
    ring_y,
    sag,
    sector_y,
    wheel_y,
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
    move,
    rot_y,
    rot_z,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

STONES = tint(["#e8e4dc", "#f4f4f2", "#d9d3c7", "#c9c1b4", "#2b2b2b"], "stone")
GOLD = tint("#d4af37", "metal")
LAPIS = tint("#2a4a8a", "stone")
SAIL = tint("#efe6d0", "fabric")
CARD_COLORS = tint(["#e05a47", "#2e86c1", "#f1c40f", "#27ae60", "#8e44ad", "#f08a2a", "#4ab0c0", "#ec7fa9", "#f4f1ea"], "paper")
ANTLER = tint("#e0d0b0", "stone")
FUR = tint(["#8a5a3a", "#7a4a2a", "#a0703a"], "fabric")
DART_CREAM = tint("#efe2c0", "fabric")
DART_RED = tint("#c0302a", "fabric")
DART_GREEN = tint("#2a7a3a", "fabric")


# ----------------------------------------------------------------- plinth
def sample_plinth(rng, size, style):
    if style_is(style, "antique"):
        kind = str(rng.choice(["classic", "column"]))
    elif style_is(style, "modern"):
        kind = "modern"
    else:
        kind = str(rng.choice(["modern", "column", "classic", "classic"]))
    return make_params("plinth", rng, size, style, STONES, "#c9c1b4", BLACK, kind=kind)


def build_plinth(p):
    """A display plinth: a moulded stone pedestal (base, shaft, cornice), a round column
    pedestal, or a plain modern white block with a shadow gap at the foot."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "modern":
        b.box((-0.46 * w, -0.46 * d, 0), (0.46 * w, 0.46 * d, 0.03 * h), p.accent)
        b.box((-w / 2, -d / 2, 0.03 * h), (w / 2, d / 2, h), p.primary)
        b.box((-w / 2 - 0.001, -d / 2 - 0.001, h - 0.005), (w / 2 + 0.001, d / 2 + 0.001, h), lighter(p.primary, 0.2))
        return b.mesh(p.size)
    if p.kind == "column":
        R = 0.5 * min(w, d)
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.06 * h), p.primary)
        b.lathe([[0, 0.06 * h], [0.9 * R, 0.06 * h], [0.9 * R, 0.09 * h], [0.78 * R, 0.12 * h], [0.7 * R, 0.14 * h],
                 [0.62 * R, 0.16 * h], [0.6 * R, 0.84 * h], [0.68 * R, 0.87 * h], [0.85 * R, 0.91 * h],
                 [0.85 * R, 0.94 * h], [0, 0.94 * h]], p.primary, sections=28)
        for k in range(16):  # flutes
            a = 2 * np.pi * k / 16
            b.box((0.6 * R * np.cos(a) - 0.005, 0.6 * R * np.sin(a) - 0.005, 0.18 * h),
                  (0.6 * R * np.cos(a) + 0.005, 0.6 * R * np.sin(a) + 0.005, 0.82 * h), darker(p.primary, 0.08))
        b.box((-w / 2, -d / 2, 0.94 * h), (w / 2, d / 2, h), p.primary)
        return b.mesh(p.size)
    steps = [(0.0, 0.05, 0.5), (0.05, 0.09, 0.47), (0.09, 0.12, 0.43), (0.12, 0.84, 0.4), (0.84, 0.87, 0.43),
             (0.87, 0.92, 0.47), (0.92, 1.0, 0.5)]
    for z0, z1, s in steps:
        col = p.primary if s < 0.42 or z0 == 0 or z1 == 1.0 else lighter(p.primary, 0.08)
        b.box((-s * w, -s * d, z0 * h), (s * w, s * d, z1 * h), col)
    b.box((-0.3 * w, 0.4 * d, 0.3 * h), (0.3 * w, 0.402 * d, 0.7 * h), darker(p.primary, 0.06))  # panel
    return b.mesh(p.size)


# ----------------------------------------------------------------- model ship
def sample_model_ship(rng, size, style):
    return make_params("model_ship", rng, size, style, ["#5c3b26", "#4a2f20", "#6b4330", BLACK],
                       wood_tones("antique"), [GOLD, "#c0392b", "#e8e6e0"], masts=int(rng.integers(2, 4)))


def _draw_ship(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x, bow at +x: a stand with two cradles, the hull with a coloured wale, a
    raised stern castle, masts with square sails on their yards, a bowsprit and rigging."""
    base = 0.05 * H
    b.box((-0.32 * L, -0.4 * B, 0), (0.32 * L, 0.4 * B, base), p.secondary)
    for x in (-0.15 * L, 0.15 * L):
        b.box((x - 0.02 * L, -0.08 * B, base), (x + 0.02 * L, 0.08 * B, base + 0.12 * H), darker(p.secondary, 0.2))
    keel = base + 0.1 * H
    deck = keel + 0.2 * H
    n = 10
    prev = None
    for k in range(n + 1):
        t = -1 + 2 * k / n
        x = t * 0.4 * L
        bw = 0.45 * B * np.sqrt(max(0.02, 1 - max(0.0, t) ** 2.2 - 0.3 * max(0.0, -t) ** 4))
        zk = keel + 0.06 * H * t ** 4
        sec = [(x, -bw, deck + 0.02 * H * t ** 2), (x, bw, deck + 0.02 * H * t ** 2), (x, -0.7 * bw, zk + 0.07 * H),
               (x, 0.7 * bw, zk + 0.07 * H), (x, 0.0, zk)]
        if prev is not None:
            b.hull(prev + sec, p.primary)
        prev = sec
    b.box((-0.4 * L, -0.46 * B, deck - 0.04 * H), (0.35 * L, 0.46 * B, deck - 0.025 * H), p.accent)  # wale
    b.box((-0.4 * L, -0.38 * B, deck), (0.3 * L, 0.38 * B, deck + 0.01 * H), lighter(p.secondary, 0.1))  # deck
    b.box((-0.44 * L, -0.4 * B, deck), (-0.26 * L, 0.4 * B, deck + 0.1 * H), p.primary)  # stern castle
    b.box((-0.45 * L, -0.3 * B, deck + 0.03 * H), (-0.44 * L, 0.3 * B, deck + 0.08 * H), p.accent)
    b.rod((0.38 * L, 0, deck + 0.02 * H), (L / 2, 0, deck + 0.12 * H), 0.006, p.secondary, sections=5)  # bowsprit
    xs = np.linspace(-0.2 * L, 0.22 * L, p.masts) if p.masts > 1 else [0.0]
    top = H - 0.04 * H
    for i, x in enumerate(xs):
        mt = top - (0.08 * H if i != len(xs) // 2 else 0.0)
        b.cyl(x, 0, deck, mt, 0.008, p.secondary, sections=6)
        for j, (z0, z1) in enumerate(((deck + 0.1 * H, deck + 0.32 * H), (deck + 0.36 * H, mt - 0.06 * H))):
            if z1 <= z0:
                continue
            sw = (0.42 - 0.1 * j) * B * 2
            b.rod((x, -sw / 2, z1), (x, sw / 2, z1), 0.004, p.secondary, sections=4)
            b.hull([(x, -sw / 2, z1), (x, sw / 2, z1), (x + 0.005, -0.45 * sw, z0), (x + 0.005, 0.45 * sw, z0),
                    (x + 0.04 * L, 0.0, (z0 + z1) / 2), (x + 0.004, -sw / 2, z1 - 0.005),
                    (x + 0.004, sw / 2, z1 - 0.005)], SAIL)
        b.box((x, -0.002, mt), (x + 0.05 * L, 0.002, mt + 0.04 * H), tint("#c0392b", "paint"))  # pennant
        b.rod((x, 0, mt), (L / 2, 0, deck + 0.12 * H), 0.0015, tint("#3a2a1a", "paint"), sections=3)
        b.rod((x, 0, mt), (-0.42 * L, 0, deck + 0.1 * H), 0.0015, tint("#3a2a1a", "paint"), sections=3)


def build_model_ship(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_ship(b, L, B, H, p))


# ----------------------------------------------------------------- sarcophagus
def sample_sarcophagus(rng, size, style):
    u = rng.random()
    kind = "egyptian" if u < 0.45 else "stone" if u < 0.75 else "coffin"
    cols = {"egyptian": [GOLD, "#c9a54a"], "stone": STONES[:4], "coffin": wood_tones("antique") + [BLACK]}[kind]
    return make_params("sarcophagus", rng, size, style, cols, [LAPIS, "#3a6a8a"], [GOLD, BRASS, "#c9a54a"], kind=kind)


def _draw_sarcophagus(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x, head at +x: an Egyptian mummy case (a tapering gilt body with a striped
    headdress and a face), a stone chest with a gabled lid and a carved panel, or a
    six-sided wooden coffin with handles."""
    if p.kind == "stone":
        lid = 0.72 * H
        b.box((-L / 2, -B / 2, 0), (L / 2, B / 2, 0.08 * H), darker(p.primary, 0.1))
        b.box((-0.48 * L, -0.47 * B, 0.08 * H), (0.48 * L, 0.47 * B, lid), p.primary)
        b.box((-0.35 * L, 0.47 * B, 0.2 * H), (0.35 * L, 0.48 * B, lid - 0.12 * H), lighter(p.primary, 0.1))
        for k in range(5):  # carved garland
            x = -0.28 * L + k * 0.14 * L
            b.sphere((x, 0.48 * B, 0.45 * H), (0.05 * L, 0.01, 0.08 * H), darker(p.primary, 0.15), subdivisions=1)
        b.hull([(-L / 2, -B / 2, lid), (L / 2, -B / 2, lid), (-L / 2, B / 2, lid), (L / 2, B / 2, lid),
                (-L / 2, -B / 2, lid + 0.06 * H), (L / 2, -B / 2, lid + 0.06 * H), (-L / 2, B / 2, lid + 0.06 * H),
                (L / 2, B / 2, lid + 0.06 * H), (-L / 2, 0, H - 0.02 * H), (L / 2, 0, H - 0.02 * H)], p.primary)
        for x in (-L / 2, L / 2 - 0.08 * L):
            for y in (-B / 2, B / 2 - 0.15 * B):
                b.box((x, y, lid + 0.06 * H), (x + 0.08 * L, y + 0.15 * B, H), lighter(p.primary, 0.05))
        return
    if p.kind == "coffin":
        def outline(s: float, z: float):
            return [(-L / 2 * s, -0.3 * B * s, z), (-L / 2 * s, 0.3 * B * s, z), (0.2 * L * s, -0.5 * B * s, z),
                    (0.2 * L * s, 0.5 * B * s, z), (L / 2 * s, -0.35 * B * s, z), (L / 2 * s, 0.35 * B * s, z)]
        b.hull(outline(0.97, 0.0) + outline(1.0, 0.62 * H), p.primary)
        b.hull(outline(1.0, 0.62 * H) + outline(1.0, 0.68 * H) + outline(0.9, H), darker(p.primary, 0.1))
        for x in (-0.25 * L, 0.0, 0.3 * L):
            for s in (-1, 1):
                yb = s * (0.42 * B if x > 0 else 0.38 * B)
                b.rod((x - 0.06 * L, yb + s * 0.04 * B, 0.35 * H), (x + 0.06 * L, yb + s * 0.04 * B, 0.35 * H), 0.01,
                      p.accent, sections=6)
        b.box((0.05 * L, -0.015 * B, H - 0.005), (0.3 * L, 0.015 * B, H + 0.002), p.accent)  # cross
        b.box((0.2 * L, -0.12 * B, H - 0.005), (0.23 * L, 0.12 * B, H + 0.002), p.accent)
        return

    def body(z: float, s: float):
        pts = []
        for x, hw in ((-0.5 * L, 0.3), (-0.35 * L, 0.36), (0.1 * L, 0.48), (0.28 * L, 0.46), (0.34 * L, 0.38),
                      (0.48 * L, 0.33), (0.5 * L, 0.2)):
            pts += [(x * s, -hw * B * s, z), (x * s, hw * B * s, z)]
        return pts

    b.hull(body(0.0, 0.97) + body(0.5 * H, 1.0), p.secondary)  # the case
    b.hull(body(0.5 * H, 1.0) + body(0.72 * H, 0.94), p.primary)  # the lid
    for k in range(5):  # bands of the wrapped body
        x = -0.42 * L + k * 0.1 * L
        b.hull([(x, -0.36 * B, 0.7 * H), (x + 0.04 * L, -0.36 * B, 0.7 * H), (x, 0.36 * B, 0.7 * H),
                (x + 0.04 * L, 0.36 * B, 0.7 * H), (x, -0.3 * B, 0.75 * H), (x + 0.04 * L, -0.3 * B, 0.75 * H),
                (x, 0.3 * B, 0.75 * H), (x + 0.04 * L, 0.3 * B, 0.75 * H)], LAPIS if k % 2 else tint("#8a2a2a", "paint"))
    hx = 0.36 * L  # the head: a striped headdress framing a gilt face
    for k in range(7):
        x0 = hx - 0.12 * L + k * 0.034 * L
        b.hull([(x0, -0.4 * B, 0.55 * H), (x0 + 0.03 * L, -0.4 * B, 0.55 * H), (x0, 0.4 * B, 0.55 * H),
                (x0 + 0.03 * L, 0.4 * B, 0.55 * H), (x0, -0.3 * B, 0.92 * H), (x0 + 0.03 * L, -0.3 * B, 0.92 * H),
                (x0, 0.3 * B, 0.92 * H), (x0 + 0.03 * L, 0.3 * B, 0.92 * H)], LAPIS if k % 2 else p.primary)
    fc = (hx + 0.02 * L, 0.0, 0.9 * H)
    b.sphere(fc, (0.09 * L, 0.2 * B, 0.1 * H), p.accent, subdivisions=2)  # face
    for s in (-1, 1):
        b.sphere((fc[0] + 0.03 * L, s * 0.07 * B, 0.985 * H), (0.02 * L, 0.04 * B, 0.012 * H), BLACK, subdivisions=1)
    b.sphere((fc[0] + 0.08 * L, 0.0, 0.96 * H), (0.02 * L, 0.03 * B, 0.03 * H), darker(p.accent, 0.15),
             subdivisions=1)  # nose
    b.box((hx + 0.12 * L, -0.06 * B, 0.72 * H), (hx + 0.16 * L, 0.06 * B, 0.86 * H), LAPIS)  # beard
    for s in (-1, 1):  # crossed arms with crook and flail
        b.rod((0.12 * L, s * 0.3 * B, 0.76 * H), (-0.02 * L, -s * 0.15 * B, 0.8 * H), 0.025 * B + 0.01, p.accent,
              sections=6)
    b.box((-0.5 * L, -0.3 * B, 0.7 * H), (-0.45 * L, 0.3 * B, 0.8 * H), p.accent)


def build_sarcophagus(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_sarcophagus(b, L, B, H, p))


# ----------------------------------------------------------------- rope barrier
def sample_rope_barrier(rng, size, style):
    return make_params("rope_barrier", rng, size, style, [BRASS, CHROME, BLACK, GOLD],
                       ["#8a1f2b", "#b8202a", "#2d4f8a", BLACK], BRASS, kind=str(rng.choice(["rope", "rope", "belt"])))


def _draw_barrier(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: stanchions on round bases with ball tops, velvet ropes sagging between
    them on their hooks (or a flat taut belt)."""
    R = 0.48 * B
    n = max(2, int(round(L / 1.2)) + 1)
    xs = np.linspace(-L / 2 + R, L / 2 - R, n)
    top = H - 0.05 * H
    for x in xs:
        b.cyl(x, 0, 0, 0.03 * H, R, p.primary, r_top=0.85 * R, sections=20)
        b.cyl(x, 0, 0.03 * H, 0.06 * H, 0.5 * R, p.primary, r_top=0.15 * R, sections=14)
        b.cyl(x, 0, 0.06 * H, top, 0.12 * R, p.primary, sections=10)
        b.sphere((x, 0, top + 0.02 * H), (0.25 * R, 0.25 * R, 0.03 * H), p.primary, subdivisions=1)
    hz = top - 0.08 * H
    for a, c in zip(xs[:-1], xs[1:], strict=True):
        if p.kind == "belt":
            b.box((a, -0.01, hz - 0.05 * H), (c, 0.01, hz), p.secondary)
            continue
        pts = sag((a + 0.14 * R, 0, hz), (c - 0.14 * R, 0, hz), 0.2 * H, 10)
        path(b, pts, 0.03 * R + 0.006, p.secondary, sections=8)
        for q in (pts[0], pts[-1]):
            b.sphere(q, 0.06 * R + 0.008, p.accent, subdivisions=0)


def build_rope_barrier(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_barrier(b, L, B, H, p))


# ----------------------------------------------------------------- cannon
def sample_cannon(rng, size, style):
    return make_params("cannon", rng, size, style, [BLACK, "#2b2b2b", "#b8862a", "#8a6a3a"],
                       wood_tones("rustic") + ["#5a6a4a"], DARK_METAL, kind=str(rng.choice(["field", "naval"])))


def _barrel(b: Builder, x0: float, x1: float, z: float, r: float, color: str) -> None:
    """A cannon barrel along x from the breech at x0 to the muzzle at x1."""
    L = x1 - x0
    prof = [[0, 0], [0.85 * r, 0], [r, 0.05 * L], [r, 0.12 * L], [0.9 * r, 0.14 * L], [0.82 * r, 0.45 * L],
            [0.88 * r, 0.47 * L], [0.7 * r, 0.5 * L], [0.62 * r, 0.9 * L], [0.78 * r, 0.95 * L], [0.75 * r, L],
            [0.35 * r, L], [0.35 * r, 0.97 * L], [0, 0.97 * L]]
    b.lathe(prof, color, sections=20, transform=move((x0, 0.0, z)) @ rot_y(np.pi / 2))
    b.sphere((x0 - 0.06 * L, 0, z), 0.35 * r, color, subdivisions=1)  # cascabel
    b.rod((x0 - 0.06 * L, 0, z), (x0, 0, z), 0.15 * r, color, sections=8)
    b.rod((x0 + L * 0.995, 0, z), (x0 + L * 1.0, 0, z), 0.35 * r, tint("#15161a", "paint"), sections=12)  # the bore


def _draw_cannon(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x, muzzle at +x: a bronze or iron barrel with its rings on a field carriage
    with two big spoked wheels and a trail, or on a stepped naval truck carriage."""
    if p.kind == "naval":
        R = 0.12 * H
        for x in (-0.28 * L, 0.18 * L):
            for y in (-0.38 * B, 0.38 * B):
                wheel_y(b, x, y, R, R, 0.1 * B, p.secondary, p.accent)
        steps = [(-0.35 * L, 0.22 * L, 0.42 * H), (-0.35 * L, 0.05 * L, 0.52 * H), (-0.35 * L, -0.12 * L, 0.6 * H)]
        for y0 in (-0.42 * B, 0.28 * B):
            for x0, x1, zt in steps:
                b.box((x0, y0, R), (x1, y0 + 0.14 * B, zt), p.secondary)
        b.box((-0.35 * L, -0.3 * B, R), (0.22 * L, 0.3 * B, R + 0.06 * H), p.secondary)
        z = 0.6 * H
        _barrel(b, -0.25 * L, L / 2, z, min(0.18 * H, 0.2 * B), p.primary)
        return
    R = 0.36 * H
    ax = 0.1 * L
    for y in (-0.42 * B, 0.42 * B):
        wheel_y(b, ax, y, R, R, 0.06 * B, p.secondary, p.accent, spokes=6)
        ring = max(R * 0.06, 0.01)
        ring_y(b, (ax, y, R), R - ring, ring, p.accent, sections=28)
    b.rod((ax, -0.45 * B, R), (ax, 0.45 * B, R), 0.03 * H, p.accent, sections=8)  # axle
    for y in (-0.18 * B, 0.18 * B):  # cheeks running back to the trail
        b.hull([(ax + 0.12 * L, y - 0.03 * B, R + 0.12 * H), (ax + 0.12 * L, y + 0.03 * B, R + 0.12 * H),
                (ax + 0.12 * L, y - 0.03 * B, R - 0.06 * H), (ax + 0.12 * L, y + 0.03 * B, R - 0.06 * H),
                (-L / 2 + 0.04 * L, y * 0.5 - 0.03 * B, 0.0), (-L / 2 + 0.04 * L, y * 0.5 + 0.03 * B, 0.0),
                (-L / 2 + 0.04 * L, y * 0.5 - 0.03 * B, 0.08 * H), (-L / 2 + 0.04 * L, y * 0.5 + 0.03 * B, 0.08 * H)],
               p.secondary)
    b.box((-L / 2, -0.12 * B, 0), (-L / 2 + 0.06 * L, 0.12 * B, 0.08 * H), p.accent)  # trail plate
    z = R + 0.16 * H
    _barrel(b, -0.22 * L, L / 2, z, min(0.14 * H, 0.16 * B), p.primary)
    b.rod((ax, -0.2 * B, z), (ax, 0.2 * B, z), 0.05 * H, p.primary, sections=8)  # trunnions


def build_cannon(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_cannon(b, L, B, H, p))


# ----------------------------------------------------------------- spinner rack
def sample_spinner_rack(rng, size, style):
    return make_params("spinner_rack", rng, size, style, [CHROME, BLACK, "#e8e6e0", "#9a9da3"], CARD_COLORS,
                       "#c0392b", tiers=int(rng.integers(4, 7)), sign=bool(rng.random() < 0.6))


def build_spinner_rack(p):
    """A rotating card rack: a pole on a cross-footed base carrying tiers of wire pockets
    on four faces, each holding postcards, a header sign on top."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    for a in (0.0, np.pi / 2):
        b.box((-0.48 * w, -0.04 * d, 0), (0.48 * w, 0.04 * d, 0.03 * h), p.primary, transform=rot_z(a))
    top = h - (0.1 * h if p.sign else 0.02 * h)
    b.cyl(0, 0, 0, h - 0.02 * h, 0.02 * min(w, d) + 0.005, p.primary, sections=8)
    z0 = 0.12 * h
    core = 0.12 * min(w, d)
    tier_h = (top - z0) / p.tiers
    span = 0.42 * min(w, d)
    for k in range(4):  # four faces, drawn on +y and turned
        m = Builder()
        m.box((-span, core, z0), (span, core + 0.005, top), p.primary, alpha=255)
        for t in range(p.tiers):
            z = z0 + t * tier_h
            m.rod((-span, core + 0.18 * span, z + 0.02 * h), (span, core + 0.18 * span, z + 0.02 * h), 0.004, p.primary,
                  sections=4)
            for c in range(2):
                x0 = -span + c * span + 0.05 * span
                col = CARD_COLORS[int(rng.integers(len(CARD_COLORS)))]
                ch = 0.85 * tier_h
                m.box((x0, core + 0.01, z + 0.01 * h), (x0 + 0.9 * span, core + 0.03, z + ch), tint("#f4f1ea", "paint"))
                m.box((x0 + 0.05 * span, core + 0.03, z + 0.03 * h), (x0 + 0.85 * span, core + 0.033, z + ch - 0.02 * h),
                      col)
        b.extend(m, rot_z(k * np.pi / 2))
    if p.sign:
        b.box((-0.3 * w, -0.01, h - 0.1 * h), (0.3 * w, 0.01, h), p.accent)
        b.box((-0.25 * w, -0.012, h - 0.08 * h), (0.25 * w, 0.012, h - 0.02 * h), tint("#f4f1ea", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- mounted antlers
def sample_mounted_antlers(rng, size, style):
    return make_params("mounted_antlers", rng, size, style, wood_tones("antique") + wood_tones("rustic")[:2], FUR,
                       ANTLER, kind=str(rng.choice(["head", "antlers"])), tines=int(rng.integers(3, 6)))


def _antler(b: Builder, base, side: int, w: float, h: float, tines: int, color: str) -> None:
    """One antler from ``base``: a main beam sweeping out, back and up, with tines rising."""
    base = np.asarray(base, dtype=float)
    beam = [base]
    for t in np.linspace(0.2, 1.0, 5):
        beam.append(base + np.array([side * 0.45 * w * np.sin(t * 1.4), -0.15 * h * t + 0.12 * h * t ** 2,
                                     0.75 * h * t]))
    path(b, beam, 0.012 * h + 0.005, color, sections=6)
    for k in range(tines):
        a = beam[1 + min(k, len(beam) - 2)]
        tip = a + np.array([side * 0.04 * w, 0.08 * h, 0.16 * h * (1 - 0.1 * k)])
        b.rod(a, tip, 0.008 * h + 0.004, color, sections=5)


def build_mounted_antlers(p):
    """A trophy on a wall shield: a deer's head with ears, eyes and branching antlers, or
    the antlers alone on a bleached skull plate."""
    w, d, h = p.size
    b = Builder()
    y0 = -d / 2
    sw = 0.32 * w
    shield = [(-sw * 0.8, 0.02 * h), (0.0, -0.03 * h), (sw * 0.8, 0.02 * h), (sw, 0.2 * h), (sw * 0.9, 0.42 * h),
              (0.0, 0.48 * h), (-sw * 0.9, 0.42 * h), (-sw, 0.2 * h)]
    shield = [(x, max(z, 0.0)) for x, z in shield]
    extrude_y(b, shield, y0, y0 + 0.08 * d, p.primary)
    if p.kind == "head":
        b.rod((0, y0 + 0.08 * d, 0.22 * h), (0, y0 + 0.45 * d, 0.3 * h), 0.22 * w, p.secondary, sections=12)  # neck
        hc = np.array([0.0, y0 + 0.55 * d, 0.36 * h])
        b.sphere(hc, (0.14 * w, 0.2 * d, 0.1 * h), p.secondary, subdivisions=2)
        b.sphere(hc + (0, 0.25 * d, -0.06 * h), (0.08 * w, 0.18 * d, 0.06 * h), p.secondary, subdivisions=2)  # snout
        b.sphere(hc + (0, 0.42 * d, -0.07 * h), (0.035 * w, 0.03 * d, 0.025 * h), BLACK, subdivisions=1)  # nose
        for s in (-1, 1):
            b.sphere(hc + (s * 0.1 * w, 0.1 * d, 0.03 * h), 0.012 * h + 0.004, BLACK, subdivisions=1)
            b.sphere(hc + (s * 0.2 * w, -0.05 * d, 0.08 * h), (0.08 * w, 0.02 * d, 0.04 * h), darker(p.secondary, 0.1),
                     subdivisions=1, transform=about(rot_y(s * 0.5), hc + (s * 0.2 * w, -0.05 * d, 0.08 * h)))
        base_z = hc[2] + 0.08 * h
        by = hc[1] - 0.05 * d
        ah = h - base_z
    else:
        b.sphere((0, y0 + 0.2 * d, 0.3 * h), (0.1 * w, 0.12 * d, 0.12 * h), tint("#efe8d8", "paint"), subdivisions=2)  # skull plate
        b.sphere((0, y0 + 0.3 * d, 0.2 * h), (0.05 * w, 0.08 * d, 0.08 * h), tint("#efe8d8", "paint"), subdivisions=1)
        base_z = 0.38 * h
        by = y0 + 0.2 * d
        ah = h - base_z
    for s in (-1, 1):
        _antler(b, (s * 0.06 * w, by, base_z), s, w, ah / 0.95, p.tines, p.accent)
    return b.mesh(p.size)


# ----------------------------------------------------------------- barber pole
def sample_barber_pole(rng, size, style):
    return make_params("barber_pole", rng, size, style, [CHROME, BRASS], "#c0202a", "#2a4a9a",
                       turns=float(rng.uniform(2.5, 4.5)), blue=bool(rng.random() < 0.7))


def build_barber_pole(p):
    """A barber's pole on a wall bracket: a cylinder spiralled red, white (and blue)
    between domed metal caps with a ball finial."""
    w, d, h = p.size
    b = Builder()
    R = 0.4 * min(w, d)
    cy = d / 2 - R
    z0, z1 = 0.16 * h, 0.84 * h
    secs, rings = 32, 48
    a = np.linspace(0, 2 * np.pi, secs, endpoint=False)
    zs = np.linspace(z0, z1, rings)
    verts, cols = [], []
    palette = [to_rgba(c) for c in ((p.secondary, "#f4f4f2", p.accent, "#f4f4f2") if p.blue else
                                   (p.secondary, "#f4f4f2"))]
    for z in zs:
        for ang in a:
            verts.append((R * np.cos(ang), cy + R * np.sin(ang), z))
            u = (ang / (2 * np.pi) + p.turns * (z - z0) / (z1 - z0)) % 1.0
            cols.append(palette[int(u * len(palette)) % len(palette)])
    faces = []
    for i in range(rings - 1):
        for j in range(secs):
            a0, a1 = i * secs + j, i * secs + (j + 1) % secs
            b0, b1 = a0 + secs, a1 + secs
            faces += [(a0, a1, b1), (a0, b1, b0)]
    b.add_colored(np.asarray(verts), np.asarray(faces), np.asarray(cols, dtype=np.uint8), role="paint")
    for zc, up in ((z1, 1), (z0, -1)):  # caps
        prof = [[0, 0], [1.1 * R, 0], [1.1 * R, 0.03 * h], [0.7 * R, 0.08 * h], [0, 0.1 * h]]
        m = trimesh.creation.revolve(np.asarray(prof, dtype=float), sections=20)
        v = np.asarray(m.vertices).copy()
        v[:, 2] = zc + up * v[:, 2]
        v[:, 1] += cy
        cap_faces = np.asarray(m.faces) if up > 0 else np.asarray(m.faces)[:, ::-1]
        b.add(v, cap_faces, p.primary)
    b.sphere((0, cy, h - 0.03 * h), 0.3 * R, p.primary, subdivisions=1)
    b.sphere((0, cy, 0.03 * h), 0.3 * R, p.primary, subdivisions=1)
    for z in (0.2 * h, 0.8 * h):  # bracket to the wall
        b.rod((0, -d / 2, z), (0, cy - 1.0 * R, z), 0.06 * R + 0.004, p.primary, sections=6)
    b.box((-0.3 * w, -d / 2, 0.15 * h), (0.3 * w, -d / 2 + 0.02 * d, 0.85 * h), p.primary)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dartboard
def sample_dartboard(rng, size, style):
    return make_params("dartboard", rng, size, style, BLACK, DART_CREAM, [DART_RED, DART_GREEN],
                       darts=int(rng.integers(0, 4)))


def build_dartboard(p):
    """A dartboard on the wall: black surround with the number ring, twenty sectors in
    black and cream, red and green double and treble rings, the bull, and darts in it."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    R = 0.5 * min(w, h)
    cz = h / 2
    y0 = -d / 2
    disc_y(b, 0, y0, y0 + 0.6 * d, cz, R, p.primary, sections=40)  # surround
    for k in range(20):
        a = np.pi / 2 + 2 * np.pi * k / 20
        b.cbox((0.9 * R * np.cos(a), y0 + 0.6 * d + 0.002, cz + 0.9 * R * np.sin(a)), (0.05 * R, 0.004, 0.05 * R),
               tint("#f4f4f2", "paint"))
    rb = 0.78 * R
    fy0, fy1 = y0 + 0.6 * d, y0 + 0.75 * d
    for k in range(20):
        a0 = np.pi / 2 + 2 * np.pi * (k - 0.5) / 20
        a1 = a0 + 2 * np.pi / 20
        dark = k % 2 == 0
        single = p.primary if dark else p.secondary
        ring = DART_RED if dark else DART_GREEN
        for r0, r1, col in ((0.1 * rb, 0.58 * rb, single), (0.58 * rb, 0.64 * rb, ring), (0.64 * rb, 0.94 * rb, single),
                            (0.94 * rb, rb, ring)):
            sector_y(b, 0, cz, fy0, fy1, r0, r1, a0, a1, col, n=2)
    disc_y(b, 0, fy0, fy1 + 0.002, cz, 0.1 * rb, DART_GREEN, sections=16)
    disc_y(b, 0, fy0, fy1 + 0.004, cz, 0.04 * rb, DART_RED, sections=12)
    for _ in range(p.darts):
        r, a = rng.uniform(0.1, 0.9) * rb, rng.uniform(0, 2 * np.pi)
        x, z = r * np.cos(a), cz + r * np.sin(a)
        b.rod((x, fy1, z), (x, d / 2 - 0.3 * d, z + 0.01), 0.006 * R, tint("#c9ccd0", "metal"), sections=4)
        b.rod((x, d / 2 - 0.3 * d, z + 0.01), (x, d / 2, z + 0.02), 0.004 * R, BLACK, sections=4)
        b.box((x - 0.05 * R, d / 2 - 0.15 * d, z + 0.015), (x + 0.05 * R, d / 2, z + 0.02), p.accent)
    return b.mesh(p.size)


slot_roles("plinth", "stone", "stone", "plastic")
register("plinth", sample_plinth, build_plinth)
slot_roles("model_ship", "wood", "wood", {"": "paint", GOLD: "metal"})
register("model_ship", sample_model_ship, build_model_ship)
slot_roles("sarcophagus", "stone", "stone", "metal")
register("sarcophagus", sample_sarcophagus, build_sarcophagus)
slot_roles("rope_barrier", "metal", "fabric", "metal")
register("rope_barrier", sample_rope_barrier, build_rope_barrier)
slot_roles("cannon", "metal", "wood", "metal")
register("cannon", sample_cannon, build_cannon)
slot_roles("spinner_rack", "metal", "paper", "paint")
register("spinner_rack", sample_spinner_rack, build_spinner_rack)
slot_roles("mounted_antlers", "wood", "fabric", "stone")
register("mounted_antlers", sample_mounted_antlers, build_mounted_antlers)
slot_roles("barber_pole", "metal", "paint", "paint")
register("barber_pole", sample_barber_pole, build_barber_pole)
# ----------------------------------------------------------------- archery target
TARGET_RINGS = ["#f2f0ea", "#1e1e20", "#2f7fc8", "#d8302c", "#f2c230"]
"""Colours of an archery face from the outside in: white, black, blue, red, gold."""


def sample_archery_target(rng, size, style):
    return make_params("archery_target", rng, size, style, ["#d9c27a", "#cdb46a", "#e0cb88"], wood_tones(style),
                       TARGET_RINGS[0], arrows=int(rng.integers(0, 5)))


def build_archery_target(p):
    """A straw boss on a three-legged wooden stand, the five-colour face on
    its front (-y), arrows in some."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    R = 0.5 * min(w, h * 0.75)
    cz = h - R
    thick = min(0.2, 0.3 * d)
    face_y = d / 2 - 0.12 * d  # the face looks forward (+y); the stand's back leg reaches back
    disc_y(b, 0, face_y - thick, face_y, cz, R, p.primary, sections=36)  # the straw boss
    for i, col in enumerate(TARGET_RINGS):  # the paper face, ring on ring
        disc_y(b, 0, face_y, face_y + 0.008 * (i + 1), cz, R * 0.92 * (1 - i / len(TARGET_RINGS)), tint(col, "paint"),
               sections=36)
    leg = max(0.02, 0.03 * R)
    for sx in (-1, 1):  # two front legs and the back leg
        b.rod((sx * 0.75 * R, face_y - thick / 2, 0), (sx * 0.45 * R, face_y - thick / 2, cz + 0.6 * R), leg,
              p.secondary, sections=8, role="wood")
    b.rod((0, -d / 2 + leg, 0), (0, face_y - thick, cz + 0.5 * R), leg, p.secondary, sections=8, role="wood")
    for _ in range(p.arrows):
        r, a = rng.uniform(0.0, 0.6) * R, rng.uniform(0, 2 * np.pi)
        x, z = r * np.cos(a), cz + r * np.sin(a)
        b.rod((x, face_y - 0.5 * thick, z), (x, d / 2, z), 0.006, tint("#8a6a3a", "wood"), sections=4)
    return b.mesh(p.size)


slot_roles("archery_target", "fabric", "wood", "paint")
register("archery_target", sample_archery_target, build_archery_target)
slot_roles("dartboard", "plastic", "fabric", "fabric")
register("dartboard", sample_dartboard, build_dartboard)
