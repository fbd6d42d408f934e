"""Algorithm 1 of AnyHome: place each room's furniture groups by their rules.

Per room, groups are taken in priority order; for each of ``repeat`` copies the anchor
is placed by its rule (:mod:`.rules`), choosing among all viable candidate poses
(:mod:`.scoring`: rule preference, spacing and seeded noise), then each member by its
rule relative to the anchor or to its ``target`` (:mod:`.groups`). A few anchor poses
are tried when members do not fit. Arrangements (:mod:`.arrangements`) lay out the
copies in rows, along the walls or about the centre. After every floor object the
room's walkways are re-checked on the 5 cm navigation raster; what does not fit is
dropped and reported, never forced. Zones offered to a bare room (:mod:`.fill`), rugs
(:mod:`.layers`) and ornaments (:mod:`.ornaments`) follow. Every weight
is a named option (:class:`~anyhome.layout.options.LayoutOptions`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from shapely.geometry import Polygon

from anyhome.house import Dropped, Floorplan, HouseObject, Room
from anyhome.layout import arrangements, fill, kitchens, layers, ornaments
from anyhome.layout.options import DEFAULT_OPTIONS, LayoutOptions
from anyhome.layout.state import RoomState
from anyhome.layout.zones import arm_zones
from anyhome.plan.spec import GroupSpec, HouseSpec, ItemSpec, RoomSpec


@dataclass
class LayoutResult:
    """The layout stage's output: placed objects and what could not be placed."""

    objects: list[HouseObject] = field(default_factory=list)
    dropped: list[Dropped] = field(default_factory=list)


def layout_house(spec: HouseSpec, floorplan: Floorplan, rng: np.random.Generator,
                 options: LayoutOptions = DEFAULT_OPTIONS) -> LayoutResult:
    """Place every room's furniture groups and ornaments (Algorithm 1 of AnyHome).

    Parameters
    ----------
    spec : the plan (rooms with groups and ornaments)
    floorplan : rooms, doors and windows the plan was laid out as
    rng : the only source of randomness; same inputs and seed give identical objects
    options : the layout's weights, try counts and noise (:class:`LayoutOptions`)

    Returns
    -------
    LayoutResult
        ``objects`` valid by construction (SCENE_FORMAT.md rules 1-4 and 6) and
        ``dropped``, one entry per object copy that found no valid spot.
    """
    result = LayoutResult()
    held = {h for r in floorplan.rooms for h in r.merged}
    for rs in spec.rooms:
        if rs.id in held:  # laid out in the open-plan room that holds it
            continue
        try:
            room = floorplan.room(rs.id)
        except KeyError:
            for item in _items(rs):
                result.dropped.append(Dropped(room=rs.id, name=item.name, reason="room is missing from the floorplan"))
            continue
        zones: dict[int, Polygon] = {}
        if room.merged:
            others = [r for r in spec.rooms if r.id in room.merged]
            zones = _group_zones(room, rs, others)
            rs = with_merged(rs, others)
        if room.open_air:  # no ceiling to hang a chandelier, a fan or a pendant from
            rs, hung = _without_ceiling_hung(rs)
            result.dropped += [Dropped(room=rs.id, name=n, reason="an open-air room has no ceiling to hang it from")
                               for n in hung]
        st = RoomState(floorplan, room, rs, rng, options, group_zones=zones)
        furnish_room(st)
        result.objects.extend(st.space.objects)
        result.dropped.extend(st.dropped)
    return result


SHRINK_SCALES = (0.85, 0.7)
"""Footprint scales of a key anchor tried when it does not fit at its planned size."""
NARROW_SCALES = (0.6, 0.8)
"""(width, depth) scales of a key anchor tried last, when it fits at none of
:data:`SHRINK_SCALES`: the narrower piece a designer would pick for a small room (a
loveseat for a sectional sofa), its depth kept more than its width."""


def furnish_room(st: RoomState) -> None:
    """The room's groups in priority order, each by its arrangement, then its rugs under
    them (:mod:`.layers`), then its ornaments.

    When a key group's anchor (:attr:`GroupSpec.key`) is dropped, the room is furnished again
    making room for it: key groups first, the others after; then with each key anchor
    dropped so far (in any of these furnishings) smaller (:data:`SHRINK_SCALES`); then with
    the other key groups' members left out (they go before a key anchor does); last, the same
    two with those anchors narrower (:data:`NARROW_SCALES`: a loveseat for a sectional). The
    furnishing that drops the fewest key anchors, then the fewest items, is kept; a key
    anchor is dropped only when none fits."""
    _make_room(st)
    keys = {g.anchor.name for g in st.spec.groups if g.key}
    st.dropped[:] = [d.model_copy(update={"key": True}) if d.name in keys else d for d in st.dropped]


def _make_room(st: RoomState) -> None:
    start = st.snapshot()
    groups = st.spec.groups
    order = sorted(range(len(groups)), key=lambda i: (groups[i].priority, kitchens.waits_for_run(groups[i])))
    _furnish(st, order, {})
    missing = _key_dropped(st)
    if not missing:
        return
    best = _outcome(st, len(missing))
    keys_first = sorted(order, key=lambda i: not groups[i].key)
    # last: the smallest, with the members of the other key groups giving way (a coat
    # rack for the boot shelf)
    smallest = (SHRINK_SCALES[-1], SHRINK_SCALES[-1])
    for scale, bare in [*(((s, s), False) for s in (1.0, *SHRINK_SCALES)), (smallest, True),
                        (NARROW_SCALES, False), (NARROW_SCALES, True)]:
        st.restore(start)
        # the members the text asked for ("a bar with eight stools") never make room
        keep = {i for i in keys_first if groups[i].key and not groups[i].required and i not in missing} if bare else set()
        _furnish(st, keys_first, {i: scale for i in missing}, bare=keep)
        dropped_now = _key_dropped(st)
        missing += [i for i in dropped_now if i not in missing]  # shrink these too next time
        now = _outcome(st, len(dropped_now))
        if now[:2] < best[:2]:
            best = now
        if now[0] == 0:
            return
    st.restore(start)
    _, _, st.space.placed[:], st.dropped[:], st.space.keep_clear[:], st.counters, st.nav.waived[:] = best
    st.nav.set_blocked(st.space.placed)


def _outcome(st: RoomState, n_key_dropped: int) -> tuple:
    """A furnishing as it stands, ranked by (key anchors dropped, items dropped)."""
    return (n_key_dropped, len(st.dropped), st.space.placed[:], st.dropped[:], st.space.keep_clear[:],
            dict(st.counters), st.nav.waived[:])


def _key_dropped(st: RoomState) -> list[int]:
    """Indices of the key groups with an anchor (a copy of it) dropped in this furnishing."""
    gone = {d.name for d in st.dropped}
    return [i for i, g in enumerate(st.spec.groups) if g.key and g.anchor.name in gone]


def _furnish(st: RoomState, order: list[int], scales: dict[int, tuple[float, float]],
             bare: set[int] | None = None) -> None:
    """The groups in ``order``; ``scales``: (width, depth) scales of some anchors' footprints; ``bare``:
    groups placed without their members, which are dropped to make room."""
    rugs = []
    zones = []
    for i in order:
        g = st.spec.groups[i]
        if bare and i in bare and g.members:
            for m in g.members:
                st.drop(m.name, "left out to make room for what the room is for", copies=g.repeat * m.count)
            g = g.model_copy(update={"members": []})
        if scales.get(i, (1.0, 1.0)) != (1.0, 1.0):
            w, d, h = g.anchor.size_m
            sw, sd = scales[i]
            g = g.model_copy(update={"anchor": g.anchor.model_copy(update={"size_m": (w * sw, d * sd, h)})})
        if layers.is_layer_group(g):
            rugs.append(g)
            continue
        if g.fill:
            zones.append(g)
            continue
        st.zone = st.group_zones.get(i)
        place_group(st, g)
    st.zone = None
    fill.place_zones(st, zones, place_group)
    layers.place_layers(st, rugs)
    ornaments.place_ornaments(st)


def place_group(st: RoomState, g: GroupSpec) -> None:
    """Every copy of ``g`` by its arrangement: rows, a kitchen run, an island, else free."""
    if g.arrangement == "rows":
        arrangements.place_rows(st, g)
    elif kitchens.is_kitchen_run(g):
        kitchens.place_kitchen(st, g)
    elif kitchens.is_island(st, g):
        kitchens.place_island(st, g)
    else:
        arrangements.place_free(st, g)


def _group_zones(room: Room, rs: RoomSpec, others: list[RoomSpec]) -> dict[int, Polygon]:
    """Index of a group of ``with_merged(rs, others)`` -> the arm of ``room`` it belongs in
    (:func:`anyhome.layout.zones.arm_zones`); {} when the room has no arms."""
    arms = arm_zones(room, [rs, *others])
    if arms is None:
        return {}
    n_own = len(rs.groups)
    return {i: arms[0] if i < n_own else arms[1] for i in range(n_own + len(others[0].groups))}


def with_merged(rs: RoomSpec, others: list[RoomSpec]) -> RoomSpec:
    """The planned room ``rs`` holding the groups and ornaments of ``others`` too (an
    open-plan room merged from several, :attr:`anyhome.house.Room.merged`): its own
    groups first among those of the same priority."""
    if not others:
        return rs
    return rs.model_copy(update={"groups": [*rs.groups, *(g for o in others for g in o.groups)],
                                 "ornaments": [*rs.ornaments, *(o for other in others for o in other.ornaments)]})


CEILING_HUNG = frozenset({"chandelier", "ceiling_fan", "pendant_light"})
"""Categories that hang from a ceiling: an open-air room (``Room.open_air``) gets none."""


def _without_ceiling_hung(rs: RoomSpec) -> tuple[RoomSpec, list[str]]:
    """``rs`` without its ceiling-hung items (a group whose anchor hangs goes whole),
    and the names of the copies left out."""
    gone: list[str] = []
    groups = []
    for g in rs.groups:
        if g.anchor.category in CEILING_HUNG:
            gone += [it.name for it in [g.anchor, *g.members] for _ in range(g.repeat * it.count)]
            continue
        keep = [m for m in g.members if m.category not in CEILING_HUNG]
        gone += [m.name for m in g.members if m.category in CEILING_HUNG for _ in range(g.repeat * m.count)]
        groups.append(g if len(keep) == len(g.members) else g.model_copy(update={"members": keep}))
    ornaments = [o for o in rs.ornaments if o.category not in CEILING_HUNG]
    gone += [o.name for o in rs.ornaments if o.category in CEILING_HUNG for _ in range(o.count)]
    if not gone:
        return rs, []
    return rs.model_copy(update={"groups": groups, "ornaments": ornaments}), gone


def _items(rs: RoomSpec) -> list[ItemSpec]:
    out = []
    for g in rs.groups:
        for _ in range(g.repeat):
            out.append(g.anchor)
            out.extend(g.members)
    return out + list(rs.ornaments)
