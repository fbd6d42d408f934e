"""The prompt templates (``anyhome/plan/prompts/*.md``) and their worked examples
(``examples.json``), filled with ``string.Template`` ($name placeholders). See
docs/llm_planner.md for what each template receives.

What the rules are and what parameters each takes (``$rules``) is not written in a
template: :func:`rule_guide` writes it from the rule registry (each rule's doc and its
parameters model: names, allowed values, ranges, defaults, descriptions), the same models
the reply schemas are built from."""

from __future__ import annotations

import json
import re
from functools import lru_cache
from pathlib import Path
from string import Template
from typing import Any

from anyhome.layout.rules import REGISTRY
from anyhome.plan.llm.schemas import ANCHOR_RULES, MEMBER_RULES, ORNAMENT_RULES, params_schema

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


STAGE_RULES = {"furniture": MEMBER_RULES, "ornaments": ORNAMENT_RULES}
"""The rules ``$rules`` describes in a stage's prompt (the furniture stage's members may
use any rule; its anchors the absolute ones, which the prompt says)."""


def _prose(doc: str) -> str:
    """A rule's doc as one plain line: without its leading name and the rst quotes."""
    text = " ".join(doc.split())
    text = re.sub(r"^``\w+``:\s*", "", text)
    return text.replace("``", "")


def _param_line(name: str, prop: dict[str, Any]) -> str:
    if "enum" in prop:
        kind = "one of " + ", ".join(json.dumps(v) for v in prop["enum"])
    else:
        lo, hi = prop.get("minimum"), prop.get("maximum")
        kind = prop.get("type", "value") + (f" {lo:g} to {hi:g}" if lo is not None and hi is not None else "")
    line = f'"{name}" ({kind}; default {json.dumps(prop["default"])})'
    desc = " ".join(str(prop.get("description", "")).replace("``", "").split()).rstrip(".")
    return f"{line}: {desc}" if desc else line


@lru_cache(maxsize=None)
def rule_guide(rules: tuple[str, ...]) -> str:
    """One line per rule: what it does (its doc) and its params, from its parameters model
    (:func:`anyhome.plan.llm.schemas.params_schema`, the schema the reply is held to)."""
    lines = []
    for rule in rules:
        props = params_schema(rule)["properties"]
        params = "; ".join(_param_line(n, p) for n, p in props.items()) if props else "none, write {}"
        where = " (relative to its target)" if REGISTRY[rule].relative else ""
        lines.append(f"- {rule}{where}: {_prose(REGISTRY[rule].doc)} Params: {params}.")
    return "\n".join(lines)


def fill(stage: str, /, **values: Any) -> str:
    """The template with its placeholders filled; ``$example`` is the stage's example and
    ``$rules`` the guide to the rules the stage's items may use (:func:`rule_guide`),
    ``$anchor_rules`` the rules an anchor may use."""
    if stage in examples():
        values.setdefault("example", json.dumps(examples()[stage], ensure_ascii=False))
    if stage in STAGE_RULES:
        values.setdefault("rules", rule_guide(STAGE_RULES[stage]))
        values.setdefault("anchor_rules", ", ".join(ANCHOR_RULES))
    return template(stage).substitute({k: str(v) for k, v in values.items()})


def messages(stage: str, /, **values: Any) -> list[dict[str, str]]:
    """System message plus the filled stage template."""
    return [{"role": "system", "content": fill("system")}, {"role": "user", "content": fill(stage, **values)}]
