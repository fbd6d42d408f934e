"""Booths, pods and enclosures: names map to their families; knobs change the mesh."""

from __future__ import annotations

import numpy as np
import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

from anyhome.assets.registry import get

CASES = [
    ("golf_simulator", "golf simulator", "golf_simulator"),
    ("photobooth", "photo booth", "photo_booth"),
    ("", "photobooth", "photo_booth"),
    ("cubicle", "cubicle", "cubicle"),
    ("phone_booth", "phone booth", "phone_booth"),
    ("", "telephone booth", "phone_booth"),
    ("", "phone pod", "phone_booth"),
    ("sleeping_pod", "sleeping pod", "sleeping_pod"),
    ("", "capsule bed", "sleeping_pod"),
    ("dj_booth", "dj booth", "dj_booth"),
    ("", "dj table", "dj_booth"),
    ("vocal_booth", "vocal booth", "vocal_booth"),
    ("", "recording booth", "vocal_booth"),
    ("elevator", "elevator", "elevator"),
    ("ticket_booth", "ticket booth", "ticket_booth"),
    ("", "box office", "ticket_booth"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("phone_booth", "kind", "telephone", "pod"),
        ("vocal_booth", "window", True, False),
        ("ticket_booth", "roof", "peaked", "flat"),
        ("cubicle", "sides", 2, 3),
        ("sleeping_pod", "curtain", True, False),
        ("elevator", "kind", "doors", "cage"),
        ("golf_simulator", "bag", True, False),
        ("dj_booth", "front", "bars", "grid"),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_style_picks_the_phone_box() -> None:
    """Victorian asks for the red telephone box, modern for the office pod."""
    size = (1.0, 1.0, 2.2)
    assert get("phone_booth").sample(np.random.default_rng(0), size, "victorian").kind == "telephone"
    assert get("phone_booth").sample(np.random.default_rng(0), size, "modern").kind == "pod"
