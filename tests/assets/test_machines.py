"""Workshop and lab machines: names map to their families; knobs change the mesh."""

from __future__ import annotations

import pytest
from procedural_helpers import assert_knob_changes_mesh, assert_maps

CASES = [
    ("microscope", "microscope", "microscope"),
    ("bunsen_burner", "bunsen burner", "bunsen_burner"),
    ("centrifuge", "centrifuge", "centrifuge"),
    ("3d_printer", "3d printer", "3d_printer"),
    ("", "3-d printer", "3d_printer"),
    ("laser_cutter", "laser cutter", "laser_cutter"),
    ("", "laser engraver", "laser_cutter"),
    ("cnc_machine", "cnc machine", "cnc_machine"),
    ("", "milling machine", "cnc_machine"),
    ("bandsaw", "bandsaw", "bandsaw"),
    ("", "band saw", "bandsaw"),
    ("drill_press", "drill press", "drill_press"),
    ("", "pillar drill", "drill_press"),
    ("lathe", "lathe", "lathe"),
    ("", "wood lathe", "lathe"),
]


def test_names_map_to_families() -> None:
    assert_maps(CASES)


@pytest.mark.parametrize(
    ("family", "knob", "a", "b"),
    [
        ("lathe", "work", "wood", "metal"),
        ("drill_press", "table", "round", "square"),
        ("bandsaw", "stand", "cabinet", "legs"),
        ("cnc_machine", "kind", "router", "mill"),
        ("3d_printer", "kind", "open", "enclosed"),
        ("bunsen_burner", "flame", True, False),
        ("centrifuge", "open", True, False),
    ],
)
def test_knob_changes_mesh(family: str, knob: str, a, b) -> None:
    assert_knob_changes_mesh(family, knob, a, b)
