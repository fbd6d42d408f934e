"""The house.json contract: data model, save and load.

See docs/house_format.md for the field-by-field description. Units are meters, the
plan frame is x east, y north, z up; ``yaw`` is radians CCW about +z and at yaw 0 an
object's front faces +y. ``position`` is the centre of the object's box bottom face.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError

from anyhome.errors import HouseFormatError

FORMAT = "anyhome.house"
VERSION = 1
HOUSE_FILE = "house.json"
JSON_DECIMALS = 4
"""Floats in house.json are rounded to 0.1 mm so output is byte-stable across runs."""

ROOM_TYPES: dict[str, bool] = {
    # functional type -> habitable (needs a window)
    "bedroom": True,
    "bathroom": False,
    "kitchen": True,
    "living_room": True,
    "dining_room": True,
    "hallway": False,
    "entry": False,
    "office": True,
    "study": True,
    "meeting_room": True,
    "classroom": True,
    "library": True,
    "playroom": True,
    "studio": True,
    "gym": True,
    "cafe": True,
    "restaurant": True,
    "bar": True,
    "shop": True,
    "waiting_room": True,
    "reception": True,
    "treatment_room": True,
    "lab": True,
    "gallery": True,
    "hall": True,
    "sunroom": True,
    "laundry": False,
    "storage": False,
    "closet": False,
    "pantry": False,
    "utility": False,
    "cellar": False,
    "changing_room": False,
    "garage": False,
    "balcony": False,
    "other": True,
}
"""The documented functional room types. ``True`` marks a habitable room (gets windows)."""


def is_habitable(room_type: str) -> bool:
    return ROOM_TYPES.get(room_type, True)


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


Point = tuple[float, float]
Segment = tuple[Point, Point]


class Room(_Model):
    id: str
    name: str
    type: str
    polygon: list[Point] = Field(description="CCW outline, no repeated closing point")
    height: float = 2.7
    style: str = ""
    materials: dict[str, str] = Field(default_factory=dict)


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


class Dropped(_Model):
    room: str
    name: str
    reason: str


class Floorplan(_Model):
    """The floorplan stage's output: rooms, openings and the connections they realise."""

    rooms: list[Room]
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    connections: list[tuple[str, str]] = Field(default_factory=list)

    def room(self, room_id: str) -> Room:
        for r in self.rooms:
            if r.id == room_id:
                return r
        raise KeyError(room_id)


class House(_Model):
    """A generated house: the content of house.json."""

    format: Literal["anyhome.house"] = FORMAT
    version: Literal[1] = VERSION
    prompt: str
    seed: int
    style: str = ""
    rooms: list[Room]
    connections: list[tuple[str, str]] = Field(default_factory=list)
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    objects: list[HouseObject] = Field(default_factory=list)
    # --- additions beyond the required core (documented in docs/house_format.md)
    building: str = "home"
    palette: list[str] = Field(default_factory=list)
    planner: str = "offline"
    dropped: list[Dropped] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    plan: dict[str, Any] | None = Field(default=None, description="the HouseSpec it came from")
    provenance: dict[str, Any] | None = Field(default=None, description="how the plan was made (LLM stages, tokens, latency)")

    _timings_s: dict[str, float] = PrivateAttr(default_factory=dict)

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
            rooms=self.rooms, doors=self.doors, windows=self.windows, connections=self.connections
        )

    # ------------------------------------------------------------------ json
    def to_json(self) -> str:
        data = _round_floats(self.model_dump(mode="json"), JSON_DECIMALS)
        return json.dumps(data, indent=1, ensure_ascii=False) + "\n"

    @classmethod
    def from_json(cls, text: str, source: str = "house.json") -> House:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as e:
            raise HouseFormatError(f"{source}: not valid JSON ({e.msg}, line {e.lineno})") from None
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise HouseFormatError(f"{source}: not an AnyHome house (format must be {FORMAT!r})")
        if data.get("version") != VERSION:
            raise HouseFormatError(
                f"{source}: house format version {data.get('version')!r} is not supported "
                f"(this AnyHome reads version {VERSION})"
            )
        try:
            return cls.model_validate(data)
        except ValidationError as e:
            first = e.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            raise HouseFormatError(f"{source}: invalid field {where}: {first['msg']}") from None

    def save(self, directory: str | os.PathLike[str]) -> Path:
        """Write ``house.json`` into ``directory`` atomically; return its path."""
        d = Path(directory)
        d.mkdir(parents=True, exist_ok=True)
        path = d / HOUSE_FILE
        atomic_write_text(path, self.to_json())
        return path


def load(path: str | os.PathLike[str]) -> House:
    """Load a house from a house.json file or a directory holding one."""
    p = Path(path)
    if p.is_dir():
        p = p / HOUSE_FILE
    if not p.is_file():
        raise HouseFormatError(f"no house found at {p}")
    return House.from_json(p.read_text(encoding="utf-8"), source=str(p))


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
