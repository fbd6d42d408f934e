"""Defining elements kept (issue 15): named objects and room-defining objects."""

from __future__ import annotations

from anyhome.evaluate.defining import defining_elements
from anyhome.pipeline import generate


def test_a_house_keeps_what_its_prompt_names_and_loses_it_when_removed() -> None:
    house = generate("A cozy Victorian parlour with a piano, a fireplace and two velvet armchairs", seed=0)
    d = defining_elements(house)
    assert d.n_named == 3 and d.kept
    without = house.model_copy(update={"objects": [o for o in house.objects if "piano" not in o.name and o.category != "piano"]})
    d2 = defining_elements(without)
    assert d2.missing == ["piano"] and not d2.kept


def test_what_the_text_rules_out_is_not_asked_for() -> None:
    house = generate("a living room with a sofa and no tv", seed=1)
    d = defining_elements(house)
    assert d.n_named == 1 and d.kept
