"""Walkways of one room while it is furnished: the house's navigation raster over the
room, kept up to date object by object (used by the layout stage).

A per-room version of :func:`anyhome.geometry.navigability` on the same 5 cm raster. The
room is rasterized together with its door strips and the keep-clear zones of its doors
in the neighbouring rooms (which rule 4 keeps free of floor objects). The room passes
when one walkable component (the *door component*) touches all its doors and some of
its own cells, and every floor object that must stay reachable has a cell within reach
(:data:`REACH_M`) that an agent of the evaluator's radius walks to from that component
(the walkways may be checked wider, :data:`WALKWAY_RADIUS_M`). The free space here is a subset of the
house-wide one, so what passes here passes the house-wide check.

Speed: a cell is walkable when no blocked cell lies within the agent radius of it. The
empty room's walkable cells come from one distance transform; each obstacle then takes
away its *shadow*, its cells dilated by the agent's disc on a window around it, which
is exactly what a distance transform of the furnished room would take away. When an
obstacle takes walkable cells away, the components are labelled on a small window round
them only (:data:`LABEL_MARGIN_CELLS`): when the walkable cells bordering the lost ones
are connected within it, every path that crossed the lost cells goes round them, so the
components are the same less the lost cells; else the whole raster is labelled again.
"""

from __future__ import annotations

import math
from bisect import bisect_left
from dataclasses import dataclass

import numpy as np
import shapely
from scipy import ndimage
from shapely.geometry import LineString

from anyhome.geometry import (
    AGENT_RADIUS_M,
    NAV_CELL_M,
    WALL_INSET_CELLS,
    footprint_polygon,
    opening_zone,
    raster_mask,
)
from anyhome.house import Floorplan
from anyhome.space import Placed, RoomSpace, room_polygon

NAV_OBSTACLE_PAD_M = 0.002
"""Obstacles block raster cells this far outside them too (robust to rounding)."""
WALKWAY_RADIUS_M = 0.3
"""Agent radius of the per-room walkway check (0.6 m walkways) when the empty room allows it."""
REACH_MARGIN_M = 0.01
"""An object counts as reachable here when a walkable cell lies this much closer to it
than the evaluator asks (robust to rounding and to the corners of its buffered outline)."""
REACH_M = AGENT_RADIUS_M + 2 * NAV_CELL_M - REACH_MARGIN_M
"""A floor object is reachable from a walkable cell whose centre lies this close to its
footprint (the evaluator's ``agent_radius_m + 2 cells``, less :data:`REACH_MARGIN_M`)."""

MADE_KEPT = 256
"""Obstacles a grid keeps to hand out again for the same footprint."""
LABEL_MARGIN_CELLS = 4
"""Cells round an obstacle's lost walkable cells within which they are labelled again
first (the module docstring)."""


_CROSS = ndimage.generate_binary_structure(2, 1)
"""4-connectivity, ndimage.label's default in 2D."""


@dataclass(frozen=True)
class Patch:
    """Raster cells ``mask`` in the window whose first cell is at row ``i0``, column ``j0``."""

    i0: int
    j0: int
    mask: np.ndarray

    @property
    def window(self) -> tuple[slice, slice]:
        h, w = self.mask.shape
        return slice(self.i0, self.i0 + h), slice(self.j0, self.j0 + w)


@dataclass(frozen=True, eq=False)
class NavState:
    """A copy of a :class:`NavGrid`'s walkways and their labels (:meth:`NavGrid.state`)."""

    walk: np.ndarray
    walk_a: np.ndarray | None
    obstacles: list[Obstacle]
    labels: np.ndarray | None
    door_labels: np.ndarray
    door_stale: bool
    door_by_near: bool
    labels_a: np.ndarray | None
    door_a: np.ndarray
    door_a_stale: bool
    known: set[Obstacle]


@dataclass(frozen=True, eq=False)
class Obstacle:
    """What one placed object does to the walkways (:attr:`anyhome.space.Placed.nav`)."""

    cells: Patch
    """Cells it blocks."""
    shadow: Patch
    """Cells it makes unwalkable (``cells`` dilated by the walkway disc)."""
    reach: Patch | None = None
    """Cells from which the agent reaches it; None when it need not stay reachable."""
    reach_shadow: Patch | None = None
    """Cells it makes unwalkable for the agent (:data:`AGENT_RADIUS_M`) when the walkways
    are checked wider; None when they are not."""


class NavGrid:
    """The walkway and reachability check of one room (see the module docstring)."""

    def __init__(self, floorplan: Floorplan, space: RoomSpace, cell_m: float = NAV_CELL_M) -> None:
        self.cell = cell_m
        polys = [room_polygon(r) for r in floorplan.rooms]
        minx, miny, _, _ = shapely.bounds(shapely.union_all(polys))
        pad = 2 * cell_m
        x0, y0 = minx - pad + cell_m / 2, miny - pad + cell_m / 2
        bx0, by0 = space.bmin - 1.0
        bx1, by1 = space.bmax + 1.0
        j0 = max(0, int(np.floor((bx0 - x0) / cell_m)))
        i0 = max(0, int(np.floor((by0 - y0) / cell_m)))
        j1 = int(np.ceil((bx1 - x0) / cell_m)) + 1
        i1 = int(np.ceil((by1 - y0) / cell_m)) + 1
        self.xs = x0 + cell_m * np.arange(j0, j1)
        self.ys = y0 + cell_m * np.arange(i0, i1)
        self._xs, self._ys = self.xs.tolist(), self.ys.tolist()
        """The same as lists (bisect on them finds what np.searchsorted finds)."""
        half = cell_m / 2
        inset = WALL_INSET_CELLS * cell_m
        self.room_mask = self._raster(space.poly.buffer(-inset, join_style="mitre"))
        free = self.room_mask.copy()
        others = {r.id: p for r, p in zip(floorplan.rooms, polys)}
        near = AGENT_RADIUS_M + 2 * cell_m
        self.door_near = []
        for d in space.doors:
            free |= self._raster(LineString(d.segment).buffer(half * 1.5, cap_style="flat"))
            for rid in d.rooms:
                if rid != space.room.id and rid in others:
                    inner = others[rid].buffer(-inset, join_style="mitre")
                    free |= self._raster(opening_zone(d.segment).intersection(inner))
            self.door_near.append(self._raster(LineString(d.segment).buffer(near)))
        if floorplan.levels:  # a flight standing in the room is walked round, as the evaluator does
            from anyhome.floorplan.levels import stairs_objects

            for o in stairs_objects(floorplan):
                if o.room == space.room.id:
                    free &= ~self._raster(footprint_polygon(o.position, o.size, o.yaw))
        self.base_free = free
        self._free_dist: np.ndarray | None = None
        """Distance (m) of each cell of ``base_free`` to the nearest cell outside it (made once)."""
        rows, cols = np.flatnonzero(free.any(1)), np.flatnonzero(free.any(0))
        self._live = (slice(int(rows[0]), int(rows[-1]) + 1), slice(int(cols[0]), int(cols[-1]) + 1)) if len(
            rows) else (slice(0, 0), slice(0, 0))
        """The window holding every cell that may be walkable (labelled alone)."""
        self._door_idx = [np.flatnonzero(m) for m in self.door_near]
        self._room_idx = np.flatnonzero(self.room_mask)
        self._door_cells = np.concatenate(self._door_idx) if self._door_idx else self._room_idx
        """Cells near a door (of the room when it has none)."""
        self._door_room_idx = np.flatnonzero(np.any(self.door_near, 0) & self.room_mask) if self.door_near else self._room_idx
        """Room cells near a door: a component touching one touches the room."""
        self._door_mask = np.zeros(self.room_mask.shape, dtype=bool)
        self._door_mask.ravel()[self._door_cells] = True
        """``_door_cells`` as a raster."""
        self._door_by_near = False
        """Every door label was found touching the room near a door (with ``_door_labels``): they
        stay the same while no cell near a door is lost and no component splits."""
        self._blocks: dict[tuple[int, int, int, float], np.ndarray] = {}
        """Shadows of a full block of cells by its size, the disc and radius (:meth:`_shadow`)."""
        self._made: dict[tuple[bytes, bool], Obstacle] = {}
        """Obstacles made (:meth:`obstacle`) by footprint, made again for a pose tried again."""
        self._known: set[Obstacle] = set()
        """Obstacles seen reached since the components were last labelled."""
        self._cells: dict[Obstacle, np.ndarray] = {}
        """Flat indices of each obstacle's reach cells (:meth:`_reach_cells`)."""
        self.obstacles: list[Obstacle] = []
        """The placed objects' obstacles, in order."""
        self.waived: list[Obstacle] = []
        """Obstacles that need not stay reachable (out of reach when placed, or cut off
        when nothing else fitted); the layout keeps this list with its snapshots."""
        self.walk = np.zeros_like(free)
        """Walkable cells of the room as furnished."""
        self.walk_a: np.ndarray | None = None
        """The same for the evaluator's agent when the walkways are checked wider (else None)."""
        self._labels_a: np.ndarray | None = None
        self._door_a = np.zeros(0, dtype=np.int32)
        """Labels of ``walk_a``'s components holding the door component (with ``_labels_a``)."""
        self._door_a_stale = True
        self._labels: np.ndarray | None = None
        """Walkable components of ``walk`` (None: to be labelled again); never written in
        place (a :class:`NavState` may hold it)."""
        self._door_labels = np.zeros(0, dtype=np.int32)
        """Labels of the door component (with ``_labels``)."""
        self._door_stale = True
        """``_door_labels`` to be found again in ``_labels``."""
        self.radius: float | None = None
        for r in (WALKWAY_RADIUS_M, AGENT_RADIUS_M):
            self._use_radius(r)
            if self.ok():
                break
        else:
            self._use_radius(None)

    # ------------------------------------------------------------ raster
    def _use_radius(self, radius: float | None) -> None:
        """Check walkways for an agent of ``radius`` (None: not at all, the empty room fails);
        objects are reached by the evaluator's agent (:data:`AGENT_RADIUS_M`) in any case."""
        self.radius = radius
        self._disc = self._disc_of(radius or AGENT_RADIUS_M)
        self.base_walk = self._walkable(radius) if radius is not None else np.zeros_like(self.base_free)
        wider = radius is not None and radius != AGENT_RADIUS_M
        self._disc_a = self._disc_of(AGENT_RADIUS_M) if wider else None
        self.base_walk_a = self._walkable(AGENT_RADIUS_M) if wider else None
        self.set_blocked([])

    def _disc_of(self, radius: float) -> np.ndarray:
        """The cells within ``radius`` of the centre one, as the distance transform measures."""
        k = int(np.ceil(radius / self.cell)) + 1
        off = np.arange(-k, k + 1, dtype=float)
        # as distance_transform_edt computes it: sqrt of the summed squares, times the cell
        far = np.sqrt(off[:, None] ** 2 + off[None, :] ** 2) * self.cell > radius
        rows, cols = np.nonzero(~far)
        return ~far[rows.min():rows.max() + 1, cols.min():cols.max() + 1]

    def _walkable(self, radius: float) -> np.ndarray:
        if self._free_dist is None:  # one transform for every radius asked
            self._free_dist = ndimage.distance_transform_edt(self.base_free) * self.cell
        return self._free_dist > radius

    def _raster(self, geom) -> np.ndarray:
        return raster_mask(geom, self.xs, self.ys)

    def _rect_patch(self, corners: np.ndarray, grow_m: float, rounded: bool) -> Patch:
        """Cells whose centre lies in a rotated rectangle, (4, 2) corners, grown by ``grow_m``
        (``rounded``: within ``grow_m`` of it; else in the rectangle grown square)."""
        (ax, ay), (bx, by), (cx, cy), (dx, dy) = corners.tolist()
        i0, i1 = bisect_left(self._ys, min(ay, by, cy, dy) - grow_m), bisect_left(self._ys, max(ay, by, cy, dy) + grow_m)
        j0, j1 = bisect_left(self._xs, min(ax, bx, cx, dx) - grow_m), bisect_left(self._xs, max(ax, bx, cx, dx) + grow_m)
        if i0 >= i1 or j0 >= j1:
            return Patch(0, 0, np.zeros((0, 0), dtype=bool))
        mx, my = (ax + bx + cx + dx) / 4, (ay + by + cy + dy) / 4  # as corners.mean(0) sums them
        ex0, ex1, ey0, ey1 = bx - ax, by - ay, dx - ax, dy - ay  # the edges, on floats as numpy has them
        hw, hd = math.sqrt(ex0 * ex0 + ex1 * ex1) / 2, math.sqrt(ey0 * ey0 + ey1 * ey1) / 2  # as np.linalg.norm
        ex0, ex1, ey0, ey1 = ex0 / (2 * hw), ex1 / (2 * hw), ey0 / (2 * hd), ey1 / (2 * hd)
        px = self.xs[j0:j1] - mx
        py = self.ys[i0:i1] - my
        if ex1 == 0.0 and ey0 == 0.0:  # square to the raster: a product of a row and a column
            lx, ly = np.abs(px * ex0)[None], np.abs(py * ey1)[:, None]
        elif ex0 == 0.0 and ey1 == 0.0:
            lx, ly = np.abs(py * ex1)[:, None], np.abs(px * ey0)[None]
        else:
            lx = np.abs(px[None] * ex0 + py[:, None] * ex1)
            ly = np.abs(px[None] * ey0 + py[:, None] * ey1)
        if rounded:
            mask = np.hypot(np.maximum(lx - hw, 0.0), np.maximum(ly - hd, 0.0)) <= grow_m
        else:
            mask = (lx <= hw + grow_m) & (ly <= hd + grow_m)
        return Patch(i0, j0, mask)

    def obstacle(self, corners: np.ndarray, reachable: bool) -> Obstacle:
        """What an object of footprint ``corners`` (4, 2) does to the walkways; ``reachable``:
        it must stay reachable (a floor object an agent walks up to)."""
        key = (corners.tobytes(), reachable)
        got = self._made.get(key)
        if got is not None:
            return got
        cells = self._rect_patch(corners, NAV_OBSTACLE_PAD_M, rounded=False)
        reach = self._rect_patch(corners, REACH_M, rounded=True) if reachable else None
        shadow_a = self._shadow(cells, self._disc_a, AGENT_RADIUS_M) if self._disc_a is not None else None
        got = Obstacle(cells, self._shadow(cells, self._disc, self.radius or AGENT_RADIUS_M), reach, shadow_a)
        if len(self._made) >= MADE_KEPT:
            self._made.clear()
        self._made[key] = got
        return got

    def _shadow(self, cells: Patch, disc: np.ndarray, radius: float) -> Patch:
        """``cells`` dilated by ``disc`` (the cells within ``radius``), clipped to the raster;
        a full block of cells (an object square to the raster) by the distance to it."""
        if self.radius is None or not np.count_nonzero(cells.mask):
            return Patch(0, 0, np.zeros((0, 0), dtype=bool))
        k = disc.shape[0] // 2
        h, w = cells.mask.shape
        ny, nx = self.base_free.shape
        i0, j0 = max(0, cells.i0 - k), max(0, cells.j0 - k)
        i1, j1 = min(ny, cells.i0 + h + k), min(nx, cells.j0 + w + k)
        if np.count_nonzero(cells.mask) == cells.mask.size:
            block = self._blocks.get((h, w, k, radius))
            if block is None:
                d = np.arange(-k, max(h, w) + k, dtype=float)  # rows (columns) from the block's first
                dy = np.maximum(0.0, np.maximum(-d[:h + 2 * k], d[:h + 2 * k] - (h - 1)))
                dx = np.maximum(0.0, np.maximum(-d[:w + 2 * k], d[:w + 2 * k] - (w - 1)))
                # as _disc_of measures: sqrt of the summed squares, times the cell
                block = ~(np.sqrt(dy[:, None] ** 2 + dx[None, :] ** 2) * self.cell > radius)
                block.flags.writeable = False  # handed out in views
                self._blocks[(h, w, k, radius)] = block
            a, b = i0 - (cells.i0 - k), j0 - (cells.j0 - k)
            return Patch(i0, j0, block[a:a + i1 - i0, b:b + j1 - j0])
        free = np.ones((h + 2 * k, w + 2 * k), dtype=bool)
        free[k:k + h, k:k + w] = ~cells.mask
        # the cells within the disc of a blocked one: its dilation by the disc, as _disc_of measures
        grown = ~(ndimage.distance_transform_edt(free) * self.cell > radius)
        a, b = i0 - (cells.i0 - k), j0 - (cells.j0 - k)
        return Patch(i0, j0, grown[a:a + i1 - i0, b:b + j1 - j0])

    # ------------------------------------------------------------ state
    def add(self, obs: Obstacle) -> None:
        """Block ``obs`` (a committed object)."""
        self.obstacles.append(obs)
        sh, sa = obs.shadow, obs.reach_shadow
        jobs = []
        lost = self.walk[sh.window] & sh.mask
        if np.count_nonzero(lost):
            self.walk[sh.window] &= ~sh.mask
            jobs.append((self._labels, self.walk, Patch(sh.i0, sh.j0, lost)))
        lost_a = None
        if self.walk_a is not None and sa is not None:
            lost_a = self.walk_a[sa.window] & sa.mask
            if np.count_nonzero(lost_a):
                self.walk_a[sa.window] &= ~sa.mask
                jobs.append((self._labels_a, self.walk_a, Patch(sa.i0, sa.j0, lost_a)))
            else:
                lost_a = None
        got = _cuts(jobs)
        if jobs and jobs[0][1] is self.walk:
            self._labels, split = got[0]
            if split or not self._door_by_near or np.count_nonzero(self._door_mask[sh.window] & lost):
                self._door_stale = self._door_a_stale = True
            if self.walk_a is None:
                self._forget(jobs[0][2], split)
        if lost_a is not None and sa is not None:
            self._labels_a, split = got[-1]
            if split or np.count_nonzero(self._door_mask[sa.window] & lost_a):
                self._door_a_stale = True
            self._forget(jobs[-1][2], split)

    def _forget(self, lost: Patch, split: bool) -> None:
        """Objects with a reach cell among the cells ``lost`` are no longer known to be reached
        (``split``: a component split, none is); the others keep a reach cell in the same
        component (:func:`_cut`)."""
        if split:
            self._known = set()
        elif self._known:
            self._known = {o for o in self._known if o.reach is None or not _overlap(o.reach, lost)}

    def set_blocked(self, placed: list[Placed]) -> None:
        """Start again from the empty room with the obstacles of ``placed``."""
        self.walk = self.base_walk.copy()
        self.walk_a = None if self.base_walk_a is None else self.base_walk_a.copy()
        self._labels = self._labels_a = None
        self.obstacles = []
        for p in placed:
            if p.nav is not None:
                self.obstacles.append(p.nav)
                self.walk[p.nav.shadow.window] &= ~p.nav.shadow.mask
                sa = p.nav.reach_shadow
                if self.walk_a is not None and sa is not None:
                    self.walk_a[sa.window] &= ~sa.mask

    def state(self) -> NavState:
        """What :meth:`load` needs to come back to the walkways as they are now."""
        return NavState(
            self.walk.copy(), None if self.walk_a is None else self.walk_a.copy(), list(self.obstacles),
            self._labels, self._door_labels, self._door_stale, self._door_by_near, self._labels_a, self._door_a,
            self._door_a_stale, set(self._known),
        )

    def load(self, s: NavState) -> None:
        """Come back to the walkways of :meth:`state` (the labels with them: none to relabel)."""
        self.walk = s.walk.copy()
        self.walk_a = None if s.walk_a is None else s.walk_a.copy()
        self.obstacles = list(s.obstacles)
        self._labels, self._door_labels, self._door_stale = s.labels, s.door_labels, s.door_stale
        self._door_by_near = s.door_by_near
        self._labels_a, self._door_a, self._door_a_stale = s.labels_a, s.door_a, s.door_a_stale
        self._known = set(s.known)

    # ------------------------------------------------------------ checks
    def ok(self) -> bool:
        """Whether the doors share a walkable component with the room and every object that
        must stay reachable is reached from it."""
        return self.unreached() == []

    def unreached(self) -> list[Obstacle] | None:
        """The obstacles that must stay reachable (``reach`` set, not waived) and are not;
        None when no walkable component touches every door and some of the room."""
        if self.radius is None:
            return []
        door = self._door_component()
        if door is None:
            return None
        labels, walk, door = self._reach_labels(door)
        known = self._known
        todo = [o for o in self.obstacles if o.reach is not None and o not in known]
        if todo and self.waived:
            waived = set(self.waived)
            todo = [o for o in todo if o not in waived]
        if not todo:
            return []
        if len(todo) == 1:  # most often the object placed last alone
            o = todo[0]
            lab = _at(labels, walk, self._reach_cells(o))
            if np.count_nonzero(_in(lab, door)):
                known.add(o)
                return []
            return [o]
        cells = [self._reach_cells(o) for o in todo]
        n = np.array([len(c) for c in cells])
        reached = np.zeros(len(todo), dtype=bool)
        some = n.nonzero()[0]  # an obstacle with no reach cells is not reached
        if some.size:
            lab = _at(labels, walk, np.concatenate([cells[i] for i in some]))
            hit = _in(lab, door)
            starts = np.concatenate(([0], np.cumsum(n[some])[:-1]))
            reached[some] = np.logical_or.reduceat(hit, starts)
        out = []
        for o, r in zip(todo, reached, strict=True):
            if r:
                self._known.add(o)
            else:
                out.append(o)
        return out

    def surely_unreached(self, obs: Obstacle) -> bool:
        """Whether ``obs``, once added, is sure to be among :meth:`unreached` (or the walkways
        closed): none of its reach cells is walkable beside it and in the door component now.
        Adding it only takes walkable cells away and splits components, so none would be then."""
        if self.radius is None or obs.reach is None:
            return False
        door = self._door_component()
        if door is None:
            return False
        labels, walk, door = self._reach_labels(door)
        lab = _at(labels, walk, self._reach_cells(obs))  # its reach cells outside its own shadow
        return not np.count_nonzero(_in(lab, door))

    def _reach_cells(self, o: Obstacle) -> np.ndarray:
        """Flat raster indices of the cells ``o`` is reached from (cached per obstacle), less
        those of its own shadow on the raster it is reached on: these are never walkable while
        it stands."""
        got = self._cells.get(o)
        if got is None:
            assert o.reach is not None
            r = o.reach
            sh = o.reach_shadow if self.walk_a is not None else o.shadow
            mask = r.mask
            if sh is not None and sh.mask.size:
                (h, w), (hs, ws) = r.mask.shape, sh.mask.shape
                i0, i1 = max(r.i0, sh.i0), min(r.i0 + h, sh.i0 + hs)
                j0, j1 = max(r.j0, sh.j0), min(r.j0 + w, sh.j0 + ws)
                if i0 < i1 and j0 < j1:
                    mask = mask.copy()
                    mask[i0 - r.i0:i1 - r.i0, j0 - r.j0:j1 - r.j0] &= ~sh.mask[i0 - sh.i0:i1 - sh.i0, j0 - sh.j0:j1 - sh.j0]
            rows, cols = np.nonzero(mask)
            got = (rows + r.i0) * self.walk.shape[1] + cols + r.j0
            self._cells[o] = got
        return got

    def _reach_labels(self, door: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Components of the agent's walkable cells (labels, the cells) and those holding the
        door component."""
        assert self._labels is not None
        if self.walk_a is None:
            return self._labels, self.walk, door
        if self._labels_a is None:
            self._labels_a = self._label(self.walk_a)
            self._known = set()
            self._door_a_stale = True
        if self._door_a_stale:
            self._door_a_stale = False
            cells = self._door_cells
            on = cells[_in(_at(self._labels, self.walk, cells), door)]
            door_a = np.unique(_at(self._labels_a, self.walk_a, on))
            if not np.array_equal(door_a, self._door_a):
                self._known = set()
            self._door_a = door_a
        return self._labels_a, self.walk_a, self._door_a

    def _label(self, walk: np.ndarray) -> np.ndarray:
        """Components of ``walk`` (ndimage.label's), labelled on the window of ``base_free``."""
        out = np.zeros(walk.shape, dtype=np.int32)
        out[self._live], _ = ndimage.label(walk[self._live], structure=_CROSS)
        return out

    def _door_component(self) -> np.ndarray | None:
        """Labels of the walkable components that touch every door and some room cells
        (None: none does)."""
        if self._labels is None:
            self._labels = self._label(self.walk)
            self._known = set()
            self._door_stale = self._door_a_stale = True
        if self._door_stale:
            self._door_stale = False
            labels, walk = self._labels, self.walk
            common: set[int] | None = None
            for idx in self._door_idx:
                lab = set(np.unique(_at(labels, walk, idx)).tolist()) - {0}
                common = lab if common is None else common & lab
            if common is None:
                common = set(np.unique(_at(labels, walk, self._room_idx)).tolist()) - {0}
            near = _at(labels, walk, self._door_room_idx)
            by_near = [bool(np.any(near == lab)) for lab in sorted(common)]
            self._door_by_near = all(by_near)
            keep = np.array([lab for lab, b in zip(sorted(common), by_near, strict=True)
                             if b or np.any(_at(labels, walk, self._room_idx) == lab)], dtype=np.int32)
            if not np.array_equal(keep, self._door_labels):
                self._known = set()
                self._door_a_stale = True
            self._door_labels = keep
        return self._door_labels if len(self._door_labels) else None


def _at(labels: np.ndarray, walk: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """Labels of the flat cells ``idx``, 0 where ``walk`` holds none (labels are kept for
    cells no longer walkable rather than cleared: see :func:`_cut`)."""
    return labels.ravel()[idx] * walk.ravel()[idx]


SMALL_SET = 8
"""Up to this many labels are looked for by comparing with each (``np.isin`` costs more)."""


def _in(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.isin(a, b)`` for 1-D ``a`` and a few labels ``b``."""
    if len(b) == 1:
        return a == b[0]
    if len(b) > SMALL_SET:
        return np.isin(a, b)
    out = np.zeros(a.shape, dtype=bool)
    for v in b.tolist():
        out |= a == v
    return out


def _meet(a: Patch, b: Patch) -> bool:
    """Whether the windows of ``a`` and ``b`` share a cell."""
    (ha, wa), (hb, wb) = a.mask.shape, b.mask.shape
    return a.i0 < b.i0 + hb and b.i0 < a.i0 + ha and a.j0 < b.j0 + wb and b.j0 < a.j0 + wa


def _overlap(a: Patch, b: Patch) -> bool:
    """Whether ``a`` and ``b`` share a cell."""
    if not _meet(a, b):
        return False
    (ha, wa), (hb, wb) = a.mask.shape, b.mask.shape
    i0, i1 = max(a.i0, b.i0), min(a.i0 + ha, b.i0 + hb)
    j0, j1 = max(a.j0, b.j0), min(a.j0 + wa, b.j0 + wb)
    return bool(np.count_nonzero(a.mask[i0 - a.i0:i1 - a.i0, j0 - a.j0:j1 - a.j0] & b.mask[i0 - b.i0:i1 - b.i0, j0 - b.j0:j1 - b.j0]))


def _cut(labels: np.ndarray | None, walk: np.ndarray, lost: Patch) -> tuple[np.ndarray | None, bool]:
    """``labels``, the components of the walkable cells before the cells ``lost`` were taken
    away from ``walk`` (already without them; labels are read where ``walk`` holds cells
    only, :func:`_at`), updated on the window
    :data:`LABEL_MARGIN_CELLS` round them, and whether a component split; None (to be
    labelled again) when that window does not settle them.

    The walkable cells bordering the lost ones (the *ring*) fall into components of the
    window. One that keeps off the window's edge is a whole component (a pocket cut off):
    it gets a label of its own. When the rest of the ring that was in one component lies
    in one component of the window, every path that crossed the lost cells goes round them
    there, so the other components are the same as before less the lost cells."""
    return _cuts([(labels, walk, lost)])[0]


def _cuts(jobs: list[tuple[np.ndarray | None, np.ndarray, Patch]]) -> list[tuple[np.ndarray | None, bool]]:
    """:func:`_cut` of each (labels, walk, lost) of ``jobs`` (two at most), their windows
    labelled in one call: stacked with an empty row between them, the second's components
    are its own, numbered on from the first's."""
    out: list[tuple[np.ndarray | None, bool]] = [(None, True)] * len(jobs)
    todo = [(k, labels, lost, walk[w], w) for k, (labels, walk, lost) in enumerate(jobs)
            if labels is not None for w in [_window(walk, lost)]]
    if len(todo) == 1:
        k, labels, lost, win, w = todo[0]
        lab, n = ndimage.label(win, structure=_CROSS)
        out[k] = _settle(labels, lab, n, lost, w)
    elif todo:
        (ka, labels_a, lost_a, win_a, wa), (kb, labels_b, lost_b, win_b, wb) = todo
        (ha, wda), (hb, wdb) = win_a.shape, win_b.shape
        both = np.zeros((ha + 1 + hb, max(wda, wdb)), dtype=bool)
        both[:ha, :wda] = win_a
        both[ha + 1:, :wdb] = win_b
        lab, n = ndimage.label(both, structure=_CROSS)  # the first's components first (scan order)
        top = lab[:ha, :wda]
        n_a = int(top.max())
        out[ka] = _settle(labels_a, top, n_a, lost_a, wa)
        out[kb] = _settle(labels_b, lab[ha + 1:, :wdb], n - n_a, lost_b, wb)
    return out


def _window(walk: np.ndarray, lost: Patch) -> tuple[slice, slice]:
    """The window :func:`_cut` labels: ``lost``'s grown by :data:`LABEL_MARGIN_CELLS`, on the raster."""
    m = LABEL_MARGIN_CELLS
    h, w = lost.mask.shape
    ny, nx = walk.shape
    return (slice(max(0, lost.i0 - m), min(ny, lost.i0 + h + m)),
            slice(max(0, lost.j0 - m), min(nx, lost.j0 + w + m)))


def _settle(labels: np.ndarray, lab: np.ndarray, n: int, lost: Patch, w: tuple[slice, slice]
            ) -> tuple[np.ndarray | None, bool]:
    """:func:`_cut`'s answer from the ``n`` components ``lab`` of its window ``w``."""
    i0, j0 = w[0].start, w[1].start
    pockets = _pockets(labels[w], lab, Patch(lost.i0 - i0, lost.j0 - j0, lost.mask)) if n > 1 else []
    if pockets is None:
        return None, True
    if not pockets:
        return labels, False  # the same components less the lost cells, which walk no longer holds
    out = labels.copy()
    top = int(out.max())
    win = out[w]
    for k, g in enumerate(pockets, 1):
        win[lab == g] = top + k
    return out, True


def _pockets(was: np.ndarray, lab: np.ndarray, lost: Patch) -> list[int] | None:
    """The components of a window (``lab``, its labels now; ``was``, its labels before
    ``lost`` was taken away) bordering ``lost`` that keep off its edge; None when two that
    reach its edge were one component before (:func:`_cut`)."""
    gone = np.zeros(lab.shape, dtype=bool)
    gone[lost.window] = lost.mask
    near = gone.copy()  # the lost cells and their 4-neighbours (ndimage.label's connectivity)
    near[1:] |= gone[:-1]
    near[:-1] |= gone[1:]
    near[:, 1:] |= gone[:, :-1]
    near[:, :-1] |= gone[:, 1:]
    ring = near & (lab > 0)
    on = lab[ring]
    if not on.size or on.min() == on.max():  # one component round them (most often): no pocket
        return []
    got, first = np.unique(on, return_index=True)
    if len(got) < 2:
        return []
    edge = np.unique(np.concatenate((lab[0], lab[-1], lab[:, 0], lab[:, -1])))
    shut = ~_in(got, edge)
    before = was[ring][first[~shut]]  # the component each one reaching the edge was part of
    if len(np.unique(before)) < len(before):
        return None
    return got[shut].tolist()
