"""Instruments, stage and chapel fittings: names map to their families; knobs change the mesh."""

from __future__ import annotations

import numpy as np
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
    ("music_stand", "music stand", "music_stand"),
    ("", "sheet music stand", "music_stand"),
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
        ("music_stand", "sheet", True, False),
        ("music_stand", "tilt", 0.25, 0.45),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_a_music_stands_desk_faces_its_player_at_the_front() -> None:
    """The desk leans back from the front (+y), where the chair of its group stands: the
    top of the desk lies behind (at lower y than) its ledge."""
    from procedural_helpers import build_with

    m = build_with("music_stand", size=(0.5, 0.4, 1.2), tilt=0.4, sheet=False)
    top = m.vertices[m.vertices[:, 2] > m.bounds[1][2] - 0.02]
    ledge_z = m.bounds[1][2] - 0.36 * np.cos(0.4)
    ledge = m.vertices[np.abs(m.vertices[:, 2] - ledge_z) < 0.03]
    assert top[:, 1].mean() < ledge[:, 1].max()
