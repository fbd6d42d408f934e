"""Matched sets: copies of one item in one group share one asset.

Dining chairs around one table, the two nightstands of a bed and their lamps, the desks
of a classroom (copies of a repeated group: ``desk-0``, ``desk-1``... are the group
``desk``), bar stools, pews: a designer buys them as a set. :func:`set_key` names the
set an object belongs to; the first copy's asset record is given to the others, each
keeping its own size. Variety only when the words ask for it (:data:`VARIETY_WORDS` in
its name, description or material: "mismatched vintage chairs").
"""

from __future__ import annotations

import copy
import re
from typing import Any

from anyhome.house import HouseObject

VARIETY_WORDS = ("mismatched", "assorted", "eclectic", "odd ", "varied", "different", "unmatched")
"""Words that ask for a set of different pieces."""


def asks_variety(text: str) -> bool:
    t = f" {text.lower()} "
    return any(w in t for w in VARIETY_WORDS)


def set_key(obj: HouseObject) -> tuple[str, str, str] | None:
    """(room, group without its copy number, name), or None: an object in no set."""
    if not obj.group or asks_variety(f"{obj.name} {obj.description} {obj.material}"):
        return None
    return obj.room, re.sub(r"-\d+$", "", obj.group), obj.name


def matched_record(record: dict[str, Any], obj: HouseObject) -> dict[str, Any]:
    """``record`` (a set's first asset) for ``obj``: the same look at ``obj``'s size."""
    out = copy.deepcopy(record)
    params = out.get("params")
    if isinstance(params, dict) and "size" in params:
        params["size"] = [float(s) for s in obj.size]
    return out
