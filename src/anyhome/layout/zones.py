"""Arms of an open-plan room: where each planned room it holds keeps its furniture.

A room merged from two planned rooms (:attr:`anyhome.house.Room.merged`, an L made by
:mod:`anyhome.floorplan.merge`) is one polygon; its furniture groups come from both
planned rooms. So that the dining table stands in the dining arm and the sofa in the
living arm, the L is cut at its inner corner into two rectangles, along whichever of
the two walls that meet there gives the squarer arms (the smaller of the two arms'
greatest aspect), the larger arm going to the planned room of the larger target area;
each planned room's groups then get a bonus for floor poses inside its own arm
(``LayoutOptions.zone_bonus``). The arms are the layout's own reading of the shape
(house.json records only which planned rooms the room holds), so they need not be the
two rectangles the floorplan solver drew. Rooms that
are no L with two planned rooms get no arms.
"""

from __future__ import annotations

from shapely.geometry import Polygon, box
from shapely.geometry.base import BaseGeometry

from anyhome.house import Room
from anyhome.plan.spec import RoomSpec

L_CORNERS = 6


def arm_zones(room: Room, planned: list[RoomSpec]) -> list[Polygon] | None:
    """One arm per planned room of ``planned`` (two: the room's own and the one it holds),
    in that order; None when ``room`` is no L or ``planned`` is not two rooms."""
    if len(planned) != 2 or len(room.polygon) != L_CORNERS:
        return None
    poly = Polygon(room.polygon)
    inner = reflex_corner(room.polygon)
    if inner is None:
        return None
    x0, y0, x1, y1 = poly.bounds
    rx, ry = inner
    best: tuple[float, list[Polygon]] | None = None
    for cut in ((box(x0, y0, rx, y1), box(rx, y0, x1, y1)), (box(x0, y0, x1, ry), box(x0, ry, x1, y1))):
        halves = [_area_part(poly.intersection(half)) for half in cut]
        arms = [h for h in halves if h is not None]
        if len(arms) != 2:
            continue
        worst = max(_aspect(a) for a in arms)
        if best is None or worst < best[0]:
            best = (worst, sorted(arms, key=lambda a: -a.area))
    if best is None:
        return None
    big, small = best[1]
    return [big, small] if planned[0].area_m2 >= planned[1].area_m2 else [small, big]


def _aspect(rect: Polygon) -> float:
    x0, y0, x1, y1 = rect.bounds
    return max(x1 - x0, y1 - y0) / max(min(x1 - x0, y1 - y0), 1e-9)


def reflex_corner(points: list[tuple[float, float]]) -> tuple[float, float] | None:
    """The corner of a CCW outline that turns clockwise (the inner corner of an L), or
    None when there is none or more than one."""
    n = len(points)
    found = []
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = points[i - 1], points[i], points[(i + 1) % n]
        if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) < -1e-12:
            found.append(points[i])
    return found[0] if len(found) == 1 else None


def _area_part(geom: BaseGeometry) -> Polygon | None:
    """The one polygon of an intersection (which may carry the lines where it only touches)."""
    parts = [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, Polygon) and g.area > 0]
    return parts[0] if len(parts) == 1 else None
