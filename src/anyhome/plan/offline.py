"""The embedded offline planner: text -> HouseSpec with no network and no model weights.

Pipeline: :func:`anyhome.plan.parse.parse` reads the text; :mod:`~anyhome.plan.program`
picks the rooms and links them; :mod:`~anyhome.plan.furnish` fills each room with
furniture groups and ornaments and applies what the text asked for;
:mod:`~anyhome.plan.appearance` chooses style, palette and materials. Every random choice
draws from the ``numpy.random.Generator`` passed in, so one text and one seed always give
the same plan. The knowledge lives in YAML files under ``knowledge/``
(see docs/knowledge_base.md).
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from anyhome.errors import PlanError
from anyhome.house import Floorplan, is_habitable
from anyhome.layout.rules import REGISTRY
from anyhome.plan import furnish as fu
from anyhome.plan.appearance import Look, choose_look, item_material, room_materials
from anyhome.plan.heights import RoomHeight, room_heights
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import resolve
from anyhome.plan.parse import Mention, Parsed, parse, plural
from anyhome.plan.program import (
    HELD_KEYS,
    Sizing,
    Slot,
    choose_program,
    connect_levels,
    fit_areas,
    fit_rooms,
    former_keeps,
    is_dwelling,
    norm_area_m2,
    open_air_by_name,
    plan_rooms,
    renumber,
    sample_areas,
    size_rng,
    sizing,
    stairwells_sized,
)
from anyhome.plan.spec import GroupSpec, HouseSpec, ItemSpec, RoomSpec, kb_context

log = logging.getLogger(__name__)

FLOOR_USE_FACTOR = 2.4
"""Room area needed per m2 of furniture footprint (walkways, clearances), for a room
type whose rooms.yaml entry gives no ``floor_use`` of its own."""

ROWS_USE_FACTOR = 1.8
"""Area of a rows arrangement per m2 of its cells (front and side clearances)."""

ROW_AISLE_M = 0.5
"""Aisle kept on two sides of each copy of a group set out in rows (as the layout does)."""

MAX_ROOM_AREA_M2 = 300.0
"""Largest area the furniture may push a room to: a 120-seat lecture hall needs about
250 m2; the busiest benchmark rooms (forty call-centre desks in rows, an 80-seat
theatre) about 240."""

MAX_HOUSE_AREA_M2 = 800.0
"""Largest total area the furniture may push a house to: twice the largest benchmark
house (a fire station, about 410 m2); beyond it the rooms that grew shrink back
in proportion."""

ESSENTIAL_PRIORITY = 1
"""Groups of this priority or a more urgent one (lower) stay in a room squeezed into a
stated total or a size word's; the others may go."""

TIGHT_PRIORITY = 0
"""Groups of this priority or a more urgent one stay in a room whose house still passes
the total a size word or a stated area sets once the groups past
:data:`ESSENTIAL_PRIORITY` went (a tiny cottage's bedroom keeps its bed, not its
reading chair)."""

MAX_ROOM_OBJECTS = 160
"""Most objects one room's plan places: a 120-seat hall with its stage, screen and
lectern fits; the busiest benchmark room (a trattoria) plans about 105. Layout time grows
with the objects a room must try to place, so this keeps a room within a second or two."""

MAX_HOUSE_OBJECTS = 400
"""Most objects a whole plan places: about twice the busiest benchmark house (a law firm,
about 180), so that generation stays within seconds."""


FloorplanStage = Callable[[HouseSpec, np.random.Generator], Floorplan]
"""floorplan(spec, rng) -> Floorplan: the run's floorplan stage (``Stages.floorplan``)."""


class OfflinePlanner:
    """Plans a house from text with the knowledge base ``kb`` (None: the one in force
    when the planner is made: shipped files, ``$ANYHOME_KNOWLEDGE_PATH``, ``--knowledge``).

    ``floorplan`` is the floorplan stage a plan is laid out with to meet a stated total
    ("a 50 m2 flat") or a size word ("tiny", "grand") in the built house
    (:func:`calibrate_total`); whoever builds the planner passes the run's stage
    (``anyhome.plan.get_planner``, ``anyhome.generate``). None: the totals are met by the
    planned room areas only, which the floorplan stage grows (halls, rooms reaching the
    depth of their block)."""

    name = "offline"

    def __init__(self, kb: KnowledgeBase | None = None, floorplan: FloorplanStage | None = None) -> None:
        self.kb = resolve(kb)
        self.floorplan = floorplan

    def plan(self, text: str, rng: np.random.Generator) -> HouseSpec:
        kb = self.kb
        if not isinstance(text, str) or not text.strip():
            raise PlanError("the text is empty: describe a house, e.g. 'a two-bedroom apartment'")
        parsed = parse(text, kb)
        warnings = list(parsed.warnings)
        if not _mostly_latin(text):
            warnings.append("the offline planner reads English; most of this text is in another script")
        if not parsed.recognized:
            warnings.append("no building, room or object in the text was recognised; planned a default home")
        program, implied = choose_program(kb, parsed)
        if parsed.one_room:  # "a one-room cabin": only the rooms the text names
            program = None
        asked_program = program
        sz = sizing(kb, parsed, program)  # the kind's room sizes, the total asked for
        program = sz.program
        slots, main_key = plan_rooms(kb, parsed, program, rng, warnings, sz)
        _main_beside_bedrooms(slots, main_key, kb.raw("programs")["programs"].get(program or "", {}))
        if sz.band is not None:
            fit_rooms(kb, parsed, slots, sz, kb.raw("programs")["programs"].get(program or ""), _furnished_need(kb))
            renumber(slots)
            open_air_by_name(kb, slots)
        if parsed.one_room and len(slots) > 1:
            warnings.append(
                f"the text asks for a one-room building but names {len(slots)} rooms; planned the named rooms"
            )
        sample_areas(slots, parsed.building_size, size_rng(rng, text), kb)
        prog = kb.raw("programs")["programs"].get(program or "", {})
        connections = connect_levels(kb, slots, prog.get("entrance", []))
        fit_areas(kb, slots, sz)
        if sz.band is not None and _stairs_resized(slots, connections):  # a tiny home's ladder, not a dog-leg
            fit_areas(kb, slots, sz)
        for s in slots:  # a stairwell holds its flight, a landing its doors, whatever the total
            if s.key in HELD_KEYS:
                s.area = s.area_range[0]
        named = kb.raw("programs")["programs"].get(asked_program or "", prog)  # "a tiny cabin" stays a home
        building = named.get("building") or (slots[0].type.replace("_", " ") if program is None else "home")
        rooms = _furnish(kb, parsed, slots, main_key, prog, rng, warnings)
        for s, (groups, _) in zip(slots, rooms):
            if s.area_from == "stated":  # "a 9 m2 bedroom": what does not fit goes, not the area
                _trim(kb, s, groups)
                if s.area > s.drawn_area * 1.05:
                    warnings.append(
                        f"the {s.name} needs about {s.area:.0f} m2 for its furniture; planned {s.area:.0f} m2 "
                        f"instead of the {s.drawn_area:.0f} m2 asked for"
                    )
        if sz.band is not None:
            _fit_furnished(kb, slots, rooms, sz, warnings)
        stairwells_sized(slots, connections)  # the kind of stairs the final areas call for (a tiny home's ladder)
        look = choose_look(kb, parsed, implied, building, rng)
        asked = {m.name for m in parsed.objects if not m.negated}  # "a low writing desk": not every desk
        for groups, ornaments in rooms:
            fu.apply_period(kb, groups, ornaments, look.styles, asked, prog.get("swap"))
        building = parsed.building_word or building
        heights = room_heights(kb, parsed, [s.type for s in slots], [s.mention for s in slots])
        specs = [_room_spec(kb, s, g, o, look, rng, h) for s, (g, o), h in zip(slots, rooms, heights)]
        log.debug("planned %d rooms for %r", len(specs), text[:60])
        spec = HouseSpec.model_validate(
            {"prompt": text, "building": building, "style": look.describe, "styles": look.styles,
             "palette": look.palette, "rooms": specs, "connections": connections, "warnings": warnings},
            context=kb_context(kb),
        )
        if (self.floorplan is not None and sz.band is not None and sz.source in ("stated", "word")
                and not any(sz.what in w for w in warnings)):
            if parsed.total_m2 is not None:  # aim at the stated figure itself
                t = float(parsed.total_m2)
                band = (t * (1 - CALIBRATION_TOLERANCE), t * (1 + CALIBRATION_TOLERANCE))
            else:  # "a tiny cabin": within the word's range, clear of its edges
                lo, hi = sz.band
                band = (lo * (1 + WORD_BAND_MARGIN), hi * (1 - WORD_BAND_MARGIN)) if lo > 0 else (lo, hi * (1 - WORD_BAND_MARGIN))
                if band[0] > band[1]:  # a range too narrow for the margins: its middle
                    band = ((lo + hi) / 2, (lo + hi) / 2)
            spec = calibrate_total(kb, spec, slots, band, np.random.default_rng(int(rng.integers(2**32))),
                                   self.floorplan)
        return spec


CALIBRATION_PROBES = 2
"""Floorplans laid out per round to see how large a stated total's rooms come out."""
CALIBRATION_ROUNDS = 3
"""Most rounds of scaling the rooms towards a stated total."""
CALIBRATION_TOLERANCE = 0.03
"""A stated total is met when the probes' mean built area is within this fraction of it
(the bar is 15 %: one layout differs from the probes' mean; at 6 % a flat whose probes
came out 6 % over was kept and one layout of it 12 % over)."""

WORD_BAND_MARGIN = 0.06
"""A size word's range is aimed at this fraction inside each of its edges: one layout
differs from the probes' mean by up to about this much, so a grand home whose probes came
out at 305 m2 was built at 292 (issue 13's bar: "grand" at least 300 m2)."""


def built_area_m2(spec: HouseSpec, rng: np.random.Generator, floorplan: FloorplanStage) -> float | None:
    """Total floor area of ``spec`` as ``floorplan`` lays it out (all storeys), or None
    when it cannot be laid out."""
    from shapely.geometry import Polygon

    from anyhome.errors import AnyHomeError

    try:
        plan = floorplan(spec, rng)
    except AnyHomeError:
        return None
    return float(sum(Polygon(r.polygon).area for r in plan.rooms))


def calibrate_total(kb: KnowledgeBase, spec: HouseSpec, slots: list[Slot], band: tuple[float, float],
                    rng: np.random.Generator, floorplan: FloorplanStage) -> HouseSpec:
    """The rooms' areas scaled so that the built house, not only the plan, lands in
    ``band`` (m2: a stated total within :data:`CALIBRATION_TOLERANCE`, a size word's
    range): ``floorplan`` grows rooms to fill its footprint (a spine's rooms reach the
    depth of their block) and may add a hallway, so the plan is laid out a few times
    (:data:`CALIBRATION_PROBES` per round, ``rng``) and, when the mean built area falls
    outside the band, its rooms are scaled by the band's nearest part over that mean
    (the band's middle for a narrow band, otherwise 3 % inside its edge), never below
    their type's ``min_area_m2`` (a room whose area the text states and the stairwells
    keep theirs). Up to :data:`CALIBRATION_ROUNDS` rounds; the plan whose layouts came
    closest is kept, and a scaled plan the solver cannot lay out is never kept."""
    lo, hi = band
    best, best_err = spec, float("inf")
    keep = {s.id for s in slots if s.area_from == "stated" or s.key in HELD_KEYS}
    norms = {s.id: norm_area_m2(kb, s) for s in slots}  # a tiny home's norms are its size word's
    types = kb.rooms.types
    for _ in range(CALIBRATION_ROUNDS):
        built = [built_area_m2(spec, rng, floorplan) for _ in range(CALIBRATION_PROBES)]
        if any(a is None for a in built):  # scaled too far for the solver: keep the last plan that laid out
            break
        mean = float(np.mean([a for a in built if a is not None]))
        err = max(lo - mean, mean - hi, 0.0) / max(lo or hi, 1e-6)
        if err < best_err:
            best, best_err = spec, err
        if err == 0.0:
            break
        narrow = hi - lo <= 2 * CALIBRATION_TOLERANCE * (lo + hi) / 2
        target = (lo + hi) / 2 if narrow else (lo * 1.03 if mean < lo else hi * 0.97)
        f = target / mean
        rooms = []
        for r in spec.rooms:
            if r.id in keep:
                rooms.append(r)
                continue
            rt = types.get(r.type, types["other"])
            least = min(norms.get(r.id, rt.min_area_m2), r.area_m2)
            rooms.append(r.model_copy(update={"area_m2": round(float(np.clip(r.area_m2 * f, least, 400.0)), 2)}))
        spec = spec.model_copy(update={"rooms": rooms})
    return best


def _stairs_resized(slots: list[Slot], edges: list[tuple[str, str]]) -> bool:
    """Stairwells sized again for the stairs the fitted areas call for
    (:func:`stairwells_sized`: a tiny home's ship's ladder, not the dog-leg its drawn
    areas called for); whether any stairwell's area changed."""
    before = [s.area_range for s in slots if s.key in HELD_KEYS]
    stairwells_sized(slots, edges)
    return before != [s.area_range for s in slots if s.key in HELD_KEYS]


def _furnished_need(kb: KnowledgeBase) -> Any:
    """``slot -> m2`` its required furniture needs at its smallest (what
    :func:`_grow_area` would grow it to), probed with a fixed generator so the plan's own
    draws stay as they are."""
    cache: dict[tuple[str, str, int | None], float] = {}

    def need(s: Slot) -> float:
        key = (s.furnish, s.type, s.beds)
        if key not in cache:
            probe = Slot(s.name, s.type, s.furnish, s.area_range, area=1.0)
            groups, _, _ = fu.furnish_room(kb, s.furnish, s.type, 1.0, np.random.default_rng(0), beds=s.beds)
            _grow_area(probe, [g for g in groups if _essential(g)], factor=_floor_use(kb, s.type))
            cache[key] = probe.area
        return cache[key]

    return need


WORK_OTHER = "other_at_work"
"""The furnishing (and zones) of a room of no known kind in a building that is no home."""


def _seated(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], main_key: str | None) -> list[tuple[int, int]]:
    """(slot index, people) for each seat count of the text: the room it follows, else
    the building's main room; a dwelling's "for 4 people" is its household, not seats."""
    out = []
    for room, n in parsed.seats:
        if room is not None:
            idx = next((i for i, s in enumerate(slots) if s.mention == room), None)
        else:
            main = next((i for i, s in enumerate(slots) if main_key and s.key == main_key), None)
            idx = None if main is None or slots[main].type == "bedroom" or in_a_home(kb, parsed) else main
        if idx is not None:
            out.append((idx, n))
    return out


def _main_beside_bedrooms(slots: list[Slot], main_key: str | None, prog: dict[str, Any]) -> None:
    """The main room of a program whose main room sleeps its people (a studio), in a
    plan that gives them bedrooms of their own, furnished as programs.yaml
    ``main_beside_bedrooms`` says (no bed of its own)."""
    furnish = prog.get("main_beside_bedrooms")
    main = next((s for s in slots if main_key is not None and s.key == main_key), None)
    if furnish and main is not None and any(s.type == "bedroom" for s in slots if s is not main):
        main.furnish = furnish


def in_a_home(kb: KnowledgeBase, parsed: Parsed) -> bool:
    """Whether the text's building is one people live in (no building word: a home)."""
    return parsed.building is None or is_dwelling(kb, kb.raw("programs")["buildings"][parsed.building]["program"])


def _mostly_latin(text: str) -> bool:
    letters = [c for c in text if c.isalpha()]
    return not letters or sum(c.isascii() for c in letters) >= len(letters) / 2


def _furnish(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], main_key: str | None, prog: dict[str, Any], rng: np.random.Generator, warnings: list[str]) -> list[tuple[list[fu.Group], list[fu.Item]]]:
    built = []
    at_work = not in_a_home(kb, parsed)
    for s in slots:
        if at_work and s.furnish == "other":  # "a bulk tank room" of a dairy: no armchairs
            s.furnish = WORK_OTHER
        groups, ornaments, unused = fu.furnish_room(kb, s.furnish, s.type, s.area, rng, beds=s.beds)
        for key in prog.get("extra", {}).get(s.key, []):
            d = fu.group_def(kb, {"group": key})
            groups.append(fu.build_group(kb, d, s.area, rng))
        built.append((groups, ornaments, unused))
    _former_features(kb, parsed, slots, main_key, built, rng)
    for m in parsed.objects:
        if m.negated:
            continue
        targets = [_room_for(kb, m, slots, main_key)]
        if m.each and m.room is not None:  # "three bedrooms, each with a desk"
            targets = [i for i, s in enumerate(slots) if s.mention == m.room] or targets
        for i in targets:
            groups, ornaments, unused = built[i]
            fu.apply_mention(kb, m, groups, ornaments, unused, slots[i].area, rng)
    for groups, _, _ in built:
        fu.drop_unasked_beds(groups)
    for i, n in _seated(kb, parsed, slots, main_key):  # "a bistro for 40 covers"
        factor = _floor_use(kb, slots[i].type)
        before = _need_m2(built[i][0], factor)
        fu.seat(built[i][0], n)
        freed = before - _need_m2(built[i][0], factor)
        if freed > 0:  # "a waiting area seating four": sized for four, not for the usual six
            least = float(kb.raw("rooms")["types"].get(slots[i].type, {}).get("min_area_m2", 0.0))
            slots[i].area = round(max(min(least, slots[i].area), slots[i].area - freed), 2)
    for m in parsed.objects:  # "a bedroom without a tv", "no rug": after what the text adds
        if not m.negated:
            continue
        negated_in = [i for i, s in enumerate(slots) if m.room is not None and s.mention == m.room] or range(len(slots))
        for i in negated_in:
            groups, ornaments, _ = built[i]
            fu.remove_mention(kb, m, groups, ornaments)
    out = []
    for s, (groups, ornaments, _) in zip(slots, built):
        fu.join_groups(kb, groups)
        out.append((groups, fu.finalize_ornaments(groups, ornaments)))
    _cap_objects(slots, out, warnings)
    for s, (groups, _) in zip(slots, out):
        _grow_area(s, groups, warnings, factor=_floor_use(kb, s.type))
        if s.size < 1.0 and s.mention is not None:  # "a small office": its furniture fits the size asked for
            _fit_small_room(kb, s, groups)
    _cap_house_area(slots, warnings)
    _add_zones(kb, parsed, slots, out, rng, at_work)
    return out


def _former_features(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], main_key: str | None,
                     built: list[tuple[list[fu.Group], list[fu.Item], Any]], rng: np.random.Generator) -> None:
    """A converted building's old features as decor in its main room (programs.yaml
    ``conversions.keeps``): a converted chapel's living room keeps stained glass, not pews."""
    entries = former_keeps(kb, parsed).get("ornaments", [])
    main = next((i for i, s in enumerate(slots) if main_key is not None and s.key == main_key), None)
    if entries and main is not None:
        built[main][1].extend(fu.make_item(kb, e, rng, ornament=True) for e in entries)


def _add_zones(kb: KnowledgeBase, parsed: Parsed, slots: list[Slot], rooms: list[tuple[list[fu.Group], list[fu.Item]]],
               rng: np.random.Generator, at_work: bool = False) -> None:
    """Each room's zones (:func:`anyhome.plan.furnish.zone_groups`) after its groups, less
    what the text rules out, within the per-room and per-house object caps (none in a room
    the text calls small: :func:`_fit_small_room`); ``at_work``
    (the building is no home): a room of no known kind zones as :data:`WORK_OTHER`."""
    total = sum(fu.object_count(g, o) for g, o in rooms)
    negated = [m for m in parsed.objects if m.negated]
    zones = kb.raw("furniture").get("zones", {})
    for s, (groups, ornaments) in zip(slots, rooms):
        if s.size < 1.0 and s.mention is not None:  # "a small office": no more than its own furniture
            continue
        furnish = WORK_OTHER if at_work and s.type == "other" and s.furnish not in zones else s.furnish
        fill = fu.zone_groups(kb, furnish, s.type, s.area, groups, rng)
        for m in negated:
            if m.room is None or s.mention == m.room:
                fu.remove_mention(kb, m, fill, [])
        n = fu.object_count(groups, ornaments)
        for g in fill:
            k = fu.object_count([g], [])
            if n + k > MAX_ROOM_OBJECTS or total + k > MAX_HOUSE_OBJECTS:
                break
            groups.append(g)
            n += k
            total += k


def _cap_objects(slots: list[Slot], rooms: list[tuple[list[fu.Group], list[fu.Item]]], warnings: list[str]) -> None:
    """Bound the objects per room (:data:`MAX_ROOM_OBJECTS`) and per house
    (:data:`MAX_HOUSE_OBJECTS`); each cap that bites adds one warning saying what was
    asked and what is planned."""
    over = []
    for i, (s, (groups, ornaments)) in enumerate(zip(slots, rooms)):
        asked = fu.object_count(groups, ornaments)
        cut = fu.cap_objects([(groups, ornaments)], MAX_ROOM_OBJECTS)
        if cut:
            over.append((s.name, asked, {name: v for (_, name), v in cut.items()}))
    if over:
        names = ", ".join(f"{name} {_fmt(n)}" for name, n, _ in over[:3]) + (f" and {len(over) - 3} more" if len(over) > 3 else "")
        what = _cuts(over[0][2])
        warnings.append(
            f"asked for more objects than a room holds ({names}); planned at most {MAX_ROOM_OBJECTS} per room"
            + (f" ({over[0][0]}: {what})" if what else "")
        )
    asked = sum(fu.object_count(g, o) for g, o in rooms)
    cut = fu.cap_objects(rooms, MAX_HOUSE_OBJECTS)
    if cut:
        merged: dict[str, tuple[int, int]] = {}
        for (_, name), (a, b) in cut.items():
            x = merged.get(name, (0, 0))
            merged[name] = (x[0] + a, x[1] + b)
        planned = sum(fu.object_count(g, o) for g, o in rooms)
        warnings.append(
            f"the rooms asked for {_fmt(asked)} objects in all; a house holds at most {MAX_HOUSE_OBJECTS}, planned {planned}"
            + (f" ({_cuts(merged)})" if merged else "")
        )


def _fmt(n: int) -> str:
    return str(n)


def _cuts(cut: dict[str, tuple[int, int]], most: int = 4) -> str:
    """"120 desks -> 37, 120 lamps -> 37": the biggest cuts first."""
    items = sorted(cut.items(), key=lambda kv: kv[1][1] - kv[1][0])[:most]
    return ", ".join(f"{a} {plural(name)} -> {b}" for name, (a, b) in items)


def _room_for(kb: KnowledgeBase, m: Mention, slots: list[Slot], main_key: str | None) -> int:
    if m.room is not None:
        for i, s in enumerate(slots):
            if s.mention == m.room or m.room in s.parts:
                return i
    prefs = kb.raw("objects").get(m.key, {}).get("rooms", [])
    for pref in prefs:
        for i, s in enumerate(slots):
            if s.furnish == pref or s.type == pref:
                return i
    for i, s in enumerate(slots):
        if main_key and s.key == main_key:
            return i
    return next((i for i, s in enumerate(slots) if is_habitable(s.type)), 0)


def _cap_house_area(slots: list[Slot], warnings: list[str]) -> None:
    """Rooms grown for their furniture shrink back in proportion when the house passes
    :data:`MAX_HOUSE_AREA_M2` (never below the area they were drawn with)."""
    total = sum(s.area for s in slots)
    grown = [(s, s.area - s.drawn_area) for s in slots if s.area > s.drawn_area]
    extra = sum(g for _, g in grown)
    if total <= MAX_HOUSE_AREA_M2 or extra <= 0:
        return
    keep = max(0.0, (MAX_HOUSE_AREA_M2 - (total - extra)) / extra)
    for s, g in grown:
        s.area = round(s.drawn_area + g * keep, 2)
    warnings.append(
        f"the furniture asked for needs {total:.0f} m2 of rooms; a house is at most {MAX_HOUSE_AREA_M2:.0f} m2, "
        f"planned {sum(s.area for s in slots):.0f} m2 (some objects may not fit)"
    )


def _fit_furnished(kb: KnowledgeBase, slots: list[Slot], rooms: list[tuple[list[fu.Group], list[fu.Item]]], sz: Sizing, warnings: list[str]) -> None:
    """Bring a furnished plan back into the total it must reach (a size word, a stated
    area): rooms the furniture grew past the total lose the groups the text did not ask
    for (most grown room first, least important group first); the rest are scaled."""
    hi = sz.band[1] if sz.band is not None else MAX_HOUSE_AREA_M2
    keeps = [ESSENTIAL_PRIORITY, TIGHT_PRIORITY] if sz.source in ("word", "stated") else [ESSENTIAL_PRIORITY]
    for keep in keeps:  # a total the text sets: the lesser essentials go too ("a tiny cottage's bedroom": the bed)
        for s, (groups, _) in sorted(zip(slots, rooms), key=lambda x: x[0].drawn_area - x[0].area):
            if sum(x.area for x in slots) <= hi:
                break
            _trim(kb, s, groups, keep)
    grown = {id(s) for s in slots if s.area > s.drawn_area + 1e-6}  # the furniture's needs stay
    fit_areas(kb, slots, sz, warnings, pinned=grown)


def _trim(kb: KnowledgeBase, s: Slot, groups: list[fu.Group], keep: int = ESSENTIAL_PRIORITY) -> None:
    """Take the room's less important groups out (least important first) until it is back
    to the area it was drawn with, or only its essential groups (asked for, or of priority
    ``keep`` or a more urgent one) are left."""
    optional = sorted((g for g in groups if not _essential(g, keep)), key=lambda g: -g["priority"])
    while optional and s.area > s.drawn_area + 1e-6:
        groups.remove(optional.pop(0))
        s.area = round(max(s.drawn_area, min(_need_m2(groups, _floor_use(kb, s.type)), MAX_ROOM_AREA_M2)), 2)


def _fit_small_room(kb: KnowledgeBase, s: Slot, groups: list[fu.Group]) -> None:
    """A room the text sizes with a word ("a small office" in a clinic) holds a smaller
    room's furniture: its groups past :data:`ESSENTIAL_PRIORITY` go and the copies of each
    group the text did not ask for shrink as its floor does, by the word's factor squared
    (at least one; four desks and a meeting table were a small office's 34 m2, now two
    desks); its area is the one drawn for it (before the furniture grew it), at most the
    middle of its range times the word's factor, or what its furniture needs."""
    for g in [g for g in groups if not _essential(g)]:
        groups.remove(g)
    for g in groups:
        if not g["required"]:
            g["repeat"] = max(1, math.floor(g["repeat"] * s.size * s.size))
    need = min(_need_m2(groups, _floor_use(kb, s.type)), MAX_ROOM_AREA_M2)
    small = (s.area_range[0] + s.area_range[1]) / 2 * s.size
    s.area = round(max(min(s.drawn_area, small), need), 2)


def _essential(g: fu.Group, keep: int = ESSENTIAL_PRIORITY) -> bool:
    """A group a room keeps when its total is tight: asked for by the text, or what
    makes the room what it is (a bed, a toilet, a kitchen run: priority 0 or 1; of
    priority ``keep`` or a more urgent one)."""
    return bool(g["required"]) or int(g["priority"]) <= keep


def _floor_use(kb: KnowledgeBase, room_type: str) -> float:
    """Room area per m2 of furniture footprint for ``room_type`` (rooms.yaml ``floor_use``)."""
    types = kb.raw("rooms")["types"]
    return float(types.get(room_type, types["other"]).get("floor_use", FLOOR_USE_FACTOR))


def _need_m2(groups: list[fu.Group], factor: float = FLOOR_USE_FACTOR) -> float:
    """Floor the groups need: their footprints with walkways and clearances (``factor``
    m2 per m2 of footprint)."""
    need = 1.0
    for g in groups:
        if g.get("arrangement") == "rows":  # a grid of cells with aisles between them
            need += _rows_cell_m2(g) * g["repeat"] * ROWS_USE_FACTOR
            continue
        for it in [g["anchor"], *g["members"]]:
            if it["rule"] in fu.ORNAMENT_RULES or it["category"] == "rug":
                continue
            w, d, _ = it["size_m"]
            need += w * d * it["count"] * g["repeat"] * factor
    return need


def _grow_area(s: Slot, groups: list[fu.Group], warnings: list[str] | None = None, factor: float = FLOOR_USE_FACTOR) -> None:
    need = _need_m2(groups, factor)
    s.drawn_area = s.area
    if need > MAX_ROOM_AREA_M2 and warnings is not None:
        warnings.append(
            f"the {s.name} needs about {need:.0f} m2 for what was asked; a room is at most "
            f"{MAX_ROOM_AREA_M2:.0f} m2, planned {max(s.area, MAX_ROOM_AREA_M2):.0f} m2 (some objects may not fit)"
        )
    s.area = round(max(s.area, min(need, MAX_ROOM_AREA_M2)), 2)


def _rows_cell_m2(g: fu.Group) -> float:
    """Floor of one copy of a rows group with its share of the aisles."""
    floor = [it for it in [g["anchor"], *g["members"]] if it["rule"] not in fu.ORNAMENT_RULES]
    width = max(it["size_m"][0] for it in floor)
    depth = sum(it["size_m"][1] for it in floor)
    return (width + ROW_AISLE_M) * (depth + ROW_AISLE_M)


HEADROOM_M = 0.4
"""Free height kept over the tallest thing a room holds (a fire engine in its bay)."""

MAX_PLANNED_HEIGHT_M = 12.0
"""Highest a room is raised to fit what it holds (RoomSpec's limit)."""


def _fits_tallest(height: RoomHeight, groups: list[GroupSpec], open_air: bool) -> RoomHeight:
    """``height`` raised, where needed, to hold the room's tallest floor item with
    :data:`HEADROOM_M` over it: a garage planned 2.6 m high for a 2.6 m fire truck is 3.0 m."""
    if open_air:
        return height
    tallest = max((it.size_m[2] for g in groups for it in [g.anchor, *g.members]
                   if REGISTRY[it.rule].kind == "floor"), default=0.0)
    need = min(MAX_PLANNED_HEIGHT_M, math.ceil((tallest + HEADROOM_M) * 20) / 20)  # up to 5 cm
    return RoomHeight(need, height.ceiling) if need > height.height_m else height


def _room_spec(kb: KnowledgeBase, s: Slot, groups: list[fu.Group], ornaments: list[fu.Item], look: Look,
               rng: np.random.Generator, height: RoomHeight | None = None) -> RoomSpec:
    rt = kb.rooms.types.get(s.type, kb.rooms.types["other"])
    materials = room_materials(look, s.type, kb)
    furniture = look.furniture
    if s.mention is not None:
        for surface, words in look.room_overrides.get(s.mention, {}).items():
            if surface == "furniture":
                furniture = words
            else:
                materials[surface] = words
    used: dict[str, int] = {}
    group_specs = []
    for g in sorted(groups, key=lambda g: (not g["required"], g["priority"])):
        used[g["name"]] = used.get(g["name"], 0) + 1
        name = g["name"] if used[g["name"]] == 1 else f"{g['name']}_{used[g['name']]}"
        items = [_item(kb, it, look, furniture, rng) for it in [g["anchor"], *g["members"]]]
        group_specs.append(
            GroupSpec(
                name=name, anchor=items[0], members=items[1:], arrangement=g["arrangement"],
                repeat=g["repeat"], priority=g["priority"], required=g["required"], fill=g.get("fill", False),
            )  # fmt: skip
        )
    height = _fits_tallest(height or RoomHeight(rt.height_m), group_specs, rt.open_air or s.open_air)
    return RoomSpec(
        id=s.id,
        name=s.name,
        type=s.type,
        area_m2=round(float(np.clip(s.area, 0.6, 400.0)), 2),
        level=s.level,
        height_m=height.height_m,
        open_air=rt.open_air or s.open_air,
        ceiling=height.ceiling,
        style=look.describe,
        materials=materials,
        groups=group_specs,
        ornaments=[_item(kb, o, look, furniture, rng) for o in ornaments],
    )


def _item(kb: KnowledgeBase, it: fu.Item, look: Look, furniture: str, rng: np.random.Generator) -> ItemSpec:
    data = dict(it)
    data.pop(fu.MENTIONED, None)
    if not data.get("material"):
        data["material"] = item_material(data["category"], look, furniture, rng, kb)
    return ItemSpec.model_validate(data, context=kb_context(kb))


# ---------------------------------------------------------------- stage fallbacks
# The LLM planner asks a model for each stage and falls back to these for a stage the
# model could not plan: the look of the house, and the furniture of one room.


def offline_look(kb: KnowledgeBase, text: str, rng: np.random.Generator) -> Look:
    """The style, palette and materials the offline planner reads from ``text``."""
    parsed = parse(text, kb)
    program, implied = choose_program(kb, parsed)
    prog = kb.raw("programs")["programs"].get(program or "", {})
    return choose_look(kb, parsed, implied, parsed.building_word or prog.get("building") or "home", rng)


def furnish_key(kb: KnowledgeBase, name: str, room_type: str) -> str:
    """The furnishing set of a room known by name: the knowledge base's own entry, else
    the nearest set by meaning, else the room type's set."""
    info = kb.raw("rooms")["names"].get(name.strip().lower())
    if info:
        return str(info.get("furnish", info["type"]))
    from anyhome.plan.openvocab import map_room

    match = map_room(name, kb)
    return match.key if match is not None else room_type


def fallback_room(kb: KnowledgeBase, name: str, room_type: str, area_m2: float, room_id: str, look: Look, rng: np.random.Generator) -> RoomSpec:
    """A room of the given name, type and area, furnished and dressed offline."""
    slot = Slot(name, room_type, furnish_key(kb, name, room_type), (area_m2, area_m2), id=room_id, area=area_m2)
    groups, ornaments, _ = fu.furnish_room(kb, slot.furnish, room_type, area_m2, rng)
    return _room_spec(kb, slot, groups, fu.finalize_ornaments(groups, ornaments), look, rng)


def item_spec(kb: KnowledgeBase, data: dict[str, Any], look: Look, rng: np.random.Generator) -> ItemSpec:
    """An item with the look's material when it names none."""
    return _item(kb, data, look, look.furniture, rng)
