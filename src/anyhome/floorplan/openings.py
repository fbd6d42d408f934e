"""Openings (doors and windows) as intervals on straight wall lines, in meters."""

from __future__ import annotations

from dataclasses import dataclass

from anyhome.floorplan.grid import SNAP_M
from anyhome.floorplan.walls import Run


@dataclass(frozen=True)
class Opening:
    """An opening on the wall line ``x = line_m`` (axis 0) or ``y = line_m`` (axis 1)."""

    axis: int
    line_m: float
    lo_m: float
    hi_m: float

    @property
    def width_m(self) -> float:
        return self.hi_m - self.lo_m

    def segment(self) -> tuple[tuple[float, float], tuple[float, float]]:
        c, a, b = round(self.line_m, 4), round(self.lo_m, 4), round(self.hi_m, 4)
        return ((c, a), (c, b)) if self.axis == 0 else ((a, c), (b, c))

    def gap_to(self, other: Opening) -> float:
        """Distance along the wall to ``other`` (inf if not on the same line)."""
        if other.axis != self.axis or abs(other.line_m - self.line_m) > 1e-6:
            return float("inf")
        return max(other.lo_m - self.hi_m, self.lo_m - other.hi_m)

    def zone_overlap_m2(self, other: Opening, depth_m: float) -> float:
        """Overlap area of the two openings' keep-clear rectangles (``depth_m`` each side)."""
        along = min(self.hi_m, other.hi_m) - max(self.lo_m, other.lo_m)
        if self.axis == other.axis:
            across = 2 * depth_m - abs(self.line_m - other.line_m)
            return max(0.0, along) * max(0.0, across)
        wx = min(self.line_m + depth_m, other.hi_m) - max(self.line_m - depth_m, other.lo_m)
        wy = min(other.line_m + depth_m, self.hi_m) - max(other.line_m - depth_m, self.lo_m)
        return max(0.0, wx) * max(0.0, wy)


def snap_m(value: float) -> float:
    """Round to the 5 cm grid (4 decimals)."""
    return round(round(value / SNAP_M) * SNAP_M, 4)


def snap_down_m(value: float) -> float:
    return round(int(value / SNAP_M + 1e-6) * SNAP_M, 4)


def run_bounds_m(run: Run, cell_m: float) -> tuple[float, float, float]:
    """(line, start, end) of a run in meters."""
    return round(run.line * cell_m, 4), round(run.t0 * cell_m, 4), round(run.t1 * cell_m, 4)
