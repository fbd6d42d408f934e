"""A limit on the layout attempts of a whole search (every storey of a house, every retry).

:func:`anyhome.floorplan.levels.solve_levels` lays out a house of several storeys with
many searches: each storey, its retries with roomier stairwells, the layouts a storey's
stair or its stacking refuses, a fallback to one storey. Each search is bounded, but
their product is large (one dev house spent 45 s CPU on 1280 refused layouts).
While an :class:`AttemptBudget` is set (:data:`ATTEMPT_BUDGET`), every attempt of
:func:`~anyhome.floorplan.solver.best_attempts` spends one; the attempt past the limit
raises :class:`AttemptsSpent`, which no search's retry loop catches (it is no
:class:`~anyhome.errors.FloorplanError`): the caller that set the budget turns it into
one FloorplanError line. Unset (one-storey houses), nothing is counted.
"""

from __future__ import annotations

from contextvars import ContextVar
from dataclasses import dataclass

from anyhome.errors import AnyHomeError


class AttemptsSpent(AnyHomeError):
    """The whole search's attempt limit is spent (caught where the budget was set)."""


@dataclass
class AttemptBudget:
    """``limit`` attempts in all; ``used`` so far."""

    limit: int
    used: int = 0

    def spend(self) -> None:
        """Count one attempt; :class:`AttemptsSpent` when the limit is already reached."""
        if self.used >= self.limit:
            raise AttemptsSpent(f"{self.limit} layout attempts spent")
        self.used += 1


ATTEMPT_BUDGET: ContextVar[AttemptBudget | None] = ContextVar("anyhome_attempt_budget", default=None)
"""The budget of the search under way (None: no limit beyond each search's own)."""


def spend_attempt() -> None:
    """Count one layout attempt against the budget in force, if any (see the module doc)."""
    budget = ATTEMPT_BUDGET.get()
    if budget is not None:
        budget.spend()
