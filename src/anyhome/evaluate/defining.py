"""Defining elements kept (issue 15): is every object the prompt names, and every object
a room is named for, in the house?

The named objects are the prompt's object mentions as the offline parser reads them
(:func:`anyhome.plan.parse.parse`; not those the text rules out, "no TV"). A named
object is **kept** when the house has an object whose name or category holds the mention's
words (the user's name: "clawfoot tub") or the prototype's key ("bathtub"), as whole words
with an optional plural (the coverage matcher), or whose category is the prototype's
(objects.yaml). The room-defining objects are the plan's key items
(:attr:`anyhome.plan.spec.GroupSpec.key`: the bed of a bedroom, the screen of a home
theater); one is kept when the furnishing figures list no drop of it
(:attr:`anyhome.evaluate.furnish_metrics.FurnishMetrics.key_dropped`). The parser reads
the prompt with the knowledge base in force, so a word it does not read as an object is
not checked here (the coverage of a prompt's expectations catches what the planner
missed altogether).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from anyhome.evaluate.coverage import matches_any, object_text
from anyhome.evaluate.furnish_metrics import FurnishMetrics, furnish_metrics
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


def defining_elements(house: House, kb: KnowledgeBase | None = None,
                      furnish: FurnishMetrics | None = None) -> Defining:
    """The figure of the module doc for one house (its ``prompt`` parsed again);
    ``furnish``: the house's furnishing figures when already computed (an
    :class:`~anyhome.evaluate.report.EvalReport`'s)."""
    from anyhome.plan.kbview import resolve
    from anyhome.plan.parse import parse

    kb = resolve(kb)
    out = Defining()
    parsed = parse(house.prompt, kb)
    objects = kb.raw("objects")
    texts = [object_text(o) for o in house.objects]
    cats = {o.category for o in house.objects}
    for m in parsed.objects:
        if m.negated or not m.key:
            continue
        out.n_named += 1
        want = [w for w in {m.name, m.key} if w]
        if (objects.get(m.key) or {}).get("category") not in cats and not any(matches_any(want, t) for t in texts):
            out.missing.append(m.name or m.key)
    out.key_dropped = list((furnish or furnish_metrics(house)).key_dropped)
    return out

