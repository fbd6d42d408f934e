"""Inner courtyards (issue 13): a riad, an atrium house, a cloister are built around an
open court that rooms open onto and take their windows from."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Polygon

from anyhome.evaluate.footprint import INSIDE_MAX_SHARE, courtyard_shares
from anyhome.floorplan import solve_floorplan
from anyhome.floorplan.grid import FREE, OUTSIDE
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.walls import wall_runs
from anyhome.floorplan.windows import free_slots
from anyhome.plan import get_planner
from anyhome.plan.knowledge import knowledge_base
from tests.floorplan.test_solver import check_floorplan

KB = knowledge_base()


def _plan(text: str, seed: int):
    spec = get_planner("offline", KB).plan(text, np.random.default_rng(seed))
    return spec, solve_floorplan(spec, np.random.default_rng(seed))


@pytest.mark.parametrize("text", ["a riad", "an atrium house", "a monastery"])
def test_courtyard_buildings_have_a_courtyard(text: str) -> None:
    """The knowledge says these buildings are built around an open court."""
    spec = get_planner("offline", KB).plan(text, np.random.default_rng(0))
    courts = [r for r in spec.rooms if r.type == "courtyard"]
    assert len(courts) == 1 and courts[0].open_air


@pytest.mark.parametrize("text", ["a riad", "a house around a courtyard", "an atrium house"])
@pytest.mark.parametrize("seed", [0, 1])
def test_courtyard_inside_footprint_with_rooms_opening_onto_it(text: str, seed: int) -> None:
    spec, fp = _plan(text, seed)
    check_floorplan(spec, fp)
    polys = {r.id: Polygon(r.polygon) for r in fp.rooms}
    court = next(r.id for r in fp.rooms if r.type == "courtyard")
    share = courtyard_shares(polys, [court])[court]
    assert share < INSIDE_MAX_SHARE, f"{court} has {share:.0%} of its perimeter on the outline"
    onto = {a if b == court else b for a, b in (d.rooms for d in fp.doors) if court in (a, b)}
    habitable_onto = [rid for rid in onto if any(r.id == rid and r.type != "hallway" for r in spec.rooms)]
    assert len(habitable_onto) >= 3, onto


def test_rooms_take_windows_from_a_courtyard() -> None:
    """A wall onto an enclosed open-air room is a window wall, other inner walls are not."""
    owner = np.full((8, 6), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    owner[1:4, 1:-1] = 0  # a room
    owner[4:6, 1:-1] = 1  # a courtyard east of it
    owner[6:7, 1:-1] = 2  # a room east of the courtyard
    runs = wall_runs(owner)
    opts = FloorplanOptions(window_corner_margin_m=0.1)
    cell = 1.0
    onto_court = [s for _, s in free_slots(0, runs, [], cell, opts, frozenset({1})) if s.axis == 0 and s.line_m == 3.0]
    assert onto_court, "no window slot on the wall onto the courtyard"
    plain = [s for _, s in free_slots(0, runs, [], cell, opts) if s.axis == 0 and s.line_m == 3.0]
    assert not plain, "a wall onto another room is not an exterior wall"
