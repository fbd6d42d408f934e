"""A dairy farm's things: names map to their families; knobs change the mesh; every
mesh is closed, fills its box and is the same for the same seed."""

from __future__ import annotations

import numpy as np
import pytest
from procedural_helpers import (
    assert_closed_in_box,
    assert_knob_changes_mesh,
    assert_maps,
    build_with,
)

from anyhome.assets.registry import typical_size

FAMILIES = ("milking_point", "cow_cubicle", "milk_tank")

CASES = [
    ("milking_point", "milking point", "milking_point"),
    ("", "milking unit", "milking_point"),
    ("cow_cubicle", "cow cubicle", "cow_cubicle"),
    ("", "freestall", "cow_cubicle"),
    ("milk_tank", "milk tank", "milk_tank"),
    ("", "bulk tank", "milk_tank"),
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
        ("milking_point", "herringbone", True, False),
        ("milking_point", "jar", True, False),
        ("cow_cubicle", "loop", True, False),
        ("cow_cubicle", "bedding", True, False),
        ("milk_tank", "upright", True, False),
        ("milk_tank", "cooler", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_a_parlour_point_hangs_four_teat_cups_below_its_meter() -> None:
    """The cluster hangs low at the pit edge: the mesh has parts below a third of its
    height in front of the rails, whatever the meter."""
    for jar in (True, False):
        m = build_with("milking_point", jar=jar)
        w, d, h = typical_size("milking_point")
        v = np.asarray(m.vertices)
        low_front = v[(v[:, 2] > 0.25 * h) & (v[:, 2] < 0.5 * h) & (v[:, 1] > 0.15 * d)]
        assert len(low_front) > 0
