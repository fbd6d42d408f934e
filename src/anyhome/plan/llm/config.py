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

import os
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any
from urllib.parse import urlparse

from anyhome.errors import LLMError

DEFAULT_BASE_URL = "http://127.0.0.1:8080/v1"
"""llama.cpp's server on its default port; Ollama is ``http://127.0.0.1:11434/v1``."""
DEFAULT_TEMPERATURE = 0.7
"""The AnyHome paper sampled with temperature 0.7 and top-p 1."""
DEFAULT_TOP_P = 1.0
DEFAULT_MAX_TOKENS = 1024
"""Most tokens one reply may hold, so a small model cannot loop for ever."""
DEFAULT_TIMEOUT_S = 180.0
DEFAULT_CONCURRENCY = 2
"""Per-room requests in flight at once (a one-slot server such as llama.cpp's queues them,
and the queueing counts against each request's timeout)."""
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
        url = urlparse(self.base_url)
        if url.scheme not in ("http", "https") or not url.netloc:
            raise LLMError(f"LLM base URL must look like http://host:port/v1, got {self.base_url!r}")
        if not 0.0 <= self.temperature <= 2.0:
            raise LLMError(f"LLM temperature must be within 0..2, got {self.temperature}")
        if not 0.0 < self.top_p <= 1.0:
            raise LLMError(f"LLM top-p must be within (0, 1], got {self.top_p}")
        if self.max_tokens < 16:
            raise LLMError(f"LLM max tokens must be at least 16, got {self.max_tokens}")
        if self.timeout_s <= 0:
            raise LLMError(f"LLM timeout must be positive, got {self.timeout_s}")
        if self.concurrency < 1:
            raise LLMError(f"LLM concurrency must be at least 1, got {self.concurrency}")

    def sampling(self) -> dict[str, Any]:
        return {"temperature": self.temperature, "top_p": self.top_p, "max_tokens": self.max_tokens}

    def public(self) -> dict[str, Any]:
        """What may be written to outputs (never the API key)."""
        return {"base_url": self.base_url, "model": self.model, **self.sampling()}


_CASTS: dict[str, Any] = {
    "base_url": str, "model": str, "temperature": float, "top_p": float, "max_tokens": int,
    "timeout_s": float, "concurrency": int, "cache_dir": Path,
}  # fmt: skip


def _cast(key: str, value: Any, where: str) -> Any:
    try:
        return _CASTS[key](value)
    except (TypeError, ValueError):
        raise LLMError(f"{where}: {key} must be a {_CASTS[key].__name__}, got {value!r}") from None


def _from_file(path: Path) -> dict[str, Any]:
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        raise LLMError("reading a config file needs Python 3.11 or newer (tomllib)") from None
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as e:
        raise LLMError(f"cannot read config file {path}: {e.strerror}") from None
    except tomllib.TOMLDecodeError as e:
        raise LLMError(f"config file {path} is not valid TOML: {e}") from None
    table = data.get("llm", {})
    if not isinstance(table, dict):
        raise LLMError(f"config file {path}: [llm] must be a table")
    if "api_key" in table:
        raise LLMError(f"config file {path}: put the API key in ANYHOME_LLM_API_KEY, not in a file")
    unknown = sorted(set(table) - set(_CASTS))
    if unknown:
        raise LLMError(f"config file {path}: unknown [llm] keys {', '.join(unknown)} (known: {', '.join(sorted(_CASTS))})")
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
    values["api_key"] = env.get(ENV_PREFIX + "API_KEY") or env.get("OPENAI_API_KEY") or None
    known = {f.name for f in fields(LLMConfig)}
    return replace(LLMConfig(), **{k: v for k, v in values.items() if k in known})
