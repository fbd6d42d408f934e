"""The floorplan solver's tunable numbers, as one frozen set of named options.

``solve_floorplan(spec, rng, options=FloorplanOptions())``: every try count, tolerance
and annealing schedule value the solver uses is a field here (units in the names); the
defaults are AnyHome's own, so the default options give the same floorplans as always.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from anyhome.errors import AnyHomeError


@dataclass(frozen=True)
class FloorplanOptions:
    """Tunable numbers of :func:`anyhome.floorplan.solve_floorplan`."""

    max_attempts: int = 40
    """Attempts before giving up with a FloorplanError."""
    slicing_max_rooms: int = 6
    """Programs up to this many rooms try the slicing search first; larger ones go to the spine."""
    slicing_attempts: int = 10
    """Slicing attempts before falling back to the constructive spine layout."""
    wanted_candidates: int = 3
    """Valid layouts to collect before keeping the best one (lowest score)."""
    area_tolerance_frac: float = 0.25
    """Allowed relative deviation of a room's area from its target (0.25: 25 %)."""
    max_room_aspect_ratio: float = 2.5
    """Longest/shortest bounding-box side of a room (hallways excepted)."""
    max_narrow_share_frac: float = 0.08
    """Share of a room's floor allowed in arms narrower than its minimum side."""
    anneal_steps_per_room: int = 150
    """Annealing steps of the slicing tree per room of the program."""
    anneal_start_temperature: float = 4.0
    """Starting temperature of the annealing (in units of the layout cost)."""
    anneal_end_temperature: float = 0.05
    """Final temperature of the annealing (geometric schedule from the start)."""

    def __post_init__(self) -> None:
        for f in fields(self):
            v = getattr(self, f.name)
            least = 0 if f.name == "slicing_attempts" else 1 if f.type == "int" else 0.0
            if isinstance(v, bool) or not isinstance(v, (int, float)) or v < least or (f.type == "int" and not isinstance(v, int)):
                raise AnyHomeError(f"FloorplanOptions.{f.name} must be a number >= {least}, got {v!r}")
