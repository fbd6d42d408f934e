"""Prompt expectations: loading ``prompts.jsonl``-style files and checking their shape.

A file holds one JSON object per line: ``{"id": str, "prompt": str, "expect": {...}}``.
An ``expect`` entry has any of these keys (see :mod:`anyhome.evaluate.coverage` for how
each is scored)::

    {"rooms":   [{"any": [term, ...], "count": n} | {"any": [...], "min": n}, ...],
     "objects": [...same...],
     "style":   [{"any": [term, ...]}, ...],
     "layout":  [{"rows": [term, ...], "min_rows": n}, ...]}

Blank lines and lines starting with ``#`` are skipped. Every problem raises
:class:`anyhome.errors.EvalError` with a one-line message naming the file and line.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from anyhome.errors import EvalError

EXPECT_KEYS = frozenset({"rooms", "objects", "style", "layout"})
"""Keys an ``expect`` entry may hold."""


def load_prompt_records(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """All records of a prompts file, in file order, each with ``id``, ``prompt``, ``expect``."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise EvalError(f"expectations file not found: {p}") from None
    except (OSError, UnicodeDecodeError) as e:
        raise EvalError(f"cannot read expectations file {p}: {e}") from None
    records: list[dict[str, Any]] = []
    seen: set[str] = set()
    for lineno, line in enumerate(text.splitlines(), start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        where = f"{p} line {lineno}"
        try:
            rec = json.loads(line)
        except json.JSONDecodeError as e:
            raise EvalError(f"{where}: not valid JSON ({e.msg})") from None
        if not isinstance(rec, dict):
            raise EvalError(f"{where}: expected a JSON object")
        for key in ("id", "prompt"):
            if not isinstance(rec.get(key), str) or not rec[key].strip():
                raise EvalError(f"{where}: missing or empty string field {key!r}")
        if rec["id"] in seen:
            raise EvalError(f"{where}: duplicate id {rec['id']!r}")
        seen.add(rec["id"])
        rec["expect"] = validate_expect(rec.get("expect", {}), where=where)
        records.append(rec)
    return records


def load_expectations(path: str | os.PathLike[str]) -> dict[str, dict[str, Any]]:
    """``{id: record}`` for every record of a prompts file, in file order.

    A record is ``{"id", "prompt", "expect", ...}``; :func:`anyhome.evaluate.evaluate_house`
    accepts a record as well as its bare ``expect`` entry.
    """
    return {rec["id"]: rec for rec in load_prompt_records(path)}


def expectation_for_prompt(
    path: str | os.PathLike[str], prompt_text: str
) -> dict[str, Any] | None:
    """The ``expect`` entry whose prompt equals ``prompt_text`` exactly, else ``None``."""
    for rec in load_prompt_records(path):
        if rec["prompt"] == prompt_text:
            return rec["expect"]
    return None


def unwrap_expect(entry: Any) -> Any:
    """A whole prompts-file record (``{"id", "prompt", "expect"}``) to its ``expect`` entry."""
    if isinstance(entry, dict) and "expect" in entry and not (set(entry) & EXPECT_KEYS):
        return entry["expect"]
    return entry


def validate_expect(expect: Any, where: str = "expectations") -> dict[str, Any]:
    """Check an ``expect`` entry's shape; return it unchanged or raise :class:`EvalError`."""
    if not isinstance(expect, dict):
        raise EvalError(f"{where}: 'expect' must be a JSON object")
    unknown = sorted(set(expect) - EXPECT_KEYS)
    if unknown:
        raise EvalError(f"{where}: unknown expectation key(s) {', '.join(map(repr, unknown))} "
                        f"(allowed: {', '.join(sorted(EXPECT_KEYS))})")
    for key, checks in expect.items():
        if not isinstance(checks, list):
            raise EvalError(f"{where}: {key!r} must be a list of checks")
        for k, check in enumerate(checks):
            _validate_check(key, check, f"{where}: {key}[{k}]")
    return expect


def _validate_check(key: str, check: Any, where: str) -> None:
    if not isinstance(check, dict):
        raise EvalError(f"{where}: a check must be a JSON object")
    if key == "layout":
        allowed, terms = {"rows", "min_rows"}, check.get("rows")
    elif key == "style":
        allowed, terms = {"any"}, check.get("any")
    else:
        allowed, terms = {"any", "count", "min"}, check.get("any")
    extra = sorted(set(check) - allowed)
    if extra:
        raise EvalError(f"{where}: unknown field(s) {', '.join(map(repr, extra))}")
    if not isinstance(terms, list) or not terms or not all(
            isinstance(t, str) and t.strip() for t in terms):
        field = "rows" if key == "layout" else "any"
        raise EvalError(f"{where}: {field!r} must be a non-empty list of words")
    for field in ("count", "min", "min_rows"):
        if field in check and (not isinstance(check[field], int) or isinstance(check[field], bool)
                               or check[field] < 0):
            raise EvalError(f"{where}: {field!r} must be a non-negative integer")
    if "count" in check and "min" in check:
        raise EvalError(f"{where}: give 'count' or 'min', not both")
