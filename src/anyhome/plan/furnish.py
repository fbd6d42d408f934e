"""Furniture groups and ornaments for planned rooms, from ``knowledge/furniture.yaml``.

Groups and items are built as plain dicts (the fields of ``GroupSpec``/``ItemSpec``) so
that text mentions can adjust them before they are validated into the spec models.
"""

from __future__ import annotations

import copy
import math
import re
from typing import Any

import numpy as np

from anyhome.layout.rules import params_for, place_around
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import vocabulary
from anyhome.plan.openvocab import fallback_object
from anyhome.plan.parse import Mention
from anyhome.plan.spec import MAX_COUNT
from anyhome.tags import tags_by_name

SIZE_JITTER = 0.10
"""Relative spread of sampled item widths and depths (heights vary by half of it)."""

CHAIR_PITCH_M = 0.6
"""Table edge length each chair around it needs."""

MAX_TABLE_M = 8.0
"""Longest table the planner will stretch a table to for more chairs."""

ORNAMENT_RULES = ("place_top", "place_on_wall")
"""Rules an ornament may use."""

ZONE_PRIORITY = 7
"""Priority of a zone group: placed after every group of its room's own set."""

Item = dict[str, Any]
Group = dict[str, Any]

MENTIONED = "_mentioned"
"""Key of an item named by a text mention (the name it was given): another named
mention of the same kind gets an item of its own. Not a field of ``ItemSpec``."""


def _proto(kb: KnowledgeBase, use: str | None) -> dict[str, Any]:
    return kb.raw("objects").get(use, {}) if use else {}


def _sample(spec: Any, rng: np.random.Generator) -> int:
    if isinstance(spec, (list, tuple)):
        return int(rng.integers(int(spec[0]), int(spec[1]) + 1))
    return int(spec if spec is not None else 1)


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_") or "object"


def make_item(kb: KnowledgeBase, entry: dict[str, Any], rng: np.random.Generator, ornament: bool = False) -> Item:
    """An ItemSpec dict from a knowledge entry (``use`` prototype plus overrides)."""
    proto = _proto(kb, entry.get("use"))
    if entry.get("names"):
        name = str(entry["names"][int(rng.integers(len(entry["names"])))])
    else:
        name = str(entry.get("name") or entry.get("use") or entry.get("category") or "object")
    size = list(entry.get("size") or proto.get("size") or [0.5, 0.5, 0.5])
    j = rng.uniform(1 - SIZE_JITTER, 1 + SIZE_JITTER, size=3)
    j[2] = 1 + (j[2] - 1) / 2
    size = [float(np.clip(round(s * f, 3), 0.005, 20.0)) for s, f in zip(size, j)]
    rule = entry.get("rule") or proto.get("rule") or "place_center"
    if ornament and rule not in ORNAMENT_RULES:
        rule = "place_top"
    # the prototype's params for its own rule, kept where the item's rule takes them too
    params = params_for(rule, {**proto.get("params", {}), **entry.get("params", {})})
    target = entry.get("target", proto.get("target") if ornament else None)
    return {
        "name": name,
        "category": entry.get("category") or proto.get("category") or _slug(name),
        "description": entry.get("description", ""),
        "size_m": tuple(size),
        "rule": rule,
        "target": target,
        "params": params,
        "count": max(1, min(MAX_COUNT, _sample(entry.get("count", 1), rng))),
        "material": entry.get("material", ""),
        # the entry's own tags, else what its name means ("low altar" with use: cabinet is
        # an altar), else its prototype's; with none of these ItemSpec derives them
        "tags": list(entry.get("tags") or tags_by_name(name, kb) or proto.get("tags") or []) or None,
    }


def _merge(base: dict[str, Any], over: dict[str, Any]) -> dict[str, Any]:
    out = copy.deepcopy(base)
    for k, v in over.items():
        if k == "members":
            members = out.get("members", [])
            for i, mv in enumerate(v):
                if i < len(members):
                    members[i] = _override(members[i], mv)
                else:
                    members.append(mv)
            out["members"] = members
        elif k == "anchor":
            out["anchor"] = _override(out.get("anchor", {}), v)
            if "name" in v:
                out["anchor"].pop("names", None)
        elif k != "group":
            out[k] = v
    return out


def _override(item: dict[str, Any], over: dict[str, Any]) -> dict[str, Any]:
    """A template's item with a set's overrides; a new rule keeps only the params it takes."""
    out = {**item, **over}
    if "rule" in over and "params" not in over and "params" in item:
        out["params"] = params_for(over["rule"], item["params"])
    return out


def group_def(kb: KnowledgeBase, entry: dict[str, Any]) -> dict[str, Any]:
    """The group template named by ``entry['group']`` with the entry's overrides."""
    template = kb.raw("furniture")["groups"].get(entry.get("group", ""), {})
    d = _merge(template, entry)
    d.setdefault("key", entry.get("group", "group"))
    return d


def build_group(kb: KnowledgeBase, d: dict[str, Any], area_m2: float, rng: np.random.Generator) -> Group:
    anchor = make_item(kb, d["anchor"], rng)
    members = []
    for m in d.get("members", []):
        p = float(m.get("prob", 1.0))
        if p >= 1.0 or rng.random() < p:
            members.append(make_item(kb, m, rng))
    repeat = _sample(d.get("repeat", 1), rng)
    if d.get("per_m2"):
        lo, hi = d["repeat"] if isinstance(d.get("repeat"), list) else (1, max(1, repeat))
        repeat = int(np.clip(round(area_m2 / float(d["per_m2"])), lo, hi))
    g = {
        "name": d.get("key", "group"),
        "anchor": anchor,
        "members": members,
        "arrangement": d.get("arrangement", "free"),
        "repeat": max(1, min(MAX_COUNT, repeat)),
        "priority": int(d.get("priority", 0)),
        "required": False,
    }
    _fit_table(g)
    return g


def furniture_set(kb: KnowledgeBase, furnish: str, room_type: str) -> dict[str, Any]:
    sets = kb.raw("furniture")["sets"]
    return sets.get(furnish) or sets.get(room_type) or sets["other"]


def furnish_room(kb: KnowledgeBase, furnish: str, room_type: str, area_m2: float, rng: np.random.Generator, beds: int | None = None) -> tuple[list[Group], list[Item], list[dict[str, Any]]]:
    """Sampled groups and ornaments of one room, and the group templates left out."""
    s = furniture_set(kb, furnish, room_type)
    groups: list[Group] = []
    unused: list[dict[str, Any]] = []
    for entry in s.get("groups", []):
        if entry.get("one_of"):
            choices = entry["one_of"]
            entry = {**entry, "group": choices[int(rng.integers(len(choices)))]}
        d = group_def(kb, entry)
        p = float(entry.get("prob", 1.0))
        if p >= 1.0 or rng.random() < p:
            groups.append(build_group(kb, d, area_m2, rng))
        else:
            unused.append(d)
    if beds:
        for g in groups:
            if g["anchor"]["category"] in ("bed", "bunk_bed"):
                g["repeat"] = beds
                break
    ornaments = []
    for entry in s.get("ornaments", []):
        p = float(entry.get("prob", 1.0))
        if p >= 1.0 or rng.random() < p:
            ornaments.append(make_item(kb, entry, rng, ornament=True))
    return groups, ornaments, unused


def zone_groups(kb: KnowledgeBase, furnish: str, room_type: str, area_m2: float, groups: list[Group],
                rng: np.random.Generator) -> list[Group]:
    """The zones offered to a room (``fill`` groups, see :attr:`anyhome.plan.spec.GroupSpec.fill`):
    furniture.yaml ``zones:`` of its furnishing set when it lists them (``[]``: none, a
    prayer hall stays open), else of its type, each built once,
    leaving out the templates ``groups`` already has. The layout places them only while
    the room's floor is under-furnished (:mod:`anyhome.layout.fill`)."""
    zones = kb.raw("furniture").get("zones", {})
    entries = zones[furnish] if furnish in zones else zones.get(room_type, [])
    have = {g["name"] for g in groups}
    out = []
    for entry in entries:
        if entry.get("one_of"):
            choices = entry["one_of"]
            entry = {**entry, "group": choices[int(rng.integers(len(choices)))]}
        d = group_def(kb, entry)
        if d["key"] in have:
            continue
        g = build_group(kb, d, area_m2, rng)
        g["fill"] = True
        g["priority"] = ZONE_PRIORITY
        have.add(g["name"])
        out.append(g)
    return out


def _named_template(kb: KnowledgeBase, m: Mention) -> str | None:
    """The group template whose anchor is the mentioned object under the mentioned word
    (its ``use`` the mention's prototype, one of its names holding the word: "an island"
    is the ``island`` template's "kitchen island", a counter), if exactly one is."""
    if not m.key:
        return None
    word = m.name.split()[-1]
    hits = []
    for key, t in kb.raw("furniture")["groups"].items():
        a = t.get("anchor", {})
        names = a.get("names") or [a.get("name") or ""]
        if a.get("use") == m.key and any(word in _words(str(n)) for n in names) and word != m.key.split()[-1]:
            hits.append(key)
    return hits[0] if len(hits) == 1 else None


def _words(text: str) -> set[str]:
    return set(text.replace("_", " ").split())


def _matches(item: Item, category: str, head: str) -> int:
    """2: same category, 1: the head noun appears in its name or category, 0: no."""
    if item["category"] == category:
        return 2
    if head in _words(item["name"]) or head in _words(item["category"]):
        return 1
    return 0


def _find(groups: list[Group], category: str, head: str, loose: bool = True,
          names: tuple[str, ...] = ()) -> tuple[Group | None, Item | None]:
    """The best-matching item: same category before same head noun (only if ``loose``),
    anchors before members, and among equals the one named as the mention is (``names``:
    "a teacher's desk" is the teacher's desk, not the 24 student desks), then the one
    planned in the most copies."""
    for level in (2, 1) if loose else (2,):
        for members in (False, True):
            cands = [
                (g, it) for g in groups
                for it in (g["members"] if members else [g["anchor"]])
                if _matches(it, category, head) == level
            ]  # fmt: skip
            if cands:
                return max(cands, key=lambda c: (c[1]["name"] in names, c[0]["repeat"] * c[1]["count"]))
    return None, None


def _fit_table(g: Group) -> None:
    """Stretch a table so that the chairs placed around it fit."""
    for m in g["members"]:
        if m["rule"] != "place_around":
            continue
        w, d, h = g["anchor"]["size_m"]
        sides = place_around.Params.model_validate(m["params"]).sides

        def capacity(w: float, d: float = d, sides: str = sides) -> int:
            n = 2 * math.floor(w / CHAIR_PITCH_M)
            return n + (2 * math.floor(d / CHAIR_PITCH_M) if sides == "all" else 0)

        while capacity(w) < m["count"] and w < MAX_TABLE_M:
            w += CHAIR_PITCH_M
        g["anchor"]["size_m"] = (round(w, 3), d, h)


SEAT_WIDTH_M = 0.6
"""Width one sitter takes on a bench, a pew, a sofa or a banquette."""
LONG_SEATS = frozenset({"bench", "pew", "sofa", "banquette", "booth_seating", "settle"})
"""Seat categories that sit several side by side (seats: width / :data:`SEAT_WIDTH_M`)."""


def item_seats(item: Item) -> int:
    """People an item seats: 0 for no seat; a bench or a pew by its width."""
    tags = item.get("tags") or []
    if "seat" not in tags and item["category"] not in LONG_SEATS:
        return 0
    per = max(1, int(item["size_m"][0] / SEAT_WIDTH_M)) if item["category"] in LONG_SEATS else 1
    return per * int(item.get("count", 1))


def group_seats(g: Group) -> int:
    """People one copy of a group seats."""
    return item_seats(g["anchor"]) + sum(item_seats(m) for m in g["members"])


def seat(groups: list[Group], n: int) -> None:
    """Make a room's seating hold about ``n`` people ("a bistro for 40 covers", "a
    boardroom for 16"): one table group alone gets that many chairs round a longer table;
    otherwise every seating group's copies scale by the same factor (at least one each)."""
    seating = [g for g in groups if group_seats(g) > 0]
    if not seating or n < 1:
        return
    if len(seating) == 1 and seating[0]["repeat"] == 1 and n <= MAX_TABLE_SEATS:
        g = seating[0]
        chairs = [m for m in g["members"] if m["rule"] == "place_around" and item_seats(m)]
        if chairs:
            chairs[0]["count"] = max(1, n - (group_seats(g) - item_seats(chairs[0])))
            _fit_table(g)
            return
    # the repeated groups (tables, pews, desks) take the count; a bar or a sofa stays one
    scaled = [g for g in seating if g["repeat"] > 1] or [max(seating, key=group_seats)]
    fixed = sum(group_seats(g) * g["repeat"] for g in seating if not any(g is x for x in scaled))
    have = sum(group_seats(g) * g["repeat"] for g in scaled)
    factor = max(n - fixed, 1) / have
    for g in scaled:
        g["repeat"] = max(1, min(MAX_COUNT, round(g["repeat"] * factor)))


MAX_TABLE_SEATS = 24
"""Most people one table seats when a room's count goes to its one table."""


def mention_count(m: Mention, proto: dict[str, Any], rng: np.random.Generator) -> int | None:
    """Copies the text asks for: its number, a plural's range, or None if unsaid."""
    if m.count is not None:
        return m.count
    if m.plural or m.many:
        lo, hi = proto.get("plural", [2, 4])
        return int(hi) if m.many else int(rng.integers(lo, hi + 1))
    return None


def apply_mention(kb: KnowledgeBase, m: Mention, groups: list[Group], ornaments: list[Item], unused: list[dict[str, Any]], area_m2: float, rng: np.random.Generator) -> None:
    """Make a room hold what the text asks for (adjusting or adding groups)."""
    proto = _proto(kb, m.key) if m.key else fallback_object(kb)
    category = proto.get("category", _slug(m.key or m.name.split()[-1]))
    head = (m.key or m.name).split()[-1]
    n = mention_count(m, proto, rng)
    if n == 0:
        groups[:] = [g for g in groups if _matches(g["anchor"], category, head) < 2]
        ornaments[:] = [o for o in ornaments if o["category"] != category]
        return
    if m.seat_of is not None and _seat_at_table(kb, m, proto, category, n, groups, rng):
        return
    named = m.name != m.key
    if proto.get("ornament"):
        _apply_ornament(kb, m, proto, category, head, n, groups, ornaments, unused, area_m2, rng)
        return
    # a one-word name ("table") may stand for any table; "bunk bed" only for bunk beds
    g, item = _find(groups, category, head, loose=" " not in (m.key or m.name), names=(m.name, m.key or m.name))
    named_group = _named_template(kb, m)
    if (g is not None and item is not None and named_group not in (None, g["name"])
            and m.name.split()[-1] not in _words(item["name"])):
        g = None  # "an island": the template named so, not the kitchen run's counter
    if item is not None and named and item.get(MENTIONED, m.name) != m.name:
        g = None  # "a blanket chest and a steamer trunk": two boxes, not one renamed twice
    if g is None:
        d = next((u for u in unused if _matches(u_anchor(kb, u), category, head) and _same_kind(kb, u, m)), None)
        if d is None and named_group is not None:
            d = group_def(kb, {"group": named_group})
        if d is None and proto.get("group"):
            d = group_def(kb, {"group": proto["group"]})
        if d is None and m.key:
            d = {"key": _slug(m.key), "anchor": {"use": m.key}}
        if d is None:
            d = {"key": _slug(m.name), "anchor": {**proto, "name": m.name, "category": category}}
        g = build_group(kb, d, area_m2, rng)
        groups.append(g)
        g2, item = _find([g], category, head)
        item = item or g["anchor"]
        if n is None and item is g["anchor"]:
            g["repeat"] = 1 if not m.plural else g["repeat"]
    assert item is not None  # _find gives a group and its item, or neither
    g["required"] = True
    g["priority"] = min(g["priority"], 0)
    if named:
        item["name"] = m.name
        item[MENTIONED] = m.name
    if m.words and vocabulary(kb).material_regex.search(" ".join(m.words)):  # "an orange tartan sofa"
        item["material"] = " ".join(m.words)
    if m.size != 1.0:
        item["size_m"] = tuple(round(min(20.0, s * m.size), 3) for s in item["size_m"])
    # a member of the group made for it (its objects.yaml group: a chair at a styling
    # station) is counted in copies of the group: three barber chairs, three stations
    per_group = item is not g["anchor"] and proto.get("group") == g["name"] and item["count"] == 1
    if n is not None and m.count is not None:
        if item is g["anchor"] or per_group:
            g["repeat"] = max(1, min(MAX_COUNT, n))
        else:
            item["count"] = max(1, min(MAX_COUNT, math.ceil(n / g["repeat"])))
    elif n is not None and g["repeat"] * item["count"] < n:
        if item is g["anchor"] or per_group:
            g["repeat"] = max(1, min(MAX_COUNT, n))
        else:
            item["count"] = max(1, min(MAX_COUNT, math.ceil(n / g["repeat"])))
    _arrange(m, g, item)
    _fit_table(g)


LONG_TABLE_MIN_M = 1.8
"""A table with a bench down each side is at least this long."""
BENCH_TABLE_MAX_H_M = 0.76
"""... and no higher than a dining table (a bar-height "long table" is lowered)."""


def _seat_at_table(kb: KnowledgeBase, m: Mention, proto: dict[str, Any], category: str, n: int | None,
                   groups: list[Group], rng: np.random.Generator) -> bool:
    """"A long oak table with benches down both sides": the seats round the table the text
    named (``m.seat_of``) become these, in place of the chairs its group planned (benches
    along its two long sides, as long as the table). False: the text's own table or its
    seats are not found, or they are already of this kind (the usual path counts them)."""
    table = m.seat_of
    assert table is not None
    g = next((g for g in groups if g["anchor"].get(MENTIONED) == table.name), None)
    if g is None:
        tproto = _proto(kb, table.key)
        g, item = _find(groups, tproto.get("category", ""), (table.key or table.name).split()[-1], loose=False)
        if g is None or item is not g["anchor"]:
            return False
    seats = [x for x in g["members"] if x["rule"] in SEATED_AT_RULES and item_seats(x)]
    if not seats or any(x["category"] == category for x in seats):
        return False
    old = seats[0]
    new = make_item(kb, {"use": m.key, "name": m.name}, rng)
    long_seat = category in LONG_SEATS
    new["rule"] = "place_around"
    new["params"] = {"sides": "long"} if long_seat else old["params"]
    if long_seat:  # a bench as long as the table, one each side, at a table sat at from a bench
        w, d, h = g["anchor"]["size_m"]
        w = max(w, LONG_TABLE_MIN_M)
        g["anchor"]["size_m"] = (w, d, min(h, BENCH_TABLE_MAX_H_M))
        new["size_m"] = (round(max(new["size_m"][0], 0.9 * w), 3), *new["size_m"][1:])
        new["count"] = min(2, n or 2)
    else:
        new["count"] = max(1, min(MAX_COUNT, n or old["count"]))
    new[MENTIONED] = m.name
    g["members"] = [new if x is old else x for x in g["members"] if x is old or x not in seats]
    g["required"] = True
    g["priority"] = min(g["priority"], 0)
    if not long_seat:
        _fit_table(g)
    return True


SEATED_AT_RULES = frozenset({"place_around", "place_front"})
"""Rules of a seat used at its group's table or desk (a dining chair, a desk chair)."""
DESK_MIN_H_M = 0.65
"""A table or desk this high or higher is sat at on a chair (a zabuton goes round a low
table or a side table, not a dining table kept at its height)."""
LOW_TABLE_MAX_H_M = 0.5
"""A table at most this high is sat at from the floor: only there does a period look
(``eastern``) swap a chair for a floor seat."""
FLOOR_SEAT_MAX_H_M = 0.3
"""A seat prototype at most this high is a floor seat (a zabuton, a floor chair)."""


def _floor_seat(proto: dict[str, Any]) -> bool:
    size = proto.get("size") or (1.0, 1.0, 1.0)
    return "seat" in (proto.get("tags") or []) and float(size[2]) <= FLOOR_SEAT_MAX_H_M


def period_rules(kb: KnowledgeBase, styles: list[str]) -> tuple[dict[str, Any], set[str]]:
    """The stand-ins and the names left out (styles.yaml ``period``) for the look led by
    ``styles``: those of every trait of its asset class (the class the assets are drawn in)."""
    from anyhome.assets.styles import style_class

    period = kb.raw("styles").get("period") or {}
    swap: dict[str, Any] = {}
    drop: set[str] = set()
    for trait in sorted(style_class(styles, kb).traits):
        rules = period.get(trait) or {}
        swap.update(rules.get("swap", {}))
        drop.update(rules.get("drop", []))
    return swap, drop


def apply_period(kb: KnowledgeBase, groups: list[Group], ornaments: list[Item], styles: list[str],
                 asked: set[str], building_swap: dict[str, Any] | None = None) -> None:
    """A period look keeps period objects: a modern item the text did not ask for
    (``asked``: the names and keys of the text's objects) takes its stand-in (an office
    chair at a Victorian desk is a side chair) or is left out (a monitor, a TV). The
    building's own stand-ins (programs.yaml ``swap``: a hotel's desk chair) come first."""
    swap, drop = period_rules(kb, styles)
    swap = {**swap, **(building_swap or {})}
    if not swap and not drop:
        return

    def gone(it: Item) -> bool:
        return it["name"] in drop and it["name"] not in asked

    for g in groups:
        for it in [g["anchor"], *g["members"]]:
            new = swap.get(it["name"])
            if new is None or it["name"] in asked:
                continue
            proto = _proto(kb, new["use"])
            if (it is not g["anchor"] and _floor_seat(proto) and it["rule"] in SEATED_AT_RULES
                    and g["anchor"]["size_m"][2] >= DESK_MIN_H_M and "low" not in _words(g["anchor"]["name"])):
                continue  # a zabuton at a standing reception desk: the chair stays (a lounge chair need not)
            it["name"], it["category"] = new["name"], proto.get("category", it["category"])
            w, d, h = proto.get("size", it["size_m"])
            it["size_m"] = (float(w), float(d), float(h))
            it["tags"] = list(proto.get("tags", it.get("tags", [])))
        g["members"] = [m for m in g["members"] if not gone(m)]
    groups[:] = [g for g in groups if g["required"] or not gone(g["anchor"])]
    ornaments[:] = [o for o in ornaments if not gone(o)]


def drop_unasked_beds(groups: list[Group]) -> None:
    """"A bedroom with a bunk bed": the bed the text asks for replaces the one the room's
    set planned, rather than standing beside it. Run after all the room's mentions."""
    def is_bed(g: Group) -> bool:
        return "bed" in (g["anchor"].get("tags") or [])

    if any(g["required"] and is_bed(g) for g in groups):
        groups[:] = [g for g in groups if g["required"] or not is_bed(g)]


def remove_mention(kb: KnowledgeBase, m: Mention, groups: list[Group], ornaments: list[Item]) -> bool:
    """Take out of a room what the text rules out ("no tv", "without a rug"): groups
    whose anchor it names, members and ornaments it names. True if anything went."""
    proto = _proto(kb, m.key) if m.key else {}
    category = proto.get("category", _slug(m.key or m.name.split()[-1]))
    head = (m.key or m.name).split()[-1]
    level = 1 if " " not in (m.key or m.name) else 2  # "no lamp": any lamp; "no floor lamp": that one

    def named(it: Item) -> bool:
        return _matches(it, category, head) >= level

    before = (len(groups), sum(len(g["members"]) for g in groups), len(ornaments))
    groups[:] = [g for g in groups if not named(g["anchor"])]
    for g in groups:
        g["members"] = [it for it in g["members"] if not named(it)]
    ornaments[:] = [o for o in ornaments if not named(o)]
    return before != (len(groups), sum(len(g["members"]) for g in groups), len(ornaments))


def object_count(groups: list[Group], ornaments: list[Item]) -> int:
    """Objects a room's plan places: every copy of every group item and ornament."""
    return sum(g["repeat"] * (g["anchor"]["count"] + sum(it["count"] for it in g["members"])) for g in groups) + sum(
        o["count"] for o in ornaments
    )


def cap_objects(rooms: list[tuple[list[Group], list[Item]]], budget: int) -> dict[tuple[int, str], tuple[int, int]]:
    """Plan fewer copies until ``rooms`` (groups and ornaments of one or more rooms)
    hold at most ``budget`` objects: the most repeated item loses a copy first, so that
    items asked in equal numbers stay equal; if every item is down to one copy, groups
    the text did not ask for and then ornaments go. Returns, per (room index, item name),
    the copies (before, after) of what was cut."""
    total = sum(object_count(g, o) for g, o in rooms)
    if total <= budget:
        return {}
    before: dict[tuple[int, str], int] = {}
    for i, (groups, ornaments) in enumerate(rooms):
        for g in groups:
            for it in [g["anchor"], *g["members"]]:
                before.setdefault((i, it["name"]), 0)
                before[(i, it["name"])] += g["repeat"] * it["count"]
        for o in ornaments:
            before[(i, o["name"])] = before.get((i, o["name"]), 0) + o["count"]
    while total > budget:
        # (copies of one kind of object, objects one copy less removes, how to remove it)
        best: tuple[int, int, Any] | None = None
        for groups, ornaments in rooms:
            for g in groups:
                per_copy = g["anchor"]["count"] + sum(it["count"] for it in g["members"])
                cands = [(g["repeat"] * g["anchor"]["count"], per_copy, ("repeat", g))] if g["repeat"] > 1 else []
                cands += [(g["repeat"] * it["count"], g["repeat"], ("count", it)) for it in [g["anchor"], *g["members"]] if it["count"] > 1]
                for c in cands:
                    if best is None or c[:2] > best[:2]:
                        best = c
            for o in ornaments:
                if o["count"] > 1 and (best is None or (o["count"], 1) > best[:2]):
                    best = (o["count"], 1, ("count", o))
        if best is None:
            break
        kind, obj = best[2]
        if kind == "repeat":
            obj["repeat"] -= 1
        else:
            obj["count"] -= 1
        total -= best[1]
    for groups, ornaments in rooms:  # every item is down to one copy: drop what was not asked for
        for g in sorted((g for g in groups if not g["required"]), key=lambda g: -g["priority"]):
            if total <= budget:
                break
            groups.remove(g)
            total -= object_count([g], [])
        while ornaments and total > budget:
            total -= ornaments.pop()["count"]
    after: dict[tuple[int, str], int] = {}
    for i, (groups, ornaments) in enumerate(rooms):
        for g in groups:
            for it in [g["anchor"], *g["members"]]:
                after[(i, it["name"])] = after.get((i, it["name"]), 0) + g["repeat"] * it["count"]
        for o in ornaments:
            after[(i, o["name"])] = after.get((i, o["name"]), 0) + o["count"]
    return {k: (n, after.get(k, 0)) for k, n in before.items() if after.get(k, 0) < n}


def _same_kind(kb: KnowledgeBase, d: dict[str, Any], m: Mention) -> bool:
    """Whether a set's unused group ``d`` can hold mention ``m``: any group of its
    category for a one-word key ("a table"), else a group of that very prototype (a den's
    "pool table" is no dining table with chairs)."""
    if not m.key or " " not in m.key:
        return True
    return d.get("anchor", {}).get("use") == m.key or m.key in u_anchor(kb, d)["name"]


def u_anchor(kb: KnowledgeBase, d: dict[str, Any]) -> Item:
    a = d.get("anchor", {})
    proto = _proto(kb, a.get("use"))
    name = a.get("name") or (a.get("names") or [a.get("use", "")])[0]
    return {"name": name, "category": a.get("category") or proto.get("category", "")}


def _arrange(m: Mention, g: Group, item: Item) -> None:
    if m.arrangement is None:
        return
    if m.arrangement == "around":
        if item is not g["anchor"]:
            _set_rule(item, "place_around")
            item["target"] = None
        return
    if item is not g["anchor"] and m.arrangement != "rows":
        return
    g["arrangement"] = m.arrangement
    anchor = g["anchor"]
    if m.arrangement == "along_walls":
        _set_rule(anchor, "place_next_wall")
    elif m.arrangement == "center":
        _set_rule(anchor, "place_center")
    elif m.arrangement == "rows" and anchor["rule"] in ("place_wall", "place_next_wall", "place_corner"):
        _set_rule(anchor, "place_center")


def _set_rule(item: dict[str, Any], rule: str) -> None:
    """Give ``item`` another rule, keeping only the params that rule takes."""
    item["rule"] = rule
    item["params"] = params_for(rule, item.get("params", {}))


WALL_MOUNT_FROM = 3
"""From this many copies, an object that may hang (``wall_mount_m`` in objects.yaml) goes on
the walls instead of on top of furniture."""


def _apply_ornament(kb: KnowledgeBase, m: Mention, proto: dict[str, Any], category: str, head: str, n: int | None, groups: list[Group], ornaments: list[Item], unused: list[dict[str, Any]], area_m2: float, rng: np.random.Generator) -> None:
    found = next((o for o in ornaments if _matches(o, category, head) == 2), None)
    if found is None:
        found = next((o for o in ornaments if _matches(o, category, head) == 1), None)
    if found is None:
        found = make_item(kb, {"use": m.key}, rng, ornament=True)
        ornaments.insert(0, found)
    if m.name != m.key:
        found["name"] = m.name
    if n is not None:
        found["count"] = max(1, min(MAX_COUNT, n))
    if proto.get("wall_mount_m") and found["count"] >= WALL_MOUNT_FROM:  # "twelve TVs along the walls"
        found["rule"], found["target"] = "place_on_wall", None
        found["params"] = {"elevation_m": float(proto["wall_mount_m"])}
        return
    target = found.get("target")
    if target and not _has_target(groups, target):  # "tv stand" or "tv_stand"
        if proto.get("group"):
            g = build_group(kb, group_def(kb, {"group": proto["group"]}), area_m2, rng)
            g["required"] = True
            groups.append(g)
            ornaments.remove(found)
            for it in g["members"]:
                if it["category"] == category:
                    it["name"], it["count"] = found["name"], found["count"]
        else:
            found["target"] = None


def _has_target(groups: list[Group], target: str) -> bool:
    t = target.replace("_", " ")
    for g in groups:
        for it in [g["anchor"], *g["members"]]:
            if it["name"] == t or it["category"] == target or it["category"] == t.replace(" ", "_"):
                return True
    return False


def join_groups(kb: KnowledgeBase, groups: list[Group]) -> None:
    """Groups that join another (furniture.yaml ``join:``) become its members when the
    room has it: the anchor is placed relative to the host's anchor (its ``target``), the
    members as before. A TV asked for in a room with a sofa group goes with that group, so
    the sofa is placed where the wall ahead can take the TV."""
    templates = kb.raw("furniture")["groups"]
    for g in list(groups):
        joins = templates.get(g["name"], {}).get("join", [])
        host = next((h for key in joins for h in groups if h is not g and h["name"] == key), None)
        if host is None:
            continue
        host["members"] = [*host["members"], {**g["anchor"], "target": host["anchor"]["name"]}, *g["members"]]
        host["required"] = host["required"] or g["required"]
        groups.remove(g)


def finalize_ornaments(groups: list[Group], ornaments: list[Item]) -> list[Item]:
    """Drop or loosen ornaments whose support is not in the room."""
    out = []
    for o in ornaments:
        if o["target"] and not _has_target(groups, o["target"]):
            if o["category"] == "tv" and o["rule"] == "place_top":
                continue
            o["target"] = None
        out.append(o)
    return out
