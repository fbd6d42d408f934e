"""The pydantic models of the knowledge files: the shipped files pass, and each kind of
bad entry is refused with ``FILE: KEY: what is wrong``."""

from __future__ import annotations

import copy

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome.errors import AnyHomeError, KnowledgeError
from anyhome.plan.kb import FILE_MODELS, KnowledgeBase, ObjectProto
from anyhome.plan.knowledge import KNOWLEDGE_DIR, KNOWLEDGE_FILES, knowledge_base, load
from anyhome.plan.spec import RULES

RAW = {name: load(name) for name in KNOWLEDGE_FILES}


def _source(name, loc):
    return f"{name}.yaml"


def _kb(**changes) -> KnowledgeBase:
    raw = copy.deepcopy(RAW)
    for name, fn in changes.items():
        fn(raw[name])
    return KnowledgeBase(raw, _source)


def test_shipped_knowledge_is_valid():
    kb = knowledge_base()
    assert set(FILE_MODELS) == set(KNOWLEDGE_FILES)
    assert len(kb.objects) == len(RAW["objects"])
    assert set(kb.furniture.sets) == set(RAW["furniture"]["sets"])
    assert issubclass(KnowledgeError, AnyHomeError)


def test_no_style_has_stray_fields():
    # "furniture: lacquered wood, velvet and brass" in a YAML flow mapping made
    # "velvet and brass" a key of its own and cut the furniture material short
    fields = set(FILE_MODELS["styles"].model_fields["styles"].annotation.__args__[1].model_fields)
    for key, style in RAW["styles"]["styles"].items():
        assert set(style) <= fields, (key, set(style) - fields)
    assert RAW["styles"]["styles"]["hollywood_regency"]["furniture"] == "lacquered wood, velvet and brass"


BAD = {
    "size zero": (lambda o: o["chair"].update(size=[0.45, 0, 0.9]), "objects.yaml: chair: size[1]:"),
    "two sizes": (lambda o: o["chair"].update(size=[0.45, 0.9]), "objects.yaml: chair: size"),
    "bad rule": (lambda o: o["chair"].update(rule="place_anywhere"), "chair: rule: unknown rule"),
    "bad plural": (lambda o: o["chair"].update(plural=[6, 4]), "chair: plural: a range [lo, hi] needs lo <= hi"),
    "bad category": (lambda o: o["chair"].update(category="Dining Chair"), "chair: category:"),
    "unknown group": (lambda o: o["sofa"].update(group="lounges"), "sofa: group: unknown group 'lounges' (did you mean"),
    "unknown room": (lambda o: o["sofa"].update(rooms=["living room"]), "sofa: rooms: unknown room type or furnishing"),
    "tags not a list": (lambda o: o["sofa"].update(tags="seat"), "sofa: tags:"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_object_entries(case):
    change, expected = BAD[case]
    with pytest.raises(KnowledgeError) as e:
        _kb(objects=change)
    assert expected in str(e.value)
    assert "\n" not in str(e.value)


def test_tags_are_accepted():
    kb = _kb(objects=lambda o: o["sofa"].update(tags=["seat", "storage"]))
    assert kb.objects["sofa"].tags == ["seat", "storage"]


@pytest.mark.parametrize("name,change,expected", [
    ("rooms", lambda r: r["types"]["kitchen"].update(area=[0, 10]), "rooms.yaml: types.kitchen: area[0]:"),
    ("rooms", lambda r: r["types"].update(ballroom=r["types"]["hall"]), "types.ballroom: unknown room type"),
    ("rooms", lambda r: r["names"]["sauna"].update(furnish="saunas") if "sauna" in r["names"]
     else r["names"].update(sauna={"type": "bathroom", "furnish": "saunas"}), "names.sauna: furnish: unknown furnishing set"),
    ("programs", lambda p: p["programs"]["home"].update(main="lounge"), "programs.home: main 'lounge' is not"),
    ("programs", lambda p: p["programs"]["home"]["rooms"][0].update(count=-1), "programs.home: rooms[0].count:"),
    ("programs", lambda p: p["buildings"][0].update(program="homes"), "programs.yaml: buildings[0]: program: unknown program"),
    ("furniture", lambda f: f["groups"]["bed"]["members"][0].update(rule="beside"), "groups.bed: members[0].rule: unknown rule"),
    ("furniture", lambda f: f["groups"]["bed"]["anchor"].update(use="bedd"), "groups.bed: anchor.use: unknown object 'bedd'"),
    ("furniture", lambda f: f["groups"]["bed"].update(arrangement="scattered"), "groups.bed: arrangement:"),
    ("furniture", lambda f: f["sets"]["bedroom"]["groups"].append({"group": "nope"}), "sets.bedroom: groups[7]: unknown group"),
    ("furniture", lambda f: f["sets"]["bedroom"]["groups"][0].update(prob=1.5), "sets.bedroom: groups[0].prob:"),
    ("furniture", lambda f: f["sets"].pop("other"), "furniture.yaml: sets: needs a set named 'other'"),
    ("styles", lambda s: s["styles"]["gothic"].update(asset_class="goth"), "styles.gothic: asset_class: unknown asset class"),
    ("styles", lambda s: s["asset_classes"]["gothic"].update(woods=["brown"]), "asset_classes.gothic: woods[0]:"),
    ("styles", lambda s: s["asset_classes"]["gothic"].update(legs=["claw"]), "asset_classes.gothic: legs[0]:"),
    ("materials", lambda m: m["words"]["oak"].update(goes_on=["table"]), "materials.yaml: words.oak: goes_on[0]:"),
    ("materials", lambda m: m["words"]["oak"].update(kind="wod"), "words.oak: kind: unknown kind 'wod' (did you mean 'wood'?)"),
    ("materials", lambda m: m["words"]["oak"].update(roughness=1.5), "words.oak: roughness:"),
    ("materials", lambda m: m["words"]["brass"].update(color="#be9f52"), "words.brass: color: is a colour word of colours.yaml"),
    ("materials", lambda m: m["words"]["oak"].update(color="brown"), "words.oak: color:"),
    ("materials", lambda m: m["words"].update(cork={"goes_on": ["floor"]}), "words.cork: names no material word with a kind"),
    ("materials", lambda m: m["words"].update(cork={"kind": "plain"}) or m["words"]["cork"].update(rank="best"), "words.cork: rank:"),
    ("materials", lambda m: m["surfaces"]["floor"]["becomes"].update(wood="parquet"), "surfaces.floor: becomes.wood: unknown kind 'parquet'"),
    ("styles", lambda s: s["category_materials"].update(sofa="{color} velvet"), "category_materials:"),
    ("styles", lambda s: s["defaults"].update(home=["modrn"]), "defaults.home: unknown style 'modrn'"),
    ("concepts", lambda c: c["objects"].update(hammock_swing=["swing"]), "concepts.yaml: objects.hammock_swing: unknown object"),
    ("concepts", lambda c: c["fallback_object"].update(rule="place_somewhere"), "fallback_object.rule: unknown rule"),
])
def test_bad_entries_in_every_file(name, change, expected):
    with pytest.raises(KnowledgeError) as e:
        _kb(**{name: change})
    msg = str(e.value)
    assert msg.startswith(f"{name}.yaml: "), msg
    assert expected in msg, msg


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(min_value=-5, max_value=30, allow_nan=False), min_size=3, max_size=3),
       st.sampled_from(RULES + ("place_nowhere",)))
def test_object_size_and_rule(size, rule):
    ok = all(0.005 <= s <= 20 for s in size) and rule in RULES
    try:
        ObjectProto.model_validate({"category": "thing", "size": size, "rule": rule})
    except ValueError:
        assert not ok
    else:
        assert ok


def test_shipped_files_live_where_load_reads_them():
    for name in KNOWLEDGE_FILES:
        assert (KNOWLEDGE_DIR / f"{name}.yaml").is_file()


def test_object_tags_are_from_the_closed_set(tmp_path, monkeypatch):
    """A user object with a tag outside anyhome.tags.TAGS is one KnowledgeError naming it."""
    import pytest as _pytest

    from anyhome.errors import KnowledgeError
    from anyhome.plan.knowledge import knowledge_base, use_knowledge

    (tmp_path / "objects.yaml").write_text(
        "hammock:\n  category: hammock\n  size: [1, 3, 1]\n  rule: place_center\n  tags: [seat, comfy]\n")
    try:
        with _pytest.raises(KnowledgeError, match=r"objects.yaml: hammock"):
            use_knowledge([tmp_path])
            knowledge_base()
    finally:
        use_knowledge([])


def test_surfaces_file_is_checked(tmp_path):
    from anyhome.errors import KnowledgeError
    from anyhome.plan.knowledge import knowledge_base, use_knowledge

    (tmp_path / "surfaces.yaml").write_text("roof: [roof, tiles]\n")
    try:
        with pytest.raises(KnowledgeError, match=r"surfaces.yaml: roof"):
            use_knowledge([tmp_path])
            knowledge_base()
    finally:
        use_knowledge([])


def test_storeys_name_known_room_types_and_say_which_rooms_go_up():
    import numpy as np

    from anyhome.plan.offline import OfflinePlanner

    with pytest.raises(KnowledgeError, match=r"programs.yaml: storeys.up: \[1\]: unknown room type .ballroomz."):
        _kb(programs=lambda p: p["storeys"].__setitem__("up", ["bedroom", "ballroomz"]))
    text = "a two-storey house with two bedrooms and a study"

    def levels(kb):
        spec = OfflinePlanner(kb).plan(text, np.random.default_rng(0))
        return {r.type: r.level for r in spec.rooms if r.type in ("bedroom", "study")}

    assert levels(knowledge_base()) == {"bedroom": 1, "study": 1}
    # the file, not the code, decides: studies only upstairs keeps the bedrooms down
    assert levels(_kb(programs=lambda p: p["storeys"].__setitem__("up", ["study"]))) == {"bedroom": 0, "study": 1}
