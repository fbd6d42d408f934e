"""A courtroom's furniture: judges_bench, witness_stand, jury_box; a lobby's
security_gate."""

from __future__ import annotations

from anyhome.assets.procedural._parts import (
    BLACK,
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

LEATHER = tint(["#2b1a10", "#4a1f1a", "#1f2f4a", "#2f3f2a"], "leather")
GATE = tint(["#d8d8d4", "#9a9da3", "#2b2b2b"], "plastic")


def _panelled(b: Builder, x0: float, x1: float, y: float, z0: float, z1: float, color: str, n: int) -> None:
    """Raised panels on a front face at ``y`` (facing +y): ``n`` panels between posts."""
    pw = (x1 - x0) / n
    for k in range(n):
        px = x0 + k * pw
        b.box((px + 0.12 * pw, y, z0 + 0.15 * (z1 - z0)), (px + 0.88 * pw, y + 0.012, z1 - 0.12 * (z1 - z0)),
              lighter(color, 0.08))


def _chair(b: Builder, x: float, y: float, z: float, s: float, color: str, back_h: float, facing: int = 1) -> None:
    """A chair at (x, y) on floor level ``z``, seat ``s`` wide, facing +y (``facing`` 1) or -y."""
    b.box((x - s / 2, y - s / 2, z + 0.4 * s), (x + s / 2, y + s / 2, z + 0.55 * s), color)
    b.box((x - 0.08 * s, y - 0.08 * s, z), (x + 0.08 * s, y + 0.08 * s, z + 0.4 * s), BLACK)
    by = y - facing * s / 2
    b.box((x - s / 2, min(by, by - facing * 0.1 * s), z + 0.55 * s), (x + s / 2, max(by, by - facing * 0.1 * s), z + back_h), color)


# ----------------------------------------------------------------- judge's bench
def sample_judges_bench(rng, size, style):
    return make_params("judges_bench", rng, size, style, wood_tones(style)[:3] or ["#5a3a22"], LEATHER, ["#c9a227", "#9a9da3"],
                       panels=int(rng.integers(3, 6)), crest=bool(rng.random() < 0.5))


def build_judges_bench(p):
    """The judge's bench, facing the room (+y): a raised dais with a step, a tall
    panelled front desk with a moulded top, and the judge's high-backed chair behind it;
    ``crest``: a round seal on the front."""
    w, d, h = p.size
    b = Builder()
    dais = 0.22 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, dais), darker(p.primary, 0.15))  # dais
    b.box((-0.45 * w, d / 2 - 0.12 * d, 0), (0.45 * w, d / 2, 0.5 * dais), darker(p.primary, 0.05))  # step
    fy = d / 2 - 0.2 * d
    b.box((-w / 2, fy - 0.25 * d, dais), (w / 2, fy, 0.78 * h), p.primary)  # front desk
    b.box((-w / 2 - 0.0, fy - 0.28 * d, 0.78 * h), (w / 2, fy + 0.02 * d, 0.82 * h), lighter(p.primary, 0.12))
    _panelled(b, -w / 2, w / 2, fy, dais, 0.78 * h, p.primary, p.panels)
    if p.crest:
        b.box((-0.08 * w, fy + 0.012, 0.5 * h), (0.08 * w, fy + 0.03, 0.7 * h), p.accent)
    _chair(b, 0.0, fy - 0.55 * d, dais, min(0.6, 0.3 * w), p.secondary, h - dais)
    return b.mesh(p.size)


# ----------------------------------------------------------------- witness stand
def sample_witness_stand(rng, size, style):
    return make_params("witness_stand", rng, size, style, wood_tones(style)[:3] or ["#5a3a22"], LEATHER, [METAL, "#c9a227"],
                       microphone=bool(rng.random() < 0.6))


def build_witness_stand(p):
    """The witness stand, facing +y: a low platform enclosed by panelled walls on three
    sides with a rail on top, open at the back to a step, a chair inside; ``microphone``
    on a gooseneck at the front rail."""
    w, d, h = p.size
    b = Builder()
    plat = 0.16 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, plat), darker(p.primary, 0.15))
    t = 0.05 * min(w, d)
    wall = 0.85 * h
    b.box((-w / 2, d / 2 - t, plat), (w / 2, d / 2, wall), p.primary)  # front
    _panelled(b, -w / 2, w / 2, d / 2, plat, wall, p.primary, 2)
    for x in (-w / 2, w / 2 - t):
        b.box((x, -0.2 * d, plat), (x + t, d / 2, wall), p.primary)
    b.box((-w / 2, d / 2 - 1.6 * t, wall), (w / 2, d / 2, wall + 0.04 * h), lighter(p.primary, 0.12))  # rail
    _chair(b, 0.0, 0.0, plat, 0.4 * min(w, d), p.secondary, h * 0.95 - plat)
    if p.microphone:
        b.rod((0.2 * w, d / 2 - t / 2, wall + 0.04 * h), (0.1 * w, d / 2 - 3 * t, h), 0.008, p.accent, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- jury box
def sample_jury_box(rng, size, style):
    return make_params("jury_box", rng, size, style, wood_tones(style)[:3] or ["#5a3a22"], LEATHER, ["#5a3a22"],
                       rows=int(rng.integers(2, 4)), seats=int(rng.integers(5, 7)))


def build_jury_box(p):
    """The jury box, facing +y: a panelled enclosure with a front rail, ``rows`` tiers of
    ``seats`` chairs each, the back tier raised."""
    w, d, h = p.size
    b = Builder()
    t = 0.03 * min(w, d) + 0.02
    front = 0.85 * h
    b.box((-w / 2, d / 2 - t, 0), (w / 2, d / 2, front), p.primary)
    _panelled(b, -w / 2, w / 2, d / 2, 0, front, p.primary, max(3, p.seats))
    b.box((-w / 2, d / 2 - 2 * t, front), (w / 2, d / 2, front + 0.04 * h), lighter(p.primary, 0.12))
    for x in (-w / 2, w / 2 - t):
        b.box((x, -d / 2, 0), (x + t, d / 2, 0.8 * front), p.primary)
    depth = (d - t) / p.rows
    s = min(0.5, 0.8 * (w - 2 * t) / p.seats, 0.7 * depth)
    for r in range(p.rows):
        y0 = d / 2 - t - (r + 1) * depth
        z = r * 0.18 * h
        if z > 0:
            b.box((-w / 2 + t, y0, 0), (w / 2 - t, y0 + depth, z), darker(p.primary, 0.15))
        for k in range(p.seats):
            x = -w / 2 + t + (k + 0.5) * (w - 2 * t) / p.seats
            _chair(b, x, y0 + 0.5 * depth, z, s, p.secondary, min(h - z, 1.6 * s))
    return b.mesh(p.size)


# ----------------------------------------------------------------- security gate
def sample_security_gate(rng, size, style):
    return make_params("security_gate", rng, size, style, GATE, ["#2b2b2b"], ["#3fbf5f", "#e05a47"],
                       tray=bool(rng.random() < 0.5))


def build_security_gate(p):
    """A walk-through metal detector: two tall side panels joined by a head box with a
    status light, on foot plates; ``tray``: a small tray table at one side."""
    w, d, h = p.size
    b = Builder()
    t = 0.12 * w
    for x in (-w / 2, w / 2 - t):
        b.box((x, -d / 2, 0), (x + t, d / 2, 0.04 * h), p.secondary)  # foot
        b.box((x, -0.3 * d, 0.04 * h), (x + t, 0.3 * d, 0.88 * h), p.primary)
    b.box((-w / 2, -0.3 * d, 0.88 * h), (w / 2, 0.3 * d, h), p.primary)
    b.box((-0.12 * w, 0.3 * d, 0.91 * h), (0.12 * w, 0.32 * d, 0.97 * h), p.accent, role="light")
    if p.tray:
        b.box((w / 2 - t - 0.01, -0.45 * d, 0.5 * h), (w / 2, 0.0, 0.52 * h), p.secondary)
    return b.mesh(p.size)


slot_roles("judges_bench", "wood", "leather", {"": "metal"})
register("judges_bench", sample_judges_bench, build_judges_bench)
slot_roles("witness_stand", "wood", "leather", "metal")
register("witness_stand", sample_witness_stand, build_witness_stand)
slot_roles("jury_box", "wood", "leather", "wood")
register("jury_box", sample_jury_box, build_jury_box)
slot_roles("security_gate", "plastic", "plastic", "light")
register("security_gate", sample_security_gate, build_security_gate)
