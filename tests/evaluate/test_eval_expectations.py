"""Loading prompts.jsonl-style expectation files."""

from __future__ import annotations

import json

import pytest
from public_prompts import PUBLIC_PROMPTS as SHARED  # noqa: E402

from anyhome.errors import EvalError
from anyhome.evaluate import expectation_for_prompt, load_expectations, load_prompt_records


def write(tmp_path, lines):
    p = tmp_path / "prompts.jsonl"
    p.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return p


def rec(i, prompt, expect=None):
    return json.dumps({"id": i, "prompt": prompt, "expect": expect or {}})


def test_load_and_lookup(tmp_path):
    p = write(tmp_path, [rec("a", "A house.", {"rooms": [{"any": ["bedroom"]}]}), "",
                         "# comment", rec("b", "B house.")])
    table = load_expectations(p)
    assert list(table) == ["a", "b"]
    assert table["a"]["prompt"] == "A house."
    assert table["a"]["expect"] == {"rooms": [{"any": ["bedroom"]}]}
    assert expectation_for_prompt(p, "A house.") == {"rooms": [{"any": ["bedroom"]}]}
    assert expectation_for_prompt(p, "a house.") is None
    assert [r["id"] for r in load_prompt_records(p)] == ["a", "b"]


def test_shared_prompts_file_loads():
    table = load_expectations(SHARED)
    assert len(table) >= 30
    assert expectation_for_prompt(SHARED, table["tea-house"]["prompt"]) == table["tea-house"]["expect"]


@pytest.mark.parametrize("lines, fragment", [
    (["{not json"], "line 1: not valid JSON"),
    (["[1, 2]"], "JSON object"),
    ([json.dumps({"prompt": "x"})], "'id'"),
    ([rec("a", "x"), rec("a", "y")], "duplicate id"),
    ([rec("a", "x", {"rooms": [{"all": ["x"]}]})], "line 1"),
])
def test_bad_files_raise_one_line(tmp_path, lines, fragment):
    p = write(tmp_path, lines)
    with pytest.raises(EvalError) as e:
        load_expectations(p)
    assert fragment in str(e.value)
    assert "\n" not in str(e.value)


def test_missing_file(tmp_path):
    with pytest.raises(EvalError, match="not found"):
        load_expectations(tmp_path / "nope.jsonl")
