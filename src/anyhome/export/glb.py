"""GLB export: one node per room part (floor, walls, ceiling) and per object.

The plan frame (x east, y north, z up) is turned into glTF's +Y-up frame by a single
root node ``house`` whose matrix maps plan ``(x, y, z)`` to glTF ``(x, z, -y)``; every
other node hangs under it with its transform in plan coordinates.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import trimesh
from shapely.geometry import Polygon

from anyhome.assets import build_object_mesh, family_for
from anyhome.assets.colors import material_color, to_rgba
from anyhome.errors import ExportError
from anyhome.export.output import write_file
from anyhome.export.walls import WALL_THICKNESS_M, solid_blocks, wall_pieces
from anyhome.house import House

FLOOR_THICKNESS_M = 0.05
"""Floor slabs run from z = -thickness to z = 0; ceilings from the room height up."""
ROOT_NODE = "house"
PLAN_TO_GLTF = np.array(
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
)
"""Plan (x, y, z) -> glTF (x, z, -y)."""
DEFAULT_COLORS = {"floor": "#a0714a", "walls": "#ece8e0", "ceiling": "#f6f4f0"}
ROUGHNESS = {"floor": 0.6, "walls": 0.9, "ceiling": 0.95}


def _material(kind: str, words: str) -> trimesh.visual.material.PBRMaterial:
    color = material_color(words or "") or DEFAULT_COLORS[kind]
    return trimesh.visual.material.PBRMaterial(
        name=f"{kind}:{words or 'default'}",
        baseColorFactor=to_rgba(color),
        metallicFactor=0.0,
        roughnessFactor=ROUGHNESS[kind],
    )


def _slab(polygon, z0: float, z1: float) -> trimesh.Trimesh:
    poly = Polygon(polygon)
    if not poly.is_valid:
        poly = poly.buffer(0)
    mesh = trimesh.creation.extrude_polygon(poly, z1 - z0)
    mesh.apply_translation((0.0, 0.0, z0))
    return mesh


def _box_corners(a, u, t0, t1, z0, z1, thick) -> np.ndarray:
    n = np.array([-u[1], u[0]]) * thick / 2
    p0, p1 = a + u * t0, a + u * t1
    quad = np.array([p0 - n, p1 - n, p1 + n, p0 + n])
    return np.vstack([np.column_stack([quad, np.full(4, z0)]), np.column_stack([quad, np.full(4, z1)])])


_BOX_FACES = np.array(
    [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
     [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
)


def wall_meshes(house: House, thickness: float = WALL_THICKNESS_M) -> dict[str, trimesh.Trimesh]:
    """One wall mesh per room (pieces shared by two rooms belong to the first)."""
    verts: dict[str, list[np.ndarray]] = {}
    for piece in wall_pieces(house):
        u = piece.direction
        for t0, t1, z0, z1 in solid_blocks(piece):
            ext0 = thickness / 2 if t0 <= 1e-9 else 0.0  # close the corners
            ext1 = thickness / 2 if t1 >= piece.length - 1e-9 else 0.0
            verts.setdefault(piece.room, []).append(
                _box_corners(piece.a, u, t0 - ext0, t1 + ext1, z0, z1, thickness))
    out = {}
    for room_id, boxes in verts.items():
        v = np.concatenate(boxes)
        f = np.concatenate([_BOX_FACES + 8 * i for i in range(len(boxes))])
        out[room_id] = trimesh.Trimesh(vertices=v, faces=f, process=False)
    return out


def object_transform(position, yaw: float) -> np.ndarray:
    """Local object frame -> plan frame."""
    m = trimesh.transformations.rotation_matrix(float(yaw), [0, 0, 1])
    m[:3, 3] = position
    return m


def build_scene(house: House) -> trimesh.Scene:
    """The house as a trimesh Scene (glTF frame via the root node)."""
    scene = trimesh.Scene()
    scene.graph.update(frame_from=scene.graph.base_frame, frame_to=ROOT_NODE, matrix=PLAN_TO_GLTF)
    scene.metadata.update({"generator": "anyhome", "prompt": house.prompt, "seed": house.seed,
                           "style": house.style, "up": "+Y", "units": "meters"})
    walls = wall_meshes(house)

    def add(mesh: trimesh.Trimesh, name: str, meta: dict, transform=None) -> None:
        mesh.metadata.update(meta)
        scene.add_geometry(mesh, node_name=name, geom_name=name, parent_node_name=ROOT_NODE,
                           transform=transform, metadata=dict(meta))

    for room in house.rooms:
        base = {"room": room.id, "room_name": room.name, "room_type": room.type}
        floor = _slab(room.polygon, -FLOOR_THICKNESS_M, 0.0)
        floor.visual = trimesh.visual.TextureVisuals(material=_material("floor", room.materials.get("floor", "")))
        add(floor, f"room:{room.id}:floor", {**base, "name": f"{room.name} floor", "category": "floor"})
        if room.id in walls:
            w = walls[room.id]
            w.visual = trimesh.visual.TextureVisuals(material=_material("walls", room.materials.get("walls", "")))
            add(w, f"room:{room.id}:walls", {**base, "name": f"{room.name} walls", "category": "walls"})
        ceil = _slab(room.polygon, room.height, room.height + FLOOR_THICKNESS_M)
        ceil.visual = trimesh.visual.TextureVisuals(
            material=_material("ceiling", room.materials.get("ceiling", "")))
        add(ceil, f"room:{room.id}:ceiling", {**base, "name": f"{room.name} ceiling", "category": "ceiling"})
    for obj in house.objects:
        mesh = build_object_mesh(obj)
        meta = {"id": obj.id, "name": obj.name, "category": obj.category, "room": obj.room,
                "support": obj.support, "material": obj.material,
                "family": (obj.asset or {}).get("family") or family_for(obj.category, obj.name)}
        add(mesh, f"object:{obj.id}", meta, object_transform(obj.position, obj.yaw))
    return scene


def write_glb(house: House, path: str | os.PathLike[str]) -> Path:
    """Write the house as a binary glTF (GLB) file atomically; return its path."""
    path = Path(path)
    try:
        data = build_scene(house).export(file_type="glb")
    except Exception as e:  # trimesh raises many kinds
        raise ExportError(f"could not build the GLB for {path.name}: {e}") from e
    return write_file(path, data)
