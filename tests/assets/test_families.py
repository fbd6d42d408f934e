"""Family records, name lookup and determinism. (Every family fitting its box at several
sizes and seeds is checked in test_invariants.py, once per mesh.)"""

from __future__ import annotations

import json

import numpy as np
import pytest
from procedural_helpers import typical_mesh

from anyhome.assets import FAMILIES, assign_asset, build_object_mesh, family_for
from anyhome.assets.registry import get, typical_size
from anyhome.house import House, HouseObject, Room

TOL_M = 1e-3


def _obj(family: str, size, **kw) -> HouseObject:
    return HouseObject(id=f"{family}_1", room="r1", name=family.replace("_", " "), category=family,
                       position=(0.0, 0.0, 0.0), size=tuple(size), **kw)


@pytest.mark.parametrize("family", FAMILIES)
def test_deterministic_and_varied(family: str) -> None:
    fam = get(family)
    size = typical_size(family)
    a = fam.sample(np.random.default_rng(1), size, "")
    assert a == fam.sample(np.random.default_rng(1), size, "")
    others = [fam.sample(np.random.default_rng(s), size, "") for s in range(2, 8)]
    assert any(o != a for o in others)
    # building is deterministic too: a fresh build equals the session's shared one
    shared = typical_mesh(family, 0, "")
    again = fam.build(fam.sample(np.random.default_rng(0), size, ""))
    np.testing.assert_array_equal(shared.vertices, again.vertices)
    np.testing.assert_array_equal(shared.faces, again.faces)


@pytest.mark.parametrize("family", FAMILIES)
def test_record_rebuilds(family: str) -> None:
    obj = _obj(family, typical_size(family), material="dark walnut")
    record = assign_asset(obj, np.random.default_rng(3), "victorian")
    assert record["source"] == "procedural" and record["family"] == family
    record = json.loads(json.dumps(record))  # JSON-serialisable
    fam = get(family)
    from anyhome.assets.registry import params_from_record

    direct = fam.build(params_from_record(record))
    placed = obj.model_copy(update={"asset": record})
    rebuilt = build_object_mesh(placed)
    np.testing.assert_array_equal(direct.vertices, rebuilt.vertices)
    np.testing.assert_array_equal(direct.faces, rebuilt.faces)


def test_record_survives_house_json_round_trip() -> None:
    obj = _obj("sofa", (2.1234567, 0.9, 0.85), material="pink velvet")
    obj = obj.model_copy(update={"asset": assign_asset(obj, np.random.default_rng(0), "")})
    house = House(prompt="x", seed=0, rooms=[Room(id="r1", name="r", type="living_room",
                                                  polygon=[(0, 0), (4, 0), (4, 4), (0, 4)])],
                  objects=[obj])
    again = House.from_json(house.to_json())
    a = build_object_mesh(House.from_json(house.to_json()).objects[0])
    b = build_object_mesh(again.objects[0])
    np.testing.assert_array_equal(a.vertices, b.vertices)
    assert obj.asset["params"]["primary"] == "#eb96af"  # pink


def test_no_record_uses_stable_seed() -> None:
    obj = _obj("chair", (0.45, 0.5, 0.9))
    a, b = build_object_mesh(obj), build_object_mesh(obj)
    np.testing.assert_array_equal(a.vertices, b.vertices)


def test_resized_object_still_fits() -> None:
    obj = _obj("bed", (1.6, 2.1, 1.1))
    obj = obj.model_copy(update={"asset": assign_asset(obj, np.random.default_rng(0), "")})
    bigger = obj.model_copy(update={"size": (1.8, 2.2, 1.2)})
    np.testing.assert_allclose(build_object_mesh(bigger).bounds, [[-0.9, -1.1, 0], [0.9, 1.1, 1.2]], atol=TOL_M)


@pytest.mark.parametrize(
    ("category", "name", "expected"),
    [
        ("sofa", "", "sofa"),
        ("couch", "", "sofa"),
        ("", "velvet couch", "sofa"),
        ("furniture", "tall bookcase", "bookshelf"),
        ("appliance", "fridge", "refrigerator"),
        ("chabudai", "low table", "coffee_table"),
        ("", "coffee table", "coffee_table"),
        ("", "Dining Chairs", "chair"),
        ("", "rabbit statue", "statue"),
        ("", "cat tree", "cat_tree"),
        ("", "king size bed", "bed"),
        ("", "potted fern", "plant"),
        ("", "flux capacitor", "generic"),
        ("zzz", "", "generic"),
        ("table", "pool table", "pool_table"),
        ("table", "billiard table", "pool_table"),
        ("cabinet", "arcade machine", "arcade_cabinet"),
        ("chair", "hair chair", "salon_chair"),
        ("bench", "pews", "pew"),
        ("weight_bench", "bench", "weight_bench"),
        ("box", "chest", "box"),
        ("lamp", "stage light", "stage_light"),
        ("exercise_bike", "spin bike", "exercise_bike"),
        ("motorcycle", "", "bicycle"),
        ("dog_crate", "", "kennel"),
        ("garden fountain", "", "fountain"),
        ("", "fish tank", "aquarium"),
        ("", "spiral staircase", "spiral_staircase"),
        ("stairs", "ship's ladder", "ship_ladder"),
        ("stairs", "stairs", "staircase"),
    ],
)
def test_family_for(category: str, name: str, expected: str) -> None:
    assert family_for(category, name) == expected


def test_families_sorted_and_complete() -> None:
    assert FAMILIES == sorted(FAMILIES)
    for must in ("bed", "sofa", "chair", "table", "desk", "toilet", "bookshelf", "lamp", "plant", "generic"):
        assert must in FAMILIES
