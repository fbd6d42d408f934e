from __future__ import annotations

import json
import struct
import zlib
from pathlib import Path

import numpy as np
import pytest

from anyhome.errors import RenderError

PROMPT = "a one-bedroom apartment"
SIZE_PX = 128
VIEW_PX = 96


def read_png(path: Path) -> np.ndarray:
    """Decode the 8-bit PNGs that anyhome.render writes (one IDAT, filter Sub)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, {}
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        tag = data[pos + 4:pos + 8]
        chunks[tag] = chunks.get(tag, b"") + data[pos + 8:pos + 8 + n]
        pos += 12 + n
    w, h, depth, ctype = struct.unpack(">IIBB", chunks[b"IHDR"][:10])
    assert depth == 8
    c = {0: 1, 2: 3, 6: 4}[ctype]
    raw = np.frombuffer(zlib.decompress(chunks[b"IDAT"]), dtype=np.uint8).reshape(h, 1 + w * c)
    assert (raw[:, 0] == 1).all()
    rows = raw[:, 1:].reshape(h, w, c).astype(np.int64)
    return (np.cumsum(rows, axis=1) % 256).astype(np.uint8)


@pytest.fixture
def small_house():
    """Two rooms, a door between them, an entrance, a window and a few objects (a tall
    wardrobe in a corner among them)."""
    from anyhome.house import Door, House, HouseObject, Room, Window

    rooms = [
        Room(id="living", name="living room", type="living_room",
             polygon=[(0, 0), (5, 0), (5, 4), (0, 4)],
             materials={"floor": "white oak", "walls": "sage green paint"}),
        Room(id="bed", name="bedroom", type="bedroom", polygon=[(5, 0), (9, 0), (9, 4), (5, 4)],
             materials={"floor": "dark walnut", "walls": "pink"}),
    ]
    doors = [Door(id="d1", rooms=("living", "bed"), segment=((5, 1.5), (5, 2.4))),
             Door(id="d0", rooms=("living", "outside"), segment=((1, 0), (2, 0)))]
    windows = [Window(id="w1", room="bed", segment=((9, 1.2), (9, 2.8)), sill=0.9, height=1.2)]
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
    return House(prompt="a small test house", seed=0, rooms=rooms, doors=doors, windows=windows,
                 objects=objs, connections=[("living", "bed"), ("living", "outside")])


@pytest.fixture(scope="session")
def gl_available() -> None:
    """Skip when moderngl or a headless EGL context is missing."""
    pytest.importorskip("moderngl")
    from anyhome.render.gl import create_context

    try:
        ctx = create_context()
    except RenderError as e:
        pytest.skip(str(e))
    ctx.release()


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
