"""Plan metrics (issue 13): how a floorplan compares with how buildings are laid out.

Figures, not violations: :func:`plan_metrics` reads only what house.json holds (rooms,
their types, polygons and levels, doors, objects of category ``stairs``, the prompt) and
the knowledge base's room norms (``rooms.yaml``: ``min_width_m``, ``circulation``,
``habitable``). It never raises on a house that loads: rooms with unusable polygons are
left out of the geometric figures, fields newer than the house (``level``,
``open_air``, ``ceiling``) are read when present and defaulted when not.

Definitions
-----------
circulation share
    Area of the rooms whose type has ``circulation: true`` (entry, hallway) over the area
    of all rooms.
min width
    Twice the radius of the room's maximum inscribed circle (the widest disc that fits).
aspect
    Long side of the room's minimum rotated rectangle over its min width (>= 1).
    An L of arms ``w`` wide gets more than ``w``: the disc at its elbow is
    ``2 w sqrt(2) / (1 + sqrt(2))`` (1.17 w) across.
length of a corridor
    A circulation room that fills its minimum rotated rectangle (a rectangle): the long
    side of that rectangle. Any other shape: the long side of the rectangle of the same
    area and perimeter (``P/4 + sqrt(P^2/16 - A)``), which for an L, T or U of one width
    is the length of its centre line (the medial path: (a - w/2) + (b - w/2) for an L of
    arms a and b); a shape too compact for such a rectangle: the long side of its
    minimum rotated rectangle.
size words, stated total
    Read from the prompt by :func:`read_size` (this evaluator's own reading, independent
    of the planner's): square feet are converted to m2; an area "per floor" / "on each
    floor" is multiplied by the house's levels; an area of the land ("a 500 m2 plot") is
    no total.
open air
    A room whose ``open_air`` flag is set, whose type is an open-air type
    (:data:`OPEN_AIR_TYPES`) or whose name says so (:data:`OPEN_AIR_NAME`). It "has a
    ceiling" when its ``open_air`` flag is not set (the format builds every other room
    with a ceiling, whatever shape its ``ceiling`` field gives; a house from before the
    flag existed: always).
levels, reachability
    Distinct ``room.level`` (1 for a house without levels). Every room must be reachable
    from a room with a door to the outside through doors, and between levels through
    objects of category ``stairs``: a stair in room R joins R to the rooms one level up
    or down whose polygon contains the stair's position (a stairwell of the same
    footprint on each level).
overhang
    Area of the rooms of each storey above the ground floor that lies over no room of
    the storey below (:func:`overhang_m2`).
signature
    The sorted (short side, long side) of every room's minimum rotated rectangle, in
    metres to the centimetre; :func:`signature_overlap` says how much two signatures
    coincide (two rooms coincide when each side is within 0.5 m of the other's).
footprint shape, courtyards
    See :mod:`anyhome.evaluate.footprint`: the ground level's building outline as
    rectangle, L, T, U, step, courtyard or other; for each courtyard, the share of its
    perimeter on its level's outline (below ``footprint.INSIDE_MAX_SHARE``: inside the
    footprint, rooms on at least three sides).
oversized
    A room drawn at more than :data:`OVERSIZE_FACTOR` times the area its plan (house.json
    ``plan``, with the rooms merged into it) asked for.
L rooms
    Rooms whose outline has more than 4 corners (:func:`corner_count`): the open-plan
    L rooms of :mod:`anyhome.floorplan.merge`. Their aspect is defined as above (the
    bounding rectangle's long side over the elbow disc), stricter than either arm's.
home
    See :func:`is_home`: ``house.building`` is a dwelling (:data:`HOME_BUILDINGS`), or a
    building word of programs.yaml whose program is one, or (a word the knowledge does
    not know, which the planner keeps as the building) the house has a bedroom or a
    living room.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon

from anyhome.evaluate import footprint
from anyhome.evaluate.polygons import is_usable, room_polygon
from anyhome.floorplan.levels import overhang_m2, reachable_rooms
from anyhome.house import House, is_habitable
from anyhome.plan.kb import KnowledgeBase

HOME_BUILDINGS = ("home", "apartment", "castle")
"""Buildings people live in: the ``building`` of the programs ``home``, ``apartment``,
``studio_apartment`` and ``castle`` (see :func:`is_home`)."""
OPEN_AIR_TYPES = ("balcony", "terrace", "deck", "patio", "porch", "courtyard", "garden", "roof_terrace")
"""Room types that are open to the sky (issue 13's list; today's knowledge files map all
of them to ``balcony``)."""
OPEN_AIR_NAME = re.compile(
    r"\b(balcony|terrace|deck|patio|porch|courtyard|veranda|verandah|loggia|garden|atrium)\b"
    r"(?!\s+(room|shed|house|studio|office|centre|center))",
    re.IGNORECASE,
)
"""A room name that says it is open air ("roof terrace", "courtyard"; not "garden room")."""
INDOOR_NAME = re.compile(r"\b(winter garden|screened porch|enclosed porch)\b", re.IGNORECASE)
"""Names that match :data:`OPEN_AIR_NAME` but are enclosed rooms."""

NARROW_BEDROOM_M = 2.4
"""The issue's bar: no bedroom narrower than this."""
NARROW_LIVING_M = 3.0
"""The issue's bar: no living room narrower than this."""
LONG_ASPECT = 2.0
"""A habitable room with aspect above this is a strip."""
WIDTH_TOL_M = 0.005
"""A width this much under a norm still meets it (the inscribed circle is found to
:data:`MIC_TOL_M`)."""
MIC_TOL_M = 0.001
"""Tolerance of the maximum-inscribed-circle search."""
RECTANGLE_FILL = 0.98
"""A polygon filling this share of its minimum rotated rectangle counts as a rectangle."""
SIGNATURE_DECIMALS = 2
"""Room sides of a signature are kept to this many decimals (centimetres)."""
SIGNATURE_TOL_M = 0.5
"""Two rooms of two signatures coincide when each side is within this of the other's.
(Until 2026-11-24 sides were first rounded to 0.5 m, which let sides up to about 1 m
apart coincide: twice the tolerance stated.)"""
REUSE_SHARE = 0.7
"""Two plans "share most of their room sizes" when this share of EACH plan's rooms has a
coinciding room in the other."""

TINY_MAX_M2 = 45.0
"""A "tiny" home has at most this total area."""
MANSION_MIN_M2 = 300.0
"""A "mansion" / "grand" home has at least this total area."""
STATED_TOL = 0.15
"""A stated total area is met within this fraction."""

SIZE_WORDS = {
    "tiny": "tiny", "small": "small", "cosy": "cosy", "cozy": "cosy", "spacious": "spacious",
    "large": "large", "grand": "grand", "mansion": "mansion",
}
"""Words that size the whole building -> their canonical form."""
_SIZE_RE = re.compile(r"\b(" + "|".join(SIZE_WORDS) + r")\b", re.IGNORECASE)
_HEAD_END = re.compile(r",|;|:|\.\s|\bwith\b|\bfeaturing\b|\bincluding\b|\bwhere\b|\bwhich\b",
                       re.IGNORECASE)
_UNITS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9,
    "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16,
    "seventeen": 17, "eighteen": 18, "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50,
    "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90,
}
_SCALES = {"hundred": 100, "thousand": 1000}
_NUMBER_WORD = r"(?:" + "|".join(sorted([*_UNITS, *_SCALES], key=len, reverse=True)) + r")"
_NUMBER_PHRASE = rf"(?:a\s+)?{_NUMBER_WORD}(?:(?:\s+and\s+|[\s-]+){_NUMBER_WORD})*"
"""A number in words: "thirty", "seventy-five", "one hundred and twenty", "a thousand"."""
SQ_FT_M2 = 0.09290304
"""Square metres in a square foot."""
_M2_UNIT = r"(?:m2|m\^2|m²|sqm|sq\.?\s?m(?:et(?:er|re)s?)?\.?|square[\s-]+met(?:er|re)s?|m(?:et(?:er|re)s?)?\s+squared)"
_FT2_UNIT = r"(?:sq\.?\s?ft\.?|sqft|square[\s-]+f(?:ee|oo)t|ft2|ft²|sf)"
_AREA_RE = re.compile(
    r"(?<![\w.,])(?<!\d\s)(\d{1,3}(?:,\d{3})+(?![\d,])|\d{1,5}(?:[.,]\d+)?|" + _NUMBER_PHRASE + r")\s*-?\s*"
    r"(?:(" + _M2_UNIT + r")|(" + _FT2_UNIT + r"))(?![a-z0-9²])",
    re.IGNORECASE,
)
"""A stated area: a number (digits, "1,200", words) and a unit of square metres or square
feet ("50 m2", "120 sqm", "a 140-square-metre home", "1,200 sq ft")."""


def _number(text: str) -> float:
    """The value of a number written in digits ("1,200": thousands; "12,5": a decimal
    comma) or in words ("one hundred and twenty")."""
    t = text.lower().strip()
    if t[0].isdigit():
        if re.fullmatch(r"\d{1,3}(?:,\d{3})+", t):
            return float(t.replace(",", ""))
        return float(t.replace(",", "."))
    total, part = 0, 0
    for w in re.findall(r"[a-z]+", t):
        if w in _UNITS:
            part += _UNITS[w]
        elif w == "hundred":
            part = max(part, 1) * 100
        elif w == "thousand":
            total += max(part, 1) * 1000
            part = 0
    return float(total + part)


# ---------------------------------------------------------------------- results
OVERSIZE_FACTOR = 2.0
"""A room drawn at more than this many times its planned area is oversized (the solver
stretched it to fill its footprint: a 10 m2 practice room drawn at 57 m2)."""
BLOAT_FACTOR = 2.5
"""A room drawn at more than this many times its planned area, and larger than
:data:`BLOAT_MIN_M2`, is bloated (a hub of the spine floorplan that took the slack: a
27 m2 family room drawn at 124 m2). A figure, not a validity violation."""
BLOAT_MIN_M2 = 30.0
"""Rooms no larger than this are never counted bloated (a 4 m2 bathroom drawn at 11 m2 is
still a small room)."""


@dataclass(frozen=True)
class RoomMetrics:
    """One room's shape against the norm for its type."""

    id: str
    type: str
    level: int
    area_m2: float
    min_width_m: float
    long_side_m: float
    aspect: float
    norm_min_width_m: float | None
    habitable: bool
    circulation: bool
    open_air: bool
    has_ceiling: bool
    planned_area_m2: float | None = None
    """The area the plan (house.json ``plan``) asked of the room and of the rooms merged
    into it; None when the house holds no plan for it."""

    @property
    def oversized(self) -> bool:
        """Drawn at more than :data:`OVERSIZE_FACTOR` times its planned area."""
        return self.planned_area_m2 is not None and self.area_m2 > OVERSIZE_FACTOR * self.planned_area_m2

    @property
    def area_ratio(self) -> float | None:
        """Drawn area over planned area; None when the plan does not hold the room."""
        if self.planned_area_m2 is None or self.planned_area_m2 <= 0:
            return None
        return self.area_m2 / self.planned_area_m2

    @property
    def bloated(self) -> bool:
        """Drawn at more than :data:`BLOAT_FACTOR` times its planned area and over
        :data:`BLOAT_MIN_M2`."""
        ratio = self.area_ratio
        return ratio is not None and ratio > BLOAT_FACTOR and self.area_m2 > BLOAT_MIN_M2

    @property
    def below_norm(self) -> bool:
        return self.norm_min_width_m is not None and self.min_width_m < self.norm_min_width_m - WIDTH_TOL_M


@dataclass(frozen=True)
class PlanMetrics:
    """The plan figures of one house (see the module docstring for each definition)."""

    building: str
    is_home: bool
    n_rooms: int
    total_area_m2: float
    circulation_area_m2: float
    circulation_share: float
    longest_corridor_m: float
    n_habitable: int
    n_habitable_aspect_over_2: int
    n_bedrooms: int
    n_bedrooms_narrow: int
    n_living_rooms: int
    n_living_rooms_narrow: int
    n_below_type_min_width: int
    size_words: tuple[str, ...]
    stated_area_m2: float | None
    tiny_ok: bool | None
    stated_area_ok: bool | None
    mansion_ok: bool | None
    n_open_air: int
    n_open_air_with_ceiling: int
    levels: int
    overhang_m2: float
    """Floor of storeys above the ground floor that is not over a room of the storey below."""
    all_reachable: bool
    n_unreachable: int
    signature: tuple[tuple[float, float], ...]
    rooms: tuple[RoomMetrics, ...]
    footprint: str = "other"
    """The ground level's outline shape (:data:`anyhome.evaluate.footprint.SHAPES`)."""
    courtyard_shares: tuple[float, ...] = ()
    """Per courtyard: the share of its perimeter on its level's outline."""
    n_l_rooms: int = 0
    """Rooms whose outline is not a rectangle (more than 4 corners once points on a
    straight side are dropped): the open-plan L rooms (anyhome.floorplan.merge)."""

    @property
    def n_planned(self) -> int:
        """Rooms whose planned area the house holds."""
        return sum(r.planned_area_m2 is not None for r in self.rooms)

    @property
    def n_oversized(self) -> int:
        """Rooms drawn at more than :data:`OVERSIZE_FACTOR` times their planned area."""
        return sum(r.oversized for r in self.rooms)

    @property
    def n_bloated(self) -> int:
        """Rooms drawn at more than :data:`BLOAT_FACTOR` times their planned area and over
        :data:`BLOAT_MIN_M2` (see :attr:`RoomMetrics.bloated`)."""
        return sum(r.bloated for r in self.rooms)

    @property
    def worst_area_ratio(self) -> float:
        """The largest drawn-over-planned area of a room; 0.0 when no room is planned."""
        return max((r.area_ratio for r in self.rooms if r.area_ratio is not None), default=0.0)

    @property
    def n_courtyards_inside(self) -> int:
        return sum(s < footprint.INSIDE_MAX_SHARE for s in self.courtyard_shares)

    @property
    def n_courtyards_enclosed(self) -> int:
        return sum(s < footprint.ENCLOSED_MAX_SHARE for s in self.courtyard_shares)

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["size_words"] = list(self.size_words)
        d["signature"] = [list(s) for s in self.signature]
        d["rooms"] = [{**asdict(r), "below_norm": r.below_norm, "oversized": r.oversized,
                      "bloated": r.bloated} for r in self.rooms]
        d["courtyard_shares"] = list(self.courtyard_shares)
        return d

    def summary_lines(self) -> list[str]:
        def verdict(v: bool | None) -> str:
            return "n/a" if v is None else ("ok" if v else "MISSED")

        stated = f"{self.stated_area_m2:g} m2" if self.stated_area_m2 is not None else "none"
        words = ", ".join(self.size_words) or "none"
        return [
            f"plan: {self.building} ({'home' if self.is_home else 'not a home'}), "
            f"{self.total_area_m2:.1f} m2, {self.levels} level(s)",
            f"  circulation {100 * self.circulation_share:.1f}% of floor, "
            f"longest corridor {self.longest_corridor_m:.1f} m",
            f"  habitable rooms with aspect > 2: {self.n_habitable_aspect_over_2}/{self.n_habitable}; "
            f"bedrooms < {NARROW_BEDROOM_M} m: {self.n_bedrooms_narrow}/{self.n_bedrooms}; "
            f"living rooms < {NARROW_LIVING_M} m: {self.n_living_rooms_narrow}/{self.n_living_rooms}; "
            f"rooms below their type's min width: {self.n_below_type_min_width}/{self.n_rooms}; "
            f"drawn at > {OVERSIZE_FACTOR:g}x their planned area: {self.n_oversized}/{self.n_planned} "
            f"(> {BLOAT_FACTOR:g}x and > {BLOAT_MIN_M2:g} m2: {self.n_bloated}; "
            f"worst {self.worst_area_ratio:.1f}x)",
            f"  size words: {words}; stated area: {stated}; tiny {verdict(self.tiny_ok)}, "
            f"stated {verdict(self.stated_area_ok)}, mansion/grand {verdict(self.mansion_ok)}",
            f"  open-air rooms with a ceiling: {self.n_open_air_with_ceiling}/{self.n_open_air}; "
            f"reachable through doors and stairs: "
            f"{'all' if self.all_reachable else f'{self.n_unreachable} rooms not'}; "
            f"upper floor over nothing: {self.overhang_m2:.1f} m2",
            f"  footprint {self.footprint}; courtyards inside the footprint: "
            f"{self.n_courtyards_inside}/{len(self.courtyard_shares)} "
            f"(rooms on every side: {self.n_courtyards_enclosed}); L-shaped rooms: {self.n_l_rooms}",
        ]


# ---------------------------------------------------------------------- prompt reading
def _room_phrases(kb: KnowledgeBase) -> tuple[str, ...]:
    return tuple({n.lower() for n in kb.rooms.names} | {t.replace("_", " ") for t in kb.rooms.types})


def _building_phrases(kb: KnowledgeBase) -> tuple[str, ...]:
    return tuple({w.lower() for b in kb.programs.buildings for w in b.words})


PER_STOREY = re.compile(r"\s*(?:per|a|each|on each|on every|for each|on all)\s+(?:floor|storey|story|level)\b",
                        re.IGNORECASE)
"""Words after an area that make it each storey's ("60 m2 per floor"): the stated total is
that times the house's levels."""
LAND_WORDS = frozenset({"plot", "lot", "site", "land", "grounds", "parcel", "acreage", "yard", "backyard", "field"})
"""An area right before one of these is the land's, not the building's ("a house on a
500 m2 plot")."""
_STOP_WORDS = frozenset({"with", "of", "and", "in", "for", "on", "including", "featuring", "plus", "or"})


def _longest(tail: str, phrases: Sequence[str]) -> int:
    return max((len(p) for p in phrases if tail == p or tail.startswith(p + " ")), default=0)


def _names_a_room(rest: str, kb: KnowledgeBase, in_head: bool, area: bool = False) -> bool:
    """``rest`` (the text after a size word or area) names a room in its first words, up
    to the first punctuation or linking word ("a small balcony", "a 20 m2 master
    bedroom"; not "80 square meters with a balcony"), or the land (:data:`LAND_WORDS`: "a
    500 m2 plot"). A building word there wins over a shorter room phrase ("a 27 m2 studio
    flat") and, after an ``area``, over a room phrase it follows ("a 90 m2 two bedroom
    flat"; in "a large two bedroom flat" the size word stays the bedroom's); a word that
    is both ("office") is the building in the head of the prompt and a room after it."""
    rest = re.split(r"[,.;:!?()]", rest.lower(), maxsplit=1)[0]
    words: list[str] = []
    for w in re.findall(r"[a-z'\-]+", rest):
        if w in _STOP_WORDS or len(words) == 4:
            break
        words.append(w)
    rooms, buildings = _room_phrases(kb), _building_phrases(kb)
    if words and words[0] in LAND_WORDS:  # "a 500 m2 plot": the land, not a floor
        return True
    for start in range(min(3, len(words))):
        tail = " ".join(words[start:])
        r, b = _longest(tail, rooms), _longest(tail, buildings)
        if area and r > b and _longest(tail[r:].strip(), buildings):  # "a 90 m2 two bedroom flat": the flat's
            return False
        if r or b:
            return r > b or (r == b and not in_head)
    return False


def read_size(text: str, kb: KnowledgeBase, levels: int = 1) -> tuple[tuple[str, ...], float | None]:
    """The size words and the stated total area (m2) of a prompt.

    A size word counts when it stands in the head of the prompt (before the first
    comma, "with", "featuring"...) and is not followed by a room ("a small balcony"
    sizes the balcony). An area ("50 m2", "about 80 square meters", "120 sqm", "thirty
    square metres", "one hundred and twenty square metres", "1,200 sq ft" in m2) counts
    anywhere unless a room or the land follows it ("a 20 m2 living room", "a 500 m2
    plot"); the first that counts is the stated total, times ``levels`` when it is each
    storey's ("60 m2 per floor").
    """
    end = _HEAD_END.search(text)
    head_end = end.start() if end else len(text)
    words: list[str] = []
    for m in _SIZE_RE.finditer(text[:head_end]):
        w = SIZE_WORDS[m.group(1).lower()]
        if w != "mansion" and _names_a_room(text[m.end():head_end], kb, True):
            continue
        if w not in words:
            words.append(w)
    area: float | None = None
    for m in _AREA_RE.finditer(text):
        if _names_a_room(text[m.end():], kb, m.start() < head_end, area=True):
            continue
        area = _number(m.group(1)) * (SQ_FT_M2 if m.group(3) else 1.0)
        if PER_STOREY.match(text, m.end()):  # "60 m2 per floor": each of the house's levels
            area *= max(1, levels)
        break
    return tuple(words), area


# ---------------------------------------------------------------------- geometry
def min_width_m(poly: Polygon) -> float:
    """Twice the radius of the polygon's maximum inscribed circle."""
    line = shapely.maximum_inscribed_circle(poly, MIC_TOL_M)
    return 2.0 * float(line.length)


def rect_sides_m(poly: Polygon) -> tuple[float, float]:
    """(short, long) sides of the polygon's minimum rotated rectangle."""
    rect = shapely.minimum_rotated_rectangle(poly)
    if not isinstance(rect, Polygon):  # degenerate: a line or a point
        return 0.0, float(rect.length)
    xs = list(rect.exterior.coords)
    a = math.dist(xs[0], xs[1])
    b = math.dist(xs[1], xs[2])
    return (a, b) if a <= b else (b, a)


def corridor_length_m(poly: Polygon) -> float:
    """Length of a corridor room along it (see the module docstring)."""
    short, long = rect_sides_m(poly)
    if short * long > 0 and poly.area >= RECTANGLE_FILL * short * long:
        return long
    quarter = poly.length / 4.0
    disc = quarter * quarter - poly.area
    return quarter + math.sqrt(disc) if disc >= 0 else long


def signature_overlap(a: Sequence[Sequence[float]], b: Sequence[Sequence[float]],
                      tol_m: float = SIGNATURE_TOL_M, of: str = "larger") -> float:
    """Share of the rooms of the ``of`` ("larger" or "smaller") of two signatures that
    have a partner in the other (short and long side each within ``tol_m``), each room
    matched at most once (a maximum bipartite matching); 0.0 when either is empty.

    "larger" is the share of both plans' rooms that coincide (the matching pairs rooms,
    so it is the least of the two plans' shares); "smaller" lets a one-room studio
    "share most of its rooms" with any house holding a room of its size."""
    small, big = (a, b) if len(a) <= len(b) else (b, a)
    if not small:
        return 0.0
    adj = [[j for j, q in enumerate(big)
            if abs(p[0] - q[0]) <= tol_m + 1e-9 and abs(p[1] - q[1]) <= tol_m + 1e-9]
           for p in small]
    match: dict[int, int] = {}

    def augment(i: int, seen: set[int]) -> bool:
        for j in adj[i]:
            if j not in seen:
                seen.add(j)
                if j not in match or augment(match[j], seen):
                    match[j] = i
                    return True
        return False

    n = sum(augment(i, set()) for i in range(len(small)))
    return n / (len(big) if of == "larger" else len(small))


# ---------------------------------------------------------------------- metrics
def _is_open_air(room: Any, kb: KnowledgeBase) -> bool:
    if getattr(room, "open_air", None) is True:
        return True
    rt = kb.rooms.types.get(room.type)
    if room.type in OPEN_AIR_TYPES or (rt is not None and getattr(rt, "open_air", False) is True):
        return True
    return bool(OPEN_AIR_NAME.search(room.name)) and not INDOOR_NAME.search(room.name)


def _has_ceiling(room: Any) -> bool:
    """The house format: a room is built with a ceiling unless ``open_air`` (``ceiling``
    is its shape, flat, pitched or vaulted; an open-air room has none whatever it says).
    A house from before ``open_air`` existed has a ceiling in every room."""
    return getattr(room, "open_air", False) is not True


def _level(room: Any) -> int:
    lv = getattr(room, "level", 0)
    return int(lv) if isinstance(lv, (int, float)) and not isinstance(lv, bool) else 0


def is_home(house: House, kb: KnowledgeBase) -> bool:
    """Is ``house`` a dwelling (see the module docstring)?"""
    building = str(house.building).strip().lower()
    if building in HOME_BUILDINGS:
        return True
    programs = kb.programs.programs
    if any(p.building == building for p in programs.values()):
        return False
    for b in kb.programs.buildings:
        if building in (w.lower() for w in b.words):
            prog = programs.get(b.program)
            return prog is not None and prog.building in HOME_BUILDINGS
    return any(r.type in ("bedroom", "living_room") for r in house.rooms)


MAX_EXTENT_M = 100_000.0
"""Polygons reaching further are left out of the figures (the validity checks report
them): the inscribed-circle search's work grows with size over its tolerance."""


def _polygon(points: Sequence[Sequence[float]]) -> Polygon | None:
    """The room's polygon; None where its numbers make none (NaN, inf: the validity
    checks report those)."""
    if not all(math.isfinite(float(v)) for pt in points for v in pt):
        return None
    try:
        return room_polygon(points)
    except (ValueError, shapely.errors.GEOSException):
        return None


def _plausible(poly: Polygon) -> bool:
    return bool(np.isfinite(poly.area)) and max(abs(v) for v in poly.bounds) <= MAX_EXTENT_M


def _planned_areas(house: House) -> dict[str, float]:
    """Room id -> area_m2 of the plan house.json holds ({} when none, or unreadable)."""
    out: dict[str, float] = {}
    rooms = (house.plan or {}).get("rooms") if isinstance(house.plan, dict) else None
    for r in rooms if isinstance(rooms, list) else []:
        if isinstance(r, dict) and isinstance(r.get("id"), str):
            a = r.get("area_m2")
            if isinstance(a, (int, float)) and not isinstance(a, bool) and math.isfinite(a) and a > 0:
                out[r["id"]] = float(a)
    return out


def _planned_area(room: Any, planned: dict[str, float]) -> float | None:
    """The planned area of ``room`` and the rooms merged into it; None if any is unknown."""
    ids = list(dict.fromkeys([room.id, *getattr(room, "merged", [])]))
    if not all(i in planned for i in ids):
        return None
    return sum(planned[i] for i in ids)


def plan_metrics(house: House, kb: KnowledgeBase) -> PlanMetrics:
    """The plan figures of ``house`` (see the module docstring)."""
    types = kb.rooms.types
    polys = {r.id: _polygon(r.polygon) for r in house.rooms}
    usable = {rid: p for rid, p in polys.items() if p is not None and is_usable(p) and _plausible(p)}
    rooms: list[RoomMetrics] = []
    signature: list[tuple[float, float]] = []
    longest = 0.0
    planned = _planned_areas(house)
    for r in house.rooms:
        rt = types.get(r.type)
        poly = usable.get(r.id)
        if poly is None:
            continue
        width = min_width_m(poly)
        short, long = rect_sides_m(poly)
        circ = bool(rt is not None and rt.circulation)
        if circ:
            longest = max(longest, corridor_length_m(poly))
        rooms.append(RoomMetrics(
            id=r.id, type=r.type, level=_level(r), area_m2=poly.area, min_width_m=width,
            long_side_m=long, aspect=long / max(width, 1e-6),
            norm_min_width_m=rt.min_width_m if rt is not None else None,
            habitable=is_habitable(r.type), circulation=circ,
            open_air=_is_open_air(r, kb), has_ceiling=_has_ceiling(r),
            planned_area_m2=_planned_area(r, planned),
        ))
        signature.append((round(short, SIGNATURE_DECIMALS), round(long, SIGNATURE_DECIMALS)))
    total = sum(m.area_m2 for m in rooms)
    circ_area = sum(m.area_m2 for m in rooms if m.circulation)
    habitable = [m for m in rooms if m.habitable]
    bedrooms = [m for m in rooms if m.type == "bedroom"]
    living = [m for m in rooms if m.type == "living_room"]
    building = str(house.building)
    home = is_home(house, kb)
    words, stated = read_size(house.prompt, kb, levels=len({_level(r) for r in house.rooms}) or 1)
    tiny_ok = total <= TINY_MAX_M2 if home and "tiny" in words else None
    mansion_ok = total >= MANSION_MIN_M2 if home and ("mansion" in words or "grand" in words) else None
    stated_ok = abs(total - stated) <= STATED_TOL * stated if stated else None
    open_air = [m for m in rooms if m.open_air]
    shares = _courtyard_shares(house, usable, kb)
    reached = reachable_rooms(house)  # through doors and stairs, as the validity check reads them
    return PlanMetrics(
        building=building, is_home=home, n_rooms=len(house.rooms), total_area_m2=total,
        circulation_area_m2=circ_area, circulation_share=circ_area / total if total > 0 else 0.0,
        longest_corridor_m=longest,
        n_habitable=len(habitable),
        n_habitable_aspect_over_2=sum(m.aspect > LONG_ASPECT for m in habitable),
        n_bedrooms=len(bedrooms),
        n_bedrooms_narrow=sum(m.min_width_m < NARROW_BEDROOM_M - WIDTH_TOL_M for m in bedrooms),
        n_living_rooms=len(living),
        n_living_rooms_narrow=sum(m.min_width_m < NARROW_LIVING_M - WIDTH_TOL_M for m in living),
        n_below_type_min_width=sum(m.below_norm for m in rooms),
        size_words=words, stated_area_m2=stated,
        tiny_ok=tiny_ok, stated_area_ok=stated_ok, mansion_ok=mansion_ok,
        n_open_air=len(open_air), n_open_air_with_ceiling=sum(m.has_ceiling for m in open_air),
        levels=len({_level(r) for r in house.rooms}) or 1,
        overhang_m2=overhang_m2([r for r in house.rooms if r.id in usable]),
        all_reachable=len(reached) == len(house.rooms) and bool(house.rooms),
        n_unreachable=len(house.rooms) - len(reached),
        signature=tuple(sorted(signature)),
        rooms=tuple(rooms),
        footprint=footprint.footprint_shape(
            (usable[r.id] for r in house.rooms if _level(r) == 0 and r.id in usable and not _is_open_air(r, kb)),
            inner_court=any(s < footprint.INSIDE_MAX_SHARE for s in shares.get(0, ()))),
        courtyard_shares=tuple(s for level in sorted(shares) for s in shares[level]),
        n_l_rooms=sum(corner_count(p) > 4 for p in usable.values()),
    )


def corner_count(poly: Polygon) -> int:
    """Corners of a polygon's outline, points on a straight side not counted."""
    pts = list(poly.exterior.coords)[:-1]
    n = len(pts)
    return sum(abs((pts[i][0] - pts[i - 1][0]) * (pts[(i + 1) % n][1] - pts[i][1])
                   - (pts[i][1] - pts[i - 1][1]) * (pts[(i + 1) % n][0] - pts[i][0])) > 1e-9 for i in range(n))


def _courtyard_shares(house: House, usable: dict[str, Polygon], kb: KnowledgeBase) -> dict[int, list[float]]:
    """Level -> boundary share of each of its courtyards (open air, of an ``enclosed``
    type or of type courtyard), against the outline of that level."""
    types = kb.rooms.types
    out: dict[int, list[float]] = {}
    for level in sorted({_level(r) for r in house.rooms}):
        rooms = {r.id: usable[r.id] for r in house.rooms if _level(r) == level and r.id in usable}
        courts = [r.id for r in house.rooms if r.id in rooms and _is_open_air(r, kb) and (
            r.type == "courtyard" or getattr(types.get(r.type), "enclosed", False))]
        if courts:
            out[level] = list(footprint.courtyard_shares(rooms, courts).values())
    return out


def signatures_share_most(a: Iterable[Sequence[float]], b: Iterable[Sequence[float]],
                          share: float = REUSE_SHARE, of: str = "larger") -> bool:
    """Two signatures "mostly coincide": at least ``share`` of the rooms of each (of the
    smaller one with ``of="smaller"``) have a coinciding room in the other."""
    return signature_overlap(list(a), list(b), of=of) >= share
