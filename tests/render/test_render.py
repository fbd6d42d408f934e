"""render_house end to end on a small generated house (headless EGL)."""

from __future__ import annotations

import sys

import numpy as np
import pytest
import shapely
from render_png import SIZE_PX, VIEW_PX, read_png
from shapely.ops import unary_union

from anyhome.errors import RenderError


def _stem(room_id: str) -> str:
    from anyhome.render.api import _stem

    return _stem(room_id)


def test_files_written(rendered, house) -> None:
    out, result, meta = rendered
    assert (out / "birdseye.png").is_file()
    for room in house.rooms:
        stem = f"views/{_stem(room.id)}"
        for suffix in (".png", ".depth.npy", ".ids.npy"):
            assert (out / f"{stem}{suffix}").is_file()
        assert meta["images"][stem]["room"] == room.id
    assert len(list((out / "views").glob("*.png"))) == len(house.rooms)
    assert set(map(str, result["files"])) >= {str(out / "birdseye.png"), str(out / "render.json")}
    assert not list(out.rglob(".*.tmp"))  # atomic writes leave no temp files
    assert result["timings_s"]["total"] > 0
    assert read_png(out / "birdseye.png").shape == (SIZE_PX, SIZE_PX, 3)


def _not_blank(img: np.ndarray) -> None:
    assert img.std() > 12.0
    colours, counts = np.unique(img.reshape(-1, 3), axis=0, return_counts=True)
    assert len(colours) > 40
    assert counts.max() < 0.6 * counts.sum()  # not one flat colour (e.g. inside a wall)
    assert img.mean() > 30  # not black


def test_images_not_blank(rendered, house) -> None:
    out, _, _ = rendered
    _not_blank(read_png(out / "birdseye.png"))
    for room in house.rooms:
        img = read_png(out / f"views/{_stem(room.id)}.png")
        assert img.shape == (VIEW_PX, VIEW_PX, 3)
        _not_blank(img)


def _footprint_mask(house, record: dict) -> np.ndarray:
    """Pixels of the bird's-eye image whose ray hits the house footprint at z = 0."""
    w, h = record["width_px"], record["height_px"]
    to_world = np.array(record["camera_to_world"])
    k = np.array(record["intrinsics"])
    u, v = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    # camera looks down -z with y up; pixel rows go down
    dirs = np.stack([(u - k[0, 2]) / k[0, 0], -(v - k[1, 2]) / k[1, 1], -np.ones_like(u)], axis=-1)
    dirs = dirs @ to_world[:3, :3].T
    eye = to_world[:3, 3]
    t = -eye[2] / dirs[..., 2]
    hit = eye[:2] + dirs[..., :2] * t[..., None]
    footprint = unary_union([shapely.Polygon(r.polygon) for r in house.rooms])
    return shapely.contains_xy(footprint, hit[..., 0], hit[..., 1])


def test_birdseye_shows_the_house(rendered, house) -> None:
    out, _, meta = rendered
    img = read_png(out / "birdseye.png").astype(float)
    inside = _footprint_mask(house, meta["images"]["birdseye"])
    assert 0.1 < inside.mean() < 0.95  # the house fills a good part of the frame
    # most of the footprint is drawn in other colours than the ground around it (a mean
    # colour comparison failed for a house whose walls and floors average to the ground's)
    ground = np.median(img[~inside], axis=0)
    assert (np.linalg.norm(img[inside] - ground, axis=1) > 15.0).mean() > 0.5
    # the footprint region holds many colours (floors, furniture), the ground few
    assert len(np.unique(img[inside].astype(np.uint8), axis=0)) > 3 * len(
        np.unique(img[~inside].astype(np.uint8), axis=0)) or img[inside].std() > img[~inside].std()


def test_depth_maps(rendered, house) -> None:
    out, _, meta = rendered
    depth = np.load(out / "birdseye.depth.npy")
    assert depth.dtype == np.float32 and depth.shape == (SIZE_PX, SIZE_PX)
    inside = _footprint_mask(house, meta["images"]["birdseye"])
    assert np.isfinite(depth[inside]).all()
    assert (depth[inside] > 0).all()
    for room in house.rooms:
        stem = f"views/{_stem(room.id)}"
        d = np.load(out / f"{stem}.depth.npy")
        ids = np.load(out / f"{stem}.ids.npy")
        finite = np.isfinite(d)
        assert finite.mean() > 0.5  # mostly walls, floor, ceiling, furniture
        assert (d[finite] > 0.04).all() and (d[finite] < 200).all()
        assert np.isfinite(d[ids >= 0]).all()  # every hit instance has a depth


def test_instance_maps(rendered, house) -> None:
    out, _, meta = rendered
    instances = meta["instances"]
    n_obj = len(house.objects)
    assert instances[:n_obj] == [f"object:{o.id}" for o in house.objects]
    ids = np.load(out / "birdseye.ids.npy")
    assert ids.dtype == np.int32 and ids.shape == (SIZE_PX, SIZE_PX)
    assert ids.min() >= -1 and ids.max() < len(instances)
    seen = {int(i) for i in np.unique(ids) if 0 <= i < n_obj}
    assert len(seen) >= 5
    assert any(instances[i].endswith(":floor") for i in np.unique(ids) if i >= n_obj)
    for room in house.rooms:
        view_ids = np.load(out / f"views/{_stem(room.id)}.ids.npy")
        if house.objects_in(room.id):
            assert ((0 <= view_ids) & (view_ids < n_obj)).any()


def test_cameras_recorded(rendered, house) -> None:
    _, _, meta = rendered
    bird = meta["images"]["birdseye"]
    assert np.allclose(np.array(bird["world_to_camera"]) @ np.array(bird["camera_to_world"]),
                       np.eye(4), atol=1e-4)
    for room in house.rooms:
        cam = meta["images"][f"views/{_stem(room.id)}"]
        assert shapely.Polygon(room.polygon).contains(shapely.Point(cam["eye"][:2]))


def test_missing_moderngl_is_one_line_error(house, tmp_path, monkeypatch) -> None:
    from anyhome.render import render_house

    monkeypatch.setitem(sys.modules, "moderngl", None)
    with pytest.raises(RenderError, match=r"pip install 'anyhome\[render\]'") as info:
        render_house(house, tmp_path, size_px=32, views=False)
    assert "\n" not in str(info.value)
