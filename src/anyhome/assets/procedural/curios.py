"""Study and museum pieces: telescope, globe, dinosaur_skeleton."""

from __future__ import annotations

import numpy as np

from anyhome.assets.colors import to_rgba
from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    lengthwise,
    make_params,
    move,
    rot_x,
    slot_roles,
    style_is,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

BRASS = tint("#c9a54a", "metal")
BONE = tint("#e6dcc4", "stone")
OCEANS = tint(["#3a6fa0", "#4f86b0", "#d9c9a0"], "paper")
LAND = tint(["#6b8f4e", "#c9a56a", "#8a6a3a"], "paper")


# ----------------------------------------------------------------- telescope
def sample_telescope(rng, size, style):
    antique = style_is(style, "antique")
    return make_params("telescope", rng, size, style, [BRASS] if antique else ["#e8e6e0", BLACK, "#2d4f8a", BRASS],
                       wood_tones(style) if antique or rng.random() < 0.3 else [DARK_METAL, METAL], BLACK,
                       tilt=float(rng.uniform(0.55, 0.85)))


def build_telescope(p):
    """A tube on a tripod, pointing up towards +x; the eyepiece low at the back."""
    w, d, h = p.size
    b = Builder()
    a = p.tilt  # elevation of the tube in radians
    axis = np.array([np.cos(a), 0.0, np.sin(a)])
    length = min(0.95 * w / max(np.cos(a), 0.3), 1.6 * h)
    mount = np.array([0.0, 0.0, h - 0.5 * length * np.sin(a) - 0.05])
    R = min(w, d) / 2
    for i in range(3):  # tripod
        ang = 2 * np.pi * i / 3 - np.pi / 2
        b.rod(mount - (0, 0, 0.06), (0.95 * R * np.cos(ang), 0.95 * R * np.sin(ang), 0.0), 0.016, p.secondary,
              sections=6)
    b.cyl(0, 0, 0.35 * mount[2], 0.35 * mount[2] + 0.02, 0.3 * R, p.secondary, sections=3)  # spreader tray
    b.cbox(mount - (0, 0, 0.05), (0.08, 0.08, 0.08), DARK_METAL)
    r = min(0.07, 0.12 * length)
    back = mount - axis * 0.4 * length
    front = mount + axis * 0.6 * length
    b.rod(back, front, r, p.primary, sections=16)
    b.rod(front - axis * 0.15 * length, front, r * 1.25, p.primary, sections=16)  # dew shield
    b.rod(front - axis * 0.005, front, r * 1.15, tint("#1c2430", "paint"), sections=16)
    b.rod(back - axis * 0.03, back, r * 0.7, p.accent, sections=12)
    b.rod(back, back + (0, 0, 0.08), 0.012, p.accent, sections=8)  # diagonal + eyepiece
    b.rod(back + (0, 0, 0.08), back + (-0.02, 0, 0.12), 0.018, p.accent, sections=8)
    finder = mount + axis * 0.1 * length + np.array([-np.sin(a), 0, np.cos(a)]) * (r + 0.03)
    b.rod(finder - axis * 0.1, finder + axis * 0.12, 0.015, p.accent, sections=8)
    for t in (-0.15, 0.15):  # tube rings
        c = mount + axis * t * length
        b.rod(c - axis * 0.015, c + axis * 0.015, r * 1.1, DARK_METAL, sections=16)
    return b.mesh(p.size)


# ----------------------------------------------------------------- globe
def sample_globe(rng, size, style):
    antique = style_is(style, "antique")
    return make_params("globe", rng, size, style, wood_tones(style), OCEANS[2] if antique else OCEANS[:2],
                       LAND[1] if antique else LAND[0], floor=bool(size[2] > 1.5 * min(size[0], size[1])))


def build_globe(p):
    """A globe in a meridian ring, tilted 23 degrees, on a floor stand or a desk foot."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    R = min(w, d) / 2 * 0.85
    cz = h - R - 0.03
    if p.floor:
        for i in range(3):
            ang = 2 * np.pi * i / 3 + np.pi / 2
            b.rod((0.3 * R * np.cos(ang), 0.3 * R * np.sin(ang), 0.55 * cz),
                  (1.1 * R * np.cos(ang), 1.1 * R * np.sin(ang), 0.0), 0.02, p.primary, sections=8)
        b.torus((0, 0, cz - 0.35 * R), 1.02 * R, 0.02, p.primary, sections=28, minor_sections=4)  # horizon ring
        b.cyl(0, 0, 0.15 * cz, cz - 0.9 * R, 0.025, p.primary, sections=10)
        b.sphere((0, 0, 0.5 * cz), (0.06, 0.06, 0.05), p.primary)
    else:
        b.cyl(0, 0, 0, 0.04, 0.6 * R, p.primary, r_top=0.5 * R, sections=20)
        b.cyl(0, 0, 0.04, cz - 0.9 * R, 0.02, p.primary, sections=10)
    import trimesh

    sph = trimesh.creation.icosphere(subdivisions=3, radius=R)
    v = np.asarray(sph.vertices)
    u = v / R
    field = np.zeros(len(v))
    for _ in range(7):  # continents: a few smooth bumps on the sphere
        c = rng.normal(size=3)
        c /= np.linalg.norm(c)
        field += np.exp((u @ c - 1) * rng.uniform(4, 9))
    land = field > np.quantile(field, 0.68)
    colors = np.where(land[:, None], to_rgba(p.accent), to_rgba(p.secondary))
    tilt = move((0, 0, cz)) @ rot_x(0.41)
    b.add_colored(v @ tilt[:3, :3].T + tilt[:3, 3], sph.faces, colors, role="paper")
    b.torus((0, 0, 0), R * 1.06, 0.012, BRASS, transform=tilt @ rot_x(np.pi / 2) @ np.eye(4), sections=32,
            minor_sections=4)  # meridian
    b.rod(tilt[:3, :3] @ (0, 0, -1.1 * R) + tilt[:3, 3], tilt[:3, :3] @ (0, 0, 1.1 * R) + tilt[:3, 3], 0.01, BRASS,
          sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- dinosaur skeleton
def sample_dinosaur_skeleton(rng, size, style):
    return make_params("dinosaur_skeleton", rng, size, style, [BONE, "#d9c9a8", "#c9b48e"], DARK_METAL,
                       "#3a3530", kind=str(rng.choice(["theropod", "sauropod"])),
                       ribs=int(rng.integers(7, 11)))


def _spine(kind: str, L: float, H: float) -> np.ndarray:
    """Points of the backbone from the tail tip (x = -L/2) to the skull (x = +L/2)."""
    t = np.linspace(0, 1, 34)
    x = -L / 2 + t * L
    if kind == "sauropod":  # long tail low, back high, long neck up
        z = H * (0.25 + 0.35 * np.sin(np.clip(t * 1.6, 0, np.pi)) ** 0.8 + 0.35 * np.clip((t - 0.65) / 0.35, 0, 1) ** 1.5)
        z[-1] = z[-2] + 0.02 * H
    else:  # theropod: tail out straight, hips high, a short S neck
        z = H * (0.35 + 0.3 * np.sin(np.clip(t, 0, 0.8) / 0.8 * np.pi * 0.5) ** 0.6
                 - 0.1 * np.clip((t - 0.8) / 0.2, 0, 1) ** 2)
    return np.column_stack([x, np.zeros_like(x), z])


def _leg(b: Builder, hip, foot_x: float, B: float, color: str, thick: float, side: int) -> None:
    hip = np.asarray(hip, dtype=float)
    knee = np.array([hip[0] + 0.12 * thick * 10, side * B * 0.32, 0.55 * hip[2]])
    ankle = np.array([foot_x - 0.05, side * B * 0.3, 0.14 * hip[2]])
    b.rod(hip + (0, side * B * 0.2, 0), knee, thick, color, sections=8)
    b.rod(knee, ankle, thick * 0.8, color, sections=8)
    b.rod(ankle, (foot_x + 0.25 * thick * 10, side * B * 0.3, 0.02), thick * 0.6, color, sections=6)
    b.sphere(knee, thick * 1.3, color, subdivisions=0)


def _draw_dinosaur(b: Builder, L: float, B: float, H: float, p) -> None:
    rng = np.random.default_rng(p.seed)
    base_h = 0.04 * H
    b.box((-L / 2, -B / 2, 0), (L / 2, B / 2, base_h), p.accent)  # plinth
    sp = _spine(p.kind, L, H - base_h) + np.array([0, 0, base_h])
    s = L / 60
    for k in range(len(sp) - 1):  # vertebrae, thicker over the body
        t = k / (len(sp) - 1)
        body = np.exp(-((t - 0.45) / 0.22) ** 2)
        r = s * (0.5 + 1.3 * body)
        b.sphere(sp[k], (r, r * 0.9, r * 1.1), p.primary, subdivisions=0)
        b.rod(sp[k], sp[k + 1], r * 0.45, p.primary, sections=6)
        if 0.25 < t < 0.7:  # neural spines
            b.rod(sp[k], sp[k] + (0, 0, 2.2 * r), r * 0.25, p.primary, sections=4)
    hip_i, chest_i = int(0.42 * len(sp)), int(0.62 * len(sp))
    ribs = p.ribs
    for j in range(ribs):  # ribs: arcs hanging from the back to either side
        i = hip_i + int((chest_i - hip_i) * j / max(1, ribs - 1))
        top = sp[i]
        depth = (0.25 + 0.35 * np.sin(np.pi * (j + 1) / (ribs + 1))) * (top[2] - base_h) * 0.75
        for side in (-1, 1):
            pts = [top + (0, side * 0.35 * B * np.sin(a), -depth * (1 - np.cos(a))) for a in np.linspace(0, np.pi * 0.55, 4)]
            for q0, q1 in zip(pts[:-1], pts[1:], strict=True):
                b.rod(q0, q1, s * 0.22, p.primary, sections=4)
    head = sp[-1]
    hl = (0.1 if p.kind == "theropod" else 0.05) * L
    hh = (0.09 if p.kind == "theropod" else 0.04) * L
    b.hull([head + (-0.2 * hl, -0.3 * hh, -0.3 * hh), head + (-0.2 * hl, 0.3 * hh, -0.3 * hh),
            head + (-0.2 * hl, -0.3 * hh, 0.5 * hh), head + (-0.2 * hl, 0.3 * hh, 0.5 * hh),
            head + (hl, -0.15 * hh, 0.0), head + (hl, 0.15 * hh, 0.0), head + (0.7 * hl, 0, 0.3 * hh)], p.primary)
    b.hull([head + (-0.1 * hl, -0.25 * hh, -0.45 * hh), head + (-0.1 * hl, 0.25 * hh, -0.45 * hh),
            head + (0.9 * hl, -0.1 * hh, -0.75 * hh), head + (0.9 * hl, 0.1 * hh, -0.75 * hh),
            head + (0.2 * hl, 0, -0.35 * hh)], p.primary)  # open jaw
    b.sphere(head + (0.15 * hl, 0.2 * hh, 0.15 * hh), 0.12 * hh, tint("#2a2520", "paint"), subdivisions=0)
    hip = sp[hip_i]
    thick = s * (1.3 if p.kind == "sauropod" else 1.0)
    for side in (-1, 1):
        _leg(b, hip, hip[0] + rng.uniform(-0.02, 0.06) * L * side, B, p.primary, thick, side)
        chest = sp[chest_i]
        if p.kind == "sauropod":
            _leg(b, chest, chest[0] + 0.03 * L * side, B, p.primary, thick, side)
        else:  # small arms
            elbow = chest + (0.04 * L, side * 0.2 * B, -0.12 * (chest[2] - base_h))
            b.rod(chest + (0, side * 0.1 * B, -0.05 * H), elbow, s * 0.35, p.primary, sections=4)
            b.rod(elbow, elbow + (0.05 * L, 0, 0.03 * H), s * 0.3, p.primary, sections=4)
    for q in (hip, sp[chest_i], sp[int(0.2 * len(sp))]):  # armature posts
        b.rod((q[0], 0, base_h), q - (0, 0, s), s * 0.25, p.secondary, sections=6)


def build_dinosaur_skeleton(p):
    """A stylised skeleton on a low plinth, along the longer side of the box, head at +x."""
    return lengthwise(p.size, lambda b, L, B, H: _draw_dinosaur(b, L, B, H, p))


slot_roles("telescope", {"": "paint", BRASS: "metal"}, {"": "wood", DARK_METAL: "metal", METAL: "metal"}, "plastic")
register("telescope", sample_telescope, build_telescope)
slot_roles("globe", "wood", "paper", "paper")
register("globe", sample_globe, build_globe)
slot_roles("dinosaur_skeleton", "stone", "metal", "stone")
register("dinosaur_skeleton", sample_dinosaur_skeleton, build_dinosaur_skeleton)
