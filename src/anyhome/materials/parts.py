"""Procedural object meshes -> parts, each with its own material.

The procedural assets label every face with its material role as they build it
(:data:`anyhome.assets.procedural._parts.Role`: wood, fabric, metal, glass...; see
:func:`~anyhome.assets.procedural._parts.face_roles`). Faces are grouped by (role, colour,
alpha); each group becomes a part whose role picks its material:

- every part: the first clause of the object's material words that names a material of
  its role, textured, tinted by the part's own colour ("oak and brass": the metal parts
  are brass; "linen bedding on dark wood": the bed's frame is the dark wood, its bedding
  the linen);
- the **body** (parts of the role the family's primary colour paints, ``body_role``)
  with no clause of its role: the words' first clause (a sofa "in green velvet" is
  velvet whatever its family paints it with); with no words, the role's own material;
- any other part: the role's plain material (:data:`ROLE_MATERIALS`);
- ``glass``: blended glass, alpha GLASS_ALPHA; a part drawn with alpha (a lamp shade) is
  blended with its own alpha.

Metal parts are always metallic (>= :data:`MIN_METALLIC`), whatever the words say.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, cast

import numpy as np
import trimesh
from trimesh.visual import ColorVisuals

from anyhome.assets.colors import to_hex
from anyhome.assets.procedural._parts import ROLES, Role, face_roles
from anyhome.materials.catalog import (
    MaterialSpec,
    material_clauses,
    spec_from_entry,
    surface_material,
    texture_size_px,
)

GLASS_ALPHA = 0.35
TRANSLUCENT_ROUGHNESS = 0.7
"""Roughness of translucent non-glass parts (lamp shades)."""
MIN_METALLIC = 0.9
"""Every metal part's metallic factor is at least this."""
ROLE_MATERIALS: dict[Role, dict[str, Any]] = {
    "wood": {"kind": "wood", "roughness": 0.55},
    "fabric": {"kind": "fabric", "roughness": 0.85},
    "leather": {"kind": "fabric", "variant": "leather", "roughness": 0.5},
    "metal": {"kind": "metal", "roughness": 0.3, "metallic": 1.0},
    "glass": {"kind": "glass", "roughness": 0.05},
    "ceramic": {"kind": "plain", "roughness": 0.15},
    "stone": {"kind": "stone", "roughness": 0.6},
    "plastic": {"kind": "plain", "roughness": 0.4},
    "rubber": {"kind": "plain", "roughness": 0.9},
    "paper": {"kind": "plain", "roughness": 0.85},
    "plant": {"kind": "plain", "roughness": 0.7},
    "light": {"kind": "plain", "roughness": 0.3},
    "screen": {"kind": "plain", "roughness": 0.1},
    "paint": {"kind": "plain", "roughness": 0.5},
}
"""Each role's own material (an entry like those of ``plan/knowledge/materials.yaml``)."""
KIND_ROLES: dict[str, Role] = {
    "wood": "wood", "planks": "wood", "fabric": "fabric", "carpet": "fabric", "tatami": "plant",
    "metal": "metal", "glass": "glass", "tile": "ceramic", "marble": "stone", "stone": "stone",
    "brick": "stone", "concrete": "stone", "plaster": "paint", "wallpaper": "paper", "plain": "paint",
}
"""The role a material kind dresses when the words name it after their first clause."""
OBJECT_TEXTURE_SCALE = 0.5
"""Object textures are this fraction of the room texture size (objects are small on screen)."""
MIN_OBJECT_PX = 32


@dataclass
class Part:
    """One material part of an object, in the object's local frame."""

    role: Role
    color: str
    mesh: trimesh.Trimesh
    spec: MaterialSpec
    body: bool = False
    """Whether the part is of the body role (dressed in the object's material words)."""


def _plain(spec: MaterialSpec) -> MaterialSpec:
    return replace(spec, kind="plain", variant="", tile_m=1.0) if spec.textured else spec


def _clause_role(entry: dict[str, Any]) -> Role:
    if entry.get("variant") == "leather":
        return "leather"
    return KIND_ROLES.get(str(entry["kind"]), "paint")


def _metallic(role: Role, spec: MaterialSpec) -> MaterialSpec:
    if role == "metal" and spec.metallic < MIN_METALLIC:
        return replace(spec, metallic=MIN_METALLIC)
    return spec


def part_spec(role: Role, color: str, words: str, size_px: int, alpha: float = 1.0,
              body: bool = False) -> MaterialSpec:
    """The material of a part of ``role`` and ``color``, given the object's material words;
    ``body``: the part is of the object's body role."""
    if role not in ROLE_MATERIALS:
        raise ValueError(f"unknown material role {role!r}")
    if role == "glass":
        return MaterialSpec(kind="glass", color=color, roughness=0.05, alpha=min(GLASS_ALPHA, round(alpha, 3)),
                            size_px=size_px)
    clauses = material_clauses(words)
    spec: MaterialSpec | None = None
    match = next((c for c in clauses if _clause_role(c[0]) == role), None)
    if match is not None:  # "linen bedding on dark wood": the frame is the wood, the bedding the linen
        spec = spec_from_entry(match[0], "furniture", match[1], color, size_px)
    elif body and clauses and (role != "metal" or clauses[0][0]["kind"] == "metal"):
        spec = surface_material(words, "furniture", size_px, color=color)
    if spec is None:
        spec = spec_from_entry(ROLE_MATERIALS[role], "furniture", [], color, size_px)
        if not body:
            spec = _plain(spec)
    if alpha < 1.0:
        spec = replace(_plain(spec), roughness=TRANSLUCENT_ROUGHNESS, alpha=round(alpha, 3))
    return _metallic(role, spec)


def split_by_role(mesh: trimesh.Trimesh) -> list[tuple[Role, str, int, np.ndarray]]:
    """(role, hex colour, alpha, face indices) per distinct (role, face colour), in
    first-seen order. The roles are those the asset builder stored per face."""
    roles = np.array([ROLES.index(r) for r in face_roles(mesh)], dtype=np.int64)
    colors = np.asarray(cast(ColorVisuals, mesh.visual).vertex_colors)[np.asarray(mesh.faces)[:, 0]]
    keys, first, inverse = np.unique(np.column_stack([roles, colors]), axis=0, return_index=True,
                                     return_inverse=True)
    out = []
    for k in np.argsort(first):
        key = keys[k]
        out.append((ROLES[int(key[0])], to_hex(key[1:4]), int(key[4]),
                    np.flatnonzero(inverse.reshape(-1) == k)))
    return out


def object_parts(mesh: trimesh.Trimesh, words: str, body_role: Role | None,
                 size_px: int | None = None, textures: bool = True) -> list[Part]:
    """Split a role-labelled object mesh into material parts (see module doc).

    ``body_role`` is the role of the object's body (the role its family's primary colour
    paints, :func:`anyhome.assets.procedural._parts.slot_role`); None: no part takes the
    words as its body. Textured parts get planar UVs in meters / tile size (faces split
    apart) and textures of ``size_px * OBJECT_TEXTURE_SCALE`` texels; plain parts keep
    shared vertices. ``textures=False`` leaves the images out of the materials (see
    :func:`anyhome.materials.images.pbr_material`).
    """
    from anyhome.materials.images import pbr_material
    from anyhome.materials.uv import textured_mesh

    size_px = max(MIN_OBJECT_PX, int(texture_size_px(size_px) * OBJECT_TEXTURE_SCALE))
    vertices, all_faces = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    parts = []
    for role, color, alpha, index in split_by_role(mesh):
        body = role == body_role
        spec = part_spec(role, color, words, size_px, alpha / 255.0, body)
        faces = all_faces[index]
        if spec.textured:
            sub = textured_mesh(vertices, faces, pbr_material(spec, textures), spec.tile_m)
        else:
            used, inverse = np.unique(faces, return_inverse=True)
            sub = trimesh.Trimesh(vertices=vertices[used], faces=inverse.reshape(-1, 3), process=False)
            sub.visual = trimesh.visual.TextureVisuals(material=pbr_material(spec))
        parts.append(Part(role, color, sub, spec, body))
    return parts
