"""Defining elements kept (issue 15): is every object the prompt names, and every object
a room is named for, in the house?

The named objects are the prompt's object mentions as the offline parser reads them
(:func:`anyhome.plan.parse.parse`; not those the text rules out, "no TV"). A named
object is **kept** when the house has an object whose name holds the mention's words
(the user's name: "clawfoot tub") or the prototype's key ("bathtub"), or whose category
is the prototype's (objects.yaml). The room-defining objects are the plan's key items
(:attr:`anyhome.plan.spec.GroupSpec.key`: the bed of a bedroom, the screen of a home
theater); one is kept when the furnishing figures list no drop of it
(:attr:`anyhome.evaluate.furnish_metrics.FurnishMetrics.key_dropped`). The parser reads
the prompt with the knowledge base in force, so a word it does not read as an object is
not checked here (the coverage of a prompt's expectations catches what the planner
missed altogether).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from anyhome.house import House
from anyhome.plan.kb import KnowledgeBase


@dataclass
class Defining:
    n_named: int = 0
    missing: list[str] = field(default_factory=list)  # named objects not in the house
    key_dropped: list[str] = field(default_factory=list)  # room-defining objects dropped

    @property
    def kept(self) -> bool:
        return not self.missing and not self.key_dropped


def _words(text: str) -> str:
    return " " + " ".join(re.findall(r"[a-z0-9]+", text.lower())) + " "


def defining_elements(house: House, kb: KnowledgeBase | None = None) -> Defining:
    """The figure of the module doc for one house (its ``prompt`` parsed again)."""
    from anyhome.evaluate.furnish_metrics import furnish_metrics
    from anyhome.plan.kbview import resolve
    from anyhome.plan.parse import parse

    kb = resolve(kb)
    out = Defining()
    parsed = parse(house.prompt, kb)
    objects = kb.raw("objects")
    names = [_words(o.name) for o in house.objects]
    cats = {o.category for o in house.objects}
    for m in parsed.objects:
        if m.negated or not m.key:
            continue
        out.n_named += 1
        want = [w for w in {m.name, m.key} if w]
        cat = (objects.get(m.key) or {}).get("category")
        if not any(_words(w) in n or _words(_singular(w)) in n for w in want for n in names) and cat not in cats:
            out.missing.append(m.name or m.key)
    out.key_dropped = list(furnish_metrics(house).key_dropped)
    return out


def _singular(word: str) -> str:
    return word[:-1] if word.endswith("s") and not word.endswith("ss") else word
