"""Room program and bubble diagram for the offline planner.

``plan_rooms`` decides which rooms the house has (from the building program, the rooms
the text names and the counts it gives) and ``connect`` links them into a connected
bubble diagram with one entrance.
"""

from __future__ import annotations

import math
import re
import unicodedata
import zlib
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from anyhome.errors import PlanError
from anyhome.house import ROOM_TYPES
from anyhome.plan.concepts import furnish_type
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import is_dwelling
from anyhome.plan.parse import ORDINAL_FLOORS, Mention, Parsed, format_count, plural
from anyhome.plan.spec import MAX_COUNT, MAX_ROOMS

HUB_MAX_DEGREE = 6
"""Most connections (entrance included) a hub room (hallway, living room...) may hold."""

ROOM_MAX_DEGREE = 2
"""Most connections a non-hub room may hold: its parent and one room behind it (two
sub-rooms of a non-hub room often cannot both share its walls in the spine layout)."""

DEFAULT_PROGRAM = "home"
"""Program used when the text names no building and no room."""

HOME_TYPES = frozenset({"bedroom", "bathroom", "kitchen", "living_room"})
"""Room types that turn a list of named rooms into a home."""

AREA_LIMITS_M2 = (1.5, 120.0)
"""Smallest and largest planned room area."""


@dataclass
class Slot:
    """One planned room before it becomes a RoomSpec."""

    name: str
    type: str
    furnish: str
    area_range: tuple[float, float]
    key: str = ""  # program room key
    mention: int | None = None  # index into Parsed.rooms that named it
    generic_name: bool = True  # the name is the program's default
    size: float = 1.0
    beds: int | None = None  # beds to plan (family sizes)
    id: str = ""
    area: float = 0.0
    drawn_area: float = 0.0  # the area drawn from the room's range, before furniture grew it
    optional: bool = False
    extra_groups: list[str] = field(default_factory=list)
    level: int = 0  # storey: 0 ground, 1 up, -1 basement
    area_from: str = "type"  # where area_range came from: type | program | name | kind
    need: float = 0.0  # floor its furniture needs (set when a total is fitted)
    open_air: bool = False  # open to the sky whatever its type (its name says so)
    parts: list[int] = field(default_factory=list)  # Parsed.rooms it takes in (a studio's kitchenette)
    least_scale: float = 1.0  # a size word's factor on its type's min_area_m2 ("tiny": Sizing.least_scale)


def _type_info(kb: KnowledgeBase, room_type: str) -> dict:
    types = kb.raw("rooms")["types"]
    return types.get(room_type, types["other"])


def _slot_from_entry(kb: KnowledgeBase, e: dict) -> Slot:
    t = e["type"] if e["type"] in ROOM_TYPES else "other"
    area = e.get("area") or _type_info(kb, t)["area"]
    s = Slot(e.get("name", t.replace("_", " ")), t, e.get("furnish", t), tuple(area), key=e.get("key", ""))
    s.area_from = "program" if e.get("area") else "type"
    return s


def _concept_info(kb: KnowledgeBase, furnish: str) -> dict:
    """Type and area of a furnishing set chosen by the embedding matcher."""
    for info in kb.raw("rooms")["names"].values():
        if info.get("furnish", info.get("type")) == furnish:
            return {"type": info["type"], "furnish": furnish, **({"area": info["area"]} if "area" in info else {})}
    return {"type": furnish_type(furnish, kb), "furnish": furnish}


def _slot_from_mention(kb: KnowledgeBase, m: Mention, idx: int, program: str | None = None) -> Slot:
    """The room a mention names, read as the building ``program`` reads it (rooms.yaml
    ``within``: "the gym" of a school is its sports hall; ``at_home`` in a dwelling: "a
    salon" in a riad is a sitting room)."""
    info = kb.raw("rooms")["names"].get(m.key) if m.key else None
    owned = bool(info and m.owner and info.get("owned"))
    if owned and info is not None:  # "the editor's office": a private office
        info = {**{k: v for k, v in info.items() if k != "owned"}, **info["owned"]}
    if info is not None and ("at_home" in info or "within" in info):
        home = is_dwelling(kb, program)
        sense = (info.get("within") or {}).get(program or "") or (info.get("at_home") if home else None) or {}
        info = {**{k: v for k, v in info.items() if k not in ("at_home", "within")}, **sense}
    if m.concept:
        info = {**_concept_info(kb, m.concept), **({"name": info["name"]} if info and "name" in info else {})}
    if info is None:
        t = "other"
        info = {}
    else:
        t = info["type"] if info["type"] in ROOM_TYPES else "other"
    name = m.name if m.words or m.concept or not info.get("name") else info["name"]
    if owned and m.owner not in name:
        name = f"{m.owner}'s {name}"
    small = (kb.raw("rooms").get("small_heads") or {}).get(m.name.split()[-1] if m.name else "")
    if small is not None and "area" not in (kb.raw("rooms")["names"].get(m.key) or {}):
        info = {**info, "area": small}  # "a meditation nook": a nook, read as a meditation room
    area = info.get("area") or _type_info(kb, t)["area"]
    s = Slot(name, t, info.get("furnish", t), tuple(area), mention=idx, generic_name=False, size=m.size)
    s.area_from = "name" if info.get("area") else "type"
    if m.area_m2 is not None:  # "a 12 m2 bedroom": that area, whatever the norms and words say
        a = float(np.clip(m.area_m2, *AREA_LIMITS_M2))
        s.area_range, s.area_from, s.size = (a, a), "stated", 1.0
    return s


def _sample_count(spec, rng: np.random.Generator) -> int:
    if isinstance(spec, list):
        return int(rng.integers(spec[0], spec[1] + 1))
    return int(spec if spec is not None else 1)


def choose_program(kb: KnowledgeBase, parsed: Parsed) -> tuple[str | None, list[str]]:
    """Program key (None: only the named rooms) and the styles the building implies."""
    if parsed.building is not None:
        b = kb.raw("programs")["buildings"][parsed.building]
        if _guessed_home(kb, parsed, b["program"]):
            return None, []
        return b["program"], list(b.get("styles", [])) + former_keeps(kb, parsed).get("styles", [])
    if any(not m.negated for m in parsed.rooms):
        types = _named_types(kb, parsed)
        if parsed.bedrooms or parsed.people or (len(types) >= 3 and types & HOME_TYPES):
            return DEFAULT_PROGRAM, []
        return None, []
    return DEFAULT_PROGRAM, []


def former_keeps(kb: KnowledgeBase, parsed: Parsed) -> dict[str, Any]:
    """What a converted building keeps of its former use (programs.yaml
    ``conversions.keeps``: a barn's farmhouse look, a chapel's stained glass); empty when
    the text names no former use."""
    if parsed.former is None:
        return {}
    programs = kb.raw("programs")
    old = programs["buildings"][parsed.former]["program"]
    return dict((programs.get("conversions") or {}).get("keeps", {}).get(old) or {})


GUESSED_HOME_MAX = 0.9
"""A building word the knowledge does not list, matched to a dwelling's program by the
embedding matcher below this score, is trusted only if the text names a room of a home
(:func:`_guessed_home`)."""


def _guessed_home(kb: KnowledgeBase, parsed: Parsed, program: str) -> bool:
    """Whether the building is a weak guess at a dwelling ("a county courthouse" read as
    a courtyard house) while the text names rooms, none of them a home's
    (:data:`HOME_TYPES`): then only the named rooms are planned, no bedrooms."""
    if parsed.building_score >= GUESSED_HOME_MAX or not is_dwelling(kb, program):
        return False
    named = sum(not m.negated for m in parsed.rooms)
    return named >= 2 and not (_named_types(kb, parsed) & HOME_TYPES) and not parsed.bedrooms and not parsed.people


def _named_types(kb: KnowledgeBase, parsed: Parsed) -> set[str]:
    """Room types of the rooms the text names (not those it rules out)."""
    return {_slot_from_mention(kb, m, i).type for i, m in enumerate(parsed.rooms) if not m.negated}


def plan_rooms(kb: KnowledgeBase, parsed: Parsed, program: str | None, rng: np.random.Generator, warnings: list[str], sizing: Sizing | None = None) -> tuple[list[Slot], str | None]:
    """Rooms of the house; returns the slots and the key of the program's main room.
    ``sizing`` (:func:`sizing`): the building kind's room sizes and the total the rooms
    must reach, which may drop or add rooms."""
    prog = kb.raw("programs")["programs"].get(program) if program else None
    slots: list[Slot] = []
    if prog is not None:
        counts = sizing.kind.get("counts", {}) if sizing is not None else {}
        for e in prog["rooms"]:
            n = _sample_count(counts.get(e["type"], e.get("count", 1)), rng)  # a mansion has more bedrooms
            opt = e.get("optional")
            if opt is not None and rng.random() >= float(opt):
                n = 0
            for _ in range(n):
                s = _slot_from_entry(kb, e)
                s.optional = opt is not None
                slots.append(s)
    fixed = _fixed_counts(kb, parsed)
    _claim_mentions(kb, parsed, slots, fixed, prog, program)
    _drop_replaced(parsed, slots, program is None or is_dwelling(kb, program))
    totals = frozenset(t for t, n in (("bedroom", parsed.bedrooms), ("bathroom", parsed.bathrooms)) if n is not None)
    _apply_fixed(kb, slots, fixed, prog, totals)
    if program is None or is_dwelling(kb, program):  # "a restaurant for 40 guests" sleeps no one
        _apply_people(kb, parsed, slots, fixed)
    _add_hallway(kb, slots, prog)
    if parsed.rooms and all(m.negated for m in parsed.rooms) and parsed.building is None and prog is not None:
        warnings.append(
            f"the text only rules out rooms ({', '.join(m.name for m in parsed.rooms)}); planned a {prog.get('building', 'home')} without them"
        )
    asked = _asked_per_type(kb, parsed, fixed, slots)
    total = _fill_total(kb, parsed, slots, prog, fixed, asked)
    _drop_negated(kb, parsed, slots)
    _cap(kb, slots, warnings, fixed, asked, total)
    if not slots:
        ruled_out = [m.name for m in parsed.rooms if m.negated]
        keep = next((e for e in (prog or {}).get("rooms", []) if not _ruled_out(kb, parsed, _slot_from_entry(kb, e))), None)
        s = _slot_from_entry(kb, keep or {"type": "living_room", "name": "living room"})
        slots.append(s)
        if ruled_out:
            warnings.append(
                f"the text rules out {', '.join(ruled_out)} and names no other room; planned a {s.name}"
            )
    if sizing is not None:
        apply_kind(kb, slots, sizing)
    _name_main_room(parsed, slots, prog)
    # a building's main room stays on its entrance storey (a dwelling's may go down: "a
    # home cinema and a wine cellar in the basement")
    venue_main = None if is_dwelling(kb, program) else (prog or {}).get("main")
    assign_levels(kb, parsed, slots, warnings, venue_main)
    _name_and_number(slots)
    open_air_by_name(kb, slots)
    return slots, (prog or {}).get("main")


def open_air_word(kb: KnowledgeBase, name: str) -> str | None:
    """The open-air room type a room's name says it is ("roof terrace" -> roof_terrace,
    "the riad's courtyard" -> courtyard), or None (rooms.yaml ``open_air``: "garden
    room", "winter garden" and the like are enclosed). The longest word wins."""
    oa = kb.raw("rooms").get("open_air") or {}
    text = " ".join(re.findall(r"[a-z0-9']+", name.lower()))
    if any(re.search(rf"\b{re.escape(e)}\b", text) for e in oa.get("enclosed", [])):
        return None
    after = "|".join(re.escape(w) for w in oa.get("not_before", []))
    for word in sorted(oa.get("words", {}), key=len, reverse=True):
        tail = rf"(?!\s+(?:{after})\b)" if after else ""
        if re.search(rf"\b{re.escape(word)}\b{tail}", text):
            return str(oa["words"][word])
    return None


def open_air_by_name(kb: KnowledgeBase, slots: list[Slot]) -> None:
    """Rooms whose name says they are open to the sky are built open: a room of an
    enclosed, non-habitable type takes the open-air type its name gives (keeping its
    furnishing and size); a habitable one ("a courtyard cafe") keeps its type and is
    marked ``open_air``."""
    for s in slots:
        if _type_info(kb, s.type).get("open_air"):
            continue
        t = open_air_word(kb, s.name)
        if t is None:
            continue
        if _type_info(kb, s.type).get("habitable") or _type_info(kb, s.type).get("circulation"):
            s.open_air = True
        else:
            s.type = t


VENUE_TYPES = frozenset({"shop", "cafe", "restaurant", "bar", "gym", "studio", "gallery", "hall", "library", "playroom"})
"""Types of a program's main room that take the user's name for the building ("a pilates
studio" -> a room named "pilates studio")."""


def _name_main_room(parsed: Parsed, slots: list[Slot], prog: dict | None) -> None:
    phrase = parsed.building_phrase
    if prog is None or not phrase:
        return
    main = next((s for s in slots if s.key == prog.get("main")), None)
    if main is None or main.mention is not None or main.type not in VENUE_TYPES or main.name == phrase:
        return
    if any(s.name == phrase for s in slots):
        return
    main.name = phrase


def _fixed_counts(kb: KnowledgeBase, parsed: Parsed) -> dict[str, int]:
    fixed: dict[str, int] = {}
    names = kb.raw("rooms")["names"]
    for m in parsed.rooms:
        info = names.get(m.key) or {}
        if info.get("generic") and m.count is not None:
            fixed[info["type"]] = fixed.get(info["type"], 0) + m.count
    if parsed.bedrooms is not None:
        fixed["bedroom"] = parsed.bedrooms
    if parsed.bathrooms is not None:
        fixed["bathroom"] = parsed.bathrooms
    return fixed


def _claim_mentions(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], fixed: dict[str, int],
                    prog: dict | None = None, program: str | None = None) -> None:
    names = kb.raw("rooms")["names"]
    main = next((s for s in slots if prog and s.key == prog.get("main")), None)
    held, taken = set((prog or {}).get("holds", [])), set[str]()
    for i, m in enumerate(parsed.rooms):
        if m.count == 0:
            continue
        proto = _slot_from_mention(kb, m, i, program)
        if main is not None and _taken_in(m, proto, held, taken):
            main.parts.append(i)
            taken.add(proto.type)
            if fixed.get(proto.type):  # "a kitchen" counted one kitchen: it is the studio's
                fixed[proto.type] -= 1
                if not fixed[proto.type]:
                    del fixed[proto.type]
            continue
        generic = bool((names.get(m.key) or {}).get("generic"))
        n = max(1, m.count) if m.count else (2 if m.plural else 1)  # "tatami rooms", "restrooms": two at least
        n = min(n, MAX_COUNT)
        first: Slot | None = None  # more rooms than the program has copy the first one's furnishing
        headed = False  # the mention claimed the program's rooms by their head word
        own = False  # ... or by their very name: the rest are the building's rooms of that name too
        # "three practice rooms" in a music school: the program's practice rooms, as the
        # building reads them, not the word's own reading (a yoga room)
        word = _room_word(m.key)
        for k in range(n):
            by_key = [s for s in slots if s.mention is None and s.key and s.key == word]
            same_name = [s for s in slots if s.mention is None and s.name in (proto.name, m.key)]
            # "twelve monks' cells" in a monastery (a name the knowledge does not list): the
            # program's cells, as it furnishes them
            same_head = [s for s in slots if s.mention is None and s.key and not m.key
                         and len(proto.name.split()) > 1 and s.name == proto.name.split()[-1]]
            # "a long range" of an archery club: its archery range, as the building furnishes it
            same_tail = [s for s in slots if s.mention is None and s.key and s.name.endswith(" " + proto.name)]
            # rooms of the catch-all type "other" are too unlike to stand in for each other
            same_type = [s for s in slots if s.mention is None and s.type == proto.type != "other"]
            same_set = [s for s in slots if s.mention is None and s.furnish == proto.furnish != "other"]
            target = next(iter(by_key or same_name or same_head or same_tail or same_set or same_type), None)
            if target is None:
                like = first or proto
                target = Slot(proto.name, like.type, like.furnish, like.area_range, key=like.key)
                slots.append(target)
            headed = headed or target in same_head or target in same_tail  # the rest copy the program's cells too
            # "six guest rooms" in a hotel: the hotel's guest rooms, furnished as it furnishes them
            own = own or (target in same_name and target.name == m.key)
            in_context = bool(target.key) and (target.key == word or headed or own)
            target.mention = i
            target.size = proto.size
            target.optional = False
            target.name = m.variants[k] if k < len(m.variants) else proto.name
            target.generic_name = generic
            if not in_context and (not generic or target.type != proto.type):
                # the word's own reading, unless the program gave it its building's
                target.furnish, target.type = proto.furnish, proto.type
                target.area_range, target.area_from = proto.area_range, proto.area_from
            elif proto.area_from == "stated":  # "a 30 m2 living room"
                target.area_range, target.area_from = proto.area_range, proto.area_from
            if generic and target.type != proto.type and fixed.get(proto.type):
                # "a dining room" of an inn is its breakfast room: the one counted
                fixed[proto.type] -= 1
                if not fixed[proto.type]:
                    del fixed[proto.type]
            first = first or target


def _taken_in(m: Mention, proto: Slot, held: set[str], taken: set[str]) -> bool:
    """Whether the program's main room takes the mention in as a part of itself ("a
    studio apartment with a kitchenette"): a room of a type it holds (``held``), named
    once, of a type not taken in yet (``taken``), not counted, sized or ruled out."""
    return (proto.type in held and proto.type not in taken and not m.negated and (m.count or 1) == 1
            and not m.plural and m.area_m2 is None)


def _room_word(key: str | None) -> str:
    """The word a room name is built on: "practice room(s)" -> "practice"."""
    words = (key or "").split()
    return " ".join(words[:-1]) if len(words) > 1 and words[-1] in ("room", "rooms") else (key or "")


COUNTED_KEEPS = frozenset({"bedroom", "bathroom", "hallway", "entry", "other"})
"""Types whose program rooms stay when the text counts separately named rooms of the
type ("two guest bedrooms" keeps the master bedroom)."""


def _drop_replaced(parsed: Parsed, slots: list[Slot], dwelling: bool) -> None:
    """"Three massage rooms" in a spa: the text fixed how many treatment rooms there are,
    so the program's unclaimed rooms of that type go; so do those of the very name
    counted ("four guest rooms" in a hotel), whatever their type. Outside a dwelling
    counted bedrooms are the building's ("three guest bedrooms" in a B&B: its guest
    rooms), not rooms beside a household's own."""
    keeps = COUNTED_KEEPS if dwelling else COUNTED_KEEPS - {"bedroom"}
    counted = {s.type for s in slots if s.mention is not None and parsed.rooms[s.mention].count}
    # "four guest rooms" in a hotel: the count is that of the hotel's own guest rooms
    named = {parsed.rooms[s.mention].key for s in slots if s.mention is not None and parsed.rooms[s.mention].count}
    for s in [s for s in slots if s.mention is None and (s.type in counted - keeps or s.name in named)]:
        slots.remove(s)


def _apply_fixed(kb: KnowledgeBase, slots: list[Slot], fixed: dict[str, int], prog: dict | None, totals: frozenset[str] = frozenset()) -> None:
    for t, n in fixed.items():
        # a count of plain rooms ("three kids' bedrooms") leaves the rooms the text names
        # otherwise ("a master suite") on top; a total ("a 2B1B") counts every room
        of_type = [s for s in slots if s.type == t and (t in totals or s.mention is None or s.generic_name)]
        while len(of_type) > n:
            victim = next((s for s in reversed(of_type) if s.mention is None), None)
            victim = victim or next((s for s in reversed(of_type) if s.generic_name), None)
            if victim is None:
                break
            slots.remove(victim)
            of_type.remove(victim)
        entry = next((e for e in (prog or {}).get("rooms", []) if e["type"] == t), None)
        while len(of_type) < min(n, MAX_ROOMS):
            s = _slot_from_entry(kb, entry or {"type": t, "name": t.replace("_", " ")})
            slots.append(s)
            of_type.append(s)


def _apply_people(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], fixed: dict[str, int]) -> None:
    if not parsed.people or "bedroom" in fixed:
        return
    people = min(parsed.people, 40)
    kids = max(0, people - 2)
    beds_per_room = [1] * kids if kids <= 2 else [2] * (kids // 2) + [1] * (kids % 2)
    want = 1 + len(beds_per_room)
    bedrooms = [s for s in slots if s.type == "bedroom"]
    while len(bedrooms) > want and any(s.mention is None for s in bedrooms):  # never a named room
        victim = next(s for s in reversed(bedrooms) if s.mention is None)
        bedrooms.remove(victim)
        slots.remove(victim)
    while len(bedrooms) < want:
        s = _slot_from_entry(kb, {"type": "bedroom", "name": "bedroom"})
        slots.append(s)
        bedrooms.append(s)
    for s, beds in zip(bedrooms[1:], beds_per_room):
        if s.mention is not None and not s.generic_name:
            continue  # "a nursery" keeps its own furnishing
        s.furnish, s.beds = "kids_bedroom", beds
        if s.generic_name:
            s.name = "kids' bedroom"
    if people >= 4 and "bathroom" not in fixed and sum(s.type == "bathroom" for s in slots) < 2:
        slots.append(_slot_from_entry(kb, {"type": "bathroom", "name": "bathroom"}))


def _asked_per_type(kb: KnowledgeBase, parsed: Parsed, fixed: dict[str, int], slots: list[Slot]) -> dict[str, int]:
    """Rooms of each type the text asked for, as written (before any cap), of the type
    the room that claimed the words has (the program may read them in context)."""
    asked: dict[str, int] = {}
    parts = {j for s in slots for j in s.parts}
    for i, m in enumerate(parsed.rooms):
        if m.negated or i in parts:  # a part of the main room (a studio's kitchenette)
            continue
        if m.asked is not None and m.asked > 0:  # repeated mentions of one room are one room
            t = next((s.type for s in slots if s.mention == i), None) or _slot_from_mention(kb, m, i).type
            asked[t] = max(asked.get(t, 0), m.asked)
    for t, n in fixed.items():
        asked[t] = max(asked.get(t, 0), n)
    return asked


def _fill_total(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], prog: dict | None, fixed: dict[str, int], asked: dict[str, int]) -> int:
    """"A hotel with 40 rooms": add copies of the program's most repeated room (guest
    rooms, bedrooms) until the house has the rooms asked for, or the most it can hold.
    Returns the number of rooms the text asked for in all."""
    want = parsed.total_rooms or 0
    if want <= len(slots) or prog is None:
        return max(want, len(slots))
    unit = max(
        (e for e in prog["rooms"] if isinstance(e.get("count"), list)),
        key=lambda e: e["count"][1], default=None,
    )  # fmt: skip
    if unit is None or _ruled_out(kb, parsed, _slot_from_entry(kb, unit)):
        return want
    added = 0
    while len(slots) < min(want, MAX_ROOMS):
        slots.append(_slot_from_entry(kb, unit))
        added += 1
    t = _slot_from_entry(kb, unit).type
    n = sum(s.type == t for s in slots)
    fixed[t] = max(fixed.get(t, 0), n)
    asked[t] = max(asked.get(t, 0), n)
    return want


def _ruled_out(kb: KnowledgeBase, parsed: Parsed, s: Slot) -> bool:
    """Whether the text rules out a room like ``s`` ("without a kitchen", "no garage",
    "0 bathrooms"): a plain room word rules out its whole type; a named room ("no wine
    cellar", "no guest bedroom") rules out rooms of that name or furnishing."""
    names = kb.raw("rooms")["names"]
    for i, m in enumerate(parsed.rooms):
        if not m.negated:
            continue
        info = names.get(m.key) or {}
        proto = _slot_from_mention(kb, m, i)
        if info.get("generic") and not m.words and s.type == info["type"]:
            return True
        if s.name in (m.name, m.key) or s.key == m.key or (proto.furnish == s.furnish and proto.furnish not in ("other", s.type)):
            return True
        if proto.type == s.type != "other" and s.name == s.type.replace("_", " ") and proto.name == s.name:
            return True
    return False


def _drop_negated(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot]) -> None:
    """Remove every room the text rules out; the user's word wins over the program (a
    house with no bathroom is still a valid house)."""
    for s in [s for s in slots if _ruled_out(kb, parsed, s)]:
        slots.remove(s)


def _cap(kb: KnowledgeBase, slots: list[Slot], warnings: list[str], fixed: dict[str, int] | None = None, asked: dict[str, int] | None = None, total: int = 0) -> None:
    """Bound rooms per type (the rooms the text names may pass a type's usual maximum)
    and rooms per plan; what the text did not ask for goes first. Each cap that bites
    says what was asked and what is planned."""
    fixed = fixed or {}
    asked = asked or {}
    by_type: dict[str, list[Slot]] = {}
    for s in slots:
        by_type.setdefault(s.type, []).append(s)
    for t, group in by_type.items():
        want = max(asked.get(t, 0), fixed.get(t, 0), sum(s.mention is not None for s in group))
        cap = max(int(_type_info(kb, t).get("max", 6)), min(want, MAX_ROOMS))
        if len(group) > cap:
            for s in sorted(group, key=lambda s: s.mention is not None)[: len(group) - cap]:
                slots.remove(s)
    asked_all = max(total, len(slots))
    if len(slots) > MAX_ROOMS:
        _trim(slots, fixed)
    for t, want in asked.items():
        planned = sum(s.type == t for s in slots)
        if want > planned:
            room = t.replace("_", " ")
            why = (
                f"a house has at most {MAX_ROOMS} rooms" if want > MAX_ROOMS or asked_all > MAX_ROOMS
                else f"a house holds at most {max(int(_type_info(kb, t).get('max', 6)), planned)} of them"
            )  # fmt: skip
            warnings.append(f"asked for {format_count(want)} {plural(room)}; {why}, planned {planned}")
    if asked_all > MAX_ROOMS and not any(f"at most {MAX_ROOMS} rooms" in w for w in warnings):
        warnings.append(f"asked for {format_count(asked_all)} rooms; a house has at most {MAX_ROOMS} rooms, planned {len(slots)}")


def _trim(slots: list[Slot], fixed: dict[str, int]) -> None:
    """Remove rooms until the plan holds :data:`MAX_ROOMS`: optional rooms first, then
    rooms the text did not ask for, then rooms of the most repeated type."""
    for s in [s for s in reversed(slots) if s.optional and s.type != "hallway"]:
        if len(slots) <= MAX_ROOMS:
            break
        slots.remove(s)
    # then rooms the program added that the text neither named nor counted
    for s in [s for s in reversed(slots[1:]) if s.mention is None and s.type not in fixed]:
        if len(slots) <= MAX_ROOMS:
            break
        slots.remove(s)
    while len(slots) > MAX_ROOMS:
        counts: dict[str, int] = {}
        for s in slots:
            if s.type != "hallway" or len(slots) <= 2:
                counts[s.type] = counts.get(s.type, 0) + 1
        t = max(counts, key=lambda k: counts[k])
        slots.remove(next(s for s in reversed(slots) if s.type == t))


def _add_hallway(kb: KnowledgeBase, slots: list[Slot], prog: dict | None) -> None:
    if prog is None or any(s.type == "hallway" for s in slots):
        return
    private = sum(s.type in ("bedroom", "bathroom", "study", "closet") for s in slots)
    if private >= 4:
        slots.append(_slot_from_entry(kb, {"type": "hallway", "name": "hallway"}))


def _slug(text: str) -> str:
    ascii_text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode()
    return re.sub(r"[^a-z0-9]+", "_", ascii_text.lower())[:48].strip("_") or "room"


def _assign_ids(slots: list[Slot]) -> None:
    """Ids from the names, unique in order: "bedroom", "bedroom_2"."""
    ids: set[str] = set()
    for s in slots:
        base = _slug(s.name)
        rid, k = base, 2
        while rid in ids:
            rid, k = f"{base}_{k}", k + 1
        ids.add(rid)
        s.id = rid


def _name_and_number(slots: list[Slot]) -> None:
    """Unique names ("bedroom", "bedroom 2") and ids; a master bedroom when several."""
    bedrooms = [s for s in slots if s.type == "bedroom" and s.furnish == "bedroom"]
    if len([s for s in slots if s.type == "bedroom"]) >= 2 and bedrooms and bedrooms[0].generic_name:
        if not any("master" in s.name for s in slots):
            bedrooms[0].name, bedrooms[0].furnish = "master bedroom", "master_bedroom"
    seen: dict[str, int] = {}
    for s in slots:
        seen[s.name] = seen.get(s.name, 0) + 1
        if seen[s.name] > 1:
            s.name = f"{s.name} {seen[s.name]}"
    _assign_ids(slots)


def sample_areas(slots: list[Slot], building_size: float, rng: np.random.Generator, kb: KnowledgeBase | None = None) -> None:
    """Draw each room's area from its range, times its size words; with ``kb``, never
    below its type's norm (``min_area_m2``, or its own smaller range), and varied by the
    knowledge's ``sizes.draw`` (programs.yaml): a factor for the whole house, one per
    room, and the shared rooms' growth with the bedrooms. A room whose area the text
    states keeps it."""
    draw = (_sizes(kb).get("draw") or {}) if kb is not None else {}
    house = _log_uniform(rng, draw.get("house"))
    bedrooms = sum(s.type == "bedroom" for s in slots)
    grow = draw.get("per_bedroom", {})
    for s in slots:
        lo, hi = s.area_range
        a = float(rng.uniform(lo, hi)) * s.size * building_size
        if s.area_from != "stated" and s.key != STAIRWELL_KEY:
            a *= house * _log_uniform(rng, draw.get("room")) * (1 + float(grow.get(s.type, 0.0)) * max(0, bedrooms - 2))
        if kb is not None:
            a = max(a, _least(kb, s))
        s.area = float(np.clip(a, *AREA_LIMITS_M2))


def _log_uniform(rng: np.random.Generator, span: list[float] | tuple[float, float] | None) -> float:
    """A factor log-uniform in ``span`` (1.0 without one)."""
    if not span:
        return 1.0
    lo, hi = float(span[0]), float(span[1])
    return float(np.exp(rng.uniform(np.log(lo), np.log(hi)))) if hi > lo else lo


def size_rng(rng: np.random.Generator, text: str) -> np.random.Generator:
    """The generator the room sizes are drawn from: one draw of the plan's ``rng`` (the
    seed) with the text's own words, so that one seed gives different sizes to different
    texts and one text different sizes under different seeds (both deterministic)."""
    words = " ".join(re.findall(r"[a-z0-9]+", text.lower()))
    try:  # a child of the seed: the plan's own later draws (furniture, looks) stay as they were
        seed = int(rng.spawn(1)[0].integers(2**32))
    except (TypeError, ValueError):  # a generator made without a seed sequence
        seed = int(rng.integers(2**32))
    return np.random.default_rng([seed, zlib.crc32(words.encode())])


_EN_SUITE = re.compile(r"\ben[ -]?suite\b")
"""A bathroom named an en-suite opens off a bedroom (the master's first), never a hall."""


def connect(kb: KnowledgeBase, slots: list[Slot], entrance_types: list[str]) -> list[tuple[str, str]]:
    """A tree over the rooms (hubs first) plus one (room, "outside") entrance edge."""
    types = kb.raw("rooms")["types"]

    def is_hub(s: Slot) -> bool:
        return bool(_type_info(kb, s.type).get("hub"))

    root = None
    for t in [*entrance_types, "entry", "reception", "hallway", "stairwell", "living_room", "waiting_room"]:
        root = next((s for s in slots if s.type == t), None)
        if root is not None:
            break
    root = root or next((s for s in slots if is_hub(s)), slots[0])
    degree = {s.id: 0 for s in slots}
    degree[root.id] = 1
    edges: list[tuple[str, str]] = []
    placed = [root]
    beds = sum(s.type == "bedroom" for s in slots)
    en_suite = beds >= ENSUITE_MIN_BEDROOMS and sum(s.type == "bathroom" for s in slots) >= beds
    bathed: set[str] = set()  # bedrooms with a bathroom of their own
    order = sorted((s for s in slots if s is not root), key=lambda s: (types.get(s.type, types["other"])["tier"], slots.index(s)))
    for s in order:
        attach = _type_info(kb, s.type).get("attach", [])

        def cap(p: Slot) -> int:
            return min(HUB_MAX_DEGREE, _type_info(kb, p.type).get("doors_max") or HUB_MAX_DEGREE) if is_hub(p) else ROOM_MAX_DEGREE

        free = [p for p in placed if degree[p.id] < cap(p)]
        ranked = [p for t in attach for p in free if p.type == t]
        # "each with its own bathroom", "a master bedroom with en suite": off a bedroom without one
        if s.type == "bathroom" and (en_suite or _EN_SUITE.search(s.name)):
            beds_free = [p for p in free if p.type == "bedroom" and p.id not in bathed]
            ranked = sorted(beds_free, key=lambda p: "master" not in p.name) + ranked
        if s.key == CORRIDOR_KEY:  # an added corridor carries on from the hallway it relieves
            ranked = [p for p in reversed(free) if p.type == "hallway"] + ranked  # the last one: a chain
        if _type_info(kb, s.type).get("habitable"):  # rooms open onto the courtyard they wrap
            ranked = [p for p in free if _type_info(kb, p.type).get("enclosed")] + ranked
        by_degree = sorted(placed, key=lambda p: degree[p.id])
        parent = (
            ranked
            or [p for p in by_degree if p in free and is_hub(p)]
            or [p for p in by_degree if p.type in attach]
            or [p for p in by_degree if is_hub(p)]
            or by_degree
        )[0]
        edges.append((parent.id, s.id))
        if s.type == "bathroom":
            bathed.add(parent.id)
        degree[parent.id] += 1
        degree[s.id] += 1
        placed.append(s)
    for s in slots:
        if s.type == "hallway":
            s.area = max(s.area, min(14.0, 1.5 + 1.3 * degree[s.id]))
    return edges + [(root.id, "outside")]



# ------------------------------------------------------------------ storeys
STAIRWELL_KEY = "stairwell"
"""Program key (and name) of the stairwell room planned on every storey of a house of
several; the floorplan stage (anyhome.floorplan.levels) stacks them."""
STAIRWELL_AREA_M2 = 8.5
"""Floor of a stairwell: a dog-leg stair (two 0.85 m flights side by side, 1.75 m, and a
half landing: 2.6 m long for a 2.9 m storey in 16 risers of 0.181 m and goings of
0.25 m, within UK Approved Document K for a private stair) and a 1 m strip of floor at
its foot (anyhome.floorplan.stairs): 6.3 m2 at least; the floorplan solver makes it
about 2 x 4 m (a tall storey's stairwell grows with its stair: floorplan.levels)."""
STAIR_HALL_M2 = 9.6
"""Floor of a stairwell with four doors or more: a stair hall (the storey's hall, in
place of a landing or a hallway): the stair and its strip (3.6 m) by the stair's width
and a 0.9 m landing beside it (2.65 m), with room for five doors
(anyhome.floorplan.stairs ``PASSAGE_M``, ``HALL_DOORS``)."""
STAIR_HALL_DOORS = 5
STAIR_HALL_M2_PER_DOOR = 2.4
"""Floor a stair hall gains per door beyond :data:`STAIR_HALL_DOORS` (0.9 m more of it)."""
SPIRAL_STAIRWELL_AREA_M2 = 5.7
"""Floor of a small house's stairwell holding a spiral stair (anyhome.floorplan.stairs
``stair_kind``: 1.75 m across, one full turn, ending over its foot) and the 1 m strip at
its foot: 2.75 x 1.75 = 4.8 m2 at least, planned 2.05 m wide as the solver's least."""
SPIRAL_STAIR_HALL_M2 = 7.3
"""Floor of a spiral stair hall (four doors or more): the stair and its strip (2.75 m)
by the stair's width and the 0.9 m landing beside it (2.65 m)."""
STAIRWELL_FEW_DOORS_M2 = 6.8
"""Floor of a dog-leg stairwell with one or two doors (an upper storey's, opening onto its
landing or two rooms): the stair and the 1 m strip at its foot, 3.6 m, by 1.9 m; the doors
open off the strip (planned at :data:`STAIRWELL_AREA_M2` the solver gave it 2.2 m2 or more
of floor no one uses)."""
LADDER_STAIRWELL_AREA_M2 = 3.5
"""Floor of a tiny house's stairwell holding its ship's ladder (anyhome.floorplan.stairs
``LADDER``: a 2.6-2.65 m storey's 11-12 risers, goings of 0.13 m and 0.5 m of floor at the
top, 1.8-1.93 m, and the 1 m strip at its foot) by the well's least width, 1.2 m: 3.5 m2."""
LADDER_STAIR_HALL_M2 = 4.4
"""Floor of a ladder's stair hall (three doors or more): the ladder and its strip (2.93 m)
by the ladder's width and the 0.9 m landing beside it (1.5 m)."""


def stairwell_area_m2(doors: int, kind: str = "dogleg") -> float:
    """Planned floor of a stairwell with ``doors`` doors holding stairs of ``kind``
    (anyhome.floorplan.stairs ``DOGLEG``, ``SPIRAL`` or ``LADDER``): a plain stairwell
    below ``stair_hall_min_doors`` (up to three doors, a ladder's up to two, open onto the strip at
    the stair's foot), else a stair hall (:data:`STAIR_HALL_M2`) growing with its doors."""
    from anyhome.floorplan.stairs import LADDER, SPIRAL, stair_hall_min_doors

    spiral = kind == SPIRAL
    if kind == LADDER:
        return LADDER_STAIRWELL_AREA_M2 if doors < stair_hall_min_doors(kind) else LADDER_STAIR_HALL_M2 + STAIR_HALL_M2_PER_DOOR * max(0, doors - STAIR_HALL_DOORS)
    if doors < stair_hall_min_doors(kind):
        return SPIRAL_STAIRWELL_AREA_M2 if spiral else STAIRWELL_FEW_DOORS_M2 if doors <= 2 else STAIRWELL_AREA_M2
    return (SPIRAL_STAIR_HALL_M2 if spiral else STAIR_HALL_M2) + STAIR_HALL_M2_PER_DOOR * max(0, doors - STAIR_HALL_DOORS)


def planned_stair_kind(slots: list[Slot]) -> str:
    """The kind of stairs the floorplan stage will build for ``slots``
    (anyhome.floorplan.stairs ``stair_kind``: a spiral for a small house) from the floor
    their rooms, stairwells and landings left out, plan now."""
    from anyhome.floorplan.stairs import stair_kind

    return stair_kind(sum(s.area for s in slots if s.key not in HELD_KEYS))


def assign_levels(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], warnings: list[str],
                  main: str | None = None) -> None:
    """Put rooms on storeys when the text asks for several ("a three-storey townhouse",
    "upstairs", "a basement", "an attic") and add one stairwell per storey. A one-storey
    text leaves every room on level 0 and adds nothing. Which rooms go up, down and
    into an attic: programs.yaml ``storeys``. ``main``: the key of a building's (not a
    dwelling's) main room, which a list's closing basement words do not take down."""
    if parsed.storeys <= 1 and not parsed.basement and not parsed.attic:
        return
    st = kb.programs.storeys
    if st is None:
        raise PlanError("the knowledge base's programs.yaml has no `storeys` section: which rooms go upstairs")
    top = parsed.storeys - 1  # highest full storey
    up = [s for s in slots if s.type in st.up]
    fillers: list[Slot] = []
    if top >= 1:
        for i, s in enumerate(up):  # contiguous runs of bedrooms per storey, bottom first
            s.level = 1 + i * top // max(1, len(up))
        fillers = _fill_empty_storeys(kb, slots, top)
        baths = [s for s in slots if s.type == "bathroom"]
        keep = 1 if len(baths) > 1 else 0  # a cloakroom stays on the ground floor
        for i, s in enumerate(baths[keep:]):
            levels = sorted({x.level for x in slots if x.type in st.up and x.level > 0})
            s.level = levels[i % len(levels)] if levels else 0
    if parsed.attic:
        pick = next((s for s in slots if "attic" in s.name or "loft" in s.name), None)
        pick = pick or next((s for t in st.attic for s in reversed(slots) if s.type == t), None)
        if pick is None or (pick.level == 0 and pick.type == "bedroom" and top >= 1):
            pick = _slot_from_entry(kb, {"type": "storage", "name": "attic"})
            slots.append(pick)
        pick.level = top + 1
    if parsed.basement:
        down = [s for s in slots if s.type in st.basement and s.level == 0]
        if len(down) == sum(s.level == 0 for s in slots):  # a basement under nothing: the words say what goes down
            down = []
        if not down:
            down = [_slot_from_entry(kb, {"type": "storage", "name": "basement"})]
            slots.append(down[0])
        for s in down:
            s.level = -1
    loose: list[tuple[Slot, int, int]] = []
    worded = _worded_levels(parsed, slots, top, set(st.up) | {"bathroom"}, loose)
    _loose_kept_down(slots, fillers, loose, top)
    for s in fillers:  # a storey the words gave rooms ("a bedroom with a bathroom at the top") needs no filler
        if any(w.level == s.level for w in worded):
            slots.remove(s)
    if top >= 1 and set(range(top + 1)) <= {s.level for s in worded}:
        # the text lists every storey's rooms ("garage and utility on the ground floor, kitchen
        # and living room on the first floor, ..."): the program's optional extras (a dining
        # room, a study) are not asked for anywhere
        slots[:] = [s for s in slots if not (s.optional and s.mention is None and _slot_span(s, parsed) is None)]
    _keep_a_ground_floor(parsed, slots, main)
    _fill_empty_storeys(kb, slots, top)  # one the words emptied
    levels = sorted({s.level for s in slots} | {0})  # "a den in the basement": entered down a stair from a hall
    while len(slots) + len(levels) > MAX_ROOMS:
        victim = next((s for s in reversed(slots) if s.mention is None and s.type not in ("hallway", "entry")), None)
        if victim is None:
            break
        slots.remove(victim)
        warnings.append(f"a house has at most {MAX_ROOMS} rooms with its stairwells; dropped the {victim.name}")
    for t in ("hallway", "entry"):  # the ground floor's stairwell is its entrance hall
        hall = next((s for s in slots if s.level == 0 and s.type == t and s.mention is None), None)
        if hall is not None:
            slots.remove(hall)
    for k in levels:
        s = Slot("stairwell", "stairwell", "hallway", (STAIRWELL_AREA_M2, STAIRWELL_AREA_M2), key=STAIRWELL_KEY)
        s.level = k
        slots.append(s)


def _keep_a_ground_floor(parsed: Parsed, slots: list[Slot], main: str | None = None) -> None:
    """A list ending "... and a few holding cells in the basement" that sent every room
    down, or the building's main room (``main``: a courthouse's courtrooms, named first in
    the list): only the room named last before the words stays in the basement, the rest
    come up to the ground floor (a building has an entrance storey)."""
    main_down = main is not None and any(s.key == main and s.level < 0 for s in slots)
    if (any(s.level == 0 for s in slots) and not main_down) or not any(s.level < 0 for s in slots):
        return
    down = [(span[0], s) for s in slots if s.level < 0 and (span := _slot_span(s, parsed)) is not None]
    if not down:
        return
    last = max(start for start, _ in down)
    for start, s in down:
        if start != last:
            s.level = 0


def _fill_empty_storeys(kb: KnowledgeBase, slots: list[Slot], top: int) -> list[Slot]:
    """A bedroom on every storey from 1 to ``top`` that has no room; returns them."""
    added = []
    for k in range(1, top + 1):
        if not any(s.level == k for s in slots):
            s = _slot_from_entry(kb, {"type": "bedroom", "name": "bedroom"})
            s.level = k
            slots.append(s)
            added.append(s)
    return added


_NOT_ADJACENT = re.compile(r"[,.;:]|\b(?:and|with|plus|or|then|while)\b")


def _worded_levels(parsed: Parsed, slots: list[Slot], top: int, up_types: set[str],
                   loose: list[tuple[Slot, int, int]] | None = None) -> list[Slot]:
    """Put each room the text places on a storey there: the storey words right before
    its name ("an upstairs study") or else the first after it in its sentence ("a
    kitchen and a dining room on the ground floor", "three bedrooms upstairs"). "First
    floor" is the floor above the ground floor where the text names a ground floor too
    (British), else the ground floor (American); "top floor" the highest full storey;
    "upstairs" any storey above the ground floor (a room already up stays where it is);
    an "upstairs" or "in the attic" after a list takes only its rooms of ``up_types`` ("a
    hallway, a kitchen and three bedrooms upstairs": the bedrooms; all of them where
    another storey's words come before in its sentence: "three bedrooms on the ground
    floor, and the kitchen, dining and living space upstairs"), right after a room
    any room ("a home cinema in the attic"). Levels stay within the storeys planned.
    The room the words themselves name ("in the attic", "in the basement") is no room of
    its own where they place another room there ("a study in the attic"). Returns the
    rooms the words placed; ``loose`` (if given) gets (room, its storey before, where it
    is named) for each room of a list sent up by words closing the list
    (:func:`_loose_kept_down`)."""
    words = parsed.floor_words
    if not words:
        return []
    moved: list[Slot] = []
    british = any(w == "ground" for _, _, w in words)
    text = parsed.text
    leading = [w for w in words if _leads(w, parsed)]
    trailing = [w for w in words if w not in leading]
    placed: set[str] = set()  # the storey words that placed a room
    # words right before a room's name ("a basement den", "an upstairs study") place that room only
    modifiers = {w for w in words if not text[w[0]:w[1]].rstrip().endswith(":")
                 and any(m.start >= w[1] and not text[w[1]:m.start].strip() for m in parsed.rooms)}
    for s in slots:
        if _storey_room(s):  # "plus an attic", "in the basement": the storey itself, moved by no word
            continue
        span = _slot_span(s, parsed)
        if span is None:
            continue
        m_start, m_end = span
        before = [w for w in words if w[1] <= m_start and len(text[w[1]:m_start].split()) <= 2
                  and not _NOT_ADJACENT.search(text[w[1]:m_start])]
        after = [w for w in trailing if w[0] >= m_end and not _LIST_OPENS.search(text[m_end:w[0]]) and w not in modifiers]
        opened = [w for w in leading if w[1] <= m_start and not _CLAUSE_END.search(text[w[1]:m_start]) and w not in modifiers]
        found = before[-1] if before else after[0] if after else opened[-1] if opened else None
        word = found[2] if found else None
        # a list after another storey's words in its sentence is that storey's whole list ("three
        # bedrooms on the ground floor, and the kitchen, dining and living space upstairs")
        own_clause = (any(w[1] <= m_start and not _CLAUSE_END.search(text[w[1]:m_start]) for w in words if w not in modifiers)
                      and found is not None and not _LIST_BREAK.search(text[m_end:found[0]]))
        listed = (not before and bool(after) and found is not None and not own_clause
                  and bool(_NOT_ADJACENT.search(text[m_end:found[0]])))
        if found is None or word is None or (listed and word in ("upstairs", "upper", "attic") and s.type not in up_types):
            continue
        placed.add(word)
        moved.append(s)
        if loose is not None and listed and word in ("top", "upstairs", "upper"):
            loose.append((s, s.level, m_start))
        if word.startswith("tier:"):  # "the lower level", "the middle level": parse._find_tiers
            s.level = max(-1 if parsed.basement else 0, min(top, int(word[5:])))
            if s.level < 0:  # the storey under the entry is the basement: no basement room of its own
                placed.add("basement")
        elif word in ("ground", "downstairs"):
            s.level = 0
        elif word in ("upstairs", "upper"):
            s.level = s.level if s.level >= 1 else min(1, top)
        elif word == "top":
            s.level = top
        elif word == "basement":
            s.level = -1 if parsed.basement else s.level
        elif word == "attic":
            s.level = top + 1 if parsed.attic else s.level
        elif word in ORDINAL_FLOORS:
            s.level = max(0, min(top, ORDINAL_FLOORS[word] - (0 if british else 1)))
    for s in [s for s in slots if _storey_room(s) and s.name.split()[-1] in placed]:  # "a study in the attic": no attic room
        slots.remove(s)
    return [s for s in moved if s in slots]


def _loose_kept_down(slots: list[Slot], fillers: list[Slot], loose: list[tuple[Slot, int, int]], top: int) -> None:
    """Where words closing a list ("... 5 bedrooms, 4 bathrooms, a library and a roof
    terrace room on the top floor") sent its rooms up and left a storey between the ground
    floor and the top with none of the rooms asked for (only ``fillers``), the words
    take only the room named last before them; the others go back to the storeys they
    had (the bedrooms spread over the upper storeys). Measured on dev_storeys3: a
    four-storey house got all 5 bedrooms, 4 bathrooms, its library and gym on the top
    floor, a filler bedroom on each storey between."""
    if top < 2 or len(loose) < 2:
        return
    asked = {s.level for s in slots if s not in fillers}
    if all(k in asked for k in range(1, top)):
        return
    last = max(loose, key=lambda x: x[2])[0]
    for s, level, _ in loose:
        if s is not last:
            s.level = level


def _slot_span(s: Slot, parsed: Parsed) -> tuple[int, int] | None:
    """Where the text names the room ``s``: its mention, or for a room planned from a
    count or a shared word ("2 baths", "dining and living room") the first place its
    name's head word is written (a bathroom: "bath", "baths"); None: nowhere."""
    if s.mention is not None and s.mention < len(parsed.rooms):
        m = parsed.rooms[s.mention]
        return (m.start, m.end)
    if s.mention is not None or not s.generic_name:
        return None
    head = "bath(?:room)?s?" if s.type == "bathroom" else re.escape(s.name.split()[0])
    found = re.search(rf"\b{head}\b", parsed.text)
    return (found.start(), found.end()) if found else None


_CLAUSE_END = re.compile(r"[.;]")
_LIST_OPENS = re.compile(r"[.:]")
"""Between a room and storey words after it: they are another sentence's, or a list's that
a colon opens ("a farmhouse with a cellar: a kitchen and a parlour on the ground floor")."""
_LIST_BREAK = re.compile(r",\s*(?:and|then|plus)\b")
"""Where one list of rooms ends and the next begins ("a kitchen and a snug, and two
bedrooms in the attic": the attic's words take only the bedrooms)."""
_ARTICLES = frozenset({"a", "an", "the", "our", "my", "its", "their"})


def _leads(word: tuple[int, int, str], parsed: Parsed) -> bool:
    """Whether the storey word ``word`` (start, end, word) opens the list of rooms after it
    ("a loft upstairs, downstairs just a kitchenette, a shower room and a living area";
    "Lowest level: a gym, a guest bedroom and a shower room"), not closes the one before
    it ("two bedrooms upstairs"; a room ends right before it, no comma between) nor
    names a room's storey as a modifier ("an upstairs study")."""
    start = word[0]
    ends = [m.end for m in parsed.rooms if m.end <= start]
    gap = parsed.text[max(ends):start] if ends else ""
    if ends and len(gap.split()) <= 3 and not re.search(r"[,;:.]", gap):
        return False
    prev = parsed.text[:start].split()
    return not (prev and prev[-1].lower() in _ARTICLES)


def _storey_room(s: Slot) -> bool:
    """The storage room an attic or a basement is planned as, named for its storey ("a
    finished basement")."""
    return s.name.split()[-1:] in (["attic"], ["basement"]) and s.type == "storage"


LANDING_DOORS = 3
"""Doors an upper storey's stairwell would have, from which the stair arrives on a
landing hallway that the rooms open off (:func:`connect_levels`), as in a farmhouse's
bedroom floor, not in a stair hall with a door on every wall (measured: a stair hall of
five doors was laid out 24 times over and the house fell back to one storey, 9-15 s;
4, three doors off the stair's strip and no landing, h-circ2 on dev_storeys2: less
circulation on a villa's, a duplex's, a cottage's upper storeys, but a Victorian
terrace failed on two seeds, 500 layout attempts)."""
LANDING_KEY = "landing"
HELD_KEYS = frozenset({STAIRWELL_KEY, LANDING_KEY})
"""Program keys of rooms whose area is what they hold (a stairwell its flight, a landing
its doors): never scaled, capped or calibrated to a total."""
LANDING_WIDTH_M = 1.2
LANDING_M_PER_DOOR = 0.95
"""A landing is :data:`LANDING_WIDTH_M` wide and this long per door off it, and 0.6 m more."""


def _landing(kb: KnowledgeBase, slots: list[Slot], level: int, doors: int) -> Slot:
    """A landing hallway on storey ``level`` for ``doors`` doors, added to ``slots``."""
    s = _slot_from_entry(kb, {"type": "hallway", "name": "landing", "key": LANDING_KEY})
    area = round(max(_type_info(kb, "hallway")["min_area_m2"], LANDING_WIDTH_M * (LANDING_M_PER_DOOR * doors + 0.6)), 2)
    s.area = s.drawn_area = area
    s.area_range = (area, area)
    s.level = level
    taken = {x.id for x in slots}
    s.id = next(i for i in ("landing", *(f"landing_{n}" for n in range(2, 99))) if i not in taken)
    slots.append(s)
    return s


CORRIDOR_KEY = "corridor"
"""Program key of a hallway added because the rooms that open off a hallway outnumber
what the hallways hold (:func:`connect_corridors`); it opens off the hallway before it."""
ENSUITE_MIN_BEDROOMS = 6
"""From this many bedrooms on, a storey with a bathroom for every bedroom ("fourteen
guest rooms, each with its own bathroom") gives each bedroom its own, rather than
lining the bathrooms up along a corridor."""
CORRIDORS_MAX = 4
"""Most hallways a house may have once corridors are added for its rooms (a hotel floor
of fourteen rooms, each with its bathroom, needs four)."""
OVERFLOW_MIN = 2
"""Rooms that would open off a hallway but land on a living room, a hall or an entry
instead: from this many on, one more hallway is planned for them (a manor's seven
bedrooms off its morning room, before; a spine of hub rooms cannot lay such a hub out)."""


def _overflow(kb: KnowledgeBase, on: list[Slot], edges: list[tuple[str, str]]) -> int:
    """Rooms whose first choice is a hallway, attached to another hub room instead."""
    by_id = {s.id: s for s in on}
    n = 0
    for a, b in edges:
        if b == "outside" or a not in by_id or b not in by_id:
            continue
        parent, child = by_id[a], by_id[b]
        attach = _type_info(kb, child.type).get("attach", [])
        info = _type_info(kb, parent.type)
        if attach[:1] == ["hallway"] and parent.type != "hallway" and info.get("hub") and not info.get("enclosed"):
            n += 1  # (rooms that open onto the courtyard they wrap are where they belong)
    return n


def _hub_overflow(kb: KnowledgeBase, on: list[Slot], edges: list[tuple[str, str]]) -> int:
    """Connections beyond the ``doors_max`` of the hubs that have one (a reception)."""
    n = 0
    for s in on:
        most = _type_info(kb, s.type).get("doors_max")
        if most:
            n += max(0, sum(s.id in e for e in edges) - int(most))
    return n


def connect_corridors(kb: KnowledgeBase, slots: list[Slot], on: list[Slot],
                      entrance_types: list[str]) -> list[tuple[str, str]]:
    """:func:`connect` over the rooms ``on`` one storey, with one more hallway (added to
    ``slots`` and ``on``) while :data:`OVERFLOW_MIN` rooms or more that open off a
    hallway would otherwise hang off a living room or a hall, or hang beyond a hub's
    ``doors_max`` (a reception's: :func:`_hub_overflow`), up to :data:`CORRIDORS_MAX`
    hallways (or the hallway type's ``max``, if more) and ``MAX_ROOMS`` rooms in all."""
    edges = connect(kb, on, entrance_types)
    cap = max(int(_type_info(kb, "hallway").get("max", 2)), CORRIDORS_MAX)
    def overflow() -> int:
        return _overflow(kb, on, edges) + _hub_overflow(kb, on, edges)

    first = overflow()
    added: list[Slot] = []
    while (overflow() >= OVERFLOW_MIN and (any(s.type == "hallway" for s in on) or _hub_overflow(kb, on, edges))
           and sum(s.type == "hallway" for s in slots) < cap and len(slots) < MAX_ROOMS):
        s = _slot_from_entry(kb, {"type": "hallway", "name": "corridor", "key": CORRIDOR_KEY})
        s.level = on[0].level
        taken = {x.id for x in slots}
        s.id = next(i for i in ("corridor", *(f"corridor_{n}" for n in range(2, 99))) if i not in taken)
        names = {x.name for x in slots}
        s.name = next(n for n in ("corridor", *(f"corridor {k}" for k in range(2, 99))) if n not in names)
        s.area = s.drawn_area = s.area_range[0]
        slots.append(s)
        if on is not slots:
            on.append(s)
        added.append(s)
        edges = connect(kb, on, entrance_types)
    if added and overflow() >= first:  # the corridors relieved nothing: none planned
        for s in added:
            slots.remove(s)
            if on is not slots:
                on.remove(s)
        edges = connect(kb, on, entrance_types)
    return edges


def connect_levels(kb: KnowledgeBase, slots: list[Slot], entrance_types: list[str]) -> list[tuple[str, str]]:
    """:func:`connect` per storey: the ground floor as a one-storey house (its stairwell a
    hub like a hallway), every other storey a tree rooted at its stairwell (no entrance).
    The stairs, not doors, join the storeys."""
    if all(s.level == 0 for s in slots):
        return connect_corridors(kb, slots, slots, entrance_types)
    edges: list[tuple[str, str]] = []
    for k in sorted({s.level for s in slots}, key=lambda k: (k != 0, k)):
        on = [s for s in slots if s.level == k]
        if k == 0:
            edges += connect_corridors(kb, slots, on, entrance_types)
            continue
        stair = next(s for s in on if s.key == STAIRWELL_KEY)
        tree = [e for e in connect(kb, [stair, *(s for s in on if s is not stair)], ["stairwell"]) if e[1] != "outside"]
        doors = sum(stair.id in e for e in tree)
        if doors >= LANDING_DOORS:
            landing = _landing(kb, slots, k, doors)
            tree = [e for e in connect(kb, [landing, *(s for s in on if s is not stair)], ["hallway"]) if e[1] != "outside"]
            tree.append((stair.id, landing.id))
        edges += tree
    stairwells_sized(slots, edges)
    entrance = [e for e in edges if e[1] == "outside"]
    return [e for e in edges if e[1] != "outside"] + entrance


def stairwells_sized(slots: list[Slot], edges: list[tuple[str, str]]) -> None:
    """Every stairwell of ``slots`` planned as big as its stairs (of the kind the rooms'
    areas now call for, :func:`planned_stair_kind`) and its doors (``edges``) need
    (:func:`stairwell_area_m2`); asked again once the rooms have their final areas, so
    the floorplan stage, which reads the kind from them, finds its stairwells sized for it."""
    wells = [s for s in slots if s.key == STAIRWELL_KEY]
    if not wells:
        return
    kind = planned_stair_kind(slots)
    for s in wells:  # a stair hall as long as its doors need
        a = stairwell_area_m2(sum(s.id in e for e in edges), kind)
        s.area, s.area_range = a, (a, a)
# ---------------------------------------------------------------- sizes
# How big the rooms are (docs/space_standards.md): the building kind's typical room
# sizes, and the total floor area a size word ("tiny", "grand") or a stated total ("a
# 50 m2 flat") sets. The rooms are dropped or added before the areas are drawn; the
# drawn areas are then scaled to the total, each within its type's norms.

KIND_BAND_OVERLAP = 0.25
"""Share of a size word's range of totals that the building kind's range must share for
the two to narrow each other; below it the word's range holds alone."""
STATED_TOLERANCE = 0.05
"""A stated total is aimed at within this fraction (the bar is 10 %: furniture may
still grow a room)."""


@dataclass
class Sizing:
    """What sets the rooms' sizes: the building kind and the total they must reach."""

    program: str | None
    kind: dict = field(default_factory=dict)  # programs.yaml sizes.kinds entry
    band: tuple[float, float] | None = None  # the total floor area to land in, m2
    what: str = ""  # "the stated 50 m2", "a tiny home": how a warning names the band
    stretch: float = 1.6
    add: list[dict] = field(default_factory=list)
    circulation_share: float = 1.0
    scale: float = 1.0  # the size word's factor on every room's range
    least_scale: float = 1.0  # the size word's factor on the types' min_area_m2 (sizes.words ``least``)
    word_factor: float = 1.0  # the size word's factor on a room's area (sizes.words ``factor``)
    source: str = ""  # what set the band: "stated" | "word" | "kind" ("" without one)


def _sizes(kb: KnowledgeBase) -> dict:
    return kb.raw("programs").get("sizes") or {}


def strongest_first(found: list[str], words: dict) -> list[str]:
    """The size words of a text, the one that sizes the building first: when all of them
    with a ``total_m2`` point the same way ("a large, grand house", "a large mansion"), the
    strongest (the highest least total; "a small, tiny cabin": the lowest most total); words that point
    both ways keep the text's order."""
    sized = [w for w in found if (words.get(w) or {}).get("total_m2")]
    ups = [w for w in sized if float(words[w].get("factor", 1.0)) >= 1.0]  # "mansion" (1.0) sizes up
    downs = [w for w in sized if float(words[w].get("factor", 1.0)) < 1.0]
    if len(sized) < 2 or (ups and downs):
        return list(found)
    if ups:
        best = max(ups, key=lambda w: float(words[w]["total_m2"][0]))
    else:
        best = min(downs, key=lambda w: float(words[w]["total_m2"][1]))
    return [best, *(w for w in found if w != best)]


def sizing(kb: KnowledgeBase, parsed: Parsed, program: str | None) -> Sizing:
    """The building kind's sizes and the total the text asks for; a home that must stay
    below ``compact.below_m2`` and has no bedrooms asked for becomes the compact program
    (one main room and a bathroom)."""
    sizes = _sizes(kb)
    homes = set(sizes.get("homes", []))
    kind: dict = {}
    if parsed.building is not None:
        key = kb.raw("programs")["buildings"][parsed.building].get("kind")
        kind = sizes.get("kinds", {}).get(key, {}) if key else {}
    sz = Sizing(program, kind, stretch=float(sizes.get("stretch", 1.6)),
                add=[*kind.get("add", []), *sizes.get("add", [])] if program in homes else [],
                circulation_share=float(sizes.get("circulation_share", 1.0)) if program in homes else 1.0)  # fmt: skip
    one_room = bool((kb.raw("programs")["programs"].get(program or "") or {}).get("one_room"))
    if one_room:  # a studio is one room and a bathroom, whatever its total
        sz.add = []
    word_band = None
    for w in strongest_first(parsed.size_words, sizes.get("words", {})):
        if one_room and sizes.get("words", {}).get(w):  # "a small studio": smaller rooms, not a home's total
            sz.scale = float(sizes["words"][w].get("factor", 1.0))
            if sizes["words"][w].get("total_m2") and program in homes:  # "a tiny house": never more than its total
                word_band = (0.0, float(sizes["words"][w]["total_m2"][1]))
                sz.what = f"a {w} home"
                sz.least_scale = float(sizes["words"][w].get("least", 1.0))
            break
        if sizes.get("words", {}).get(w, {}).get("total_m2"):
            word_band = tuple(sizes["words"][w]["total_m2"])
            sz.word_factor = float(sizes["words"][w].get("factor", 1.0))
            sz.least_scale = float(sizes["words"][w].get("least", 1.0)) if program in homes else 1.0
            sz.scale = float(sizes["words"][w].get("scale", 1.0)) if program in homes else 1.0
            sz.what = f"a {w} {'home' if program in homes else 'building'}"
            break
    if parsed.total_m2 is not None:
        t = float(parsed.total_m2)
        sz.band = (t * (1 - STATED_TOLERANCE), t * (1 + STATED_TOLERANCE))
        sz.what = f"the stated {t:.0f} m2"
        sz.source = "stated"
        sz.stretch = max(sz.stretch, float(sizes.get("stated_stretch", sz.stretch)))  # the text says how big
    elif program in homes and word_band is not None:
        kt = kind.get("total_m2")
        lo, hi = word_band
        # "a grand mansion": both hold, where they share a good part of the word's range (a
        # villa's range ends at 300 m2, where "grand" begins: the word's)
        if kt and not one_room and min(hi, kt[1]) - max(lo, kt[0]) >= KIND_BAND_OVERLAP * (hi - lo):
            lo, hi = max(lo, kt[0]), min(hi, kt[1])
        sz.band = (float(lo), float(hi))
        sz.source = "word"
    elif program in homes and kind.get("total_m2"):
        sz.band = (float(kind["total_m2"][0]), float(kind["total_m2"][1]))
        sz.what = f"a {parsed.building_word or 'home'}"
        sz.source = "kind"
    compact = sizes.get("compact")
    asks_bedrooms = parsed.bedrooms or parsed.people or any(
        not m.negated and _slot_from_mention(kb, m, i).type == "bedroom" for i, m in enumerate(parsed.rooms)
    )
    if (
        compact and sz.band is not None and sz.band[1] <= float(compact["below_m2"]) and program in homes
        and program != compact["program"] and not asks_bedrooms
    ):  # fmt: skip
        sz.program = compact["program"]
    return sz


def norm_area_m2(kb: KnowledgeBase, s: Slot) -> float:
    """The room type's least area (rooms.yaml ``min_area_m2``), times the size word's
    ``least`` factor (:attr:`Slot.least_scale`: a tiny home's sitting room is smaller than
    the norm of a family home's), never below a square of the type's ``min_width_m``."""
    info = _type_info(kb, s.type)
    norm = float(info["min_area_m2"])
    if s.least_scale < 1.0:
        width = float(info.get("min_width_m", 0.0))
        norm = min(norm, max(norm * s.least_scale, width * width))
    return norm


def _least(kb: KnowledgeBase, s: Slot) -> float:
    """Smallest area the room may shrink to: its type's norm (:func:`norm_area_m2`), or
    its own smaller range (a booth, a cubicle)."""
    if s.area_from == "stated":  # "a 12 m2 bedroom" stays 12 m2
        return float(s.area_range[0])
    if s.key in HELD_KEYS:  # it holds its flight (its doors) whatever the total
        return float(s.area_range[0])
    return float(max(min(norm_area_m2(kb, s), s.area_range[0]), s.need))


def _most(kb: KnowledgeBase, s: Slot, sz: Sizing) -> float:
    """Largest area the room may grow to; circulation never grows to fill a total."""
    if s.area_from == "stated":
        return float(s.area_range[1])
    if s.key in HELD_KEYS:
        return float(s.area_range[0])
    if _type_info(kb, s.type).get("circulation"):
        return max(s.area, s.area_range[1])
    return float(min(s.area_range[1] * sz.stretch, AREA_LIMITS_M2[1]))


def apply_kind(kb: KnowledgeBase, slots: list[Slot], sz: Sizing) -> None:
    """A building kind's area ranges replace the type defaults ("a cabin's bedroom" is
    smaller than a mansion's); its scale and the size word's multiply the other rooms'
    ranges."""
    areas = sz.kind.get("areas", {})
    for s in slots:
        scale = sz.scale * float(sz.kind.get("scale", 1.0))
        if s.area_from == "type" and s.type in areas:  # the kind's own sizes already say how big
            lo_m2, hi_m2 = (float(x) for x in areas[s.type])
            s.area_range, s.area_from, scale = (lo_m2, hi_m2), "kind", 1.0
        if scale != 1.0:
            lo, hi = s.area_range
            s.area_range = (max(lo * scale, min(lo, _least(kb, s))), hi * scale)


def _mid(s: Slot) -> float:
    return max((s.area_range[0] + s.area_range[1]) / 2 * s.size, s.need)


HOUSEHOLD_OVER = 1.15
"""A household the text counts whose rooms, at the middle of their ranges, pass a size
word's total by more than this factor no longer gets that total (:func:`fit_rooms`)."""


def fit_rooms(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], sz: Sizing, prog: dict | None, need: Callable[[Slot], float]) -> None:
    """Drop or add rooms so that the total can reach ``sz.band``: optional rooms the text
    did not ask for go first when the rooms are too big for it, then repeated rooms it
    did not count; rooms of the kind's (then the homes') ``add`` list join when they are
    too few. ``need(slot)``: the floor its furniture needs. Rooms keep their names and
    ids; call :func:`renumber` after. A household the text counts ("a cosy lodge for 12
    guests") fixes the bedrooms: none goes for a size word's total, and when the rooms
    left cannot fit in it the word no longer sets a total (``sz.band`` None) but scales
    the rooms' ranges by its ``factor``."""
    if sz.band is None or not slots:
        return
    for s in slots:
        s.need = need(s)
        s.least_scale = sz.least_scale
    lo, hi = sz.band
    main = (prog or {}).get("main")
    fixed = _fixed_counts(kb, parsed)
    household = bool(parsed.people) and sz.source == "word"  # "a cosy lodge for 12 guests": the guests fix the bedrooms

    def keeps_storey(s: Slot) -> bool:
        """A stairwell, or the last room besides it on a storey above or below the ground."""
        return s.key == STAIRWELL_KEY or (s.level != 0 and sum(x.level == s.level and x.key != STAIRWELL_KEY for x in slots) <= 1)

    def droppable(strict: bool) -> list[Slot]:
        out = [s for s in reversed(slots) if s.optional and s.mention is None and s.key != main]
        if strict:
            seen: set[str] = set()
            extra = []
            for s in slots:
                if s.type in seen and s.mention is None and s.type not in fixed and s.key != main:
                    extra.append(s)
                seen.add(s.type)
            out += list(reversed(extra))
            out += [s for s in slots if _type_info(kb, s.type).get("circulation") and s.mention is None and s not in out]
        return [s for s in out if not keeps_storey(s) and not (household and s.type == "bedroom")]

    if household and sum(_mid(s) for s in slots) > hi * HOUSEHOLD_OVER:  # the word cannot hold the guests' rooms: it scales them
        for s in slots:
            if s.area_from != "stated" and s.key not in HELD_KEYS and sz.word_factor != 1.0:
                a, b = s.area_range
                s.area_range = (max(a * sz.word_factor, min(a, _least(kb, s))), b * sz.word_factor)
        sz.band, sz.source = None, ""
        return

    while sum(_mid(s) for s in slots) > hi and (victims := droppable(False)):
        slots.remove(victims[0])
    while sum(_mid(s) for s in slots) > hi * 1.15 and (victims := droppable(True)) and len(slots) > 2:
        slots.remove(victims[0])
    while sum(_least(kb, s) for s in slots) > hi and (victims := droppable(True)) and len(slots) > 1:
        slots.remove(victims[0])
    # a home gains the kind's and the homes' adds; another building the optional rooms
    # of its program the draw left out ("an office of 200 m2" has its reception)
    keys = {s.key for s in slots}
    adds = list(sz.add) or [
        {**e, "_key": True} for e in (prog or {}).get("rooms", []) if e.get("optional") is not None and e.get("key") not in keys
    ]
    while sum(_mid(s) for s in slots) < lo * 0.9 and adds and len(slots) < MAX_ROOMS:
        e = adds.pop(0)
        if e.get("_key") and any(x.key == e.get("key") for x in slots):
            continue
        if not e.get("_key") and sum(x.type == e["type"] for x in slots) >= min(int(e.get("up_to", 1)), int(_type_info(kb, e["type"]).get("max", 6))):
            continue
        new = _slot_from_entry(kb, {k: v for k, v in e.items() if k not in ("up_to", "_key", "optional", "count")})
        if _ruled_out(kb, parsed, new):
            continue
        apply_kind(kb, [new], sz)
        new.need = need(new)
        new.least_scale = sz.least_scale
        slots.append(new)


def renumber(slots: list[Slot]) -> None:
    """Unique names and ids again after rooms were added: the rooms planned before keep
    theirs, an added "bathroom" becomes the next free "bathroom 3"."""
    used: set[str] = set()
    for s in slots:
        if s.name in used:
            k = 2
            while f"{s.name} {k}" in used:
                k += 1
            s.name = f"{s.name} {k}"
        used.add(s.name)
    _assign_ids(slots)


def _scale_to(kb: KnowledgeBase, slots: list[Slot], target: float, sz: Sizing, floors: dict[int, float]) -> None:
    """Scale the rooms' areas so that the total is ``target``, each within [_least (or
    its floor in ``floors``), _most] (a room that hits a bound keeps it and the others
    take the rest)."""
    pinned: set[int] = set()
    for _ in range(len(slots) + 1):
        free = [s for s in slots if id(s) not in pinned]
        rest = sum(s.area for s in slots if id(s) in pinned)
        base = sum(s.area for s in free)
        if not free or base <= 0:
            return
        f = max(target - rest, 0.0) / base
        hit = False
        for s in free:
            a = s.area * f
            lo = max(_least(kb, s), floors.get(id(s), 0.0))
            hi = max(_most(kb, s, sz), lo, s.area if f < 1 else 0.0)
            if a < lo or a > hi:
                s.area, hit = float(np.clip(a, lo, hi)), True
                pinned.add(id(s))
        if not hit:
            for s in free:
                s.area = s.area * f
            return


def fit_areas(kb: KnowledgeBase, slots: list[Slot], sz: Sizing, warnings: list[str] | None = None, pinned: set[int] | None = None) -> None:
    """Scale the drawn areas into ``sz.band`` and keep the circulation's share of a
    home at most ``sz.circulation_share``; ``warnings`` (the last fit) says when the
    rooms cannot reach the band within their norms. ``pinned``: rooms that may grow
    but not shrink (the furniture grew them)."""
    pinned = set(pinned or ())
    for s in slots:
        if s.area_from != "stated":
            s.area = max(s.area, s.need)
    for s in slots:
        if s.key == STAIRWELL_KEY:  # a stairwell holds its flight: never capped nor scaled (a spiral's is smaller)
            s.area = min(STAIRWELL_AREA_M2, s.area_range[0])
    circ = [s for s in slots if _type_info(kb, s.type).get("circulation") and s.key != STAIRWELL_KEY]
    total = sum(s.area for s in slots)
    if circ and sz.circulation_share < 1.0:
        cap = sz.circulation_share * total
        have = sum(s.area for s in circ)
        if have > cap:
            for s in circ:
                s.area = max(_least(kb, s), s.area * cap / have)
    if sz.band is None:
        return
    lo, hi = sz.band
    total = sum(s.area for s in slots)
    target = float(np.clip(total, lo, hi))
    if abs(target - total) > 1e-6:
        _scale_to(kb, slots, target, sz, {id(s): s.area for s in slots if id(s) in pinned})
    for s in slots:
        s.area = round(s.area, 2)
    total = sum(s.area for s in slots)
    off = lo - total if total < lo else hi - total if total > hi else 0.0
    if slots and 0 < abs(off) < 0.01 * len(slots):  # the rounding pushed it out of the band
        big = max(slots, key=lambda s: s.area)
        big.area = round(big.area + off + math.copysign(0.01, off), 2)
        total = sum(s.area for s in slots)
    if warnings is not None and not lo * (1 - STATED_TOLERANCE) <= total <= hi * (1 + STATED_TOLERANCE):
        if total > hi:
            warnings.append(
                f"{sz.what} cannot hold the rooms asked for ({len(slots)} rooms need at least "
                f"{sum(_least(kb, s) if id(s) not in pinned else s.area for s in slots):.0f} m2 within the space standards); planned {total:.0f} m2"
            )
        else:
            warnings.append(f"{sz.what} is more than the rooms asked for can fill within their norms; planned {total:.0f} m2")
