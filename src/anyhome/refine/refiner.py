"""Geometric refinement: settle what the placement rules left rough.

Every change is checked with the contract's own geometry (:mod:`anyhome.geometry`) and
kept only if the object it touches (and whatever stands on it) ends up valid, so a
valid layout stays valid; a room whose walkways a change would close gets its
original objects back.
"""

from __future__ import annotations

import logging
import math

import numpy as np
from shapely.geometry import Polygon

from anyhome.geometry import (
    TOLERANCE_M,
    back_edge,
    blocks_navigation,
    boxes_collide,
    footprint_corners,
    footprint_polygon,
    inside,
    navigability,
    opening_zone,
)
from anyhome.geometry import wrap_yaw as _wrap
from anyhome.house import Floorplan, HouseObject
from anyhome.plan.spec import WALL_RULES
from anyhome.space import (
    WALL_OPENING_MARGIN_M,
    Placed,
    RoomSpace,
    Wall,
    rect_corners,
    room_polygon,
    storey_doors,
)
from anyhome.tags import is_seat, is_table

log = logging.getLogger(__name__)

SNAP_DISTANCE_M = 0.15
"""Floor objects whose back is this close to a wall (and parallel to it) are pushed flush."""
FACE_TABLE_DISTANCE_M = 0.6
"""A seat this close to a table or desk is turned to face it."""
MOVE_RADII_M = (0.02, 0.05, 0.1, 0.15, 0.2, 0.3)
"""Distances tried when moving an object out of a penetration."""
YAW_SNAP_RAD = 0.2
"""Floor and on-top objects turned less than this off a right angle are squared up."""
FACE_TABLE_RULES = ("place_around", "place_center", "place_next")
"""Seats placed by these rules are turned to face the table they sit at; the others
(``place_front`` with its explicit facing, seats against walls, beside things) keep
the facing their rule gave them."""


def refine_objects(floorplan: Floorplan, objects: list[HouseObject], rng: np.random.Generator) -> list[HouseObject]:
    """Snap, turn and un-penetrate objects; drop what cannot be fixed.

    Parameters
    ----------
    floorplan : rooms, doors and windows the objects stand in
    objects : placed objects (not modified)
    rng : seeded generator (part of the stage signature; the geometric refiner is
        deterministic and draws nothing from it)

    Returns
    -------
    objects : the refined list, same order, possibly shorter (dropped objects and
        whatever stood on them are left out; an object whose group anchor was dropped
        stands on as an object of no group's, ``anchor`` None, so no id is left dangling)
    """
    ref = _Refiner(floorplan, objects, rng)
    ref.settle()
    ref.resolve()
    ref.guard_navigation()
    live = [o for o in ref.objs if o is not None]
    ids = {o.id for o in live}
    return [o if o.anchor is None or o.anchor in ids else o.model_copy(update={"anchor": None}) for o in live]


def _is_seat(o: HouseObject) -> bool:
    """A seat (tag ``seat``) that is not also a table."""
    return is_seat(o.tags)


def _is_table(o: HouseObject) -> bool:
    """A table or work surface (tags ``table``, ``work_surface``) that is not a seat."""
    return is_table(o.tags)


class _Refiner:
    def __init__(self, floorplan: Floorplan, objects: list[HouseObject], rng: np.random.Generator) -> None:
        self.fp = floorplan
        self.rng = rng
        self.original = list(objects)
        self.objs: list[HouseObject | None] = [o.model_copy() for o in objects]
        self.rooms = {r.id: room_polygon(r) for r in floorplan.rooms}
        self.heights = {r.id: r.height for r in floorplan.rooms}
        self.levels = {r.id: r.level for r in floorplan.rooms}
        self.zones = {lv: [opening_zone(d.segment) for d in storey_doors(floorplan, lv)]
                      for lv in set(self.levels.values())}
        """Storey -> the zones of its doors (a door of another storey is no obstacle)."""
        self.spaces = {r.id: RoomSpace(floorplan, r) for r in floorplan.rooms}
        self.changed_rooms: set[str] = set()

    # ------------------------------------------------------------ queries
    def _live(self) -> list[HouseObject]:
        return [o for o in self.objs if o is not None]

    def _index(self, oid: str) -> int | None:
        for i, o in enumerate(self.objs):
            if o is not None and o.id == oid:
                return i
        return None

    def _obj(self, k: int) -> HouseObject:
        """Object ``k``, one known to be live (not dropped)."""
        o = self.objs[k]
        assert o is not None, k
        return o

    def _children(self, oid: str) -> list[int]:
        out = []
        for i, o in enumerate(self.objs):
            if o is not None and o.support == oid:
                out.append(i)
                out += self._children(o.id)
        return out

    def problems(self, o: HouseObject, skip: set[str] | None = None) -> int:
        """Number of contract rules (1-4) ``o`` breaks against the current objects."""
        n = 0
        room = self.rooms.get(o.room)
        if room is None:
            return 1
        poly = footprint_polygon(o.position, o.size, o.yaw)
        if not inside(room, poly):
            n += 1
        if o.position[2] + o.size[2] > self.heights[o.room] + TOLERANCE_M:
            n += 1
        if o.support == "floor":
            if abs(o.position[2]) > TOLERANCE_M:
                n += 1
            for z in self.zones.get(self.levels[o.room], []):
                if poly.intersects(z) and poly.intersection(z).area > 1e-6:
                    n += 1
        elif o.support == "wall":
            if not self._on_wall(o):
                n += 1
        else:
            k = self._index(o.support)
            sup = self.objs[k] if k is not None else None
            if sup is None:
                return n + 10
            if abs(o.position[2] - (sup.position[2] + sup.size[2])) > TOLERANCE_M:
                n += 1
            if not inside(footprint_polygon(sup.position, sup.size, sup.yaw), poly):
                n += 1
        lo, hi = poly.bounds[:2], poly.bounds[2:]
        for other in self._live():
            if other.id == o.id or (skip and other.id in skip) or other.room != o.room:
                continue
            c = footprint_corners(other.position, other.size, other.yaw)
            if np.any(c.min(0) > hi) or np.any(c.max(0) < lo):
                continue
            if boxes_collide(o.position, o.size, o.yaw, other.position, other.size, other.yaw):
                n += 1
        return n

    def _on_wall(self, o: HouseObject) -> bool:
        space = self.spaces[o.room]
        be = back_edge(o.position, o.size, o.yaw)
        for w in space.walls:
            rel = be - w.a
            if np.all(np.abs(rel @ w.n) <= TOLERANCE_M / 2):
                t = rel @ w.u
                if t.min() < -TOLERANCE_M or t.max() > w.length + TOLERANCE_M:
                    continue
                return bool(space.wall_clear(w, np.array([t.min() + WALL_OPENING_MARGIN_M]),
                                             np.array([t.max() - WALL_OPENING_MARGIN_M]),
                                             o.position[2], o.position[2] + o.size[2])[0])
        return False

    # ------------------------------------------------------------ changes
    def _try(self, i: int, new: HouseObject) -> bool:
        """Replace object i by ``new`` (children follow); keep it only if nothing gets worse."""
        old = self.objs[i]
        if old is None:
            return False
        if (np.allclose(old.position, new.position, atol=1e-7) and abs(_wrap(old.yaw - new.yaw)) < 1e-7
                and np.allclose(old.size, new.size, atol=1e-9)):
            return False
        kids = self._children(old.id)
        before = self.problems(old) + sum(self.problems(self._obj(k)) for k in kids)
        saved = {k: self.objs[k] for k in kids}
        self.objs[i] = new
        for k in kids:
            self.objs[k] = _carry(self._obj(k), old, new)
        after = self.problems(new) + sum(self.problems(self._obj(k)) for k in kids)
        if after < before or (after == 0 and before == 0):
            self.changed_rooms.add(new.room)
            return True
        self.objs[i] = old
        for k, o in saved.items():
            self.objs[k] = o
        return False

    # ------------------------------------------------------------ settle
    def settle(self) -> None:
        """Snap wall objects and on-top objects, push wall furniture flush, turn seats."""
        for i in range(len(self.objs)):
            o = self.objs[i]
            if o is None:
                continue
            snapped = _snap_yaw(o.yaw)
            if o.support != "wall" and 1e-9 < abs(_wrap(snapped - o.yaw)) < YAW_SNAP_RAD:
                self._try(i, o.model_copy(update={"yaw": snapped}))
                o = self._obj(i)
            if o.support == "wall":
                new = self._snap_wall(o)
                if new is not None:
                    self._try(i, new)
            elif o.support == "floor":
                if o.rule in WALL_RULES:
                    new = self._snap_wall(o)
                    if new is not None:
                        self._try(i, new)
                if _is_seat(o) and o.rule in FACE_TABLE_RULES:
                    new = self._face_table(self._obj(i))
                    if new is not None:
                        self._try(i, new)
            else:
                new = self._settle_top(o)
                if new is not None:
                    self._try(i, new)

    def _nearest_wall(self, o: HouseObject) -> Wall | None:
        space = self.spaces.get(o.room)
        if space is None:
            return None
        be = back_edge(o.position, o.size, o.yaw)
        mid = be.mean(0)
        best, best_d = None, SNAP_DISTANCE_M
        for w in space.walls:
            if abs(abs(math.cos(o.yaw - w.yaw)) - 1.0) > 0.02 and o.support == "floor":
                continue
            rel = mid - w.a
            t = float(rel @ w.u)
            d = abs(float(rel @ w.n))
            if -0.01 <= t <= w.length + 0.01 and d < best_d:
                best, best_d = w, d
        return best

    def _snap_wall(self, o: HouseObject) -> HouseObject | None:
        """Back flush on the nearest wall, front facing the room (turned round if needed)."""
        w = self._nearest_wall(o)
        if w is None:
            o = o.model_copy(update={"yaw": _wrap(o.yaw + math.pi)})
            w = self._nearest_wall(o)
        if w is None:
            return None
        mid = back_edge(o.position, o.size, o.yaw).mean(0)
        t = float((mid - w.a) @ w.u)
        t = min(max(t, o.size[0] / 2), w.length - o.size[0] / 2)
        xy = w.a + w.u * t + w.n * (o.size[1] / 2)
        return o.model_copy(update={"position": (float(xy[0]), float(xy[1]), o.position[2]), "yaw": w.yaw})

    def _face_table(self, o: HouseObject) -> HouseObject | None:
        poly = footprint_polygon(o.position, o.size, o.yaw)
        best, best_d = None, FACE_TABLE_DISTANCE_M
        for t in self._live():
            if t.room != o.room or t.id == o.id or not _is_table(t) or t.support != "floor":
                continue
            d = poly.distance(footprint_polygon(t.position, t.size, t.yaw))
            if t.id == o.anchor and d < FACE_TABLE_DISTANCE_M:
                best, best_d = t, -1.0  # the table it was placed around wins
            elif d < best_d:
                best, best_d = t, d
        if best is None:
            return None
        # face the table side the seat is at: snap the direction to the table's axes
        rel = np.asarray(o.position[:2]) - np.asarray(best.position[:2])
        c, s = math.cos(best.yaw), math.sin(best.yaw)
        lx, ly = rel @ np.array([c, s]), rel @ np.array([-s, c])
        ex, ey = abs(lx) - best.size[0] / 2, abs(ly) - best.size[1] / 2
        if ey >= ex:  # on the table's front or back side
            yaw = best.yaw + (math.pi if ly > 0 else 0.0)
        else:
            yaw = best.yaw + (math.pi / 2 if lx > 0 else -math.pi / 2)
        yaw = _wrap(yaw)
        if abs(_wrap(yaw - o.yaw)) < 1e-6:
            return None
        return o.model_copy(update={"yaw": yaw})

    def _settle_top(self, o: HouseObject) -> HouseObject | None:
        k = self._index(o.support)
        if k is None:
            return None
        sup = self._obj(k)
        z = sup.position[2] + sup.size[2]
        # clamp into the supporter's top, in its frame
        c, s = math.cos(sup.yaw), math.sin(sup.yaw)
        ex, ey = np.array([c, s]), np.array([-s, c])
        rel = np.asarray(o.position[:2]) - np.asarray(sup.position[:2])
        corners = footprint_corners(o.position, o.size, o.yaw) - np.asarray(sup.position[:2])
        hx = np.abs(corners @ ex - rel @ ex).max()
        hy = np.abs(corners @ ey - rel @ ey).max()
        lim_x, lim_y = sup.size[0] / 2 - hx - 0.005, sup.size[1] / 2 - hy - 0.005
        if lim_x < 0 or lim_y < 0:
            return None
        lx = float(np.clip(rel @ ex, -lim_x, lim_x))
        ly = float(np.clip(rel @ ey, -lim_y, lim_y))
        xy = np.asarray(sup.position[:2]) + ex * lx + ey * ly
        return o.model_copy(update={"position": (float(xy[0]), float(xy[1]), z)})

    # ------------------------------------------------------------ resolve
    def resolve(self) -> None:
        """Move or drop objects that still break a rule, latest first."""
        for i in range(len(self.objs) - 1, -1, -1):
            o = self.objs[i]
            if o is None or self.problems(o) == 0:
                continue
            if self._move_out(i):
                continue
            log.info("refine drops %s: no valid spot nearby", o.id)
            for k in [i] + self._children(o.id):
                self.objs[k] = None
            self.changed_rooms.add(o.room)

    def _move_out(self, i: int) -> bool:
        o = self._obj(i)
        space = self.spaces.get(o.room)
        if space is None:
            return False
        base = np.asarray(o.position[:2])
        dirs = np.array([[math.cos(a), math.sin(a)] for a in np.arange(16) * math.pi / 8])
        if o.support == "wall":
            w = self._nearest_wall(o)
            if w is None:
                return False
            dirs = np.array([w.u, -w.u])
        offs = np.concatenate([np.zeros((1, 2))] + [dirs * r for r in MOVE_RADII_M])
        yaws = [o.yaw]
        snapped = _snap_yaw(o.yaw)
        if abs(_wrap(snapped - o.yaw)) > 1e-9:
            yaws.append(snapped)
        xy = np.concatenate([base[None] + offs for _ in yaws])
        yaw = np.concatenate([np.full(len(offs), y) for y in yaws])
        order = np.argsort(np.linalg.norm(xy - base[None], axis=1) + 0.01 * (yaw != o.yaw), kind="stable")
        xy, yaw = xy[order], yaw[order]
        kind = "floor" if o.support == "floor" else ("wall" if o.support == "wall" else "top")
        space.placed = []
        others = [x for x in self._live() if x.room == o.room and x.id != o.id and x.support != o.id]
        for x in others:
            c = rect_corners(np.asarray(x.position[:2])[None], x.size[:2], [x.yaw])[0]
            space.placed.append(Placed(x, c, x.position[2], x.position[2] + x.size[2], x.support == "floor"))
        corners = rect_corners(xy, o.size[:2], yaw)
        ok = space.valid(corners, np.full(len(xy), o.position[2]), np.full(len(xy), o.position[2] + o.size[2]),
                         floor=kind == "floor", doors=kind != "top")
        space.placed = []
        for j in np.nonzero(ok)[0]:
            new = o.model_copy(update={"position": (float(xy[j, 0]), float(xy[j, 1]), o.position[2]),
                                       "yaw": float(yaw[j])})
            if self._try(i, new) and self.problems(self._obj(i)) == 0:
                return True
        return False

    # ------------------------------------------------------------ navigation
    def _nav_ok(self, objs: list[HouseObject]) -> bool:
        rooms = [(r.id, r.polygon) for r in self.fp.rooms]
        doors = [(d.id, d.rooms, d.segment) for d in self.fp.doors]
        obst = [Polygon(footprint_corners(o.position, o.size, o.yaw)) for o in objs
                if blocks_navigation(o.category, o.size[2], o.support, o.tags)]
        return navigability(rooms, doors, obst).ok

    def guard_navigation(self) -> None:
        """Give rooms their original objects back if the changes closed a walkway."""
        if not self.changed_rooms or not self.fp.doors:
            return
        if not self._nav_ok(self.original) or self._nav_ok(self._live()):
            return
        orig = {o.id: o for o in self.original}
        for rid in sorted(self.changed_rooms):
            for i, o in enumerate(self.objs):
                if o is not None and o.room == rid:
                    self.objs[i] = orig.get(o.id, o)
            for i, o in enumerate(self.original):
                if o.room == rid and self.objs[i] is None:
                    self.objs[i] = o
            if self._nav_ok(self._live()):
                return


def _snap_yaw(yaw: float) -> float:
    return _wrap(round(yaw / (math.pi / 2)) * (math.pi / 2))


def _carry(child: HouseObject, old: HouseObject, new: HouseObject) -> HouseObject:
    """Move an object standing on ``old`` so it keeps its place on ``new``."""
    dyaw = new.yaw - old.yaw
    c, s = math.cos(dyaw), math.sin(dyaw)
    rel = np.asarray(child.position[:2]) - np.asarray(old.position[:2])
    rel = np.array([c * rel[0] - s * rel[1], s * rel[0] + c * rel[1]])
    xy = np.asarray(new.position[:2]) + rel
    dz = (new.position[2] + new.size[2]) - (old.position[2] + old.size[2])
    return child.model_copy(update={
        "position": (float(xy[0]), float(xy[1]), child.position[2] + dz),
        "yaw": _wrap(child.yaw + dyaw),
    })
