"""The knowledge base is passed explicitly to the stages (issue 12): two knowledge bases
in one process give different houses for the same text, with no environment variable and
no ``use_knowledge``; the default still honours ``$ANYHOME_KNOWLEDGE_PATH``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import anyhome
from anyhome.plan.knowledge import ENV_VAR, knowledge_base, overlay

TREEHOUSE = {
    "objects.yaml": "hammock stand: {category: hammock, size: [1.0, 3.2, 1.2], rule: place_center, "
    "rooms: [hammock_deck, balcony], synonyms: [hammock frame], group: hammock}\n",
    "furniture.yaml": "groups:\n  hammock: {anchor: {use: hammock stand}}\n"
    "sets:\n  hammock_deck: {groups: [{group: hammock}]}\n",
    "rooms.yaml": "names:\n  hammock deck: {type: balcony, furnish: hammock_deck, area: [6, 9]}\n",
    "programs.yaml": "buildings:\n  - {words: [treehouse, tree house], program: treehouse, styles: [rustic]}\n"
    "programs:\n  treehouse:\n    building: treehouse\n    main: cabin\n    entrance: [living_room]\n"
    "    rooms:\n      - {key: cabin, type: living_room, name: cabin}\n"
    "      - {key: deck, type: balcony, name: hammock deck, furnish: hammock_deck}\n",
    # the haunted style's assets look futuristic in this knowledge base
    "styles.yaml": "styles:\n  haunted: {asset_class: futuristic}\n",
}
TEXT = "a haunted treehouse with a hammock stand"


def _folder(root: Path) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    for name, text in TREEHOUSE.items():
        (root / name).write_text(text, encoding="utf-8")
    return root


pytestmark = pytest.mark.usefixtures("no_knowledge_overlay")  # tests/conftest.py


def _classes(house: anyhome.House) -> set[str]:
    return {o.asset["params"]["style"] for o in house.objects if o.asset}


def test_two_knowledge_bases_in_one_process_give_different_houses(tmp_path):
    shipped = knowledge_base([])
    user = knowledge_base([str(_folder(tmp_path / "kb"))])
    assert overlay() == ()  # nothing in force: the knowledge travels only as an argument
    a = anyhome.generate(TEXT, seed=0, knowledge=user)
    b = anyhome.generate(TEXT, seed=0, knowledge=shipped)
    a2 = anyhome.generate(TEXT, seed=0, knowledge=user)  # no table of one leaks into the other
    assert a.to_json() == a2.to_json()
    assert a.to_json() != b.to_json()
    assert "hammock deck" in {r.name for r in a.rooms} and "hammock deck" not in {r.name for r in b.rooms}
    # the default (nothing passed, nothing in force) is the shipped knowledge
    assert anyhome.generate(TEXT, seed=0).to_json() == b.to_json()


def test_the_assets_stage_reads_the_knowledge_base_passed_in(tmp_path):
    user = knowledge_base([str(_folder(tmp_path / "kb"))])
    house = anyhome.generate("a haunted bedroom", seed=0, knowledge=knowledge_base([]))
    assert house.styles[0] == "haunted" and _classes(house) == {"gothic"}
    again = anyhome.generate_from_spec(house.plan, seed=0, knowledge=user)
    assert _classes(again) == {"futuristic"}
    assert [o.position for o in again.objects] == [o.position for o in house.objects]
    assert _classes(anyhome.relayout(house, seed=0, knowledge=user)) == {"futuristic"}
    assert _classes(anyhome.restyle(house, "haunted", knowledge=user)) == {"futuristic"}
    assert _classes(anyhome.restyle(house, "haunted")) == {"gothic"}


def test_default_knowledge_honours_the_environment_variable(tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(_folder(tmp_path / "kb")))
    house = anyhome.generate(TEXT, seed=0)
    assert "hammock deck" in {r["name"] for r in json.loads(house.to_json())["rooms"]}


def test_knowledge_must_be_a_knowledge_base():
    with pytest.raises(anyhome.AnyHomeError, match="knowledge must be a KnowledgeBase"):
        anyhome.generate("a kitchen", knowledge="kb")  # type: ignore[arg-type]


# A user knowledge base with a brand-new asset class, a style that uses it, and a new
# object whose name holds a shipped word ("couch": a sofa, tags [seat]) but whose own tags
# differ. Passed only as an argument: nothing in force knows any of it.
NEON = {
    "styles.yaml": "asset_classes:\n"
    "  neon: {traits: [modern], legs: [metal], woods: ['#ff10f0', '#f011ff'], fabrics: ['#00ffe1', '#10ffd0']}\n"
    "styles:\n"
    "  cyberpunk: {words: [cyberpunk, neon noir], describe: 'cyberpunk, neon and chrome', "
    "palette: [black, neon pink], floor: polished concrete, walls: black paint, ceiling: black paint, "
    "furniture: glossy lacquer, asset_class: neon}\n",
    "objects.yaml": "hover couch: {category: sofa, size: [2.0, 0.9, 0.8], rule: place_wall, rooms: [bedroom], "
    "tags: [seat, light_source]}\n",
}
NEON_COLOURS = {"#ff10f0", "#f011ff", "#00ffe1", "#10ffd0"}


def _neon(root: Path) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    for name, text in NEON.items():
        (root / name).write_text(text, encoding="utf-8")
    return root


def test_a_new_asset_class_and_new_tags_reach_the_stages_when_passed_explicitly(tmp_path):
    from anyhome.assets import build_object_mesh
    from anyhome.tags import tags_for

    user = knowledge_base([str(_neon(tmp_path / "kb"))])
    house = anyhome.generate("a cyberpunk bedroom with a hover couch", seed=0, knowledge=user)
    assert overlay() == ()
    assert house.styles[0] == "cyberpunk"
    assert _classes(house) == {"neon"}  # the new class, not the plain one a global lookup finds
    # the factories drew their colours from the new class
    hexes = {"#%02x%02x%02x" % tuple(int(c) for c in rgb)
             for o in house.objects for rgb in build_object_mesh(o, user).visual.face_colors[:, :3]}
    assert NEON_COLOURS & hexes
    # the planner's tags of the new object are the user's, not the shipped sofa's
    couch = [o for o in house.objects if o.name == "hover couch"]
    assert couch and all(set(o.tags) == {"seat", "light_source"} for o in couch)
    assert set(tags_for("hover couch", "sofa", user)) == {"seat", "light_source"}
    assert set(tags_for("hover couch", "sofa", knowledge_base([]))) == {"seat"}
    # a spec without tags (as the LLM planner writes it) derives them in the kb passed in
    plan = json.loads(json.dumps(house.plan))
    for room in plan["rooms"]:
        for group in room["groups"]:
            for item in [group["anchor"], *group["members"]]:
                item.pop("tags", None)
    again = anyhome.generate_from_spec(plan, seed=0, knowledge=user)
    assert {tuple(sorted(o.tags)) for o in again.objects if o.name == "hover couch"} == {("light_source", "seat")}
    assert _classes(again) == {"neon"}


def test_materials_and_asset_words_read_the_knowledge_base_passed_in(tmp_path):
    from anyhome.assets.catalog import knowledge_map
    from anyhome.assets.colors import material_color
    from anyhome.assets.registry import family_for
    from anyhome.materials.catalog import surface_material

    root = _neon(tmp_path / "kb")
    (root / "materials.yaml").write_text(
        "words:\n  neonite: {kind: metal, color: '#12ff34', goes_on: [furniture, floor]}\n", encoding="utf-8")
    user, shipped = knowledge_base([str(root)]), knowledge_base([])
    assert material_color("neonite", user) == "#12ff34" and material_color("neonite", shipped) is None
    assert surface_material("neonite", "floor", 8, kb=user).color == "#12ff34"
    assert surface_material("neonite", "floor", 8, kb=shipped).color != "#12ff34"
    assert family_for("", "hover couch", user) == "sofa"
    assert "hover couch" in knowledge_map(user)["sofa"]["objects"]
    assert "hover couch" not in knowledge_map(shipped)["sofa"]["objects"]
