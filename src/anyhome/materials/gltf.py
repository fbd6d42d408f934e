"""Embed material textures into a GLB that was exported without them.

trimesh re-encodes every texture of every material it exports. Instead the scene is
exported with untextured materials named by :func:`anyhome.materials.images.material_key`
and this module adds the images afterwards: each distinct image once (its bytes are
cached across exports), one texture per image, shared by all materials that use it.
"""

from __future__ import annotations

import json
import struct
from collections.abc import Mapping

from anyhome.materials.catalog import MaterialSpec
from anyhome.materials.images import EncodedImage, encoded_images, texture_factors

_GLB_MAGIC = b"glTF"
_JSON = b"JSON"
_BIN = b"BIN\x00"
REPEAT = 10497
LINEAR = 9729
LINEAR_MIPMAP_LINEAR = 9987


def read_glb(data: bytes) -> tuple[dict, bytes]:
    """(JSON tree, binary chunk) of a GLB."""
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    if magic != _GLB_MAGIC or version != 2:
        raise ValueError("not a glTF 2.0 binary")
    offset, tree, binary = 12, None, b""
    while offset < length:
        size, kind = struct.unpack_from("<I4s", data, offset)
        chunk = data[offset + 8 : offset + 8 + size]
        if kind == _JSON:
            tree = json.loads(chunk)
        elif kind == _BIN:
            binary = bytes(chunk)
        offset += 8 + size
    if tree is None:
        raise ValueError("GLB without a JSON chunk")
    return tree, binary


def write_glb_bytes(tree: dict, binary: bytes) -> bytes:
    """A GLB from a JSON tree and a binary chunk (both padded to 4 bytes)."""
    js = json.dumps(tree, separators=(",", ":")).encode("utf-8")
    js += b" " * (-len(js) % 4)
    binary += b"\x00" * (-len(binary) % 4)
    total = 12 + 8 + len(js) + (8 + len(binary) if binary else 0)
    out = [struct.pack("<4sII", _GLB_MAGIC, 2, total), struct.pack("<I4s", len(js), _JSON), js]
    if binary:
        out += [struct.pack("<I4s", len(binary), _BIN), binary]
    return b"".join(out)


class _Images:
    """Appends images to the binary chunk once each and hands out texture indices."""

    def __init__(self, tree: dict, binary: bytes) -> None:
        self.tree = tree
        self.parts = [binary + b"\x00" * (-len(binary) % 4)]
        self.length = len(self.parts[0])
        self.index: dict[bytes, int] = {}
        self.sampler = len(tree.setdefault("samplers", []))
        tree["samplers"].append({"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR,
                                 "wrapS": REPEAT, "wrapT": REPEAT})

    def texture(self, image: EncodedImage) -> int:
        key = image.data
        if key not in self.index:
            data = image.data + b"\x00" * (-len(image.data) % 4)
            views = self.tree.setdefault("bufferViews", [])
            views.append({"buffer": 0, "byteOffset": self.length, "byteLength": len(image.data)})
            self.parts.append(data)
            self.length += len(data)
            images = self.tree.setdefault("images", [])
            images.append({"bufferView": len(views) - 1, "mimeType": image.mime_type})
            textures = self.tree.setdefault("textures", [])
            textures.append({"sampler": self.sampler, "source": len(images) - 1})
            self.index[key] = len(textures) - 1
        return self.index[key]

    def binary(self) -> bytes:
        return b"".join(self.parts)


def _srgb_to_linear(c: float) -> float:
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_factors(tree: dict) -> None:
    """Turn every material's base colour and emissive factors from the sRGB values
    AnyHome works in to the linear values glTF defines (viewers would show them washed
    out otherwise). Texture images stay sRGB, as glTF wants."""
    for m in tree.get("materials", []):
        pbr = m.get("pbrMetallicRoughness", {})
        if "baseColorFactor" in pbr:
            r, g, b, a = pbr["baseColorFactor"]
            pbr["baseColorFactor"] = [round(_srgb_to_linear(float(x)), 5) for x in (r, g, b)] + [a]
        if "emissiveFactor" in m:
            m["emissiveFactor"] = [round(_srgb_to_linear(float(x)), 5) for x in m["emissiveFactor"]]


def embed_textures(glb: bytes, specs: Mapping[str, MaterialSpec]) -> bytes:
    """Give every material named by a textured spec in ``specs`` its texture images.

    The base colour factor becomes white and the roughness and metallic factors those of
    :func:`anyhome.materials.images.texture_factors`. Materials with other names are left
    alone.
    """
    tree, binary = read_glb(glb)
    todo = [(m, specs[m["name"]]) for m in tree.get("materials", [])
            if m.get("name") in specs and specs[m["name"]].textured]
    linear_factors(tree)
    images = _Images(tree, binary)
    for material, spec in todo:
        base, mr, normal = encoded_images(spec)
        pbr = material.setdefault("pbrMetallicRoughness", {})
        pbr["baseColorTexture"] = {"index": images.texture(base)}
        pbr["metallicRoughnessTexture"] = {"index": images.texture(mr)}
        rough, metal = texture_factors(spec)
        pbr["baseColorFactor"] = [1.0, 1.0, 1.0, 1.0]
        pbr["metallicFactor"] = metal
        pbr["roughnessFactor"] = rough
        material["normalTexture"] = {"index": images.texture(normal)}
    out = images.binary()
    buffers = tree.setdefault("buffers", [{}])
    buffers[0]["byteLength"] = len(out)
    return write_glb_bytes(tree, out)
