"""Sport and games: boxing_ring, punching_bag, climbing_wall, pool_table,
ping_pong_table, arcade_cabinet, vending_machine."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    corners,
    darker,
    leg_style,
    lengthwise,
    lighter,
    make_params,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

HOLD_COLORS = tint(["#e05a47", "#f1c40f", "#2e86c1", "#27ae60", "#8e44ad", "#f08a2a", "#ec7fa9", "#1f1f22"], "plastic")
FELTS = tint(["#2f6b3a", "#24588a", "#7a1f2b", "#3a5f4a"], "fabric")
PRODUCTS = tint(["#c0392b", "#f1c40f", "#2e86c1", "#27ae60", "#e67e22", "#8e44ad", "#ecf0f1", "#d35400"], "paper")
SCREEN_GLOW = tint(["#3a7bd5", "#4ab0c0", "#7b4ad5"], "screen")


# ----------------------------------------------------------------- boxing ring
def sample_boxing_ring(rng, size, style):
    return make_params("boxing_ring", rng, size, style, ["#2d4f8a", "#1f1f22", "#b8322a", "#3a3b3e"],
                       ["#e8e6e0", "#d0d8e0", "#3a6fb0"], ["#c0392b", "#e8e6e0", "#2d4f8a"],
                       ropes=int(rng.choice([3, 4])))


def build_boxing_ring(p):
    w, d, h = p.size
    b = Builder()
    deck = 0.35 * h
    apron = 0.45
    inner_w, inner_d = w - 2 * apron * 0.5, d - 2 * apron * 0.5
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.02, deck - 0.05), p.primary)  # skirt
    b.box((-w / 2, -d / 2, deck - 0.05), (w / 2, d / 2, deck), p.secondary)  # canvas
    b.box((-inner_w / 2 * 0.5, d / 2 - 0.02 + 0.001, 0.3 * deck), (inner_w / 2 * 0.5, d / 2 - 0.015, 0.7 * deck),
          lighter(p.primary, 0.35))  # a logo band on the skirt
    post_r = 0.06
    pad = [p.accent, "#e8e6e0", "#2d4f8a" if p.accent != "#2d4f8a" else "#c0392b", "#e8e6e0"]
    cs = corners(inner_w, inner_d, 0.0)
    for (x, y), col in zip(cs, pad, strict=True):
        b.cyl(x, y, deck, h, post_r, DARK_METAL, sections=10)
        b.cyl(x, y, deck + 0.15 * (h - deck), h - 0.02, post_r * 1.6, col, sections=10, role="leather")  # corner pad
    for k in range(p.ropes):
        z = deck + (h - deck) * (0.3 + 0.65 * k / max(1, p.ropes - 1))
        col = [p.accent, "#e8e6e0", "#2d4f8a"][k % 3]
        for i in range(4):
            (x0, y0), (x1, y1) = cs[i], cs[(i + 1) % 4]
            b.rod((x0, y0, z), (x1, y1, z), 0.02, col, sections=6, role="fabric")
    return b.mesh(p.size)


# ----------------------------------------------------------------- punching bag
def sample_punching_bag(rng, size, style):
    return make_params("punching_bag", rng, size, style, ["#b8322a", BLACK, "#2d4f8a", "#5c3b26", "#3f6b4a"],
                       ["#e8e6e0", BLACK, "#d9a32a"], DARK_METAL, mount=str(rng.choice(["stand", "ceiling"])))


def build_punching_bag(p):
    """A heavy bag hanging on chains from a wall-bracket stand (its post at -y) or a ceiling hook."""
    w, d, h = p.size
    b = Builder()
    r = 0.42 * min(w, d) if p.mount == "ceiling" else 0.34 * min(w, d)
    cy = 0.0 if p.mount == "ceiling" else d / 2 - r - 0.01
    bag_top = h - (0.25 if p.mount == "ceiling" else 0.3) * h * 0.6
    bag_bot = bag_top - min(1.1, 0.62 * h)
    b.cyl(0, cy, bag_bot + 0.05, bag_top - 0.05, r, p.primary, sections=20)
    b.cyl(0, cy, bag_bot, bag_bot + 0.05, r * 0.95, p.primary, r_top=r, sections=20)
    b.cyl(0, cy, bag_top - 0.05, bag_top, r, darker(p.primary, 0.1), r_top=r * 0.85, sections=20)
    for z in (bag_bot + 0.2 * (bag_top - bag_bot), bag_top - 0.15 * (bag_top - bag_bot)):
        b.cyl(0, cy, z, z + 0.05, r * 1.01, p.secondary, sections=20)
    b.cyl(0, cy, bag_top, bag_top + 0.02, 0.04, DARK_METAL, sections=8)
    hook = np.array([0, cy, h - 0.06 if p.mount == "stand" else h - 0.03])
    for a in range(4):
        ang = np.pi / 4 + a * np.pi / 2
        b.rod((0.8 * r * np.cos(ang), cy + 0.8 * r * np.sin(ang), bag_top), hook, 0.006, METAL, sections=4)
    if p.mount == "ceiling":
        b.cyl(0, cy, h - 0.03, h, 0.08, p.accent, sections=12)
        return b.mesh(p.size)
    post_y = -d / 2 + 0.04
    b.box((-0.04, post_y - 0.04, 0), (0.04, post_y + 0.04, h), p.accent)  # post
    b.box((-0.04, post_y, h - 0.06), (0.04, cy + 0.04, h), p.accent)  # arm over the bag
    b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + 0.12, 0.04), p.accent)  # foot
    b.rod((0, post_y, h - 0.3), (0, post_y + 0.3 * (cy - post_y), h - 0.06), 0.02, p.accent, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- climbing wall
def sample_climbing_wall(rng, size, style):
    return make_params("climbing_wall", rng, size, style, ["#d9c3a0", "#c9ccd0", "#8a9aa8", "#e8e6e0", "#3a3b3e"],
                       ["#2d4f8a", "#3a3b3e", "#c0392b"], HOLD_COLORS[0], panels=int(rng.integers(2, 4)),
                       holds_per_m2=float(rng.uniform(3.0, 5.0)))


def build_climbing_wall(p):
    """Panels of plywood (vertical, slab, overhang) covered in coloured holds, a crash mat in front."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    mat_d = min(0.35 * d, 0.4)  # floor kept clear of overhangs in front of the panels
    back = -d / 2
    n = p.panels
    pw = w / n
    overhang = [(0.0, 1.0, 0.5)[i % 3] for i in range(n)]  # share of the free depth each panel's top leans out
    rng.shuffle(overhang)
    free = d - mat_d - 0.08
    for i in range(n):
        x0 = -w / 2 + i * pw
        y_top = back + 0.05 + overhang[i] * free
        face = [(back, 0), (back + 0.05, 0), (y_top, h), (back, h)]
        col = p.primary if i % 2 == 0 else lighter(p.primary, 0.1)
        b.extrude_x(face, x0, x0 + pw - 0.01, col)
        for _ in range(int(pw * h * p.holds_per_m2)):
            u, v = rng.uniform(0.05, 0.95), rng.uniform(0.04, 0.97)
            s = rng.uniform(0.05, 0.11)
            colour = HOLD_COLORS[int(rng.integers(len(HOLD_COLORS)))]
            b.sphere((x0 + u * pw, back + 0.05 + (y_top - back - 0.05) * v + 0.01, v * h),
                     (s, 0.04, s * rng.uniform(0.6, 1.0)), colour, subdivisions=0)
        if pw > 0.8:  # a triangular volume on the panel
            u, v = rng.uniform(0.25, 0.75), rng.uniform(0.3, 0.7)
            c = np.array([x0 + u * pw, back + 0.05 + (y_top - back - 0.05) * v, v * h])
            s = min(0.35, 0.25 * pw)
            b.hull([c + (-s, 0, -s), c + (s, 0, -s), c + (0, 0, s), c + (0, 0.6 * s, -0.3 * s)],
                   HOLD_COLORS[i % len(HOLD_COLORS)])
    b.box((-w / 2, -d / 2, h - 0.02), (w / 2, -d / 2 + 0.06, h), darker(p.primary, 0.3))
    b.box((-w / 2 + 0.02, back + 0.08, 0), (w / 2 - 0.02, d / 2, min(0.25, 0.08 * h)), p.secondary)
    return b.mesh(p.size)


# ----------------------------------------------------------------- pool table
def sample_pool_table(rng, size, style):
    return make_params("pool_table", rng, size, style, wood_tones(style) + [BLACK], FELTS, "#e8e6e0",
                       legs=leg_style(rng, style), balls=bool(rng.random() < 0.8))


def _draw_pool_table(b: Builder, L: float, B: float, H: float, p) -> None:
    rng = np.random.default_rng(p.seed)
    rail = min(0.14, 0.1 * B)
    top = H
    body = top - 0.05
    apron = 0.22 * H
    b.box((-L / 2 + 0.03, -B / 2 + 0.03, body - apron), (L / 2 - 0.03, B / 2 - 0.03, body), p.primary)
    legs = corners(L, B, 0.16) + [(0, -B / 2 + 0.16), (0, B / 2 - 0.16)] if L > 2.2 else corners(L, B, 0.16)
    b.legs(legs, 0, body - apron, 0.07, p.legs if p.legs != "metal" else "straight", p.primary)
    b.box((-L / 2 + rail, -B / 2 + rail, body - 0.03), (L / 2 - rail, B / 2 - rail, body), p.secondary)  # bed
    for sy in (-1, 1):  # rails: wood cap and a felt cushion
        b.box((-L / 2, sy * B / 2 - (rail if sy > 0 else 0), body), (L / 2, sy * B / 2 + (rail if sy < 0 else 0), top),
              p.primary)
        y = sy * (B / 2 - rail)
        b.box((-L / 2 + rail, min(y, y - sy * 0.03), body), (L / 2 - rail, max(y, y - sy * 0.03), top - 0.015),
              darker(p.secondary, 0.15))
    for sx in (-1, 1):
        b.box((min(sx * L / 2, sx * (L / 2 - rail)), -B / 2, body), (max(sx * L / 2, sx * (L / 2 - rail)), B / 2, top),
              p.primary)
    for x in (-L / 2 + rail * 0.6, 0.0, L / 2 - rail * 0.6):  # pockets
        for sy in (-1, 1):
            b.cyl(x, sy * (B / 2 - rail * 0.6), top - 0.004, top + 0.002, 0.055, tint("#111111", "leather"), sections=12)
    for i in range(6):  # diamonds on the rails
        x = -L / 2 + (i + 1) * L / 7
        for sy in (-1, 1):
            b.cbox((x, sy * (B / 2 - rail / 2), top), (0.02, 0.02, 0.004), tint("#e8dcc0", "plastic"))
    if p.balls:
        r = 0.028
        x0 = L / 4
        k = 0
        for row in range(4):
            for j in range(row + 1):
                col = ["#f1c40f", "#2e86c1", "#c0392b", "#8e44ad", "#e67e22", "#27ae60", "#7a1f2b", BLACK,
                       "#f1c40f", "#2e86c1"][k % 10]
                b.sphere((x0 + row * 2 * r * 0.87, (j - row / 2) * 2 * r, body + r), r, col, subdivisions=1, role="plastic")
                k += 1
        b.sphere((-L / 4, 0.0, body + r), r, tint("#f4f1ea", "plastic"), subdivisions=1)
        a = rng.uniform(-0.3, 0.3)
        b.rod((-L / 4 - 0.05, 0, body + 0.03), (-L / 4 - 0.05 - 1.3 * np.cos(a) * 0.6 * L / 1.3, np.sin(a) * 0.3 * B,
                                                  body + 0.06), 0.012, tint("#c9a06a", "wood"), sections=6)


def build_pool_table(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_pool_table(b, L, B, H, p))


# ----------------------------------------------------------------- ping pong table
def sample_ping_pong_table(rng, size, style):
    return make_params("ping_pong_table", rng, size, style, ["#1f3f6a", "#2f5a3a", "#1f4f7a"], "#f4f1ea",
                       ["#c0392b", BLACK], paddles=bool(rng.random() < 0.7))


def _draw_ping_pong(b: Builder, L: float, B: float, H: float, p) -> None:
    net_h = 0.17 * H
    top = H - net_h
    b.box((-L / 2, -B / 2, top - 0.025), (L / 2, B / 2, top), p.primary)
    line = 0.02
    for sy in (-1, 1):
        b.box((-L / 2, sy * B / 2 - line * (sy > 0), top), (L / 2, sy * B / 2 + line * (sy < 0), top + 0.001),
              p.secondary)
    for sx in (-1, 1):
        b.box((sx * L / 2 - line * (sx > 0), -B / 2, top), (sx * L / 2 + line * (sx < 0), B / 2, top + 0.001),
              p.secondary)
    b.box((-L / 2, -0.003, top), (L / 2, 0.003, top + 0.001), p.secondary)  # centre line
    b.box((-0.004, -B / 2, top), (0.004, B / 2, H - 0.01), tint("#2b2b2b", "fabric"), alpha=200)  # net
    b.box((-0.006, -B / 2, H - 0.012), (0.006, B / 2, H), tint("#f4f1ea", "paint"))
    for sy in (-1, 1):
        b.cyl(0, sy * (B / 2 - 0.01), top, H, 0.012, DARK_METAL, sections=8)
    for sx in (-1, 1):  # two undercarriages with wheels
        x = sx * L / 4
        for sy in (-1, 1):
            b.box((x - 0.03, sy * (B / 2 - 0.15) - 0.02, 0.06), (x + 0.03, sy * (B / 2 - 0.15) + 0.02, top - 0.025),
                  DARK_METAL)
            b.rod((x, sy * (B / 2 - 0.15), 0.04), (x + 0.001, sy * (B / 2 - 0.15), 0.04), 0.04, BLACK, sections=10)
            b.sphere((x, sy * (B / 2 - 0.15), 0.04), 0.04, BLACK, subdivisions=1)
        b.box((x - 0.02, -B / 2 + 0.15, 0.3 * top), (x + 0.02, B / 2 - 0.15, 0.3 * top + 0.04), DARK_METAL)
    if p.paddles:
        for sx, fy in ((-1, 0.2), (1, -0.25)):
            x = sx * L / 3
            b.cyl(x, fy * B, top, top + 0.012, 0.08, p.accent, sections=16)
            b.box((x - 0.012, fy * B + 0.07, top), (x + 0.012, fy * B + 0.17, top + 0.02), tint("#c9a06a", "wood"))
        b.sphere((L / 6, 0.1 * B, top + 0.02), 0.02, tint("#f4f1ea", "plastic"), subdivisions=1)


def build_ping_pong_table(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_ping_pong(b, L, B, H, p))


# ----------------------------------------------------------------- arcade cabinet
def sample_arcade_cabinet(rng, size, style):
    w, d, _ = size
    kind = "pinball" if d > 1.4 * w else "upright"
    return make_params("arcade_cabinet", rng, size, style,
                       [BLACK, "#2d4f8a", "#b8322a", "#3f6b4a", "#e8c53a", "#6a3a8a"], SCREEN_GLOW,
                       ["#f1c40f", "#e74c3c", "#3498db"], kind=kind, players=int(rng.integers(1, 3)))


def _screen(b: Builder, x0: float, x1: float, pts, glow: str) -> None:
    b.hull([(x0, *q) for q in pts] + [(x1, *q) for q in pts], glow)


def build_arcade_cabinet(p):
    """Upright: marquee on top, slanted screen, control panel towards the player (+y).
    Pinball (a box much deeper than wide): a sloping table on legs, backbox at -y."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "pinball":
        leg_top = 0.45 * h
        yb = -d / 2 + 0.12 * d
        front_z, back_z = leg_top + 0.2, leg_top + 0.3
        b.hull([(-w / 2, d / 2, leg_top), (w / 2, d / 2, leg_top), (-w / 2, yb, leg_top), (w / 2, yb, leg_top),
                (-w / 2, d / 2, front_z), (w / 2, d / 2, front_z), (-w / 2, yb, back_z), (w / 2, yb, back_z)],
               p.primary)
        _screen(b, -w / 2 + 0.04, w / 2 - 0.04, [(d / 2 - 0.08, front_z), (yb + 0.05, back_z),
                                                 (d / 2 - 0.08, front_z + 0.005), (yb + 0.05, back_z + 0.005)],
                p.secondary)
        rng = np.random.default_rng(p.seed)
        for _ in range(6):  # bumpers
            t = rng.uniform(0.2, 0.7)
            b.cyl(rng.uniform(-0.3, 0.3) * w, d / 2 - 0.08 - t * (d / 2 - 0.08 - yb),
                  front_z + t * (back_z - front_z), front_z + t * (back_z - front_z) + 0.04, 0.035, p.accent,
                  sections=10)
        b.box((-w / 2, -d / 2, leg_top), (w / 2, yb, h), p.primary)  # backbox
        b.box((-w / 2 + 0.04, yb, back_z + 0.1), (w / 2 - 0.04, yb + 0.01, h - 0.05), p.accent)
        b.box((-w / 2 + 0.08, yb + 0.01, back_z + 0.2), (w / 2 - 0.08, yb + 0.012, h - 0.2), p.secondary)
        for x, y in corners(w, d, 0.05):
            b.box((x - 0.03, y - 0.03, 0), (x + 0.03, y + 0.03, leg_top), DARK_METAL)
        return b.mesh(p.size)
    # upright side profile (y, z)
    yf, yb = d / 2, -d / 2
    panel_z = 0.48 * h
    prof = [(yb, 0), (yf - 0.1 * d, 0), (yf - 0.1 * d, panel_z - 0.1 * h), (yf, panel_z - 0.02 * h),
            (yf, panel_z + 0.02 * h), (yf - 0.3 * d, panel_z + 0.06 * h), (yf - 0.12 * d, 0.86 * h),
            (yf - 0.05 * d, 0.88 * h), (yf - 0.05 * d, h), (yb, h)]
    side = 0.03
    b.extrude_x(prof, -w / 2, -w / 2 + side, p.primary)
    b.extrude_x(prof, w / 2 - side, w / 2, p.primary)
    inner = [(y if y < yf - 0.3 * d else y - 0.01, z) for y, z in prof]
    b.extrude_x(inner, -w / 2 + side, w / 2 - side, BLACK)
    _screen(b, -w / 2 + side, w / 2 - side, [(yf - 0.3 * d + 0.01, panel_z + 0.08 * h), (yf - 0.13 * d, 0.83 * h),
                                              (yf - 0.3 * d, panel_z + 0.08 * h), (yf - 0.14 * d, 0.83 * h)],
            p.secondary)
    b.box((-w / 2 + side, yf - 0.05 * d - 0.02, 0.88 * h + 0.01), (w / 2 - side, yf - 0.05 * d, h - 0.01), p.accent)
    b.box((-w / 2 + side, yf - 0.3 * d, panel_z + 0.05 * h), (w / 2 - side, yf, panel_z + 0.055 * h), DARK_METAL)
    cols = ["#e74c3c", "#3498db", "#f1c40f", "#2ecc71"]
    for pl in range(p.players):
        cx = (-0.22 if p.players == 2 and pl == 0 else (0.22 if p.players == 2 else 0.0)) * w
        b.rod((cx - 0.08, yf - 0.12 * d, panel_z + 0.02 * h), (cx - 0.08, yf - 0.12 * d, panel_z + 0.1 * h), 0.008,
              BLACK, sections=6)
        b.sphere((cx - 0.08, yf - 0.12 * d, panel_z + 0.1 * h), 0.025, tint("#e74c3c", "paint"), subdivisions=1)
        for k in range(3):
            b.cyl(cx + 0.02 + 0.045 * k, yf - 0.12 * d, panel_z + 0.03 * h, panel_z + 0.045 * h, 0.016, cols[k],
                  sections=10, role="plastic")
    b.box((-0.08, yf - 0.1 * d - 0.005, 0.2 * h), (0.08, yf - 0.1 * d, 0.3 * h), DARK_METAL)  # coin door
    b.box((-0.02, yf - 0.1 * d - 0.008, 0.27 * h), (0.02, yf - 0.1 * d - 0.004, 0.28 * h), tint("#e74c3c", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- vending machine
def sample_vending_machine(rng, size, style):
    return make_params("vending_machine", rng, size, style,
                       ["#b8322a", "#2d4f8a", BLACK, "#e8e6e0", "#3f6b4a", "#d9a32a"], "#c8dce6", METAL,
                       rows=int(rng.integers(5, 7)), drinks=bool(rng.random() < 0.5))


def build_vending_machine(p):
    """Glass front with rows of goods on the left, keypad and coin slot on the right, a
    pick-up flap at the bottom."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    yf = d / 2
    b.box((-w / 2, -d / 2, 0.04), (w / 2, yf - 0.02, h), p.primary)
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.04, 0.04), BLACK)
    gx0, gx1 = -w / 2 + 0.05, w / 2 - 0.3 * w
    gz0, gz1 = 0.25 * h, h - 0.08
    b.box((gx0, yf - 0.2, gz0), (gx1, yf - 0.02, gz1), tint("#1c2430", "paint"))  # dark interior
    rows = p.rows
    for r in range(rows):
        z = gz0 + (r + 0.15) * (gz1 - gz0) / rows
        b.box((gx0, yf - 0.2, z - 0.01), (gx1, yf - 0.03, z), METAL)
        n = max(4, int((gx1 - gx0) / 0.09))
        for i in range(n):
            x = gx0 + (i + 0.5) * (gx1 - gx0) / n
            col = PRODUCTS[(r * 3 + i * (1 + r % 2) + int(rng.integers(2))) % len(PRODUCTS)]
            item_h = 0.6 * (gz1 - gz0) / rows
            if p.drinks:
                b.cyl(x, yf - 0.08, z, z + item_h, 0.028, col, sections=8)
            else:
                b.box((x - 0.03, yf - 0.1, z), (x + 0.03, yf - 0.05, z + item_h * 0.8), col)
    b.box((gx0 - 0.005, yf - 0.02, gz0), (gx1 + 0.005, yf, gz1), p.secondary, alpha=90)  # glass
    for x in (gx0 - 0.02, gx1):
        b.box((x, yf - 0.02, gz0 - 0.02), (x + 0.02, yf + 0.005, gz1 + 0.02), darker(p.primary, 0.2))
    b.box((gx0 - 0.02, yf - 0.02, gz1), (gx1 + 0.02, yf + 0.005, gz1 + 0.02), darker(p.primary, 0.2))
    b.box((gx0 - 0.02, yf - 0.02, gz0 - 0.02), (gx1 + 0.02, yf + 0.005, gz0), darker(p.primary, 0.2))
    px0 = gx1 + 0.04
    b.box((px0, yf - 0.02, 0.55 * h), (w / 2 - 0.04, yf + 0.005, 0.75 * h), tint("#2b2b2b", "paint"))  # keypad panel
    for r in range(4):
        for c in range(3):
            b.cbox((px0 + 0.03 + c * (w / 2 - 0.07 - px0) / 3, yf + 0.008, 0.58 * h + r * 0.04 * h),
                   (0.025, 0.008, 0.025), tint("#c9ccd0", "metal"))
    b.box((px0 + 0.02, yf - 0.02, 0.8 * h), (w / 2 - 0.06, yf + 0.005, 0.86 * h), tint("#3ab0a0", "screen"))  # display
    b.box((gx0, yf - 0.02, 0.08 * h), (gx1, yf + 0.005, 0.18 * h), BLACK)  # pick-up flap
    b.box((gx0, yf - 0.02, h - 0.07), (w / 2 - 0.04, yf + 0.004, h - 0.02), lighter(p.primary, 0.35))
    return b.mesh(p.size)


slot_roles("boxing_ring", "fabric", "fabric", "fabric")
register("boxing_ring", sample_boxing_ring, build_boxing_ring)
slot_roles("punching_bag", "leather", "fabric", "metal")
register("punching_bag", sample_punching_bag, build_punching_bag)
slot_roles("climbing_wall", {"": "wood", "#c9ccd0": "metal"}, "plastic", "plastic")
register("climbing_wall", sample_climbing_wall, build_climbing_wall)
slot_roles("pool_table", "wood", "fabric", "plastic")
register("pool_table", sample_pool_table, build_pool_table)
slot_roles("ping_pong_table", "paint", "paint", "plastic")
register("ping_pong_table", sample_ping_pong_table, build_ping_pong_table)
slot_roles("arcade_cabinet", "paint", "screen", "plastic")
register("arcade_cabinet", sample_arcade_cabinet, build_arcade_cabinet)
slot_roles("vending_machine", "paint", "glass", "metal")
register("vending_machine", sample_vending_machine, build_vending_machine)
