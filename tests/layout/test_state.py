"""RoomState: committing poses that keep the walkways open and the floor objects reachable."""

from __future__ import annotations

import math

import numpy as np

from anyhome.layout.options import DEFAULT_OPTIONS
from anyhome.layout.state import Choice, RoomState
from anyhome.plan.spec import RoomSpec

from .helpers import item, rect, single_room

CABINET = item("cabinet", "cabinet", (0.5, 0.5, 0.9), "place_corner")
WARDROBE = item("wardrobe", "wardrobe", (1.2, 0.6, 2.0), "place_wall")
WALLING = Choice(np.array([0.6, 2.2]), 0.0, 0.0)
"""The wardrobe right in front of the cabinet in the top-left corner: it walls it in."""
FREE = Choice(np.array([3.7, 1.6]), math.pi / 2, 0.0)
"""The wardrobe against the right wall, clear of the cabinet."""


def _state() -> RoomState:
    fp = single_room(rect(0, 0, 4, 3))
    spec = RoomSpec(id="r1", name="room", type="bedroom", area_m2=12.0)
    st = RoomState(fp, fp.rooms[0], spec, np.random.default_rng(0), DEFAULT_OPTIONS)
    st.commit(CABINET, CABINET.size_m, Choice(np.array([0.25, 2.75]), 0.0, 0.0), "floor", "place_corner", None, None)
    return st


def test_a_pose_that_walls_in_an_earlier_object_gives_way_to_one_that_does_not():
    st = _state()
    assert st.nav.radius is not None
    obj = st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING, FREE], "floor", "place_wall", None, None)
    assert obj is not None and obj.position[0] > 3.0
    assert st.nav.ok() and st.nav.waived == []


def test_with_no_other_pose_the_object_is_placed_and_what_it_cuts_off_is_waived():
    st = _state()
    obj = st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING], "floor", "place_wall", None, None)
    assert obj is not None  # not dropped: the walkways stay open
    cabinet = st.space.placed[0].nav
    assert st.nav.waived == [cabinet]
    assert st.unreached_since(st.snapshot()) == 0


def test_more_poses_are_asked_for_when_none_keeps_every_object_reachable():
    st = _state()
    asked = []

    def more():
        asked.append(True)
        return [WALLING, FREE]

    obj = st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING], "floor", "place_wall", None, None, more=more)
    assert asked and obj is not None and obj.position[0] > 3.0 and st.nav.waived == []


def test_restore_forgets_what_was_waived_after_the_snapshot():
    st = _state()
    snap = st.snapshot()
    st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING], "floor", "place_wall", None, None)
    assert st.unreached_since(snap) == 1
    st.restore(snap)
    assert st.nav.waived == [] and st.nav.ok() and len(st.space.placed) == 1


def test_a_pose_tried_and_given_up_takes_no_id_and_leaves_no_trace_on_the_walkways():
    st = _state()
    obj = st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING, FREE], "floor", "place_wall", None, None)
    assert obj is not None and obj.id == "r1-wardrobe-0"  # the walling pose was tried first, on the walkways alone
    plain = _state()
    plain.commit(WARDROBE, WARDROBE.size_m, FREE, "floor", "place_wall", None, None)
    assert np.array_equal(st.nav.walk, plain.nav.walk) and st.nav.obstacles == [p.nav for p in st.space.placed]
    assert st.nav.ok() and st.nav.waived == []


def test_footprint_is_what_commit_places():
    st = _state()
    corners, obs = st.footprint(WARDROBE, WARDROBE.size_m, FREE, "floor")
    obj = st.commit(WARDROBE, WARDROBE.size_m, FREE, "floor", "place_wall", None, None)
    p = st.space.placed[-1]
    assert p.obj is obj and np.array_equal(p.corners, corners) and p.nav is obs
    rug = item("rug", "rug", (2.0, 1.4, 0.01), "place_center")
    assert st.footprint(rug, rug.size_m, FREE, "floor")[1] is None  # walked over


def test_resume_comes_back_to_the_room_of_an_outcome():
    st = _state()
    snap = st.snapshot()
    st.commit_if_walkable(WARDROBE, WARDROBE.size_m, [WALLING], "floor", "place_wall", None, None)
    st.rng.random(3)
    kept = st.outcome()
    objs, walk, waived, draw = st.space.objects, st.nav.walk.copy(), list(st.nav.waived), st.rng.random()
    st.restore(snap)
    st.commit(WARDROBE, WARDROBE.size_m, FREE, "floor", "place_wall", None, None)  # another trial
    st.restore(snap)
    st.resume(kept)
    assert st.space.objects == objs and np.array_equal(st.nav.walk, walk) and st.nav.waived == waived
    assert st.counters == {"cabinet": 1, "wardrobe": 1} and st.rng.random() == draw
    assert st.unreached_since(snap) == 1
