"""Everything else: tv, piano, fireplace, whiteboard, easel, treadmill, exercise_bike,
cat_tree, and the generic fallback."""

from __future__ import annotations

import numpy as np
from shapely.geometry import Polygon

from anyhome.assets.procedural._parts import (
    BLACK,
    METAL,
    Builder,
    about,
    darker,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register


def sample_tv(rng, size, style):
    return make_params("tv", rng, size, style, [BLACK, "#2b2b2b", "#3a3b3e"], "#10141a", METAL,
                       wall=bool(rng.random() < 0.0))


def build_tv(p):
    w, d, h = p.size
    b = Builder()
    has_foot = d > 0.08
    foot_h = min(0.08, 0.12 * h) if has_foot else 0.0
    sd = min(0.05, d * 0.5) if has_foot else d
    y0 = -sd / 2 if has_foot else -d / 2
    b.box((-w / 2, y0, foot_h), (w / 2, y0 + sd * 0.8, h), p.primary)  # body
    b.box((-w / 2 + 0.015, y0 + sd * 0.8, foot_h + 0.02), (w / 2 - 0.015, y0 + sd, h - 0.015), p.secondary)
    b.box((-w / 2 + 0.05, y0 + sd * 0.8 + 0.001, foot_h + 0.06),
          (-w / 2 + 0.35 * w, y0 + sd + 0.0005, h - 0.05), tint("#1c2430", "paint"))  # a faint reflection
    if has_foot:
        b.box((-0.04, -0.02, 0.01), (0.04, 0.0, foot_h + 0.15 * h), p.accent)
        b.box((-0.18 * w, -d / 2, 0), (0.18 * w, d / 2, 0.012), p.accent)
    return b.mesh(p.size)


def sample_piano(rng, size, style):
    return make_params("piano", rng, size, style, [BLACK, "#1f1f22", "#5c3b26", "#f0ede6"], "#f4f1ea", BLACK,
                       lid_open=bool(rng.random() < 0.6))


def _keys(b: Builder, w: float, y0: float, y1: float, z: float) -> None:
    b.box((-w / 2, y0, z), (w / 2, y1, z + 0.02), tint("#f4f1ea", "paint"))
    n = max(7, int(w / 0.023))
    xs = np.linspace(-w / 2, w / 2, n + 1)
    for i, x in enumerate(xs[1:-1]):
        if i % 7 in (2, 6):
            continue
        b.box((x - 0.006, y0 + 0.4 * (y1 - y0), z + 0.02), (x + 0.006, y1, z + 0.032), tint("#151515", "paint"))


def build_piano(p):
    w, d, h = p.size
    b = Builder()
    kz = min(0.72, 0.7 * h)
    if d < 1.0:  # upright
        body_d = 0.6 * d
        b.box((-w / 2, -d / 2, 0.08), (w / 2, -d / 2 + body_d, h), p.primary)
        b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, -d / 2 + body_d, 0.08), darker(p.primary, 0.3))
        b.box((-w / 2, -d / 2 + body_d, kz - 0.06), (w / 2, d / 2 - 0.1, kz), p.primary)  # key bed
        _keys(b, w - 0.12, -d / 2 + body_d, d / 2 - 0.12, kz)
        for x in (-w / 2 + 0.03, w / 2 - 0.06):
            b.box((x, -d / 2 + body_d, 0), (x + 0.03, d / 2, kz - 0.06), p.primary)
        b.box((-0.3, -d / 2 + body_d, kz + 0.15), (0.3, -d / 2 + body_d + 0.03, kz + 0.35), p.primary)
        return b.mesh(p.size)
    # grand: the keyboard at the front (+y), the curved tail towards -y
    body_z0 = 0.45 * h if p.lid_open else 0.6 * h
    top = h if not p.lid_open else 0.78 * h
    outline = [(-w / 2, d / 2 - 0.25), (w / 2, d / 2 - 0.25), (w / 2, -0.05 * d), (w * 0.2, -0.35 * d),
               (w * 0.05, -d / 2), (-w * 0.3, -d / 2), (-w / 2, -0.3 * d)]
    import trimesh

    body = trimesh.creation.extrude_polygon(Polygon(outline), top - body_z0)
    b.add(np.asarray(body.vertices) + np.array([0, 0, body_z0]), body.faces, p.primary)
    if p.lid_open:
        lid = trimesh.creation.extrude_polygon(Polygon(outline), 0.02)
        m = about(rot_x(0.0), (0, 0, 0))
        m = about(np.array(trimesh.transformations.rotation_matrix(0.7, [0, -1, 0])), (w / 2, 0, top)) @ m
        b.add(np.asarray(lid.vertices) + np.array([0, 0, top]), lid.faces, darker(p.primary, 0.1), transform=m)
    b.box((-w / 2, d / 2 - 0.25, body_z0 + 0.02), (w / 2, d / 2 - 0.1, body_z0 + 0.08), p.primary)
    _keys(b, w - 0.1, d / 2 - 0.25, d / 2 - 0.1, body_z0 + 0.08)
    for x, y in ((-w / 2 + 0.1, d / 2 - 0.2), (w / 2 - 0.1, d / 2 - 0.2), (-w * 0.1, -0.4 * d)):
        b.cyl(x, y, 0.03, body_z0, 0.04, p.primary, r_top=0.05)
        b.sphere((x, y, 0.03), 0.03, tint("#c9a54a", "metal"))
    b.box((-0.3, d / 2 - 0.3, body_z0 + 0.08), (0.3, d / 2 - 0.27, body_z0 + 0.3), p.primary)
    return b.mesh(p.size)


def sample_fireplace(rng, size, style):
    return make_params("fireplace", rng, size, style, ["#e8e6e0", "#b5a58a", "#8a4a3a", "#3a3a3c", "#cfcac0"],
                       wood_tones(style), "#2a1e18", lit=bool(rng.random() < 0.6))


def build_fireplace(p):
    w, d, h = p.size
    b = Builder()
    ow, oh = 0.55 * w, 0.55 * h
    mantel = 0.08
    b.box((-w / 2 + 0.03, -d / 2, 0.05), (-ow / 2, d / 2 - 0.05, h - mantel), p.primary)
    b.box((ow / 2, -d / 2, 0.05), (w / 2 - 0.03, d / 2 - 0.05, h - mantel), p.primary)
    b.box((-ow / 2, -d / 2, oh), (ow / 2, d / 2 - 0.05, h - mantel), p.primary)
    b.box((-ow / 2, -d / 2, 0.05), (ow / 2, -d / 2 + 0.1, oh), p.accent)  # firebox back
    b.box((-ow / 2, -d / 2, 0.05), (ow / 2, d / 2 - 0.1, 0.07), p.accent)
    b.box((-w / 2, -d / 2, h - mantel), (w / 2, d / 2, h), p.secondary)  # mantel shelf
    b.box((-w / 2 + 0.02, -d / 2, 0), (w / 2 - 0.02, d / 2, 0.05), darker(p.primary, 0.2))  # hearth
    for dx in (-0.1, 0.1):
        b.rod((dx - 0.15 * ow, -0.05, 0.1), (dx + 0.15 * ow, 0.0, 0.12), 0.04, tint("#6b4a30", "paint"))
    if p.lit:
        b.sphere((0, -0.05, 0.2), (0.18 * ow, 0.06, 0.12), tint("#f08a2a", "paint"))
        b.sphere((0, -0.05, 0.24), (0.08 * ow, 0.04, 0.1), tint("#ffd060", "light"))
    return b.mesh(p.size)


def sample_whiteboard(rng, size, style):
    return make_params("whiteboard", rng, size, style, ["#c9ccd0", "#9a9da3"], "#f8f8f6", ["#2e4a8b", "#c0392b"])


def build_whiteboard(p):
    w, d, h = p.size
    b = Builder()
    mobile = d > 0.25 and h > 1.2
    if mobile:
        z0, z1 = 0.75, h - 0.05
        for s in (-1, 1):
            x = s * (w / 2 - 0.03)
            b.box((x - 0.02, -0.02, 0.05), (x + 0.02, 0.02, h), p.primary)
            b.box((x - 0.03, -d / 2, 0.04), (x + 0.03, d / 2, 0.08), p.primary)
            for y in (-d / 2 + 0.03, d / 2 - 0.03):
                b.sphere((x, y, 0.025), 0.025, BLACK)
        y0, y1 = -0.015, 0.015
    else:
        z0, z1 = 0.0, h
        y0, y1 = -d / 2, d / 2
    f = 0.02
    b.box((-w / 2 + 0.01, y0, z0), (w / 2 - 0.01, y1 - 0.003, z1), p.primary)
    b.box((-w / 2 + f, y1 - 0.005, z0 + f), (w / 2 - f, y1, z1 - f), p.secondary)
    b.box((-w / 2 + 0.1, y1, z0), (w / 2 - 0.1, y1 + 0.05, z0 + 0.02), p.primary)  # tray
    b.box((-w / 2 + 0.15, y1, z0 + 0.3 * (z1 - z0)), (-w / 2 + 0.45 * w, y1 + 0.001, z0 + 0.32 * (z1 - z0)),
          p.accent)
    b.box((-w / 2 + 0.15, y1, z0 + 0.6 * (z1 - z0)), (-w / 2 + 0.3 * w, y1 + 0.001, z0 + 0.62 * (z1 - z0)),
          p.accent)
    return b.mesh(p.size)


def sample_easel(rng, size, style):
    return make_params("easel", rng, size, style, wood_tones(style), "#f4f1ea", ["#c0392b", "#2e86c1", "#f1c40f"])


def build_easel(p):
    w, d, h = p.size
    b = Builder()
    top = (0, -d * 0.1, h)
    for s in (-1, 1):
        b.rod((s * w * 0.4, d * 0.35, 0), top, 0.015, p.primary, sections=8)
    b.rod((0, -d / 2 + 0.02, 0), (0, -d * 0.12, h * 0.95), 0.015, p.primary, sections=8)
    tz = 0.45 * h
    b.box((-w * 0.4, d * 0.1, tz), (w * 0.4, d * 0.3, tz + 0.03), p.primary)  # tray
    cw, ch = w * 0.85, 0.45 * h
    tilt = about(rot_x(-0.2), (0, d * 0.2, tz))
    b.box((-cw / 2, d * 0.17, tz + 0.03), (cw / 2, d * 0.2, tz + 0.03 + ch), p.secondary, transform=tilt)
    b.box((-cw / 3, d * 0.2, tz + 0.15), (cw / 6, d * 0.205, tz + 0.3), p.accent, transform=tilt)
    return b.mesh(p.size)


def sample_treadmill(rng, size, style):
    return make_params("treadmill", rng, size, style, [BLACK, "#3a3b3e", "#5f6b7a"], "#1c1c1c", METAL)


def build_treadmill(p):
    """A treadmill with its console at the front (+y), the user facing +y."""
    w, d, h = p.size
    b = Builder()
    deck = 0.2
    b.box((-w / 2 + 0.05, -d / 2, 0), (w / 2 - 0.05, d / 2 - 0.15, deck), p.primary)
    b.box((-w / 2 + 0.1, -d / 2 + 0.02, deck), (w / 2 - 0.1, d / 2 - 0.2, deck + 0.01), p.secondary)
    for s in (-1, 1):
        b.box((s * (w / 2 - 0.075) - 0.025, -d / 2, deck), (s * (w / 2 - 0.075) + 0.025, d / 2 - 0.2, deck + 0.02),
              p.accent)
        b.rod((s * (w / 2 - 0.05), d / 2 - 0.2, deck), (s * (w / 2 - 0.05), d / 2 - 0.1, h - 0.15), 0.025,
              p.primary)
        b.rod((s * (w / 2 - 0.05), d / 2 - 0.1, h - 0.3), (s * (w / 2 - 0.05), d / 2 - 0.45, h - 0.3), 0.02,
              p.accent)
    b.box((-w / 2 + 0.05, d / 2 - 0.2, 0), (w / 2 - 0.05, d / 2, deck + 0.05), p.primary)
    b.box((-w / 2 + 0.02, d / 2 - 0.2, h - 0.2), (w / 2 - 0.02, d / 2, h), p.primary,
          transform=about(rot_x(0.3), (0, d / 2 - 0.1, h - 0.1)))
    b.box((-0.15, d / 2 - 0.22, h - 0.16), (0.15, d / 2 - 0.18, h - 0.04), tint("#2f6b8a", "paint"),
          transform=about(rot_x(0.3), (0, d / 2 - 0.1, h - 0.1)))
    return b.mesh(p.size)


def sample_exercise_bike(rng, size, style):
    return make_params("exercise_bike", rng, size, style, [BLACK, "#3a3b3e", "#e8e6e0", "#c0392b"], "#1c1c1c",
                       METAL)


def build_exercise_bike(p):
    """Seat towards -y, handlebars and flywheel towards +y (the rider faces +y)."""
    w, d, h = p.size
    b = Builder()
    for y in (-d / 2 + 0.05, d / 2 - 0.05):
        b.rod((-w / 2, y, 0.04), (w / 2, y, 0.04), 0.04, p.secondary)
    b.rod((0, -d / 2 + 0.05, 0.05), (0, d / 2 - 0.05, 0.05), 0.03, p.primary)
    fy = d / 2 - 0.25
    b.rod((-0.03, fy, 0.35), (0.03, fy, 0.35), 0.25, p.primary, sections=28)  # flywheel
    b.rod((-0.035, fy, 0.35), (0.035, fy, 0.35), 0.08, p.accent, sections=16)
    b.rod((0, -d / 2 + 0.15, 0.05), (0, -0.1 * d, h * 0.62), 0.035, p.primary)  # seat tube
    b.rod((0, -0.1 * d, 0.3), (0, fy, 0.35), 0.03, p.primary)
    b.rod((0, fy, 0.35), (0, d / 2 - 0.12, h - 0.1), 0.03, p.primary)  # handlebar post
    b.rod((-w * 0.35, d / 2 - 0.12, h - 0.05), (w * 0.35, d / 2 - 0.12, h - 0.05), 0.018, p.accent)
    b.rod((0, d / 2 - 0.12, h - 0.1), (0, d / 2 - 0.12, h - 0.05), 0.02, p.primary)
    b.sphere((0, -0.12 * d, h * 0.65), (0.1, 0.15, 0.04), p.secondary)  # saddle
    b.box((-0.06, d / 2 - 0.1, h - 0.2), (0.06, d / 2 - 0.06, h - 0.1), tint("#2f6b8a", "paint"))
    for s in (-1, 1):
        b.rod((s * 0.04, fy, 0.35), (s * 0.12, fy - 0.08, 0.25), 0.01, p.accent)
        b.box((s * 0.12 - 0.04, fy - 0.12, 0.24), (s * 0.12 + 0.04, fy - 0.04, 0.26), p.secondary)
    return b.mesh(p.size)


def sample_cat_tree(rng, size, style):
    return make_params("cat_tree", rng, size, style, ["#c9c1b4", "#8c8f94", "#d9c3a0", "#6f7a86"], "#c9a77c",
                       "#e8dcc4", levels=int(rng.integers(2, 5)))


def build_cat_tree(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04), p.primary)
    cube = min(w, d) * 0.5
    b.box((-w / 2 + 0.02, -d / 2 + 0.02, 0.04), (-w / 2 + 0.02 + cube, -d / 2 + 0.02 + cube, 0.04 + cube), p.primary)
    b.rod((-w / 2 + 0.02 + cube / 2, -d / 2 + 0.02 + cube + 0.001, 0.04 + cube / 2),
          (-w / 2 + 0.02 + cube / 2, -d / 2 + 0.025 + cube, 0.04 + cube / 2), cube * 0.3, tint("#2a2522", "paint"))
    z_prev = 0.04 + cube
    for k in range(p.levels):
        z = z_prev + (h - z_prev) / (p.levels - k)
        mx, my = min(0.1, w / 4), min(0.1, d / 4)
        x = rng.uniform(-w / 2 + mx, w / 2 - mx)
        y = rng.uniform(-d / 2 + my, d / 2 - my)
        b.cyl(x, y, 0.04 if k == 0 else z_prev - 0.03, z - 0.03, 0.045, p.secondary, sections=12)
        pw, pd = min(0.4, w * 0.6), min(0.4, d * 0.6)
        cx = float(np.clip(x, -w / 2 + pw / 2, w / 2 - pw / 2))
        cy = float(np.clip(y, -d / 2 + pd / 2, d / 2 - pd / 2))
        b.box((cx - pw / 2, cy - pd / 2, z - 0.03), (cx + pw / 2, cy + pd / 2, z), p.primary)
        z_prev = z
    b.cyl(0, 0, h - 0.03, h, min(w, d) * 0.25, p.accent, sections=20)
    b.sphere((w * 0.2, d * 0.2, 0.3 * h), 0.04, tint("#e05a47", "paint"), subdivisions=1)
    return b.mesh(p.size)


def sample_generic(rng, size, style):
    return make_params("generic", rng, size, style, wood_tones(style) + ["#8c8f94", "#e8e6e0", "#5f6b7a"],
                       "#3a3530", "#c9a54a", rounded=bool(rng.random() < 0.5))


def build_generic(p):
    """A rounded block on a plinth with a front panel: reads as 'some object', not a crate."""
    w, d, h = p.size
    b = Builder()
    pl = min(0.08 * h, 0.06)
    b.box((-w / 2 + 0.04 * w, -d / 2 + 0.04 * d, 0), (w / 2 - 0.04 * w, d / 2 - 0.04 * d, pl), p.secondary)
    body_top = h * (0.88 if p.rounded else 0.95)
    b.box((-w / 2, -d / 2, pl), (w / 2, d / 2, body_top), p.primary)
    if p.rounded:
        b.cyl(0, 0, body_top - 0.001, h, w / 2, lighter(p.primary, 0.08), r_top=w / 2 * 0.6, ry=d / 2, sections=24)
    else:
        b.box((-w / 2 * 0.96, -d / 2 * 0.96, body_top), (w / 2 * 0.96, d / 2 * 0.96, h), lighter(p.primary, 0.1))
    b.box((-w / 2 * 0.7, d / 2, pl + 0.15 * (body_top - pl)), (w / 2 * 0.7, d / 2 + 0.005, pl + 0.8 * (body_top - pl)),
          darker(p.primary, 0.15))
    b.sphere((0, d / 2 + 0.005, pl + 0.5 * (body_top - pl)), min(w, h) * 0.04, p.accent)
    return b.mesh(p.size)


slot_roles("tv", "plastic", "screen", "metal")
register("tv", sample_tv, build_tv)
slot_roles("piano", "paint", "ceramic", "plastic")
register("piano", sample_piano, build_piano)
slot_roles("fireplace", "stone", "wood", "stone")
register("fireplace", sample_fireplace, build_fireplace)
slot_roles("whiteboard", "metal", "plastic", "plastic")
register("whiteboard", sample_whiteboard, build_whiteboard)
slot_roles("easel", "wood", "fabric", "paint")
register("easel", sample_easel, build_easel)
slot_roles("treadmill", "plastic", "rubber", "metal")
register("treadmill", sample_treadmill, build_treadmill)
slot_roles("exercise_bike", "paint", "plastic", "metal")
register("exercise_bike", sample_exercise_bike, build_exercise_bike)
slot_roles("cat_tree", "fabric", "fabric", "fabric")
register("cat_tree", sample_cat_tree, build_cat_tree)
slot_roles("generic", "wood", "fabric", "metal")
register("generic", sample_generic, build_generic)
