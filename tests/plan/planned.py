"""Helpers of the planner tests: the offline plan of a text, and what a planned room holds."""

from __future__ import annotations

import numpy as np

from anyhome.plan import get_planner


def plan_of(text, seed=0):
    """The offline planner's plan of ``text`` with ``seed``."""
    return get_planner("offline").plan(text, np.random.default_rng(seed))


def names_of(room):
    """Every object the room plans, one name per copy."""
    return ([g.anchor.name for g in room.groups for _ in range(g.repeat)]
            + [m.name for g in room.groups for m in g.members for _ in range(g.repeat * m.count)]
            + [o.name for o in room.ornaments])
