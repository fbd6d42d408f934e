"""Structured JSON replies from any OpenAI-compatible chat server, cached on disk.

Servers take structured output differently: OpenAI and vLLM accept
``response_format={"type": "json_schema", ...}``; llama.cpp's server answers that with an
error and takes ``{"type": "json_object", "schema": ...}``; Ollama has its own ``format``.
:class:`LLMClient` tries the modes in :data:`MODES` order, keeps the first the server
accepts and remembers it per base URL (``servers.json`` in the cache folder). The last
mode, ``prompt``, sends no response format and puts the schema in the prompt.

A server that cannot be reached or times out is marked down for the rest of the run:
later calls fail at once (cache hits are still served) and the planner falls back.
"""

from __future__ import annotations

import json
import logging
import re
import threading
import time
from dataclasses import dataclass, field
from typing import Any

from anyhome.errors import LLMError
from anyhome.plan.llm.cache import ReplyCache, request_key
from anyhome.plan.llm.config import LLMConfig

log = logging.getLogger(__name__)

MODES: tuple[str, ...] = ("json_schema", "json_object_schema", "ollama_format", "prompt")
"""Structured-output modes, most precise first."""
NO_KEY = "sk-no-key"
"""Sent as the API key to local servers that need none (the client requires one)."""


class Unavailable(Exception):
    """The server is down, timed out or refused every mode: the stage falls back."""


@dataclass
class Reply:
    content: str
    prompt_tokens: int
    completion_tokens: int
    latency_s: float
    cached: bool
    mode: str


@dataclass
class Usage:
    """Totals of one run (cache hits count their original tokens but no call)."""

    calls: int = 0
    cache_hits: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_s: float = 0.0
    lock: threading.Lock = field(default_factory=threading.Lock, repr=False)

    def add(self, reply: Reply) -> None:
        with self.lock:
            self.calls += not reply.cached
            self.cache_hits += reply.cached
            self.prompt_tokens += reply.prompt_tokens
            self.completion_tokens += reply.completion_tokens
            self.latency_s += 0.0 if reply.cached else reply.latency_s


def request_options(mode: str, schema: dict[str, Any], name: str) -> dict[str, Any]:
    """Keyword arguments of ``chat.completions.create`` that ask for ``schema`` in ``mode``."""
    if mode == "json_schema":
        return {"response_format": {"type": "json_schema", "json_schema": {"name": name, "schema": schema, "strict": True}}}
    if mode == "json_object_schema":
        return {"response_format": {"type": "json_object", "schema": schema}}
    if mode == "ollama_format":
        return {"extra_body": {"format": schema}}
    if mode == "prompt":
        return {}
    raise ValueError(f"unknown structured-output mode {mode!r}")


def schema_in_prompt(messages: list[dict[str, str]], schema: dict[str, Any]) -> list[dict[str, str]]:
    """The messages with the schema appended to the last one (mode ``prompt``)."""
    last = messages[-1]
    text = f"{last['content']}\n\nReply with one JSON object that matches this JSON Schema:\n{json.dumps(schema, separators=(',', ':'))}"
    return [*messages[:-1], {**last, "content": text}]


_FENCE = re.compile(r"```(?:json)?\s*(.*?)```", re.DOTALL)


def parse_json(content: str) -> Any:
    """The JSON object in a reply, allowing code fences or text around it.

    Raises ValueError with a short reason."""
    text = content.strip()
    m = _FENCE.search(text)
    if m:
        text = m.group(1).strip()
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        pass
    start, end = text.find("{"), text.rfind("}")
    if start < 0 or end <= start:
        raise ValueError("the reply holds no JSON object" + (" (it was cut off)" if start >= 0 else ""))
    try:
        return json.loads(text[start : end + 1])
    except json.JSONDecodeError as e:
        raise ValueError(f"the reply is not valid JSON: {e.msg} at character {e.pos}") from None


class LLMClient:
    """One OpenAI-compatible server, one model, a reply cache."""

    def __init__(self, config: LLMConfig, cache: ReplyCache | None = None) -> None:
        try:
            import openai
        except ModuleNotFoundError:
            raise LLMError("the LLM planner needs the openai client: pip install 'anyhome[llm]'") from None
        self._openai = openai
        self.config = config
        self.cache = cache or ReplyCache(config.cache_dir, enabled=config.cache)
        self._client = openai.OpenAI(
            base_url=config.base_url, api_key=config.api_key or NO_KEY,
            timeout=config.timeout_s, max_retries=0,
        )  # fmt: skip
        note = self.cache.server_note(config.base_url)
        self.mode: str | None = note.get("mode") if note.get("mode") in MODES else None
        self.down: str | None = None
        self.usage = Usage()
        self._model = config.model
        self._mode_lock = threading.Lock()

    # ------------------------------------------------------------ model
    def model(self) -> str:
        """The configured model, else the one this server served last time, else the first
        the server lists. Raises Unavailable when none can be found."""
        if self._model:
            return self._model
        note = self.cache.server_note(self.config.base_url)
        if note.get("model"):
            self._model = str(note["model"])
            return self._model
        try:
            listed = [m.id for m in self._client.models.list()]
        except self._openai.APIError as e:
            self._mark_down(e)
            raise Unavailable(self.down or "no model") from None
        if not listed:
            raise Unavailable(f"{self.config.base_url} lists no model; set --llm-model")
        self._model = listed[0]
        self.cache.remember_server(self.config.base_url, model=self._model)
        return self._model

    def _mark_down(self, e: Exception) -> None:
        if isinstance(e, self._openai.APITimeoutError):
            self.down = f"the LLM server at {self.config.base_url} timed out after {self.config.timeout_s:g} s"
        elif isinstance(e, self._openai.APIConnectionError):
            self.down = f"the LLM server at {self.config.base_url} is unreachable"
        elif isinstance(e, self._openai.AuthenticationError):
            self.down = f"the LLM server at {self.config.base_url} refused the API key"
        else:
            self.down = f"the LLM server at {self.config.base_url} failed: {type(e).__name__}"

    # ------------------------------------------------------------ calls
    def chat_json(self, messages: list[dict[str, str]], schema: dict[str, Any], name: str, seed: int, max_tokens: int | None = None) -> Reply:
        """One reply for ``messages`` that should match ``schema``: from the cache, else
        from the server. Raises Unavailable when the server cannot answer."""
        sampling = {**self.config.sampling(), "seed": int(seed)}
        if max_tokens is not None:
            sampling["max_tokens"] = min(int(max_tokens), self.config.max_tokens)
        model = self.model()
        key = request_key(self.config.base_url, model, messages, schema, sampling)
        hit = self.cache.get(key)
        if hit is not None:
            reply = Reply(hit["content"], int(hit.get("prompt_tokens", 0)), int(hit.get("completion_tokens", 0)),
                          float(hit.get("latency_s", 0.0)), True, str(hit.get("mode", "")))  # fmt: skip
            self.usage.add(reply)
            return reply
        if self.down:
            raise Unavailable(self.down)
        if self.mode is None:
            with self._mode_lock:  # one request finds the mode; the others then use it
                reply = self._send(model, messages, schema, name, sampling)
        else:
            reply = self._send(model, messages, schema, name, sampling)
        self.cache.put(key, {
            "model": model, "name": name, "messages": messages, "content": reply.content, "mode": reply.mode,
            "prompt_tokens": reply.prompt_tokens, "completion_tokens": reply.completion_tokens,
            "latency_s": round(reply.latency_s, 3),
        })  # fmt: skip
        self.usage.add(reply)
        return reply

    def _send(self, model: str, messages: list[dict[str, str]], schema: dict[str, Any], name: str, sampling: dict[str, Any]) -> Reply:
        modes = [self.mode] if self.mode else list(MODES)
        refusals = []
        for mode in modes:
            if self.down:
                raise Unavailable(self.down)
            sent = schema_in_prompt(messages, schema) if mode == "prompt" else messages
            t0 = time.perf_counter()
            try:
                resp = self._client.chat.completions.create(
                    model=model, messages=sent, **sampling, **request_options(mode, schema, name),
                )  # fmt: skip
            except (self._openai.APIConnectionError, self._openai.AuthenticationError) as e:
                self._mark_down(e)
                raise Unavailable(self.down) from None
            except self._openai.APIStatusError as e:  # this server does not take this mode
                refusals.append(f"{mode}: HTTP {e.status_code}")
                log.info("%s refused structured-output mode %s: HTTP %s", self.config.base_url, mode, e.status_code)
                continue
            latency = round(time.perf_counter() - t0, 3)  # as the cache keeps it, so a rerun sums the same
            if self.mode != mode:
                self.mode = mode
                self.cache.remember_server(self.config.base_url, mode=mode, model=model)
            content = resp.choices[0].message.content or "" if resp.choices else ""
            usage = resp.usage
            return Reply(content, int(getattr(usage, "prompt_tokens", 0) or 0), int(getattr(usage, "completion_tokens", 0) or 0),
                         latency, False, mode)  # fmt: skip
        if self.mode and len(modes) == 1:  # the remembered mode stopped working: detect again
            self.mode = None
            return self._send(model, messages, schema, name, sampling)
        raise Unavailable(f"the LLM server at {self.config.base_url} refused every request ({'; '.join(refusals)})")
