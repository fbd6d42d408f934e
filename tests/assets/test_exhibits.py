"""Exhibits and wall features: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("dartboard", "dartboard", "dartboard"),
    ("", "dart board", "dartboard"),
    ("spinner_rack", "spinner rack", "spinner_rack"),
    ("", "postcard rack", "spinner_rack"),
    ("barber_pole", "barber pole", "barber_pole"),
    ("mounted_antlers", "mounted antlers", "mounted_antlers"),
    ("", "deer head", "mounted_antlers"),
    ("plinth", "plinth", "plinth"),
    ("", "display pedestal", "plinth"),
    ("model_ship", "model ship", "model_ship"),
    ("", "ship in a bottle", "model_ship"),
    ("sarcophagus", "sarcophagus", "sarcophagus"),
    ("", "coffin", "sarcophagus"),
    ("rope_barrier", "rope barrier", "rope_barrier"),
    ("", "velvet rope", "rope_barrier"),
    ("cannon", "cannon", "cannon"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("plinth", "kind", "classic", "column"),
        ("plinth", "kind", "classic", "modern"),
        ("model_ship", "masts", 2, 3),
        ("sarcophagus", "kind", "egyptian", "stone"),
        ("sarcophagus", "kind", "stone", "coffin"),
        ("rope_barrier", "kind", "rope", "belt"),
        ("cannon", "kind", "field", "naval"),
        ("spinner_rack", "tiers", 4, 6),
        ("mounted_antlers", "kind", "head", "antlers"),
        ("barber_pole", "blue", True, False),
        ("dartboard", "darts", 0, 3),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
