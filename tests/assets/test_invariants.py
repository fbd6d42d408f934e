"""Invariants over every procedural family x seeds x styles x sizes (Infinigen-style)."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome.assets import FAMILIES
from anyhome.assets.procedural._parts import Params
from anyhome.assets.registry import get, typical_size

MIN_FACES, MAX_FACES = 12, 20000
FILL_TOL = 0.02
"""Share of each side of the box the mesh bounds may differ by."""
INSIDE_TOL_M = 1e-4
SEEDS = (0, 7)
STYLES = ("", "modern", "victorian", "industrial")
AWKWARD_SIZES = [(1.0, 0.05, 1.0), (0.1, 0.1, 0.1), (0.3, 0.3, 2.6), (3.0, 3.0, 0.1)]
"""Boxes a planner may hand any family: thin, tiny, tall, flat."""


def _sizes(family: str) -> list[tuple[float, float, float]]:
    w, d, h = typical_size(family)
    return [(w, d, h), (0.5, 0.5, 0.5), (2.0, 0.8, 1.6), (1.3 * w, 0.8 * d, 1.1 * h)]


def _check_mesh(mesh, size, where: str) -> None:
    w, d, h = size
    assert len(mesh.vertices) > 0 and len(mesh.faces) > 0, where
    assert MIN_FACES <= len(mesh.faces) <= MAX_FACES, f"{where}: {len(mesh.faces)} faces"
    v = np.asarray(mesh.vertices)
    assert np.isfinite(v).all(), where
    lo = np.array([-w / 2, -d / 2, 0.0])
    hi = np.array([w / 2, d / 2, h])
    assert (v >= lo - INSIDE_TOL_M).all() and (v <= hi + INSIDE_TOL_M).all(), f"{where}: outside the box"
    np.testing.assert_allclose(mesh.extents, hi - lo, rtol=FILL_TOL, err_msg=f"{where}: does not fill the box")
    assert mesh.is_winding_consistent, f"{where}: inconsistent winding"
    colors = np.asarray(mesh.visual.vertex_colors)
    assert colors.shape == (len(v), 4), f"{where}: vertex colours missing"
    assert (colors[:, 3] > 0).all(), f"{where}: invisible vertices"


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("seed", SEEDS)
def test_invariants(family: str, seed: int) -> None:
    fam = get(family)
    for size in _sizes(family):
        for style in STYLES:
            params = fam.sample(np.random.default_rng(seed), size, style)
            assert params.family == family
            _check_mesh(fam.build(params), size, f"{family} seed={seed} style={style!r} size={size}")


@pytest.mark.parametrize("family", FAMILIES)
def test_awkward_sizes(family: str) -> None:
    fam = get(family)
    for size in AWKWARD_SIZES:
        _check_mesh(fam.build(fam.sample(np.random.default_rng(0), size, "")), size, f"{family} size={size}")


@pytest.mark.parametrize("family", FAMILIES)
def test_rebuild_from_record_is_identical(family: str) -> None:
    fam = get(family)
    for seed, size in zip((0, 7, 11), _sizes(family), strict=False):
        params = fam.sample(np.random.default_rng(seed), size, ("", "victorian", "modern")[seed % 3])
        record = json.loads(json.dumps(params.to_record()))  # as saved in house.json
        again = Params.from_record(family, record)
        assert again == params
        a, b = fam.build(params), fam.build(again)
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
                f"{family} seed={seed} style={style!r} size={size}")
