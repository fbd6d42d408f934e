"""Sanity of the knowledge files: every rule valid, sizes positive, names known."""

import numpy as np
import pytest

from anyhome.house import ROOM_TYPES
from anyhome.plan import furnish
from anyhome.plan.knowledge import KNOWLEDGE_FILES, knowledge_base, load, vocabulary
from anyhome.plan.spec import RULES, GroupSpec, ItemSpec

OBJECTS = load("objects")
GROUPS = load("furniture")["groups"]
SETS = load("furniture")["sets"]


def test_files_load():
    for name in KNOWLEDGE_FILES:
        assert load(name)
    vocabulary()


@pytest.mark.parametrize("key", sorted(OBJECTS))
def test_object_prototypes(key):
    p = OBJECTS[key]
    assert p["category"] and p["category"] == p["category"].lower() and " " not in p["category"]
    assert len(p["size"]) == 3 and all(0.005 <= s <= 20 for s in p["size"])
    assert p["rule"] in RULES
    for room in p.get("rooms", []):
        assert room in ROOM_TYPES or room in SETS or room in ("museum", "parlor", "reading_nook", "music_room", "meditation_room", "yoga_room", "cat_room", "art_studio", "nap_room", "game_room")
    if p.get("group"):
        assert p["group"] in GROUPS


def _items(d):
    return [d.get("anchor", {}), *d.get("members", [])]


@pytest.mark.parametrize("key", sorted(GROUPS))
def test_group_templates(key):
    g = GROUPS[key]
    for it in _items(g):
        assert it.get("use") in OBJECTS
        assert it.get("rule", OBJECTS[it["use"]]["rule"]) in RULES
        assert all(s > 0 for s in it.get("size", [1, 1, 1]))


@pytest.mark.parametrize("key", sorted(SETS))
def test_sets_build_valid_specs(key):
    rng = np.random.default_rng(0)
    for entry in SETS[key].get("groups", []):
        for name in entry.get("one_of", [entry.get("group")]):
            assert name in GROUPS, name
    for _ in range(3):
        groups, ornaments, _ = furnish.furnish_room(knowledge_base(), key, "other", 20.0, rng)
        for g in groups:
            g = dict(g)
            GroupSpec(**{**g, "anchor": ItemSpec(**g["anchor"]), "members": [ItemSpec(**m) for m in g["members"]]})
        for o in ornaments:
            assert ItemSpec(**o).rule in ("place_top", "place_on_wall")


def test_room_vocabulary_types():
    rooms = load("rooms")
    for t in rooms["types"]:
        assert t in ROOM_TYPES
    for name, info in rooms["names"].items():
        assert info["type"] in ROOM_TYPES, name
        if "furnish" in info:
            assert info["furnish"] in SETS, name


def test_programs():
    progs = load("programs")
    for b in progs["buildings"]:
        assert b["program"] in progs["programs"]
        for s in b.get("styles", []):
            assert s in load("styles")["styles"]
    for key, p in progs["programs"].items():
        assert p["rooms"], key
        for r in p["rooms"]:
            assert r["type"] in ROOM_TYPES
            assert r.get("furnish", r["type"]) in SETS or r["type"] in SETS


def test_no_knowledge_file_names_a_key_twice():
    """YAML keeps the last of two equal keys silently: a phrase written twice loses one sense."""
    from pathlib import Path

    import yaml

    import anyhome.plan.knowledge as knowledge_module

    class Strict(yaml.SafeLoader):
        pass

    def mapping(loader, node):
        keys = [loader.construct_object(k) for k, _ in node.value]
        twice = {k for k in keys if keys.count(k) > 1}
        assert not twice, f"line {node.start_mark.line + 1}: {sorted(map(str, twice))} twice"
        return dict(loader.construct_pairs(node))

    Strict.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, mapping)
    folder = Path(knowledge_module.__file__).parent / "knowledge"
    files = sorted(folder.glob("*.yaml"))
    assert files
    for f in files:
        yaml.load(f.read_text(encoding="utf-8"), Loader=Strict)
