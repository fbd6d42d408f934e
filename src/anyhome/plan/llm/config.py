"""Settings of the LLM planner, from (strongest first) command-line options, environment
variables, a TOML config file, then defaults.

Environment: ``ANYHOME_LLM_BASE_URL``, ``ANYHOME_LLM_MODEL``, ``ANYHOME_LLM_API_KEY``
(else ``OPENAI_API_KEY``), ``ANYHOME_LLM_TEMPERATURE``, ``ANYHOME_LLM_TOP_P``,
``ANYHOME_LLM_MAX_TOKENS``, ``ANYHOME_LLM_TIMEOUT_S``, ``ANYHOME_LLM_CONCURRENCY``,
``ANYHOME_CACHE_DIR``; ``ANYHOME_CONFIG`` names the config file (default
``~/.config/anyhome/config.toml``), whose ``[llm]`` table takes the same keys in lower
case without the prefix (``base_url = "http://127.0.0.1:11434/v1"``). The API key is
read from the environment only, never from a file, and never written to any output.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any
from urllib.parse import urlparse

from anyhome.errors import LLMError
from anyhome.sanitize import clean_text, redact_url

DEFAULT_BASE_URL = "http://127.0.0.1:8080/v1"
"""llama.cpp's server on its default port; Ollama is ``http://127.0.0.1:11434/v1``."""
DEFAULT_TEMPERATURE = 0.7
"""The AnyHome paper sampled with temperature 0.7 and top-p 1."""
DEFAULT_TOP_P = 1.0
DEFAULT_MAX_TOKENS = 1024
"""Most tokens one reply may hold, so a small model cannot loop for ever."""
DEFAULT_TIMEOUT_S = 180.0
"""Seconds one request may take in all (connecting, waiting, reading), not per read."""
MAX_TIMEOUT_S = 3600.0
DEFAULT_CONCURRENCY = 2
"""Per-room requests in flight at once (a one-slot server such as llama.cpp's queues them,
and the queueing counts against each request's timeout)."""
MAX_CONCURRENCY = 32
MAX_MAX_TOKENS = 1_000_000
MAX_MODEL_CHARS = 200
ENV_PREFIX = "ANYHOME_LLM_"
CONFIG_ENV = "ANYHOME_CONFIG"
CACHE_ENV = "ANYHOME_CACHE_DIR"


def default_config_file() -> Path:
    return Path(os.environ.get("XDG_CONFIG_HOME") or Path.home() / ".config") / "anyhome" / "config.toml"


def default_cache_dir() -> Path:
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "anyhome" / "llm"


@dataclass(frozen=True)
class LLMConfig:
    """Where the model is and how to sample it. ``model=None``: ask the server."""

    base_url: str = DEFAULT_BASE_URL
    model: str | None = None
    temperature: float = DEFAULT_TEMPERATURE
    top_p: float = DEFAULT_TOP_P
    max_tokens: int = DEFAULT_MAX_TOKENS
    timeout_s: float = DEFAULT_TIMEOUT_S
    concurrency: int = DEFAULT_CONCURRENCY
    cache: bool = True
    cache_dir: Path = field(default_factory=default_cache_dir)
    api_key: str | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        shown = redact_url(self.base_url) if isinstance(self.base_url, str) else repr(self.base_url)
        try:
            url = urlparse(self.base_url)
            url.port  # noqa: B018  (raises on a port that is not a number in 0..65535)
        except (TypeError, ValueError, AttributeError):
            raise LLMError(f"LLM base URL must look like http://host:port/v1, got {shown!r}") from None
        if url.scheme not in ("http", "https") or not url.hostname or clean_text(self.base_url) != self.base_url or " " in self.base_url:
            raise LLMError(f"LLM base URL must look like http://host:port/v1, got {shown!r}")
        if self.model is not None and (not isinstance(self.model, str) or not self.model.strip()
                                       or clean_text(self.model) != self.model or len(self.model) > MAX_MODEL_CHARS):  # fmt: skip
            raise LLMError(f"LLM model must be a name of 1 to {MAX_MODEL_CHARS} printable characters, got {clean_text(str(self.model))[:MAX_MODEL_CHARS]!r}")
        _number("temperature", self.temperature, 0.0, 2.0, "within 0..2")
        _number("top-p", self.top_p, 0.0, 1.0, "within (0, 1]", low_open=True)
        _number("timeout", self.timeout_s, 0.0, MAX_TIMEOUT_S, f"more than 0 and at most {MAX_TIMEOUT_S:g} seconds", low_open=True)
        _integer("max tokens", self.max_tokens, 16, MAX_MAX_TOKENS)
        _integer("concurrency", self.concurrency, 1, MAX_CONCURRENCY)

    def sampling(self) -> dict[str, Any]:
        return {"temperature": self.temperature, "top_p": self.top_p, "max_tokens": self.max_tokens}

    def public(self) -> dict[str, Any]:
        """What may be written to outputs (never the API key)."""
        return {"base_url": redact_url(self.base_url), "model": self.model, **self.sampling()}


def _number(label: str, value: Any, lo: float, hi: float, rule: str, low_open: bool = False) -> None:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if not ok or not (lo < value <= hi if low_open else lo <= value <= hi):
        raise LLMError(f"LLM {label} must be {rule}, got {value!r}")


def _integer(label: str, value: Any, lo: int, hi: int) -> None:
    if not isinstance(value, int) or isinstance(value, bool) or not lo <= value <= hi:
        raise LLMError(f"LLM {label} must be a whole number from {lo} to {hi}, got {value!r}")


_CASTS: dict[str, Any] = {
    "base_url": str, "model": str, "temperature": float, "top_p": float, "max_tokens": int,
    "timeout_s": float, "concurrency": int, "cache_dir": Path,
}  # fmt: skip
_KIND_NAMES = {str: "a string", float: "a number", int: "a whole number", Path: "a folder path"}


def _cast(key: str, value: Any, where: str) -> Any:
    """``value`` (from a TOML file or an environment variable) as the type of ``key``."""
    kind = _CASTS[key]
    shown = redact_url(value) if key == "base_url" and isinstance(value, str) else value
    bad = LLMError(f"{where}: {key} must be {_KIND_NAMES[kind]}, got {clean_text(repr(shown))[:80]}")
    if isinstance(value, bool):  # TOML true/false is no number, path or name
        raise bad
    if kind is int:
        if isinstance(value, float):  # 512.0 is fine; 1e400 (inf), nan and 2.5 are not
            if not math.isfinite(value) or not value.is_integer():
                raise bad
            value = int(value)
        elif isinstance(value, str):
            try:
                value = int(value.strip())
            except ValueError:
                raise bad from None
        if not isinstance(value, int):
            raise bad
        return value
    if kind is float:
        if isinstance(value, str):
            try:
                value = float(value.strip())
            except ValueError:
                raise bad from None
        if not isinstance(value, (int, float)):
            raise bad
        return float(value)
    if not isinstance(value, str) or (kind is Path and (not value or "\0" in value)):
        raise bad
    return kind(value)


def _from_file(path: Path) -> dict[str, Any]:
    try:
        import tomllib  # type: ignore[import-not-found, unused-ignore]  # standard library from 3.11 on
    except ModuleNotFoundError:  # Python 3.10
        raise LLMError("reading a config file needs Python 3.11 or newer (tomllib)") from None
    try:
        data = tomllib.loads(path.read_bytes().decode("utf-8"))
    except OSError as e:
        raise LLMError(f"cannot read config file {path}: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise LLMError(f"config file {path} is not UTF-8 text (byte {e.start})") from None
    except tomllib.TOMLDecodeError as e:
        raise LLMError(f"config file {path} is not valid TOML: {clean_text(str(e))}") from None
    table = data.get("llm", {})
    if not isinstance(table, dict):
        raise LLMError(f"config file {path}: [llm] must be a table")
    if "api_key" in table:
        raise LLMError(f"config file {path}: put the API key in ANYHOME_LLM_API_KEY, not in a file")
    unknown = sorted(set(table) - set(_CASTS))
    if unknown:
        shown = clean_text(", ".join(unknown))[:200]
        raise LLMError(f"config file {path}: unknown [llm] keys {shown} (known: {', '.join(sorted(_CASTS))})")
    return {k: _cast(k, v, str(path)) for k, v in table.items()}


def _from_env(env: dict[str, str]) -> dict[str, Any]:
    out = {}
    for key in _CASTS:
        name = ENV_PREFIX + key.upper()
        if key == "cache_dir":
            name = CACHE_ENV
        if env.get(name):
            out[key] = _cast(key, env[name], name)
    return out


def load_config(options: dict[str, Any] | None = None, env: dict[str, str] | None = None, config_file: str | os.PathLike[str] | None = None) -> LLMConfig:
    """Merge options (None values ignored) over the environment over the config file.

    A config file named explicitly (argument or ``ANYHOME_CONFIG``) must exist; the
    default one is read only if present.
    """
    env = dict(os.environ if env is None else env)
    named = config_file or env.get(CONFIG_ENV)
    path = Path(named) if named else default_config_file()
    values: dict[str, Any] = {}
    if named and not path.is_file():
        raise LLMError(f"config file {path} does not exist")
    if path.is_file():
        values.update(_from_file(path))
    values.update(_from_env(env))
    values.update({k: v for k, v in (options or {}).items() if v is not None})
    key_name = ENV_PREFIX + "API_KEY" if env.get(ENV_PREFIX + "API_KEY") else "OPENAI_API_KEY"
    values["api_key"] = env.get(key_name) or None
    if values["api_key"] is not None and (clean_text(values["api_key"]) != values["api_key"] or not values["api_key"].isascii()):
        raise LLMError(f"{key_name} holds control or non-ASCII characters; an API key cannot be sent so")  # never echo the key
    known = {f.name for f in fields(LLMConfig)}
    return replace(LLMConfig(), **{k: v for k, v in values.items() if k in known})
