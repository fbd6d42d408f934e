"""The house.json contract: data model, save and load.

See docs/house_format.md for the field-by-field description. Units are meters, the
plan frame is x east, y north, z up; ``yaw`` is radians CCW about +z and at yaw 0 an
object's front faces +y. ``position`` is the centre of the object's box bottom face.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from collections.abc import Iterable, Iterator, Sequence
from functools import lru_cache
from pathlib import Path
from typing import Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, model_validator
from shapely.geometry import Polygon

from anyhome.errors import HouseFormatError
from anyhome.sanitize import clean_text, is_safe_id
from anyhome.tags import Tag, tags_for

FORMAT: Final = "anyhome.house"
VERSION: Final = 2
"""The version written; version-1 files (one storey, no level fields) are still read."""
READ_VERSIONS: Final = (1, 2)
HOUSE_FILE = "house.json"
JSON_DECIMALS = 4
"""Floats in house.json are rounded to 0.1 mm so output is byte-stable across runs."""

# ------------------------------------------------------------------ limits
# A house.json beyond these is refused at load (one line naming the field), so that no
# later stage (eval grids, meshes, renders) is asked for an absurd amount of work.
MAX_FILE_BYTES = 128 * 1024 * 1024
"""Largest house.json read (128 MiB)."""
MAX_JSON_DEPTH = 64
"""Deepest nesting of JSON arrays and objects (the format itself needs 5)."""
MAX_ROOMS = 2_000
MAX_OBJECTS = 20_000
MAX_DOORS = 10_000
MAX_WINDOWS = 10_000
MAX_CONNECTIONS = 10_000
MAX_POLYGON_POINTS = 1_000
"""Most corners of one room polygon."""
MAX_ROOM_SIDE_M = 200.0
"""Largest side of a room's bounding box."""
MAX_HOUSE_EXTENT_M = 500.0
"""Largest side of the bounding box of all rooms."""
MAX_COORD_M = 10_000.0
"""Every coordinate (polygon corners, opening ends, object positions) lies within this
distance of the origin on each axis."""
MIN_LENGTH_M = 0.001
"""Smallest object size, room, door and window height and opening width (1 mm: more
than the 0.1 mm house.json rounds to, so what loads still loads once saved)."""
MAX_HEIGHT_M = 50.0
"""Largest room height, door or window height and window sill."""
MAX_OBJECT_SIZE_M = MAX_ROOM_SIDE_M
"""Largest object extent along any axis."""
MIN_LEVEL, MAX_LEVEL = -5, 50
"""Lowest and highest storey number (0 = ground, -1 = the first basement)."""
MAX_YAW_RAD = 1_000.0
"""Largest |yaw| (any angle can be written within a few turns)."""
MAX_ASSET_KNOB = 1_000
"""Largest |value| of a numeric asset knob (part counts, ratios, lengths)."""
SUPPORTS = ("floor", "wall", "ceiling")
"""``objects[].support`` is one of these or the id of another object."""
OUTSIDE = "outside"
"""The pseudo-room on the far side of an entrance door."""
_COLOR_RE = re.compile(r"#[0-9a-fA-F]{6}")
_SURROGATE_RE = re.compile("[\ud800-\udfff]")

ROOMS_FILE: Final = Path(__file__).parent / "plan" / "knowledge" / "rooms.yaml"
"""The shipped room knowledge; its ``types:`` section is the one list of room types."""


def _room_types(path: Path) -> dict[str, bool]:
    import yaml

    data = yaml.load(path.read_text(encoding="utf-8"), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    return {str(t): bool(v.get("habitable", True)) for t, v in data["types"].items()}


ROOM_TYPES: Final[dict[str, bool]] = _room_types(ROOMS_FILE)
"""The functional room types -> habitable (a room people stay in, which gets windows),
read once from the shipped ``plan/knowledge/rooms.yaml`` (``types:``, ``habitable:``);
the knowledge base's checks keep the two one list."""


def is_habitable(room_type: str) -> bool:
    return ROOM_TYPES.get(room_type, True)


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


Point = tuple[float, float]
CeilingShape = Literal["flat", "pitched", "vaulted"]
"""A room's ceiling: flat at ``height``; pitched: two planes rising from the long walls to
a ridge along the room's long axis; vaulted: a barrel vault across the short side (see
:data:`CEILING_RISE`)."""
CEILING_RISE: Final[dict[str, float]] = {"flat": 0.0, "pitched": 0.25, "vaulted": 0.3}
"""Rise of the ridge (pitched) or crown (vaulted) above ``height``, as a share of the
room's short side (plan/knowledge/heights.yaml ``shapes`` says the same for the planner)."""
Segment = tuple[Point, Point]


class Room(_Model):
    id: str
    name: str
    type: str
    polygon: list[Point] = Field(description="CCW outline, no repeated closing point")
    height: float = 2.7
    style: str = ""
    materials: dict[str, str] = Field(default_factory=dict)
    open_air: bool = Field(default=False, description="no roof (balcony, terrace, courtyard): no ceiling, "
                           "railings on the sides it shares with no enclosed room")
    ceiling: CeilingShape = Field(default="flat", description="ceiling shape; meaningless (and kept 'flat') "
                                  "when open_air")
    level: int = Field(default=0, description="storey: 0 ground, 1 the first floor up, -1 a basement")
    merged: list[str] = Field(default_factory=list, exclude_if=lambda v: not v,
                              description="ids of the planned rooms (plan.rooms) this room also holds: an "
                              "open-plan room merged from several (anyhome.floorplan.merge); their furniture is "
                              "laid out here. Written only when not empty, so other houses read as before")


class Level(_Model):
    """One storey: its floor's height above the ground floor's and its storey height
    (floor to the next floor: the tallest room plus the slab)."""

    level: int
    elevation_m: float
    height_m: float
    stairs_at: tuple[float, float, float] | None = Field(
        default=None, exclude_if=lambda v: v is None,
        description="where the flight up from this storey stands, fixed by the floorplan stage: (x of its "
        "foot end, y of its -y side, yaw 0 or pi; anyhome.floorplan.levels.stack_box). None: no flight up, "
        "or a file written before it was recorded (the place is then found again from the stairwells)")
    stairs_kind: Literal["spiral", "ladder"] | None = Field(
        default=None, exclude_if=lambda v: v is None,
        description="the kind of the flight up from this storey: 'spiral' (a small house's spiral stair, one "
        "full turn in a square box), 'ladder' (a tiny house's ship's ladder: one steep straight flight, "
        "alternating treads, arriving at the far end of its box); anyhome.floorplan.stairs.stair_kind; "
        "None: a dog-leg")


class Door(_Model):
    id: str
    rooms: tuple[str, str] = Field(description="(room_id, room_id or 'outside')")
    segment: Segment
    height: float = 2.1
    kind: Literal["door", "open"] = "door"


class Window(_Model):
    id: str
    room: str
    segment: Segment
    height: float = 1.2
    sill: float = 0.9


class HouseObject(_Model):
    id: str
    room: str
    name: str
    category: str
    description: str = ""
    position: tuple[float, float, float]
    size: tuple[float, float, float]
    yaw: float = 0.0
    support: str = "floor"
    group: str | None = None
    anchor: str | None = None
    rule: str = "place_center"
    material: str = ""
    asset: dict[str, Any] | None = Field(
        default=None, description="how the mesh was made: family and parameters or file"
    )
    tags: list[Tag] = Field(
        default_factory=list,
        description="semantic tags (anyhome.tags.TAGS); derived from name and category when absent",
    )

    @model_validator(mode="before")
    @classmethod
    def _derive_tags(cls, data: Any) -> Any:
        """Files written before tags existed: derive them from the knowledge base."""
        if isinstance(data, dict) and data.get("tags") is None:
            name, category = data.get("name"), data.get("category")
            if isinstance(name, str) and isinstance(category, str):
                data = {**data, "tags": list(tags_for(name, category))}
        return data


class Dropped(_Model):
    room: str
    name: str
    reason: str
    key: bool = False
    """A key item: the text asked for it, or it makes the room what it is (a bed, a sofa)."""


class Floorplan(_Model):
    """The floorplan stage's output: rooms, openings and the connections they realise."""

    rooms: list[Room]
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    connections: list[tuple[str, str]] = Field(default_factory=list)
    levels: list[Level] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list, description="what the stage could not do as planned (the house's warnings)")

    def room(self, room_id: str) -> Room:
        for r in self.rooms:
            if r.id == room_id:
                return r
        raise KeyError(room_id)


class House(_Model):
    """A generated house: the content of house.json."""

    format: Literal["anyhome.house"] = FORMAT
    version: Literal[2] = VERSION
    prompt: str
    seed: int
    style: str = ""
    styles: list[str] = Field(default_factory=list, description="style keys of the knowledge base, the lead first")
    rooms: list[Room]
    connections: list[tuple[str, str]] = Field(default_factory=list)
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    objects: list[HouseObject] = Field(default_factory=list)
    levels: list[Level] = Field(
        default_factory=list, description="storeys of a house of several; empty: one storey, level 0 at 0 m")
    # --- additions beyond the required core (documented in docs/house_format.md)
    building: str = "home"
    palette: list[str] = Field(default_factory=list)
    planner: str = "offline"
    dropped: list[Dropped] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    plan: dict[str, Any] | None = Field(default=None, description="the HouseSpec it came from")
    provenance: dict[str, Any] | None = Field(default=None, description="how the plan was made (LLM stages, tokens, latency)")

    _timings_s: dict[str, float] = PrivateAttr(default_factory=dict)

    @model_validator(mode="after")
    def _check(self) -> House:
        problem = next(_problems(self), None)
        if problem is not None:
            raise ValueError(problem)
        return self

    @property
    def timings_s(self) -> dict[str, float]:
        """Seconds per stage of the run that made this house (not saved: not reproducible)."""
        return self._timings_s

    def room(self, room_id: str) -> Room:
        for r in self.rooms:
            if r.id == room_id:
                return r
        raise KeyError(room_id)

    def object(self, object_id: str) -> HouseObject:
        for o in self.objects:
            if o.id == object_id:
                return o
        raise KeyError(object_id)

    def objects_in(self, room_id: str) -> list[HouseObject]:
        return [o for o in self.objects if o.room == room_id]

    @property
    def floorplan(self) -> Floorplan:
        return Floorplan(
            rooms=self.rooms, doors=self.doors, windows=self.windows, connections=self.connections,
            levels=self.levels,
        )

    def level_numbers(self) -> list[int]:
        """The storeys that hold rooms, lowest first."""
        return sorted({r.level for r in self.rooms})

    def elevation_m(self, level: int) -> float:
        """Height of a storey's floor above the ground floor's (0 for a one-storey house)."""
        return next((lv.elevation_m for lv in self.levels if lv.level == level), 0.0)

    def room_level(self, room_id: str) -> int:
        """The storey of a room (``outside``: 0)."""
        return next((r.level for r in self.rooms if r.id == room_id), 0)

    # ------------------------------------------------------------------ json
    def to_json(self) -> str:
        data = _round_floats(self.model_dump(mode="json"), JSON_DECIMALS)
        try:
            text = json.dumps(data, indent=1, ensure_ascii=False, allow_nan=False) + "\n"
        except ValueError as e:  # a NaN put in after validation
            raise HouseFormatError(f"house cannot be saved: {e}") from None
        # surrogates cannot be written as UTF-8: a pair becomes the character it encodes, a
        # lone one (from a JSON "\\ud800" escape) the escape it came from, so the file stays
        # UTF-8 and loads back the same
        if _SURROGATE_RE.search(text):
            text = text.encode("utf-16", "surrogatepass").decode("utf-16", "surrogatepass")
            text = _SURROGATE_RE.sub(lambda m: f"\\u{ord(m.group()):04x}", text)
        return text

    @classmethod
    def from_json(cls, text: str | bytes, source: str = "house.json") -> House:
        """Parse and validate a house.json text; any problem is a one-line
        :class:`HouseFormatError` naming ``source`` and the field."""
        source = clean_text(str(source))
        if isinstance(text, (bytes, bytearray)):
            if len(text) > MAX_FILE_BYTES:
                raise HouseFormatError(f"{source}: larger than {MAX_FILE_BYTES // 2**20} MiB")
            try:
                text = bytes(text).decode("utf-8")
            except UnicodeDecodeError as e:
                raise HouseFormatError(
                    f"{source}: not UTF-8 text (byte 0x{e.object[e.start]:02x} at offset {e.start})"
                ) from None
        if len(text) > MAX_FILE_BYTES:
            raise HouseFormatError(f"{source}: larger than {MAX_FILE_BYTES // 2**20} MiB")
        try:
            data = json.loads(text, parse_constant=_refuse_constant, parse_float=_finite_float)
        except json.JSONDecodeError as e:
            raise HouseFormatError(f"{source}: not valid JSON ({e.msg}, line {e.lineno})") from None
        except _BadNumber as e:
            raise HouseFormatError(f"{source}: not valid JSON ({e})") from None
        except ValueError as e:  # an integer of thousands of digits
            raise HouseFormatError(f"{source}: not valid JSON ({clean_text(str(e))[:200]})") from None
        except RecursionError:
            raise HouseFormatError(f"{source}: JSON nested too deeply") from None
        if _depth_exceeds(data, MAX_JSON_DEPTH):
            raise HouseFormatError(f"{source}: JSON nested deeper than {MAX_JSON_DEPTH} levels")
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise HouseFormatError(f"{source}: not an AnyHome house (format must be {FORMAT!r})")
        if data.get("version") not in READ_VERSIONS or isinstance(data.get("version"), bool):
            raise HouseFormatError(
                f"{source}: house format version {_short(data.get('version'))} is not supported "
                f"(this AnyHome reads versions {', '.join(map(str, READ_VERSIONS))})"
            )
        if data["version"] == 1:  # one storey: every room on level 0, no levels list
            if "levels" in data or any(isinstance(r, dict) and "level" in r for r in data.get("rooms") or []):
                raise HouseFormatError(f"{source}: a version-1 house has no level fields")
            data = {**data, "version": VERSION}
        try:
            return cls.model_validate(data)
        except ValidationError as e:
            raise HouseFormatError(f"{source}: {_first_error(e)}") from None

    def save(self, directory: str | os.PathLike[str]) -> Path:
        """Write ``house.json`` into ``directory`` atomically; return its path."""
        d = Path(directory)
        d.mkdir(parents=True, exist_ok=True)
        path = d / HOUSE_FILE
        atomic_write_text(path, self.to_json())
        return path


def stand_ins(objects: Iterable[HouseObject]) -> list[HouseObject]:
    """The objects whose asset record says their mesh only stands in for them
    (``approximate``: no procedural family draws them as themselves yet)."""
    return [o for o in objects if (o.asset or {}).get("approximate")]


def load(path: str | os.PathLike[str]) -> House:
    """Load a house from a house.json file or a directory holding one."""
    p = Path(path)
    try:
        if p.is_dir():
            p = p / HOUSE_FILE
        if not p.is_file():
            raise HouseFormatError(f"no house found at {clean_text(str(p))}")
        with p.open("rb") as f:
            data = f.read(MAX_FILE_BYTES + 1)
    except OSError as e:
        raise HouseFormatError(f"cannot read {clean_text(str(p))}: {e.strerror or e}") from None
    return House.from_json(data, source=str(p))


def atomic_write_text(path: Path, text: str) -> None:
    atomic_write_bytes(path, text.encode("utf-8"))


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write a file so that readers see the old content or the new one, never a part."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def _round_floats(value: Any, ndigits: int) -> Any:
    if isinstance(value, float):
        r = round(value, ndigits)
        return 0.0 if r == 0 else r
    if isinstance(value, dict):
        return {k: _round_floats(v, ndigits) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_round_floats(v, ndigits) for v in value]
    return value


# ------------------------------------------------------------------ validation
class _BadNumber(ValueError):
    pass


def _refuse_constant(name: str) -> float:
    raise _BadNumber(f"{name} is not a JSON number")


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise _BadNumber(f"number {text[:40]} is out of range")
    return value


def _depth_exceeds(data: Any, limit: int) -> bool:
    stack = [(data, 1)]
    while stack:
        value, depth = stack.pop()
        if isinstance(value, (dict, list)):
            if depth > limit:
                return True
            items = value.values() if isinstance(value, dict) else value
            stack.extend((v, depth + 1) for v in items if isinstance(v, (dict, list)))
    return False


def _short(value: Any, n: int = 40) -> str:
    text = clean_text(repr(value))
    return text if len(text) <= n else text[: n - 3] + "..."


def _path(loc: tuple) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + clean_text(str(part))[:60]
    return out


def _first_error(e: ValidationError) -> str:
    """One line: the field path and what is wrong with it."""
    first = e.errors(include_url=False)[0]
    msg = clean_text(str(first.get("msg", "invalid")))
    if first.get("type") == "value_error":
        # our own checks: the message already starts with the field path
        return msg.removeprefix("Value error, ")
    where = _path(tuple(first.get("loc", ())))
    return f"{where}: {msg}" if where else msg


def _bad_number(x: Any) -> bool:
    return not isinstance(x, (int, float)) or isinstance(x, bool) or not math.isfinite(x)


def _check_coords(path: str, values) -> str | None:
    for i, x in enumerate(values):
        if _bad_number(x):
            return f"{path}[{i}]: must be a finite number"
        if abs(x) > MAX_COORD_M:
            return f"{path}[{i}]: {x:g} is farther than {MAX_COORD_M:g} m from the origin"
    return None


def _check_height(path: str, value: float, allow_zero: bool = False) -> str | None:
    if _bad_number(value):
        return f"{path}: must be a finite number"
    if allow_zero and value < 0:
        return f"{path}: must be >= 0"
    if not allow_zero and value < MIN_LENGTH_M:
        return f"{path}: must be > 0 (at least {MIN_LENGTH_M:g} m)"
    if value > MAX_HEIGHT_M:
        return f"{path}: {value:g} m is more than the maximum {MAX_HEIGHT_M:g} m"
    return None


def _check_segment(path: str, segment) -> str | None:
    for j, p in enumerate(segment):
        if err := _check_coords(f"{path}[{j}]", p):
            return err
    (x0, y0), (x1, y1) = segment
    if math.hypot(x1 - x0, y1 - y0) < MIN_LENGTH_M:
        return f"{path}: the two ends are the same point (less than {MIN_LENGTH_M:g} m apart)"
    return None


def _non_finite(value: Any, path: str) -> str | None:
    """The path of a NaN or infinite number anywhere in a JSON-like value."""
    stack = [(value, path)]
    while stack:
        v, p = stack.pop()
        if isinstance(v, float) and not math.isfinite(v):
            return p
        if isinstance(v, dict):
            stack.extend((x, f"{p}.{clean_text(str(k))[:60]}") for k, x in v.items())
        elif isinstance(v, (list, tuple)):
            stack.extend((x, f"{p}[{i}]") for i, x in enumerate(v))
    return None


def _problems(h: House) -> Iterator[str]:
    """Every reason the house is malformed, as ``field.path: problem`` (lazily)."""
    for name, items, limit in (("rooms", h.rooms, MAX_ROOMS), ("objects", h.objects, MAX_OBJECTS),
                               ("doors", h.doors, MAX_DOORS), ("windows", h.windows, MAX_WINDOWS),
                               ("connections", h.connections, MAX_CONNECTIONS)):
        if len(items) > limit:
            yield f"{name}: {len(items)} entries, more than the maximum {limit}"
    if not h.rooms:
        yield "rooms: a house needs at least one room"
    with_ids: tuple[tuple[str, Sequence[Room | HouseObject | Door | Window]], ...] = (
        ("rooms", h.rooms), ("objects", h.objects), ("doors", h.doors), ("windows", h.windows))
    for name, entries in with_ids:
        seen: set[str] = set()
        for i, item in enumerate(entries):
            if not is_safe_id(item.id):
                yield (f"{name}[{i}].id: {_short(item.id)} is not a valid id (letters, digits "
                       f"and _ . : - only, at most 128 characters)")
            if item.id in seen:
                yield f"{name}[{i}].id: duplicate id {item.id!r}"
            seen.add(item.id)
    listed: set[int] = set()
    for i, lv in enumerate(h.levels):
        if not MIN_LEVEL <= lv.level <= MAX_LEVEL:
            yield f"levels[{i}].level: must be from {MIN_LEVEL} to {MAX_LEVEL}"
        if lv.level in listed:
            yield f"levels[{i}].level: level {lv.level} is listed twice"
        listed.add(lv.level)
        if _bad_number(lv.elevation_m) or abs(lv.elevation_m) > MAX_COORD_M:
            yield f"levels[{i}].elevation_m: must be a finite number within {MAX_COORD_M:g} m"
        if err := _check_height(f"levels[{i}].height_m", lv.height_m):
            yield err
    room_ids = {r.id for r in h.rooms}
    for i, r in enumerate(h.rooms):
        for j, held in enumerate(r.merged):
            if not is_safe_id(held) or held in room_ids:
                yield (f"rooms[{i}].merged[{j}]: {_short(held)} must be a valid id (letters, digits and "
                       f"_ . : - only) and no room's own id")
        if not MIN_LEVEL <= r.level <= MAX_LEVEL:
            yield f"rooms[{i}].level: must be from {MIN_LEVEL} to {MAX_LEVEL}"
        elif r.level != 0 and r.level not in listed:
            yield f"rooms[{i}].level: level {r.level} is not in levels (its elevation)"
    rooms = {r.id for r in h.rooms}
    objects = {o.id for o in h.objects}
    x0 = y0 = math.inf
    x1 = y1 = -math.inf
    for i, r in enumerate(h.rooms):
        where = f"rooms[{i}]"
        if err := _check_height(f"{where}.height", r.height):
            yield err
        if not 3 <= len(r.polygon) <= MAX_POLYGON_POINTS:
            yield f"{where}.polygon: needs 3 to {MAX_POLYGON_POINTS} points, has {len(r.polygon)}"
            continue
        errs = [e for j, p in enumerate(r.polygon) if (e := _check_coords(f"{where}.polygon[{j}]", p))]
        if errs:
            yield errs[0]
            continue
        xs = [p[0] for p in r.polygon]
        ys = [p[1] for p in r.polygon]
        side = max(max(xs) - min(xs), max(ys) - min(ys))
        if side > MAX_ROOM_SIDE_M:
            yield (f"{where}.polygon: the room is {side:g} m across, more than the maximum "
                   f"{MAX_ROOM_SIDE_M:g} m")
        # checked as given and as saved (rounded), so a house that loads loads once saved
        for poly in (Polygon(r.polygon), Polygon(_round_floats(r.polygon, JSON_DECIMALS))):
            if not poly.is_valid:
                yield f"{where}.polygon: not a simple polygon (its edges cross or touch)"
            if poly.area < MIN_LENGTH_M**2:
                yield f"{where}.polygon: has no area"
        x0, y0 = min(x0, min(xs)), min(y0, min(ys))
        x1, y1 = max(x1, max(xs)), max(y1, max(ys))
    if h.rooms and max(x1 - x0, y1 - y0) > MAX_HOUSE_EXTENT_M:
        yield (f"rooms: the house is {max(x1 - x0, y1 - y0):g} m across, more than the maximum "
               f"{MAX_HOUSE_EXTENT_M:g} m")
    sides = rooms | {OUTSIDE}
    for i, pair in enumerate(h.connections):
        for j, rid in enumerate(pair):
            if rid not in sides:
                yield f"connections[{i}][{j}]: unknown room {_short(rid)}"
    for i, d in enumerate(h.doors):
        where = f"doors[{i}]"
        for j, rid in enumerate(d.rooms):
            if rid not in sides:
                yield f"{where}.rooms[{j}]: unknown room {_short(rid)} (a room id or 'outside')"
        if d.rooms[0] == d.rooms[1]:
            yield f"{where}.rooms: a door joins two different rooms"
        if err := _check_segment(f"{where}.segment", d.segment):
            yield err
        if err := _check_height(f"{where}.height", d.height):
            yield err
    for i, w in enumerate(h.windows):
        where = f"windows[{i}]"
        if w.room not in rooms:
            yield f"{where}.room: unknown room {_short(w.room)}"
        if err := _check_segment(f"{where}.segment", w.segment):
            yield err
        if err := _check_height(f"{where}.height", w.height):
            yield err
        if err := _check_height(f"{where}.sill", w.sill, allow_zero=True):
            yield err
    for i, o in enumerate(h.objects):
        where = f"objects[{i}]"
        if o.room not in rooms:
            yield f"{where}.room: unknown room {_short(o.room)}"
        if err := _check_coords(f"{where}.position", o.position):
            yield err
        for j, s in enumerate(o.size):
            if _bad_number(s):
                yield f"{where}.size[{j}]: must be a finite number"
            elif s < MIN_LENGTH_M:
                yield f"{where}.size[{j}]: must be > 0 (at least {MIN_LENGTH_M:g} m)"
            elif s > MAX_OBJECT_SIZE_M:
                yield f"{where}.size[{j}]: {s:g} m is more than the maximum {MAX_OBJECT_SIZE_M:g} m"
        if _bad_number(o.yaw) or abs(o.yaw) > MAX_YAW_RAD:
            yield f"{where}.yaw: must be a finite angle in radians (|yaw| <= {MAX_YAW_RAD:g})"
        if o.support not in SUPPORTS and o.support not in objects:
            yield f"{where}.support: {_short(o.support)} is not floor, wall, ceiling or an object id"
        elif o.support == o.id:
            yield f"{where}.support: an object cannot stand on itself"
        if o.anchor is not None and o.anchor not in objects:
            yield f"{where}.anchor: unknown object {_short(o.anchor)}"
        if o.asset is not None and (err := _check_asset(f"{where}.asset", o.asset)):
            yield err
    for name in ("plan", "provenance"):
        if (bad := _non_finite(getattr(h, name), name)) is not None:
            yield f"{bad}: must be a finite number"


KNOB_SAMPLE_SCALES = (0.25, 0.5, 1.0, 2.0, 4.0)
"""Sizes, times the family's typical size, at which :func:`_knob_schema` samples."""
KNOB_SAMPLE_SEEDS = 16
"""Seeds per size at which :func:`_knob_schema` samples (cycling through the style classes)."""


@lru_cache(maxsize=None)
def _knob_schema(family: str) -> dict[str, tuple[type, float, float]] | None:
    """The knobs a procedural family's records carry: name -> (type, lowest, highest
    allowed). Learnt from the family's own sampler (:data:`KNOB_SAMPLE_SEEDS` seeds for
    each of :data:`KNOB_SAMPLE_SCALES` times its typical size, in every asset style class):
    a count it can make 0 or 1 may go down to that; a count it always makes >= 2 must be at
    least half its smallest; a number it draws down to near zero (its smallest under a
    tenth of its largest) may be 0; another positive number must be at least a quarter
    of its smallest; a number it never makes negative >= 0; and no number may exceed four
    times the largest it makes (at least 16 for counts, 4 for other numbers). None: no
    such family."""
    import numpy as np

    from anyhome.assets.registry import _loaded, typical_size
    from anyhome.assets.styles import asset_classes

    fam = _loaded().get(family)
    if fam is None:
        return None
    seen: dict[str, list] = {}
    base = np.asarray(typical_size(family), dtype=float)
    styles = ["", *sorted(asset_classes())]
    for scale in KNOB_SAMPLE_SCALES:
        for seed in range(KNOB_SAMPLE_SEEDS):
            style = styles[seed % len(styles)]
            params = fam.sample(np.random.default_rng(seed), tuple(base * scale), style)
            for k, v in params.knobs:
                seen.setdefault(k, []).append(v)
    schema = {}
    for k, values in seen.items():
        kind = type(values[0])
        if kind in (int, float):
            lo_seen, hi_seen = min(values), max(abs(v) for v in values)
            lo = 0 if lo_seen >= 0 else -math.inf
            if kind is int and lo_seen >= 2:
                lo = max(1, math.ceil(lo_seen / 2))
            elif kind is int and lo_seen == 1:
                lo = 1
            elif kind is float and lo_seen > 0 and lo_seen >= 0.1 * hi_seen:
                lo = max(lo_seen / 4, 10.0**-JSON_DECIMALS)  # stays > 0 once rounded
            hi = min(MAX_ASSET_KNOB, max(4 * hi_seen, 16 if kind is int else 4))
            schema[k] = (kind, max(lo, -hi), hi)
        else:
            schema[k] = (kind, -math.inf, math.inf)
    return schema


_SHA256_RE = re.compile(r"[0-9a-f]{64}")


def _check_library_asset(path: str, asset: dict[str, Any]) -> str | None:
    """A library record (:mod:`anyhome.assets.library`) names its file (a string path
    and library folder), the file's sha256, its up axis, front axis and unit; its
    ``fallback``, if any, is a procedural record checked as one."""
    from anyhome.assets.library import AXES, DEFAULT_FRONT, UNIT_SCALES_M

    for key in ("library", "path", "name"):
        if not isinstance(asset.get(key), str) or (key == "path" and not asset[key]):
            return f"{path}.{key}: must be a string"
    if not isinstance(asset.get("sha256"), str) or not _SHA256_RE.fullmatch(asset["sha256"]):
        return f"{path}.sha256: must be 64 lowercase hex digits"
    if asset.get("up") not in DEFAULT_FRONT:
        return f"{path}.up: must be one of {', '.join(DEFAULT_FRONT)}"
    front = asset.get("front", DEFAULT_FRONT[asset["up"]])
    if front not in AXES or front[1] == asset["up"]:
        return f"{path}.front: must be an axis across the up axis, like +z or -y"
    if asset.get("unit") not in UNIT_SCALES_M:
        return f"{path}.unit: must be one of {', '.join(UNIT_SCALES_M)}"
    fallback = asset.get("fallback")
    if fallback is None:
        return None
    if not isinstance(fallback, dict) or fallback.get("source") != "procedural":
        return f"{path}.fallback: must be a procedural asset record"
    return _check_asset(f"{path}.fallback", fallback)


def _check_asset(path: str, asset: dict[str, Any]) -> str | None:
    """A procedural asset record must rebuild: the family's knobs, of their types, in
    range; a library record must name its file, hash and orientation
    (:func:`_check_library_asset`). Records of another source or an unknown family are ignored by the mesh
    builder (it samples an asset from the object id), so only their numbers are checked."""
    if (bad := _non_finite(asset, path)) is not None:
        return f"{bad}: must be a finite number"
    for key in ("source", "family"):
        if key in asset and not isinstance(asset[key], str):
            return f"{path}.{key}: must be a string"
    if asset.get("source") == "library":
        return _check_library_asset(path, asset)
    family = asset.get("family")
    if asset.get("source") != "procedural" or not isinstance(family, str):
        return None
    schema = _knob_schema(family)
    if schema is None:
        return None
    params = asset.get("params")
    if not isinstance(params, dict):
        return f"{path}.params: must be an object"
    size = params.get("size")
    if (not isinstance(size, list) or len(size) != 3
            or any(_bad_number(x) or not MIN_LENGTH_M <= x <= MAX_OBJECT_SIZE_M for x in size)):
        return (f"{path}.params.size: must be 3 numbers from {MIN_LENGTH_M:g} to "
                f"{MAX_OBJECT_SIZE_M:g}")
    for key in ("primary", "secondary", "accent"):
        if key in params and not (isinstance(params[key], str) and _COLOR_RE.fullmatch(params[key])):
            return f"{path}.params.{key}: must be a colour like '#a0714a'"
    if "style" in params and not isinstance(params["style"], str):
        return f"{path}.params.style: must be a string"
    seed = params.get("seed", 0)
    if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed < 2**63:
        return f"{path}.params.seed: must be an integer in [0, 2**63)"
    knobs = params.get("knobs", {})
    if not isinstance(knobs, dict) or set(knobs) != set(schema):
        return f"{path}.params.knobs: must hold exactly the knobs of family {family!r}"
    for key, (want, lo, hi) in schema.items():
        v = knobs[key]
        where = f"{path}.params.knobs.{clean_text(key)}"
        ok = (isinstance(v, bool) if want is bool else
              isinstance(v, want) and not isinstance(v, bool) if want is int else
              isinstance(v, (int, float)) and not isinstance(v, bool) if want is float else
              isinstance(v, want))
        if not ok:
            return f"{where}: must be of type {want.__name__}"
        if want in (int, float) and not lo <= v <= hi:
            return f"{where}: {v!r} is out of the family's range [{lo:g}, {hi:g}]"
    return None
