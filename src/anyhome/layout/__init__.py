"""Layout stage: Floorplan + HouseSpec -> placed objects (Algorithm 1 of AnyHome)."""

from anyhome.layout.solver import LayoutResult, layout_house

__all__ = ["LayoutResult", "layout_house"]
