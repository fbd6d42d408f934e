"""Object parts get their materials from the roles the asset builder stored per face."""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import numpy as np
import pytest

from anyhome.assets import assign_asset, build_object_mesh
from anyhome.assets.procedural._kit import BRASS, CHROME, COPPER, STEEL
from anyhome.assets.procedural._parts import GLASS, METAL, Builder, tint
from anyhome.house import HouseObject
from anyhome.materials.parts import MIN_METALLIC, object_parts, part_spec

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from two_rooms import two_room_house  # noqa: E402

METAL_FAMILIES = ["beer_tap", "sink", "lamp", "radiator", "espresso_machine", "brew_kettle", "towel_rack",
                  "fermentation_tank", "dance_pole", "shower"]
"""Families with steel, chrome, brass, copper or iron parts."""


def _obj(category: str, material: str, size=(2.0, 0.9, 0.85), oid: str | None = None,
         position=(0.0, 0.0, 0.0)) -> HouseObject:
    obj = HouseObject(id=oid or f"{category}1", room="living", name=category.replace("_", " "),
                      category=category, position=position, size=size, material=material)
    obj.asset = assign_asset(obj, np.random.default_rng(0), "modern")
    return obj


def test_sofa_parts_keep_the_mesh_and_texture_the_body() -> None:
    obj = _obj("sofa", "blue velvet")
    mesh = build_object_mesh(obj)
    parts = object_parts(mesh, obj.material, "fabric", 32)
    assert sum(len(p.mesh.faces) for p in parts) == len(mesh.faces)
    lo = np.min([p.mesh.bounds[0] for p in parts], axis=0)
    hi = np.max([p.mesh.bounds[1] for p in parts], axis=0)
    np.testing.assert_allclose([lo, hi], mesh.bounds, atol=1e-9)
    body = [p for p in parts if p.body]
    assert body and all(p.role == "fabric" and p.spec.kind == "fabric" and p.spec.variant == "velvet"
                        for p in body)
    main = next(p for p in body if p.color == obj.asset["params"]["primary"])
    assert main.spec.textured and main.mesh.visual.uv.shape == (len(main.mesh.vertices), 2)
    assert main.mesh.visual.material.baseColorTexture is not None
    for p in parts:
        if not p.spec.textured:
            assert p.mesh.visual.material.baseColorTexture is None


def test_later_clauses_dress_the_parts_of_their_role() -> None:
    brass = part_spec("metal", "#222222", "oak and brass", 32)
    assert brass.metallic >= MIN_METALLIC and brass.kind == "metal" and brass.textured  # it shows as metal
    legs = part_spec("wood", "#3a2a1f", "charcoal upholstery on dark wood", 32)
    assert legs.kind == "wood" and legs.textured  # the legs are the dark wood, grain and all
    # a body takes the clause of its own role first: a bed's frame is the wood, not the linen
    frame = part_spec("wood", "#5a3f27", "green linen bedding on dark wood", 32, body=True)
    assert frame.kind == "wood"
    assert part_spec("fabric", "#4a6a4a", "green linen bedding on dark wood", 32).kind == "fabric"
    assert part_spec("fabric", "#b9b2a6", "oak", 32).roughness >= 0.8  # the role's own material
    # the body takes the first clause; a metal part never becomes wood
    assert part_spec("wood", "#a0714a", "marble", 32, body=True).kind == "marble"
    assert part_spec("metal", "#9a9da3", "oak", 32, body=True).metallic >= MIN_METALLIC


@pytest.mark.parametrize("color", [METAL, CHROME, STEEL, BRASS, COPPER])
@pytest.mark.parametrize("words", ["", "oak", "cast iron", "matte black metal and walnut"])
def test_metal_parts_are_metallic_whatever_the_words(color: str, words: str) -> None:
    for body in (False, True):
        spec = part_spec("metal", color, words, 32, body=body)
        assert spec.metallic >= MIN_METALLIC and spec.roughness <= 0.7


def test_glass_and_translucent_parts() -> None:
    glass = part_spec("glass", GLASS, "oak", 32)
    assert glass.kind == "glass" and glass.alpha == pytest.approx(0.35)
    shade = part_spec("fabric", "#d9c3a0", "linen", 32, 200 / 255)
    assert 0.0 < shade.alpha < 1.0 and not shade.textured


def test_parts_follow_the_stored_roles_not_the_colours() -> None:
    b = Builder()
    b.box((0, 0, 0), (1, 1, 0.1), tint("#a0714a", "wood"))
    b.box((0, 0, 0.1), (0.1, 0.1, 1), METAL)
    b.box((0.2, 0.2, 0.1), (0.5, 0.5, 0.4), GLASS, alpha=90)
    b.box((0.6, 0.6, 0.1), (0.9, 0.9, 0.4), "#a0714a", role="leather")  # same colour, other role
    parts = object_parts(b.mesh((1, 1, 1)), "walnut", "wood", 32)
    assert sorted(p.role for p in parts) == ["glass", "leather", "metal", "wood"]
    top = next(p for p in parts if p.role == "wood")
    assert top.body and top.spec.kind == "wood"
    # planar UVs in meters / tile size: the 1 m top face spans 1 / tile_m in u
    assert np.ptp(top.mesh.visual.uv[:, 0]) == pytest.approx(1.0 / top.spec.tile_m, rel=1e-6)
    assert next(p for p in parts if p.role == "metal").spec.metallic >= MIN_METALLIC


def _json_chunk(data: bytes) -> dict:
    (length,) = struct.unpack_from("<I", data, 12)
    return json.loads(data[20:20 + length])


def test_metal_parts_are_metallic_in_the_glb(tmp_path) -> None:
    from anyhome.export.glb import write_glb

    objs = [_obj(f, "", size=None or (0.6, 0.5, 0.8), oid=f"{f}_{k}", position=(0.5 + 0.4 * k, 1.0 + 0.1 * i, 0))
            for i, f in enumerate(METAL_FAMILIES) for k in range(2)]
    objs += [_obj("table", "oak and brass", size=(1.2, 0.8, 0.75), oid="tbl", position=(3, 3, 0))]
    path = write_glb(two_room_house(objs), tmp_path / "h.glb", texture_px=16)
    tree = _json_chunk(path.read_bytes())
    metal_nodes = 0
    per_object: set[str] = set()
    for node in tree["nodes"]:
        extras = node.get("extras", {})
        if extras.get("role") != "metal" or "mesh" not in node:
            continue
        mat = tree["materials"][tree["meshes"][node["mesh"]]["primitives"][0]["material"]]
        pbr = mat["pbrMetallicRoughness"]
        assert pbr.get("metallicFactor", 1.0) >= MIN_METALLIC, (node["name"], mat)
        assert pbr.get("roughnessFactor", 1.0) <= 0.7, (node["name"], mat)
        metal_nodes += 1
        per_object.add(extras["object"])
    # every metal family shows metal parts (built with two seeds each)
    assert {o.split("_")[0] for o in per_object} >= {f.split("_")[0] for f in METAL_FAMILIES}
    assert metal_nodes >= len(METAL_FAMILIES)
