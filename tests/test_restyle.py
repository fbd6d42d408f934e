"""anyhome.restyle: new materials and assets for a new style, nothing moved."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

import anyhome
from anyhome.house import House

TEXT = "a two-bedroom apartment with a living room, a kitchen and a bathroom"


@pytest.fixture(scope="module")
def house() -> House:
    return anyhome.generate(TEXT, seed=3)


def _geometry(h: House) -> tuple:
    objs = [(o.id, o.position, o.size, o.yaw, o.support, o.room, o.name, o.category, o.group, o.anchor, o.rule)
            for o in h.objects]
    rooms = [(r.id, r.name, r.type, r.polygon, r.height) for r in h.rooms]
    return objs, rooms, [d.model_dump() for d in h.doors], [w.model_dump() for w in h.windows], h.connections


@pytest.mark.parametrize("style", ["gothic", "japanese", ["victorian", "gothic"], "a spooky old manor"])
def test_restyle_moves_nothing(house: House, style) -> None:
    new = anyhome.restyle(house, style)
    assert new is not house
    assert _geometry(new) == _geometry(house)
    # and it survives a save: the geometry in house.json is byte-identical
    a, b = json.loads(house.to_json()), json.loads(new.to_json())
    for key in ("rooms", "objects"):
        for x, y in zip(a[key], b[key], strict=True):
            for drop in ("style", "materials", "material", "asset"):
                x.pop(drop, None), y.pop(drop, None)
        assert a[key] == b[key]
    assert a["doors"] == b["doors"] and a["windows"] == b["windows"]


def test_restyle_rederives_materials_and_assets(house: House) -> None:
    new = anyhome.restyle(house, "gothic")
    assert new.styles == ["gothic"] and "gothic" in new.style
    assert {o.asset["params"]["style"] for o in new.objects} == {"gothic"}
    living = next(r for r in new.rooms if r.type == "living_room")
    assert living.materials["floor"] == "dark oak planks"
    bath = next(r for r in new.rooms if r.type == "bathroom")
    assert bath.materials["floor"] == next(r for r in house.rooms if r.type == "bathroom").materials["floor"]
    assert any(o.material != n.material for o, n in zip(house.objects, new.objects, strict=True))
    assert new.plan is not None and new.plan["styles"] == ["gothic"]
    # each object's size is what its asset was sampled for
    assert all(tuple(o.asset["params"]["size"]) == tuple(o.size) for o in new.objects)
    # reproducible, and the input is untouched
    assert anyhome.restyle(house, "gothic").to_json() == new.to_json()
    assert house.styles != ["gothic"]


def test_restyle_back_and_forth_keeps_geometry(house: House) -> None:
    there = anyhome.restyle(anyhome.restyle(house, "japanese"), "industrial")
    assert _geometry(there) == _geometry(house)
    assert {o.asset["params"]["style"] for o in there.objects} == {"industrial"}


@pytest.mark.parametrize("style", ["zzqqxx", "", ["gothic", "nope"]])
def test_unknown_style_is_one_line_error(house: House, style) -> None:
    with pytest.raises(anyhome.AnyHomeError) as e:
        anyhome.restyle(house, style)
    msg = str(e.value)
    assert "\n" not in msg and "unknown style" in msg and "gothic" in msg


def test_restyled_house_saves_and_loads(tmp_path, house: House) -> None:
    new = anyhome.restyle(house, "art deco")
    path = tmp_path / "house.json"
    path.write_text(new.to_json(), encoding="utf-8")
    code = ("import sys, anyhome; h = anyhome.load(sys.argv[1]); "
            "from anyhome.evaluate import evaluate_house; r = evaluate_house(h); print(h.styles, r.ok)")
    out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "['art_deco'] True"
