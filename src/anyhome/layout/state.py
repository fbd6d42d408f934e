"""A room being furnished: its free space, walkways, placed objects and bookkeeping."""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from shapely.geometry import Polygon

from anyhome.geometry import blocks_navigation, walked_up_to
from anyhome.house import Dropped, Floorplan, HouseObject, Room
from anyhome.layout.options import LayoutOptions
from anyhome.layout.rules import wrap
from anyhome.navgrid import NavGrid, NavState, Obstacle
from anyhome.plan.spec import ItemSpec, RoomSpec
from anyhome.space import Placed, RoomSpace, Wall, nav_blocks, rect_corners

SLUG_MAX_CHARS = 40
"""Longest name part of an object id (ids are at most 128 characters, see anyhome.sanitize)."""


@functools.lru_cache(maxsize=1024)
def slugify(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower())[:SLUG_MAX_CHARS].strip("_") or "object"


@dataclass
class Choice:
    """A chosen pose for one object."""

    xy: np.ndarray
    yaw: float
    z: float


@dataclass
class Snapshot:
    n_placed: int
    counters: dict[str, int]
    n_dropped: int
    n_keep_clear: int = 0
    n_waived: int = 0
    placed: list[Placed] | None = None
    """The placed objects then, and the walkways with them: restored without rebuilding."""
    nav: NavState | None = None


@dataclass
class Outcome:
    """Everything a furnishing step changed, kept to come back to it (:meth:`RoomState.outcome`)
    rather than taking the step again."""

    placed: list[Placed]
    keep_clear: list[np.ndarray]
    dropped: list[Dropped]
    counters: dict[str, int]
    waived: list[Obstacle]
    nav: NavState
    rng: Mapping[str, Any]


@dataclass
class RoomState:
    """One room being furnished; ``space.objects`` and ``dropped`` hold the outcome."""

    floorplan: Floorplan
    room: Room
    spec: RoomSpec
    rng: np.random.Generator
    options: LayoutOptions
    space: RoomSpace = field(init=False)
    nav: NavGrid = field(init=False)
    dropped: list[Dropped] = field(default_factory=list)
    counters: dict[str, int] = field(default_factory=dict)
    rows_wall: Wall | None = None
    """The wall a ``rows`` arrangement faces, once one is laid out."""
    group_zones: dict[int, Polygon] = field(default_factory=dict)
    """Index of a group in ``spec.groups`` -> the arm of an open-plan room it belongs in
    (:mod:`anyhome.layout.zones`)."""
    zone: Polygon | None = None
    """The arm of the group being placed: floor poses inside it score higher."""
    spread: bool = False
    """A zone is being placed (:mod:`anyhome.layout.fill`): anchor poses away from the
    furniture already there score higher."""

    def __post_init__(self) -> None:
        self.space = RoomSpace(self.floorplan, self.room)
        self.nav = NavGrid(self.floorplan, self.space)

    # ------------------------------------------------------------ bookkeeping
    def snapshot(self) -> Snapshot:
        return Snapshot(len(self.space.placed), dict(self.counters), len(self.dropped), len(self.space.keep_clear),
                        len(self.nav.waived), list(self.space.placed), self.nav.state())

    def restore(self, snap: Snapshot) -> None:
        del self.space.placed[snap.n_placed:]
        del self.space.keep_clear[snap.n_keep_clear:]
        del self.dropped[snap.n_dropped:]
        self.counters = dict(snap.counters)
        del self.nav.waived[snap.n_waived:]
        then = snap.placed
        if snap.nav is not None and then is not None and len(then) == len(self.space.placed) and all(
                a is b for a, b in zip(then, self.space.placed, strict=True)):
            self.nav.load(snap.nav)  # the same objects: the walkways as they were
        else:
            self.nav.set_blocked(self.space.placed)

    def outcome(self) -> Outcome:
        """The room as it stands, the random state included: :meth:`resume` comes back to it."""
        return Outcome(list(self.space.placed), list(self.space.keep_clear), list(self.dropped), dict(self.counters),
                       list(self.nav.waived), self.nav.state(), self.rng.bit_generator.state)

    def resume(self, o: Outcome) -> None:
        """Come back to the room of :meth:`outcome` (after a :meth:`restore`): the same objects,
        walkways and random state as when it was taken."""
        self.space.placed[:] = o.placed
        self.space.keep_clear[:] = o.keep_clear
        self.dropped[:] = o.dropped
        self.counters = dict(o.counters)
        self.nav.waived[:] = o.waived
        self.nav.load(o.nav)
        self.rng.bit_generator.state = o.rng

    def drop(self, name: str, reason: str, copies: int = 1) -> None:
        self.dropped.extend(self.dropped_entry(name, reason) for _ in range(copies))

    def dropped_entry(self, name: str, reason: str) -> Dropped:
        return Dropped(room=self.room.id, name=name, reason=reason)

    def new_id(self, name: str) -> str:
        slug = slugify(name)
        k = self.counters.get(slug, 0)
        self.counters[slug] = k + 1
        return f"{self.room.id}-{slug}-{k}"

    def footprint(self, item: ItemSpec, size: Sequence[float], ch: Choice, support: str
                  ) -> tuple[np.ndarray, Obstacle | None]:
        """Corners (4, 2) of ``item`` at ``ch``, as :meth:`commit` makes them, and what it would
        do to the walkways (None: nothing)."""
        corners = rect_corners(ch.xy[None], size[:2], [wrap(ch.yaw)])[0]
        height, tags = float(size[2]), list(item.tags)
        if not blocks_navigation(item.category, height, support, tags):
            return corners, None
        return corners, self.nav.obstacle(corners, reachable=walked_up_to(item.category, height, support, tags))

    def commit(self, item: ItemSpec, size: Sequence[float], ch: Choice, support: str, rule: str,
               group: str | None, anchor: str | None, layer: bool = False,
               blocked: tuple[np.ndarray, Obstacle | None] | None = None) -> HouseObject:
        """Place ``item`` at ``ch``: it joins the room's objects and blocks walkways
        (``layer``: a rug under furniture, :mod:`anyhome.layout.layers`); a floor object an
        agent walks up to must stay reachable from then on (:meth:`reach_cost`).
        ``blocked``: its :meth:`footprint`, already added to the walkways."""
        obj = HouseObject(
            id=self.new_id(item.name), room=self.room.id, name=item.name, category=item.category,
            description=item.description,
            position=(float(ch.xy[0]), float(ch.xy[1]), float(ch.z)),
            size=(float(size[0]), float(size[1]), float(size[2])), yaw=wrap(ch.yaw),
            support=support, group=group, anchor=anchor, rule=rule, material=item.material,
            tags=list(item.tags),
        )
        if blocked is not None:
            corners, obs = blocked
        else:
            corners = rect_corners(ch.xy[None], size[:2], [obj.yaw])[0]
            obs = self.nav.obstacle(corners, reachable=walked_up_to(obj.category, obj.size[2], obj.support, obj.tags)) if nav_blocks(obj) else None
        self.space.placed.append(Placed(obj, corners, ch.z, ch.z + size[2], support == "floor", obs, layer))
        if obs is not None and blocked is None:
            self.nav.add(obs)
        return obj

    def reach_cost(self) -> tuple[int, int] | None:
        """What the object committed last costs: None when the doors no longer share a
        walkable component with the room, else (earlier objects it cuts off, 1 when it
        cannot be reached itself); (0, 0) when every object stays reachable."""
        return self._cost(self.space.placed[-1].nav if self.space.placed else None)

    def _cost(self, last: Obstacle | None) -> tuple[int, int] | None:
        """:meth:`reach_cost` of the walkways as they are, ``last`` the obstacle added last."""
        cut = self.nav.unreached()
        if cut is None:
            return None
        itself = int(last in cut)
        return len(cut) - itself, itself

    def commit_checked(self, item: ItemSpec, size: Sequence[float], ch: Choice, support: str, rule: str,
                       group: str | None, anchor: str | None, check: bool = True
                       ) -> tuple[HouseObject, tuple[int, int]] | None:
        """``item`` committed at ``ch`` with its :meth:`reach_cost` (``check`` False:
        unchecked, (0, 0)); None (left out) when it closes a walkway; what it leaves out of
        reach need not stay reachable from then on."""
        snap = self.snapshot()
        obj = self.commit(item, size, ch, support, rule, group, anchor)
        cost = self.reach_cost() if check and nav_blocks(obj) else (0, 0)
        if cost is None:
            self.restore(snap)
            return None
        if cost != (0, 0):
            self.nav.waived.extend(self.nav.unreached() or [])
        return obj, cost

    def commit_if_walkable(self, item: ItemSpec, size: Sequence[float], choices: Iterable[Choice], support: str,
                           rule: str, group: str | None, anchor: str | None,
                           more: Callable[[], list[Choice]] | None = None) -> HouseObject | None:
        """The first of ``choices`` that keeps every walkway open and every floor object
        reachable, itself included, committed; when none does, the same among ``more()``
        (a longer list that starts with ``choices``); else the one that keeps the walkways
        open and leaves the fewest earlier objects, then itself, out of reach; None if none
        keeps the walkways open (``more()`` is asked only when some of ``choices`` keeps
        them open: when every one closes a walkway, more poses are taken to close it too).
        ``choices`` may be checked lazily
        (:func:`~anyhome.layout.scoring.verified_lazily`): each is taken with the room as it was."""
        best: tuple[tuple[int, int], Choice] | None = None
        tried = 0
        for stage in range(2):
            todo: Iterable[Choice] = choices if stage == 0 else (more()[tried:] if more is not None else [])
            for ch in todo:
                tried += 1
                if best is not None and best[0] <= (0, 1) and self._surely_unreached(item, size, ch, support):
                    continue  # it would cost (k, 1) at best: no better than the best so far
                blocked = self.footprint(item, size, ch, support)
                if blocked[1] is None:  # no walkway to close
                    return self.commit(item, size, ch, support, rule, group, anchor, blocked=blocked)
                walkways = self.nav.state()  # tried on the walkways alone, the object made only when kept
                self.nav.add(blocked[1])
                cost = self._cost(blocked[1])
                if cost == (0, 0):
                    return self.commit(item, size, ch, support, rule, group, anchor, blocked=blocked)
                self.nav.load(walkways)
                if cost is not None and (best is None or cost < best[0]):
                    best = (cost, ch)
            if best is None and tried:  # every pose closes a walkway: more of them would too
                return None
        if best is None:
            return None
        got = self.commit_checked(item, size, best[1], support, rule, group, anchor)
        return None if got is None else got[0]

    def _surely_unreached(self, item: ItemSpec, size: Sequence[float], ch: Choice, support: str) -> bool:
        """Whether ``item`` committed at ``ch`` is sure to be out of reach itself, the room as
        it is (:meth:`NavGrid.surely_unreached`)."""
        if not walked_up_to(item.category, float(size[2]), support, list(item.tags)):
            return False
        corners = rect_corners(ch.xy[None], size[:2], [wrap(ch.yaw)])[0]  # as commit makes them
        return self.nav.surely_unreached(self.nav.obstacle(corners, reachable=True))

    def unreached_since(self, snap: Snapshot) -> int:
        """Objects left out of reach since ``snap``."""
        return len(self.nav.waived) - snap.n_waived

    def room_windows(self) -> bool:
        """Whether the room has a window."""
        return any(not op[4] for w in self.space.walls for op in w.openings)

    # ------------------------------------------------------------ lookup
    def match(self, target: str | None, exclude: str | None = None) -> list[HouseObject]:
        """Objects of this room named or categorised as ``target``, best match first."""
        if not target:
            return []
        t = target.lower().strip()
        objs = [o for o in self.space.objects if o.id != exclude]
        tiers = [
            [o for o in objs if o.name.lower() == t],
            [o for o in objs if t in o.name.lower()],
            [o for o in objs if o.category.lower() == t or t in o.category.lower()],
            [o for o in objs if o.category.lower() in t],
        ]
        seen, out = set(), []
        for tier in tiers:
            for o in tier:
                if o.id not in seen:
                    seen.add(o.id)
                    out.append(o)
        return out
