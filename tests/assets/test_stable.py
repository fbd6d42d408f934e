"""A horse barn's things: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("hay_bale", "hay bale", "hay_bale"),
    ("", "straw bale", "hay_bale"),
    ("water_trough", "water trough", "water_trough"),
    ("", "automatic waterer", "water_trough"),
    ("manger", "hay rack", "manger"),
    ("", "manger", "manger"),
    ("hose_reel", "hose reel", "hose_reel"),
    ("", "hosepipe", "hose_reel"),
    ("saddle_rack", "saddle rack", "saddle_rack"),
    ("", "saddle stand", "saddle_rack"),
    ("feed_bin", "feed bin", "box"),
    ("coat_hook", "bridle hooks", "coat_hook"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("hay_bale", "round", True, False),
        ("hay_bale", "ties", 2, 3),
        ("water_trough", "feed", True, False),
        ("water_trough", "valve", True, False),
        ("water_trough", "legs", True, False),
        ("hose_reel", "cart", True, False),
        ("hose_reel", "wound", 4, 7),
        ("saddle_rack", "saddle", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_a_saddle_cloth_shows_under_a_saddle() -> None:
    assert_knob_changes_mesh("saddle_rack", "pad", True, False, saddle=True)
