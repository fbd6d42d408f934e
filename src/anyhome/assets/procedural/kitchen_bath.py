"""Kitchen, laundry and bath: counter, refrigerator, stove, sink, vanity, washing_machine,
dryer, fume_hood, toilet, bathtub, shower."""

from __future__ import annotations

from dataclasses import replace

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
from anyhome.assets.procedural.storage import HANDLE, case
from anyhome.assets.registry import register
from anyhome.assets.styles import class_name

APPLIANCE = tint(["#e9e9e6", "#c8cacd", "#b9bcc0", "#2b2b2b"], "paint")
WORKTOPS = tint(["#e4e1da", "#3a3a3c", "#d9cfb8", "#9a958c", "#f0eeea"], "stone")
PORCELAIN = tint("#f2f2ef", "ceramic")


def _cabinet_params(name, rng, size, style, **knobs):
    cab = wood_tones(style) + ["#e8e6e0", "#9fb2a0", "#3f4a5a", "#f0ede6"]
    return make_params(name, rng, size, style, cab, WORKTOPS, [HANDLE, "#2b2b2b", METAL], legs="straight",
                       **knobs)


def _base_cabinet(b: Builder, p, w, d, h, top_t=0.04) -> None:
    body = p.primary
    n = max(1, min(6, int(round(w / 0.6))))
    sec = replace(p, secondary=body)
    object.__setattr__(sec, "secondary", body)  # the fronts are the body's material, not the worktop's
    case(b, w, d - 0.02, h - top_t, sec, [("doors", n), ("drawers", n)], "plinth", 0.1)
    b.box((-w / 2, -d / 2, h - top_t), (w / 2, d / 2, h), p.secondary)


def sample_counter(rng, size, style):
    return _cabinet_params("counter", rng, size, style)


def build_counter(p):
    w, d, h = p.size
    b = Builder()
    _base_cabinet(b, p, w, d, h)
    return b.mesh(p.size)


def sample_sink(rng, size, style):
    return _cabinet_params("sink", rng, size, style, double=bool(rng.random() < 0.3))


def _basin(b: Builder, cx, cy, bw, bd, z, color) -> None:
    b.box((cx - bw / 2, cy - bd / 2, z - 0.004), (cx + bw / 2, cy + bd / 2, z + 0.006), color)
    b.box((cx - bw / 2 + 0.02, cy - bd / 2 + 0.02, z + 0.006), (cx + bw / 2 - 0.02, cy + bd / 2 - 0.02, z + 0.008),
          darker(color, 0.45))
    b.cyl(cx, cy, z + 0.008, z + 0.009, 0.025, DARK_METAL)


def _faucet(b: Builder, x, y, z, reach) -> None:
    b.cyl(x, y, z, z + 0.03, 0.03, METAL)
    b.cyl(x, y, z + 0.03, z + 0.25, 0.012, METAL)
    b.rod((x, y, z + 0.25), (x, y + reach, z + 0.22), 0.012, METAL)
    for dx in (-0.08, 0.08):
        b.cyl(x + dx, y, z, z + 0.05, 0.015, METAL)


def build_sink(p):
    w, d, h = p.size
    b = Builder()
    _base_cabinet(b, p, w, d, h)
    n = 2 if p.double and w > 1.0 else 1
    bw = min(0.55, (w - 0.1) / n)
    for i in range(n):
        cx = (i - (n - 1) / 2) * (bw + 0.05)
        _basin(b, cx, 0.02, bw - 0.04, d * 0.6, h, METAL)
    _faucet(b, 0, -d / 2 + 0.06, h, d * 0.3)
    return b.mesh(p.size)


def sample_vanity(rng, size, style):
    return _cabinet_params("vanity", rng, size, style, on_legs=bool(rng.random() < 0.4))


def build_vanity(p):
    w, d, h = p.size
    b = Builder()
    t = 0.04
    n = max(1, min(4, int(round(w / 0.5))))
    q = replace(p, secondary=p.primary, knobs=(("legs", "tapered" if p.on_legs else "straight"),))
    object.__setattr__(q, "secondary", p.primary)  # the fronts are the body's material, not the top's
    case(b, w, d - 0.02, h - t, q, [("doors", n), ("drawers", 1)], "legs" if p.on_legs else "plinth",
         0.18 * h if p.on_legs else 0.08)
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), PORCELAIN if p.secondary in WORKTOPS[:1] else p.secondary)
    nb = 2 if w > 1.3 else 1
    for i in range(nb):
        cx = (i - (nb - 1) / 2) * w / 2
        b.cyl(cx, 0.02, h, h + 0.01, min(0.22, w / (2 * nb) - 0.05), PORCELAIN, ry=d * 0.3, sections=24)
        b.cyl(cx, 0.02, h + 0.01, h + 0.012, min(0.18, w / (2 * nb) - 0.08), tint("#c9ccd0", "metal"), ry=d * 0.24, sections=24)
        _faucet(b, cx, -d / 2 + 0.05, h, d * 0.25)
    return b.mesh(p.size)


def sample_refrigerator(rng, size, style):
    return make_params("refrigerator", rng, size, style, APPLIANCE + ["#a8c8d8", "#e8c8c0"], METAL, DARK_METAL,
                       freezer_top=bool(rng.random() < 0.6), french=bool(rng.random() < 0.3))


def build_refrigerator(p):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2, -d / 2, 0.03), (w / 2, d / 2 - 0.04, h), p.primary)
    b.box((-w / 2 + 0.03, -d / 2, 0), (w / 2 - 0.03, d / 2 - 0.08, 0.03), BLACK)
    split = 0.7 * h if p.freezer_top else 0.32 * h
    fy = d / 2 - 0.04
    front = lighter(p.primary, 0.08)
    g = 0.006
    if p.french and w > 0.75:
        for s in (-1, 1):
            b.box((min(0, s * w / 2) + g, fy, split + g), (max(0, s * w / 2) - g, d / 2, h - g), front)
            b.box((s * 0.04 - 0.01, d / 2, split + 0.1), (s * 0.04 + 0.01, d / 2 + 0.025, h - 0.15), p.secondary)
        b.box((-w / 2 + g, fy, 0.03), (w / 2 - g, d / 2, split - g), front)
        b.box((-0.2, d / 2, split - 0.1), (0.2, d / 2 + 0.025, split - 0.08), p.secondary)
    else:
        hx = w / 2 - 0.06
        for z0, z1 in ((0.03, split), (split, h)):
            b.box((-w / 2 + g, fy, z0 + g), (w / 2 - g, d / 2, z1 - g), front)
            hz0 = z1 - 0.35 * (z1 - z0) if z1 < h else z0 + 0.08
            b.box((hx - 0.012, d / 2, hz0), (hx + 0.012, d / 2 + 0.03, hz0 + min(0.45, 0.3 * (z1 - z0))), p.secondary)
    return b.mesh(p.size)


def sample_stove(rng, size, style):
    return make_params("stove", rng, size, style, APPLIANCE + ["#1f1f22", "#7a1f2b", "#2f4a3a"],
                       BLACK, METAL)


def build_stove(p):
    w, d, h = p.size
    b = Builder()
    top = min(h, 0.92)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.02, top - 0.02), p.primary)
    b.box((-w / 2, -d / 2, top - 0.02), (w / 2, d / 2, top), p.secondary)  # cooktop
    for x in (-w / 4, w / 4):
        for y in (-d / 5, d / 6):
            b.cyl(x, y, top, top + 0.01, min(w, d) * 0.12, DARK_METAL, sections=20)
            b.cyl(x, y, top + 0.01, top + 0.015, min(w, d) * 0.05, BLACK, sections=12)
    # oven door with window and bar handle
    b.box((-w / 2 + 0.03, d / 2 - 0.02, 0.12), (w / 2 - 0.03, d / 2, top - 0.2), lighter(p.primary, 0.05))
    b.box((-w / 2 + 0.1, d / 2, 0.25), (w / 2 - 0.1, d / 2 + 0.005, top - 0.32), tint("#25282c", "paint"))
    b.rod((-w / 2 + 0.08, d / 2 + 0.035, top - 0.24), (w / 2 - 0.08, d / 2 + 0.035, top - 0.24), 0.012, p.accent)
    for x in np.linspace(-w / 2 + 0.1, w / 2 - 0.1, 5):
        b.rod((x, d / 2, top - 0.1), (x, d / 2 + 0.03, top - 0.1), 0.02, p.accent, sections=10)
    if h > top + 0.05:  # back splash panel
        b.box((-w / 2, -d / 2, top), (w / 2, -d / 2 + 0.05, h), p.primary)
    return b.mesh(p.size)


def _front_loader(name, rng, size, style):
    return make_params(name, rng, size, style, ["#eeeeec", "#e0e2e4", "#9a9da3", "#2b2b2b"], GLASS, DARK_METAL)


def sample_washing_machine(rng, size, style):
    return _front_loader("washing_machine", rng, size, style)


def _laundry(p, dryer: bool):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.02, h), p.primary)
    b.box((-w / 2 + 0.01, d / 2 - 0.02, h * 0.82), (w / 2 - 0.01, d / 2, h * 0.98), lighter(p.primary, 0.1))
    b.box((-w / 2 + 0.05, d / 2, h * 0.86), (-w / 2 + 0.25, d / 2 + 0.005, h * 0.94), tint("#c9ccd0", "metal"))  # drawer
    b.rod((w / 4, d / 2, h * 0.9), (w / 4, d / 2 + 0.02, h * 0.9), 0.03, p.accent, sections=16)
    b.box((w / 4 + 0.06, d / 2, h * 0.88), (w / 4 + 0.16, d / 2 + 0.004, h * 0.92), tint("#2b2b2b", "paint"))
    r = min(w, h) * 0.3
    cz = h * 0.45
    b.rod((0, d / 2 - 0.02, cz), (0, d / 2 + 0.03, cz), r, tint("#c9ccd0", "metal"), sections=32)
    b.rod((0, d / 2, cz), (0, d / 2 + 0.035, cz), r * 0.75, tint("#3a4a55", "paint") if not dryer else tint("#2b2b2b", "paint"), sections=32)
    if not dryer:
        b.rod((0, d / 2, cz), (0, d / 2 + 0.038, cz), r * 0.5, p.secondary, sections=24, alpha=170)
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.05, 0.02), BLACK)
    return b.mesh(p.size)


def build_washing_machine(p):
    return _laundry(p, dryer=False)


def sample_dryer(rng, size, style):
    return _front_loader("dryer", rng, size, style)


def build_dryer(p):
    return _laundry(p, dryer=True)


def sample_fume_hood(rng, size, style):
    return make_params("fume_hood", rng, size, style, ["#e8e6e0", "#d9dde2"], GLASS, ["#2b2b2b", "#3f4a5a"])


def build_fume_hood(p):
    w, d, h = p.size
    b = Builder()
    work = min(0.9, 0.4 * h)
    b.box((-w / 2 + 0.02, -d / 2, 0), (w / 2 - 0.02, d / 2 - 0.02, work - 0.04), p.primary)
    for i in range(2):
        x0 = -w / 2 + 0.04 + i * (w - 0.08) / 2
        b.box((x0 + 0.005, d / 2 - 0.02, 0.1), (x0 + (w - 0.08) / 2 - 0.005, d / 2, work - 0.06),
              lighter(p.primary, 0.3))
    b.box((-w / 2, -d / 2, work - 0.04), (w / 2, d / 2, work), p.accent)
    top0 = h - 0.3
    for x in (-w / 2, w / 2 - 0.08):
        b.box((x, -d / 2, work), (x + 0.08, d / 2, top0), p.primary)
    b.box((-w / 2, -d / 2, work), (w / 2, -d / 2 + 0.04, top0), darker(p.primary, 0.05))
    b.box((-w / 2, -d / 2, top0), (w / 2, d / 2, h - 0.12), p.primary)
    b.box((-w / 2 + 0.08, d / 2 - 0.05, work + 0.35), (w / 2 - 0.08, d / 2 - 0.03, top0), p.secondary, alpha=110)
    b.box((-w / 2 + 0.08, d / 2 - 0.06, work + 0.33), (w / 2 - 0.08, d / 2 - 0.02, work + 0.37), p.accent)
    b.cyl(0, 0, h - 0.12, h, min(0.15, w / 6), tint("#c9ccd0", "metal"))
    return b.mesh(p.size)


def sample_toilet(rng, size, style):
    return make_params("toilet", rng, size, style, [PORCELAIN, "#ecebe6", "#e9ecef"], PORCELAIN, METAL,
                       lid_open=bool(rng.random() < 0.3))


def build_toilet(p):
    w, d, h = p.size
    b = Builder()
    seat = min(0.42, 0.55 * h)
    tank_d = min(0.2, 0.3 * d)
    # tank at the back
    b.box((-w / 2, -d / 2, seat - 0.05), (w / 2, -d / 2 + tank_d, h - 0.03), p.primary)
    b.box((-w / 2 - 0.0, -d / 2, h - 0.03), (w / 2, -d / 2 + tank_d + 0.01, h), lighter(p.primary, 0.1))
    b.cyl(w / 2 - 0.06, -d / 2 + tank_d / 2, h, h + 0.01, 0.015, p.accent)
    # pedestal and bowl
    by = -d / 2 + tank_d + (d - tank_d) / 2 - 0.02
    b.cyl(0, by - 0.03, 0, seat * 0.6, w * 0.22, p.primary, r_top=w * 0.3, ry=(d - tank_d) * 0.3)
    b.cyl(0, by, seat * 0.55, seat - 0.03, w * 0.33, p.primary, r_top=w * 0.48, ry=(d - tank_d) * 0.44, sections=24)
    b.cyl(0, by, seat - 0.03, seat, w * 0.48, p.secondary, ry=(d - tank_d) * 0.48, sections=24)
    b.cyl(0, by, seat, seat + 0.003, w * 0.32, tint("#9fb4c0", "glass"), ry=(d - tank_d) * 0.3, sections=20)
    if p.lid_open:
        b.box((-w * 0.42, -d / 2 + tank_d + 0.01, seat), (w * 0.42, -d / 2 + tank_d + 0.03, seat + 0.4),
              p.secondary)
    else:
        b.cyl(0, by, seat + 0.003, seat + 0.02, w * 0.46, p.secondary, ry=(d - tank_d) * 0.46, sections=24)
    return b.mesh(p.size)


def sample_bathtub(rng, size, style):
    return make_params("bathtub", rng, size, style, [PORCELAIN, "#ecebe6", "#e9ecef", "#2b2b2b"], "#cfe3ea",
                       METAL, clawfoot=bool(rng.random() < (0.7 if "victorian" in class_name(style) else 0.15)))


def build_bathtub(p):
    w, d, h = p.size
    b = Builder()
    z0 = 0.12 * h if p.clawfoot else 0.0
    t = 0.07
    if p.clawfoot:
        for x in (-w / 2 + 0.15, w / 2 - 0.15):
            for y in (-d / 2 + 0.12, d / 2 - 0.12):
                b.sphere((x, y, z0 / 2), (0.05, 0.05, z0 / 2), p.accent)
        b.cyl(0, 0, z0, h, w / 2 * 0.93, p.primary, r_top=w / 2, ry=d / 2 * 0.9, sections=32)
        b.cyl(0, 0, h - 0.005, h + 0.002, w / 2 - t, tint("#d8e8ee", "paint"), ry=d / 2 - t, sections=32)
    else:
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, h - 0.04), p.primary)
        b.box((-w / 2, -d / 2, h - 0.04), (w / 2, d / 2, h), lighter(p.primary, 0.1))
        b.cyl(0, 0, h - 0.004, h + 0.002, w / 2 - t, tint("#d8e8ee", "paint"), ry=d / 2 - t, sections=32)
    b.cyl(-w / 2 + 0.12, 0, h, h + 0.04, 0.02, p.accent)
    b.rod((-w / 2 + 0.12, 0, h + 0.04), (-w / 2 + 0.22, 0, h + 0.03), 0.015, p.accent)
    return b.mesh(p.size)


def sample_shower(rng, size, style):
    return make_params("shower", rng, size, style, ["#e9ecef", "#d9d4c7", "#c9ccd0"], GLASS, METAL)


def build_shower(p):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.08), p.primary)
    b.box((-w / 2 + 0.05, -d / 2 + 0.05, 0.08), (w / 2 - 0.05, d / 2 - 0.05, 0.085), darker(p.primary, 0.1))
    b.cyl(0, 0, 0.085, 0.09, 0.04, DARK_METAL)
    # glass on the front and the right side, frame profile
    b.box((-w / 2, d / 2 - 0.01, 0.08), (w / 2, d / 2, h - 0.02), p.secondary, alpha=90)
    b.box((w / 2 - 0.01, -d / 2, 0.08), (w / 2, d / 2, h - 0.02), p.secondary, alpha=90)
    b.box((-w / 2, d / 2 - 0.02, h - 0.04), (w / 2, d / 2, h - 0.02), p.accent)
    b.box((w / 2 - 0.02, -d / 2, h - 0.04), (w / 2, d / 2, h - 0.02), p.accent)
    for x, y in ((-w / 2, d / 2 - 0.02), (w / 2 - 0.02, d / 2 - 0.02), (w / 2 - 0.02, -d / 2)):
        b.box((x, y, 0.08), (x + 0.02, y + 0.02, h - 0.02), p.accent)
    # riser pipe and head on the back wall
    b.cyl(0, -d / 2 + 0.03, 0.9, h - 0.15, 0.012, p.accent)
    b.rod((0, -d / 2 + 0.03, h - 0.15), (0, -d / 2 + 0.25, h - 0.1), 0.012, p.accent)
    b.cyl(0, -d / 2 + 0.25, h - 0.12, h - 0.09, 0.1, p.accent, sections=20)
    b.cyl(0.0, -d / 2 + 0.03, 1.0, 1.06, 0.035, p.accent)
    b.box((-w / 2 + 0.05, -d / 2, 1.2), (-w / 2 + 0.25, -d / 2 + 0.1, 1.22), p.accent)
    return b.mesh(p.size)


slot_roles("counter", "wood", "stone", "metal")
register("counter", sample_counter, build_counter)
slot_roles("sink", "wood", "stone", "metal")
register("sink", sample_sink, build_sink)
slot_roles("vanity", "wood", "stone", "metal")
register("vanity", sample_vanity, build_vanity)
slot_roles("refrigerator", "metal", "metal", "metal")
register("refrigerator", sample_refrigerator, build_refrigerator)
slot_roles("stove", "metal", "plastic", "metal")
register("stove", sample_stove, build_stove)
slot_roles("washing_machine", "metal", "plastic", "glass")
register("washing_machine", sample_washing_machine, build_washing_machine)
slot_roles("dryer", "metal", "plastic", "glass")
register("dryer", sample_dryer, build_dryer)
slot_roles("fume_hood", "paint", "glass", "plastic")
register("fume_hood", sample_fume_hood, build_fume_hood)
slot_roles("toilet", "ceramic", "ceramic", "metal")
register("toilet", sample_toilet, build_toilet)
slot_roles("bathtub", "ceramic", "ceramic", "metal")
register("bathtub", sample_bathtub, build_bathtub)
slot_roles("shower", {"": "ceramic", "#c9ccd0": "metal"}, "glass", "metal")
register("shower", sample_shower, build_shower)
