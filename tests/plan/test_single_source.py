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
    assets = yaml.safe_load(Path(asset_colors.__file__).with_name("colors.yaml").read_text(encoding="utf-8"))
    assert set(assets) == {"materials"}
    assert not set(assets["materials"]) & set(kb.colours.colours)


def test_longest_colour_phrase_wins() -> None:
    rgb = knowledge_base().colours.colours
    assert material_color("sky blue velvet") == to_hex(rgb["sky blue"]) != to_hex(rgb["blue"])


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
