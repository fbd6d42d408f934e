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


def test_sky_above_open_air_room_not_above_enclosed(gl_available, terrace_house, tmp_path) -> None:
    from anyhome.render import render_house

    render_house(terrace_house, tmp_path, size_px=VIEW, view_size_px=VIEW, ids=True, depth=True)
    for room in terrace_house.rooms:
        depth = np.load(tmp_path / "views" / f"{room.id}.depth.npy")
        top = depth[: VIEW // 4]
        sky = float(np.isinf(top).mean())  # nothing drawn: the sky
        if room.open_air:
            assert sky > 0.5, f"{room.id}: only {sky:.0%} of the top quarter is sky"
        else:
            assert sky == 0.0, f"{room.id}: {sky:.0%} sky through its ceiling"


def test_camera_aims_higher_in_a_tall_room() -> None:
    church = generate("a church", seed=0)
    nave = next(r for r in church.rooms if r.type == "hall")
    cam = room_camera(church, nave, 32)
    assert cam.target[2] > LOOK_AT_HEIGHT_M + 1.0
    flat = generate("a two-bedroom flat with a terrace", seed=0)
    bedroom = next(r for r in flat.rooms if r.type == "bedroom")
    assert room_camera(flat, bedroom, 32).target[2] == LOOK_AT_HEIGHT_M
