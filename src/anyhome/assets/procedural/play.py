"""Play and lounging: doll_house, play_tent, ball_pit, climbing_frame, playground_slide,
sandbox, hammock, bean_bag."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._kit import (
    CHROME,
    disc_y,
    extrude_y,
    path,
)
from anyhome.assets.procedural._parts import (
    BLACK,
    METAL,
    Builder,
    about,
    darker,
    fabric_tones,
    lengthwise,
    lighter,
    make_params,
    rot_x,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

TOY = tint(["#e05a47", "#f1c40f", "#2e86c1", "#27ae60", "#8e44ad", "#f08a2a", "#ec7fa9", "#4ab0c0"], "plastic")
PASTELS = tint(["#f4c6d0", "#c6e0f4", "#f4ecc6", "#d0f0d8", "#e8d8f4", "#f4f1ea"], "paint")
SAND = tint("#e6cf98", "stone")


# ----------------------------------------------------------------- doll house
def sample_doll_house(rng, size, style):
    return make_params("doll_house", rng, size, style, PASTELS + ["#e8e6e0"], ["#c0392b", "#8a5a6a", "#5f6b7a",
                                                                             "#3f6b4a"], wood_tones(style),
                       floors=3 if size[2] > 3 * size[1] and rng.random() < 0.5 else 2)


def build_doll_house(p):
    """An open-fronted doll's house: rooms on two or three floors with wallpaper and tiny
    furniture, windows in the side walls, a gabled roof with a round attic window."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    eave = 0.7 * h
    t = 0.03 * min(w, d) + 0.005
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, 0.04 * h), darker(p.primary, 0.25))
    b.box((-w / 2 + t, -d / 2, 0.04 * h), (w / 2 - t, -d / 2 + t, eave), p.primary)
    for x in (-w / 2, w / 2 - t):
        b.box((x, -d / 2, 0.04 * h), (x + t, d / 2, eave), p.primary)
        for k in range(p.floors):  # side windows
            z = 0.04 * h + (k + 0.35) * (eave - 0.04 * h) / p.floors
            b.box((x - 0.002, -0.15 * d, z), (x + t + 0.002, 0.15 * d, z + 0.35 * (eave - 0.04 * h) / p.floors),
                  tint("#9ac4e0", "paint"))
    n = p.floors
    fh = (eave - 0.04 * h) / n
    for k in range(n):
        z0 = 0.04 * h + k * fh
        if k:
            b.box((-w / 2 + t, -d / 2 + t, z0 - 0.015), (w / 2 - t, d / 2, z0), p.accent)
        b.box((-0.01, -d / 2 + t, z0), (0.01, 0.2 * d, z0 + fh - 0.015), p.primary)  # partition
        for side in (-1, 1):  # wallpaper and a piece of furniture in each room
            x0, x1 = (-w / 2 + t, -0.01) if side < 0 else (0.01, w / 2 - t)
            b.box((x0, -d / 2 + t, z0), (x1, -d / 2 + t + 0.003, z0 + fh - 0.015),
                  PASTELS[int(rng.integers(len(PASTELS)))])
            b.box((x0, -d / 2 + t, z0), (x1, d / 2, z0 + 0.004), lighter(p.accent, 0.2))
            cx = (x0 + x1) / 2
            kind = int(rng.integers(4))
            col = TOY[int(rng.integers(len(TOY)))]
            fw = 0.6 * (x1 - x0)
            if kind == 0:  # bed
                b.box((cx - fw / 2, -d / 2 + t, z0), (cx + fw / 2, -d / 2 + t + 0.5 * d, z0 + 0.18 * fh), tint("#f4f1ea", "paint"))
                b.box((cx - fw / 2, -d / 2 + t + 0.15 * d, z0 + 0.18 * fh), (cx + fw / 2, -d / 2 + t + 0.5 * d,
                                                                             z0 + 0.2 * fh), col)
            elif kind == 1:  # table with a lamp
                b.box((cx - fw / 3, -0.1 * d, z0 + 0.25 * fh), (cx + fw / 3, 0.15 * d, z0 + 0.28 * fh), p.accent)
                b.box((cx - 0.005, 0.0, z0), (cx + 0.005, 0.01, z0 + 0.25 * fh), p.accent)
                b.cyl(cx, 0.02, z0 + 0.28 * fh, z0 + 0.45 * fh, 0.02, col, r_top=0.01, sections=8)
            elif kind == 2:  # sofa
                b.box((cx - fw / 2, -d / 2 + t, z0), (cx + fw / 2, -d / 2 + t + 0.25 * d, z0 + 0.15 * fh), col)
                b.box((cx - fw / 2, -d / 2 + t, z0), (cx + fw / 2, -d / 2 + t + 0.08 * d, z0 + 0.3 * fh), col)
            else:  # bathtub or stove
                b.box((cx - fw / 2, -d / 2 + t, z0), (cx + fw / 2, -0.05 * d, z0 + 0.2 * fh), tint("#f4f4f2", "paint"))
                b.box((cx - fw / 2 + 0.01, -d / 2 + t + 0.01, z0 + 0.2 * fh), (cx + fw / 2 - 0.01, -0.06 * d,
                                                                              z0 + 0.205 * fh), tint("#9ac4e0", "paint"))
    b.box((-w / 2 + t, -d / 2 + t, eave - 0.015), (w / 2 - t, d / 2, eave), p.accent)
    apex = h - 0.02 * h
    over = 0.04 * w
    gable = [(-w / 2 + t, eave), (w / 2 - t, eave), (0.0, apex - 0.06 * h)]
    extrude_y(b, gable, -d / 2, d / 2 - 0.02 * d, p.primary)
    disc_y(b, 0, d / 2 - 0.02 * d, d / 2 - 0.015 * d, eave + 0.3 * (apex - eave), 0.12 * (apex - eave), tint("#9ac4e0", "paint"),
           sections=14)
    for s in (-1, 1):  # roof slabs
        b.hull([(s * (w / 2 + over), -d / 2, eave - 0.03 * h), (s * (w / 2 + over), d / 2, eave - 0.03 * h),
                (0, -d / 2, apex), (0, d / 2, apex), (s * (w / 2 + over), -d / 2, eave - 0.01 * h),
                (s * (w / 2 + over), d / 2, eave - 0.01 * h), (0, -d / 2, h), (0, d / 2, h)], p.secondary)
    b.box((0.2 * w, -0.2 * d, eave + 0.4 * (h - eave)), (0.3 * w, 0.0, h), darker(p.secondary, 0.2))  # chimney
    return b.mesh(p.size)


# ----------------------------------------------------------------- play tent
def sample_play_tent(rng, size, style):
    return make_params("play_tent", rng, size, style, ["#f4f1ea", "#e8dcc0", "#f4c6d0", "#c6e0f4", "#d0e8d0"],
                       TOY + ["#5f6b7a"], wood_tones("modern")[:3], poles=int(rng.integers(4, 7)))


def build_play_tent(p):
    """A teepee: poles crossing above a six-sided canvas cone, the door flaps tied back
    over a dark opening, and bunting across the front."""
    w, d, h = p.size
    b = Builder()
    R = 0.45 * min(w, d)
    top = 0.82 * h
    sx, sy = w / 2 / R * 0.98, d / 2 / R * 0.98
    scale = np.diag([sx, sy, 1.0, 1.0])
    b.cyl(0, 0, 0, top, R, p.primary, r_top=0.08 * R, sections=6, transform=scale)
    c30 = np.cos(np.pi / 6)

    def face(z: float, out: float = 0.0) -> float:  # y of the front face at height z
        return (R * (1 - 0.92 * z / top) * c30 + out) * sy

    dz = 0.55 * top
    half = 0.32 * R * sx
    b.hull([(-half, face(0, 0.004), 0.0), (half, face(0, 0.004), 0.0), (0.0, face(dz, 0.004), dz),
            (-half, face(0, -0.01), 0.0), (half, face(0, -0.01), 0.0), (0.0, face(dz, -0.01), dz)], tint("#3a3230", "paint"))
    for s in (-1, 1):  # flaps tied back
        b.hull([(s * half, face(0, 0.006), 0.0), (s * 1.3 * half, face(0, 0.006), 0.0),
                (s * 0.05 * half, face(dz, 0.006), dz), (s * half, face(0, 0.012), 0.0),
                (s * 1.3 * half, face(0, 0.012), 0.0), (s * 0.05 * half, face(dz, 0.012), dz)],
               lighter(p.primary, 0.4) if p.primary != tint("#f4f1ea", "paint") else tint("#e8dcc0", "paint"))
    for k in range(p.poles):
        a = 2 * np.pi * k / p.poles + 0.3
        foot = (0.95 * R * np.cos(a) * sx, 0.95 * R * np.sin(a) * sy, 0.0)
        tip = (-0.15 * R * np.cos(a) * sx, -0.15 * R * np.sin(a) * sy, h)
        b.rod(foot, tip, 0.015, p.accent, sections=6)
    n = 7
    for k in range(n):  # bunting on the front
        t0 = k / n
        x = -0.5 * R * sx + t0 * R * sx
        z = 0.72 * top - 0.05 * top * np.sin(np.pi * t0)
        b.hull([(x, face(z, o), z) for o in (0.008, 0.014)] + [(x + 0.12 * R * sx, face(z, o), z) for o in (0.008, 0.014)]
               + [(x + 0.06 * R * sx, face(z - 0.08 * top, o), z - 0.08 * top) for o in (0.008, 0.014)],
               TOY[k % len(TOY)])
    return b.mesh(p.size)


# ----------------------------------------------------------------- ball pit
def sample_ball_pit(rng, size, style):
    return make_params("ball_pit", rng, size, style, ["#2e86c1", "#e8e6e0", "#f08a2a", "#27ae60", "#ec7fa9"],
                       ["#f1c40f", "#e8e6e0", "#2e86c1"], TOY[0], shape=str(rng.choice(["square", "round"])))


def build_ball_pit(p):
    """A padded pool brim-full of coloured plastic balls (square or round)."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = 0.09 * min(w, d)
    fill = 0.78 * h
    if p.shape == "round":
        R = min(w, d) / 2
        sc = np.diag([w / 2 / R, d / 2 / R, 1.0, 1.0])
        b.lathe([[R - t, 0], [R, 0], [R, h - 0.04 * h], [R - 0.02, h], [R - t + 0.02, h], [R - t, h - 0.04 * h]],
                p.primary, sections=32, transform=sc)
        b.torus((0, 0, 0.5 * h), R + 0.003, 0.02 * h, p.secondary, transform=sc, sections=32, minor_sections=4)
        b.cyl(0, 0, 0, fill - 0.05 * h, R - t, darker(TOY[2], 0.2), sections=24, transform=sc)

        def inside(x: float, y: float) -> bool:
            return (x / (w / 2 - t)) ** 2 + (y / (d / 2 - t)) ** 2 < 0.9

    else:
        for i, (lo, hi) in enumerate((((-w / 2, -d / 2), (w / 2, -d / 2 + t)), ((-w / 2, d / 2 - t), (w / 2, d / 2)),
                                      ((-w / 2, -d / 2), (-w / 2 + t, d / 2)), ((w / 2 - t, -d / 2), (w / 2, d / 2)))):
            b.box((lo[0], lo[1], 0), (hi[0], hi[1], h - 0.04 * h), p.primary if i % 2 == 0 else p.secondary)
            if hi[0] - lo[0] > hi[1] - lo[1]:
                b.rod((lo[0], (lo[1] + hi[1]) / 2, h - 0.04 * h), (hi[0], (lo[1] + hi[1]) / 2, h - 0.04 * h),
                      0.04 * h, p.primary if i % 2 == 0 else p.secondary, sections=8)
            else:
                b.rod(((lo[0] + hi[0]) / 2, lo[1], h - 0.04 * h), ((lo[0] + hi[0]) / 2, hi[1], h - 0.04 * h),
                      0.04 * h, p.primary if i % 2 == 0 else p.secondary, sections=8)
        b.box((-w / 2 + t, -d / 2 + t, 0), (w / 2 - t, d / 2 - t, fill - 0.05 * h), darker(TOY[2], 0.2))

        def inside(x: float, y: float) -> bool:
            return abs(x) < w / 2 - t and abs(y) < d / 2 - t

    n = 13
    r = min((w - 2 * t) / (2 * n), (d - 2 * t) / (2 * n), 0.12 * h)
    for i in range(n):
        for j in range(n):
            x = -w / 2 + t + (i + 0.5) * (w - 2 * t) / n + rng.uniform(-0.3, 0.3) * r
            y = -d / 2 + t + (j + 0.5) * (d - 2 * t) / n + rng.uniform(-0.3, 0.3) * r
            if not inside(x, y):
                continue
            b.sphere((x, y, fill - r * rng.uniform(0.4, 1.2)), r, TOY[int(rng.integers(len(TOY)))], subdivisions=0)
    return b.mesh(p.size)


# ----------------------------------------------------------------- climbing frame
def sample_climbing_frame(rng, size, style):
    return make_params("climbing_frame", rng, size, style, ["#27ae60", "#2e86c1", "#e05a47", "#f1c40f"] +
                       wood_tones("rustic")[:2], ["#f1c40f", "#e05a47", "#2e86c1"], ["#f08a2a", "#e05a47", "#27ae60"],
                       roof=bool(rng.random() < 0.6))


def build_climbing_frame(p):
    """A jungle gym: a two-bay pipe frame with monkey bars over one bay, a deck with a
    little roof in the other, climbing rungs at the end and a slide off the front."""
    w, d, h = p.size
    b = Builder()
    r = min(0.03, 0.02 * w)
    xs = (-0.46 * w, -0.02 * w, 0.46 * w)
    ys = (-0.4 * d, 0.1 * d)
    top = 0.78 * h if p.roof else h - r
    for x in xs:
        for y in ys:
            b.cyl(x, y, 0, top, r, p.primary, sections=8)
    for y in ys:
        b.rod((xs[0], y, top - r), (xs[2], y, top - r), r, p.secondary, sections=8)
    for x in xs:
        b.rod((x, ys[0], top - r), (x, ys[1], top - r), r, p.secondary, sections=8)
    for k in range(1, 7):  # monkey bars
        x = xs[0] + k * (xs[1] - xs[0]) / 7
        b.rod((x, ys[0], top - r), (x, ys[1], top - r), 0.7 * r, CHROME, sections=6)
    for k in range(1, 6):  # rungs at the left end
        z = k * (top - r) / 6
        b.rod((xs[0], ys[0], z), (xs[0], ys[1], z), 0.7 * r, p.secondary, sections=6)
    deck = 0.45 * h
    b.box((xs[1], ys[0], deck - 0.04), (xs[2], ys[1], deck), p.accent)
    for x in (xs[1], xs[2]):  # guard rails on the deck
        b.rod((x, ys[0], deck + 0.35 * (top - deck)), (x, ys[1], deck + 0.35 * (top - deck)), 0.7 * r, p.secondary,
              sections=6)
    if p.roof:
        b.hull([(xs[1] - 0.03, ys[0] - 0.05, top), (xs[2] + 0.03, ys[0] - 0.05, top),
                (xs[1] - 0.03, ys[1] + 0.05, top), (xs[2] + 0.03, ys[1] + 0.05, top),
                ((xs[1] + xs[2]) / 2, ys[0] - 0.05, h), ((xs[1] + xs[2]) / 2, ys[1] + 0.05, h)], p.secondary)
    sx0, sx1 = xs[1] + 0.1 * w, xs[2] - 0.1 * w
    pts = [(ys[1], deck), (0.3 * d, 0.55 * deck), (d / 2 - 0.08 * d, 0.12 * deck), (d / 2, 0.1 * deck)]
    for (y0, z0), (y1, z1) in zip(pts[:-1], pts[1:], strict=True):  # the slide chute
        b.hull([(sx0, y0, z0), (sx1, y0, z0), (sx0, y1, z1), (sx1, y1, z1), (sx0, y0, z0 - 0.03),
                (sx1, y0, z0 - 0.03), (sx0, y1, z1 - 0.03), (sx1, y1, z1 - 0.03)], p.accent)
        for x in (sx0, sx1):
            b.hull([(x - 0.015, y0, z0), (x + 0.015, y0, z0), (x - 0.015, y1, z1), (x + 0.015, y1, z1),
                    (x - 0.015, y0, z0 + 0.1), (x + 0.015, y0, z0 + 0.1), (x - 0.015, y1, z1 + 0.1),
                    (x + 0.015, y1, z1 + 0.1)], darker(p.accent, 0.1))
    b.cyl((sx0 + sx1) / 2 - 0.1, d / 2 - 0.1 * d, 0, 0.1 * deck, 0.02, METAL, sections=6)
    return b.mesh(p.size)


# ----------------------------------------------------------------- playground slide
def sample_playground_slide(rng, size, style):
    return make_params("playground_slide", rng, size, style, TOY[:6], ["#2e86c1", "#27ae60", "#e8e6e0", METAL],
                       ["#f1c40f", "#e05a47"], wavy=bool(rng.random() < 0.4))


def build_playground_slide(p):
    """A freestanding slide along y: a ladder at the back up to a small platform with
    hand loops, and the chute curving down to the front."""
    w, d, h = p.size
    b = Builder()
    plat_z = 0.72 * h
    py0, py1 = -d / 2 + 0.12 * d, -d / 2 + 0.26 * d
    cw = 0.75 * w
    for x in (-w / 2 + 0.03, w / 2 - 0.03):  # ladder rails
        b.rod((x, -d / 2, 0.0), (x, py0, plat_z), 0.02, p.secondary, sections=8)
        b.rod((x, py0, 0.0), (x, py0, h - 0.02), 0.02, p.secondary, sections=8)
        path(b, [(x, py0, h - 0.02), (x, py1 - 0.02, h - 0.02), (x, py1, plat_z)], 0.018, p.accent, sections=6)
    n = max(3, int(plat_z / 0.25))
    for k in range(1, n):
        t = k / n
        y = -d / 2 + t * (py0 + d / 2)
        b.box((-w / 2 + 0.04, y - 0.04, t * plat_z - 0.015), (w / 2 - 0.04, y + 0.04, t * plat_z), p.secondary)
    b.box((-w / 2 + 0.02, py0, plat_z - 0.04), (w / 2 - 0.02, py1, plat_z), p.primary)  # platform
    b.cyl(0, py1 + 0.05, 0, plat_z - 0.05, 0.02, p.secondary, sections=6)
    m = 12
    pts = []
    for k in range(m + 1):
        t = k / m
        y = py1 + t * (d / 2 - py1)
        z = plat_z * (1 - t) ** 1.4 if t < 0.9 else plat_z * 0.1 ** 1.4 * 0.6
        if p.wavy:
            z += 0.05 * h * np.sin(3 * np.pi * t) * (1 - t)
        pts.append((y, max(0.05 * h, z)))
    for (y0, z0), (y1, z1) in zip(pts[:-1], pts[1:], strict=True):
        b.hull([(-cw / 2, y0, z0), (cw / 2, y0, z0), (-cw / 2, y1, z1), (cw / 2, y1, z1), (-cw / 2, y0, z0 - 0.03),
                (cw / 2, y0, z0 - 0.03), (-cw / 2, y1, z1 - 0.03), (cw / 2, y1, z1 - 0.03)], p.primary)
        for s in (-1, 1):
            x = s * cw / 2
            b.hull([(x - 0.02, y0, z0 - 0.02), (x + 0.02, y0, z0 - 0.02), (x - 0.02, y1, z1 - 0.02),
                    (x + 0.02, y1, z1 - 0.02), (x - 0.02, y0, z0 + 0.1), (x + 0.02, y0, z0 + 0.1),
                    (x - 0.02, y1, z1 + 0.1), (x + 0.02, y1, z1 + 0.1)], darker(p.primary, 0.12))
    b.box((-cw / 2, d / 2 - 0.05, 0), (cw / 2, d / 2 - 0.02, pts[-1][1] - 0.03), p.secondary)
    return b.mesh(p.size)


# ----------------------------------------------------------------- sandbox
def sample_sandbox(rng, size, style):
    return make_params("sandbox", rng, size, style, wood_tones("rustic") + ["#3f8a4a", "#2e86c1"], SAND, TOY,
                       seats=bool(rng.random() < 0.7))


def build_sandbox(p):
    """A wooden sandbox: a board frame with corner seats, heaped sand, a bucket, a spade
    and a little sand castle."""
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = 0.06 * min(w, d)
    for lo, hi in (((-w / 2, -d / 2), (w / 2, -d / 2 + t)), ((-w / 2, d / 2 - t), (w / 2, d / 2)),
                   ((-w / 2, -d / 2), (-w / 2 + t, d / 2)), ((w / 2 - t, -d / 2), (w / 2, d / 2))):
        b.box((lo[0], lo[1], 0), (hi[0], hi[1], 0.92 * h), p.primary)
        b.box((lo[0], lo[1], 0.45 * h), (hi[0], hi[1], 0.47 * h), darker(p.primary, 0.15))
    if p.seats:
        s = 0.22 * min(w, d)
        for sx in (-1, 1):
            for sy in (-1, 1):
                cx, cy = sx * w / 2, sy * d / 2
                b.hull([(cx, cy, 0.92 * h), (cx - sx * s, cy, 0.92 * h), (cx, cy - sy * s, 0.92 * h),
                        (cx, cy, h), (cx - sx * s, cy, h), (cx, cy - sy * s, h)], lighter(p.primary, 0.1))
    b.box((-w / 2 + t, -d / 2 + t, 0), (w / 2 - t, d / 2 - t, 0.65 * h), p.secondary)
    for _ in range(4):  # mounds
        x, y = rng.uniform(-0.3, 0.3) * w, rng.uniform(-0.3, 0.3) * d
        b.sphere((x, y, 0.65 * h), (0.15 * w, 0.12 * d, 0.12 * h), darker(p.secondary, 0.05), subdivisions=1)
    bx, by = 0.22 * w, 0.15 * d
    c1, c2 = TOY[int(rng.integers(len(TOY)))], TOY[int(rng.integers(len(TOY)))]
    rb = min(0.07, 0.06 * w)
    b.cyl(bx, by, 0.65 * h, 0.65 * h + 1.2 * rb, 0.75 * rb, c1, r_top=rb, sections=12)  # bucket
    path(b, [(bx - rb, by, 0.65 * h + 1.2 * rb), (bx, by, 0.65 * h + 1.9 * rb), (bx + rb, by, 0.65 * h + 1.2 * rb)],
         0.004, c1, sections=4)
    b.rod((-0.2 * w, 0.2 * d, 0.67 * h), (-0.05 * w, 0.05 * d, 0.7 * h), 0.01, c2, sections=6)  # spade
    b.box((-0.25 * w, 0.22 * d, 0.65 * h), (-0.17 * w, 0.28 * d, 0.68 * h), c2)
    cx, cy = -0.15 * w, -0.18 * d  # castle
    b.cyl(cx, cy, 0.65 * h, 0.65 * h + 0.08, 0.08, darker(p.secondary, 0.1), r_top=0.07, sections=10)
    b.cyl(cx, cy, 0.65 * h + 0.08, 0.65 * h + 0.14, 0.05, darker(p.secondary, 0.1), r_top=0.035, sections=10)
    return b.mesh(p.size)


# ----------------------------------------------------------------- hammock
def sample_hammock(rng, size, style):
    return make_params("hammock", rng, size, style, wood_tones(style) + [BLACK, "#3a3b3e"], fabric_tones(style) + TOY[:4],
                       ["#f4f1ea", "#e8dcc0"], stripes=bool(rng.random() < 0.6))


def _draw_hammock(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x: an arched stand, the striped sling sagging between its hooks on spreader
    bars and ropes."""
    r = min(0.04, 0.05 * B)
    arch = []
    for t in np.linspace(-1, 1, 11):  # the stand: low in the middle, rising to the hooks
        x = t * 0.47 * L
        z = 0.06 * H + (H - 0.08 * H) * abs(t) ** 2.2
        arch.append((x, 0.0, z))
    for (a, c) in zip(arch[:-1], arch[1:], strict=True):
        b.hull([(a[0], -r, a[2] - r), (a[0], r, a[2] - r), (a[0], -r, a[2] + r), (a[0], r, a[2] + r),
                (c[0], -r, c[2] - r), (c[0], r, c[2] - r), (c[0], -r, c[2] + r), (c[0], r, c[2] + r)], p.primary)
    for x in (-0.25 * L, 0.25 * L):
        b.box((x - r, -B / 2, 0), (x + r, B / 2, 0.06 * H), p.primary)
    hz = H - 0.05 * H
    hx = 0.45 * L
    sb = 0.36 * L
    bw = 0.75 * B
    nx, ny = 12, 6
    low = 0.35 * H
    for i in range(nx):
        for j in range(ny):
            pts = []
            for ii in (i, i + 1):
                for jj in (j, j + 1):
                    u = -1 + 2 * ii / nx
                    v = -1 + 2 * jj / ny
                    x = u * sb
                    z = low + (hz - 0.25 * H - low) * u ** 2 + 0.08 * H * v ** 2 * (1 - 0.5 * u ** 2)
                    y = v * bw / 2 * (0.75 + 0.25 * (1 - u ** 2))
                    pts += [(x, y, z), (x, y, z - 0.015)]
            col = p.secondary if (not p.stripes or j % 2 == 0) else p.accent
            b.hull(pts, col)
    zb = hz - 0.25 * H + 0.08 * H
    for s in (-1, 1):
        b.rod((s * sb, -bw / 2 - 0.03, zb), (s * sb, bw / 2 + 0.03, zb), 0.015, p.primary, sections=6)
        for y in np.linspace(-bw / 2, bw / 2, 5):
            b.rod((s * sb, y, zb), (s * hx, 0, hz), 0.004, tint("#e8dcc0", "paint"), sections=4)
        b.sphere((s * hx, 0, hz), 0.02, METAL, subdivisions=0)


def build_hammock(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_hammock(b, L, B, H, p))


# ----------------------------------------------------------------- bean bag
def sample_bean_bag(rng, size, style):
    return make_params("bean_bag", rng, size, style, fabric_tones(style) + TOY[:5], BLACK, "#7a7a7a",
                       slouch=float(rng.uniform(0.0, 1.0)))


def build_bean_bag(p):
    """A bean bag chair: a squat, bulging sack with a raised back lump and a seat hollow
    in front, a seam round its belly."""
    w, d, h = p.size
    b = Builder()
    R = 0.5 * min(w, d)
    lean = 0.3 * d  # the top slumps back, leaving a sloping seat at the front
    shear = np.array([[w / 2 / R * 0.82, 0, 0, 0], [0, d / 2 / R * 0.75, -lean / h, 0.12 * d], [0, 0, 1, 0],
                      [0, 0, 0, 1.0]])
    top = h * (1 - 0.1 * p.slouch)
    b.lathe([[0, 0], [0.85 * R, 0], [R, 0.12 * top], [0.98 * R, 0.3 * top], [0.82 * R, 0.55 * top],
             [0.55 * R, 0.8 * top], [0.25 * R, 0.96 * top], [0, top]], p.primary, sections=32, transform=shear)
    seat = about(rot_x(-0.7), (0, 0.1 * d, 0.5 * h))
    b.sphere((0, 0.1 * d, 0.5 * h), (0.34 * w, 0.28 * d, 0.05 * h), darker(p.primary, 0.25), subdivisions=2,
             transform=seat)  # seat hollow
    b.torus((0, 0, 0.2 * top), R * 0.99, 0.008, darker(p.primary, 0.3), transform=shear, sections=32,
            minor_sections=4)
    return b.mesh(p.size)


slot_roles("doll_house", "paint", "paint", "wood")
register("doll_house", sample_doll_house, build_doll_house)
slot_roles("play_tent", "fabric", "fabric", "wood")
register("play_tent", sample_play_tent, build_play_tent)
slot_roles("ball_pit", "fabric", "plastic", "plastic")
register("ball_pit", sample_ball_pit, build_ball_pit)
slot_roles("climbing_frame", "plastic", "plastic", "plastic")
register("climbing_frame", sample_climbing_frame, build_climbing_frame)
slot_roles("playground_slide", "plastic", {"": "plastic", METAL: "metal"}, "plastic")
register("playground_slide", sample_playground_slide, build_playground_slide)
slot_roles("sandbox", "wood", "stone", "plastic")
register("sandbox", sample_sandbox, build_sandbox)
slot_roles("hammock", "wood", "fabric", "fabric")
register("hammock", sample_hammock, build_hammock)
slot_roles("bean_bag", "fabric", "plastic", "plastic")
register("bean_bag", sample_bean_bag, build_bean_bag)
