"""Benchmark: ``anyhome.evaluate`` on many objects and on a huge room.

Usage: .venv/bin/python benchmarks/eval_scale.py [--cases spread-1000,stacked-10000,...]
                                                 [--timeout 120]

Cases (each runs in its own Python process, so a crash or a timeout is recorded, not fatal):

* ``spread-N``: a 10 x 10 grid of 9.5 m rooms joined by doors, an entrance and a window
  per room, boxes on a 0.85 m grid in every room (a navigable, valid house), and as many
  lamps standing on boxes as needed to reach N objects.
* ``stacked-N``: one 6 x 6 m room with N identical boxes at the same place (every pair
  collides: the worst case of rule 2).
* ``tower-N``: one room with N boxes stacked on top of each other (every footprint
  overlaps, no two boxes overlap in z).
* ``km-room``: one 1 km x 1 km room with a chair (the navigation raster at 5 cm would
  need 20,004^2 cells).

Prints one row per case: objects, seconds for ``evaluate_house``, violations, whether
the house is valid, the peak resident memory of the process (MB) and the exit status.
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time

DEFAULT_CASES = ("spread-1000", "stacked-1000", "spread-10000", "stacked-10000",
                 "tower-10000", "km-room")
ROOM_M = 9.5
MATERIALS = {"floor": "oak planks", "walls": "white paint"}
GRID = 10


def _house(rooms, doors, windows, objects, connections):
    from anyhome.house import House

    return House(prompt="eval scale benchmark", seed=0, rooms=rooms, doors=doors,
                 windows=windows, objects=objects, connections=connections)


def _box(oid, room, x, y, z=0.0, size=(0.3, 0.3, 0.8), support="floor", category="box"):
    from anyhome.house import HouseObject

    return HouseObject(id=oid, room=room, name=category, category=category,
                       position=(x, y, z), size=size, support=support)


def spread_house(n: int):
    from anyhome.house import Door, Room, Window

    rooms, doors, windows, connections = [], [], [], []
    for r in range(GRID):
        for c in range(GRID):
            x, y, rid = c * ROOM_M, r * ROOM_M, f"r{r}-{c}"
            rooms.append(Room(id=rid, name="office", type="office",
                              polygon=[(x, y), (x + ROOM_M, y), (x + ROOM_M, y + ROOM_M),
                                       (x, y + ROOM_M)], materials=MATERIALS))
            mid = ROOM_M / 2
            if c > 0:
                doors.append(Door(id=f"dx{r}-{c}", rooms=(f"r{r}-{c - 1}", rid),
                                  segment=((x, y + mid - 0.5), (x, y + mid + 0.5))))
                connections.append((f"r{r}-{c - 1}", rid))
            if r > 0:
                doors.append(Door(id=f"dy{r}-{c}", rooms=(f"r{r - 1}-{c}", rid),
                                  segment=((x + mid - 0.5, y), (x + mid + 0.5, y))))
                connections.append((f"r{r - 1}-{c}", rid))
            # a window on an exterior wall where there is one, else the room needs none
            if r == 0:
                windows.append(Window(id=f"w{r}-{c}", room=rid,
                                      segment=((x + 1.5, y), (x + 2.5, y))))
            elif r == GRID - 1:
                windows.append(Window(id=f"w{r}-{c}", room=rid,
                                      segment=((x + 2.5, y + ROOM_M), (x + 1.5, y + ROOM_M))))
            elif c == 0:
                windows.append(Window(id=f"w{r}-{c}", room=rid,
                                      segment=((x, y + 2.5), (x, y + 1.5))))
            elif c == GRID - 1:
                windows.append(Window(id=f"w{r}-{c}", room=rid,
                                      segment=((x + ROOM_M, y + 1.5), (x + ROOM_M, y + 2.5))))
            else:
                rooms[-1] = rooms[-1].model_copy(update={"type": "storage", "name": "store"})
    doors.append(Door(id="entrance", rooms=("r0-0", "outside"),
                      segment=((ROOM_M / 2 - 0.5, 0), (ROOM_M / 2 + 0.5, 0))))
    connections.append(("r0-0", "outside"))
    steps = [1.0 + 0.85 * k for k in range(int((ROOM_M - 2.0) / 0.85) + 1)]
    spots = [(sx, sy) for sx in steps for sy in steps]
    boxes = []
    for room in rooms:
        x0, y0 = room.polygon[0]
        for k, (sx, sy) in enumerate(spots):
            boxes.append(_box(f"{room.id}-b{k}", room.id, x0 + sx, y0 + sy))
    objects = boxes[:n]
    k = 0
    while len(objects) < n:
        b = boxes[k % len(boxes)]
        objects.append(_box(f"lamp{k}", b.room, b.position[0], b.position[1], 0.8,
                            size=(0.2, 0.2, 0.4), support=b.id, category="table_lamp"))
        k += 1
    return _house(rooms, doors, windows, objects, connections)


def one_room(size_m: float, objects):
    from anyhome.house import Door, Room, Window

    room = Room(id="R", name="hall", type="hall",
                polygon=[(0, 0), (size_m, 0), (size_m, size_m), (0, size_m)],
                materials=MATERIALS)
    door = Door(id="d", rooms=("R", "outside"), segment=((0.5, 0), (1.5, 0)))
    win = Window(id="w", room="R", segment=((size_m, 1), (size_m, 2)))
    return _house([room], [door], [win], objects, [("R", "outside")])


def stacked_house(n: int):
    return one_room(6.0, [_box(f"o{k}", "R", 3.0, 3.0, size=(0.5, 0.5, 0.8)) for k in range(n)])


def tower_house(n: int):
    objs = [_box("o0", "R", 3.0, 3.0, size=(0.5, 0.5, 0.01))]
    for k in range(1, n):
        objs.append(_box(f"o{k}", "R", 3.0, 3.0, 0.01 * k, size=(0.5, 0.5, 0.01),
                         support=f"o{k - 1}"))
    return one_room(6.0, objs)


def build(case: str):
    if case == "km-room":
        return one_room(1000.0, [_box("chair", "R", 500.0, 500.0)])
    kind, n = case.rsplit("-", 1)
    return {"spread": spread_house, "stacked": stacked_house, "tower": tower_house}[kind](int(n))


def run_case(case: str) -> dict:
    from anyhome.evaluate import evaluate_house

    house = build(case)
    t0 = time.perf_counter()
    report = evaluate_house(house)
    seconds = time.perf_counter() - t0
    notes = [v.message for v in report.violations if v.rule == "limits"][:2]
    return {"case": case, "objects": len(house.objects), "seconds": seconds,
            "violations": len(report.violations), "ok": report.ok,
            "codes": sorted(report.codes()),
            "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
            "notes": notes}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", default=",".join(DEFAULT_CASES))
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per case")
    ap.add_argument("--one", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.one:
        print(json.dumps(run_case(args.one)))
        return 0
    print("| case | objects | eval s | violations | valid | peak MB | exit | codes |")
    print("|---|---|---|---|---|---|---|---|")
    for case in args.cases.split(","):
        t0 = time.perf_counter()
        try:
            proc = subprocess.run([sys.executable, __file__, "--one", case], capture_output=True,
                                  text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            print(f"| {case} | | > {args.timeout:.0f} (killed) | | | | timeout | |", flush=True)
            continue
        if proc.returncode != 0:
            last = (proc.stderr.strip().splitlines() or [""])[-1][:80]
            print(f"| {case} | | {time.perf_counter() - t0:.1f} (whole process) | | | | "
                  f"{proc.returncode} | {last} |", flush=True)
            continue
        r = json.loads(proc.stdout.strip().splitlines()[-1])
        codes = ", ".join(r["codes"][:6])
        print(f"| {case} | {r['objects']} | {r['seconds']:.2f} | {r['violations']} | "
              f"{'yes' if r['ok'] else 'no'} | {r['peak_mb']:.0f} | 0 | {codes} |", flush=True)
        for note in r.get("notes", []):
            print(f"|   | note: {note} | | | | | | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
