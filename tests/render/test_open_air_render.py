"""Renders of open-air and tall rooms: the sky shows above an open-air room (no ceiling),
a room's camera aims with its height."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.pipeline import generate
from anyhome.render.cameras import LOOK_AT_HEIGHT_M, room_camera

VIEW = 64


@pytest.fixture(scope="module")
def terrace_house():
    return generate("a two-bedroom flat with a terrace", seed=0)


def _sky_through_ceiling(camera, room, sky: np.ndarray) -> int:
    """How many sky pixels look up through where ``room``'s ceiling is (or would be): their ray
    meets the ceiling plane inside the room's outline. Sky seen through a window or a door
    meets a wall plane first, so its ceiling point lies outside the outline."""
    from shapely.geometry import Point, Polygon

    outline = Polygon(room.polygon).buffer(-0.05)
    k = camera.intrinsics()
    view = camera.view_matrix()
    right, up, back = view[0, :3], view[1, :3], view[2, :3]
    eye = np.asarray(camera.eye, float)
    count = 0
    for v, u in zip(*np.nonzero(sky)):
        x = (u + 0.5 - k[0, 2]) / k[0, 0]
        y = -(v + 0.5 - k[1, 2]) / k[1, 1]
        ray = x * right + y * up - back
        if ray[2] <= 1e-9:
            continue
        t = (room.height - eye[2]) / ray[2]
        hit = eye + t * ray
        count += outline.contains(Point(hit[0], hit[1]))
    return count


def test_sky_above_open_air_room_not_above_enclosed(gl_available, terrace_house, tmp_path) -> None:
    from anyhome.render import render_house

    render_house(terrace_house, tmp_path, size_px=VIEW, view_size_px=VIEW, ids=True, depth=True)
    for room in terrace_house.rooms:
        depth = np.load(tmp_path / "views" / f"{room.id}.depth.npy")
        sky = np.isinf(depth)
        overhead = _sky_through_ceiling(room_camera(terrace_house, room, VIEW), room, sky)
        if room.open_air:
            assert sky[: VIEW // 4].mean() > 0.5, f"{room.id}: only {sky[: VIEW // 4].mean():.0%} of the top quarter is sky"
            assert overhead > VIEW, f"{room.id}: only {overhead} pixels of sky overhead"
        else:
            assert overhead == 0, f"{room.id}: {overhead} pixels of sky through its ceiling"


def test_camera_aims_higher_in_a_tall_room() -> None:
    church = generate("a church", seed=0)
    nave = next(r for r in church.rooms if r.type == "hall")
    cam = room_camera(church, nave, 32)
    assert cam.target[2] > LOOK_AT_HEIGHT_M + 1.0
    flat = generate("a two-bedroom flat with a terrace", seed=0)
    bedroom = next(r for r in flat.rooms if r.type == "bedroom")
    assert room_camera(flat, bedroom, 32).target[2] == LOOK_AT_HEIGHT_M
