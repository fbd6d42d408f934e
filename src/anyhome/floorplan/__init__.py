"""Floorplan stage: HouseSpec -> Floorplan (room polygons, doors, windows)."""

from anyhome.floorplan.solver import floorplan_errors, solve_floorplan

__all__ = ["floorplan_errors", "solve_floorplan"]
