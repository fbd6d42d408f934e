"""Room polygons built defensively: a malformed outline must be reported, not crash."""

from __future__ import annotations

from collections.abc import Sequence

from shapely.geometry import Polygon


def room_polygon(points: Sequence[Sequence[float]]) -> Polygon:
    """The shapely polygon of an outline; an empty polygon if it has fewer than 3 points."""
    return Polygon(points) if len(points) >= 3 else Polygon()


def is_usable(poly: Polygon) -> bool:
    """A polygon the geometric checks can run on: non-empty, valid, positive area."""
    return not poly.is_empty and poly.is_valid and poly.area > 0
