"""Scoring and checking poses (src/anyhome/layout/scoring.py): the exact checks asked
for as poses are tried, and asked again for none."""

from __future__ import annotations

import numpy as np

from anyhome.layout import scoring
from anyhome.layout.options import DEFAULT_OPTIONS
from anyhome.layout.rules.place_wall import place_wall
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import RoomSpec

from .helpers import item, rect, single_room

BOOKCASE = item("bookcase", "shelf", (0.9, 0.35, 1.9), "place_wall")


def _state() -> RoomState:
    fp = single_room(rect(0, 0, 4, 3))
    spec = RoomSpec(id="r1", name="room", type="bedroom", area_m2=12.0)
    st = RoomState(fp, fp.rooms[0], spec, np.random.default_rng(0), DEFAULT_OPTIONS)
    st.commit(BOOKCASE, BOOKCASE.size_m, Choice(np.array([2.0, 0.175 + 2.825]), np.pi, 0.0), "floor",
              "place_wall", None, None)
    return st


def _key(chs: list[Choice]) -> list[tuple[float, float, float]]:
    return [(float(c.xy[0]), float(c.xy[1]), c.yaw) for c in chs]


def test_the_verifier_gives_the_choices_verified_gives_and_goes_on_where_it_stopped():
    st = _state()
    size = BOOKCASE.size_m
    c = place_wall(st.space, size)
    order = scoring.rank(st, c, size, "floor", 0.0, spacing=False)
    for sep in (0.0, 0.5):
        poses = scoring.Verifier(st, c, order, size, "floor", None, min_sep_m=sep)
        first = list(poses.upto(2))
        assert _key(first) == _key(scoring.verified(st, c, order, size, "floor", None, k=2, min_sep_m=sep))
        checked = poses._next
        more = poses.list(6)
        assert _key(more) == _key(scoring.verified(st, c, order, size, "floor", None, k=6, min_sep_m=sep))
        assert more[:2] == first  # the same choices, not checked again
        assert poses._next > checked


def test_the_verifier_checks_a_pose_only_when_it_is_asked_for():
    st = _state()
    size = BOOKCASE.size_m
    c = place_wall(st.space, size)
    order = scoring.rank(st, c, size, "floor", 0.0, spacing=False)
    poses = scoring.Verifier(st, c, order, size, "floor", None)
    todo = poses.upto(6)
    assert poses._next == 0 and poses.found == []
    next(todo)
    assert len(poses.found) == 1
