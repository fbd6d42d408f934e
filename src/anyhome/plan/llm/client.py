"""Structured JSON replies from any OpenAI-compatible chat server, cached on disk.

Servers take structured output differently: OpenAI and vLLM accept
``response_format={"type": "json_schema", ...}``; llama.cpp's server answers that with an
error and takes ``{"type": "json_object", "schema": ...}``; Ollama has its own ``format``.
:class:`LLMClient` tries the modes in :data:`MODES` order, keeps the first the server
accepts and remembers it per base URL (``servers.json`` in the cache folder). The last
mode, ``prompt``, sends no response format and puts the schema in the prompt.

A server that cannot be reached or times out is marked down for the rest of the run:
later calls fail at once (cache hits are still served) and the planner falls back.

Whatever the server sends is treated as hostile. Every request has a total deadline
(``timeout_s``: connecting, waiting and reading together, not per read), enforced by the
transport under the openai client (:class:`_GuardedTransport`), which also stops reading
a body past :data:`MAX_BODY_BYTES`. The answer is parsed here, not by the openai client,
so a body that is not JSON, has no choices, or holds a content that is no string is a
rejected reply (:class:`ReplyRejected`) and never a crash; a content longer than
:data:`MAX_REPLY_CHARS` is rejected too, and neither is cached. Credentials in the base
URL are used for the requests but every recorded or shown form of it is redacted.
"""

from __future__ import annotations

import json
import logging
import re
import socket
import sys
import threading
import time
import urllib.request
from dataclasses import dataclass, field
from typing import Any

from anyhome.errors import LLMError
from anyhome.plan.llm.cache import ReplyCache, request_key
from anyhome.plan.llm.config import LLMConfig
from anyhome.sanitize import clean_text, redact_url

log = logging.getLogger(__name__)

MODES: tuple[str, ...] = ("json_schema", "json_object_schema", "ollama_format", "prompt")
"""Structured-output modes, most precise first."""
NO_KEY = "sk-no-key"
"""Sent as the API key to local servers that need none (the client requires one)."""
MAX_REPLY_CHARS = 256 * 1024
"""Longest message content accepted from the model; a longer one is rejected, not cached."""
MAX_BODY_BYTES = 4 * MAX_REPLY_CHARS
"""Most bytes of one HTTP answer read (the JSON around the content, its escapes); the
transport stops reading past this."""
MAX_CLAIMED_TOKENS = 10_000_000
"""A token count claimed by a server above this (or not a whole number) counts as 0."""
MAX_MODEL_CHARS = 200
"""Longest model name taken from a server's /models list."""


class Unavailable(Exception):
    """The server is down, timed out or refused every mode: the stage falls back."""


class ReplyRejected(Unavailable):
    """The server answered, but nothing usable: a body that is not an OpenAI chat answer,
    or a content too large. That stage falls back; the server is not marked down."""


class _TooLarge(Exception):
    """Raised by the transport when an answer's body passes MAX_BODY_BYTES."""


def _httpx_module(openai: Any) -> Any:
    """The httpx module the openai client is built on (httpx, or httpx2 in newer releases)."""
    for cls in openai.DefaultHttpxClient.__mro__:
        if cls.__name__ == "Client" and cls.__module__.split(".")[0] != "openai":
            return sys.modules[cls.__module__.split(".")[0]]
    raise LLMError("the openai client's HTTP library was not found")  # pragma: no cover


def _shut(sock: Any) -> None:
    """Wake any thread blocked reading ``sock``: its read returns at once."""
    try:
        socket.socket.shutdown(sock, socket.SHUT_RDWR)  # the base method: an SSL socket keeps its state
    except (OSError, TypeError, ValueError):
        pass


def _guarded_transport(httpx: Any, timeout_s: float, max_body: int, proxy: str | None) -> Any:
    """An httpx transport whose every request ends by ``timeout_s`` after it starts, and
    whose answers are read whole up to ``max_body`` bytes (more raises :class:`_TooLarge`).

    httpx's timeouts are per operation, so a server sending one byte a second never trips
    them. Here a timer shuts the request's socket down at the deadline (the socket comes
    from httpcore's documented ``trace`` extension; connections are not kept alive, so
    every request makes its own), which ends any blocked read, headers included."""

    class _GuardedTransport(httpx.BaseTransport):
        def __init__(self) -> None:
            limits = httpx.Limits(max_connections=None, max_keepalive_connections=0)
            self.inner = httpx.HTTPTransport(limits=limits, proxy=proxy)

        def handle_request(self, request: Any) -> Any:
            lock = threading.Lock()
            socks: list[Any] = []
            fired = threading.Event()
            previous = request.extensions.get("trace")

            def trace(name: str, info: dict[str, Any]) -> None:
                if name.endswith((".connect_tcp.complete", ".start_tls.complete")) and info.get("return_value") is not None:
                    sock = info["return_value"].get_extra_info("socket")
                    with lock:
                        socks.append(sock)
                        if fired.is_set():
                            _shut(sock)
                if previous is not None:
                    previous(name, info)

            def cut() -> None:
                with lock:
                    fired.set()
                    for sock in socks:
                        _shut(sock)

            request.extensions = {**request.extensions, "trace": trace}
            request.headers["Accept-Encoding"] = "identity"  # no compressed body to blow up
            deadline = time.monotonic() + timeout_s
            timer = threading.Timer(timeout_s, cut)
            timer.daemon = True
            timer.start()
            try:
                response = self.inner.handle_request(request)
                chunks, size = [], 0
                try:
                    for chunk in response.stream:
                        size += len(chunk)
                        if size > max_body:
                            raise _TooLarge(f"the answer was larger than {max_body // 1024} KiB")
                        if fired.is_set() or time.monotonic() > deadline:
                            break
                        chunks.append(chunk)
                finally:
                    response.close()
                if fired.is_set() or time.monotonic() > deadline:  # a cut body may look complete
                    raise httpx.ReadTimeout(f"no complete answer within {timeout_s:g} s", request=request)
            except httpx.TransportError:
                if fired.is_set():
                    raise httpx.ReadTimeout(f"no complete answer within {timeout_s:g} s", request=request) from None
                raise
            finally:
                timer.cancel()
            headers = [(k, v) for k, v in response.headers.raw
                       if k.lower() not in (b"content-encoding", b"transfer-encoding", b"content-length")]  # fmt: skip
            return httpx.Response(response.status_code, headers=headers, content=b"".join(chunks), request=request,
                                  extensions={k: v for k, v in response.extensions.items() if k in ("http_version", "reason_phrase")})  # fmt: skip

        def close(self) -> None:
            self.inner.close()

    return _GuardedTransport()


def _proxy_for(base_url: str) -> str | None:
    """The proxy the environment names for ``base_url`` (``HTTP(S)_PROXY``, ``NO_PROXY``)."""
    from urllib.parse import urlsplit

    parts = urlsplit(base_url)
    proxy = urllib.request.getproxies().get(parts.scheme)
    if not proxy or urllib.request.proxy_bypass(parts.hostname or ""):
        return None
    return proxy


def _split_credentials(base_url: str) -> tuple[str, dict[str, str]]:
    """The base URL without ``user:password@`` and the header that sends them (HTTP basic
    auth, as httpx would send them from the URL). The libraries below then never see the
    credentials in a URL, so none of their logs or errors can show them."""
    import base64
    from urllib.parse import unquote, urlsplit

    parts = urlsplit(base_url)
    if parts.username is None and parts.password is None:
        return base_url, {}
    pair = f"{unquote(parts.username or '')}:{unquote(parts.password or '')}".encode()
    return redact_url(base_url), {"Authorization": "Basic " + base64.b64encode(pair).decode("ascii")}


def _count(value: Any) -> int:
    """A token count a server claims, or 0 when it is not a plausible whole number."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return 0
    if isinstance(value, float) and not (value.is_integer() and abs(value) <= MAX_CLAIMED_TOKENS):
        return 0
    return int(value) if 0 <= value <= MAX_CLAIMED_TOKENS else 0


def _json_body(body: bytes, what: str) -> Any:
    try:
        return json.loads(body.decode("utf-8"))
    except UnicodeDecodeError:
        raise ReplyRejected(f"{what} is not UTF-8 text") from None
    except RecursionError:
        raise ReplyRejected(f"{what} is nested too deeply") from None
    except ValueError as e:
        raise ReplyRejected(f"{what} is not JSON ({e.msg if isinstance(e, json.JSONDecodeError) else 'bad number'}; it starts {_preview(body)})") from None


def _preview(body: bytes | str, n: int = 40) -> str:
    """A short, printable start of a body, for a message."""
    text = body[:n].decode("utf-8", "replace") if isinstance(body, bytes) else body[:n]
    return repr(clean_text(text)) + ("..." if len(body) > n else "")


def chat_answer(body: bytes) -> tuple[str, int, int]:
    """(content, prompt tokens, completion tokens) of a chat completion's HTTP body.

    Raises ReplyRejected when the body is not a usable answer."""
    data = _json_body(body, "the answer")
    if not isinstance(data, dict):
        raise ReplyRejected(f"the answer is a JSON {type(data).__name__}, not an object")
    choices = data.get("choices")
    if not isinstance(choices, list) or not choices:
        raise ReplyRejected("the answer holds no choices")
    first = choices[0]
    message = first.get("message") if isinstance(first, dict) else None
    if not isinstance(message, dict):
        raise ReplyRejected("the answer's first choice holds no message")
    content = message.get("content")
    if not isinstance(content, str):
        kind = "null" if content is None else type(content).__name__
        raise ReplyRejected(f"the answer's message content is {kind}, not text")
    if len(content) > MAX_REPLY_CHARS:
        raise ReplyRejected(f"the reply was longer than {MAX_REPLY_CHARS // 1024} KiB")
    usage = data.get("usage")
    usage = usage if isinstance(usage, dict) else {}
    return content, _count(usage.get("prompt_tokens")), _count(usage.get("completion_tokens"))


def listed_models(body: bytes) -> list[str]:
    """The model ids of a /models answer that are safe to use and record."""
    data = _json_body(body, "the /models answer")
    items = data.get("data") if isinstance(data, dict) else None
    if not isinstance(items, list):
        raise ReplyRejected("the /models answer holds no model list")
    ids = [m.get("id") for m in items if isinstance(m, dict)]
    return [i for i in ids if isinstance(i, str) and i.strip() and clean_text(i) == i and len(i) <= MAX_MODEL_CHARS]


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
    except RecursionError:
        raise ValueError("the reply is nested too deeply") from None
    start, end = text.find("{"), text.rfind("}")
    if start < 0 or end <= start:
        raise ValueError("the reply holds no JSON object" + (" (it was cut off)" if start >= 0 else ""))
    try:
        return json.loads(text[start : end + 1])
    except json.JSONDecodeError as e:
        raise ValueError(f"the reply is not valid JSON: {e.msg} at character {e.pos}") from None
    except RecursionError:
        raise ValueError("the reply is nested too deeply") from None


class LLMClient:
    """One OpenAI-compatible server, one model, a reply cache."""

    def __init__(self, config: LLMConfig, cache: ReplyCache | None = None) -> None:
        try:
            import openai
        except ModuleNotFoundError:
            raise LLMError("the LLM planner needs the openai client: pip install 'anyhome[llm]'") from None
        self._openai = openai
        self.config = config
        self.url = redact_url(config.base_url)  # what is recorded and shown; config.base_url is what is used
        self.cache = cache or ReplyCache(config.cache_dir, enabled=config.cache)
        httpx = _httpx_module(openai)
        http_client = openai.DefaultHttpxClient(
            transport=_guarded_transport(httpx, config.timeout_s, MAX_BODY_BYTES, _proxy_for(config.base_url)),
            timeout=config.timeout_s, trust_env=False, follow_redirects=False,
        )  # fmt: skip
        request_url, auth = _split_credentials(config.base_url)
        self._client = openai.OpenAI(
            base_url=request_url, api_key=config.api_key or NO_KEY, default_headers=auth or None,
            timeout=config.timeout_s, max_retries=0, http_client=http_client,
        )  # fmt: skip
        note = self.cache.server_note(self.url)
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
        note = self.cache.server_note(self.url)
        remembered = note.get("model")
        if isinstance(remembered, str) and remembered.strip() and clean_text(remembered) == remembered and len(remembered) <= MAX_MODEL_CHARS:
            self._model = remembered
            return self._model
        try:
            listed = listed_models(self._client.models.with_raw_response.list().content)
        except _TooLarge:
            raise ReplyRejected(f"the LLM server at {self.url} sent a /models answer larger than {MAX_BODY_BYTES // 1024} KiB") from None
        except ReplyRejected as e:
            raise ReplyRejected(f"the LLM server at {self.url}: {e}") from None
        except self._openai.APIError as e:
            self._mark_down(e)
            raise Unavailable(self.down or "no model") from None
        if not listed:
            raise Unavailable(f"{self.url} lists no usable model; set --llm-model")
        self._model = listed[0]
        self.cache.remember_server(self.url, model=self._model)
        return self._model

    def _mark_down(self, e: Exception) -> None:
        if isinstance(e, self._openai.APITimeoutError):
            self.down = f"the LLM server at {self.url} timed out after {self.config.timeout_s:g} s"
        elif isinstance(e, self._openai.APIConnectionError):
            self.down = f"the LLM server at {self.url} is unreachable"
        elif isinstance(e, self._openai.AuthenticationError):
            self.down = f"the LLM server at {self.url} refused the API key"
        elif isinstance(e, self._openai.APIStatusError):
            self.down = f"the LLM server at {self.url} answered HTTP {e.status_code}"
        else:
            self.down = f"the LLM server at {self.url} failed: {type(e).__name__}"

    # ------------------------------------------------------------ calls
    def chat_json(self, messages: list[dict[str, str]], schema: dict[str, Any], name: str, seed: int, max_tokens: int | None = None) -> Reply:
        """One reply for ``messages`` that should match ``schema``: from the cache, else
        from the server. Raises Unavailable when the server cannot answer, ReplyRejected
        (a kind of Unavailable) when its answer is unusable."""
        sampling = {**self.config.sampling(), "seed": int(seed)}
        if max_tokens is not None:
            sampling["max_tokens"] = min(int(max_tokens), self.config.max_tokens)
        model = self.model()
        key = request_key(self.url, model, messages, schema, sampling)
        hit = self.cache.get(key)
        if hit is not None and len(hit["content"]) <= MAX_REPLY_CHARS:
            latency = hit.get("latency_s", 0.0)
            latency = float(latency) if isinstance(latency, (int, float)) and not isinstance(latency, bool) and 0 <= latency < 1e6 else 0.0
            reply = Reply(hit["content"], _count(hit.get("prompt_tokens")), _count(hit.get("completion_tokens")),
                          latency, True, clean_text(str(hit.get("mode", "")))[:40])  # fmt: skip
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
                raw = self._client.chat.completions.with_raw_response.create(
                    # plain role/content dicts: openai types each message as one of its TypedDicts
                    model=model, messages=sent,  # type: ignore[arg-type]
                    **sampling, **request_options(mode, schema, name),
                )  # fmt: skip
                body = raw.content
            except _TooLarge:
                raise ReplyRejected(f"the LLM server at {self.url} sent an answer larger than {MAX_BODY_BYTES // 1024} KiB; reading stopped there") from None
            except (self._openai.APIConnectionError, self._openai.AuthenticationError) as e:  # timeouts included
                self._mark_down(e)
                raise Unavailable(self.down) from None
            except self._openai.APIStatusError as e:  # this server does not take this mode
                refusals.append(f"{mode}: HTTP {e.status_code}")
                log.info("%s refused structured-output mode %s: HTTP %s", self.url, mode, e.status_code)
                continue
            except self._openai.APIError as e:  # anything else the client raises: not this stage's reply
                raise ReplyRejected(f"the LLM server at {self.url} answered unusably ({type(e).__name__})") from None
            latency = round(time.perf_counter() - t0, 3)  # as the cache keeps it, so a rerun sums the same
            try:
                content, prompt_tokens, completion_tokens = chat_answer(body)
            except ReplyRejected as e:
                raise ReplyRejected(f"the LLM server at {self.url}: {e}") from None
            if self.mode != mode:  # only a well-formed answer shows the server takes this mode
                self.mode = mode
                self.cache.remember_server(self.url, mode=mode, model=model)
            return Reply(content, prompt_tokens, completion_tokens, latency, False, mode)
        if self.mode and len(modes) == 1:  # the remembered mode stopped working: detect again
            self.mode = None
            return self._send(model, messages, schema, name, sampling)
        raise Unavailable(f"the LLM server at {self.url} refused every request ({'; '.join(refusals)})")
