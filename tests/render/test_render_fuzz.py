"""Malformed houses that load must render or fail with one RenderError line (a smaller
sample than tests/fuzz: a render takes longer). Needs EGL, like the other render tests."""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "fuzz"))
from house_mutants import mutant, odd_geometry  # noqa: E402
from test_house_fuzz import base, one_line  # noqa: E402

from anyhome.errors import AnyHomeError, HouseFormatError  # noqa: E402
from anyhome.house import House  # noqa: E402


def _render(text: str) -> None:
    from anyhome.render import render_house

    try:
        house = House.from_json(text)
    except HouseFormatError as e:
        one_line(e)
        return
    with tempfile.TemporaryDirectory() as tmp:
        try:
            render_house(house, tmp, size_px=32, view_size_px=16, supersample=1)
        except AnyHomeError as e:
            one_line(e)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_render_malformed_house(gl_available, data) -> None:
    text, _ = data.draw(odd_geometry(base("two_rooms")) | mutant(base("two_rooms")))
    _render(text)
