"""Semantic tags: what an object *is*, as data instead of word lists in code.

Every prototype in ``plan/knowledge/objects.yaml`` names its ``tags:``, each one of the
closed set :data:`TAGS`. The planner copies them onto ``ItemSpec.tags``, the layout
stage onto ``HouseObject.tags`` (house.json); layout, refine and navigation read them.

The tags and the code that reads each one:

===============  ================================================================  ==========================
tag              meaning                                                           read by
===============  ================================================================  ==========================
seat             something one sits on (chairs, stools, sofas, benches, pews)      refine (turned to face a
                                                                                   table), layout (never
                                                                                   carries ornaments)
table            a top others are placed at or on, at table height                 refine, layout supporters
work_surface     a counter, desk or bench one works at                              refine, layout supporters
storage          furniture that stores things (cabinets, shelves, dressers);       layout supporters (when
                 its top carries ornaments when at a reachable height              its top is 0.4-1.2 m)
surface          another piece whose top carries ornaments (piano, tv stand)       layout supporters
front_of_room    what a room set out in rows faces (boards, screens, altars,       layout (rows front wall)
                 lecterns, stages, TVs)
floor_layer      walkable floor covering (rugs, mats)                              navigation (ignored)
bed              a bed of any kind                                                 layout (never a supporter)
plumbing         a fixture on water pipes (sink, toilet, bath, shower, pool)       layout (never a supporter)
appliance        an electrical or gas appliance                                    layout (never a supporter)
light_source     something that gives light (lamps, fireplaces)                    layout (never a supporter)
equipment        machines, instruments, gym, workshop, vehicle and play gear       layout (never a supporter
                                                                                   unless also ``surface``)
decor            ornaments, art, plants                                            layout (never a supporter)
outdoor          garden and yard things                                            layout (never a supporter
                                                                                   unless also ``table``)
===============  ================================================================  ==========================

Unknown objects: :func:`tags_for` resolves an object by its name (exact prototype key
or synonym, then the last prototype phrase the name contains, "oak dining table" ->
dining table), then by its category (a prototype key, or the first prototype of that
asset family). An object none of these finds gets **no tags** (``()``): it is never
a supporter, a seat, a table or front of room, and it blocks navigation like any
other object. That is the explicit, safe fallback.

Every lookup reads the knowledge base ``kb`` it is given (the planner passes its own);
None is the knowledge base in force: the explicit default for a house file read from
disk without tags (:class:`anyhome.house.HouseObject`) and for navigation of an object
given without tags.
"""

from __future__ import annotations

import functools
from collections.abc import Collection
from typing import TYPE_CHECKING, Literal, get_args

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

Tag = Literal[
    "seat", "table", "work_surface", "storage", "surface", "front_of_room", "floor_layer",
    "bed", "plumbing", "appliance", "light_source", "equipment", "decor", "outdoor",
]  # fmt: skip
TAGS: frozenset[str] = frozenset(get_args(Tag))
"""The closed set of semantic tags."""

SUPPORT_TAGS: frozenset[str] = frozenset({"table", "work_surface", "storage", "surface"})
"""An object with one of these may carry ornaments without a named target on its top."""
NO_SUPPORT_TAGS: frozenset[str] = frozenset(
    {"seat", "bed", "plumbing", "appliance", "light_source", "floor_layer", "decor"}
)
"""An object with one of these never carries untargeted ornaments, whatever else it is."""
TABLE_TAGS: frozenset[str] = frozenset({"table", "work_surface"})
"""What a seat nearby is turned to face."""


def is_seat(tags: Collection[str]) -> bool:
    return "seat" in tags and not TABLE_TAGS.intersection(tags)


def is_table(tags: Collection[str]) -> bool:
    return bool(TABLE_TAGS.intersection(tags)) and "seat" not in tags


def is_supporter(tags: Collection[str]) -> bool:
    return bool(SUPPORT_TAGS.intersection(tags)) and not NO_SUPPORT_TAGS.intersection(tags)


def is_front_of_room(tags: Collection[str]) -> bool:
    return "front_of_room" in tags


def is_floor_layer(tags: Collection[str]) -> bool:
    return "floor_layer" in tags


def _resolve(kb: KnowledgeBase | None) -> KnowledgeBase:
    from anyhome.plan.kbview import resolve

    return resolve(kb)


@functools.lru_cache(maxsize=8)
def _tables(kb: KnowledgeBase) -> tuple[dict[str, tuple[str, ...]], dict[str, tuple[str, ...]]]:
    by_key: dict[str, tuple[str, ...]] = {}
    by_category: dict[str, tuple[str, ...]] = {}
    for key, proto in kb.raw("objects").items():
        tags = tuple(proto.get("tags") or ())
        by_key[key] = tags
        by_category.setdefault(str(proto.get("category", "")), tags)
    return by_key, by_category


def prototype_of_name(name: str, kb: KnowledgeBase | None = None) -> str | None:
    """The object prototype a name means in ``kb``: the name itself as a key or synonym
    (plurals too), else the last prototype phrase inside it (the head of an English noun
    phrase comes last: "oak dining table" is a dining table); None when it names none."""
    return _prototype_of_name(name, _resolve(kb))


@functools.lru_cache(maxsize=4096)
def _prototype_of_name(name: str, kb: KnowledgeBase) -> str | None:
    from anyhome.plan.kbview import vocabulary
    from anyhome.plan.knowledge import normalize

    voc = vocabulary(kb)
    n = normalize(name)
    hit = voc.forms.get(n)
    if hit is not None and hit[0].kind == "object":
        return hit[0].key
    found = [m for m in voc.regex.finditer(n) if voc.forms[m.group(0)][0].kind == "object"]
    return voc.forms[found[-1].group(0)][0].key if found else None


def tags_by_name(name: str, kb: KnowledgeBase | None = None) -> tuple[str, ...]:
    """The tags of the prototype ``name`` means in ``kb`` (see :func:`prototype_of_name`),
    else ``()``."""
    kb = _resolve(kb)
    key = _prototype_of_name(name, kb)
    return _tables(kb)[0].get(key, ()) if key is not None else ()


def tags_for(name: str, category: str = "", kb: KnowledgeBase | None = None) -> tuple[str, ...]:
    """The semantic tags of an object called ``name`` of asset family ``category``, in
    ``kb`` (None: the knowledge base in force).

    Order: the name as a prototype key or synonym (plural forms too), then the
    longest prototype phrase inside the name, then ``category`` as a prototype key,
    then the first prototype of that asset family; else ``()`` (see module docs).
    """
    return _tags_for(name, category, _resolve(kb))


@functools.lru_cache(maxsize=4096)
def _tags_for(name: str, category: str, kb: KnowledgeBase) -> tuple[str, ...]:
    by_key, by_category = _tables(kb)
    key = _prototype_of_name(name, kb)
    if key is not None:
        return by_key.get(key, ())
    c = category.strip().lower()
    if c in by_key:
        return by_key[c]
    if c.replace("_", " ") in by_key:
        return by_key[c.replace("_", " ")]
    return by_category.get(c, ())
