"""Materials: PBR materials per surface with procedural, tileable textures.

``surface_material(words, surface)`` turns material words ("dark walnut planks",
"blue velvet") into a :class:`MaterialSpec` (texture kind, colour, roughness,
metallic, tile size); ``texture_images(spec)`` gives its base colour,
metallicRoughness and normal images, cached so equal materials share one texture;
``object_parts`` splits a procedural object mesh into parts with their own materials.
Knowledge lives in ``plan/knowledge/materials.yaml``; textures are numpy (``textures.generate``).
"""

from anyhome.materials.catalog import MaterialSpec, surface_material, texture_size_px
from anyhome.materials.images import encoded_images, material_key, pbr_material, texture_images
from anyhome.materials.parts import Part, object_parts
from anyhome.materials.textures import Texture, generate, kinds

__all__ = [
    "MaterialSpec",
    "Part",
    "Texture",
    "encoded_images",
    "generate",
    "kinds",
    "material_key",
    "object_parts",
    "pbr_material",
    "surface_material",
    "texture_images",
    "texture_size_px",
]
