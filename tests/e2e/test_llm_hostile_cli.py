"""End to end: ``anyhome generate --planner llm`` in a subprocess against the fake
OpenAI-compatible server serving hostile answers, with an API key planted in the
environment and credentials in the base URL. Bad LLM settings are one ``error:`` line."""

from __future__ import annotations

import json
import os
import struct
import subprocess
import sys
from pathlib import Path

import pytest
from fake_llm_server import PROGRAM, Answer, appearance, fake_llm  # noqa: F401

from anyhome.sanitize import clean_text

KEY = "sk-PLANTED-7c1e0b9d4a"
PASSWORD = "SECRETPW"
RUN_TIMEOUT_S = 120  # a hang guard, not a speed target
CAT = "a cat cafe"


def run(args: list[str], tmp_path: Path, **env: str) -> subprocess.CompletedProcess:
    full_env = {**os.environ, "ANYHOME_LLM_API_KEY": KEY, "ANYHOME_CACHE_DIR": str(tmp_path / "cache"),
                "XDG_CONFIG_HOME": str(tmp_path / "no-config"), **env}  # fmt: skip
    return subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True, text=True,
                          timeout=RUN_TIMEOUT_S, env=full_env)  # fmt: skip


def controls(text: str) -> str:
    """The control characters of ``text`` other than newlines and tabs (empty if none)."""
    return "".join(sorted({c for c in text if clean_text(c, newlines=True) != c}))


def glb_json(data: bytes) -> str:
    """The glTF JSON chunk of a GLB file."""
    magic, _, _ = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF"
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A  # JSON
    return data[20 : 20 + length].decode("utf-8")


def test_no_secret_and_no_control_character_in_any_output(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    program = json.loads(json.dumps(PROGRAM))
    program["rooms"][1]["name"] = "\x1b]0;pwned\x07kitchen\x1b[31m\x9b"
    fake_llm.script["program"] = Answer.chat(json.dumps(program))
    look = appearance(["living_room", "kitchen", "bedroom"], style="\x1b]0;pwned\x07cozy\x1b[31m red\x1b[0m",
                      palette=["\x1b[1mcream\x00", "oak\u202e"])  # fmt: skip
    fake_llm.script["appearance"] = Answer.chat(json.dumps(look))
    fake_llm.script["furniture"] = Answer.huge_chat(50_000_000)  # each room's furniture: a 50 MB reply
    fake_llm.script["ornaments"] = Answer(body=b"<html>\x1b]0;pwned\x07</html>", content_type="text/html")
    url = fake_llm.base_url.replace("http://", f"http://user:{PASSWORD}@")
    out = tmp_path / "house"
    # -v: the debug and HTTP logs of the libraries below go to stderr too, and are scanned
    proc = run(["-v", "generate", CAT, "--planner", "llm", "--llm-base-url", url, "--out", str(out), "--llm-timeout", "10"], tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert fake_llm.chat_requests("furniture") and fake_llm.chat_requests("ornaments")  # the server was asked

    house = json.loads((out / "house.json").read_text(encoding="utf-8"))
    assert house["style"] == "cozy red" and "kitchen" in [r["name"] for r in house["rooms"]]
    assert house["provenance"]["llm"]["base_url"] == fake_llm.base_url
    stages = {s["stage"]: s["source"] for s in house["provenance"]["stages"]}
    assert stages["program"] == stages["appearance"] == "llm"
    assert {v for k, v in stages.items() if k.startswith(("furniture:", "ornaments:"))} == {"offline"}
    assert any("larger than 1024 KiB" in w for w in house["warnings"])
    assert f"at {fake_llm.base_url}:" in proc.stdout  # the summary shows the redacted URL
    assert "Warning: LLM furniture:" in proc.stdout

    files = [p for p in [*out.rglob("*"), *(tmp_path / "cache").rglob("*")] if p.is_file()]
    assert {"house.json", "house.glb", "floorplan.svg", "servers.json"} <= {p.name for p in files}
    for p in files:
        data = p.read_bytes()
        assert KEY.encode() not in data and PASSWORD.encode() not in data, p
        assert b"pwned" not in data or p.parent.parent == tmp_path / "cache", p  # only the raw cached reply
        text = glb_json(data) if p.suffix == ".glb" else data.decode("utf-8")
        assert not controls(text), (p, controls(text))
    assert sum(p.stat().st_size for p in files if p.is_relative_to(tmp_path / "cache")) < 256 * 1024
    assert (out / "house.json").stat().st_size < 1024 * 1024
    assert "HTTP Request: POST" in proc.stderr  # the library logs were on
    for stream in (proc.stdout, proc.stderr):
        assert KEY not in stream and PASSWORD not in stream and "dXNlcjpTRUNSRVRQVw" not in stream
        assert not controls(stream), controls(stream)

    check = run(["eval", str(out), "--strict"], tmp_path)
    assert check.returncode == 0, check.stdout[-2000:]


@pytest.mark.parametrize(
    "flags",
    [
        ["--llm-timeout", "nan"],
        ["--llm-timeout", "inf"],
        ["--llm-timeout", "0"],
        ["--llm-temperature", "nan"],
        ["--llm-top-p", "2"],
        ["--llm-concurrency", "100000"],
        ["--llm-base-url", f"ftp://user:{PASSWORD}@127.0.0.1:1/v1"],
    ],
)
def test_bad_llm_flags_are_one_error_line_before_any_work(fake_llm, tmp_path: Path, flags: list[str]) -> None:  # noqa: F811
    out = tmp_path / "house"
    proc = run(["generate", CAT, "--planner", "llm", "--llm-base-url", fake_llm.base_url, "--out", str(out), *flags], tmp_path)
    assert proc.returncode == 2, proc.stderr
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: LLM "), proc.stderr
    assert PASSWORD not in proc.stderr and "Traceback" not in proc.stderr
    assert not out.exists() and fake_llm.requests == []  # nothing generated, nothing asked


@pytest.mark.parametrize(
    "content, match",
    [
        (b"[llm]\nmax_tokens = 1e400\n", "max_tokens must be a whole number"),
        (b"[llm]\nmodel = '\xff\xfe'\n", "is not UTF-8"),
        (b"[llm\n", "is not valid TOML"),
        (b"[llm]\napi_key = 'sk-x'\n", "ANYHOME_LLM_API_KEY"),
    ],
)
def test_bad_config_files_through_the_cli(fake_llm, tmp_path: Path, content: bytes, match: str) -> None:  # noqa: F811
    config = tmp_path / "config.toml"
    config.write_bytes(content)
    out = tmp_path / "house"
    proc = run(["generate", CAT, "--planner", "llm", "--llm-base-url", fake_llm.base_url, "--out", str(out), "--config", str(config)], tmp_path)
    assert proc.returncode == 2, proc.stderr
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: ") and match in lines[0], proc.stderr
    assert not out.exists() and fake_llm.requests == []
