import json
from pathlib import Path

from anyhome.plan.llm.cache import MAX_ENTRY_BYTES, ReplyCache, request_key

MSGS = [{"role": "user", "content": "hi"}]


def test_key_changes_with_every_input() -> None:
    base = request_key("http://a/v1", "m", MSGS, {"type": "object"}, {"temperature": 0.7})
    assert base == request_key("http://a/v1/", "m", MSGS, {"type": "object"}, {"temperature": 0.7})
    others = [
        request_key("http://b/v1", "m", MSGS, {"type": "object"}, {"temperature": 0.7}),
        request_key("http://a/v1", "m2", MSGS, {"type": "object"}, {"temperature": 0.7}),
        request_key("http://a/v1", "m", [{"role": "user", "content": "ho"}], {"type": "object"}, {"temperature": 0.7}),
        request_key("http://a/v1", "m", MSGS, {"type": "array"}, {"temperature": 0.7}),
        request_key("http://a/v1", "m", MSGS, {"type": "object"}, {"temperature": 0.2}),
    ]
    assert len({base, *others}) == 6


def test_put_get_roundtrip_and_disabled(tmp_path: Path) -> None:
    c = ReplyCache(tmp_path)
    assert c.get("ab" * 32) is None
    c.put("ab" * 32, {"content": "{}", "prompt_tokens": 3})
    assert c.get("ab" * 32)["prompt_tokens"] == 3
    assert (tmp_path / "ab" / f"{'ab' * 32}.json").is_file()
    off = ReplyCache(tmp_path, enabled=False)
    assert off.get("ab" * 32) is None
    off.put("cd" * 32, {"content": "{}"})
    assert not (tmp_path / "cd").exists()


def test_damaged_entry_is_a_miss(tmp_path: Path) -> None:
    c = ReplyCache(tmp_path)
    key = "ef" * 32
    (tmp_path / "ef").mkdir()
    (tmp_path / "ef" / f"{key}.json").write_text("{not json", encoding="utf-8")
    assert c.get(key) is None
    (tmp_path / "ef" / f"{key}.json").write_text(json.dumps({"content": 3}), encoding="utf-8")
    assert c.get(key) is None


def test_server_notes_merge_and_persist(tmp_path: Path) -> None:
    c = ReplyCache(tmp_path)
    c.remember_server("http://a/v1/", mode="json_object_schema")
    c.remember_server("http://a/v1", model="smol")
    assert ReplyCache(tmp_path).server_note("http://a/v1") == {"mode": "json_object_schema", "model": "smol"}
    assert c.server_note("http://other/v1") == {}


def test_credentials_are_neither_hashed_nor_recorded(tmp_path: Path) -> None:
    with_pw = request_key("http://u:SECRETPW@a/v1", "m", MSGS, {}, {})
    assert with_pw == request_key("http://a/v1", "m", MSGS, {}, {})  # the key is of the redacted URL
    c = ReplyCache(tmp_path)
    c.remember_server("http://u:SECRETPW@a/v1", mode="prompt")
    assert c.server_note("http://a/v1") == {"mode": "prompt"}
    assert b"SECRETPW" not in (tmp_path / "servers.json").read_bytes()


def test_entries_are_ascii_and_oversized_ones_are_misses(tmp_path: Path) -> None:
    c = ReplyCache(tmp_path)
    c.put("ab" * 32, {"content": "caf\u00e9 \x1b]0;t\x07 \x9b"})
    path = tmp_path / "ab" / f"{'ab' * 32}.json"
    assert path.read_bytes().isascii() and c.get("ab" * 32)["content"] == "caf\u00e9 \x1b]0;t\x07 \x9b"  # lossless
    path.write_text(json.dumps({"content": "x" * (MAX_ENTRY_BYTES + 1)}), encoding="utf-8")
    assert c.get("ab" * 32) is None
    path.write_text("[" * 100_000 + "]" * 100_000, encoding="utf-8")
    assert c.get("ab" * 32) is None
