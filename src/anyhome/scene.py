"""The house as one 3-D scene, built once for the GLB export and the renderer.

Nodes: one per room part (``room:<id>:floor|walls|ceiling``) and per object
(``object:<id>``, with one child per material part, ``object:<id>:<role>``), plus the
architecture pieces (doors, windows, skirting, lights), all under a single root node
``house`` whose matrix maps plan ``(x, y, z)`` (x east, y north, z up) to glTF's +Y-up
``(x, z, -y)``; every other node hangs under it with its transform in plan coordinates.

Surfaces carry PBR materials with procedural textures (``anyhome.materials``): floors,
walls and ceilings get planar UVs in meters / tile size. Ceilings stay their own nodes
(category ``ceiling``) so a viewer can hide them; an open-air room (``Room.open_air``)
has none, a pitched or vaulted one is sloped (:mod:`anyhome.export.ceilings`). Texture size: ``texture_px``, else
``$ANYHOME_TEXTURE_PX``, else 256. :mod:`anyhome.export.glb` writes the scene as a GLB
file; :mod:`anyhome.render` flattens it for the GPU.
"""

from __future__ import annotations

import numpy as np
import shapely
import trimesh
from shapely.geometry import Polygon

from anyhome.assets import build_object_mesh, family_for
from anyhome.assets.library import SOURCE as LIBRARY_SOURCE
from anyhome.assets.library import library_parts
from anyhome.assets.procedural._parts import slot_role
from anyhome.assets.registry import procedural_record
from anyhome.errors import ExportError
from anyhome.export.architecture import architecture_meshes
from anyhome.export.ceilings import ceiling_mesh, slab, structure_mesh
from anyhome.export.walls import WALL_THICKNESS_M, solid_blocks, wall_pieces
from anyhome.house import House, HouseObject, Room
from anyhome.materials import (
    MaterialSpec,
    material_key,
    object_parts,
    pbr_material,
    surface_material,
    texture_size_px,
)
from anyhome.materials.catalog import ceiling_materials
from anyhome.materials.uv import face_normals, textured_mesh
from anyhome.sanitize import clean_text

FLOOR_THICKNESS_M = 0.05
"""Floor slabs run from z = -thickness to z = 0; ceilings from the room height up."""
ROOT_NODE = "house"
PLAN_TO_GLTF = np.array(
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
)
"""Plan (x, y, z) -> glTF (x, z, -y)."""
ROOM_PARTS: tuple[str, ...] = ("floor", "walls", "ceiling")
WALL_PROBE_M = 0.03
"""A wall face belongs to the room this far in front of it (see room_wall_meshes)."""


def _slab(polygon, z0: float, z1: float, hole: Polygon | None = None) -> trimesh.Trimesh | None:
    """The polygon extruded from ``z0`` to ``z1``, less ``hole`` (a stair opening); None
    when nothing is left."""
    poly = Polygon(polygon)
    if not poly.is_valid:
        poly = poly.buffer(0)
    return slab(poly, z0, z1, hole)


def stair_openings(house: House) -> dict[tuple[str, str], Polygon]:
    """(room id, "floor" | "ceiling") -> the opening a flight of stairs needs: over every
    ``stairs`` object, the ceiling of its room and the floor of the room one storey up
    that lies over it (the stairwell of the same footprint), so the flight climbs through
    an open well instead of into a slab."""
    from anyhome.geometry import footprint_polygon

    out: dict[tuple[str, str], Polygon] = {}
    rooms = {r.id: r for r in house.rooms}
    for o in house.objects:
        room = rooms.get(o.room)
        if o.category != "stairs" or room is None:
            continue
        box = footprint_polygon(o.position, o.size, o.yaw)
        keys = [(room.id, "ceiling")]
        above = [r for r in house.rooms if r.level == room.level + 1 and Polygon(r.polygon).intersects(box)]
        keys += [(r.id, "floor") for r in above]
        for key in keys:
            out[key] = out[key].union(box) if key in out else box
    return out


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


def room_wall_meshes(house: House, thickness: float = WALL_THICKNESS_M) -> dict[str, trimesh.Trimesh]:
    """Wall faces grouped by the room they face, so each side of a wall shared by two
    rooms wears its own room's wall material.

    An upright face belongs to the room a point ``WALL_PROBE_M`` in front of it lies in;
    faces that face no room (outside faces, tops, the reveals of openings) stay with the
    room that owns the wall piece (see :func:`wall_meshes`).
    """
    owned = wall_meshes(house, thickness)
    index = {room.id: i for i, room in enumerate(house.rooms)}
    parts = [(index[rid], m) for rid, m in owned.items() if rid in index]
    if not parts:
        return {}
    corners = np.concatenate([np.asarray(m.vertices)[np.asarray(m.faces)] for _, m in parts])
    room_of = np.concatenate([np.full(len(m.faces), i) for i, m in parts])
    normals = face_normals(corners)
    probe = corners.mean(axis=1)[:, :2] + normals[:, :2] * WALL_PROBE_M
    upright = np.abs(normals[:, 2]) < 0.5
    for i, room in enumerate(house.rooms):
        poly = Polygon(room.polygon)
        room_of[upright & shapely.contains_xy(poly, probe[:, 0], probe[:, 1])] = i
    out = {}
    for i, room in enumerate(house.rooms):
        mine = corners[room_of == i]
        if len(mine):
            out[room.id] = trimesh.Trimesh(vertices=mine.reshape(-1, 3),
                                           faces=np.arange(3 * len(mine)).reshape(-1, 3), process=False)
    return out


def object_transform(position, yaw: float) -> np.ndarray:
    """Local object frame -> plan frame."""
    m = trimesh.transformations.rotation_matrix(float(yaw), [0, 0, 1])
    m[:3, 3] = position
    return m


class _SceneBuilder:
    """Adds nodes under the root node and remembers every material spec used."""

    def __init__(self, house: House, texture_px: int | None, textures: bool) -> None:
        self.scene = trimesh.Scene()
        self.scene.graph.update(frame_from=self.scene.graph.base_frame, frame_to=ROOT_NODE,
                                matrix=PLAN_TO_GLTF)
        self.scene.metadata.update({"generator": "anyhome", "prompt": house.prompt, "seed": house.seed,
                                    "style": house.style, "up": "+Y", "units": "meters"})
        self.px = texture_size_px(texture_px)
        self.textures = textures
        self.walls = room_wall_meshes(house)
        self.openings = stair_openings(house)
        self.specs: dict[str, MaterialSpec] = {}

    def add(self, mesh: trimesh.Trimesh, name: str, meta: dict, transform=None,
            parent: str = ROOT_NODE) -> None:
        mesh.metadata.update(meta)
        self.scene.add_geometry(mesh, node_name=name, geom_name=name, parent_node_name=parent,
                                transform=transform, metadata=dict(meta))

    def surface(self, mesh: trimesh.Trimesh, spec: MaterialSpec) -> trimesh.Trimesh:
        self.specs[material_key(spec)] = spec
        return textured_mesh(mesh.vertices, mesh.faces, pbr_material(spec, self.textures), spec.tile_m)

    def room(self, room: Room, parent: str = ROOT_NODE) -> None:
        base: dict[str, str | bool] = {"room": room.id, "room_name": room.name, "room_type": room.type}
        if room.open_air:  # no ceiling node: open to the sky
            base["open_air"] = True
        elif room.ceiling != "flat":
            base["ceiling_shape"] = room.ceiling
        slabs = {"floor": _slab(room.polygon, -FLOOR_THICKNESS_M, 0.0, self.openings.get((room.id, "floor"))),
                 "ceiling": ceiling_mesh(room, FLOOR_THICKNESS_M, self.openings.get((room.id, "ceiling")))}
        ceiling, structure, structure_spec = ceiling_materials(room.materials.get("ceiling", ""), self.px)
        for part in ROOM_PARTS:
            mesh = slabs.get(part) if part != "walls" else self.walls.get(room.id)
            if mesh is None:
                continue
            words = room.materials.get(part, "")
            spec = ceiling if part == "ceiling" else surface_material(words, part, self.px)
            meta = {**base, "name": f"{room.name} {part}", "category": part, "material": words,
                    "texture": spec.kind}
            self.add(self.surface(mesh, spec), f"room:{room.id}:{part}", meta, parent=parent)
        mesh = structure_mesh(room, structure) if structure is not None and slabs["ceiling"] is not None else None
        if structure is not None and structure_spec is not None and mesh is not None:  # beams, coffers
            meta = {**base, "name": f"{room.name} {structure}", "category": structure,
                    "material": room.materials.get("ceiling", ""), "texture": structure_spec.kind}
            self.add(self.surface(mesh, structure_spec), f"room:{room.id}:{structure}", meta, parent=parent)

    def object(self, obj: HouseObject, parent: str = ROOT_NODE) -> None:
        node = f"object:{obj.id}"
        meta = {"id": obj.id, "name": obj.name, "category": obj.category, "room": obj.room,
                "support": obj.support, "material": obj.material,
                "family": (obj.asset or {}).get("family") or family_for(obj.category, obj.name)}
        self.scene.graph.update(frame_from=parent, frame_to=node,
                                matrix=object_transform(obj.position, obj.yaw), metadata=dict(meta))
        if self.library_object(obj, node):
            return
        record = _asset_record(obj)
        mesh = build_object_mesh(obj)  # (loads the families, so their slot roles are known)
        body = slot_role(record["family"], 0, str(record["params"].get("primary", "")))
        seen: dict[str, int] = {}
        for part in object_parts(mesh, obj.material, body, self.px, self.textures):
            seen[part.role] = seen.get(part.role, 0) + 1
            suffix = "" if seen[part.role] == 1 else f"-{seen[part.role]}"
            self.specs[material_key(part.spec)] = part.spec
            self.add(part.mesh, f"{node}:{part.role}{suffix}",
                     {"object": obj.id, "room": obj.room, "category": obj.category,
                      "role": part.role, "body": part.body, "texture": part.spec.kind}, parent=node)


    def library_object(self, obj: HouseObject, node: str) -> bool:
        """Add the parts of an object built from a library model, each with the model's
        own material or colours (``object:<id>:model``, ``-2``...); False when the object
        has no library record or its file is missing or changed (then the procedural
        fallback is built)."""
        record = obj.asset or {}
        if record.get("source") != LIBRARY_SOURCE:
            return False
        parts = library_parts(record, obj.size)
        if parts is None:
            return False
        for k, part in enumerate(parts):
            mat = getattr(part.visual, "material", None)
            if mat is not None:  # a name of its own: never one of the scene's material keys
                mat.name = f"library:{obj.id}:{k + 1}"
            suffix = "" if k == 0 else f"-{k + 1}"
            self.add(part, f"{node}:model{suffix}",
                     {"object": obj.id, "room": obj.room, "category": obj.category, "role": "model",
                      "body": True, "texture": "library", "asset": str(record.get("path", ""))}, parent=node)
        return True


def _asset_record(obj: HouseObject) -> dict:
    """The procedural asset record ``build_object_mesh`` builds the object from: its own,
    a library record's fallback, or one sampled from the object id when it has none."""
    record = obj.asset
    if record and record.get("source") == LIBRARY_SOURCE:
        record = record.get("fallback")
    return procedural_record(obj, record)


def scene_and_materials(house: House, texture_px: int | None = None, textures: bool = True
                        ) -> tuple[trimesh.Scene, dict[str, MaterialSpec]]:
    """The scene (see :func:`build_scene`) and every material spec it uses, by key.

    ``textures`` False leaves the images off the materials (the GLB writer embeds them
    from the specs, once per distinct image).
    """
    b = _SceneBuilder(house, texture_px, textures)
    storeys = house.level_numbers()
    if len(storeys) <= 1:
        _add_storey(b, house, ROOT_NODE)
        return b.scene, b.specs
    from anyhome.floorplan.levels import level_view

    b.walls = {}
    for k in storeys:  # each storey's walls, openings and lights on its own, under a node at its elevation
        part = level_view(house, k)
        b.walls.update(room_wall_meshes(part))
        node = f"level:{k}"
        b.scene.graph.update(frame_from=ROOT_NODE, frame_to=node, metadata={"level": k},
                             matrix=trimesh.transformations.translation_matrix((0.0, 0.0, house.elevation_m(k))))
        _add_storey(b, part, node)
    return b.scene, b.specs


def _add_storey(b: _SceneBuilder, house: House, parent: str) -> None:
    for room in house.rooms:
        b.room(room, parent)
    for obj in house.objects:
        b.object(obj, parent)
    for name, mesh, meta in architecture_meshes(house):  # doors, windows, skirting, lights
        b.add(mesh, name, meta, parent=parent)


def build_scene(house: House, texture_px: int | None = None) -> trimesh.Scene:
    """The house as a trimesh Scene (glTF frame via the root node), with textured PBR
    materials (PIL images on the materials).

    A house of several storeys has one node ``level:<k>`` per storey, raised to its
    elevation, holding that storey's nodes. Nodes: ``room:<id>:floor|walls|ceiling`` (one mesh each) and ``object:<id>`` (no
    mesh; the object's transform and metadata) with one child per material part,
    ``object:<id>:<role>`` (the part's material role: wood, fabric, metal, glass...; a ``-2`` suffix
    for repeats), in the object's local frame.
    """
    try:
        return scene_and_materials(house, texture_px, textures=True)[0]
    except Exception as e:  # trimesh and the asset builders raise many kinds
        raise ExportError(f"could not build the 3D scene: {one_line(e)}") from e


def one_line(e: Exception) -> str:
    """An exception as one clean line, never a bare "'x'" (the str of a KeyError)."""
    detail = clean_text(str(e)) if str(e) and not isinstance(e, LookupError) else ""
    return detail or f"{type(e).__name__} {clean_text(str(e))}".strip()
