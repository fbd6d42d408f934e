"""Play and lounging: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("hammock", "hammock", "hammock"),
    ("beanbag", "bean bag", "bean_bag"),
    ("", "beanbag chair", "bean_bag"),
    ("doll_house", "doll house", "doll_house"),
    ("", "dollhouse", "doll_house"),
    ("play_tent", "play tent", "play_tent"),
    ("", "teepee", "play_tent"),
    ("ball_pit", "ball pit", "ball_pit"),
    ("jungle_gym", "climbing frame", "climbing_frame"),
    ("", "jungle gym", "climbing_frame"),
    ("playground_slide", "playground slide", "playground_slide"),
    ("sandbox", "sandbox", "sandbox"),
    ("", "sandpit", "sandbox"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("doll_house", "floors", 2, 3),
        ("play_tent", "poles", 4, 6),
        ("ball_pit", "shape", "square", "round"),
        ("climbing_frame", "roof", True, False),
        ("playground_slide", "wavy", True, False),
        ("sandbox", "seats", True, False),
        ("hammock", "stripes", True, False),
        ("bean_bag", "slouch", 0.0, 1.0),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
