"""What each LLM stage must reply: pydantic models and the JSON Schema sent to the server.

The schemas are strict-mode compatible (every property required, no extra properties,
no ``$ref``: definitions are inlined so every server's grammar converter reads them) and
every array is bounded (``maxItems``), so a small model cannot loop.
"""

from __future__ import annotations

import copy
from functools import lru_cache
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field

from anyhome.house import ROOM_TYPES
from anyhome.layout.rules import REGISTRY
from anyhome.plan.spec import MAX_COUNT, MAX_ROOMS, RULES
from anyhome.sanitize import clean_text

MAX_GROUPS = 5
"""Most furniture groups one room reply may hold."""
MAX_MEMBERS = 3
MAX_ORNAMENTS = 8
MAX_PALETTE = 6
MAX_CONNECTIONS = 2 * MAX_ROOMS
MAX_ITEM_COUNT = 40
NAME_CHARS = 60
WORDS_CHARS = 80

if TYPE_CHECKING:  # Literals built from the knowledge and the rule registry at run time; a checker sees str
    RoomType = str
    RuleName = str
    AnchorRule = str
    OrnamentRule = str
else:
    RoomType = Literal[tuple(ROOM_TYPES)]
    RuleName = Literal[RULES]
    # an anchor is placed by an absolute rule; an ornament on a top or a wall
    AnchorRule = Literal[tuple(n for n, r in REGISTRY.items() if not r.relative)]
    OrnamentRule = Literal[tuple(n for n, r in REGISTRY.items() if r.kind != "floor")]
ArrangementName = Literal["free", "rows", "along_walls", "center", "symmetric"]


def _clean(value: Any) -> Any:
    """A string from the model without escape sequences or control characters, trimmed:
    cleaned at the boundary, before any length check, so nothing later prints one."""
    return " ".join(clean_text(value).split()) if isinstance(value, str) else value


Clean = BeforeValidator(_clean)
Name = Annotated[str, Clean, Field(min_length=1, max_length=NAME_CHARS)]
Words = Annotated[str, Clean, Field(min_length=1, max_length=WORDS_CHARS)]
RoomId = Annotated[str, Field(pattern=r"^[a-z][a-z0-9_]{0,31}$")]
Size3 = Annotated[list[float], Field(min_length=3, max_length=3)]


class _Reply(BaseModel):
    model_config = ConfigDict(extra="forbid")


class RoomReply(_Reply):
    id: RoomId
    name: Name
    type: RoomType
    area_m2: float


class ProgramReply(_Reply):
    """Stage 1: the house program and its bubble diagram."""

    building: Name
    rooms: Annotated[list[RoomReply], Field(min_length=1, max_length=MAX_ROOMS)]
    connections: Annotated[list[Annotated[list[str], Field(min_length=2, max_length=2)]], Field(max_length=MAX_CONNECTIONS)]
    entrance: str


class ItemReply(_Reply):
    name: Name
    category: Name
    size_m: Size3
    rule: RuleName
    target: Annotated[str, Clean, Field(max_length=NAME_CHARS)]
    count: Annotated[int, Field(ge=1, le=MAX_ITEM_COUNT)]


class AnchorReply(ItemReply):
    rule: AnchorRule  # an anchor is placed by an absolute rule


class GroupReply(_Reply):
    name: Name
    anchor: AnchorReply
    members: Annotated[list[ItemReply], Field(max_length=MAX_MEMBERS)]
    arrangement: ArrangementName
    repeat: Annotated[int, Field(ge=1, le=MAX_COUNT)]


class FurnitureReply(_Reply):
    """Stage 2, per room: furniture groups (anchor, members, rules, sizes in meters)."""

    groups: Annotated[list[GroupReply], Field(min_length=1, max_length=MAX_GROUPS)]


class OrnamentReply(ItemReply):
    rule: OrnamentRule  # on top of furniture or on a wall


class OrnamentsReply(_Reply):
    """Stage 3, per room: small objects on furniture and on the walls."""

    ornaments: Annotated[list[OrnamentReply], Field(max_length=MAX_ORNAMENTS)]


class RoomLookReply(_Reply):
    id: RoomId
    floor: Words
    walls: Words
    ceiling: Words


class AppearanceReply(_Reply):
    """Stage 4: style, palette and the material words of every surface."""

    style: Words
    palette: Annotated[list[Words], Field(min_length=1, max_length=MAX_PALETTE)]
    furniture: Words
    rooms: Annotated[list[RoomLookReply], Field(max_length=MAX_ROOMS)]


STAGES: dict[str, type[_Reply]] = {
    "program": ProgramReply,
    "furniture": FurnitureReply,
    "ornaments": OrnamentsReply,
    "appearance": AppearanceReply,
}


def _inline(node: Any, defs: dict[str, Any]) -> Any:
    if isinstance(node, dict):
        if "$ref" in node:
            return _inline(copy.deepcopy(defs[node["$ref"].rsplit("/", 1)[-1]]), defs)
        return {k: _inline(v, defs) for k, v in node.items() if k not in ("title", "$defs")}
    if isinstance(node, list):
        return [_inline(v, defs) for v in node]
    return node


def _strict(node: Any) -> Any:
    """Every object closed and every property required, as strict structured output wants."""
    if isinstance(node, dict):
        node = {k: _strict(v) for k, v in node.items()}
        if node.get("type") == "object" and "properties" in node:
            node["additionalProperties"] = False
            node["required"] = list(node["properties"])
        return node
    if isinstance(node, list):
        return [_strict(v) for v in node]
    return node


def _self_contained(model: type[BaseModel]) -> dict[str, Any]:
    raw = model.model_json_schema()
    return _strict(_inline(raw, raw.get("$defs", {})))


@lru_cache(maxsize=None)
def _schema(stage: str) -> dict[str, Any]:
    return _self_contained(STAGES[stage])


@lru_cache(maxsize=None)
def _params_schema(rule: str) -> dict[str, Any]:
    return _self_contained(REGISTRY[rule].params)


def params_schema(rule: str) -> dict[str, Any]:
    """The JSON Schema of a placement rule's ``params`` (a fresh copy), derived from the
    rule's parameters model (:mod:`anyhome.layout.rules`), so what a reply may set and what
    ``ItemSpec`` accepts are one statement. Defaults are kept (``"default"``), every field
    required as strict structured output wants."""
    return copy.deepcopy(_params_schema(rule))


def json_schema(stage: str, room_ids: list[str] | None = None, targets: list[str] | None = None) -> dict[str, Any]:
    """The self-contained JSON Schema of a stage's reply (a fresh copy).

    What the request already knows narrows it, so a server that enforces schemas cannot
    produce a wrong reference: ``room_ids`` (appearance) the ids a room entry may name,
    ``targets`` (ornaments) the furniture an ornament may stand on or hang above."""
    schema = copy.deepcopy(_schema(stage))
    if stage == "appearance" and room_ids:
        schema["properties"]["rooms"]["items"]["properties"]["id"] = {"type": "string", "enum": list(room_ids)}
    if stage == "ornaments" and targets is not None:
        schema["properties"]["ornaments"]["items"]["properties"]["target"] = {"type": "string", "enum": ["", *targets]}
    return schema
