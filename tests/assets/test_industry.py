"""Brewery, warehouse and factory: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("fermentation_tank", "fermentation tank", "fermentation_tank"),
    ("", "fermenter", "fermentation_tank"),
    ("brew_kettle", "brew kettle", "brew_kettle"),
    ("", "mash tun", "brew_kettle"),
    ("pallet", "shipping pallet", "pallet"),
    ("", "euro pallet", "pallet"),
    ("forklift", "forklift", "forklift"),
    ("conveyor_belt", "conveyor belt", "conveyor_belt"),
    ("", "conveyor", "conveyor_belt"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


def test_pallet_rack_is_still_a_shelf() -> None:
    from anyhome.assets.registry import family_for

    assert family_for("", "pallet rack") == "shelf"


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("fermentation_tank", "legs", 3, 4),
        ("brew_kettle", "kind", "copper", "steel"),
        ("forklift", "forks_up", 0.0, 0.3),
        ("conveyor_belt", "kind", "belt", "rollers"),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_a_tall_box_holds_a_stack_of_pallets() -> None:
    from procedural_helpers import build_with

    one = build_with("pallet", size=(1.2, 1.0, 0.15), load=False)
    stack = build_with("pallet", size=(1.2, 1.0, 0.6), load=False)
    assert len(stack.faces) > 3 * len(one.faces)
