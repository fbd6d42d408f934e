from __future__ import annotations

import json
import struct

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, MultiPoint, Polygon
from shapely.ops import unary_union

from anyhome.export import architecture as arch
from anyhome.export.architecture import OUTSIDE, architecture_meshes
from anyhome.export.walls import WALL_THICKNESS_M, solid_blocks, wall_pieces
from anyhome.geometry import blocks_navigation, footprint_polygon
from anyhome.house import Door, House, Room
from anyhome.pipeline import generate

TOL = 1e-6
PROMPTS = [(p, s) for p in ("a two-bedroom apartment", "a cat cafe") for s in range(3)]
CATEGORIES = {
    ("door", "frame"): "door_frame", ("door", "leaf"): "door_leaf",
    ("window", "frame"): "window_frame", ("window", "glass"): "window_glass",
    ("room", "skirting"): "skirting", ("room", "light"): "ceiling_light",
}


@pytest.fixture(scope="module", params=PROMPTS, ids=[f"{p}-{s}" for p, s in PROMPTS])
def generated(request) -> tuple[House, dict[str, tuple[trimesh.Trimesh, dict]]]:
    house = generate(request.param[0], seed=request.param[1])
    pieces = architecture_meshes(house)
    names = [name for name, _, _ in pieces]
    assert len(names) == len(set(names)), "node names must be unique"
    return house, {name: (mesh, meta) for name, mesh, meta in pieces}


# ---------------------------------------------------------------- helpers
def _hull2d(points: np.ndarray) -> Polygon:
    return MultiPoint([tuple(p) for p in points]).convex_hull


def _segment_coords(segment, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Points in the segment's frame: (along from the start, across), and its length."""
    a = np.asarray(segment[0], dtype=float)
    v = np.asarray(segment[1], dtype=float) - a
    length = float(np.linalg.norm(v))
    u = v / length
    rel = points[:, :2] - a
    return rel @ u, rel @ np.array([-u[1], u[0]]), length


def _opening_rect(segment, half_depth: float, inset: float = 0.0) -> Polygon:
    a, b = (np.asarray(p, dtype=float) for p in segment)
    u = (b - a) / np.linalg.norm(b - a)
    n = np.array([-u[1], u[0]]) * half_depth
    a, b = a + u * inset, b - u * inset
    return Polygon([a - n, b - n, b + n, a + n])


def _wall_solids(house: House, z0: float, z1: float) -> list[Polygon]:
    """Footprints of wall blocks overlapping the height range (z0, z1)."""
    out = []
    for piece in wall_pieces(house):
        u = piece.direction
        n = np.array([-u[1], u[0]]) * WALL_THICKNESS_M / 2
        for t0, t1, b0, b1 in solid_blocks(piece):
            if min(b1, z1) - max(b0, z0) > 1e-6:
                p0, p1 = piece.a + u * t0, piece.a + u * t1
                out.append(Polygon([p0 - n, p1 - n, p1 + n, p0 + n]))
    return out


# ---------------------------------------------------------------- generated houses
def test_one_piece_of_each_kind(generated) -> None:
    house, pieces = generated
    for door in house.doors:
        assert f"door:{door.id}:frame" in pieces
        assert (f"door:{door.id}:leaf" in pieces) == (door.kind == "door")
    for window in house.windows:
        assert f"window:{window.id}:frame" in pieces and f"window:{window.id}:glass" in pieces
    for room in house.rooms:
        assert f"room:{room.id}:skirting" in pieces and f"room:{room.id}:light" in pieces
    n_leaves = sum(d.kind == "door" for d in house.doors)
    assert len(pieces) == len(house.doors) + n_leaves + 2 * len(house.windows) + 2 * len(house.rooms)


def test_metadata(generated) -> None:
    house, pieces = generated
    for name, (_, meta) in pieces.items():
        kind, oid, part = name.split(":")
        open_air = kind == "room" and house.room(oid).open_air  # a wall lantern, not a ceiling light
        assert meta["category"] == ("wall_light" if open_air and part == "light" else CATEGORIES[(kind, part)])
        assert isinstance(meta["material"], str) and meta["material"]
        json.dumps(meta)  # glTF extras must serialise
        if kind == "door":
            assert meta["rooms"] == list(next(d for d in house.doors if d.id == oid).rooms)
        elif kind == "window":
            assert meta["rooms"] == [next(w for w in house.windows if w.id == oid).room]
        else:
            assert meta["room"] == oid


def test_meshes_small_finite_closed(generated) -> None:
    _, pieces = generated
    for name, (mesh, _) in pieces.items():
        assert len(mesh.faces) > 0 and np.isfinite(mesh.vertices).all(), name
        assert mesh.is_winding_consistent and mesh.volume > 0, name
        assert len(mesh.faces) < 1000, name
        assert isinstance(mesh.visual.material, trimesh.visual.material.PBRMaterial), name



def _leaves(generated):
    """(door, leaf mesh, leaf metadata, leaf footprint) for every door that has a leaf."""
    house, pieces = generated
    for door in house.doors:
        if door.kind == "door":
            mesh, meta = pieces[f"door:{door.id}:leaf"]
            yield door, mesh, meta, _hull2d(mesh.vertices[:, :2])

def test_leaves_inside_their_rooms_and_out_of_walls(generated) -> None:
    house, _ = generated
    for door, mesh, meta, leaf in _leaves(generated):
        rooms = [house.room(r) for r in door.rooms if r != OUTSIDE]
        union = unary_union([Polygon(r.polygon) for r in rooms]).buffer(WALL_THICKNESS_M)
        assert union.contains(leaf), door.id
        z = mesh.vertices[:, 2]
        assert z.min() >= -TOL and z.max() <= door.height + TOL
        # within the room it swings into (or the opening itself)
        assert meta["swing_room"] in door.rooms and meta["swing_room"] != OUTSIDE
        swing = Polygon(house.room(meta["swing_room"]).polygon)
        assert swing.union(_opening_rect(door.segment, WALL_THICKNESS_M / 2)).buffer(TOL).contains(leaf)
        # not through any wall
        for wall in _wall_solids(house, z.min(), z.max()):
            assert leaf.intersection(wall).area < 1e-6, door.id
        # open, and off the furniture
        assert meta["open_angle_deg"] > 0
        for obj in house.objects_in(meta["swing_room"]):
            if blocks_navigation(obj.category, obj.size[2], obj.support):
                fp = footprint_polygon(obj.position, obj.size, obj.yaw)
                assert leaf.intersection(fp).area < 1e-4, (door.id, obj.id)


def test_leaves_keep_the_way_clear(generated) -> None:
    """An open leaf may not cut its room's walkway in two."""
    house, _ = generated
    for door, mesh, meta, leaf in _leaves(generated):
        inner = Polygon(house.room(meta["swing_room"]).polygon).buffer(-WALL_THICKNESS_M / 2, join_style="mitre")
        walk = inner.buffer(-arch.LEAF_WALKWAY_M / 2, join_style="mitre")
        cut = walk.difference(leaf.buffer(arch.LEAF_WALKWAY_M / 2))
        assert arch._count_parts(cut) <= arch._count_parts(walk), door.id


def test_entrance_leaf_swings_inside(generated) -> None:
    house, pieces = generated
    entrances = [d for d in house.doors if OUTSIDE in d.rooms and d.kind == "door"]
    assert entrances
    for door in entrances:
        inside = next(r for r in door.rooms if r != OUTSIDE)
        assert pieces[f"door:{door.id}:leaf"][1]["swing_room"] == inside


def test_door_frames_hug_the_opening(generated) -> None:
    house, pieces = generated
    for door in house.doors:
        mesh, _ = pieces[f"door:{door.id}:frame"]
        t, n, length = _segment_coords(door.segment, mesh.vertices)
        reach = arch.CASING_WIDTH_M - arch.JAMB_WIDTH_M
        assert t.min() >= -reach - TOL and t.max() <= length + reach + TOL
        assert np.abs(n).max() <= WALL_THICKNESS_M / 2 + arch.CASING_THICKNESS_M + TOL
        z = mesh.vertices[:, 2]
        assert z.min() >= -TOL and z.max() <= door.height + arch.CASING_WIDTH_M + TOL


def test_window_glass_in_its_wall_segment(generated) -> None:
    house, pieces = generated
    for window in house.windows:
        glass, meta = pieces[f"window:{window.id}:glass"]
        t, n, length = _segment_coords(window.segment, glass.vertices)
        assert t.min() >= -TOL and t.max() <= length + TOL
        assert np.abs(n).max() <= WALL_THICKNESS_M / 2 + TOL
        z = glass.vertices[:, 2]
        assert z.min() >= window.sill - TOL and z.max() <= window.sill + window.height + TOL
        mat = glass.visual.material
        assert mat.alphaMode == "BLEND"
        assert 0.2 <= np.asarray(mat.baseColorFactor)[3] / 255 <= 0.4
        frame, _ = pieces[f"window:{window.id}:frame"]
        t, n, length = _segment_coords(window.segment, frame.vertices)
        assert t.min() >= -arch.SILL_OVERHANG_M - TOL and t.max() <= length + arch.SILL_OVERHANG_M + TOL
        assert np.abs(n).max() <= WALL_THICKNESS_M / 2 + arch.SILL_PROJECTION_M + TOL


def test_skirting_along_walls_cut_at_doors(generated) -> None:
    house, pieces = generated
    for room in house.rooms:
        mesh, _ = pieces[f"room:{room.id}:skirting"]
        z = mesh.vertices[:, 2]
        assert z.min() >= -TOL and z.max() <= arch.SKIRTING_HEIGHT_M + TOL
        inner = Polygon(room.polygon).buffer(-WALL_THICKNESS_M / 2, join_style="mitre")
        # every corner inside (an L room is not convex: its skirting's hull would cross the inner corner)
        assert inner.buffer(TOL).contains(MultiPoint([tuple(p) for p in mesh.vertices[:, :2]]))
        lines = trimesh.intersections.mesh_plane(mesh, [0, 0, 1], [0, 0, arch.SKIRTING_HEIGHT_M / 2])
        assert len(lines) > 0
        section = unary_union([LineString(seg[:, :2]) for seg in lines])
        for door in house.doors:
            if room.id in door.rooms:
                hole = _opening_rect(door.segment, WALL_THICKNESS_M, inset=0.01)
                assert not section.intersects(hole), (room.id, door.id)


def test_one_light_per_room_inside_below_ceiling(generated) -> None:
    house, pieces = generated
    for room in house.rooms:
        mesh, meta = pieces[f"room:{room.id}:light"]
        assert Polygon(room.polygon).contains(_hull2d(mesh.vertices[:, :2]))
        z = mesh.vertices[:, 2]
        lowest = arch.LANTERN_BOTTOM_M if room.open_air else arch.PENDANT_BOTTOM_M
        assert z.max() < room.height and z.min() >= lowest - TOL
        assert np.asarray(mesh.visual.material.emissiveFactor).max() > 0
        assert meta["style"] in (("wall lantern",) if room.open_air else ("pendant", "flush disc"))


def test_deterministic(generated) -> None:
    house, pieces = generated
    again = {name: mesh for name, mesh, _ in architecture_meshes(house)}
    for name, (mesh, _) in pieces.items():
        np.testing.assert_array_equal(mesh.vertices, again[name].vertices)


# ---------------------------------------------------------------- hand-made houses
def test_small_house_swings(small_house) -> None:
    pieces = {name: meta for name, _, meta in architecture_meshes(small_house)}
    assert pieces["door:d0:leaf"]["swing_room"] == "living"  # entrance: inward
    assert pieces["door:d1:leaf"]["swing_room"] == "bed"  # the smaller room
    assert pieces["door:d1:leaf"]["open_angle_deg"] == arch.OPEN_ANGLES_DEG[0]


def test_open_doors_get_no_leaf(small_house) -> None:
    doors = [d.model_copy(update={"kind": "open"}) if d.id == "d1" else d for d in small_house.doors]
    names = {name for name, _, _ in architecture_meshes(small_house.model_copy(update={"doors": doors}))}
    assert "door:d1:frame" in names and "door:d1:leaf" not in names
    assert "door:d0:leaf" in names


def test_corridor_entrance_folds_flat() -> None:
    """A door in the middle of a corridor's long side may not block the corridor."""
    rooms = [Room(id="hall", name="hallway", type="hallway", polygon=[(0, 0), (8, 0), (8, 1.3), (0, 1.3)])]
    doors = [Door(id="e", rooms=("hall", OUTSIDE), segment=((3.5, 0), (4.5, 0)))]
    house = House(prompt="corridor", seed=0, rooms=rooms, doors=doors)
    meta = next(m for name, _, m in architecture_meshes(house) if name == "door:e:leaf")
    assert meta["open_angle_deg"] == arch.FLAT_OPEN_DEG


def test_light_in_largest_rectangle_of_an_l_room() -> None:
    room = Room(id="l", name="l room", type="bedroom",
                polygon=[(0, 0), (6, 0), (6, 2), (2, 2), (2, 5), (0, 5)])
    assert arch.light_position(room) == pytest.approx((3.0, 1.0))
    square = Room(id="s", name="square", type="bedroom", polygon=[(0, 0), (4, 0), (4, 3), (0, 3)])
    assert arch.light_position(square) == pytest.approx((2.0, 1.5))


def test_glb_round_trip(small_house) -> None:
    scene = trimesh.Scene()
    for name, mesh, meta in architecture_meshes(small_house):
        scene.add_geometry(mesh, node_name=name, geom_name=name, metadata=dict(meta))
    data = scene.export(file_type="glb")
    chunk_len = struct.unpack_from("<I", data, 12)[0]
    tree = json.loads(data[20 : 20 + chunk_len])
    names = {n.get("name") for n in tree["nodes"]}
    assert {"door:d0:frame", "door:d0:leaf", "window:w1:glass", "room:bed:light"} <= names
    assert any(m.get("alphaMode") == "BLEND" for m in tree["materials"])
    assert any(max(m.get("emissiveFactor", [0])) > 0 for m in tree["materials"])


@settings(max_examples=40, deadline=None)
@given(
    w1=st.floats(1.5, 6.0), w2=st.floats(1.2, 6.0), depth=st.floats(1.2, 5.0),
    where=st.floats(0.0, 1.0), entrance=st.booleans(),
)
def test_leaf_invariants_on_two_rooms(w1, w2, depth, where, entrance) -> None:
    """Two rooms side by side, a door anywhere along the shared wall (or the front wall)."""
    w1, w2, depth = round(w1, 2), round(w2, 2), round(depth, 2)
    rooms = [Room(id="a", name="a", type="bedroom", polygon=[(0, 0), (w1, 0), (w1, depth), (0, depth)]),
             Room(id="b", name="b", type="office", polygon=[(w1, 0), (w1 + w2, 0), (w1 + w2, depth), (w1, depth)])]
    if entrance:
        x0 = round(0.1 + where * (w1 - 1.1), 2)
        door = Door(id="d", rooms=("a", OUTSIDE), segment=((x0, 0), (x0 + 0.9, 0)))
    else:
        y0 = round(0.1 + where * (depth - 1.1), 2)
        door = Door(id="d", rooms=("a", "b"), segment=((w1, y0), (w1, y0 + 0.9)))
    house = House(prompt="two rooms", seed=0, rooms=rooms, doors=[door])
    mesh, meta = next((m, mt) for name, m, mt in architecture_meshes(house) if name == "door:d:leaf")
    leaf = _hull2d(mesh.vertices[:, :2])
    swing = Polygon(house.room(meta["swing_room"]).polygon)
    assert swing.union(_opening_rect(door.segment, WALL_THICKNESS_M / 2)).buffer(TOL).contains(leaf)
    for wall in _wall_solids(house, 0.0, door.height):
        assert leaf.intersection(wall).area < 1e-6
    if entrance:
        assert meta["swing_room"] == "a"
