"""The material-words figure (issue 15): what of the plan's material words the GLB shows."""

from __future__ import annotations

import pytest

from anyhome.evaluate.material_words import material_words, phrase_words
from anyhome.export import write_glb
from anyhome.house import House
from anyhome.pipeline import generate


def test_phrase_words() -> None:
    assert phrase_words("peeling damask wallpaper") == [("damask", "texture"), ("peeling", "weathering")]  # the pattern decides
    assert phrase_words("exposed oak beams") == [("oak beams", "structure")]  # the beams are the oak
    assert phrase_words("oak and matte black metal") == [("oak", "texture"), ("metal", "texture")]


@pytest.fixture(scope="module")
def aged_house(tmp_path_factory) -> tuple[House, str]:
    house = generate("a haunted cottage with peeling damask wallpaper, dusty oak floors and exposed beams", seed=0)
    path = write_glb(house, tmp_path_factory.mktemp("glb") / "house.glb", texture_px=16)
    return house, str(path)


def test_a_generated_house_shows_its_material_words(aged_house) -> None:
    house, glb = aged_house
    rep = material_words(house, glb)
    assert rep.n_words >= 10
    assert rep.by_kind["weathering"][0] == rep.by_kind["weathering"][1] > 0
    assert rep.by_kind["structure"][0] == rep.by_kind["structure"][1] > 0
    assert rep.share is not None and rep.share >= 0.9


def test_a_surface_that_does_not_show_its_word_is_a_miss(aged_house) -> None:
    from anyhome.evaluate.material_words import glb_materials

    house, glb = aged_house
    nodes = glb_materials(glb)
    room = next(r for r in house.rooms if "wallpaper" in r.materials.get("walls", ""))
    nodes[f"room:{room.id}:walls"] = ["plaster #ffffff r0.90 m0.00 16px"]  # neither paper nor aged
    for k in [k for k in nodes if k.endswith((":beams", ":coffers"))]:
        del nodes[k]
    rep = material_words(house, nodes)
    assert any(m.startswith("walls") and m.endswith(": damask") for m in rep.misses)
    assert any(m.startswith("walls") and m.endswith(": peeling") for m in rep.misses)
    assert rep.by_kind["structure"][0] == 0
