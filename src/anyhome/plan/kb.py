"""Typed models of the knowledge files (``plan/knowledge/*.yaml``) and their checks.

Each file has a pydantic model (``extra="forbid"``: a misspelt field is an error, not a
silently ignored default); :class:`KnowledgeBase` holds the six validated files and checks
the references between them (a furniture set naming a group that does not exist, a
program naming an unknown room type, a style naming an unknown asset class...).

Every problem is reported as a :class:`~anyhome.errors.KnowledgeError` whose message is
one line, ``FILE: KEY: what is wrong``; ``FILE`` is the file the faulty entry came from
(a shipped file or a user's overlay file, see :mod:`anyhome.plan.knowledge`).

The planner still reads the raw mappings (``knowledge.load(name)``); the models are the
contract those mappings satisfy, and what later stages take as ``KnowledgeBase``.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Mapping
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    RootModel,
    ValidationError,
    field_validator,
    model_validator,
)

from anyhome.errors import KnowledgeError
from anyhome.plan.spec import RULES, Arrangement, Rule
from anyhome.tags import Tag

MIN_SIZE_M = 0.005
MAX_SIZE_M = 20.0

SizeM = Annotated[float, Field(ge=MIN_SIZE_M, le=MAX_SIZE_M)]
Size = tuple[SizeM, SizeM, SizeM]
"""``[width, depth, height]`` in metres, each within 0.005..20 m (as ``ItemSpec.size_m``)."""
Area = Annotated[float, Field(gt=0, le=1000)]
Prob = Annotated[float, Field(ge=0, le=1)]
NonNeg = Annotated[int, Field(ge=0)]
HexColour = Annotated[str, Field(pattern=r"^#[0-9a-fA-F]{6}$")]
Word = Annotated[str, Field(min_length=1)]
Category = Annotated[str, Field(pattern=r"^[a-z0-9_]+$")]
Surface = Literal["furniture", "floor", "walls", "ceiling"]


def _ordered(v: Any) -> Any:
    if isinstance(v, (list, tuple)) and len(v) == 2 and all(isinstance(x, (int, float)) for x in v) and v[0] > v[1]:
        raise ValueError(f"a range [lo, hi] needs lo <= hi, got {list(v)}")
    return v


AreaRange = Annotated[tuple[Area, Area], Field(description="[lo, hi] m2")]
CountRange = tuple[NonNeg, NonNeg]
Count = NonNeg | CountRange
"""``n`` or ``[lo, hi]`` (one drawn per seed)."""


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


# ------------------------------------------------------------------ programs.yaml
class Building(_Model):
    """Words in the text that name a kind of building, its program and implied styles."""

    words: list[Word] = Field(min_length=1)
    program: str
    styles: list[str] = Field(default_factory=list)
    kind: str | None = Field(default=None, description="building kind: a key of sizes.kinds (its room sizes)")
    unless: list[Word] = Field(default_factory=list, description=(
        "the words name no building when the text holds one of these ('a studio' with easels is an artist's workspace)"))


class ProgramRoom(_Model):
    key: Word
    type: str
    name: Word | None = None
    furnish: str | None = None
    area: AreaRange | None = None
    count: Count | None = None
    optional: Prob | None = None

    _r = field_validator("area", "count")(classmethod(lambda cls, v: _ordered(v)))


class PeriodSwap(_Model):
    """A modern object's stand-in in a period look: an objects.yaml prototype and the name it takes."""

    use: str
    name: Word


class Program(_Model):
    building: Word
    main: str
    entrance: list[str] = Field(min_length=1)
    rooms: list[ProgramRoom] = Field(min_length=1)
    extra: dict[str, list[str]] = Field(default_factory=dict, description="room key -> extra group names")
    holds: list[str] = Field(default_factory=list, description=(
        "room types the main room takes in: one mention of each is read as a part of it, "
        "not a room of its own (a studio apartment's kitchenette, its sleeping area)"))
    main_beside_bedrooms: str | None = Field(default=None, description=(
        "furnishing set of the main room where the plan gives the home bedrooms of its own "
        "(a tiny house's studio under two sleeping lofts: its sleeping area is theirs)"))
    one_room: bool = Field(default=False, description=(
        "its rooms are all it has: it gains no rooms to reach a total, and a size word scales "
        "its rooms ('a small studio') instead of setting a home's total"))
    swap: dict[str, PeriodSwap] = Field(default_factory=dict, description=(
        "item name -> the stand-in the building uses instead, unless the text asks for the item "
        "(a hotel's desk chair is upholstered, not a mesh office chair)"))
    object_words: dict[str, str] = Field(default_factory=dict, description=(
        "object key -> the object key the building reads the word as (a lab's 'workbenches' "
        "are lab benches, a workshop's are woodworking benches)"))

    @model_validator(mode="after")
    def _keys(self) -> Program:
        keys = [r.key for r in self.rooms]
        if len(set(keys)) != len(keys):
            raise ValueError(f"room keys must be unique: {keys}")
        if self.main not in keys:
            raise ValueError(f"main {self.main!r} is not the key of one of its rooms ({', '.join(keys)})")
        for k in self.extra:
            if k not in keys:
                raise ValueError(f"extra names room {k!r}, not one of its rooms ({', '.join(keys)})")
        return self


class SizeWord(_Model):
    """A size word ("tiny", "grand"): its factor on what it stands before, and the total
    floor area it means for a home."""

    factor: Annotated[float, Field(gt=0, le=3)] = Field(default=1.0, description="factor on a room's area or an object's size")
    total_m2: AreaRange | None = None
    scale: Annotated[float, Field(gt=0, le=3)] = Field(default=1.0, description="factor on every room's area range")
    least: Annotated[float, Field(gt=0, le=1)] = Field(default=1.0, description=(
        "factor on the room types' min_area_m2 in a home this word sizes, never below a square of the type's "
        "min_width_m (a tiny home's sitting room is smaller than a family home's)"))

    _r = field_validator("total_m2")(classmethod(lambda cls, v: _ordered(v)))


class AddedRoom(_Model):
    """A room a dwelling gains when its total calls for more rooms."""

    type: str
    name: Word
    up_to: Annotated[int, Field(ge=1, le=12)] = Field(default=1, description="added only while the home has fewer rooms of the type")


class BuildingKind(_Model):
    """Typical room sizes of one kind of building (a cabin's bedrooms are smaller than a
    mansion's): area ranges by room type, a factor on the others, a typical total."""

    scale: Annotated[float, Field(gt=0, le=3)] = 1.0
    areas: dict[str, AreaRange] = Field(default_factory=dict, description="room type -> [lo, hi] m2")
    total_m2: AreaRange | None = None
    add: list[AddedRoom] | None = Field(default=None, description="rooms added first when the total needs more")
    counts: dict[str, Count] = Field(default_factory=dict, description="room type -> how many its program plans")

    _r = field_validator("total_m2")(classmethod(lambda cls, v: _ordered(v)))

    @field_validator("areas", "counts")
    @classmethod
    def _areas(cls, v: dict[str, Any]) -> dict[str, Any]:
        for r in v.values():
            _ordered(r)
        return v


class Compact(_Model):
    program: str
    below_m2: Area


class SizeDraw(_Model):
    """programs.yaml ``sizes.draw``: the seeded variation of a plan's room sizes."""

    house: AreaRange = Field(description="factor on every room of one house, log-uniform in [lo, hi]")
    room: AreaRange = Field(description="factor on each room on top of it, log-uniform in [lo, hi]")
    per_bedroom: dict[str, Annotated[float, Field(ge=-0.5, le=0.5)]] = Field(
        default_factory=dict, description="room type -> share its area grows per bedroom past the second")

    _r = field_validator("house", "room")(classmethod(lambda cls, v: _ordered(v)))


class Sizes(_Model):
    """programs.yaml ``sizes``: how big dwellings are (docs/space_standards.md)."""

    homes: list[str] = Field(min_length=1, description="programs the size words and stated totals resize")
    compact: Compact
    stretch: Annotated[float, Field(ge=1, le=4)] = Field(description="most a room grows past its range's top")
    stated_stretch: Annotated[float, Field(ge=1, le=4)] | None = Field(
        default=None, description="most a room grows past its range's top to fill a total the text states")
    circulation_share: Annotated[float, Field(gt=0, le=1)] = Field(
        default=1.0, description="most of a home's planned area its entries and hallways take")
    add: list[AddedRoom] = Field(default_factory=list, description="rooms a home gains when its total needs more")
    words: dict[Word, SizeWord] = Field(default_factory=dict)
    land_words: list[Word] = Field(default_factory=list, description=(
        "words after an area that make it the land's, not the building's ('a 500 m2 plot')"))
    kinds: dict[Word, BuildingKind] = Field(default_factory=dict)
    draw: SizeDraw | None = Field(default=None, description="how far one house's rooms vary from the ranges' draws")


class Storeys(_Model):
    """programs.yaml ``storeys``: which rooms go where in a house of several storeys."""

    up: list[str] = Field(min_length=1, description="room types that go upstairs (bathrooms follow them)")
    basement: list[str] = Field(min_length=1, description="room types that go down to a basement")
    attic: list[str] = Field(min_length=1, description="room types an attic takes (the first of them the plan has)")


class ConversionLook(_Model):
    """What a converted building keeps of its former use: looks and features as decor."""

    styles: list[str] = Field(default_factory=list)
    ornaments: list[GroupItem] = Field(default_factory=list, description="decor in the home's main room")


class Conversions(_Model):
    """A building's former use ("a converted chapel", "a barn conversion", "a former
    school turned into flats"): the building is what it became, never the old one."""

    program: str = Field(description="the building a conversion is when the text names no other")
    before: list[Word] = Field(min_length=1, description="words before the old building's word: converted, former")
    after: list[Word] = Field(default_factory=list, description="words right after it: conversion")
    into: list[Word] = Field(default_factory=list, description="words leading to what it became: turned into, now a")
    keeps: dict[str, ConversionLook] = Field(default_factory=dict, description="former program -> what the home keeps")


class ProgramsFile(_Model):
    buildings: list[Building]
    conversions: Conversions | None = None
    programs: dict[str, Program] = Field(min_length=1)
    sizes: Sizes | None = None
    storeys: Storeys | None = None


# ------------------------------------------------------------------ rooms.yaml
class SurfaceMaterials(_Model):
    floor: str
    walls: str
    ceiling: str


class RoomType(_Model):
    habitable: bool = Field(description="a room people stay in (gets windows); anyhome.house.ROOM_TYPES reads it")
    area: AreaRange
    tier: NonNeg
    hub: bool = False
    attach: list[str] = Field(default_factory=list)
    max: Annotated[int, Field(ge=1)]
    wet: bool = False
    materials: SurfaceMaterials
    min_width_m: Annotated[float, Field(gt=0, le=20, description="narrowest clear width (docs/space_standards.md)")]
    min_area_m2: Area = Field(description="smallest area the norms allow (docs/space_standards.md)")
    floor_use: Annotated[float, Field(ge=1, le=5)] | None = Field(
        default=None, description="room m2 per m2 of furniture footprint (default: the planner's FLOOR_USE_FACTOR)")
    circulation: bool = Field(default=False, description="a room for passing through (entry, hallway)")
    doors_max: Annotated[int, Field(ge=2)] | None = Field(
        default=None, description="a hub that is not a corridor (a reception): most connections it holds, the "
        "entrance included; the rooms beyond open off a corridor planned for them")
    height_m: Annotated[float, Field(ge=2.1, le=12, description="floor-to-ceiling height (heights.yaml adjusts it)")]
    open_air: bool = Field(default=False, description="no roof: no ceiling, railings on its exterior sides")
    enclosed: bool = Field(default=False, description="open_air inside the footprint: rooms around it, not at the edge")

    _r = field_validator("area")(classmethod(lambda cls, v: _ordered(v)))

    @model_validator(mode="after")
    def _open_air_not_habitable(self) -> RoomType:
        if self.open_air and self.habitable:
            raise ValueError("an open_air room cannot be habitable (it has no window, no ceiling)")
        return self


class HomeSense(_Model):
    """How a room word reads in a dwelling ("a salon" in a riad: a sitting room)."""

    type: str
    furnish: str | None = None
    area: AreaRange | None = None

    _r = field_validator("area")(classmethod(lambda cls, v: _ordered(v)))


class RoomName(_Model):
    type: str
    generic: bool = False
    name: Word | None = None
    furnish: str | None = None
    area: AreaRange | None = None
    at_home: HomeSense | None = Field(None, description="the word's reading in a dwelling (a program of sizes.homes)")
    within: dict[str, HomeSense] = Field(default_factory=dict, description=(
        "program -> the word's reading in that building (a gym in a school is its sports hall)"))
    noun_only: bool = Field(False, description=(
        "the word is also an adjective: it names a room only where no word of a name follows it "
        "('a cosy snug,' is a room; 'a snug bedroom', 'solar panels' are not)"))
    owned: HomeSense | None = Field(None, description=(
        "the word's reading after a person's possessive ('the editor's office' is a private office)"))
    only_within: list[str] = Field(default_factory=list, description=(
        "programs in which alone the word names a room (a riding stable's 'stalls' are its loose "
        "boxes; a market's 'vendor stalls' are no rooms); empty: every building"))

    _r = field_validator("area")(classmethod(lambda cls, v: _ordered(v)))


class OpenAirWords(_Model):
    """Words that say a room is open to the sky (rooms.yaml ``open_air``)."""

    words: dict[str, str] = Field(description="word or phrase -> the open-air room type it stands for")
    not_before: list[str] = Field(default_factory=list, description="a word followed by one of these is no open air ('garden room')")
    enclosed: list[str] = Field(default_factory=list, description="names with such a word that are enclosed ('winter garden')")


class RoomsFile(_Model):
    types: dict[str, RoomType]
    names: dict[str, RoomName]
    open_air: OpenAirWords | None = None
    small_heads: dict[str, AreaRange] = Field(
        default_factory=dict,
        description="a room name's last word that makes it a small room, and its area range "
                    "(a 'meditation nook' read as a meditation room is a nook's size)",
    )
    own_parts: list[str] = Field(default_factory=list, description=(
        "room types a room of several may each have as its own part, listed after the first "
        "('four suites, each with its own sitting area, a balcony and a bathroom')"))

    @model_validator(mode="after")
    def _open_air_types(self) -> RoomsFile:
        for t in self.own_parts:
            if t not in self.types:
                raise ValueError(f"own_parts names {t!r}, not a room type")
        for word, t in (self.open_air.words.items() if self.open_air else ()):
            if t not in self.types or not self.types[t].open_air:
                raise ValueError(f"open_air word {word!r} names {t!r}, not an open_air room type")
        return self


# ------------------------------------------------------------------ heights.yaml
CeilingShape = Literal["flat", "pitched", "vaulted"]


class HeightLimits(_Model):
    min_m: Annotated[float, Field(ge=2.1, le=12)]
    max_m: Annotated[float, Field(ge=2.1, le=12)]

    @model_validator(mode="after")
    def _ordered(self) -> HeightLimits:
        if self.min_m > self.max_m:
            raise ValueError(f"min_m {self.min_m} is more than max_m {self.max_m}")
        return self


class BuildingHeight(_Model):
    scale: Annotated[float, Field(gt=0.5, le=3)]


class HeightWord(_Model):
    scale: Annotated[float, Field(gt=0.5, le=3)] = 1.0
    add_m: Annotated[float, Field(ge=-1, le=3)] = 0.0
    ceiling: CeilingShape | None = None


class HeightsFile(_Model):
    limits: HeightLimits
    buildings: dict[Word, BuildingHeight] = Field(default_factory=dict)
    words: dict[Word, HeightWord] = Field(default_factory=dict)


# ------------------------------------------------------------------ objects.yaml
class ObjectProto(_Model):
    """An object prototype: what the planner knows of a kind of object."""

    category: Category = Field(description="asset family (lowercase, underscores)")
    size: Size = Field(description="[width, depth, height] m of the whole box")
    rule: Rule
    params: dict[str, Any] = Field(default_factory=dict)
    target: str | None = None
    rooms: list[str] = Field(default_factory=list)
    synonyms: list[Word] = Field(default_factory=list)
    plural: CountRange | None = None
    ornament: bool = False
    group: str | None = None
    wall_mount_m: Annotated[float, Field(gt=0, le=10)] | None = None
    tags: list[Tag] = Field(default_factory=list, description="semantic tags (anyhome.tags.TAGS)")

    _r = field_validator("plural")(classmethod(lambda cls, v: _ordered(v)))


class ObjectsFile(RootModel[dict[str, ObjectProto]]):
    pass


# ------------------------------------------------------------------ furniture.yaml
class GroupItem(_Model):
    """An anchor, member or ornament: an object prototype (``use``) with overrides."""

    use: str | None = None
    name: Word | None = None
    names: list[Word] | None = None
    category: Category | None = None
    size: Size | None = None
    rule: Rule | None = None
    target: str | None = None
    params: dict[str, Any] = Field(default_factory=dict)
    count: Count = 1
    prob: Prob = 1.0

    _r = field_validator("count")(classmethod(lambda cls, v: _ordered(v)))


class Group(_Model):
    anchor: GroupItem
    members: list[GroupItem] = Field(default_factory=list)
    join: list[str] = Field(default_factory=list, description=(
        "groups (by template) this one joins when its room has one: its items become that "
        "group's members (a TV asked for by itself goes with the sofa's group)"))
    priority: int = 0
    arrangement: Arrangement = "free"
    repeat: Annotated[int, Field(ge=1)] | tuple[Annotated[int, Field(ge=1)], Annotated[int, Field(ge=1)]] = 1
    per_m2: Annotated[float, Field(gt=0)] | None = None

    _r = field_validator("repeat")(classmethod(lambda cls, v: _ordered(v)))


class SetEntry(_Model):
    """A group of a furnishing set: a template (``group``) or one of several
    (``one_of``), with overrides."""

    group: str | None = None
    one_of: list[str] | None = None
    prob: Prob = 1.0
    anchor: GroupItem | None = None
    members: list[GroupItem] | None = None
    priority: int | None = None
    arrangement: Arrangement | None = None
    repeat: Annotated[int, Field(ge=1)] | tuple[Annotated[int, Field(ge=1)], Annotated[int, Field(ge=1)]] | None = None
    per_m2: Annotated[float, Field(gt=0)] | None = None

    _r = field_validator("repeat")(classmethod(lambda cls, v: _ordered(v)))

    @model_validator(mode="after")
    def _one(self) -> SetEntry:
        if (self.group is None) == (self.one_of is None):
            raise ValueError("give exactly one of group or one_of")
        if self.one_of is not None and not self.one_of:
            raise ValueError("one_of needs at least one group")
        return self


class FurnitureSet(_Model):
    groups: list[SetEntry] = Field(default_factory=list)
    ornaments: list[GroupItem] = Field(default_factory=list)


class FurnitureFile(_Model):
    groups: dict[str, Group]
    sets: dict[str, FurnitureSet]
    zones: dict[str, list[SetEntry]] = Field(
        default_factory=dict, description="furnishing set or room type -> zone groups a large room may get")


# ------------------------------------------------------------------ styles.yaml
class Style(_Model):
    words: list[Word] = Field(min_length=1)
    describe: Word
    palette: list[Word] = Field(min_length=1)
    floor: Word
    walls: Word
    ceiling: Word
    furniture: Word
    asset_class: str


class AssetClass(_Model):
    traits: list[Literal["antique", "modern", "industrial", "rustic", "eastern"]]
    legs: list[Literal["straight", "tapered", "turned", "metal"]] = Field(min_length=1)
    woods: list[HexColour] = Field(min_length=1)
    fabrics: list[HexColour] = Field(min_length=1)


class PeriodRules(_Model):
    """What a look of one trait does not have, unless the text asks for it (styles.yaml ``period``)."""

    swap: dict[str, PeriodSwap] = Field(default_factory=dict, description="item name -> its stand-in")
    drop: list[Word] = Field(default_factory=list, description="item names left out")


class StylesFile(_Model):
    styles: dict[str, Style] = Field(min_length=1)
    asset_classes: dict[str, AssetClass]
    defaults: dict[str, list[str]] = Field(description="program -> style keys drawn when the text names none")
    category_materials: dict[str, str]
    period: dict[str, PeriodRules] = Field(default_factory=dict, description="asset-class trait -> what its looks leave out")
    moods: list[Word] = Field(default_factory=list, description="style words that say a mood, not a look: their styles follow the others")

    @field_validator("category_materials")
    @classmethod
    def _patterns(cls, v: dict[str, str]) -> dict[str, str]:
        for k, p in v.items():
            try:
                p.format(colour="", furniture="")
            except (KeyError, IndexError, ValueError) as e:
                raise ValueError(f"{k}: pattern {p!r} may use only {{colour}} and {{furniture}} ({e})") from None
        return v


# ------------------------------------------------------------------ concepts.yaml
class FallbackObject(_Model):
    size: Size
    rule: Rule


class ConceptsFile(_Model):
    rooms: dict[str, list[Word]] = Field(default_factory=dict)
    objects: dict[str, list[Word]] = Field(default_factory=dict)
    buildings: dict[str, list[Word]] = Field(default_factory=dict)
    non_objects: list[Word] = Field(default_factory=list)
    quantity_words: list[Word] = Field(default_factory=list, description=(
        "object words that name no object before 'of' ('a wide range of teas', not a kitchen range)"))
    setting_words: list[Word] = Field(default_factory=list, description=(
        "words before a building that say where it stands, never its style ('a village fire station')"))
    list_rooms: dict[Word, str] = Field(default_factory=dict, description=(
        "object words that are rooms when listed among rooms ('a restaurant, a bar and a spa')"))
    fallback_object: FallbackObject | None = None


# ------------------------------------------------------------------ materials.yaml
Rank = Literal["pattern", "material", "generic"]
RANKS: dict[str, int] = {"pattern": 2, "material": 1, "generic": 0}
"""How strongly a material word decides its clause (higher wins; ties: the later word)."""
Unit = Annotated[float, Field(ge=0, le=1)]
TileM = Annotated[float, Field(gt=0, le=100)]


class MaterialLook(_Model):
    """What a material word (or one surface of it) overrides of its kind's defaults."""

    kind: str | None = None
    variant: str | None = None
    roughness: Unit | None = None
    metallic: Unit | None = None
    alpha: Unit | None = None
    tile_m: TileM | None = None
    color: HexColour | None = None


class MaterialVariant(_Model):
    roughness: Unit | None = None
    metallic: Unit | None = None
    alpha: Unit | None = None
    tile_m: TileM | None = None
    color: HexColour | None = None


class MaterialKind(MaterialVariant):
    variants: dict[Word, MaterialVariant] = Field(default_factory=dict)


class MaterialWord(MaterialLook):
    """One material word with every fact about it (see materials.yaml's header)."""

    rank: Rank = "material"
    floor: MaterialLook | None = None
    walls: MaterialLook | None = None
    ceiling: MaterialLook | None = None
    furniture: MaterialLook | None = None
    goes_on: list[Surface] = Field(default_factory=list, description="where the planner puts it when the text does not say")

    @model_validator(mode="after")
    def _phrase(self) -> MaterialWord:
        if self.kind is None:
            extra = sorted(f for f in self.model_fields_set if f != "goes_on")
            if extra:
                raise ValueError(f"an entry without a kind may only give goes_on (it has {', '.join(extra)})")
            if not self.goes_on:
                raise ValueError("give a kind (or goes_on, for a phrase known by its words)")
        return self


class SurfaceRule(_Model):
    becomes: dict[str, str] = Field(default_factory=dict, description="kind -> the kind it becomes on this surface")
    default: str = Field(description="material words when a phrase names none")


class MaterialsFile(_Model):
    """materials.yaml: texture kinds, every material word, surface rules, finish and tone words."""

    kinds: dict[str, MaterialKind] = Field(min_length=1)
    words: dict[Word, MaterialWord] = Field(min_length=1)
    surfaces: dict[Surface, SurfaceRule]
    finish: dict[Word, Annotated[float, Field(ge=-1, le=1)]] = Field(default_factory=dict)
    tone: dict[Word, Annotated[float, Field(gt=0, le=3)]] = Field(default_factory=dict)
    weathering: list[Word] = Field(default_factory=list, description=(
        "words that age a surface visibly: its texture is drawn weathered (stains, wear, cracks)"))
    ceiling_structure: dict[Word, Literal["beams", "coffers"]] = Field(default_factory=dict, description=(
        "ceiling words that are geometry under a plaster ceiling (beams across the room, a grid of coffers)"))

    @field_validator("surfaces")
    @classmethod
    def _all(cls, v: dict[str, SurfaceRule]) -> dict[str, SurfaceRule]:
        missing = [s for s in ("floor", "walls", "ceiling", "furniture") if s not in v]
        if missing:
            raise ValueError(f"missing the rules of {', '.join(missing)}")
        return v


def material_words(text: str) -> list[str]:
    """The words of a material phrase as the material tables match them (letters only,
    lower case: "Bouclé" stays one word)."""
    return re.findall(r"[^\W\d_]+", text.lower())


# ------------------------------------------------------------------ colours.yaml
RGB = tuple[Annotated[int, Field(ge=0, le=255)], Annotated[int, Field(ge=0, le=255)], Annotated[int, Field(ge=0, le=255)]]


class ColoursFile(_Model):
    """colours.yaml: every colour word with its base colour, and the words that shade
    (``modifiers``) or mute (``muting``) the colour after them."""

    colours: dict[Word, RGB] = Field(min_length=1, description="colour word or phrase -> [r, g, b] (sRGB 0-255)")
    modifiers: dict[Word, Annotated[float, Field(gt=0, le=2)]] = Field(default_factory=dict)
    muting: dict[Word, Annotated[float, Field(ge=0, le=1)]] = Field(default_factory=dict)


# ------------------------------------------------------------------ assets.yaml
def word_key(text: str) -> str:
    """An object word as the asset tables key it: lower case, runs of other characters
    as one ``_`` ("Teacher's desk" -> ``teacher_s_desk``)."""
    return "_".join(re.findall(r"[a-z0-9]+", text.lower()))


class AssetsFile(_Model):
    """assets.yaml: what the asset side knows that no object prototype holds."""

    categories: dict[Category, Category] = Field(
        default_factory=dict, description="object category that is no family -> the family it is built as")
    words: dict[Category, Category] = Field(
        default_factory=dict, description="object word no prototype names -> family")
    sizes: dict[Category, Size] = Field(
        default_factory=dict, description="typical box of a family no prototype covers")
    stand_ins: list[Category] = Field(
        default_factory=list, description="object words whose family draws something else: shown with a stand-in mesh")


class SurfacesFile(RootModel[dict[Surface, list[Word]]]):
    """surfaces.yaml: the words naming each room surface a material phrase can dress."""


FILE_MODELS: dict[str, type[BaseModel]] = {
    "programs": ProgramsFile,
    "rooms": RoomsFile,
    "objects": ObjectsFile,
    "furniture": FurnitureFile,
    "styles": StylesFile,
    "concepts": ConceptsFile,
    "surfaces": SurfacesFile,
    "assets": AssetsFile,
    "colours": ColoursFile,
    "materials": MaterialsFile,
    "heights": HeightsFile,
}
"""The model of each knowledge file, by file name (without ``.yaml``)."""

SECTIONED = frozenset(FILE_MODELS) - {"objects", "surfaces"}
"""Files whose top level holds sections (``types:``, ``names:``...); objects.yaml's top
level holds the entries themselves."""


Source = Callable[[str, tuple[Any, ...]], str]
"""``(file name, location) -> path`` of the file an entry came from."""


def _where(name: str, loc: tuple[Any, ...]) -> tuple[tuple[Any, ...], tuple[Any, ...]]:
    """Split a location into the entry's key and the path inside the entry."""
    n = 1 if name not in SECTIONED else 2
    return tuple(loc[:n]), tuple(loc[n:])


def _dotted(parts: tuple[Any, ...]) -> str:
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


def _fail(source: Source, name: str, loc: tuple[Any, ...], msg: str) -> KnowledgeError:
    key, rest = _where(name, loc)
    what = f"{_dotted(rest)}: {msg}" if rest else msg
    return KnowledgeError(f"{source(name, loc)}: {_dotted(key) or 'top level'}: {what}")


def _params_problem(rule: str, params: dict[str, Any]) -> str | None:
    """What is wrong with ``params`` for ``rule`` (its model in anyhome.layout.rules), or None."""
    from anyhome.layout.rules import params_problem

    if (bad := params_problem(rule, params)) is None:
        return None
    return f"{bad.where}: {bad.what} for {rule} (its parameters: {bad.known})"


def validate_file(name: str, data: Any, source: Source) -> BaseModel:
    """The model of one knowledge file's (merged) content, or a :class:`KnowledgeError`
    naming the first bad entry."""
    try:
        return FILE_MODELS[name].model_validate(data)
    except ValidationError as e:
        err = e.errors()[0]
        n = 1 if name not in SECTIONED else 2
        loc = tuple(err["loc"][:n]) + tuple(x for x in err["loc"][n:] if not _is_tag(x))
        raise _fail(source, name, loc, _message(err)) from None


def _is_tag(part: Any) -> bool:
    """True for the parts pydantic adds to a location inside a union ("int",
    "tuple[int, int]", "function-after[...]"): they are no field of the file."""
    return isinstance(part, str) and (part in {"int", "float", "str", "bool", "list", "dict", "none"} or "[" in part
                                      or part.startswith(("constrained-", "function-")))


def _message(err: Mapping[str, Any]) -> str:
    msg = str(err["msg"]).removeprefix("Value error, ")
    if err["type"] == "extra_forbidden":
        return "unknown field (misspelt?)"
    if err["type"] == "literal_error" and "rule" in [str(x) for x in err["loc"]][-1:]:
        return f"unknown rule {err.get('input')!r} (known: {', '.join(RULES)})"
    if err["type"] == "missing":
        return "missing (required)"
    return msg


# ------------------------------------------------------------------ the whole base
class KnowledgeBase:
    """The knowledge files, validated, with every reference between them checked."""

    def __init__(self, raw: Mapping[str, Any], source: Source) -> None:
        self.source = source
        self._raw = raw
        self.programs: ProgramsFile = validate_file("programs", raw["programs"], source)  # type: ignore[assignment]
        self.rooms: RoomsFile = validate_file("rooms", raw["rooms"], source)  # type: ignore[assignment]
        objects: ObjectsFile = validate_file("objects", raw["objects"], source)  # type: ignore[assignment]
        self.objects: dict[str, ObjectProto] = objects.root
        self.furniture: FurnitureFile = validate_file("furniture", raw["furniture"], source)  # type: ignore[assignment]
        self.styles: StylesFile = validate_file("styles", raw["styles"], source)  # type: ignore[assignment]
        self.concepts: ConceptsFile = validate_file("concepts", raw["concepts"], source)  # type: ignore[assignment]
        self.surfaces: SurfacesFile = validate_file("surfaces", raw["surfaces"], source)  # type: ignore[assignment]
        self.assets: AssetsFile = validate_file("assets", raw["assets"], source)  # type: ignore[assignment]
        self.colours: ColoursFile = validate_file("colours", raw["colours"], source)  # type: ignore[assignment]
        self.materials: MaterialsFile = validate_file("materials", raw["materials"], source)  # type: ignore[assignment]
        self.heights: HeightsFile = validate_file("heights", raw["heights"], source)  # type: ignore[assignment]
        self._check_references()

    def raw(self, name: str) -> dict[str, Any]:
        """The merged content of ``<name>.yaml`` as plain mappings (what the planner reads)."""
        return self._raw[name]

    def _bad(self, name: str, loc: tuple[Any, ...], msg: str) -> KnowledgeError:
        return _fail(self.source, name, loc, msg)

    def _check_item_params(self, it: GroupItem, name: str, loc: tuple[Any, ...]) -> None:
        """A group item's ``params`` against the rule it is placed by (its own, else its
        prototype's)."""
        proto = self.objects.get(it.use or "")
        rule = it.rule or (proto.rule if proto is not None else None)
        if it.params and rule is not None and (bad := _params_problem(rule, it.params)) is not None:
            raise self._bad(name, loc, bad)

    def _check_sizes(self, need: Callable[..., None], known: Callable[..., str], types: set[str]) -> None:
        """programs.yaml ``sizes``; a kind's area ranges start at their type's min_area_m2 or above."""
        least = {t: rt.min_area_m2 for t, rt in self.rooms.types.items()}
        programs = self.programs.programs
        if (st := self.programs.storeys) is not None:
            for part in ("up", "basement", "attic"):
                for i, t in enumerate(getattr(st, part)):
                    need(t in types, "programs", ("storeys", part, i), lambda: known(t, types, "room type"))
        sz = self.programs.sizes
        if sz is None:
            return
        for i, h in enumerate(sz.homes):
            need(h in programs, "programs", ("sizes", "homes", i), lambda: known(h, programs, "program"))
        need(sz.compact.program in programs, "programs", ("sizes", "compact", "program"), lambda: known(sz.compact.program, programs, "program"))
        for i, a in enumerate(sz.add):
            need(a.type in types, "programs", ("sizes", "add", i, "type"), lambda: known(a.type, types, "room type"))
        for k, kind in sz.kinds.items():
            for t, rng in kind.areas.items():
                need(t in types, "programs", ("sizes", "kinds", k, "areas", t), lambda: known(t, types, "room type"))
                need(rng[0] >= least.get(t, 0.0), "programs", ("sizes", "kinds", k, "areas", t),
                     f"starts below the type's min_area_m2 ({least.get(t)} m2)")
            for t in kind.counts:
                need(t in types, "programs", ("sizes", "kinds", k, "counts", t), lambda: known(t, types, "room type"))
            for i, a in enumerate(kind.add or []):
                need(a.type in types, "programs", ("sizes", "kinds", k, "add", i, "type"), lambda: known(a.type, types, "room type"))

    def _check_references(self) -> None:  # noqa: C901 - one check per reference, in file order
        from anyhome.house import ROOM_TYPES

        types = set(ROOM_TYPES)
        groups, sets = self.furniture.groups, self.furniture.sets
        programs, styles, objects = self.programs.programs, self.styles.styles, self.objects
        furnish_names = {n.furnish for n in self.rooms.names.values() if n.furnish}
        furnish_names |= {r.furnish for p in programs.values() for r in p.rooms if r.furnish}
        room_refs = types | set(sets) | furnish_names | set(programs)

        def need(ok: bool, name: str, loc: tuple[Any, ...], msg: str | Callable[[], str]) -> None:
            if not ok:  # the message (close matches: slow) only for an entry that fails
                raise self._bad(name, loc, msg() if callable(msg) else msg)

        def known(v: str, pool: Any, what: str) -> str:
            near = difflib.get_close_matches(v, [str(p) for p in pool], n=3, cutoff=0.6)
            if near:
                return f"unknown {what} {v!r} (did you mean {' or '.join(repr(x) for x in near)}?)"
            return f"unknown {what} {v!r} ({len(pool)} known, e.g. {', '.join(sorted(map(str, pool))[:5])})"

        # programs.yaml
        for i, b in enumerate(self.programs.buildings):
            need(b.program in programs, "programs", ("buildings", i, "program"), lambda: known(b.program, programs, "program"))
            for s in b.styles:
                need(s in styles, "programs", ("buildings", i, "styles"), lambda: known(s, styles, "style"))
            if b.kind is not None:
                kinds = self.programs.sizes.kinds if self.programs.sizes else {}
                need(b.kind in kinds, "programs", ("buildings", i, "kind"), lambda: known(str(b.kind), kinds, "building kind (sizes.kinds)"))
        if (conv := self.programs.conversions) is not None:
            need(conv.program in {b.program for b in self.programs.buildings}, "programs", ("conversions", "program"),
                 lambda: known(conv.program, programs, "program with building words"))
            for k, look in conv.keeps.items():
                need(k in programs, "programs", ("conversions", "keeps", k), lambda: known(k, programs, "program"))
                for s in look.styles:
                    need(s in styles, "programs", ("conversions", "keeps", k, "styles"), lambda: known(s, styles, "style"))
                for j, it in enumerate(look.ornaments):
                    need(it.use in objects, "programs", ("conversions", "keeps", k, "ornaments", j, "use"),
                         lambda: known(str(it.use), objects, "object"))
        self._check_sizes(need, known, types)
        for key, p in programs.items():
            for t in p.entrance:
                need(t in types, "programs", ("programs", key, "entrance"), lambda: known(t, types, "room type"))
            for j, r in enumerate(p.rooms):
                need(r.type in types, "programs", ("programs", key, "rooms", j, "type"), lambda: known(r.type, types, "room type"))
                if r.furnish is not None:
                    need(r.furnish in sets, "programs", ("programs", key, "rooms", j, "furnish"), lambda: known(str(r.furnish), sets, "furnishing set"))
            if p.main_beside_bedrooms is not None:
                need(p.main_beside_bedrooms in sets, "programs", ("programs", key, "main_beside_bedrooms"),
                     lambda: known(str(p.main_beside_bedrooms), sets, "furnishing set"))
            for t in p.holds:
                need(t in types, "programs", ("programs", key, "holds"), lambda: known(t, types, "room type"))
            for room, gs in p.extra.items():
                for g in gs:
                    need(g in groups, "programs", ("programs", key, "extra", room), lambda: known(g, groups, "group"))
            for word, obj in p.object_words.items():
                for said in (word, obj):
                    need(said in objects, "programs", ("programs", key, "object_words", word),
                         f"unknown object {said!r} (object_words names objects.yaml keys)")
            for item, sw in p.swap.items():
                need(sw.use in objects, "programs", ("programs", key, "swap", item, "use"),
                     lambda: known(sw.use, objects, "object prototype"))
        # rooms.yaml
        for t, rt in self.rooms.types.items():
            need(t in types, "rooms", ("types", t),
                 lambda: known(t, types, "room type (the types are those of the shipped rooms.yaml)"))
            need(rt.habitable == ROOM_TYPES[t], "rooms", ("types", t, "habitable"),
                 f"is {str(ROOM_TYPES[t]).lower()} in the shipped rooms.yaml; an overlay may not change it")
            for a in rt.attach:
                need(a in types, "rooms", ("types", t, "attach"), lambda: known(a, types, "room type"))
            need(rt.min_area_m2 >= rt.min_width_m**2 - 1e-9, "rooms", ("types", t, "min_area_m2"),
                 f"{rt.min_area_m2} m2 is less than a square of its min_width_m ({rt.min_width_m ** 2:.2f} m2)")
            need(rt.area[0] >= rt.min_area_m2, "rooms", ("types", t, "area"), f"starts below min_area_m2 ({rt.min_area_m2} m2)")
        for n, rn in self.rooms.names.items():
            for prog_key in [*rn.within, *rn.only_within]:
                need(prog_key in programs, "rooms", ("names", n, "within", prog_key),
                     lambda: known(prog_key, programs, "program"))
            senses = [((), rn), (("at_home",), rn.at_home), *((("within", k), v) for k, v in rn.within.items())]
            for where, sense in senses:
                if sense is None:
                    continue
                need(sense.type in types, "rooms", ("names", n, *where, "type"), lambda: known(sense.type, types, "room type"))
                if sense.furnish is not None:
                    need(sense.furnish in sets, "rooms", ("names", n, *where, "furnish"),
                         lambda: known(str(sense.furnish), sets, "furnishing set"))
        # objects.yaml
        for k, o in objects.items():
            if o.group is not None:
                need(o.group in groups, "objects", (k, "group"), lambda: known(str(o.group), groups, "group"))
            for ref in o.rooms:
                need(ref in room_refs, "objects", (k, "rooms"), lambda: known(ref, room_refs, "room type or furnishing"))
            if (bad := _params_problem(o.rule, o.params)) is not None:
                raise self._bad("objects", (k, "params"), bad)
        # furniture.yaml
        for g, grp in groups.items():
            for j, it in enumerate([grp.anchor, *grp.members]):
                loc = ("groups", g, "anchor") if j == 0 else ("groups", g, "members", j - 1)
                need(it.use is not None, "furniture", loc, "missing use (the object prototype)")
                need(it.use in objects, "furniture", (*loc, "use"), lambda: known(str(it.use), objects, "object"))
                self._check_item_params(it, "furniture", (*loc, "params"))
            for host in grp.join:
                need(host in groups, "furniture", ("groups", g, "join"), lambda: known(host, groups, "group"))
        need("other" in sets, "furniture", ("sets",), "needs a set named 'other' (rooms with no set of their own)")
        for s, fs in sets.items():
            for j, e in enumerate(fs.groups):
                for g in e.one_of or [str(e.group)]:
                    need(g in groups, "furniture", ("sets", s, "groups", j), lambda: known(str(g), groups, "group"))
                for part in [e.anchor, *(e.members or [])]:
                    if part is not None and part.use is not None:
                        use = part.use
                        need(use in objects, "furniture", ("sets", s, "groups", j, "use"), lambda: known(use, objects, "object"))
                for part in [e.anchor, *(e.members or [])]:
                    if part is not None:
                        self._check_item_params(part, "furniture", ("sets", s, "groups", j, "params"))
            for j, it in enumerate(fs.ornaments):
                need(it.use is not None, "furniture", ("sets", s, "ornaments", j), "missing use (the object prototype)")
                need(it.use in objects, "furniture", ("sets", s, "ornaments", j, "use"), lambda: known(str(it.use), objects, "object"))
                self._check_item_params(it, "furniture", ("sets", s, "ornaments", j, "params"))
        for z, entries in self.furniture.zones.items():
            need(z in sets or z in types, "furniture", ("zones", z), lambda: known(z, sets, "furnishing set"))
            for j, e in enumerate(entries):
                for g in e.one_of or [str(e.group)]:
                    need(g in groups, "furniture", ("zones", z, j), lambda: known(str(g), groups, "group"))
                for part in [e.anchor, *(e.members or [])]:
                    if part is not None:
                        self._check_item_params(part, "furniture", ("zones", z, j, "params"))
        # styles.yaml
        classes = self.styles.asset_classes
        need("plain" in classes, "styles", ("asset_classes",), "needs the 'plain' class (no particular look)")
        for k, st in styles.items():
            need(st.asset_class in classes, "styles", ("styles", k, "asset_class"), lambda: known(st.asset_class, classes, "asset class"))
            if k in classes:
                need(st.asset_class == k, "styles", ("styles", k, "asset_class"), f"a style named like the class {k!r} must use it")
        for prog, keys in self.styles.defaults.items():
            for s in keys:
                need(s in styles, "styles", ("defaults", prog), lambda: known(s, styles, "style"))
        # assets.yaml: nothing a prototype already says
        proto_words = {word_key(w): k for k, o in objects.items() for w in (k, *o.synonyms)}
        for w in self.assets.words:
            need(w not in proto_words, "assets", ("words", w),
                 lambda: f"is a word of the object prototype {proto_words[w]!r} (objects.yaml), which gives its family; "
                         "keep it in one place")
        covers = {o.category: k for k, o in objects.items()} | {word_key(k): k for k in objects}
        for f in self.assets.sizes:
            need(f not in covers, "assets", ("sizes", f),
                 lambda: f"the object prototype {covers[f]!r} (objects.yaml) gives this family's size; keep it in one place")
        # colours.yaml: a word is a colour or a shading word, not both
        for w in self.colours.colours:
            need(w not in self.colours.modifiers and w not in self.colours.muting, "colours", ("colours", w),
                 "is also a modifier or muting word; keep it in one place")
        self._check_materials()
        # concepts.yaml
        for kind, pool, what in (("rooms", sets, "furnishing set"), ("objects", objects, "object"), ("buildings", programs, "program")):
            for k in getattr(self.concepts, kind):
                need(k in pool, "concepts", (kind, k), lambda: known(k, pool, what))

    def _check_materials(self) -> None:
        """materials.yaml: every kind named exists; a phrase without a kind is known by its words."""
        m = self.materials
        kinds = set(m.kinds)

        def bad(loc: tuple[Any, ...], msg: str) -> KnowledgeError:
            return self._bad("materials", loc, msg)

        def known(k: str) -> str:
            near = difflib.get_close_matches(k, sorted(kinds), n=2, cutoff=0.6)
            hint = f"did you mean {' or '.join(map(repr, near))}?" if near else f"known: {', '.join(sorted(kinds))}"
            return f"unknown kind {k!r} ({hint})"

        with_kind = {tuple(material_words(w)) for w, e in m.words.items() if e.kind is not None}
        longest = max((len(w) for w in with_kind), default=1)
        for w, e in m.words.items():
            for surface in ("", "floor", "walls", "ceiling", "furniture"):
                look = getattr(e, surface) if surface else e
                if look is not None and look.kind is not None and look.kind not in kinds:
                    raise bad(("words", w, *((surface,) if surface else ()), "kind"), known(look.kind))
            if e.color is not None and w in self.colours.colours:
                raise bad(("words", w, "color"), "is a colour word of colours.yaml, which gives its RGB; keep it in one place")
            if e.kind is None:
                ws = material_words(w)
                grams = {tuple(ws[i:i + n]) for n in range(1, longest + 1) for i in range(len(ws) - n + 1)}
                if not grams & with_kind:
                    raise bad(("words", w), "names no material word with a kind (give it a kind)")
        for s, rule in m.surfaces.items():
            for a, b in rule.becomes.items():
                for k in (a, b):
                    if k not in kinds:
                        raise bad(("surfaces", s, "becomes", a), known(k))
