"""Exact layouts of a storey of two or three rooms (a tiny house's loft and shower room
over its ladder; a tower home's kitchen beside its stairs).

The slicing search draws a footprint of random proportions and cuts it at random; for a
storey of a few small rooms near their least widths it seldom finds one whose every room
is wide enough (measured: a tiny A-frame's ground storey, 24 of 24 attempts "too
narrow" at its planned 20 m2), and the storey is laid out again with a roomier stairwell,
which the stacking trims back into the rooms beside it: the tiny house comes out a third
larger than planned. A storey of two or three rooms has few arrangements worth trying:
side by side in strips, or one room along a whole side and the other two beside it.
:func:`small_owners` tries them all over every footprint depth and gives the best few
(by area error and proportions) as owner arrays for
:func:`anyhome.floorplan.solver._constructed_attempt`, which checks them, gives them
doors and windows, and hands them to the caller's own checks (the stair) like any
other layout.
"""

from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING

import numpy as np

from anyhome.floorplan.grid import FREE, OUTSIDE, min_side_cells
from anyhome.floorplan.slicing import Rect, shared_wall_cells

if TYPE_CHECKING:
    from anyhome.floorplan.options import FloorplanOptions
    from anyhome.floorplan.program import Program


def small_owners(prog: Program, opts: FloorplanOptions, rng: np.random.Generator) -> list[np.ndarray]:
    """Owner arrays (cells of ``opts.spine_cell_m``, a ring of outside around them) of the
    best exact arrangements of a storey of 2 to ``opts.small_exact_max_rooms`` rooms of a
    house of several (``prog.stacked``), best first, at most ``opts.small_exact_candidates``;
    [] for any other program or when ``small_exact_max_rooms`` is 0."""
    if not prog.stacked or not 2 <= prog.n <= opts.small_exact_max_rooms:
        return []
    cell = opts.spine_cell_m
    want = prog.areas_m2 / cell**2
    least = [min_side_cells(prog.min_side_m(k), cell, opts) for k in range(prog.n)]
    longest = [math.ceil(m / cell - 1e-9) for m in (prog.min_length_m or (0.0,) * prog.n)]
    # a room is measured against the least rectangle its widths allow (a stairwell as long as its stair)
    target = np.maximum(want, np.array([s * max(s, n) for s, n in zip(least, longest)], dtype=float))
    aspect = [prog.max_aspect(k) for k in range(prog.n)]
    door_cells = math.ceil(opts.small_door_wall_m / cell - 1e-9)
    stairs = [m > 0 for m in (prog.stair_m or (0.0,) * prog.n)]
    scored: list[tuple[float, dict[int, Rect]]] = []
    total = float(target.sum())
    for depth in range(max(2, min(least)), int(math.sqrt(total) * 3) + 1):
        for rects in _arrangements(prog.n, depth, target, least):
            score = _score(rects, target, least, longest, aspect, opts, prog.circulation or (False,) * prog.n, stairs)
            if score is not None and all(shared_wall_cells(rects[a], rects[b]) >= door_cells for a, b in prog.edges):
                scored.append((score + _compactness(rects, opts), rects))
    scored.sort(key=lambda t: t[0])
    out = []
    for _, rects in scored[: opts.small_exact_candidates]:
        owner = _owner(rects)
        out.append(owner if rng.random() < 0.5 else np.ascontiguousarray(owner.T))  # either way round
    return out


def _arrangements(n: int, depth: int, target: np.ndarray, least: list[int]):
    """Every arrangement of ``n`` rooms (2 or 3; ``target`` cells each, at least ``least``
    wide) in a rectangle ``depth`` cells deep: strips side by side in each order; with
    three, also one room along the whole depth and the other two one above the other
    beside it."""
    for order in itertools.permutations(range(n)):
        x = 0
        strips: dict[int, Rect] = {}
        for k in order:
            w = max(least[k], round(target[k] / depth))
            strips[k] = (x, 0, x + w, depth)
            x += w
        yield strips
        if n == 3:
            a, b, c = order
            wa = max(least[a], round(target[a] / depth))
            rest = max(least[b], least[c], round((target[b] + target[c]) / depth))
            hb = max(least[b], round(target[b] / rest))
            if hb < depth:
                yield {a: (0, 0, wa, depth), b: (wa, 0, wa + rest, hb), c: (wa, hb, wa + rest, depth)}


def _score(rects: dict[int, Rect], target: np.ndarray, least: list[int], longest: list[int], aspect: list[float],
           opts: FloorplanOptions, circulation: tuple[bool, ...], stairs: list[bool]) -> float | None:
    """The arrangement's area error plus its aspect penalty (as the solver scores a
    layout), a stairwell's or hall's floor beyond its target counted
    ``small_circulation_excess_weight`` times more; None where a room is off its area, too
    narrow, too short or too elongated (the solver's own checks,
    :func:`anyhome.floorplan.solver._check_rooms`). A room holding a stair (``stairs``)
    may be larger by up to ``small_stair_excess_frac``: the stacking gives its ends beyond
    the stair to the room across (:func:`anyhome.floorplan.wells.wells_end_trimmed`)."""
    score = 0.0
    for k, (x0, y0, x1, y1) in rects.items():
        w, h = x1 - x0, y1 - y0
        short, long_ = min(w, h), max(w, h)
        ratio = w * h / target[k]
        over = opts.small_stair_excess_frac if stairs[k] else opts.area_tolerance_frac
        if not -opts.area_tolerance_frac <= ratio - 1 <= over or short < least[k] or long_ < longest[k]:
            return None
        if long_ / short > aspect[k] + 1e-9:
            return None
        score += abs(ratio - 1) + opts.score_aspect_weight * max(0.0, long_ / short - opts.score_aspect_free_ratio)
        if circulation[k]:
            score += opts.small_circulation_excess_weight * max(0.0, ratio - 1)
    return score


def _compactness(rects: dict[int, Rect], opts: FloorplanOptions) -> float:
    """Penalty of a footprint longer than ``footprint_aspect_max`` (a storey is a block,
    not a corridor of rooms), as a room's aspect is penalised."""
    w = max(r[2] for r in rects.values())
    h = max(r[3] for r in rects.values())
    ratio = max(w, h) / min(w, h)
    return opts.score_aspect_weight * max(0.0, ratio - opts.footprint_aspect_max)


def _owner(rects: dict[int, Rect]) -> np.ndarray:
    """The owner array of ``rects`` (room index per cell) with a ring of outside cells."""
    w = max(r[2] for r in rects.values())
    h = max(r[3] for r in rects.values())
    owner = np.full((w + 2, h + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    for k, (x0, y0, x1, y1) in rects.items():
        owner[x0 + 1 : x1 + 1, y0 + 1 : y1 + 1] = k
    return owner
