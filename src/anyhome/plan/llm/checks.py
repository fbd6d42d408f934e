"""The plan's own sanity rules, applied to a reply that already matches its schema.

Each check returns a list of errors, one short line each, quoted back to the model in
the repair request; an empty list means the reply is usable. The knowledge they read is
the one passed in (the planner's), never a module-level load.

A parameter value wrong for its rule (``"facing": "up"``) is refused earlier, by the
reply's model (:mod:`.schemas`: each rule's ``params`` is that rule's parameters model),
and gets the same repair request.
"""

from __future__ import annotations

from collections import deque

from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.llm.schemas import FurnitureReply, ItemReply, OrnamentsReply, ProgramReply
from anyhome.plan.spec import MAX_COUNT, RELATIVE_RULES

ROOM_AREA_M2 = (1.5, 300.0)
"""Smallest and largest floor area of any planned room."""
AREA_SLACK = (0.35, 4.0)
"""A room may be this much smaller / larger than its type's usual range (rooms.yaml)."""
ITEM_SIDE_M = (0.03, 8.0)
"""Smallest and largest side of a furniture box."""
ORNAMENT_SIDE_M = (0.02, 2.5)
MAX_FOOTPRINT_SHARE = 0.6
"""No single item may cover more of the room's floor than this."""
MAX_OBJECTS_PER_M2 = 3.0
"""Most floor objects (copies included) per m2 of room: more is a looping model."""


def type_area_m2(kb: KnowledgeBase, room_type: str) -> tuple[float, float]:
    types = kb.rooms.types
    lo, hi = (types.get(room_type) or types["other"]).area
    return max(ROOM_AREA_M2[0], lo * AREA_SLACK[0]), min(ROOM_AREA_M2[1], hi * AREA_SLACK[1])


def check_program(reply: ProgramReply, kb: KnowledgeBase) -> list[str]:
    errors: list[str] = []
    ids = [r.id for r in reply.rooms]
    dupes = sorted({i for i in ids if ids.count(i) > 1})
    if dupes:
        errors.append(f"room ids must be unique; repeated: {', '.join(dupes)}")
    for i, r in enumerate(reply.rooms):
        lo, hi = type_area_m2(kb, r.type)
        if not lo <= r.area_m2 <= hi:
            errors.append(f"rooms[{i}] ({r.id}): area_m2 {r.area_m2:g} is implausible for a {r.type}; use {lo:g} to {hi:g}")
    known = set(ids)
    edges: list[tuple[str, str]] = []
    for i, (a, b) in enumerate(reply.connections):
        bad = [x for x in (a, b) if x not in known and x != "outside"]
        if bad:
            errors.append(f"connections[{i}]: unknown room id {bad[0]!r}; use ids from rooms")
        elif a == b:
            errors.append(f"connections[{i}]: a room cannot connect to itself ({a})")
        elif "outside" not in (a, b):
            edges.append((a, b))
    if reply.entrance not in known:
        errors.append(f"entrance {reply.entrance!r} is not a room id; use one of {', '.join(ids)}")
    elif not dupes:
        lost = _unreachable(reply.entrance, ids, edges)
        if lost:
            errors.append(f"rooms not reachable from the entrance through connections: {', '.join(lost)}")
    return errors


def _unreachable(start: str, ids: list[str], edges: list[tuple[str, str]]) -> list[str]:
    seen, todo = {start}, deque([start])
    while todo:
        cur = todo.popleft()
        for a, b in edges:
            for x, y in ((a, b), (b, a)):
                if x == cur and y not in seen:
                    seen.add(y)
                    todo.append(y)
    return [i for i in ids if i not in seen]


def _size_errors(where: str, it: ItemReply, side_m: tuple[float, float], room_area_m2: float) -> list[str]:
    errors = []
    lo, hi = side_m
    if not all(lo <= s <= hi for s in it.size_m):
        errors.append(f"{where} ({it.name}): size_m {it.size_m} must be meters, each side {lo:g} to {hi:g}")
    elif it.size_m[0] * it.size_m[1] > MAX_FOOTPRINT_SHARE * room_area_m2:
        errors.append(f"{where} ({it.name}): {it.size_m[0]:g} x {it.size_m[1]:g} m is too big for a {room_area_m2:g} m2 room")
    return errors


def check_furniture(reply: FurnitureReply, room_area_m2: float) -> list[str]:
    errors: list[str] = []
    floor_objects = 0
    for gi, g in enumerate(reply.groups):
        where = f"groups[{gi}]"
        errors += _size_errors(f"{where}.anchor", g.anchor, ITEM_SIDE_M, room_area_m2)
        names = {g.anchor.name.lower(), g.anchor.category.lower()}
        for mi, m in enumerate(g.members):
            errors += _size_errors(f"{where}.members[{mi}]", m, ITEM_SIDE_M, room_area_m2)
            if m.rule in RELATIVE_RULES and m.target and m.target.lower() not in names:
                errors.append(f"{where}.members[{mi}] ({m.name}): target {m.target!r} is not an item of this group; use the anchor's name or \"\"")
            names |= {m.name.lower(), m.category.lower()}
        copies = g.repeat * (g.anchor.count + sum(m.count for m in g.members if m.rule not in ("place_top", "place_on_wall")))
        floor_objects += copies
        if g.repeat * max([g.anchor.count, *(m.count for m in g.members)]) > MAX_COUNT:
            errors.append(f"{where}: more than {MAX_COUNT} copies of one item")
    if floor_objects > MAX_OBJECTS_PER_M2 * room_area_m2:
        errors.append(f"{floor_objects} floor objects cannot fit a {room_area_m2:g} m2 room")
    return errors


def check_ornaments(reply: OrnamentsReply, room_objects: set[str]) -> list[str]:
    """``room_objects``: lower-case names and categories of the room's furniture."""
    errors: list[str] = []
    for i, o in enumerate(reply.ornaments):
        where = f"ornaments[{i}] ({o.name})"
        lo, hi = ORNAMENT_SIDE_M
        if not all(lo <= s <= hi for s in o.size_m):
            errors.append(f"{where}: size_m {o.size_m} must be meters, each side {lo:g} to {hi:g}")
        if o.target and o.target.lower() not in room_objects:
            errors.append(f"{where}: target {o.target!r} is not furniture of this room; use one of: {', '.join(sorted(room_objects)) or 'none'}, or \"\"")
        if o.rule == "place_top" and not o.target and not room_objects:
            errors.append(f"{where}: place_top needs furniture to stand on")
    return errors


def check_appearance(room_ids: set[str], looked: list[str]) -> list[str]:
    return [f"rooms: unknown room id {i!r}; use ids from: {', '.join(sorted(room_ids))}" for i in looked if i not in room_ids]
