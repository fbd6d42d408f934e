"""Ceiling heights and shapes of planned rooms (``knowledge/heights.yaml``).

A room's height is its type's ``height_m`` (rooms.yaml) times the scale of the building
the text names ("cottage" 0.89, "mansion" 1.15) times the scale of each height word that
applies to it ("double height" 2, "low ceilings" 0.89), plus ``add_m`` ("sunken"),
clamped to the file's ``limits`` and rounded to 5 cm. A height word applies to the room
it modifies ("a double-height living room"), else to the nearest room named before it in
its clause ("a living room with high ceilings"), else to every enclosed room (a ceiling
shape: every enclosed habitable room). Open-air rooms keep their type's height and have
no ceiling shape.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from anyhome.house import CeilingShape, is_habitable
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.parse import Parsed

HEIGHT_STEP_M = 0.05
"""Heights are rounded to this."""

PREMODIFIER_TOKENS = 2
"""A height word directly before a room word (at most this many words between them)
modifies that room ("double height open living room")."""

_CLAUSE_BREAK = re.compile(r"[,.;:!?]")


@dataclass(frozen=True)
class RoomHeight:
    height_m: float
    ceiling: CeilingShape = "flat"


@lru_cache(maxsize=8)
def _regex(words: tuple[str, ...]) -> re.Pattern[str] | None:
    if not words:
        return None
    alts = sorted(words, key=len, reverse=True)
    return re.compile(r"(?<![a-z0-9])(?:" + "|".join(re.escape(w) for w in alts) + r")(?![a-z0-9])")


def _target(parsed: Parsed, start: int, end: int) -> int | None:
    """Index into ``parsed.rooms`` of the room a height word at ``[start, end)`` applies to."""
    text = parsed.text
    after = [(m.start, i) for i, m in enumerate(parsed.rooms) if m.start >= end and not m.negated]
    if after:
        s, i = min(after)
        gap = text[end:s]
        if not _CLAUSE_BREAK.search(gap) and len(gap.split()) <= PREMODIFIER_TOKENS:
            return i
    before = [(m.end, i) for i, m in enumerate(parsed.rooms) if m.end <= start and not m.negated]
    if before:
        e, i = max(before)
        if not _CLAUSE_BREAK.search(text[e:start]):
            return i
    return None


def room_heights(kb: KnowledgeBase, parsed: Parsed, types: list[str], mentions: list[int | None]) -> list[RoomHeight]:
    """The height and ceiling shape of each planned room (``types[k]``, named by the
    room mention ``mentions[k]`` or by none)."""
    h = kb.heights
    text = parsed.text
    rooms = kb.rooms.types
    scale = 1.0
    if (rx := _regex(tuple(h.buildings))) is not None and (m := rx.search(text)) is not None:
        scale = h.buildings[m.group()].scale
    per_room: list[list] = [[] for _ in types]
    if (rx := _regex(tuple(h.words))) is not None:
        for m in rx.finditer(text):
            word = h.words[m.group()]
            target = _target(parsed, m.start(), m.end())
            hits = [k for k, mi in enumerate(mentions) if target is not None and mi == target]
            if not hits:  # the whole house
                hits = [k for k, t in enumerate(types) if not word.ceiling or is_habitable(t)]
            for k in hits:
                per_room[k].append(word)
    out = []
    for k, t in enumerate(types):
        rt = rooms.get(t, rooms["other"])
        if rt.open_air:
            out.append(RoomHeight(rt.height_m))
            continue
        ceiling: CeilingShape = "flat"
        height, add = rt.height_m * scale, 0.0
        for w in per_room[k]:
            height *= w.scale
            add += w.add_m
            ceiling = w.ceiling or ceiling
        height = min(max(height + add, h.limits.min_m), h.limits.max_m)
        out.append(RoomHeight(round(round(height / HEIGHT_STEP_M) * HEIGHT_STEP_M, 2), ceiling))
    return out
