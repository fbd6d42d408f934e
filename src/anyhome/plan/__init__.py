"""Stage 1, plan: text -> HouseSpec. Planners are interchangeable (see ``Planner``)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np

from anyhome.errors import PlanError
from anyhome.plan.spec import GroupSpec, HouseSpec, ItemSpec, RoomSpec

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase
    from anyhome.plan.offline import FloorplanStage

__all__ = ["GroupSpec", "HouseSpec", "ItemSpec", "Planner", "RoomSpec", "get_planner", "plan_house"]


class Planner(Protocol):
    """Anything that turns text into a HouseSpec, deterministically for a given RNG state."""

    name: str

    def plan(self, text: str, rng: np.random.Generator) -> HouseSpec: ...


PLANNERS = ("offline", "llm")


def get_planner(name: str = "offline", kb: KnowledgeBase | None = None,
                floorplan: FloorplanStage | None = None) -> Planner:
    """A planner by name, reading the knowledge base ``kb`` (None: the one in force);
    "llm" takes its settings from the environment and config file. ``floorplan`` is the
    run's floorplan stage, which the planner lays plans out with to meet stated totals
    (None: the default, ``anyhome.floorplan.levels.solve_levels``)."""
    if floorplan is None:
        from anyhome.floorplan.levels import solve_levels

        floorplan = solve_levels
    if name == "offline":
        from anyhome.plan.offline import OfflinePlanner

        return OfflinePlanner(kb, floorplan=floorplan)
    if name == "llm":
        from anyhome.floorplan import floorplan_errors
        from anyhome.plan.llm import LLMPlanner, load_config

        return LLMPlanner(load_config(), floorplan_check=floorplan_errors, kb=kb, floorplan=floorplan)
    raise PlanError(f"unknown planner {name!r} (available: {', '.join(PLANNERS)})")


def plan_house(text: str, rng: np.random.Generator, planner: str = "offline", kb: KnowledgeBase | None = None) -> HouseSpec:
    return get_planner(planner, kb).plan(text, rng)
