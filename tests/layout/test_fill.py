"""Zones for under-furnished rooms (anyhome.layout.fill): placed while the floor is bare,
stopped once covered, never reported as dropped, away from the furniture already there."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Polygon

from anyhome.geometry import footprint_polygon
from anyhome.layout import layout_house
from anyhome.layout.fill import FILL_COVERAGE, FILL_MIN_AREA_M2
from tests.layout.helpers import check_valid, group, house_spec, item, rect, single_room

SOFA = item("sofa", "sofa", (2.1, 0.9, 0.85), "place_wall", params={"wall": "longest"}, tags=["seat"])
CHAIR = item("reading chair", "armchair", (0.85, 0.85, 0.9), "place_corner", tags=["seat"])
LAMP = item("reading lamp", "floor_lamp", (0.4, 0.4, 1.6), "place_beside", params={"side": "left"})
CABINET = item("display cabinet", "cabinet", (1.0, 0.45, 1.8), "place_wall", tags=["storage"])
BIG = item("grand table", "table", (3.0, 3.0, 0.75), "place_center", tags=["table"])


def _zones(*anchors, repeat=1):
    return [group(f"zone{i}", a, [LAMP] if a is CHAIR else [], fill=True, priority=7, repeat=repeat)
            for i, a in enumerate(anchors)]


def _covered(fp, objects):
    room = Polygon(fp.rooms[0].polygon)
    feet = [footprint_polygon(o.position, o.size, o.yaw) for o in objects if o.support == "floor"]
    return sum(f.area for f in feet) / room.area


def _lay(polygon, groups, seed=0):
    fp = single_room(polygon)
    res = layout_house(house_spec({"r1": groups}), fp, np.random.default_rng(seed))
    return fp, res


@pytest.mark.parametrize("seed", range(3))
def test_a_bare_large_room_gets_zones_until_covered(seed):
    fp, res = _lay(rect(0, 0, 6.0, 5.0), [group("lounge", SOFA), *_zones(CHAIR, CABINET, CHAIR, CABINET)], seed)
    assert check_valid(fp, res.objects) == []
    names = [o.name for o in res.objects]
    assert "sofa" in names and "reading chair" in names
    assert res.dropped == []
    # each zone was placed while the floor was under-covered: without the last one it is
    last = res.objects[-1].group
    assert last.startswith("zone")
    assert _covered(fp, [o for o in res.objects if o.group != last]) < FILL_COVERAGE


def test_zones_stop_once_the_floor_is_covered():
    """A room already covered past FILL_COVERAGE gets none of its zones."""
    fp, res = _lay(rect(0, 0, 4.0, 4.0), [group("table", BIG), *_zones(CHAIR, CABINET)])
    assert _covered(fp, [o for o in res.objects if o.name == "grand table"]) >= FILL_COVERAGE
    assert [o.name for o in res.objects] == ["grand table"]
    assert res.dropped == []


def test_a_small_room_gets_no_zones():
    side = (FILL_MIN_AREA_M2 - 1.0) ** 0.5
    fp, res = _lay(rect(0, 0, side, side), _zones(CHAIR, CABINET))
    assert res.objects == [] and res.dropped == []


def test_a_zone_that_does_not_fit_is_left_out_without_a_warning():
    huge = item("huge cabinet", "cabinet", (9.0, 0.5, 1.8), "place_wall", tags=["storage"])
    fp, res = _lay(rect(0, 0, 5.0, 4.0), [group("lounge", SOFA), *_zones(huge)])
    assert [o.name for o in res.objects] == ["sofa"]
    assert res.dropped == []


def test_a_large_room_goes_round_its_zones_again():
    """A 120 m2 hall with one zone offered gets several copies of it, each its own group copy."""
    fp, res = _lay(rect(0, 0, 12.0, 10.0), _zones(CHAIR))
    chairs = [o for o in res.objects if o.name == "reading chair"]
    assert len(chairs) >= 2
    assert len({o.group for o in chairs}) == len(chairs)
    assert check_valid(fp, res.objects) == []


def test_a_zone_is_drawn_away_from_the_furniture_there():
    """A conversation table is placed in the free half of the room, not against the sofa's."""
    table = item("round side table", "side_table", (0.6, 0.6, 0.55), "place_center", tags=["table"])
    far = []
    for seed in range(4):
        fp, res = _lay(rect(0, 0, 8.0, 5.0), [group("lounge", SOFA), *_zones(table)], seed)
        sofa = next(o for o in res.objects if o.name == "sofa")
        t = next(o for o in res.objects if o.name == "round side table")
        gap = footprint_polygon(sofa.position, sofa.size, sofa.yaw).distance(
            footprint_polygon(t.position, t.size, t.yaw))
        far.append(gap)
    assert min(far) >= 1.5, far
