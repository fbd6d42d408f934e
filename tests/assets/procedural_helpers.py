"""Helpers for the per-module tests of the procedural families."""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import trimesh

from anyhome.assets.procedural._parts import Params
from anyhome.assets.registry import family_for, get, typical_size


def fresh_mesh(family: str, seed: int, size, style: str = "") -> trimesh.Trimesh:
    """The family's mesh sampled with ``seed`` in box ``size`` for ``style``, built now."""
    fam = get(family)
    return fam.build(fam.sample(np.random.default_rng(seed), tuple(size), style))


@lru_cache(maxsize=None)
def typical_mesh(family: str, seed: int, style: str = "") -> trimesh.Trimesh:
    """The family's mesh at its typical size for ``seed`` and ``style``, built once per
    test session and shared by every test that checks it (invariants, roles, materials).
    Callers must not modify it."""
    return fresh_mesh(family, seed, typical_size(family), style)


def mesh_for(family: str, seed: int, size, style: str = "") -> trimesh.Trimesh:
    """:func:`typical_mesh` when ``size`` is the typical box (shared), else a fresh build."""
    if tuple(size) == typical_size(family):
        return typical_mesh(family, seed, style)
    return fresh_mesh(family, seed, size, style)


def build_with(family: str, seed: int = 0, size=None, style: str = "", **knobs) -> trimesh.Trimesh:
    """The family's mesh for a sampled record with some knobs overridden (as a saved
    house.json record edited by hand would be)."""
    fam = get(family)
    params = fam.sample(np.random.default_rng(seed), size or typical_size(family), style)
    record = params.to_record()
    unknown = set(knobs) - set(record["knobs"])
    assert not unknown, f"{family} has no knobs {unknown}"
    record["knobs"].update(knobs)
    return fam.build(Params.from_record(family, record))


def meshes_differ(a: trimesh.Trimesh, b: trimesh.Trimesh) -> bool:
    if a.vertices.shape != b.vertices.shape or a.faces.shape != b.faces.shape:
        return True
    return not np.allclose(a.vertices, b.vertices) or not np.array_equal(a.visual.vertex_colors,
                                                                         b.visual.vertex_colors)


def assert_knob_changes_mesh(family: str, knob: str, a, b, **fixed) -> None:
    """Setting ``knob`` to ``a`` or ``b`` (other knobs as sampled, or ``fixed``) gives
    different meshes, both filling the family's typical box."""
    ma = build_with(family, **{knob: a}, **fixed)
    mb = build_with(family, **{knob: b}, **fixed)
    assert meshes_differ(ma, mb), f"{family}: {knob}={a!r} and {knob}={b!r} build the same mesh"
    for m in (ma, mb):
        np.testing.assert_allclose(m.extents, typical_size(family), rtol=0.02)


def assert_maps(cases) -> None:
    """Every (category, name, family) resolves through ``family_for`` as listed."""
    wrong = [(c, n, family_for(c, n), f) for c, n, f in cases if family_for(c, n) != f]
    assert not wrong, f"(category, name, got, expected): {wrong}"


def assert_closed_in_box(family: str, seed: int) -> None:
    """The family's mesh at its typical size is closed, exactly fills its box (centred on
    x and y, from the floor up) and is the same when built again from the same seed."""
    size = typical_size(family)
    mesh = fresh_mesh(family, seed, size)
    assert mesh.is_watertight
    np.testing.assert_allclose(mesh.bounds, [[-size[0] / 2, -size[1] / 2, 0.0], [size[0] / 2, size[1] / 2, size[2]]],
                               atol=1e-6)
    np.testing.assert_array_equal(mesh.vertices, fresh_mesh(family, seed, size).vertices)
