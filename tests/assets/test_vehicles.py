"""Things that move: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("boat", "boat", "boat"),
    ("", "rowing boat", "boat"),
    ("", "dinghy", "boat"),
    ("kayak", "kayak", "kayak"),
    ("canoe", "canoe", "kayak"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b", "fixed"),
    [
        ("boat", "kind", "rowing", "motor", {}),
        ("boat", "oars", True, False, {"kind": "rowing"}),  # a motor boat carries no oars
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b, fixed) -> None:
    assert_knob_changes_mesh(family, knob, a, b, **fixed)
