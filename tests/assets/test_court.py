"""A courtroom's furniture and a lobby's security gate: names map to their families;
knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("judges_bench", "judge's bench", "judges_bench"),
    ("", "judges bench", "judges_bench"),
    ("witness_stand", "witness stand", "witness_stand"),
    ("", "witness box", "witness_stand"),
    ("jury_box", "jury box", "jury_box"),
    ("", "jury bench", "jury_box"),
    ("security_gate", "security scanner", "security_gate"),
    ("", "metal detector", "security_gate"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("judges_bench", "crest", True, False),
        ("judges_bench", "panels", 3, 5),
        ("witness_stand", "microphone", True, False),
        ("jury_box", "rows", 2, 3),
        ("jury_box", "seats", 5, 6),
        ("security_gate", "tray", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
