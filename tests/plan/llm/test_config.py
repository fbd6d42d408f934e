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
        ("[llm]\ntemperature = 'hot'\n", "temperature must be a float"),
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
    with pytest.raises(LLMError, match="at least 16"):
        load_config(env={"ANYHOME_LLM_MAX_TOKENS": "3"})
