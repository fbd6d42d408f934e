"""Render every procedural asset family into one labelled contact sheet.

    .venv/bin/python benchmarks/contact_sheet.py [--out benchmarks/contact_sheet.png]
        [--seed 0] [--style ""] [--tile 128] [--only FAMILY ...]

Each family is built at its typical size (seed 0, no style) and drawn in a 3/4 view
(from the front, +y, and the +x side, above) by a small software rasteriser: triangles
are projected orthographically and filled with Pillow polygons back to front (painter's
algorithm: whole parts ordered by their bounding boxes, then faces by depth), shaded
with a two-sided Lambert term over the mean vertex colour of each face; see-through
faces (glass, water) are alpha-blended. No GPU, no moderngl.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from anyhome.assets import FAMILIES
from anyhome.assets.registry import get, typical_size

OUT = Path(__file__).with_name("contact_sheet.png")
COLUMNS = 10
"""Tiles per row of the sheet."""
SUPERSAMPLE = 3
"""Each tile is drawn this many times larger, then downsampled (cheap antialiasing)."""
VIEW_DIR = np.array([0.75, 1.0, 0.75])
"""Direction from the object towards the camera: front (+y), right (+x), above."""
LIGHT_DIR = np.array([-0.35, 0.8, 1.0])
"""Direction towards the light (upper left of the front)."""
AMBIENT = 0.38
"""Share of light that reaches faces turned away from the light."""
LABEL_PX = 14
"""Height of the name strip at the bottom of a tile, in output pixels."""
BACKGROUND = (236, 238, 241)
LABEL_BG = (255, 255, 255)
SEPARATION_EPS_M = 1e-4
"""Parts whose boxes touch within this distance count as separated (a plinth under a body)."""
MAX_SORTED_PARTS = 2000
"""Above this many parts, parts are simply sorted by their farthest corner."""


def _camera() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit vectors (right, up, towards camera) of the orthographic view."""
    v = VIEW_DIR / np.linalg.norm(VIEW_DIR)
    right = np.cross([0.0, 0.0, 1.0], v)
    right /= np.linalg.norm(right)
    up = np.cross(v, right)
    return right, up, v


def part_order(lo: np.ndarray, hi: np.ndarray, towards: np.ndarray) -> list[int]:
    """Parts far to near, from their bounding boxes ``lo``, ``hi`` : (n, 3) float.

    Newell-style: when the boxes of two parts are separated along an axis, the part on
    the camera's side of the gap is drawn later; the remaining freedom (and any cycle)
    is settled by the depth of each box's farthest corner.
    """
    import heapq

    n = len(lo)
    key = np.minimum(lo * towards, hi * towards).sum(axis=1)
    if n > MAX_SORTED_PARTS:
        return [int(i) for i in np.argsort(key)]
    # after[i, j]: part j lies wholly on the camera side of part i along some axis
    gap = np.where(towards > 0, lo[None, :, :] - hi[:, None, :], lo[:, None, :] - hi[None, :, :])
    after = ((gap >= -SEPARATION_EPS_M) & (np.abs(towards) > 1e-9)).any(axis=2)
    np.fill_diagonal(after, False)
    conflict = after & after.T
    after &= ~conflict
    indegree = after.sum(axis=0)
    heap = [(key[i], i) for i in range(n) if indegree[i] == 0]
    heapq.heapify(heap)
    done = np.zeros(n, dtype=bool)
    order: list[int] = []
    while len(order) < n:
        if not heap:  # a cycle: release the farthest part left
            i = int(np.argmin(np.where(done, np.inf, key)))
            indegree[i] = 0
            heap.append((key[i], i))
        _, i = heapq.heappop(heap)
        if done[i]:
            continue
        done[i] = True
        order.append(i)
        for j in np.flatnonzero(after[i]):
            indegree[j] -= 1
            if indegree[j] == 0 and not done[j]:
                heapq.heappush(heap, (key[j], j))
    return order


def draw_order(mesh, towards: np.ndarray) -> np.ndarray:
    """Face indices in drawing order for the painter's algorithm.

    A procedural mesh is a set of separate closed parts (boxes, cylinders, lathes), so
    whole parts are ordered (see :func:`part_order`); within a part, faces turned away
    from the camera come first, then the others far to near.
    """
    import trimesh

    faces = np.asarray(mesh.faces)
    labels = trimesh.graph.connected_component_labels(mesh.face_adjacency, node_count=len(faces))
    v = np.asarray(mesh.vertices, dtype=float)
    n = int(labels.max()) + 1 if len(labels) else 0
    lo = np.full((n, 3), np.inf)
    hi = np.full((n, 3), -np.inf)
    corners = v[faces].reshape(-1, 3)
    lab3 = np.repeat(labels, 3)
    np.minimum.at(lo, lab3, corners)
    np.maximum.at(hi, lab3, corners)
    rank = np.empty(n, dtype=int)
    rank[part_order(lo, hi, towards)] = np.arange(n)
    facing = np.asarray(mesh.face_normals) @ towards > 0
    face_depth = v[faces].mean(axis=1) @ towards
    return np.lexsort((face_depth, facing, rank[labels]))


def render_mesh(mesh, px: int) -> Image.Image:
    """The mesh drawn into a ``px`` x ``px`` RGB image, scaled to fit with a margin.

    Parameters
    ----------
    mesh : trimesh.Trimesh
        Vertex-coloured mesh.
    px : int
        Side of the square image in pixels.
    """
    right, up, towards = _camera()
    v = np.asarray(mesh.vertices, dtype=float)
    f = np.asarray(mesh.faces)
    sx, sy = v @ right, v @ up
    lo = np.array([sx.min(), sy.min()])
    span = max(sx.max() - lo[0], sy.max() - lo[1], 1e-9)
    margin = 0.07 * px
    scale = (px - 2 * margin) / span
    off = np.array([(px - (sx.max() - lo[0]) * scale) / 2, (px - (sy.max() - lo[1]) * scale) / 2])
    x = (sx - lo[0]) * scale + off[0]
    y = px - ((sy - lo[1]) * scale + off[1])

    normals = np.asarray(mesh.face_normals, dtype=float)
    normals = np.where((normals @ towards < 0)[:, None], -normals, normals)  # two-sided
    light = LIGHT_DIR / np.linalg.norm(LIGHT_DIR)
    shade = AMBIENT + (1 - AMBIENT) * np.clip(normals @ light, 0.0, 1.0)
    colors = np.asarray(mesh.visual.vertex_colors, dtype=float)[f].mean(axis=1)
    rgba = np.column_stack([colors[:, :3] * shade[:, None], colors[:, 3]])
    rgba = np.clip(np.round(rgba), 0, 255).astype(np.uint8)

    img = Image.new("RGB", (px, px), BACKGROUND)
    draw = ImageDraw.Draw(img, "RGBA")  # blends see-through faces (glass, water) over what is behind
    for i in draw_order(mesh, towards):
        a, b, c = f[i]
        draw.polygon([(x[a], y[a]), (x[b], y[b]), (x[c], y[c])], fill=tuple(int(k) for k in rgba[i]))
    return img


def _font(size: int) -> ImageFont.ImageFont:
    try:
        return ImageFont.load_default(size=size)
    except TypeError:  # Pillow < 10.1 has one bitmap size
        return ImageFont.load_default()


def tile(family: str, px: int, seed: int, style: str) -> Image.Image:
    """One labelled tile for a family built at its typical size."""
    fam = get(family)
    mesh = fam.build(fam.sample(np.random.default_rng(seed), typical_size(family), style))
    body = px - LABEL_PX
    img = render_mesh(mesh, body * SUPERSAMPLE).resize((body, body), Image.LANCZOS)
    out = Image.new("RGB", (px, px), LABEL_BG)
    out.paste(img, ((px - body) // 2, 0))
    draw = ImageDraw.Draw(out)
    font = _font(11)
    label = f"{family} ({len(mesh.faces)})"
    w = draw.textlength(label, font=font)
    if w > px - 2:
        label, w = family, draw.textlength(family, font=font)
    draw.text(((px - w) / 2, px - LABEL_PX), label, fill=(30, 30, 30), font=font)
    return out


def contact_sheet(families: list[str], px: int = 128, seed: int = 0, style: str = "") -> Image.Image:
    """Tiles of ``families`` in rows of ``COLUMNS``."""
    rows = math.ceil(len(families) / COLUMNS)
    sheet = Image.new("RGB", (COLUMNS * px, rows * px), (200, 200, 200))
    for k, name in enumerate(families):
        sheet.paste(tile(name, px, seed, style), ((k % COLUMNS) * px, (k // COLUMNS) * px))
    return sheet


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(OUT))
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--style", default="")
    ap.add_argument("--tile", type=int, default=128)
    ap.add_argument("--only", nargs="*", help="families to draw (default: all)")
    args = ap.parse_args(argv)
    names = args.only or list(FAMILIES)
    contact_sheet(names, args.tile, args.seed, args.style).save(args.out)
    print(f"{len(names)} families -> {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
