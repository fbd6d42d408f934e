"""Floorplans of several storeys: one solve per storey, stairwells stacked, stairs objects.

A plan whose rooms all sit on level 0 goes straight to :func:`solve_floorplan` (the same
floorplan, byte for byte). Otherwise every storey is solved as a house of its own (an
upper storey or a basement gets a stand-in entrance through its stairwell, dropped
afterwards), until its stairwell comes out as a rectangle at least
:data:`STAIRWELL_MIN_LONG_M` x :data:`STAIRWELL_MIN_SHORT_M`. Each storey is then turned
(a quarter turn when needed) so its stairwell's long side runs east-west, and placed on
(a basement: under) the storey next to it toward the ground with a corner of its
stairwell on the same corner of that one's: the stairwells overlap in a rectangle that
holds a straight flight clear of their doors. The flight is a
``stairs`` object in the lower storey's stairwell (:func:`stairs_objects`).

The narrow interface (:func:`solve_levels`, :func:`stairs_objects`) is what the pipeline
sees; a solver that takes a footprint and a fixed stairwell rectangle can replace the
per-storey solve without changing it. Storeys are not solved inside the floor below: of a
few layouts of each, mirrored and with its stairwell on any corner of the one below, the
one hanging least over nothing is kept (:func:`overhang_m2`; an upper storey may still
overhang).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from anyhome.errors import FloorplanError
from anyhome.floorplan.merge import merge_open_plan
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.solver import solve_floorplan
from anyhome.geometry import opening_zone
from anyhome.house import Door, Floorplan, HouseObject, Level, Room, Window
from anyhome.plan.spec import HouseSpec

STAIRWELL_MIN_LONG_M = 3.5
"""Shortest long side of a stairwell: a 3.3 m flight (a 2.9 m storey in 15 risers of
0.193 m and 14 goings of 0.236 m: within UK Approved Document K for a private stair,
rise <= 220 mm, going >= 220 mm, pitch <= 42 deg)."""
STAIRWELL_MIN_SHORT_M = 1.95
"""Shortest short side of a stairwell: a 0.9 m flight (Document K's usual minimum width)
beside a landing strip."""
FLIGHT_WIDTH_M = 0.9
FLIGHT_MIN_LENGTH_M = 3.3
SLAB_M = 0.2
"""Floor structure between a storey's ceiling and the next storey's floor."""
STAIRS_CATEGORY = "stairs"


def stair_room(spec: HouseSpec, level: int) -> str:
    """The id of the stairwell of ``level``: its room named or id'd like a stair."""
    for r in spec.rooms:
        if r.level == level and ("stair" in r.id.lower() or "stair" in r.name.lower()):
            return r.id
    raise FloorplanError(f"level {level} has no stairwell room (a room named 'stairwell')")


def solve_levels(spec: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None = None) -> Floorplan:
    """Lay out every storey of ``spec`` (see the module doc); one storey: solve_floorplan."""
    numbers = sorted({r.level for r in spec.rooms})
    if numbers == [0]:
        return merge_open_plan(solve_floorplan(spec, rng, options), spec, rng, options)
    if 0 not in numbers:
        raise FloorplanError("a house of several storeys needs rooms on the ground floor (level 0)")
    attempts = (options or FloorplanOptions()).level_attempts
    why = ""
    for _ in range(attempts):
        try:
            plan = _stacked(spec, numbers, rng, options)
            stairs_objects(plan)  # a flight fits where both stairwells meet, clear of their doors
            return plan
        except FloorplanError as e:
            why = str(e)
    return _one_storey(spec, rng, options, why)


def _stacked(spec: HouseSpec, numbers: list[int], rng: np.random.Generator, options: FloorplanOptions | None) -> Floorplan:
    opts = options or FloorplanOptions()
    plans: dict[int, Floorplan] = {0: _solve_storey(spec, 0, rng, options)}
    outward = [n for n in numbers if n > 0] + sorted((n for n in numbers if n < 0), reverse=True)
    for k in outward:  # each storey on (or under) the one next to it toward the ground
        ref = k - 1 if k > 0 else k + 1
        best: tuple[float, Floorplan] | None = None
        why = ""
        for _ in range(opts.storey_candidates):  # a few layouts of the storey; the one that sits best
            try:
                hang, placed = _best_placed(spec, plans, _solve_storey(spec, k, rng, options), k, ref)
            except FloorplanError as e:
                why = str(e)
                continue
            if best is None or hang < best[0] - 1e-6:
                best = (hang, placed)
            if hang <= opts.overhang_ok_m2:
                break
        if best is None:
            raise FloorplanError(why)
        plans[k] = best[1]
    heights = {k: max(r.height_m for r in spec.rooms if r.level == k) + SLAB_M for k in numbers}
    elevation = {0: 0.0}
    for k in (n for n in numbers if n > 0):
        elevation[k] = elevation[k - 1] + heights[k - 1]
    for k in sorted((n for n in numbers if n < 0), reverse=True):
        elevation[k] = elevation[k + 1] - heights[k]
    return _joined(spec, plans, [Level(level=k, elevation_m=round(elevation[k], 4), height_m=round(heights[k], 4)) for k in numbers])


MIRRORS = ((False, False), (True, False), (False, True), (True, True))
"""The four mirror images of a storey: as laid out, flipped east-west, north-south, both."""


def _mirrored(plan: Floorplan, stair: str, flip_x: bool, flip_y: bool) -> Floorplan:
    """``plan`` mirrored about its stairwell's centre lines, so the stairwell stays put
    (outlines are reversed to stay counter-clockwise)."""
    if not (flip_x or flip_y):
        return plan
    x0, y0, w, h = _rect(plan.room(stair))
    cx, cy = x0 + w / 2, y0 + h / 2
    out = _map(plan, lambda p: (round(2 * cx - p[0], 6) if flip_x else p[0], round(2 * cy - p[1], 6) if flip_y else p[1]))
    if flip_x != flip_y:  # one reflection turns outlines clockwise
        out = out.model_copy(update={"rooms": [r.model_copy(update={"polygon": list(reversed(r.polygon))}) for r in out.rooms]})
    return out


def _best_placed(spec: HouseSpec, plans: dict[int, Floorplan], plan: Floorplan, k: int,
                 ref: int) -> tuple[float, Floorplan]:
    """Storey ``k`` (``plan``) placed on (a basement: under) storey ``ref``: of its four mirror
    images (:data:`MIRRORS`), each with a corner of its stairwell on the same corner of
    the stairwell of ``ref``, the one whose floor lies most over (under) ``ref``'s, among
    those where a flight fits in both stairwells clear of their doors; with the area of
    its floor outside ``ref``'s (m2)."""
    stair, ref_stair = stair_room(spec, k), stair_room(spec, ref)
    rx, ry, rw, rh = _rect(plans[ref].room(ref_stair))
    best: tuple[float, Floorplan] | None = None
    for fx, fy in MIRRORS:
        mirrored = _mirrored(plan, stair, fx, fy)
        x0, y0, w, h = _rect(mirrored.room(stair))
        for cx, cy in ((0, 0), (1, 0), (0, 1), (1, 1)):  # south-west, south-east, north-west, north-east
            cand = _moved(mirrored, rx + cx * rw - (x0 + cx * w), ry + cy * rh - (y0 + cy * h))
            lo, hi = (plans[ref], cand) if k > ref else (cand, plans[ref])
            pair = Floorplan.model_construct(rooms=[*lo.rooms, *hi.rooms], doors=[*lo.doors, *hi.doors], windows=[],
                                             connections=[], levels=[], warnings=[])
            if _flight_box(pair, *((ref_stair, stair) if k > ref else (stair, ref_stair))) is None:
                continue
            hang = _outside_m2([r.polygon for r in cand.rooms], [r.polygon for r in plans[ref].rooms])
            if best is None or hang < best[0] - 1e-6:
                best = (hang, cand)
    if best is None:
        raise FloorplanError(f"no room for a flight of stairs between {ref_stair!r} and {stair!r}")
    return best


def _outside_m2(outlines: Iterable, below: Iterable) -> float:
    """Area of the union of ``outlines`` that lies outside the union of ``below``."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    floor = unary_union([Polygon(p).buffer(0) for p in outlines])
    return float(floor.difference(unary_union([Polygon(p).buffer(0) for p in below]).buffer(1e-6)).area)


def overhang_m2(rooms: Iterable) -> float:
    """Area of the rooms of each storey above the ground floor that lies over no room of
    the storey below (floor hanging in the air). ``rooms``: objects with ``polygon`` and
    ``level`` (a missing level is 0)."""
    by_level: dict[int, list] = {}
    for r in rooms:
        by_level.setdefault(getattr(r, "level", 0) or 0, []).append(r.polygon)
    return sum((_outside_m2(by_level[k], by_level.get(k - 1, [])) for k in by_level if k > 0), 0.0)


def _storey_spec(spec: HouseSpec, k: int) -> HouseSpec:
    """Storey ``k`` of ``spec`` as a house of its own: an upper storey or a basement gets a
    stand-in entrance through its stairwell (the stairs come in there; dropped after)."""
    ids = {r.id for r in spec.rooms if r.level == k}
    links = [c for c in spec.connections if c[0] in ids and (c[1] in ids or (k == 0 and c[1] == "outside"))]
    if k != 0:
        links.append((stair_room(spec, k), "outside"))
    return spec.model_copy(update={"rooms": [r for r in spec.rooms if r.level == k], "connections": links})


ONE_STOREY_NOTE = "could not stack the storeys"
"""Start of the floorplan's note when a house of several storeys was laid out on one."""


def _one_storey(spec: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None, why: str) -> Floorplan:
    """Every room on the ground floor, each stairwell joined to the one above it by a
    door: a valid house where the storeys would not stack (the pipeline warns)."""
    rooms = [r.model_copy(update={"level": 0}) for r in spec.rooms]
    numbers = sorted({r.level for r in spec.rooms})
    links = list(spec.connections)
    links += [(stair_room(spec, a), stair_room(spec, b)) for a, b in zip(numbers, numbers[1:])]
    flat = spec.model_copy(update={"rooms": rooms, "connections": links})
    plan = solve_floorplan(flat, rng, options)
    return plan.model_copy(update={"warnings": [*plan.warnings, f"{ONE_STOREY_NOTE} ({why}); every room is on the ground floor"]})


def _solve_storey(spec: HouseSpec, k: int, rng: np.random.Generator, options: FloorplanOptions | None) -> Floorplan:
    stair = stair_room(spec, k)
    sub = _storey_spec(spec, k)
    why = "its stairwell never came out as a rectangle large enough for a flight"
    attempts = (options or FloorplanOptions()).level_attempts
    for _ in range(attempts):
        try:
            plan = solve_floorplan(sub, rng, options)
        except FloorplanError as e:
            why = str(e)
            continue
        if k != 0:
            plan = plan.model_copy(update={"doors": [d for d in plan.doors if "outside" not in d.rooms]})
        x0, y0, w, h = _rect(plan.room(stair))
        if w < h:
            plan = _turned(plan)
            x0, y0, w, h = _rect(plan.room(stair))
        top = k == max(r.level for r in spec.rooms)
        if w >= STAIRWELL_MIN_LONG_M - 1e-6 and h >= STAIRWELL_MIN_SHORT_M - 1e-6 and (top or _flight_box(plan, stair)):
            return plan
    raise FloorplanError(f"could not lay out level {k} in {attempts} attempts ({why})")


def _rect(room: Room) -> tuple[float, float, float, float]:
    """(x0, y0, width, height) of a room that is a rectangle; zeros if it is not."""
    xs = [p[0] for p in room.polygon]
    ys = [p[1] for p in room.polygon]
    if len(room.polygon) != 4:
        return (min(xs), min(ys), 0.0, 0.0)
    return (min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys))


def _map(plan: Floorplan, f) -> Floorplan:
    rooms = [r.model_copy(update={"polygon": [f(p) for p in r.polygon]}) for r in plan.rooms]
    doors = [d.model_copy(update={"segment": (f(d.segment[0]), f(d.segment[1]))}) for d in plan.doors]
    windows = [w.model_copy(update={"segment": (f(w.segment[0]), f(w.segment[1]))}) for w in plan.windows]
    return plan.model_copy(update={"rooms": rooms, "doors": doors, "windows": windows})


def _turned(plan: Floorplan) -> Floorplan:
    """A quarter turn counter-clockwise (outlines stay counter-clockwise)."""
    return _map(plan, lambda p: (-p[1], p[0]))


def _moved(plan: Floorplan, dx: float, dy: float) -> Floorplan:
    return _map(plan, lambda p: (p[0] + dx, p[1] + dy))


def _flight_box(plan: Floorplan, stair: str, upper: str | None = None) -> tuple[float, float, float, float, float] | None:
    """(x0, y0, x1, y1, yaw) of a flight along a long wall of the stairwell, its top end
    against a short wall, touching no door of either stairwell (None: every place does).
    The flight stays inside the rectangle where both stairwells overlap, so its top
    lands in the upper one."""
    from shapely.geometry import LineString, box

    x0, y0, w, h = _rect(plan.room(stair))
    if upper is not None:  # where the two stairwells overlap
        ux0, uy0, uw, uh = _rect(plan.room(upper))
        if uw <= 0:
            return None
        ax, ay = max(x0, ux0), max(y0, uy0)
        w, h = min(x0 + w, ux0 + uw) - ax, min(y0 + h, uy0 + uh) - ay
        x0, y0 = ax, ay
        if w < FLIGHT_MIN_LENGTH_M - 1e-6 or h < FLIGHT_WIDTH_M - 1e-6:
            return None
    doors = [opening_zone(d.segment).union(LineString(d.segment)) for d in plan.doors
             if stair in d.rooms or (upper is not None and upper in d.rooms)]  # its swing, on both sides
    for ya, yb in ((y0, y0 + FLIGHT_WIDTH_M), (y0 + h - FLIGHT_WIDTH_M, y0 + h)):
        for xa, yaw in ((x0, 0.0), (x0 + w - FLIGHT_MIN_LENGTH_M, math.pi)):
            run = box(xa, ya, xa + FLIGHT_MIN_LENGTH_M, yb).buffer(0.05)
            if not any(run.intersects(d) for d in doors):
                return (xa, ya, xa + FLIGHT_MIN_LENGTH_M, yb, yaw)
    return None


def _joined(spec: HouseSpec, plans: dict[int, Floorplan], levels: list[Level]) -> Floorplan:
    by_id = {r.id: r for p in plans.values() for r in p.rooms}
    rooms = [by_id[r.id].model_copy(update={"level": r.level}) for r in spec.rooms]
    doors: list[Door] = []
    windows: list[Window] = []
    for k in sorted(plans):
        doors += [d.model_copy(update={"id": f"door-{len(doors) + i}"}) for i, d in enumerate(plans[k].doors)]
        windows += [w.model_copy(update={"id": f"win-{len(windows) + i}"}) for i, w in enumerate(plans[k].windows)]
    return Floorplan(rooms=rooms, doors=doors, windows=windows, connections=list(spec.connections), levels=levels)


def stairs_objects(plan: Floorplan) -> list[HouseObject]:
    """One straight flight per pair of storeys, in the lower stairwell, rising to the
    upper storey's floor (its height is the difference of the two elevations). Its
    ``position`` is, as for every object, relative to its room's floor."""
    if not plan.levels:
        return []
    out = []
    numbers = [lv.level for lv in plan.levels]
    elev = {lv.level: lv.elevation_m for lv in plan.levels}
    for lo, hi in zip(numbers, numbers[1:]):
        low = _stairwell(plan, lo)
        up = _stairwell(plan, hi)
        fb = _flight_box(plan, low.id, up.id)
        if fb is None:
            raise FloorplanError(f"no room for a flight of stairs in {low.id!r}")
        xa, ya, xb, yb, yaw = fb
        rise = elev[hi] - elev[lo]
        out.append(HouseObject(
            id=f"{low.id}-stairs", room=low.id, name="stairs", category=STAIRS_CATEGORY,
            description=f"a straight flight from level {lo} up to level {hi}",
            position=(round((xa + xb) / 2, 4), round((ya + yb) / 2, 4), 0.0),
            size=(FLIGHT_MIN_LENGTH_M, FLIGHT_WIDTH_M, round(rise, 4)),
            yaw=yaw, rule="place_wall", tags=["equipment"],
        ))
    return out


def _stairwell(plan: Floorplan, level: int) -> Room:
    for r in plan.rooms:
        if r.level == level and ("stair" in r.id.lower() or "stair" in r.name.lower()):
            return r
    raise FloorplanError(f"level {level} has no stairwell room")


def stair_link(plan: Floorplan, obj: HouseObject) -> tuple[str, str] | None:
    """The two rooms a ``stairs`` object joins: its own and the room of the next storey
    up over its top end (None: not stairs, or nothing above)."""
    if obj.category != STAIRS_CATEGORY:
        return None
    from shapely.geometry import Point, Polygon

    here = next((r for r in plan.rooms if r.id == obj.room), None)
    if here is None:
        return None
    above = sorted(lv.level for lv in plan.levels if lv.level > here.level)
    if not above:
        return None
    x, y, _ = obj.position
    c, s = math.cos(obj.yaw), math.sin(obj.yaw)
    half = obj.size[0] / 2 - 0.1
    top = Point(x - c * half, y - s * half)  # the flight rises toward its local -x
    for r in plan.rooms:
        if r.level == above[0] and Polygon(r.polygon).buffer(1e-6).contains(top):
            return (here.id, r.id)
    return None


def level_view(house, level: int):
    """The storey ``level`` of ``house`` as a house of its own: its rooms, the doors and
    windows of those rooms, their objects (the checks of one storey run on it)."""
    ids = {r.id for r in house.rooms if r.level == level}
    return house.model_copy(update={
        "rooms": [r for r in house.rooms if r.id in ids],
        "doors": [d for d in house.doors if all(x in ids or x == "outside" for x in d.rooms)],
        "windows": [w for w in house.windows if w.room in ids],
        "objects": [o for o in house.objects if o.room in ids],
        "connections": [c for c in house.connections if all(x in ids or x == "outside" for x in c)],
    })


def reachable_rooms(house) -> set[str]:
    """Rooms reachable from the outside through doors and stairs (:func:`stair_link`)."""
    adj: dict[str, set[str]] = {}
    links = [tuple(d.rooms) for d in house.doors]
    links += [lk for o in house.objects if (lk := stair_link(house.floorplan, o)) is not None]
    for a, b in links:
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    seen = {"outside"}
    todo = ["outside"]
    while todo:
        for nxt in adj.get(todo.pop(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen - {"outside"}
