from __future__ import annotations

import json
import struct

import numpy as np
import pytest
import trimesh

from anyhome.export import write_glb
from anyhome.export.walls import WALL_THICKNESS_M, wall_pieces
from anyhome.scene import PLAN_TO_GLTF, room_wall_meshes, wall_meshes


def _json_chunk(data: bytes) -> dict:
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    chunk_len, chunk_type = struct.unpack_from("<I4s", data, 12)
    assert chunk_type == b"JSON"
    return json.loads(data[20 : 20 + chunk_len])


@pytest.fixture
def glb(small_house, tmp_path):
    return write_glb(small_house, tmp_path / "house.glb")


def test_nodes_and_json(glb, small_house) -> None:
    tree = _json_chunk(glb.read_bytes())
    names = {n.get("name") for n in tree["nodes"]}
    for room in small_house.rooms:
        for part in ("floor", "walls", "ceiling"):
            assert f"room:{room.id}:{part}" in names
    for obj in small_house.objects:
        assert f"object:{obj.id}" in names
    node = next(n for n in tree["nodes"] if n.get("name") == "object:sofa1")
    assert node["extras"]["category"] == "sofa" and node["extras"]["room"] == "living"
    assert not list(glb.parent.glob(".*.tmp"))  # atomic write leaves no temp file


def object_mesh(scene: trimesh.Scene, oid: str) -> trimesh.Trimesh:
    """An object's parts (the child nodes of its ``object:<id>`` node) in world frame."""
    node = f"object:{oid}"
    parts = [n for n in scene.graph.nodes_geometry if scene.graph.transforms.parents.get(n) == node]
    assert parts, f"{node} has no part nodes"
    return trimesh.util.concatenate(
        [scene.geometry[scene.graph[n][1]].copy().apply_transform(scene.graph[n][0]) for n in parts])


def test_object_bounds_after_axis_conversion(glb, small_house) -> None:
    scene = trimesh.load(glb)
    assert isinstance(scene, trimesh.Scene)
    for oid in ("bed1", "vase1", "ct"):
        obj = small_house.object(oid)
        mesh = object_mesh(scene, oid)
        lo, hi = mesh.bounds
        x, y, z = obj.position
        w, d, h = obj.size  # yaw 0: axis-aligned
        # plan (x, y, z) -> glTF (x, z, -y)
        np.testing.assert_allclose(lo, [x - w / 2, z, -(y + d / 2)], atol=2e-3)
        np.testing.assert_allclose(hi, [x + w / 2, z + h, -(y - d / 2)], atol=2e-3)


def test_axis_convention() -> None:
    p = PLAN_TO_GLTF @ np.array([0.0, 5.0, 0.0, 1.0])
    assert np.allclose(p[:3], [0, 0, -5])  # plan y = +5 -> glTF z = -5
    up = PLAN_TO_GLTF @ np.array([0.0, 0.0, 1.0, 0.0])
    assert np.allclose(up[:3], [0, 1, 0])  # plan z up -> glTF +y


def _inside_any_box(mesh: trimesh.Trimesh, point) -> bool:
    """Walls are boxes of 8 vertices each (axis-aligned in this house)."""
    v = mesh.vertices.reshape(-1, 8, 3)
    p = np.asarray(point)
    lo, hi = v.min(axis=1), v.max(axis=1)
    return bool(np.any(np.all((lo < p - 1e-6) & (p + 1e-6 < hi), axis=1)))


def test_door_and_window_openings(small_house) -> None:
    walls = wall_meshes(small_house)
    allw = trimesh.util.concatenate(list(walls.values()))
    assert not _inside_any_box(allw, (5.0, 1.95, 1.0))  # inside the interior door opening
    assert not _inside_any_box(allw, (1.5, 0.0, 1.0))  # the entrance
    assert _inside_any_box(allw, (5.0, 1.95, 2.4))  # the lintel above the door
    assert _inside_any_box(allw, (5.0, 3.0, 1.0))  # next to the door
    assert not _inside_any_box(allw, (9.0, 2.0, 1.5))  # the window
    assert _inside_any_box(allw, (9.0, 2.0, 0.5))  # below the sill
    assert _inside_any_box(allw, (9.0, 2.0, 2.4))  # above the window


def test_shared_wall_drawn_once(small_house) -> None:
    shared = [p for p in wall_pieces(small_house) if abs(p.a[0] - 5) < 1e-9 and abs(p.b[0] - 5) < 1e-9]
    assert len(shared) == 1 and shared[0].rooms == {"living", "bed"}
    assert WALL_THICKNESS_M == pytest.approx(0.1)


def test_each_side_of_a_shared_wall_faces_its_room(small_house) -> None:
    by_room = room_wall_meshes(small_house)
    owned = wall_meshes(small_house)
    assert sum(len(m.faces) for m in by_room.values()) == sum(len(m.faces) for m in owned.values())

    def faces_at_x(mesh: trimesh.Trimesh, x: float) -> np.ndarray:
        """Normals' x of the upright faces in the plane x = const, away from the corners."""
        tri = mesh.vertices[mesh.faces]
        on = np.all(np.abs(tri[:, :, 0] - x) < 1e-9, axis=1) & (np.abs(mesh.face_normals[:, 2]) < 0.5)
        on &= np.all((tri[:, :, 1] > 0.2) & (tri[:, :, 1] < 3.8), axis=1)
        return mesh.face_normals[on, 0]

    half = WALL_THICKNESS_M / 2  # the shared wall at x = 5 is owned by "living"
    assert len(faces_at_x(by_room["bed"], 5 + half)) and np.all(faces_at_x(by_room["bed"], 5 + half) > 0.9)
    assert len(faces_at_x(by_room["living"], 5 - half)) and not len(faces_at_x(by_room["living"], 5 + half))


def test_t_junction_split() -> None:
    from anyhome.house import House, Room

    house = House(prompt="t", seed=0, rooms=[
        Room(id="a", name="a", type="other", polygon=[(0, 0), (4, 0), (4, 4), (0, 4)]),
        Room(id="b", name="b", type="other", polygon=[(4, 0), (7, 0), (7, 2), (4, 2)]),
        Room(id="c", name="c", type="other", polygon=[(4, 2), (7, 2), (7, 4), (4, 4)]),
    ])
    on_x4 = [p for p in wall_pieces(house) if abs(p.a[0] - 4) < 1e-9 and abs(p.b[0] - 4) < 1e-9]
    assert len(on_x4) == 2  # split at (4, 2), each shared once


# ------------------------------------------------------------------ materials
HAUNTED = "A one-bedroom, one-bathroom haunted house featuring dark wood and antique furnishings."


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    from anyhome.pipeline import generate

    house = generate(HAUNTED, seed=0)
    return house, write_glb(house, tmp_path_factory.mktemp("glb") / "house.glb")


def _textured(material: dict) -> bool:
    pbr = material.get("pbrMetallicRoughness", {})
    return "baseColorTexture" in pbr and "metallicRoughnessTexture" in pbr and "normalTexture" in material


def test_room_surfaces_are_textured(generated) -> None:
    house, path = generated
    tree = _json_chunk(path.read_bytes())
    mats = tree["materials"]
    by_name = {n["name"]: n for n in tree["nodes"]}
    for room in house.rooms:
        for part in ("floor", "walls"):
            mesh = tree["meshes"][by_name[f"room:{room.id}:{part}"]["mesh"]]
            prim = mesh["primitives"][0]
            assert "TEXCOORD_0" in prim["attributes"]
            assert _textured(mats[prim["material"]]), f"{room.id} {part} has no textures"
    samplers = tree["samplers"]
    assert all(s["wrapS"] == s["wrapT"] == 10497 for s in samplers)  # REPEAT: textures tile


def test_textures_are_shared(generated) -> None:
    _, path = generated
    tree = _json_chunk(path.read_bytes())
    textured = [m for m in tree["materials"] if _textured(m)]
    used = {m["pbrMetallicRoughness"][k]["index"] for m in textured
            for k in ("baseColorTexture", "metallicRoughnessTexture")}
    used |= {m["normalTexture"]["index"] for m in textured}
    sources = {tree["textures"][t]["source"] for t in used}
    views = {tree["images"][i]["bufferView"] for i in sources}
    assert len(sources) == len(views) == len(tree["images"])  # each image stored once
    assert len(sources) < 3 * len(textured)  # normal / roughness maps shared between colours


def test_loads_back_with_textures(generated) -> None:
    house, path = generated
    scene = trimesh.load(path)
    tf, geom = scene.graph[f"room:{house.rooms[0].id}:floor"]
    floor = scene.geometry[geom]
    mat = floor.visual.material
    assert mat.baseColorTexture is not None and mat.normalTexture is not None
    assert floor.visual.uv is not None and len(floor.visual.uv) == len(floor.vertices)
    # ceilings are their own nodes, so a viewer can hide them
    for room in house.rooms:
        assert scene.graph[f"room:{room.id}:ceiling"][1] is not None
    tree = _json_chunk(path.read_bytes())
    ceilings = [n for n in tree["nodes"] if n.get("name", "").endswith(":ceiling")]
    assert len(ceilings) == len(house.rooms)
    assert all(n["extras"]["category"] == "ceiling" for n in ceilings)


def test_objects_have_textured_body_parts(generated) -> None:
    house, path = generated
    tree = _json_chunk(path.read_bytes())
    nodes = tree["nodes"]
    by_name = {n["name"]: n for n in nodes}
    textured_objects = 0
    for obj in house.objects:
        node = by_name[f"object:{obj.id}"]
        assert node["extras"]["id"] == obj.id and "mesh" not in node
        children = [nodes[i] for i in node.get("children", [])]
        assert children and all(c["name"].startswith(f"object:{obj.id}:") for c in children)
        for c in children:
            mat = tree["materials"][tree["meshes"][c["mesh"]]["primitives"][0]["material"]]
            if c["extras"]["body"] and _textured(mat):
                textured_objects += 1
                break
    assert textured_objects >= len(house.objects) // 2


def test_glass_is_blended(small_house, tmp_path) -> None:
    from anyhome.house import HouseObject

    house = small_house.model_copy(deep=True)
    house.objects.append(HouseObject(id="tbl", room="living", name="glass coffee table",
                                     category="coffee_table", position=(1.0, 1.0, 0),
                                     size=(0.9, 0.5, 0.4), material="glass and chrome"))
    tree = _json_chunk(write_glb(house, tmp_path / "g.glb").read_bytes())
    blended = [m for m in tree["materials"] if m.get("alphaMode") == "BLEND"]
    assert blended and all(m["pbrMetallicRoughness"]["baseColorFactor"][3] < 1 for m in blended)


def test_glb_size_of_a_house(generated, tmp_path) -> None:
    house, path = generated
    assert len(house.rooms) >= 5
    assert path.stat().st_size < 30 * 2**20
    small = write_glb(house, tmp_path / "small.glb", texture_px=64)
    assert small.stat().st_size < path.stat().st_size


def test_the_glb_holds_the_architecture_pieces(tmp_path):
    from anyhome.pipeline import generate

    house = generate("a two-bedroom apartment", seed=0)
    scene = trimesh.load(write_glb(house, tmp_path / "h.glb"), force="scene")
    nodes = set(scene.graph.nodes)
    assert all(f"door:{d.id}:frame" in nodes for d in house.doors)
    assert all(f"window:{w.id}:glass" in nodes for w in house.windows)
    assert all(f"room:{r.id}:light" in nodes and f"room:{r.id}:skirting" in nodes for r in house.rooms)
