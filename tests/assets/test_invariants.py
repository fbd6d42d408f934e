"""Invariants over every procedural family x seeds x styles x sizes (Infinigen-style).

One grid of meshes per family and seed, each mesh checked once for everything a built
mesh must hold: in and filling its box, sane face count, consistent winding, colours, a
material role per face. The typical-size meshes are built once per session
(:func:`procedural_helpers.typical_mesh`) and shared with the role and material tests."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from procedural_helpers import mesh_for

from anyhome.assets import FAMILIES
from anyhome.assets.procedural._parts import ROLE_ATTRIBUTE, ROLES, Params
from anyhome.assets.registry import get, typical_size

MIN_FACES, MAX_FACES = 12, 20000
FILL_TOL = 0.02
"""Share of each side of the box the mesh bounds may differ by."""
INSIDE_TOL_M = 1e-4
BOUNDS_TOL_M = 1e-3
"""The mesh bounds are the box's, to this many meters."""
SEEDS = (0, 7)
STYLES = ("", "modern", "victorian", "industrial")
AWKWARD_SIZES = [(1.0, 0.05, 1.0), (0.1, 0.1, 0.1), (0.3, 0.3, 2.6), (3.0, 3.0, 0.1)]
"""Boxes a planner may hand any family: thin, tiny, tall, flat."""


def _sizes(family: str) -> list[tuple[float, float, float]]:
    w, d, h = typical_size(family)
    return [(w, d, h), (0.5, 0.5, 0.5), (2.0, 0.8, 1.6), (1.3 * w, 0.8 * d, 1.1 * h)]


def _check_mesh(mesh, size, where: str, fits: bool = True) -> None:
    """Everything a built mesh holds; ``fits``: its bounds are the box's to BOUNDS_TOL_M
    (the grid's boxes; random boxes only need to be filled to FILL_TOL)."""
    w, d, h = size
    assert len(mesh.vertices) > 0 and len(mesh.faces) > 0, where
    assert MIN_FACES < len(mesh.faces) <= MAX_FACES, f"{where}: {len(mesh.faces)} faces"
    v = np.asarray(mesh.vertices)
    assert np.isfinite(v).all(), where
    lo = np.array([-w / 2, -d / 2, 0.0])
    hi = np.array([w / 2, d / 2, h])
    assert (v >= lo - INSIDE_TOL_M).all() and (v <= hi + INSIDE_TOL_M).all(), f"{where}: outside the box"
    np.testing.assert_allclose(mesh.extents, hi - lo, rtol=FILL_TOL, err_msg=f"{where}: does not fill the box")
    if fits:
        np.testing.assert_allclose(mesh.bounds, [lo, hi], atol=BOUNDS_TOL_M, err_msg=f"{where}: bounds are not the box")
    assert mesh.is_winding_consistent, f"{where}: inconsistent winding"
    colors = np.asarray(mesh.visual.vertex_colors)
    assert colors.shape == (len(v), 4), f"{where}: vertex colours missing"
    assert (colors[:, 3] > 0).all(), f"{where}: invisible vertices"
    codes = mesh.face_attributes.get(ROLE_ATTRIBUTE)
    assert codes is not None and len(codes) == len(mesh.faces), f"{where}: faces without a material role"
    assert 0 <= int(np.min(codes)) and int(np.max(codes)) < len(ROLES), f"{where}: unknown role code"


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", SEEDS)
def test_invariants(family: str, seed: int) -> None:
    fam = get(family)
    for size in _sizes(family):
        for style in STYLES:
            assert fam.sample(np.random.default_rng(seed), size, style).family == family
            _check_mesh(mesh_for(family, seed, size, style), size, f"{family} seed={seed} style={style!r} size={size}")


@pytest.mark.parametrize("family", FAMILIES)
def test_awkward_sizes(family: str) -> None:
    fam = get(family)
    for size in AWKWARD_SIZES:
        _check_mesh(fam.build(fam.sample(np.random.default_rng(0), size, "")), size, f"{family} size={size}",
                    fits=False)


@pytest.mark.parametrize("family", FAMILIES)
def test_rebuild_from_record_is_identical(family: str) -> None:
    fam = get(family)
    for seed, size in zip((0, 7, 11), _sizes(family), strict=False):
        style = ("", "victorian", "modern")[seed % 3]
        params = fam.sample(np.random.default_rng(seed), size, style)
        record = json.loads(json.dumps(params.to_record()))  # as saved in house.json
        again = Params.from_record(family, record)
        assert again == params
        a = mesh_for(family, seed, size, style)
        b = fam.build(again)
        np.testing.assert_array_equal(a.vertices, b.vertices)
        np.testing.assert_array_equal(a.faces, b.faces)
        np.testing.assert_array_equal(a.visual.vertex_colors, b.visual.vertex_colors)


def test_enough_families() -> None:
    assert len(FAMILIES) >= 60


@settings(max_examples=150, deadline=None)
@given(
    family=st.sampled_from(FAMILIES),
    size=st.tuples(st.floats(0.05, 6.0), st.floats(0.05, 6.0), st.floats(0.05, 3.0)),
    seed=st.integers(0, 2**31 - 1),
    style=st.sampled_from(["", "modern", "rustic", "gothic", "cyberpunk", "japandi"]),
)
def test_any_box_any_family(family: str, size: tuple[float, float, float], seed: int, style: str) -> None:
    fam = get(family)
    _check_mesh(fam.build(fam.sample(np.random.default_rng(seed), size, style)), size,
                f"{family} seed={seed} style={style!r} size={size}", fits=False)
