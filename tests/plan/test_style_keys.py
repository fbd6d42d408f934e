"""The plan carries its style as knowledge keys, and those keys reach the assets."""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from anyhome.plan import get_planner
from anyhome.plan.appearance import look_for, room_materials, style_keys
from anyhome.plan.knowledge import knowledge_base, load
from anyhome.plan.spec import HouseSpec, RoomSpec

STYLES = load("styles")["styles"]


def _room(**kw) -> RoomSpec:
    return RoomSpec(**{"id": "r", "name": "room", "type": "bedroom", "area_m2": 10, **kw})


def test_offline_plan_carries_the_keys() -> None:
    import numpy as np

    spec = get_planner("offline").plan("a gothic victorian house with two bedrooms", np.random.default_rng(0))
    assert spec.styles == ["gothic", "victorian"]
    assert "gothic" in spec.style  # the words stay, for display


def test_spec_reads_keys_from_words_when_none_given() -> None:
    spec = HouseSpec(prompt="x", style="art deco, geometric and gilded", rooms=[_room()], connections=[("r", "outside")])
    assert spec.styles == ["art_deco"]
    spec = HouseSpec(prompt="x", style="plain", rooms=[_room()], connections=[("r", "outside")])
    assert spec.styles == []


def test_unknown_style_key_is_refused() -> None:
    with pytest.raises(ValidationError, match="unknown style 'gothik'"):
        HouseSpec(prompt="x", styles=["gothik"], rooms=[_room()], connections=[("r", "outside")])
    with pytest.raises(ValidationError, match="unknown style"):
        _room(styles=["nope"])


def test_room_styles_override_the_house() -> None:
    spec = HouseSpec(prompt="x", styles=["Art Deco"], connections=[("a", "outside"), ("a", "b")],
                     rooms=[_room(id="a", styles=["japanese"]), _room(id="b")])
    assert spec.styles == ["art_deco"]
    assert spec.styles_for("a") == ["japanese"] and spec.styles_for("b") == ["art_deco"]


@pytest.mark.parametrize("key", list(STYLES))
def test_every_style_key_reads_back(key: str) -> None:
    assert style_keys(key) == [key]
    assert style_keys(STYLES[key]["words"][0])[0] == key


def test_look_for_matches_the_planner() -> None:
    import numpy as np

    from anyhome.plan.appearance import choose_look
    from anyhome.plan.parse import parse

    look = choose_look(knowledge_base(), parse("a cottage"), [], "home", np.random.default_rng(0))
    same = look_for(look.styles)
    assert (same.describe, same.palette, same.floor, same.walls, same.furniture) == \
        (look.describe, look.palette, look.floor, look.walls, look.furniture)
    assert room_materials(same, "bathroom")["floor"] != same.floor  # wet rooms keep their floor
