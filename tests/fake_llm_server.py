"""A fake OpenAI-compatible server for the LLM planner's tests, scripted per test.

A ``ThreadingHTTPServer`` on 127.0.0.1 (port 0), started and stopped by the ``fake_llm``
fixture. It answers ``GET /v1/models`` and ``POST /v1/chat/completions``; by default
with a valid reply for each stage (told apart by the ``json_schema`` name the client
sends), and otherwise with what the test scripts: any status, any body (truncated
JSON, HTML, numbers where text belongs), a delay, a body dripped one byte at a time
(head included or not), or a huge body streamed without holding it in memory.

    fake_llm.script["appearance"] = Answer.chat("not json")   # every appearance request
    fake_llm.script["program"] = [Answer.chat("{"), Answer.chat(valid)]  # first, then second
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

import pytest

MODEL = "fake-model"


@dataclass
class Answer:
    """One scripted HTTP answer."""

    status: int = 200
    body: bytes = b""
    content_type: str = "application/json"
    delay_s: float = 0.0  # wait before sending anything
    drip_s: float = 0.0  # pause between bytes (the head too if drip_head)
    drip_head: bool = False
    filler: tuple[bytes, bytes, int] | None = None  # (before, after, n): before + "a" * n + after, streamed

    @staticmethod
    def json(data: Any, **kw: Any) -> Answer:
        return Answer(body=json.dumps(data).encode(), **kw)

    @staticmethod
    def chat(content: Any, prompt_tokens: Any = 11, completion_tokens: Any = 22, **kw: Any) -> Answer:
        """A chat completion whose message content is ``content`` (any JSON value)."""
        return Answer.json(envelope(content, prompt_tokens, completion_tokens), **kw)

    @staticmethod
    def huge_chat(n_bytes: int) -> Answer:
        """A chat completion whose content is ``n_bytes`` of 'a', streamed."""
        before, after = json.dumps(envelope("@", 1, 1)).encode().split(b"@")
        return Answer(filler=(before, after, n_bytes))

    def length(self) -> int:
        if self.filler:
            return len(self.filler[0]) + self.filler[2] + len(self.filler[1])
        return len(self.body)

    def pieces(self) -> Iterator[bytes]:
        if not self.filler:
            yield self.body
            return
        before, after, n = self.filler
        yield before
        block = b"a" * 65536
        while n > 0:
            yield block[: min(n, len(block))]
            n -= len(block)
        yield after


def envelope(content: Any, prompt_tokens: Any = 11, completion_tokens: Any = 22) -> dict[str, Any]:
    return {
        "id": "chatcmpl-fake", "object": "chat.completion", "created": 0, "model": MODEL,
        "choices": [{"index": 0, "message": {"role": "assistant", "content": content}, "finish_reason": "stop"}],
        "usage": {"prompt_tokens": prompt_tokens, "completion_tokens": completion_tokens},
    }  # fmt: skip


PROGRAM = {
    "building": "home",
    "rooms": [
        {"id": "living_room", "name": "living room", "type": "living_room", "area_m2": 20},
        {"id": "kitchen", "name": "kitchen", "type": "kitchen", "area_m2": 10},
        {"id": "bedroom", "name": "bedroom", "type": "bedroom", "area_m2": 12},
    ],
    "connections": [["living_room", "kitchen"], ["living_room", "bedroom"]],
    "entrance": "living_room",
}
FURNITURE = {"groups": [{
    "name": "storage", "arrangement": "free", "repeat": 1, "members": [],
    "anchor": {"name": "cabinet", "category": "cabinet", "size_m": [0.8, 0.4, 0.9], "rule": "place_wall", "target": "", "count": 1},
}]}  # fmt: skip
ORNAMENTS = {"ornaments": [
    {"name": "painting", "category": "wall art", "size_m": [0.6, 0.04, 0.4], "rule": "place_on_wall", "target": "", "count": 1},
]}  # fmt: skip


def appearance(room_ids: list[str], **over: Any) -> dict[str, Any]:
    return {
        "style": "calm modern", "palette": ["white", "oak"], "furniture": "oak wood",
        "rooms": [{"id": i, "floor": "oak planks", "walls": "white paint", "ceiling": "white paint"} for i in room_ids],
        **over,
    }  # fmt: skip


def stage_of(request: dict[str, Any]) -> str:
    fmt = request.get("response_format") or {}
    return (fmt.get("json_schema") or {}).get("name", "?")


def valid_reply(request: dict[str, Any]) -> Any:
    """A reply every check accepts, for the stage the request asks."""
    stage = stage_of(request)
    if stage == "program":
        return PROGRAM
    if stage == "furniture":
        return FURNITURE
    if stage == "ornaments":
        return ORNAMENTS
    if stage == "appearance":
        schema = request["response_format"]["json_schema"]["schema"]
        return appearance(schema["properties"]["rooms"]["items"]["properties"]["id"].get("enum", []))
    raise AssertionError(f"the fake server got a request for no known stage: {stage}")


Script = Answer | list[Answer] | Callable[[dict[str, Any]], Answer]


@dataclass
class FakeLLM:
    """The server's script and what it received (``requests``: path, headers, JSON)."""

    models: Answer = field(default_factory=lambda: Answer.json({"object": "list", "data": [{"id": MODEL, "object": "model"}]}))
    script: dict[str, Script] = field(default_factory=dict)
    requests: list[dict[str, Any]] = field(default_factory=list)
    hung_up: int = 0  # answers the client stopped reading before their end
    port: int = 0
    stopping: threading.Event = field(default_factory=threading.Event)
    lock: threading.Lock = field(default_factory=threading.Lock)

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def chat_requests(self, stage: str | None = None) -> list[dict[str, Any]]:
        return [r["json"] for r in self.requests if r["path"].endswith("/chat/completions") and (stage is None or stage_of(r["json"]) == stage)]

    def answer_chat(self, request: dict[str, Any]) -> Answer:
        stage = stage_of(request)
        with self.lock:
            scripted = self.script.get(stage)
            if isinstance(scripted, list):
                scripted = scripted.pop(0) if len(scripted) > 1 else scripted[0]
        if scripted is None:
            return Answer.chat(json.dumps(valid_reply(request)))
        return scripted(request) if callable(scripted) else scripted


def _handler(server: FakeLLM) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args: Any) -> None:  # quiet
            pass

        def _send(self, answer: Answer) -> None:
            if answer.delay_s and server.stopping.wait(answer.delay_s):
                return
            head = (f"HTTP/1.1 {answer.status} X\r\nContent-Type: {answer.content_type}\r\n"
                    f"Content-Length: {answer.length()}\r\nConnection: close\r\n\r\n").encode()  # fmt: skip
            try:
                if answer.drip_s:
                    data = (head if answer.drip_head else b"") + b"".join(answer.pieces())
                    if not answer.drip_head:
                        self.wfile.write(head)
                        self.wfile.flush()
                    for i in range(len(data)):
                        self.wfile.write(data[i : i + 1])
                        self.wfile.flush()
                        if server.stopping.wait(answer.drip_s):
                            return
                    return
                self.wfile.write(head)
                for piece in answer.pieces():
                    self.wfile.write(piece)
                self.wfile.flush()
            except OSError:  # the client hung up (as it should on a huge or slow answer)
                with server.lock:
                    server.hung_up += 1

        def _record(self, data: Any) -> None:
            with server.lock:
                server.requests.append({"path": self.path, "headers": {k.lower(): v for k, v in self.headers.items()},
                                        "authorization": self.headers.get_all("Authorization") or [], "json": data})  # fmt: skip

        def do_GET(self) -> None:  # noqa: N802
            self._record(None)
            self._send(server.models if self.path.rstrip("/").endswith("/models") else Answer(status=404))

        def do_POST(self) -> None:  # noqa: N802
            body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
            data = json.loads(body)
            self._record(data)
            if not self.path.endswith("/chat/completions"):
                self._send(Answer(status=404))
                return
            self._send(server.answer_chat(data))

    return Handler


@pytest.fixture
def fake_llm():
    """A fake OpenAI-compatible server of this test's own, stopped after it."""
    state = FakeLLM()
    httpd = ThreadingHTTPServer(("127.0.0.1", 0), _handler(state))
    httpd.daemon_threads = True
    state.port = httpd.server_address[1]
    thread = threading.Thread(target=httpd.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    thread.start()
    try:
        yield state
    finally:
        state.stopping.set()  # ends drips and delays
        httpd.shutdown()
        httpd.server_close()
        thread.join(timeout=5)


def wait_until(predicate: Callable[[], bool], timeout_s: float = 30.0) -> None:
    """A hang guard for polling, not a timing assertion."""
    deadline = time.monotonic() + timeout_s
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError("condition not met before the hang guard")
        time.sleep(0.02)
