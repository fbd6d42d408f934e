"""Stairwells trimmed to their stair: the floor a storey's solve left beside the stair goes
to the room across the stairwell's long wall.

A storey is laid out as a house of its own, and its stairwell comes out as wide as the
slicing of its footprint left it (measured: 11-13 m2 for 8.5 m2 planned, a chalet's
one-door stairwell 3.6 x 3.2 m beside a 1.75 m stair). Once the storeys are stacked and
the stair's place is known (:func:`anyhome.floorplan.levels.stack_box`), the band of a
stairwell beyond what its stair needs (the stair's width, the landing in front of doors in
that long wall, :data:`~anyhome.floorplan.stairs.PASSAGE_M`, and the doors in its end
walls) is given to the room whose wall spans that whole long wall, where the room stays a
rectangle or an L within its aspect limit (its doors onto the stairwell move with the
wall), or to the outside where that long wall is an outside wall (its doors and windows
move with it).

Then its ends (:func:`wells_end_trimmed`): the stretch of a stairwell beyond the stair's
box at one end and beyond the strip at its foot at the other (doors in its long walls
kept inside) goes the same way to the room across that end wall, or to the outside where
nothing of the storey above stands on it; a well trimmed so may come out flush with a
corner of the room its stair opens onto, which then takes it as an L
(:func:`anyhome.floorplan.levels.stairs_opened`).

Before both, where the well is not merged into a room, the doors in its long walls that
open beside the stair's box or beyond the strip at its foot are slid onto the strip
(:func:`wells_doors_to_strip`): a landing only as big as its doors need.
"""

from __future__ import annotations

import math

from shapely.geometry import LineString, Polygon, box

from anyhome.floorplan.grid import SNAP_M
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.stairs import (
    DOGLEG,
    PASSAGE_M,
    STAIR_CLEAR_M,
    STRIP_M,
    is_stairwell,
    stair_width_m,
    well_width_m,
)
from anyhome.house import Floorplan, Room


def wells_trimmed(plan: Floorplan, ya: float, wells: dict[int, str], opts: FloorplanOptions,
                  kind: str = DOGLEG, boxes: dict[int, tuple[float, float]] | None = None) -> Floorplan:
    """``plan`` with each stairwell of ``wells`` (storey -> room id; rectangles whose long
    side runs east-west, their stair of ``kind`` on the strip ``ya`` to ``ya`` + the
    stair's width) trimmed on each long side to what its stair and doors need (see the
    module doc; a ladder's well keeps its passage beside the ladder). ``boxes``: storey
    -> the x span of its stair's box, where known: a door in a long wall clear of it
    opens onto the strip at the stair's foot and needs no passage beside the stair."""
    width_m = stair_width_m(kind)
    from anyhome.house import is_habitable

    for k, well_id in wells.items():
        for north in (True, False):
            well = plan.room(well_id)
            if len(well.polygon) != 4:
                continue
            xs, ys = [p[0] for p in well.polygon], [p[1] for p in well.polygon]
            x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
            edge = y1 if north else y0
            wall = LineString([(x0, edge), (x1, edge)])
            doors = [d for d in plan.doors if well_id in d.rooms]
            on_wall = [d for d in doors if _on(d.segment, wall)]
            span = (boxes or {}).get(k)
            passage = [d for d in on_wall if span is None or _beside(d.segment, span)]
            keep = max(well_width_m(kind), width_m + (PASSAGE_M if passage else 0.0))
            in_ends = [p[1] for d in doors if abs(d.segment[0][0] - d.segment[1][0]) < 1e-6 for p in d.segment]
            if north:  # the band from the stair (and the doors in the end walls) to the north wall
                cut = _snap_out(max([ya + keep, *in_ends]), up=True)
                band = box(x0, cut, x1, y1) if y1 - cut >= opts.well_trim_min_m - 1e-6 else None
            else:
                cut = _snap_out(min([ya + width_m - keep, *in_ends]), up=False)
                band = box(x0, y0, x1, cut) if cut - y0 >= opts.well_trim_min_m - 1e-6 else None
            if band is None:
                continue
            other = _across(plan, k, well_id, wall)
            if other is None and _outside(plan, k, well_id, wall):  # the band goes to the outside
                plan = _moved_wall(plan, well, None, None, band, cut, edge, on_wall)
                continue
            if other is None:
                continue
            outline = _grown(other, band, opts.max_habitable_aspect_ratio if is_habitable(other.type) else opts.max_room_aspect_ratio)
            if outline is not None:
                plan = _moved_wall(plan, well, other, outline, band, cut, edge, on_wall)
    return plan


def wells_doors_to_strip(plan: Floorplan, place: tuple[float, float, float], wells: dict[int, str]) -> Floorplan:
    """``plan`` with the doors in each long wall of each stairwell of ``wells`` (storey ->
    room id; rectangles whose long side runs east-west) that open off the strip at the
    foot of the stair of ``place`` ((foot_x, y0, yaw), :func:`anyhome.floorplan.levels.stack_box`),
    beside the stair's box or beyond the strip, slid along their wall onto the strip
    (:func:`anyhome.floorplan.levels._clear_spot`: the nearest place whose swing is clear
    of the rest of the well, still on both rooms' walls, no door near), where every such
    door of that wall finds one; a wall with one that does not keeps them all. The doors
    then need no passage beside the stair and no floor beyond the strip, which go to the
    room across (:func:`wells_trimmed`, :func:`wells_end_trimmed`), as a landing is only
    as big as its doors need (measured: the stairwells of storeys whose bedrooms opened
    beside the flight or past the strip stayed 2.1-2.7 m wide or 0.6 m long beyond
    it, 7.4-9.7 m2 for 6.3)."""
    from shapely.ops import unary_union

    from anyhome.floorplan.levels import _clear_spot

    foot, _, yaw = place
    lo, hi = (foot, foot + STRIP_M) if abs(yaw) < 0.1 else (foot - STRIP_M, foot)
    for k, well_id in wells.items():
        well = plan.room(well_id)
        if len(well.polygon) != 4:
            continue
        xs, ys = [p[0] for p in well.polygon], [p[1] for p in well.polygon]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
        if lo < x0 - 1e-6 or hi > x1 + 1e-6:
            continue
        rest = unary_union([box(x0 - 1.0, y0, lo, y1), box(hi, y0, x1 + 1.0, y1)]).buffer(STAIR_CLEAR_M)  # the well off the strip
        outlines = {r.id: Polygon(r.polygon).exterior.buffer(1e-6) for r in plan.rooms if r.level == k}
        for edge in (y0, y1):
            wall = LineString([(x0, edge), (x1, edge)])
            doors = list(plan.doors)
            moving = [i for i, d in enumerate(doors) if well_id in d.rooms and "outside" not in d.rooms
                      and _on(d.segment, wall) and LineString(d.segment).intersects(rest)]
            for i in moving:
                other = next(x for x in doors[i].rooms if x != well_id)
                seg = _clear_spot(doors[i].segment, rest, (outlines[well_id], outlines.get(other)),
                                  [e.segment for j, e in enumerate(doors) if j != i and e.rooms[0] in outlines])
                if seg is None:
                    break
                doors[i] = doors[i].model_copy(update={"segment": seg})
            else:
                if moving:
                    plan = plan.model_copy(update={"doors": doors})
    return plan


def _beside(segment, span: tuple[float, float]) -> bool:
    """Whether a door in a long wall (``segment``) lies along the stair's box (its x
    ``span``, grown by the stair's clearance from doors)."""
    lo, hi = sorted(p[0] for p in segment)
    return hi > span[0] - STAIR_CLEAR_M + 1e-6 and lo < span[1] + STAIR_CLEAR_M - 1e-6


def wells_end_trimmed(plan: Floorplan, place: tuple[float, float, float], lengths: dict[int, float],
                      wells: dict[int, str], opts: FloorplanOptions) -> Floorplan:
    """``plan`` with each stairwell of ``wells`` (storey -> room id; rectangles whose long
    side runs east-west) cut at its ends to the stair of ``place`` ((foot_x, y0, yaw),
    :func:`anyhome.floorplan.levels.stack_box`): its box ``lengths[k]`` long and the strip
    at its foot, and every door in its long walls (see the module doc). The end behind
    the box is cut only where no door is in it (a door there opens beside the flight)."""
    from anyhome.house import is_habitable

    foot, _, yaw = place
    for k, well_id in wells.items():
        for east in (True, False):
            well = plan.room(well_id)
            if len(well.polygon) != 4 or k not in lengths:
                continue
            xs, ys = [p[0] for p in well.polygon], [p[1] for p in well.polygon]
            x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
            lo, hi = (foot - lengths[k], foot + STRIP_M) if abs(yaw) < 0.1 else (foot - STRIP_M, foot + lengths[k])
            doors = [d for d in plan.doors if well_id in d.rooms]
            along = [p[0] for d in doors if abs(d.segment[0][1] - d.segment[1][1]) < 1e-6 for p in d.segment]
            lo, hi = min([lo, *along]), max([hi, *along])
            edge = x1 if east else x0
            wall = LineString([(edge, y0), (edge, y1)])
            on_wall = [d for d in doors if _on(d.segment, wall)]
            if on_wall and east != (abs(yaw) < 0.1):  # the end behind the box: its door opens beside the flight
                continue
            if east:
                cut = _snap_out(hi, up=True)
                band = box(cut, y0, x1, y1) if x1 - cut >= opts.well_trim_min_m - 1e-6 else None
            else:
                cut = _snap_out(lo, up=False)
                band = box(x0, y0, cut, y1) if cut - x0 >= opts.well_trim_min_m - 1e-6 else None
            if band is None:
                continue
            other = _across(plan, k, well_id, wall)
            if other is None and _outside(plan, k, well_id, wall) and not _above(plan, k, band):
                plan = _moved_wall(plan, well, None, None, band, cut, edge, on_wall, axis=0)
                continue
            if other is None:
                continue
            most = opts.max_habitable_aspect_ratio if is_habitable(other.type) else opts.max_room_aspect_ratio
            outline = _grown(other, band, most)
            if outline is not None:
                plan = _moved_wall(plan, well, other, outline, band, cut, edge, on_wall, axis=0)
    return plan


def _above(plan: Floorplan, k: int, band) -> bool:
    """Whether a room of the storey over storey ``k`` stands on ``band``."""
    return any(r.level == k + 1 and Polygon(r.polygon).intersection(band).area > 1e-6 for r in plan.rooms)


def _outside(plan: Floorplan, k: int, well_id: str, wall: LineString) -> bool:
    """Whether ``wall`` touches no other room of storey ``k`` (it is an outside wall)."""
    return not any(r.level == k and r.id != well_id and Polygon(r.polygon).exterior.intersection(wall).length > 1e-6
                   for r in plan.rooms)


def _snap_out(v: float, up: bool) -> float:
    """``v`` on the 5 cm grid, rounded away from the stair (up: toward +y)."""
    q = v / SNAP_M
    return round((math.ceil(q - 1e-6) if up else math.floor(q + 1e-6)) * SNAP_M, 4)


def _on(segment, wall: LineString) -> bool:
    return bool(wall.buffer(1e-6).contains(LineString(segment)))


def _across(plan: Floorplan, k: int, well_id: str, wall: LineString) -> Room | None:
    """The room of storey ``k`` whose outline holds the whole of ``wall``, if any (not a
    stairwell, not open to the sky)."""
    for r in plan.rooms:
        if r.level != k or r.id == well_id or r.open_air or is_stairwell(r):
            continue
        if Polygon(r.polygon).exterior.buffer(1e-6).contains(wall):
            return r
    return None


def _grown(room: Room, band, most_aspect: float) -> list[tuple[float, float]] | None:
    """``room``'s outline with ``band`` added, when a rectangle or an L within ``most_aspect``."""
    from anyhome.floorplan.merge import l_aspect_over, union_outline

    outline = union_outline(room.polygon, [(round(x, 4), round(y, 4)) for x, y in band.exterior.coords[:-1]])
    if outline is None or l_aspect_over(outline, most_aspect + 1e-9):
        return None
    return outline


def _moved_wall(plan: Floorplan, well: Room, other: Room | None, outline, band, cut: float, edge: float,
                on_wall: list, axis: int = 1) -> Floorplan:
    """``plan`` with ``band`` of ``well`` given to ``other`` (``outline``; None: to the
    outside): the wall at ``edge`` (a y, ``axis`` 1; an x, ``axis`` 0) moved to ``cut``,
    the doors on it with it; the well's windows in the band given to ``other`` (to the
    outside: those in the moved wall move with it, the others go)."""
    pts = [(p[1 - axis], p[axis]) for p in well.polygon]  # (along the wall, across it)
    a0, a1 = min(p[0] for p in pts), max(p[0] for p in pts)
    lo, hi = (min(p[1] for p in pts), cut) if edge > cut else (cut, max(p[1] for p in pts))

    def xy(along: float, across: float) -> tuple[float, float]:
        return (along, across) if axis == 1 else (across, along)

    def at_cut(p) -> tuple[float, float]:
        return (p[0], cut) if axis == 1 else (cut, p[1])

    rect = [xy(a0, lo), xy(a1, lo), xy(a1, hi), xy(a0, hi)]
    if axis == 0:  # (y, x) corners listed so: counter-clockwise again
        rect = [rect[0], rect[3], rect[2], rect[1]]
    rooms = [r.model_copy(update={"polygon": rect}) if r.id == well.id
             else r.model_copy(update={"polygon": outline}) if other is not None and r.id == other.id else r
             for r in plan.rooms]
    moved = {id(d) for d in on_wall}
    doors = [d.model_copy(update={"segment": tuple(at_cut(p) for p in d.segment)}) if id(d) in moved else d
             for d in plan.doors]
    inside = band.buffer(1e-6)
    wall = LineString([xy(a0, edge), xy(a1, edge)]).buffer(1e-6)
    windows = []
    for w in plan.windows:
        if w.room == well.id and inside.contains(LineString(w.segment)):
            if other is not None:
                w = w.model_copy(update={"room": other.id})
            elif wall.contains(LineString(w.segment)):
                w = w.model_copy(update={"segment": tuple(at_cut(p) for p in w.segment)})
            else:
                continue
        windows.append(w)
    return plan.model_copy(update={"rooms": rooms, "doors": doors, "windows": windows})
