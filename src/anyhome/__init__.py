"""AnyHome: free-form text to a structured, furnished 3D house."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from anyhome.errors import AnyHomeError
from anyhome.house import House, load
from anyhome.restyle import restyle as restyle

if TYPE_CHECKING:
    from anyhome.stages import Stages

__version__ = "0.1.0"
__all__ = ["AnyHomeError", "House", "Stages", "__version__", "generate", "generate_from_spec", "load", "relayout"]


def generate(text: str, seed: int = 0, **options: Any) -> House:
    """Plan, lay out and furnish a house from text. See ``anyhome.pipeline.generate``."""
    from anyhome.pipeline import generate as _generate

    return _generate(text, seed=seed, **options)


def generate_from_spec(spec: Any, seed: int = 0, stages: Stages | None = None, **options: Any) -> House:
    """Every stage after planning, from a HouseSpec. See ``anyhome.pipeline.generate_from_spec``."""
    from anyhome.pipeline import generate_from_spec as _generate_from_spec

    return _generate_from_spec(spec, seed=seed, stages=stages, **options)


def relayout(house: House, rooms: Any = None, seed: int = 0, stages: Stages | None = None, **options: Any) -> House:
    """Lay out some rooms of a house again, keeping the others. See ``anyhome.pipeline.relayout``
    (``knowledge=kb``: the run's knowledge base)."""
    from anyhome.pipeline import relayout as _relayout

    return _relayout(house, rooms=rooms, seed=seed, stages=stages, **options)


def __getattr__(name: str) -> Any:
    if name == "Stages":  # imported on first use: it pulls in every stage
        from anyhome.stages import Stages

        return Stages
    raise AttributeError(f"module 'anyhome' has no attribute {name!r}")
