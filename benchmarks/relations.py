"""Benchmark of relations (issue 14): are the relations a room's plan states met?

Usage::

    PYTHONPATH=src .venv/bin/python benchmarks/relations.py [--rooms 8] [--seed 0] [--out FILE] [--list]

A seeded set of synthetic rooms (``--rooms`` per object count, 5, 10, 20 and 30
objects: 32 by default), rectangles and L shapes whose area grows with the object
count (:data:`AREA_M2`), with one or two doors and one or two windows on their
outline. Each room is furnished from groups of :data:`TEMPLATES` that state the
relations of :mod:`anyhome.evaluate.relations` (near, far, in front, beside, symmetric
pairs, around, facing, aligned, runs along a wall), one room at a time by
:func:`anyhome.layout.solver.furnish_room` (timed alone), then checked with
:func:`anyhome.evaluate.relations.room_relations` on the placed geometry.

Prints a markdown table: relations met by kind (%) per object count, items placed (%)
and the median layout time per room (ms) by object count.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from anyhome.evaluate.relations import KINDS, Relation, room_relations
from anyhome.house import Door, Floorplan, Room, Window
from anyhome.layout import solver as layout_solver
from anyhome.layout.options import DEFAULT_OPTIONS
from anyhome.layout.state import RoomState
from anyhome.plan.spec import GroupSpec, ItemSpec, RoomSpec

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floorplans import emit  # noqa: E402

COUNTS = (5, 10, 20, 30)
"""Object counts of the rooms."""
AREA_M2 = {5: (10.0, 18.0), 10: (16.0, 28.0), 20: (28.0, 45.0), 30: (40.0, 60.0)}
"""Floor area range (m2) of a room by its object count."""
L_SHARE = 0.5
"""Share of L-shaped rooms."""
DOOR_W_M = 0.9
WINDOW_W_M = 1.2


def _it(name: str, cat: str, size: tuple[float, float, float], rule: str, **kw: Any) -> ItemSpec:
    return ItemSpec(name=name, category=cat, size_m=size, rule=rule, **kw)


def _sofa(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("sofa", "sofa", (2.0, 0.9, 0.85), "place_wall", params={"wall": "longest"}),
            [_it("coffee table", "table", (1.1, 0.6, 0.45), "place_front", params={"distance_m": 0.4}),
             _it("tv stand", "tv_stand", (1.6, 0.45, 0.55), "place_front",
                 params={"distance_m": 2.2, "to_wall": True}),
             _it("side table", "table", (0.5, 0.5, 0.55), "place_beside", count=2)], {})


def _bed(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("bed", "bed", (1.6, 2.1, 0.6), "place_wall"),
            [_it("nightstand", "nightstand", (0.5, 0.4, 0.55), "place_beside", count=2),
             _it("painting", "painting", (0.9, 0.04, 0.6), "place_on_wall"),
             _it("laundry basket", "basket", (0.45, 0.35, 0.55), "place_wall", params={"far_m": 1.5})], {})


def _dining(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    n = int(rng.integers(4, 7))
    return (_it("dining table", "table", (1.6, 0.9, 0.75), "place_center"),
            [_it("dining chair", "chair", (0.45, 0.5, 0.9), "place_around", count=n),
             _it("sideboard", "cabinet", (1.4, 0.45, 0.85), "place_next_wall")], {})


def _desk(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("desk", "desk", (1.2, 0.6, 0.75), "place_wall"),
            [_it("desk chair", "chair", (0.5, 0.5, 0.9), "place_front", params={"distance_m": 0.15}),
             _it("desk shelf", "shelf", (0.8, 0.35, 1.9), "place_next_wall", count=2)], {})


def _shelves(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return _it("bookcase", "shelf", (0.9, 0.35, 1.9), "place_next_wall"), [], {"repeat": int(rng.integers(3, 5))}


def _corner(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("armchair", "armchair", (0.85, 0.85, 0.95), "place_corner"),
            [_it("floor lamp", "lamp", (0.4, 0.4, 1.6), "place_beside", params={"side": "right"}),
             _it("footstool", "ottoman", (0.5, 0.5, 0.4), "place_front", params={"distance_m": 0.3})], {})


def _pets(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("cat tree", "cat_tree", (0.6, 0.6, 1.5), "place_wall"),
            [_it("litter box", "box", (0.5, 0.4, 0.4), "place_center", params={"far_m": 2.5})], {})


def _easels(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return _it("easel", "easel", (0.7, 0.7, 1.7), "place_next"), [], {"repeat": 3}


def _kitchen(rng: np.random.Generator) -> tuple[ItemSpec, list[ItemSpec], dict[str, Any]]:
    return (_it("counter", "counter", (1.2, 0.6, 0.9), "place_wall"),
            [_it("stove", "stove", (0.6, 0.6, 0.9), "place_next_wall"),
             _it("sink", "sink", (0.8, 0.6, 0.9), "place_next_wall"),
             _it("fridge", "refrigerator", (0.7, 0.7, 1.8), "place_next_wall")], {})


Template = Callable[[np.random.Generator], tuple[ItemSpec, list[ItemSpec], dict[str, Any]]]
TEMPLATES: tuple[Template, ...] = (_sofa, _bed, _dining, _desk, _shelves, _corner, _pets, _easels, _kitchen)
"""Group makers: (anchor, members, GroupSpec fields), each stating some relations."""
FILLER = _it("plant", "plant", (0.4, 0.4, 1.0), "place_corner")
"""Fills a room to its object count (states no relation)."""


def _n(anchor: ItemSpec, members: list[ItemSpec], extra: dict[str, Any]) -> int:
    return int(extra.get("repeat", 1)) * (1 + sum(m.count for m in members))


def room_groups(n_objects: int, rng: np.random.Generator) -> list[GroupSpec]:
    """Groups of exactly ``n_objects`` objects: templates drawn in turn, plants to fill."""
    groups: list[GroupSpec] = []
    left = n_objects
    order = list(rng.permutation(len(TEMPLATES)))
    tries = 0
    while left > 0 and tries < 3 * len(TEMPLATES):
        tmpl = TEMPLATES[order[tries % len(order)]]
        tries += 1
        anchor, members, extra = tmpl(rng)
        k = _n(anchor, members, extra)
        if k > left:
            continue
        groups.append(GroupSpec(name=f"g{len(groups)}", anchor=anchor, members=members,
                                priority=len(groups), **extra))
        left -= k
    for _ in range(left):
        groups.append(GroupSpec(name=f"g{len(groups)}", anchor=FILLER, priority=len(groups)))
    return groups


def _outline(area_m2: float, l_shape: bool, rng: np.random.Generator) -> list[tuple[float, float]]:
    aspect = float(rng.uniform(1.0, 1.8))
    if not l_shape:
        w = float(np.sqrt(area_m2 * aspect))
        h = area_m2 / w
        return [(0, 0), (w, 0), (w, h), (0, h)]
    cut = float(rng.uniform(0.2, 0.35))  # share of the bounding box cut away
    bw = float(np.sqrt(area_m2 / (1 - cut) * aspect))
    bh = area_m2 / (1 - cut) / bw
    cw = bw * float(np.sqrt(cut))
    ch = bw * bh * cut / cw
    return [(0, 0), (bw, 0), (bw, bh - ch), (bw - cw, bh - ch), (bw - cw, bh), (0, bh)]


def synthetic_room(n_objects: int, rng: np.random.Generator) -> tuple[Floorplan, Room, RoomSpec]:
    """One room of the benchmark: outline, doors, windows and its plan of ``n_objects`` objects."""
    area = float(rng.uniform(*AREA_M2[n_objects]))
    poly = _outline(area, bool(rng.random() < L_SHARE), rng)
    edges = [(np.asarray(poly[i], float), np.asarray(poly[(i + 1) % len(poly)], float)) for i in range(len(poly))]
    long_edges = [i for i, (a, b) in enumerate(edges) if np.linalg.norm(b - a) >= 2.0]
    picks = list(rng.permutation(long_edges))
    doors, windows = [], []
    n_doors, n_windows = int(rng.integers(1, 3)), int(rng.integers(1, 3))
    for k, i in enumerate(picks[: n_doors + n_windows]):
        a, b = edges[i]
        length = float(np.linalg.norm(b - a))
        w = DOOR_W_M if k < n_doors else WINDOW_W_M
        t = float(rng.uniform(0.2, length - w - 0.2))
        u = (b - a) / length
        seg = ((float((a + u * t)[0]), float((a + u * t)[1])), (float((a + u * (t + w))[0]), float((a + u * (t + w))[1])))
        if k < n_doors:
            doors.append(Door(id=f"d{k}", rooms=("r1", "outside"), segment=seg))
        else:
            windows.append(Window(id=f"w{k}", room="r1", segment=seg))
    room = Room(id="r1", name="room", type="living_room", polygon=poly)
    fp = Floorplan(rooms=[room], doors=doors, windows=windows, connections=[("r1", "outside")])
    spec = RoomSpec(id="r1", name="room", type="living_room", area_m2=area, height_m=2.7, open_air=False,
                    groups=room_groups(n_objects, rng))
    return fp, room, spec


@dataclass
class RoomResult:
    n_objects: int
    planned: int
    placed: int
    ms: float
    cpu_ms: float
    relations: list[Relation] = field(default_factory=list)


def run_room(n_objects: int, seed: int) -> RoomResult:
    rng = np.random.default_rng(seed)
    fp, room, spec = synthetic_room(n_objects, rng)
    st = RoomState(fp, room, spec, np.random.default_rng(seed), DEFAULT_OPTIONS)
    t0, c0 = time.perf_counter(), time.process_time()
    layout_solver.furnish_room(st)
    ms, cpu_ms = 1000 * (time.perf_counter() - t0), 1000 * (time.process_time() - c0)
    objs = st.space.objects
    rels = room_relations(spec.groups, objs, room.polygon)
    # planned less dropped: a kitchen run adds filler counters and cabinets beyond its plan
    return RoomResult(n_objects, n_objects, n_objects - len(st.dropped), ms, cpu_ms, rels)


def _pct(met: int, n: int) -> str:
    return f"{100 * met / n:.1f} % ({met}/{n})" if n else "-"


def table(results: list[RoomResult]) -> str:
    cols = [c for c in COUNTS if any(r.n_objects == c for r in results)]
    lines = ["| figure | " + " | ".join(f"{c} objects" for c in cols) + " | all |",
             "|---|" + "---|" * (len(cols) + 1)]
    buckets = [[r for r in results if r.n_objects == c] for c in cols] + [results]

    def row(label: str, fmt: Callable[[list[RoomResult]], str]) -> None:
        lines.append(f"| {label} | " + " | ".join(fmt(b) for b in buckets) + " |")

    row("rooms", lambda b: str(len(b)))
    row("items placed", lambda b: _pct(sum(r.placed for r in b), sum(r.planned for r in b)))
    row("**relations met (all kinds)**",
        lambda b: _pct(sum(x.met for r in b for x in r.relations), sum(len(r.relations) for r in b)))
    for k in KINDS:
        row(f"... {k}", lambda b, k=k: _pct(sum(x.met for r in b for x in r.relations if x.kind == k),
                                            sum(x.kind == k for r in b for x in r.relations)))
    row("layout ms per room, median", lambda b: f"{statistics.median(r.ms for r in b):.0f}")
    row("layout ms per room, max", lambda b: f"{max(r.ms for r in b):.0f}")
    row("layout CPU ms per room (process_time), median", lambda b: f"{statistics.median(r.cpu_ms for r in b):.0f}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rooms", type=int, default=8, help="rooms per object count")
    ap.add_argument("--seed", type=int, default=0, help="seed of the first room")
    ap.add_argument("--counts", default=",".join(map(str, COUNTS)), help="object counts, of 5,10,20,30")
    ap.add_argument("--out", default=None, help="write the markdown table here")
    ap.add_argument("--list", action="store_true", help="list every relation not met")
    args = ap.parse_args(argv)
    counts = [int(c) for c in args.counts.split(",")]
    if any(c not in COUNTS for c in counts):
        print(f"error: object counts are among {COUNTS}", file=sys.stderr)
        return 2
    results = []
    for c in counts:
        for k in range(args.rooms):
            results.append(run_room(c, args.seed + 1000 * c + k))
    md = table(results) + "\n"
    if args.list:
        for r in results:
            for x in r.relations:
                if not x.met:
                    md += f"\n- {r.n_objects} objects: {x.kind}: {x.item} -> {x.target}: {x.detail}"
        md += "\n"
    emit(md, args.out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
