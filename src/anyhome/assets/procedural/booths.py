"""Booths, pods and enclosures: phone_booth, photo_booth, vocal_booth, ticket_booth,
cubicle, sleeping_pod, elevator, golf_simulator, dj_booth."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    BRASS,
    CHROME,
    GLOW_RED,
    SCREEN,
    STEEL,
    arc,
    disc_y,
    extrude_y,
    frame_y,
    ring_y,
    vent_lines,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    FABRICS,
    GLASS,
    Builder,
    darker,
    lighter,
    make_params,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register
from anyhome.assets.styles import Style

FELTS = tint(["#5f6b7a", "#7d8c74", "#3f4a5a", "#8c8f94", "#2b2b2b", "#a6896b", "#c9c1b4"], "fabric")
PANE = tint("#cfe0e6", "glass")
SIGN_LIGHT = tint("#fff4c8", "light")
NEON = tint(["#e040a0", "#40c0e0", "#7b4ad5", "#40e080"], "light")


def _antique(style: Style, rng, share: float) -> bool:
    if style_is(style, "antique", "rustic"):
        return True
    if style_is(style, "modern"):
        return False
    return bool(rng.random() < share)


def _panes(b: Builder, x0: float, x1: float, z0: float, z1: float, y0: float, y1: float, cols: int, rows: int,
           bar: float, color: str, pane: str = PANE) -> None:
    """A window of ``cols`` x ``rows`` panes in a frame of ``color`` (x-z plane, y0..y1)."""
    b.box((x0, y0 + 0.3 * (y1 - y0), z0), (x1, y0 + 0.6 * (y1 - y0), z1), pane)
    frame_y(b, x0, x1, z0, z1, y0, y1, bar, color)
    for i in range(1, cols):
        x = x0 + i * (x1 - x0) / cols
        b.box((x - bar / 3, y0, z0), (x + bar / 3, y1, z1), color)
    for j in range(1, rows):
        z = z0 + j * (z1 - z0) / rows
        b.box((x0, y0, z - bar / 3), (x1, y1, z + bar / 3), color)


def _turned(b: Builder, w: float, d: float, draw) -> None:
    """Draw a face of a box (``draw(b, half_width, y_face)``) on all four sides."""
    from anyhome.assets.procedural._parts import rot_z

    for k, (hw, hy) in enumerate(((w / 2, d / 2), (d / 2, w / 2), (w / 2, d / 2), (d / 2, w / 2))):
        sub = Builder()
        draw(sub, hw, hy, k)
        b.extend(sub, rot_z(k * np.pi / 2))


# ----------------------------------------------------------------- phone booth
def sample_phone_booth(rng, size, style):
    red = _antique(style, rng, 0.35)
    return make_params("phone_booth", rng, size, style, ["#c8202a", "#b81c24"] if red else FELTS,
                       SIGN_LIGHT if red else [BLACK, "#2b2b2b", "#e8e6e0"], wood_tones(style),
                       kind="telephone" if red else "pod")


def build_phone_booth(p):
    """A red telephone box (windows of small panes on every side, a lit TELEPHONE sign
    and a domed roof) or an office phone pod (felt shell, a full glass door, a shelf
    and a stool inside)."""
    w, d, h = p.size
    b = Builder()
    if p.kind == "telephone":
        body = 0.86 * h
        b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04 * h), darker(p.primary, 0.3))
        post = 0.1 * min(w, d)
        b.box((-w / 2 + post, -d / 2 + post, 0.04 * h), (w / 2 - post, d / 2 - post, body), tint("#3a2a26", "paint"))  # inside

        def side(s: Builder, hw: float, hy: float, k: int) -> None:
            s.box((-hw, hy - post, 0.04 * h), (-hw + post, hy, body), p.primary)  # corner post
            s.box((-hw + post, hy - 0.4 * post, 0.04 * h), (hw - post, hy - 0.1 * post, 0.16 * h), p.primary)
            _panes(s, -hw + post, hw - post, 0.16 * h, 0.78 * h, hy - 0.4 * post, hy - 0.1 * post, 3, 8,
                   0.012, p.primary)
            s.box((-hw + post, hy - 0.4 * post, 0.78 * h), (hw - post, hy - 0.1 * post, body), p.primary)
            s.box((-hw + 1.5 * post, hy - 0.1 * post, 0.8 * h), (hw - 1.5 * post, hy, 0.84 * h), p.secondary)
            s.box((-0.25 * hw, hy, 0.815 * h), (0.25 * hw, hy + 0.002, 0.825 * h), BLACK)  # lettering
            s.box((-hw, hy - post, body), (hw, hy, body + 0.03 * h), p.primary)
            if k == 0:
                s.box((hw - post - 0.12 * hw, hy, 0.45 * h), (hw - post - 0.08 * hw, hy + 0.01, 0.52 * h), tint("#3a2a26", "paint"))

        _turned(b, w, d, side)
        top = body + 0.03 * h
        b.hull([(-w / 2, -d / 2, top), (w / 2, -d / 2, top), (-w / 2, d / 2, top), (w / 2, d / 2, top),
                (-0.35 * w, -0.35 * d, h - 0.04 * h), (0.35 * w, -0.35 * d, h - 0.04 * h),
                (-0.35 * w, 0.35 * d, h - 0.04 * h), (0.35 * w, 0.35 * d, h - 0.04 * h)], p.primary)
        b.box((-0.12 * w, -0.12 * d, h - 0.04 * h), (0.12 * w, 0.12 * d, h), darker(p.primary, 0.1))  # crown
        b.box((-0.15 * w, -d / 2 + post, 0.45 * h), (0.05 * w, -d / 2 + post + 0.08, 0.6 * h), BLACK)  # phone
        return b.mesh(p.size)
    t = 0.06 * min(w, d)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04 * h), BLACK)
    b.box((-w / 2, -d / 2, 0.04 * h), (w / 2, -d / 2 + t, h - 0.06 * h), p.primary)  # back
    for x0 in (-w / 2, w / 2 - t):
        b.box((x0, -d / 2, 0.04 * h), (x0 + t, d / 2, h - 0.06 * h), p.primary)
    b.box((-w / 2, -d / 2, h - 0.06 * h), (w / 2, d / 2, h), p.secondary)  # roof
    vent_lines(b, -0.3 * w, 0.3 * w, h - 0.05 * h, h - 0.01 * h, d / 2, 3, darker(p.secondary, 0.5))
    b.box((-w / 2 + t, -d / 2 + t, 0.04 * h), (w / 2 - t, -d / 2 + t + 0.01, h - 0.06 * h), lighter(p.primary, 0.15))
    b.box((-w / 2 + t, -d / 2 + t, 0.48 * h), (w / 2 - t, -d / 2 + 0.35 * d, 0.5 * h), p.accent)  # shelf
    b.cyl(0, 0.05 * d, 0.04 * h, 0.28 * h, 0.03, DARK_METAL, sections=8)
    b.cyl(0, 0.05 * d, 0.28 * h, 0.31 * h, 0.17 * min(w, d), p.accent, sections=16)  # stool
    b.box((-w / 2 + t, -d / 2 + t, h - 0.08 * h), (w / 2 - t, d / 2 - 0.02, h - 0.06 * h), tint("#fff8e0", "light"))  # light
    frame_y(b, -w / 2, w / 2, 0.04 * h, h - 0.06 * h, d / 2 - 0.03, d / 2, 0.025, p.secondary)
    b.box((-w / 2 + 0.025, d / 2 - 0.02, 0.04 * h), (w / 2 - 0.025, d / 2 - 0.01, h - 0.06 * h), GLASS, alpha=90)
    b.box((w / 2 - 0.1 * w, d / 2, 0.35 * h), (w / 2 - 0.08 * w, d / 2 + 0.0, 0.6 * h), CHROME)
    b.box((w / 2 - 0.1 * w, d / 2 - 0.01, 0.35 * h), (w / 2 - 0.07 * w, d / 2, 0.6 * h), CHROME)
    return b.mesh(p.size)


# ----------------------------------------------------------------- photo booth
def sample_photo_booth(rng, size, style):
    return make_params("photo_booth", rng, size, style, ["#c0392b", BLACK, "#c9ccd0", "#e8e6e0", "#2d4f8a"],
                       ["#b8322a", "#2b2b2b", "#6e2233", "#2f4a3a"], SIGN_LIGHT)


def build_photo_booth(p):
    """A photo booth: a cabinet with a curtained doorway on the front right, a panel of
    sample photo strips and the payment slot on the left, and a lit sign on top."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    sign = 0.82 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.04, sign), p.primary)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.05 * h), darker(p.primary, 0.4))
    split = -0.05 * w
    b.box((-w / 2, d / 2 - 0.04, 0.05 * h), (split, d / 2, sign), p.primary)  # front left panel
    b.box((split, d / 2 - 0.04, 0.05 * h), (w / 2, d / 2 - 0.02, 0.07 * h), darker(p.primary, 0.2))
    b.box((split + 0.02, d / 2 - 0.05, 0.07 * h), (w / 2 - 0.03, d / 2 - 0.04, sign), tint("#2a2528", "paper"))  # doorway
    n = max(6, int((w / 2 - split) / 0.06))
    for k in range(n):  # curtain folds
        x = split + 0.04 + (k + 0.5) * (w / 2 - split - 0.07) / n
        b.cyl(x, d / 2 - 0.025, 0.14 * h, sign - 0.02 * h, (w / 2 - split) / n * 0.6, p.secondary, sections=8)
    b.rod((split + 0.02, d / 2 - 0.02, sign - 0.015 * h), (w / 2 - 0.02, d / 2 - 0.02, sign - 0.015 * h), 0.01,
          CHROME, sections=6)
    sx0, sx1 = -w / 2 + 0.08 * w, split - 0.08 * w
    b.box((sx0 - 0.02, d / 2, 0.42 * h), (sx1 + 0.02, d / 2 + 0.005, 0.76 * h), tint("#f4f1ea", "paint"))  # sample panel
    cols = ["#d9a070", "#6a8ab0", "#c0708a", "#80a070", "#a0a0a0"]
    for i in range(3):
        xa = sx0 + i * (sx1 - sx0) / 3 + 0.02
        xb = sx0 + (i + 1) * (sx1 - sx0) / 3 - 0.02
        for j in range(4):
            z0 = 0.44 * h + j * 0.08 * h
            b.box((xa, d / 2 + 0.005, z0), (xb, d / 2 + 0.008, z0 + 0.065 * h), cols[int(rng.integers(len(cols)))], role="paint")
    b.box((sx0, d / 2, 0.25 * h), (sx1, d / 2 + 0.03, 0.35 * h), darker(p.primary, 0.3))  # payment box
    b.box((sx0 + 0.03, d / 2 + 0.03, 0.31 * h), (sx0 + 0.08, d / 2 + 0.032, 0.33 * h), BLACK)
    b.box((sx1 - 0.12, d / 2 + 0.03, 0.28 * h), (sx1 - 0.03, d / 2 + 0.032, 0.33 * h), SCREEN)
    b.box((sx0, d / 2, 0.15 * h), (sx1, d / 2 + 0.01, 0.17 * h), BLACK)  # print slot
    b.box((-w / 2, -d / 2, sign), (w / 2, d / 2, h), darker(p.primary, 0.2))  # sign box
    b.box((-w / 2 + 0.03, d / 2, sign + 0.02 * h), (w / 2 - 0.03, d / 2 + 0.006, h - 0.02 * h), p.accent)
    for k in range(5):  # the word on the sign, in blocks
        x = -0.3 * w + k * 0.15 * w
        b.box((x - 0.04 * w, d / 2 + 0.006, sign + 0.06 * h), (x + 0.04 * w, d / 2 + 0.009, h - 0.06 * h),
              darker(p.primary, 0.1) if p.primary != BLACK else tint("#c0392b", "paper"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- vocal booth
def sample_vocal_booth(rng, size, style):
    return make_params("vocal_booth", rng, size, style, ["#8c8f94", "#5f6b7a", "#3a3b3e", "#c9c1b4", "#d9dadc"],
                       ["#3a3b3e", BLACK, "#5f6b7a"], GLOW_RED, window=bool(rng.random() < 0.6))


def build_vocal_booth(p):
    """A sound isolation booth: panelled walls with seams, a heavy door with a small
    window, an ON AIR light above it, ventilation silencers on the roof, and a side window
    showing the microphone inside."""
    w, d, h = p.size
    b = Builder()
    roof = 0.9 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2 - 0.01, roof), p.primary)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04 * h), p.secondary)
    b.box((-w / 2, -d / 2, roof - 0.02 * h), (w / 2, d / 2, roof), p.secondary)
    n = max(2, int(w / 0.6))
    for k in range(1, n):
        x = -w / 2 + k * w / n
        b.box((x - 0.006, d / 2 - 0.01, 0.04 * h), (x + 0.006, d / 2, roof - 0.02 * h), darker(p.primary, 0.2))
    m = max(2, int(d / 0.6))
    for k in range(1, m):
        y = -d / 2 + k * d / m
        b.box((w / 2 - 0.0, y - 0.006, 0.04 * h), (w / 2 + 0.004, y + 0.006, roof - 0.02 * h), darker(p.primary, 0.2))
    dx0, dx1 = -0.15 * w, 0.3 * w
    b.box((dx0, d / 2 - 0.01, 0.04 * h), (dx1, d / 2 + 0.03, 0.82 * h), lighter(p.primary, 0.1))  # door
    frame_y(b, dx0 - 0.03, dx1 + 0.03, 0.04 * h, 0.84 * h, d / 2 - 0.01, d / 2 + 0.015, 0.03, p.secondary)
    b.box((dx0 + 0.25 * (dx1 - dx0), d / 2 + 0.03, 0.55 * h), (dx1 - 0.25 * (dx1 - dx0), d / 2 + 0.034, 0.72 * h),
          tint("#2a3038", "paint"))
    b.box((dx1 - 0.06, d / 2 + 0.03, 0.35 * h), (dx1 - 0.03, d / 2 + 0.07, 0.5 * h), CHROME)  # lever
    b.box((-0.08 * w + 0.075 * w, d / 2, 0.855 * h), (0.08 * w + 0.075 * w, d / 2 + 0.03, 0.885 * h), p.accent)
    if p.window:
        b.box((w / 2 - 0.001, -0.3 * d, 0.45 * h), (w / 2 + 0.004, 0.2 * d, 0.75 * h), tint("#2a3038", "paint"))
        b.cyl(0.2 * w, -0.05 * d, 0.04 * h, 0.55 * h, 0.012, DARK_METAL, sections=6)
    for x in (-0.3 * w, 0.3 * w):  # silencer boxes on the roof
        b.box((x - 0.12 * w, -0.3 * d, roof), (x + 0.12 * w, 0.2 * d, h), p.secondary)
        b.box((x - 0.08 * w, 0.2 * d, roof + 0.02 * h), (x + 0.08 * w, 0.21 * d, h - 0.02 * h), BLACK)
    return b.mesh(p.size)


# ----------------------------------------------------------------- ticket booth
def sample_ticket_booth(rng, size, style):
    old = _antique(style, rng, 0.5)
    return make_params("ticket_booth", rng, size, style, ["#8a1f2b", "#2d4f8a", "#3f6b4a"] + wood_tones(style)[:2],
                       ["#e8e6e0", "#d9c39a", BRASS], [SIGN_LIGHT, "#f1c40f"], roof="peaked" if old else "flat")


def build_ticket_booth(p):
    """A ticket kiosk: panelled lower walls, a counter ledge under a big glass window with
    a speaking grille, a roof over it and a sign ringed with bulbs."""
    w, d, h = p.size
    b = Builder()
    cz = 0.45 * h
    wz = 0.8 * h
    b.box((-w / 2 + 0.03, -d / 2, 0), (w / 2 - 0.03, d / 2 - 0.08 * d, cz), p.primary)
    for k in range(3):  # raised panels
        x0 = -w / 2 + 0.08 * w + k * 0.29 * w
        b.box((x0, d / 2 - 0.08 * d, 0.08 * h), (x0 + 0.25 * w, d / 2 - 0.08 * d + 0.01, cz - 0.08 * h),
              lighter(p.primary, 0.15))
    b.box((-w / 2, -d / 2, cz), (w / 2, d / 2 - 0.02, cz + 0.03 * h), p.secondary)  # counter
    for x in (-w / 2 + 0.03, w / 2 - 0.09):
        b.box((x, -d / 2, cz), (x + 0.06, d / 2 - 0.1 * d, wz), p.primary)
    b.box((-w / 2 + 0.09, d / 2 - 0.11 * d, cz + 0.03 * h), (w / 2 - 0.09, d / 2 - 0.1 * d, wz), GLASS, alpha=120)
    b.box((-w / 2 + 0.03, -d / 2, cz), (w / 2 - 0.03, -d / 2 + 0.05, wz), p.primary)
    ring_y(b, (0, d / 2 - 0.1 * d + 0.005, cz + 0.2 * h), 0.05, 0.01, p.secondary, sections=16)
    b.box((-0.12 * w, d / 2 - 0.12 * d, cz + 0.03 * h), (0.12 * w, d / 2 - 0.09 * d, cz + 0.05 * h), DARK_METAL)
    b.box((-w / 2 + 0.09, -d / 2 + 0.05, cz + 0.03 * h), (w / 2 - 0.09, d / 2 - 0.12 * d, wz), tint("#4a3a30", "paint"))  # inside
    for x in (-w / 2 + 0.03, w / 2 - 0.09):  # side windows
        b.box((x - 0.001, -0.25 * d, cz + 0.06 * h), (x + 0.061, 0.2 * d, wz - 0.04 * h), GLASS)
    sign_z = wz + 0.02 * h
    b.box((-w / 2, -d / 2, wz), (w / 2, d / 2, sign_z), p.secondary)  # eaves
    if p.roof == "peaked":
        b.hull([(-w / 2, -d / 2, sign_z), (w / 2, -d / 2, sign_z), (-w / 2, d / 2, sign_z), (w / 2, d / 2, sign_z),
                (-0.05 * w, -0.05 * d, h - 0.03 * h), (0.05 * w, -0.05 * d, h - 0.03 * h),
                (-0.05 * w, 0.05 * d, h - 0.03 * h), (0.05 * w, 0.05 * d, h - 0.03 * h)], darker(p.primary, 0.2))
        b.cyl(0, 0, h - 0.04 * h, h, 0.03, p.secondary, sections=8)
        sz0, sz1 = sign_z + 0.01 * h, sign_z + 0.09 * h
    else:
        b.box((-w / 2 + 0.05, -d / 2 + 0.05, sign_z), (w / 2 - 0.05, d / 2 - 0.05, h - 0.13 * h), p.primary)
        sz0, sz1 = sign_z + 0.01 * h, h
    sx = 0.32 * w
    b.box((-sx, d / 2 - 0.02, sz0), (sx, d / 2, sz1), p.accent)  # sign
    for k in range(4):
        x = -0.22 * w + k * 0.147 * w
        b.box((x - 0.05 * w, d / 2, sz0 + 0.25 * (sz1 - sz0)), (x + 0.05 * w, d / 2 + 0.004,
                                                                sz1 - 0.25 * (sz1 - sz0)), tint("#8a1f2b", "paint"))
    for t in np.linspace(0, 1, 12):  # bulbs round the sign
        for z in (sz0, sz1):
            b.sphere((-sx + t * 2 * sx, d / 2 + 0.005, z), 0.012 * w, tint("#ffe890", "light"), subdivisions=0)
    return b.mesh(p.size)


# ----------------------------------------------------------------- cubicle
def sample_cubicle(rng, size, style):
    return make_params("cubicle", rng, size, style, FELTS, ["#e8e6e0", "#c9a77c", "#d9dadc"], ["#2b2b2b", BLACK],
                       sides=int(rng.choice([2, 3])))


def build_cubicle(p):
    """An office cubicle: fabric partition panels on the back and sides, an L-shaped
    worktop with a pedestal, a monitor and keyboard, papers pinned up, a desk chair."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = 0.05
    trim = "#c9ccd0"
    panels = [((-w / 2, -d / 2), (w / 2, -d / 2 + t)), ((-w / 2, -d / 2), (-w / 2 + t, d / 2))]
    if p.sides == 3:
        panels.append(((w / 2 - t, -d / 2), (w / 2, 0.0)))
    for (x0, y0), (x1, y1) in panels:
        b.box((x0, y0, 0.02 * h), (x1, y1, h - 0.02 * h), p.primary)
        b.box((x0, y0, h - 0.02 * h), (x1, y1, h), trim, role="metal")
        b.box((x0, y0, 0), (x1, y1, 0.02 * h), DARK_METAL)
    dz = min(0.74, 0.5 * h)
    b.box((-w / 2 + t, -d / 2 + t, dz - 0.03), (w / 2 - (t if p.sides == 3 else 0), -d / 2 + t + 0.6 * d * 0.42, dz),
          p.secondary)
    b.box((-w / 2 + t, -d / 2 + t, dz - 0.03), (-w / 2 + t + 0.35 * w, d / 2 - 0.05, dz), p.secondary)
    b.box((-w / 2 + t + 0.02, 0.0, 0), (-w / 2 + t + 0.3 * w, 0.3 * d, dz - 0.03), lighter(p.primary, 0.25))
    for k in range(3):
        z = 0.15 * dz + k * 0.28 * dz
        b.box((-w / 2 + t + 0.02, 0.3 * d, z), (-w / 2 + t + 0.3 * w, 0.302 * d, z + 0.02), DARK_METAL)
    mx, my = 0.05 * w, -d / 2 + t + 0.08
    b.box((mx - 0.08, my, dz), (mx + 0.08, my + 0.15, dz + 0.01), p.accent)
    b.box((mx - 0.02, my + 0.03, dz), (mx + 0.02, my + 0.05, dz + 0.18), p.accent)
    b.box((mx - 0.28, my + 0.05, dz + 0.1), (mx + 0.28, my + 0.08, dz + 0.42), p.accent)  # monitor
    b.box((mx - 0.26, my + 0.08, dz + 0.12), (mx + 0.26, my + 0.081, dz + 0.4), tint("#3a5a7a", "paint"))
    b.box((mx - 0.22, my + 0.22, dz), (mx + 0.22, my + 0.36, dz + 0.02), tint("#3a3b3e", "paint"))  # keyboard
    cols = ["#f4f1ea", "#f1e6a0", "#a8d0e8", "#f4c0c0"]
    for _ in range(5):  # notes pinned to the back panel
        x = rng.uniform(-0.4 * w, 0.3 * w)
        z = dz + rng.uniform(0.25, 0.75) * (h - dz)
        b.box((x, -d / 2 + t, z), (x + 0.06 * w, -d / 2 + t + 0.003, z + 0.15 * (h - dz)),
              cols[int(rng.integers(len(cols)))], role="paper")
    cx, cy = 0.1 * w, 0.22 * d  # desk chair
    b.cyl(cx, cy, 0, 0.03, 0.28, DARK_METAL, sections=5)
    b.cyl(cx, cy, 0.03, 0.42, 0.025, DARK_METAL, sections=8)
    b.box((cx - 0.24, cy - 0.22, 0.42), (cx + 0.24, cy + 0.22, 0.5), tint("#2b2b2b", "paint"))
    b.box((cx - 0.22, cy + 0.2, 0.5), (cx + 0.22, cy + 0.26, min(1.0, h - 0.05)), tint("#2b2b2b", "paint"))
    return b.mesh(p.size)


# ----------------------------------------------------------------- sleeping pod
def sample_sleeping_pod(rng, size, style):
    return make_params("sleeping_pod", rng, size, style, ["#e8e6e0", "#f2f1ed", "#c9a77c", "#8c8f94", "#2b2b2b"],
                       ["#e8e6e0", "#f4f1ea"], FABRICS, curtain=bool(rng.random() < 0.5))


def build_sleeping_pod(p):
    """A sleeping capsule running back along y: a rounded shell open at the front end,
    a lit interior with mattress, pillow and blanket, a reading light and a half-drawn
    curtain."""
    w, d, h = p.size
    b = Builder()
    r = min(0.35 * w, 0.4 * h)
    outer = [(-w / 2, 0), (w / 2, 0)] + arc(w / 2 - r, h - r, r, 0, np.pi / 2, 6) + \
        arc(-w / 2 + r, h - r, r, np.pi / 2, np.pi, 6)
    t = 0.06 * min(w, h)
    ri = max(r - t, 0.01)
    inner = [(-w / 2 + t, 0.12 * h), (w / 2 - t, 0.12 * h)] + arc(w / 2 - r, h - r, ri, 0, np.pi / 2, 6) + \
        arc(-w / 2 + r, h - r, ri, np.pi / 2, np.pi, 6)
    outer = [(x, min(max(z, 0.0), h)) for x, z in outer]
    extrude_y(b, outer, -d / 2, -d / 2 + 0.04, p.primary)  # back cap
    extrude_y(b, outer, -d / 2 + 0.04, d / 2 - 0.04, p.primary, holes=[inner[::-1]])
    extrude_y(b, outer, d / 2 - 0.04, d / 2, darker(p.primary, 0.15), holes=[inner[::-1]])  # front rim
    b.box((-w / 2 + t, -d / 2 + 0.04, 0.12 * h), (w / 2 - t, d / 2 - 0.04, 0.13 * h), tint("#4a4c50", "paint"))
    b.box((-w / 2 + t, -d / 2 + 0.05, 0.13 * h), (w / 2 - t, d / 2 - 0.06, 0.22 * h), p.secondary)  # mattress
    b.box((-0.3 * w, -d / 2 + 0.06, 0.22 * h), (0.3 * w, -d / 2 + 0.06 + 0.18 * d, 0.3 * h), tint("#f8f8f6", "fabric"))  # pillow
    b.box((-w / 2 + t, -d / 2 + 0.3 * d, 0.22 * h), (w / 2 - t, d / 2 - 0.1, 0.26 * h), p.accent)  # blanket
    b.box((-w / 2 + t, -d / 2 + 0.04, 0.55 * h), (-w / 2 + t + 0.01, -d / 2 + 0.5 * d, 0.58 * h), tint("#fff1c4", "light"))
    b.box((-w / 2 + t, -d / 2 + 0.15 * d, 0.5 * h), (-w / 2 + t + 0.01, -d / 2 + 0.3 * d, 0.65 * h), SCREEN)
    if p.curtain:
        n = 6
        for k in range(n):
            x = -w / 2 + t + (k + 0.5) * (0.45 * w) / n
            b.cyl(x, d / 2 - 0.06, 0.13 * h, h - r * 0.4 - t, 0.45 * w / n * 0.6, p.accent, sections=8)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.03 * h), darker(p.primary, 0.3))
    return b.mesh(p.size)


# ----------------------------------------------------------------- elevator
def sample_elevator(rng, size, style):
    cage = _antique(style, rng, 0.2)
    return make_params("elevator", rng, size, style, ["#e8e6e0", "#d9d3c7", "#c9c1b4", "#b8b0a0"],
                       [BRASS, BLACK] if cage else [STEEL, CHROME, "#9a9da3"], "#f0a030",
                       kind="cage" if cage else "doors")


def build_elevator(p):
    """A lift in its shaft: a steel portal with two sliding doors and the floor indicator
    above them, call buttons beside; or an old cage lift behind a folding lattice gate
    with a dial indicator."""
    w, d, h = p.size
    b = Builder()
    fy = d / 2 - 0.04
    b.box((-w / 2, -d / 2, 0), (w / 2, fy, h), p.primary)
    dw = min(0.55 * w, 1.1)
    dh = min(0.82 * h, 2.1)
    fr = 0.06
    if p.kind == "cage":
        b.box((-dw / 2, fy - 0.6 * d, 0.02), (dw / 2, fy, dh), tint("#5c3b26", "paint"))  # the car inside
        b.box((-dw / 2 + 0.05, fy - 0.58 * d, 0.3 * dh), (dw / 2 - 0.05, fy - 0.57 * d, 0.9 * dh), tint("#7a5030", "paint"))
        b.box((-dw / 2, fy - 0.6 * d, 0), (dw / 2, fy, 0.02), tint("#3a2a1a", "paint"))
        frame_y(b, -dw / 2 - fr, dw / 2 + fr, 0, dh + fr, fy, d / 2, fr, p.secondary)
        n = 9
        for k in range(n + 1):  # lattice gate
            x0 = -dw / 2 + k * dw / n
            for s in (-1, 1):
                xa, xb = x0, x0 + s * dw / n
                if -dw / 2 - 1e-6 <= xb <= dw / 2 + 1e-6:
                    for j in range(4):
                        za, zb = j * dh / 4, (j + 1) * dh / 4
                        xa2, xb2 = (xa, xb) if j % 2 == 0 else (xb, xa)
                        b.rod((xa2, d / 2 - 0.02, za), (xb2, d / 2 - 0.02, zb), 0.006, p.secondary, sections=4)
            b.box((x0 - 0.006, d / 2 - 0.03, 0), (x0 + 0.006, d / 2 - 0.01, dh), p.secondary)
        cz = dh + fr + 0.5 * (h - dh - fr)
        R = min(0.4 * (h - dh - fr), 0.2 * w)
        extrude_y(b, arc(0, cz - 0.5 * R, R, 0, np.pi, 12), fy, d / 2, p.secondary)
        extrude_y(b, arc(0, cz - 0.45 * R, 0.85 * R, 0, np.pi, 12), d / 2, d / 2 + 0.003, tint("#f4f1e6", "paint"))
        b.rod((0, d / 2 + 0.004, cz - 0.45 * R), (0.5 * R, d / 2 + 0.004, cz + 0.2 * R), 0.008, BLACK, sections=4)
        return b.mesh(p.size)
    frame_y(b, -dw / 2 - fr, dw / 2 + fr, 0, dh + fr, fy, d / 2, fr, p.secondary)
    for s in (-1, 1):
        x0, x1 = sorted((0.0, s * dw / 2))
        b.box((x0 + 0.003, fy - 0.01, 0), (x1 - 0.003, fy + 0.01, dh), lighter(p.secondary, 0.15))
    b.box((-0.002, fy + 0.01, 0), (0.002, fy + 0.011, dh), DARK_METAL)
    b.box((-0.12 * w, fy, dh + fr + 0.05), (0.12 * w, d / 2, dh + fr + 0.05 + 0.15), BLACK)  # indicator
    b.box((-0.03 * w, d / 2, dh + fr + 0.08), (0.03 * w, d / 2 + 0.002, dh + fr + 0.17), p.accent)
    px = dw / 2 + fr + 0.12
    b.box((px - 0.05, fy, 0.45 * dh), (px + 0.05, d / 2 - 0.01, 0.6 * dh), p.secondary)  # call panel
    for k, z in enumerate((0.5 * dh, 0.55 * dh)):
        disc_y(b, px, d / 2 - 0.01, d / 2, z, 0.02, p.accent if k else CHROME, sections=10)
    b.box((-w / 2, fy, 0), (w / 2, d / 2, 0.02), tint("#9a9da3", "metal"))  # sill
    return b.mesh(p.size)


# ----------------------------------------------------------------- golf simulator
def sample_golf_simulator(rng, size, style):
    return make_params("golf_simulator", rng, size, style, [BLACK, "#2b2b2b", "#3a3b3e"], ["#3a8a3a", "#4a9a3a"],
                       ["#8ac4e8", "#9ad0f0", "#a8c8e0"], bag=bool(rng.random() < 0.6))


def build_golf_simulator(p):
    """A golf simulator bay: a black frame, the impact screen at the back showing sky,
    trees and a fairway with the flag, netting on the sides, turf with a hitting mat, a
    ball on its tee and the projector on the top rail."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = 0.05
    for x in (-w / 2, w / 2 - t):
        for y in (-d / 2, d / 2 - t):
            b.box((x, y, 0), (x + t, y + t, h), p.primary)
    for y in (-d / 2, d / 2 - t):
        b.box((-w / 2, y, h - t), (w / 2, y + t, h), p.primary)
    for x in (-w / 2, w / 2 - t):
        b.box((x, -d / 2, h - t), (x + t, d / 2, h), p.primary)
    sy = -d / 2 + t
    b.box((-w / 2 + t, sy, 0.55 * h), (w / 2 - t, sy + 0.02, h - t), p.accent)  # sky
    b.box((-w / 2 + t, sy, 0.05), (w / 2 - t, sy + 0.02, 0.55 * h), tint("#5aa04a", "fabric"))  # fairway
    b.hull([(-0.2 * w, sy + 0.021, 0.3 * h), (0.25 * w, sy + 0.021, 0.3 * h), (-0.05 * w, sy + 0.021, 0.55 * h),
            (0.05 * w, sy + 0.021, 0.55 * h), (-0.2 * w, sy + 0.023, 0.3 * h), (0.25 * w, sy + 0.023, 0.3 * h),
            (-0.05 * w, sy + 0.023, 0.55 * h), (0.05 * w, sy + 0.023, 0.55 * h)], tint("#8ad06a", "paint"))
    for _ in range(8):  # trees along the horizon
        x = rng.uniform(-0.45 * w, 0.45 * w)
        if abs(x) < 0.12 * w:
            continue
        r = rng.uniform(0.04, 0.07) * h
        b.sphere((x, sy + 0.03, 0.55 * h + 0.6 * r), (r, 0.01, r), tint("#2a5a2a", "paint"), subdivisions=1)
    b.box((0.0, sy + 0.024, 0.5 * h), (0.004 * w + 0.006, sy + 0.028, 0.6 * h), tint("#f4f4f4", "paint"))  # flag pole
    b.box((0.004 * w + 0.006, sy + 0.024, 0.57 * h), (0.03 * w + 0.02, sy + 0.028, 0.6 * h), tint("#d63a2a", "paint"))
    for x0 in (-w / 2 + t / 2, w / 2 - t / 2 - 0.01):  # side nets
        b.box((x0, -d / 2 + t, 0.05), (x0 + 0.01, d / 2 - t, h - t), tint("#303234", "paint"), alpha=110)
    b.box((-w / 2 + t, -d / 2 + t, h - t - 0.01), (w / 2 - t, -d / 2 + 0.25 * d, h - t), tint("#303234", "paint"), alpha=110)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.03), p.secondary)  # turf
    b.box((-0.2 * w, 0.05 * d, 0.03), (0.2 * w, 0.35 * d, 0.05), tint("#6ab85a", "rubber"))  # hitting mat
    b.cyl(0.0, 0.15 * d, 0.05, 0.07, 0.005, tint("#f4f4f4", "paint"), sections=6)
    b.sphere((0.0, 0.15 * d, 0.09), 0.025, tint("#fbfbfb", "paint"), subdivisions=1)
    b.box((0.12 * w, 0.2 * d, 0.05), (0.16 * w, 0.26 * d, 0.12), BLACK)  # launch monitor
    b.box((-0.05 * w, d / 2 - t - 0.4, h - t - 0.2), (0.05 * w, d / 2 - t - 0.05, h - t), tint("#e8e6e0", "paint"))  # projector
    disc_y(b, 0, d / 2 - t - 0.42, d / 2 - t - 0.4, h - t - 0.1, 0.05, tint("#2a4a6a", "paint"), sections=12)
    b.box((-0.01, d / 2 - t - 0.3, h - t), (0.01, d / 2 - t - 0.25, h), p.primary)
    if p.bag:
        bx, by = 0.35 * w, 0.2 * d
        b.cyl(bx, by, 0.03, 0.9, 0.13, tint("#2d4f8a", "paint"), sections=12)
        for k in range(5):
            a = 2 * np.pi * k / 5
            b.rod((bx + 0.06 * np.cos(a), by + 0.06 * np.sin(a), 0.85), (bx + 0.08 * np.cos(a), by + 0.08 * np.sin(a),
                                                                          1.1), 0.012, CHROME, sections=5)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dj booth
def sample_dj_booth(rng, size, style):
    return make_params("dj_booth", rng, size, style, [BLACK, "#2b2b2b", "#e8e6e0", "#3a3b3e"], ["#15161a", BLACK],
                       NEON, front=str(rng.choice(["bars", "grid", "panel"])))


def build_dj_booth(p):
    """A DJ booth: a facade with glowing light bars, two turntables either side of a
    mixer with knobs and faders, a laptop on its stand and monitor speakers at the ends."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    top = 0.86 * h
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, top), p.primary)
    if p.front == "bars":
        for k in range(5):
            z = 0.12 * top + k * 0.17 * top
            b.box((-0.45 * w, d / 2, z), (0.45 * w, d / 2 + 0.01, z + 0.04 * top), p.accent)
    elif p.front == "grid":
        for i in range(12):
            for j in range(5):
                col = p.accent if rng.random() < 0.6 else lighter(p.accent, 0.5)
                b.cbox((-0.44 * w + (i + 0.5) * 0.88 * w / 12, d / 2 + 0.004, 0.14 * top + (j + 0.5) * 0.7 * top / 5),
                       (0.05 * w, 0.008, 0.1 * top), col)
    else:
        b.box((-0.4 * w, d / 2, 0.2 * top), (0.4 * w, d / 2 + 0.01, 0.8 * top), p.accent)
        b.box((-0.36 * w, d / 2 + 0.01, 0.25 * top), (0.36 * w, d / 2 + 0.012, 0.75 * top), darker(p.accent, 0.4))
    b.box((-w / 2 - 0.0, -d / 2, top), (w / 2, d / 2, top + 0.02 * h), p.secondary)
    z = top + 0.02 * h
    for s in (-1, 1):  # turntables
        cx = s * 0.22 * w
        b.box((cx - 0.2, -0.2, z), (cx + 0.2, 0.15, z + 0.05), DARK_METAL)
        b.cyl(cx - 0.03, -0.03, z + 0.05, z + 0.06, 0.14, CHROME, sections=24)
        b.cyl(cx - 0.03, -0.03, z + 0.06, z + 0.065, 0.135, BLACK, sections=24)
        b.cyl(cx - 0.03, -0.03, z + 0.065, z + 0.067, 0.045, p.accent, sections=12)
        b.rod((cx + 0.15, -0.15, z + 0.08), (cx + 0.08, 0.05, z + 0.07), 0.006, CHROME, sections=5)
    b.box((-0.09, -0.18, z), (0.09, 0.15, z + 0.06), tint("#2b2b2b", "paint"))  # mixer
    for i in range(3):
        for j in range(4):
            b.cyl(-0.06 + 0.06 * i, -0.14 + 0.06 * j, z + 0.06, z + 0.075, 0.012, tint("#c9ccd0", "metal"), sections=6)
    b.box((-0.07, 0.1, z + 0.06), (0.07, 0.11, z + 0.07), CHROME)
    lx = 0.0
    b.box((lx - 0.08, -d / 2 + 0.05, z), (lx + 0.08, -d / 2 + 0.2, z + 0.12), DARK_METAL)  # laptop stand
    b.box((lx - 0.17, -d / 2 + 0.05, z + 0.12), (lx + 0.17, -d / 2 + 0.28, z + 0.13), tint("#9a9da3", "metal"))
    b.box((lx - 0.17, -d / 2 + 0.04, z + 0.13), (lx + 0.17, -d / 2 + 0.06, h), tint("#9a9da3", "metal"))
    b.box((lx - 0.15, -d / 2 + 0.061, z + 0.15), (lx + 0.15, -d / 2 + 0.062, h - 0.01), tint("#2a3a5a", "paint"))
    for s in (-1, 1):  # monitors
        x = s * (w / 2 - 0.1)
        b.box((x - 0.09, -d / 2 + 0.02, z), (x + 0.09, -d / 2 + 0.24, z + 0.28), BLACK)
        disc_y(b, x, -d / 2 + 0.24, -d / 2 + 0.25, z + 0.1, 0.06, tint("#3a3b3e", "paint"), sections=12)
    return b.mesh(p.size)


slot_roles("phone_booth", "paint", "light", "wood")
register("phone_booth", sample_phone_booth, build_phone_booth)
slot_roles("photo_booth", {"": "paint", "#c9ccd0": "metal"}, "fabric", "light")
register("photo_booth", sample_photo_booth, build_photo_booth)
slot_roles("vocal_booth", "fabric", "paint", "light")
register("vocal_booth", sample_vocal_booth, build_vocal_booth)
slot_roles("ticket_booth", "paint", {"": "wood", BRASS: "metal"}, "light")
register("ticket_booth", sample_ticket_booth, build_ticket_booth)
slot_roles("cubicle", "fabric", "plastic", "plastic")
register("cubicle", sample_cubicle, build_cubicle)
slot_roles("sleeping_pod", "plastic", "fabric", "fabric")
register("sleeping_pod", sample_sleeping_pod, build_sleeping_pod)
slot_roles("elevator", "paint", "metal", "light")
register("elevator", sample_elevator, build_elevator)
slot_roles("golf_simulator", "fabric", "fabric", "fabric")
register("golf_simulator", sample_golf_simulator, build_golf_simulator)
slot_roles("dj_booth", "paint", "plastic", "light")
register("dj_booth", sample_dj_booth, build_dj_booth)
