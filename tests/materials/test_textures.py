from __future__ import annotations

import numpy as np
import pytest

from anyhome.materials.textures import VARIANTS, generate, kinds

ALL = [(k, v) for k in kinds() for v in VARIANTS.get(k, ("",))]
SIZE = 64


def seam_ratio(a: np.ndarray, axis: int) -> float:
    """How the step across the wrap-around seam compares with the largest step between
    neighbouring texel lines inside the texture (<= 1 for a seam no worse than the rest)."""
    b = np.moveaxis(a if a.ndim == 3 else a[..., None], axis, 0)
    inner = np.abs(np.diff(b, axis=0)).mean(axis=(1, 2))
    seam = np.abs(b[0] - b[-1]).mean()
    return float(seam / max(inner.max(), 1e-9))


@pytest.mark.parametrize(("kind", "variant"), ALL)
def test_shapes_and_ranges(kind: str, variant: str) -> None:
    tex = generate(kind, SIZE, "#a08060", 0.5, variant)
    assert tex.color.shape == (SIZE, SIZE, 3) and tex.normal.shape == (SIZE, SIZE, 3)
    assert tex.roughness.shape == (SIZE, SIZE) and tex.height.shape == (SIZE, SIZE)
    assert 0.0 <= tex.color.min() and tex.color.max() <= 1.0
    assert 0.0 < tex.roughness.min() and tex.roughness.max() <= 1.0
    assert np.allclose(np.linalg.norm(tex.normal, axis=-1), 1.0, atol=1e-5)
    assert tex.normal[..., 2].min() > 0.0  # tangent-space normals face out
    assert np.all(np.isfinite(tex.height))
    assert tex.color.std() > 1e-3  # a pattern, not a flat colour


@pytest.mark.parametrize(("kind", "variant"), ALL)
@pytest.mark.parametrize("size", [64, 128])
def test_tiles(kind: str, variant: str, size: int) -> None:
    tex = generate(kind, size, "#a08060", 0.5, variant)
    for field in (tex.color, tex.height):
        assert seam_ratio(field, 1) <= 1.25, "left/right edges do not meet"
        assert seam_ratio(field, 0) <= 1.25, "top/bottom edges do not meet"


def test_seam_check_catches_a_texture_that_does_not_tile() -> None:
    rng = np.random.default_rng(0)
    noise = np.cumsum(rng.normal(size=(64, 64)), axis=1)  # a random walk along u
    gradient = np.tile(np.linspace(0, 1, 64), (64, 1))
    assert seam_ratio(noise, 1) > 1.25 and seam_ratio(gradient, 1) > 1.25


@pytest.mark.parametrize(("kind", "variant"), ALL)
def test_deterministic(kind: str, variant: str) -> None:
    a = generate(kind, 32, "#6e1928", 0.4, variant, seed=3)
    b = generate(kind, 32, "#6e1928", 0.4, variant, seed=3)
    for x, y in ((a.color, b.color), (a.roughness, b.roughness), (a.normal, b.normal)):
        assert np.array_equal(x, y)


@pytest.mark.parametrize(("kind", "variant"), ALL)
def test_relief_does_not_depend_on_the_colour(kind: str, variant: str) -> None:
    """Normal and roughness maps are shared between colours of one material."""
    a = generate(kind, 32, "#6e1928", 0.4, variant)
    b = generate(kind, 32, "#e0e0d8", 0.4, variant)
    assert np.array_equal(a.normal, b.normal) and np.array_equal(a.roughness, b.roughness)
    assert not np.array_equal(a.color, b.color)


def test_tinted_by_the_colour() -> None:
    dark = generate("planks", 64, "#392518").color.mean(axis=(0, 1))
    light = generate("planks", 64, "#d8bf98").color.mean(axis=(0, 1))
    assert np.all(light > dark)
    red = generate("brick", 64, "#b02020").color.mean(axis=(0, 1))
    assert red[0] > red[1] and red[0] > red[2]


def test_seed_changes_the_layout() -> None:
    assert not np.array_equal(generate("stone", 32, seed=0).color, generate("stone", 32, seed=1).color)


def test_bad_arguments() -> None:
    with pytest.raises(KeyError, match="unknown texture kind"):
        generate("plutonium", 32)
    with pytest.raises(ValueError):
        generate("tile", 4)
