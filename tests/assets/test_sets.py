"""Matched sets (anyhome.assets.sets): copies of one item in one group look alike, in a
generated house and after a restyle; words asking for variety keep them apart."""

from __future__ import annotations

from anyhome.assets.sets import set_key
from anyhome.house import HouseObject
from anyhome.pipeline import generate
from anyhome.restyle import restyle


def _looks(house, name):
    return {repr(sorted((k, v) for k, v in o.asset["params"].items() if k != "size"))
            for o in house.objects if o.name == name}


def test_dining_chairs_are_one_set_before_and_after_a_restyle():
    house = generate("a dining room with a dining table and eight dining chairs", seed=3)
    assert sum(o.name == "dining chair" for o in house.objects) >= 4
    assert len(_looks(house, "dining chair")) == 1
    assert len(_looks(restyle(house, "gothic"), "dining chair")) == 1


def test_copies_of_a_repeated_group_share_a_set_key():
    a = HouseObject(id="r-desk-0", room="r", name="desk", category="desk", position=(0, 0, 0),
                    size=(1, 1, 1), yaw=0.0, support="floor", group="desks-0", rule="place_wall")
    b = a.model_copy(update={"id": "r-desk-1", "group": "desks-11"})
    assert set_key(a) == set_key(b) == ("r", "desks", "desk")
    assert set_key(a.model_copy(update={"group": None})) is None
    assert set_key(a.model_copy(update={"name": "mismatched vintage chair"})) is None
