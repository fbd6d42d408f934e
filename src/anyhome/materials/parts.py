"""Procedural object meshes -> parts, each with its own material.

The procedural assets build one vertex-coloured mesh whose colours come from the asset
record (``params.primary``, ``secondary``, ``accent``) and a few fixed colours (metal,
black, glass...). Faces are grouped by colour; each group becomes a part whose role
picks its material:

- ``primary`` (the primary colour, or a lighter/darker shade of it): the object's
  material words, textured, tinted by the part's own colour;
- ``secondary`` / ``accent``: the next clauses of the material words if there are
  ("oak and matte black metal": the metal), else fabric (secondary) or, for an accent,
  the metal the words name or a semi-gloss finish; plain factors;
- ``glass`` (the assets' glass colour): blended glass, alpha GLASS_ALPHA;
- ``translucent`` (any other colour with alpha, a lamp shade): blended, its own alpha;
- ``metal``, ``black``, ``textile``, ``detail``: plain factors.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import trimesh

from anyhome.assets.colors import to_hex, to_rgba
from anyhome.assets.procedural._parts import BLACK, DARK_METAL, GLASS, METAL, TEXTILE_WHITE
from anyhome.materials.catalog import (
    MaterialSpec,
    material_clauses,
    spec_from_entry,
    surface_material,
    texture_size_px,
)

BRASS = "#c9a54a"
"""The brass of the fixture and curio assets."""
GLASS_ALPHA = 0.35
TRANSLUCENT_ROUGHNESS = 0.7
"""Roughness of translucent non-glass parts (lamp shades)."""
SHADE_TOL = 1.6
"""How far (0-255 per channel) a colour may be from an exact shade of the primary."""
MAX_SHADE = 0.75
"""The largest lighten/darken amount still counted as a shade of the primary."""
FIXED: dict[str, tuple[str, dict[str, Any]]] = {
    METAL: ("metal", {"kind": "metal", "roughness": 0.35, "metallic": 1.0}),
    DARK_METAL: ("metal", {"kind": "metal", "roughness": 0.45, "metallic": 0.9}),
    BLACK: ("black", {"kind": "plain", "roughness": 0.5}),
    BRASS: ("metal", {"kind": "metal", "roughness": 0.3, "metallic": 1.0}),
    TEXTILE_WHITE: ("textile", {"kind": "fabric", "roughness": 0.9}),
}
"""The assets' fixed colours -> (role, entry)."""
ROLE_DEFAULTS: dict[str, dict[str, Any]] = {
    "secondary": {"kind": "fabric", "roughness": 0.85},
    "accent": {"kind": "plain", "roughness": 0.5},
    "detail": {"kind": "plain", "roughness": 0.6},
}
OBJECT_TEXTURE_SCALE = 0.5
"""Object textures are this fraction of the room texture size (objects are small on screen)."""
MIN_OBJECT_PX = 32


@dataclass
class Part:
    """One material part of an object, in the object's local frame."""

    role: str
    color: str
    mesh: trimesh.Trimesh
    spec: MaterialSpec


def shade_of(color: str, base: str) -> bool:
    """Whether ``color`` is ``base`` mixed towards white or black by at most MAX_SHADE."""
    c = to_rgba(color)[:3].astype(float)
    b = to_rgba(base)[:3].astype(float)
    for target in (np.zeros(3), np.full(3, 255.0)):
        span = target - b
        if np.abs(span).max() < 1.0:
            continue
        t = float(np.dot(c - b, span) / np.dot(span, span))
        if 0.0 < t <= MAX_SHADE and np.abs(b + span * t - c).max() <= SHADE_TOL:
            return True
    return False


def _plain(spec: MaterialSpec) -> MaterialSpec:
    return replace(spec, kind="plain", variant="", tile_m=1.0) if spec.textured else spec


def part_spec(role: str, color: str, words: str, size_px: int, alpha: float = 1.0) -> MaterialSpec:
    """The material of a part with a role and colour, given the object's material words."""
    if role == "glass":
        return MaterialSpec(kind="glass", color=color, roughness=0.05, alpha=GLASS_ALPHA,
                            size_px=size_px)
    if role == "translucent":
        return MaterialSpec(kind="plain", color=color, roughness=TRANSLUCENT_ROUGHNESS,
                            alpha=round(alpha, 3), size_px=size_px)
    if role == "primary":
        return surface_material(words, "furniture", size_px, color=color)
    if color in FIXED:  # the assets' own metal, black and textile colours
        return _plain(spec_from_entry(FIXED[color][1], "furniture", [], color, size_px))
    clauses = material_clauses(words)
    index = {"secondary": 1, "accent": 2}.get(role)
    if index is not None and len(clauses) > index:
        entry, clause_words = clauses[index]
        return _plain(spec_from_entry(entry, "furniture", clause_words, color, size_px))
    metals = [c for c in clauses if c[0]["kind"] == "metal"]
    if role == "accent" and metals:  # handles and trim of "oak and brass"
        return _plain(spec_from_entry(metals[0][0], "furniture", metals[0][1], color, size_px))
    entry = ROLE_DEFAULTS.get(role, ROLE_DEFAULTS["detail"])
    return _plain(spec_from_entry(entry, "furniture", [], color, size_px))


def role_of(color: str, alpha: int, params: dict[str, Any]) -> str:
    """A part's role from its colour and the asset's colour parameters."""
    if color == GLASS:
        return "glass"
    if alpha < 255:
        return "translucent"
    primary = str(params.get("primary", "")).lower()
    if primary and color == primary:
        return "primary"
    for role in ("secondary", "accent"):
        if color == str(params.get(role, "")).lower():
            return role
    if color in FIXED:
        return FIXED[color][0]
    if primary and shade_of(color, primary):
        return "primary"
    return "detail"


def split_by_color(mesh: trimesh.Trimesh) -> list[tuple[str, int, np.ndarray]]:
    """(hex colour, alpha, face indices) per distinct face colour, in first-seen order."""
    colors = np.asarray(mesh.visual.vertex_colors)[np.asarray(mesh.faces)[:, 0]]
    keys, first, inverse = np.unique(colors, axis=0, return_index=True, return_inverse=True)
    out = []
    for k in np.argsort(first):
        rgba = keys[k]
        out.append((to_hex(rgba[:3]), int(rgba[3]), np.flatnonzero(inverse.reshape(-1) == k)))
    return out


def object_parts(mesh: trimesh.Trimesh, params: dict[str, Any], words: str,
                 size_px: int | None = None, textures: bool = True) -> list[Part]:
    """Split a vertex-coloured object mesh into material parts (see module doc).

    Textured parts get planar UVs in meters / tile size (faces split apart) and textures
    of ``size_px * OBJECT_TEXTURE_SCALE`` texels; plain parts keep shared vertices. ``textures=False`` leaves the images out of the
    materials (see :func:`anyhome.materials.images.pbr_material`).
    """
    from anyhome.materials.images import pbr_material
    from anyhome.materials.uv import textured_mesh

    size_px = max(MIN_OBJECT_PX, int(texture_size_px(size_px) * OBJECT_TEXTURE_SCALE))
    vertices, all_faces = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    parts = []
    for color, alpha, index in split_by_color(mesh):
        role = role_of(color, alpha, params)
        spec = part_spec(role, color, words, size_px, alpha / 255.0)
        faces = all_faces[index]
        if spec.textured:
            sub = textured_mesh(vertices, faces, pbr_material(spec, textures), spec.tile_m)
        else:
            used, inverse = np.unique(faces, return_inverse=True)
            sub = trimesh.Trimesh(vertices=vertices[used], faces=inverse.reshape(-1, 3), process=False)
            sub.visual = trimesh.visual.TextureVisuals(material=pbr_material(spec))
        parts.append(Part(role, color, sub, spec))
    return parts
