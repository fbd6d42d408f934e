"""Stage 1, plan: text -> HouseSpec. Planners are interchangeable (see ``Planner``)."""

from __future__ import annotations

from typing import Protocol

import numpy as np

from anyhome.errors import PlanError
from anyhome.plan.spec import GroupSpec, HouseSpec, ItemSpec, RoomSpec

__all__ = ["GroupSpec", "HouseSpec", "ItemSpec", "Planner", "RoomSpec", "get_planner", "plan_house"]


class Planner(Protocol):
    """Anything that turns text into a HouseSpec, deterministically for a given RNG state."""

    name: str

    def plan(self, text: str, rng: np.random.Generator) -> HouseSpec: ...


PLANNERS = ("offline", "llm")


def get_planner(name: str = "offline") -> Planner:
    """A planner by name; "llm" takes its settings from the environment and config file."""
    if name == "offline":
        from anyhome.plan.offline import OfflinePlanner

        return OfflinePlanner()
    if name == "llm":
        from anyhome.floorplan import floorplan_errors
        from anyhome.plan.llm import LLMPlanner, load_config

        return LLMPlanner(load_config(), floorplan_check=floorplan_errors)
    raise PlanError(f"unknown planner {name!r} (available: {', '.join(PLANNERS)})")


def plan_house(text: str, rng: np.random.Generator, planner: str = "offline") -> HouseSpec:
    return get_planner(planner).plan(text, rng)
