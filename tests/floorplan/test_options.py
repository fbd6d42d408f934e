"""FloorplanOptions: the solver's tunables as named options passed in."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.errors import AnyHomeError
from anyhome.floorplan import FloorplanOptions, solve_floorplan
from anyhome.plan import get_planner


def _spec():
    return get_planner("offline").plan("a two-bedroom apartment", np.random.default_rng(0))


def test_default_options_are_the_solver_default():
    spec = _spec()
    a = solve_floorplan(spec, np.random.default_rng(1))
    b = solve_floorplan(spec, np.random.default_rng(1), options=FloorplanOptions())
    assert a.model_dump() == b.model_dump()


def test_options_change_the_search():
    spec = _spec()
    one = solve_floorplan(spec, np.random.default_rng(1), options=FloorplanOptions(slicing_attempts=0, wanted_candidates=1))
    assert one.rooms  # the spine alone, first valid layout kept


def test_bad_option_is_refused():
    with pytest.raises(AnyHomeError, match="max_attempts"):
        FloorplanOptions(max_attempts=0)
