"""A distribution warehouse's things and a lab's: names map to their families; knobs
change the mesh; every mesh is closed, fills its box and is the same for the same seed."""

from __future__ import annotations

import pytest
from procedural_helpers import (
    assert_closed_in_box,
    assert_knob_changes_mesh,
    assert_maps,
)

FAMILIES = ("dock_leveller", "roller_shutter", "battery_charger", "autoclave", "gas_tap")

CASES = [
    ("dock_leveller", "dock leveller", "dock_leveller"),
    ("", "dock leveler", "dock_leveller"),
    ("roller_shutter", "roller shutter door", "roller_shutter"),
    ("", "roller shutter", "roller_shutter"),
    ("battery_charger", "battery charger", "battery_charger"),
    ("", "forklift charger", "battery_charger"),
    ("autoclave", "autoclave", "autoclave"),
    ("", "steam steriliser", "autoclave"),
    ("gas_tap", "gas tap", "gas_tap"),
    ("biosafety_cabinet", "biosafety cabinet", "fume_hood"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", [0, 3])
def test_closed_in_its_box_and_deterministic(family: str, seed: int) -> None:
    assert_closed_in_box(family, seed)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("dock_leveller", "lip_up", True, False),
        ("dock_leveller", "bumpers", True, False),
        ("roller_shutter", "open_share", 0.0, 0.5),
        ("roller_shutter", "vision", True, False),
        ("battery_charger", "cable", True, False),
        ("battery_charger", "plinth", True, False),
        ("autoclave", "top_loading", True, False),
        ("autoclave", "gauges", 1, 2),
        ("gas_tap", "double", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
