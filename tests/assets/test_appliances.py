"""Appliances: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps, build_with

CASES = [
    ("beer_tap", "beer tap", "beer_tap"),
    ("beer_tap", "draft tower", "beer_tap"),
    ("dishwasher", "dishwasher", "dishwasher"),
    ("", "dish washer", "dishwasher"),
    ("microwave", "microwave", "microwave"),
    ("", "microwave oven", "microwave"),
    ("dough_mixer", "dough mixer", "dough_mixer"),
    ("coffee_roaster", "coffee roaster", "coffee_roaster"),
    ("popcorn_machine", "popcorn machine", "popcorn_machine"),
    ("printer", "printer", "printer"),
    ("", "laser printer", "printer"),
    ("photocopier", "photocopier", "photocopier"),
    ("", "copy machine", "photocopier"),
    ("water_cooler", "water cooler", "water_cooler"),
    ("", "water dispenser", "water_cooler"),
    ("projector", "projector", "projector"),
    ("record_player", "record player", "record_player"),
    ("", "turntable", "record_player"),
    ("radio", "radio", "radio"),
    ("typewriter", "typewriter", "typewriter"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("dishwasher", "handle", "bar", "pocket"),
        ("microwave", "dials", True, False),
        ("printer", "feeder", True, False),
        ("photocopier", "drawers", 2, 4),
        ("water_cooler", "bottle", True, False),
        ("beer_tap", "tower", "tee", "pillars"),
        ("beer_tap", "taps", 3, 6),
        ("projector", "kind", "video", "film"),
        ("record_player", "kind", "turntable", "gramophone"),
        ("radio", "kind", "transistor", "cathedral"),
        ("typewriter", "paper", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)


def test_antique_style_picks_old_forms() -> None:
    """A victorian radio is an arched cathedral set; a tall victorian record player is a
    gramophone with a horn."""
    import numpy as np

    from anyhome.assets.registry import get

    assert get("radio").sample(np.random.default_rng(0), (0.35, 0.2, 0.25), "victorian").kind == "cathedral"
    assert get("radio").sample(np.random.default_rng(0), (0.35, 0.2, 0.25), "modern").kind == "transistor"
    rp = get("record_player").sample(np.random.default_rng(0), (0.45, 0.45, 0.6), "victorian")
    assert rp.kind == "gramophone"
    assert build_with("record_player", size=(0.45, 0.45, 0.6), style="victorian").faces.shape[0] > 0
