"""What each LLM stage must reply: pydantic models and the JSON Schema sent to the server.

The schemas are strict-mode compatible (every property required, no extra properties,
no ``$ref``: definitions are inlined so every server's grammar converter reads them) and
every array is bounded (``maxItems``), so a small model cannot loop.

An item (anchor, member, ornament) is one variant per placement rule it may use: the
variant's ``rule`` is that rule's name and its ``params`` that rule's parameters model
(:mod:`anyhome.layout.rules`), so what a reply may set is derived from the models the
layout reads (a pydantic union discriminated on ``rule``; ``anyOf`` in the schema). A
reply without ``params`` (an older cache, a server that ignores schemas) validates: the
reply models default them, though the schema lists them as required.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Iterable
from functools import lru_cache
from typing import TYPE_CHECKING, Annotated, Any, Literal, Union

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, create_model

from anyhome.house import ROOM_TYPES
from anyhome.layout.rules import REGISTRY, RuleParams
from anyhome.plan.spec import MAX_COUNT, MAX_ROOMS, RULES
from anyhome.sanitize import clean_text

MAX_GROUPS = 5
"""Most furniture groups one room reply may hold."""
MAX_MEMBERS = 3
MAX_ORNAMENTS = 8
M2_PER_GROUP = 5.0
"""Floor area per furniture group a room's request allows (at least one, at most
:data:`MAX_GROUPS`): a 4 m2 washroom is asked for one group, a 12 m2 bedroom for three."""
M2_PER_ORNAMENT = 2.0
"""Floor area per ornament a room's request allows (2 to :data:`MAX_ORNAMENTS`)."""
MAX_PALETTE = 6
MAX_CONNECTIONS = 2 * MAX_ROOMS
MAX_ITEM_COUNT = 40
NAME_CHARS = 60
WORDS_CHARS = 80

ANCHOR_RULES: tuple[str, ...] = tuple(n for n, r in REGISTRY.items() if not r.relative)
"""Rules an anchor may use: the absolute ones."""
MEMBER_RULES: tuple[str, ...] = RULES
ORNAMENT_RULES: tuple[str, ...] = tuple(n for n, r in REGISTRY.items() if r.kind != "floor")
"""Rules an ornament may use: on a top or on a wall."""

if TYPE_CHECKING:  # Literals built from the knowledge and the rule registry at run time; a checker sees str
    RoomType = str
    RuleName = str
else:
    RoomType = Literal[tuple(ROOM_TYPES)]
    RuleName = Literal[RULES]
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
    """What every item variant holds; :func:`item_union` makes one variant per rule."""

    name: Name
    category: Name
    size_m: Size3
    rule: RuleName
    target: Annotated[str, Clean, Field(max_length=NAME_CHARS)]
    count: Annotated[int, Field(ge=1, le=MAX_ITEM_COUNT)]
    params: RuleParams = Field(default_factory=RuleParams)  # the rule's own model in each variant

    def given_params(self) -> dict[str, Any]:
        """The params as ``ItemSpec.params``: the values that differ from the rule's
        defaults. A strict schema makes a model write every parameter; a default written
        out means the same as one left out (so ``place_on_wall`` above a target still
        clears the target's top unless a height other than the default is asked)."""
        fields = type(self.params).model_fields
        return {k: v for k, v in self.params.model_dump().items() if v != fields[k].default}


def item_union(base: type[ItemReply], rules: Iterable[str]) -> Any:
    """``base`` as a union discriminated on ``rule``: one variant per rule, whose
    ``params`` is that rule's parameters model (defaulted: a reply may leave it out)."""
    def variant(rule: str) -> type[ItemReply]:
        name: Any = Literal[rule]  # a Literal of a run-time value; a checker cannot see it
        model = REGISTRY[rule].params
        return create_model(f"{base.__name__}_{rule}", __base__=base, __doc__=REGISTRY[rule].doc,
                            rule=(name, ...), params=(model, Field(default_factory=model)))  # fmt: skip

    variants = tuple(variant(rule) for rule in rules)
    return Annotated[Union[variants], Field(discriminator="rule")]  # noqa: UP007


if TYPE_CHECKING:  # one variant per rule at run time; a checker sees the base
    AnchorReply = ItemReply
    MemberReply = ItemReply
    OrnamentReply = ItemReply
else:
    AnchorReply = item_union(ItemReply, ANCHOR_RULES)  # an anchor is placed by an absolute rule
    MemberReply = item_union(ItemReply, MEMBER_RULES)
    OrnamentReply = item_union(ItemReply, ORNAMENT_RULES)  # on top of furniture or on a wall


class GroupReply(_Reply):
    name: Name
    anchor: AnchorReply
    members: Annotated[list[MemberReply], Field(max_length=MAX_MEMBERS)]
    arrangement: ArrangementName
    repeat: Annotated[int, Field(ge=1, le=MAX_COUNT)]


class FurnitureReply(_Reply):
    """Stage 2, per room: furniture groups (anchor, members, rules, sizes in meters)."""

    groups: Annotated[list[GroupReply], Field(min_length=1, max_length=MAX_GROUPS)]


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
    """Every object closed and every property required, as strict structured output wants;
    a union is ``anyOf`` (no ``oneOf``, no ``discriminator``) and a constant a one-value
    ``enum``, which every grammar converter and strict mode read."""
    if isinstance(node, dict):
        node = {k: _strict(v) for k, v in node.items() if k != "discriminator"}
        if "oneOf" in node:
            node["anyOf"] = node.pop("oneOf")
        if "const" in node:
            node["enum"] = [node.pop("const")]
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


def max_groups(area_m2: float) -> int:
    """How many furniture groups a room of ``area_m2`` is asked for (:data:`M2_PER_GROUP`)."""
    return int(min(MAX_GROUPS, max(1, math.ceil(area_m2 / M2_PER_GROUP))))


def max_ornaments(area_m2: float) -> int:
    """How many ornaments a room of ``area_m2`` is asked for (:data:`M2_PER_ORNAMENT`)."""
    return int(min(MAX_ORNAMENTS, max(2, math.ceil(area_m2 / M2_PER_ORNAMENT))))


def json_schema(stage: str, room_ids: list[str] | None = None, targets: list[str] | None = None,
                max_items: int | None = None) -> dict[str, Any]:  # fmt: skip
    """The self-contained JSON Schema of a stage's reply (a fresh copy).

    What the request already knows narrows it, so a server that enforces schemas cannot
    produce a wrong reference or a room crammed beyond its size: ``room_ids`` (appearance)
    the ids a room entry may name, ``targets`` (ornaments) the furniture an ornament may
    stand on or hang above, ``max_items`` (furniture, ornaments) the most groups or
    ornaments the room is asked for (:func:`max_groups`, :func:`max_ornaments`; a small
    model fills whatever the schema allows, measured: a 4 m2 washroom got 15 floor objects)."""
    schema = copy.deepcopy(_schema(stage))
    if max_items is not None and stage in ("furniture", "ornaments"):
        key = "groups" if stage == "furniture" else "ornaments"
        schema["properties"][key]["maxItems"] = min(schema["properties"][key]["maxItems"], max(1, int(max_items)))
    if stage == "appearance" and room_ids:
        schema["properties"]["rooms"]["items"]["properties"]["id"] = {"type": "string", "enum": list(room_ids)}
    if stage == "ornaments" and targets is not None:
        for variant in item_variants(schema["properties"]["ornaments"]["items"]):
            variant["properties"]["target"] = {"type": "string", "enum": ["", *targets]}
    return schema


def item_variants(node: dict[str, Any]) -> list[dict[str, Any]]:
    """The per-rule object schemas of an item's schema (its ``anyOf``; itself if one)."""
    return list(node.get("anyOf", [node]))


def variant_rule(variant: dict[str, Any]) -> str:
    """The rule an item variant's schema is for."""
    (rule,) = variant["properties"]["rule"]["enum"]
    return str(rule)
