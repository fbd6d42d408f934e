"""Clinic equipment: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("wheelchair", "wheelchair", "wheelchair"),
    ("medical_cart", "medical cart", "medical_cart"),
    ("", "crash cart", "medical_cart"),
    ("xray_machine", "x-ray machine", "xray_machine"),
    ("", "x-ray machine", "xray_machine"),
    ("xray_machine", "mri scanner", "medical_scanner"),
    ("xray_machine", "ct scanner", "medical_scanner"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("wheelchair", "spokes", 8, 12),
        ("medical_cart", "monitor", True, False),
        ("medical_cart", "drawers", 4, 6),
        ("xray_machine", "wall_stand", True, False),
        ("medical_scanner", "kind", "mri", "ct"),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
