"""Things that move: kayak (also canoe), boat (a rowing boat or a small motor boat), car,
bicycle (also motorcycle)."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    DARK_METAL,
    METAL,
    Builder,
    darker,
    lengthwise,
    lighter,
    make_params,
    move,
    rot_x,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

CAR_PAINTS = tint(["#b8322a", "#2d4f8a", "#e8e6e0", "#2b2b2b", "#9a9da3", "#3f6b4a", "#d9a32a", "#5a6b7a"], "paint")
TYRE = tint("#1c1c1e", "rubber")


# ----------------------------------------------------------------- kayak / canoe / boat
def sample_kayak(rng, size, style):
    w, d, _ = size
    long_, broad = max(w, d), min(w, d)
    kind = "boat" if broad > 0.3 * long_ else str(rng.choice(["kayak", "kayak", "canoe"]))
    return make_params("kayak", rng, size, style,
                       ["#d9502a", "#e8c53a", "#2d6fa8", "#3f8a4a", "#b8322a", "#e8e6e0"],
                       wood_tones(style), [BLACK, "#2b2b2b"], kind=kind)


def _hull(b: Builder, L: float, B: float, H: float, color: str, inner: str | None = None) -> None:
    """Half of a cigar (its lower half) along x, the gunwale at height H; open on top."""
    n = 20
    t = np.linspace(-1, 1, n)
    r = np.sqrt(np.clip(1 - np.abs(t) ** 2.2, 0, 1))
    prof = np.column_stack([np.maximum(r, 1e-4), t * L / 2])
    prof[0, 0] = prof[-1, 0] = 0.0
    import trimesh

    m = trimesh.creation.revolve(prof, angle=np.pi, sections=12)
    v = np.asarray(m.vertices)
    # revolve axis z -> x; half-turn lies on y >= 0 -> downwards (z <= 0)
    out = np.column_stack([v[:, 2], v[:, 0] * B / 2, -v[:, 1] * H + H])
    b.add(out, m.faces[:, ::-1], color)  # the axis swap mirrors; flip faces to stay outward
    if inner is not None:
        inside = np.column_stack([v[:, 2] * 0.97, v[:, 0] * B / 2 * 0.93, -v[:, 1] * H * 0.93 + H])
        b.add(inside, m.faces, inner)


def _draw_kayak(b: Builder, L: float, B: float, H: float, p) -> None:
    if p.kind == "boat":
        hull_h = 0.55 * H
        _hull(b, L, B, hull_h, p.primary, p.secondary)
        b.cyl(0, 0, hull_h - 0.04, hull_h, L / 2 * 0.995, lighter(p.primary, 0.3), ry=B / 2 * 0.995, sections=28)
        b.box((-0.25 * L, -0.35 * B, hull_h - 0.05), (0.1 * L, 0.35 * B, 0.8 * H), tint("#e8e6e0", "paint"))  # cabin
        b.box((-0.27 * L, -0.37 * B, 0.8 * H), (0.12 * L, 0.37 * B, 0.85 * H), darker(p.primary, 0.1))
        b.box((0.1 * L, -0.3 * B, 0.62 * H), (0.101 * L + 0.01, 0.3 * B, 0.78 * H), tint("#4a6a80", "paint"))
        b.rod((0.0, 0, 0.85 * H), (0.0, 0, H), 0.02, METAL, sections=6)
        return
    hull_h = 0.75 * H
    if p.kind == "canoe":
        _hull(b, L, B, hull_h, p.primary, lighter(p.primary, 0.25))
        b.torus((0, 0, hull_h), 1.0, 0.02, darker(p.primary, 0.3), sections=40, minor_sections=4,
                transform=np.diag([L / 2 * 0.99, B / 2 * 0.99, 1.0, 1.0]))
        for x in (-0.28 * L, 0.0, 0.28 * L):  # seats and thwart
            bw = B * 0.92 * np.sqrt(max(0.0, 1 - (2 * x / L) ** 2))
            b.box((x - 0.06, -bw / 2, hull_h - 0.06), (x + 0.06, bw / 2, hull_h - 0.03), p.secondary)
        b.rod((-0.1 * L, -0.2 * B, hull_h + 0.02), (0.35 * L, 0.15 * B, hull_h - 0.02), 0.015, p.secondary,
              sections=6)
        b.cbox((0.35 * L, 0.15 * B, hull_h - 0.02), (0.14 * L * 0.5, 0.09, 0.015), p.secondary)
        return
    _hull(b, L, B, hull_h, p.primary)
    b.sphere((0, 0, hull_h), (L / 2 * 0.99, B / 2 * 0.99, H - hull_h), lighter(p.primary, 0.1), subdivisions=2)
    b.cyl(0.05 * L, 0, hull_h, H * 1.001, 0.16 * L, p.accent, ry=0.32 * B, sections=20)  # cockpit
    b.torus((0.05 * L, 0, H), 1.0, 0.015, BLACK, sections=24, minor_sections=4,
            transform=move((0.05 * L, 0, 0)) @ np.diag([0.16 * L, 0.32 * B, 1.0, 1.0])
            @ move((-0.05 * L, 0, 0)))
    for x in (-0.3 * L, 0.32 * L):  # deck lines
        b.rod((x, -0.3 * B, hull_h + 0.7 * (H - hull_h)), (x, 0.3 * B, hull_h + 0.7 * (H - hull_h)), 0.006, BLACK,
              sections=4)


def build_kayak(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_kayak(b, L, B, H, p))


# ----------------------------------------------------------------- boat
def sample_boat(rng, size, style):
    return make_params("boat", rng, size, style, ["#f4f1ea", "#2d6fa8", "#b8322a", "#3f8a4a", "#1f3a5a"],
                       wood_tones("rustic")[:3], ["#e8c53a", "#f4f1ea", "#b8322a"],
                       kind=str(rng.choice(["rowing", "rowing", "motor"])), oars=bool(rng.random() < 0.7))


def _draw_boat(b: Builder, L: float, B: float, H: float, p) -> None:
    """A boat along x, its bow at +x: an open rowing boat (a wooden hull lining, a
    transom at the stern, three thwarts, ``oars`` laid along it) or a small motor boat
    (a cabin, a windscreen and an outboard on the transom)."""
    hull_h = 0.7 * H if p.kind == "rowing" else 0.55 * H
    _hull(b, L, B, hull_h, p.primary, p.secondary)
    b.torus((0, 0, hull_h), 1.0, 0.025, p.accent, sections=40, minor_sections=4,
            transform=np.diag([L / 2 * 0.99, B / 2 * 0.99, 1.0, 1.0]))  # gunwale stripe
    r = float(np.sqrt(1 - 0.88**2.2))  # the hull's half-breadth (share) where the transom stands
    b.box((-0.45 * L, -0.45 * r * B, (1 - 0.85 * r) * hull_h), (-0.43 * L, 0.45 * r * B, hull_h),
          darker(p.primary, 0.1))  # transom
    if p.kind == "motor":
        b.box((-0.2 * L, -0.35 * B, hull_h - 0.05), (0.12 * L, 0.35 * B, 0.85 * H), tint("#e8e6e0", "paint"))
        b.box((0.12 * L, -0.32 * B, 0.7 * H), (0.13 * L, 0.32 * B, H), tint("#4a6a80", "glass"), alpha=200)
        b.box((-0.49 * L, -0.06 * B, 0.3 * hull_h), (-0.45 * L, 0.06 * B, hull_h + 0.15 * H), DARK_METAL)  # outboard
        return
    for x in (-0.25 * L, 0.0, 0.25 * L):  # thwarts
        bw = B * 0.92 * np.sqrt(max(0.0, 1 - (2 * x / L) ** 2))
        b.box((x - 0.07, -bw / 2, hull_h - 0.1 * H), (x + 0.07, bw / 2, hull_h - 0.05 * H), p.secondary)
    if p.oars:
        for sgn in (-1, 1):
            y = sgn * 0.22 * B
            b.rod((-0.35 * L, y, hull_h - 0.04 * H), (0.3 * L, y, hull_h - 0.02 * H), 0.02, p.secondary, sections=6)
            b.cbox((0.34 * L, y, hull_h - 0.02 * H), (0.05 * L, 0.06, 0.01), p.secondary)  # blade


def build_boat(p):
    return lengthwise(p.size, lambda b, L, B, H: _draw_boat(b, L, B, H, p))


# ----------------------------------------------------------------- car
def sample_car(rng, size, style):
    return make_params("car", rng, size, style, CAR_PAINTS, "#2a3440", METAL,
                       body=str(rng.choice(["sedan", "hatch", "suv"])))


def _draw_car(b: Builder, L: float, B: float, H: float, p) -> None:
    """Car along x, its nose at +x."""
    r = 0.23 * H if p.body != "suv" else 0.26 * H
    belt = 0.6 * H if p.body != "suv" else 0.62 * H
    sill = 0.28 * r
    b.box((-L / 2 + 0.04 * L, -B / 2 + 0.02, sill), (L / 2 - 0.04 * L, B / 2 - 0.02, belt), p.primary)
    for s in (-1, 1):  # rounded nose and tail
        b.rod((s * (L / 2 - 0.04 * L), -B / 2 + 0.03, (sill + belt) / 2 + 0.02),
              (s * (L / 2 - 0.04 * L), B / 2 - 0.03, (sill + belt) / 2 + 0.02), (belt - sill) / 2 - 0.02, p.primary,
              sections=16)
        b.box((s * L / 2 - 0.04 * L * (s > 0), -B / 2 + 0.05, sill + 0.02),
              (s * L / 2 + 0.04 * L * (s < 0), B / 2 - 0.05, sill + 0.12), darker(p.primary, 0.4))
    cab = {"sedan": (-0.3, 0.18, -0.22, 0.05), "hatch": (-0.42, 0.15, -0.4, 0.0),
           "suv": (-0.45, 0.2, -0.44, 0.08)}[p.body]
    x0, x1, t0, t1 = (c * L for c in cab)
    inset = 0.07 * B
    glass = [(x0, -B / 2 + 0.02, belt), (x1, -B / 2 + 0.02, belt), (x0, B / 2 - 0.02, belt), (x1, B / 2 - 0.02, belt),
             (t0, -B / 2 + inset, H - 0.03), (t1, -B / 2 + inset, H - 0.03), (t0, B / 2 - inset, H - 0.03),
             (t1, B / 2 - inset, H - 0.03)]
    b.hull(glass, p.secondary)
    b.box((t0 + 0.02, -B / 2 + inset + 0.01, H - 0.035), (t1 - 0.02, B / 2 - inset - 0.01, H), p.primary)
    xm = (t0 + t1) / 2 + 0.05 * L
    b.hull([(xm - 0.03, -B / 2 + 0.015, belt), (xm + 0.03, -B / 2 + 0.015, belt),
            (xm - 0.03, -B / 2 + inset - 0.005, H - 0.03), (xm + 0.03, -B / 2 + inset - 0.005, H - 0.03),
            (xm - 0.03, B / 2 - 0.015, belt), (xm + 0.03, B / 2 - 0.015, belt),
            (xm - 0.03, B / 2 - inset + 0.005, H - 0.03), (xm + 0.03, B / 2 - inset + 0.005, H - 0.03)], p.primary)
    for x in (-0.31 * L, 0.31 * L):
        for s in (-1, 1):
            y0, y1 = s * (B / 2 - 0.2 * B), s * B / 2
            b.rod((x, y0, r), (x, y1, r), r, TYRE, sections=18)
            b.rod((x, y1 - s * 0.005, r), (x, y1 + s * 0.002, r), 0.6 * r, p.accent, sections=12)
    for s in (-1, 1):
        b.box((L / 2 - 0.012, s * (B / 2 - 0.2 * B) - 0.1 * B, belt - 0.12 * H),
              (L / 2, s * (B / 2 - 0.2 * B) + 0.1 * B, belt - 0.04 * H), tint("#f4f1d8", "rubber"))
        b.box((-L / 2, s * (B / 2 - 0.15 * B) - 0.1 * B, belt - 0.1 * H),
              (-L / 2 + 0.012, s * (B / 2 - 0.15 * B) + 0.1 * B, belt - 0.03 * H), tint("#c0392b", "rubber"))
        b.box((x0 - 0.02 * L, s * B / 2 - 0.02, belt - 0.01), (x0 + 0.02, s * B / 2 + (0.0 if s > 0 else 0.0), belt + 0.05),
              p.primary)  # mirrors


def build_car(p):
    """A car; its nose points along the longer side of the box (+y when deeper than wide)."""
    return lengthwise(p.size, lambda b, L, B, H: _draw_car(b, L, B, H, p))


# ----------------------------------------------------------------- bicycle / motorcycle
def sample_bicycle(rng, size, style):
    w, d, _ = size
    motor = min(w, d) >= 0.7  # a wide box holds a motorcycle
    return make_params("bicycle", rng, size, style,
                       ["#b8322a", "#2d4f8a", BLACK, "#3f6b4a", "#e8e6e0", "#d9a32a", "#5a6b7a"], BLACK, METAL,
                       motor=bool(motor), basket=bool(not motor and rng.random() < 0.25))


def _wheel(b: Builder, x: float, z: float, r: float, tyre: float, rim: str, spokes: int) -> None:
    turn = rot_x(np.pi / 2)  # ring about the y axis... then about x: wheel plane x-z
    b.torus((0, 0, 0), r - tyre, tyre, TYRE, transform=move((x, 0, z)) @ turn, sections=28,
            minor_sections=5)
    b.torus((0, 0, 0), r - 2.2 * tyre, 0.3 * tyre + 0.004, rim, transform=move((x, 0, z)) @ turn,
            sections=24, minor_sections=4)
    for k in range(spokes):
        a = np.pi * k / spokes
        dx, dz = np.cos(a) * (r - 2 * tyre), np.sin(a) * (r - 2 * tyre)
        b.rod((x - dx, 0, z - dz), (x + dx, 0, z + dz), 0.003 + 0.2 * tyre * (spokes <= 6), rim, sections=4)


def _draw_bicycle(b: Builder, L: float, B: float, H: float, p) -> None:
    """Along x, front wheel at +x."""
    r = 0.36 * H if not p.motor else 0.3 * H
    tyre = 0.02 if not p.motor else 0.05
    xr, xf = -L / 2 + r, L / 2 - r
    _wheel(b, xr, r, r, tyre, p.accent, 8 if not p.motor else 5)
    _wheel(b, xf, r, r, tyre, p.accent, 8 if not p.motor else 5)
    fr = 0.018 if not p.motor else 0.03
    bb = (xr + 0.42 * (xf - xr), 0.0, 0.9 * r)  # bottom bracket
    seat = (xr + 0.3 * (xf - xr), 0.0, 0.78 * H)
    head = (xf - 0.12 * (xf - xr), 0.0, 0.8 * H)
    for a, c in ((bb, seat), (seat, head), (bb, (head[0] - 0.02, 0, head[2] - 0.1 * H)), ((xr, 0, r), bb),
                 ((xr, 0, r), (seat[0] + 0.02, 0, seat[2] - 0.05 * H)), (head, (xf, 0, r))):
        b.rod(a, c, fr, p.primary, sections=8)
    bar_w = B * 0.95
    b.rod((head[0] - 0.03, 0, head[2]), (head[0] - 0.05, 0, H - 0.03), fr, p.accent, sections=8)
    b.rod((head[0] - 0.08, -bar_w / 2, H - 0.03), (head[0] - 0.08, bar_w / 2, H - 0.03), 0.012 + fr * 0.3,
          p.accent, sections=8)
    for s in (-1, 1):
        b.rod((head[0] - 0.08, s * bar_w / 2 * 0.7, H - 0.03), (head[0] - 0.08, s * bar_w / 2, H - 0.03), 0.018,
              BLACK, sections=8)
    if p.motor:
        b.sphere(((seat[0] + head[0]) / 2, 0, 0.8 * H), (0.17 * (head[0] - seat[0]) + 0.08, 0.13, 0.08),
                 p.primary)  # tank
        b.box((bb[0] - 0.2, -0.13, 0.7 * r), (bb[0] + 0.15, 0.13, 1.55 * r), DARK_METAL)  # engine
        for k in range(3):  # cooling fins
            z = 0.9 * r + k * 0.2 * r
            b.box((bb[0] - 0.21, -0.14, z), (bb[0] + 0.16, 0.14, z + 0.03), METAL)
        b.rod((bb[0] + 0.1, 0.15, 0.8 * r), (xr - 0.2 * r, 0.15, 1.1 * r), 0.04, METAL, sections=10)  # exhaust
        b.box((seat[0] - 0.32, -0.13, 0.78 * H - 0.05), (seat[0] + 0.12, 0.13, 0.8 * H), BLACK)  # seat
        b.rod((head[0] + 0.02, 0, 0.8 * H), (head[0] + 0.1, 0, 0.8 * H), 0.07, tint("#f4f1d8", "paint"), sections=12)
        for x in (xr, xf):  # mudguards just over the tyres
            b.box((x - 0.45 * r, -0.07, 2 * r + 0.01), (x + 0.45 * r, 0.07, 2 * r + 0.03), p.primary)
        return
    b.sphere((seat[0] - 0.02, 0, seat[2] + 0.02), (0.11, 0.06, 0.025), p.secondary)  # saddle
    b.rod((bb[0], -0.1, bb[2]), (bb[0], 0.1, bb[2]), 0.02, p.secondary, sections=8)
    for s in (-1, 1):
        px = bb[0] + s * 0.14
        b.rod((bb[0], s * 0.09, bb[2]), (px, s * 0.09, bb[2] - s * 0.08), 0.012, METAL, sections=6)
        b.cbox((px, s * 0.12, bb[2] - s * 0.08), (0.08, 0.05, 0.02), BLACK)
    b.rod((bb[0], 0.03, bb[2]), (bb[0], 0.04, bb[2]), 0.09, METAL, sections=16)  # chainring
    if p.basket:
        b.box((xf - 0.14, -0.15, 0.72 * H), (xf + 0.14, 0.15, 0.88 * H), tint("#c9a06a", "paint"))


def build_bicycle(p):
    """A bicycle (or, in a wide box, a motorcycle) along the longer side of the box."""
    return lengthwise(p.size, lambda b, L, B, H: _draw_bicycle(b, L, B, H, p))


slot_roles("kayak", "plastic", "wood", "plastic")
register("kayak", sample_kayak, build_kayak)
slot_roles("boat", {"": "paint"}, "wood", "paint")
register("boat", sample_boat, build_boat)
slot_roles("car", "paint", "glass", "metal")
register("car", sample_car, build_car)
slot_roles("bicycle", "paint", "rubber", "metal")
register("bicycle", sample_bicycle, build_bicycle)
