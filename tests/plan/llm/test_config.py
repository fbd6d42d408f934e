from pathlib import Path

import pytest

from anyhome.errors import LLMError
from anyhome.plan.llm.config import DEFAULT_BASE_URL, LLMConfig, load_config


def _file(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "config.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_defaults_without_env_or_file(tmp_path: Path) -> None:
    c = load_config(env={"XDG_CONFIG_HOME": str(tmp_path)})
    assert c.base_url == DEFAULT_BASE_URL
    assert c.model is None
    assert (c.temperature, c.top_p) == (0.7, 1.0)  # the paper's sampling
    assert c.api_key is None


def test_options_beat_env_beat_file(tmp_path: Path) -> None:
    f = _file(tmp_path, '[llm]\nbase_url = "http://file:1/v1"\nmodel = "file-model"\ntemperature = 0.1\ntop_p = 0.5\n')
    env = {"ANYHOME_LLM_MODEL": "env-model", "ANYHOME_LLM_TEMPERATURE": "0.3"}
    c = load_config({"temperature": 0.9, "model": None}, env=env, config_file=f)
    assert c.base_url == "http://file:1/v1"  # only the file sets it
    assert c.model == "env-model"  # env over file; a None option is ignored
    assert c.temperature == 0.9  # option over env
    assert c.top_p == 0.5


def test_config_file_from_env_variable(tmp_path: Path) -> None:
    f = _file(tmp_path, '[llm]\nmodel = "m"\ncache_dir = "/tmp/x"\n')
    c = load_config(env={"ANYHOME_CONFIG": str(f)})
    assert c.model == "m" and c.cache_dir == Path("/tmp/x")


def test_api_key_comes_from_the_environment_only(tmp_path: Path) -> None:
    assert load_config(env={"OPENAI_API_KEY": "k1"}).api_key == "k1"
    assert load_config(env={"OPENAI_API_KEY": "k1", "ANYHOME_LLM_API_KEY": "k2"}).api_key == "k2"
    f = _file(tmp_path, '[llm]\napi_key = "secret"\n')
    with pytest.raises(LLMError, match="ANYHOME_LLM_API_KEY"):
        load_config(env={}, config_file=f)
    c = LLMConfig(api_key="secret-key")
    assert "secret-key" not in repr(c) and "secret-key" not in str(c.public())


@pytest.mark.parametrize(
    "text, match",
    [
        ("[llm]\nmodle = 'x'\n", "unknown \\[llm\\] keys modle"),
        ("[llm\n", "not valid TOML"),
        ("[llm]\ntemperature = 'hot'\n", "temperature must be a number"),
        ("[llm]\ntemperature = 5.0\n", "temperature must be within"),
        ("[llm]\nbase_url = 'localhost:8080'\n", "base URL must look like"),
    ],
)
def test_bad_config_files_give_one_line_errors(tmp_path: Path, text: str, match: str) -> None:
    with pytest.raises(LLMError, match=match) as e:
        load_config(env={}, config_file=_file(tmp_path, text))
    assert "\n" not in str(e.value)


def test_a_named_config_file_must_exist(tmp_path: Path) -> None:
    with pytest.raises(LLMError, match="does not exist"):
        load_config(env={"ANYHOME_CONFIG": str(tmp_path / "nope.toml")})


def test_bad_env_values(tmp_path: Path) -> None:
    with pytest.raises(LLMError, match="ANYHOME_LLM_MAX_TOKENS"):
        load_config(env={"ANYHOME_LLM_MAX_TOKENS": "lots"})
    with pytest.raises(LLMError, match="max tokens must be a whole number from 16"):
        load_config(env={"ANYHOME_LLM_MAX_TOKENS": "3"})


BAD_NUMBERS = [
    ("timeout_s", float("nan")), ("timeout_s", float("inf")), ("timeout_s", 0.0), ("timeout_s", -1.0), ("timeout_s", 1e9),
    ("temperature", float("nan")), ("temperature", float("inf")), ("temperature", -0.1), ("temperature", 2.5),
    ("top_p", float("nan")), ("top_p", float("-inf")), ("top_p", 0.0), ("top_p", 1.5),
    ("max_tokens", 0), ("max_tokens", 10**12), ("concurrency", 0), ("concurrency", 10**6), ("concurrency", -3),
]  # fmt: skip


@pytest.mark.parametrize("key, value", BAD_NUMBERS)
def test_bad_numbers_are_one_line_errors_from_options_env_and_file(tmp_path: Path, key: str, value: float) -> None:
    for where in ("options", "env", "file"):
        options, env, file = None, {"XDG_CONFIG_HOME": str(tmp_path)}, None
        if where == "options":
            options = {key: value}
        elif where == "env":
            env["ANYHOME_LLM_" + key.upper()] = repr(value)
        else:
            literal = {"nan": "nan", "inf": "inf", "-inf": "-inf"}.get(repr(value), repr(value))
            file = _file(tmp_path, f"[llm]\n{key} = {literal}\n")
        with pytest.raises(LLMError) as e:
            load_config(options, env=env, config_file=file)
        assert "\n" not in str(e.value) and key.split("_")[0].replace("top", "top-") in str(e.value).lower().replace("top_p", "top-p")


@pytest.mark.parametrize(
    "text, match",
    [
        ("[llm]\nmax_tokens = 1e400\n", "max_tokens must be a whole number"),  # TOML reads it as inf
        ("[llm]\nmax_tokens = nan\n", "max_tokens must be a whole number"),
        ("[llm]\nmax_tokens = 100.5\n", "max_tokens must be a whole number"),
        ("[llm]\nconcurrency = true\n", "concurrency must be a whole number"),
        ("[llm]\ntemperature = false\n", "temperature must be a number"),
        ("[llm]\ntimeout_s = 'soon'\n", "timeout_s must be a number"),
        ("[llm]\nmodel = 7\n", "model must be a string"),
        ("[llm]\ncache_dir = ''\n", "cache_dir must be a folder path"),
        ("[llm]\nbase_url = 'http://h:99999/v1'\n", "base URL must look like"),
        ("[llm]\nbase_url = 'http://u:SECRETPW@h:1/v1 x'\n", "base URL must look like"),
        ('[llm]\nmodel = "\\u001b]0;pwned\\u0007m"\n', "model must be a name"),
        ("llm = 3\n", "must be a table"),
    ],
)
def test_more_bad_config_files(tmp_path: Path, text: str, match: str) -> None:
    with pytest.raises(LLMError, match=match) as e:
        load_config(env={}, config_file=_file(tmp_path, text))
    msg = str(e.value)
    assert "\n" not in msg and "\x1b" not in msg and "\x07" not in msg and "SECRETPW" not in msg


def test_integral_floats_are_whole_numbers(tmp_path: Path) -> None:
    c = load_config(env={}, config_file=_file(tmp_path, "[llm]\nmax_tokens = 512.0\nconcurrency = 3\ntimeout_s = 2\n"))
    assert (c.max_tokens, c.concurrency, c.timeout_s) == (512, 3, 2.0)


def test_a_config_file_that_is_not_utf8_is_one_line(tmp_path: Path) -> None:
    p = tmp_path / "config.toml"
    p.write_bytes(b"[llm]\nmodel = '\xff\xfe caf\xe9'\n")
    with pytest.raises(LLMError, match="not UTF-8") as e:
        load_config(env={}, config_file=p)
    assert "\n" not in str(e.value)


def test_credentials_in_the_base_url_are_never_shown(tmp_path: Path) -> None:
    c = load_config({"base_url": "http://user:SECRETPW@127.0.0.1:9/v1"}, env={})
    assert c.base_url == "http://user:SECRETPW@127.0.0.1:9/v1"  # still used for the requests
    assert c.public()["base_url"] == "http://127.0.0.1:9/v1" and "SECRETPW" not in repr(c.public())
    with pytest.raises(LLMError) as e:
        load_config({"base_url": "ftp://user:SECRETPW@127.0.0.1:9/v1"}, env={})
    assert "SECRETPW" not in str(e.value)


def test_an_api_key_with_control_characters_is_refused_without_echoing_it() -> None:
    with pytest.raises(LLMError, match="ANYHOME_LLM_API_KEY") as e:
        load_config(env={"ANYHOME_LLM_API_KEY": "sk-abc\r\nX-Evil: 1"})
    assert "sk-abc" not in str(e.value)
