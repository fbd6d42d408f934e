"""Scoring and checking poses (src/anyhome/layout/scoring.py): the exact checks asked
for as poses are tried, and asked again for none."""

from __future__ import annotations

import numpy as np

from anyhome.layout import scoring
from anyhome.layout.options import DEFAULT_OPTIONS
from anyhome.layout.rules.place_wall import place_wall
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import RoomSpec
from anyhome.space import rect_corners

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


def _crowded() -> RoomState:
    fp = single_room(rect(0, 0, 5, 4), windows=[((0.0, 1.0), (0.0, 2.2))])
    spec = RoomSpec(id="r1", name="room", type="bedroom", area_m2=20.0)
    st = RoomState(fp, fp.rooms[0], spec, np.random.default_rng(0), DEFAULT_OPTIONS)
    for x, y, yaw in ((2.0, 3.825, np.pi), (3.5, 3.825, np.pi), (4.825, 2.0, np.pi / 2), (2.5, 2.0, 0.3)):
        st.commit(BOOKCASE, BOOKCASE.size_m, Choice(np.array([x, y]), yaw, 0.0), "floor", "place_wall", None, None)
    return st


def _ranking(st: RoomState, seed: int, all_at_once: bool) -> scoring.Ranking:
    st.rng = np.random.default_rng(seed)
    size = (0.6, 0.45, 1.2)  # tall: kept off the window
    c = place_wall(st.space, size)
    c = c + place_wall(st.space, size).shifted_pref(-0.2)  # ties of bound broken by index

    r = scoring.rank(st, c, size, "floor", 0.3, spacing=True, bonus=lambda x: scoring.Cands(
        x.xy, x.yaw, x.z, x.pref + 0.5 * (x.xy[:, 0] > 2.5)), bonus_max=0.5)
    if all_at_once:
        r._chunk = len(c)
    return r


def test_a_ranking_found_lazily_is_the_order_all_candidates_checked_at_once_give():
    st = _crowded()
    for seed in range(3):
        lazy, full = _ranking(st, seed, False), _ranking(st, seed, True)
        first = lazy.get(0)
        assert first is not None and len(lazy._rest) > 0  # the best found before all were checked
        assert first == full.get(0)
        assert lazy.all().tolist() == full.all().tolist()
        size = (0.6, 0.45, 1.2)
        corners = rect_corners(lazy.c.xy, size[:2], lazy.c.yaw)
        valid = st.space.valid(corners, 0.0, size[2], floor=True)
        assert sorted(full.found) == np.flatnonzero(valid).tolist()  # every valid candidate, once


def test_a_candidates_noise_does_not_depend_on_which_others_are_valid():
    st = _crowded()
    r = _ranking(st, 1, True)
    r.all()
    u = np.random.default_rng(1).random(len(r.c))
    assert np.allclose(r._base, r.c.pref + 0.3 * u)
