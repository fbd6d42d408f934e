"""Crafts and trades: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("anvil", "anvil", "anvil"),
    ("forge", "forge", "forge"),
    ("", "blacksmith forge", "forge"),
    ("pegboard", "pegboard", "pegboard"),
    ("", "tool wall", "pegboard"),
    ("loom", "weaving loom", "loom"),
    ("", "weaving loom", "loom"),
    ("spinning_wheel", "spinning wheel", "spinning_wheel"),
    ("kiln", "kiln", "kiln"),
    ("pottery_wheel", "pottery wheel", "pottery_wheel"),
    ("", "potter's wheel", "pottery_wheel"),
    ("printing_press", "printing press", "printing_press"),
    ("", "letterpress", "printing_press"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("kiln", "kind", "electric", "brick"),
        ("forge", "blower", True, False),
        ("anvil", "stump", True, False),
        ("pottery_wheel", "seat", True, False),
        ("printing_press", "kind", "wooden", "iron"),
        ("loom", "harnesses", 2, 4),
        ("spinning_wheel", "spokes", 8, 12),
        ("pegboard", "spacing", 0.05, 0.075),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
