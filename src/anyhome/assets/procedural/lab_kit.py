"""A laboratory's kit: autoclave (a steam steriliser, front-loading on the floor or a
top-loading pot on a stand) and gas_tap (a bench gas tap for a Bunsen burner)."""

from __future__ import annotations

import math

from anyhome.assets.procedural._kit import BRASS, CHROME, GLOW_GREEN, SCREEN, disc_y, ring_y
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    Builder,
    darker,
    lighter,
    make_params,
    slot_roles,
    tint,
)
from anyhome.assets.registry import register

STAINLESS = tint(["#c9ccd0", "#b4b8bd", "#d4d6d8"], "metal")
PANELS = tint(["#eceae4", "#2d6fb0", "#5f6b7a", "#e8e6e0"], "paint")
GAUGE_FACE = tint("#f4f4f2", "ceramic")


def sample_autoclave(rng, size, style):
    return make_params("autoclave", rng, size, style, STAINLESS, PANELS, BLACK,
                       top_loading=bool(rng.random() < 0.3), gauges=int(rng.integers(1, 3)))


def build_autoclave(p):
    """A steam steriliser facing +y. Front-loading: a stainless cabinet on a plinth with
    a round chamber door on the front (a thick disc with a locking wheel of spokes), a
    control panel with a screen and a lamp above it and ``gauges`` pressure gauges.
    ``top_loading``: a round steel pot on a stand with a domed lid clamped down by a
    ring of wing bolts, a control box in front and the gauges on the lid."""
    w, d, h = p.size
    b = Builder()
    if p.top_loading:
        r = 0.45 * min(w, d)
        b.box((-0.45 * w, -0.45 * d, 0), (0.45 * w, 0.45 * d, 0.35 * h), p.secondary)  # the stand
        b.cyl(0.0, -0.05 * d, 0.35 * h, 0.85 * h, r, p.primary, sections=24)
        b.cyl(0.0, -0.05 * d, 0.85 * h, 0.9 * h, r * 1.04, lighter(p.primary, 0.1), sections=24)
        b.cyl(0.0, -0.05 * d, 0.9 * h, 0.95 * h, r * 0.95, r_top=0.5 * r, color=p.primary, sections=24)
        for k in range(6):  # wing bolts round the lid
            a = k * math.pi / 3
            b.box((r * math.cos(a) - 0.02 * w, -0.05 * d + r * math.sin(a) - 0.02 * d, 0.84 * h),
                  (r * math.cos(a) + 0.02 * w, -0.05 * d + r * math.sin(a) + 0.02 * d, 0.92 * h), DARK_METAL)
        for g in range(p.gauges):
            x = (g - (p.gauges - 1) / 2) * 0.25 * w
            b.cyl(x, -0.05 * d, 0.95 * h, h, 0.06 * w + 0.01, GAUGE_FACE, sections=14)
        b.box((-0.3 * w, 0.38 * d, 0.12 * h), (0.3 * w, d / 2, 0.3 * h), p.secondary)
        b.box((-0.2 * w, d / 2 - 0.002, 0.18 * h), (0.1 * w, d / 2, 0.26 * h), SCREEN)
        return b.mesh(p.size)
    plinth = 0.08 * h
    b.box((-0.48 * w, -0.48 * d, 0), (0.48 * w, 0.46 * d, plinth), darker(p.primary, 0.4))
    b.box((-w / 2, -d / 2, plinth), (w / 2, 0.42 * d, 0.8 * h), p.primary)  # the cabinet round the chamber
    b.box((-w / 2, -d / 2, 0.8 * h), (w / 2, 0.42 * d, h), p.secondary)  # the control head
    b.box((-0.3 * w, 0.42 * d, 0.85 * h), (0.15 * w, 0.43 * d, 0.95 * h), SCREEN)
    b.sphere((0.3 * w, 0.43 * d, 0.9 * h), 0.02 * w + 0.005, GLOW_GREEN)
    cz = 0.45 * h
    R = 0.4 * min(w, 0.7 * h)
    disc_y(b, 0.0, 0.42 * d, 0.47 * d, cz, R * 1.08, darker(p.primary, 0.15), sections=28)  # door frame
    disc_y(b, 0.0, 0.47 * d, 0.52 * d, cz, R, lighter(p.primary, 0.08), sections=28)  # the door
    ring_y(b, (0.0, 0.53 * d, cz), 0.45 * R, 0.04 * R, CHROME, sections=20)  # locking wheel
    for k in range(4):
        a = k * math.pi / 2 + math.pi / 4
        b.rod((0.0, 0.53 * d, cz), (0.45 * R * math.cos(a), 0.53 * d, cz + 0.45 * R * math.sin(a)), 0.03 * R, CHROME,
              sections=6)
    disc_y(b, 0.0, 0.52 * d, 0.56 * d, cz, 0.1 * R, p.accent, sections=12)  # hub
    for g in range(p.gauges):
        x = 0.3 * w - g * 0.18 * w
        disc_y(b, x, 0.42 * d, 0.45 * d, 0.72 * h, 0.06 * min(w, h), GAUGE_FACE, sections=14)
    return b.mesh(p.size)


# ----------------------------------------------------------------- gas tap
def sample_gas_tap(rng, size, style):
    return make_params("gas_tap", rng, size, style, [CHROME, BRASS], tint(["#e8c020", "#e07020"], "paint"), BLACK,
                       double=bool(rng.random() < 0.4))


def build_gas_tap(p):
    """A bench gas tap facing +y: a round flange on the bench top, an upright pipe, a
    valve body with a lever handle (painted gas yellow) and a serrated hose nozzle
    pointing forward; ``double``: two nozzles and levers either side of one upright."""
    w, d, h = p.size
    b = Builder()
    r = 0.18 * min(w, d)
    b.cyl(0.0, 0.0, 0.0, 0.06 * h, 0.45 * min(w, d), p.primary, sections=14)  # flange
    b.cyl(0.0, 0.0, 0.06 * h, 0.75 * h, r, p.primary, sections=12)  # upright
    b.sphere((0.0, 0.0, 0.75 * h), (1.3 * r, 1.3 * r, 0.1 * h), p.primary)  # valve body
    sides = (-1, 1) if p.double else (0,)
    for s in sides:
        x = s * 0.3 * w
        b.rod((x, 0.0, 0.68 * h), (x, d / 2, 0.62 * h), 0.6 * r, p.primary, sections=10)  # nozzle
        for k in range(3):  # serrations
            y = 0.2 * d + k * 0.1 * d
            disc_y(b, x, y, y + 0.04 * d, 0.66 * h - k * 0.012 * h, 0.8 * r, darker(p.primary, 0.1), sections=10)
        b.box((x - 0.08 * w, -d / 2, 0.82 * h), (x + 0.08 * w, 0.1 * d, h), p.secondary)  # lever
    return b.mesh(p.size)


slot_roles("autoclave", "metal", {"": "paint"}, "plastic")
register("autoclave", sample_autoclave, build_autoclave)
slot_roles("gas_tap", "metal", "paint", "plastic")
register("gas_tap", sample_gas_tap, build_gas_tap)
