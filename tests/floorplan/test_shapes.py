"""Issue 13's shape bars for the floorplan solver: real proportions, short circulation,
the hooks (footprint, fixed) and programs of many rooms."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon, box

from anyhome.errors import FloorplanError
from anyhome.floorplan import solve_floorplan
from anyhome.house import Floorplan, is_habitable
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.spec import HouseSpec, RoomSpec
from tests.floorplan.programs import family_home, planner_like_program
from tests.floorplan.test_solver import check_floorplan

KB = knowledge_base()


def _sides(poly: list[tuple[float, float]]) -> tuple[float, float]:
    """(short, long) side of a room's bounding box."""
    x0, y0, x1, y1 = Polygon(poly).bounds
    return min(x1 - x0, y1 - y0), max(x1 - x0, y1 - y0)


def check_shapes(fp: Floorplan) -> None:
    """Habitable rooms at most twice as long as wide; no room (of a filled rectangle)
    narrower than its type's min_width_m."""
    for r in fp.rooms:
        short, long_ = _sides(r.polygon)
        if is_habitable(r.type):
            assert long_ <= 2 * short + 1e-6, (r.id, r.type, short, long_)
        if abs(Polygon(r.polygon).area - short * long_) < 1e-6:  # a rectangle: its short side is its width
            assert short >= KB.rooms.types[r.type].min_width_m - 0.06, (r.id, r.type, short)


def _spec(rooms: list[tuple[str, str, float]], conns: list[tuple[str, str]], construct: bool = False) -> HouseSpec:
    specs = [RoomSpec(id=i, name=t.replace("_", " "), type=t, area_m2=a) for i, t, a in rooms]
    if construct:  # more rooms than a planner's spec may hold today (HouseSpec's MAX_ROOMS)
        return HouseSpec.model_construct(prompt="many rooms", building="hotel", style="", styles=[], palette=[],
                                         rooms=specs, connections=conns, warnings=[], provenance=None)
    return HouseSpec(prompt="hand-built", rooms=specs, connections=conns)


def one_bed_home() -> HouseSpec:
    """The offline planner's 1-bed haunted house program (the spine made its living room
    2.8 x 5.95 m and its bedroom 2.45 x 5.95 m)."""
    return _spec(
        [("living_room", "living_room", 18.68), ("kitchen", "kitchen", 12.91), ("bedroom", "bedroom", 14.19),
         ("bathroom", "bathroom", 6.04), ("dining_room", "dining_room", 15.13), ("entry", "entry", 4.27)],
        [("entry", "living_room"), ("living_room", "dining_room"), ("dining_room", "kitchen"),
         ("living_room", "bedroom"), ("bedroom", "bathroom"), ("entry", "outside")],
    )


@pytest.mark.parametrize("seed", range(3))
def test_a_home_keeps_real_proportions(seed: int) -> None:
    spec = one_bed_home()
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    check_floorplan(spec, fp)
    check_shapes(fp)
    living = next(r for r in fp.rooms if r.type == "living_room")
    assert _sides(living.polygon)[0] >= 3.0


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**31), n_rooms=st.integers(2, 12))
def test_planner_like_programs_meet_the_shape_bars(seed: int, n_rooms: int) -> None:
    spec = planner_like_program(np.random.default_rng(seed), n_rooms)
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    check_floorplan(spec, fp)
    check_shapes(fp)


def hotel_floor(n_guest: int) -> HouseSpec:
    rooms = [("lobby", "entry", 12.0), ("corridor", "hallway", 40.0)]
    conns = [("lobby", "corridor"), ("lobby", "outside")]
    for i in range(n_guest):
        rooms += [(f"guest{i}", "bedroom", 16.0), (f"bath{i}", "bathroom", 4.5)]
        conns += [("corridor", f"guest{i}"), (f"guest{i}", f"bath{i}")]
    return _spec(rooms, conns, construct=True)


def test_a_forty_room_corridor_building_solves() -> None:
    spec = hotel_floor(19)
    assert len(spec.rooms) == 40
    fp = solve_floorplan(spec, np.random.default_rng(0))
    check_floorplan(spec, fp)
    check_shapes(fp)


@pytest.mark.parametrize("rect", [(0.0, 0.0, 9.0, 8.5), (2.0, 1.0, 13.5, 8.0)])
def test_a_rectangular_footprint_is_filled_exactly(rect: tuple[float, float, float, float]) -> None:
    spec = family_home()
    fp = solve_floorplan(spec, np.random.default_rng(1), footprint=box(*rect))
    check_floorplan(spec, fp)
    union = Polygon(fp.rooms[0].polygon)
    for r in fp.rooms[1:]:
        union = union.union(Polygon(r.polygon))
    assert union.symmetric_difference(box(*rect)).area < 1e-6


def test_a_footprint_as_points_is_accepted() -> None:
    spec = family_home()
    fp = solve_floorplan(spec, np.random.default_rng(2), footprint=[(0, 0), (10, 0), (10, 8), (0, 8)])
    assert sum(Polygon(r.polygon).area for r in fp.rooms) == pytest.approx(80.0)


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        ({"footprint": [(0, 0), (10, 0), (10, 4), (5, 4), (5, 8), (0, 8)]}, "rectangle"),
        ({"footprint": box(0, 0, 9.03, 8)}, "grid"),
        ({"footprint": box(0, 0, 9, 8), "fixed": {"bath": (0.0, 0.0, 2.0, 2.5)}}, "fixed"),
        ({"fixed": {"bath": (0.0, 0.0, 2.0, 2.5)}}, "fixed"),
        ({"footprint": box(0, 0, 3, 3)}, "could not lay out"),
    ],
)
def test_hooks_refuse_what_they_cannot_honour_in_one_line(kwargs: dict, words: str) -> None:
    with pytest.raises(FloorplanError) as e:
        solve_floorplan(family_home(), np.random.default_rng(0), **kwargs)
    assert words in str(e.value) and "\n" not in str(e.value)


@pytest.mark.parametrize("seed", range(3))
def test_a_room_with_four_doors_keeps_wall_between_them(seed: int) -> None:
    """A kindergarten's cloakroom opens to the play room, the nap room, the kitchenette and
    outside: it is at least hub_min_side_m wide (at 1.6 m its bench had no wall left)."""
    from anyhome.floorplan.options import FloorplanOptions

    spec = _spec(
        [("cloakroom", "entry", 3.8), ("play", "playroom", 42.0), ("nap", "bedroom", 30.0),
         ("kitchenette", "kitchen", 6.7), ("bath", "bathroom", 6.4)],
        [("cloakroom", "play"), ("cloakroom", "nap"), ("cloakroom", "kitchenette"), ("play", "bath"),
         ("cloakroom", "outside")],
    )
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    check_floorplan(spec, fp)
    cloak = next(r for r in fp.rooms if r.id == "cloakroom")
    assert _sides(cloak.polygon)[0] >= FloorplanOptions().hub_min_side_m - 0.06
