"""Material specs -> texture images and trimesh PBR materials, cached.

Equal specs share one set of images (``lru_cache``), and the roughness/metallic and
normal images are shared between specs that differ only in colour, so rooms and
objects of the same material share their textures in memory and in a GLB.
"""

from __future__ import annotations

import io
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

from anyhome.assets.colors import to_rgba
from anyhome.errors import AnyHomeError
from anyhome.materials.catalog import MaterialSpec
from anyhome.materials.textures import Texture, generate

if TYPE_CHECKING:
    import trimesh
    from PIL import Image

CACHE_SIZE = 256
"""Texture sets kept in memory (about 0.5 MB each at 256 texels)."""
JPEG_QUALITY = 90
"""Quality of the base-colour JPEG written into a GLB."""
PNG_COMPRESS_LEVEL = 3
"""zlib level of the PNG maps written into a GLB (speed over a few percent of size)."""
OPAQUE_WHITE = (255, 255, 255, 255)


@dataclass(frozen=True)
class EncodedImage:
    """An image file's bytes, ready to be embedded."""

    data: bytes
    mime_type: str


def _u8(x: np.ndarray) -> np.ndarray:
    return (np.clip(x, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)


_DetailKey = tuple[str, str, float, int, bool]
_details: dict[_DetailKey, tuple[Image.Image, Image.Image, float]] = {}
"""(kind, variant, roughness, size) -> (metallicRoughness, normal, roughness factor); the
maps do not depend on the colour, so every colour of a material shares them."""


def _pil():
    """PIL.Image, or an error that says what to install."""
    try:
        from PIL import Image
    except ImportError:
        raise AnyHomeError("textures need Pillow: pip install Pillow") from None
    return Image


def _detail_images(key: _DetailKey, tex: Texture | None = None) -> tuple[Image.Image, Image.Image, float]:
    """The shared maps for ``key``, made from ``tex`` (or generated) the first time.

    The roughness map is stored divided by its maximum, which becomes the material's
    roughnessFactor; metallic is all ones, scaled by metallicFactor. So a reader that
    ignores the map still gets about the right roughness and metallic.
    """
    Image = _pil()
    if key not in _details:
        kind, variant, roughness, size, aged = key
        tex = tex or generate(kind, size, "#808080", roughness, variant, weathered=aged)
        factor = float(np.ceil(tex.roughness.max() * 255.0) / 255.0)
        n = tex.roughness.shape[0]
        ones = np.full((n, n), 255, np.uint8)
        mr = np.dstack([ones, _u8(tex.roughness / factor), ones])
        if len(_details) >= CACHE_SIZE:
            _details.pop(next(iter(_details)))
        _details[key] = (Image.fromarray(mr, "RGB"), Image.fromarray(_u8(tex.normal * 0.5 + 0.5), "RGB"),
                         factor)
    return _details[key]


@lru_cache(maxsize=CACHE_SIZE)
def _texture_images(kind: str, variant: str, color: str, roughness: float, size: int, aged: bool = False
                    ) -> tuple[Image.Image, Image.Image, Image.Image, float]:
    Image = _pil()
    tex = generate(kind, size, color, roughness, variant, weathered=aged)
    mr, normal, factor = _detail_images((kind, variant, roughness, size, aged), tex)
    return Image.fromarray(_u8(tex.color), "RGB"), mr, normal, factor


def texture_images(spec: MaterialSpec) -> tuple[Image.Image, Image.Image, Image.Image]:
    """(base colour, metallicRoughness, normal) images of a textured spec.

    The base colour is sRGB. The metallicRoughness image follows glTF (roughness in
    green, metallic in blue, red unused), scaled by the factors of
    :func:`texture_factors`. Raises ValueError for untextured kinds.
    """
    return _images(spec)[:3]


def texture_factors(spec: MaterialSpec) -> tuple[float, float]:
    """(roughnessFactor, metallicFactor) that go with :func:`texture_images`."""
    return _images(spec)[3], spec.metallic


def _images(spec: MaterialSpec) -> tuple[Image.Image, Image.Image, Image.Image, float]:
    if not spec.textured:
        raise ValueError(f"material kind {spec.kind!r} has no texture")
    return _texture_images(spec.kind, spec.variant, spec.color, spec.roughness, spec.size_px, spec.weathered)


def _encode(image: Image.Image, fmt: str) -> EncodedImage:
    buf = io.BytesIO()
    if fmt == "JPEG":
        image.save(buf, format="JPEG", quality=JPEG_QUALITY)
        return EncodedImage(buf.getvalue(), "image/jpeg")
    image.save(buf, format="PNG", compress_level=PNG_COMPRESS_LEVEL)
    return EncodedImage(buf.getvalue(), "image/png")


_encoded_details: dict[_DetailKey, tuple[EncodedImage, EncodedImage]] = {}


@lru_cache(maxsize=CACHE_SIZE)
def _encoded(spec: MaterialSpec) -> tuple[EncodedImage, EncodedImage, EncodedImage]:
    base, mr, normal = texture_images(spec)
    key = (spec.kind, spec.variant, spec.roughness, spec.size_px, spec.weathered)
    if key not in _encoded_details:
        if len(_encoded_details) >= CACHE_SIZE:
            _encoded_details.pop(next(iter(_encoded_details)))
        _encoded_details[key] = (_encode(mr, "PNG"), _encode(normal, "PNG"))
    return (_encode(base, "JPEG"), *_encoded_details[key])


def encoded_images(spec: MaterialSpec) -> tuple[EncodedImage, EncodedImage, EncodedImage]:
    """The texture images of a spec as files: base colour JPEG, the maps PNG (lossless).
    Equal images come back as the same object."""
    return _encoded(replace(spec, tile_m=1.0, metallic=0.0))


def material_key(spec: MaterialSpec) -> str:
    """A name that differs whenever the exported material differs (not the UV scale)."""
    kind = f"{spec.kind}/{spec.variant}" if spec.variant else spec.kind
    tex = f" {spec.size_px}px" if spec.textured else ""
    alpha = f" a{spec.alpha:.2f}" if spec.alpha < 1.0 else ""
    aged = " weathered" if spec.weathered and spec.textured else ""
    return f"{kind} {spec.color} r{spec.roughness:.2f} m{spec.metallic:.2f}{alpha}{tex}{aged}"


@lru_cache(maxsize=CACHE_SIZE)
def pbr_material(spec: MaterialSpec, textures: bool = True) -> trimesh.visual.material.PBRMaterial:
    """A trimesh PBR material for a spec, named by :func:`material_key`.

    Textured specs get baseColor, metallicRoughness and normal textures with the factors
    of :func:`texture_factors` (white base colour factor) unless ``textures`` is False,
    which gives plain factors without images (the spec's colour, roughness and metallic,
    for exporters that embed the images themselves). Untextured specs get constant
    factors; alpha below 1 is blended.
    """
    import trimesh

    blend = spec.alpha < 1.0
    kwargs: dict[str, Any] = dict(name=material_key(spec), alphaMode="BLEND" if blend else "OPAQUE",
                                  doubleSided=blend)
    if spec.textured and textures:
        base, mr, normal = texture_images(spec)
        rough, metal = texture_factors(spec)
        kwargs.update(baseColorFactor=OPAQUE_WHITE, metallicFactor=metal, roughnessFactor=rough,
                      baseColorTexture=base, metallicRoughnessTexture=mr, normalTexture=normal)
    else:
        kwargs.update(baseColorFactor=to_rgba(spec.color, int(round(spec.alpha * 255))),
                      metallicFactor=spec.metallic, roughnessFactor=spec.roughness)
    return trimesh.visual.material.PBRMaterial(**kwargs)


def clear_caches() -> None:
    """Forget every cached texture, encoded image and material (for timing, or memory)."""
    for cached in (_texture_images, _encoded, pbr_material):
        cached.cache_clear()
    _details.clear()
    _encoded_details.clear()
