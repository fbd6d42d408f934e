import pytest
from pydantic import ValidationError

from anyhome.plan.knowledge import knowledge_base
from anyhome.plan.llm.checks import (
    check_appearance,
    check_furniture,
    check_ornaments,
    check_program,
)
from anyhome.plan.llm.prompts import examples
from anyhome.plan.llm.schemas import FurnitureReply, OrnamentsReply, ProgramReply

KB = knowledge_base()


def _program(**over) -> ProgramReply:
    return ProgramReply.model_validate({**examples()["program"], **over})


def test_the_example_program_is_sane() -> None:
    assert check_program(_program(), KB) == []


def test_program_errors() -> None:
    rooms = examples()["program"]["rooms"]
    huge = [dict(rooms[0], area_m2=900), *rooms[1:]]
    assert any("area_m2 900 is implausible" in e for e in check_program(_program(rooms=huge), KB))
    dup = [*rooms, dict(rooms[1])]
    assert any("unique" in e for e in check_program(_program(rooms=dup), KB))
    assert any("unknown room id 'garden'" in e for e in check_program(_program(connections=[["living_room", "garden"]]), KB))
    assert any("not a room id" in e for e in check_program(_program(entrance="porch"), KB))
    cut = [["living_room", "kitchen"]]  # bedroom and bathroom left unreachable
    errors = check_program(_program(connections=cut), KB)
    assert any("not reachable" in e and "bedroom" in e and "bathroom" in e for e in errors)
    assert any("itself" in e for e in check_program(_program(connections=[*cut, ["kitchen", "kitchen"]]), KB))


def _furniture(**anchor_over) -> FurnitureReply:
    data = examples()["furniture"]
    g0 = dict(data["groups"][0], anchor={**data["groups"][0]["anchor"], **anchor_over})
    return FurnitureReply.model_validate({"groups": [g0, *data["groups"][1:]]})


def test_furniture_rules() -> None:
    assert check_furniture(_furniture(), 14.0) == []
    with pytest.raises(ValidationError, match="anchor\n.*tag 'place_top'"):  # the schema allows anchors absolute rules only
        _furniture(rule="place_top")
    assert any("must be meters" in e for e in check_furniture(_furniture(size_m=[160, 205, 100]), 14.0))
    assert any("too big" in e for e in check_furniture(_furniture(size_m=[4, 4, 1]), 14.0))
    data = examples()["furniture"]
    g = dict(data["groups"][0], members=[dict(data["groups"][0]["members"][0], target="piano")])
    assert any("target 'piano'" in e for e in check_furniture(FurnitureReply.model_validate({"groups": [g]}), 14.0))
    crowd = dict(data["groups"][1], repeat=100)
    assert any("cannot fit" in e for e in check_furniture(FurnitureReply.model_validate({"groups": [crowd]}), 14.0))


def test_ornament_targets_and_sizes() -> None:
    reply = OrnamentsReply.model_validate(examples()["ornaments"])
    assert check_ornaments(reply, {"coffee table", "bookshelf", "sofa"}) == []
    errors = check_ornaments(reply, {"sofa"})
    assert any("'coffee table' is not furniture" in e for e in errors)
    big = OrnamentsReply.model_validate({"ornaments": [dict(examples()["ornaments"]["ornaments"][2], size_m=[5, 0.1, 3])]})
    assert any("must be meters" in e for e in check_ornaments(big, {"sofa"}))


def test_appearance_room_ids() -> None:
    assert check_appearance({"a", "b"}, ["a"]) == []
    assert check_appearance({"a"}, ["z"]) == ["rooms: unknown room id 'z'; use ids from: a"]
