"""Kitchen figures (issue 14): do a room's sink, cooktop and fridge stand in counter runs,
and are there wall cabinets over the counters?

Definitions
-----------
kitchen
    A room holding a floor object of category ``counter`` and floor objects of at least
    two of the categories ``sink``, ``stove`` and ``refrigerator`` (a shop's counter and
    drinks fridge is no kitchen).
run piece
    A floor object of category ``counter``, ``sink``, ``stove`` or ``refrigerator`` whose
    back edge (middle) lies within :data:`WALL_GAP_M` of its room's outline.
run
    Run pieces chained by touching footprints (at most :data:`TOUCH_M` apart), along a
    wall and round a corner.
work run
    Of each of sink, cooktop and fridge the kitchen has, one stands in a run that holds a
    counter, and the kitchen's run pieces form at most two runs (one run, an L or a U; or
    the two facing runs of a galley).
wall cabinets
    A kitchen has them when an object of category ``cabinet`` hung on a wall (support
    ``wall``) lies over a counter: their footprints overlap seen from above by more than
    :data:`OVER_M2` and its bottom is above the counter's top.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon

from anyhome import geometry
from anyhome.house import HouseObject

WALL_GAP_M = 0.15
"""A run piece whose back is at most this far from a wall stands against it."""
TOUCH_M = 0.03
"""Two run pieces this close (footprint to footprint) are side by side in one run."""
OVER_M2 = 0.01
"""Least overlap (seen from above) of a wall cabinet with a counter it hangs over."""
RUN_CATEGORIES = frozenset({"counter", "sink", "stove", "refrigerator"})
"""Categories of the pieces of a kitchen's counter run."""
WORK_CATEGORIES = ("sink", "stove", "refrigerator")
"""The three points of the work triangle."""
MAX_RUNS = 2
"""A kitchen's run pieces in more runs than this are scattered, not laid out as runs."""


@dataclass
class KitchenFigures:
    """Counts over a house's kitchens."""

    n_kitchens: int = 0
    n_work_run: int = 0
    n_wall_cabinets: int = 0


def kitchen_figures(rooms: dict[str, Polygon], objects: dict[str, list[HouseObject]]) -> KitchenFigures:
    """The figures of the rooms ``rooms`` (id -> floor polygon), ``objects`` by room id."""
    out = KitchenFigures()
    for rid, poly in rooms.items():
        objs = objects.get(rid, [])
        cats = {o.category for o in objs if o.support == "floor"}
        if "counter" not in cats or len(cats & set(WORK_CATEGORIES)) < 2:
            continue
        out.n_kitchens += 1
        pieces = [o for o in objs if o.support == "floor" and o.category in RUN_CATEGORIES and _on_wall(o, poly)]
        runs = _runs(pieces)
        if _work_run(runs, objs):
            out.n_work_run += 1
        if _has_wall_cabinets(objs):
            out.n_wall_cabinets += 1
    return out



def _on_wall(o: HouseObject, poly: Polygon) -> bool:
    back = np.asarray(o.position[:2]) - geometry.front_dir(o.yaw) * o.size[1] / 2
    return bool(poly.exterior.distance(shapely.Point(back)) <= WALL_GAP_M)


def _runs(pieces: list[HouseObject]) -> list[list[HouseObject]]:
    """``pieces`` chained into runs (connected by touching footprints)."""
    fps = [geometry.footprint_polygon(o.position, o.size, o.yaw) for o in pieces]
    label = list(range(len(pieces)))

    def root(i: int) -> int:
        while label[i] != i:
            i = label[i]
        return i

    for i in range(len(pieces)):
        for j in range(i + 1, len(pieces)):
            if fps[i].distance(fps[j]) <= TOUCH_M:
                label[root(i)] = root(j)
    runs: dict[int, list[HouseObject]] = {}
    for i, o in enumerate(pieces):
        runs.setdefault(root(i), []).append(o)
    return list(runs.values())


def _work_run(runs: list[list[HouseObject]], objs: list[HouseObject]) -> bool:
    if not runs or len(runs) > MAX_RUNS:
        return False
    with_counter = [r for r in runs if any(o.category == "counter" for o in r)]
    for cat in WORK_CATEGORIES:
        if not any(o.support == "floor" and o.category == cat for o in objs):
            continue
        if not any(o.category == cat for r in with_counter for o in r):
            return False
    return True


def _has_wall_cabinets(objs: list[HouseObject]) -> bool:
    counters = [o for o in objs if o.support == "floor" and o.category == "counter"]
    hung = [o for o in objs if o.support == "wall" and o.category == "cabinet"]
    for c in counters:
        cfp = geometry.footprint_polygon(c.position, c.size, c.yaw)
        top = c.position[2] + c.size[2]
        for h in hung:
            hfp = geometry.footprint_polygon(h.position, h.size, h.yaw)
            if h.position[2] >= top and hfp.intersection(cfp).area > OVER_M2:
                return True
    return False
