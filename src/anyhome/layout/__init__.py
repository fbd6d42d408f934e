"""Layout stage: Floorplan + HouseSpec -> placed objects (Algorithm 1 of AnyHome).

Modules: :mod:`.rules` (the placement rules, one module each, and their registry),
:mod:`.options` (:class:`LayoutOptions`), :mod:`.state` (a room being furnished),
:mod:`.scoring` (ranking and checking candidate poses), :mod:`.placement` (one object by
its rule), :mod:`.groups` (anchors and members), :mod:`.arrangements` (rows, along the
walls, centre), :mod:`.ornaments` and :mod:`.solver` (the stage itself).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from anyhome.layout.options import LayoutOptions

if TYPE_CHECKING:
    from anyhome.layout.solver import LayoutResult, layout_house

__all__ = ["LayoutOptions", "LayoutResult", "layout_house"]


def __getattr__(name: str) -> Any:
    # the solver is imported on first use: plan/spec.py imports the rule registry
    # (anyhome.layout.rules), and the solver imports plan/spec.py
    if name in ("LayoutResult", "layout_house"):
        from anyhome.layout import solver

        return getattr(solver, name)
    raise AttributeError(f"module 'anyhome.layout' has no attribute {name!r}")
