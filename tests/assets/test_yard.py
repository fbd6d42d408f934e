"""Garden and yard: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("sun_lounger", "sun lounger", "sun_lounger"),
    ("", "deck chair", "sun_lounger"),
    ("pergola", "pergola", "pergola"),
    ("", "gazebo", "pergola"),
    ("surfboard", "surfboard", "surfboard"),
    ("beehive", "beehive", "beehive"),
    ("chicken_coop", "chicken coop", "chicken_coop"),
    ("", "hen house", "chicken_coop"),
    ("lawn_mower", "lawn mower", "lawn_mower"),
    ("", "lawnmower", "lawn_mower"),
    ("wheelbarrow", "wheelbarrow", "wheelbarrow"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("pergola", "vines", True, False),
        ("sun_lounger", "cushion", True, False),
        ("surfboard", "stripe", True, False),
        ("beehive", "kind", "boxes", "skep"),
        ("chicken_coop", "hens", 1, 3),
        ("lawn_mower", "bag", True, False),
        ("lawn_mower", "kind", "push", "ride_on"),
        ("wheelbarrow", "load", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
