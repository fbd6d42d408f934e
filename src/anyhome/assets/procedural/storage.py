"""Case furniture: nightstand, dresser, cabinet, wardrobe, tv_stand, bookshelf, shelf,
display_case, wine_rack, toy_box, box."""

from __future__ import annotations

import numpy as np

from anyhome.assets.procedural._parts import (
    BLACK,
    GLASS,
    METAL,
    Builder,
    Params,
    darker,
    leg_style,
    lighter,
    make_params,
    slot_roles,
    tint,
    wood_tones,
)
from anyhome.assets.registry import register

BOOK_COLORS = tint(["#8b2e2e", "#2e4a8b", "#2f6b45", "#c8a24a", "#5a3a6e", "#d9d2c0", "#1f1f22",
               "#b5562d", "#3f6f7a", "#7a1f3d"], "paper")
HANDLE = tint("#b9b3a6", "metal")


def case(b: Builder, w: float, d: float, h: float, p: Params, rows: list[tuple[str, int]],
         base: str = "plinth", base_h: float = 0.08, top_overhang: float = 0.0) -> None:
    """A carcass with fronts: ``rows`` from bottom to top, each ("drawers"|"doors"|"open", n)."""
    if base == "legs":
        b.legs([(x, y) for x in (-w / 2 + 0.04, w / 2 - 0.04) for y in (-d / 2 + 0.04, d / 2 - 0.06)],
               0, base_h, 0.025, p.legs, p.primary)
    else:
        b.box((-w / 2 + 0.03, -d / 2 + 0.02, 0), (w / 2 - 0.03, d / 2 - 0.05, base_h), darker(p.primary, 0.3))
    top_t = min(0.03, h * 0.05)
    b.box((-w / 2, -d / 2, base_h), (w / 2, d / 2 - 0.02, h - top_t), p.primary)
    b.box((-w / 2 - top_overhang, -d / 2, h - top_t), (w / 2 + top_overhang, d / 2, h), darker(p.primary, 0.08))
    total = sum(1.0 if k != "drawers" else 0.7 for k, _ in rows)
    z = base_h + 0.01
    span = h - top_t - base_h - 0.02
    fy = d / 2 - 0.02
    gap = 0.006
    for kind, n in rows:
        rh = span * (1.0 if kind != "drawers" else 0.7) / total
        cw = (w - 0.04) / n
        for i in range(n):
            x0 = -w / 2 + 0.02 + i * cw
            if kind == "open":
                b.box((x0 + 0.02, fy - 0.01, z + 0.02), (x0 + cw - 0.02, fy + 0.001, z + rh - 0.02), tint("#2a2522", "paint"))
                continue
            b.box((x0 + gap, fy, z + gap), (x0 + cw - gap, fy + 0.02, z + rh - gap), p.secondary)
            if kind == "drawers":
                b.box((x0 + cw / 2 - min(0.08, cw / 4), fy + 0.02, z + rh * 0.6 - 0.008),
                      (x0 + cw / 2 + min(0.08, cw / 4), fy + 0.035, z + rh * 0.6 + 0.008), p.accent)
            else:
                hx = x0 + cw - 0.04 if i % 2 == 0 else x0 + 0.04
                if n == 1:
                    hx = x0 + cw - 0.04
                b.box((hx - 0.008, fy + 0.02, z + rh * 0.45), (hx + 0.008, fy + 0.035, z + rh * 0.75), p.accent)
        z += rh


def _case_params(name: str, rng, size, style, **knobs) -> Params:
    wood = wood_tones(style)
    prim = wood[int(rng.integers(len(wood)))]
    sec = prim if rng.random() < 0.7 else lighter(prim, 0.5)
    return make_params(name, rng, size, style, prim, sec, [HANDLE, "#c9a54a", "#2b2b2b", METAL],
                       legs=leg_style(rng, style), **knobs)


def sample_nightstand(rng, size, style):
    return _case_params("nightstand", rng, size, style, drawers=int(rng.integers(1, 3)),
                        on_legs=bool(rng.random() < 0.5))


def build_nightstand(p):
    w, d, h = p.size
    b = Builder()
    rows = [("open", 1)] + [("drawers", 1)] * p.drawers
    case(b, w, d, h, p, rows, "legs" if p.on_legs else "plinth", 0.15 * h if p.on_legs else 0.05)
    return b.mesh(p.size)


def sample_dresser(rng, size, style):
    return _case_params("dresser", rng, size, style, drawer_rows=int(rng.integers(3, 5)),
                        on_legs=bool(rng.random() < 0.4))


def build_dresser(p):
    w, d, h = p.size
    b = Builder()
    cols = 2 if w > 0.9 else 1
    rows = [("drawers", cols)] * p.drawer_rows
    case(b, w, d, h, p, rows, "legs" if p.on_legs else "plinth", 0.12 * h if p.on_legs else 0.06, 0.01)
    return b.mesh(p.size)


def sample_cabinet(rng, size, style):
    return _case_params("cabinet", rng, size, style, top_drawers=bool(rng.random() < 0.5))


def build_cabinet(p):
    w, d, h = p.size
    b = Builder()
    n = max(1, min(4, int(round(w / 0.5))))
    rows = [("doors", n)] + ([("drawers", n)] if p.top_drawers and h > 0.6 else [])
    case(b, w, d, h, p, rows, "plinth", min(0.08, 0.1 * h), 0.01)
    return b.mesh(p.size)


def sample_wardrobe(rng, size, style):
    return _case_params("wardrobe", rng, size, style, cornice=bool(rng.random() < 0.5),
                        bottom_drawer=bool(rng.random() < 0.5))


def build_wardrobe(p):
    w, d, h = p.size
    b = Builder()
    n = max(2, min(4, int(round(w / 0.5))))
    rows = ([("drawers", max(1, n // 2))] if p.bottom_drawer else []) + [("doors", n), ("doors", n)]
    body_h = h - (0.05 if p.cornice else 0)
    case(b, w, d, body_h, p, rows, "plinth", 0.08)
    if p.cornice:
        b.box((-w / 2, -d / 2, body_h), (w / 2, d / 2, h), darker(p.primary, 0.1))
    return b.mesh(p.size)


def sample_tv_stand(rng, size, style):
    return _case_params("tv_stand", rng, size, style, on_legs=bool(rng.random() < 0.5))


def build_tv_stand(p):
    w, d, h = p.size
    b = Builder()
    n = max(2, min(4, int(round(w / 0.45))))
    base_h = 0.2 * h if p.on_legs else 0.04
    case(b, w, d, h, p, [("doors", n)], "legs" if p.on_legs else "plinth", base_h)
    # an open middle bay
    cw = (w - 0.04) / n
    if n >= 3:
        x0 = -w / 2 + 0.02 + cw * (n // 2)
        b.box((x0 + 0.01, d / 2 - 0.02, base_h + 0.02), (x0 + cw - 0.01, d / 2 + 0.001, h - 0.05), tint("#2a2522", "paint"))
        b.box((x0 + 0.1 * cw, d / 2 - 0.15, base_h + 0.03), (x0 + 0.9 * cw, d / 2 - 0.03, base_h + 0.09), BLACK)
    return b.mesh(p.size)


def _books(b: Builder, rng, x0: float, x1: float, y0: float, y1: float, z: float, hmax: float) -> None:
    x = x0
    while x < x1 - 0.02:
        t = float(rng.uniform(0.02, 0.05))
        if x + t > x1:
            break
        hb = hmax * float(rng.uniform(0.65, 0.95))
        if rng.random() < 0.08:  # a gap
            x += t * 2
            continue
        yb = y1 - (y1 - y0) * float(rng.uniform(0.7, 0.95))
        b.box((x, yb, z), (x + t, y1, z + hb), BOOK_COLORS[int(rng.integers(len(BOOK_COLORS)))])
        x += t + 0.002


def sample_bookshelf(rng, size, style):
    wood = wood_tones(style)
    return make_params("bookshelf", rng, size, style, wood, "#2a2522", HANDLE,
                       fill=float(rng.uniform(0.6, 1.0)))


def build_bookshelf(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    t = 0.025
    b.box((-w / 2, -d / 2, 0), (-w / 2 + t, d / 2, h), p.primary)
    b.box((w / 2 - t, -d / 2, 0), (w / 2, d / 2, h), p.primary)
    b.box((-w / 2, -d / 2, 0), (w / 2, -d / 2 + 0.01, h), darker(p.primary, 0.25))
    b.box((-w / 2 + t, -d / 2, 0), (w / 2 - t, d / 2, 0.07), darker(p.primary, 0.1))
    b.box((-w / 2, -d / 2, h - t), (w / 2, d / 2, h), p.primary)
    n = max(2, int(round((h - 0.1) / 0.35)))
    zs = np.linspace(0.07, h - t, n + 1)
    cols = max(1, int(round(w / 0.8)))
    for z in zs[1:-1]:
        b.box((-w / 2 + t, -d / 2, z - t / 2), (w / 2 - t, d / 2 - 0.005, z + t / 2), p.primary)
    for c in range(1, cols):
        x = -w / 2 + c * w / cols
        b.box((x - t / 2, -d / 2, 0.07), (x + t / 2, d / 2 - 0.005, h - t), p.primary)
    for z0, z1 in zip(zs[:-1], zs[1:], strict=True):
        for c in range(cols):
            xa = -w / 2 + t + c * (w - 2 * t) / cols + 0.01
            xb = xa + (w - 2 * t) / cols * p.fill - 0.02
            _books(b, rng, xa, xb, -d / 2 + 0.01, d / 2 - 0.02, z0 + t / 2, (z1 - z0) * 0.85)
    return b.mesh(p.size)


def sample_shelf(rng, size, style):
    return make_params("shelf", rng, size, style, wood_tones(style) + ["#f0ede6"], "#2a2522",
                       [METAL, "#2b2b2b"], boards=int(rng.integers(1, 4)))


def build_shelf(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    n = p.boards if h > 0.25 else 1
    zs = np.linspace(0, h, n + 1)[1:] if n > 1 else [h]
    for z in zs:
        t = min(0.025, h / 6)
        b.box((-w / 2, -d / 2, z - t), (w / 2, d / 2, z), p.primary)
        for x in (-w / 2 + 0.1 * w, w / 2 - 0.1 * w):
            b.box((x - 0.01, -d / 2, z - t - min(0.12, h / 3)), (x + 0.01, -d / 2 + 0.6 * d, z - t), p.accent)
        _books(b, rng, -w / 2 + 0.05, -w / 2 + 0.45 * w, -d / 2 + 0.01, d / 2 - 0.01, z,
               min(0.22, (h / n) * 0.8))
    return b.mesh(p.size)


def sample_display_case(rng, size, style):
    return make_params("display_case", rng, size, style, wood_tones(style) + ["#2b2b2b", "#e8e6e0"],
                       GLASS, ["#c9a54a", "#8b2e2e", "#2e4a8b", "#e0ddd5"])


def build_display_case(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    base = min(0.3 * h, 0.35)
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, base), p.primary)
    b.box((-w / 2, -d / 2, h - 0.05), (w / 2, d / 2, h), p.primary)
    for x in (-w / 2, w / 2 - 0.03):
        for y in (-d / 2, d / 2 - 0.03):
            b.box((x, y, base), (x + 0.03, y + 0.03, h), p.primary)
    b.box((-w / 2 + 0.01, -d / 2 + 0.01, base), (w / 2 - 0.01, d / 2 - 0.01, h - 0.05), p.secondary, alpha=90)
    n = max(1, int((h - base) / 0.4))
    for z in np.linspace(base, h - 0.05, n + 1)[:-1]:
        b.box((-w / 2 + 0.03, -d / 2 + 0.03, z), (w / 2 - 0.03, d / 2 - 0.03, z + 0.01), lighter(p.secondary, 0.3))
        for x in np.linspace(-w / 2 + 0.15, w / 2 - 0.15, max(1, int(w / 0.3))):
            r = float(rng.uniform(0.03, 0.06))
            c = p.accent if rng.random() < 0.5 else "#e0ddd5"
            if rng.random() < 0.5:
                b.cyl(x, 0, z + 0.01, z + 0.01 + r * 3, r, c, r_top=r * 0.6, role="ceramic")
            else:
                b.sphere((x, 0, z + 0.01 + r), r, c, role="ceramic")
    return b.mesh(p.size)


WINE_RACK_MAX_CELLS = 220
"""Most bottle cells in one wine rack (keeps a wall-sized rack under the triangle budget)."""


def sample_wine_rack(rng, size, style):
    return make_params("wine_rack", rng, size, style, wood_tones(style), "#27401f", "#6b1a2a")


def build_wine_rack(p):
    w, d, h = p.size
    b = Builder()
    rng = np.random.default_rng(p.seed)
    cell = max(0.11, float(np.sqrt(w * h / WINE_RACK_MAX_CELLS)))  # bigger cells in a huge rack
    cols = max(2, int(w / cell))
    rows = max(2, int(h / cell))
    for x in np.linspace(-w / 2, w / 2, cols + 1):
        b.box((x - 0.01, -d / 2, 0), (x + 0.01, d / 2, h), p.primary)
    for z in np.linspace(0, h, rows + 1):
        b.box((-w / 2, -d / 2, z - 0.01), (w / 2, d / 2, z + 0.01), p.primary)
    cw, rh = w / cols, h / rows
    r = min(cw, rh) * 0.38
    for i in range(cols):
        for j in range(rows):
            if rng.random() < 0.25:
                continue
            cx, cz = -w / 2 + (i + 0.5) * cw, (j + 0.5) * rh
            c = p.secondary if rng.random() < 0.7 else p.accent
            b.rod((cx, -d / 2 + 0.02, cz), (cx, d / 2 - 0.12, cz), r, c, sections=10)
            b.rod((cx, d / 2 - 0.12, cz), (cx, d / 2, cz), r * 0.35, c, sections=8)
    return b.mesh(p.size)


def sample_toy_box(rng, size, style):
    return make_params("toy_box", rng, size, style, ["#e8c65a", "#7fb3d5", "#e58f8f", "#93c47d", "#f2efe8"],
                       "#f2efe8", ["#e05a47", "#3f7fbf", "#f2c12e", "#5aa75a"])


def build_toy_box(p):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2 + 0.01, -d / 2 + 0.01, 0), (w / 2 - 0.01, d / 2 - 0.01, h * 0.85), p.primary)
    b.box((-w / 2, -d / 2, h * 0.85), (w / 2, d / 2, h * 0.95), p.secondary)
    for i, c in enumerate((p.accent, "#3f7fbf", "#5aa75a")):
        b.box((-w / 2 + 0.1 + i * 0.12, -d / 2 + 0.1, h * 0.95), (-w / 2 + 0.2 + i * 0.12, -d / 2 + 0.2, h), c, role="plastic")
    b.box((-w / 2 + 0.02, d / 2 - 0.01, h * 0.2), (w / 2 - 0.02, d / 2, h * 0.3), p.accent)
    b.box((-0.06, d / 2 - 0.01, h * 0.6), (0.06, d / 2 + 0.01, h * 0.7), darker(p.primary, 0.3))
    return b.mesh(p.size)


def sample_box(rng, size, style):
    return make_params("box", rng, size, style, ["#c49a66", "#b5875a", "#d7b98c", "#e8e6e0", "#6f7a86"],
                       "#d9cfa8", "#8a6a44")


def build_box(p):
    w, d, h = p.size
    b = Builder()
    b.box((-w / 2, -d / 2, 0), (w / 2, d / 2, h * 0.97), p.primary)
    b.box((-0.03 * w, -d / 2, h * 0.97), (0.03 * w, d / 2, h), p.secondary)  # tape
    b.box((-w / 2, -0.004, h * 0.97), (w / 2, 0.004, h * 0.98), darker(p.primary, 0.3))
    b.box((-w * 0.3, d / 2, h * 0.55), (w * 0.3, d / 2 + 0.002, h * 0.75), lighter(p.primary, 0.6))  # label
    return b.mesh(p.size)


slot_roles("nightstand", "wood", "wood", "metal")
register("nightstand", sample_nightstand, build_nightstand)
slot_roles("dresser", "wood", "wood", "metal")
register("dresser", sample_dresser, build_dresser)
slot_roles("cabinet", "wood", "wood", "metal")
register("cabinet", sample_cabinet, build_cabinet)
slot_roles("wardrobe", "wood", "wood", "metal")
register("wardrobe", sample_wardrobe, build_wardrobe)
slot_roles("tv_stand", "wood", "wood", "metal")
register("tv_stand", sample_tv_stand, build_tv_stand)
slot_roles("bookshelf", "wood", "paper", "metal")
register("bookshelf", sample_bookshelf, build_bookshelf)
slot_roles("shelf", "wood", "paper", "metal")
register("shelf", sample_shelf, build_shelf)
slot_roles("display_case", "wood", "glass", {"": "paint", "#c9a54a": "metal"})
register("display_case", sample_display_case, build_display_case)
slot_roles("wine_rack", "wood", "glass", "glass")
register("wine_rack", sample_wine_rack, build_wine_rack)
slot_roles("toy_box", "paint", "paint", "paint")
register("toy_box", sample_toy_box, build_toy_box)
slot_roles("box", "paper", "paper", "paper")
register("box", sample_box, build_box)
