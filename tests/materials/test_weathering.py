"""Weathering words give visibly aged textures (issue 15), and ceiling words that are
geometry (beams, coffers) are read apart from the ceiling's own material."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.materials.catalog import ceiling_structure, clause_heads, surface_material, weathered
from anyhome.materials.images import material_key, texture_images
from anyhome.materials.textures import generate

SIZE = 64


@pytest.mark.parametrize("kind", ["plaster", "wallpaper", "planks", "metal", "stone"])
def test_a_weathered_texture_is_darker_rougher_and_seeded(kind: str) -> None:
    clean = generate(kind, SIZE, "#c8b89a", 0.5)
    aged = generate(kind, SIZE, "#c8b89a", 0.5, weathered=True)
    again = generate(kind, SIZE, "#c8b89a", 0.5, weathered=True)
    assert np.array_equal(aged.color, again.color) and np.array_equal(aged.normal, again.normal)
    assert aged.roughness.mean() > clean.roughness.mean() + 0.05
    # stains and flakes: the colour varies much more than the clean pattern does
    assert np.abs(aged.color - clean.color).mean() > 0.03
    assert 0.0 <= aged.color.min() and aged.color.max() <= 1.0
    assert np.allclose(np.linalg.norm(aged.normal, axis=-1), 1.0, atol=1e-5)


def test_paint_flakes_to_plaster_and_metal_rusts() -> None:
    paint = generate("plaster", SIZE, "#2a3a5a", 0.6, weathered=True)  # dark blue paint
    pale = (paint.color.mean(axis=-1) > 0.7).mean()  # the plaster showing through
    assert pale > 0.05
    iron = generate("metal", SIZE, "#3a3a3c", 0.4, weathered=True)
    rust = (iron.color[..., 0] > iron.color[..., 2] + 0.15).mean()  # red over blue: rust
    assert rust > 0.05


@pytest.mark.parametrize(("words", "aged"), [
    ("peeling damask wallpaper", True), ("damask wallpaper", False), ("dusty dark oak planks", True),
    ("rusty wrought iron", True), ("cream plaster", False), ("faded burgundy velvet", True),
])
def test_weathering_words_reach_the_spec_and_its_key(words: str, aged: bool) -> None:
    spec = surface_material(words, "walls")
    assert weathered(words) is aged and spec.weathered is aged
    assert material_key(spec).endswith(" weathered") is aged


def test_a_weathered_spec_has_its_own_images() -> None:
    clean = texture_images(surface_material("damask wallpaper", "walls", 32))[0]
    aged = texture_images(surface_material("peeling damask wallpaper", "walls", 32))[0]
    assert np.asarray(clean).tolist() != np.asarray(aged).tolist()


@pytest.mark.parametrize(("words", "structure", "rest"), [
    ("exposed oak beams", "beams", "exposed"), ("timber beams", "beams", ""), ("beamed white plaster", "beams", "white plaster"),
    ("gilded coffered plaster", "coffers", "gilded plaster"), ("white plaster", None, "white plaster"),
])
def test_ceiling_structure_words(words: str, structure: str | None, rest: str) -> None:
    assert ceiling_structure(words) == (structure, rest)


def test_clause_heads_are_the_words_that_decide() -> None:
    assert clause_heads("warm oak linen and brass") == ["linen", "brass"]  # oak is linen's colour
    assert clause_heads("charcoal upholstery on dark wood") == ["upholstery", "wood"]
    assert clause_heads("sunny and bright") == []
