"""Floorplan stage: HouseSpec -> Floorplan (room polygons, doors, windows)."""

from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.solver import floorplan_errors, solve_floorplan

__all__ = ["FloorplanOptions", "floorplan_errors", "solve_floorplan"]
