from __future__ import annotations

import pytest

from anyhome.assets.colors import material_color, to_rgba
from anyhome.errors import ExportError
from anyhome.materials.catalog import (
    SURFACES,
    TEXTURE_PX_ENV,
    MaterialSpec,
    clauses,
    surface_material,
    texture_size_px,
)
from anyhome.materials.textures import kinds


@pytest.mark.parametrize(
    ("words", "surface", "kind", "variant"),
    [
        ("dark walnut", "floor", "planks", ""),
        ("dark walnut planks", "floor", "planks", ""),
        ("dark walnut", "furniture", "wood", ""),
        ("mahogany parquet", "floor", "planks", "parquet"),
        ("white shiplap", "walls", "planks", "shiplap"),
        ("timber log walls", "walls", "planks", "logs"),
        ("blue marble", "walls", "marble", ""),
        ("blue marble accent", "walls", "marble", ""),
        ("exposed brick walls", "walls", "brick", ""),
        ("exposed red brick", "walls", "brick", ""),
        ("tatami", "floor", "tatami", ""),
        ("tatami mats", "floor", "tatami", ""),
        ("white subway tiles", "walls", "tile", "subway"),
        ("white ceramic tiles", "floor", "tile", ""),
        ("green zellige", "walls", "tile", "zellige"),
        ("terracotta tiles", "floor", "tile", "terracotta"),
        ("saltillo", "floor", "tile", "terracotta"),
        ("warm terracotta paint", "walls", "plaster", "paint"),
        ("white render", "walls", "plaster", ""),
        ("white plaster", "ceiling", "plaster", ""),
        ("burgundy damask wallpaper", "walls", "wallpaper", "damask"),
        ("peeling faded damask wallpaper", "walls", "wallpaper", "damask"),
        ("shoji paper screens and light cedar", "walls", "wallpaper", "shoji"),
        ("worn stone flags", "floor", "stone", "flags"),
        ("flagstone", "floor", "stone", "flags"),
        ("rough castle stone", "walls", "stone", "rubble"),
        ("slate", "floor", "stone", "flags"),
        ("polished concrete", "floor", "concrete", ""),
        ("cement", "floor", "concrete", ""),
        ("terrazzo", "floor", "concrete", "terrazzo"),
        ("beige carpet", "floor", "carpet", ""),
        ("wool rug", "floor", "carpet", ""),
        ("blue velvet", "furniture", "fabric", "velvet"),
        ("grey linen", "furniture", "fabric", ""),
        ("tan leather", "furniture", "fabric", "leather"),
        ("iron black woven wool", "furniture", "fabric", ""),
        ("sand upholstery on whitewashed wood and rattan", "furniture", "fabric", ""),
        ("brushed stainless steel", "furniture", "metal", ""),
        ("brass and linen", "furniture", "metal", ""),
        ("oak and matte black metal", "furniture", "wood", ""),
        ("exposed ductwork and steel beams", "ceiling", "metal", ""),
        ("white painted boards", "ceiling", "planks", ""),
        ("glass and chrome", "furniture", "glass", ""),
        ("white porcelain", "furniture", "plain", ""),
    ],
)
def test_words_choose_the_kind(words: str, surface: str, kind: str, variant: str) -> None:
    spec = surface_material(words, surface, 64)
    assert (spec.kind, spec.variant) == (kind, variant)


@pytest.mark.parametrize("surface", SURFACES)
def test_every_surface_has_a_default(surface: str) -> None:
    spec = surface_material("", surface, 64)
    assert spec.kind in (*kinds(), "plain", "glass")
    if surface != "furniture":
        assert spec.textured


def test_colour_from_the_words_else_the_kind() -> None:
    assert surface_material("dark walnut", "floor").color == material_color("dark walnut")
    assert surface_material("oak and matte black metal", "furniture").color == material_color("oak")
    brick = surface_material("exposed brick", "walls")
    assert brick.color == material_color("brick")
    assert surface_material("tatami", "floor").color == material_color("tatami")
    plain = surface_material("soft vinyl", "floor")
    assert plain.color.startswith("#") and len(plain.color) == 7
    assert surface_material("blue velvet", "furniture", color="#123456").color == "#123456"


def test_finish_words_shift_roughness() -> None:
    assert surface_material("polished concrete", "floor").roughness < surface_material("concrete", "floor").roughness
    assert surface_material("glossy white tiles", "floor").roughness < surface_material("white tiles", "floor").roughness
    assert surface_material("matte black metal", "furniture").roughness > surface_material("black metal", "furniture").roughness


def test_metals_are_metallic_and_glass_is_clear() -> None:
    assert surface_material("brass", "furniture").metallic > 0.5
    assert surface_material("oak", "furniture").metallic == 0.0
    glass = surface_material("glass", "furniture")
    assert glass.alpha < 1.0 and not glass.textured


def test_whitewashed_is_lighter() -> None:
    def grey(spec: MaterialSpec) -> int:
        return int(to_rgba(spec.color)[:3].astype(int).sum())

    assert grey(surface_material("whitewashed oak planks", "floor")) > grey(surface_material("oak planks", "floor"))


def test_specs_are_hashable_and_equal_for_equal_words() -> None:
    a = surface_material("white oak planks", "floor", 64)
    b = surface_material("white oak planks", "floor", 64)
    assert a == b and hash(a) == hash(b) and isinstance(a, MaterialSpec)


def test_clauses() -> None:
    assert clauses("oak and matte black metal") == ["oak", "matte black metal"]
    assert clauses("sand upholstery on whitewashed wood and rattan") == [
        "sand upholstery", "whitewashed wood", "rattan"]


def test_texture_size(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(TEXTURE_PX_ENV, raising=False)
    assert texture_size_px() == 256
    assert texture_size_px(128) == 128
    monkeypatch.setenv(TEXTURE_PX_ENV, "512")
    assert texture_size_px() == 512 and surface_material("oak", "floor").size_px == 512
    for bad in ("lots", "100000", "4", "-1"):  # refused in one line, not silently replaced
        monkeypatch.setenv(TEXTURE_PX_ENV, bad)
        with pytest.raises(ExportError, match=TEXTURE_PX_ENV):
            texture_size_px()
    with pytest.raises(ExportError, match="texture size"):
        texture_size_px(100000)


def test_unknown_surface() -> None:
    for words in ("oak", ""):
        with pytest.raises(ValueError, match="surface"):
            surface_material(words, "roof")
