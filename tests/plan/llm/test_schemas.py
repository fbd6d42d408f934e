import json

import pytest

from anyhome.plan.llm.prompts import TEMPLATES, examples, fill, messages
from anyhome.plan.llm.schemas import STAGES, item_variants, json_schema, variant_rule


def _walk(node):
    yield node
    if isinstance(node, dict):
        for v in node.values():
            yield from _walk(v)
    elif isinstance(node, list):
        for v in node:
            yield from _walk(v)


@pytest.mark.parametrize("stage", list(STAGES))
def test_schemas_are_self_contained_strict_and_bounded(stage: str) -> None:
    schema = json_schema(stage)
    text = json.dumps(schema)
    assert "$ref" not in text and "$defs" not in text
    for node in _walk(schema):
        if isinstance(node, dict) and node.get("type") == "object":
            assert node["additionalProperties"] is False
            assert sorted(node["required"]) == sorted(node["properties"])
        if isinstance(node, dict) and node.get("type") == "array":
            assert "maxItems" in node  # a small model cannot loop through an endless list


@pytest.mark.parametrize("stage", list(STAGES))
def test_the_prompt_examples_match_their_schemas(stage: str) -> None:
    STAGES[stage].model_validate(examples()[stage])


def test_templates_fill_without_leftover_placeholders() -> None:
    values = dict(text="a cat cafe", max_rooms=12, types="bedroom, cafe", building="cafe", name="cat lounge",
                  type="cafe", area_m2="30", max_groups=8, furniture="sofa", max_ornaments=10,
                  rooms="cafe (cafe)", max_palette=6, errors="- x")
    for name in TEMPLATES:
        text = fill(name, **values)
        assert "$" not in text, name
    m = messages("program", **values)
    assert [x["role"] for x in m] == ["system", "user"] and "a cat cafe" in m[1]["content"]


def test_what_a_request_knows_narrows_its_schema() -> None:
    s = json_schema("appearance", room_ids=["cafe", "kitchen"])
    assert s["properties"]["rooms"]["items"]["properties"]["id"]["enum"] == ["cafe", "kitchen"]
    s = json_schema("ornaments", targets=["sofa"])
    assert all(v["properties"]["target"]["enum"] == ["", "sofa"] for v in item_variants(s["properties"]["ornaments"]["items"]))
    anchor = json_schema("furniture")["properties"]["groups"]["items"]["properties"]["anchor"]
    anchor_rules = [variant_rule(v) for v in item_variants(anchor)]
    assert "place_top" not in anchor_rules and "place_wall" in anchor_rules
    assert "enum" not in json_schema("appearance")["properties"]["rooms"]["items"]["properties"]["id"]
