"""Zones for under-furnished rooms: the plan's ``fill`` groups, placed while they are needed.

The planner offers a room functional zones beyond its set (a reading corner, a second
seating group, a sideboard: furniture.yaml ``zones:``, as groups with
:attr:`anyhome.plan.spec.GroupSpec.fill`). The layout places them after the room's own
groups, in a room of at least :data:`FILL_MIN_AREA_M2`, one after another in the plan's
order and only while the furniture covers less than :data:`FILL_COVERAGE` of the floor
(the furnishing metric's floor coverage: floor objects' footprints, rugs left out). A
large room goes round the list again (one more copy of each zone per
:data:`ZONE_ROUND_M2` of floor, at most :data:`ZONE_ROUNDS` in all). A zone copy of
which nothing finds a spot is taken out whole; one of which only some members fit keeps
them. A zone's anchor prefers floor away from the furniture already there
(``LayoutOptions.zone_spacing_weight``). Either way nothing is reported as dropped, since the text did not ask for it.
"""

from __future__ import annotations

from collections.abc import Callable

from shapely.geometry import Polygon

from anyhome.geometry import floor_coverage
from anyhome.layout.arrangements import place_free
from anyhome.layout.kitchens import is_island
from anyhome.layout.state import RoomState
from anyhome.plan.spec import GroupSpec

FILL_COVERAGE = 0.22
"""A room's floor is under-furnished while its furniture covers less than this fraction."""

FILL_MIN_AREA_M2 = 10.0
"""A room smaller than this gets no zones, however bare: its own set is what it holds."""

ZONE_ROUND_M2 = 30.0
"""A room goes round its zones once more for every this many square metres of floor."""

ZONE_ROUNDS = 3
"""Most rounds of zones in one room (a 90 m2 hall: up to three reading corners)."""


def coverage(st: RoomState) -> float:
    """Fraction of the room's floor under its floor objects (rugs and other layers left out)."""
    return floor_coverage([Polygon(p.corners) for p in st.space.placed if p.floor and not p.layer], st.space.poly)


def place_zones(st: RoomState, zones: list[GroupSpec], place: Callable[[RoomState, GroupSpec], None]) -> None:
    """Place copies of ``zones`` while the room needs them (see the module docstring): the
    first round each by ``place`` (the solver's, by arrangement), later rounds one more
    copy of each freely arranged zone."""
    if not zones or st.space.area < FILL_MIN_AREA_M2:
        return
    rounds = min(ZONE_ROUNDS, 1 + int(st.space.area // ZONE_ROUND_M2))
    st.spread = True
    try:
        for r in range(rounds):
            for g in zones:
                if coverage(st) >= FILL_COVERAGE:
                    return
                if r > 0 and (g.arrangement != "free" or is_island(st, g)):
                    continue
                snap = st.snapshot()
                if r == 0:
                    place(st, g)
                else:
                    place_free(st, g.model_copy(update={"repeat": g.repeat * (r + 1)}), start=g.repeat * r)
                if len(st.space.placed) == snap.n_placed:
                    st.restore(snap)
                else:
                    del st.dropped[snap.n_dropped:]
    finally:
        st.spread = False
