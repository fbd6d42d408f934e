"""The room program in index form: what the solver needs from a HouseSpec."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from anyhome.floorplan.grid import OUTSIDE
from anyhome.floorplan.options import FloorplanOptions
from anyhome.house import is_habitable
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.spec import HouseSpec

CORRIDOR_TYPES = frozenset({"hallway"})
"""Types grown as long, narrow corridors."""
HUB_TYPES = frozenset({"hallway", "entry"})
"""Types pulled to the middle of the footprint."""
STACKED_TYPES = frozenset({"stairwell"})
"""Types that mark a storey of a house of several: its footprint is drawn without a U's
notch, which the storeys above or below would hang over."""


@dataclass(frozen=True)
class Program:
    """Rooms by index; ``links`` holds (a, b or OUTSIDE) per spec connection, in order;
    ``options`` are the search's tunables (the minimum room sides among them);
    ``min_width_m`` the knowledge base's narrowest width per room type (rooms.yaml
    ``min_width_m``), 0 for a type it does not know; ``circulation`` its flag of
    rooms for passing through."""

    ids: tuple[str, ...]
    types: tuple[str, ...]
    areas_m2: np.ndarray
    links: tuple[tuple[int, int], ...]
    options: FloorplanOptions
    min_width_m: tuple[float, ...] = ()
    circulation: tuple[bool, ...] = ()
    enclosed: tuple[bool, ...] = ()
    """Per room: an open-air room the building wraps around (rooms.yaml ``enclosed``: a
    courtyard); the rooms around it may take their windows from it."""
    min_length_m: tuple[float, ...] = ()
    """Per room: the shortest long side it may have (``solve_floorplan(min_length_m=)``:
    a stairwell holds its stair and the floor at the stair's foot), 0 for none."""
    stair_m: tuple[float, ...] = ()
    """Per room: the length of the stair box it holds (``solve_floorplan(stair_m=)``: a
    stairwell's doors are placed where the stair leaves them clear), 0 for none."""

    @classmethod
    def from_spec(cls, spec: HouseSpec, options: FloorplanOptions, kb: KnowledgeBase | None = None) -> Program:
        ids = tuple(r.id for r in spec.rooms)
        index = {rid: k for k, rid in enumerate(ids)} | {"outside": OUTSIDE}
        types = kb.rooms.types if kb is not None else {}
        widths = tuple(types[r.type].min_width_m if r.type in types else 0.0 for r in spec.rooms)
        circulation = tuple(bool(types[r.type].circulation) if r.type in types else False for r in spec.rooms)
        enclosed = tuple(bool(types[r.type].enclosed) and r.open_air if r.type in types else False for r in spec.rooms)
        return cls(
            min_width_m=widths,
            circulation=circulation,
            enclosed=enclosed,
            ids=ids,
            types=tuple(r.type for r in spec.rooms),
            areas_m2=np.array([r.area_m2 for r in spec.rooms], dtype=float),
            links=tuple((index[a], index[b]) for a, b in spec.connections),
            options=options,
        )

    @property
    def n(self) -> int:
        return len(self.ids)

    @property
    def edges(self) -> list[tuple[int, int]]:
        return [(a, b) for a, b in self.links if b != OUTSIDE]

    @property
    def stacked(self) -> bool:
        """A storey of a house of several (it holds a stairwell)."""
        return any(t in STACKED_TYPES for t in self.types)

    @cached_property
    def doors(self) -> np.ndarray:
        """Per room: the doors its links give it, the way out included."""
        return np.bincount([k for link in self.links for k in link if k != OUTSIDE], minlength=self.n)

    def habitable(self, k: int) -> bool:
        return is_habitable(self.types[k])

    def tree(self, root: int, rng: np.random.Generator | None = None) -> list[list[int]] | None:
        """Children of every room in a breadth-first tree of the bubble diagram from
        ``root`` (each room's unseen neighbours in index order, shuffled by ``rng`` when
        given); None when the diagram is not connected."""
        adj: list[list[int]] = [[] for _ in range(self.n)]
        for a, b in self.edges:
            adj[a].append(b)
            adj[b].append(a)
        children: list[list[int]] = [[] for _ in range(self.n)]
        seen, order = {root}, [root]
        for k in order:
            nbrs = sorted(set(adj[k]) - seen)
            if rng is not None:
                rng.shuffle(nbrs)
            for j in nbrs:
                seen.add(j)
                children[k].append(j)
                order.append(j)
        return children if len(seen) == self.n else None

    def needs_exterior(self) -> np.ndarray:
        entrances = {a for a, b in self.links if b == OUTSIDE}
        return np.array([self.habitable(k) or k in entrances for k in range(self.n)])

    def hubs(self) -> np.ndarray:
        ext = self.needs_exterior()
        return np.array([self.types[k] in HUB_TYPES or not ext[k] for k in range(self.n)])

    def min_side_m(self, k: int) -> float:
        """The narrowest side room ``k`` may have: its type's norm (``min_width_m``), never
        below the options' floor for its kind (corridor, habitable, service); a stairwell
        (``stair_m``) the side asked for its stair (anyhome.floorplan.levels), a hub's
        floor where it has ``hub_min_doors`` doors."""
        opts = self.options
        if self.stair_m and self.stair_m[k] > 0 and self.min_width_m:  # a stairwell: as wide as its stair asks
            return max(self.min_width_m[k], opts.hub_min_side_m if self.doors[k] >= opts.hub_min_doors else 0.0)
        if self.types[k] in CORRIDOR_TYPES:
            floor = opts.corridor_width_m
        else:
            floor = opts.min_side_habitable_m if self.habitable(k) else opts.min_side_service_m
        norm = self.min_width_m[k] if self.min_width_m else 0.0
        if self.types[k] not in CORRIDOR_TYPES and self.doors[k] >= opts.hub_min_doors:
            floor = max(floor, opts.hub_min_side_m)
        return max(floor, norm)

    def max_aspect(self, k: int) -> float:
        """Longest/shortest side room ``k`` may have (corridors and other circulation
        rooms, rooms.yaml ``circulation``: no limit)."""
        if self.types[k] in CORRIDOR_TYPES or (self.circulation and self.circulation[k]):
            return float("inf")
        opts = self.options
        return opts.max_habitable_aspect_ratio if self.habitable(k) else opts.max_room_aspect_ratio

    def label(self, k: int) -> str:
        return "outside" if k == OUTSIDE else self.ids[k]
