"""Courtyard rings (anyhome.floorplan.court): rooms on every side of an open court, or a
U of three wings, laid out by the constructive ring search."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Polygon

from anyhome.evaluate.footprint import ENCLOSED_MAX_SHARE, courtyard_shares, footprint_shape
from anyhome.floorplan import solve_floorplan
from anyhome.floorplan.court import court_owner
from anyhome.floorplan.grid import OUTSIDE
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.program import Program
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.offline import OfflinePlanner
from tests.floorplan.test_solver import check_floorplan

KB = knowledge_base()
RING = FloorplanOptions(court_open_side_probability=0.0)


def _spec(text: str, seed: int):
    return OfflinePlanner(KB).plan(text, np.random.default_rng(seed))


def _court_neighbours(owner: np.ndarray, court: int) -> set[int]:
    mask = owner == court
    out: set[int] = set()
    for axis in (0, 1):
        for step in (1, -1):
            out |= set(np.unique(np.roll(owner, step, axis=axis)[mask]).tolist())
    return out - {court}


@pytest.mark.parametrize(("text", "seed"), [("a riad", 2), ("a riad", 3), ("an atrium house", 1), ("an atrium house", 2)])
def test_a_courtyard_prompt_gives_a_court_with_rooms_on_every_side(text: str, seed: int) -> None:
    spec = _spec(text, seed)
    fp = solve_floorplan(spec, np.random.default_rng(seed), RING)
    check_floorplan(spec, fp)
    polys = {r.id: Polygon(r.polygon) for r in fp.rooms}
    court = next(r for r in fp.rooms if r.type == "courtyard")
    assert courtyard_shares(polys, [court.id])[court.id] < ENCLOSED_MAX_SHARE
    x0, y0, x1, y1 = polys[court.id].bounds
    sides = {"south": ((x0, y0), (x1, y0)), "east": ((x1, y0), (x1, y1)),
             "north": ((x0, y1), (x1, y1)), "west": ((x0, y0), (x0, y1))}
    for side, (p, q) in sides.items():  # a room along every side of the court
        line = LineString([p, q])
        assert any(poly.boundary.intersection(line).length > 0.5 for rid, poly in polys.items() if rid != court.id), side
    onto = {a if b == court.id else b for a, b in (d.rooms for d in fp.doors) if court.id in (a, b)}
    assert len(onto) >= 4, onto
    assert footprint_shape([polys[r.id] for r in fp.rooms if not r.open_air]) == "courtyard"


def test_a_u_of_wings_opens_the_court_on_one_side() -> None:
    spec = _spec("a monastery", 1)
    prog = Program.from_spec(spec, FloorplanOptions(), KB)
    court = prog.ids.index(next(r.id for r in spec.rooms if r.type == "courtyard"))
    rng = np.random.default_rng(0)
    owners = [court_owner(prog, rng, open_side=True) for _ in range(40)]
    found = [o for o in owners if not isinstance(o, str)]
    assert found, "no U of wings in 40 attempts"
    for owner in found:
        assert OUTSIDE in _court_neighbours(owner, court)
        built = owner.copy()
        built[built == court] = OUTSIDE
        cells = [Polygon([(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)]) for x, y in np.argwhere(built >= 0)]
        assert footprint_shape(cells) == "U"


def test_a_closed_ring_keeps_the_outside_off_the_court() -> None:
    spec = _spec("an atrium house", 3)
    prog = Program.from_spec(spec, FloorplanOptions(), KB)
    court = prog.ids.index(next(r.id for r in spec.rooms if r.type == "courtyard"))
    rng = np.random.default_rng(1)
    found = [o for o in (court_owner(prog, rng) for _ in range(40)) if not isinstance(o, str)]
    assert found
    for owner in found:
        assert OUTSIDE not in _court_neighbours(owner, court)
        assert set(np.unique(owner).tolist()) == set(range(prog.n)) | {OUTSIDE}


def test_too_few_rooms_onto_the_court_is_a_reason_not_a_ring() -> None:
    lonely = Program(ids=("court", "bed", "kitchen"), types=("courtyard", "bedroom", "kitchen"),
                     areas_m2=np.array([20.0, 12.0, 10.0]), links=((1, 0), (2, 0), (1, OUTSIDE)),
                     options=FloorplanOptions(), enclosed=(True, False, False))
    assert "too few" in court_owner(lonely, np.random.default_rng(0))
    assert "too few" in court_owner(lonely, np.random.default_rng(0), open_side=True)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), text=st.sampled_from(["a riad", "an atrium house", "a monastery"]),
       open_side=st.sampled_from([0.0, 1.0]))
def test_courtyard_plans_pass_the_floorplan_checks(seed: int, text: str, open_side: float) -> None:
    spec = _spec(text, seed)
    fp = solve_floorplan(spec, np.random.default_rng(seed), FloorplanOptions(court_open_side_probability=open_side))
    check_floorplan(spec, fp)
