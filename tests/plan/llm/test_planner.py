"""The LLM planner against a real llama.cpp server (SmolLM2-135M), a closed port and a
port that never answers."""

import json
from pathlib import Path

import numpy as np
import pytest

from anyhome.layout.rules import REGISTRY
from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.llm import LLMPlanner
from anyhome.plan.llm.cache import ReplyCache
from anyhome.plan.llm.client import LLMClient
from anyhome.plan.llm.config import LLMConfig
from anyhome.plan.llm.planner import STAGE_MAX_TOKENS, replace_groups, replace_ornaments
from anyhome.plan.llm.prompts import examples, messages
from anyhome.plan.llm.schemas import FurnitureReply, OrnamentsReply, ProgramReply, json_schema
from anyhome.plan.offline import fallback_room, offline_look

CAT = "a cat cafe"


def _config(tmp_path: Path, base_url: str, **over) -> LLMConfig:
    return LLMConfig(base_url=base_url, model="smollm2", cache_dir=tmp_path / "cache", **over)


def test_llama_cpp_server_takes_json_object_with_schema(llama_server, tmp_path: Path) -> None:
    client = LLMClient(_config(tmp_path, llama_server.base_url, max_tokens=600))
    msgs = messages("program", text=CAT, max_rooms=12, types="cafe, kitchen, bathroom")
    reply = client.chat_json(msgs, json_schema("program"), "program", seed=1)
    # llama-cpp-python refuses {"type": "json_schema"} (HTTP 500); the client moved on
    assert client.mode == "json_object_schema"
    assert ReplyCache(tmp_path / "cache").server_note(llama_server.base_url)["mode"] == "json_object_schema"
    assert reply.completion_tokens > 0 and not reply.cached
    ProgramReply.model_validate(json.loads(reply.content))  # the grammar held it to the schema
    again = LLMClient(_config(tmp_path, llama_server.base_url, max_tokens=600))
    assert again.mode == "json_object_schema"  # remembered per server
    hit = again.chat_json(msgs, json_schema("program"), "program", seed=1)
    assert hit.cached and hit.content == reply.content and again.usage.calls == 0


@pytest.mark.parametrize("stage", ["ornaments", "furniture"])
def test_llama_cpp_server_holds_items_to_their_rules_params(stage: str, llama_server, tmp_path: Path) -> None:
    """The item schemas (one variant per rule, each with that rule's params model) go
    through the real server's grammar converter, and the reply it samples has, for every
    item, exactly its rule's parameters."""
    client = LLMClient(_config(tmp_path, llama_server.base_url, max_tokens=STAGE_MAX_TOKENS[stage]))
    furniture = ["sofa", "coffee table"]
    values = dict(text=CAT, building="cafe", name="cat lounge", type="cafe", area_m2="30", max_groups=1,
                  furniture=", ".join(furniture), max_ornaments=3)  # fmt: skip
    cap = values["max_groups"] if stage == "furniture" else values["max_ornaments"]
    schema = json_schema(stage, targets=furniture, max_items=int(cap))  # as the planner asks: the prompt's cap
    reply = client.chat_json(messages(stage, **values), schema, stage, seed=2)
    assert client.mode == "json_object_schema"  # the server took the schema (no fallback to plain JSON)
    data = json.loads(reply.content)
    model = OrnamentsReply if stage == "ornaments" else FurnitureReply
    parsed = model.model_validate(data)
    if stage == "ornaments":
        items = data["ornaments"]
    else:
        items = [it for g in data["groups"] for it in [g["anchor"], *g["members"]]]
    assert items, "the model listed no item"
    for it in items:
        assert set(it["params"]) == set(REGISTRY[it["rule"]].params.model_fields), it
    assert parsed is not None


def test_invalid_reply_gets_one_repair_then_the_offline_stage(llama_server, tmp_path: Path) -> None:
    planner = LLMPlanner(_config(tmp_path, llama_server.base_url, max_tokens=16))  # replies cut off
    planner.client = LLMClient(planner.config)
    warnings: list[str] = []
    msgs = messages("program", text=CAT, max_rooms=12, types="cafe, kitchen, bathroom")
    from anyhome.plan.llm import checks

    obj, rec = planner._ask("program", "program", msgs, ProgramReply, lambda r: checks.check_program(r, planner.kb), 3, warnings)
    assert obj is None and rec.source == "offline" and rec.requests == 2
    assert rec.errors and ("cut off" in rec.errors[0] or "JSON" in rec.errors[0])
    assert warnings and "still invalid after one repair" in warnings[0]
    entries = [json.loads(p.read_text()) for p in (tmp_path / "cache").glob("*/*.json")]
    repair = [e for e in entries if len(e["messages"]) == 4]
    assert len(entries) == 2 and len(repair) == 1
    assert repair[0]["messages"][2] == {"role": "assistant", "content": next(e for e in entries if e is not repair[0])["content"]}
    assert rec.errors[0] in repair[0]["messages"][3]["content"]  # the repair quotes the errors


def test_server_down_gives_the_offline_house_with_warnings(closed_port_url, tmp_path: Path) -> None:
    planner = LLMPlanner(_config(tmp_path, closed_port_url))
    spec = planner.plan(CAT, np.random.default_rng(0))
    stages = spec.provenance["stages"]
    assert {s["source"] for s in stages} == {"offline"}
    assert stages[0]["stage"] == "program" and any(s["stage"].startswith("furniture:") for s in stages)
    assert any("unreachable" in w for w in spec.warnings)
    assert planner.client.usage.calls == 0
    assert len(spec.rooms) >= 2 and any(g for r in spec.rooms for g in r.groups)


def test_no_model_and_no_server_plans_offline(closed_port_url, tmp_path: Path) -> None:
    planner = LLMPlanner(LLMConfig(base_url=closed_port_url, cache_dir=tmp_path))
    spec = planner.plan(CAT, np.random.default_rng(0))
    stages = spec.provenance["stages"]
    assert spec.provenance["totals"]["stages_from_offline"] == len(stages) == 2 + 2 * len(spec.rooms)
    assert all("unreachable" in s["errors"][0] and s["requests"] == 0 for s in stages)
    assert any("planned the whole house" in w for w in spec.warnings)


def test_a_server_that_hangs_times_out_and_falls_back(silent_server, tmp_path: Path) -> None:
    planner = LLMPlanner(_config(tmp_path, silent_server, timeout_s=0.5))
    spec = planner.plan(CAT, np.random.default_rng(0))
    assert any("timed out after 0.5 s" in w for w in spec.warnings)
    assert {s["source"] for s in spec.provenance["stages"]} == {"offline"}


def test_replies_become_groups_and_ornaments(tmp_path: Path) -> None:
    look = offline_look(knowledge_base(), CAT, np.random.default_rng(0))
    room = fallback_room(knowledge_base(), "guest bedroom", "bedroom", 14.0, "guest", look, np.random.default_rng(0))
    fur = FurnitureReply.model_validate(examples()["furniture"])
    got = replace_groups(knowledge_base(), room, fur, look, np.random.default_rng(0))
    assert [g.anchor.name for g in got.groups] == [g.anchor.name for g in fur.groups]
    assert got.groups[0].members[0].rule == "place_beside" and got.groups[0].members[0].target is None  # the anchor
    assert all(it.material for g in got.groups for it in [g.anchor, *g.members])
    orn = OrnamentsReply.model_validate(examples()["ornaments"])
    got = replace_ornaments(knowledge_base(), got, orn, look, np.random.default_rng(0))
    assert [o.name for o in got.ornaments] == [o.name for o in orn.ornaments]
    assert got.ornaments[2].rule == "place_on_wall" and got.ornaments[2].target == "sofa"
