"""The colour pass uses glTF's metallicRoughness and normal maps (render.meshes carries
them and per-vertex tangents, render.renderer binds them, render.shaders applies them)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

from anyhome.house import House, Room
from anyhome.render import meshes as render_meshes
from anyhome.render.meshes import corner_appearance, scene_meshes

DATA = Path(__file__).parent / "data"
GOLDEN = DATA / "no_maps_before.png"
"""The no-maps scene of :func:`_mixed_scene` rendered by the renderer before it read the
maps (``python tests/render/test_pbr_maps.py`` rewrites it: do that only on purpose)."""
SIDE_M = 4.0


def _pil():
    import PIL.Image

    return PIL.Image


def _house() -> House:
    return House(prompt="t", seed=0, rooms=[Room(id="r", name="room", type="other",
                                                 polygon=[(0, 0), (SIDE_M, 0), (SIDE_M, SIDE_M),
                                                          (0, SIDE_M)])])


def _floor(material, uv_scale: float = 1.0 / SIDE_M) -> trimesh.Trimesh:
    """A 4 m square slab at z = 0 (top face), UVs from plan x, y."""
    floor = trimesh.creation.box(extents=(SIDE_M, SIDE_M, 0.05))
    floor.apply_translation((SIDE_M / 2, SIDE_M / 2, -0.025))
    floor.visual = trimesh.visual.TextureVisuals(uv=floor.vertices[:, :2] * uv_scale, material=material)
    return floor


def _material(**kwargs):
    kwargs.setdefault("baseColorFactor", [200, 200, 200, 255])
    return trimesh.visual.material.PBRMaterial(**kwargs)


def _scene(*meshes: tuple[str, trimesh.Trimesh]) -> trimesh.Scene:
    scene = trimesh.Scene()
    for name, mesh in meshes:
        scene.add_geometry(mesh, node_name=name, geom_name=name)
    return scene


def _render(scene: trimesh.Scene, lights, camera=None, supersample: int = 1, ceilings: bool = False,
            **kwargs):
    from anyhome.render import Renderer, birdseye_camera

    house = _house()
    meshes = scene_meshes(house, scene)
    camera = camera or birdseye_camera(house, 64, elevation_deg=90.0)
    with Renderer(meshes, lights, supersample=supersample) as renderer:
        return renderer.render(camera, ceilings=ceilings, **kwargs)


def _light(position, range_m: float = 1000.0, power: float = 1.5):
    from anyhome.render.lights import RoomLight

    return RoomLight(tuple(float(x) for x in position), range_m, (power, power, power))


GRAZING = [_light((SIDE_M / 2 - 400.0, SIDE_M / 2, 40.0), power=3.0)]
"""A far light low in the west (where the sun is, too): about 6 degrees above the floor,
the same everywhere on it."""


def _ridges(px: int = 16, tilt_deg: float = 50.0):
    """A normal map of stripes along v, 2 texels wide, tilted alternately east and west."""
    s, c = np.sin(np.radians(tilt_deg)), np.cos(np.radians(tilt_deg))
    east = (np.arange(px) // 2) % 2 == 0
    nx = np.where(east, s, -s)
    rgb = np.zeros((px, px, 3))
    rgb[..., 0], rgb[..., 1], rgb[..., 2] = nx[None, :], 0.0, c
    return _pil().fromarray(np.rint((rgb * 0.5 + 0.5) * 255).astype(np.uint8), "RGB")


def _flat_normal_map(px: int = 4):
    return _pil().new("RGB", (px, px), (128, 128, 255))


def _centre(frame, half: int = 12) -> np.ndarray:
    h, w = frame.color.shape[:2]
    return frame.color[h // 2 - half:h // 2 + half, w // 2 - half:w // 2 + half].astype(float)


# ---------------------------------------------------------------- meshes


def test_corner_tangents_follow_u_and_handedness() -> None:
    verts = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    faces = np.array([[0, 1, 2]])
    up = np.tile([0.0, 0.0, 1.0], (3, 1))
    tan = render_meshes.corner_tangents(verts, faces, verts[faces[0], :2].copy(), up)
    assert np.allclose(tan, [[1.0, 0.0, 0.0, 1.0]] * 3)
    # u mirrored: the tangent turns round and the frame becomes left-handed (v still +y)
    mirrored = verts[faces[0], :2] * [-1.0, 1.0]
    tan = render_meshes.corner_tangents(verts, faces, mirrored, up)
    assert np.allclose(tan, [[-1.0, 0.0, 0.0, -1.0]] * 3)
    assert np.allclose(tan[:, 3:] * np.cross(up, tan[:, :3]), [0.0, 1.0, 0.0])
    # degenerate UVs: no tangent
    assert np.allclose(render_meshes.corner_tangents(verts, faces, np.zeros((3, 2)), up), 0.0)


def test_corner_tangents_of_shared_vertices_are_smooth_and_perpendicular() -> None:
    cyl = trimesh.creation.cylinder(radius=1.0, height=2.0, sections=16)
    angle = np.arctan2(cyl.vertices[:, 1], cyl.vertices[:, 0])
    uv = np.column_stack([angle, cyl.vertices[:, 2]])[cyl.faces.reshape(-1)]
    normals = np.asarray(cyl.vertex_normals)[cyl.faces.reshape(-1)]
    tan = render_meshes.corner_tangents(np.asarray(cyl.vertices), cyl.faces, uv, normals)
    good = np.linalg.norm(tan[:, :3], axis=1) > 0.5
    assert good.mean() > 0.5
    assert np.allclose(np.einsum("ij,ij->i", tan[good, :3], normals[good]), 0.0, atol=1e-9)
    assert np.allclose(np.linalg.norm(tan[good, :3], axis=1), 1.0)


def test_maps_reach_the_batches() -> None:
    mr = _pil().new("RGB", (4, 4), (255, 128, 255))
    normal = _ridges()
    mat = _material(metallicRoughnessTexture=mr, normalTexture=normal, roughnessFactor=0.5)
    mat.normalScale = 0.5
    floor = _floor(mat)
    look = corner_appearance(floor)
    assert look.mr_texture is mr and look.normal_texture is normal and look.texture is None
    assert look.uv is not None and look.normal_scale == 0.5
    plain = trimesh.creation.box()
    plain.apply_translation((1, 1, 1))
    meshes = scene_meshes(_house(), _scene(("room:r:floor", floor), ("object:box", plain)))
    mapped = [b for b in meshes.batches if b.normal_texture is not None]
    assert len(mapped) == 1 and mapped[0].mr_texture is mr and mapped[0].normal_scale == 0.5
    tan = mapped[0].vertices["tan"]
    top = mapped[0].vertices["nrm"][:, 2] > 0.9
    assert np.allclose(tan[top], [1.0, 0.0, 0.0, 1.0], atol=1e-6)  # u = east on the floor
    for b in meshes.batches:
        if b.normal_texture is None:
            assert (b.vertices["tan"] == 0).all()


def test_exported_house_batches_carry_the_material_maps(small_house) -> None:
    from anyhome.scene import build_scene

    meshes = scene_meshes(small_house, build_scene(small_house))
    textured = [b for b in meshes.batches if b.texture is not None]
    assert textured
    for b in textured:
        assert b.mr_texture is not None and b.normal_texture is not None
        good = np.linalg.norm(b.vertices["tan"][:, :3], axis=1) > 0.5
        assert good.mean() > 0.95
        dots = np.einsum("ij,ij->i", b.vertices["tan"][good, :3], b.vertices["nrm"][good])
        assert np.abs(dots).max() < 1e-3
    # colours of one material share its maps: hardly more batches than base textures
    assert len({id(b.normal_texture) for b in textured}) <= len(textured)


# ---------------------------------------------------------------- renders


DARK = [90, 90, 90, 255]
"""A base colour the lights leave well below white."""


def test_normal_map_gives_relief_under_a_grazing_light(gl_available) -> None:
    def floor(**kw):
        return _scene(("room:r:floor", _floor(_material(baseColorFactor=DARK, **kw))))

    relief = _centre(_render(floor(normalTexture=_ridges()), GRAZING))
    flat = _centre(_render(floor(normalTexture=_flat_normal_map()), GRAZING))
    none = _centre(_render(floor(), GRAZING))
    assert flat.mean(axis=2).std() < 1.0 and none.mean(axis=2).std() < 1.0  # uniform
    assert np.abs(flat - none).max() <= 2  # the flat map is (almost) no map: 128 is not 127.5
    lum = relief.mean(axis=2)
    assert lum.max() - lum.min() > 40 and lum.std() > 10  # stripes facing and turned from the light
    cols = lum.mean(axis=0)  # stripes run north-south: the contrast is across the columns
    assert cols.max() - cols.min() > 40 and lum.std(axis=0).max() < 2


def test_normal_scale_zero_flattens_the_map(gl_available) -> None:
    mat = _material(normalTexture=_ridges(), baseColorFactor=DARK)
    mat.normalScale = 0.0
    scaled = _centre(_render(_scene(("room:r:floor", _floor(mat))), GRAZING))
    none = _centre(_render(_scene(("room:r:floor", _floor(_material(baseColorFactor=DARK)))), GRAZING))
    assert np.abs(scaled - none).max() <= 1


def _highlight_scene(mr_rgb, metallic: float = 0.0, base=(60, 60, 60, 255)):
    mr = _pil().new("RGB", (4, 4), mr_rgb)
    mat = _material(metallicRoughnessTexture=mr, roughnessFactor=1.0, metallicFactor=metallic,
                    baseColorFactor=list(base))
    return _scene(("room:r:floor", _floor(mat)))


OVERHEAD = [_light((SIDE_M / 2, SIDE_M / 2, 6.0), range_m=50.0)]
"""A light above the floor's centre, beside the camera: the mirror highlight is in view."""


def test_roughness_map_sets_the_highlight(gl_available) -> None:
    shiny = _centre(_render(_highlight_scene((255, 0, 255)), OVERHEAD), 16).mean(axis=2)
    rough = _centre(_render(_highlight_scene((255, 255, 255)), OVERHEAD), 16).mean(axis=2)
    # a small bright highlight at the centre on the shiny floor, none on the rough one
    assert shiny[12:20, 12:20].max() > rough.max() + 60
    assert shiny.max() - np.median(shiny) > 60
    assert rough.max() - np.median(rough) < 15


def test_metallic_map_sets_the_metalness(gl_available) -> None:
    base = (200, 60, 40, 255)
    dielectric = _centre(_render(_highlight_scene((255, 255, 0), 1.0, base), GRAZING))
    metal = _centre(_render(_highlight_scene((255, 255, 255), 1.0, base), GRAZING))
    assert dielectric.mean() > metal.mean() + 10  # a rough metal has (almost) no diffuse light


def test_neutral_maps_render_exactly_like_none(gl_available) -> None:
    """A white metallicRoughness map leaves the factors as they are, to the bit."""
    white = _pil().new("RGB", (4, 4), (255, 255, 255))
    lights = OVERHEAD + GRAZING
    for metallic in (0.0, 0.7):
        kw = dict(roughnessFactor=0.3, metallicFactor=metallic)
        with_map = _render(_scene(("room:r:floor", _floor(_material(metallicRoughnessTexture=white, **kw)))),
                           lights)
        without = _render(_scene(("room:r:floor", _floor(_material(**kw)))), lights)
        assert np.array_equal(with_map.color, without.color)


def _mixed_scene() -> trimesh.Scene:
    """A checker-textured floor, a vertex-coloured box, a shiny metal box and a rough
    blue one: no metallicRoughness or normal maps anywhere."""
    checker = np.kron((np.indices((4, 4)).sum(axis=0) % 2), np.ones((4, 4)))
    img = _pil().fromarray(np.where(checker[..., None] > 0, [190, 150, 110], [90, 60, 40]).astype(np.uint8))
    floor = _floor(_material(baseColorTexture=img, baseColorFactor=[255, 255, 255, 255],
                             roughnessFactor=0.4))
    coloured = trimesh.creation.box(extents=(0.8, 0.8, 0.8))
    coloured.apply_translation((1.0, 1.0, 0.4))
    coloured.visual.vertex_colors = [40, 160, 70, 255]
    metal = trimesh.creation.icosphere(subdivisions=2, radius=0.6)
    metal.apply_translation((2.8, 1.4, 0.6))
    metal.visual = trimesh.visual.TextureVisuals(material=_material(
        baseColorFactor=[220, 180, 90, 255], metallicFactor=0.9, roughnessFactor=0.25))
    blue = trimesh.creation.box(extents=(1.2, 0.5, 1.4))
    blue.apply_translation((2.2, 3.2, 0.7))
    blue.visual = trimesh.visual.TextureVisuals(material=_material(
        baseColorFactor=[50, 70, 200, 255], roughnessFactor=0.9))
    return _scene(("room:r:floor", floor), ("object:a", coloured), ("object:b", metal),
                  ("object:c", blue))


def _mixed_render():
    from anyhome.render import Camera

    camera = Camera(eye=(-1.0, -1.5, 3.0), target=(2.2, 2.2, 0.3), fov_y_deg=60.0, width_px=96,
                    height_px=96)
    lights = [_light((2.0, 2.0, 2.4), range_m=2.5, power=1.6)]
    return _render(_mixed_scene(), lights, camera, supersample=2)


def test_without_maps_renders_as_before(gl_available) -> None:
    """Geometry without metallicRoughness and normal maps renders as the renderer did
    before it read them (golden image from then; llvmpipe is deterministic, the slack is
    for another Mesa build)."""
    from render_png import read_png

    now = _mixed_render().color.astype(int)
    before = read_png(GOLDEN).astype(int)
    diff = np.abs(now - before).max(axis=2)
    assert (diff <= 1).mean() > 0.995 and diff.max() <= 24


def test_maps_leave_depth_and_ids_alone(gl_available) -> None:
    mat = _material(normalTexture=_ridges(), metallicRoughnessTexture=_pil().new("RGB", (4, 4), (0, 30, 200)))
    box = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    box.apply_translation((2.0, 2.0, 0.5))
    a = _render(_scene(("room:r:floor", _floor(mat)), ("object:x", box)), GRAZING, depth=True, ids=True)
    b = _render(_scene(("room:r:floor", _floor(_material())), ("object:x", box)), GRAZING,
                depth=True, ids=True)
    assert np.array_equal(a.depth, b.depth) and np.array_equal(a.ids, b.ids)
    assert not np.array_equal(a.color, b.color)


def test_brick_wall_of_a_house_shows_relief(gl_available, small_house) -> None:
    """A house's brick wall, seen from a metre away, renders differently once its maps
    count: relief, not a darker or brighter wall."""
    from anyhome.render import Camera, Renderer
    from anyhome.render.lights import room_lights
    from anyhome.scene import build_scene

    house = small_house.model_copy(deep=True)
    house.rooms[0].materials = {**house.rooms[0].materials, "walls": "red brick"}
    meshes = scene_meshes(house, build_scene(house))
    cam = Camera(eye=(2.5, 2.8, 1.3), target=(2.5, 4.0, 1.5), fov_y_deg=60.0, width_px=96, height_px=96)
    lights = room_lights(house, meshes.fixtures)
    with Renderer(meshes, lights, supersample=1) as r:
        mapped = r.render(cam).color.astype(int)
    for b in meshes.batches:
        b.mr_texture = b.normal_texture = None
    with Renderer(meshes, lights, supersample=1) as r:
        plain = r.render(cam).color.astype(int)
    changed = np.abs(mapped - plain).max(axis=2) > 4
    assert changed.mean() > 0.1
    assert abs(mapped.mean() - plain.mean()) < 8


def _fine_detail(grey: np.ndarray, k: int = 9) -> float:
    """Standard deviation of what a k x k box blur takes out (fine detail, noise)."""
    from numpy.lib.stride_tricks import sliding_window_view

    blurred = sliding_window_view(grey, (k, k)).mean(axis=(2, 3))
    return float((grey[k // 2:-(k // 2), k // 2:-(k // 2)] - blurred).std())


def test_plaster_ceiling_stays_calm_under_its_light(gl_available) -> None:
    """A white plaster ceiling lit by a light just under it (grazing it) keeps a quiet
    surface: its normal map may show, but not as noise, and the ceiling is not darker."""
    from anyhome.materials import pbr_material, surface_material
    from anyhome.materials.uv import textured_mesh
    from anyhome.render import Camera

    spec = surface_material("white plaster", "ceiling")
    slab = trimesh.creation.box(extents=(SIDE_M, SIDE_M, 0.05))
    slab.apply_translation((SIDE_M / 2, SIDE_M / 2, 2.625))
    mat = pbr_material(spec)
    assert mat.normalTexture is not None and mat.metallicRoughnessTexture is not None
    without = _material(baseColorTexture=mat.baseColorTexture, baseColorFactor=mat.baseColorFactor,
                        roughnessFactor=mat.roughnessFactor, metallicFactor=mat.metallicFactor)
    cam = Camera(eye=(0.6, 0.6, 1.6), target=(2.4, 2.4, 2.6), fov_y_deg=60.0, width_px=128, height_px=128)
    light = [_light((2.0, 2.0, 2.3), range_m=2.5, power=1.6)]

    def shoot(material) -> np.ndarray:
        ceiling = textured_mesh(slab.vertices, slab.faces, material, spec.tile_m)
        return _render(_scene(("room:r:ceiling", ceiling)), light, cam, ceilings=True).color[4:52, 8:120]

    mapped, flat = shoot(mat), shoot(without)
    assert abs(mapped.mean() - flat.mean()) < 3
    grey = mapped.astype(float).mean(axis=2)
    assert _fine_detail(grey) < 1.5  # the plain glTF reading of the map gives about 2.6


if __name__ == "__main__":  # rewrite the golden image (see GOLDEN)
    from anyhome.render.images import write_png

    DATA.mkdir(exist_ok=True)
    write_png(GOLDEN, _mixed_render().color)
    print(f"wrote {GOLDEN}")
