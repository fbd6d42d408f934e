"""Music and stage: microphone, speaker, drum_kit, guitar, music_stand, stage_platform."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    Role,
    about,
    darker,
    lighter,
    make_params,
    move,
    rot_x,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

BRASS = tint("#c9a54a", "metal")
DRUM_SHELLS = tint(["#b8322a", "#2d4f8a", BLACK, "#e8e6e0", "#5c3b26", "#3f6b4a", "#7a2a5a"], "paint")
DRUM_HEAD = tint("#f0ede6", "plastic")


def _along_y(x: float, y0: float, y1: float, z: float, rx: float, rz: float
             ) -> tuple[tuple[float, float, float, float, float], np.ndarray]:
    """Arguments and transform that lay an elliptic ``Builder.cyl`` along y: the section
    (rx across x, rz up z) centred on (x, z), from y0 to y1."""
    return (0.0, 0.0, y0, y1, rx), move((x, 0, z)) @ rot_x(-np.pi / 2) @ np.diag([1.0, rz / rx, 1.0, 1.0])


def _disc_y(b: Builder, x: float, y0: float, y1: float, z: float, r: float, color: str, sections: int = 20,
            role: Role | None = None) -> None:
    """A round disc facing +y (a speaker cone, a drum head, a knob)."""
    b.rod((x, y0, z), (x, y1, z), r, color, sections=sections, role=role)


# ----------------------------------------------------------------- microphone
def sample_microphone(rng, size, style):
    return make_params("microphone", rng, size, style, [BLACK, DARK_METAL, "#2b2b2b"], ["#b0b3b8", "#3a3b3e"],
                       METAL, base=str(rng.choice(["tripod", "round"])), boom=bool(rng.random() < 0.5))


def build_microphone(p):
    w, d, h = p.size
    b = Builder()
    R = min(w, d) / 2
    if p.base == "tripod":
        hub = min(0.3, 0.18 * h)
        for i in range(3):
            a = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0, 0, hub), (0.95 * R * np.cos(a), 0.95 * R * np.sin(a), 0.01), 0.01, p.primary, sections=6)
            b.sphere((0.95 * R * np.cos(a), 0.95 * R * np.sin(a), 0.012), 0.015, BLACK, subdivisions=0)
    else:
        b.cyl(0, 0, 0, 0.03, 0.8 * R, p.primary, r_top=0.75 * R, sections=24)
    top = h * (0.75 if p.boom else 0.86)
    b.cyl(0, 0, 0, top, 0.012, p.primary, sections=8)
    b.cyl(0, 0, 0.55 * top, 0.58 * top, 0.02, p.accent, sections=8)  # height clutch
    if p.boom:
        tip = np.array([0, 0.9 * d / 2, h - 0.09])
        tail = np.array([0, -0.7 * d / 2, top - 0.15 * (h - top)])
        b.rod(tail, tip, 0.01, p.primary, sections=8)
        b.sphere((0, 0, top), 0.025, p.accent, subdivisions=0)
        b.cyl(tail[0], tail[1], tail[2] - 0.05, tail[2] + 0.03, 0.03, p.primary, sections=10)  # counterweight
        base_mic = tip
    else:
        base_mic = np.array([0, 0, top])
    direction = np.array([0, 0.45, 1.0])
    direction /= np.linalg.norm(direction)
    clip_end = base_mic + direction * 0.04
    b.rod(base_mic, clip_end, 0.012, p.accent, sections=8)
    body_end = clip_end + direction * 0.13
    b.rod(clip_end, body_end, 0.02, p.primary, sections=10)
    head = body_end + direction * 0.02
    b.sphere(head, 0.035, p.secondary, subdivisions=2)
    return b.mesh(p.size)


# ----------------------------------------------------------------- speaker / amplifier
def sample_speaker(rng, size, style):
    w, _, h = size
    kind = "amp" if w >= 0.9 * h else ("tower" if h >= 1.5 * w else "monitor")
    return make_params("speaker", rng, size, style,
                       [BLACK, "#2b2b2b", "#3a3b3e"] + (wood_tones(style)[:2] if kind != "amp" else ["#e8dcc0"]),
                       ["#1c1c1e", "#2b2b2b"], ["#9a9da3", BRASS, "#e8e6e0"], kind=kind,
                       grille=bool(kind != "amp" and rng.random() < 0.3))


def _driver(b: Builder, x: float, y: float, z: float, r: float, cone: str) -> None:
    _disc_y(b, x, y - 0.01, y + 0.004, z, r, BLACK, 24)
    _disc_y(b, x, y + 0.004, y + 0.008, z, 0.82 * r, cone, 24)
    b.sphere((x, y + 0.008, z), (0.25 * r, 0.12 * r, 0.25 * r), darker(cone, 0.3), subdivisions=1)


def build_speaker(p):
    w, d, h = p.size
    b = Builder()
    y = d / 2
    if p.kind == "amp":
        b.box((-w / 2, -d / 2, 0.02), (w / 2, d / 2 - 0.01, h - 0.03), p.primary)
        b.box((-w / 2 + 0.03, y - 0.01, 0.05), (w / 2 - 0.03, y, 0.72 * h), p.secondary)  # grille cloth
        for k in range(1, 6):
            z = 0.05 + k * (0.67 * h - 0.05) / 6
            b.box((-w / 2 + 0.03, y, z - 0.002), (w / 2 - 0.03, y + 0.002, z + 0.002), darker(p.secondary, 0.4))
        b.box((-w / 2 + 0.03, y - 0.01, 0.76 * h), (w / 2 - 0.03, y, h - 0.06), tint("#c9ccd0", "metal"))  # control panel
        n = 6
        for i in range(n):
            _disc_y(b, -w / 2 + 0.08 + i * (w - 0.16) / (n - 1), y, y + 0.02, 0.83 * h, 0.014, BLACK, 10)
        b.box((-0.12 * w, y, 0.6 * h), (0.12 * w, y + 0.004, 0.66 * h), p.accent)  # logo
        b.box((-0.12, -0.02, h - 0.03), (0.12, 0.02, h), BLACK)  # handle
        for sx in (-1, 1):
            for sy in (-1, 1):
                b.cbox((sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 0.01), (0.04, 0.04, 0.02), BLACK)
        return b.mesh(p.size)
    foot = 0.03
    b.box((-w / 2, -d / 2, foot), (w / 2, d / 2 - 0.01, h), p.primary)
    b.box((-w / 2 + 0.01, y - 0.012, foot + 0.01), (w / 2 - 0.01, y - 0.008, h - 0.01), BLACK)  # baffle
    for sx in (-1, 1):
        for sy in (-1, 1):
            b.cyl(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), 0, foot, 0.02, METAL, r_top=0.008, sections=8)
    r = min(0.44 * w, 0.2)
    zs = [foot + r + 0.04]
    if p.kind == "tower":
        zs.append(zs[0] + 2 * r + 0.03)
    for z in zs:
        _driver(b, 0, y - 0.008, z, r, p.accent if p.accent != BRASS else METAL)
    zt = max(zs) + r + 0.1
    _driver(b, 0, y - 0.008, min(zt, h - 0.08), 0.05, tint("#c9ccd0", "metal"))
    _disc_y(b, 0, y - 0.01, y, max(0.06, zs[0] - r - 0.02), 0.025, tint("#111111", "plastic"), 12)  # port
    if p.grille:  # a cloth grille over the lower half, as if half removed
        b.box((-w / 2 + 0.015, y, foot + 0.02), (w / 2 - 0.015, y + 0.012, foot + 0.45 * (h - foot)), p.secondary,
              alpha=235)
    return b.mesh(p.size)


# ----------------------------------------------------------------- drum kit
def sample_drum_kit(rng, size, style):
    return make_params("drum_kit", rng, size, style, DRUM_SHELLS, DRUM_HEAD, BRASS, toms=int(rng.integers(1, 3)),
                       front_logo=bool(rng.random() < 0.6))


def _drum(b: Builder, x: float, y: float, z0: float, z1: float, r: float, shell: str, tilt: float = 0.0) -> None:
    m = about(rot_x(tilt), (x, y, (z0 + z1) / 2))
    b.cyl(x, y, z0, z1 - 0.006, r, shell, sections=20, transform=m)
    b.cyl(x, y, z1 - 0.006, z1, r * 1.02, DRUM_HEAD, sections=20, transform=m)
    b.cyl(x, y, z0, z0 + 0.012, r * 1.03, METAL, sections=20, transform=m)


def _cymbal(b: Builder, x: float, y: float, z: float, r: float, tilt: float = 0.0) -> None:
    b.cyl(x, y, 0.0, z - 0.01, 0.008, METAL, sections=6)
    m = about(rot_x(tilt), (x, y, z))
    b.cyl(x, y, z, z + 0.012, r, BRASS, r_top=0.15 * r, sections=20, transform=m)
    for i in range(3):
        a = 2 * np.pi * i / 3
        b.rod((x, y, 0.25 * z), (x + 0.16 * np.cos(a), y + 0.16 * np.sin(a), 0.0), 0.006, METAL, sections=4)


def build_drum_kit(p):
    """Drawn on a 1.8 x 1.5 x 1.2 m layout and fitted to the box; the drummer sits at -y."""
    b = Builder()
    shell = p.primary
    # bass drum, axis along y, front head towards the audience (+y)
    args, m = _along_y(0, 0.0, 0.42, 0.29, 0.28, 0.28)
    b.cyl(*args, shell, sections=24, transform=m)
    args, m = _along_y(0, 0.42, 0.44, 0.29, 0.29, 0.29)
    b.cyl(*args, DRUM_HEAD if not p.front_logo else BLACK, sections=24, transform=m)
    if p.front_logo:
        _disc_y(b, 0, 0.44, 0.445, 0.29, 0.12, DRUM_HEAD, 20)
    for y in (0.0, 0.42):
        args, m = _along_y(0, y - 0.012, y + 0.012, 0.29, 0.295, 0.295)
        b.cyl(*args, METAL, sections=24, transform=m)
    for sx in (-1, 1):  # spurs
        b.rod((sx * 0.2, 0.35, 0.12), (sx * 0.32, 0.42, 0.0), 0.008, METAL, sections=4)
    b.box((-0.05, -0.12, 0.0), (0.05, 0.05, 0.04), DARK_METAL)  # pedal
    # rack toms on the bass drum, floor tom, snare
    for i in range(p.toms):
        x = 0.0 if p.toms == 1 else (-0.16 + 0.32 * i)
        b.rod((x, 0.2, 0.56), (x, 0.15, 0.68), 0.01, METAL, sections=6)
        _drum(b, x, 0.12, 0.65, 0.87, 0.15, shell, tilt=0.35)
    _drum(b, 0.48, -0.15, 0.3, 0.64, 0.21, shell)
    for i in range(3):
        a = 2 * np.pi * i / 3
        b.rod((0.48 + 0.2 * np.cos(a), -0.15 + 0.2 * np.sin(a), 0.35),
              (0.48 + 0.25 * np.cos(a), -0.15 + 0.25 * np.sin(a), 0.0), 0.008, METAL, sections=4)
    _drum(b, -0.38, -0.2, 0.55, 0.69, 0.17, shell)
    for i in range(3):
        a = 2 * np.pi * i / 3
        b.rod((-0.38, -0.2, 0.5), (-0.38 + 0.2 * np.cos(a), -0.2 + 0.2 * np.sin(a), 0.0), 0.007, METAL, sections=4)
    # cymbals: hi-hat (two plates), crash, ride
    _cymbal(b, -0.72, -0.1, 0.88, 0.17)
    b.cyl(-0.72, -0.1, 0.86, 0.87, 0.17, BRASS, r_top=0.05, sections=20)
    _cymbal(b, -0.55, 0.42, 1.17, 0.22, tilt=0.25)
    _cymbal(b, 0.66, 0.3, 1.08, 0.25, tilt=-0.2)
    # throne
    b.cyl(0, -0.58, 0.5, 0.58, 0.17, BLACK, sections=20)
    b.cyl(0, -0.58, 0.0, 0.5, 0.02, METAL, sections=8)
    for i in range(3):
        a = 2 * np.pi * i / 3 + np.pi / 6
        b.rod((0, -0.58, 0.2), (0.2 * np.cos(a), -0.58 + 0.2 * np.sin(a), 0.0), 0.008, METAL, sections=4)
    return b.mesh(p.size)


# ----------------------------------------------------------------- guitar on a stand
def sample_guitar(rng, size, style):
    _, _, h = size
    kind = "cello" if h >= 1.15 else str(rng.choice(["acoustic", "acoustic", "electric"]))
    body = (["#c98a4a", "#d9a766", "#a0603a", "#5c3b26"] if kind != "electric"
            else ["#b8322a", BLACK, "#e8e6e0", "#2d4f8a", "#d9a32a", "#3f8a7a"])
    if kind == "cello":
        body = ["#8a4a22", "#7a3a1a", "#9a5a2a"]
    return make_params("guitar", rng, size, style, body, "#2a1d16", DARK_METAL, kind=kind)


def _bout(b: Builder, z: float, rx: float, rz: float, t: float, color: str) -> None:
    args, m = _along_y(0, -t / 2, t / 2, z, rx, rz)
    b.cyl(*args, color, sections=24, transform=m)


def _guitar(b: Builder, p, H: float) -> None:
    """Upright instrument H tall, face towards +y, bottom at z = 0."""
    cello = p.kind == "cello"
    base = 0.08 * H if cello else 0.0
    body_top = base + (0.55 if cello else 0.48) * H
    bl = body_top - base
    t = 0.11 if cello else (0.09 if p.kind == "acoustic" else 0.045)
    lower, upper = (0.2, 0.16) if not cello else (0.22, 0.18)
    _bout(b, base + 0.3 * bl, lower, 0.3 * bl, t, p.primary)
    _bout(b, base + 0.74 * bl, upper, 0.26 * bl, t, p.primary)
    if p.kind == "electric":
        b.hull([(-0.06, t / 2, base + 0.25 * bl), (0.12, t / 2, base + 0.35 * bl), (0.1, t / 2, base + 0.75 * bl),
                (-0.02, t / 2, base + 0.6 * bl), (-0.06, t / 2 + 0.003, base + 0.25 * bl),
                (0.12, t / 2 + 0.003, base + 0.35 * bl), (0.1, t / 2 + 0.003, base + 0.75 * bl)], tint("#f0ede6", "paint"))
        for z in (0.45, 0.62):
            b.cbox((0, t / 2 + 0.004, base + z * bl), (0.08, 0.01, 0.025), BLACK)
        for i in range(3):
            _disc_y(b, 0.1 - 0.03 * i, t / 2, t / 2 + 0.012, base + (0.2 + 0.06 * i) * bl, 0.012, DARK_METAL, 8)
    elif cello:
        for sx in (-1, 1):
            b.cbox((sx * 0.07, t / 2, base + 0.5 * bl), (0.012, 0.006, 0.16 * bl), BLACK)
        b.cbox((0, t / 2 + 0.01, base + 0.38 * bl), (0.09, 0.012, 0.03), tint("#d9c3a0", "paint"))  # bridge
        b.cyl(0, 0, 0.0, base + 0.02, 0.008, METAL, sections=6)  # endpin
    else:
        _disc_y(b, 0, t / 2 - 0.001, t / 2 + 0.002, base + 0.66 * bl, 0.05, tint("#1a1411", "wood"), 20)
        b.cbox((0, t / 2 + 0.004, base + 0.28 * bl), (0.12, 0.01, 0.02), p.secondary)
    neck_w = 0.055 if not cello else 0.07
    neck_top = H - (0.09 if not cello else 0.07) * H
    b.box((-neck_w / 2, t / 2 - 0.03, body_top - 0.04), (neck_w / 2, t / 2 + 0.012, neck_top), p.secondary)
    if cello:
        b.sphere((0, t / 2 - 0.02, H - 0.035 * H), (0.03, 0.03, 0.035 * H), p.primary)
        b.box((-0.025, t / 2 - 0.04, neck_top), (0.025, t / 2 - 0.005, H - 0.06 * H), p.primary)
    else:
        b.box((-0.045, t / 2 - 0.035, neck_top), (0.045, t / 2 - 0.005, H), p.secondary)
        for sx in (-1, 1):
            for k in range(3):
                z = neck_top + (0.2 + 0.28 * k) * (H - neck_top)
                b.rod((sx * 0.045, t / 2 - 0.02, z), (sx * 0.065, t / 2 - 0.02, z), 0.006, METAL, sections=4)
    b.box((-0.018, t / 2 + 0.012, base + 0.28 * bl), (0.018, t / 2 + 0.014, neck_top), tint("#e0e0dc", "paint"))  # strings


def build_guitar(p):
    """A guitar (or, in a box over 1.15 m, a cello) on an A-frame stand, leaning back."""
    w, d, h = p.size
    b = Builder()
    g = Builder()
    H = 0.97 * h
    _guitar(g, p, H)
    lean = 0.2
    b.extend(g, move((0, 0.1 * d, 0.04 * h)) @ rot_x(lean))
    for sx in (-1, 1):  # stand: two back legs to a neck yoke, two front rests
        b.rod((sx * 0.12, -d / 2 + 0.02, 0.0), (0, -0.1 * d - 0.6 * H * np.sin(lean), 0.6 * H), 0.01, BLACK,
              sections=6)
        b.rod((sx * 0.14, d / 2 - 0.02, 0.0), (sx * 0.1, 0.02 * d, 0.06 * h), 0.01, BLACK, sections=6)
        b.rod((sx * 0.1, 0.02 * d, 0.06 * h), (sx * 0.1, 0.12 * d, 0.08 * h), 0.012, tint("#3a3b3e", "paint"), sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- music stand
def sample_music_stand(rng, size, style):
    return make_params("music_stand", rng, size, style, [BLACK, DARK_METAL, BLACK, METAL] + wood_tones(style)[:1],
                       [BLACK], ["#f4f1e8"], tilt=float(rng.uniform(0.25, 0.45)), sheet=bool(rng.random() < 0.6))


def build_music_stand(p):
    """A music stand facing +y (its front): a tripod of thin legs, a pole and a desk tilted back with
    a ledge for the music along its bottom edge (a sheet on it, sometimes)."""
    w, d, h = p.size
    b = Builder()
    foot = min(w, d) * 0.45
    for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3):
        b.rod((0, 0, 0.22 * h), (foot * np.cos(a), foot * np.sin(a), 0.0), 0.008, p.primary, sections=6)
    desk_h = min(0.36, 0.3 * h)
    z0 = h - desk_h * np.cos(p.tilt)
    b.rod((0, 0, 0.0), (0, 0, z0 + 0.02), 0.011, p.primary, sections=8)
    tilt = move((0, 0, z0)) @ rot_x(p.tilt)  # the desk leans back, away from the player at +y
    dw = min(w, 0.5)
    b.box((-dw / 2, -0.006, 0.0), (dw / 2, 0.006, desk_h), p.primary, transform=tilt)
    b.box((-dw / 2, 0.0, -0.01), (dw / 2, 0.05, 0.012), p.primary, transform=tilt)  # the ledge
    if p.sheet:
        b.box((-dw * 0.42, 0.006, 0.012), (dw * 0.42, 0.012, desk_h * 0.92), p.accent, transform=tilt)
    return b.mesh(p.size)


# ----------------------------------------------------------------- stage platform
def sample_stage_platform(rng, size, style):
    return make_params("stage_platform", rng, size, style,
                       ["#2b2b2b", "#3a3b3e", *wood_tones(style)[:2]], ["#1c1c1e", "#5a1f2b", "#2a2a44"], METAL,
                       steps_side=int(rng.choice([-1, 1])), edge=bool(rng.random() < 0.6))


def build_stage_platform(p):
    """A low deck with a pleated skirt and steps at one end of the back half."""
    w, d, h = p.size
    b = Builder()
    n_steps = max(1, int(round(h / 0.2)) - 1)
    tread = min(0.3, 0.25 * w / n_steps)
    run = n_steps * tread
    sx = p.steps_side
    x_deck0, x_deck1 = (-w / 2, w / 2 - run) if sx > 0 else (-w / 2 + run, w / 2)
    deck = 0.05
    b.box((x_deck0, -d / 2, h - deck), (x_deck1, d / 2, h), p.primary)
    skirt = 0.012  # pleats stand flush with the deck edge, so no part hides under the deck
    b.box((x_deck0 + skirt, -d / 2 + skirt, 0), (x_deck1 - skirt, d / 2 - skirt, h - deck), p.secondary)
    if p.edge:
        b.box((x_deck0, d / 2 - 0.05, h - 0.002), (x_deck1, d / 2, h), tint("#e8e6e0", "paint"))
    pleat = 0.16
    fold = darker(p.secondary, 0.25)
    for i in range(int((x_deck1 - x_deck0) / pleat)):
        x = x_deck0 + (i + 0.5) * pleat
        b.box((x - 0.03, d / 2 - skirt, 0.01), (x + 0.03, d / 2, h - deck), fold)
    xs = x_deck1 if sx < 0 else x_deck0  # the open side, away from the steps
    for i in range(int(d / pleat)):
        y = -d / 2 + (i + 0.5) * pleat
        b.box((min(xs, xs - sx * skirt), y - 0.03, 0.01), (max(xs, xs - sx * skirt), y + 0.03, h - deck), fold)
    sw = min(1.2, 0.45 * d)
    y0 = -d / 2 + 0.1 * d
    for k in range(n_steps):
        z = (k + 1) * h / (n_steps + 1)
        xe = x_deck1 + (n_steps - k) * tread if sx > 0 else x_deck0 - (n_steps - k) * tread
        lo, hi = sorted((x_deck1 if sx > 0 else x_deck0, xe))
        b.box((lo, y0, 0), (hi, y0 + sw, z), p.primary if k % 2 else lighter(p.primary, 0.06))
    return b.mesh(p.size)


slot_roles("microphone", "metal", "metal", "metal")
register("microphone", sample_microphone, build_microphone)
slot_roles("speaker", "wood", "fabric", "metal")
register("speaker", sample_speaker, build_speaker)
slot_roles("drum_kit", "paint", "plastic", "metal")
register("drum_kit", sample_drum_kit, build_drum_kit)
slot_roles("guitar", "wood", "wood", "metal")
register("guitar", sample_guitar, build_guitar)
slot_roles("music_stand", "metal", "metal", "paper")
register("music_stand", sample_music_stand, build_music_stand)
slot_roles("stage_platform", "wood", "fabric", "metal")
register("stage_platform", sample_stage_platform, build_stage_platform)
