"""Tables and desks: table, dining_table, coffee_table, side_table, conference_table,
lab_bench, desk, reception_desk, bar_counter."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    METAL,
    Builder,
    darker,
    leg_style,
    lighter,
    make_params,
    slot_roles,
    wood_tones,
)
from anyhome.assets.procedural.storage import HANDLE
from anyhome.assets.registry import register


def _table_params(name, rng, size, style, **extra):
    w, d, _ = size
    roundish = abs(w - d) < 0.15 * max(w, d)
    return make_params(name, rng, size, style, wood_tones(style), "#2a2522", DARK_METAL,
                       legs=leg_style(rng, style), round=bool(roundish and rng.random() < 0.5),
                       apron=bool(rng.random() < 0.6), top_t=float(rng.uniform(0.025, 0.05)), **extra)


def _table(b: Builder, p, w, d, h, n_legs: int | None = None) -> None:
    t = min(p.top_t, h * 0.2)
    if p.round:
        b.cyl(0, 0, h - t, h, w / 2, p.primary, ry=d / 2, sections=32)
        b.cyl(0, 0, 0, 0.03, w * 0.22, p.primary, ry=d * 0.22)
        b.cyl(0, 0, 0.03, h - t, 0.05, p.primary, r_top=0.07)
        return
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), p.primary)
    r = 0.025 if p.legs != "turned" else 0.03
    n = n_legs or (6 if w > 2.2 else 4)
    xs = np.linspace(-w / 2 + 0.06, w / 2 - 0.06, n // 2)
    pts = [(x, y) for x in xs for y in (-d / 2 + 0.06, d / 2 - 0.06)]
    b.legs(pts, 0, h - t, r, p.legs, p.primary)
    if p.apron and h > 0.5:
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, h - t - 0.08), (w / 2 - 0.05, d / 2 - 0.05, h - t),
              darker(p.primary, 0.1))


def sample_table(rng, size, style):
    return _table_params("table", rng, size, style)


def build_table(p):
    w, d, h = p.size
    b = Builder()
    _table(b, p, w, d, h)
    return b.mesh(p.size)


def sample_dining_table(rng, size, style):
    return _table_params("dining_table", rng, size, style, runner=bool(rng.random() < 0.3))


def build_dining_table(p):
    w, d, h = p.size
    b = Builder()
    _table(b, p, w, d, h)
    if p.runner and not p.round:
        b.box((-w / 2 + 0.1, -0.15 * d, h - 0.001), (w / 2 - 0.1, 0.15 * d, h + 0.004), lighter(p.accent, 0.6))
    return b.mesh(p.size)


def sample_coffee_table(rng, size, style):
    return _table_params("coffee_table", rng, size, style, shelf=bool(rng.random() < 0.5),
                         glass=bool(rng.random() < 0.2))


def build_coffee_table(p):
    w, d, h = p.size
    b = Builder()
    _table(b, p, w, d, h)
    if p.shelf and not p.round:
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, 0.1 * h), (w / 2 - 0.05, d / 2 - 0.05, 0.1 * h + 0.02),
              darker(p.primary, 0.1))
    if p.glass and not p.round:
        b.box((-w / 2 + 0.03, -d / 2 + 0.03, h), (w / 2 - 0.03, d / 2 - 0.03, h + 0.01), GLASS, alpha=140)
    return b.mesh(p.size)


def sample_side_table(rng, size, style):
    return _table_params("side_table", rng, size, style, drawer=bool(rng.random() < 0.4))


def build_side_table(p):
    w, d, h = p.size
    b = Builder()
    _table(b, p, w, d, h)
    if p.drawer and not p.round and h > 0.3:
        t = min(p.top_t, h * 0.2)
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, h - t - 0.1), (w / 2 - 0.05, d / 2 - 0.04, h - t), darker(p.primary, 0.1))
        b.sphere((0, d / 2 - 0.03, h - t - 0.05), 0.015, HANDLE)
    return b.mesh(p.size)


def sample_conference_table(rng, size, style):
    return make_params("conference_table", rng, size, style, wood_tones(style) + ["#e8e6e0", "#2b2b2b"],
                       METAL, BLACK, top_t=float(rng.uniform(0.035, 0.06)))


def build_conference_table(p):
    w, d, h = p.size
    b = Builder()
    t = p.top_t
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), p.primary)
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, h - t - 0.02), (w / 2 - 0.02, d / 2 - 0.02, h - t), darker(p.primary, 0.2))
    n = max(2, int(round(w / 1.4)))
    for x in np.linspace(-w / 2 + 0.5, w / 2 - 0.5, n) if w > 1.2 else [0.0]:
        b.box((x - 0.05, -d * 0.3, 0), (x + 0.05, d * 0.3, 0.04), p.secondary)
        b.box((x - 0.04, -0.05, 0.04), (x + 0.04, 0.05, h - t - 0.02), p.secondary)
        b.box((x - 0.03, -d * 0.3, h - t - 0.05), (x + 0.03, d * 0.3, h - t - 0.02), p.secondary)
    # cable boxes on the top
    for x in np.linspace(-w / 2 + 0.6, w / 2 - 0.6, max(1, int(w / 1.5))) if w > 1.4 else []:
        b.box((x - 0.1, -0.05, h - 0.001), (x + 0.1, 0.05, h + 0.004), p.accent)
    return b.mesh(p.size)


def sample_lab_bench(rng, size, style):
    return make_params("lab_bench", rng, size, style, ["#e8e6e0", "#c9d3d9", "#9fb2c0"], "#2b2b2b",
                       ["#4f8fbf", "#bf4f4f", "#5aa75a", "#e0c050"])


def build_lab_bench(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    riser = h > 1.2  # a tall box gets a reagent shelf riser
    top = min(0.92, 0.9 * h) if riser else h
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.05, 0.1), darker(p.primary, 0.4))
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0.1), (w / 2 - 0.02, d / 2 - 0.04, top - 0.04), p.primary)
    n = max(2, int(w / 0.5))
    for i in range(n):
        x0 = -w / 2 + 0.02 + i * (w - 0.04) / n
        x1 = x0 + (w - 0.04) / n
        b.box((x0 + 0.005, d / 2 - 0.04, 0.12), (x1 - 0.005, d / 2 - 0.02, top - 0.06), lighter(p.primary, 0.3))
        b.box(((x0 + x1) / 2 - 0.06, d / 2 - 0.02, top - 0.12), ((x0 + x1) / 2 + 0.06, d / 2 - 0.005, top - 0.1), METAL)
    b.box((-w / 2, -d / 2, top - 0.04), (w / 2, d / 2, top), p.secondary)
    if riser:
        for x in (-w / 2 + 0.03, w / 2 - 0.03):
            b.box((x - 0.02, -d / 2, top), (x + 0.02, -d / 2 + 0.04, h), METAL)
        for z in (top + 0.45 * (h - top), h - 0.02):
            b.box((-w / 2, -d / 2, z - 0.02), (w / 2, -d / 2 + 0.25, z), p.primary)
            for x in np.linspace(-w / 2 + 0.1, w / 2 - 0.1, max(2, int(w / 0.2))):
                if rng.random() < 0.6:
                    c = p.accent if rng.random() < 0.5 else GLASS
                    b.cyl(x, -d / 2 + 0.12, z, z + 0.1, 0.03, c, r_top=0.012)
    for x in np.linspace(-w / 2 + 0.2, w / 2 - 0.2, 3):
        b.cyl(x, -0.1 * d, top, top + 0.12, 0.04, GLASS, r_top=0.015, alpha=160)
    return b.mesh(p.size)


def sample_desk(rng, size, style):
    return make_params("desk", rng, size, style, wood_tones(style) + ["#e8e6e0", "#2b2b2b"],
                       DARK_METAL, HANDLE, legs=leg_style(rng, style),
                       panels=bool(rng.random() < 0.5), drawer_right=bool(rng.random() < 0.7))


def build_desk(p):
    w, d, h = p.size
    b = Builder()
    t = 0.03
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), p.primary)
    bw = min(0.42, w * 0.35)
    s = 1 if p.drawer_right else -1
    x_in = s * (w / 2 - bw)
    # drawer block on one side
    x0, x1 = sorted((x_in, s * (w / 2 - 0.01)))
    b.box((x0, -d / 2 + 0.02, 0.02), (x1, d / 2 - 0.02, h - t), p.primary)
    for k in range(3):
        z0 = 0.04 + k * (h - t - 0.06) / 3
        z1 = z0 + (h - t - 0.06) / 3 - 0.01
        b.box((x0 + 0.01, d / 2 - 0.02, z0), (x1 - 0.01, d / 2, z1), lighter(p.primary, 0.1))
        b.box(((x0 + x1) / 2 - 0.05, d / 2, z1 - 0.05), ((x0 + x1) / 2 + 0.05, d / 2 + 0.012, z1 - 0.035), p.accent)
    xo = -s * (w / 2 - 0.02)
    if p.panels:
        b.box((xo - 0.02, -d / 2 + 0.01, 0), (xo + 0.02, d / 2 - 0.01, h - t), p.primary)
    else:
        b.legs([(-s * (w / 2 - 0.04), -d / 2 + 0.04), (-s * (w / 2 - 0.04), d / 2 - 0.04)], 0, h - t, 0.022,
               p.legs, p.primary)
    # modesty panel at the back
    b.box((-w / 2 + 0.03, -d / 2 + 0.02, h * 0.4), (w / 2 - 0.03, -d / 2 + 0.04, h - t), darker(p.primary, 0.1))
    return b.mesh(p.size)


def sample_reception_desk(rng, size, style):
    return make_params("reception_desk", rng, size, style, ["#e8e6e0", "#2b2b2b"] + wood_tones(style),
                       wood_tones(style), ["#c9a54a", "#9fb2c0", "#e8e6e0"])


def build_reception_desk(p):
    w, d, h = p.size
    b = Builder()
    work = min(0.76, 0.7 * h)
    # work surface behind (-y), tall front panel facing visitors (+y)
    b.box((-w / 2, -d / 2, work - 0.03), (w / 2, d / 2 - 0.1, work), p.secondary)
    b.box((-w / 2, d / 2 - 0.1, 0), (w / 2, d / 2 - 0.02, h - 0.03), p.primary)
    b.box((-w / 2, d / 2 - 0.3, h - 0.03), (w / 2, d / 2, h), p.secondary)  # transaction ledge
    b.box((-w / 2 + 0.05, d / 2 - 0.02, 0.1), (w / 2 - 0.05, d / 2, 0.16), p.accent)
    for x in (-w / 2, w / 2 - 0.04):
        b.box((x, -d / 2, 0), (x + 0.04, d / 2 - 0.1, work - 0.03), p.primary)
    b.box((-0.25, -d / 2 + 0.1, work), (0.25, -d / 2 + 0.12, work + 0.3), BLACK)  # monitor
    b.box((-0.03, -d / 2 + 0.12, work), (0.03, -d / 2 + 0.16, work + 0.1), DARK_METAL)
    return b.mesh(p.size)


def sample_bar_counter(rng, size, style):
    return make_params("bar_counter", rng, size, style, wood_tones(style), ["#2b2b2b", "#e8e6e0", "#5c3b26"],
                       ["#c9a54a", METAL])


def build_bar_counter(p):
    w, d, h = p.size
    b = Builder()
    t = 0.05
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.15, 0.1), darker(p.primary, 0.4))
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0.1), (w / 2 - 0.02, d / 2 - 0.15, h - t), p.primary)
    n = max(1, int(w / 0.6))
    for x in np.linspace(-w / 2 + 0.3, w / 2 - 0.3, n):
        b.box((x - 0.22, d / 2 - 0.15, 0.2), (x + 0.22, d / 2 - 0.14, h - t - 0.1), darker(p.primary, 0.15))
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), p.secondary)
    b.rod((-w / 2 + 0.05, d / 2 - 0.08, 0.22), (w / 2 - 0.05, d / 2 - 0.08, 0.22), 0.02, p.accent)
    for x in (-w / 2 + 0.1, w / 2 - 0.1):
        b.rod((x, d / 2 - 0.08, 0.22), (x, d / 2 - 0.15, 0.22), 0.015, p.accent)
    return b.mesh(p.size)


slot_roles("table", "wood", "wood", "metal")
register("table", sample_table, build_table)
slot_roles("dining_table", "wood", "wood", "metal")
register("dining_table", sample_dining_table, build_dining_table)
slot_roles("coffee_table", "wood", "wood", "metal")
register("coffee_table", sample_coffee_table, build_coffee_table)
slot_roles("side_table", "wood", "wood", "metal")
register("side_table", sample_side_table, build_side_table)
slot_roles("conference_table", "wood", "metal", "plastic")
register("conference_table", sample_conference_table, build_conference_table)
slot_roles("lab_bench", "stone", "paint", "plastic")
register("lab_bench", sample_lab_bench, build_lab_bench)
slot_roles("desk", "wood", "metal", "metal")
register("desk", sample_desk, build_desk)
slot_roles("reception_desk", "wood", "wood", "metal")
register("reception_desk", sample_reception_desk, build_reception_desk)
slot_roles("bar_counter", "wood", "stone", "metal")
register("bar_counter", sample_bar_counter, build_bar_counter)
