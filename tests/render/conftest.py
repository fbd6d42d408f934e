from __future__ import annotations

import json

import pytest
from render_png import SIZE_PX, VIEW_PX

PROMPT = "a one-bedroom apartment"


@pytest.fixture
def small_house():
    """Two rooms, a door between them, an entrance, a window and a few objects (a tall
    wardrobe in a corner among them)."""
    from two_rooms import two_room_house

    from anyhome.house import HouseObject

    objs = [
        HouseObject(id="sofa1", room="living", name="grey sofa", category="sofa",
                    position=(2.5, 3.5, 0), size=(2.0, 0.9, 0.85), yaw=3.141592653589793),
        HouseObject(id="ct", room="living", name="coffee table", category="coffee_table",
                    position=(2.5, 2.2, 0), size=(1.1, 0.6, 0.42)),
        HouseObject(id="bed1", room="bed", name="double bed", category="bed",
                    position=(7.0, 1.05, 0), size=(1.6, 2.1, 1.1), material="dark walnut"),
        HouseObject(id="wr", room="bed", name="wardrobe", category="wardrobe",
                    position=(8.45, 3.7, 0), size=(1.0, 0.6, 2.1), yaw=3.141592653589793),
    ]
    return two_room_house(objs)


@pytest.fixture(scope="session")
def house():
    from anyhome.pipeline import generate

    return generate(PROMPT, seed=0)


@pytest.fixture(scope="session")
def rendered(gl_available, house, tmp_path_factory):
    """(out folder, render_house result, render.json) for a small render with depth and ids."""
    from anyhome.render import render_house

    out = tmp_path_factory.mktemp("render")
    result = render_house(house, out, size_px=SIZE_PX, view_size_px=VIEW_PX, depth=True, ids=True)
    meta = json.loads((out / "render.json").read_text(encoding="utf-8"))
    return out, result, meta
