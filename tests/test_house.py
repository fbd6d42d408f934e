"""house.json contract: lossless save/load, refusal of other formats, atomic writes."""

import json

import pytest

from anyhome.errors import HouseFormatError
from anyhome.house import Door, House, HouseObject, Room, Window, load


def small_house() -> House:
    return House(
        prompt="a test house",
        seed=3,
        style="plain",
        rooms=[
            Room(id="living", name="living room", type="living_room",
                 polygon=[(0, 0), (4, 0), (4, 4), (0, 4)], materials={"floor": "oak", "walls": "white"}),
            Room(id="bed", name="bedroom", type="bedroom",
                 polygon=[(4, 0), (7, 0), (7, 4), (4, 4)], materials={"floor": "carpet", "walls": "blue"}),
        ],
        connections=[("living", "bed"), ("living", "outside")],
        doors=[
            Door(id="door-0", rooms=("living", "bed"), segment=((4, 1), (4, 1.9))),
            Door(id="door-1", rooms=("living", "outside"), segment=((1, 0), (1.9, 0))),
        ],
        windows=[Window(id="win-0", room="bed", segment=((7, 1), (7, 2.2)))],
        objects=[
            HouseObject(id="o1", room="bed", name="bed", category="bed", position=(5.5, 3.0, 0),
                        size=(1.4, 2.0, 0.5), yaw=3.14159, rule="place_wall", material="oak"),
        ],
    )


def test_roundtrip_is_lossless(tmp_path):
    h = small_house()
    path = h.save(tmp_path)
    again = load(tmp_path)
    assert again == House.from_json(path.read_text())
    assert again.to_json() == h.to_json()
    assert again.objects[0].yaw == pytest.approx(3.1416)


def test_required_fields_present(tmp_path):
    data = json.loads(small_house().save(tmp_path).read_text())
    for key in ("format", "version", "prompt", "seed", "style", "rooms", "connections",
                "doors", "windows", "objects"):
        assert key in data
    assert data["format"] == "anyhome.house" and data["version"] == 1
    obj = data["objects"][0]
    for key in ("id", "room", "name", "category", "description", "position", "size", "yaw",
                "support", "group", "anchor", "rule", "material"):
        assert key in obj


@pytest.mark.parametrize(
    "mutate, message",
    [
        (lambda d: d.update(format="other.scene"), "not an AnyHome house"),
        (lambda d: d.update(version=2), "version 2 is not supported"),
        (lambda d: d["rooms"][0].pop("polygon"), r"house.json: rooms\[0\]\.polygon: Field required"),
    ],
)
def test_refuses_other_formats(tmp_path, mutate, message):
    data = json.loads(small_house().to_json())
    mutate(data)
    (tmp_path / "house.json").write_text(json.dumps(data))
    with pytest.raises(HouseFormatError, match=message):
        load(tmp_path)


def test_refuses_non_json_and_missing(tmp_path):
    (tmp_path / "house.json").write_text("{not json")
    with pytest.raises(HouseFormatError, match="not valid JSON"):
        load(tmp_path)
    with pytest.raises(HouseFormatError, match="no house found"):
        load(tmp_path / "nowhere")


def test_save_is_atomic_and_leaves_no_temp_files(tmp_path):
    h = small_house()
    h.save(tmp_path)
    h.save(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["house.json"]
