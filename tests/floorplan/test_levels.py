"""Houses of several storeys, many rooms, and house.json version 2 (issue 13, part D)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from anyhome.evaluate import evaluate_house
from anyhome.floorplan.levels import reachable_rooms, stair_link
from anyhome.house import House, load
from anyhome.pipeline import generate


@pytest.fixture(scope="module")
def townhouse() -> House:
    return generate("a three-storey townhouse", 0)


def test_townhouse_has_three_storeys_joined_by_stairs(townhouse):
    assert townhouse.level_numbers() == [0, 1, 2]
    assert [lv.elevation_m for lv in townhouse.levels] == sorted(lv.elevation_m for lv in townhouse.levels)
    assert townhouse.levels[1].elevation_m > 2.0
    stairs = [o for o in townhouse.objects if o.category == "stairs"]
    assert len(stairs) == 2
    links = [stair_link(townhouse.floorplan, o) for o in stairs]
    levels = sorted((townhouse.room_level(a), townhouse.room_level(b)) for a, b in links)
    assert levels == [(0, 1), (1, 2)]
    for o in stairs:
        assert o.asset is not None and o.asset.get("family") == "staircase"
    assert reachable_rooms(townhouse) == {r.id for r in townhouse.rooms}
    report = evaluate_house(townhouse)
    assert report.violations == []
    assert report.metrics["connections_realized"] == 1.0


def test_hotel_floor_fourteen_rooms_each_with_its_bathroom():
    h = generate("a hotel floor with fourteen guest rooms, each with its own bathroom", 0)
    guest = [r for r in h.rooms if r.type == "bedroom"]
    baths = [r for r in h.rooms if r.type == "bathroom"]
    assert len(guest) == 14 and len(baths) == 14
    assert any(r.name == "corridor" for r in h.rooms)
    guest_ids = {r.id for r in guest}
    for b in baths:  # each bathroom opens from a guest room
        assert any(b.id in d.rooms and (set(d.rooms) - {b.id}) <= guest_ids for d in h.doors)
    assert evaluate_house(h).violations == []


def test_version_1_file_still_loads_and_evaluates(tmp_path):
    h = generate("a small studio apartment", 0)
    data = json.loads(h.to_json())
    assert data["version"] == 2
    data["version"] = 1
    del data["levels"]
    for r in data["rooms"]:
        del r["level"]
    path = tmp_path / "house.json"
    path.write_text(json.dumps(data))
    old = load(path)
    assert old.version == 2 and all(r.level == 0 for r in old.rooms)
    assert evaluate_house(old).violations == []
    assert old.to_json() == h.to_json()


def test_version_1_file_with_levels_is_refused(tmp_path):
    data = json.loads(generate("a small studio apartment", 0).to_json())
    data["version"] = 1
    path = tmp_path / "house.json"
    path.write_text(json.dumps(data))
    out = subprocess.run([sys.executable, "-m", "anyhome", "eval", str(path)], capture_output=True, text=True, timeout=60)
    assert out.returncode == 2 and "version-1 house has no level fields" in out.stderr


def test_per_storey_svgs_written(tmp_path):
    out = tmp_path / "h"
    run = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a two-storey house with a basement",
                          "--out", str(out), "--no-glb", "-q"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    names = sorted(p.name for p in out.glob("floorplan*.svg"))
    assert names == ["floorplan-1.svg", "floorplan-b1.svg", "floorplan.svg"]
    h = load(out)
    for name, level in (("floorplan.svg", 0), ("floorplan-1.svg", 1), ("floorplan-b1.svg", -1)):
        text = (out / name).read_text()
        assert all(r.name in text for r in h.rooms if r.level == level)
    assert "kitchen" in (out / "floorplan.svg").read_text()
    assert "kitchen" not in (out / "floorplan-b1.svg").read_text()


def test_glb_stacks_each_storey_at_its_elevation(townhouse, tmp_path):
    """One node per storey, raised to its elevation (glTF is y-up); its rooms under it."""
    import numpy as np
    import trimesh

    from anyhome.export.glb import write_glb

    path = write_glb(townhouse, tmp_path / "house.glb")
    scene = trimesh.load(path)
    for lv in townhouse.levels:
        node = f"level:{lv.level}"
        assert node in scene.graph.nodes
        assert np.isclose(scene.graph.get(node)[0][1, 3], lv.elevation_m)
        for r in townhouse.rooms:
            if r.level == lv.level:
                assert np.isclose(scene.graph.get(f"room:{r.id}:floor")[0][1, 3], lv.elevation_m)
    top = max(townhouse.levels, key=lambda lv: lv.level)
    assert scene.bounds[1][1] >= top.elevation_m + 2.0  # the top storey stands above the others


def test_each_storey_has_its_birdseye_and_rerender_keeps_the_folder_ours(townhouse, gl_available, tmp_path):
    out = tmp_path / "town"
    subprocess.run([sys.executable, "-m", "anyhome", "generate", "a three-storey townhouse", "--out", str(out),
                    "--render", "--view-size", "64", "--size", "96", "--no-glb"], check=True, timeout=300)
    meta = json.loads((out / "render.json").read_text())
    assert {"birdseye", "birdseye-1", "birdseye-2"} <= set(meta["images"])
    assert set(meta["instances_by_level"]) == {"0", "1", "2"}
    rooms = {r["id"]: r["level"] for r in json.loads((out / "house.json").read_text())["rooms"]}
    for name, rec in meta["images"].items():
        if name.startswith("views/"):
            assert rec["level"] == rooms[rec["room"]]
    proc = subprocess.run([sys.executable, "-m", "anyhome", "render", str(out), "--view-size", "64", "--size", "96"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert (out / "birdseye-2.png").is_file()


def test_storeys_that_cannot_stack_become_one_valid_storey_with_a_warning():
    """An attic cottage whose ground-floor stairwell never comes out large enough for a
    flight (seed 1, measured): the house is laid out on the ground floor, its stairwells
    joined by a door, and says so."""
    h = generate("a cozy cottage with an attic bedroom", 1)
    assert h.level_numbers() == [0] and not h.levels
    assert not [o for o in h.objects if o.category == "stairs"]
    assert any("could not stack the storeys" in w for w in h.warnings)
    report = evaluate_house(h)
    assert report.violations == [] and report.metrics["connections_realized"] == 1.0
