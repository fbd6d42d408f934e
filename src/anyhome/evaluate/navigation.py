"""Rule 6 of SCENE_FORMAT.md: every room and door reachable by a walking agent.

A thin adapter over :func:`geometry.navigability`: the obstacles are the footprints of
objects for which :func:`geometry.blocks_navigation` holds (rugs, objects under 3 cm and
objects standing on other objects excepted). Rooms with malformed polygons are left out
of the raster (rule 5 reports them).
"""

from __future__ import annotations

from shapely.geometry import Polygon

from anyhome import geometry
from anyhome.evaluate.polygons import is_usable, room_polygon
from anyhome.evaluate.report import Violation
from anyhome.house import House


def navigation_obstacles(house: House) -> list[Polygon]:
    return [
        geometry.footprint_polygon(o.position, o.size, o.yaw)
        for o in house.objects
        if geometry.blocks_navigation(o.category, o.size[2], o.support)
    ]


def run_navigability(house: House) -> geometry.NavResult:
    return geometry.navigability(
        rooms=[(r.id, r.polygon) for r in house.rooms if is_usable(room_polygon(r.polygon))],
        doors=[(d.id, d.rooms, d.segment) for d in house.doors],
        obstacles=navigation_obstacles(house),
    )


def check_navigable(nav: geometry.NavResult) -> list[Violation]:
    out = [
        Violation(6, "unreachable_room",
                  f"no walkable path from the entrance reaches room {rid}", (rid,))
        for rid in nav.unreachable_rooms
    ]
    out += [
        Violation(6, "unreachable_door",
                  f"no walkable path from the entrance reaches door {did}", (did,))
        for did in nav.unreachable_doors
    ]
    return out
