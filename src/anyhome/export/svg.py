"""Top-down floorplan SVG: rooms, walls, doors, windows, object footprints, scale, north.

The SVG's y axis points down, so plan y is flipped (north is up on the page).

Every text that comes from the house (prompt, names, ids) is cleaned of characters XML
1.0 forbids and of terminal escapes (:func:`anyhome.sanitize.clean_text`), then escaped:
element text with :func:`_text_of`, attribute values (quotes included) with
:func:`_attr`, so a house.json cannot add elements or attributes to the drawing.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import numpy as np
from shapely.geometry import Point, Polygon
from shapely.ops import polylabel

from anyhome.export.output import write_file
from anyhome.export.walls import WALL_THICKNESS_M, solid_blocks, wall_pieces
from anyhome.geometry import footprint_corners
from anyhome.house import House
from anyhome.sanitize import clean_text

PX_PER_M = 60.0
"""Drawing scale."""
MARGIN_PX = 70.0
LABEL_MIN_AREA_M2 = 0.35
"""Objects with a footprint at least this large get a name label."""
ROOM_FILLS = {
    "bedroom": "#e8eefb", "bathroom": "#e3f4f6", "kitchen": "#fdf1de", "living_room": "#fbf3e4",
    "dining_room": "#f8ebe2", "hallway": "#eeeeee", "entry": "#eeeeee", "office": "#eef6e8",
    "study": "#eef6e8", "library": "#f1ece3", "playroom": "#fdeef4", "gym": "#eaf0f0",
    "laundry": "#e8f1f6", "storage": "#ececec", "closet": "#ececec", "garage": "#e6e6e6",
}
DEFAULT_FILL = "#f3f1ea"
WALL_COLOR = "#333333"
DOOR_COLOR = "#c0392b"
WINDOW_COLOR = "#2e86c1"
OBJECT_FILL = "#d9d2c5"
OPEN_AIR_COLOR = "#5b8a5b"
"""Outline and hatching of an open-air room (balcony, terrace, courtyard...)."""
RAILING_STROKE = 0.35
"""A parapet's line width, as a share of a wall's."""
OPEN_AIR_DEFS = (
    '<defs><pattern id="open-air-hatch" patternUnits="userSpaceOnUse" width="10" height="10" '
    'patternTransform="rotate(45)"><line x1="0" y1="0" x2="0" y2="10" '
    f'stroke="{OPEN_AIR_COLOR}" stroke-width="1" stroke-opacity="0.45"/></pattern></defs>'
)


class _Canvas:
    def __init__(self, house: House) -> None:
        pts = np.array([p for r in house.rooms for p in r.polygon], dtype=float).reshape(-1, 2)
        self.x0: float
        self.y0: float
        self.x1: float
        self.y1: float
        self.x0, self.y0 = pts.min(axis=0) if len(pts) else (0.0, 0.0)
        self.x1, self.y1 = pts.max(axis=0) if len(pts) else (1.0, 1.0)
        self.width = (self.x1 - self.x0) * PX_PER_M + 2 * MARGIN_PX
        self.height = (self.y1 - self.y0) * PX_PER_M + 2 * MARGIN_PX + 40

    def xy(self, x: float, y: float) -> tuple[float, float]:
        return ((x - self.x0) * PX_PER_M + MARGIN_PX, (self.y1 - y) * PX_PER_M + MARGIN_PX)

    def pts(self, points) -> str:
        return " ".join("{:.1f},{:.1f}".format(*self.xy(float(x), float(y))) for x, y in points)


def _text_of(s: str) -> str:
    """Element text: cleaned, with ``& < >`` escaped."""
    return escape(clean_text(s))


def _attr(s: str) -> str:
    """An attribute value, cleaned, escaped and quoted (``"..."`` included)."""
    return quoteattr(clean_text(s))


def _text(x: float, y: float, s: str, size: float, weight: str = "normal", fill: str = "#222") -> str:
    return (f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size:.1f}" font-weight="{weight}" fill="{fill}" '
            f'text-anchor="middle" dominant-baseline="middle">{_text_of(s)}</text>')


def render_svg(house: House) -> str:
    """The floorplan as SVG text."""
    c = _Canvas(house)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{c.width:.0f}" height="{c.height:.0f}" '
           f'viewBox="0 0 {c.width:.0f} {c.height:.0f}" font-family="Helvetica, Arial, sans-serif">',
           f'<title>{_text_of(house.prompt[:200])}</title>',
           f'<rect x="0" y="0" width="{c.width:.0f}" height="{c.height:.0f}" fill="white"/>']
    if any(r.open_air for r in house.rooms):
        out.append(OPEN_AIR_DEFS)
    out.append('<g id="rooms">')
    for room in house.rooms:
        fill = ROOM_FILLS.get(room.type, DEFAULT_FILL)
        out.append(f'<polygon id={_attr("room-" + room.id)} class="room" points="{c.pts(room.polygon)}" '
                   f'fill="{fill}" stroke="none"><title>{_text_of(room.name)}</title></polygon>')
        if room.open_air:  # hatched, with a dashed outline: open to the sky
            out.append(f'<polygon id={_attr("open-" + room.id)} class="open-air" points="{c.pts(room.polygon)}" '
                       f'fill="url(#open-air-hatch)" stroke="{OPEN_AIR_COLOR}" stroke-width="1.5" '
                       f'stroke-dasharray="6,4"/>')
    out.append('</g><g id="objects">')
    labels = []
    for obj in sorted(house.objects, key=lambda o: (o.support not in ("floor", "wall"), o.position[2])):
        corners = footprint_corners(obj.position, obj.size, obj.yaw)
        on_top = obj.support not in ("floor", "wall")
        style = 'fill="#c9bfae" fill-opacity="0.9"' if on_top else f'fill="{OBJECT_FILL}" fill-opacity="0.85"'
        if obj.category in ("rug", "carpet", "mat", "yoga_mat"):
            style = 'fill="#e0cdb0" fill-opacity="0.5"'
        out.append(f'<polygon class="object" id={_attr("object-" + obj.id)} points="{c.pts(corners)}" {style} '
                   f'stroke="#7a6f60" stroke-width="1"><title>{_text_of(obj.name)}</title></polygon>')
        front = (corners[2] + corners[3]) / 2
        ctr = corners.mean(axis=0)
        out.append(f'<line x1="{c.xy(*ctr)[0]:.1f}" y1="{c.xy(*ctr)[1]:.1f}" x2="{c.xy(*front)[0]:.1f}" '
                   f'y2="{c.xy(*front)[1]:.1f}" stroke="#7a6f60" stroke-width="0.8" stroke-dasharray="2,2"/>')
        if obj.size[0] * obj.size[1] >= LABEL_MIN_AREA_M2 and not on_top:
            x, y = c.xy(*ctr)
            labels.append(_text(x, y, obj.name[:18], 9, fill="#5a4f40"))
    out += labels
    out.append('</g><g id="walls">')
    stroke = WALL_THICKNESS_M * PX_PER_M
    for piece in wall_pieces(house):
        u = piece.direction
        spans = _floor_spans(piece)
        for t0, t1 in spans:
            a, b = piece.a + u * t0, piece.a + u * t1
            (ax, ay), (bx, by) = c.xy(*a), c.xy(*b)
            if piece.railing:  # a low parapet: a thin line, not a wall
                out.append(f'<line class="railing" x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" '
                           f'stroke="{WALL_COLOR}" stroke-width="{stroke * RAILING_STROKE:.1f}" '
                           f'stroke-linecap="square"/>')
                continue
            out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="{WALL_COLOR}" '
                       f'stroke-width="{stroke:.1f}" stroke-linecap="square"/>')
    out.append('</g><g id="openings">')
    out += _windows(house, c)
    out += _doors(house, c)
    out.append('</g><g id="labels">')
    for room in house.rooms:
        poly = Polygon(room.polygon)
        p = _label_point(poly, [o for o in house.objects if o.room == room.id])
        x, y = c.xy(p.x, p.y)
        out.append(_text(x, y - 8, room.name, 14, "bold"))
        area = f"{poly.area:.1f} m²"
        out.append(_text(x, y + 9, f"open · {area}" if room.open_air else area, 11, fill="#555"))
    out.append('</g>')
    out += _scale_and_north(c)
    out.append('</svg>')
    return "\n".join(out) + "\n"


def _label_point(poly: Polygon, objects) -> Point:
    """A point well inside the room and, if possible, off the furniture."""
    free = poly
    for o in objects:
        free = free.difference(Polygon(footprint_corners(o.position, o.size, o.yaw)).buffer(0.3))
    if not free.is_empty and free.area > 1.0:
        if free.geom_type == "MultiPolygon":
            free = max(free.geoms, key=lambda g: g.area)
        return polylabel(free, tolerance=0.05)
    return polylabel(poly, tolerance=0.05) if poly.is_valid else poly.representative_point()


def _floor_spans(piece) -> list[tuple[float, float]]:
    """Stretches of a wall piece that are solid at floor level (doors leave gaps)."""
    spans: list[tuple[float, float]] = []
    for t0, t1, z0, _ in solid_blocks(piece):
        if z0 > 1e-6:
            continue
        if spans and abs(spans[-1][1] - t0) < 1e-6:
            spans[-1] = (spans[-1][0], t1)
        else:
            spans.append((t0, t1))
    return spans


def _windows(house: House, c: _Canvas) -> list[str]:
    out = []
    for w in house.windows:
        a, b = (np.asarray(p, dtype=float) for p in w.segment)
        v = b - a
        n = np.array([-v[1], v[0]]) / max(np.linalg.norm(v), 1e-9) * WALL_THICKNESS_M * 0.3
        out.append(f'<polygon class="window" id={_attr("window-" + w.id)} '
                   f'points="{c.pts([a - n * 1.6, b - n * 1.6, b + n * 1.6, a + n * 1.6])}" fill="white" '
                   f'stroke="{WINDOW_COLOR}" stroke-width="1.2"/>')
        for s in (-1, 1):
            (x1, y1), (x2, y2) = c.xy(*(a + s * n)), c.xy(*(b + s * n))
            out.append(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="{WINDOW_COLOR}" '
                       f'stroke-width="1.5"/>')
    return out


def _doors(house: House, c: _Canvas) -> list[str]:
    out = []
    centroids = {r.id: np.array(Polygon(r.polygon).centroid.coords[0]) for r in house.rooms}
    for d in house.doors:
        a, b = (np.asarray(p, dtype=float) for p in d.segment)
        width = float(np.linalg.norm(b - a))
        if width < 1e-6:
            continue
        (ax, ay), (bx, by) = c.xy(*a), c.xy(*b)
        out.append(f'<line class="door" id={_attr("door-" + d.id)} x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" '
                   f'y2="{by:.1f}" stroke="{DOOR_COLOR}" stroke-width="2" stroke-dasharray="4,3"/>')
        if d.kind == "open":
            continue
        # the leaf swings into the first room that is not outside
        inside = next((r for r in d.rooms if r in centroids), None)
        u = (b - a) / width
        n = np.array([-u[1], u[0]])
        if inside is not None and (centroids[inside] - (a + b) / 2) @ n < 0:
            n = -n
        tip = a + n * width
        (tx, ty) = c.xy(*tip)
        r = width * PX_PER_M
        cross = (tip - a)[0] * (b - a)[1] - (tip - a)[1] * (b - a)[0]
        sweep = 1 if cross > 0 else 0  # page y is flipped
        out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{tx:.1f}" y2="{ty:.1f}" stroke="{DOOR_COLOR}" '
                   f'stroke-width="2"/>')
        out.append(f'<path d="M {tx:.1f} {ty:.1f} A {r:.1f} {r:.1f} 0 0 {sweep} {bx:.1f} {by:.1f}" fill="none" '
                   f'stroke="{DOOR_COLOR}" stroke-width="1" stroke-dasharray="3,2"/>')
    return out


def _scale_and_north(c: _Canvas) -> list[str]:
    span_m = max(1, int(math.floor((c.x1 - c.x0) / 4))) if c.x1 > c.x0 else 1
    x0, y0 = MARGIN_PX, c.height - 30
    out = ['<g id="scale">']
    for i in range(span_m):
        fill = "#333" if i % 2 == 0 else "white"
        out.append(f'<rect x="{x0 + i * PX_PER_M:.1f}" y="{y0:.1f}" width="{PX_PER_M:.1f}" height="6" '
                   f'fill="{fill}" stroke="#333" stroke-width="1"/>')
    out.append(_text(x0, y0 - 9, "0", 10))
    out.append(_text(x0 + span_m * PX_PER_M, y0 - 9, f"{span_m} m", 10))
    nx, ny = c.width - MARGIN_PX / 2 - 10, MARGIN_PX / 2 + 10
    out.append(f'<polygon id="north" points="{nx:.1f},{ny - 22:.1f} {nx - 8:.1f},{ny + 6:.1f} {nx:.1f},{ny:.1f} '
               f'{nx + 8:.1f},{ny + 6:.1f}" fill="#333"/>')
    out.append(_text(nx, ny + 18, "N", 12, "bold"))
    out.append('</g>')
    return out


def write_svg(house: House, path: str | os.PathLike[str]) -> Path:
    """Write a top-down floorplan SVG atomically; return its path."""
    path = Path(path)
    return write_file(path, render_svg(house).encode("utf-8"))


def level_svg_name(level: int) -> str:
    """``floorplan.svg`` for the ground floor, ``floorplan-1.svg``... above it,
    ``floorplan-b1.svg``... for basements."""
    return "floorplan.svg" if level == 0 else f"floorplan-{level}.svg" if level > 0 else f"floorplan-b{-level}.svg"


def write_level_svgs(house: House, folder: str | os.PathLike[str]) -> list[Path]:
    """One floorplan SVG per storey (:func:`level_svg_name`) into ``folder``; a
    one-storey house: just floorplan.svg, the same as :func:`write_svg`."""
    from anyhome.floorplan.levels import level_view

    numbers = house.level_numbers()
    if numbers == [0] or len(numbers) <= 1:
        return [write_svg(house, Path(folder) / "floorplan.svg")]
    return [write_svg(level_view(house, k), Path(folder) / level_svg_name(k)) for k in numbers]
