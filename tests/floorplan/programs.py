"""Random and fixed room programs for the floorplan tests."""

from __future__ import annotations

import numpy as np

from anyhome.house import ROOM_TYPES
from anyhome.plan.spec import HouseSpec, RoomSpec

AREA_RANGE_M2 = {
    "bathroom": (3.5, 8.0),
    "closet": (2.5, 5.0),
    "pantry": (2.5, 5.0),
    "storage": (3.0, 8.0),
    "laundry": (3.0, 7.0),
    "hallway": (5.0, 12.0),
    "entry": (4.0, 9.0),
}
"""Target areas per type; other non-habitable types get SERVICE, habitable HABITABLE."""
SERVICE_RANGE_M2 = (3.0, 9.0)
HABITABLE_RANGE_M2 = (8.0, 28.0)


def random_program(rng: np.random.Generator, n_rooms: int, extra_edges: int = 2) -> HouseSpec:
    """A random spec: random types and areas, a random tree plus a few extra edges."""
    types = sorted(ROOM_TYPES)
    rooms = []
    for k in range(n_rooms):
        t = types[int(rng.integers(len(types)))]
        lo, hi = AREA_RANGE_M2.get(t, HABITABLE_RANGE_M2 if ROOM_TYPES[t] else SERVICE_RANGE_M2)
        rooms.append(RoomSpec(id=f"r{k}", name=t.replace("_", " "), type=t, area_m2=round(float(rng.uniform(lo, hi)), 1)))
    edges = {(int(rng.integers(k)), k) for k in range(1, n_rooms)}
    for _ in range(extra_edges if n_rooms > 2 else 0):
        a, b = sorted(rng.choice(n_rooms, size=2, replace=False).tolist())
        edges.add((a, b))
    conns = [(f"r{a}", f"r{b}") for a, b in sorted(edges)]
    conns.append((f"r{int(rng.integers(n_rooms))}", "outside"))
    return HouseSpec(prompt="random", rooms=rooms, connections=conns)


def family_home() -> HouseSpec:
    """A realistic 5-room program: living hub, kitchen, two bedrooms, bathroom."""
    rooms = [
        RoomSpec(id="living", name="living room", type="living_room", area_m2=24),
        RoomSpec(id="kitchen", name="kitchen", type="kitchen", area_m2=12),
        RoomSpec(id="bed1", name="master bedroom", type="bedroom", area_m2=15),
        RoomSpec(id="bed2", name="kids bedroom", type="bedroom", area_m2=11),
        RoomSpec(id="bath", name="bathroom", type="bathroom", area_m2=5),
    ]
    conns = [("living", "kitchen"), ("living", "bed1"), ("living", "bed2"), ("living", "bath"), ("living", "outside")]
    return HouseSpec(prompt="family home", rooms=rooms, connections=conns)


def large_home() -> HouseSpec:
    """A 12-room program around a hallway."""
    spec = [
        ("hall", "hallway", 12), ("entry", "entry", 6), ("living", "living_room", 28),
        ("dining", "dining_room", 14), ("kitchen", "kitchen", 12), ("bed1", "bedroom", 16),
        ("bed2", "bedroom", 12), ("bed3", "bedroom", 11), ("bath1", "bathroom", 6),
        ("bath2", "bathroom", 4.5), ("study", "study", 10), ("laundry", "laundry", 4),
    ]
    rooms = [RoomSpec(id=i, name=i, type=t, area_m2=a) for i, t, a in spec]
    conns = [
        ("entry", "outside"), ("entry", "hall"), ("entry", "living"), ("living", "dining"),
        ("dining", "kitchen"), ("kitchen", "laundry"), ("hall", "bed1"), ("hall", "bed2"),
        ("hall", "bed3"), ("hall", "bath1"), ("bed1", "bath2"), ("hall", "study"),
    ]
    return HouseSpec(prompt="large home", rooms=rooms, connections=conns)


def planner_like_program(rng: np.random.Generator, n_rooms: int) -> HouseSpec:
    """A tree like the offline planner's: a hub (hallway or living room) with up to six
    neighbours, each with at most two sub-rooms (en-suite, pantry...) that are leaves,
    one entrance on the hub."""
    types = sorted(t for t in ROOM_TYPES if t not in ("hallway", "entry"))
    hub_type = "hallway" if rng.random() < 0.5 else "living_room"
    rooms = [RoomSpec(id="r0", name=hub_type, type=hub_type, area_m2=8.0 if hub_type == "hallway" else 24.0)]
    children = {0: 0}
    depth = {0: 0}
    conns = []
    for k in range(1, n_rooms):
        t = types[int(rng.integers(len(types)))]
        lo, hi = AREA_RANGE_M2.get(t, HABITABLE_RANGE_M2 if ROOM_TYPES[t] else SERVICE_RANGE_M2)
        rooms.append(RoomSpec(id=f"r{k}", name=t.replace("_", " "), type=t, area_m2=round(float(rng.uniform(lo, hi)), 1)))
        parents = [p for p, c in children.items() if c < (6 if p == 0 else 2) and depth[p] < 2]
        parent = parents[int(rng.integers(len(parents)))] if rng.random() < 0.4 else 0
        if children[parent] >= (6 if parent == 0 else 2):
            parent = parents[0]
        children[parent] += 1
        children[k] = 0
        depth[k] = depth[parent] + 1
        conns.append((f"r{parent}", f"r{k}"))
    conns.append(("r0", "outside"))
    return HouseSpec(prompt="planner-like", rooms=rooms, connections=conns)
