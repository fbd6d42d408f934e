"""Issue 13: small homes get short halls, and habitable rooms keep their proportions.

Measured as the evaluator measures them (``anyhome.evaluate.plan_metrics``): a corridor's
length is the long side of its minimum rotated rectangle (the centre line of an L), a
room's aspect its long side over the diameter of its largest inscribed circle.
"""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from anyhome.evaluate.plan_metrics import LONG_ASPECT, corridor_length_m, min_width_m, rect_sides_m
from anyhome.floorplan.solver import solve_floorplan
from anyhome.house import is_habitable
from anyhome.plan import get_planner
from anyhome.plan.spec import HouseSpec, RoomSpec

SMALL_HOME_CORRIDOR_M = 8.0
"""Issue 13's bar: no corridor longer than this in a home of 8 rooms or fewer."""
CIRCULATION = {"hallway", "entry"}


def _problems(fp) -> list[str]:
    out = []
    small = len(fp.rooms) <= 8
    for r in fp.rooms:
        poly = Polygon(r.polygon)
        if small and r.type in CIRCULATION and corridor_length_m(poly) > SMALL_HOME_CORRIDOR_M:
            out.append(f"{r.id}: corridor {corridor_length_m(poly):.1f} m")
        if is_habitable(r.type):
            aspect = rect_sides_m(poly)[1] / min_width_m(poly)
            if aspect > LONG_ASPECT:
                out.append(f"{r.id}: aspect {aspect:.2f}")
    return out


@pytest.mark.parametrize(
    "prompt",
    [
        "A gamer's apartment with a game room, two bedrooms and a bathroom.",
        "A mid-century modern two-bedroom house with a blue marble accent in the bathroom.",
        "A cozy cottage with a reading nook, a fireplace and a small kitchen.",
    ],
)
def test_small_homes_have_short_halls_and_no_strips(prompt):
    planner = get_planner("offline")
    for seed in range(3):
        spec = planner.plan(prompt, np.random.default_rng(seed))
        fp = solve_floorplan(spec, np.random.default_rng(seed))
        assert _problems(fp) == [], (prompt, seed)


def _hall_home(bedrooms: int, bathrooms: int, areas: list[float], open_plan: bool) -> HouseSpec:
    """A home whose rooms hang off one hall: living (with a kitchen off it) and the
    bedrooms and bathrooms; the entrance into the hall."""
    rooms = [RoomSpec(id="hall", name="hallway", type="hallway", area_m2=7.0),
             RoomSpec(id="living", name="living room", type="living_room", area_m2=areas[0]),
             RoomSpec(id="kitchen", name="kitchen", type="kitchen", area_m2=areas[1])]
    conns = [("hall", "living"), ("living", "kitchen") if open_plan else ("hall", "kitchen")]
    for i in range(bedrooms):
        rooms.append(RoomSpec(id=f"bed{i}", name="bedroom", type="bedroom", area_m2=areas[2 + i]))
        conns.append(("hall", f"bed{i}"))
    for i in range(bathrooms):
        rooms.append(RoomSpec(id=f"bath{i}", name="bathroom", type="bathroom", area_m2=4.5 + i))
        conns.append(("hall", f"bath{i}"))
    conns.append(("hall", "outside"))
    return HouseSpec(prompt="a home", building="home", rooms=rooms, connections=conns)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    bedrooms=st.integers(1, 3),
    bathrooms=st.integers(1, 2),
    areas=st.lists(st.floats(10.0, 18.0), min_size=5, max_size=5),
    open_plan=st.booleans(),
    seed=st.integers(0, 2**16),
)
def test_a_hall_home_of_eight_rooms_or_fewer_has_a_hall_of_8_m_at_most(bedrooms, bathrooms, areas, open_plan, seed):
    areas = [areas[0] + 6.0, areas[1] - 2.0, *areas[2:]]  # a living room, a kitchen, bedrooms
    spec = _hall_home(bedrooms, bathrooms, areas, open_plan)
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    assert _problems(fp) == []


CIRCULATION_SHARE_P90 = 0.18
"""Issue 13's bar for the circulation share of homes (90th percentile)."""


@pytest.mark.parametrize("seed", range(4))
def test_an_entry_is_not_stretched_along_the_rooms_beside_it(seed):
    """A mudroom whose one neighbour leads on to three more rooms stays a mudroom, not a
    corridor as long as those rooms."""
    spec = get_planner("offline").plan(
        "A ranch house with a mudroom, a laundry room, a kitchen, a living room and two bedrooms.",
        np.random.default_rng(seed),
    )
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    areas = {r.id: Polygon(r.polygon).area for r in fp.rooms}
    circ = sum(a for r in fp.rooms for a in [areas[r.id]] if r.type in CIRCULATION)
    assert circ / sum(areas.values()) <= CIRCULATION_SHARE_P90
    for r in spec.rooms:
        if r.type == "entry":
            assert areas[r.id] <= 1.5 * r.area_m2
