"""HouseSpec: the amodal plan of a house, the output of every planner.

A plan says *what* the house holds, never *where*: rooms with target areas, the bubble
diagram (connections), and per room the furniture groups (an anchor and its members,
each with a placement rule), ornaments, style and material words. The floorplan and
layout stages turn it into geometry.

Placement rules (the ten rules of the AnyHome paper)
----------------------------------------------------
Each rule is one module of :mod:`anyhome.layout.rules` (``place_wall``, ``place_front``,
...) holding its parameters model, whose fields and defaults are the only statement of
what ``ItemSpec.params`` may hold for it: an unknown key or a bad value is refused when
the item is built. :data:`RULES`, :data:`RELATIVE_RULES` and :data:`WALL_RULES` derive
from the registry. Absolute rules (``place_corner``, ``place_wall``, ``place_next_wall``,
``place_center``, ``place_next``) need no other object; relative rules place an object
against ``x`` = ``ItemSpec.target``: the name of another item of the same group (default
the group's anchor) or, for ornaments, the name or category of any object already in the
room, ``None`` meaning "any suitable one".

Group ``arrangement`` (how ``repeat`` copies of a group are laid out):
``"free"`` each copy placed by the anchor's rule; ``"rows"`` anchors on a regular grid
facing one wall ("desks in neat rows facing a whiteboard"); ``"along_walls"`` anchors in
runs against the walls; ``"center"`` anchors around the room centre; ``"symmetric"``
members mirrored about the anchor.

Sizes are meters, ``size_m = (width, depth, height)``: width along the object's local x,
depth front-to-back (local y, front faces +y), height along z.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationInfo,
    field_validator,
    model_validator,
)

from anyhome.layout.rules import RELATIVE_RULES as RELATIVE_RULES  # re-exported
from anyhome.layout.rules import RULES, params_problem
from anyhome.layout.rules import WALL_RULES as WALL_RULES  # re-exported
from anyhome.sanitize import clean_text, is_safe_id
from anyhome.tags import Tag, tags_for

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

KB_CONTEXT = "kb"
"""The validation context key of the knowledge base a spec is read in: the planner and
the entry points validate with ``HouseSpec.model_validate(data, context=kb_context(kb))``;
without it (a spec built by hand, a tool) the knowledge base in force is read."""


def kb_context(kb: KnowledgeBase) -> dict[str, Any]:
    """The pydantic validation context that makes the validators read ``kb``."""
    return {KB_CONTEXT: kb}


def _context_kb(info: ValidationInfo) -> KnowledgeBase | None:
    ctx = info.context
    return ctx.get(KB_CONTEXT) if isinstance(ctx, dict) else None


if TYPE_CHECKING:  # a Literal built from the rule registry at run time; a checker sees str
    Rule = str
else:
    Rule = Literal[RULES]
"""A placement rule's name: a key of :data:`anyhome.layout.rules.REGISTRY`."""
Arrangement = Literal["free", "rows", "along_walls", "center", "symmetric"]

MAX_COUNT = 120
"""Most copies of one item (``count``) or group (``repeat``) a plan holds; a text asking
for more is capped with a warning."""

MAX_ROOMS = 48
"""Most rooms one plan may hold, all storeys together (a hotel floor of 14 guest rooms with
their bathrooms, a school wing)."""

MIN_LEVEL, MAX_LEVEL = -2, 5
"""Lowest and highest storey a plan may use (0 = ground, -1 = a basement)."""


MAX_TEXT_CHARS = 2000
"""Longest name, description or warning a plan keeps (the prompt keeps its own length)."""


def _clean(v: Any) -> Any:
    """A string from outside (the user's text, an LLM reply) without control characters
    or terminal escape sequences, on one line, trimmed; anything else is left for the
    type check."""
    return clean_text(v).strip()[:MAX_TEXT_CHARS] if isinstance(v, str) else v


def _clean_deep(v: Any) -> Any:
    """:func:`_clean` on every string inside lists and dicts (keys too)."""
    if isinstance(v, str):
        return clean_text(v, newlines=True)
    if isinstance(v, dict):
        return {_clean_deep(k): _clean_deep(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return type(v)(_clean_deep(x) for x in v)
    return v


MAX_ROOM_ID_CHARS = 64
"""Room ids are cut to this length, so an object id (``<room>-<item>-<k>``, the item part
at most 40 characters) stays within the 128 of house.json's id alphabet."""


def _safe_id(v: Any) -> Any:
    """A room id in the safe alphabet of house.json (:data:`anyhome.sanitize.ID_PATTERN`):
    other characters become ``_``, so the same id always maps the same way (the
    connections keep pointing at their rooms)."""
    if not isinstance(v, str) or (is_safe_id(v) and len(v) <= MAX_ROOM_ID_CHARS):
        return v
    out = re.sub(r"[^A-Za-z0-9_.:-]+", "_", clean_text(v))[:MAX_ROOM_ID_CHARS]
    if out and not re.match(r"[A-Za-z0-9_]", out):
        out = "_" + out[: MAX_ROOM_ID_CHARS - 1]
    return out


CleanStr = Annotated[str, BeforeValidator(_clean)]
"""A string cleaned of control characters and escape sequences before validation."""

RoomId = Annotated[str, BeforeValidator(_safe_id)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", validate_assignment=True)


class ItemSpec(_Model):
    """One kind of object to place, possibly several copies of it."""

    name: CleanStr = Field(min_length=1, description="open-vocabulary name, e.g. 'canopy bed'")
    category: CleanStr = Field(min_length=1, description="asset family, e.g. 'bed'")
    description: CleanStr = ""
    size_m: tuple[float, float, float] = Field(description="(width, depth, height) in meters")
    rule: Rule
    target: CleanStr | None = None
    params: Annotated[dict[str, Any], BeforeValidator(_clean_deep)] = Field(default_factory=dict)
    count: int = Field(default=1, ge=1, le=MAX_COUNT)
    material: CleanStr = ""
    tags: list[Tag] = Field(
        default_factory=list,
        description="semantic tags (anyhome.tags); derived from name and category when not given",
    )

    @model_validator(mode="before")
    @classmethod
    def _derive_tags(cls, data: Any, info: ValidationInfo) -> Any:
        """Items built without tags (the LLM planner's) get them from the knowledge base
        (the context's, see :data:`KB_CONTEXT`)."""
        if isinstance(data, dict) and data.get("tags") is None:
            name, category = data.get("name"), data.get("category")
            if isinstance(name, str) and isinstance(category, str):
                data = {**data, "tags": list(tags_for(name, category, _context_kb(info)))}
        return data

    @model_validator(mode="after")
    def _check_params(self) -> ItemSpec:
        """``params`` as the rule's parameters model takes them (anyhome.layout.rules)."""
        if (bad := params_problem(self.rule, self.params)) is not None:
            raise ValueError(f"{self.rule} params: {bad.where}: {bad.what} (parameters: {bad.known})")
        return self

    @field_validator("size_m")
    @classmethod
    def _positive_size(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        if not all(0.005 <= s <= 20.0 for s in v):
            raise ValueError(f"every size must be within 0.005..20 m, got {v}")
        return v


class GroupSpec(_Model):
    """A semantic asset group: an anchor and the members placed relative to it."""

    name: CleanStr = Field(min_length=1)
    anchor: ItemSpec
    members: list[ItemSpec] = Field(default_factory=list)
    arrangement: Arrangement = "free"
    repeat: int = Field(default=1, ge=1, le=MAX_COUNT)
    priority: int = Field(default=0, description="lower is placed earlier")
    required: bool = Field(default=False, description="the text asked for it explicitly")
    fill: bool = Field(default=False, description=(
        "a zone proposed for a large room (a reading corner, a second seating group): placed "
        "only while the room's floor is under-furnished, and left out without a warning when it "
        "does not fit (anyhome.layout.fill)"))

    @property
    def key(self) -> bool:
        """A group its room must keep: asked for by the text, or what makes the room what
        it is (priority :data:`KEY_PRIORITY` or lower: the bed, the sofa)."""
        return not self.fill and (self.required or self.priority <= KEY_PRIORITY)


KEY_PRIORITY = 0
"""A group of this priority or lower makes its room what it is (:attr:`GroupSpec.key`)."""


def _style_keys(v: Any) -> Any:
    """Style keys as written in styles.yaml: lower case, ``_`` for spaces and hyphens,
    each once, in order."""
    if not isinstance(v, list):
        return v
    keys = [re.sub(r"[\s-]+", "_", clean_text(k).strip().lower()) if isinstance(k, str) else k for k in v]
    return list(dict.fromkeys(keys))


def _check_style_keys(keys: list[str], info: ValidationInfo) -> list[str]:
    """``keys`` when each is a style of the context's knowledge base (see
    :data:`KB_CONTEXT`; none: the knowledge base in force)."""
    if not keys:
        return keys
    from anyhome.plan.kbview import resolve

    known = resolve(_context_kb(info)).raw("styles")["styles"]
    unknown = [k for k in keys if k not in known]
    if unknown:
        raise ValueError(f"unknown style {unknown[0]!r}; known styles include {', '.join(list(known)[:8])}")
    return keys


def _keys_from_words(style: str, kb: KnowledgeBase | None) -> list[str]:
    from anyhome.plan.appearance import style_keys

    return style_keys(style, kb=kb)


StyleKeys = Annotated[list[str], BeforeValidator(_style_keys)]
"""Keys of plan/knowledge/styles.yaml (``["gothic", "victorian"]``), the lead style first."""


class RoomSpec(_Model):
    """One planned room."""

    id: RoomId = Field(min_length=1)
    name: CleanStr = Field(min_length=1)
    type: CleanStr = Field(min_length=1, description="functional type, see anyhome.house.ROOM_TYPES")
    area_m2: float = Field(gt=0.5, le=400.0)
    height_m: float = Field(default=2.7, ge=2.0, le=12.0, description="when not given: the type's (rooms.yaml)")
    open_air: bool = Field(default=False, description="no roof; when not given: the type's (rooms.yaml open_air)")
    ceiling: Literal["flat", "pitched", "vaulted"] = Field(default="flat", description="ceiling shape (flat when open_air)")
    level: int = Field(default=0, ge=MIN_LEVEL, le=MAX_LEVEL, description="storey: 0 ground, 1 up, -1 basement")
    style: CleanStr = Field(default="", description="the room's style in words, for display")
    styles: StyleKeys = Field(
        default_factory=list,
        description="the room's own style keys (styles.yaml), when it differs from the house; empty: the house's",
    )
    materials: dict[CleanStr, CleanStr] = Field(default_factory=dict)
    groups: list[GroupSpec] = Field(default_factory=list)
    ornaments: list[ItemSpec] = Field(default_factory=list)

    @model_validator(mode="before")
    @classmethod
    def _type_defaults(cls, data: Any, info: ValidationInfo) -> Any:
        """``height_m`` and ``open_air`` left out (the LLM planner's rooms): the room
        type's, from rooms.yaml (the context's knowledge base, see :data:`KB_CONTEXT`)."""
        if not isinstance(data, dict) or ("height_m" in data and "open_air" in data):
            return data
        from anyhome.plan.kbview import resolve

        types = resolve(_context_kb(info)).raw("rooms")["types"]
        t = data.get("type")
        info_t = types.get(t if isinstance(t, str) else "", types["other"])
        data = dict(data)
        data.setdefault("height_m", float(info_t["height_m"]))
        data.setdefault("open_air", bool(info_t.get("open_air", False)))
        return data

    @model_validator(mode="after")
    def _materials_complete(self) -> RoomSpec:
        for key in ("floor", "walls", "ceiling"):
            self.materials.setdefault(key, "")
        if self.open_air and self.ceiling != "flat":
            self.ceiling = "flat"
        return self

    @field_validator("styles")
    @classmethod
    def _known_styles(cls, v: list[str], info: ValidationInfo) -> list[str]:
        return _check_style_keys(v, info)


class HouseSpec(_Model):
    """The whole plan: rooms, bubble diagram, appearance."""

    prompt: Annotated[str, BeforeValidator(lambda v: clean_text(v, newlines=True) if isinstance(v, str) else v)]
    building: CleanStr = Field(default="home", description="kind of building: home, office, cafe...")
    style: CleanStr = Field(default="", description="the style in words, for display")
    styles: StyleKeys = Field(
        default_factory=list,
        description="style keys of plan/knowledge/styles.yaml, the lead first: assets and materials read them. "
        "Read from `style` when empty",
    )
    palette: list[CleanStr] = Field(default_factory=list)
    rooms: list[RoomSpec] = Field(min_length=1, max_length=MAX_ROOMS)
    connections: list[tuple[RoomId, RoomId]] = Field(
        default_factory=list,
        description="bubble-diagram edges; (room_id, 'outside') marks the entrance room",
    )
    warnings: list[CleanStr] = Field(default_factory=list)
    provenance: Annotated[dict[str, Any] | None, BeforeValidator(_clean_deep)] = Field(
        default=None, description="where each stage came from (the LLM planner: stages, tokens, latency)"
    )

    @model_validator(mode="after")
    def _check_graph(self) -> HouseSpec:
        ids = [r.id for r in self.rooms]
        if len(set(ids)) != len(ids):
            raise ValueError(f"room ids must be unique: {ids}")
        known = set(ids) | {"outside"}
        for a, b in self.connections:
            if a not in known or b not in known or a == b:
                raise ValueError(f"bad connection {a!r}-{b!r}")
            if a == "outside":
                raise ValueError("write the entrance as (room_id, 'outside')")
        if not any(b == "outside" for _, b in self.connections):
            raise ValueError("the plan has no entrance: add (room_id, 'outside')")
        return self

    @model_validator(mode="before")
    @classmethod
    def _styles_from_words(cls, data: Any, info: ValidationInfo) -> Any:
        if isinstance(data, dict) and not data.get("styles") and isinstance(data.get("style"), str):
            data = {**data, "styles": _keys_from_words(clean_text(data["style"]), _context_kb(info))}
        return data

    @field_validator("styles")
    @classmethod
    def _known_styles(cls, v: list[str], info: ValidationInfo) -> list[str]:
        return _check_style_keys(v, info)

    def styles_for(self, room_id: str) -> list[str]:
        """The style keys of a room: its own, else the house's."""
        return self.room(room_id).styles or self.styles

    @property
    def entrance_room(self) -> str:
        return next(a for a, b in self.connections if b == "outside")

    def room(self, room_id: str) -> RoomSpec:
        for r in self.rooms:
            if r.id == room_id:
                return r
        raise KeyError(room_id)
