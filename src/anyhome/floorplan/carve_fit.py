"""Carve searches known to fail, told before they are run.

A storey whose stairwell opens onto one room only is first searched with the stairwell
carved from a corner of that room (:mod:`anyhome.floorplan.carve`,
:func:`anyhome.floorplan.levels._carved_storey`): ``stair_carve_max_attempts`` layout
attempts, each as costly as any other. Measured on dev_storeys, dev_storeys2 and
dev_storeys3 (seeds 0-2, the planner's and the floorplan stage's searches together): 384
of 956 carve searches found no layout, and they took about two thirds of the carve
searches' CPU. Two kinds of them are told here from the storey's program alone:

- **a crowded hall** (:func:`crowded_hall`): a hallway carved into the stair and the
  passage beside it (``stair_carve_left_m``) that must still door onto
  ``stair_carve_hall_max_links`` or more rooms (the outside counted: an upper storey's
  stand-in entrance): 0 of 88 such searches found a layout (upper storeys' landings
  between four or five bedrooms and bathrooms);
- **two rooms that cannot share a rectangle** (:func:`two_rooms_unfit`): a storey of the
  carved room and one other is laid out in a rectangular footprint (fewer rooms than
  ``l_shape_min_rooms``) cut once; where no footprint of the drawn proportions
  (``footprint_aspect_min`` to ``footprint_aspect_max``) and no straight cut gives both
  rooms their area (within ``area_tolerance_frac``), least side, greatest aspect and the
  carved room the stair's length, to within ``stair_carve_fit_slack_cells`` of a grid cell, no slicing can (a cottage's
  small kitchen beside a living room holding the stair: of 266 such searches, 199 found
  nothing; 169 of those are told, none of the 67 that found a layout).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from anyhome.floorplan.grid import cell_size_m
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.program import Program
from anyhome.plan.spec import HouseSpec

CROWDED_HALL_TYPES = frozenset({"hallway"})
"""Room types :func:`crowded_hall` applies to (an entry of as many links did find layouts
on a large spine-laid storey: not included)."""


def crowded_hall(carved_sub: HouseSpec, room: str, opts: FloorplanOptions) -> bool:
    """Whether ``room`` of the carved storey ``carved_sub`` is a hallway with
    ``stair_carve_hall_max_links`` or more links (its carve search is known to fail)."""
    r = next((x for x in carved_sub.rooms if x.id == room), None)
    links = sum(room in c for c in carved_sub.connections)
    return r is not None and r.type in CROWDED_HALL_TYPES and links >= opts.stair_carve_hall_max_links


def two_rooms_unfit(carved_sub: HouseSpec, room: str, long_m: float, side_m: float, opts: FloorplanOptions,
                    kb=None) -> bool:
    """Whether the carved storey ``carved_sub`` is two rooms (``room``, which holds the
    stairwell, at least ``long_m`` long and ``side_m`` wide, and one other) that no
    rectangular footprint cut once can hold (see the module doc); False for any other
    storey (nothing known)."""
    if len(carved_sub.rooms) != 2 or opts.l_shape_min_rooms <= 2 or opts.u_shape_min_rooms <= 2:
        return False
    if kb is None:
        from anyhome.plan.knowledge import knowledge_base

        kb = knowledge_base()
    prog = Program.from_spec(carved_sub, opts, kb)
    i = prog.ids.index(room)
    prog = replace(prog, min_width_m=tuple(max(w, side_m) if k == i else w
                                           for k, w in enumerate(prog.min_width_m or (0.0,) * prog.n)))
    areas = [float(a) for a in prog.areas_m2]
    total_m2 = sum(areas)
    slack_m = opts.stair_carve_fit_slack_cells * cell_size_m(total_m2, opts)
    least = [prog.min_side_m(k) for k in range(2)]
    aspect = [prog.max_aspect(k) for k in range(2)]

    def fits(k: int, w: np.ndarray, h: float) -> np.ndarray:  # room k as w x h (every w at once), give or take a cell
        short, long_ = np.minimum(w, h), np.maximum(w, h)
        ok = (short + slack_m >= least[k]) & ((long_ - slack_m) / (short + slack_m) <= aspect[k] + 1e-9)
        if k == i:
            ok &= long_ + slack_m >= long_m
        ratio = w * h / max(areas[k], least[k] ** 2)
        return ok & ((np.abs(ratio - 1) <= opts.area_tolerance_frac)
                     | ((ratio > 1) & (w * h <= (1 + opts.area_tolerance_frac) * least[k] ** 2)))

    other = 1 - i
    for a in np.linspace(opts.footprint_aspect_min, opts.footprint_aspect_max, max(2, opts.stair_carve_fit_steps // 8)):
        x_m = max(math.sqrt(total_m2 * a), long_m)
        y_m = total_m2 / x_m
        for along_m, across_m in ((x_m, y_m), (y_m, x_m)):  # the cut across ``along_m``, at every place t
            t = np.linspace(0.0, along_m, opts.stair_carve_fit_steps)[1:-1]
            if np.any(fits(other, t, across_m) & fits(i, along_m - t, across_m)):
                return False
    return True
