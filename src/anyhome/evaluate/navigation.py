"""Rule 6 of SCENE_FORMAT.md: every room and door reachable by a walking agent.

A thin adapter over :func:`geometry.navigability`: the obstacles are the footprints of
objects for which :func:`geometry.blocks_navigation` holds (rugs, objects under 3 cm and
objects standing on other objects excepted). Rooms with malformed polygons are left out
of the raster (rule 5 reports them). The raster holds at most
``geometry.MAX_NAV_CELLS`` cells: a house too large for it even at
``geometry.MAX_NAV_CELL_M`` is not checked and gets the violation
``navigation_not_checked`` (a house that cannot be checked is not certified valid).
"""

from __future__ import annotations

from collections.abc import Sequence

from shapely.geometry import Polygon

from anyhome import geometry
from anyhome.evaluate.polygons import is_usable, room_polygon
from anyhome.evaluate.report import Violation
from anyhome.house import House


def navigation_obstacles(house: House, footprints: Sequence[Polygon] | None = None
                         ) -> list[Polygon]:
    """Footprints of the objects that block the agent (``footprints``: those of
    ``house.objects`` in order, when already built)."""
    if footprints is None:
        footprints = [geometry.footprint_polygon(o.position, o.size, o.yaw)
                      for o in house.objects]
    return [
        fp for o, fp in zip(house.objects, footprints)
        if geometry.blocks_navigation(o.category, o.size[2], o.support, o.tags)
    ]


def run_navigability(house: House, footprints: Sequence[Polygon] | None = None
                     ) -> geometry.NavResult:
    """Rule 6 on ``house``; its ``targets_reached`` are those of :func:`furniture`, in order."""
    if footprints is None:
        footprints = [geometry.footprint_polygon(o.position, o.size, o.yaw) for o in house.objects]
    return geometry.navigability(
        rooms=[(r.id, r.polygon) for r in house.rooms if is_usable(room_polygon(r.polygon))],
        doors=[(d.id, d.rooms, d.segment) for d in house.doors],
        obstacles=navigation_obstacles(house, footprints),
        targets=[footprints[i] for i in furniture(house)],
    )


def furniture(house: House) -> list[int]:
    """Indices of the objects an agent walks up to: on the floor, blocking, not stairs."""
    return [i for i, o in enumerate(house.objects) if geometry.walked_up_to(o.category, o.size[2], o.support, o.tags)]


def check_navigable(nav: geometry.NavResult) -> list[Violation]:
    if not nav.checked:
        return [Violation(6, "navigation_not_checked",
                          f"navigability not checked: {nav.skipped}", ())]
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
