"""The constructive spine layout keeps large rooms in proportion."""

import numpy as np
import pytest

from anyhome.floorplan.solver import solve_floorplan
from anyhome.plan.offline import OfflinePlanner

THEATRE = "A community theatre with a stage, 80 seats in rows facing it, two dressing rooms and a box office."


@pytest.mark.parametrize("seed", range(4))
def test_a_large_room_beside_the_spine_is_not_a_strip(seed):
    spec = OfflinePlanner().plan(THEATRE, np.random.default_rng(seed))
    big = max(spec.rooms, key=lambda r: r.area_m2)
    assert big.area_m2 > 100  # the auditorium with its seats
    fp = solve_floorplan(spec, np.random.default_rng(seed))
    room = next(r for r in fp.rooms if r.id == big.id)
    v = np.asarray(room.polygon)
    w, d = v.max(axis=0) - v.min(axis=0)
    assert max(w, d) / min(w, d) <= 2.5
