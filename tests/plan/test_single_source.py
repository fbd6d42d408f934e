"""Issue 12: no fact is kept in two files. One test per fact class fails when a fact
reappears in a second place; broken entries of the new files are one CLI line, exit 2."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

import anyhome.house
from anyhome.assets import colors as asset_colors
from anyhome.assets.colors import material_color, to_hex
from anyhome.assets.registry import _tables, families, family_for, typical_size
from anyhome.house import ROOM_TYPES
from anyhome.plan.kb import word_key
from anyhome.plan.knowledge import KNOWLEDGE_DIR, knowledge_base, vocabulary

SRC = Path(anyhome.house.__file__).parent


def _proto_words() -> dict[str, str]:
    return {word_key(w): k for k, o in knowledge_base().objects.items() for w in (k, *o.synonyms)}


# ------------------------------------------------------------------ object words
def test_no_word_is_both_a_prototype_word_and_an_asset_word() -> None:
    kb = knowledge_base()
    both = sorted(set(kb.assets.words) & set(_proto_words()))
    assert both == []
    assert not (SRC / "assets" / "synonyms.yaml").exists()


def test_prototype_words_decide_the_family() -> None:
    # the prototype's word is built as the prototype's family, and nothing else says otherwise
    fams = set(families())
    for key, o in knowledge_base().objects.items():
        fam = word_key(key) if word_key(key) in fams else o.category
        if fam in fams:
            for w in o.synonyms:
                assert family_for("", w) == fam, (key, w)
    assert family_for("table", "billiard table") == "pool_table"
    assert family_for("cabinet", "arcade machine") == "arcade_cabinet"


def test_asset_words_and_categories_name_families() -> None:
    kb, fams = knowledge_base(), set(families())
    assert {f for f in kb.assets.words.values()} <= fams
    assert {f for f in kb.assets.categories.values()} <= fams
    assert not set(kb.assets.categories) & fams  # a family is its own category


# ------------------------------------------------------------------ sizes
def test_no_family_has_two_sizes() -> None:
    kb = knowledge_base()
    covered = {word_key(k) for k in kb.objects} | {o.category for o in kb.objects.values()}
    assert sorted(set(kb.assets.sizes) & covered) == []
    assert not (SRC / "assets" / "typical_sizes.yaml").exists()
    for key, o in kb.objects.items():
        if word_key(key) in families():
            assert typical_size(word_key(key)) == tuple(o.size), key
    assert set(families()) <= set(_tables(kb).sizes)


def test_beds_boxes_include_their_headboards() -> None:
    for key in ("bed", "bunk bed", "crib", "hospital bed"):
        assert knowledge_base().objects[key].size[2] >= 0.9, key


# ------------------------------------------------------------------ colours
def test_every_colour_word_has_one_rgb() -> None:
    kb = knowledge_base()
    text = (KNOWLEDGE_DIR / "colours.yaml").read_text(encoding="utf-8")
    keys = re.findall(r"^  ([^:#\n]+):", text.split("\nmodifiers:")[0], flags=re.M)
    assert len(keys) == len(set(keys)) == len(kb.colours.colours) >= 124
    for word, rgb in kb.colours.colours.items():
        assert material_color(word) == to_hex(rgb), word  # the assets read the same RGB
        assert vocabulary().colour_regex.fullmatch(word), word  # and the planner the same word
    styles = yaml.safe_load((KNOWLEDGE_DIR / "styles.yaml").read_text(encoding="utf-8"))
    assert "colours" not in styles
    assert not (Path(asset_colors.__file__).with_name("colors.yaml")).exists()
    # a word that is both a colour and a material ("brass") has its RGB in colours.yaml only
    both = set(kb.materials.words) & set(kb.colours.colours)
    assert both and not [w for w in both if kb.materials.words[w].color is not None]


def test_longest_colour_phrase_wins() -> None:
    rgb = knowledge_base().colours.colours
    assert material_color("sky blue velvet") == to_hex(rgb["sky blue"]) != to_hex(rgb["blue"])


# ------------------------------------------------------------------ material words
def test_no_material_word_is_in_two_tables() -> None:
    # styles.yaml (where the planner puts a word), assets/colors.yaml (its RGB) and
    # materials/materials.yaml (its look) were three tables that disagreed
    assert "materials" not in yaml.safe_load((KNOWLEDGE_DIR / "styles.yaml").read_text(encoding="utf-8"))
    assert not (SRC / "assets" / "colors.yaml").exists()
    assert not (SRC / "materials" / "materials.yaml").exists()
    text = (KNOWLEDGE_DIR / "materials.yaml").read_text(encoding="utf-8")
    keys = re.findall(r'^  ("[^"]+"|[^:#\n]+):', text.split("\nwords:\n")[1].split("\n\n")[0], flags=re.M)
    assert len(keys) == len(set(keys)) == len(knowledge_base().materials.words) >= 250


def test_every_planner_material_word_is_known_to_the_catalog() -> None:
    from anyhome.materials.catalog import material_clauses, surface_material

    kb = knowledge_base()
    planner = {w for w, e in kb.materials.words.items() if e.goes_on}
    assert len(planner) >= 160
    for word in planner:
        assert vocabulary().material_regex.fullmatch(word), word  # the planner finds it
        assert material_clauses(word), word  # and the catalog knows what it is
    # the words the planner knew and the renderer did not: now each has a kind of its own
    assert surface_material("soapstone", "furniture").kind == "stone"
    assert surface_material("corduroy", "furniture").kind == "fabric"
    assert surface_material("wainscoting", "walls").variant == "shiplap"
    assert surface_material("pine tongue and groove", "walls").variant == "shiplap"
    assert surface_material("shou sugi ban", "walls").color == "#2a2420"
    assert material_color("bouclé") == "#e6e1d4"


def test_a_material_word_has_one_colour_for_assets_and_surfaces() -> None:
    from anyhome.materials.catalog import surface_material

    for word, e in knowledge_base().materials.words.items():
        if e.color is not None:
            assert material_color(word) == e.color, word  # the assets' colour of the word
            tone = {"whitewashed", "charred", "smoked"} & set(word.split())
            if not tone:
                assert surface_material(word, "furniture").color == e.color, word  # the renderer's
    # a colour the material catalog alone knew now reaches the assets: a mirror is silver, not glass blue
    assert material_color("silvered glass") == knowledge_base().materials.words["silvered glass"].color
    assert material_color("silvered glass") != material_color("glass")
    # the first material decides when no colour is named; a colour word still beats a material
    assert material_color("rough-hewn oak and wrought iron") == material_color("oak")
    assert material_color("black wrought iron") == material_color("black")


def test_user_material_word_reaches_planner_catalog_and_colours(tmp_path: Path) -> None:
    from anyhome.materials.catalog import _tables_of

    (tmp_path / "materials.yaml").write_text(
        "words:\n  cork: {kind: plain, roughness: 0.8, color: '#b48c5f', goes_on: [floor]}\n"
        "  oak: {color: '#102030'}\n", encoding="utf-8")
    kb = knowledge_base([str(tmp_path)])
    assert kb.materials.words["oak"].kind == "wood"  # the overlay changed one field of oak
    assert kb.materials.words["oak"].color == "#102030"
    assert kb.materials.words["oak"].goes_on == ["furniture", "floor"]
    from anyhome.plan.kbview import vocabulary as kb_vocabulary

    assert kb_vocabulary(kb).material_regex.fullmatch("cork")
    assert _tables_of(kb).lexicon[("cork",)][1]["roughness"] == 0.8


# ------------------------------------------------------------------ room types
def test_room_types_are_one_list() -> None:
    types = knowledge_base().rooms.types
    assert list(ROOM_TYPES) == list(types)
    assert all(ROOM_TYPES[t] == rt.habitable for t, rt in types.items())
    assert not re.search(r'"bedroom":\s*True', (SRC / "house.py").read_text(encoding="utf-8"))
    # house.py reads the shipped file without importing the planner
    code = "import sys, anyhome.house; print('anyhome.plan' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "False"


# ------------------------------------------------------------------ broken user files
@pytest.mark.parametrize("name,body,where", [
    ("assets.yaml", "words:\n  couch: sofa\n", "assets.yaml: words.couch: is a word of the object prototype 'sofa'"),
    ("assets.yaml", "sizes:\n  bed: [1, 2, 1]\n", "assets.yaml: sizes.bed: the object prototype 'bed'"),
    ("colours.yaml", "colours:\n  ultramarine: [18, 10, 300]\n", "colours.yaml: colours.ultramarine"),
    ("colours.yaml", "colours:\n  dark: [1, 2, 3]\n", "colours.yaml: colours.dark: is also a modifier"),
    ("rooms.yaml", "types:\n  bedroom: {habitable: false}\n", "rooms.yaml: types.bedroom: habitable: is true"),
    ("materials.yaml", "words:\n  cork: {kind: korky}\n", "materials.yaml: words.cork: kind: unknown kind 'korky'"),
    ("materials.yaml", "words:\n  oak: {goes_on: [roof]}\n", "materials.yaml: words.oak: goes_on[0]:"),
    ("materials.yaml", "words:\n  cork: {goes_on: [floor]}\n", "materials.yaml: words.cork: names no material"),
])
def test_cli_bad_entry_is_one_line(tmp_path: Path, name: str, body: str, where: str) -> None:
    kdir = tmp_path / "kb"
    kdir.mkdir()
    (kdir / name).write_text(body, encoding="utf-8")
    r = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a small house", "--knowledge", str(kdir),
                        "--out", str(tmp_path / "h"), "-q"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and where in lines[0], r.stderr
    assert "Traceback" not in r.stderr
