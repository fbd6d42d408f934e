"""Styles reach the assets: every style of styles.yaml names a known asset style class,
and different styles give the same families different looks."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome.assets import assign_asset
from anyhome.assets.registry import get, typical_size
from anyhome.assets.styles import DEFAULT_CLASS, LEG_SHAPES, asset_classes, class_name, style_class
from anyhome.house import HouseObject
from anyhome.plan.knowledge import load

STYLES = load("styles")["styles"]
FAMILIES = ("chair", "dining_table", "bed")
SEEDS = range(12)


@pytest.mark.parametrize("key", list(STYLES))
def test_every_style_names_a_known_asset_class(key: str) -> None:
    """No style falls to the default class silently: its entry names its class."""
    entry = STYLES[key]
    assert "asset_class" in entry, f"styles.yaml: {key} has no asset_class"
    assert entry["asset_class"] in asset_classes()
    assert class_name(key) == entry["asset_class"]
    assert class_name([key]) == entry["asset_class"]
    if entry["asset_class"] == DEFAULT_CLASS:
        return
    # the class has a look of its own: not the default's legs and woods
    cls, plain = style_class(key), style_class(DEFAULT_CLASS)
    assert (cls.legs, cls.woods) != (plain.legs, plain.woods)


def test_asset_classes_are_well_formed() -> None:
    for name, cls in asset_classes().items():
        assert cls.name == name and cls.legs and set(cls.legs) <= LEG_SHAPES and cls.woods and cls.fabrics


def _sampled(family: str, style: str) -> tuple[set[str], set[str], set[str]]:
    fam, size = get(family), typical_size(family)
    params = [fam.sample(np.random.default_rng(s), size, style) for s in SEEDS]
    legs = {p.legs for p in params}
    return {p.style for p in params}, legs, {p.primary for p in params}


@pytest.mark.parametrize("family", FAMILIES)
def test_gothic_victorian_japanese_differ(family: str) -> None:
    """The bar of issue 12's bug 1: the same families get different asset style classes
    (and so different legs or wood) in a gothic, a victorian and a japanese room."""
    got = {s: _sampled(family, s) for s in ("gothic", "victorian", "japanese")}
    classes = {s: g[0] for s, g in got.items()}
    assert classes == {"gothic": {"gothic"}, "victorian": {"victorian"}, "japanese": {"japanese"}}
    assert got["victorian"][1] == {"turned"} and "turned" not in got["gothic"][1] | got["japanese"][1]
    woods = {s: g[2] for s, g in got.items()}
    assert not woods["gothic"] & woods["victorian"] and not woods["gothic"] & woods["japanese"]
    assert not woods["victorian"] & woods["japanese"]


@pytest.mark.parametrize("style_words", ["gothic, pointed arches and dark carved wood",
                                          "victorian, ornate and layered"])
def test_prose_is_not_a_style(style_words: str) -> None:
    """Prose is not a key: it is the planner's job to give assets the keys."""
    assert class_name(style_words) == DEFAULT_CLASS


def _obj(category: str) -> HouseObject:
    size = typical_size(category)
    return HouseObject(id=f"r-{category}-1", room="r", name=category, category=category,
                       position=(0.0, 0.0, 0.0), size=size)


def test_assign_asset_reads_the_lead_style_key() -> None:
    rec = assign_asset(_obj("chair"), np.random.default_rng(0), ["gothic", "victorian"])
    assert rec["params"]["style"] == "gothic"
    rec = assign_asset(_obj("chair"), np.random.default_rng(0), ["no_such_style", "victorian"])
    assert rec["params"]["style"] == "victorian"
    assert assign_asset(_obj("chair"), np.random.default_rng(0), [])["params"]["style"] == DEFAULT_CLASS


@settings(max_examples=30, deadline=None)
@given(key=st.sampled_from(list(STYLES)), family=st.sampled_from(FAMILIES + ("sofa", "wardrobe", "bookshelf")),
       seed=st.integers(0, 2**16))
def test_sampled_colours_follow_the_class(key: str, family: str, seed: int) -> None:
    """Wood-coloured families draw their main colour from the class's woods."""
    p = get(family).sample(np.random.default_rng(seed), typical_size(family), key)
    cls = style_class(key)
    assert p.style == cls.name
    if family in ("dining_table", "wardrobe", "bookshelf", "bed"):
        assert p.primary in cls.woods
    if "legs" in dict(p.knobs) and len(cls.legs) == 1:
        assert p.legs == cls.legs[0]
