"""Open-air rooms (no ceiling, parapets, no ceiling-hung objects, hatched in the SVG) and
ceiling heights and shapes (tall, low, pitched and vaulted rooms) in house.json, the GLB
and the floorplan SVG, on generated houses."""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Point, Polygon

from anyhome.evaluate.evaluator import evaluate_house
from anyhome.export import write_glb
from anyhome.export.ceilings import ceiling_height_at, ceiling_mesh
from anyhome.export.svg import render_svg
from anyhome.export.walls import RAILING_HEIGHT_M, wall_pieces
from anyhome.house import CEILING_RISE, House, Room
from anyhome.layout.solver import CEILING_HUNG
from anyhome.pipeline import generate
from anyhome.scene import PLAN_TO_GLTF

OPEN_AIR_TYPES = {"balcony", "terrace", "deck", "patio", "porch", "courtyard", "garden", "roof_terrace"}


@pytest.fixture(scope="module")
def terrace_house() -> House:
    return generate("a two-bedroom flat with a terrace and a balcony with a ceiling fan and a chandelier", seed=0)


@pytest.fixture(scope="module")
def terrace_glb(terrace_house, tmp_path_factory):
    path = write_glb(terrace_house, tmp_path_factory.mktemp("glb") / "house.glb", texture_px=16)
    return trimesh.load(path)


def _node_vertices(scene: trimesh.Scene, node: str) -> np.ndarray:
    """A node's vertices in the plan frame (undoing the root's glTF axis swap)."""
    matrix, geom = scene.graph[node]
    v = trimesh.transform_points(scene.geometry[geom].vertices, np.linalg.inv(PLAN_TO_GLTF) @ matrix)
    return np.asarray(v)


def test_open_air_rooms_in_house_json(terrace_house) -> None:
    by_type = {r.type: r for r in terrace_house.rooms}
    assert {"terrace", "balcony"} <= set(by_type)
    for r in terrace_house.rooms:
        assert r.open_air == (r.type in OPEN_AIR_TYPES), r.id
        if r.open_air:  # outdoor floor, no ceiling material ("open sky" was a blue ceiling)
            assert r.materials.get("ceiling", "") == "" and "sky" not in json.dumps(r.materials)
            assert r.materials["floor"] in ("stone flags", "teak decking")
            assert r.ceiling == "flat"
    assert evaluate_house(terrace_house).ok


def test_open_air_rooms_have_no_ceiling_node(terrace_house, terrace_glb) -> None:
    names = set(terrace_glb.graph.nodes)
    for r in terrace_house.rooms:
        assert (f"room:{r.id}:ceiling" in names) == (not r.open_air), r.id
        assert f"room:{r.id}:floor" in names
        geom = terrace_glb.graph[f"room:{r.id}:floor"][1]
        assert terrace_glb.geometry[geom].metadata.get("open_air", False) == r.open_air


def test_no_ceiling_hung_object_in_open_air_rooms(terrace_house) -> None:
    open_ids = {r.id for r in terrace_house.rooms if r.open_air}
    hung = [o for o in terrace_house.objects if o.room in open_ids and o.category in CEILING_HUNG]
    assert not hung
    # the text asked for them on the balcony: dropped, with the reason said
    reasons = [d.reason for d in terrace_house.dropped if d.room in open_ids]
    assert any("no ceiling" in reason for reason in reasons)


def _cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _edges(room: Room) -> list[tuple[np.ndarray, np.ndarray]]:
    pts = [np.asarray(p, dtype=float) for p in room.polygon]
    return [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]


def test_parapet_on_exterior_sides_full_wall_on_shared_ones(terrace_house, terrace_glb) -> None:
    enclosed = [Polygon(r.polygon) for r in terrace_house.rooms if not r.open_air]
    for room in (r for r in terrace_house.rooms if r.open_air):
        pieces = [p for p in wall_pieces(terrace_house) if room.id in p.rooms]
        shared = [p for p in pieces if not p.railing]
        exterior = [p for p in pieces if p.railing]
        assert exterior, f"{room.id} has no open side"
        assert all(p.height <= RAILING_HEIGHT_M <= 1.1 for p in exterior)
        assert shared and all(p.height >= 2.3 for p in shared)  # the house wall it is entered from
        door = next(d for d in terrace_house.doors if room.id in d.rooms)
        mid = np.mean(np.asarray(door.segment, dtype=float), axis=0)
        assert any(abs(_cross(p.b - p.a, mid - p.a)) / p.length < 0.02 for p in shared)
        # the GLB: wall vertices on the sides no enclosed room touches are at most railing high
        walls = _node_vertices(terrace_glb, f"room:{room.id}:walls")
        faces = walls[np.asarray(terrace_glb.geometry[terrace_glb.graph[f"room:{room.id}:walls"][1]].faces)]
        centres = faces.mean(axis=1)
        checked = 0
        for a, b in _edges(room):
            mid_edge = (a + b) / 2
            if any(poly.buffer(0.05).contains(Point(*mid_edge)) for poly in enclosed):
                continue  # a side shared with an enclosed room
            length = float(np.linalg.norm(b - a))
            u = (b - a) / length
            rel = centres[:, :2] - a
            on = (np.abs(rel @ np.array([-u[1], u[0]])) < 0.06) & (rel @ u > 0.1) & (rel @ u < length - 0.1)
            if on.any():
                checked += 1
                assert faces[on][:, :, 2].max() <= RAILING_HEIGHT_M + 1e-6
        assert checked, f"{room.id}: no exterior side found in the GLB"


def test_svg_marks_open_air_rooms(terrace_house) -> None:
    svg = render_svg(terrace_house)
    for r in terrace_house.rooms:
        assert (f'id="open-{r.id}"' in svg) == r.open_air
    assert 'class="railing"' in svg and "open · " in svg and 'id="open-air-hatch"' in svg


# ------------------------------------------------------------------ heights
@pytest.mark.parametrize("text, room_type", [("a church", "hall"), ("a house with a ballroom", "hall")])
def test_tall_rooms(text, room_type) -> None:
    house = generate(text, seed=0)
    tall = [r for r in house.rooms if r.type == room_type]
    assert tall and all(r.height >= 5.0 for r in tall)
    assert evaluate_house(house).ok  # doors and windows still below the ceilings


def test_low_ceilinged_cottage() -> None:
    house = generate("a low-ceilinged cottage", seed=0)
    assert all(r.height < 2.6 for r in house.rooms if not r.open_air)
    assert all(d.height < min(house.room(x).height for x in d.rooms if x != "outside") for d in house.doors)
    assert evaluate_house(house).ok


def test_double_height_living_room_is_one_room() -> None:
    house = generate("a flat with a double-height living room", seed=0)
    living = [r for r in house.rooms if r.type == "living_room"]
    assert len(living) == 1 and living[0].name == "living room"
    assert living[0].height >= 5.0
    assert max(r.height for r in house.rooms if r.type == "bedroom") < 3.0


def test_vaulted_cabin_has_sloped_ceiling_in_glb(tmp_path) -> None:
    house = generate("a cabin with a vaulted ceiling", seed=0)
    vaulted = [r for r in house.rooms if r.ceiling == "vaulted"]
    assert vaulted and any(r.type == "living_room" for r in vaulted)
    scene = trimesh.load(write_glb(house, tmp_path / "house.glb", texture_px=16))
    for r in vaulted:
        z = _node_vertices(scene, f"room:{r.id}:ceiling")[:, 2]
        xs, ys = zip(*r.polygon, strict=True)
        short = min(max(xs) - min(xs), max(ys) - min(ys))
        assert z.min() == pytest.approx(r.height, abs=1e-3)
        assert z.max() == pytest.approx(r.height + CEILING_RISE["vaulted"] * short, abs=1e-3)
    assert evaluate_house(house).ok


def test_version1_file_without_new_fields_loads(terrace_house) -> None:
    data = json.loads(terrace_house.to_json())
    for r in data["rooms"]:
        del r["open_air"], r["ceiling"]
    old = House.from_json(json.dumps(data))
    assert all(not r.open_air and r.ceiling == "flat" for r in old.rooms)


# ------------------------------------------------------------------ sloped geometry
@st.composite
def rooms(draw) -> Room:
    w = draw(st.floats(1.5, 9.0))
    d = draw(st.floats(1.5, 9.0))
    notch = draw(st.floats(0.0, 0.6))
    pts = [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]
    if notch > 0.05:  # an L: a corner cut away
        cx, cy = w * (1 - notch), d * (1 - notch)
        pts = [(0.0, 0.0), (w, 0.0), (w, cy), (cx, cy), (cx, d), (0.0, d)]
    return Room(id="r", name="r", type="living_room", polygon=pts, height=draw(st.floats(2.3, 6.0)),
                ceiling=draw(st.sampled_from(["pitched", "vaulted"])))


@settings(max_examples=40, deadline=None)
@given(rooms())
def test_sloped_ceiling_covers_the_room_and_meets_the_walls(room) -> None:
    mesh = ceiling_mesh(room, 0.05)
    assert mesh is not None
    v = np.asarray(mesh.vertices)
    xs, ys = zip(*room.polygon, strict=True)
    short = min(max(xs) - min(xs), max(ys) - min(ys))
    assert v[:, 2].min() == pytest.approx(room.height, abs=1e-6)
    assert v[:, 2].max() <= room.height + CEILING_RISE[room.ceiling] * short + 1e-6
    # every vertex lies on the ceiling surface or on a gable below it, inside the outline
    poly = Polygon(room.polygon)
    for x, y, z in v:
        assert poly.distance(Point(x, y)) < 1e-6
        assert z <= ceiling_height_at(room, x, y) + 1e-6
    # the sloped surface covers the floor: its upward projection has the room's area
    top = [f for f in np.asarray(mesh.faces) if abs(np.cross(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]])[2]) > 1e-12]
    area = sum(abs(np.cross(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]])[2]) / 2 for f in top) / 2  # both sides
    assert area == pytest.approx(Polygon(room.polygon).area, rel=1e-6)


def test_open_air_room_has_no_ceiling_mesh() -> None:
    room = Room(id="t", name="terrace", type="terrace", polygon=[(0, 0), (4, 0), (4, 3), (0, 3)], open_air=True)
    assert ceiling_mesh(room, 0.05) is None
