"""The family catalog, and coverage of the object knowledge base by families."""

from __future__ import annotations

import json

import pytest

from anyhome.assets import FAMILIES, family_for
from anyhome.assets.catalog import (
    describe,
    documented_fallbacks,
    family_names,
    knowledge_map,
    triangle_range,
)
from anyhome.assets.registry import GENERIC, _tables, synonyms
from anyhome.plan.knowledge import knowledge_base, load


@pytest.fixture(scope="module")
def records() -> list[dict]:
    return describe()


def test_family_names() -> None:
    assert family_names() == FAMILIES == sorted(FAMILIES)
    assert len(family_names()) >= 60


def test_describe_is_json_and_complete(records: list[dict]) -> None:
    again = json.loads(json.dumps(records))
    assert again == records
    assert [r["name"] for r in records] == FAMILIES
    for r in records:
        assert set(r) >= {"name", "typical_size_m", "triangles", "categories", "objects", "synonyms"}
        assert len(r["typical_size_m"]) == 3 and all(s > 0 for s in r["typical_size_m"])
        lo, hi = r["triangles"]
        assert 12 <= lo <= hi <= 20000, r["name"]


def test_triangle_range_is_measured() -> None:
    lo, hi = triangle_range("drum_kit")
    assert 0 < lo <= hi


def test_every_family_has_its_own_typical_size() -> None:
    sizes = _tables(knowledge_base()).sizes
    assert sorted(set(FAMILIES) - set(sizes)) == []


def test_synonyms_name_families() -> None:
    for word, fam in synonyms().items():
        assert fam in FAMILIES, f"synonym {word!r} -> unknown family {fam!r}"


def test_every_object_category_has_a_family_or_a_documented_fallback() -> None:
    fallbacks = set(documented_fallbacks())
    missing = []
    for key, proto in load("objects").items():
        category = proto.get("category", "")
        if family_for(category, key) == GENERIC and category not in fallbacks:
            missing.append(f"{key} ({category})")
    assert missing == []


def test_knowledge_map_sends_new_categories_to_new_families() -> None:
    known = knowledge_map()
    assert "fountain" in known["fountain"]["categories"]
    assert "pool table" in known["pool_table"]["objects"]
    assert "dog_crate" in known["kennel"]["categories"]
    generic = set(known[GENERIC]["categories"])
    assert generic <= set(documented_fallbacks())
    used = [name for name in FAMILIES if known[name]["objects"]]
    assert len(used) >= 80
