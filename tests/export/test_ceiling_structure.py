"""Beamed and coffered ceilings are geometry under a plaster ceiling (issue 15), in the
export and in the GLB scene."""

from __future__ import annotations

import numpy as np
import trimesh
from shapely.geometry import Polygon

from anyhome.export.ceilings import BEAM_DEPTH_M, structure_mesh
from anyhome.house import Room
from anyhome.scene import build_scene


def _room(w: float, d: float, ceiling: str = "flat", materials: dict | None = None) -> Room:
    return Room(id="r", name="room", type="living_room", polygon=[(0, 0), (w, 0), (w, d), (0, d)], height=2.7,
                ceiling=ceiling, materials=materials or {"floor": "oak", "walls": "white paint", "ceiling": "exposed beams"})


def test_beams_span_the_short_side_under_the_ceiling() -> None:
    room = _room(6.0, 3.5)
    mesh = structure_mesh(room, "beams")
    assert mesh is not None
    lo, hi = mesh.bounds
    assert np.isclose(hi[2], room.height) and np.isclose(lo[2], room.height - BEAM_DEPTH_M)
    assert Polygon(room.polygon).buffer(1e-6).contains(Polygon([(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])]))
    parts = mesh.split(only_watertight=False)
    assert 4 <= len(parts) <= 6  # about one every 1.1 m along the 6 m side
    for p in parts:  # each spans the 3.5 m side
        ext = p.bounds[1] - p.bounds[0]
        assert np.isclose(ext[1], 3.5) and ext[0] < 0.2


def test_coffers_cross_both_ways_and_sloped_or_narrow_rooms_get_none() -> None:
    beams = structure_mesh(_room(5.0, 4.0), "beams")
    coffers = structure_mesh(_room(5.0, 4.0), "coffers")
    assert beams is not None and coffers is not None and coffers.area > beams.area
    assert structure_mesh(_room(5.0, 4.0, ceiling="pitched"), "beams") is None
    assert structure_mesh(_room(5.0, 1.0), "beams") is None  # a corridor keeps a plain ceiling
    assert structure_mesh(_room(5.0, 4.0), "dome") is None


def test_the_scene_hangs_wooden_beams_under_a_plaster_ceiling(tmp_path) -> None:
    from anyhome.pipeline import generate

    house = generate("a cottage living room with exposed oak beams and cream plaster walls", seed=0)
    scene = build_scene(house, texture_px=16)
    beams = [n for n in scene.graph.nodes_geometry if n.endswith(":beams")]
    assert beams
    for node in beams:
        room = node.split(":")[1]
        beam = scene.geometry[scene.graph[node][1]]
        ceiling = scene.geometry[scene.graph[f"room:{room}:ceiling"][1]]
        assert beam.visual.material.name.startswith("wood")
        assert ceiling.visual.material.name.startswith("plaster")
        assert isinstance(beam, trimesh.Trimesh) and beam.volume > 0.05


def test_beams_are_hidden_with_the_ceiling_from_the_birds_eye_view() -> None:
    """The bird's-eye view hides the ceiling layer: beams and coffers hang in it (before,
    a beamed manor's bird's-eye was a lattice of beams over its rooms)."""
    from anyhome.house import House
    from anyhome.render.meshes import scene_meshes

    house = House(prompt="a beamed room", seed=0, rooms=[_room(5.0, 4.0)])
    meshes = scene_meshes(house, build_scene(house, texture_px=16))
    ceiling = np.concatenate([b.vertices["pos"] for b in meshes.batches if b.layer == "ceiling"])
    main = np.concatenate([b.vertices["pos"] for b in meshes.batches if b.layer == "main"])
    under = 2.7 - BEAM_DEPTH_M + 1e-3
    assert (ceiling[:, 2] <= under).any()  # the beams' undersides are in the ceiling layer
    beam_x = ceiling[ceiling[:, 2] <= under][:, 0]
    assert ((beam_x > 0.3) & (beam_x < 4.7)).any()  # the beams across the room
    high = (main[:, 0] > 0.3) & (main[:, 0] < 4.7) & (main[:, 2] > 2.0)
    assert not high.any()  # nothing of them is left in the main layer (walls stand at x 0 and 5)
