"""Semantic tags (anyhome.tags): data in objects.yaml, read by layout, refine and navigation.

The misfire tests below each failed on the substring lists the tags replace
(layout's FRONT_WORDS matched "board" in cupboard/sideboard/keyboard/ironing board;
refine's TABLE_WORDS matched "bar"/"bench" in barrel/bench press/toolbar/crowbar).
"""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome import geometry
from anyhome.house import HouseObject
from anyhome.layout.placement import front_item as _front_item
from anyhome.plan.knowledge import load
from anyhome.plan.parse import surface_of_word
from anyhome.plan.spec import ItemSpec
from anyhome.refine.refiner import _is_seat, _is_table
from anyhome.tags import TAGS, is_supporter, tags_for


def _obj(name: str, category: str, **kw) -> HouseObject:
    return HouseObject(id="r-x-0", room="r", name=name, category=category,
                       position=(1.0, 1.0, 0.0), size=(1.0, 0.5, 0.8), **kw)


def _item(name: str, category: str) -> ItemSpec:
    return ItemSpec(name=name, category=category, size_m=(1.0, 0.5, 0.8), rule="place_wall")


@pytest.mark.parametrize("name,category", [
    ("cupboard", "cabinet"), ("sideboard", "cabinet"), ("keyboard", "piano"),
    ("ironing board", "ironing_board"),
])
def test_boards_that_are_not_front_of_room(name, category):
    assert not _front_item(_item(name, category))


@pytest.mark.parametrize("name,category", [
    ("whiteboard", "whiteboard"), ("blackboard", "whiteboard"), ("lectern", "lectern"),
    ("altar", "altar"), ("tv", "tv"), ("projector screen", "projector_screen"),
])
def test_front_of_room_items_still_are(name, category):
    assert _front_item(_item(name, category))


@pytest.mark.parametrize("name,category", [
    ("barrel", "barrel"), ("bench press", "bench_press"), ("toolbar", "toolbar"), ("crowbar", "crowbar"),
])
def test_bar_and_bench_words_are_not_tables(name, category):
    o = _obj(name, category)
    assert not _is_table(o)
    assert not _is_seat(o)  # a bench press is gym equipment, not somewhere to sit at a table


def test_seats_and_tables_from_tags():
    assert _is_seat(_obj("dining chair", "chair"))
    assert _is_table(_obj("oak dining table", "dining_table"))
    assert _is_table(_obj("lab bench", "lab_bench"))
    assert not _is_table(_obj("church pew", "pew"))


def test_supporters_by_tag():
    assert is_supporter(tags_for("sideboard", "cabinet"))  # storage with a top
    assert is_supporter(tags_for("nightstand", "nightstand"))
    for name, cat in [("sofa", "sofa"), ("bed", "bed"), ("toilet", "toilet"), ("rug", "rug"),
                      ("crowbar", "crowbar")]:
        assert not is_supporter(tags_for(name, cat)), name


def test_every_prototype_has_tags_from_the_closed_set():
    protos = load("objects")
    assert len(protos) > 300
    for key, proto in protos.items():
        tags = proto.get("tags")
        assert tags, f"{key}: no tags"
        assert set(tags) <= TAGS, f"{key}: {set(tags) - TAGS}"
        assert len(set(tags)) == len(tags), key


def test_every_tag_is_used_by_some_prototype():
    used = {t for p in load("objects").values() for t in p["tags"]}
    assert used == TAGS


def test_lookup_by_synonym_head_and_category_and_unknown():
    assert tags_for("bookcase", "") == tags_for("bookshelf", "bookshelf")
    assert "table" in tags_for("oak dining table", "")  # a prototype phrase inside the name
    assert tags_for("thingamajig", "yoga_mat") == ("floor_layer",)  # by category
    assert tags_for("thingamajig", "whatsit") == ()  # unknown: explicitly no tags


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=30), st.text(max_size=15))
def test_lookup_never_fails_and_stays_in_the_set(name, category):
    assert set(tags_for(name, category)) <= TAGS


def test_rug_is_ignored_by_navigation_through_its_tag():
    rug = _obj("flokati", "shaggy_thing", tags=["floor_layer"])
    assert not geometry.blocks_navigation(rug.category, 0.05, "floor", rug.tags)
    assert geometry.blocks_navigation(rug.category, 0.05, "floor", [])
    # derived from the knowledge when a file has no tags
    assert _obj("persian rug", "rug").tags == ["floor_layer"]
    assert not geometry.blocks_navigation("rug", 0.05, "floor")


def test_house_object_tags_derived_on_load_and_kept_in_json():
    o = _obj("sideboard", "cabinet")
    assert o.tags == ["storage"]
    data = json.loads(o.model_dump_json())
    assert data["tags"] == ["storage"]
    data["tags"] = ["decor"]  # tags written in the file win
    assert HouseObject.model_validate(data).tags == ["decor"]
    with pytest.raises(ValueError):
        HouseObject.model_validate({**data, "tags": ["not_a_tag"]})


def test_item_spec_gets_tags_like_the_llm_planner_builds_it():
    assert _item("wingback chair", "armchair").tags == ["seat"]
    assert _item("glowing orb", "orb").tags == []


def test_room_surface_words_come_from_the_knowledge():
    assert surface_of_word("parquet") == "floor"
    assert surface_of_word("wallpaper") == "walls"
    assert surface_of_word("countertops") == "furniture"
    assert surface_of_word("sofa") is None
