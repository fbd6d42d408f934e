"""The user's knowledge overlay: folders from $ANYHOME_KNOWLEDGE_PATH and ``generate
--knowledge DIR`` add to or override the shipped knowledge files, and a bad file is one
line ``error: FILE: KEY: what is wrong`` with exit 2, through the real CLI."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from anyhome.errors import KnowledgeError
from anyhome.plan import knowledge
from anyhome.plan.knowledge import ENV_VAR, knowledge_base, load, use_knowledge, vocabulary

HAMMOCK = {
    "objects.yaml": "hammock stand: {category: hammock, size: [1.0, 3.2, 1.2], rule: place_center, "
    "rooms: [hammock_deck, balcony], synonyms: [hammock frame], group: hammock}\n",
    "furniture.yaml": "groups:\n  hammock: {anchor: {use: hammock stand}}\n"
    "sets:\n  hammock_deck: {groups: [{group: hammock}, {group: plant, prob: 0.5}]}\n",
    "rooms.yaml": "names:\n  hammock deck: {type: balcony, furnish: hammock_deck, area: [6, 9]}\n",
    "programs.yaml": "buildings:\n  - {words: [treehouse, tree house], program: treehouse, styles: [rustic]}\n"
    "programs:\n  treehouse:\n    building: treehouse\n    main: cabin\n    entrance: [living_room]\n"
    "    rooms:\n      - {key: cabin, type: living_room, name: cabin}\n"
    "      - {key: deck, type: balcony, name: hammock deck, furnish: hammock_deck}\n"
    "      - {key: bunk, type: bedroom, name: bunk room}\n",
}


def _folder(root: Path, files: dict[str, str]) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (root / name).write_text(text, encoding="utf-8")
    return root


def _cli(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    e = {k: v for k, v in os.environ.items() if k != ENV_VAR}
    return subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True, text=True,
                          timeout=60, env={**e, **(env or {})})


pytestmark = pytest.mark.usefixtures("no_knowledge_overlay")  # tests/conftest.py


# ------------------------------------------------------------------ through the CLI
def test_cli_user_object_room_and_program_are_planned(tmp_path):
    kdir = _folder(tmp_path / "kb", HAMMOCK)
    out = tmp_path / "house"
    r = _cli("generate", "a treehouse with a hammock stand", "--knowledge", str(kdir), "--out", str(out),
             "--no-glb", "--no-svg", "-q")
    assert r.returncode == 0, r.stderr
    house = json.loads((out / "house.json").read_text())
    rooms = {room["id"]: room for room in house["rooms"]}
    assert "hammock deck" in [room["name"] for room in rooms.values()]
    stands = [o for o in house["objects"] if o["name"] == "hammock stand"]
    assert stands, [o["name"] for o in house["objects"]]
    assert {rooms[o["room"]]["name"] for o in stands} == {"hammock deck"}
    assert {o["category"] for o in stands} == {"hammock"}


BROKEN = {
    "negative size": ({"objects.yaml": "chair: {size: [0.45, -1, 0.9]}\n"}, "objects.yaml: chair: size[1]:"),
    "unknown rule": ({"objects.yaml": "hammock stand: {category: hammock, size: [1, 3, 1], rule: place_floating}\n"},
                     "objects.yaml: hammock stand: rule: unknown rule 'place_floating'"),
    "set names a missing object": ({"furniture.yaml": "sets:\n  balcony: {ornaments: [{use: garden gnome}]}\n"},
                                   "furniture.yaml: sets.balcony: ornaments[0].use: unknown object 'garden gnome'"),
    "group names a missing object": ({"furniture.yaml": "groups:\n  hammock: {anchor: {use: hammock stand}}\n"},
                                     "furniture.yaml: groups.hammock: anchor.use: unknown object 'hammock stand'"),
    "program names an unknown room type": (
        {"programs.yaml": "programs:\n  hut:\n    building: hut\n    main: a\n    entrance: [gazebo]\n"
                          "    rooms: [{key: a, type: living_room}]\n"},
        "programs.yaml: programs.hut: entrance: unknown room type 'gazebo'"),
    "style names an unknown asset class": ({"styles.yaml": "styles:\n  gothic: {asset_class: gothik}\n"},
                                           "styles.yaml: styles.gothic: asset_class: unknown asset class 'gothik'"),
    "bad colour": ({"styles.yaml": "asset_classes:\n  gothic: {woods: ['#12345']}\n"},
                   "styles.yaml: asset_classes.gothic: woods[0]:"),
    "invalid yaml": ({"objects.yaml": "bed: {size: [1, 2, 3]\nsofa: {}\n"}, "objects.yaml: line 2: invalid YAML"),
    "top level not a mapping": ({"rooms.yaml": "- kitchen\n- bedroom\n"}, "rooms.yaml: top level: must be a mapping"),
    "unknown field": ({"objects.yaml": "bed: {colour: red}\n"}, "objects.yaml: bed: colour: unknown field"),
    "unknown rule parameter": ({"objects.yaml": "bed: {params: {distnce_m: 0.4}}\n"},
                               "objects.yaml: bed: params: distnce_m: unknown parameter for place_wall"),
    "bad rule parameter value": ({"furniture.yaml": "groups:\n  bed:\n    anchor: {use: bed, params: {wall: sideways}}\n"},
                                 "furniture.yaml: groups.bed: anchor.params: wall: Input should be"),
    "unknown file": ({"object.yaml": "bed: {size: [1, 2, 1]}\n"}, "object.yaml: top level: not a knowledge file"),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_cli_broken_user_file_is_one_line(tmp_path, case):
    files, expected = BROKEN[case]
    kdir = _folder(tmp_path / "kb", files)
    r = _cli("generate", "a small house", "--knowledge", str(kdir), "--out", str(tmp_path / "h"), "-q")
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith(f"error: {kdir}{os.sep}"), lines[0]
    assert expected in lines[0]
    assert "Traceback" not in r.stderr and not (tmp_path / "h").exists()


def test_cli_env_path_missing_folder_is_one_line(tmp_path):
    r = _cli("generate", "a small house", "--out", str(tmp_path / "h"), "-q",
             env={ENV_VAR: str(tmp_path / "nowhere")})
    assert r.returncode == 2
    assert r.stderr.strip() == f"error: {tmp_path / 'nowhere'}: top level: knowledge folder not found " \
                               f"(from ${ENV_VAR} or --knowledge)"


def test_cli_env_path_broken_file_is_one_line(tmp_path):
    kdir = _folder(tmp_path / "kb", {"rooms.yaml": "names:\n  sauna: {type: bathroom, area: [8, 4]}\n"})
    r = _cli("generate", "a small house", "--out", str(tmp_path / "h"), "-q", env={ENV_VAR: str(kdir)})
    assert r.returncode == 2
    assert r.stderr.strip().startswith(f"error: {kdir / 'rooms.yaml'}: names.sauna: area: ")


# ------------------------------------------------------------------ merge rules, in process
def test_entry_fields_merge_and_other_entries_stay(tmp_path, monkeypatch):
    shipped = dict(load("objects")["bookshelf"])
    kdir = _folder(tmp_path / "kb", {"objects.yaml": "bookshelf: {size: [1.1, 0.4, 2.4]}\n"})
    monkeypatch.setenv(ENV_VAR, str(kdir))
    mine = load("objects")["bookshelf"]
    assert mine["size"] == [1.1, 0.4, 2.4]
    assert {k: v for k, v in mine.items() if k != "size"} == {k: v for k, v in shipped.items() if k != "size"}
    monkeypatch.delenv(ENV_VAR)
    assert load("objects")["bookshelf"] == shipped


def test_later_folders_win_and_cli_folders_come_last(tmp_path, monkeypatch):
    a = _folder(tmp_path / "a", {"objects.yaml": "bookshelf: {size: [1.1, 0.4, 2.1]}\n"})
    b = _folder(tmp_path / "b", {"objects.yaml": "bookshelf: {size: [1.2, 0.4, 2.2]}\n"})
    c = _folder(tmp_path / "c", {"objects.yaml": "bookshelf: {size: [1.3, 0.4, 2.3]}\n"})
    monkeypatch.setenv(ENV_VAR, os.pathsep.join([str(a), str(b)]))
    assert load("objects")["bookshelf"]["size"] == [1.2, 0.4, 2.2]
    use_knowledge([str(c)])
    assert load("objects")["bookshelf"]["size"] == [1.3, 0.4, 2.3]
    assert knowledge.overlay() == (str(a), str(b), str(c))


def test_lists_and_buildings(tmp_path, monkeypatch):
    kdir = _folder(tmp_path / "kb", {
        "colours.yaml": "colours: {white: [255, 255, 255], ultramarine: [18, 10, 143]}\n",
        "programs.yaml": "buildings:\n  - {words: [cottage], program: apartment}\n",
        "concepts.yaml": "non_objects: [widget]\n",
    })
    monkeypatch.setenv(ENV_VAR, str(kdir))
    cols = load("colours")["colours"]
    assert cols["white"] == [255, 255, 255] and list(cols)[-1] == "ultramarine"
    assert vocabulary().colour_regex.fullmatch("ultramarine")
    from anyhome.assets.colors import material_color  # the overlay reaches the assets too

    assert material_color("ultramarine velvet") == "#120a8f"
    assert load("concepts")["non_objects"][-1] == "widget"
    # the user's building words come first, so they win over the shipped ones
    assert load("programs")["buildings"][0]["program"] == "apartment"
    assert load("programs")["buildings"][vocabulary().building_forms["cottage"]]["program"] == "apartment"


def test_caches_follow_the_overlay(tmp_path, monkeypatch):
    assert "hammock stand" not in vocabulary().forms
    kdir = _folder(tmp_path / "kb", HAMMOCK)
    monkeypatch.setenv(ENV_VAR, str(kdir))
    assert "hammock stand" in load("objects")
    assert vocabulary().forms["hammock frames"][0].key == "hammock stand"
    assert "hammock stand" in knowledge_base().objects
    monkeypatch.delenv(ENV_VAR)
    assert "hammock stand" not in load("objects") and "hammock stand" not in vocabulary().forms
    assert "hammock stand" not in knowledge_base().objects


def test_overriding_a_size_changes_the_generated_size(tmp_path, monkeypatch):
    from anyhome.pipeline import generate

    text = "a one bedroom house with a study with a bookshelf"

    def heights() -> list[float]:
        house = generate(text, seed=0)
        return [o.size[2] for o in house.objects if o.name == "bookshelf"]

    before = heights()
    assert before and max(before) < 2.3
    kdir = _folder(tmp_path / "kb", {"objects.yaml": "bookshelf: {size: [1.0, 0.35, 2.6]}\n"})
    monkeypatch.setenv(ENV_VAR, str(kdir))
    after = heights()
    assert after and min(after) > 2.3
    monkeypatch.delenv(ENV_VAR)
    assert heights() == before  # nothing of the overlay is left in any cache


def test_in_process_error_is_knowledge_error(tmp_path, monkeypatch):
    kdir = _folder(tmp_path / "kb", {"rooms.yaml": "types:\n  kitchen: {max: 0}\n"})
    monkeypatch.setenv(ENV_VAR, str(kdir))
    with pytest.raises(KnowledgeError, match=r"rooms\.yaml: types\.kitchen: max: "):
        load("objects")  # any file: every file is validated before one is handed out
    monkeypatch.delenv(ENV_VAR)
    assert load("objects")


def test_a_room_words_reading_within_an_unknown_building_is_refused(tmp_path, monkeypatch):
    """rooms.yaml ``within`` names programs; a misspelt one is a one-line KnowledgeError."""
    kdir = _folder(tmp_path / "kb", {"rooms.yaml": "names:\n  gym: {type: gym, within: {schol: {type: gym}}}\n"})
    monkeypatch.setenv(ENV_VAR, str(kdir))
    with pytest.raises(KnowledgeError, match=r"rooms\.yaml: names\.gym: within\.schol: unknown program .schol. \(did you mean .school."):
        load("rooms")
    monkeypatch.delenv(ENV_VAR)


def test_a_buildings_swap_must_name_a_prototype(tmp_path, monkeypatch):
    kdir = _folder(tmp_path / "kb", {"programs.yaml": "programs:\n  hotel:\n    swap: {office chair: {use: cheir, name: desk chair}}\n"})
    monkeypatch.setenv(ENV_VAR, str(kdir))
    with pytest.raises(KnowledgeError, match=r"programs\.yaml: programs\.hotel: swap\.office chair\.use: unknown object prototype .cheir."):
        load("programs")
    monkeypatch.delenv(ENV_VAR)
