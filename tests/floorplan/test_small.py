"""Exact arrangements of a storey of two or three rooms (floorplan.small), and the
storeys they lay out: a tiny house's storeys keep their planned floor."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from shapely.geometry import Polygon

from anyhome.floorplan import solver
from anyhome.floorplan.grid import OUTSIDE
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.program import Program
from anyhome.floorplan.small import small_owners
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.spec import HouseSpec, RoomSpec


def _storey(rooms: list[tuple[str, str, float]], links: list[tuple[str, str]]) -> HouseSpec:
    return HouseSpec(prompt="a storey", rooms=[RoomSpec(id=i, name=i.replace("_", " "), type=t, area_m2=a, level=0)
                                               for i, t, a in rooms], connections=links)


LOFT = _storey([("loft", "bedroom", 6.5), ("bathroom", "bathroom", 3.8), ("stairwell", "stairwell", 4.0)],
               [("stairwell", "outside"), ("stairwell", "loft"), ("loft", "bathroom")])


def _prog(spec: HouseSpec, opts: FloorplanOptions, **kw) -> Program:
    prog = Program.from_spec(spec, opts, knowledge_base())
    return dataclasses.replace(prog, **kw) if kw else prog


def test_a_small_storeys_arrangements_keep_widths_lengths_and_links():
    opts = FloorplanOptions()
    prog = _prog(LOFT, opts, min_length_m=(0.0, 0.0, 3.3), stair_m=(0.0, 0.0, 2.3))
    owners = small_owners(prog, opts, np.random.default_rng(0))
    assert 1 <= len(owners) <= opts.small_exact_candidates
    for owner in owners:
        assert not (owner[1:-1, 1:-1] == OUTSIDE).any()  # a full rectangle: every cell a room's
        for k in range(prog.n):
            xs, ys = np.nonzero(owner == k)
            w, h = (xs.max() - xs.min() + 1) * opts.spine_cell_m, (ys.max() - ys.min() + 1) * opts.spine_cell_m
            assert len(xs) == round(w * h / opts.spine_cell_m**2)  # a rectangle
            assert min(w, h) >= prog.min_side_m(k) - 0.2 - 1e-9
        xs, ys = np.nonzero(owner == 2)
        assert max(np.ptp(xs), np.ptp(ys)) + 1 >= 33  # the stairwell as long as its stair
    laid = [solver._constructed_attempt(prog, o, np.random.default_rng(0), opts) for o in owners]
    assert any(not isinstance(lay, str) for lay in laid)  # given doors (every link's rooms share a wall) and windows


def test_only_small_storeys_of_a_house_of_several_are_arranged():
    opts = FloorplanOptions()
    one_storey = _storey([("living_room", "living_room", 14.0), ("bathroom", "bathroom", 4.0)],
                         [("living_room", "outside"), ("living_room", "bathroom")])
    assert small_owners(_prog(one_storey, opts), opts, np.random.default_rng(0)) == []  # no stairwell: not a storey
    four = _storey([("a", "bedroom", 10.0), ("b", "bedroom", 10.0), ("c", "bathroom", 4.0), ("s", "stairwell", 4.0)],
                   [("s", "outside"), ("s", "a"), ("s", "b"), ("s", "c")])
    assert small_owners(_prog(four, opts), opts, np.random.default_rng(0)) == []
    off = dataclasses.replace(opts, small_exact_max_rooms=0)
    assert small_owners(_prog(LOFT, off), off, np.random.default_rng(0)) == []


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_tiny_storey_is_laid_out_near_its_planned_floor(seed):
    opts = FloorplanOptions()
    plan = solver.solve_floorplan(LOFT, np.random.default_rng(seed), opts, min_length_m={"stairwell": 3.3},
                                  stair_m={"stairwell": 2.3})
    built = sum(Polygon(r.polygon).area for r in plan.rooms)
    least = 6.5 + 3.8 + 3.3 * 1.75  # the stairwell as long as its stair and as wide as its hall
    assert built <= least * 1.25
