"""Dog-leg stairs: how many risers a storey's rise takes and the box its two flights fill.

A dog-leg (half-turn) stair climbs one flight to a half landing at the far end of its
box, turns back and climbs the second flight beside the first, so it ends at the same
end of the box as it started: stacked storey over storey, every flight's foot and top
open onto the same strip of floor in front of the box (:data:`STRIP_M`), and the flight
above runs a full storey over the one below (headroom).

Box frame (the ``stairs`` object's own, before its yaw): ``length`` along x, ``width``
along y. The first flight runs on the -y half from its foot at +x toward -x, the half
landing fills the -x end, the second flight runs on the +y half back toward +x and its
top reaches the upper floor at the +x end.

Dimensions follow UK Approved Document K (private stair): rise <= 220 mm, going >=
220 mm, pitch <= 42 deg; here risers of at most :data:`RISER_MAX_M` and goings of
:data:`GOING_M`.
"""

from __future__ import annotations

import math
import re
from contextvars import ContextVar
from dataclasses import dataclass

RISER_MAX_M = 0.19
"""Highest riser: a storey's rise is split into as many equal risers as this needs."""
GOING_M = 0.25
"""Going (tread depth, nosing to nosing) of every step."""
FLIGHT_WIDTH_M = 0.85
"""Width of one flight (Document K sets no minimum for a private stair; 0.8-0.9 m is usual)."""
WELL_GAP_M = 0.05
"""Gap between the two flights (the well: a balustrade or a thin wall)."""
STAIR_WIDTH_M = round(2 * FLIGHT_WIDTH_M + WELL_GAP_M, 4)
"""Width of a dog-leg stair's box: two flights and the well between them."""
STRIP_M = 1.0
"""Depth of the floor in front of the box where a flight starts and the one below
arrives: a flight's width at least, and room for a 0.9 m door in a long wall of the
stairwell (:data:`DOOR_CORNER_M` from the corner, :data:`STAIR_CLEAR_M` clear of the stair)."""
PASSAGE_M = 0.9
"""Width of the landing beside the stair in a stair hall (a stairwell that is also its
storey's hall): doors in the long wall across from the stair open onto it, their swing
clear of the stair."""
HALL_DOORS = 5
"""Doors a stair hall of the stair's length holds: two in the end wall at the stair's
foot, two or three in the long wall across from the stair."""
STAIR_HALL_MIN_DOORS = 4
"""Doors from which a dog-leg's or a spiral's stairwell is a stair hall, planned and laid
out with a landing beside its stair (:data:`PASSAGE_M`): up to three, the front door
among them, open onto the strip at the stair's foot (its end wall and its two sides), so
such a stairwell is planned as a plain one (measured on dev_storeys: a narrow
townhouse's three-door ground-floor stair hall came out 11-13 m2, then 6.5-10 m2, its
circulation share 0.13-0.17 -> 0.10-0.15). A ladder's narrower well: from three."""
LADDER_HALL_MIN_DOORS = 3


def stair_hall_min_doors(kind: str) -> int:
    """Doors from which the stairwell of a stair of ``kind`` is a stair hall."""
    return LADDER_HALL_MIN_DOORS if kind == LADDER else STAIR_HALL_MIN_DOORS


HALL_DOOR_M = 0.9
"""Length a stair hall gains for every door beyond :data:`HALL_DOORS`."""
STAIR_CLEAR_M = 0.03
"""Gap kept between the stair's box and a door or the floor its leaf swings over."""
DOOR_CORNER_M = 0.05
"""Wall left between a door moved to the strip and the stairwell's corner."""
HEADROOM_MIN_M = 2.0
"""Clear height over a flight's pitch line (Document K)."""
STAIR_DEPTH_M = 0.25
"""Structural depth of a flight under its pitch line (stringer and treads)."""


SPIRAL = "spiral"
"""Stair kind of a small house (:func:`stair_kind`): a spiral stair, one full turn."""
DOGLEG = "dogleg"
"""Stair kind of every other house of several storeys: the dog-leg of this module."""
SPIRAL_DIAMETER_M = STAIR_WIDTH_M
"""Diameter of a spiral stair: the dog-leg box's width, so it stands in the same
stairwells and stacks the same way (1.2-2.0 m is usual for a home's main spiral stair)."""
SPIRAL_RISER_MAX_M = 0.22
"""Highest riser of a spiral stair (BS 5395-2, a private stair: 0.17-0.22 m)."""
SPIRAL_MAX_FLOOR_M2 = 60.0
"""A house of several storeys whose rooms (its stairwells left out) plan at most this
much floor gets spiral stairs (:func:`stair_kind`): a tiny or small home, where a
dog-leg's stairwell of 6-8.5 m2 per storey would take an eighth of the floor or more."""
SPIRAL_NAME = "spiral stairs"
"""Name of a spiral ``stairs`` object (the asset factory builds it as a spiral staircase)."""


LADDER = "ladder"
"""Stair kind of a tiny house (:func:`stair_kind`): a ship's ladder (an alternating-tread
stair), one steep straight flight, as tiny houses and cabins with a sleeping loft use."""
LADDER_MAX_FLOOR_M2 = 45.0
"""A house of several storeys whose rooms (its stairwells left out) plan at most this
much floor, a tiny home's whole floor (issue 13's bar), gets a ship's ladder
(:func:`stair_kind`): even a spiral's two stairwells (about 11 m2) would not fit in it."""
LADDER_WIDTH_M = 0.6
"""Width of a ship's ladder (IBC 2018 1011.15: 20 in, 0.51 m, at least)."""
LADDER_RISER_MAX_M = 0.24
"""Highest riser of a ship's ladder (IBC 2018 1011.14-15: 9.5 in, 0.241 m)."""
LADDER_GOING_M = 0.13
"""Projected tread (going) of a ship's ladder (IBC 2018 1011.14-15: 5 in, 0.127 m, at
least): a pitch of 60-62 degrees for risers of 0.22-0.24 m."""
LADDER_TOP_M = 0.5
"""Floor at the ladder's top end inside its box, where one steps off onto the storey
above (the flight's box is its run and this)."""
LADDER_WELL_WIDTH_M = 1.2
"""Narrowest side of a ladder's stairwell: the ladder and a 0.6 m passage beside it; its
doors open onto the strip at the foot (:data:`STRIP_M`, on every storey as for the other
kinds: in its end wall or in a long wall). (Measured: a top storey's well without the strip,
1.93 x 1.45 m, came out with its doors in its end walls, in the ladder's way, and the
storeys fell back to one.)"""
LADDER_NAME = "ship's ladder"
"""Name of a ladder ``stairs`` object (the asset factory builds it as a ship's ladder)."""


def stair_kind(floor_m2: float) -> str:
    """The kind of stair of a house whose rooms, its stairwells left out, plan ``floor_m2``
    of floor in all: :data:`LADDER` for a tiny home (:data:`LADDER_MAX_FLOOR_M2`),
    :data:`SPIRAL` for a small one (:data:`SPIRAL_MAX_FLOOR_M2`), else :data:`DOGLEG`."""
    if floor_m2 <= LADDER_MAX_FLOOR_M2 + 1e-9:
        return LADDER
    return SPIRAL if floor_m2 <= SPIRAL_MAX_FLOOR_M2 + 1e-9 else DOGLEG


def stair_width_m(kind: str) -> float:
    """Width of the box of a stair of ``kind``: a ladder's, else two flights' (a spiral's
    diameter is the dog-leg's width)."""
    return LADDER_WIDTH_M if kind == LADDER else STAIR_WIDTH_M


def well_width_m(kind: str) -> float:
    """Narrowest side of a plain stairwell holding a stair of ``kind``."""
    return LADDER_WELL_WIDTH_M if kind == LADDER else STAIR_WIDTH_M


def ladder_risers(rise_m: float) -> int:
    """Risers of a ship's ladder climbing ``rise_m`` (:data:`LADDER_RISER_MAX_M`)."""
    if rise_m <= 0:
        raise ValueError(f"a stair needs a positive rise, got {rise_m}")
    return max(2, math.ceil(rise_m / LADDER_RISER_MAX_M - 1e-9))


def stair_length_m(kind: str, rise_m: float) -> float:
    """Length of the box (along its foot-to-far-end axis) of a stair of ``kind`` climbing
    ``rise_m``: a dog-leg's (:func:`dogleg`), a spiral's diameter, a ladder's run and the
    floor at its top (:data:`LADDER_TOP_M`). A dog-leg and a spiral end over their foot
    (a spiral turns once round), so the same strip of floor serves both ends; a ladder
    ends at the far end of its box, on the floor of the storey above."""
    if kind == LADDER:
        return round((ladder_risers(rise_m) - 1) * LADDER_GOING_M + LADDER_TOP_M, 4)
    return SPIRAL_DIAMETER_M if kind == SPIRAL else dogleg(rise_m).length_m


def spiral_risers(rise_m: float) -> int:
    """Risers of a spiral stair climbing ``rise_m`` (:data:`SPIRAL_RISER_MAX_M`)."""
    if rise_m <= 0:
        raise ValueError(f"a stair needs a positive rise, got {rise_m}")
    return max(2, math.ceil(rise_m / SPIRAL_RISER_MAX_M - 1e-9))


@dataclass(frozen=True)
class DogLeg:
    """One dog-leg stair of a given rise (all lengths in meters)."""

    rise_m: float
    risers: int
    """Risers in all; the first flight has the larger half."""
    going_m: float

    @property
    def riser_m(self) -> float:
        return self.rise_m / self.risers

    @property
    def first_risers(self) -> int:
        """Risers of the first flight (its last one steps onto the half landing)."""
        return (self.risers + 1) // 2

    @property
    def second_risers(self) -> int:
        return self.risers - self.first_risers

    @property
    def landing_m(self) -> float:
        """Depth of the half landing (as deep as a flight is wide)."""
        return FLIGHT_WIDTH_M

    @property
    def length_m(self) -> float:
        """Box length: the longer flight's goings plus the half landing."""
        return round((self.first_risers - 1) * self.going_m + self.landing_m, 4)

    @property
    def width_m(self) -> float:
        """Box width: two flights and the well between them."""
        return STAIR_WIDTH_M


def dogleg(rise_m: float) -> DogLeg:
    """The dog-leg stair that climbs ``rise_m`` (a storey's floor-to-floor height)."""
    if rise_m <= 0:
        raise ValueError(f"a stair needs a positive rise, got {rise_m}")
    return DogLeg(rise_m=rise_m, risers=max(2, math.ceil(rise_m / RISER_MAX_M - 1e-9)), going_m=GOING_M)


def dogleg_in_box(length_m: float, width_m: float, rise_m: float) -> DogLeg:
    """The dog-leg stair a ``length_m`` x ``width_m`` box of height ``rise_m`` holds:
    as :func:`dogleg`, its goings stretched to fill the box (never shorter)."""
    d = dogleg(rise_m)
    steps = max(1, d.first_risers - 1)
    going = max(d.going_m, (length_m - d.landing_m) / steps) if length_m > d.landing_m else d.going_m
    return DogLeg(rise_m=rise_m, risers=d.risers, going_m=going)


def is_dogleg_box(length_m: float, width_m: float) -> bool:
    """Whether a ``stairs`` box is a dog-leg (wide enough for two flights side by side)
    rather than a straight flight."""
    short, long_ = sorted((length_m, width_m))
    return short >= 2 * FLIGHT_WIDTH_M - 1e-6 and long_ <= 2.5 * short


_STAIR_WORD = re.compile(r"(?<![a-z])stair")
""""stair" starting a word ("stairwell_2", "spiral stairs"), not the end of "upstairs" or
"downstairs": a "downstairs loo" is no stairwell (measured: a semi's downstairs loo was
taken for its ground floor's stairwell and the storeys fell back to one)."""


def says_stair(text: str) -> bool:
    """Whether a room's id or name ``text`` names a stair."""
    return _STAIR_WORD.search(text.lower()) is not None


def is_stairwell(room) -> bool:
    """Whether ``room`` (anything with an ``id`` and a ``name``: a planned or laid-out
    room) is a stairwell: its id or name says stair (:func:`says_stair`)."""
    return says_stair(room.id) or says_stair(room.name)


def flight_rect(foot: float, y0: float, length: float, width: float, yaw: float):
    """The box of a flight ``length`` long whose foot end is at ``foot`` (x; its long side
    runs east-west), on the strip ``y0`` to ``y0`` + ``width``; ``yaw`` 0: foot toward +x,
    pi: toward -x."""
    from shapely.geometry import box

    return box(foot - length, y0, foot, y0 + width) if yaw == 0.0 else box(foot, y0, foot + length, y0 + width)


def doors_joined(rect: tuple[float, float, float, float], flight, doors: list) -> bool:
    """Whether one walkable piece of the stairwell ``rect`` (x0, y0, w, h) round the
    flight's box ``flight`` reaches every door of it (``doors``: their segments, shapely
    lines) and the strip at the stair's foot: a flight across the whole well would cut it
    in two."""
    pieces = walkable_pieces(rect, flight)
    return pieces_joined(pieces, [reached_pieces(pieces, d) for d in doors] if len(pieces) > 1 else [], bool(doors))


def walkable_pieces(rect: tuple[float, float, float, float], flight) -> list:
    """The walkable pieces of the stairwell ``rect`` (x0, y0, w, h) round the flight's box
    ``flight`` (:func:`doors_joined`; shapely polygons)."""
    from shapely.geometry import box

    from anyhome.geometry import AGENT_RADIUS_M

    x0, y0, w, h = rect
    free = box(x0, y0, x0 + w, y0 + h).difference(flight).buffer(-AGENT_RADIUS_M)
    return [g for g in getattr(free, "geoms", [free]) if not g.is_empty]


def reached_pieces(pieces: list, door) -> set[int]:
    """The pieces of ``pieces`` (:func:`walkable_pieces`, more than one) a door (its
    segment, a shapely line) opens onto."""
    from anyhome.geometry import AGENT_RADIUS_M

    near = AGENT_RADIUS_M + 0.1
    return {i for i, g in enumerate(pieces) if g.distance(door) <= near}


def pieces_joined(pieces: list, reached: list[set[int]], any_doors: bool) -> bool:
    """:func:`doors_joined` of the walkable ``pieces``, each door's ``reached`` pieces
    given (where more than one piece; ``any_doors``: whether the stairwell has doors)."""
    if len(pieces) <= 1:
        return bool(pieces) or not any_doors
    return bool(reached) and bool(set.intersection(*reached))


STAIR_WIDTH: ContextVar[float] = ContextVar("anyhome_stair_width", default=STAIR_WIDTH_M)
"""Width of the box of the stair of the storey being laid out (:func:`stair_width_m`),
which :func:`stair_fits` asks for: set by anyhome.floorplan.levels around a storey's
solve; a dog-leg's by default."""


def stair_fits(rect: tuple[float, float, float, float], doors: list, length_m: float) -> bool:
    """Whether a stairwell ``rect`` (x0, y0, w, h) holds a dog-leg stair box ``length_m``
    long (along its longer side) with the strip at its foot, clear of its ``doors``
    (segments ((x, y), (x, y)); each with its swing, :data:`STAIR_CLEAR_M` apart) and
    leaving them joined (:func:`doors_joined`): the one-storey form of
    :func:`anyhome.floorplan.levels.stack_box`, asked while its doors are placed."""
    return stair_fitter(rect, doors, length_m)([])


def stair_fitter(rect: tuple[float, float, float, float], doors: list, length_m: float):
    """``extra`` (more door segments) -> ``stair_fits(rect, [*doors, *extra], length_m)``,
    the same answer, with the work that does not depend on ``extra`` (the four places of
    the box, the zones of ``doors``) done once: a stairwell's door is placed by asking
    this of every opening along its walls."""
    from shapely.geometry import LineString

    from anyhome.geometry import opening_zone

    x0, y0, w, h = rect
    turned = w < h
    if turned:  # turned a quarter so the long side runs along x
        rect = (y0, x0, h, w)
        doors = [((a[1], a[0]), (b[1], b[0])) for a, b in doors]
        x0, y0, w, h = rect
    width_m = STAIR_WIDTH.get()
    if w < length_m + STRIP_M - 1e-6 or h < width_m - 1e-6:
        return lambda extra: False
    zones = [opening_zone(d).union(LineString(d)) for d in doors]
    lines = [LineString(d) for d in doors]
    places = []  # (the box, grown by the clearance) where no door of ``doors`` is in the way
    for ya in (y0, y0 + h - width_m):
        for foot, yaw in ((x0 + length_m, 0.0), (x0 + w - length_m, math.pi)):  # the box against an end wall
            box_ = flight_rect(foot, ya, length_m, width_m, yaw)
            clear = box_.buffer(STAIR_CLEAR_M)
            if not any(clear.intersects(z) for z in zones):
                places.append((box_, clear))

    joined: dict[int, tuple[list, list[set[int]]]] = {}  # place -> its walkable pieces, the pieces each of ``doors`` reaches

    def joined_with(i: int, extra_lines: list) -> bool:  # doors_joined(rect, box_, lines + extra_lines), the doors' share once
        if i not in joined:
            pieces = walkable_pieces(rect, places[i][0])
            joined[i] = pieces, [reached_pieces(pieces, d) for d in lines] if len(pieces) > 1 else []
        pieces, reached = joined[i]
        more = [reached_pieces(pieces, d) for d in extra_lines] if len(pieces) > 1 else []
        return pieces_joined(pieces, reached + more, bool(lines or extra_lines))

    def fits(extra: list) -> bool:
        if turned:
            extra = [((a[1], a[0]), (b[1], b[0])) for a, b in extra]
        more = [opening_zone(d).union(LineString(d)) for d in extra]
        extra_lines = [LineString(d) for d in extra]
        return any(not any(clear.intersects(z) for z in more) and joined_with(i, extra_lines)
                   for i, (_, clear) in enumerate(places))

    return fits
