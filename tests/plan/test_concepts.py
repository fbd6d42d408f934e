"""Concept tables and nearest-concept matching."""

import pytest

from anyhome.plan import concepts
from anyhome.plan.concepts import KINDS, furnish_type, nearest, query_forms
from anyhome.plan.knowledge import load


@pytest.mark.parametrize("kind", KINDS)
def test_every_concept_has_phrases_and_embeddings(kind):
    idx = concepts.index(kind, "lexical")
    assert len(idx.keys) >= 10
    assert idx.matrix.shape[0] == len(idx.phrases) == len(idx.owner)
    assert set(idx.owner.tolist()) == set(range(len(idx.keys)))


def test_concepts_yaml_names_only_existing_keys():
    c = load("concepts")
    sets = load("furniture")["sets"]
    objects = load("objects")
    programs = load("programs")["programs"]
    assert set(c["rooms"]) <= set(sets)
    assert set(c["objects"]) <= set(objects)
    assert set(c["buildings"]) <= set(programs)


def test_generic_head_is_dropped_for_rooms_only():
    assert query_forms("séance room", "rooms") == ["séance"]
    assert query_forms("wine cellar", "rooms") == ["wine cellar"]
    assert query_forms("treasure chest", "objects") == ["treasure chest"]


@pytest.mark.parametrize("backend", ["hybrid", "minilm", "lexical"])
def test_easy_cases_map_right(backend):
    assert nearest("rooms", "pottery studio", backend).key == "art_studio"
    assert nearest("objects", "treasure chest", backend).key in ("box", "toy box")


@pytest.mark.parametrize("backend", ["hybrid", "minilm", "lexical", "static"])
@pytest.mark.parametrize("junk", ["qqqq", "zxcvbnm", "一个房间", "", "12345"])
def test_nonsense_and_other_scripts_match_nothing(backend, junk):
    for kind in KINDS:
        assert nearest(kind, junk, backend) is None


def test_leave_one_out_excludes_the_phrase_itself():
    idx = concepts.index("rooms", "lexical")
    assert idx.rank("man cave", k=1)[0].via == "man cave"
    assert idx.rank("man cave", k=1, exclude=frozenset({"man cave"}))[0].via != "man cave"


def test_furnish_type():
    assert furnish_type("bedroom") == "bedroom"
    assert furnish_type("wine_cellar") == "cellar"
    assert furnish_type("no_such_set") == "other"
