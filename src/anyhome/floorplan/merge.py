"""Open-plan L rooms: two rooms joined by a wide opening become one L-shaped room.

A post-solve step on a finished one-storey :class:`~anyhome.house.Floorplan`: where a
pair of rooms of ``open_plan.yaml``'s ``pairs`` (living + dining, kitchen + dining,
living + kitchen) is joined by a door and their two rectangles, flush at one end,
share a wall over only part of one room's side, the two are replaced by their union,
a 6-corner CCW L polygon. Only some houses get one: always when the prompt or style says open plan
(``words``), else with the seeded chance ``FloorplanOptions.open_plan_probability``.
It runs on one-storey houses (:func:`anyhome.floorplan.levels.solve_levels` calls it
after the solver); the storeys of a house of several keep their rectangles, since the
stacking matches rooms across storeys by their planned ids.

Design (issue 13): the plan (``HouseSpec``) is left as it is, both rooms and their
furniture groups stay planned rooms; the floorplan records the merge instead. The
merged room keeps the first room of the pair (its id, type, materials; the name joins
both names, "Living Room and Dining Room") and lists the other in
:attr:`anyhome.house.Room.merged`; the layout stage furnishes such a room with the
groups and ornaments of every planned room it holds (:func:`anyhome.layout.solver.
layout_house`), each planned room's groups preferring their own arm of the L
(:mod:`anyhome.layout.zones`), so nothing planned is lost and ``relayout`` of the room
lays out both.

Doors and windows stay where the solver put them, which keeps them consistent: the
doors between the two rooms (on the wall that goes) are removed, every other door and
window of the absorbed room now names the merged room and still lies on its outline
(the union's outline is the two outlines less the shared wall), windows stay on
exterior walls. Connections follow the same renaming, less the pair's own.

A merge is refused where the union would not be an L (a wall shared over its whole
length makes a rectangle, an offset at both ends a Z), where the two rooms differ in
height, storey or ceiling shape, where either is open-air or already merged, and where
the L is more elongated than ``max_habitable_aspect_ratio``. The aspect of an L room
is its bounding box's long side over the widest disc that fits in it (at the elbow),
as the plan metrics measure every room (:func:`l_aspect`); it is stricter than the
aspect of either arm, and each arm, being one of the solver's rectangles, keeps its
own within the habitable limit too.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
import shapely
import yaml
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from anyhome.floorplan.options import FloorplanOptions
from anyhome.house import Floorplan, Room
from anyhome.plan.spec import HouseSpec

OPEN_PLAN_FILE = Path(__file__).with_name("open_plan.yaml")
L_CORNERS = 6
"""Corners of an L polygon."""
INSCRIBED_TOL_M = 0.001
"""Tolerance of the widest-disc search of :func:`l_aspect`."""


@dataclass(frozen=True)
class OpenPlan:
    """The data of ``open_plan.yaml``."""

    words: tuple[str, ...]
    pairs: tuple[tuple[str, str], ...]
    open_stair: frozenset[str] = frozenset()
    """Room types an open stair may rise in (a stairwell opening onto one of them only
    merges into it: :func:`anyhome.floorplan.levels.stairs_opened`)."""
    basement_stair: frozenset[str] = frozenset()
    """Room types of a basement (the lowest storey, below the ground) that its stair may
    rise from in the open: nobody passes through them to a storey further down."""
    stair_hall: frozenset[str] = frozenset()
    """Circulation room types a stair may stand in as the storey's stair hall (an entry, a
    hallway, a landing): it opens onto one of them only, it merges into it, and a storey
    searched with it carved from that room plans the room no larger than the stair and a
    passage beside it need (it doubles as the hall), not as large as both."""


@lru_cache(maxsize=1)
def open_plan_data(path: Path = OPEN_PLAN_FILE) -> OpenPlan:
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    return OpenPlan(tuple(str(w).lower() for w in data["words"]),
                    tuple((str(a), str(b)) for a, b in data["pairs"]),
                    frozenset(str(t) for t in data.get("open_stair", ())),
                    frozenset(str(t) for t in data.get("basement_stair", ())),
                    frozenset(str(t) for t in data.get("stair_hall", ())))


def asks_open_plan(spec: HouseSpec, data: OpenPlan | None = None) -> bool:
    """True when the prompt or the house style names open-plan living (``words``)."""
    text = f"{spec.prompt} {spec.style}".lower()
    return any(re.search(r"(?<![\w-])" + re.escape(w) + r"(?![\w-])", text) for w in (data or open_plan_data()).words)


def merge_open_plan(floorplan: Floorplan, spec: HouseSpec, rng: np.random.Generator,
                    options: FloorplanOptions | None = None) -> Floorplan:
    """``floorplan`` with at most ``options.open_plan_max_rooms`` open-plan pairs merged
    into L rooms (see the module doc); ``rng`` draws whether this house gets any (one
    draw, made only when some pair could merge)."""
    opts = options or FloorplanOptions()
    if opts.open_plan_max_rooms == 0:
        return floorplan
    data = open_plan_data()
    if not l_candidates(floorplan, data, opts):
        return floorplan
    chance = opts.open_plan_words_probability if asks_open_plan(spec, data) else opts.open_plan_probability
    if rng.random() >= chance:
        return floorplan
    for _ in range(opts.open_plan_max_rooms):
        pairs = l_candidates(floorplan, data, opts)
        if not pairs:
            break
        floorplan = merge_rooms(floorplan, *pairs[0])
    return floorplan


def l_candidates(floorplan: Floorplan, data: OpenPlan, opts: FloorplanOptions) -> list[tuple[str, str]]:
    """(kept, absorbed) room id pairs that would merge into an L, best first: in the
    order of ``data.pairs``, then the larger union first."""
    rooms = {r.id: r for r in floorplan.rooms}
    rank = {pair: i for i, pair in enumerate(data.pairs)}
    found: list[tuple[int, float, str, str]] = []
    for a, b in {tuple(d.rooms) for d in floorplan.doors}:
        if a not in rooms or b not in rooms:
            continue
        ra, rb = rooms[a], rooms[b]
        if (rb.type, ra.type) in rank and (ra.type, rb.type) not in rank:
            ra, rb = rb, ra
        key = (ra.type, rb.type)
        if key not in rank or not _compatible(ra, rb):
            continue
        union = l_polygon(ra.polygon, rb.polygon)
        if union is None or l_aspect_over(union, opts.max_habitable_aspect_ratio + 1e-9):
            continue
        found.append((rank[key], -Polygon(union).area, ra.id, rb.id))
    return [(a, b) for _, _, a, b in sorted(found)]


def _compatible(a: Room, b: Room) -> bool:
    return (not a.open_air and not b.open_air and a.level == b.level and abs(a.height - b.height) < 1e-6
            and a.ceiling == b.ceiling == "flat" and not a.merged and not b.merged)


def l_polygon(a: list[tuple[float, float]], b: list[tuple[float, float]]) -> list[tuple[float, float]] | None:
    """The CCW 6-corner outline of the union of two touching room outlines, or None when
    the union is no L (not one piece, a rectangle, a Z, a T...)."""
    return union_outline(a, b, (L_CORNERS,))


def union_outline(a: list[tuple[float, float]], b: list[tuple[float, float]],
                  corners: tuple[int, ...] = (4, L_CORNERS)) -> list[tuple[float, float]] | None:
    """The CCW outline of the union of two touching room outlines, starting at its lowest
    corner, when it is one piece with a number of corners in ``corners`` (4: a
    rectangle, 6: an L); else None."""
    union = Polygon(a).union(Polygon(b))
    if not isinstance(union, Polygon) or union.interiors:
        return None
    union = orient(union.simplify(0.0), 1.0)
    points = [(round(x, 4), round(y, 4)) for x, y in union.exterior.coords[:-1]]
    points = [p for i, p in enumerate(points) if not _collinear(points[i - 1], p, points[(i + 1) % len(points)])]
    if len(points) not in corners:
        return None
    start = points.index(min(points))
    return points[start:] + points[:start]


def _collinear(p, q, r) -> bool:
    return abs((q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0])) < 1e-9


def l_aspect(points: list[tuple[float, float]]) -> float:
    """Aspect of an L room: its bounding box's long side over the widest disc that fits
    in it (the plan metrics' aspect, :mod:`anyhome.evaluate.plan_metrics`; for a
    rectangle, long over short side)."""
    return _l_aspect(tuple((float(x), float(y)) for x, y in points))


@lru_cache(maxsize=4096)
def _l_aspect(points: tuple[tuple[float, float], ...]) -> float:
    """:func:`l_aspect`, once per outline: a storey's outlines are measured again when
    its stairwells are opened a second time (``levels._stacked``), half of the calls."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    long_m = max(max(xs) - min(xs), max(ys) - min(ys))
    width_m = 2.0 * float(shapely.maximum_inscribed_circle(Polygon(points), INSCRIBED_TOL_M).length)
    return long_m / max(width_m, 1e-9)


def l_aspect_over(points: list[tuple[float, float]], limit: float) -> bool:
    """Whether ``l_aspect(points) > limit``, answered without the widest-disc search where
    the bounding box's own aspect is over ``limit``: no disc in the outline is wider than
    the box's short side (a ray from its centre leaves the outline within the box), so
    the box's aspect is a lower bound of :func:`l_aspect`'s (the short side taken a
    billionth wider, for the disc's rounding)."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    w_m, h_m = max(xs) - min(xs), max(ys) - min(ys)
    if min(w_m, h_m) > 0 and max(w_m, h_m) / (min(w_m, h_m) * (1 + 1e-9)) > limit:
        return True
    return l_aspect(points) > limit


def merge_rooms(floorplan: Floorplan, keep: str, absorb: str, name: str | None = None,
                outline: list[tuple[float, float]] | None = None) -> Floorplan:
    """``floorplan`` with room ``absorb`` merged into room ``keep`` (they must make an L,
    :func:`l_polygon`, unless ``outline``, their union, is given): one room, named
    ``name`` (default: both names joined), the doors between them gone, the rest renamed."""
    rooms = {r.id: r for r in floorplan.rooms}
    a, b = rooms[keep], rooms[absorb]
    outline = outline or l_polygon(a.polygon, b.polygon)
    if outline is None:
        raise ValueError(f"rooms {keep!r} and {absorb!r} do not make an L")
    merged = a.model_copy(update={"polygon": outline, "name": name or f"{a.name} and {b.name}",
                                  "merged": [*a.merged, b.id, *b.merged]})
    new_rooms = [merged if r.id == keep else r for r in floorplan.rooms if r.id != absorb]

    def rename(room_id: str) -> str:
        return keep if room_id == absorb else room_id

    doors = [d.model_copy(update={"rooms": (rename(d.rooms[0]), rename(d.rooms[1]))})
             for d in floorplan.doors if set(d.rooms) != {keep, absorb}]
    windows = [w.model_copy(update={"room": rename(w.room)}) for w in floorplan.windows]
    connections: list[tuple[str, str]] = []
    for x, y in floorplan.connections:
        link = (rename(x), rename(y))
        if link[0] != link[1] and link not in connections and link[::-1] not in connections:
            connections.append(link)
    return floorplan.model_copy(update={"rooms": new_rooms, "doors": doors, "windows": windows,
                                        "connections": connections})
