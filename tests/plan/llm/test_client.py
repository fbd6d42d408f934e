import json

import pytest

from anyhome.plan.llm.client import (
    MODES,
    ReplyRejected,
    _count,
    chat_answer,
    listed_models,
    parse_json,
    request_options,
    schema_in_prompt,
)


def test_parse_json_accepts_fences_and_surrounding_text() -> None:
    assert parse_json('{"a": 1}') == {"a": 1}
    assert parse_json('```json\n{"a": 1}\n```') == {"a": 1}
    assert parse_json('Sure! Here it is: {"a": {"b": 2}} Hope it helps.') == {"a": {"b": 2}}


@pytest.mark.parametrize("text, match", [("no json here", "no JSON object"), ('{"a": 1', "cut off"), ('{"a": }', "not valid JSON")])
def test_parse_json_reasons(text: str, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        parse_json(text)


def test_request_options_per_mode() -> None:
    schema = {"type": "object"}
    assert request_options("json_schema", schema, "n")["response_format"]["json_schema"]["schema"] == schema
    assert request_options("json_object_schema", schema, "n") == {"response_format": {"type": "json_object", "schema": schema}}
    assert request_options("ollama_format", schema, "n") == {"extra_body": {"format": schema}}
    assert request_options("prompt", schema, "n") == {}
    assert MODES[-1] == "prompt"
    with pytest.raises(ValueError):
        request_options("xml", schema, "n")


def test_schema_in_prompt_extends_the_last_message_only() -> None:
    msgs = [{"role": "system", "content": "s"}, {"role": "user", "content": "u"}]
    out = schema_in_prompt(msgs, {"type": "object"})
    assert out[0] == msgs[0] and out[1]["content"].startswith("u\n") and '{"type":"object"}' in out[1]["content"]
    assert msgs[1]["content"] == "u"


def test_deeply_nested_replies_are_a_reason_not_a_crash() -> None:
    with pytest.raises(ValueError, match="nested too deeply"):
        parse_json("[" * 100_000 + "]" * 100_000)


@pytest.mark.parametrize("value, expected", [(12, 12), (12.0, 12), ("12", 0), ("lots", 0), (True, 0), (None, 0), (-1, 0),
                                             (10**30, 0), (float("inf"), 0), (float("nan"), 0), (1.5, 0), ([3], 0)])  # fmt: skip
def test_claimed_token_counts(value, expected) -> None:
    assert _count(value) == expected


def test_chat_answer_takes_a_well_formed_body_only() -> None:
    ok = json.dumps({"choices": [{"message": {"content": "{}"}}], "usage": {"prompt_tokens": 3, "completion_tokens": "x"}})
    assert chat_answer(ok.encode()) == ("{}", 3, 0)
    for body in [b"", b"{", b"<html>", b"null", b'{"choices": null}', b'{"choices": [null]}', b'{"choices": [{"message": "hi"}]}',
                 b'{"choices": [{"message": {"content": ["a"]}}]}', b'{"choices": [{"message": {"content": 1e400}}]}', b"1" * 5000]:  # fmt: skip
        with pytest.raises(ReplyRejected):
            chat_answer(body)


def test_listed_models_drops_unsafe_ids() -> None:
    body = json.dumps({"data": [{"id": "\x1b[31mred"}, {"id": ""}, {"id": "m" * 500}, {"id": 3}, "x", {"id": "good-model"}]})
    assert listed_models(body.encode()) == ["good-model"]
