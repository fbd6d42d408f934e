"""Prompt coverage: how many of a prompt's expectations a house satisfies.

Matching is fixed so that scores are comparable across versions:

* A **term** matches a text when ``re.search(r"\\b" + re.escape(term.lower()) +
  r"(s|es)?\\b", text)`` succeeds: whole words only, an optional plural ``s``/``es``
  ("chair" matches "chairs", "bench" matches "benches", "bed" does not match
  "bedside table").
* A room's text is ``(room.name + " " + room.type.replace("_", " ")).lower()``; an
  object's is ``(obj.name + " " + obj.category.replace("_", " ")).lower()``.
* ``rooms`` / ``objects`` checks ``{"any": [terms], "count": n}`` pass when exactly ``n``
  rooms (objects) match at least one term, ``{"any": [...], "min": n}`` when at least
  ``n`` do; without ``count`` or ``min`` the check is ``min: 1``. A room or object counts
  once per check however many terms it matches.
* ``style`` checks ``{"any": [terms]}`` pass when any term matches the joined lowercase
  text of ``house.style``, ``house.palette``, every room's ``style`` and material words,
  and every object's ``material`` and ``description``. ``found`` is the number of terms
  found.
* ``layout`` checks ``{"rows": [terms], "min_rows": n}`` (default ``n = 1``): in each room
  the objects matching the terms are grouped into rows by :func:`count_rows`; ``found``
  is the largest number of rows in one room and the check passes when it is ``>= n``.
  A row is a cluster of at least ``MIN_ROW_SIZE`` objects; a lone matching object (a
  teacher's desk in front of the class rows) forms no row but does not fail the check.

The score is satisfied checks / total checks (1.0 when the entry holds no checks).
"""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Iterable, Sequence
from functools import lru_cache
from typing import Any

import numpy as np

from anyhome.evaluate.expectations import unwrap_expect, validate_expect
from anyhome.evaluate.report import CheckResult, Coverage
from anyhome.house import House, HouseObject, Room

ROW_GAP_M = 0.5
"""Objects whose positions along the facing direction differ by more than this start a new row."""
MIN_ROW_SIZE = 2
"""Fewest objects a cluster needs to count as a row."""
DEFAULT_MIN_ROWS = 1
"""``min_rows`` of a layout check that gives none."""


@lru_cache(maxsize=1024)
def term_pattern(term: str) -> re.Pattern[str]:
    """The compiled whole-word, optionally plural pattern of a term (see module doc)."""
    return re.compile(r"\b" + re.escape(term.lower()) + r"(s|es)?\b")


def matches_any(terms: Iterable[str], text: str) -> bool:
    return any(term_pattern(t).search(text) for t in terms)


def room_text(room: Room) -> str:
    return (room.name + " " + room.type.replace("_", " ")).lower()


def object_text(obj: HouseObject) -> str:
    return (obj.name + " " + obj.category.replace("_", " ")).lower()


def style_text(house: House) -> str:
    parts = [house.style, *house.palette]
    for room in house.rooms:
        parts.append(room.style)
        parts.extend(room.materials.values())
    for obj in house.objects:
        parts.extend((obj.material, obj.description))
    return " \n ".join(p for p in parts if p).lower()


def evaluate_coverage(house: House, expect: dict[str, Any]) -> Coverage:
    """Score ``house`` against one ``expect`` entry (raises EvalError if it is malformed).

    A whole prompts-file record (``{"id", "prompt", "expect"}``) is accepted too.
    """
    expect = validate_expect(unwrap_expect(expect))
    checks: list[CheckResult] = []
    room_texts = [room_text(r) for r in house.rooms]
    object_texts = [object_text(o) for o in house.objects]
    for check in expect.get("rooms", []):
        checks.append(_count_check("rooms", check, room_texts))
    for check in expect.get("objects", []):
        checks.append(_count_check("objects", check, object_texts))
    if expect.get("style"):
        text = style_text(house)
        for check in expect["style"]:
            found = sum(bool(term_pattern(t).search(text)) for t in check["any"])
            checks.append(CheckResult("style", f"style {_terms(check['any'])}", found > 0, found,
                                      ">= 1 term"))
    for check in expect.get("layout", []):
        checks.append(_rows_check(house, check))
    return Coverage(tuple(checks))


def _terms(terms: Sequence[str]) -> str:
    return " | ".join(f'"{t}"' for t in terms)


def _count_check(kind: str, check: dict[str, Any], texts: list[str]) -> CheckResult:
    found = sum(matches_any(check["any"], t) for t in texts)
    if "count" in check:
        n = check["count"]
        passed, expected = found == n, f"== {n}"
    else:
        n = check.get("min", 1)
        passed, expected = found >= n, f">= {n}"
    return CheckResult(kind, f"{kind} {_terms(check['any'])}", passed, found, expected)


def _rows_check(house: House, check: dict[str, Any]) -> CheckResult:
    terms = check["rows"]
    need = check.get("min_rows", DEFAULT_MIN_ROWS)
    by_room: dict[str, list[HouseObject]] = {}
    for obj in house.objects:
        if matches_any(terms, object_text(obj)):
            by_room.setdefault(obj.room, []).append(obj)
    found = max((len(count_rows(objs)) for objs in by_room.values()), default=0)
    return CheckResult("layout", f"rows of {_terms(terms)}", found >= need, found, f">= {need}")


def count_rows(objects: Sequence[HouseObject]) -> list[list[HouseObject]]:
    """Group objects into rows.

    The majority facing (yaw rounded to a multiple of 90 degrees) gives the facing
    direction ``(-sin yaw, cos yaw)``; positions projected on it are sorted and split
    wherever consecutive values differ by more than ``ROW_GAP_M``. Clusters of fewer than
    ``MIN_ROW_SIZE`` objects are not rows.

    Returns
    -------
    rows : list of rows, front-to-back along the facing direction, each a list of objects
    """
    if not objects:
        return []
    quarter = Counter(round(o.yaw / (math.pi / 2)) % 4 for o in objects)
    k = max(quarter, key=lambda q: (quarter[q], -q))
    yaw = k * math.pi / 2
    facing = np.array([-math.sin(yaw), math.cos(yaw)])
    depth = np.array([o.position[:2] for o in objects], dtype=float) @ facing
    order = np.argsort(depth, kind="stable")
    clusters: list[list[HouseObject]] = [[objects[order[0]]]]
    for prev, cur in zip(order[:-1], order[1:]):
        if depth[cur] - depth[prev] > ROW_GAP_M:
            clusters.append([])
        clusters[-1].append(objects[cur])
    return [c for c in clusters if len(c) >= MIN_ROW_SIZE]
