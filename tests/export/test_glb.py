from __future__ import annotations

import json
import struct

import numpy as np
import pytest
import trimesh

from anyhome.export import write_glb
from anyhome.export.glb import PLAN_TO_GLTF, wall_meshes
from anyhome.export.walls import WALL_THICKNESS_M, wall_pieces


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


def test_object_bounds_after_axis_conversion(glb, small_house) -> None:
    scene = trimesh.load(glb)
    assert isinstance(scene, trimesh.Scene)
    for oid in ("bed1", "vase1", "ct"):
        obj = small_house.object(oid)
        tf, geom = scene.graph[f"object:{oid}"]
        mesh = scene.geometry[geom].copy().apply_transform(tf)
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


def test_t_junction_split() -> None:
    from anyhome.house import House, Room

    house = House(prompt="t", seed=0, rooms=[
        Room(id="a", name="a", type="other", polygon=[(0, 0), (4, 0), (4, 4), (0, 4)]),
        Room(id="b", name="b", type="other", polygon=[(4, 0), (7, 0), (7, 2), (4, 2)]),
        Room(id="c", name="c", type="other", polygon=[(4, 2), (7, 2), (7, 4), (4, 4)]),
    ])
    on_x4 = [p for p in wall_pieces(house) if abs(p.a[0] - 4) < 1e-9 and abs(p.b[0] - 4) < 1e-9]
    assert len(on_x4) == 2  # split at (4, 2), each shared once
