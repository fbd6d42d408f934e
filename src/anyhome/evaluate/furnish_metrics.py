"""Furnishing metrics (issue 14): how a room's furniture compares with a designer's.

Figures, not violations: :func:`furnish_metrics` reads only what house.json holds (rooms,
objects with their tags, groups and asset records, ``dropped``, and the plan it was made
from) and never raises on a house that loads.

Definitions
-----------
planned items
    Every object copy the plan asked for: the placed objects (stairs left out) plus the
    ``dropped`` entries. **drop rate**: dropped over planned.
key items
    The anchor of every group the text asked for (``required``) or that makes the room
    what it is (priority ``KEY_PRIORITY`` or lower, as :attr:`anyhome.plan.spec.GroupSpec.key`:
    the bed, the sofa, the kitchen run). A dropped entry is a key
    item dropped when its room holds a key item of that name.
floor layers
    Objects tagged ``floor_layer`` (rugs, mats, runners). **rugs kept**: placed floor
    layers over the planned ones (the plan's items tagged ``floor_layer``).
TV stands
    Floor objects of category ``tv_stand``. **Against a wall**: the middle of the back
    edge of its footprint lies within :data:`WALL_GAP_M` of its room's outline. **Facing
    the seating**: the room's largest seat (tag ``seat``, a sofa first) lies within
    :data:`FACING_DEG` of the stand's front, and the stand within that of the seat's.
    **View blocked**: an object taller than :data:`VIEW_HEIGHT_M` (other than the two)
    stands in the strip between them, as wide as the narrower of the two.
sets
    Objects of one name in one group of one room, copies of a repeated group counted
    together (group ``dining-0`` and ``dining-1`` are the group ``dining``), two or more.
    A set is **mismatched** when their asset records differ in anything but size (family,
    colours, shape parameters). Sets whose words ask for variety
    (:func:`anyhome.assets.sets.set_key`: "mismatched chairs") are left out.
relations
    Every relation the plan's groups state (near, far, in front, beside, symmetric pair,
    around, facing, aligned, run), checked on the placed geometry by
    :func:`anyhome.evaluate.relations.house_relations`: met and checked, by kind.
kitchens
    :mod:`anyhome.evaluate.kitchen_metrics`: kitchens whose sink, cooktop and fridge
    stand in counter runs (**work run**), kitchens with wall cabinets over the counters.
floor coverage
    For a habitable room: the area of the union of its floor objects' footprints (floor
    layers and stairs left out) over the room's area.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon

from anyhome import geometry
from anyhome.assets.sets import set_key
from anyhome.evaluate.kitchen_metrics import kitchen_figures
from anyhome.evaluate.polygons import is_usable, room_polygon
from anyhome.evaluate.relations import house_relations, met_by_kind, planned_rooms
from anyhome.house import House, HouseObject, is_habitable
from anyhome.tags import is_floor_layer

WALL_GAP_M = 0.15
"""A TV stand whose back is at most this far from a wall stands against it."""
FACING_DEG = 35.0
"""Largest angle between an object's front and the direction to what it faces."""
VIEW_HEIGHT_M = 0.6
"""Objects taller than this between a seat and its TV block the view (a coffee table does not)."""
LOW_COVERAGE = 0.15
"""A habitable room whose furniture covers less of its floor than this is empty."""
SEAT_CATEGORIES = ("sofa", "sectional", "couch", "loveseat", "bench", "armchair")
"""Seats a TV is watched from, the first found in a room chosen."""


@dataclass
class FurnishMetrics:
    """The furnishing figures of one house (see the module docstring)."""

    n_planned: int = 0
    n_dropped: int = 0
    n_key: int = 0
    key_dropped: list[str] = field(default_factory=list)
    n_layers_planned: int = 0
    n_layers_placed: int = 0
    n_tv_stands: int = 0
    n_tv_against_wall: int = 0
    n_tv_with_seat: int = 0
    n_tv_facing_seat: int = 0
    n_tv_view_blocked: int = 0
    n_sets: int = 0
    mismatched_sets: list[str] = field(default_factory=list)
    coverage: dict[str, float] = field(default_factory=dict)
    """Habitable room id -> floor coverage."""
    relations: dict[str, list[int]] = field(default_factory=dict)
    """Relation kind -> [met, checked] over the relations the plan's groups state
    (:mod:`anyhome.evaluate.relations`)."""
    n_kitchens: int = 0
    n_kitchen_work_run: int = 0
    n_kitchen_wall_cabinets: int = 0

    @property
    def drop_rate(self) -> float:
        return self.n_dropped / self.n_planned if self.n_planned else 0.0

    @property
    def n_low_coverage(self) -> int:
        return sum(c < LOW_COVERAGE for c in self.coverage.values())

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["drop_rate"] = self.drop_rate
        d["n_low_coverage"] = self.n_low_coverage
        return d

    def summary_lines(self) -> list[str]:
        cov = sorted(self.coverage.values())
        med = f"{100 * cov[len(cov) // 2]:.0f}%" if cov else "n/a"
        return [
            f"furnishing: {self.n_dropped}/{self.n_planned} items dropped ({100 * self.drop_rate:.1f}%), "
            f"key items dropped: {len(self.key_dropped)}/{self.n_key}"
            + (f" ({', '.join(self.key_dropped[:4])})" if self.key_dropped else ""),
            f"  rugs kept {self.n_layers_placed}/{self.n_layers_planned}; TV stands against a wall "
            f"{self.n_tv_against_wall}/{self.n_tv_stands}, facing the seating {self.n_tv_facing_seat}/"
            f"{self.n_tv_with_seat}, view blocked {self.n_tv_view_blocked}",
            f"  mismatched sets {len(self.mismatched_sets)}/{self.n_sets}; habitable rooms with floor "
            f"coverage < {100 * LOW_COVERAGE:.0f}%: {self.n_low_coverage}/{len(self.coverage)} (median {med})",
            f"  relations met {sum(v[0] for v in self.relations.values())}/"
            f"{sum(v[1] for v in self.relations.values())}"
            + (" (" + ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in self.relations.items()) + ")" if self.relations else ""),
            f"  kitchens with sink, cooktop and fridge in counter runs {self.n_kitchen_work_run}/{self.n_kitchens}, "
            f"with wall cabinets {self.n_kitchen_wall_cabinets}/{self.n_kitchens}",
        ]


def furnish_metrics(house: House) -> FurnishMetrics:
    m = FurnishMetrics()
    objects = [o for o in house.objects if o.category != "stairs"]
    placeable = [o for o in objects if _finite(o)]
    m.n_dropped = len(house.dropped)
    m.n_planned = len(objects) + m.n_dropped
    host = {h: r.id for r in house.rooms for h in r.merged}
    key, layers = _planned(house.plan or {}, host)
    m.n_key = sum(n for names in key.values() for n in names.values())
    for d in house.dropped:
        if d.name in key.get(d.room, {}):
            m.key_dropped.append(f"{d.room}:{d.name}")
    m.n_layers_planned = layers
    m.n_layers_placed = sum(1 for o in objects if is_floor_layer(o.tags) and o.support == "floor")
    polys = {r.id: room_polygon(r.polygon) for r in house.rooms
             if all(math.isfinite(v) for pt in r.polygon for v in pt)}
    polys = {k: p for k, p in polys.items() if is_usable(p)}
    by_room: dict[str, list[HouseObject]] = {}
    for o in placeable:
        by_room.setdefault(o.room, []).append(o)
    for o in placeable:
        if o.category == "tv_stand" and o.support == "floor":
            _tv_stand(m, o, polys.get(o.room), by_room.get(o.room, []))
    _sets(m, objects)
    k = kitchen_figures(polys, by_room)
    m.n_kitchens, m.n_kitchen_work_run, m.n_kitchen_wall_cabinets = k.n_kitchens, k.n_work_run, k.n_wall_cabinets
    for r in house.rooms:
        poly = polys.get(r.id)
        if poly is not None and is_habitable(r.type) and poly.area > 0:
            fps = [geometry.footprint_polygon(o.position, o.size, o.yaw) for o in by_room.get(r.id, [])
                   if o.support == "floor" and not is_floor_layer(o.tags)]
            m.coverage[r.id] = round(geometry.floor_coverage(fps, poly), 4)
    if len(placeable) == len(objects) and len(polys) == len(house.rooms):  # every pose measurable
        m.relations = {k: list(v) for k, v in met_by_kind(house_relations(house)).items()}
    return m


def _finite(o: HouseObject) -> bool:
    """An object whose pose and size can be measured (the validity rules report the others)."""
    vals = [*o.position, *o.size, o.yaw]
    return all(math.isfinite(v) for v in vals) and all(v > 0 for v in o.size)


def _planned(plan: Any, host: dict[str, str]) -> tuple[dict[str, dict[str, int]], int]:
    """(room id -> key item name -> copies, planned floor-layer copies) from a plan dict
    (what the models refuse in it left out: :func:`~anyhome.evaluate.relations.planned_rooms`)."""
    key: dict[str, dict[str, int]] = {}
    layers = 0
    for rid, (groups, ornaments) in planned_rooms(plan, host).items():
        for g in groups:
            for i, it in enumerate([g.anchor, *g.members]):
                n = g.repeat * it.count
                if is_floor_layer(it.tags):
                    layers += n
                if i == 0 and g.key:
                    names = key.setdefault(rid, {})
                    names[it.name] = names.get(it.name, 0) + n
        layers += sum(o.count for o in ornaments if is_floor_layer(o.tags))
    return key, layers



def _facing(a: HouseObject, b: HouseObject) -> bool:
    """Whether ``b`` lies within FACING_DEG of ``a``'s front."""
    v = np.asarray(b.position[:2]) - np.asarray(a.position[:2])
    n = float(np.linalg.norm(v))
    return n > 1e-6 and float(geometry.front_dir(a.yaw) @ v) / n >= math.cos(math.radians(FACING_DEG))


def _tv_stand(m: FurnishMetrics, o: HouseObject, poly: Polygon | None, others: list[HouseObject]) -> None:
    m.n_tv_stands += 1
    back = np.asarray(o.position[:2]) - geometry.front_dir(o.yaw) * o.size[1] / 2
    if poly is not None and poly.exterior.distance(shapely.Point(back)) <= WALL_GAP_M:
        m.n_tv_against_wall += 1
    seats = [s for s in others if s.support == "floor" and s.id != o.id
             and any(c in s.category for c in SEAT_CATEGORIES)]
    if not seats:
        return
    seat = max(seats, key=lambda s: (s.category != "armchair", s.size[0] * s.size[1]))
    m.n_tv_with_seat += 1
    if _facing(o, seat) and _facing(seat, o):
        m.n_tv_facing_seat += 1
    a, b = np.asarray(o.position[:2]), np.asarray(seat.position[:2])
    width = min(o.size[0], seat.size[0])
    strip = shapely.LineString([a, b]).buffer(width / 2, cap_style="flat")
    for x in others:
        if x.id in (o.id, seat.id) or x.support != "floor" or x.size[2] <= VIEW_HEIGHT_M:
            continue
        if geometry.footprint_polygon(x.position, x.size, x.yaw).intersection(strip).area > 0.01:
            m.n_tv_view_blocked += 1
            return


def _sets(m: FurnishMetrics, objects: list[HouseObject]) -> None:
    sets: dict[tuple[str, str, str], list[HouseObject]] = {}
    for o in objects:
        if (key := set_key(o)) is not None:
            sets.setdefault(key, []).append(o)
    for (room, group, name), objs in sorted(sets.items()):
        if len(objs) < 2:
            continue
        m.n_sets += 1
        looks = {_look(o.asset) for o in objs}
        if len(looks) > 1:
            m.mismatched_sets.append(f"{room}:{group}:{name}")


def _look(asset: dict[str, Any] | None) -> str:
    """An asset record without its size, as a comparable string."""
    if not asset:
        return ""
    params = {k: v for k, v in (asset.get("params") or {}).items() if k != "size"}
    return repr((asset.get("family"), asset.get("source"), asset.get("path"), sorted(params.items())))
