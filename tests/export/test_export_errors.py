"""Export errors reach the user as one AnyHomeError line."""

from __future__ import annotations

import pytest


def test_scene_errors_are_one_line_export_errors(small_house) -> None:
    """A reference broken after validation (a door to a room that is gone) used to reach
    the user as a bare KeyError from the renderer's scene builder."""
    from anyhome.errors import ExportError
    from anyhome.scene import build_scene

    small_house.doors[0] = small_house.doors[0].model_copy(update={"rooms": ("living", "attic")})
    with pytest.raises(ExportError, match=r"could not build the 3D scene: KeyError 'attic'"):
        build_scene(small_house, texture_px=16)
