"""Floorplan stage: HouseSpec -> Floorplan (room polygons, doors, windows)."""

from anyhome.floorplan.solver import solve_floorplan

__all__ = ["solve_floorplan"]
