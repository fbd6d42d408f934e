"""The sanitising helpers every output path uses."""

from hypothesis import given
from hypothesis import strategies as st

from anyhome.sanitize import clean_text, is_safe_id, redact_url


def test_escape_sequences_removed_whole():
    assert clean_text("a\x1b]0;pwned\x07b") == "ab"
    assert clean_text("\x1b[31mred\x1b[0m sofa") == "red sofa"
    assert clean_text("x\x1bPq#0;2;0;0;0\x1b\\y") == "xy"


def test_controls_and_bidi_removed():
    assert clean_text("be\x00d\x07room\x7f\x85") == "bedroom"
    assert clean_text("safe\u202eexe.txt") == "safeexe.txt"
    assert clean_text("two\nlines") == "two lines"
    assert clean_text("two\nlines", newlines=True) == "two\nlines"
    assert clean_text("sé\tance") == "sé\tance"


@given(st.text())
def test_clean_text_has_no_controls(s):
    out = clean_text(s)
    assert not any(ord(c) < 32 and c != "\t" for c in out)
    assert not any(0x7F <= ord(c) <= 0x9F for c in out)
    assert clean_text(out) == out


def test_ids():
    assert is_safe_id("living_room-couch-0")
    assert is_safe_id("door-3")
    for bad in ['x" onmouseover="alert(1)', "", "a b", "ü", "a/b", "x" * 129, "-lead"]:
        assert not is_safe_id(bad), bad


def test_redact_url():
    assert redact_url("http://user:sk-SECRET@host:8080/v1") == "http://host:8080/v1"
    assert redact_url("https://sk-SECRET@api.example/v1") == "https://api.example/v1"
    assert redact_url("http://127.0.0.1:8080/v1") == "http://127.0.0.1:8080/v1"
    assert "SECRET" not in redact_url("http://u:SECRET@[::1]:99/v1")
    assert "SECRET" not in redact_url("http://u:SECRET@host:notaport/v1")
