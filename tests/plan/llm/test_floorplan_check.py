"""The LLM planner's floorplan check is passed in, not imported inside plan/llm."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import numpy as np
from fake_llm_server import PROGRAM, Answer, fake_llm  # noqa: F401

from anyhome.floorplan import floorplan_errors
from anyhome.plan.llm import LLMConfig, LLMPlanner
from anyhome.plan.spec import HouseSpec, RoomSpec

# a 2 m2 bathroom with five doors: the planner's sanity rules accept it, the floorplan
# solver cannot give it wall enough for its doors
CROWDED = {
    "building": "home",
    "rooms": [
        {"id": "bathroom", "name": "bathroom", "type": "bathroom", "area_m2": 2},
        *({"id": f"bedroom{i}", "name": "bedroom", "type": "bedroom", "area_m2": 12} for i in range(5)),
    ],
    "connections": [["bathroom", f"bedroom{i}"] for i in range(5)],
    "entrance": "bathroom",
}


def _planner(fake: Any, tmp_path: Path, check: Any) -> LLMPlanner:
    config = LLMConfig(base_url=fake.base_url, cache_dir=tmp_path / "cache", timeout_s=5.0)
    return LLMPlanner(config, floorplan_check=check)


def _repair_texts(fake: Any) -> list[str]:
    return [r["messages"][-1]["content"] for r in fake.chat_requests("program")[1:]]


def test_floorplan_errors_says_why_a_program_cannot_be_laid_out() -> None:
    crowded = HouseSpec(prompt="", rooms=[RoomSpec(**{k: r[k] for k in ("id", "name", "type", "area_m2")})
                                          for r in CROWDED["rooms"]],
                        connections=[tuple(c) for c in CROWDED["connections"]] + [("bathroom", "outside")])
    (why,) = floorplan_errors(crowded)
    assert "bathroom" in why and "too small for its" in why
    fine = crowded.model_copy(update={"rooms": [r.model_copy(update={"area_m2": 6.0}) if r.id == "bathroom" else r
                                                for r in crowded.rooms]})
    assert floorplan_errors(fine) == []


def test_the_passed_check_asks_for_a_repair(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.script["program"] = [Answer.chat(json.dumps(CROWDED)), Answer.chat(json.dumps(PROGRAM))]
    seen: list[HouseSpec] = []

    def check(spec: HouseSpec) -> list[str]:
        seen.append(spec)
        return floorplan_errors(spec)

    spec = _planner(fake_llm, tmp_path, check).plan("a house", np.random.default_rng(0))
    assert [r.id for r in seen[0].rooms] == [r["id"] for r in CROWDED["rooms"]]
    (repair,) = _repair_texts(fake_llm)
    assert "cannot be laid out as a floorplan" in repair and "too small for its" in repair
    assert [r.id for r in spec.rooms] == [r["id"] for r in PROGRAM["rooms"]]  # the repaired program


def test_without_a_check_the_program_is_taken_as_it_is(fake_llm, tmp_path: Path) -> None:  # noqa: F811
    fake_llm.script["program"] = Answer.chat(json.dumps(CROWDED))
    spec = _planner(fake_llm, tmp_path, None).plan("a house", np.random.default_rng(0))
    assert _repair_texts(fake_llm) == []
    assert [r.id for r in spec.rooms] == [r["id"] for r in CROWDED["rooms"]]


def test_the_planner_factory_passes_the_floorplan_check(tmp_path: Path) -> None:
    from anyhome.plan import get_planner

    assert get_planner("llm").floorplan_check is floorplan_errors


def test_plan_llm_does_not_import_the_floorplan_solver() -> None:
    import anyhome.plan.llm as pkg

    for path in Path(pkg.__file__).parent.glob("*.py"):
        imports = re.findall(r"^\s*(?:from|import) anyhome\.floorplan\b", path.read_text(encoding="utf-8"), re.M)
        assert imports == [], path.name
