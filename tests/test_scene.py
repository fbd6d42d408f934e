"""The shared 3-D scene (anyhome/scene.py): stair openings in the slabs of a house of
several storeys."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Polygon

from anyhome.geometry import footprint_polygon
from anyhome.pipeline import generate
from anyhome.scene import build_scene, stair_openings


def _top_area_m2(mesh) -> float:
    """Area of a slab's upward faces (its plan area)."""
    up = mesh.face_normals[:, 2] > 0.9
    return float(mesh.area_faces[up].sum())


@pytest.mark.parametrize("text", ["a three-storey townhouse", "a house with a basement gym and a home office"])
def test_every_flight_climbs_through_an_opening(text) -> None:
    house = generate(text, 0)
    stairs = [o for o in house.objects if o.category == "stairs"]
    assert stairs, "the house has no stairs to test"
    rooms = {r.id: r for r in house.rooms}
    scene = build_scene(house, texture_px=8)
    openings = stair_openings(house)
    for o in stairs:
        box = footprint_polygon(o.position, o.size, o.yaw)
        below = rooms[o.room]
        above = [r for r in house.rooms if r.level == below.level + 1 and Polygon(r.polygon).intersection(box).area > 1e-6]
        assert above, f"the flight in {below.id} leads to no room one storey up"
        for room, part in [(below, "ceiling"), *((r, "floor") for r in above)]:
            poly = Polygon(room.polygon)
            cut = poly.intersection(box).area
            assert cut > 1.0, (room.id, part)  # the flight's box lies over this slab
            assert openings[(room.id, part)].contains(box)
            mesh = scene.geometry[f"room:{room.id}:{part}"]
            assert _top_area_m2(mesh) == pytest.approx(poly.area - cut, abs=0.05), (room.id, part)
    # a room no flight passes through keeps its whole floor
    plain = next(r for r in house.rooms if (r.id, "floor") not in openings)
    assert _top_area_m2(scene.geometry[f"room:{plain.id}:floor"]) == pytest.approx(Polygon(plain.polygon).area, abs=0.01)


def test_a_one_storey_house_has_no_openings() -> None:
    house = generate("a two-bedroom apartment", 0)
    assert stair_openings(house) == {}
    assert np.isfinite(build_scene(house, texture_px=8).bounds).all()
