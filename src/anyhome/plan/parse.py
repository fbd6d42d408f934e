"""Text parsing for the offline planner: counts, rooms, objects, styles, materials.

``parse(text)`` finds, in one pass over the normalized text, the kind of building,
the rooms and objects it names (with counts and the user's own words), arrangement
phrases, styles, colours and material phrases. It makes no random choice; the
planner (:mod:`anyhome.plan.offline`) turns the result into a ``HouseSpec``.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

from anyhome.plan import openvocab as ov
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import is_dwelling, resolve, vocabulary
from anyhome.plan.knowledge import normalize, planner_materials
from anyhome.plan.spec import MAX_COUNT
from anyhome.sanitize import clean_text

MAX_PARSE_CHARS = 4000
"""Only this many characters of the text are parsed; the rest is ignored with a warning."""

NUMBER_WORDS: dict[str, int] = {
    "zero": 0, "no": 0, "a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "double": 2,
    "twin": 2, "pair": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "dozen": 12, "thirteen": 13,
    "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
    "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60,
    "seventy": 70, "eighty": 80, "ninety": 90, "hundred": 100,
    "thousand": 1000, "million": 10**6, "billion": 10**9, "trillion": 10**12,
}  # fmt: skip
"""Count words; "a"/"an" count as one."""

MAX_EXPONENT = 99
"""Largest power of ten a number in the text is read as ("10^999" is read as 1e99): the
count is capped long before, this only bounds the arithmetic."""

MANY_WORDS = frozenset({"several", "many", "some", "few", "multiple", "lots", "plenty", "numerous"})
"""Words meaning "more than one, number unsaid"."""

FULL_WORDS = (
    "full of", "filled with", "lined with", "packed with", "lots of", "rows of", "row of", "wall of", "walls of",
    "shelves of", "racks of", "dozens of", "scores of", "hundreds of", "thousands of", "millions of", "billions of",
    "tons of", "loads of", "bank of", "banks of",
)  # fmt: skip
"""Phrases asking for the generous end of a plural's range."""

@functools.lru_cache(maxsize=8)
def size_factors(kb: KnowledgeBase) -> dict[str, float]:
    """Size adjectives -> area (rooms, buildings) or size (objects) factor: programs.yaml
    ``sizes.words`` (docs/space_standards.md)."""
    words = (kb.raw("programs").get("sizes") or {}).get("words") or {}
    return {w: float(e.get("factor", 1.0)) for w, e in words.items()}

STOP_WORDS = frozenset(
    "the and or with of in on at for to by from into inside near next as is are has have "
    "having that which where featuring containing plus also some my our their his her its "
    "this these those there here it them each every per own off".split()
)
"""Words that end the look-back from a mention towards its count and adjectives."""

EACH_OPENER = re.compile(r"^\s*(?:[,;:]\s*)?(?:(?:that|which)\s+)?(?:each|every one|all|both)(?: of them)?\s*(?:,\s*)?(?=with|has|have|having|gets?|featuring|containing|equipped|furnished)")
"""Text right after a plural room mention that gives every one of those rooms what follows."""

CONTEXT_OPENERS = re.compile(
    r"^\s*(?:,\s*)?(?:(?:(?:that|which)\s+)?(?:each|every one|all)(?: of them)?\s*(?:,\s*)?)?(?:with|without|full of|filled with|lined with|packed with|featuring|containing|"
    r"that has|which has|has|have|having|where|equipped with|furnished with|holding|housing|that holds|which holds|that houses|which houses|"
    r"hung with|decorated with|adorned with|dressed with)\b"
)
"""Text right after a room mention that makes the following objects belong to it."""


USED = r"used (?:for|as)\b"
"""What a room is used for: "a main hall used for assemblies, PE and lunch"."""
USED_AS = re.compile(r"^\s*(?:,\s*)?" + USED + r"[^.;:]*?,(?=\s*(?:with|featuring|containing|equipped|furnished)\b)")
"""What a room is used for, before what it has: "a main hall used for assemblies, PE and
lunch, with a small stage"."""


WHERE_FIRST = re.compile(
    r"^\s*(?:,\s*)?(?:(?:on|in|at|under|up in|down in) the (?:[\w-]+ ){0,2}(?:floor|storey|story|level|attic|basement|"
    r"loft|eaves|back|front|rear|top|end|corner)|upstairs|downstairs|below|above|beneath|underneath|next door|"
    r"out back|behind it|alongside)\s*,?")
"""Where a room is, said before what it has: "a long gallery on the top floor hung with
portraits"."""


def _opens_context(tail: str) -> bool:
    """Whether ``tail`` (text right after a room mention) makes the objects after it the
    room's: a context opener, or an each opener ("two bedrooms; both get ..."), after
    what the room is used for or where it is, if said."""
    if used := USED_AS.match(tail):
        tail = tail[used.end() :]
    if where := WHERE_FIRST.match(tail):
        tail = tail[where.end() :]
    return bool(CONTEXT_OPENERS.match(tail) or EACH_OPENER.match(tail) or OF_MANY.match(tail))


OF_MANY = re.compile(r"^\s*of\s+(?!(?:the|a|an|his|her|its|their|my|our|your|one)\b)(?:[\w-]+\s+){0,3}?[\w-]+s\b(?!\s+(?:of|with)\b)")
"""A room "of" many things holds them: "a nave of pews", "three galleries of glass
display cases" (not "a suite of her own", "a kitchen of the 1950s")."""

IN_ROOM = re.compile(r"^\s*(?:in|inside|for|into|within|of|on|at)(?:\s+(?:the|a|an|my|our|each))?\s*$")
"""Text between an object and a room that puts the object in that room."""

ARRANGEMENTS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"\bin (?:\w+ )?rows?\b|\bin a (?:\w+ )?grid\b|\bclassroom style\b"), "rows"),
    (re.compile(r"\b(?:along|against|lining|around|on) (?:all )?(?:the |each )?(?:\w+ )?walls?\b"), "along_walls"),
    (re.compile(r"\bin the (?:center|centre|middle)\b|\bcent(?:er|re)piece\b|\bin the (?:\w+ )?(?:center|centre|middle)\b"), "center"),
    (re.compile(r"\baround (?:a|an|the|one) (?:\w+ )?(?:\w+ )?table\b"), "around"),
    (re.compile(r"\bsymmetric(?:al|ally)?\b"), "symmetric"),
]  # fmt: skip
"""Arrangement phrases -> GroupSpec arrangement ("around" -> place_around a table);
each applies to the objects named before it in its clause."""

FORWARD_ARRANGEMENTS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"\b(?:rows?|lines?) of\b"), "rows"),
]
"""Arrangement phrases that apply to the object named right after them ("two rows of pews")."""

@functools.lru_cache(maxsize=8)
def _surface_words(kb: KnowledgeBase) -> dict[str, str]:
    """Word after a material phrase -> the room surface it dresses (knowledge/surfaces.yaml)."""
    return {w: surface for surface, words in kb.raw("surfaces").items() for w in words}


def surface_of_word(word: str, kb: KnowledgeBase | None = None) -> str | None:
    """The room surface (walls, floor, ceiling, furniture) a word names, or None."""
    return _surface_words(resolve(kb)).get(word)

_TOKEN = re.compile(r"[^\W_]+(?:'[^\W_]+)*|[.,;:!?()]")
_BED_BATH = re.compile(
    r"\b(\d{1,3})\s*(?:b|br|bd|bed|beds|bdr|bdrm)\s*(?:,|and|\+)?\s*(\d{1,2}(?:\.5)?)\s*"
    r"(?:b|ba|bth|bath|baths)\b"
)
_ONE_ROOM_HOMES = r"(?:house|home|apartment|flat|cabin|cottage|studio|dwelling|hut|shack|bothy)"
_ONE_ROOM = re.compile(
    rf"\b(?:one|single|1) room (?:\w+ ){{0,2}}{_ONE_ROOM_HOMES}\b"  # "a one-room (fire lookout) cabin"
    rf"|\b{_ONE_ROOM_HOMES}(?:\s*[:,-]\s*|\s+(?:with|of|is|has)\s+)(?:a single|just one|only one|one single) room\b"  # "a cabin: a single room"
)
_BED_BATH_WORDS = re.compile(r"\b(\w+) bed(?:room)?s?\s*(?:,|and|\+)?\s*(\w+) bath(?:room)?s?\b")
_BR_ONLY = re.compile(r"\b(\d{1,3})\s*(?:br|bd|bdr|bdrm)\b")
_BED_HOME = re.compile(
    r"\b(\w+) bed(?:ed)?\s+(?:[a-z]+\s+)?(?:flat|apartment|house|home|bungalow|cottage|semi|terrace|maisonette"
    r"|condo|townhouse|villa|cabin|chalet|penthouse|unit|duplex|detached|property)s?\b")
"""An estate agent's "2 bed flat", "a three-bed semi", "4 bed detached house": bedrooms, not beds."""
_PEOPLE = re.compile(
    r"\b(?:family|household|group) of (\w+)\b|\bfor (\w+) (?:people|persons|adults|kids|children|guests)\b"
    r"|\bsleep(?:s|ing)? (?:up to )?(\w+)\b"
)
SEATS = re.compile(
    r"\b(?:for|seating(?: for)?|seats|sits|holding|with room for|with seating for|capacity(?: of)?)\s+"
    r"(?:up to\s+|about\s+|around\s+)?([\w-]+)(?:\s+(covers|diners|guests|people|persons|worshippers|pupils|students|children|kids|"
    r"seats|visitors|customers|patrons|members|delegates|spectators|congregants|drinkers|audience))?\b")
"""How many a room or a venue seats: "a bistro for 40 covers", "a dining room seating
12", "a boardroom for 16", "a church that seats 200"."""
TOILET_ROOM_WORDS = frozenset(
    "pupil pupils staff customer customers public guest guests visitor visitors disabled accessible men's "
    "women's ladies gents unisex separate shared communal children's kids' boys' girls' patron patrons".split())
"""Words before "toilets" that make them rooms (WCs) for people, not pans in a room."""
WASH_TYPES = frozenset({"bathroom", "changing_room"})


def _room_before(mentions: list[Mention], i: int) -> Mention | None:
    """The last room mention before ``mentions[i]``."""
    return next((x for x in reversed(mentions[:i]) if x.kind == "room"), None)


def _last_before(mentions: list[Mention], pos: int) -> Mention | None:
    """The mention that ends last at or before ``pos``."""
    return max((m for m in mentions if m.end <= pos), key=lambda m: m.end, default=None)


def _bath_in_a_list(text: str, kb: KnowledgeBase, mentions: list[Mention]) -> None:
    """"A couples' suite with two tables and a bath": a bathtub in the suite, not a room
    (a bedroom's "with a bath" stays its bathroom)."""
    names = kb.raw("rooms")["names"]
    for i, m in enumerate(mentions):
        if m.kind != "room" or m.key or m.name not in ("bath", "tub") or (before := _room_before(mentions, i)) is None:
            continue
        gap = text[before.end : m.start]
        if _opens_context(gap) and not re.search(r"[.;]", gap) and (names.get(before.key) or {}).get("type") != "bedroom":
            m.kind, m.key, m.concept = "object", "bathtub", None


_LIST_GAP = re.compile(r"^\s*(?:,\s*(?:and\s+)?|and\s+|&\s+)(?:(?:a|an|the)\s+)?$")
"""Between two items of one list: ", a", " and a", ", and the"."""


def _rooms_in_a_list(text: str, kb: KnowledgeBase, p: Parsed, mentions: list[Mention]) -> None:
    """"A hotel with a restaurant, a bar and a spa": a word that names an object and a room
    (concepts.yaml ``list_rooms``) is the room when rooms stand either side of it in one
    list, in a building that is no home (a home's "kitchen, a bar and a den" keeps its
    bar counter)."""
    words = kb.raw("concepts").get("list_rooms", {})
    if not words or p.building is None:
        return
    if is_dwelling(kb, kb.raw("programs")["buildings"][p.building]["program"]):
        return
    names = kb.raw("rooms")["names"]
    for i, m in enumerate(mentions):
        word = m.name if m.name in words else None
        if m.kind != "object" or word is None or m.negated or m.count not in (None, 1):
            continue
        prev = mentions[i - 1] if i > 0 else None
        nxt = mentions[i + 1] if i + 1 < len(mentions) else None
        if prev is None or prev.kind != "room" or not _LIST_GAP.match(text[prev.end : m.start]):
            continue
        if nxt is not None and (nxt.kind != "room" or not _LIST_GAP.match(text[m.end : nxt.start])):
            continue
        key = words[word]
        if key in names:
            m.kind, m.key = "room", key


def _toilet_rooms(text: str, kb: KnowledgeBase, mentions: list[Mention]) -> None:
    """"Pupil toilets", "two customer toilets", "a hall with a stage and toilets": rooms (a
    restroom each), not toilet pans; "a restroom with three toilets" keeps its pans."""
    names = kb.raw("rooms")["names"]
    for i, m in enumerate(mentions):
        if m.kind != "object" or m.key != "toilet" or m.negated:
            continue
        people = any(w in TOILET_ROOM_WORDS for w in m.name.split()[:-1])
        if not (people or m.plural):
            continue
        before = _room_before(mentions, i)
        if (not people and before is not None and not re.search(r"[.;]", text[before.end : m.start])
                and (names.get(before.key) or {}).get("type") in WASH_TYPES):
            continue
        m.kind, m.key = "room", "restroom"


THE_BEFORE = re.compile(r"\bthe\s+$")


_FOR_USE = re.compile(r"\s+for\s+$")
_USE_LIST = re.compile(r"\s*(?:and|or|&)\s*$")


def _purpose_words(text: str, mentions: list[Mention]) -> list[Mention]:
    """"A cellar for storage and preserves": the room words right after a room's "for",
    with no article or number, joined by "and" or "or", say what the room is for; they
    are no rooms of their own."""
    out: list[Mention] = []
    owner: Mention | None = None  # the room whose "for" list is being read
    last_end = 0  # end of the mention read last, kept or not
    for m in mentions:
        if m.kind == "room" and m.count is None and out:
            if owner is None and out[-1].kind == "room" and _FOR_USE.fullmatch(text[out[-1].end:m.start]):
                owner, last_end = out[-1], m.end
                continue
            if owner is not None and _USE_LIST.fullmatch(text[last_end:m.start]):
                last_end = m.end
                continue
        owner, last_end = None, m.end
        out.append(m)
    return out


def _corefer(text: str, p: Parsed, mentions: list[Mention]) -> list[Mention]:
    """"The hall" after "a church hall", "the kitchen" after "a kitchen": the room named
    before, not another one; "the church" of a parish church is the building (its main
    room). What the later mention holds goes to the room it refers to."""
    rooms = [m for m in mentions if m.kind == "room"]
    head = (p.building_phrase or "").split()[-1:]
    alias: dict[int, int | None] = {}
    head_end = text.find(":")  # "a farmhouse with a cellar: ..., and a cellar for storage": the one announced
    for j, m in enumerate(rooms):
        announced = (0 < head_end < m.start and (m.count or 1) == 1 and not m.plural and not m.negated
                     and any(r.name == m.name and r.end <= head_end and (r.count or 1) == 1 for r in rooms[:j]))
        if not announced and (m.count is not None or m.plural or m.negated or not THE_BEFORE.search(text[: m.start])):
            continue
        earlier = next((i for i in range(j - 1, -1, -1)
                        if i not in alias and (rooms[i].name == m.name or rooms[i].name.endswith(" " + m.name))), None)
        if earlier is not None:
            alias[j] = earlier
        elif head and m.name == head[0] and not m.key:
            alias[j] = None
    return _aliased(mentions, rooms, alias)


FORMER_ROOM = re.compile(r"\b(?:former|old|original|one time|erstwhile|disused)\s+(?:[\w'-]+\s+){0,2}$")
"""Words before a room that say it was once that room ("the old engine bay is ...")."""

NOW_ROOM = re.compile(
    r"(?:\s*,[^,.;:()]{1,40},)?\s+(?:(?:is|was)\s+)?(?:now\s+)?"
    r"(?:is|has become|became|becomes|is becoming|will become|serves as|is used as|used as|turned into|houses|now)"
    r"(?:\s+now)?\s+(?:the|a|an|our|my|his|her|their)\s+(?:[\w'-]+\s+){0,2}")
"""What links a room's former use to the room it now is: "... is now the", "... has become
a", "..., right next to ours, is becoming the"."""


def _former_rooms(text: str, mentions: list[Mention]) -> list[Mention]:
    """"The old engine bay is the living room", "the former crew dormitory is now the
    primary bedroom": a room named as what it was, linked to the room it is now, is that
    room (what the text puts in it goes there); the old use names no room of its own. A
    plain "the kitchen is the heart of the home" says no former use: the first room must
    be said to be old or former, or the link must say "now" or "become"."""
    rooms = [m for m in mentions if m.kind == "room"]
    alias: dict[int, int | None] = {}
    for j, (a, b) in enumerate(zip(rooms, rooms[1:])):
        link = NOW_ROOM.fullmatch(text, a.end, b.start)
        if link is None or a.negated or b.negated or not (b.key or b.name.split()[-1] in DESCRIBED_HEADS):
            continue
        said_old = FORMER_ROOM.search(text, max(0, a.start - 40), a.start) is not None or any(
            w in {"former", "old", "original", "erstwhile", "disused"} for w in a.name.split())
        if said_old or re.search(r"\b(?:now|become|became|becomes|becoming)\b", link.group()):
            alias[j] = j + 1
    return _aliased(mentions, rooms, alias)


APPOSED = re.compile(r"\s*\(\s*|\s*:\s*(?:a|an|the|one)\s+(?:[\w'-]+\s+){0,3}")
"""Between a room and another name for it: "a Turkish bath (hammam", "the cabinet of
curiosities: a wood-panelled room"."""

DESCRIBED_HEADS = frozenset({"room", "space", "chamber"})
"""Words a description of a room ends in ("a wood-panelled room"), naming no kind of room."""


def _apposed_rooms(text: str, mentions: list[Mention]) -> list[Mention]:
    """A room named again right after itself is one room: in brackets ("a Turkish bath
    (hammam)"), or described after a colon by words that name no kind of room ("the
    cabinet of curiosities: a wood-panelled room lined with cases"). What the text puts
    in the second goes to the first."""
    rooms = [m for m in mentions if m.kind == "room"]
    alias: dict[int, int | None] = {}
    for j, (a, b) in enumerate(zip(rooms, rooms[1:])):
        link = APPOSED.fullmatch(text, a.end, b.start)
        if link is None or a.negated or b.negated or (b.count or 1) > 1 or j in alias:
            continue
        if "(" in link.group() or (not b.key and b.name.split()[-1] in DESCRIBED_HEADS):
            alias[j + 1] = j
    return _aliased(mentions, rooms, alias)


def _aliased(mentions: list[Mention], rooms: list[Mention], alias: dict[int, int | None]) -> list[Mention]:
    """``mentions`` without the rooms ``alias`` maps (index in ``rooms`` -> the room they
    are, or None), each object in one of them moved to the room it maps to."""
    if not alias:
        return mentions
    keep = {j: k for k, j in enumerate(j for j in range(len(rooms)) if j not in alias)}
    for o in mentions:
        if o.kind == "object" and o.room is not None:
            r: int | None = o.room
            while r is not None and r in alias:
                r = alias[r]
            o.room = None if r is None else keep[r]
    gone = {id(rooms[j]) for j in alias}
    return [m for m in mentions if id(m) not in gone]


_MORE_WORDS = frozenset({"further", "other", "additional", "extra", "remaining"})
"""Words that say a room is one more of its kind, not what kind ("three further
bedrooms" are bedrooms, not "further bedrooms")."""
TOTAL_KEYS = frozenset({"bedroom", "bathroom"})
"""Rooms whose count before the building's noun is the house's total ("a four-bedroom
detached house"; :func:`_house_totals`)."""
TOTAL_GAP_TOKENS = 3
"""Most words between such a count and the building's noun ("four-bedroom detached family home")."""


def _house_totals(text: str, p: Parsed, mentions: list[Mention]) -> list[Mention]:
    """"A four-bedroom family home ... a master bedroom, three further bedrooms": the
    count hyphenated before the building's noun is the house's total, and the bedrooms
    the text names after it are among them, not more (measured on dev_storeys3: eight
    bedrooms for a four-bedroom home, "a three-bedroom house with a master bedroom" four).
    The total keeps the rooms not named (four less the four named: none)."""
    rooms = [m for m in mentions if m.kind == "room"]
    head = p.building_phrase or ""
    alias: dict[int, int | None] = {}
    for j, t in enumerate(rooms):
        total = t.count or 0
        if t.key not in TOTAL_KEYS or total < 1 or t.negated:
            continue
        at = text.find(head, t.end) if head else -1
        if at < 0 or len(_tokens(text[t.end:at])) > TOTAL_GAP_TOKENS or re.search(r"[,.;:]", text[t.end:at]):
            continue
        named = [i for i in range(j + 1, len(rooms)) if not rooms[i].negated
                 and (rooms[i].key == t.key or rooms[i].name.endswith(" " + t.key))]
        if not named:
            continue
        n_named = sum(rooms[i].count or 1 for i in named)
        if n_named >= total:
            alias[j] = named[0]
        else:
            t.count = t.asked = total - n_named
    return _aliased(mentions, rooms, alias)


ONE_PERSON_HEADS = frozenset("desk desks workstation bed cot berth station locker".split())
"""Heads of things one person uses each: "desks for forty" are forty desks (a table for
six is one table; chairs are left out: "stacking chairs for a hundred" in a hall of
tables are its tables' chairs, not a hundred more)."""

SEAT_GAP_TOKENS = 3
"""A seat count belongs to the room named at most this many words before it ("a dining
room seating 12", "a boardroom for 16")."""


def _find_seats(text: str, p: Parsed, mentions: list[Mention]) -> None:
    """``p.seats``: (room mention index or None for the building, people) for each seat
    count; a table's ("a table for six") is its own, read where tables are sized."""
    for mt in SEATS.finditer(text):
        n = parse_number(mt.group(1))
        if n is None or n < 2:
            continue
        last = _last_before(mentions, mt.start())
        gap = text[last.end : mt.start()] if last is not None else ""
        near = last is not None and len(_tokens(gap)) <= SEAT_GAP_TOKENS and not re.search(r"[.;:,]", gap)
        if near and last is not None and last.kind == "object":
            if last.plural and last.count is None and (last.key or last.name).split()[-1] in ONE_PERSON_HEADS:
                per = 2 if "bunk" in last.name.split() else 1  # "bunk beds for twelve": six
                last.count = last.asked = -(-n // per)  # "hot desks for forty": forty desks
                p.objects = [o for o in p.objects if not (o.start < mt.start(1) and mt.start() < o.end)]
            continue
        if near and last is not None and last.kind == "room":
            p.seats.append((next(i for i, r in enumerate(p.rooms) if r is last), n))
        elif mt.group(2) or last is None:  # "a bistro for 40 covers", "a church that seats 200"
            p.seats.append((None, n))
        else:
            continue
        # "seats 200", "seating for 35": the verb is no seat object
        p.objects = [o for o in p.objects if not (o.start < mt.start(1) and mt.start() < o.end)]


_COUPLE = re.compile(r"\b(?:couple(?! of\b)|newlyweds|two people)\b")  # "a couple of armchairs" counts chairs
_MEMBERS = re.compile(
    r"\b(?!an?\b)(\w+) (parents|adults|grandparents|roommates|flatmates|friends|kids|children|toddlers|babies|"
    r"boys|girls|teens|teenagers|sons|daughters)\b(?!'|\s+(?:room|rooms|bedroom|bedrooms|bathroom|bathrooms|area|"
    r"corner|zone|space|wing|bed|beds|table|tables|desk|desks|furniture|play)\b)"
)
"""Household members counted when no "family of N" is given ("two parents and three
kids"); not a room or an object named for them ("a kids room", "two kids' desks")."""
_UNKNOWN_ROOM = re.compile(
    r"\b([^\W\d_]+(?:'s|s')?) (room|nook|corner|suite|lounge|den|booth|cave|shed|chamber|parlou?r|studio|"
    r"cellar|loft|workshop|bay|quarters|sanctuary)s?\b"
)


NEGATIONS = re.compile(
    r"\b(?:without|no|nor|neither|not (?:a|an|any|one|a single)|(?:do|does|did|will|would|should)(?:n't| not) "
    r"(?:have|need|want|include|contain|get)(?: (?:a|an|any))?|free of|lacking(?: (?:a|an|any))?)$"
)
"""Words that rule out the room or object right after them ("a house without a kitchen",
"but no garage", "a bedroom with no tv", "doesn't need a dining room")."""

NEGATION_BLOCKERS = frozenset("more less fewer longer than matter doubt bigger larger smaller other extra need".split())
"""Words after "no" that make it no negation of what follows ("no more than two
bedrooms", "no bigger than", "no need for"... the last one is a negation but of
"need", so it is left to the mention's own words)."""

NEGATION_FILLERS = frozenset("a an any the single one separate real proper".split())
"""Words that may stand between a negation and what it rules out."""

LIST_JOINERS = frozenset({",", "or", "nor", "and"})
"""Words that continue a negated list ("no tv, rug or lamp")."""

ROOMS_TOTAL = re.compile(r"\b(\w+) rooms?\b")
"""A bare room count: "a hotel with 40 rooms"."""


@dataclass
class Mention:
    """A room or object named in the text."""

    kind: str  # "room" | "object"
    key: str  # rooms.yaml names key / objects.yaml key ("" for unknown rooms)
    name: str  # the user's words, singular ("canopy bed", "wine cellar")
    start: int
    end: int
    count: int | None = None  # explicit number, None if unsaid
    plural: bool = False
    many: bool = False  # "full of", "lots of", "several"
    size: float = 1.0  # size factor from adjectives
    words: list[str] = field(default_factory=list)  # adjectives kept in the name
    room: int | None = None  # index of the room mention it belongs to (objects)
    arrangement: str | None = None  # rows | along_walls | center | around | symmetric
    concept: str | None = None  # rooms: furnishing set found by the embedding matcher
    open_vocab: bool = False  # found by anyhome.plan.openvocab, not by a knowledge phrase
    each: bool = False  # objects: "rooms, each with ..." -> one set in every such room
    negated: bool = False  # "without a kitchen", "no rug", "0 kitchens": the text rules it out
    asked: int | None = None  # the count as the text wrote it, before any cap
    host: Mention | None = None  # objects: the room word right before it ("a courtyard fountain")
    area_m2: float | None = None  # rooms: the area the text states for it ("a 12 m2 bedroom")
    owner: str | None = None  # rooms: the possessive right before it ("the editor's office": "editor")
    variants: list[str] = field(default_factory=list)  # rooms: a name per copy ("east and west side rooms")
    seat_of: Mention | None = None  # objects: the table these seats come with ("a table with benches")


@dataclass
class MaterialMention:
    phrase: str  # "blue marble accent"
    material: str  # "marble"
    surfaces: list[str]  # floor | walls | ceiling | furniture
    start: int
    room: int | None = None  # room mention index, None -> whole house
    explicit: bool = False  # a surface word (walls, floor...) named the surface


@dataclass
class Parsed:
    """Everything ``parse`` found in the text."""

    text: str
    building: int | None = None  # index into programs.yaml buildings
    building_word: str | None = None  # the user's word when the embedding matcher chose the program
    building_score: float = 1.0  # how close the embedding matcher found it (1.0: a word the knowledge lists)
    building_size: float = 1.0
    building_phrase: str | None = None  # the user's words for the building ("pilates studio", "sushi restaurant")
    former: int | None = None  # buildings entry of the building's former use ("a converted chapel")
    rooms: list[Mention] = field(default_factory=list)
    objects: list[Mention] = field(default_factory=list)
    styles: list[str] = field(default_factory=list)  # style keys, in order of appearance
    style_words: list[str] = field(default_factory=list)  # the user's style words, as written
    colours: list[str] = field(default_factory=list)
    materials: list[MaterialMention] = field(default_factory=list)
    aged: dict[str, list[str]] = field(default_factory=dict)  # surface -> weathering words on it alone ("dusty floors")
    bedrooms: int | None = None  # from "3B2B" / "3br"
    bathrooms: int | None = None
    people: int | None = None
    seats: list[tuple[int | None, int]] = field(default_factory=list)  # (room mention or None: the building, people)
    one_room: bool = False  # "a one-room house"
    total_rooms: int | None = None  # "a hotel with 40 rooms": rooms asked for in all
    storeys: int = 1  # "a three-storey townhouse", "two floors": storeys above ground, ground included
    basement: bool = False  # "with a basement", "a cellar gym"
    attic: bool = False  # "an attic bedroom", "a loft conversion"
    total_m2: float | None = None  # "a 50 m2 flat", "500 sq ft": the floor area the text states
    floor_words: list[tuple[int, int, str]] = field(default_factory=list)  # (start, end, storey word): "on the first floor" -> "first"
    size_words: list[str] = field(default_factory=list)  # sizes.words found before the building word ("tiny")
    room_areas: list[tuple[int, float]] = field(default_factory=list)  # (end of "12 m2", m2) right before a room word
    proper_words: frozenset[str] = frozenset()  # words written capitalised mid-sentence, lower-cased
    warnings: list[str] = field(default_factory=list)

    @property
    def recognized(self) -> bool:
        return bool(
            self.building is not None or self.rooms or self.objects or self.styles
            or self.bedrooms or self.people or self.total_rooms
        )  # fmt: skip


_SCI_TOKEN = re.compile(r"(\d{1,3})e(\d{1,3})")
_NEG_TOKEN = re.compile(r"neg(\d{1,30})")


def parse_number(word: str) -> int | None:
    """``"12"`` -> 12, ``"twelve"`` -> 12, ``"a"`` -> 1, ``"1e9"`` -> 10**9, the
    parser's own ``"neg3"`` (what ``"-3"`` in the text becomes) -> -3; None for other words."""
    if word.isdigit():
        return int(word) if len(word) <= 30 else 10**MAX_EXPONENT
    if (mt := _SCI_TOKEN.fullmatch(word)) is not None:
        return int(mt.group(1)) * 10 ** min(int(mt.group(2)), MAX_EXPONENT)
    if (mt := _NEG_TOKEN.fullmatch(word)) is not None:
        return -int(mt.group(1))
    return NUMBER_WORDS.get(word)


def format_count(n: int) -> str:
    """A count for a warning: ``1200``, or ``1e9`` from a million up."""
    if abs(n) >= 10**6:
        digits = str(abs(n))
        lead = digits[0] + ("." + digits[1:3].rstrip("0") if digits[1:3].strip("0") else "")
        return ("-" if n < 0 else "") + f"{lead}e{len(digits) - 1}"
    return str(n)


_NUM_EXPR = re.compile(
    r"(?<![\w.,])(?P<neg>[-\u2212] ?)?(?P<int>\d{1,3}(?:,\d{3})+(?![\d,])|\d+)(?P<frac>\.\d+)?"
    r"(?:(?: ?(?:\^|\*\*) ?(?P<exp>[-\u2212]?\d+))|(?:e\+?(?P<sci>\d+)))?(?![\w.]\w)"
)
"""A number written in figures: ``12``, ``-3``, ``1,000,000``, ``2.5``, ``1e9``, ``1.5e+6``,
``10^9``, ``10**9``."""

_WORD_UNITS = {w: n for w, n in NUMBER_WORDS.items() if w in (
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen "
    "sixteen seventeen eighteen nineteen").split()}  # fmt: skip
_WORD_TENS = {w: n for w, n in NUMBER_WORDS.items() if w in "twenty thirty forty fifty sixty seventy eighty ninety".split()}
_WORD_SCALES = {"hundred": 100, "dozen": 12, "thousand": 10**3, "million": 10**6, "billion": 10**9, "trillion": 10**12}
_WORD_RUN = re.compile(r"\b(?:(?:a|an|and|\d+|" + "|".join([*_WORD_UNITS, *_WORD_TENS, *_WORD_SCALES]) + r") ?)+\b")


def _words_value(words: list[str]) -> tuple[int, int]:
    """Value of the longest number phrase at the start of ``words`` ("two hundred and
    fifty", "a million", "3 dozen") and how many words it takes; (0, 0) if none."""
    total = cur = used = 0
    last = ""  # "", "a", "small" (a unit, teen or figure), "tens", "hundred", "scale", "and"
    for i, w in enumerate(words):
        if w in ("a", "an") and last == "":
            kind = "a"
        elif w.isdigit() and last in ("", "and", "scale") and len(w) <= 15:
            kind = "small"
        elif w in _WORD_UNITS and last in ("", "tens", "hundred", "scale", "and"):
            kind = "small"
        elif w in _WORD_TENS and last in ("", "hundred", "scale", "and"):
            kind = "tens"
        elif w in _WORD_SCALES and last in ("a", "small", "tens"):
            kind = "hundred" if _WORD_SCALES[w] < 1000 else "scale"
        elif w == "and" and last in ("hundred", "scale") and i + 1 < len(words) and (words[i + 1] in _WORD_UNITS or words[i + 1] in _WORD_TENS):
            kind = "and"
        else:
            break
        if kind == "a":
            cur = 1
        elif kind in ("small", "tens"):
            cur += int(w) if w.isdigit() else NUMBER_WORDS[w]
        elif kind == "hundred":
            cur *= _WORD_SCALES[w]
        elif kind == "scale":
            total, cur = total + cur * _WORD_SCALES[w], 0
        last = kind
        if kind not in ("a", "and"):
            used = i + 1
    if last == "a" and used == 0:
        return 0, 0
    return total + cur, used


def _canonical(n: int) -> str:
    """A count as one token ``parse_number`` reads back: ``12``, ``1e9``, ``neg3``."""
    if n < 0:
        return f"neg{min(-n, 10**30)}"
    if n >= 10**12:
        return f"{str(n)[0]}e{min(len(str(n)) - 1, MAX_EXPONENT)}"
    return str(n)


def _figures_value(mt: re.Match[str]) -> int:
    """The count a :data:`_NUM_EXPR` match stands for, at most ``10**MAX_EXPONENT``."""
    digits = mt.group("int").replace(",", "").lstrip("0") or "0"
    mantissa = float(f"{digits[:15]}{mt.group('frac') or ''}") if len(digits) <= 15 else float(f"{digits[0]}.{digits[1:15]}")
    log10 = (len(digits) - 1 if len(digits) > 15 else 0) + (math.log10(mantissa) if mantissa > 0 else -math.inf)
    if mt.group("exp") is not None:
        log10 *= int(mt.group("exp").replace("\u2212", "-")[:6])
    elif mt.group("sci") is not None:
        log10 += int(mt.group("sci")[:6])
    if mantissa == 0 or log10 < -MAX_EXPONENT:
        n = 0 if mantissa == 0 else 1
    elif log10 >= MAX_EXPONENT:
        n = 10**MAX_EXPONENT
    else:
        n = math.ceil(10.0**log10 - 1e-9) if log10 < 15 else int(10.0**log10)  # "2.5 baths": a half bath is a room
    return -n if mt.group("neg") else n


_APPROX = re.compile(r"\b(?:about|around|approximately|roughly|nearly|almost|circa|at least|up to)\s+(?=(?:\d|(?:"
                     + "|".join(sorted(NUMBER_WORDS, key=len, reverse=True)) + r")\b))")
"""A word that hedges the count after it ("about twenty desks"): the count is read as given."""


def rewrite_numbers(text: str) -> str:
    """``text`` (normalised) with every count written as one token: figures with
    separators, decimals, powers and exponents ("1,000", "10^9", "1e9", "-3") and number
    phrases ("two hundred and fifty", "a million", "3 dozen") become ``parse_number``'s
    forms; a hedge before a count ("about twenty") goes. Single words ("a", "twelve",
    "no") are left as they are."""
    text = _APPROX.sub("", text)
    text = _NUM_EXPR.sub(lambda mt: _canonical(_figures_value(mt)), text)
    out, pos = [], 0
    for mt in _WORD_RUN.finditer(text):
        words = mt.group().split()
        start = mt.start()
        while words:
            value, used = _words_value(words)
            phrase = " ".join(words[:used])
            if used >= 2:
                out.append(text[pos:start])
                out.append(_canonical(value))
                pos = start + len(phrase)
            step = max(used, 1)
            start += len(" ".join(words[:step])) + 1
            words = words[step:]
    out.append(text[pos:])
    return "".join(out)


def _tokens(text: str) -> list[tuple[str, int, int]]:
    return [(m.group(), m.start(), m.end()) for m in _TOKEN.finditer(text)]


PAIR_WORDS = {"pair": 2, "couple": 2, "brace": 2, "trio": 3}
"""Nouns that count what follows them with "of" ("a pair of speakers": two)."""
PAIR_OF = re.compile(r"\b(?:a|one)\s+(pair|couple|brace|trio)\s+of\s+$")
"""The words right before a mention's phrase that count it (:data:`PAIR_WORDS`)."""


COMPOUND_ADJECTIVES = {"floor to ceiling": "tall", "wall to wall": "fitted", "top of range": "premium"}
"""Hyphenated adjectives of three words (hyphens read as spaces) -> the one word they
mean; read as one adjective, not as their last word ("floor-to-ceiling bookshelves" are
tall bookshelves, not "ceiling bookshelves")."""


ROOM_NUMBER_ADJECTIVES = frozenset({"single", "double", "twin"})
"""Number words that say what kind a room is, not how many ("a double bedroom")."""


def _look_back(m: Mention, text: str, tokens: list[tuple[str, int, int]], taken: list[tuple[int, int]], keep_words: bool, kb: KnowledgeBase) -> None:
    """Fill count, size and adjectives of ``m`` from the words just before it."""
    sizes = size_factors(kb)
    before = [t for t in tokens if t[2] <= m.start]
    for i in range(len(before) - 1, 0, -1):  # "an open-plan kitchen": a kitchen, the plan is open
        if before[i][0] == "plan" and before[i - 1][0] == "open" and i >= len(before) - 4:
            del before[i - 1:i + 1]
            break
    if len(before) >= 3 and (phrase := COMPOUND_ADJECTIVES.get(" ".join(t[0] for t in before[-3:]))):
        before[-3:] = [(phrase, before[-3][1], before[-1][2])]  # "floor-to-ceiling bookshelves": tall ones
    words: list[str] = []
    first = m.start  # where the phrase with its adjectives starts
    for tok, s, e in reversed(before[-4:]):
        if any(a <= s < b for a, b in taken) or tok == "no":  # "no": see _apply_negation
            break
        n = parse_number(tok)
        if n is not None and m.kind == "room" and tok in ROOM_NUMBER_ADJECTIVES and not m.key:
            if tok != "single":  # a room the knowledge does not know: "a single panelled room" is one
                break
        elif n is not None and m.kind == "room" and tok in ROOM_NUMBER_ADJECTIVES:
            n = None  # "a double bedroom" is one room, "six twin bedrooms" six
            if keep_words:
                words.insert(0, tok)
            first = s
            continue
        if n is not None:
            m.count = n
            break
        if tok in MANY_WORDS:
            m.many = True
            break
        if tok in sizes:
            m.size *= sizes[tok]
            first = s
            continue
        if tok.endswith("'s") and m.kind == "room":
            m.owner = tok[:-2]  # "the editor's office": a person's own room
        if tok in STOP_WORDS or not tok.isalpha() or tok.endswith("'s") or len(words) >= 2:
            break
        if keep_words:
            words.insert(0, tok)
        first = s
    prefix = text[max(0, first - 16) : first]  # "rows of wooden pews", "full of old books"
    if any(prefix.rstrip().endswith(f) for f in FULL_WORDS):
        m.many = True
    if m.count is None and (pair := PAIR_OF.search(prefix)) is not None:  # "a pair of sawhorses"
        m.count = PAIR_WORDS[pair.group(1)]
    m.words = words
    if m.count is not None and m.count > 1:
        m.plural = True


def _parse_building(kb: KnowledgeBase, text: str, p: Parsed, taken: list[tuple[int, int]]) -> tuple[int, int] | None:
    voc = vocabulary(kb)
    longer = [mt.span() for mt in voc.regex.finditer(text)]
    buildings = kb.raw("programs")["buildings"]
    matches = [
        b for b in voc.building_regex.finditer(text)
        if not any(a <= b.start() and b.end() <= e and e - a > b.end() - b.start() for a, e in longer)
        and not _ruled_out_building(buildings[voc.building_forms[b.group()]], text)
    ]  # fmt: skip  ("a box office": a room, not an office building)
    old = _former_uses(kb, text, matches)
    if old:  # "a converted chapel": the chapel names neither the building nor a room
        (first, (a, e)), into_end = old[0], _into_end(kb, text, old[0][1][1])
        p.former = voc.building_forms[first.group()]
        taken.extend(span for _, span in old)
        matches = [b for b in matches if not any(x <= b.start() < y for _, (x, y) in old)
                   and (b.start() < a or not text[e : b.start()].strip()  # "a hotel in a former bank", "a chapel home"
                        or (into_end is not None and b.start() >= into_end and len(_tokens(text[into_end : b.start()])) <= 3))]
        if not matches:
            return _converted_building(kb, text, p, (a, e), into_end)
    if not matches:
        return None
    best = matches[0]
    run_start = best.start()  # "a mid-terrace house": the run of building words is the building's, no room's
    for nxt in matches[1:]:  # "a boutique hotel": the head of adjacent building words wins
        if text[best.end() : nxt.start()].strip():
            break
        if not _plain_home_after_a_home(kb, best, nxt):  # "a narrowboat home" stays a narrowboat
            best = nxt
    opening = _opening_building(kb, text, best.start(), taken)
    if opening is not None:  # "a steakhouse with ... a bar": the text's subject is the building
        program, span, head, score = opening
        p.building = next(i for i, b in enumerate(kb.raw("programs")["buildings"]) if b["program"] == program)
        p.building_word, p.building_score = head, score
        _building_modifiers(kb, text, span[0], p, taken=taken)
        _size_words(kb, text, span[1], p)  # the head itself may be the size word ("a tiny")
        p.building_phrase = _with_modifier(kb, text, span[0], head, taken)
        return span
    p.building = voc.building_forms[best.group()]
    _building_modifiers(kb, text, run_start, p, taken=taken)
    _size_words(kb, text, best.end(), p)  # "a tiny house": the size word is in the building's phrase
    p.building_phrase = _with_modifier(kb, text, best.start(), best.group(), taken)
    return run_start, best.end()


def _plain_home_after_a_home(kb: KnowledgeBase, first: re.Match[str], head: re.Match[str]) -> bool:
    """Whether ``head`` is the plain word for a home (the first buildings entry: house,
    home) after a word naming a kind of home ("a narrowboat home", "a farmhouse home"):
    the kind says more, its look and sizes included."""
    forms = vocabulary(kb).building_forms
    buildings = kb.raw("programs")["buildings"]
    return forms[head.group()] == 0 and forms[first.group()] != 0 and is_dwelling(kb, buildings[forms[first.group()]]["program"])


def _words_alternation(words: Sequence[str]) -> str:
    """A regex alternation of ``words`` as the parser reads them, longest first."""
    return "|".join(re.escape(normalize(w)) for w in sorted(words, key=len, reverse=True)) or "(?!)"


FORMER_GAP_WORDS = 3
"""Words that may stand between a `before` word and the old building's word ("converted
1920s fire station", "a former Methodist chapel", "converted grade ii listed barn")."""


def _former_uses(kb: KnowledgeBase, text: str, matches: Sequence[re.Match[str]]) -> list[tuple[re.Match[str], tuple[int, int]]]:
    """The building words that name a building's former use (programs.yaml
    ``conversions``), each with the span of its words ("converted stone barn", "chapel
    conversion"). A dwelling's word is never one: "a converted farmhouse" is a farmhouse."""
    conv = kb.raw("programs").get("conversions")
    if not conv:
        return []
    before = re.compile(rf"\b(?:{_words_alternation(conv['before'])})\s+(?:[\w'-]+\s+){{0,{FORMER_GAP_WORDS}}}$")
    after = re.compile(rf"\s+(?:{_words_alternation(conv.get('after', []))})\b")
    buildings = kb.raw("programs")["buildings"]
    out = []
    for b in matches:
        if is_dwelling(kb, buildings[vocabulary(kb).building_forms[b.group()]]["program"]):
            continue
        start, end = b.span()
        if (pre := before.search(text, 0, b.start())) is not None:
            start = pre.start()
        if (post := after.match(text, b.end())) is not None:
            end = post.end()
        if (start, end) == b.span() and _into_end(kb, text, end) is None:
            continue
        out.append((b, (start, end)))
    return out


def _into_end(kb: KnowledgeBase, text: str, pos: int) -> int | None:
    """Where an `into` phrase right after ``pos`` ends ("turned into", ", now a"), if any."""
    conv = kb.raw("programs").get("conversions") or {}
    into = re.compile(rf"[\s,]*(?:(?:that|which)\s+(?:is|was|has been)\s+)?(?:{_words_alternation(conv.get('into', []))})\b")
    mt = into.match(text, pos)
    return mt.end() if mt is not None else None


def _converted_building(kb: KnowledgeBase, text: str, p: Parsed, span: tuple[int, int], into_end: int | None) -> tuple[int, int]:
    """The building a converted one is, when the text names no other building word: a
    plural after its `into` phrase ("turned into flats"), else ``conversions.program``'s
    first building entry. Returns the old building's span (the building's phrase)."""
    buildings = kb.raw("programs")["buildings"]
    forms = vocabulary(kb).building_forms
    target = None
    if into_end is not None:
        for tok, _, _ in _tokens(text[into_end:])[:FORMER_GAP_WORDS + 1]:
            if tok.isalpha() and (word := _singular(tok)[0]) in forms:
                target = forms[word]
                break
    if target is None:
        program = kb.raw("programs")["conversions"]["program"]
        target = next(i for i, b in enumerate(buildings) if b["program"] == program)
    p.building = target
    _building_modifiers(kb, text, span[0], p, taken=[])
    _size_words(kb, text, span[1], p)
    p.building_phrase = text[span[0] : span[1]]
    return span


def _ruled_out_building(entry: dict, text: str) -> bool:
    """Whether the text holds one of the building entry's ``unless`` words ("a studio"
    with an easel is no studio apartment)."""
    return any(re.search(rf"\b{re.escape(w.lower())}(?:s|'s|s')?(?!\w)", text) for w in entry.get("unless", []))  # "architects'"


def _with_modifier(kb: KnowledgeBase, text: str, start: int, phrase: str, taken: list[tuple[int, int]]) -> str:
    """The building word with the one plain word before it ("sushi" restaurant), if any."""
    voc = vocabulary(kb)
    before = _tokens(text[:start])[-1:]
    for tok, s, _ in before:
        if (
            tok.isalpha() and tok not in STOP_WORDS and tok not in size_factors(kb) and tok not in MANY_WORDS
            and parse_number(tok) is None and tok not in voc.style_forms and not voc.colour_regex.fullmatch(tok)
            and not voc.material_regex.fullmatch(tok) and not any(a <= s < b for a, b in taken) and len(tok) > 2
            and tok not in voc.forms and tok not in voc.building_forms
        ):  # fmt: skip
            return f"{tok} {phrase}"
    return phrase


def _opening_building(kb: KnowledgeBase, text: str, known_start: int, taken: list[tuple[int, int]]) -> tuple[str, tuple[int, int], str, float] | None:
    """The program for the head of the text's opening noun phrase when the first known
    building word only comes after it; None when the head maps to no building."""
    tokens = _tokens(text)
    fnp = ov.first_noun_phrase(text, tokens)
    if fnp is None or fnp[2] > known_start or not text[fnp[2] : known_start].strip():
        return None  # "a village dentist's surgery": the opening word qualifies the building
    head = fnp[0].split()[-1]
    s = fnp[2] - len(head)
    if any(a < fnp[2] and s < b for a, b in taken) or head in ov.non_objects(kb) or head in vocabulary(kb).forms:
        return None
    if head in size_factors(kb):  # "a small 65 m2 house", "a grand, rambling house": a size, not a building
        return None
    mb = ov.map_building(head, kb)
    return (mb.key, (s, fnp[2]), head, mb.score) if mb is not None else None


def _filler(tok: str, kb: KnowledgeBase) -> bool:
    """A word that may stand between a negation or a list joiner and the next mention:
    an article or an adjective, never a count, a break word or a blocker."""
    if tok in NEGATION_FILLERS or tok in size_factors(kb):
        return True
    return (
        tok.isalpha() and tok not in STOP_WORDS and tok not in ov.PHRASE_BREAKS and tok not in NEGATION_BLOCKERS
        and parse_number(tok) is None and tok not in MANY_WORDS and not NEGATIONS.search(tok)
    )  # fmt: skip


def _apply_negation(text: str, mentions: list[Mention], kb: KnowledgeBase) -> None:
    """Mark what the text rules out: a mention right after a negation word (with only
    articles and adjectives between) and the list it heads ("no tv, rug or lamp";
    "without a kitchen and bathroom"; but "no garage, a big kitchen" rules out the
    garage only). A zero count ("0 kitchens", "zero chairs") rules out too."""
    ordered = sorted(mentions, key=lambda m: m.start)
    k = 0
    while k < len(ordered):
        m = ordered[k]
        if m.count == 0:
            m.negated = True
        prev_end = ordered[k - 1].end if k else 0
        head = _tokens(text[prev_end : m.start])
        negated = False
        for _ in range(4):  # the negation, then up to three articles or adjectives
            if not head:
                break
            if NEGATIONS.search(text[prev_end : prev_end + head[-1][2]]):
                negated = True
                break
            if not _filler(head[-1][0], kb):
                break
            head.pop()
        if not negated:
            k += 1
            continue
        chain = [m]
        joiners: list[set[str]] = []
        j = k + 1
        while j < len(ordered):
            between = _tokens(text[chain[-1].end : ordered[j].start])
            words = {t for t, _, _ in between}
            if not between or len(between) > 5 or not words & LIST_JOINERS:
                break
            if not all(t in LIST_JOINERS or _filler(t, kb) for t in words):
                break
            chain.append(ordered[j])
            joiners.append(words)
            j += 1
        last_or = max((i for i, w in enumerate(joiners) if w & {"or", "nor"}), default=-1)
        if last_or >= 0:  # "no tv, a rug or a lamp": the whole list up to the last "or"
            chain = chain[: last_or + 2]
        else:  # "without a kitchen and bathroom", but "no garage and a pool" keeps the pool
            n = 1
            while n < len(chain) and not joiners[n - 1] & {"a", "an", "the"}:
                n += 1
            chain = chain[:n]
        for x in chain:
            x.count, x.negated, x.plural, x.many = 0, True, False, False
        k += len(chain)


def _building_modifiers(kb: KnowledgeBase, text: str, start: int, p: Parsed, keep_unmapped: bool = True, taken: Sequence[tuple[int, int]] = ()) -> None:
    """Size words and the user's own style words just before the building word
    ("a Craftsman bungalow", "a neon lit retro arcade"); words that match no style are
    kept only if ``keep_unmapped`` (the head word was recognised) and the user wrote
    them capitalised mid-sentence, as names of styles are ("a Craftsman bungalow", not "a
    day spa")."""
    voc = vocabulary(kb)
    for tok, s, _ in reversed(_tokens(text[:start])[-3:]):
        if any(a <= s < b for a, b in taken):
            break
        if tok in size_factors(kb):
            p.building_size *= size_factors(kb)[tok]
            continue
        if tok in STOP_WORDS or not tok.isalpha() or parse_number(tok) is not None or tok in MANY_WORDS:
            break
        if tok in voc.forms or tok in voc.style_forms or voc.colour_regex.fullmatch(tok) or tok in ov.non_objects(kb) or tok in voc.building_forms:
            continue
        ms = ov.map_style(tok, kb)
        if ms is None and not (keep_unmapped and tok in p.proper_words):
            continue
        p.style_words.insert(0, tok)
        if ms is not None and ms.key not in p.styles:
            p.styles.append(ms.key)


def _find_mentions(kb: KnowledgeBase, text: str, p: Parsed, taken: list[tuple[int, int]]) -> list[Mention]:
    voc = vocabulary(kb)
    found: list[Mention] = []
    names = kb.raw("rooms")["names"]
    program = kb.raw("programs")["buildings"][p.building]["program"] if p.building is not None else None
    words = (kb.raw("programs")["programs"].get(program or "") or {}).get("object_words", {})
    for mt in voc.regex.finditer(text):
        if any(a < mt.end() and mt.start() < b for a, b in taken):
            continue
        entry, plural = voc.forms[mt.group()]
        only = names.get(entry.key, {}).get("only_within") if entry.kind == "room" else None
        if only and program not in only:  # "vendor stalls" of a market: no rooms
            if mt.group() not in voc.hidden_objects:
                continue
            entry, plural = voc.hidden_objects[mt.group()]  # "the range" of a farmhouse kitchen: its stove
        key = words.get(entry.key, entry.key) if entry.kind == "object" else entry.key  # a lab's workbench
        phrase = key if key != entry.key else entry.phrase  # ... is a lab bench, by name too
        found.append(Mention(entry.kind, key, phrase, mt.start(), mt.end(), plural=plural))
    found = _merge_adjacent(text, found)
    spans = taken + [(m.start, m.end) for m in found]
    for mt in _UNKNOWN_ROOM.finditer(text):
        word = mt.group(1)
        if word in STOP_WORDS or word in NUMBER_WORDS or word in size_factors(kb) or word in MANY_WORDS:
            continue
        if any(a < mt.end() and mt.start() < b for a, b in spans):
            continue
        name = f"{word} {mt.group(2)}"
        found.append(Mention("room", "", name, mt.start(), mt.end(), plural=mt.group().endswith("s")))
    found.sort(key=lambda m: m.start)
    return found


def _merge_adjacent(text: str, found: list[Mention]) -> list[Mention]:
    """Join object words written back to back ("buddha statue") into one mention."""
    out: list[Mention] = []
    for m in found:
        prev = out[-1] if out else None
        if (
            prev is not None and prev.kind == "object" and m.kind == "object"
            and not text[prev.end : m.start].strip() and not prev.plural
        ):  # fmt: skip
            m.name = f"{prev.name} {m.name}"
            m.start = prev.start
            out[-1] = m
        else:
            out.append(m)
    return out


_AREA_WORDS = ("ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen",
               "nineteen", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety", "hundred")
"""Number words an area may be written with ("thirty square metres"; number phrases
such as "one hundred and twenty" are figures by then, see :func:`rewrite_numbers`)."""

_AREA = re.compile(
    r"\b(\d{1,6}(?:\.\d+|,\d{1,2}(?!\d))?|" + "|".join(_AREA_WORDS) + r")[\s-]*(m2|m²|m\^2|sqm|sq\.? ?m(?:et(?:er|re)s?)?\.?|square met(?:er|re)s?|m(?:et(?:er|re)s?)? squared|"
    r"sq\.? ?ft\.?|sqft|square f(?:ee|oo)t|ft2|ft²|sf)(?![\w²])"
)
"""A stated floor area: a number and a unit ("50 m2", "30 square meters", "500 sq ft")."""

SQ_FT_M2 = 0.09290304
"""Square metres in a square foot."""

PER_STOREY = re.compile(r"\s*(?:per|a|each|on each|on every|for each|on all)\s+(?:floor|storey|story|level)\b")
"""Words after an area that make it each storey's ("60 m2 per floor", "50 square metres
on each floor"): the total is that times the storeys (a basement and an attic each one)."""


def _stated_area(kb: KnowledgeBase, text: str, p: Parsed, taken: list[tuple[int, int]]) -> None:
    """The floor area the text states for the whole building ("a 50 m2 apartment", "about
    30 square meters"); an area right before a room word ("a 12 m2 bedroom") or a word
    of the land (programs.yaml ``sizes.land_words``: "a 500 m2 plot") is no total.
    Every area's span joins ``taken``: its number counts nothing."""
    voc = vocabulary(kb)
    land = set((kb.raw("programs").get("sizes") or {}).get("land_words") or [])
    for mt in _AREA.finditer(text):
        taken.append(mt.span())
        after = _tokens(text[mt.end() :])[:3]
        nxt = " ".join(t for t, _, _ in after)
        if after and after[0][0] in land:  # "a house on a 500 m2 plot": the land's area
            continue
        num = mt.group(1)
        value = float(NUMBER_WORDS[num] if num in NUMBER_WORDS else num.replace(",", "."))  # "12,5 m2"
        value *= SQ_FT_M2 if "f" in mt.group(2) or mt.group(2) == "sf" else 1.0
        room, building = _room_prefix(kb, nxt), _building_prefix(kb, nxt)
        # "a 12 m2 bedroom"; "a 30 m2 studio flat" is the flat's; "a house with a 20 m2
        # studio": a word of both kinds after another building word is a room
        if room and (room > building or (room == building and voc.building_regex.search(text[: mt.start()]))):
            p.room_areas.append((mt.end(), value))
            continue
        if p.total_m2 is None and value > 0:
            p.total_m2 = value
            if PER_STOREY.match(text, mt.end()):  # "60 m2 per floor": every storey's
                p.total_m2 = value * max(1, p.storeys + p.basement + p.attic)


def _building_words(kb: KnowledgeBase) -> frozenset[str]:
    """Every word and phrase programs.yaml names a building with ("studio flat")."""
    return frozenset(w.lower() for b in kb.raw("programs")["buildings"] for w in b.get("words", []))


def _prefixes(phrase: str) -> list[str]:
    words = phrase.split()
    return [" ".join(words[:n]) for n in range(len(words), 0, -1)]


def _room_prefix(kb: KnowledgeBase, phrase: str) -> int:
    """Length of the longest room word ``phrase`` starts with (0: none)."""
    forms = vocabulary(kb).forms
    return max((len(f) for f in _prefixes(phrase) if f in forms and forms[f][0].kind == "room"), default=0)


def _building_prefix(kb: KnowledgeBase, phrase: str) -> int:
    """Length of the longest building word ``phrase`` starts with (0: none)."""
    return max((len(f) for f in _prefixes(phrase) if f in _building_words(kb)), default=0)


SIZE_WORD_SPAN = 4
"""A size word sizes the building when it stands among this many words ending with the
building word, not counting the words that give its storeys ("a tiny three storey tower
house" is tiny)."""
STOREY_WORDS = frozenset({"storey", "story", "storeys", "stories", "storeyed", "storied", "level", "levels", "floor", "floors"})


def _size_words(kb: KnowledgeBase, text: str, start: int, p: Parsed) -> None:
    """Size words (programs.yaml sizes.words) among the few words before the building
    word, within its clause ("a tiny off-grid cabin", "a grand old mansion"); the words
    of a storey count ("three storey", "two-level") are skipped over."""
    words = ((kb.raw("programs").get("sizes") or {}).get("words")) or {}
    seen, storey = 0, False
    for tok, _, _ in reversed(_tokens(text[:start])):
        if seen and (tok in STOREY_WORDS or (storey and parse_number(tok) is not None)):  # "a tiny three-storey tower house"
            storey = tok in STOREY_WORDS
            continue
        seen, storey = seen + 1, False
        if seen > SIZE_WORD_SPAN or not tok.isalpha() or tok in ("with", "and", "or", "but", "of", "for"):
            break
        if (words.get(tok) or {}).get("total_m2") and tok not in p.size_words:
            p.size_words.append(tok)


HEAD_END = re.compile(r",|;|:|\.\s|\(|\bwith\b|\bfeaturing\b|\bincluding\b|\bwhere\b|\bwhich\b")
"""Where the head of the text ends: the words before it describe the whole building."""


def _head_size_words(kb: KnowledgeBase, text: str, p: Parsed) -> None:
    """Size words (programs.yaml sizes.words with a ``total_m2``) anywhere in the head of
    the text (before the first comma, "with", "featuring"...) that are not followed by a
    room in the words after them ("a grand old Victorian brick house"; not "a large
    kitchen and a house"): the whole building's size, as the evaluator reads it."""
    words = ((kb.raw("programs").get("sizes") or {}).get("words")) or {}
    end = HEAD_END.search(text)
    head = text[: end.start()] if end else text
    toks = _tokens(head)
    for i, (tok, _, _) in enumerate(toks):
        if not (words.get(tok) or {}).get("total_m2") or tok in p.size_words:
            continue
        after = [t for t, _, _ in toks[i + 1 : i + 4]]
        nxt = " ".join(after)
        if after and parse_number(after[0]) is not None and _room_prefix(kb, " ".join(after[1:])):
            continue  # "a large 2 bedroom flat": a count of rooms ends the size word's phrase
        room, building = _room_prefix(kb, nxt), _building_prefix(kb, nxt)
        if room > building and nxt.split()[:1] != [tok]:
            continue
        p.size_words.append(tok)


def _apply_codes(text: str, p: Parsed, taken: list[tuple[int, int]]) -> None:
    """Bed/bath codes ("3B2B", "two bed, two bath") and household sizes; a code's span
    joins ``taken`` so that its "bed" and "bath" are not read as objects or styles."""
    mt = _BED_BATH.search(text)
    mw = _BED_BATH_WORDS.search(text)
    if mt:
        p.bedrooms = int(mt.group(1))
        p.bathrooms = max(1, int(float(mt.group(2))))
        taken.append(mt.span())
    elif (mw and parse_number(mw.group(1)) is not None and parse_number(mw.group(2)) is not None
          and not _FLOOR_WORDS.match(text[mw.end():].lstrip(" ,"))):  # "two bedrooms and a bathroom on the
        # second floor" lists one storey's rooms, not the home's totals
        p.bedrooms = parse_number(mw.group(1))
        p.bathrooms = max(1, parse_number(mw.group(2)) or 1)
        if "room" not in mw.group():  # "bedroom"/"bathroom" stay room mentions
            taken.append(mw.span())
    else:
        mt2 = _BR_ONLY.search(text)
        mt4 = _BED_HOME.search(text)
        if mt2:
            p.bedrooms = int(mt2.group(1))
        elif mt4 and (n := parse_number(mt4.group(1))) is not None and n > 0:
            p.bedrooms = n
            taken.append((mt4.start(), mt4.start(1) + len(mt4.group(1)) + len(" bed")))
    mt3 = _PEOPLE.search(text)
    if mt3:
        n = parse_number(mt3.group(1) or mt3.group(2) or mt3.group(3) or "")
        if n:
            p.people = n
    else:
        adults = 2 if _COUPLE.search(text) else 0
        kids = 0
        for mt in _MEMBERS.finditer(text):
            n = parse_number(mt.group(1)) or 0
            if mt.group(2) in ("parents", "adults", "grandparents", "roommates", "flatmates", "friends"):
                adults += n
            else:
                kids += n
        if adults or kids:
            p.people = max(adults, 2 if kids else 1) + kids


_STOREYS = re.compile(
    r"\b(\w+)[- ](?:storey|story|storeyed|storied|level|floor)s?\b(?! plan)|\b(\w+) (?:storeys|stories|floors|levels)\b")
_UPSTAIRS = re.compile(r"\b(?:upstairs|downstairs|upper floor|upper storey|up the stairs)\b")
STYLE_SUFFIX = re.compile(r"\b(?!(?:classroom|theatre|theater|cabaret|banquet|boardroom|dorm|dormitory|family|buffet)-)([A-Za-z]+)-style\b")
"""A word made a style by "-style" ("Speakeasy-style", "Shaker-style") reads as the word;
seating layouts ("classroom-style") keep theirs."""
IN_A_BASEMENT = re.compile(r"\s*(?:,\s*)?(?:set |tucked away |hidden )?(?:in|into) (?:a|an|the) (?:[\w-]+ )?(?:basement|cellar|vault)s?\b")
"""Right after the building: the building itself is below ground ("a speakeasy in a
basement"), one storey, no basement storey under it."""
IN_A_PLACE = re.compile(
    r"\s*(?:,\s*)?(?:(?:set|tucked away|hidden|located|housed|built)\s+)?(?:in|inside|within|on|at|under|beneath|above|beside|by|behind|off) "
    r"(?:a|an|the) (?:[\w'-]+ ){0,2}?(?:shopping arcade|arcade|shopping mall|mall|shopping cent(?:re|er)|market hall|market|"
    r"railway arch(?:es)?|arch(?:es)?|high street|main street|street|square|tower block|office block|block|terminal|airport|"
    r"harbou?r|marina|quay|canal|river|village|town|city|suburb|medina|old town|quarter|district|neighbou?rhood|campus|"
    r"industrial estate|business park|retail park|estate)\b")
"""Right after the building: where it stands ("a nail salon in a shopping arcade", "a
boxing gym under a railway arch"); the place's words name no rooms or objects."""
_BASEMENT = re.compile(r"\b(?:basement|lower ground(?: floor)?|underground level)s?\b|(?<!wine )(?<!beer )\bcellars?\b(?! (?:bar|club|door)s?\b)")
_ATTIC = re.compile(r"\b(?:attic|loft conversion|garret)s?\b")
_ROOF_SPACE = r"\b(?:in|into|under|up in|up into|up under)\s+the\s+(eaves|roof space|roof)\b(?![\w-]|\s+(?:terrace|garden|deck|top)s?\b)"
"""The space under the roof as a place ("under the eaves", "in the roof"; not "the roof
terrace"): its one group names it (:data:`_ROOF_ROOMS`, :data:`_FLOOR_WORDS`)."""
_ROOF_ROOMS = re.compile(_ROOF_SPACE)
"""Words that put a room under the roof ("a bedroom under the eaves", "a bedroom in the
roof"): the attic of a house whose storeys the text does not count; the top storey of
one it does ("a three-storey micro-house ... bedroom in the roof" has three storeys, not
four: :func:`_find_levels`)."""
_MEZZANINE = re.compile(r"\bmezzanines?\b")
_FLOOR_WORDS = re.compile(
    r"\b(?:on|in|at)\s+the\s+(ground|first|1st|second|2nd|third|3rd|top|upper)\s+(?:floor|storey|story|level)\b"
    r"|\b(?:on|in|at)\s+the\s+(second|2nd|third|3rd)\b(?=\s*(?:[,;.]|and\b|$))"
    r"|\b(?:on|in|into|up in|up into|down in|down into)\s+the\s+(basement|cellar|attic|garret)\b"
    rf"|{_ROOF_SPACE}"
    r"|\b(downstairs|upstairs)\b|\bup (?:the )?(stairs)\b"
    r"|\b(?:at|on)\s+(street|garden|ground)\s+(?:level|floor)\b|\b(underneath|beneath) (?:them|it)\b"
    r"|\bat the very (top)\b(?!\s+of)|\b(?:at|on) the (top)\b(?=\s*(?:[,;.]|and\b|$))"
    r"|(?:^|(?<=[.;]\s))(?:raised\s+|upper\s+)?(ground|first|1st|second|2nd|third|3rd|top)(?:\s+(?:floor|storey|story))?\s*:"
    r"|(?:^|(?<=[.;]\s))(lower ground|attic|basement)(?:\s+(?:floor|level))?\s*:")
"""Words that put the rooms named before them on a storey ("a kitchen on the ground
floor", "three bedrooms upstairs", "two bedrooms on the second" after "... on the first
floor", "two sleeping lofts, underneath them a kitchenette", a sentence opening "Ground floor:";
:func:`anyhome.plan.program.assign_levels`)."""
_STOREY_NOUN = re.compile(r"\b(?:floor|storey|story|level)\b")
"""A storey's noun: "at the top" without one names a storey only in a text of several
("a shelf at the top" of a one-storey home names none)."""
_FLOOR_WORD_OF = {"lower ground": "basement", "cellar": "basement", "stairs": "upstairs", "street": "ground", "garret": "attic",
                  "garden": "ground", "underneath": "downstairs", "beneath": "downstairs"}
"""Floor words read as another ("at street level" is the ground floor: a "first floor"
named with it is the one above, British usage)."""
_ROOF_WORDS = frozenset({"eaves", "roof space", "roof"})
"""Floor words for the space under the roof: the attic, or the top storey of a house whose
storeys the text counts (:data:`_ROOF_ROOMS`)."""
_TIERS = re.compile(
    r"\b(?:(?:on|in|at)\s+the\s+)?(lowest|lower|bottom|middle|main|entry|upper|top)\s+(?:level|floor|storey|story)\b"
    r"|\b(half a flight up|half a level up)\b")
"""Storeys named by their place among the others ("the lower level", "the middle level",
"the main floor", "half a flight up" in a split-level; :func:`_find_tiers`)."""
_BARE_TIERS = re.compile(r"\b(?:at|on)\s+the\s+(bottom|top)\b(?!\s+of)|\bin\s+the\s+(middle)\b(?!\s+of)")
"""Places named without a storey word ("a kitchen at the bottom, a sitting room in the
middle, a bedroom at the top"): storeys only in a text of several storeys that names two
places or more this way (:func:`_find_tiers`)."""
_TIER_OF = {"lowest": "low", "lower": "low", "bottom": "low", "middle": "mid", "main": "mid", "entry": "mid",
            "half a flight up": "mid", "half a level up": "mid", "upper": "high", "top": "high"}
_ENTRANCE_WORDS = re.compile(r"\b(?:entry|entrance|foyer|front door|lobby|vestibule)\b")
_SOME_STOREYS = {"duplex": 2, "triplex": 3, "twoup twodown": 2}  # "a two-up two-down" (its numbers joined, _number_adjectives)
"""Building words that give a number of storeys ("a duplex apartment"; "split-level": _STOREYS)."""
ORDINAL_FLOORS = {"first": 1, "1st": 1, "second": 2, "2nd": 2, "third": 3, "3rd": 3}
"""Floors named by number: "the second floor" is the second storey, or the third where the
text names a ground floor too (British usage)."""
MAX_STOREYS = 4
"""Most storeys above ground a plan holds (ground floor included)."""


def _find_levels(text: str, p: Parsed) -> None:
    """Storeys ("two-storey", "3-story", "three floors"; "upstairs", a mezzanine: two),
    a basement and an attic."""
    one_storey = False  # "a single-storey bungalow with a basement": "upstairs" is its ground floor
    for mt in _STOREYS.finditer(text):
        word = mt.group(1) or mt.group(2)
        n = {"single": 1, "one": 1, "double": 2, "twin": 2, "multi": 3, "split": 2}.get(word) or parse_number(word)
        one_storey = one_storey or n == 1
        if n is not None and n >= 1:
            if n > MAX_STOREYS:
                p.warnings.append(f"asked for {n} storeys; a plan holds at most {MAX_STOREYS}, planned {MAX_STOREYS}")
            p.storeys = max(p.storeys, min(n, MAX_STOREYS))
    for word, n in _SOME_STOREYS.items():
        if re.search(rf"\b{word}\b", text):
            p.storeys = max(p.storeys, n)
    named = {_FLOOR_WORD_OF.get(g, g) for mt in _FLOOR_WORDS.finditer(text) for g in [next(g for g in mt.groups() if g)]}
    for word, n in ORDINAL_FLOORS.items():  # "bedrooms on the first floor" of a house with a ground floor: two
        if word in named:
            p.storeys = max(p.storeys, min(MAX_STOREYS, n + ("ground" in named)))
    p.basement = bool(_BASEMENT.search(text))
    counted = p.storeys >= 2  # "a two-storey cottage with a bedroom under the eaves": the eaves are its top storey
    p.attic = bool(_ATTIC.search(text)) or (not counted and bool(_ROOF_ROOMS.search(text)))
    above = {m.group(0) for m in _UPSTAIRS.finditer(text)} - ({"downstairs"} if p.attic else set())
    above |= named & {"upstairs", "downstairs"} - ({"downstairs"} if p.attic else set())  # "underneath them a kitchenette": the lofts are up
    if p.storeys == 1 and (_MEZZANINE.search(text) or (above and not (one_storey and p.basement))):
        p.storeys = 2  # "downstairs" in a house with an attic: the attic is its upstairs
    roof_word = "attic" if p.attic else "top"  # the roof words (_ROOF_WORDS) read as one or the other
    p.floor_words = [(mt.start(), mt.end(), roof_word if g in _ROOF_WORDS else _FLOOR_WORD_OF.get(g, g))
                     for mt in _FLOOR_WORDS.finditer(text) for g in [next(g for g in mt.groups() if g)]
                     if not (p.storeys <= 1 and g == "top" and not _STOREY_NOUN.search(mt.group()))]
    _find_tiers(text, p)


_STOREY_MODIFIERS = frozenset({"basement", "attic"})


def _storey_modifiers(text: str, p: Parsed) -> None:
    """A basement or an attic named right before another room ("a basement gym", "a
    basement playroom") is that room's storey, not a room of its own: a floor word
    (:data:`_FLOOR_WORDS`) at its place (measured on the dev storey sets: "a three-storey
    house with a basement playroom" put the playroom on the top floor and a storage room
    in the basement)."""
    for m, nxt in zip(p.rooms, p.rooms[1:]):
        if (m.key in _STOREY_MODIFIERS and m.name == m.key and m.count in (None, 1) and nxt.key not in _STOREY_MODIFIERS
                and nxt.start > m.end and not text[m.end:nxt.start].strip()):
            p.floor_words.append((m.start, m.end, m.key))
    p.floor_words.sort()


def _find_tiers(text: str, p: Parsed) -> None:
    """Storeys named by their place ("Lowest level: a gym ... Middle level: the entry foyer,
    a kitchen ... top floor: the master bedroom", "garage and den on the lower level,
    kitchen half a flight up, bedrooms on the upper level"): as many storeys as places
    named, the one holding the entrance (a "main" or "entry" floor, or one whose rooms
    include an entry or foyer) the ground floor and a place under it the basement. Each
    place becomes a floor word naming its level ("tier:-1", "tier:0", ...), in place of
    an ordinary floor word at the same words ("the top floor", "the upper level")."""
    named = [(mt.start(), mt.end(), next(g for g in mt.groups() if g)) for mt in _TIERS.finditer(text)]
    bare = [(mt.start(), mt.end(), next(g for g in mt.groups() if g)) for mt in _BARE_TIERS.finditer(text)
            if not any(s <= mt.start() < e for s, e, _ in named)]
    if p.storeys >= 2 and len({_TIER_OF[w] for _, _, w in bare}) >= 2:  # "a three storey tower: a kitchen at the bottom, ..."
        named = sorted(named + bare)
    found = [(s, e, _TIER_OF[w]) for s, e, w in named]
    tiers = [t for t in ("low", "mid", "high") if any(f[2] == t for f in found)]
    if tiers == ["low"] and p.storeys >= 2:  # "a duplex ... on the lower level": the ground floor
        tiers = ["low", "high"]
    if not tiers or (len(tiers) == 1 and tiers != ["mid"]):
        return  # "the top floor" alone: an ordinary floor word
    ground = "low"
    for i, (start, end, tier) in enumerate(found):  # the middle storey holds the entry: the ground floor
        nxt = next((f[0] for f in found[i + 1:] if f[2] != tier), len(text))
        prev = max((f[1] for f in found[:i] if f[2] != tier), default=0)
        if tier == "mid" and (named[i][2] in ("main", "entry") or _ENTRANCE_WORDS.search(text[prev:start])
                              or _ENTRANCE_WORDS.search(text[end:nxt])):
            ground = "mid"
    if ground not in tiers:
        ground = tiers[0]
    g = tiers.index(ground)
    level = {t: i - g for i, t in enumerate(tiers)}
    if min(level.values()) < 0:
        p.basement = True
    above = min(MAX_STOREYS, max(level.values()) + 1)
    p.storeys = above if len(tiers) >= 2 else max(p.storeys, above)  # "a triplex: lowest, middle, top": one under
    spans = [(s, e) for s, e, _ in found]
    p.floor_words = sorted([w for w in p.floor_words if not any(s < w[1] and w[0] < e for s, e in spans)]
                           + [(s, e, f"tier:{level[t]}") for s, e, t in found])


def _own_part(m: Mention, kb: KnowledgeBase) -> bool:
    """Whether a room named later in an "each with ..." list is each room's own (rooms.yaml
    ``own_parts``: a balcony, a bathroom; a sitting area) rather than the building's."""
    rooms = kb.raw("rooms")
    info = rooms["names"].get(m.key) or {}
    return info.get("type") in rooms.get("own_parts", []) or m.name.split()[-1] in ("area", "corner", "nook")


def _assign_rooms(text: str, mentions: list[Mention], kb: KnowledgeBase) -> None:
    """Attach each object mention to the room mention that governs it, if any."""
    context: int | None = None
    each: Mention | None = None
    rooms = [x for x in mentions if x.kind == "room"]
    room_idx = {id(m): i for i, m in enumerate(rooms)}
    spread: list[Mention] = []  # rooms and objects each of the rooms got, in a row
    per: Mention | None = None  # "six workbenches, each with its own sink": objects each object has
    last: Mention | None = None  # the last object given to each of them: a comma after it ends the list
    for i, m in enumerate(mentions):
        if per is not None and (m.kind == "room" or re.search(r"[.;:]", text[per.end : m.start])
                                or (last is not None and "," in text[last.end : m.start])):
            per = None
        if m.kind == "room":
            prev = mentions[i - 1] if i > 0 else None
            # "each with an en-suite", not "..., and a kitchen"; "each with its own sitting
            # area, a balcony and a bathroom": the list goes on
            right_after = prev is not None and (prev is each or (
                any(prev is x for x in spread) and EACH_LIST.match(text[prev.end : m.start]) is not None
                and _own_part(m, kb)))
            closed = prev is not None and _EACH_CLOSED.match(text[prev.end : m.start]) is not None and not _own_part(m, kb)
            if (each is not None and ((m.count is None and not closed) or (m.count == 1 and not m.plural and right_after))
                    and "." not in text[each.end : m.start]):
                m.count, m.plural = each.count, True  # "six guest rooms, each with its own bathroom" / "an en-suite"
                spread.append(m)
                if _opens_context(text[m.end : m.end + 120]):  # "... and a bathroom with a bathtub"
                    context = room_idx[id(m)]
                continue
            tail = text[m.end : m.end + 120]
            outer = context
            context = room_idx[id(m)] if _opens_context(tail) else None
            if context is None and outer is not None and OWN_PART.search(text[rooms[outer].end : m.start]):
                context = outer  # "a suite with its own sitting area and a tub": the tub is the suite's
            plural_room = (m.count or 0) > 1 or m.plural
            each = m if plural_room and m.count and EACH_OPENER.match(tail) else None
            continue
        if each is not None and "." in text[each.end : m.start]:
            each = None
        if per is not None:  # one for each of them, where they are
            m.count = (m.count or 1) * (per.count or 1)
            m.room, m.each = per.room, per.each
            last = m
            continue
        if (m.count or 0) > 1 and EACH_OPENER.match(text[m.end : m.end + 60]):
            per, last = m, None  # what follows, each of these has
        if m.host is not None and id(m.host) in room_idx:
            m.room = room_idx[id(m.host)]
            _spread(m, m.host)  # "six en-suite showers": one in each
            continue
        m.room = None if context is not None and _out_of_place(m, rooms[context], kb) else context
        m.each = each is not None and context is not None and any(rooms[context] is x for x in [each, *spread])
        if m.each:
            spread.append(m)
        if not m.each and context is not None and EACH_AFTER.match(text[m.end : m.end + 24]):
            m.each = (rooms[context].count or 0) > 1 or rooms[context].plural  # "twenty desks in each"
        if not m.each and context is not None:
            _spread(m, rooms[context])
        nxt = next((x for x in mentions[i + 1 :] if x.kind == "room"), None)
        if nxt is not None:
            between = text[m.end : nxt.start]
            words_before = _strip_lookback(text, nxt)
            if IN_ROOM.match(between[: len(between) - words_before]):
                m.room = room_idx[id(nxt)]


def _out_of_place(obj: Mention, room: Mention, kb: KnowledgeBase) -> bool:
    """Whether ``obj``, listed after ``room`` ("a shower room with a composting toilet
    and a built-in sofa"), is a known object that never stands in a wet room of that
    type (objects.yaml ``rooms`` without it): it goes where the house's other loose
    objects go, not into the bathroom."""
    rooms = kb.raw("rooms")
    rtype = (rooms["names"].get(room.key) or {}).get("type")
    if not rtype or not rooms["types"].get(rtype, {}).get("wet"):
        return False
    where = (kb.raw("objects").get(obj.key) or {}).get("rooms") or []
    return bool(where) and rtype not in where


_EACH_CLOSED = re.compile(r"^\s*,\s*and\b")
"""", and" before a room that is no room's own part ends an "each with" list ("eight
bedrooms each with an en suite, and staff quarters": the staff quarters are one, not eight)."""
EACH_LIST = re.compile(r"^\s*(?:,\s*(?:and\s+)?|and\s+)(?:(?:a|an|its own|their own)\s+)?[^\W\d_]*\s*$")
"""Text between two items of one "each with ..." list: ", a", " and a", ", and an"."""

EACH_AFTER = re.compile(r"^\s*(?:each|apiece|(?:in|for) (?:each|every)(?: one| room| of them)?|per room|a room)\b")
"""Words after an object that give its count per room ("four classrooms with twenty
desks each", "... in each"): every room gets that many, rather than a share."""


OWN_PART = re.compile(r"\b(?:its|their|his|her) own\b[^.;]*$")
"""Text between a room and a room named as its part ("a suite with its own sitting
area"): what the text lists after the part still belongs to the room."""


def _spread(obj: Mention, room: Mention) -> None:
    """"Three bedrooms with bunk beds": objects in the plural after a counted plural room
    are shared out, one each (or the count split evenly: "two bathrooms with four
    sinks"), not all put in the first room."""
    rooms = room.count or 0
    if rooms < 2 or obj.many:
        return
    if obj.count is None and (obj.plural or (obj.start - room.end <= 1 and not obj.words)):
        obj.each, obj.plural = True, False  # "six en-suite showers"/"en-suites with showers": one each
    elif obj.count is not None and obj.count >= rooms and obj.count % rooms == 0:
        obj.each, obj.count = True, obj.count // rooms
        obj.plural = obj.count > 1


PAIRED_OWNERS = re.compile(r"\b[a-z]+(?:'s|s')\s+(?:and|&)\s+[a-z]+(?:'s|s')\s+(?:[a-z]+\s+)?$")
"""Two owners before a room word in the plural: "men's and women's changing rooms"."""


PAIRED_WORDS = re.compile(r"(?:^|[\s,;:(])([a-z]+(?:'s|s'|')?)\s+(?:and|&)\s+([a-z]+(?:'s|s'|')?)\s+$")
"""Two words before a plural room word, the second kept in its name: "east and west side
rooms", "his and hers bathrooms", "men's and women's changing rooms"."""


PAIRED_PRONOUNS = frozenset({"his", "her"})
"""Stop words that still name one of a pair ("his and hers bathrooms")."""


_SEATS_WITH = re.compile(r"^\s*(?:with|w/)\s+$")
"""Between a table and its seats: "a long oak table with benches"."""


def _table_seats(text: str, kb: KnowledgeBase, mentions: list[Mention]) -> None:
    """"A refectory table with benches down both sides", "a kitchen table with stools":
    those seats are the table's (``Mention.seat_of``), in place of its chairs."""
    objects = kb.raw("objects")
    for m in mentions:
        proto = (objects.get(m.key) or {}) if m.kind == "object" else {}
        if "seat" not in (proto.get("tags") or []) or m.negated:
            continue
        head = m.start - _strip_lookback(text, m)
        before = _last_before(mentions, head)
        if before is None or before.kind != "object" or before.negated:
            continue
        table = objects.get(before.key) or {}
        if "table" not in str(table.get("category", "")).split("_"):
            continue
        gap = text[before.end : head]
        gap = re.sub(r"\b(?:\d+|" + "|".join(NUMBER_WORDS) + r"|a|an|its|their|matching)\b", " ", gap)
        if _SEATS_WITH.match(gap):
            m.seat_of = before


def _paired_rooms(text: str, mentions: list[Mention]) -> None:
    """"Men's and women's changing rooms", "boys' and girls' toilets", "east and west side
    rooms": one room each, two in all, when the text gives no count of its own; each room
    named by its own word (``Mention.variants``), not two of the second."""
    for m in list(mentions):
        if m.kind != "room" or m.count is not None or not m.plural:
            continue
        if PAIRED_OWNERS.search(text[max(0, m.start - 40) : m.start]):
            m.count = 2
        lo = max(0, m.start - 50)
        mt = PAIRED_WORDS.search(text[lo : m.start])
        if mt is None:
            continue
        a, b = mt.group(1), mt.group(2)
        a_start = lo + mt.start(1)
        if (a in STOP_WORDS and a not in PAIRED_PRONOUNS) or a in NUMBER_WORDS or parse_number(a) is not None:
            continue
        over = [x for x in mentions if x is not m and x.start <= a_start < x.end]
        if any(x.key or x.name != a for x in over):
            continue  # "kitchen and dining rooms": a room of its own
        b_word = b.rstrip("'").removesuffix("'s")
        if m.words and m.words[0] == b_word:  # "his and hers bathrooms": "hers bathroom"
            rest = m.name.split(" ", 1)[1] if " " in m.name else m.name
            m.variants = [f"{a} {rest}", f"{b} {rest}"]
        elif b != b_word:  # "men's and women's changing rooms": the owners, as written
            m.variants = [f"{a} {m.name}", f"{b} {m.name}"]
        else:
            continue
        for x in over:  # "east" taken for a room or an object of its own
            mentions.remove(x)
        m.count = 2


SUBJECT_ROOM = re.compile(r"^\s*(?:in|inside|within|of|at) (?:a|an|the|my|our|this)\b")
"""Words after a text's opening room that make the building its setting ("a collector's
study in an old townhouse: ...")."""
SUBJECT_ROOM_START = 40
"""The opening room starts within this many characters of the text."""


def _subject_room(text: str, p: Parsed, mentions: list[Mention]) -> None:
    """"A collector's study in an old townhouse: a curiosity cabinet, two armchairs ...":
    the text is about its one room, set in a building; what it lists with no room of its
    own goes there, not to the building's main room."""
    rooms = [m for m in mentions if m.kind == "room"]
    if (p.building is None or len(rooms) != 1 or rooms[0].negated or rooms[0].start > SUBJECT_ROOM_START
            or not SUBJECT_ROOM.match(text[rooms[0].end : rooms[0].end + 12])):
        return
    for m in mentions:
        if m.kind == "object" and m.room is None and m.host is None:
            m.room = 0


def _strip_lookback(text: str, m: Mention) -> int:
    """Characters of adjectives/counts just before mention ``m`` (part of its phrase)."""
    n = 0
    if m.words:
        n = len(" ".join(m.words)) + 1
    return n


def _apply_arrangements(text: str, mentions: list[Mention]) -> None:
    for pattern, kind in FORWARD_ARRANGEMENTS:
        for mt in pattern.finditer(text):
            nxt = next((x for x in mentions if x.start >= mt.end()), None)
            if nxt is not None and nxt.kind == "object" and nxt.start - mt.end() <= 30:
                nxt.arrangement = nxt.arrangement or kind
    for pattern, kind in ARRANGEMENTS:
        for mt in pattern.finditer(text):
            clause_start = max(
                [x.end for x in mentions if x.kind == "room" and x.end <= mt.start()]
                + [text.rfind(".", 0, mt.start()) + 1, 0]
            )
            cands = [x for x in mentions if x.kind == "object" and clause_start <= x.start < mt.start()]
            prior_arr = [x for x in cands if x.arrangement is not None]
            if prior_arr:
                cands = [x for x in cands if x.start > prior_arr[-1].start]
            if kind == "around":
                cands = [x for x in cands if x.key != "table"][-1:]
            for x in cands:
                x.arrangement = x.arrangement or kind


def _find_styles(kb: KnowledgeBase, text: str, p: Parsed) -> None:
    voc = vocabulary(kb)
    moods = set(kb.raw("styles").get("moods") or [])
    weak: list[str] = []  # styles named only by a mood word ("cozy") follow those named by a look
    for mt in voc.style_regex.finditer(text):
        key = voc.style_forms[mt.group()]
        if mt.group() in moods:
            weak.append(key)
        elif key not in p.styles:
            p.styles.append(key)
        if mt.group() not in p.style_words:
            p.style_words.append(mt.group())
    p.styles += [k for k in dict.fromkeys(weak) if k not in p.styles]
    for mt in voc.colour_regex.finditer(text):
        c = mt.group()
        if c not in ("dark", "light", "pale", "deep", "bright", "pastel") and c not in p.colours:
            p.colours.append(c)


def _find_materials(kb: KnowledgeBase, text: str, p: Parsed, rooms: list[Mention]) -> None:
    voc = vocabulary(kb)
    defaults = planner_materials(kb)
    weathering = set(kb.raw("materials").get("weathering") or ())
    for mt in voc.material_regex.finditer(text):
        material = mt.group()
        words = [t for t, _, _ in _tokens(text[max(0, mt.start() - 30) : mt.start()])][-2:]
        modifiers = [w for w in words if voc.colour_regex.fullmatch(w) or w in weathering]
        after = _tokens(text[mt.end() : mt.end() + 30])[:2]
        surfaces: list[str] = []
        explicit = False
        phrase = " ".join(modifiers + [material])  # with its colour and weathering words ("peeling")
        for tok, _, _ in after:
            surface = surface_of_word(tok, kb)
            if surface is not None:
                surfaces.append(surface)
                explicit = True
                phrase += " " + tok
                break
        if not surfaces:
            surfaces = list(defaults.get(material, ["furniture"]))
        room: int | None = None
        tail = text[mt.end() : mt.end() + 50]
        inm = re.match(r"^[\w ]{0,20}?\b(?:in|for|throughout) (?:the |a |an |my )?", tail)
        if inm:
            pos = mt.end() + inm.end()
            room = next((i for i, r in enumerate(rooms) if r.start - len(" ".join(r.words)) - 2 <= pos <= r.start + 1), None)
        if room is None:
            for i, r in enumerate(rooms):
                if r.end <= mt.start() and _opens_context(text[r.end : r.end + 40]) and "." not in text[r.end : mt.start()] and mt.start() - r.end < 60:
                    room = i
        p.materials.append(MaterialMention(phrase, material, surfaces, mt.start(), room, explicit))
    tokens = _tokens(text)
    for k, (tok, _, _) in enumerate(tokens[:-1]):  # "dusty floors", "peeling walls": no material named
        nxt = tokens[k + 1][0]
        surface = None if voc.material_regex.fullmatch(nxt) else surface_of_word(nxt, kb)  # "peeling wallpaper" is a material
        if tok in weathering and surface is not None and tok not in p.aged.get(surface, []):
            p.aged.setdefault(surface, []).append(tok)


ROOM_FOR = re.compile(r"\b(rooms?) (?:used )?for ([a-z]+)\b")


def _room_for(kb: KnowledgeBase, text: str) -> str:
    """"A smaller room for meditation" reads as "a smaller meditation room" where the
    knowledge names such a room (no "room for two", no "room for everything")."""
    forms = vocabulary(kb).forms

    def sub(mt: re.Match[str]) -> str:
        word = _singular(mt.group(2))[0]
        for w in (mt.group(2), word):
            name = f"{w} {mt.group(1)}"
            if forms.get(name) is not None and forms[name][0].kind == "room":
                return name
        return mt.group()

    return ROOM_FOR.sub(sub, text)


def _singular(word: str) -> tuple[str, bool]:
    if len(word) > 4 and word.endswith("ies"):
        return word[:-3] + "y", True
    if len(word) > 4 and word.endswith(("ches", "shes", "sses", "xes")):
        return word[:-2], True
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")):
        return word[:-1], True
    return word, False


def _known_spans(kb: KnowledgeBase, text: str, taken: list[tuple[int, int]], mentions: list[Mention]) -> tuple[list[tuple[int, int]], list[tuple[int, int]]]:
    """Spans of what the lexical pass found: (mentions and codes, modifier words).

    Modifier words (styles, materials, colours, weathering and ceiling-structure words:
    "peeling", "exposed") may stand inside an open-vocabulary object phrase; mentions may
    not."""
    voc = vocabulary(kb)
    spans = list(taken)
    for m in mentions:
        spans.append((m.start - len(" ".join(m.words)) - (1 if m.words else 0), m.end))
    soft = [(mt.start(), mt.end()) for rx in (voc.style_regex, voc.material_regex, voc.colour_regex, voc.finish_regex)
            for mt in rx.finditer(text)]
    return spans, soft


def _open_vocabulary(kb: KnowledgeBase, text: str, p: Parsed, taken: list[tuple[int, int]], mentions: list[Mention], tokens: list[tuple[str, int, int]]) -> list[Mention]:
    """Add what the knowledge base does not list, mapped by the embedding matcher."""
    hard, soft = _known_spans(kb, text, taken, mentions)
    spans = hard + soft
    if p.building is None:
        fnp = ov.first_noun_phrase(text, tokens)
        if fnp is not None:  # only the head counts ("a Moroccan riad" -> "riad")
            head = fnp[0].split()[-1]
            fnp = (head, fnp[2] - len(head), fnp[2])
        if fnp and not any(a < fnp[2] and fnp[1] < b for a, b in spans) and fnp[0] not in ov.non_objects(kb):
            phrase = fnp[0]
            mb = ov.map_building(phrase, kb)
            if mb is not None:
                p.building = next(i for i, b in enumerate(kb.raw("programs")["buildings"]) if b["program"] == mb.key)
                p.building_word, p.building_score = phrase, mb.score
                spans.append((fnp[1], fnp[2]))
                head_start = fnp[2] - len(phrase.split()[-1])
                _building_modifiers(kb, text, head_start, p, taken=spans)
            elif (mr := ov.map_room(phrase, kb)) is not None:
                m = Mention("room", "", phrase, fnp[1], fnp[2], concept=mr.key, open_vocab=True)
                mentions.append(m)
                spans.append((fnp[1], fnp[2]))
            if mb is None:  # "a French patisserie": the opening phrase's modifiers are style words
                _building_modifiers(kb, text, fnp[1], p, keep_unmapped=False, taken=spans)
    for m in mentions:
        if m.kind != "room":
            continue
        if not m.key:
            mr = ov.map_room(m.name, kb)
            m.concept = mr.key if mr else None
        elif m.words:
            mr = ov.map_modified_room(m.key, m.words, kb)
            m.concept = mr.key if mr else None
    hard += spans[len(hard) + len(soft) :]  # what the building step above added
    _room_compounds(kb, text, tokens, mentions, hard)
    found = ov.find_object_phrases(text, tokens, hard, lambda t: parse_number(t) is not None, soft=soft, kb=kb)
    unknown: list[str] = []
    for phrase, s, e in found:
        words = phrase.split()
        while words and (words[0] in size_factors(kb) or words[0] in NOT_NOUNS or words[0] in ADVERBS):
            words = words[1:]
        while words and words[-1] in NOT_NOUNS:  # "under the eaves full (of beanbags)"
            words = words[:-1]
        if not words or words[-1] in ADVERBS or words[-1] in ov.non_objects(kb):  # "downstairs just (a kitchenette)": no object
            continue
        head, plural = _singular(words[-1])
        name = " ".join([*words[:-1], head])
        if _USED_FOR.search(text[:s]):  # "used for assemblies, PE and lunch": what it is for
            continue
        before = _last_before(mentions, s)
        on_object = before is not None and before.kind == "object" and OBJECT_WITH.match(text[before.end : s]) is not None
        room_ok = not _HELD_FOR.search(text[:s]) and not on_object and head not in THING_HEADS
        kind, mo = ov.classify(name, kb, room_ok=room_ok)
        if kind == "room":
            m = Mention("room", "", name, s, e, plural=plural, concept=mo.key if mo else None, open_vocab=True)
            _look_back(m, text, tokens, spans, keep_words=False, kb=kb)
            mentions.append(m)
            continue
        if mo is None and _FOR_WHOM.search(text[:s]):
            continue
        m = Mention("object", mo.key if mo else "", name, s, e, plural=plural, open_vocab=True)
        _look_back(m, text, tokens, spans, keep_words=False, kb=kb)
        m.plural = m.plural or plural
        if mo is None:
            unknown.append(name)
        mentions.append(m)
    if unknown:
        p.warnings.append(
            "no known object is like " + ", ".join(repr(u) for u in unknown)
            + "; planned as plain pieces of furniture under the user's name"
        )
    mentions.sort(key=lambda m: m.start)
    return mentions


_USED_FOR = re.compile(r"\b" + USED + r"\s+(?:[\w'-]+(?:\s*,\s*|\s+))*$")
"""Text before a phrase that lists what a room is used for: activities, not rooms or objects."""
THING_HEADS = frozenset("gear equipment kit machinery machine machines apparatus unit units system systems".split())
"""Heads that name things, whatever the words before them ("the cooling gear" is no cold room)."""
OBJECT_WITH = re.compile(r"^\s*(?:with|w/)\s+(?:(?:a|an|its|their|built-in|built in)\s+)?(?:[\w-]+\s+)?$")
"""Between an object and a phrase: what the object comes with is no room ("four pedicure
chairs with foot spas")."""
_FOR_WHOM = re.compile(r"\bfor (?:the |his |her |their |our |my |its |your )?$")
"""Text before a phrase that says whom or what a thing is for: "an altar table for the
ancestors": an unknown word there is no object of its own."""
_HELD_FOR = re.compile(r"\bfor (?:up to )?(?:\d+|a|an|one|two|three|four|five|six|seven|eight|nine|ten|twelve)(?: \w+)?\s*$")
"""Text before a phrase that makes it what a room holds, not a room: "an apparatus bay
for two (fire) engines", "a garage for three cars"."""

NOT_NOUNS = frozenset("full empty upstairs downstairs outside inside below above nearby too only alone together overlooking".split())
"""Words after a room word that are not a noun ("a studio full of easels", "a loft upstairs")."""

ADVERBS = frozenset("just only also even then still simply merely mostly mainly down up".split())
"""Words that are never an object's name nor lead one ("downstairs just a kitchenette")."""

STAIR_HEADS = frozenset("stair stairs staircase staircases stairway ladder".split())
"""Words that, right after a room word, make it a kind of stair, not a room ("a storage
staircase": a stair with cupboards under its treads; the storeys' stairs are planned
with them)."""

ROOM_SUFFIXES = frozenset("area corner bay zone space nook wing section suite end".split())
"""Words that, right after a room word, make a larger room name ("kennel area", "café corner")."""


def _room_compounds(kb: KnowledgeBase, text: str, tokens: list[tuple[str, int, int]], mentions: list[Mention], hard: list[tuple[int, int]]) -> None:
    """A room word followed by one more noun: "a kennel area" extends the room's name;
    "a courtyard fountain" adds a fountain in the courtyard; a count before a singular
    room word and a plural noun counts the noun ("six study carrels")."""
    starts = {s: k for k, (_, s, _) in enumerate(tokens)}
    for m in [x for x in mentions if x.kind == "room"]:
        k = starts.get(m.end + 1)  # the very next word, one space on
        if k is None:
            continue
        word, s, e = tokens[k]
        after = tokens[k + 1][0] if k + 1 < len(tokens) else "."
        if word in STAIR_HEADS:  # "a storage staircase" is no storage room
            mentions.remove(m)
            continue
        if _opens_context(text[m.end :]) or word in NOT_NOUNS:
            continue
        known = next((x for x in mentions if x.kind == "object" and x.start == s), None)
        if known is not None:  # "a courtyard fountain", "a kitchen island"
            known.host = m
            continue
        if (
            not word.isalpha() or word in STOP_WORDS or word in ov.PHRASE_BREAKS or word in NUMBER_WORDS
            or any(a < e and s < b for a, b in hard) or word.endswith(("ing", "ed", "ly"))
            or not (after in ov.PHRASE_BREAKS or not after.isalpha())
        ):  # fmt: skip
            continue
        head, plural = _singular(word)
        if head in ROOM_SUFFIXES:
            m.name, m.end = f"{m.name} {head}", e
            hard.append((s, e))
            continue
        if head in ov.non_objects(kb) or len(head) < 3:
            continue
        kind, mo = ov.classify(head, kb)
        if kind != "object":
            continue
        obj = Mention("object", mo.key if mo else "", head, s, e, plural=plural, open_vocab=True, host=m)
        if plural and (m.count or 1) > 1 and not text[m.start : m.end].endswith("s"):
            obj.count, m.count, m.plural = m.count, 1, False  # "six study carrels": six carrels, one study
        mentions.append(obj)
        hard.append((s, e))
    mentions.sort(key=lambda m: m.start)


def plural(name: str) -> str:
    """English plural of a name, for warnings ("chair" -> "chairs", "library" -> "libraries")."""
    if name.endswith(("s", "x", "ch", "sh")):
        return name + "es"
    if len(name) > 1 and name.endswith("y") and name[-2] not in "aeiou":
        return name[:-1] + "ies"
    return name + "s"


def _check_counts(p: Parsed, mentions: list[Mention]) -> None:
    """Keep each count as asked (``asked``) and make it one the planner can use: a
    negative count is read as no count, an object count above :data:`MAX_COUNT` is
    capped; both with a warning. Room counts are capped by the planner, which knows how
    many rooms a house holds."""
    for m in mentions:
        if m.count is None:
            continue
        m.asked = m.count
        if m.count < 0:
            p.warnings.append(
                f"asked for {format_count(m.count)} {plural(m.name)}; a count cannot be negative, "
                f"planned {'them' if m.plural else 'it'} as if no number was given"
            )
            m.count = None
        elif m.count > MAX_COUNT:
            if m.kind == "object":
                p.warnings.append(f"asked for {format_count(m.count)} {plural(m.name)}; planned at most {MAX_COUNT}")
            m.count = MAX_COUNT


def _total_rooms(text: str, p: Parsed, mentions: list[Mention]) -> None:
    """A bare room count ("a hotel with 40 rooms") outside any room mention."""
    spans = [(m.start, m.end) for m in mentions]
    for mt in ROOMS_TOTAL.finditer(text):
        n = parse_number(mt.group(1))
        word_start = mt.end(1) + 1
        if n is None or mt.group(1) in ("a", "an", "no") or any(a < mt.end() and word_start < b for a, b in spans):
            continue
        if n <= 0:
            p.warnings.append(f"asked for {format_count(n)} rooms; planned the rooms the text names")
            continue
        p.total_rooms = max(p.total_rooms or 0, n)


_NO_COMPOUND = re.compile(r"\b([Nn]o)[-\u2010\u2011](?=[^\W\d_])")
"""A hyphenated "no-" adjective ("no-frills") is one word, not a negation."""

COUNT_COMPOUNDS = frozenset(
    "bedroom bedrooms bathroom bathrooms bed beds bath baths room rooms storey storeys story stories floor "
    "floors level levels square sq metre metres meter meters m m2 foot feet ft sqft year years month months "
    "person people family families bay bays stall stalls".split())
"""Words that keep a hyphenated number before them a count ("a two-bedroom flat", "a
50-square-metre studio"); before other words it is part of an adjective."""
_NUMBER_COMPOUND = re.compile(
    r"\b(\d{1,3}|one|two|three|four|five|six|seven|eight|nine|ten|twelve)[-\u2010\u2011]([a-z]+)(?=\s+[a-z])", re.I)
"""A number hyphenated to a word before a noun: "a three-seater sofa", "a two-group machine"."""


TOPS = re.compile(r"\b(two|four|six|eight|ten|twelve|[2-9]|1[0-2])[-\u2010\u2011 ]tops?\b", re.I)
"""Restaurant talk for tables by their seats: "two-tops and four-tops"."""


def _number_adjectives(text: str, kb: KnowledgeBase) -> str:
    """"A three-seater sofa" is one sofa: a number hyphenated to a word that is no room,
    unit or object word, before a noun, is written as one word ("threeseater"), as
    "no-frills" is; "a two-bedroom flat", "a two-car garage" and "a four-poster bed" keep
    their number."""
    voc = vocabulary(kb)

    def join(mt: re.Match[str]) -> str:
        word = mt.group(2).lower()
        known = f"{mt.group(1).lower()} {word}"
        if word in COUNT_COMPOUNDS or word in voc.forms or any(f.startswith(known) for f in voc.forms):
            return mt.group(0)
        return mt.group(1) + mt.group(2)

    text = TOPS.sub(lambda mt: f"tables for {mt.group(1)}", text)  # "a dining room of two-tops"
    return _NUMBER_COMPOUND.sub(join, text)


_CAPITALISED = re.compile(r"\b[A-Z][a-z]+\b")


def _proper_words(text: str) -> frozenset[str]:
    """Words capitalised where a sentence does not start ("a Quaker meeting house")."""
    out = set()
    for mt in _CAPITALISED.finditer(text):
        before = text[: mt.start()].rstrip()
        if before and before[-1] not in ".!?:;\"'(":
            out.add(mt.group().lower())
    return frozenset(out)


def _mask_height_words(kb: KnowledgeBase, norm: str) -> str:
    """``norm`` with the height words of heights.yaml blanked (same length, so positions
    hold): "a double height living room" is one living room, not two named "height
    living room"."""
    words = tuple(kb.heights.words)
    if not words or not any(w in norm for w in words):
        return norm
    rx = re.compile(r"(?<![a-z0-9])(?:" + "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))
                    + r")(?![a-z0-9])")
    return rx.sub(lambda m: " " * len(m.group()), norm)


AFTER_A_NOUN = frozenset(
    "and or with without for where that which who above below beside behind under over off on in at of to by "
    "from near next upstairs downstairs overlooking facing opposite as plus "
    "has have had holds hold is was gets seats leads opens looks doubles".split())
"""Words that may follow a room word standing as a noun ("a snug with a fire", "the
lord's solar above the hall", "the snug has a fireplace")."""


BEFORE_AN_ADJECTIVE = frozenset(
    "feel feels felt is are was were be being look looks seem seems stay stays keep keeps remain remains "
    "very so too quite really rather extra and but yet".split())
"""Words before a ``noun_only`` room word that make it an adjective ("feels snug")."""


OF_QUANTITY = re.compile(r"\s+of\s+(?!(?:the|a|an|this|that|his|her|its|their|my|our|your)\b)")
"""What follows a word used as a quantity: "a range of teas", not "the range of the house"."""


QUANTITY_LEAD = re.compile(r"\b(?:a|an|the|this|that)\s+(?:[a-z]+\s+){0,2}$")
"""The article and adjectives before a quantity word ("a wide range")."""


EN_SUITE_KEYS = frozenset({"en-suite", "ensuite"})
"""Room words that, written before a bedroom, say it has its own bathroom."""


def _ensuite_counts(kb: KnowledgeBase, text: str, mentions: list[Mention]) -> None:
    """"Three en-suite bedrooms": the count is the bedrooms' too (an en-suite each), not
    three bathrooms beside bedrooms of any number."""
    names = kb.raw("rooms")["names"]
    for a, b in zip(mentions, mentions[1:]):
        if (a.kind == b.kind == "room" and a.key in EN_SUITE_KEYS and b.count is None and a.count is not None
                and (names.get(b.key) or {}).get("type") == "bedroom" and not text[a.end : b.start].strip()):
            b.count, b.plural = a.count, a.plural


def _nouns_only(kb: KnowledgeBase, text: str, mentions: list[Mention]) -> list[Mention]:
    """``mentions`` less the rooms named by a word that is here an adjective (rooms.yaml
    ``noun_only``): "a snug bedroom", "solar panels", "buttery leather"; and less the
    objects named by a word that is here a quantity (concepts.yaml ``quantity_words``):
    "a wide range of teas" holds no kitchen range."""
    names = kb.raw("rooms")["names"]
    quantities = frozenset(kb.raw("concepts").get("quantity_words", []))
    keep = []
    for m in mentions:
        if m.kind == "object" and m.name.split()[-1] in quantities and OF_QUANTITY.match(text, m.end):
            if (lead := QUANTITY_LEAD.search(text, 0, m.start)) is not None:
                m.start = lead.start()  # "a wide range": its adjectives name nothing either
            continue
        if m.kind == "room" and (names.get(m.key) or {}).get("noun_only"):
            nxt = re.match(r"\s*([a-z][a-z'-]*)", text[m.end :])
            if nxt is not None and nxt.group(1) not in AFTER_A_NOUN:
                continue
            before = re.search(r"([a-z]+)\s*$", text[: m.start])
            if before is not None and before.group(1) in BEFORE_AN_ADJECTIVE:
                continue  # "the room feels snug and warm"
        keep.append(m)
    return keep


def _joined_room_words(kb: KnowledgeBase, text: str, mentions: list[Mention]) -> list[Mention]:
    """``mentions`` with two room words of one type written side by side taken as one
    room, named by the second ("an entry foyer": a foyer, not an entry and a foyer)."""
    names = kb.raw("rooms")["names"]

    def room_type(m: Mention) -> str | None:
        return (names.get(m.key) or {}).get("type") if m.kind == "room" else None

    out: list[Mention] = []
    for m in mentions:
        prev = out[-1] if out else None
        if (prev is not None and prev.count is None and room_type(prev) is not None
                and room_type(prev) == room_type(m) and not text[prev.end:m.start].strip()):
            out[-1] = dataclasses.replace(m, start=prev.start)
            continue
        out.append(m)
    return out


def parse(text: str, kb: KnowledgeBase | None = None) -> Parsed:
    """Parse ``text`` into a :class:`Parsed` with the knowledge base ``kb`` (None: the
    one in force); never raises on odd input."""
    kb = resolve(kb)
    text = _NO_COMPOUND.sub(r"\1", clean_text(text))  # escape sequences never reach a name
    text = _number_adjectives(text, kb)
    text = STYLE_SUFFIX.sub(r"\1", text)  # "a speakeasy-style cocktail bar": a speakeasy cocktail bar
    norm = normalize(text)
    p = Parsed(text=norm, proper_words=_proper_words(text))
    if len(norm) > MAX_PARSE_CHARS:
        p.warnings.append(f"text is {len(norm)} characters long; only the first {MAX_PARSE_CHARS} were read")
        norm = norm[:MAX_PARSE_CHARS]
    norm = rewrite_numbers(norm)
    norm = _room_for(kb, norm)
    p.text = norm
    norm = _mask_height_words(kb, norm)  # read by anyhome.plan.heights from p.text
    taken: list[tuple[int, int]] = []
    _apply_codes(norm, p, taken)
    _find_levels(norm, p)
    _stated_area(kb, norm, p, taken)
    span = _parse_building(kb, norm, p, taken)
    _head_size_words(kb, norm, p)
    if span:
        taken.append(span)
        if (down := IN_A_BASEMENT.match(norm, span[1])) is not None:  # "a cocktail bar in a basement"
            taken.append(down.span())
            p.basement = bool(_BASEMENT.search(norm[: down.start()] + " " + norm[down.end() :]))
        elif (place := IN_A_PLACE.match(norm, span[1])) is not None:  # "... in a shopping arcade"
            taken.append(place.span())
    found = _joined_room_words(kb, norm, _find_mentions(kb, norm, p, taken))
    mentions = _nouns_only(kb, norm, found)
    taken.extend((m.start, m.end) for m in found if m not in mentions)  # "a snug little sitting room": an adjective, never a room
    tokens = _tokens(norm)
    spans = taken + [(m.start, m.end) for m in mentions]
    for m in mentions:
        _look_back(m, norm, tokens, spans, keep_words=True, kb=kb)
        if m.kind == "room":
            kept = []
            for w in m.words:
                if w in vocabulary(kb).style_forms or vocabulary(kb).colour_regex.fullmatch(w) or w in _MORE_WORDS:
                    continue
                kept.append(w)
            m.words = kept
        if m.words:
            m.name = " ".join(m.words + [m.name])
    _ensuite_counts(kb, norm, mentions)
    mentions = _open_vocabulary(kb, norm, p, taken, mentions, tokens)
    _apply_negation(norm, mentions, kb)
    _paired_rooms(norm, mentions)
    _check_counts(p, mentions)
    _total_rooms(norm, p, mentions)
    if _ONE_ROOM.search(norm):
        p.one_room = True
    _bath_in_a_list(norm, kb, mentions)
    _toilet_rooms(norm, kb, mentions)
    _rooms_in_a_list(norm, kb, p, mentions)
    _paired_rooms(norm, mentions)  # "boys' and girls' toilets" are rooms now
    mentions = _purpose_words(norm, mentions)
    _assign_rooms(norm, mentions, kb)
    _subject_room(norm, p, mentions)
    _table_seats(norm, kb, mentions)
    mentions = _corefer(norm, p, mentions)
    mentions = _former_rooms(norm, mentions)
    mentions = _apposed_rooms(norm, mentions)
    mentions = _house_totals(norm, p, mentions)
    _apply_arrangements(norm, mentions)
    p.rooms = [m for m in mentions if m.kind == "room"]
    _storey_modifiers(norm, p)
    for end, value in p.room_areas:  # "a 12 m2 bedroom": the next room word's own area
        room = next((m for m in p.rooms if m.start >= end and len(_tokens(norm[end : m.start])) <= 2), None)
        if room is not None and value > 0:
            room.area_m2 = value
    p.objects = [m for m in mentions if m.kind == "object"]
    _find_seats(norm, p, mentions)
    _find_styles(kb, norm, p)
    _find_materials(kb, norm, p, p.rooms)
    return p
