"""Open vocabulary: words of the text the knowledge base does not list.

The lexical parser (:mod:`anyhome.plan.parse`) finds every phrase the knowledge base
knows. This module finds what it missed and maps it through
:func:`anyhome.plan.concepts.nearest`:

* **objects**: noun phrases in an object list ("with a hammock, a jukebox and two
  chaise longues") become object mentions mapped to the nearest object prototype; the
  user's words stay the object's name. With no confident match the object still comes,
  as a generic piece of the fallback size, and a warning says so.
* **the building**: when no known building word is found, the head of the text's
  first noun phrase ("A dojo with ...") is mapped to the nearest building program, or
  failing that to the nearest room concept (a one-room building).
* **rooms**: unknown room words ("séance room") and known heads with an unknown
  modifier ("recital hall") get the furnishing of the nearest room concept.

Knowledge (nouns that are never objects, the fallback object) is in
``knowledge/concepts.yaml``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from anyhome.plan.concepts import GENERIC_HEADS, Match, nearest, threshold
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import resolve

DETERMINERS = frozenset("a an the one two three four five six seven eight nine ten eleven twelve dozen several some many few multiple lots plenty pair couple".split())
"""Words that start a noun phrase in an object list."""

LIST_OPENERS = frozenset("with featuring including containing plus has have having boasting".split())
"""Words after which a clause lists objects."""

PHRASE_BREAKS = frozenset(
    """and or with in on at for to by from into inside near next as is are has have having that which
    where featuring containing plus also of each every per its their his her my our this these those
    there here it them but while so than like along around against under over above below behind
    beside between facing off own all both surrounded arranged placed painted covered hung mounted
    stacked running overlooking holding leading opening looking sitting standing lining""".split()
)
"""Words that end a noun phrase."""

MAX_PHRASE_WORDS = 3
"""Longest open-vocabulary object phrase kept."""

ROOM_MARGIN = 0.1
"""How much better a list phrase must match a room concept than an object to be a room."""

LIST_ROOM_MIN = 0.65
"""Least room score for a phrase in an object list to be taken as a room (a list names
objects unless the room match is strong: "hammock" is not the "hammam")."""

MIN_STYLE_CHARS = 4
"""Shortest unknown word the matcher may read as a style."""

MAX_OPEN_OBJECTS = 12
"""Most open-vocabulary object mentions taken from one text."""


def non_objects(kb: KnowledgeBase | None = None) -> frozenset[str]:
    return frozenset(resolve(kb).raw("concepts").get("non_objects", []))


def find_object_phrases(
    text: str, tokens: list[tuple[str, int, int]], taken: list[tuple[int, int]], is_number: Callable[[str], bool],
    soft: Sequence[tuple[int, int]] = (), kb: KnowledgeBase | None = None,
) -> list[tuple[str, int, int]]:
    """Noun phrases in object lists that no known phrase covers.

    Returns (phrase, start, end) triples; a phrase qualifies when a list
    opener ("with", "featuring"..., or a colon) precedes it in the same clause and a determiner, a
    count, a comma or "and" stands right before it. Words in ``soft`` spans (colours,
    materials, styles) may modify a phrase ("a tufted pink ottoman", "six steel
    fermentation tanks") but never end it.
    """
    non_objects_ = non_objects(kb)

    def is_taken(s: int, e: int) -> bool:
        return any(a < e and s < b for a, b in taken)

    def is_soft(s: int, e: int) -> bool:
        return any(a <= s and e <= b for a, b in soft)

    out: list[tuple[str, int, int]] = []
    in_list = False
    i = 0
    n = len(tokens)
    while i < n:
        tok, s, e = tokens[i]
        if tok in ".;!?()":
            in_list = False
            i += 1
            continue
        if tok in LIST_OPENERS or tok == ":":  # "a monastery: twelve cells, a chapel" lists as "with" does
            in_list = True
            i += 1
            continue
        prev = tokens[i - 1][0] if i > 0 else ""
        starts = prev in DETERMINERS or is_number(prev) or prev in (",", "and", "of", ":") or prev in LIST_OPENERS
        if not (in_list and starts) or (is_taken(s, e) and not is_soft(s, e)) or not tok.isalpha() or tok in PHRASE_BREAKS or tok in DETERMINERS:
            i += 1
            continue
        j = i
        words: list[str] = []
        hard = 0  # words not in a soft span
        while j < n and hard < MAX_PHRASE_WORDS:
            t, ts, te = tokens[j]
            if not t.isalpha() or t in PHRASE_BREAKS or is_taken(ts, te) or is_number(t):
                break
            words.append(t)
            hard += not is_soft(ts, te)
            j += 1
        while words and is_soft(*tokens[i + len(words) - 1][1:]):
            words.pop()
        j = i + len(words)
        if words and words[-1] not in non_objects_ and len(words[-1]) >= 3:
            out.append((" ".join(words), tokens[i][1], tokens[j - 1][2]))
        i = max(j, i + 1)
        if len(out) >= MAX_OPEN_OBJECTS:
            break
    return out


def first_noun_phrase(text: str, tokens: list[tuple[str, int, int]]) -> tuple[str, int, int] | None:
    """The text's opening noun phrase ("a dojo" -> "dojo"), up to the first break word."""
    words: list[tuple[str, int, int]] = []
    for tok, s, e in tokens:
        if not words and tok in DETERMINERS:
            continue
        if not tok.isalpha() or tok in PHRASE_BREAKS:
            break
        words.append((tok, s, e))
        if len(words) > 4:
            return None
    if not words:
        return None
    return " ".join(w for w, _, _ in words), words[0][1], words[-1][2]


def classify(phrase: str, kb: KnowledgeBase | None = None, room_ok: bool = True) -> tuple[str, Match | None]:
    """Whether an unknown list phrase names a room or an object, and its concept.

    A phrase is a room when its room match clears the threshold and beats its object
    match by ``ROOM_MARGIN`` ("a home theater", "a sauna"); otherwise an object.
    ``room_ok=False``: the context says it is what a room holds ("a bay for two
    engines"), so an object whatever it matches. A closed compound on "room"
    ("courtroom") is a room whatever it matches, with no concept when its room match is
    weak (a courtroom is no control room: it is furnished as a room of type ``other``).
    """
    mo = _best(nearest("objects", phrase, with_score=True, kb=kb), None)
    mr = _best(nearest("rooms", phrase, with_score=True, kb=kb), None)
    head = phrase.split()[-1]
    objectness = mo  # how much the phrase reads as an object, a sibling's word included
    if head != phrase and head not in GENERIC_HEADS:  # "front porch": the head decides too
        hr = nearest("rooms", head, with_score=True, kb=kb)
        ho = nearest("objects", head, with_score=True, kb=kb)
        mr = _best(mr, hr)
        objectness = _best(mo, ho)
        if ho is not None and _head_match(ho, head) is None and mo is not None and mo.score < SIBLING_MIN:
            mo = None  # "a shoeshine stand": no tv stand, and nothing else is near: the user's own
        mo = _best(mo, _head_match(ho, head))
    if (room_ok and mr is not None and mr.score >= max(threshold("rooms", kb=kb), LIST_ROOM_MIN)
            and (objectness is None or mr.score > objectness.score + ROOM_MARGIN)):
        return "room", mr
    if room_ok and _room_compound(head):  # "two courtrooms": a room; its concept only when close
        return "room", mr if mr is not None and mr.score >= LIST_ROOM_MIN else None
    return "object", mo if mo is not None and mo.score >= threshold("objects", kb=kb) else None


ROOM_COMPOUND_MIN_CHARS = 7
"""A closed compound on "room" needs this many letters to be read as one ("courtroom",
"stockroom"), so that a plain "room" or "broom" is not."""
NOT_ROOM_COMPOUNDS = frozenset("mushroom mushrooms broom brooms vroom heirloom".split())
"""Words that end in "room" and are no room."""


def _room_compound(word: str) -> bool:
    """Whether ``word`` is a closed compound naming a room ("courtroom", "boardroom",
    "storeroom", "stillroom"): it ends in "room" and is no known exception."""
    return word.endswith("room") and len(word) >= ROOM_COMPOUND_MIN_CHARS and word not in NOT_ROOM_COMPOUNDS


SIBLING_MIN = 0.65
"""Where a phrase's head matched only a sibling ("tv stand" for "truing stand"), the whole
phrase's match must reach this score to stand; else the object keeps the user's name."""


def _head_match(m: Match | None, head: str) -> Match | None:
    """A head word's own match, or None where it matched a sibling of the phrase: a
    concept with the same head and another modifier ("tv stand" for the head of "wheel
    truing stand", "shoeshine stand") says what the head is not, not what it is."""
    if m is None:
        return None
    words = m.key.split()
    return None if len(words) > 1 and words[-1] in (head, head + "s") else m


def _best(a: Match | None, b: Match | None) -> Match | None:
    if a is None or (b is not None and b.score > a.score):
        return b
    return a


def map_room(phrase: str, kb: KnowledgeBase | None = None) -> Match | None:
    """The furnishing set for an unknown room phrase."""
    return nearest("rooms", phrase, kb=kb)


PLACE_WORDS = frozenset(
    "main principal central big large small little old new front back rear upper lower "
    "first second third top ground side inner outer middle far near".split())
"""Modifiers that say which room or where, not what for: "the main hall" of a school is
its hall, not a main bedroom."""


def map_modified_room(head: str, words: list[str], kb: KnowledgeBase | None = None) -> Match | None:
    """A better furnishing for a known generic head with unknown modifiers ("recital hall")."""
    words = [w for w in words if w not in PLACE_WORDS]
    if head not in GENERIC_HEADS or not words:  # "eucalyptus steam room" stays a steam room
        return None
    return nearest("rooms", " ".join([*words, head]), kb=kb)


def map_building(phrase: str, kb: KnowledgeBase | None = None) -> Match | None:
    """The building program for an unknown building word."""
    return nearest("buildings", phrase, kb=kb)


def map_style(word: str, kb: KnowledgeBase | None = None) -> Match | None:
    """The style for an unknown style word before the building ("craftsman", "neon");
    words under ``MIN_STYLE_CHARS`` letters ("mid" of "mid-size") are not mapped."""
    if len(word) < MIN_STYLE_CHARS or word in resolve(kb).raw("concepts").get("setting_words", []):
        return None
    return nearest("styles", word, kb=kb)


def fallback_object(kb: KnowledgeBase | None = None) -> dict:
    """Prototype fields for an object no concept matches (``concepts.yaml``)."""
    return dict(resolve(kb).raw("concepts").get("fallback_object") or {"size": [0.6, 0.6, 0.8], "rule": "place_wall"})

