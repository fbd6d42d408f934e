"""A photography studio is a studio with a backdrop, studio lights and a camera, not a
darkroom (issue 15); the darkroom keeps its own word."""

from __future__ import annotations

import pytest
from planned import names_of, plan_of


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("text", ["a photography studio with a backdrop and lights", "A photo studio."])
def test_a_photography_studio_has_a_backdrop_and_studio_lights(text, seed):
    spec = plan_of(text, seed)
    studio = next(r for r in spec.rooms if "studio" in r.name)
    assert studio.type == "studio" and "dark" not in studio.name
    names = names_of(studio)
    assert "backdrop" in names
    assert sum(n == "studio light" for n in names) >= 2
    assert "camera tripod" in names
    assert not any("darkroom" in r.name or "enlarger" in names_of(r) for r in spec.rooms)


def test_a_darkroom_is_still_a_darkroom():
    spec = plan_of("a darkroom for developing film")
    assert any(r.name == "darkroom" for r in spec.rooms)
