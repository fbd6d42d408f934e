"""Gym and gymnastics equipment: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("rowing_machine", "rowing machine", "rowing_machine"),
    ("", "rower", "rowing_machine"),
    ("stair_climber", "stair climber", "stair_climber"),
    ("", "stairmaster", "stair_climber"),
    ("cable_machine", "cable machine", "cable_machine"),
    ("", "cable crossover", "cable_machine"),
    ("leg_press", "leg press", "leg_press"),
    ("ballet_barre", "ballet barre", "ballet_barre"),
    ("", "barre", "ballet_barre"),
    ("pommel_horse", "pommel horse", "pommel_horse"),
    ("", "vaulting horse", "pommel_horse"),
    ("parallel_bars", "parallel bars", "parallel_bars"),
    ("trampoline", "trampoline", "trampoline"),
    ("wall_bars", "wall bars", "wall_bars"),
    ("", "swedish ladder", "wall_bars"),
    ("pull_up_bar", "pull-up bar", "pull_up_bar"),
    ("", "chin up bar", "pull_up_bar"),
    ("dance_pole", "dance pole", "dance_pole"),
    ("basketball_hoop", "basketball hoop", "basketball_hoop"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("rowing_machine", "kind", "air", "water"),
        ("stair_climber", "steps", 5, 7),
        ("cable_machine", "shrouds", True, False),
        ("leg_press", "plates", 2, 4),
        ("ballet_barre", "kind", "wall", "free"),
        ("pommel_horse", "pommels", True, False),
        ("parallel_bars", "mats", True, False),
        ("wall_bars", "spacing", 0.14, 0.16),
        ("pull_up_bar", "grips", True, False),
        ("dance_pole", "stage", True, False),
        ("basketball_hoop", "ball", True, False),
        ("trampoline", "legs", 4, 8),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
