"""The generation stages as replaceable functions (as ProcTHOR's generation functions are).

:class:`Stages` names one function per stage; ``anyhome.generate``,
``anyhome.generate_from_spec`` and ``anyhome.relayout`` take one and call only it, so a
replacement for one stage runs with the defaults of the others::

    from anyhome.stages import Stages

    def no_refine(floorplan, objects, rng):
        return objects

    house = anyhome.generate("a kitchen", stages=Stages(refine=no_refine))

Every stage gets its own child RNG (:func:`stage_rngs`), so a change inside one stage
does not shift the random draws of the others.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from anyhome.assets import assign_asset
from anyhome.assets.library import Library, Match, best_matches, library_record
from anyhome.assets.sets import matched_record, set_key
from anyhome.errors import AnyHomeError
from anyhome.floorplan.levels import solve_levels
from anyhome.house import Floorplan, HouseObject
from anyhome.layout import LayoutResult, layout_house
from anyhome.pipeline import STAGES
from anyhome.plan import HouseSpec, Planner
from anyhome.plan.kb import KnowledgeBase
from anyhome.refine import refine_objects

PlanStage = Callable[[str, np.random.Generator, Planner], HouseSpec]
"""plan(text, rng, planner) -> HouseSpec. The planner holds the run's knowledge base
(``get_planner(name, kb)``, ``OfflinePlanner(kb)``)."""
FloorplanStage = Callable[[HouseSpec, np.random.Generator], Floorplan]
"""floorplan(spec, rng) -> Floorplan (rooms, doors, windows)."""
LayoutStage = Callable[[HouseSpec, Floorplan, np.random.Generator], LayoutResult]
"""layout(spec, floorplan, rng) -> LayoutResult: the objects of ``spec.rooms`` (only
those: relayout passes a spec holding just the rooms it lays out again) and what was
dropped."""
RefineStage = Callable[[Floorplan, list[HouseObject], np.random.Generator], list[HouseObject]]
"""refine(floorplan, objects, rng) -> the refined objects (the input is not modified)."""
AssetsStage = Callable[[list[HouseObject], np.random.Generator, HouseSpec, KnowledgeBase], list[HouseObject]]
"""assets(objects, rng, spec, kb) -> the objects with their asset records; ``kb`` is the
run's knowledge base (its styles' asset classes shape the assets)."""


def plan_text(text: str, rng: np.random.Generator, planner: Planner) -> HouseSpec:
    """The default plan stage: ``planner.plan(text, rng)``."""
    return planner.plan(text, rng)


def assign_assets(objects: list[HouseObject], rng: np.random.Generator, spec: HouseSpec,
                  kb: KnowledgeBase) -> list[HouseObject]:
    """The default assets stage: an asset record per object, drawn in order from ``rng``;
    the copies of one item in one group share the first copy's (:mod:`anyhome.assets.sets`)."""
    first: dict[tuple[str, str, str], dict] = {}
    for obj in objects:
        key = set_key(obj)
        if key is not None and key in first:
            obj.asset = matched_record(first[key], obj)
            continue
        obj.asset = assign_asset(obj, rng, spec.styles_for(obj.room), kb)
        if key is not None:
            first[key] = obj.asset
    return objects


def library_assets(library: Library) -> AssetsStage:
    """An assets stage that uses the models of an asset library (``--assets DIR``,
    :func:`anyhome.assets.library.open_library`) where an object's words match one
    (:func:`anyhome.assets.library.best_matches`), and procedural assets elsewhere.

    Every object first gets its procedural record from :func:`assign_assets` (the same
    random draws as without a library); a matched object's library record keeps it as
    its ``fallback``. The copies of a matched set take the first copy's model."""

    def assets(objects: list[HouseObject], rng: np.random.Generator, spec: HouseSpec,
               kb: KnowledgeBase) -> list[HouseObject]:
        objects = assign_assets(objects, rng, spec, kb)
        matches = best_matches(library, [(o.name, o.category, o.size) for o in objects])
        chosen: dict[tuple[str, str, str], Match | None] = {}
        for obj, match in zip(objects, matches):
            key = set_key(obj)
            if key is not None:
                match = chosen.setdefault(key, match)
            if match is not None and obj.asset is not None:
                obj.asset = library_record(library, match, obj.asset)
        return objects

    return assets


@dataclass(frozen=True)
class Stages:
    """One function per generation stage; replace any with ``Stages(layout=...)`` or
    ``dataclasses.replace(stages, refine=...)``. Field order is the run order."""

    plan: PlanStage = plan_text
    floorplan: FloorplanStage = solve_levels
    layout: LayoutStage = layout_house
    refine: RefineStage = refine_objects
    assets: AssetsStage = assign_assets

    def __post_init__(self) -> None:
        for name in STAGES:
            if not callable(getattr(self, name)):
                raise AnyHomeError(f"stage {name!r} must be a function, got {type(getattr(self, name)).__name__}")


def stage_rngs(seed: int) -> dict[str, np.random.Generator]:
    """One child generator per stage (:data:`anyhome.pipeline.STAGES`), spawned from ``seed``."""
    children = np.random.SeedSequence(int(seed)).spawn(len(STAGES))
    return dict(zip(STAGES, (np.random.default_rng(s) for s in children)))
