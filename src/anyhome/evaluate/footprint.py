"""Footprint figures (issue 13): the outline's shape and where courtyards sit.

Definitions
-----------
building outline
    The union of a level's rooms that are not open-air (the roofed part of the house).
footprint shape
    Of the ground level's building outline (:func:`footprint_shape`): ``courtyard`` when
    it has a hole (an open court, or nothing, walled in on every side) or a courtyard of
    the level lies inside the footprint (see below); else from the
    *notches*, the pieces of its bounding box it leaves empty (pieces under
    :data:`NOTCH_MIN_M2` ignored): none ``rectangle``; one at a corner ``L``; one in the
    middle of a side ``U``; two at the corners of one side ``T``; two at opposite corners
    ``step``; anything else ``other``.
courtyard boundary share
    For a courtyard (an open-air room whose type is ``enclosed`` in rooms.yaml, or of type
    ``courtyard``): the share of its perimeter that lies on the outline of its level (the
    union of all its level's rooms, open-air ones included): 0 when rooms wrap it on every
    side, about 0.25 when a square courtyard is open on one side.
courtyard inside the footprint
    Boundary share below :data:`INSIDE_MAX_SHARE`: rooms on at least three sides.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

import shapely
from shapely.geometry import MultiPolygon, Polygon, box
from shapely.ops import unary_union

SHAPES = ("rectangle", "L", "T", "U", "step", "courtyard", "other")
"""Footprint shapes, in the order the benchmark table lists them."""
NOTCH_MIN_M2 = 0.5
"""Empty pieces of the bounding box smaller than this are not notches (wall jogs)."""
INSIDE_MAX_SHARE = 0.3
"""A courtyard with less of its perimeter on the outline than this is inside the
footprint: rooms on at least three of its sides (a square's side is 0.25)."""
ENCLOSED_MAX_SHARE = 0.02
"""A courtyard with less of its perimeter on the outline than this has rooms on every side."""
_TOL_M = 0.01
"""Gap closed between rooms when their polygons are merged into an outline."""
_EDGE_M = 0.002
"""How far a courtyard wall may lie from the outline and still count as on it."""


def outline(polys: Iterable[Polygon]) -> Polygon | MultiPolygon:
    """The union of ``polys``, hairline gaps between them closed."""
    merged = unary_union([p for p in polys if not p.is_empty])
    return merged.buffer(_TOL_M, join_style="mitre").buffer(-_TOL_M, join_style="mitre")


def footprint_shape(built: Iterable[Polygon], inner_court: bool = False) -> str:
    """The shape class (:data:`SHAPES`) of the outline of ``built`` (see the module doc);
    ``inner_court``: a courtyard lies inside the footprint."""
    shape = outline(built)
    if inner_court:
        return "courtyard"
    if shape.is_empty:
        return "other"
    if isinstance(shape, MultiPolygon):
        return "other"
    if any(Polygon(ring).area >= NOTCH_MIN_M2 for ring in shape.interiors):
        return "courtyard"
    x0, y0, x1, y1 = shape.bounds
    rest = box(x0, y0, x1, y1).difference(Polygon(shape.exterior))
    pieces = [g for g in getattr(rest, "geoms", [rest]) if isinstance(g, Polygon) and g.area >= NOTCH_MIN_M2]
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    held = [[i for i, c in enumerate(corners) if g.buffer(_TOL_M).contains(shapely.Point(c))] for g in pieces]
    if not pieces:
        return "rectangle"
    if len(pieces) == 1:
        return {0: "U", 1: "L"}.get(len(held[0]), "other")
    if len(pieces) == 2 and all(len(h) == 1 for h in held):
        a, b = held[0][0], held[1][0]
        return "step" if (a - b) % 4 == 2 else "T"
    return "other"


def courtyard_shares(rooms: Mapping[str, Polygon], courts: Iterable[str]) -> dict[str, float]:
    """Boundary share (see the module doc) of each room of ``courts`` among ``rooms``
    (one level's room polygons, by id)."""
    shape = outline(rooms.values())
    edge = shape.boundary.buffer(_EDGE_M)
    out = {}
    for rid in courts:
        ring = rooms[rid].exterior
        out[rid] = float(ring.intersection(edge).length / ring.length) if ring.length > 0 else 0.0
    return out
