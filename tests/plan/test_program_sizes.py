"""The room program's sizes (issue 13): norms by room type, building kinds, size words
and stated totals decide which rooms a house has and their target areas."""

from __future__ import annotations

import copy
import json
import statistics
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from anyhome.errors import KnowledgeError
from anyhome.floorplan.levels import solve_levels
from anyhome.plan import get_planner
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.knowledge import KNOWLEDGE_FILES, load
from anyhome.plan.offline import built_area_m2
from anyhome.plan.parse import parse
from anyhome.stages import stage_rngs

ROOT = Path(__file__).resolve().parents[2]
PLANNER = get_planner("offline")
RAW = {name: load(name) for name in KNOWLEDGE_FILES}
TYPES = RAW["rooms"]["types"]


def plan(text: str, seed: int = 0):
    return PLANNER.plan(text, stage_rngs(seed)["plan"])


def total(spec) -> float:
    return sum(r.area_m2 for r in spec.rooms)


def count(spec, room_type: str) -> int:
    return sum(r.type == room_type for r in spec.rooms)


# ------------------------------------------------------------------ the norms
def test_every_type_range_is_compatible_with_its_min_width():
    for t, info in TYPES.items():
        least = info["min_area_m2"]
        assert least >= info["min_width_m"] ** 2 - 1e-9, t  # at least a square of its width
        assert info["area"][0] >= least, t


def test_bedroom_norms_are_the_nationally_described_space_standard():
    # NDSS 2015: a single bedroom is at least 7.5 m2, a double 11.5 m2 and 2.55 m wide
    assert TYPES["bedroom"]["min_area_m2"] == 7.5
    assert TYPES["bedroom"]["min_width_m"] == 2.55
    assert TYPES["bedroom"]["area"][0] >= 7.5


def _kb(fn) -> KnowledgeBase:
    raw = copy.deepcopy(RAW)
    fn(raw)
    return KnowledgeBase(raw, lambda name, loc: f"{name}.yaml")


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda r: r["rooms"]["types"]["bedroom"].update(min_area_m2=5.0), "rooms.yaml: types.bedroom: min_area_m2:"),
        (lambda r: r["rooms"]["types"]["bedroom"].update(area=[6, 12]), "rooms.yaml: types.bedroom: area: starts below"),
        (lambda r: r["programs"]["sizes"]["kinds"]["cabin"]["areas"].update(bedroom=[4, 9]),
         "programs.yaml: sizes.kinds: cabin.areas.bedroom"),
        (lambda r: r["programs"]["sizes"]["kinds"]["cabin"]["areas"].update(parlour=[10, 12]), "unknown room type 'parlour'"),
        (lambda r: r["programs"]["buildings"][1].update(kind="shack"), "programs.yaml: buildings[1]: kind: unknown building kind (sizes.kinds) 'shack'"),
        (lambda r: r["programs"]["sizes"]["words"]["tiny"].update(total_m2=[42, 22]), "a range [lo, hi] needs lo <= hi"),
        (lambda r: r["programs"]["sizes"]["words"]["tiny"].update(totl_m2=[22, 42]), "unknown field (misspelt?)"),
    ],
)  # fmt: skip
def test_a_bad_size_entry_names_its_file_and_key(change, message):
    with pytest.raises(KnowledgeError, match=None) as e:
        _kb(change)
    assert message in str(e.value), str(e.value)
    assert "\n" not in str(e.value)


# ------------------------------------------------------------------ size words
@pytest.mark.parametrize("text", ["a tiny off-grid cabin", "a tiny cabin", "a tiny cottage", "a tiny house"])
def test_a_tiny_home_is_at_most_45_m2(text):
    for seed in range(5):
        spec = plan(text, seed)
        assert total(spec) <= 45, (seed, [(r.name, r.area_m2) for r in spec.rooms])
        assert len(spec.rooms) <= 3  # one main room, a bathroom (and a sleeping nook)
        assert count(spec, "bathroom") == 1


def test_a_tiny_cabin_stays_a_cabin_home():
    spec = plan("a tiny cabin")  # planned as the compact program, still a home in the cabin's style
    assert spec.building == "home"
    assert "cottage" in spec.styles


def test_a_grand_mansion_with_six_bedrooms_is_at_least_300_m2():
    for seed in range(3):
        spec = plan("a grand mansion with a ballroom and six bedrooms", seed)
        assert total(spec) >= 300, seed
        assert count(spec, "bedroom") == 6
        assert count(spec, "bathroom") >= 2
        assert any("ballroom" in r.name for r in spec.rooms)


def test_a_mansion_has_more_bedrooms_and_bathrooms_and_at_most_one_entry():
    specs = [plan("a mansion", s) for s in range(3)]
    for spec in specs:
        assert total(spec) >= 300
        assert count(spec, "bedroom") >= 3
        assert count(spec, "bathroom") >= 3
        assert count(spec, "entry") <= 1
        names = [r.name for r in spec.rooms]
        assert len(set(names)) == len(names) and not any(n.endswith(" 2 2") for n in names), names
    assert any(count(spec, "entry") == 1 for spec in specs)  # an entrance hall where the rooms leave space


def test_size_words_order_the_totals():
    med = {}
    for word in ["tiny", "small", "", "spacious", "grand"]:
        med[word] = statistics.median(total(plan(f"a {word} house".replace("  ", " "), s)) for s in range(3))
    assert med["tiny"] <= 45 < med["small"] <= 75 < med[""] < med["spacious"] < med["grand"]
    assert med["grand"] >= 300


def test_cosy_and_cozy_are_one_word():
    assert parse("a cosy cottage").size_words == ["cosy"]
    assert parse("a cozy cottage").size_words == ["cozy"]
    assert all(total(plan("a cosy cottage", s)) <= 85 * 1.05 for s in range(3))


def test_a_size_word_for_a_room_does_not_resize_the_home():
    p = parse("a house with a small kitchen")
    assert p.size_words == []
    assert p.rooms[0].size < 1


@pytest.mark.parametrize(("text", "words"), [
    ("A small 65 m2 house with two bedrooms", ["small"]),  # the number ends the opening phrase
    ("A grand 1920s Art Deco house", ["grand"]),
    ("A grand, rambling country house with a ballroom", ["grand"]),
    ("A grand old Victorian brick house with a ballroom", ["grand"]),  # far from the building word
    ("A house like a mansion", ["mansion"]),
    ("A large kitchen and a small house", ["small"]),
])
def test_a_size_word_in_the_head_sizes_the_home_and_is_never_the_building(text, words):
    p = parse(text)
    assert p.size_words == words
    assert RAW["programs"]["buildings"][p.building]["program"] == "home"  # not a chapel or a flat


def test_the_strongest_of_several_size_words_sizes_the_home():
    from anyhome.plan.program import choose_program, sizing

    kb = _kb(lambda raw: None)
    for text, least in [("A large mansion", 300), ("A large, grand house", 300), ("a small, tiny cabin", 0)]:
        p = parse(text)
        sz = sizing(kb, p, choose_program(kb, p)[0])
        assert sz.source == "word" and sz.band is not None and sz.band[0] >= least, (text, sz.band)
    p = parse("a small, tiny cabin")
    assert sizing(kb, p, choose_program(kb, p)[0]).band[1] <= 45


# ------------------------------------------------------------------ stated totals
@pytest.mark.parametrize(
    ("text", "m2"),
    [
        ("a 50 m2 apartment", 50.0),
        ("a flat of about 30 square meters", 30.0),
        ("a 120 sqm house", 120.0),
        ("a 500 sq ft apartment", 500 * 0.09290304),
        ("a 50 m² flat", 50.0),
        ("a 95 square metre flat with two bedrooms", 95.0),
        ("a 1,200 sq. ft. bungalow", 1200 * 0.09290304),
    ],
)
def test_a_stated_total_is_honoured_within_ten_percent(text, m2):
    """The built house (the floorplan stage as the pipeline runs it), not only the plan,
    holds the stated total: the solver grows rooms and may add a hallway."""
    assert parse(text).total_m2 == pytest.approx(m2)
    for seed in range(3):
        spec = plan(text, seed)
        area = built_area_m2(spec, stage_rngs(seed)["floorplan"], solve_levels)
        assert area is not None and abs(area - m2) <= 0.10 * m2, (seed, area, total(spec))
        assert not any("stated" in w for w in spec.warnings)


def test_an_area_per_floor_and_an_area_of_land():
    assert parse("a two-storey house with 60 m2 per floor").total_m2 == pytest.approx(120.0)
    assert parse("a three storey townhouse, 50 square metres on each floor").total_m2 == pytest.approx(150.0)
    assert parse("a house on a 500 m2 plot with three bedrooms").total_m2 is None
    assert parse("a 120 m2 house on a 600 m2 plot").total_m2 == pytest.approx(120.0)
    assert parse("a 90 m2 two bedroom flat").total_m2 == pytest.approx(90.0)
    assert parse("a studio of 27,5 m2").total_m2 == pytest.approx(27.5)  # a decimal comma
    assert parse("a 1,200 sq ft house").total_m2 == pytest.approx(1200 * 0.09290304)  # thousands


def test_the_number_of_an_area_counts_no_rooms():
    p = parse("a 120 sqm house with a kitchen")
    assert p.total_rooms is None
    assert all(m.count in (None, 1) for m in p.rooms)
    assert parse("a 12 m2 bedroom and a kitchen").total_m2 is None  # a room's area, not the home's


def test_a_stated_total_too_small_for_the_rooms_warns_and_keeps_them():
    spec = plan("a 40 m2 house with four bedrooms")
    assert count(spec, "bedroom") == 4
    assert any("stated 40 m2 cannot hold the rooms asked for" in w for w in spec.warnings), spec.warnings
    for r in spec.rooms:  # squeezed, but never below the norms
        info = TYPES[r.type]
        assert r.area_m2 >= min(info["min_area_m2"], info["area"][0]) - 0.01, r


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(m2=st.integers(min_value=35, max_value=260), word=st.sampled_from(["house", "apartment", "cottage", "bungalow", "flat"]))
def test_any_stated_home_total_is_met_or_explained(m2, word):
    spec = plan(f"a {m2} m2 {word}")
    area = built_area_m2(spec, stage_rngs(0)["floorplan"], solve_levels)
    assert area is not None
    err = abs(area - m2) / m2  # the built house, within issue 13's 15 %
    assert err <= 0.15 or any(f"stated {m2} m2" in w for w in spec.warnings), (area, total(spec), spec.warnings)


# ------------------------------------------------------------------ kinds and diversity
def _shared(a, b) -> float:
    """Share of rooms of ``a`` whose type and area (within 5 %) a room of ``b`` repeats."""
    pool = [(r.type, r.area_m2) for r in b.rooms]
    same = 0
    for r in a.rooms:
        hit = next((x for x in pool if x[0] == r.type and abs(x[1] - r.area_m2) <= 0.05 * r.area_m2), None)
        if hit is not None:
            pool.remove(hit)
            same += 1
    return same / max(len(a.rooms), 1)


def test_building_kinds_give_different_room_sizes():
    kinds = ["a bungalow", "a cabin", "a chalet", "a riad", "a mansion", "a villa", "a cottage", "a flat"]
    specs = {k: plan(k) for k in kinds}
    for i, a in enumerate(kinds):
        for b in kinds[i + 1 :]:
            assert _shared(specs[a], specs[b]) < 0.5, (a, b)


def test_a_mansions_bedrooms_are_larger_than_a_cabins():
    def bedrooms(text):
        return statistics.median(r.area_m2 for s in range(3) for r in plan(text, s).rooms if r.type == "bedroom")

    assert bedrooms("a mansion") > bedrooms("a bungalow") > bedrooms("a cabin")


def test_seeds_give_different_programs():
    a, b = plan("a riad", 0), plan("a riad", 1)
    assert [r.area_m2 for r in a.rooms] != [r.area_m2 for r in b.rooms]


# ------------------------------------------------------------------ circulation
def _public_prompts() -> list[str]:
    with open(ROOT / "tests/data/public_prompts.jsonl", encoding="utf-8") as f:
        return [json.loads(line)["prompt"] for line in f]


def test_circulation_share_of_home_programs_is_small():
    circ = {t for t, v in TYPES.items() if v.get("circulation")}
    shares = []
    for text in _public_prompts():
        spec = plan(text)
        if spec.building in ("home", "apartment"):
            shares.append(sum(r.area_m2 for r in spec.rooms if r.type in circ) / total(spec))
    assert len(shares) >= 8
    assert statistics.median(shares) <= 0.12
    assert max(shares) <= 0.13  # a named mudroom may grow past its share for its furniture


def test_the_cli_honours_a_stated_total_and_warns_when_it_cannot(tmp_path):
    for text, out in (("a 60 m2 flat", "flat"), ("a 40 m2 house with four bedrooms", "crowded")):
        run = subprocess.run(
            [sys.executable, "-m", "anyhome", "generate", text, "--seed", "1", "--out", str(tmp_path / out), "--no-glb", "--no-svg"],
            capture_output=True, text=True, timeout=60,
        )  # fmt: skip
        assert run.returncode == 0, run.stderr
        house = json.loads((tmp_path / out / "house.json").read_text())
        planned = sum(r["area_m2"] for r in house["plan"]["rooms"])
        if out == "flat":
            assert abs(planned - 60) <= 6
            assert not any("stated" in w for w in house["warnings"])
        else:
            assert any("the stated 40 m2 cannot hold" in w for w in house["warnings"])
            assert "the stated 40 m2 cannot hold" in run.stdout + run.stderr


def test_size_word_factors_come_from_the_knowledge_file():
    assert parse("a house with a tiny kitchen").rooms[0].size == pytest.approx(RAW["programs"]["sizes"]["words"]["tiny"]["factor"])

    def halve(raw):
        raw["programs"]["sizes"]["words"]["tiny"]["factor"] = 0.5

    assert parse("a house with a tiny kitchen", _kb(halve)).rooms[0].size == pytest.approx(0.5)


def test_a_room_keeps_the_area_the_text_states_for_it():
    spec = plan("a 60 m2 flat with a 30 m2 living room")
    living = next(r for r in spec.rooms if r.type == "living_room")
    assert living.area_m2 == pytest.approx(30.0)  # the flat's total is met by the other rooms
    assert abs(total(spec) - 60) <= 6
    assert plan("a 12 m2 bedroom").rooms[0].area_m2 == pytest.approx(12.0)


def test_a_stated_room_too_small_for_its_furniture_says_so():
    spec = plan("a house with a 5 m2 bedroom")
    small = [r for r in spec.rooms if r.type == "bedroom" and r.area_m2 < 10]
    assert small and any("instead of the 5 m2 asked for" in w for w in spec.warnings), spec.warnings


def test_a_grand_villa_is_sized_by_the_word_not_the_villa():
    # a villa's range ends where "grand" begins: the two met at one figure and the band's
    # margins crossed (282-318 m2), so the house was scaled to under 300 m2
    spec = plan("a grand villa with a drawing room, a dining room, a library, five bedrooms and two bathrooms", 1)
    assert total(spec) >= 300


def test_an_en_suite_opens_off_the_master_bedroom():
    for text in ("a bungalow with three bedrooms, an en-suite and a family bathroom",
                 "a family house on two floors: living room and kitchen downstairs; upstairs three bedrooms, one "
                 "with an en suite, and a family bathroom"):
        spec = plan(text)
        pairs = {frozenset((c[0], c[1])) if isinstance(c, tuple) else frozenset((c.a, c.b)) for c in spec.connections}
        suite = next(r.id for r in spec.rooms if "en-suite" in r.name)
        assert any(suite in p and any(x.startswith("master_bedroom") for x in p) for p in pairs), pairs
