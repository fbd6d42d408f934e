"""A distribution warehouse's things: dock_leveller (the hinged steel ramp at a loading
bay's door), roller_shutter (a slatted steel door that rolls up into a box over the
opening) and battery_charger (a forklift battery charger with its cable and plug)."""

from __future__ import annotations

from anyhome.assets.procedural._kit import GLOW_GREEN, GLOW_RED, RUBBER, SCREEN, path, vent_lines
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
)
from anyhome.assets.registry import register

DECK = tint(["#6b6e72", "#5f6b7a", "#7a7d82"], "metal")
HAZARD_YELLOW = tint("#e8c020", "paint")
SHUTTER = tint(["#b4b8bd", "#e8e6e0", "#5f6b7a", "#2d6fb0", "#3f6a4a", "#8a2a2a"], "paint")
DARK_OPENING = tint("#1a1b1e", "paint")
PLUG_RED = tint("#c0392b", "plastic")
CHARGER = tint(["#e8e6e0", "#2d6fb0", "#e07020", "#3f8a4a", "#5f6b7a"], "paint")


# ----------------------------------------------------------------- dock leveller
def sample_dock_leveller(rng, size, style):
    return make_params("dock_leveller", rng, size, style, DECK, HAZARD_YELLOW, RUBBER,
                       lip_up=bool(rng.random() < 0.4), bumpers=bool(rng.random() < 0.8))


def build_dock_leveller(p):
    """A dock leveller set in the floor at a loading door (the door side at +y): a steel
    deck of checker plate a little proud of the floor, its frame and side toe guards
    painted in yellow and black hazard stripes, the hinged lip at the door end (raised
    when ``lip_up``), and, when ``bumpers``, the two black rubber dock bumpers either
    side of it that a lorry backs up to."""
    w, d, h = p.size
    b = Builder()
    deck = 0.1 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, 0.42 * d, 0.3 * deck), darker(p.primary, 0.3))  # the pit frame
    dw = 0.8 * w if p.bumpers else w
    b.box((-dw / 2, -d / 2, 0.3 * deck), (dw / 2, 0.42 * d, deck), p.primary)
    for k in range(9):  # the checker plate's raised ribs
        y = -0.45 * d + k * 0.1 * d
        b.box((-0.4 * dw, y, deck), (0.4 * dw, y + 0.02 * d, deck + 0.01 * h), lighter(p.primary, 0.12))
    for k in range(8):  # hazard stripes along the deck's edges
        y0 = -d / 2 + k * 0.115 * d
        c = p.secondary if k % 2 == 0 else BLACK
        for s in (-1, 1):
            b.box((s * dw / 2 - 0.04 * w, y0, 0.3 * deck), (s * dw / 2, y0 + 0.115 * d, deck + 0.005 * h), c)
    # the hinged lip at the door end
    lip_top = deck + (0.35 * h if p.lip_up else 0.0)
    b.hull([(-dw / 2, 0.42 * d, 0.3 * deck), (dw / 2, 0.42 * d, 0.3 * deck), (-dw / 2, 0.42 * d, deck),
            (dw / 2, 0.42 * d, deck), (-dw / 2, d / 2, lip_top - 0.02 * h), (dw / 2, d / 2, lip_top - 0.02 * h),
            (-dw / 2, d / 2, lip_top), (dw / 2, d / 2, lip_top)], darker(p.primary, 0.1))
    if p.bumpers:
        for s in (-1, 1):
            x = s * (w / 2 - 0.05 * w)
            b.box((x - 0.05 * w, 0.4 * d, 0.0), (x + 0.05 * w, d / 2, h), p.accent)
            for z in (0.3 * h, 0.6 * h):  # the laminated blocks' bolts
                b.box((x - 0.02 * w, d / 2 - 0.002, z), (x + 0.02 * w, d / 2, z + 0.05 * h), DARK_METAL)
    else:
        b.box((-w / 2, 0.44 * d, 0.0), (-0.45 * w, d / 2, h), p.accent)  # a wheel guide post
    return b.mesh(p.size)


# ----------------------------------------------------------------- roller shutter
def sample_roller_shutter(rng, size, style):
    return make_params("roller_shutter", rng, size, style, SHUTTER, DARK_METAL, HAZARD_YELLOW,
                       open_share=float(rng.choice([0.0, 0.0, 0.3, 0.6])), vision=bool(rng.random() < 0.3))


def build_roller_shutter(p):
    """An industrial roller shutter door on a wall (the room side at +y): two steel
    guide rails up the sides, the coil box across the top, the curtain of horizontal
    slats between them (rolled up by ``open_share`` of the height, showing the dark
    opening below), a bottom rail with a yellow edge, and a row of glazed ``vision``
    slats."""
    w, d, h = p.size
    b = Builder()
    rail_w = 0.05 * w + 0.02
    box_h = 0.12 * h
    for s in (-1, 1):  # guide rails
        b.box((s * w / 2 - (rail_w if s > 0 else 0.0), -d / 2, 0),
              (s * w / 2 + (rail_w if s < 0 else 0.0), 0.1 * d, h - box_h), p.secondary)
    b.box((-w / 2, -d / 2, h - box_h), (w / 2, d / 2, h), darker(p.primary, 0.1))  # the coil box
    top = h - box_h
    bottom = p.open_share * top
    x0, x1 = -w / 2 + rail_w, w / 2 - rail_w
    if bottom > 0.01 * h:  # the opening under a part-raised curtain
        b.box((x0, -d / 2, 0.0), (x1, -0.45 * d, bottom), DARK_OPENING)
    n = max(4, int((top - bottom) / (0.08 * h) + 0.5))
    step = (top - bottom) / n
    for k in range(n):
        z = bottom + k * step
        c = GLASS if p.vision and k == int(0.6 * n) else (p.primary if k % 2 == 0 else lighter(p.primary, 0.06))
        b.box((x0, -0.35 * d, z), (x1, -0.15 * d, z + 0.96 * step), c)
    b.box((x0, -0.38 * d, bottom), (x1, -0.12 * d, bottom + 0.03 * h), p.accent)  # bottom rail
    b.box((-0.05 * w, -0.12 * d, bottom + 0.03 * h), (0.05 * w, -0.05 * d, bottom + 0.06 * h), BLACK)  # pull handle
    return b.mesh(p.size)



# ----------------------------------------------------------------- battery charger
def sample_battery_charger(rng, size, style):
    return make_params("battery_charger", rng, size, style, CHARGER, BLACK, METAL,
                       cable=bool(rng.random() < 0.8), plinth=bool(rng.random() < 0.5))


def build_battery_charger(p):
    """A forklift battery charger facing +y: a steel cabinet (on a floor ``plinth`` or
    on wall brackets over the floor) with a vented side, a display, a green and a red
    lamp and a mains switch on its front, and, when ``cable``, its heavy charging cable
    looping down to the red battery plug hung on a hook."""
    w, d, h = p.size
    b = Builder()
    z0 = 0.0 if p.plinth else 0.35 * h
    if p.plinth:
        b.box((-0.45 * w, -0.45 * d, 0.0), (0.45 * w, 0.45 * d, 0.06 * h), p.secondary)
    else:  # a bracket down to the floor keeps the box inside its footprint
        b.box((-0.3 * w, -d / 2, 0.0), (0.3 * w, -0.42 * d, z0), DARK_METAL)
    base = z0 + (0.06 * h if p.plinth else 0.0)
    top = base + 0.55 * h if not p.plinth else 0.75 * h
    b.box((-0.42 * w, -d / 2, base), (0.42 * w, 0.3 * d, top), p.primary)
    vent_lines(b, -0.3 * w, 0.3 * w, base + 0.1 * (top - base), base + 0.35 * (top - base), 0.3 * d, 5)
    b.box((-0.25 * w, 0.3 * d, top - 0.3 * (top - base)), (0.1 * w, 0.31 * d, top - 0.1 * (top - base)), SCREEN)
    b.sphere((0.22 * w, 0.31 * d, top - 0.15 * (top - base)), 0.02 * w + 0.005, GLOW_GREEN)
    b.sphere((0.22 * w, 0.31 * d, top - 0.25 * (top - base)), 0.02 * w + 0.005, GLOW_RED)
    b.box((0.15 * w, 0.3 * d, top - 0.5 * (top - base)), (0.3 * w, 0.34 * d, top - 0.4 * (top - base)), p.accent)
    if p.cable:
        hook_z = h
        b.box((-0.42 * w, 0.25 * d, hook_z - 0.06 * h), (-0.3 * w, 0.35 * d, hook_z), p.accent)  # hook post top
        b.box((-0.42 * w, 0.25 * d, top), (-0.38 * w, 0.29 * d, hook_z - 0.06 * h), p.accent)
        path(b, [(-0.2 * w, 0.3 * d, base + 0.1 * (top - base)), (-0.05 * w, d / 2 - 0.06 * d, 0.12 * h),
                 (-0.35 * w, d / 2 - 0.05 * d, 0.2 * h), (-0.36 * w, 0.32 * d, hook_z - 0.12 * h)],
             0.02 * min(w, d) + 0.008, RUBBER, sections=6)
        b.box((-0.42 * w, 0.3 * d, hook_z - 0.2 * h), (-0.28 * w, d / 2, hook_z - 0.1 * h), PLUG_RED)
    else:
        b.box((-0.42 * w, 0.3 * d, top), (-0.3 * w, d / 2, h), p.accent)  # a cable reel on top
    return b.mesh(p.size)


slot_roles("dock_leveller", "metal", "paint", "rubber")
register("dock_leveller", sample_dock_leveller, build_dock_leveller)
slot_roles("roller_shutter", {"": "paint", "#b4b8bd": "metal"}, "metal", "paint")
register("roller_shutter", sample_roller_shutter, build_roller_shutter)
slot_roles("battery_charger", "paint", "plastic", "metal")
register("battery_charger", sample_battery_charger, build_battery_charger)
