"""Part roles tell the truth (issue 12): every part of every family has a role, the parts
named metal export as metal, and a table of known truths (what a rug, a tv screen, a sink
basin... is made of) holds. Nothing is rendered: the parts and their material specs are
what export and render dress the meshes with."""

from __future__ import annotations

import itertools
from collections import defaultdict

import numpy as np
import pytest
from procedural_helpers import build_with, typical_mesh

from anyhome.assets import FAMILIES
from anyhome.assets.procedural._kit import BRASS
from anyhome.assets.procedural._parts import ROLES, face_roles, slot_role
from anyhome.materials.parts import MIN_METALLIC, object_parts

SEEDS = (0, 7)
STYLES = ("", "victorian", "industrial")
"""Built by test_invariants too: the meshes are shared for the session."""
WORDS = ("", "dark oak")
"""Object material words: none, and words of another material (metal stays metal)."""


def _role_areas(mesh) -> dict[str, float]:
    areas: dict[str, float] = defaultdict(float)
    for role, a in zip(face_roles(mesh), mesh.area_faces, strict=True):
        areas[role] += float(a)
    return areas


def _dominant(mesh) -> str:
    areas = _role_areas(mesh)
    return max(areas, key=areas.__getitem__)


@pytest.mark.parametrize("family", FAMILIES)
def test_every_part_has_a_role_and_metal_parts_are_metallic(family: str) -> None:
    for seed, style, words in itertools.product(SEEDS, STYLES, WORDS):
        mesh = typical_mesh(family, seed, style)
        body = slot_role(family, 0, "")
        parts = object_parts(mesh, words, body, size_px=64, textures=False)
        assert parts, family
        assert sum(len(p.mesh.faces) for p in parts) == len(mesh.faces), family
        for p in parts:
            where = f"{family} seed={seed} style={style!r} words={words!r} part {p.role} {p.color}"
            assert p.role in ROLES, where
            if p.role == "metal":
                assert p.spec.metallic >= MIN_METALLIC, where
            else:
                assert p.spec.metallic < MIN_METALLIC, where


# family -> the roles its parts may have (every seed and style)
ONLY_ROLES: dict[str, set[str]] = {
    "rug": {"fabric"},
    "yoga_mat": {"rubber"},
    "curtain": {"fabric", "metal"},
    "chicken_coop": {"wood", "paint", "metal", "glass"},  # hens are no fabric
    "pool_table": {"wood", "fabric", "leather", "plastic", "paint"},  # pockets, sights, balls: no metal
}
# family -> roles that must be among its parts
HAS_ROLES: dict[str, set[str]] = {
    "tv": {"screen"},
    "sink": {"wood", "stone", "metal"},  # a kitchen sink: cabinet, worktop, steel basin and tap
    "vanity": {"wood", "ceramic", "metal"},  # a porcelain basin
    "counter": {"wood", "stone"},
    "toilet": {"ceramic"},
    "bathtub": {"ceramic"},
    "bed": {"wood", "fabric"},
    "bookshelf": {"wood", "paper"},
    "beer_tap": {"metal"},
    "shower": {"glass", "metal"},
    "plant": {"plant"},
    "potted_tree": {"plant"},
    "lamp": {"light", "fabric"},
    "wine_rack": {"glass"},
    "bicycle": {"rubber", "metal"},
    "wheelchair": {"rubber", "metal"},
    "forklift": {"rubber"},
    "lawn_mower": {"rubber"},
    "wheelbarrow": {"rubber"},
    "car": {"rubber", "glass"},
}
# family -> roles its largest surface (by area) may have
BODY_ROLES: dict[str, set[str]] = {
    "refrigerator": {"metal", "paint"},
    "sink": {"wood"},
    "counter": {"wood"},
    "vanity": {"wood"},
    "toilet": {"ceramic"},
    "bathtub": {"ceramic"},
    "sofa": {"fabric", "leather"},
    "wardrobe": {"wood"},
    "dining_table": {"wood"},
    "rug": {"fabric"},
    "mirror": {"glass", "metal", "paint", "wood"},
}


@pytest.mark.parametrize("family", sorted(set(ONLY_ROLES) | set(HAS_ROLES) | set(BODY_ROLES)))
def test_known_truths(family: str) -> None:
    for seed, style in itertools.product(SEEDS, STYLES):
        mesh = typical_mesh(family, seed, style)
        roles = set(face_roles(mesh))
        where = f"{family} seed={seed} style={style!r}: {sorted(roles)}"
        if family in ONLY_ROLES:
            assert roles <= ONLY_ROLES[family], where
        if family in HAS_ROLES:
            assert roles >= HAS_ROLES[family], where
        if family in BODY_ROLES:
            assert _dominant(mesh) in BODY_ROLES[family], where


def test_tv_screen_and_cabinet_sinks() -> None:
    """The tv's front panel is its screen. A kitchen sink is a cabinet (primary: wood) with
    a worktop (secondary: stone) and a steel basin; its door fronts are the cabinet's
    material, not the worktop's (they were labelled stone, or metal on a sink)."""
    assert slot_role("tv", 1, "#10141a") == "screen"
    for family in ("sink", "counter", "vanity"):
        assert slot_role(family, 0, "#5c3b26") == "wood" and slot_role(family, 1, "#e4e1da") == "stone"
        mesh = typical_mesh(family, 0, "")
        front = np.asarray(mesh.visual.vertex_colors)[mesh.faces[:, 0], :3]
        body = tuple(int(str(typical_mesh_params(family).primary)[i:i + 2], 16) for i in (1, 3, 5))
        roles = np.array(face_roles(mesh))
        assert set(roles[(front == body).all(axis=1)]) == {"wood"}, family


@pytest.mark.parametrize("gold", [BRASS, "#d4af37"])
def test_a_rugs_gold_is_thread(gold: str) -> None:
    """A rug's gold pattern is woven thread, not metal (the role table once said metal)."""
    assert slot_role("rug", 1, gold) == "fabric"
    assert slot_role("rug", 2, gold) == "fabric"


def test_hens_are_not_cloth() -> None:
    mesh = build_with("chicken_coop", hens=3)
    assert "fabric" not in set(face_roles(mesh))


def test_a_wooden_lathe_workpiece_is_wood() -> None:
    wood = _role_areas(build_with("lathe", work="wood"))
    metal = _role_areas(build_with("lathe", work="metal"))
    assert wood["wood"] > metal.get("wood", 0.0) and wood["metal"] < metal["metal"]


def test_black_tyres_are_rubber() -> None:
    for family in ("wheelchair", "forklift", "lawn_mower", "wheelbarrow"):
        assert "rubber" in set(face_roles(typical_mesh(family, 0))), family


def typical_mesh_params(family: str):
    from anyhome.assets.registry import get, typical_size

    return get(family).sample(np.random.default_rng(0), typical_size(family), "")
