"""The prompt templates (``anyhome/plan/prompts/*.md``) and their worked examples
(``examples.json``), filled with ``string.Template`` ($name placeholders). See
docs/llm_planner.md for what each template receives."""

from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path
from string import Template
from typing import Any

PROMPTS_DIR = Path(__file__).resolve().parent.parent / "prompts"
TEMPLATES = ("system", "program", "furniture", "ornaments", "appearance", "repair")


@lru_cache(maxsize=None)
def template(name: str) -> Template:
    if name not in TEMPLATES:
        raise KeyError(f"unknown prompt template {name!r}")
    return Template((PROMPTS_DIR / f"{name}.md").read_text(encoding="utf-8").strip())


@lru_cache(maxsize=1)
def examples() -> dict[str, Any]:
    return json.loads((PROMPTS_DIR / "examples.json").read_text(encoding="utf-8"))


def fill(stage: str, /, **values: Any) -> str:
    """The template with its placeholders filled; ``$example`` is the stage's example."""
    if stage in examples():
        values.setdefault("example", json.dumps(examples()[stage], ensure_ascii=False))
    return template(stage).substitute({k: str(v) for k, v in values.items()})


def messages(stage: str, /, **values: Any) -> list[dict[str, str]]:
    """System message plus the filled stage template."""
    return [{"role": "system", "content": fill("system")}, {"role": "user", "content": fill(stage, **values)}]
