"""Rule params in the LLM planner's replies: the furniture and ornaments schemas hold, per
rule, exactly that rule's parameters schema (from the rule registry's models); the params
a reply sets reach the ItemSpecs; a wrong value is a reply error; a reply without params
still works; the prompts describe the params from the same models; the checks read the
planner's knowledge base."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any, Literal, get_args, get_origin

import numpy as np
import pytest
from fake_llm_server import FURNITURE, ORNAMENTS, Answer, fake_llm  # noqa: F401
from hypothesis import given, settings
from hypothesis import strategies as st
from llama_cpp.llama_grammar import LlamaGrammar

from anyhome.layout.rules import REGISTRY, RULES
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.llm import LLMConfig, LLMPlanner
from anyhome.plan.llm.prompts import fill
from anyhome.plan.llm.schemas import (
    ANCHOR_RULES,
    MAX_GROUPS,
    ORNAMENT_RULES,
    STAGES,
    FurnitureReply,
    OrnamentsReply,
    item_variants,
    json_schema,
    max_groups,
    max_ornaments,
    params_schema,
    variant_rule,
)
from anyhome.plan.spec import ItemSpec

CAT = "a cat cafe"


def _item(name: str, category: str, size: list[float], rule: str, target: str = "", count: int = 1,
          params: dict[str, Any] | None = None) -> dict[str, Any]:
    out: dict[str, Any] = {"name": name, "category": category, "size_m": size, "rule": rule, "target": target, "count": count}
    if params is not None:
        out["params"] = params
    return out


# a living room whose reply sets a parameter of every rule that takes one
FURNITURE_WITH_PARAMS = {"groups": [
    {"name": "lounge", "arrangement": "free", "repeat": 1,
     "anchor": _item("sofa", "sofa", [2.0, 0.9, 0.85], "place_wall", params={"wall": "longest"}),
     "members": [_item("coffee table", "coffee table", [1.0, 0.5, 0.45], "place_front", "sofa",
                       params={"distance_m": 0.6, "facing": "toward"}),
                 _item("armchair", "armchair", [0.8, 0.8, 0.9], "place_beside", "sofa", params={"side": "left"})]},
    {"name": "dining", "arrangement": "free", "repeat": 1,
     "anchor": _item("dining table", "table", [1.6, 0.9, 0.75], "place_center", params={"facing": "door"}),
     "members": [_item("dining chair", "chair", [0.45, 0.5, 0.9], "place_around", "dining table", 4,
                       params={"sides": "long"})]},
]}  # fmt: skip
ORNAMENTS_WITH_PARAMS = {"ornaments": [
    _item("mirror", "mirror", [0.6, 0.03, 0.9], "place_on_wall", "", params={"elevation_m": 1.6}),
    _item("vase", "vase", [0.15, 0.15, 0.3], "place_top", "coffee table", params={}),
]}  # fmt: skip


def _planner(fake: Any, tmp_path: Path, kb: Any = None) -> LLMPlanner:
    config = LLMConfig(base_url=fake.base_url, cache_dir=tmp_path / "cache", timeout_s=10.0)
    return LLMPlanner(config, kb=kb)


def _items(spec: Any) -> dict[str, ItemSpec]:
    return {it.name: it for r in spec.rooms for g in r.groups for it in [g.anchor, *g.members]} | {
        o.name: o for r in spec.rooms for o in r.ornaments}


def _stage(spec: Any, prefix: str) -> list[dict[str, Any]]:
    return [s for s in spec.provenance["stages"] if s["stage"].startswith(prefix)]


# ------------------------------------------------------------------ schemas
def _variants_by_rule(item_schema: dict[str, Any]) -> dict[str, dict[str, Any]]:
    variants = item_variants(item_schema)
    by_rule = {variant_rule(v): v for v in variants}
    assert len(by_rule) == len(variants)  # one variant per rule
    return by_rule


@pytest.mark.parametrize(("where", "rules"), [
    ("anchor", ANCHOR_RULES), ("members", RULES), ("ornaments", ORNAMENT_RULES),
])  # fmt: skip
def test_each_item_schema_holds_exactly_each_rules_params_schema(where: str, rules: tuple[str, ...]) -> None:
    if where == "ornaments":
        item = json_schema("ornaments")["properties"]["ornaments"]["items"]
    else:
        group = json_schema("furniture")["properties"]["groups"]["items"]["properties"]
        item = group["anchor"] if where == "anchor" else group["members"]["items"]
    by_rule = _variants_by_rule(item)
    assert list(by_rule) == list(rules)
    for rule, variant in by_rule.items():
        assert variant["properties"]["params"] == params_schema(rule), rule
        assert variant["required"] == list(variant["properties"]) and variant["additionalProperties"] is False
    assert set(ANCHOR_RULES) == {n for n, r in REGISTRY.items() if not r.relative}
    assert set(ORNAMENT_RULES) == {"place_top", "place_on_wall"}


@pytest.mark.parametrize("stage", list(STAGES))
def test_llama_cpp_grammar_converter_accepts_every_stage_schema(stage: str) -> None:
    """llama-cpp-python's own JSON-schema-to-GBNF converter (what its server runs on a
    schema) turns every stage's schema, narrowed as a request narrows it, into a grammar."""
    schema = json_schema(stage, room_ids=["cafe", "kitchen"], targets=["sofa", "coffee table"])
    grammar = LlamaGrammar.from_json_schema(json.dumps(schema), verbose=False)
    assert grammar is not None
    if stage in ("furniture", "ornaments"):
        text = grammar._grammar  # the GBNF the server samples with: each rule's params keys are in it

        def key(name: str) -> str:
            return '"\\"' + name + '\\""'

        assert key("params") in text
        for rule in ORNAMENT_RULES if stage == "ornaments" else RULES:
            assert key(rule) in text
            for name in REGISTRY[rule].params.model_fields:
                assert key(name) in text, (stage, rule, name)


def test_narrowed_ornament_targets_reach_every_variant() -> None:
    items = json_schema("ornaments", targets=["sofa"])["properties"]["ornaments"]["items"]
    for variant in item_variants(items):
        assert variant["properties"]["target"]["enum"] == ["", "sofa"]


# ------------------------------------------------------------------ the reply models
def _param_values(rule: str) -> st.SearchStrategy[dict[str, Any]]:
    fields: dict[str, st.SearchStrategy[Any]] = {}
    for name, field in REGISTRY[rule].params.model_fields.items():
        if get_origin(field.annotation) is Literal:
            fields[name] = st.sampled_from(get_args(field.annotation))
        else:
            fields[name] = st.floats(0.0, 3.0, allow_nan=False).map(lambda v: round(v, 3))
    return st.fixed_dictionaries(fields)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(ORNAMENT_RULES).flatmap(lambda r: st.tuples(st.just(r), _param_values(r))))
def test_any_valid_params_go_through_the_reply_into_an_item_spec(case: tuple[str, dict[str, Any]]) -> None:
    rule, params = case
    reply = OrnamentsReply.model_validate({"ornaments": [_item("clock", "clock", [0.3, 0.05, 0.3], rule, "", 1, params)]})
    (o,) = reply.ornaments
    given_ = o.given_params()
    defaults = {k: f.default for k, f in REGISTRY[rule].params.model_fields.items()}
    assert given_ == {k: v for k, v in params.items() if v != defaults[k]}
    spec = ItemSpec(name="clock", category="clock", size_m=(0.3, 0.05, 0.3), rule=rule, params=given_)
    assert REGISTRY[rule].parse(spec.params) == REGISTRY[rule].parse(params)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(RULES), st.data())
def test_a_param_value_wrong_for_its_rule_is_refused_by_the_reply_model(rule: str, data: Any) -> None:
    fields = REGISTRY[rule].params.model_fields
    if fields:
        name = data.draw(st.sampled_from(sorted(fields)))
        bad = data.draw(st.sampled_from(["sideways", -5.0, 1e6, None, [1]]))
    else:
        name, bad = "height", 1.0  # a rule without parameters takes none
    item = _item("thing", "box", [0.5, 0.5, 0.5], rule, "", 1, {name: bad})
    reply = {"groups": [{"name": "g", "arrangement": "free", "repeat": 1,
                         "anchor": _item("table", "table", [1, 1, 0.7], "place_center"), "members": [item]}]}  # fmt: skip
    with pytest.raises(ValueError, match="params"):
        FurnitureReply.model_validate(reply)


# ------------------------------------------------------------------ through the planner
def test_reply_params_reach_the_item_specs(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.script["furniture"] = Answer.chat(json.dumps(FURNITURE_WITH_PARAMS))
    fake_llm.script["ornaments"] = Answer.chat(json.dumps(ORNAMENTS_WITH_PARAMS))
    spec = _planner(fake_llm, tmp_path).plan(CAT, np.random.default_rng(0))
    assert {s["source"] for s in _stage(spec, "furniture:") + _stage(spec, "ornaments:")} == {"llm"}
    items = _items(spec)
    assert items["sofa"].params == {"wall": "longest"}
    assert items["coffee table"].params == {"distance_m": 0.6}  # "facing": "toward" is the default
    assert items["armchair"].params == {"side": "left"}
    assert items["dining table"].params == {"facing": "door"}
    assert items["dining chair"].params == {"sides": "long"}
    assert items["mirror"].params == {"elevation_m": 1.6}
    assert items["vase"].params == {}
    # the prompts list every rule's parameters and allowed values, from the models
    (request, *_) = fake_llm.chat_requests("furniture")
    prompt = request["messages"][-1]["content"]
    for rule in RULES:
        for name, prop in params_schema(rule)["properties"].items():
            assert f'"{name}"' in prompt and json.dumps(prop["default"]) in prompt
            for value in prop.get("enum", []):
                assert f'"{value}"' in prompt
    assert "$" not in prompt


def test_a_bad_param_value_is_repaired_or_falls_back_with_a_warning(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    bad = copy.deepcopy(FURNITURE_WITH_PARAMS)
    bad["groups"][1]["anchor"]["params"] = {"facing": "up"}
    orn_bad = copy.deepcopy(ORNAMENTS_WITH_PARAMS)
    orn_bad["ornaments"][0]["params"] = {"elevation_m": -2}
    fake_llm.script["furniture"] = Answer.chat(json.dumps(bad))  # every furniture request: still bad after a repair
    orn_good = copy.deepcopy(ORNAMENTS_WITH_PARAMS)
    orn_good["ornaments"][1]["target"] = ""  # any room's furniture (the offline planner's here)
    # the first ornaments request gets the bad value, every later one (its repair too) a good reply
    fake_llm.script["ornaments"] = [Answer.chat(json.dumps(orn_bad)), Answer.chat(json.dumps(orn_good))]
    spec = _planner(fake_llm, tmp_path).plan(CAT, np.random.default_rng(0))
    furniture = _stage(spec, "furniture:")
    assert furniture and all(s["source"] == "offline" and s["requests"] == 2 for s in furniture)
    assert all(any("params" in e and "facing" in e for e in s["errors"]) for s in furniture)
    assert any("furniture:" in w and "still invalid after one repair" in w and "facing" in w for w in spec.warnings)
    reply_anchors = [g["anchor"]["name"] for g in bad["groups"]]
    assert all([g.anchor.name for g in r.groups] != reply_anchors for r in spec.rooms)  # the offline planner filled it
    # the first ornaments reply was repaired: its repair request quotes the parameter's error
    repairs = [r for r in fake_llm.chat_requests("ornaments") if len(r["messages"]) == 4]
    assert repairs and "elevation_m" in repairs[0]["messages"][-1]["content"]
    ornaments = _stage(spec, "ornaments:")
    assert sorted(s["source"] for s in ornaments) == ["llm"] * (len(ornaments) - 1) + ["llm_repaired"]


def test_a_reply_without_params_still_works(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    assert all("params" not in it for g in FURNITURE["groups"] for it in [g["anchor"], *g["members"]])
    assert all("params" not in o for o in ORNAMENTS["ornaments"])
    spec = _planner(fake_llm, tmp_path).plan(CAT, np.random.default_rng(0))  # the fake's canned replies
    assert {s["source"] for s in spec.provenance["stages"]} == {"llm"}
    items = _items(spec)
    assert items["cabinet"].params == {} and items["painting"].params == {}


# ------------------------------------------------------------------ the knowledge base in force
def test_the_checks_read_the_planners_knowledge_base(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    """A user overlay that makes bedrooms 60-90 m2: the fake's 12 m2 bedroom is then
    implausible for the planner holding that knowledge, and fine for the shipped one."""
    overlay = tmp_path / "kb"
    overlay.mkdir()
    (overlay / "rooms.yaml").write_text("types:\n  bedroom: {area: [60, 90]}\n", encoding="utf-8")
    kb = knowledge_base(dirs=[str(overlay)])
    spec = _planner(fake_llm, tmp_path, kb=kb).plan(CAT, np.random.default_rng(0))
    (program,) = _stage(spec, "program")
    assert program["source"] == "offline"
    assert any("implausible for a bedroom" in e for e in program["errors"])
    shipped = _planner(fake_llm, tmp_path / "b", kb=knowledge_base(dirs=[])).plan(CAT, np.random.default_rng(0))
    assert _stage(shipped, "program")[0]["source"] == "llm"


def test_the_furniture_prompt_fills_from_the_registry() -> None:
    text = fill("furniture", text=CAT, building="cafe", name="lounge", type="cafe", area_m2="30", max_groups=5)
    for rule in RULES:
        assert f"- {rule}" in text
    assert ", ".join(ANCHOR_RULES) in text
    text = fill("ornaments", text=CAT, building="cafe", name="lounge", type="cafe", furniture="sofa", max_ornaments=5)
    assert "- place_on_wall" in text and "- place_wall" not in text and '"elevation_m"' in text


def test_a_rooms_request_asks_for_as_many_groups_and_ornaments_as_its_size_holds(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    """The schema sent for each room caps its groups and ornaments by its area (a small
    model fills whatever the schema allows: a 4 m2 washroom got 15 floor objects), and the
    prompt says the same number."""
    spec = _planner(fake_llm, tmp_path).plan(CAT, np.random.default_rng(0))
    areas = {r.name: r.area_m2 for r in spec.rooms}
    for stage, key, cap in (("furniture", "groups", max_groups), ("ornaments", "ornaments", max_ornaments)):
        requests = [r for r in fake_llm.chat_requests(stage) if len(r["messages"]) == 2]
        assert len(requests) == len(spec.rooms)
        seen = []
        for r in requests:
            schema = r["response_format"]["json_schema"]["schema"]
            name = next(n for n in areas if f"Room: {n}, a " in r["messages"][1]["content"])
            assert schema["properties"][key]["maxItems"] == cap(areas[name]), (stage, name)
            assert f"at most {cap(areas[name])}" in r["messages"][1]["content"].lower()
            seen.append(cap(areas[name]))
        assert len(set(seen)) > 1  # the cat cafe's rooms differ in size: so do their caps
    assert max_groups(4.0) == 1 and max_groups(12.0) == 3 and max_groups(200.0) == MAX_GROUPS


def test_every_rooms_prompt_starts_with_the_same_text_so_a_server_reuses_it() -> None:
    """llama.cpp reuses the evaluated prefix its previous request shares; the rules guide and
    the example come first, the room last (measured: furniture prompts of 1,150 tokens re-read
    from the 1,200-token shared prefix instead of evaluated again)."""
    for stage, extra in (("furniture", dict(area_m2="30", max_groups=5)), ("ornaments", dict(furniture="sofa", max_ornaments=5))):
        a = fill(stage, text=CAT, building="cafe", name="lounge", type="cafe", **extra)
        b = fill(stage, text="a riad", building="home", name="salon", type="living room", **extra)
        i = next(i for i, (x, y) in enumerate(zip(a, b)) if x != y)
        assert i > 0.8 * len(a), (stage, i, len(a))
