from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from anyhome.materials import encoded_images, pbr_material, surface_material, texture_images
from anyhome.materials.images import texture_factors


def test_images_of_a_spec() -> None:
    spec = surface_material("white subway tiles", "walls", 64)
    base, mr, normal = texture_images(spec)
    assert all(im.mode == "RGB" and im.size == (64, 64) for im in (base, mr, normal))
    rough, metal = texture_factors(spec)
    g = np.asarray(mr)[..., 1] / 255.0 * rough  # glTF: roughness in green
    assert abs(float(np.median(g)) - spec.roughness) < 0.1
    assert 0.0 < rough <= 1.0 and metal == spec.metallic == 0.0
    n = np.asarray(normal).astype(float) / 127.5 - 1.0
    assert n[..., 2].mean() > 0.8  # mostly facing out


def test_equal_specs_share_images_and_colours_share_maps() -> None:
    a = surface_material("white oak planks", "floor", 64)
    b = surface_material("white oak planks", "floor", 64)
    assert all(x is y for x, y in zip(texture_images(a), texture_images(b), strict=True))
    dark = surface_material("dark walnut planks", "floor", 64)
    (base_a, mr_a, nrm_a), (base_d, mr_d, nrm_d) = texture_images(a), texture_images(dark)
    assert base_a is not base_d and mr_a is mr_d and nrm_a is nrm_d


def test_encoded_images() -> None:
    spec = surface_material("exposed brick", "walls", 64)
    base, mr, normal = encoded_images(spec)
    assert base.mime_type == "image/jpeg" and mr.mime_type == normal.mime_type == "image/png"
    assert Image.open(io.BytesIO(base.data)).size == (64, 64)
    assert encoded_images(spec)[0] is base


def test_pbr_materials() -> None:
    floor = pbr_material(surface_material("dark walnut", "floor", 64))
    assert floor.baseColorTexture is not None and floor.normalTexture is not None
    assert floor.metallicRoughnessTexture is not None
    bare = pbr_material(surface_material("dark walnut", "floor", 64), textures=False)
    assert bare.baseColorTexture is None and bare.name == floor.name
    glass = pbr_material(surface_material("glass", "furniture", 64))
    assert glass.alphaMode == "BLEND" and glass.baseColorTexture is None
    assert glass.baseColorFactor[3] < 255


def test_untextured_spec_has_no_images() -> None:
    with pytest.raises(ValueError, match="no texture"):
        texture_images(surface_material("glass", "furniture", 64))
