"""Kitchen run plans (anyhome.layout.kitchen_plan): shapes a room allows, the order they
are tried in, and the fill of one run (appliances apart, counters in every gap)."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.house import Door, Floorplan, Room, Window
from anyhome.layout.kitchen_plan import (
    LANDING_M,
    MIN_COUNTER_M,
    _gaps_ok,
    _stove_options,
    plan_run,
    run_shapes,
    shape_order,
)
from anyhome.space import RoomSpace

from .helpers import rect

WIDTHS = {"fridge": 0.8, "sink": 0.8, "stove": 0.7}


def space(w, h, door=((1.0, 0.0), (1.9, 0.0)), windows=()):
    room = Room(id="k", name="kitchen", type="kitchen", polygon=rect(0, 0, w, h), height=2.7)
    fp = Floorplan(rooms=[room], doors=[Door(id="d0", rooms=("k", "outside"), segment=door)],
                   windows=[Window(id=f"w{i}", room="k", segment=s) for i, s in enumerate(windows)],
                   connections=[("k", "outside")])
    return RoomSpace(fp, room)


def test_shapes_a_room_allows():
    narrow = {s.shape for s in run_shapes(space(2.3, 4.5, door=((0.7, 0.0), (1.6, 0.0))), 0.6, 0.7, 1.8, None)}
    assert "galley" in narrow and "U" not in narrow  # 2.3 - 1.2 leaves a 1.1 m aisle, too narrow for a U
    wide = {s.shape for s in run_shapes(space(4.0, 5.0), 0.6, 0.7, 1.8, None)}
    assert {"one", "L", "U"} <= wide and "galley" not in wide  # 2.8 m between the runs is no galley
    capped = run_shapes(space(4.0, 5.0), 0.6, 0.7, 1.8, 3.0)
    assert {s.shape for s in capped} <= {"one", "L"} and all(s.length_m <= 3.0 + 0.6 + 1e-6 for s in capped)


@pytest.mark.parametrize("short, open_plan, more, first", [
    (2.0, False, False, "L"), (2.4, False, False, "galley"), (3.0, False, False, "L"),
    (4.0, False, False, "U"), (4.0, False, True, "L"), (4.0, True, False, "L"),
])
def test_shape_order_by_room_width(short, open_plan, more, first):
    assert shape_order(short, open_plan, more)[0] == first


def test_gaps_between_appliances_hold_a_counter():
    sp = space(3.0, 5.0)
    leg = max((s for s in run_shapes(sp, 0.6, 0.7, 1.8, None) if s.shape == "one"), key=lambda s: s.length_m).legs[0]
    t = leg.t0
    assert _gaps_ok(leg, [("fridge", t, t + 0.8), ("sink", t + 0.8 + LANDING_M, t + 1.6 + LANDING_M)])
    assert not _gaps_ok(leg, [("fridge", t, t + 0.8), ("sink", t + 0.8, t + 1.6)])  # side by side
    assert not _gaps_ok(leg, [("stove", t, t + 0.7)])  # a cooktop at a run end has no landing
    assert not _gaps_ok(leg, [("sink", t + MIN_COUNTER_M / 2, t + 0.8 + MIN_COUNTER_M / 2)])  # a sliver


def test_a_plan_fills_the_run_and_puts_the_sink_under_the_window():
    sp = space(3.0, 5.0, windows=[((3.0, 2.0), (3.0, 3.2))])
    for shape in (s for s in run_shapes(sp, 0.6, 0.7, 1.8, None) if s.shape == "L"):
        slots = plan_run(sp, shape, WIDTHS)
        assert slots is not None
        for i, leg in enumerate(shape.legs):  # pieces tile each leg end to end
            mine = sorted((s.t0, s.t1) for s in slots if s.leg == i)
            assert abs(mine[0][0] - leg.t0) < 1e-6 and abs(mine[-1][1] - leg.t1) < 1e-6
            assert all(abs(a[1] - b[0]) < 1e-6 for a, b in zip(mine, mine[1:]))
        assert sorted(s.role for s in slots if s.role != "counter") == ["fridge", "sink", "stove"]
        on_window_wall = any(leg.wall.index == 1 for leg in shape.legs)
        sink = next(s for s in slots if s.role == "sink")
        if on_window_wall:
            assert shape.legs[sink.leg].wall.index == 1 and 2.0 <= (sink.t0 + sink.t1) / 2 <= 3.2


@pytest.mark.parametrize("landing", [LANDING_M, 0.0])
def test_stove_positions_are_those_every_gap_rule_allows(landing):
    # positions beside an appliance are ruled out before the gap rules are asked: the
    # same positions as asking the rules of every one
    sp = space(4.0, 3.0)
    for shape in run_shapes(sp, 0.6, 0.7, 0.9, None):
        for fixed in ([], [(0, "fridge", shape.legs[0].t0, shape.legs[0].t0 + 0.8)],
                      [(0, "fridge", shape.legs[0].t0, shape.legs[0].t0 + 0.8),
                       (len(shape.legs) - 1, "sink", shape.legs[-1].t1 - 1.7, shape.legs[-1].t1 - 0.9)]):
            want = []
            for i, leg in enumerate(shape.legs):
                for t0 in np.arange(leg.lo, leg.hi - 0.7 + 1e-6, 0.1):
                    p = (i, "stove", float(t0), float(t0) + 0.7)
                    if _gaps_ok(leg, [x[1:] for x in (*fixed, p) if x[0] == i], landing):
                        want.append(p)
            got = [p for _, p in _stove_options(shape, WIDTHS, fixed, landing)]
            assert got == want
