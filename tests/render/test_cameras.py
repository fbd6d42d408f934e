from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from anyhome.render.cameras import EYE_HEIGHT_M, Camera, birdseye_camera, house_points, room_camera


def test_view_matrix_looks_down_minus_z() -> None:
    cam = Camera((0.0, -5.0, 1.6), (0.0, 0.0, 1.6), 60.0, 64, 64)
    p = cam.view_matrix() @ np.array([0.0, 0.0, 1.6, 1.0])
    assert np.allclose(p[:3], [0.0, 0.0, -5.0])
    px = cam.project(np.array([[0.0, 0.0, 1.6]]))
    assert np.allclose(px, [[32.0, 32.0]])


def test_birdseye_frames_the_whole_house(small_house) -> None:
    cam = birdseye_camera(small_house, 200)
    px = cam.project(house_points(small_house))
    assert (px >= 0).all() and (px <= 200).all()
    assert cam.eye[2] > max(r.height for r in small_house.rooms)


def test_room_cameras_stand_inside_at_eye_height(small_house) -> None:
    for room in small_house.rooms:
        cam = room_camera(small_house, room, 64)
        poly = Polygon(room.polygon)
        assert poly.buffer(-0.1).contains(Point(cam.eye[:2]))
        assert cam.eye[2] == pytest.approx(EYE_HEIGHT_M)
        assert cam.fov_y_deg == pytest.approx(75.0)
        # looks across the room: the target is a corner at least half the diagonal away
        reach = np.linalg.norm(np.subtract(cam.target[:2], cam.eye[:2]))
        lo, hi = np.min(room.polygon, axis=0), np.max(room.polygon, axis=0)
        assert reach > 0.5 * np.linalg.norm(hi - lo)


def test_room_camera_keeps_clear_of_tall_furniture(small_house) -> None:
    from anyhome.geometry import footprint_polygon

    for room in small_house.rooms:
        cam = room_camera(small_house, room, 64)
        for obj in small_house.objects_in(room.id):
            if obj.position[2] + obj.size[2] > EYE_HEIGHT_M - 0.3:
                fp = footprint_polygon(obj.position, obj.size, obj.yaw)
                assert fp.distance(Point(cam.eye[:2])) > 0.2
