"""Instruments, stage and chapel fittings: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("pipe_organ", "pipe organ", "pipe_organ"),
    ("", "church organ", "pipe_organ"),
    ("votive_stand", "votive stand", "votive_stand"),
    ("", "candle rack", "votive_stand"),
    ("gong", "gong", "gong"),
    ("stage_light", "stage light", "stage_light"),
    ("lamp", "stage light", "stage_light"),
    ("", "par can", "stage_light"),
    ("harp", "harp", "harp"),
    ("", "celtic harp", "harp"),
    ("marimba", "marimba", "marimba"),
    ("", "xylophone", "marimba"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("harp", "strings", 26, 38),
        ("marimba", "octaves", 3, 5),
        ("pipe_organ", "manuals", 2, 3),
        ("pipe_organ", "towers", 3, 5),
        ("gong", "boss", True, False),
        ("stage_light", "kind", "par", "fresnel"),
        ("stage_light", "kind", "par", "moving"),
        ("votive_stand", "tiers", 3, 4),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
