"""Arms of an open-plan L room (anyhome.layout.zones) and the layout of such a room."""

from __future__ import annotations

import pytest
from shapely.geometry import Polygon

import anyhome
from anyhome.house import Room
from anyhome.layout.zones import arm_zones, reflex_corner
from anyhome.plan.spec import RoomSpec

L_OUTLINE = [(0.0, 0.0), (8.0, 0.0), (8.0, 3.0), (5.0, 3.0), (5.0, 4.0), (0.0, 4.0)]


def _planned(area_a: float, area_b: float) -> list[RoomSpec]:
    return [RoomSpec(id="a", name="a", type="living_room", area_m2=area_a),
            RoomSpec(id="b", name="b", type="dining_room", area_m2=area_b)]


def test_the_inner_corner_of_an_l() -> None:
    assert reflex_corner(L_OUTLINE) == (5.0, 3.0)
    assert reflex_corner([(0, 0), (1, 0), (1, 1), (0, 1)]) is None


@pytest.mark.parametrize(("areas", "first_is_big"), [((20, 9), True), ((9, 20), False)])
def test_arms_split_the_l_at_its_inner_corner(areas: tuple[float, float], first_is_big: bool) -> None:
    room = Room(id="a", name="a", type="living_room", polygon=L_OUTLINE, merged=["b"])
    arms = arm_zones(room, _planned(*areas))
    assert arms is not None and len(arms) == 2
    assert sum(a.area for a in arms) == pytest.approx(Polygon(L_OUTLINE).area)
    assert arms[0].union(arms[1]).equals(Polygon(L_OUTLINE))
    assert (arms[0].area > arms[1].area) == first_is_big
    # the squarer cut: x = 5 (5 x 4 and 3 x 3), not y = 3 (8 x 3 and 5 x 1)
    assert sorted(a.bounds for a in arms) == [(0.0, 0.0, 5.0, 4.0), (5.0, 0.0, 8.0, 3.0)]


def test_a_rectangle_has_no_arms() -> None:
    room = Room(id="a", name="a", type="living_room", polygon=[(0, 0), (4, 0), (4, 3), (0, 3)])
    assert arm_zones(room, _planned(10, 5)) is None


def test_relayout_of_an_l_room_lays_out_both_planned_rooms_again() -> None:
    house = anyhome.generate("An open-plan two-bedroom apartment with a living room, a dining room and a kitchen.",
                             seed=0)
    (room,) = [r for r in house.rooms if r.merged]
    again = anyhome.relayout(house, [room.id], seed=3)
    names = {o.name for o in again.objects_in(room.id)}
    assert "dining table" in names
    assert not any(d.reason == "room is missing from the floorplan" for d in again.dropped)
