"""The LLM planner against a fake OpenAI-compatible server serving hostile answers.

Every case ends in a plan (a valid HouseSpec), the affected stage from the offline
planner with a warning, and nothing from the server raw in it: never a traceback, never
a hang. The plan runs in a thread joined with a generous hang guard."""

from __future__ import annotations

import base64
import json
import threading
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fake_llm_server import FURNITURE, PROGRAM, Answer, appearance, fake_llm, wait_until  # noqa: F401

from anyhome.plan.llm import LLMPlanner
from anyhome.plan.llm.cache import MAX_ENTRY_BYTES
from anyhome.plan.llm.client import MAX_BODY_BYTES, MAX_REPLY_CHARS
from anyhome.plan.llm.config import LLMConfig
from anyhome.plan.llm.planner import MAX_ECHO_CHARS, MAX_KEPT_REPLY_CHARS
from anyhome.plan.spec import HouseSpec
from anyhome.sanitize import clean_text

CAT = "a cat cafe"
HANG_GUARD_S = 60.0
ESCAPES = "\x1b]0;pwned\x07\x1b[31m\x9b\x00\u202e\x7f"


def plan(fake: Any, tmp_path: Path, **over: Any) -> tuple[HouseSpec, LLMPlanner]:
    config = LLMConfig(**{"base_url": fake.base_url, "cache_dir": tmp_path / "cache", "timeout_s": 2.0, **over})
    planner = LLMPlanner(config)
    out: dict[str, Any] = {}

    def run() -> None:
        try:
            out["spec"] = planner.plan(CAT, np.random.default_rng(0))
        except BaseException as e:  # handed to the test thread, which fails with it
            out["error"] = e

    t = threading.Thread(target=run, daemon=True)
    t.start()
    t.join(HANG_GUARD_S)
    assert not t.is_alive(), "the planner hung"
    if "error" in out:
        raise out["error"]
    spec = HouseSpec.model_validate(out["spec"].model_dump())  # still a valid plan
    return spec, planner


def sources(spec: HouseSpec) -> dict[str, str]:
    return {s["stage"]: s["source"] for s in spec.provenance["stages"]}


def has_control(text: str) -> bool:
    return clean_text(text, newlines=True) != text


def assert_clean(spec: HouseSpec) -> None:
    """No control character anywhere in the plan (what is printed and written)."""
    for s in _strings(spec.model_dump(mode="json")):
        assert not has_control(s), repr(s)


def _strings(node: Any):
    if isinstance(node, str):
        yield node
    elif isinstance(node, dict):
        for k, v in node.items():
            yield str(k)
            yield from _strings(v)
    elif isinstance(node, list):
        for v in node:
            yield from _strings(v)


def _chat(content: str) -> bytes:
    return json.dumps({"choices": [{"message": {"role": "assistant", "content": content}}]}).encode()


APPEARANCE_OK = json.dumps(appearance(["living_room", "kitchen", "bedroom"]))
HOSTILE = {
    "truncated JSON": (Answer(body=_chat(APPEARANCE_OK)[:60]), "not JSON"),
    "HTML body": (Answer(body=b"<!doctype html><html><body>502 Bad Gateway</body></html>", content_type="text/html"), "not JSON"),
    "content is a number": (Answer.chat(42), "content is int, not text"),
    "content is an object": (Answer.chat({"style": "x"}), "content is dict, not text"),
    "content is null": (Answer.chat(None), "content is null, not text"),
    "choices [{}]": (Answer.json({"choices": [{}]}), "holds no message"),
    "choices []": (Answer.json({"choices": []}), "holds no choices"),
    "no choices at all": (Answer.json({"error": "nope"}), "holds no choices"),
    "a JSON list": (Answer.json([1, 2, 3]), "JSON list, not an object"),
    "not UTF-8": (Answer(body=b"\xff\xfe{\x00"), "not UTF-8"),
    "deeply nested body": (Answer(body=b"[" * 100_000 + b"]" * 100_000), "nested too deeply"),
    "content over the cap": (Answer.chat("x" * (MAX_REPLY_CHARS + 1)), "longer than 256 KiB"),
}  # fmt: skip


@pytest.mark.parametrize("case", list(HOSTILE))
def test_a_hostile_answer_costs_only_its_stage(fake_llm, tmp_path: Path, case: str) -> None:  # noqa: F811
    answer, why = HOSTILE[case]
    fake_llm.script["appearance"] = answer
    spec, planner = plan(fake_llm, tmp_path)
    got = sources(spec)
    assert got.pop("appearance") == "offline"
    assert set(got.values()) == {"llm"}  # the other stages still came from the server
    warning = next(w for w in spec.warnings if w.startswith("LLM appearance:"))
    assert why in warning and "the offline planner filled it" in warning
    assert spec.style and spec.palette  # the offline look
    record = next(s for s in spec.provenance["stages"] if s["stage"] == "appearance")
    assert record["reply"] is None and why in record["errors"][0]
    assert len(fake_llm.chat_requests("appearance")) == 1  # rejected: no repair request
    assert not any(json.loads(p.read_text())["name"] == "appearance" for p in (tmp_path / "cache").glob("*/*.json"))
    assert_clean(spec)
    assert planner.client.down is None  # the server is not marked down for one bad answer


def test_an_html_models_answer_plans_the_whole_house_offline(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.models = Answer(body=b"<html><body>login</body></html>", content_type="text/html")
    spec, _ = plan(fake_llm, tmp_path)
    assert set(sources(spec).values()) == {"offline"}
    assert any("/models answer is not JSON" in w and "planned the whole house" in w for w in spec.warnings)
    assert fake_llm.chat_requests() == []


@pytest.mark.parametrize(
    "models, why",
    [
        ({"data": "x"}, "holds no model list"),
        ({"data": [{"id": 5}, {"id": "\x1b]0;pwned\x07"}]}, "lists no usable model"),
        ({"data": []}, "lists no usable model"),
        (Answer(filler=(b'{"data": [{"id": "', b'"}]}', 50_000_000)), "/models answer larger than 1024 KiB"),
    ],
)
def test_odd_models_lists(fake_llm, tmp_path: Path, models: Any, why: str) -> None:  # noqa: F811
    fake_llm.models = models if isinstance(models, Answer) else Answer.json(models)
    spec, _ = plan(fake_llm, tmp_path)
    assert set(sources(spec).values()) == {"offline"} and any(why in w for w in spec.warnings)
    assert_clean(spec)


@pytest.mark.parametrize("prompt_tokens", ["lots", 10**30, 1e400, -5, True, None, [1]])
def test_token_counts_that_are_not_counts_count_zero(fake_llm, tmp_path: Path, prompt_tokens: Any) -> None:  # noqa: F811
    fake_llm.script["program"] = Answer.chat(json.dumps(PROGRAM), prompt_tokens=prompt_tokens, completion_tokens=1e300)
    spec, _ = plan(fake_llm, tmp_path)
    program = next(s for s in spec.provenance["stages"] if s["stage"] == "program")
    assert program["source"] == "llm"  # the reply itself is fine and used
    assert program["prompt_tokens"] == 0 and program["completion_tokens"] == 0


def test_a_50_mb_reply_is_cut_not_stored_not_echoed(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.script["furniture"] = Answer.huge_chat(50_000_000)
    spec, _ = plan(fake_llm, tmp_path)
    assert {v for k, v in sources(spec).items() if k.startswith("furniture:")} == {"offline"}
    assert any(f"larger than {MAX_BODY_BYTES // 1024} KiB" in w for w in spec.warnings)
    assert len(spec.model_dump_json()) < 200_000
    sizes = [p.stat().st_size for p in (tmp_path / "cache").rglob("*") if p.is_file()]
    assert sizes and max(sizes) < 64 * 1024 and max(sizes) < MAX_ENTRY_BYTES
    assert len(fake_llm.chat_requests("furniture")) == 3  # one per room, no repair echoing it


def test_escapes_in_names_style_and_palette_are_cleaned(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    program = json.loads(json.dumps(PROGRAM))
    program["rooms"][0]["name"] = f"{ESCAPES}living\x1b[0m room"
    program["building"] = f"home{ESCAPES}"
    furniture = json.loads(json.dumps(FURNITURE))
    furniture["groups"][0]["anchor"]["name"] = f"\x1b[2J\x1b[Hcab{ESCAPES}inet"
    look = appearance(["living_room", "kitchen", "bedroom"], style="\x1b]0;pwned\x07cozy\x1b[31m red", palette=["\x1b[1mcream", "oak\x00"])
    look["rooms"][0]["floor"] = "oak\x1b]8;;http://evil\x07 planks"
    fake_llm.script["program"] = Answer.chat(json.dumps(program))
    fake_llm.script["furniture"] = Answer.chat(json.dumps(furniture))
    fake_llm.script["appearance"] = Answer.chat(json.dumps(look))
    spec, _ = plan(fake_llm, tmp_path)
    assert set(sources(spec).values()) == {"llm"}  # cleaned, then used
    assert spec.rooms[0].name == "living room" and spec.building == "home"
    assert spec.style == "cozy red" and spec.palette == ["cream", "oak"]
    assert spec.rooms[0].groups[0].anchor.name == "cabinet"
    assert spec.rooms[0].materials["floor"] == "oak planks"
    assert_clean(spec)


def test_a_name_of_only_escapes_is_invalid_then_repaired(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    look = appearance(["living_room", "kitchen", "bedroom"], style="\x1b]0;pwned\x07\x1b[31m")
    fake_llm.script["appearance"] = [Answer.chat(json.dumps(look)), Answer.chat(APPEARANCE_OK)]
    spec, _ = plan(fake_llm, tmp_path)
    assert sources(spec)["appearance"] == "llm_repaired" and spec.style == "calm modern"
    repair = fake_llm.chat_requests("appearance")[1]["messages"]
    assert "style" in repair[-1]["content"]  # the error quoted to the model
    assert_clean(spec)


def test_hostile_validation_errors_are_cleaned_and_bounded(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    bad = {**PROGRAM, "entrance": "\x1b]0;pwned\x07" + "z" * 100_000, f"\x1b[31m{'k' * 5000}": 1}
    fake_llm.script["program"] = Answer.chat(json.dumps(bad))
    spec, _ = plan(fake_llm, tmp_path)
    record = next(s for s in spec.provenance["stages"] if s["stage"] == "program")
    assert record["source"] == "offline" and record["requests"] == 2
    assert record["errors"] and all(len(e) <= 300 for e in record["errors"])
    assert all(len(w) < 1000 for w in spec.warnings)
    assert len(json.dumps(record["reply"])) <= MAX_KEPT_REPLY_CHARS + 100  # the kept reply is bounded
    assert_clean(spec)


def test_a_long_invalid_reply_is_echoed_only_in_part(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    junk = "not json " * 20_000  # 180 KB: under the cap, so it is a reply, but not JSON
    fake_llm.script["program"] = Answer.chat(junk)
    spec, _ = plan(fake_llm, tmp_path)
    first, repair = fake_llm.chat_requests("program")
    echoed = repair["messages"][2]
    assert echoed["role"] == "assistant" and len(echoed["content"]) <= MAX_ECHO_CHARS + 20
    record = next(s for s in spec.provenance["stages"] if s["stage"] == "program")
    assert isinstance(record["reply"], str) and len(record["reply"]) <= MAX_KEPT_REPLY_CHARS + 10


def test_claimed_huge_counts_in_a_reply_are_refused(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    furniture = json.loads(json.dumps(FURNITURE))
    furniture["groups"][0]["repeat"] = 10**9
    furniture["groups"][0]["anchor"]["count"] = 10**12
    furniture["groups"][0]["anchor"]["size_m"] = [1e308, 1e400, float("nan")]
    fake_llm.script["furniture"] = Answer(body=_chat(json.dumps(furniture).replace("Infinity", "1e400")))
    spec, _ = plan(fake_llm, tmp_path)
    assert {v for k, v in sources(spec).items() if k.startswith("furniture:")} == {"offline"}
    assert all(o.count <= 120 for r in spec.rooms for g in r.groups for o in [g.anchor, *g.members])
    assert "NaN" not in json.dumps(spec.provenance) and "Infinity" not in json.dumps(spec.provenance)


@pytest.mark.parametrize("drip_head", [False, True])
def test_a_drip_fed_answer_is_cut_at_the_total_deadline(fake_llm, tmp_path: Path, drip_head: bool) -> None:  # noqa: F811
    # a byte every 0.2 s never trips a per-read timeout of 1 s; the whole answer would take minutes
    fake_llm.script["program"] = Answer.chat(json.dumps(PROGRAM), drip_s=0.2, drip_head=drip_head)
    spec, planner = plan(fake_llm, tmp_path, timeout_s=1.0)
    assert set(sources(spec).values()) == {"offline"}
    assert any("timed out after 1 s" in w for w in spec.warnings)
    assert planner.client.down and "timed out" in planner.client.down
    wait_until(lambda: fake_llm.hung_up >= 1)  # the client closed the connection: reading really stopped
    assert not list((tmp_path / "cache").glob("*/*.json"))


def test_a_server_slower_than_the_deadline_times_out(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.script["ornaments"] = Answer.chat("{}", delay_s=30)
    spec, _ = plan(fake_llm, tmp_path, timeout_s=0.5)
    got = sources(spec)
    assert {v for k, v in got.items() if k.startswith("ornaments:")} == {"offline"}
    assert got["program"] == "llm" and any("timed out after 0.5 s" in w for w in spec.warnings)


@pytest.mark.parametrize("status", [400, 404, 500, 503])
def test_error_statuses_fall_back(fake_llm, tmp_path: Path, status: int) -> None:  # noqa: F811
    fake_llm.script["program"] = Answer(status=status, body=b"<html>" + b"x" * 2_000_000)  # a huge error page too
    spec, planner = plan(fake_llm, tmp_path)
    assert sources(spec)["program"] == "offline"
    assert any("LLM program:" in w for w in spec.warnings)


def test_credentials_in_the_base_url_are_used_but_never_recorded(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    url = fake_llm.base_url.replace("http://", "http://user:SECRETPW@")
    fake_llm.script["appearance"] = Answer.chat(None)  # a warning that names the server
    spec, planner = plan(fake_llm, tmp_path, base_url=url)
    sent = fake_llm.requests[0]["headers"]
    assert len(fake_llm.requests[0]["authorization"]) == 1
    assert sent["authorization"] == "Basic " + base64.b64encode(b"user:SECRETPW").decode()  # used for the request
    assert spec.provenance["llm"]["base_url"] == fake_llm.base_url
    assert any(fake_llm.base_url in w for w in spec.warnings)
    assert "SECRETPW" not in json.dumps(spec.model_dump(mode="json"))
    for p in (tmp_path / "cache").rglob("*"):
        if p.is_file():
            assert b"SECRETPW" not in p.read_bytes(), p
            assert p.read_bytes().isascii()
    assert (tmp_path / "cache" / "servers.json").is_file()
    assert fake_llm.base_url in json.loads((tmp_path / "cache" / "servers.json").read_text())
