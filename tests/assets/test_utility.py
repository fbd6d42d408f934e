"""Household and building utilities: names map to their families; knobs change the mesh."""

from __future__ import annotations

import numpy as np
import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

from anyhome.assets.registry import get

CASES = [
    ("safe", "strongbox", "safe"),
    ("", "gun safe", "safe"),
    ("acoustic_panel", "acoustic panel", "acoustic_panel"),
    ("", "acoustic foam", "acoustic_panel"),
    ("wall_sconce", "wall sconce", "wall_sconce"),
    ("", "wall lamp", "wall_sconce"),
    ("ladder", "ladder", "ladder"),
    ("", "stepladder", "ladder"),
    ("coat_hook", "coat hook", "coat_hook"),
    ("", "peg rail", "coat_hook"),
    ("mailbox", "mailbox", "mailbox"),
    ("", "letterbox", "mailbox"),
    ("ironing_board", "ironing board", "ironing_board"),
    ("towel_rack", "towel rack", "towel_rack"),
    ("", "heated towel rail", "towel_rack"),
    ("urinal", "urinal", "urinal"),
    ("water_heater", "water heater", "water_heater"),
    ("", "boiler", "water_heater"),
    ("generator", "generator", "generator"),
    ("air_conditioner", "air conditioner", "air_conditioner"),
    ("", "ac unit", "air_conditioner"),
    ("radiator", "radiator", "radiator"),
    ("trash_can", "trash can", "trash_can"),
    ("", "recycling bin", "trash_can"),
    ("room_divider", "room divider", "room_divider"),
    ("", "folding screen", "room_divider"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


def test_a_plain_bin_is_still_a_box() -> None:
    """Only bins named for rubbish are trash cans; a storage bin stays a box."""
    from anyhome.assets.registry import family_for

    assert family_for("", "storage bin") == "box"
    assert family_for("", "bin") == "box"


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("radiator", "kind", "column", "panel"),
        ("water_heater", "gas", True, False),
        ("air_conditioner", "flap", 0.2, 0.7),
        ("generator", "wheels", True, False),
        ("trash_can", "kind", "pedal", "swing"),
        ("trash_can", "kind", "basket", "wheelie"),
        ("ironing_board", "iron", True, False),
        ("towel_rack", "kind", "rail", "ladder"),
        ("urinal", "valve", True, False),
        ("ladder", "kind", "leaning", "step"),
        ("coat_hook", "kind", "hooks", "pegs"),
        ("mailbox", "kind", "letterbox", "pigeonholes"),
        ("wall_sconce", "kind", "shade", "candle"),
        ("wall_sconce", "kind", "torch", "cylinder"),
        ("room_divider", "kind", "fabric", "shoji"),
        ("room_divider", "panels", 3, 5),
        ("safe", "lock", "dial", "keypad"),
        ("acoustic_panel", "kind", "foam", "slats"),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_a_deep_box_gets_a_stepladder() -> None:
    fam = get("ladder")
    assert fam.sample(np.random.default_rng(0), (0.45, 0.3, 2.2), "").kind == "leaning"
    assert fam.sample(np.random.default_rng(0), (0.5, 0.9, 1.5), "").kind == "step"
