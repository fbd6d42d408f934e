from __future__ import annotations

import numpy as np
import pytest
import trimesh

from anyhome.house import House, Room
from anyhome.render.meshes import corner_appearance, node_kind, scene_meshes, srgb_to_linear


def test_node_kind() -> None:
    assert node_kind("room:living:walls", {}) == ("walls", "living")
    assert node_kind("room:a:b:ceiling", {}) == ("ceiling", "a:b")
    assert node_kind("window:w1:glass", {}) == ("glass", None)
    assert node_kind("object:sofa1", {"room": "living"}) == ("object", "living")


def test_scene_meshes_of_exported_house(small_house) -> None:
    from anyhome.scene import build_scene

    meshes = scene_meshes(small_house, build_scene(small_house))
    n = len(small_house.objects)
    assert meshes.instances[:n] == [f"object:{o.id}" for o in small_house.objects]
    assert len(set(meshes.instances)) == len(meshes.instances)
    layers = {b.layer for b in meshes.batches}
    assert {"main", "ceiling"} <= layers
    verts = np.concatenate([b.vertices for b in meshes.batches])
    assert np.isfinite(verts["pos"]).all()
    assert np.allclose(np.linalg.norm(verts["nrm"], axis=1), 1.0, atol=1e-3)
    # plan frame: floors at z <= 0, nothing above the tallest ceiling slab
    assert meshes.bounds[0, 2] < 0.0 < meshes.bounds[1, 2] <= 2.7 + 0.06
    # every object's vertices carry its room
    used = set(verts["inst"][verts["inst"] >= 0].tolist())
    assert set(range(n)) <= used
    obj_rooms = {i: small_house.objects[i].room for i in range(n)}
    for i, room in obj_rooms.items():
        rooms = set(verts["room"][verts["inst"] == i].tolist())
        assert rooms == {[r.id for r in small_house.rooms].index(room)}


def test_appearance_of_vertex_colours_and_textures() -> None:
    box = trimesh.creation.box()
    box.visual.vertex_colors = [255, 0, 0, 255]
    look = corner_appearance(box)
    assert look.color.shape == (len(box.faces) * 3, 4)
    assert np.allclose(look.color[0], [1.0, 0.0, 0.0, 1.0])
    import PIL.Image as PIL  # noqa: N814
    img = PIL.new("RGB", (4, 4), (0, 128, 0))
    mat = trimesh.visual.material.PBRMaterial(baseColorTexture=img, baseColorFactor=[255, 255, 255, 128],
                                              roughnessFactor=0.3, alphaMode="BLEND")
    box.visual = trimesh.visual.TextureVisuals(uv=box.vertices[:, :2] + 0.5, material=mat)
    look = corner_appearance(box)
    assert look.texture is img and look.uv.shape == (len(box.faces) * 3, 2)
    assert look.roughness == pytest.approx(0.3) and look.blend
    assert look.color[0, 3] == pytest.approx(128 / 255)


def test_srgb_to_linear_endpoints() -> None:
    assert np.allclose(srgb_to_linear([0.0, 1.0]), [0.0, 1.0])
    assert srgb_to_linear(0.5) == pytest.approx(0.214, abs=1e-3)


def test_textured_floor_is_drawn_with_its_texture(gl_available) -> None:
    """A floor with a red texture (white factor) renders red from above."""
    import PIL.Image as PIL  # noqa: N814

    from anyhome.render import Renderer, birdseye_camera
    from anyhome.render.lights import room_lights

    house = House(prompt="t", seed=0, rooms=[Room(id="r", name="room", type="other",
                                                  polygon=[(0, 0), (4, 0), (4, 4), (0, 4)])])
    floor = trimesh.creation.box(extents=(4, 4, 0.05))
    floor.apply_translation((2, 2, -0.025))
    mat = trimesh.visual.material.PBRMaterial(baseColorTexture=PIL.new("RGB", (8, 8), (220, 20, 20)),
                                              baseColorFactor=[255, 255, 255, 255])
    floor.visual = trimesh.visual.TextureVisuals(uv=floor.vertices[:, :2] / 4, material=mat)
    scene = trimesh.Scene()
    scene.add_geometry(floor, node_name="room:r:floor", geom_name="room:r:floor")
    meshes = scene_meshes(house, scene)
    cam = birdseye_camera(house, 64, elevation_deg=90.0)
    with Renderer(meshes, room_lights(house), supersample=1) as renderer:
        frame = renderer.render(cam, ceilings=False, ids=True)
    centre = frame.color[24:40, 24:40].reshape(-1, 3).mean(axis=0)
    assert centre[0] > 2 * centre[1] and centre[0] > 2 * centre[2]
    assert (frame.ids[24:40, 24:40] == meshes.instances.index("room:r:floor")).all()
