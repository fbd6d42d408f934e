"""Turn the house's trimesh Scene (:mod:`anyhome.scene`) into flat vertex batches for the GPU.

Every triangle corner becomes one vertex (no index buffer) carrying its plan-frame
position and normal, a tangent (for normal maps), texture coordinates, linear base
colour, roughness/metallic factors, the room whose light reaches it and the instance it
belongs to. Corners are grouped into batches by layer (``"ceiling"`` or ``"main"``) and
textures: base colour, metallicRoughness and normal map (glTF's three PBR maps; the
last two are shared by every colour of a material, so they add hardly any batches).

Tangents are computed here, per vertex in numpy, from each triangle's positions and UVs
(:func:`corner_tangents`), only for meshes with a normal map; the shader
Gram-Schmidts them against the interpolated normal. (A per-fragment cotangent frame
from screen-space derivatives would need no vertex data but costs every shaded pixel
more, which is what software Mesa pays for.)

Colour spaces: base-colour textures are sRGB (decoded in the shader, as glTF says).
glTF says ``baseColorFactor`` and vertex colours are linear. The in-memory scene of
:func:`anyhome.scene.build_scene` keeps AnyHome's sRGB values there (hex colours as
they are; ``write_glb`` converts them to linear in the file, see
:func:`anyhome.materials.gltf.linear_factors`), so ``FACTORS_ARE_SRGB`` decodes them here.

Layers: ``"main"`` (opaque, always drawn), ``"ceiling"`` (ceilings and ceiling light
fixtures, hidden from above) and ``"glass"`` (blended, drawn last, casts no shadow and
is left out of depth and instance maps).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np
import shapely
import trimesh
from shapely.geometry import Polygon
from trimesh.visual import ColorVisuals

from anyhome.house import House
from anyhome.scene import ROOT_NODE

SMOOTH_ANGLE_DEG = 35.0
"""Corners whose vertex normal is within this angle of the face normal shade smoothly."""
DEFAULT_ROUGHNESS = 0.7
"""Roughness of geometry without a material (vertex-coloured objects)."""
DEFAULT_COLOR = (0.6, 0.6, 0.6, 1.0)
"""Linear base colour of geometry with neither material colour nor vertex colours."""
ROOM_PROBE_M = 0.03
"""A wall face belongs to the room that a point this far in front of it lies in."""
WALL_REACH_M = 0.06
"""A face on a wall's edge (a door jamb) counts as in a room it lies this close to."""
FACTORS_ARE_SRGB = True
"""Decode baseColorFactor and vertex colours as sRGB (see the module doc); False is glTF's reading."""
CEILING_PARTS = frozenset({"ceiling", "light", "beams", "coffers"})
"""Room parts (``room:<id>:<part>``) hidden from the bird's-eye view: the ceiling, its
light and what hangs under it (beams, coffers: anyhome.export.ceilings)."""
PROBED_PARTS = frozenset({"walls", "skirting", "frame", "leaf", "glass"})
"""Parts whose faces take the light of the room they face (walls and what sits in them)."""
GROUND_COLOR = (0.16, 0.19, 0.13, 1.0)
"""Linear colour of the ground plane under the house."""
GROUND_MARGIN_M = 40.0
"""How far the ground plane reaches beyond the house."""
GROUND_Z_M = -0.06
"""Height of the ground plane (just under the floor slabs, which end at -0.05 m)."""

VERTEX_DTYPE = np.dtype([
    ("pos", "<f4", 3), ("nrm", "<f4", 3), ("tan", "<f4", 4), ("uv", "<f4", 2), ("col", "<f4", 4),
    ("rm", "<f4", 2), ("emi", "<f4", 3), ("room", "<i4"), ("inst", "<i4"),
])
"""One vertex as uploaded; ``VERTEX_FORMAT`` is the same layout for moderngl. ``tan``:
unit tangent (direction of increasing u) and handedness w (bitangent = w * cross(nrm,
tan)), zero where the batch has no normal map."""
VERTEX_FORMAT = "3f 3f 4f 2f 4f 2f 3f 1i 1i"
VERTEX_ATTRS = ("in_pos", "in_nrm", "in_tan", "in_uv", "in_col", "in_rm", "in_emi", "in_room",
                "in_inst")


@dataclass
class Batch:
    """Vertices that draw with one texture (or none) in one layer."""

    layer: str
    texture: Any | None
    """A PIL image (the material's baseColorTexture) or None."""
    vertices: np.ndarray
    """(n,) VERTEX_DTYPE, three per triangle."""
    mr_texture: Any | None = None
    """PIL image of the metallicRoughnessTexture (roughness in G, metallic in B) or None."""
    normal_texture: Any | None = None
    """PIL image of the tangent-space normalTexture or None."""
    normal_scale: float = 1.0
    """normalTexture.scale: multiplies the map's x and y."""


@dataclass
class SceneMeshes:
    """Everything the renderer draws, in the plan frame."""

    batches: list[Batch]
    instances: list[str]
    """Instance names by index: the house's objects first (``object:<id>``, in
    ``house.objects`` order; an object's part nodes count as the object), then the
    other geometry nodes (``room:<id>:walls``...)."""
    bounds: np.ndarray
    """(2, 3) float: min and max corner of the house geometry."""
    n_triangles: int
    room_ids: list[str] = field(default_factory=list)
    """Room ids by the room index stored in each vertex."""
    fixtures: dict[str, np.ndarray] = field(default_factory=dict)
    """Room id -> (2, 3) bounds of its ceiling light fixture (``room:<id>:light``), if any."""


_NO_MAPS = (0, 0, 0, 1.0)
"""Batch key of geometry without textures."""


def node_kind(node: str, meta: dict) -> tuple[str, str | None]:
    """(part, room id) of a scene node: ``room:<id>:<part>`` gives its part (floor,
    walls, ceiling, skirting, light...), ``door:<id>:<part>`` and ``window:<id>:<part>``
    theirs (room None), anything else is an ``"object"`` of ``meta["room"]``."""
    head, _, rest = node.partition(":")
    if head == "room" and ":" in rest:
        room_id, part = rest.rsplit(":", 1)
        return part, meta.get("room", room_id)
    if head in ("door", "window") and ":" in rest:
        return rest.rsplit(":", 1)[1], None
    return "object", meta.get("room")


def _owner(node: str, parents: dict[str, str], objects: dict[str, str]) -> str:
    """The instance a geometry node belongs to: its nearest ancestor (or itself) that
    is a house object's node ``object:<id>``, else the node itself."""
    at: str | None = node
    seen = set()
    while at is not None and at not in seen:
        if at in objects:
            return at
        seen.add(at)
        at = parents.get(at)
    return node


def _plan_transforms(scene: trimesh.Scene) -> dict[str, np.ndarray]:
    """Node -> 4x4 transform from the geometry's frame to the plan frame."""
    graph = scene.graph
    to_plan: np.ndarray = np.eye(4)
    if ROOT_NODE in graph.nodes:
        to_plan = np.linalg.inv(graph.get(ROOT_NODE)[0])
    return {node: to_plan @ graph.get(node)[0] for node in graph.nodes_geometry}


def _material_of(visual: Any) -> Any | None:
    mat = getattr(visual, "material", None)
    if mat is None:
        return None
    if not hasattr(mat, "baseColorFactor") and hasattr(mat, "to_pbr"):
        mat = mat.to_pbr()
    return mat


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    """sRGB-encoded values in [0, 1] -> linear."""
    c = np.asarray(c, dtype=np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _unit_rgba(values: Any, n: int) -> np.ndarray:
    """Colour(s) as (n, 4) linear float from uint8 or float input (alpha kept as is)."""
    a = np.asarray(values)
    scale = 255.0 if a.dtype.kind in "ui" else 1.0
    a = np.atleast_2d(a.astype(np.float64) / scale)
    if a.shape[1] == 3:
        a = np.column_stack([a, np.ones(len(a))])
    if FACTORS_ARE_SRGB:
        a = np.column_stack([srgb_to_linear(a[:, :3]), a[:, 3]])
    return np.broadcast_to(a, (n, 4)) if len(a) == 1 else a


@dataclass
class Appearance:
    """Per-corner appearance of one mesh."""

    color: np.ndarray
    """(3F, 4) float: linear base colour and alpha of each triangle corner."""
    uv: np.ndarray | None = None
    """(3F, 2) float texture coordinates (origin bottom-left, as trimesh keeps them)."""
    texture: Any | None = None
    """PIL image of the base colour, or None."""
    mr_texture: Any | None = None
    """PIL image of glTF's metallicRoughnessTexture (G roughness, B metallic), or None."""
    normal_texture: Any | None = None
    """PIL image of the tangent-space normal map, or None."""
    normal_scale: float = 1.0
    """glTF normalTexture.scale (read from a ``normalScale`` attribute of the material
    where a loader keeps it; trimesh drops it, AnyHome's exporter writes none)."""
    roughness: float = DEFAULT_ROUGHNESS
    metallic: float = 0.0
    emissive: tuple[float, float, float] = (0.0, 0.0, 0.0)
    """Linear emitted colour (glTF emissiveFactor)."""
    blend: bool = False
    """Drawn transparent (glTF alphaMode BLEND)."""


def corner_appearance(mesh: trimesh.Trimesh) -> Appearance:
    """The appearance of each triangle corner of ``mesh`` from its visual: vertex or face
    colours, or a PBR (or simple) material with factor, texture and UVs."""
    faces = mesh.faces
    n = len(faces) * 3
    visual = mesh.visual
    color = np.broadcast_to(np.asarray(DEFAULT_COLOR), (n, 4))
    out = Appearance(color)
    kind = getattr(visual, "kind", None)
    if kind == "vertex":
        color = _unit_rgba(cast(ColorVisuals, visual).vertex_colors, len(mesh.vertices))[faces.reshape(-1)]
    elif kind == "face":
        color = np.repeat(_unit_rgba(cast(ColorVisuals, visual).face_colors, len(faces)), 3, axis=0)
    mat = _material_of(visual)
    if mat is not None:
        factor = getattr(mat, "baseColorFactor", None)
        if factor is not None:
            color = _unit_rgba(factor, 1)[0] * np.ones((n, 4))
        vcol = (getattr(visual, "vertex_attributes", None) or {}).get("color")
        if vcol is not None and len(vcol) == len(mesh.vertices):
            color = color * _unit_rgba(vcol, len(mesh.vertices))[faces.reshape(-1)]
        vuv = getattr(visual, "uv", None)
        if vuv is not None and len(vuv) == len(mesh.vertices):
            maps = [getattr(mat, name, None) for name in
                    ("baseColorTexture", "metallicRoughnessTexture", "normalTexture")]
            if any(m is not None for m in maps):
                out.texture, out.mr_texture, out.normal_texture = maps
                out.uv = np.asarray(vuv, dtype=np.float64)[faces.reshape(-1)]
        scale = getattr(mat, "normalScale", None)
        if out.normal_texture is not None and scale is not None:
            out.normal_scale = float(scale)
        if getattr(mat, "roughnessFactor", None) is not None:
            out.roughness = float(mat.roughnessFactor)
        if getattr(mat, "metallicFactor", None) is not None:
            out.metallic = float(mat.metallicFactor)
        emissive = getattr(mat, "emissiveFactor", None)
        if emissive is not None:
            e = np.asarray(emissive, dtype=np.float64).ravel()  # glTF: three numbers
            out.emissive = (float(e[0]), float(e[1]), float(e[2]))
        out.blend = getattr(mat, "alphaMode", None) == "BLEND"
    out.color = np.asarray(color, dtype=np.float64)
    return out


def corner_normals(mesh: trimesh.Trimesh) -> np.ndarray:
    """(3F, 3) shading normals: smooth across gentle edges, flat across sharp ones."""
    fn = np.asarray(mesh.face_normals, dtype=np.float64)
    vn = np.asarray(mesh.vertex_normals, dtype=np.float64)[mesh.faces]
    smooth = np.einsum("fcj,fj->fc", vn, fn) > np.cos(np.radians(SMOOTH_ANGLE_DEG))
    return np.where(smooth[..., None], vn, fn[:, None, :]).reshape(-1, 3)


def corner_tangents(verts: np.ndarray, faces: np.ndarray, uv: np.ndarray,
                    normals: np.ndarray) -> np.ndarray:
    """(3F, 4) per-corner tangents for normal mapping: xyz the unit direction of
    increasing u (made perpendicular to the corner's normal), w the handedness (+1 or
    -1: the direction of increasing v is ``w * cross(normal, tangent)``).

    Each triangle's tangent and bitangent come from its edges and UV differences; a
    vertex shared by several triangles gets the sum of theirs (area weighted), so
    tangents are smooth where UVs are. Triangles with degenerate UVs get a zero tangent
    (the shader then leaves their normal unperturbed).

    Parameters
    ----------
    verts : (V, 3) float, vertex positions in the frame the normals are in
    faces : (F, 3) int
    uv : (3F, 2) float, each corner's texture coordinates
    normals : (3F, 3) float, unit shading normals of the corners
    """
    tri = verts[faces]
    e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    duv = uv.reshape(-1, 3, 2)
    d1, d2 = duv[:, 1] - duv[:, 0], duv[:, 2] - duv[:, 0]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    ok = np.abs(det) > 1e-12
    sign = np.where(det < 0, -1.0, 1.0)
    # (e1 d2v - e2 d1v) / det, times |det| (the UV area) as the weight of the sum
    t = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * (sign * ok)[:, None]
    b = (e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * (sign * ok)[:, None]
    idx = faces.reshape(-1)
    n_v = len(verts)
    # AnyHome's planar-UV meshes give every face vertices of its own (nothing to sum)
    split = n_v == len(idx) and bool((idx == np.arange(n_v)).all())
    if not split and np.bincount(idx, minlength=n_v).max() > 1:
        acc_t = np.column_stack([np.bincount(idx, np.repeat(t[:, k], 3), n_v) for k in range(3)])
        acc_b = np.column_stack([np.bincount(idx, np.repeat(b[:, k], 3), n_v) for k in range(3)])
        ct, cb = acc_t[idx], acc_b[idx]
    else:
        ct, cb = np.repeat(t, 3, axis=0), np.repeat(b, 3, axis=0)
    ct = ct - normals * np.einsum("ij,ij->i", ct, normals)[:, None]
    length = np.linalg.norm(ct, axis=1)
    good = length > 1e-12
    out = np.zeros((len(idx), 4))
    out[good, :3] = ct[good] / length[good, None]
    n, t3 = normals, out[:, :3]
    handed = ((n[:, 1] * t3[:, 2] - n[:, 2] * t3[:, 1]) * cb[:, 0]
              + (n[:, 2] * t3[:, 0] - n[:, 0] * t3[:, 2]) * cb[:, 1]
              + (n[:, 0] * t3[:, 1] - n[:, 1] * t3[:, 0]) * cb[:, 2])  # (n x t) . b
    out[good, 3] = np.where(handed[good] < 0, -1.0, 1.0)
    return out


def _face_rooms(tri: np.ndarray, normals: np.ndarray, rooms: list[Polygon]) -> np.ndarray:
    """Room index of each triangle's front side (-1 outside every room)."""
    centre = tri.mean(axis=1)
    probe = centre[:, :2] + normals[:, :2] * ROOM_PROBE_M
    out = np.full(len(tri), -1, dtype=np.int32)
    for reach in (0.0, WALL_REACH_M):
        for i, poly in enumerate(rooms):
            todo = out < 0
            if not todo.any():
                return out
            area = poly.buffer(reach) if reach else poly
            hit = shapely.contains_xy(area, probe[todo, 0], probe[todo, 1])
            out[np.flatnonzero(todo)[hit]] = i
    return out


def _ground(bounds: np.ndarray, inst: int) -> np.ndarray:
    lo, hi = bounds[0, :2] - GROUND_MARGIN_M, bounds[1, :2] + GROUND_MARGIN_M
    quad = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    tri = quad[[0, 1, 2, 0, 2, 3]]
    v = np.zeros(6, dtype=VERTEX_DTYPE)
    v["pos"] = np.column_stack([tri, np.full(6, GROUND_Z_M)])
    v["nrm"] = (0.0, 0.0, 1.0)
    v["uv"] = tri
    v["col"] = GROUND_COLOR
    v["rm"] = (0.95, 0.0)
    v["room"] = -1
    v["inst"] = inst
    return v


def scene_meshes(house: House, scene: trimesh.Scene) -> SceneMeshes:
    """Flatten ``scene`` (from :func:`anyhome.scene.build_scene`) into batches.

    Parameters
    ----------
    house : the house the scene was built from (rooms give light zones, objects give ids)
    scene : nodes ``room:<id>:floor|walls|ceiling`` and ``object:<id>``
    """
    room_ids = [r.id for r in house.rooms]
    room_index = {rid: i for i, rid in enumerate(room_ids)}
    polys = [Polygon(r.polygon).buffer(0) for r in house.rooms]
    instances = [f"object:{o.id}" for o in house.objects]
    inst_index = {name: i for i, name in enumerate(instances)}
    groups: dict[tuple[str, tuple], list[np.ndarray]] = defaultdict(list)
    textures: dict[tuple, tuple] = {_NO_MAPS: (None, None, None, 1.0)}  # key (map ids) -> maps
    fixtures: dict[str, np.ndarray] = {}
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    n_tri = 0
    object_rooms = {f"object:{o.id}": o.room for o in house.objects}
    parents = scene.graph.transforms.parents
    for node, matrix in _plan_transforms(scene).items():
        geom_name = scene.graph[node][1]
        mesh = scene.geometry.get(geom_name)
        if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
            continue
        owner = _owner(node, parents, object_rooms)
        room_id: str | None
        if owner in object_rooms:
            category, room_id = "object", object_rooms[owner]
        else:
            category, room_id = node_kind(node, dict(mesh.metadata or {}))
        if owner not in inst_index:
            inst_index[owner] = len(instances)
            instances.append(owner)
        verts = trimesh.transform_points(mesh.vertices, matrix)
        tri = verts[mesh.faces]
        lin = matrix[:3, :3]
        nrm_mat = np.linalg.inv(lin).T
        normals = corner_normals(mesh) @ nrm_mat.T
        normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
        face_n = np.asarray(mesh.face_normals) @ nrm_mat.T
        look = corner_appearance(mesh)
        v = np.zeros(len(tri) * 3, dtype=VERTEX_DTYPE)
        v["pos"] = tri.reshape(-1, 3)
        v["nrm"] = normals
        if look.normal_texture is not None and look.uv is not None:  # set together
            v["tan"] = corner_tangents(verts, mesh.faces, look.uv, normals)
        v["uv"] = 0.0 if look.uv is None else look.uv
        v["col"] = look.color
        v["rm"] = (look.roughness, look.metallic)
        v["emi"] = look.emissive
        if category in PROBED_PARTS or (room_id is None and category != "object"):
            v["room"] = np.repeat(_face_rooms(tri, face_n, polys), 3)
        else:
            v["room"] = room_index.get(room_id, -1) if room_id is not None else -1
        v["inst"] = inst_index[owner]
        if category == "light" and room_id is not None:
            fixtures[room_id] = np.array([verts.min(axis=0), verts.max(axis=0)])
        layer = "glass" if look.blend else "ceiling" if category in CEILING_PARTS else "main"
        maps = (look.texture, look.mr_texture, look.normal_texture)
        key = (*(0 if m is None else id(m) for m in maps),
               look.normal_scale if look.normal_texture is not None else 1.0)
        textures[key] = (*maps, key[3])
        groups[(layer, key)].append(v)
        lo, hi = np.minimum(lo, verts.min(axis=0)), np.maximum(hi, verts.max(axis=0))
        n_tri += len(tri)
    if n_tri == 0:
        lo, hi = np.zeros(3), np.ones(3)
    bounds = np.array([lo, hi])
    groups[("main", _NO_MAPS)].append(_ground(bounds, -1))
    order = {"main": 0, "ceiling": 1, "glass": 2}  # glass last: it blends over the rest
    batches = []
    for (layer, key), parts in sorted(groups.items(), key=lambda kv: order[kv[0][0]]):
        base, mr, normal, scale = textures[key]
        batches.append(Batch(layer, base, np.concatenate(parts), mr, normal, scale))
    return SceneMeshes(batches, instances, bounds, n_tri, room_ids, fixtures)
