"""Windows on the exterior walls: every habitable room gets one, bathrooms a small high one.

A window sits in the largest free stretch of an exterior wall run, at least
``FloorplanOptions.window_corner_margin_m`` from the run's ends and from any door on that wall line,
its width a share of the wall.
"""

from __future__ import annotations

from dataclasses import dataclass

from anyhome.floorplan.doors import PlacedDoor
from anyhome.floorplan.grid import OUTSIDE
from anyhome.floorplan.openings import Opening, run_bounds_m, snap_down_m, snap_m
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.walls import Run

WINDOW_SILL_M = 0.9
"""Sill height of a window (a physical standard, not an option)."""
WINDOW_HEIGHT_M = 1.2
"""Height of a window opening."""
BATH_WINDOW_WIDTH_M = 0.8
"""Width of a bathroom's small high window."""
BATH_WINDOW_SILL_M = 1.5
"""Sill height of a bathroom window (high, for privacy)."""
BATH_WINDOW_HEIGHT_M = 0.6
"""Height of a bathroom window."""


@dataclass(frozen=True)
class PlacedWindow:
    room: int
    opening: Opening
    sill_m: float = WINDOW_SILL_M
    height_m: float = WINDOW_HEIGHT_M


def free_slots(
    room: int, runs: list[Run], doors: list[PlacedDoor], cell_m: float, opts: FloorplanOptions,
    outdoors: frozenset[int] = frozenset(),
) -> list[tuple[float, Opening]]:
    """Free stretches of ``room``'s exterior walls as (run length, stretch), longest first;
    a wall onto a room of ``outdoors`` (an open-air courtyard) counts as exterior."""
    slots = []
    for run in runs:
        other = run.b if run.a == room else run.a
        if not (run.touches(room) and (other == OUTSIDE or other in outdoors)):
            continue
        line, start, end = run_bounds_m(run, cell_m)
        blocked = [
            d.opening for d in doors
            if room in d.rooms and d.opening.axis == run.axis and abs(d.opening.line_m - line) < 1e-6
        ]
        margin = opts.window_corner_margin_m
        for lo, hi in _free_intervals(start + margin, end - margin, blocked, margin):
            slots.append((end - start, Opening(run.axis, line, lo, hi)))
    return sorted(slots, key=lambda s: (-s[1].width_m, -s[0]))


def _free_intervals(lo: float, hi: float, blocked: list[Opening], margin_m: float) -> list[tuple[float, float]]:
    pieces = [(lo, hi)]
    for b in blocked:
        cut_lo, cut_hi = b.lo_m - margin_m, b.hi_m + margin_m
        pieces = [
            piece
            for a, z in pieces
            for piece in ((a, min(z, cut_lo)), (max(a, cut_hi), z))
            if piece[1] - piece[0] > 1e-9
        ]
    return pieces


def window_room_ok(slots: list[tuple[float, Opening]], opts: FloorplanOptions) -> bool:
    return bool(slots) and slots[0][1].width_m >= opts.window_min_width_m - 1e-9


def place_windows(
    room: int, habitable: bool, bathroom: bool, slots: list[tuple[float, Opening]], opts: FloorplanOptions
) -> list[PlacedWindow]:
    """Windows of one room in its free exterior stretches (``slots`` from :func:`free_slots`)."""
    if bathroom:
        usable = [s for _, s in slots if s.width_m >= BATH_WINDOW_WIDTH_M - 1e-9]
        if not usable:
            return []
        return [PlacedWindow(room, _centred(usable[0], BATH_WINDOW_WIDTH_M), BATH_WINDOW_SILL_M, BATH_WINDOW_HEIGHT_M)]
    if not habitable:
        return []
    out: list[PlacedWindow] = []
    used_lines: set[tuple[int, float]] = set()
    for run_len, slot in slots:
        if slot.width_m < opts.window_min_width_m - 1e-9 or (slot.axis, slot.line_m) in used_lines:
            continue
        if out and run_len < opts.second_window_run_m:
            continue
        share_m = snap_down_m(opts.window_wall_share_frac * run_len)
        width = min(opts.window_max_width_m, max(opts.window_min_width_m, share_m))
        out.append(PlacedWindow(room, _centred(slot, min(width, snap_down_m(slot.width_m)))))
        used_lines.add((slot.axis, slot.line_m))
        if len(out) >= opts.max_windows_per_room:
            break
    return out


def _centred(slot: Opening, width: float) -> Opening:
    """A ``width`` opening centred in ``slot``, snapped to the grid and kept inside it."""
    lo = snap_m(slot.lo_m + (slot.width_m - width) / 2)
    lo = min(max(lo, slot.lo_m), slot.hi_m - width)
    return Opening(slot.axis, slot.line_m, round(lo, 4), round(lo + width, 4))
