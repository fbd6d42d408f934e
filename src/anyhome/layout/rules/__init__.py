"""The ten placement rules of the AnyHome paper, one module each, and their registry.

Each module (``place_wall``, ``place_front``, ...) defines its parameters model
(``Params``: pydantic, unknown keys refused, defaults stated there once) and its
candidate generator, and exports ``RULE``, a :class:`PlacementRule`. :data:`REGISTRY`
maps a rule's name to it; :data:`RULES`, :data:`RELATIVE_RULES` and :data:`WALL_RULES`
derive from it (plan/spec.py re-exports them), as do ``ItemSpec.params`` validation
and the LLM planner's JSON schemas.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from anyhome.layout.rules import (
    place_around,
    place_beside,
    place_center,
    place_corner,
    place_front,
    place_next,
    place_next_wall,
    place_on_wall,
    place_top,
    place_wall,
)
from anyhome.layout.rules.base import (
    Cands,
    Kind,
    NoParams,
    PlacementRule,
    RuleContext,
    RuleParams,
    front_dir,
    right_dir,
    wrap,
    yaw_facing,
)

REGISTRY: dict[str, PlacementRule] = {
    r.name: r
    for r in (
        place_corner.RULE,
        place_next_wall.RULE,
        place_wall.RULE,
        place_center.RULE,
        place_next.RULE,
        place_beside.RULE,
        place_around.RULE,
        place_front.RULE,
        place_top.RULE,
        place_on_wall.RULE,
    )
}
"""Rule name -> rule, in the order plans and prompts list them."""

RULES: tuple[str, ...] = tuple(REGISTRY)
RELATIVE_RULES: frozenset[str] = frozenset(n for n, r in REGISTRY.items() if r.relative)
"""Rules placing an object relative to a target (``ItemSpec.target``)."""
WALL_RULES: frozenset[str] = frozenset(n for n, r in REGISTRY.items() if r.against_wall)
"""Rules that put an object against (or on) a wall."""


@dataclass(frozen=True)
class ParamsProblem:
    """What is wrong with an item's ``params`` for its rule: the first bad entry
    (``where``), what is wrong with it, and the parameters the rule takes."""

    where: str
    what: str
    known: str


def params_problem(rule: str, params: dict[str, Any]) -> ParamsProblem | None:
    """``params`` checked against ``rule``'s model (the plan's ``ItemSpec`` and the
    knowledge files both report through this); None when they are right."""
    try:
        REGISTRY[rule].parse(params)
    except ValidationError as e:
        err = e.errors()[0]
        what = "unknown parameter" if err["type"] == "extra_forbidden" else err["msg"]
        known = ", ".join(REGISTRY[rule].params.model_fields) or "none"
        return ParamsProblem(".".join(str(x) for x in err["loc"]), what, known)
    return None


def params_for(rule: str, params: dict[str, Any]) -> dict[str, Any]:
    """The entries of ``params`` that ``rule`` takes ({} for a rule not in the registry)."""
    return REGISTRY[rule].taken(params) if rule in REGISTRY else {}


__all__ = [
    "REGISTRY",
    "RELATIVE_RULES",
    "RULES",
    "WALL_RULES",
    "Cands",
    "Kind",
    "NoParams",
    "PlacementRule",
    "RuleContext",
    "RuleParams",
    "front_dir",
    "right_dir",
    "ParamsProblem",
    "params_for",
    "params_problem",
    "wrap",
    "yaw_facing",
]
