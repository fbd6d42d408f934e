"""Beds: a floor futon reads as a futon (a thin mattress on the floor), not a bed frame."""

from __future__ import annotations

from procedural_helpers import assert_knob_changes_mesh, assert_maps, build_with

CASES = [
    ("floor_futon", "futon", "floor_futon"),
    ("", "futon mattress", "floor_futon"),
    ("", "shikibuton", "floor_futon"),
    ("bed", "double bed", "bed"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


def test_a_floor_futon_lies_on_the_floor_whatever_its_box() -> None:
    m = build_with("floor_futon", size=(1.0, 2.05, 0.15))
    assert m.bounds[0][2] >= -1e-6 and m.bounds[1][2] <= 0.15 + 1e-6
    assert abs((m.bounds[1][1] - m.bounds[0][1]) - 2.05) < 0.02  # the full length of a sleeper


def test_knob_changes_mesh() -> None:
    assert_knob_changes_mesh("floor_futon", "fold", 0.0, 0.25)
