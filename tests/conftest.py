"""Test configuration.

Being here puts tests/ on sys.path, so tests can import ``public_prompts``. Under CI
(``CI`` set) hypothesis runs derandomized, so a CI run is reproducible; local runs keep
exploring new examples.
"""

import os

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

# A real llama.cpp server for the LLM planner tests (tests/plan/llm, tests/e2e).
from llama_server import closed_port_url, llama_server, own_server, silent_server  # noqa: E402, F401


@pytest.fixture
def no_knowledge_overlay(monkeypatch):
    """The test starts and ends with the shipped knowledge only: no $ANYHOME_KNOWLEDGE_PATH,
    no ``--knowledge`` folders left in force by another test."""
    from anyhome.plan.knowledge import ENV_VAR, use_knowledge

    monkeypatch.delenv(ENV_VAR, raising=False)
    use_knowledge(None)
    yield
    use_knowledge(None)


@pytest.fixture(scope="session")
def gl_available() -> None:
    """Skip when moderngl or a headless EGL context is missing, except under CI (``CI``
    set, as .ci/run does), where the renders must run and a missing renderer fails."""
    if not os.environ.get("CI"):
        pytest.importorskip("moderngl")
    from anyhome.errors import RenderError
    from anyhome.render.gl import create_context

    try:
        ctx = create_context()
    except RenderError as e:
        if os.environ.get("CI"):
            raise
        pytest.skip(str(e))
    ctx.release()


SERVER_FIXTURES = frozenset({"llama_server", "own_server"})
"""Fixtures that run the real LLM server: its tests wait on a 135M model on one core."""


def pytest_collection_modifyitems(config, items):
    """The test files that talk to the real LLM server run first (order kept otherwise).
    They wait on the server most of their time, so under ``-n auto --dist loadfile
    --no-loadscope-reorder`` they overlap the CPU-bound files on the other workers,
    instead of being scheduled last (fewest tests) and running alone at the end."""
    first = {item.path for item in items if SERVER_FIXTURES & set(getattr(item, "fixturenames", ()))}
    items[:] = [i for i in items if i.path in first] + [i for i in items if i.path not in first]
