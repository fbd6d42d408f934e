"""The rule registry: one parameters model per rule, used by ItemSpec, the layout and the
LLM schemas alike; LayoutOptions reach the layout."""

from __future__ import annotations

import json
import subprocess
import sys
from typing import Literal, get_args, get_origin

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pydantic import ValidationError

from anyhome.layout import LayoutOptions, layout_house
from anyhome.layout.rules import REGISTRY, RELATIVE_RULES, RULES, WALL_RULES, RuleParams
from anyhome.plan import spec as spec_module
from anyhome.plan.llm import schemas

from .helpers import check_valid, group, house_spec, item, rect, single_room

ROOM = rect(0, 0, 5, 4)

BAD_VALUES = {  # a wrong value for each parameter a rule takes
    ("place_wall", "wall"): "north",
    ("place_wall", "far_m"): -2.0,
    ("place_center", "facing"): "up",
    ("place_center", "far_m"): "far",
    ("place_beside", "side"): "above",
    ("place_around", "sides"): "some",
    ("place_front", "distance_m"): -1.0,
    ("place_front", "facing"): "sideways",
    ("place_front", "to_wall"): "maybe",
    ("place_on_wall", "elevation_m"): "high",
}


def _layout(groups, ornaments=(), seed=0, options=None):
    fp = single_room(ROOM)
    spec = house_spec({"r1": groups}, ornaments={"r1": list(ornaments)})
    kw = {} if options is None else {"options": options}
    res = layout_house(spec, fp, np.random.default_rng(seed), **kw)
    assert check_valid(fp, res.objects) == []
    return res


def _named(res, name):
    return [o for o in res.objects if o.name == name]


# ------------------------------------------------------------------ the registry
def test_every_rule_has_an_entry_with_a_params_model():
    assert set(get_args(spec_module.Rule)) == set(RULES) == set(REGISTRY)
    assert len(RULES) == 10
    for name, rule in REGISTRY.items():
        assert rule.name == name
        assert issubclass(rule.params, RuleParams)
        assert rule.params.model_config.get("extra") == "forbid"
        assert rule.params.model_validate({}) is not None  # every parameter has a default
        assert rule.doc.strip()


def test_rule_sets_derive_from_the_registry():
    assert spec_module.RULES is RULES
    assert spec_module.RELATIVE_RULES == RELATIVE_RULES == {n for n, r in REGISTRY.items() if r.relative}
    assert spec_module.WALL_RULES == WALL_RULES == {n for n, r in REGISTRY.items() if r.against_wall}
    assert RELATIVE_RULES == {"place_beside", "place_around", "place_front", "place_top", "place_on_wall"}
    assert WALL_RULES == {"place_wall", "place_corner", "place_next_wall", "place_on_wall"}


def test_spec_imports_without_the_layout_solver():
    """plan/spec.py pulls in the registry, not the solver (which imports plan/spec.py)."""
    code = ("import sys, anyhome.plan.spec as s; "
            "print(s.RULES[0], 'anyhome.layout.solver' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["place_corner", "False"]


# ------------------------------------------------------------------ params validated per rule
@pytest.mark.parametrize("rule", RULES)
def test_unknown_param_is_refused_with_a_clear_message(rule):
    with pytest.raises(ValidationError) as e:
        item("x", "x", (0.5, 0.5, 0.5), rule, params={"distnce_m": 0.3})
    msg = str(e.value)
    assert f"{rule} params: distnce_m: unknown parameter" in msg
    assert "parameters: " in msg


@pytest.mark.parametrize(("rule", "key"), sorted(BAD_VALUES))
def test_bad_param_value_is_refused(rule, key):
    with pytest.raises(ValidationError) as e:
        item("x", "x", (0.5, 0.5, 0.5), rule, params={key: BAD_VALUES[(rule, key)]})
    assert f"{rule} params: {key}: " in str(e.value)


def test_every_param_has_a_bad_value_case():
    fields = {(n, f) for n, r in REGISTRY.items() for f in r.params.model_fields}
    assert fields == set(BAD_VALUES)


def test_param_of_another_rule_is_refused():
    """``wall`` belongs to place_wall: on place_center it was silently ignored before."""
    with pytest.raises(ValidationError, match="place_center params: wall: unknown parameter"):
        item("altar", "table", (1.8, 0.8, 1.0), "place_center", params={"wall": "opposite_door"})
    item("altar", "table", (1.8, 0.8, 1.0), "place_wall", params={"wall": "opposite_door"})


def test_knowledge_sets_build_valid_params():
    """Every set of the shipped knowledge furnishes rooms whose items pass the check
    (a set overriding a template's rule keeps only the params the new rule takes)."""
    from anyhome.plan import furnish
    from anyhome.plan.knowledge import knowledge_base

    kb = knowledge_base()
    rng = np.random.default_rng(0)
    for key in kb.raw("furniture")["sets"]:
        groups, ornaments, _ = furnish.furnish_room(kb, key, "other", 20.0, rng)
        for it in [*(i for g in groups for i in (g["anchor"], *g["members"])), *ornaments]:
            REGISTRY[it["rule"]].parse(it["params"])


def test_params_stay_as_written_in_the_plan():
    """Validation does not fill defaults into the plan (house.json's plan is unchanged)."""
    it = item("chair", "chair", (0.5, 0.5, 0.9), "place_front", params={"facing": "toward"})
    assert it.params == {"facing": "toward"}


# ------------------------------------------------------------------ defaults come from the model
def test_front_distance_default_comes_from_the_model():
    default = REGISTRY["place_front"].params.model_fields["distance_m"].default
    desk = item("desk", "desk", (1.2, 0.6, 0.75), "place_wall")

    def chair_gap(params):
        chair = item("chair", "chair", (0.5, 0.5, 0.9), "place_front", params=params)
        res = _layout([group("desk", desk, [chair])])
        d, c = _named(res, "desk")[0], _named(res, "chair")[0]
        return float(np.linalg.norm(np.subtract(c.position[:2], d.position[:2]))) - (d.size[1] + c.size[1]) / 2

    implicit, explicit, far = chair_gap({}), chair_gap({"distance_m": default}), chair_gap({"distance_m": 3 * default})
    assert implicit == pytest.approx(explicit, abs=1e-9)
    assert far > implicit + default


def test_wall_elevation_default_comes_from_the_model():
    default = REGISTRY["place_on_wall"].params.model_fields["elevation_m"].default
    bed = item("bed", "bed", (1.6, 2.0, 0.5), "place_wall")
    painting = item("painting", "painting", (0.8, 0.05, 0.6), "place_on_wall")
    res = _layout([group("bed", bed)], ornaments=[painting])
    assert _named(res, "painting")[0].position[2] == pytest.approx(default)
    lower = item("painting", "painting", (0.8, 0.05, 0.6), "place_on_wall", params={"elevation_m": default - 0.5})
    res = _layout([group("bed", bed)], ornaments=[lower])
    assert _named(res, "painting")[0].position[2] == pytest.approx(default - 0.5)


# ------------------------------------------------------------------ LayoutOptions reach the layout
def test_layout_options_gap_above_target():
    dresser = item("dresser", "dresser", (1.2, 0.5, 1.5), "place_wall")
    mirror = item("mirror", "mirror", (0.6, 0.05, 0.5), "place_on_wall")
    g = group("dresser", dresser, [mirror])
    z_default = _named(_layout([g]), "mirror")[0].position[2]
    z_wide = _named(_layout([g], options=LayoutOptions(wall_item_gap_m=0.4)), "mirror")[0].position[2]
    assert z_default == pytest.approx(1.5 + LayoutOptions().wall_item_gap_m)
    assert z_wide == pytest.approx(1.5 + 0.4)


def test_layout_options_noise_is_the_only_seed_dependence_of_a_free_room():
    """Without noise (and without on-top items, whose spot is drawn), every seed gives the
    same room; with the default noise, seeds differ."""
    groups = [group("bed", item("bed", "bed", (1.6, 2.0, 0.5), "place_wall")),
              group("desk", item("desk", "desk", (1.2, 0.6, 0.75), "place_wall"),
                    [item("chair", "chair", (0.5, 0.5, 0.9), "place_front")]),
              group("rug", item("rug", "rug", (1.2, 0.8, 0.01), "place_center"))]
    quiet = LayoutOptions(noise=0.0, member_noise=0.0)

    def poses(seed, options=None):
        return [(o.name, o.position, o.yaw) for o in _layout(groups, seed=seed, options=options).objects]

    assert len({json.dumps(poses(s, quiet)) for s in range(4)}) == 1
    assert len({json.dumps(poses(s)) for s in range(4)}) > 1


def test_layout_options_are_frozen():
    with pytest.raises(AttributeError):
        LayoutOptions().noise = 0.0  # type: ignore[misc]


# ------------------------------------------------------------------ the LLM schemas
@pytest.mark.parametrize("rule", RULES)
def test_llm_params_schema_is_the_models(rule):
    model = REGISTRY[rule].params
    schema = schemas.params_schema(rule)
    assert schema["type"] == "object" and schema["additionalProperties"] is False
    assert list(schema["properties"]) == list(model.model_fields) == schema["required"]
    for name, field in model.model_fields.items():
        prop = schema["properties"][name]
        assert prop["default"] == field.default
        if get_origin(field.annotation) is Literal:
            assert prop["enum"] == list(get_args(field.annotation))
        # the schema's default is a value the model takes
        model.model_validate({name: prop["default"]})
    schema["properties"].clear()  # a fresh copy each call
    assert schemas.params_schema(rule)["properties"].keys() == model.model_fields.keys()


def test_llm_stage_rules_derive_from_the_registry():
    def rules(item):  # one variant per rule (tests/plan/llm/test_params.py checks their params)
        return [schemas.variant_rule(v) for v in schemas.item_variants(item)]

    fur = schemas.json_schema("furniture")["properties"]["groups"]["items"]["properties"]
    assert rules(fur["members"]["items"]) == list(RULES)
    assert rules(fur["anchor"]) == [n for n in RULES if n not in RELATIVE_RULES]
    orn = schemas.json_schema("ornaments")["properties"]["ornaments"]["items"]
    assert rules(orn) == [n for n, r in REGISTRY.items() if r.kind != "floor"] == ["place_top", "place_on_wall"]


# ------------------------------------------------------------------ property: any valid params lay out validly
def _params_strategy(rule: str) -> st.SearchStrategy[dict]:
    fields = {}
    for name, field in REGISTRY[rule].params.model_fields.items():
        if get_origin(field.annotation) is Literal:
            fields[name] = st.sampled_from(get_args(field.annotation))
        elif field.annotation is bool or field.annotation == "bool":
            fields[name] = st.booleans()
        else:
            hi = 2.0 if name == "elevation_m" else 1.5
            fields[name] = st.floats(0.0, hi, allow_nan=False).map(lambda v: round(v, 3))
    return st.fixed_dictionaries({}, optional=fields)


@st.composite
def _rule_and_params(draw):
    rule = draw(st.sampled_from(RULES))
    return rule, draw(_params_strategy(rule)), draw(st.integers(1, 3)), draw(st.integers(0, 2**16))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_rule_and_params())
def test_random_valid_params_validate_and_lay_out_validly(case):
    rule, params, count, seed = case
    it = item("thing", "box", (0.5, 0.4, 0.5), rule, params=params, count=count)
    assert REGISTRY[rule].parse(it.params).model_dump(exclude_unset=True) == params
    table = item("table", "table", (1.2, 0.8, 0.75), "place_center")
    if rule in RELATIVE_RULES:
        groups = [group("table", table, [it.model_copy(update={"target": None})])]
    else:
        groups = [group("table", table), group("thing", it.model_copy(update={"count": 1}), repeat=count)]
    res = _layout(groups, seed=seed)
    placed = _named(res, "thing")
    dropped = [d for d in res.dropped if d.name == "thing"]
    assert len(placed) + len(dropped) == count
    assert all(o.rule in REGISTRY for o in res.objects)


def test_house_format_documents_every_rule_and_parameter():
    """docs/house_format.md's rule table names every rule of the registry and each of its
    parameters with its default, so the format document follows the models."""
    from pathlib import Path

    from anyhome.layout.rules import REGISTRY

    doc = (Path(__file__).resolve().parents[2] / "docs" / "house_format.md").read_text(encoding="utf-8")
    rows = {line.split("|")[1].strip().strip("`"): line for line in doc.splitlines() if line.startswith("| `place_")}
    assert set(rows) == set(REGISTRY)
    for name, rule in REGISTRY.items():
        for key, field in rule.params.model_fields.items():
            assert f"`{key}`" in rows[name], (name, key)
            assert f"({field.default})" in rows[name] or f"(`{field.default}`)" in rows[name], (name, key, field.default)
