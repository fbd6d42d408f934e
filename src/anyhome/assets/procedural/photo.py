"""A photography studio: backdrop, studio_light, camera_tripod."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import CHROME, GLOW_RED, extrude_x, path, ring_y
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    GLASS,
    Builder,
    about,
    darker,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    tint,
)
from anyhome.assets.registry import register

PAPERS = ["#f4f4f2", "#8c8f94", "#1f1f22", "#3aa655", "#3a6ab0", "#d9c8a8", "#b8c4cc"]
"""Seamless paper colours: white, grey, black, chroma green, blue, sand, slate."""
STANDS = [DARK_METAL, "#1f1f22", "#55585d"]
"""Light and backdrop stands: black or graphite steel."""


def _stand(b: Builder, x: float, y: float, top: float, spread: float, color: str, z_hub: float) -> None:
    """A tripod light stand at (x, y): three splayed legs meeting a hub at ``z_hub`` and a
    pole up to ``top``."""
    r = 0.012 + 0.01 * spread
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        b.rod((x + spread * np.cos(a), y + spread * np.sin(a), 0), (x, y, z_hub), r, color, sections=6)
        b.rod((x + 0.4 * spread * np.cos(a), y + 0.4 * spread * np.sin(a), 0.5 * z_hub), (x, y, 0.8 * z_hub),
              0.6 * r, color, sections=5)  # brace
    b.cyl(x, y, 0.7 * z_hub, top, r * 1.3, color, sections=10)
    b.cyl(x, y, z_hub, z_hub + 0.04 * top, r * 2.0, lighter(color, 0.2), sections=10)  # clamp collar


# ----------------------------------------------------------------- backdrop
def sample_backdrop(rng, size, style):
    return make_params("backdrop", rng, size, style, PAPERS, STANDS, CHROME,
                       sweep=float(rng.uniform(0.55, 0.9)))


def build_backdrop(p):
    """A seamless paper backdrop: two stands at the ends carrying a crossbar with the
    paper roll, the paper hanging down and curving onto the floor towards the front
    (+y), ``sweep`` of the box deep."""
    w, d, h = p.size
    b = Builder()
    spread = min(0.45 * d, 0.08 * w + 0.1)
    y_stand = -d / 2 + spread
    for s in (-1, 1):
        _stand(b, s * (w / 2 - spread), y_stand, h - 0.05 * h, spread, p.secondary, 0.18 * h)
    roll_r = 0.035 * h + 0.01
    roll_z = h - roll_r
    b.rod((-w / 2 + 0.3 * spread, y_stand, roll_z), (w / 2 - 0.3 * spread, y_stand, roll_z), 0.015 * h / 2.8 + 0.004,
          p.secondary, sections=8)  # crossbar
    for s in (-1, 1):
        b.cyl(s * (w / 2 - spread), y_stand, roll_z - 0.03 * h, roll_z + 0.02 * h, 0.02 * h / 2.8 + 0.012, p.accent,
              sections=8)  # the bar's holders on the stands
    x0, x1 = -w / 2 + 1.4 * spread, w / 2 - 1.4 * spread
    b.rod((x0, y_stand, roll_z), (x1, y_stand, roll_z), roll_r, lighter(p.primary, 0.05), sections=16)
    # the paper in profile (y, z): down the front of the roll, a cove, out along the floor
    t = 0.004 * h + 0.002
    y_face = y_stand + roll_r
    cove = min(0.35 * h, 0.45 * (d / 2 - y_face))
    y_end = y_face + p.sweep * (d / 2 - y_face)
    outer = [(y_face, roll_z)] + [(y_face + cove - cove * np.cos(a), cove - cove * np.sin(a))
                                  for a in np.linspace(0, np.pi / 2, 8)] + [(y_end, 0.0)]
    inner = [(y_end, t)] + [(y_face + cove - (cove - t) * np.cos(a), cove - (cove - t) * np.sin(a))
                            for a in np.linspace(np.pi / 2, 0, 8)] + [(y_face + t, roll_z)]
    extrude_x(b, outer + inner, x0 + 0.01 * w, x1 - 0.01 * w, p.primary, role="paper")
    b.box((x0 + 0.2 * (x1 - x0), y_end - 0.04 * d, 0), (x0 + 0.3 * (x1 - x0), y_end, t + 0.002), tint("#e8c53a",
                                                                                                      "paper"))  # tape
    return b.mesh(p.size)


# ----------------------------------------------------------------- studio light
def sample_studio_light(rng, size, style):
    return make_params("studio_light", rng, size, style, STANDS, ["#f4f4f2", "#eceae4"], tint("#fff6e0", "light"),
                       kind=str(rng.choice(["softbox", "softbox", "umbrella", "ring"])),
                       tilt=float(rng.uniform(0.1, 0.35)))


def build_studio_light(p):
    """A studio light on a tripod stand, aimed to the front (+y): a square softbox (a
    black pyramid with a white diffuser), a strobe with a white shoot-through umbrella,
    or a ring light with a phone holder in its middle."""
    w, d, h = p.size
    b = Builder()
    spread = 0.38 * min(w, d)
    head_z = 0.78 * h
    _stand(b, 0, 0, head_z, spread, p.primary, 0.2 * h)
    aim = about(rot_x(-p.tilt), (0, 0, head_z))
    head = Builder()
    size = min(0.48 * w, 0.22 * h)
    if p.kind == "ring":
        ring_y(head, (0, 0.05 * d, head_z + 0.02 * h), size * 0.85, size * 0.12, p.accent, sections=28)
        ring_y(head, (0, 0.05 * d - 0.01, head_z + 0.02 * h), size * 0.85, size * 0.15, BLACK, sections=28)
        head.box((-0.05 * size, 0.05 * d, head_z - 0.1 * size), (0.05 * size, 0.05 * d + 0.01, head_z + 0.35 * size),
                 p.primary)
        head.box((-0.22 * size, 0.05 * d + 0.01, head_z + 0.02 * h - 0.4 * size),
                 (0.22 * size, 0.05 * d + 0.02, head_z + 0.02 * h + 0.4 * size), BLACK)  # the phone
        b.extend(head, aim)
        return b.mesh(p.size)
    strobe_y0, strobe_y1 = -0.12 * d, 0.05 * d
    head.rod((0, strobe_y0, head_z + 0.05 * h), (0, strobe_y1, head_z + 0.05 * h), 0.06 * min(w, d) + 0.02,
             darker(p.primary, 0.1), sections=14)  # the strobe body
    head.box((-0.05 * w, strobe_y0 - 0.02 * d, head_z), (0.05 * w, strobe_y0, head_z + 0.06 * h), DARK_METAL)
    head.sphere((0.04 * w, strobe_y0 - 0.021 * d, head_z + 0.03 * h), 0.01 * min(w, d) + 0.004, GLOW_RED)
    cz = head_z + 0.05 * h
    if p.kind == "umbrella":
        r = 0.48 * min(w, h)
        tip = np.array([0.0, strobe_y1 + 0.02 * d, cz])
        rim_y = tip[1] + 0.3 * d
        pts = [tip] + [(r * np.cos(a), rim_y, cz + r * np.sin(a)) for a in np.linspace(0, 2 * np.pi, 17)[:-1]]
        head.hull(pts, p.secondary, alpha=235)
        head.rod((0, strobe_y0, cz), (0, rim_y + 0.05 * d, cz), 0.006 * min(w, d) + 0.002, DARK_METAL, sections=5)
        b.extend(head, aim)
        return b.mesh(p.size)
    # softbox: a square pyramid opening towards +y, the diffuser on its face
    face_y = 0.4 * d
    back = [(sx * 0.1 * size, strobe_y1, cz + sz * 0.1 * size) for sx in (-1, 1) for sz in (-1, 1)]
    front = [(sx * size, face_y, cz + sz * size) for sx in (-1, 1) for sz in (-1, 1)]
    head.hull(back + front, tint("#1f1f22", "fabric"))
    head.box((-0.96 * size, face_y, cz - 0.96 * size), (0.96 * size, face_y + 0.01 * d, cz + 0.96 * size),
             p.secondary)
    head.box((-0.8 * size, face_y + 0.01 * d, cz - 0.8 * size), (0.8 * size, face_y + 0.012 * d, cz + 0.8 * size),
             p.accent)  # the glow through it
    b.extend(head, aim)
    return b.mesh(p.size)


# ----------------------------------------------------------------- camera tripod
def sample_camera_tripod(rng, size, style):
    return make_params("camera_tripod", rng, size, style, STANDS + [CHROME], [BLACK, "#2b2b2b", "#c9ccd0"], DARK_METAL,
                       grip=bool(rng.random() < 0.5), flash=bool(rng.random() < 0.4))


def build_camera_tripod(p):
    """A camera on a tripod looking to the front (+y): three telescoping legs with locks,
    a centre column, a pan head with its handle reaching back, and a camera body with a
    lens barrel, a viewfinder hump, a grip (and a flash on the hot shoe)."""
    w, d, h = p.size
    b = Builder()
    spread = 0.45 * min(w, d)
    hub_z = 0.7 * h
    leg_r = 0.012 * h / 1.6 + 0.003
    for k in range(3):
        a = 2 * np.pi * k / 3 - np.pi / 2  # one leg to the back (-y), two to the front
        foot = np.array([spread * np.cos(a) * (w / min(w, d)) * 0.95, spread * np.sin(a), 0.0])
        top = np.array([0.08 * spread * np.cos(a), 0.08 * spread * np.sin(a), hub_z])
        mid = foot + 0.5 * (top - foot)
        b.rod(foot, mid, leg_r * 0.75, p.primary, sections=6)
        b.rod(mid, top, leg_r, p.primary, sections=6)
        b.sphere(mid, leg_r * 1.4, BLACK, subdivisions=0)  # leg lock
        b.sphere(foot, leg_r * 1.1, tint("#1c1c1e", "rubber"), subdivisions=0)
    b.cyl(0, 0, hub_z - 0.02 * h, hub_z + 0.02 * h, 0.06 * min(w, d) + 0.01, p.accent, sections=12)
    col_top = hub_z + 0.08 * h
    b.cyl(0, 0, hub_z - 0.1 * h, col_top, leg_r * 0.9, p.primary, sections=8)
    b.sphere((0, 0, col_top + 0.015 * h), 0.02 * h + 0.004, p.accent)  # ball head
    path(b, [(0, 0, col_top), (0.02 * w, -0.3 * d, col_top - 0.03 * h)], 0.006 * h + 0.002, BLACK,
         sections=6)  # pan handle
    body_z0 = col_top + 0.03 * h
    cw, cd, ch = min(0.3 * w, 0.16), min(0.16 * d, 0.08), min(0.09 * h, 0.1)
    body_top = min(h - 0.02 * h, body_z0 + ch)
    b.box((-cw / 2, -cd / 2, body_z0), (cw / 2, cd / 2, body_top), p.secondary)
    b.hull([(-0.2 * cw, -cd / 2, body_top), (0.2 * cw, -cd / 2, body_top), (-0.2 * cw, cd / 3, body_top),
            (0.2 * cw, cd / 3, body_top), (-0.12 * cw, -cd / 2, h), (0.12 * cw, -cd / 2, h), (-0.12 * cw, 0, h),
            (0.12 * cw, 0, h)], p.secondary)  # viewfinder hump
    if p.grip:
        b.box((cw / 2 - 0.25 * cw, cd / 2, body_z0), (cw / 2, cd / 2 + 0.2 * cd, body_top - 0.1 * ch),
              tint("#1c1c1e", "rubber"))
    lz = body_z0 + 0.45 * (body_top - body_z0)
    lr = 0.42 * (body_top - body_z0)
    b.rod((-0.1 * cw, cd / 2, lz), (-0.1 * cw, d / 2 - 0.01 * d, lz), lr, BLACK, sections=16)  # lens barrel
    b.rod((-0.1 * cw, 0.7 * cd, lz), (-0.1 * cw, cd, lz), lr * 1.05, tint("#3a3b3e", "rubber"), sections=16)
    b.rod((-0.1 * cw, d / 2 - 0.012 * d, lz), (-0.1 * cw, d / 2, lz), 0.8 * lr, GLASS, sections=16)
    if p.flash:
        fz = body_top
        b.box((0.12 * cw, -cd / 3, fz), (0.42 * cw, cd / 3, fz + 0.6 * (h - fz)), BLACK)
        b.box((0.1 * cw, -cd / 3, fz + 0.6 * (h - fz)), (0.44 * cw, cd / 2, h), BLACK)
        b.box((0.13 * cw, cd / 2, fz + 0.65 * (h - fz)), (0.41 * cw, cd / 2 + 0.004, h - 0.1 * (h - fz)),
              tint("#fffbe8", "light"))
    return b.mesh(p.size)


slot_roles("backdrop", "paper", "metal", "metal")
register("backdrop", sample_backdrop, build_backdrop)
slot_roles("studio_light", "metal", "fabric", "light")
register("studio_light", sample_studio_light, build_studio_light)
slot_roles("camera_tripod", "metal", "plastic", "metal")
register("camera_tripod", sample_camera_tripod, build_camera_tripod)
