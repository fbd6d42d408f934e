from __future__ import annotations

import numpy as np
import pytest

from anyhome.assets import assign_asset, build_object_mesh
from anyhome.assets.colors import mix
from anyhome.assets.procedural._parts import GLASS, METAL, Builder
from anyhome.house import HouseObject
from anyhome.materials.parts import object_parts, part_spec, role_of, shade_of


def _obj(category: str, material: str, size=(2.0, 0.9, 0.85)) -> HouseObject:
    obj = HouseObject(id=f"{category}1", room="r", name=category, category=category,
                      position=(0, 0, 0), size=size, material=material)
    obj.asset = assign_asset(obj, np.random.default_rng(0), "modern")
    return obj


def test_sofa_parts_keep_the_mesh_and_texture_the_primary() -> None:
    obj = _obj("sofa", "blue velvet")
    mesh = build_object_mesh(obj)
    parts = object_parts(mesh, obj.asset["params"], obj.material, 32)
    assert sum(len(p.mesh.faces) for p in parts) == len(mesh.faces)
    lo = np.min([p.mesh.bounds[0] for p in parts], axis=0)
    hi = np.max([p.mesh.bounds[1] for p in parts], axis=0)
    np.testing.assert_allclose([lo, hi], mesh.bounds, atol=1e-9)
    primary = [p for p in parts if p.role == "primary"]
    assert primary and all(p.spec.kind == "fabric" and p.spec.variant == "velvet" for p in primary)
    main = next(p for p in primary if p.color == obj.asset["params"]["primary"])
    assert main.spec.textured and main.mesh.visual.uv is not None
    assert main.mesh.visual.uv.shape == (len(main.mesh.vertices), 2)
    assert main.mesh.visual.material.baseColorTexture is not None
    for p in parts:
        if not p.spec.textured:
            assert p.mesh.visual.material.baseColorTexture is None


def test_second_clause_dresses_the_secondary() -> None:
    spec = part_spec("secondary", "#222222", "oak and matte black metal", 32)
    assert spec.metallic > 0.5 and not spec.textured
    assert part_spec("secondary", "#b9b2a6", "oak", 32).roughness >= 0.8  # fabric by default


def test_glass_and_metal_parts() -> None:
    glass = part_spec(role_of(GLASS, 255, {"primary": "#a0714a"}), GLASS, "oak", 32)
    assert glass.kind == "glass" and glass.alpha == pytest.approx(0.35)
    metal = part_spec(role_of(METAL, 255, {"primary": "#a0714a"}), METAL, "oak", 32)
    assert metal.metallic > 0.5
    shade = part_spec(role_of("#d9c3a0", 200, {}), "#d9c3a0", "linen", 32, 200 / 255)
    assert 0.0 < shade.alpha < 1.0 and not shade.textured


def test_shades_of_the_primary() -> None:
    assert shade_of(mix("#5f6b7a", "#ffffff", 0.12), "#5f6b7a")
    assert shade_of(mix("#5f6b7a", "#000000", 0.35), "#5f6b7a")
    assert not shade_of("#eeebe4", "#5f6b7a")
    assert not shade_of("#5f6b7a", "#5f6b7a")
    params = {"primary": "#5f6b7a", "secondary": "#a0714a", "accent": "#7d8c74"}
    assert role_of(mix("#5f6b7a", "#ffffff", 0.12), 255, params) == "primary"
    assert role_of("#a0714a", 255, params) == "secondary"
    assert role_of("#7d8c74", 255, params) == "accent"


def test_split_by_colour_on_a_built_mesh() -> None:
    b = Builder()
    b.box((0, 0, 0), (1, 1, 0.1), "#a0714a")
    b.box((0, 0, 0.1), (0.1, 0.1, 1), METAL)
    b.box((0.2, 0.2, 0.1), (0.5, 0.5, 0.4), GLASS, alpha=90)
    parts = object_parts(b.mesh((1, 1, 1)), {"primary": "#a0714a"}, "walnut", 32)
    assert sorted(p.role for p in parts) == ["glass", "metal", "primary"]
    top = next(p for p in parts if p.role == "primary")
    assert top.spec.kind == "wood"
    # planar UVs in meters / tile size: the 1 m top face spans 1 / tile_m in u
    uv = top.mesh.visual.uv
    assert np.ptp(uv[:, 0]) == pytest.approx(1.0 / top.spec.tile_m, rel=1e-6)
