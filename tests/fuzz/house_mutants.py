"""Hypothesis strategies that corrupt a valid house.json, one field at a time (or a few).

A mutant is a JSON text: the valid house with 1 to 3 mutations, each at a path chosen
among every value of the document (top-level fields, every room, door, window and
object field, every coordinate). Mutations: wrong type, NaN / inf / -inf (written as
bare tokens, as ``json.dumps`` does), huge, tiny, negative, zero, missing, null,
unknown reference, duplicate id, hostile strings, empty and repeated list entries.
"""

from __future__ import annotations

import copy
import json
from typing import Any

from hypothesis import strategies as st

Path = tuple[str | int, ...]

HOSTILE_STRINGS = [
    "",
    '" onmouseover="alert(document.cookie)',
    "<svg onload=alert(1)>",
    "a & b ]]> <!--",
    "\x1b]0;pwned\x07\x1b[31mred",
    "\x00\x01\x08\x0b\x1f\x7f\x9f",
    "\u202egnp.exe\u2066",
    "\ud800\udfff\ufffe",
    "../../etc/passwd",
    "x" * 5000,
    "outside",
    "floor",
    "living",
    "nowhere",
]
NUMBERS = [float("nan"), float("inf"), float("-inf"), 1e300, -1e300, 1e-300, -1.0, -0.0, 0.0,
           1e6, -1e6, 2**63, -(2**63), 10**30, 3.5, 1]
PLAUSIBLE = [0.0, 1e-6, 1e-3, 0.01, -0.01, 0.5, 2.0, 4.0, 49.9, 50.0, 199.0, 499.0, -499.0, 9999.0,
             -9999.0, 3.14159, 999.0]
"""Values within the load limits (the limits themselves included)."""
WRONG_TYPES: list[Any] = [None, True, False, "12", "nan", [], {}, [1, 2], {"a": 1}, [[0, 0]] * 2]


def paths(doc: Any, prefix: Path = ()) -> list[Path]:
    """Every path in a JSON document (containers and leaves, not the root)."""
    out: list[Path] = []
    if isinstance(doc, dict):
        for k, v in doc.items():
            out.append((*prefix, k))
            out += paths(v, (*prefix, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            out.append((*prefix, i))
            out += paths(v, (*prefix, i))
    return out


def _get(doc: Any, path: Path) -> Any:
    for p in path:
        doc = doc[p]
    return doc


def _ids(doc: dict) -> list[str]:
    lists = [doc.get(kind) for kind in ("rooms", "objects", "doors", "windows")]
    return [e["id"] for entries in lists if isinstance(entries, list)
            for e in entries if isinstance(e, dict) and isinstance(e.get("id"), str)]


@st.composite
def mutation(draw, doc: dict) -> tuple[str, Path]:
    """Apply one random mutation to ``doc`` in place; return (kind, path) for the report."""
    all_paths = paths(doc)
    if not all_paths:
        return "none", ()
    path = draw(st.sampled_from(all_paths))
    parent, key = _get(doc, path[:-1]), path[-1]
    old = parent[key]
    kind = draw(st.sampled_from(["number", "wrong_type", "missing", "string", "reference",
                                 "duplicate", "scale", "empty", "repeat", "plausible", "plausible"]))
    if kind == "plausible" and not (isinstance(old, (int, float)) and not isinstance(old, bool)):
        kind = "reference" if isinstance(old, str) else "repeat"
    if kind == "plausible":  # loads, but odd: the geometry the later stages must survive
        parent[key] = draw(st.sampled_from(PLAUSIBLE) | st.floats(-60, 60))
    elif kind == "number":
        parent[key] = draw(st.sampled_from(NUMBERS) | st.floats(allow_nan=True, allow_infinity=True))
    elif kind == "wrong_type":
        parent[key] = copy.deepcopy(draw(st.sampled_from(WRONG_TYPES)))
    elif kind == "missing":
        del parent[key]
    elif kind == "string":
        parent[key] = draw(st.sampled_from(HOSTILE_STRINGS) | st.text(max_size=30))
    elif kind == "reference":
        ids = _ids(doc) + ["outside", "floor", "wall", "ceiling", "nowhere"]
        parent[key] = draw(st.sampled_from(ids))
    elif kind == "duplicate":
        # give this entry (or the entry holding this field) the id of another entry
        entry_path = path if isinstance(old, dict) else path[:-1]
        entry = _get(doc, entry_path)
        ids = _ids(doc)
        if isinstance(entry, dict) and ids:
            entry["id"] = draw(st.sampled_from(ids))
    elif kind == "scale":
        if isinstance(old, (int, float)) and not isinstance(old, bool):
            parent[key] = old * draw(st.sampled_from([-1, 0, 1e-9, 1e3, 1e5, 1e9]))
        else:
            parent[key] = draw(st.sampled_from(NUMBERS))
    elif kind == "empty":
        parent[key] = type(old)() if isinstance(old, (list, dict, str)) else None
    elif kind == "repeat":
        if isinstance(parent, list):
            parent.insert(key, copy.deepcopy(old))  # a repeated entry: duplicate ids, points
        else:
            parent[key] = [old, old]
    return kind, path


@st.composite
def mutant(draw, base: dict, max_mutations: int = 3) -> tuple[str, list]:
    """(house.json text, list of (kind, path)) with 1..max_mutations mutations of ``base``."""
    doc = copy.deepcopy(base)
    done = [draw(mutation(doc)) for _ in range(draw(st.integers(1, max_mutations)))]
    return json.dumps(doc, ensure_ascii=draw(st.booleans())), done


def _numeric_paths(doc: Any) -> list[Path]:
    return [p for p in paths(doc) if isinstance(_get(doc, p), (int, float))
            and not isinstance(_get(doc, p), bool) and p[0] in ("rooms", "doors", "windows", "objects")]


@st.composite
def odd_geometry(draw, base: dict, max_mutations: int = 4) -> tuple[str, list]:
    """A house that mostly still loads but whose geometry is odd: numbers within the load
    limits (zero sill, 50 m ceilings, objects kilometres away or a millimetre wide, rooms
    moved onto each other, doors off every wall) and references swapped among valid ids."""
    doc = copy.deepcopy(base)
    numeric = _numeric_paths(doc)
    refs = [p for p in paths(doc) if p[-1] in ("room", "support", "anchor") or
            (len(p) > 2 and p[-2] in ("rooms",) and p[0] == "doors")]
    done = []
    for _ in range(draw(st.integers(1, max_mutations))):
        if refs and draw(st.integers(0, 3)) == 0:
            path = draw(st.sampled_from(refs))
            ids = _ids(doc) + ["outside", "floor", "wall", "ceiling"]
            value: Any = draw(st.sampled_from(ids))
        else:
            path = draw(st.sampled_from(numeric))
            value = draw(st.sampled_from(PLAUSIBLE) | st.floats(-60, 60) | st.floats(-1, 1))
            if path[0] == "rooms" and "polygon" in path:  # keep most houses within the limits
                value = draw(st.floats(-20, 40))
        parent = _get(doc, path[:-1])
        parent[path[-1]] = value
        done.append(("odd", path))
    return json.dumps(doc), done
