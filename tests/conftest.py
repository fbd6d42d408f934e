"""Test configuration.

Being here puts tests/ on sys.path, so tests can import ``public_prompts``. Under CI
(``CI`` set) hypothesis runs derandomized, so a CI run is reproducible; local runs keep
exploring new examples.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

# A real llama.cpp server for the LLM planner tests (tests/plan/llm, tests/e2e).
from llama_server import closed_port_url, llama_server, own_server, silent_server  # noqa: E402, F401
