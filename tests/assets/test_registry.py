"""anyhome.assets.registry: which family an object is built as, and when it only stands in."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from anyhome.assets.registry import GENERIC, assign_asset, family_for, is_stand_in
from anyhome.house import HouseObject
from anyhome.plan.kb import FILE_MODELS, KnowledgeBase
from anyhome.plan.knowledge import knowledge_base


def _obj(name, category, size=(0.5, 0.5, 0.8)):
    return HouseObject(id=f"r-{name.replace(' ', '_')}-0", name=name, category=category, room="r",
                       position=(1.0, 1.0, 0.0), size=size, yaw=0.0)


def _listing(*words):
    """The knowledge base in force with assets.yaml ``stand_ins`` set to ``words``."""
    kb = knowledge_base()
    raw = {name: kb.raw(name) for name in FILE_MODELS}
    raw["assets"] = {**raw["assets"], "stand_ins": list(words)}
    return KnowledgeBase(raw, kb.source)


@pytest.mark.parametrize("name,category", [
    ("cello", "cello"), ("old cello", "cello"), ("motorcycle", "motorcycle"), ("vintage motorcycle", ""),
])
def test_listed_words_are_stand_ins_and_say_so_in_their_record(name, category):
    kb = _listing("cello", "motorcycle")  # a cello drawn as a guitar, a motorcycle as a bicycle
    fam = family_for(category, name, kb)
    assert fam != GENERIC and is_stand_in(category, name, fam, kb)
    rec = assign_asset(_obj(name, category), np.random.default_rng(0), kb=kb)
    assert rec["approximate"] is True
    assert not is_stand_in(category, name, fam, _listing())  # a knowledge base that lists neither
    assert is_stand_in(category, name, fam)  # the shipped one lists both: their families draw something else


@pytest.mark.parametrize("name,category", [
    ("dining chair", "chair"), ("king bed", "bed"), ("bathtub", "bathtub"), ("table lamp", "lamp"),
    ("pew", "pew"), ("pottery wheel", "pottery_wheel"), ("sauna heater", "sauna_stove"),
    ("old brass candelabra", "candelabra"), ("suit of armour", "suit_of_armour"), ("loft bed", "loft_bed"),
])
def test_objects_a_family_draws_are_not_stand_ins(name, category):
    assert not is_stand_in(category, name, family_for(category, name))
    assert "approximate" not in assign_asset(_obj(name, category), np.random.default_rng(0))


def test_the_generic_block_is_always_a_stand_in():
    assert is_stand_in("flux_capacitor", "flux capacitor", GENERIC)


def test_generate_counts_stand_ins_in_its_summary_and_eval(tmp_path):
    out = tmp_path / "h"
    run = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a parlour with a candelabra and a suit of armour and a zorbulator",
                          "--out", str(out), "--no-glb", "--no-svg", "--json"], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    n = json.loads(run.stdout)["stand_ins"]
    house = json.loads((out / "house.json").read_text())
    flagged = [o["name"] for o in house["objects"] if (o.get("asset") or {}).get("approximate")]
    assert n == len(flagged) >= 1 and "zorbulator" in flagged  # no family: the generic block, flagged
    assert not any(f.startswith(("suit of armo", "candelabra")) for f in flagged)  # drawn by their own families
    ev = subprocess.run([sys.executable, "-m", "anyhome", "eval", str(out), "--json"], capture_output=True, text=True, timeout=300)
    assert json.loads(ev.stdout)["metrics"]["n_stand_in_objects"] == n
