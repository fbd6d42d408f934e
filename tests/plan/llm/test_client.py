import pytest

from anyhome.plan.llm.client import MODES, parse_json, request_options, schema_in_prompt


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
