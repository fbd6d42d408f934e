"""Material roles: every part of every family says what it is made of (issue 12)."""

from __future__ import annotations

import itertools
from collections import Counter
from pathlib import Path

import numpy as np
import pytest
import trimesh
import yaml
from procedural_helpers import typical_mesh

from anyhome.assets import FAMILIES
from anyhome.assets.procedural._parts import (
    METAL,
    ROLE_ATTRIBUTE,
    ROLES,
    Builder,
    face_roles,
    tint,
)
from anyhome.assets.registry import get, typical_size

STYLES = ("", "victorian", "industrial")
SEEDS = (0, 7)
KNOWLEDGE = Path(__file__).resolve().parents[2] / "src/anyhome/plan/knowledge/objects.yaml"


def _build(family: str, seed: int, style: str = "", size=None) -> trimesh.Trimesh:
    fam = get(family)
    return fam.build(fam.sample(np.random.default_rng(seed), size or typical_size(family), style))


def test_every_face_of_every_family_has_a_role() -> None:
    used: Counter[str] = Counter()
    per_family: dict[str, set[str]] = {}
    for family in FAMILIES:
        for seed, style in itertools.product(SEEDS, STYLES):
            mesh = typical_mesh(family, seed, style)  # shared with test_invariants
            codes = mesh.face_attributes.get(ROLE_ATTRIBUTE)
            assert codes is not None and len(codes) == len(mesh.faces), family
            assert int(np.max(codes)) < len(ROLES), family
            roles = face_roles(mesh)
            used.update(roles)
            per_family.setdefault(family, set()).update(roles)
    # the labels are real, not one role for everything
    assert len(used) >= 12, used
    assert sum(len(r) > 1 for r in per_family.values()) >= 0.9 * len(FAMILIES)
    assert per_family["bed"] >= {"wood", "fabric"}
    assert "metal" in per_family["beer_tap"] and "glass" in per_family["shower"]


def test_a_part_without_a_role_is_refused() -> None:
    b = Builder()
    with pytest.raises(ValueError, match="no material role"):
        b.box((0, 0, 0), (1, 1, 1), "#a0714a")
    with pytest.raises(ValueError, match="unknown material role"):
        b.box((0, 0, 0), (1, 1, 1), "#a0714a", role="cheese")  # type: ignore[arg-type]
    b.box((0, 0, 0), (1, 1, 1), "#a0714a", role="wood")
    b.cyl(0, 0, 1, 2, 0.1, METAL)
    b.sphere((0, 0, 2), 0.2, tint("#f4f1ea", "ceramic"))
    b.rod((0, 0, 0), (0, 1, 0), 0.05, METAL, role="rubber")  # role= wins over the colour's
    mesh = b.mesh((1, 1, 1))
    assert [r for r, _ in Counter(face_roles(mesh)).items()] == ["wood", "metal", "ceramic", "rubber"]


def _kb_size(key: str) -> tuple[float, float, float]:
    data = yaml.safe_load(KNOWLEDGE.read_text(encoding="utf-8"))
    return tuple(float(x) for x in data[key]["size"])  # type: ignore[return-value]


def _surface_z(mesh: trimesh.Trimesh, x: float, y: float) -> float:
    """Height of the highest surface over (x, y): the highest triangle whose plan
    projection holds the point, interpolated there."""
    t = np.asarray(mesh.triangles)
    a, b, c = t[:, 0], t[:, 1], t[:, 2]
    v0, v1 = b[:, :2] - a[:, :2], c[:, :2] - a[:, :2]
    v2 = np.array([x, y]) - a[:, :2]
    den = v0[:, 0] * v1[:, 1] - v1[:, 0] * v0[:, 1]
    ok = np.abs(den) > 1e-12
    den = np.where(ok, den, 1.0)
    u = (v2[:, 0] * v1[:, 1] - v1[:, 0] * v2[:, 1]) / den
    v = (v0[:, 0] * v2[:, 1] - v2[:, 0] * v0[:, 1]) / den
    inside = ok & (u >= -1e-9) & (v >= -1e-9) & (u + v <= 1 + 1e-9)
    z = a[:, 2] + u * (b[:, 2] - a[:, 2]) + v * (c[:, 2] - a[:, 2])
    return float(z[inside].max())


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("source", ["knowledge", "typical"])
def test_beds_hold_their_headboard_and_a_mattress_at_sitting_height(seed: int, source: str) -> None:
    size = _kb_size("bed") if source == "knowledge" else typical_size("bed")
    assert size[2] >= 0.9  # the box reaches the headboard
    w, d, h = size
    mesh = _build("bed", seed, ("", "victorian", "modern", "rustic")[seed], size)
    # the headboard (at -y) reaches the top of the box; the sleeping surface, seen from
    # above at the foot half, sits at a sitting height
    assert max(_surface_z(mesh, 0.0, -d / 2 + dy) for dy in (0.03, 0.075)) == pytest.approx(h, abs=0.02)
    top = _surface_z(mesh, 0.0, 0.25 * d)
    assert 0.45 <= top <= 0.65, top


@pytest.mark.parametrize("key,family", [("bunk bed", "bunk_bed"), ("crib", "crib")])
def test_other_beds_boxes_reach_their_rails(key: str, family: str) -> None:
    assert _kb_size(key)[2] >= 0.9 and typical_size(family)[2] >= 0.9
