"""Footprint figures (anyhome.evaluate.footprint): outline shapes, courtyard boundary
shares, and the window rule for walls onto an open-air courtyard."""

from __future__ import annotations

import pytest
from shapely.geometry import Polygon, box

from anyhome.evaluate.floorplan import check_windows
from anyhome.evaluate.footprint import courtyard_shares, footprint_shape
from anyhome.evaluate.plan_metrics import plan_metrics
from anyhome.house import Door, House, Room, Window
from anyhome.plan.knowledge import knowledge_base


def cells(*xy: tuple[int, int]) -> list[Polygon]:
    """Unit squares at the given cells."""
    return [box(x, y, x + 1, y + 1) for x, y in xy]


GRID3 = [(x, y) for x in range(3) for y in range(3)]


@pytest.mark.parametrize(("shape", "squares"), [
    ("rectangle", GRID3),
    ("L", [c for c in GRID3 if c != (2, 2)]),
    ("T", [c for c in GRID3 if c not in ((0, 0), (2, 0))]),
    ("U", [c for c in GRID3 if c != (1, 2)]),
    ("step", [c for c in GRID3 if c not in ((0, 0), (2, 2))]),
    ("courtyard", [c for c in GRID3 if c != (1, 1)]),
    ("other", [c for c in GRID3 if c not in ((0, 0), (2, 0), (0, 2), (2, 2))]),
])
def test_footprint_shapes(shape: str, squares: list[tuple[int, int]]) -> None:
    # 2 m cells: notches of 4 m2, well above the jog threshold
    assert footprint_shape([Polygon([(2 * x, 2 * y) for x, y in p.exterior.coords]) for p in cells(*squares)]) == shape


def test_courtyard_shares() -> None:
    rooms = {f"r{x}{y}": p for (x, y), p in zip(GRID3, cells(*GRID3))}
    assert courtyard_shares(rooms, ["r11"])["r11"] == pytest.approx(0.0)
    del rooms["r12"]  # open on its north side: a quarter of its perimeter
    assert courtyard_shares(rooms, ["r11"])["r11"] == pytest.approx(0.25, abs=0.01)
    assert courtyard_shares(rooms, ["r00"])["r00"] == pytest.approx(0.5, abs=0.01)


def _court_house(open_air: bool) -> House:
    rooms = [
        Room(id="bed", name="bedroom", type="bedroom", polygon=[(0, 0), (4, 0), (4, 4), (0, 4)]),
        Room(id="court", name="courtyard", type="courtyard", open_air=open_air,
             polygon=[(4, 0), (8, 0), (8, 4), (4, 4)]),
    ]
    doors = [Door(id="d0", rooms=("bed", "outside"), segment=((0, 1), (0, 2))),
             Door(id="d1", rooms=("bed", "court"), segment=((4, 0.5), (4, 1.5)))]
    windows = [Window(id="w0", room="bed", segment=((4, 2.5), (4, 3.5)))]
    return House(prompt="a house", seed=0, rooms=rooms, doors=doors, windows=windows, objects=[])


def test_a_window_may_look_onto_an_open_air_courtyard() -> None:
    assert check_windows(_court_house(open_air=True)) == []
    assert [v.code for v in check_windows(_court_house(open_air=False))] == ["window_off_boundary", "habitable_without_window"]


def _grid_around_court(prompt: str, missing: tuple[tuple[int, int], ...]) -> House:
    """4 m square bedrooms on a 3 x 3 grid less ``missing``, a courtyard in the middle."""
    cells = [(x, y) for x in range(3) for y in range(3) if (x, y) != (1, 1) and (x, y) not in missing]
    rooms = [Room(id=f"r{x}{y}", name="bedroom", type="bedroom", polygon=[(4 * x, 4 * y), (4 * x + 4, 4 * y),
                  (4 * x + 4, 4 * y + 4), (4 * x, 4 * y + 4)]) for x, y in cells]
    rooms.append(Room(id="court", name="courtyard", type="courtyard", open_air=True,
                      polygon=[(4, 4), (8, 4), (8, 8), (4, 8)]))
    return House(prompt=prompt, seed=0, rooms=rooms, objects=[],
                 doors=[Door(id="d0", rooms=("r00", "outside"), segment=((0, 1), (0, 2)))])


def test_plan_metrics_report_courtyards_and_footprint() -> None:
    m = plan_metrics(_grid_around_court("a riad", ()), knowledge_base())
    assert m.footprint == "courtyard"
    assert m.courtyard_shares == (pytest.approx(0.0),)
    assert m.n_courtyards_inside == 1 and m.n_courtyards_enclosed == 1


def test_a_courtyard_open_on_one_side_is_still_inside() -> None:
    house = _grid_around_court("a house around a courtyard", ((1, 2),))
    m = plan_metrics(house, knowledge_base())
    assert m.courtyard_shares == (pytest.approx(0.25, abs=0.01),)
    assert m.n_courtyards_inside == 1 and m.n_courtyards_enclosed == 0
    assert m.footprint == "courtyard"
    assert footprint_shape([Polygon(r.polygon) for r in house.rooms if not r.open_air]) == "U"
