"""anyhome.assets.registry: which family an object is built as, and when it only stands in."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from anyhome.assets.registry import GENERIC, assign_asset, family_for, is_stand_in
from anyhome.house import HouseObject


def _obj(name, category, size=(0.5, 0.5, 0.8)):
    return HouseObject(id=f"r-{name.replace(' ', '_')}-0", name=name, category=category, room="r",
                       position=(1.0, 1.0, 0.0), size=size, yaw=0.0)


@pytest.mark.parametrize("name,category", [
    ("sauna heater", "sauna_stove"), ("candelabra", "lamp"), ("old brass candelabra", "lamp"),
    ("suit of armour", "statue"), ("cash register", "counter"), ("loft bed", "bed"),
])
def test_listed_words_are_stand_ins_and_say_so_in_their_record(name, category):
    fam = family_for(category, name)
    assert is_stand_in(category, name, fam)
    rec = assign_asset(_obj(name, category), np.random.default_rng(0))
    assert rec["approximate"] is True


@pytest.mark.parametrize("name,category", [
    ("dining chair", "chair"), ("king bed", "bed"), ("bathtub", "bathtub"), ("table lamp", "lamp"),
    ("pew", "pew"), ("pottery wheel", "pottery_wheel"),
])
def test_objects_a_family_draws_are_not_stand_ins(name, category):
    assert not is_stand_in(category, name, family_for(category, name))
    assert "approximate" not in assign_asset(_obj(name, category), np.random.default_rng(0))


def test_the_generic_block_is_always_a_stand_in():
    assert is_stand_in("flux_capacitor", "flux capacitor", GENERIC)


def test_generate_counts_stand_ins_in_its_summary_and_eval(tmp_path):
    out = tmp_path / "h"
    run = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a parlour with a candelabra on the mantel and a suit of armour",
                          "--out", str(out), "--no-glb", "--no-svg", "--json"], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    n = json.loads(run.stdout)["stand_ins"]
    house = json.loads((out / "house.json").read_text())
    flagged = [o["name"] for o in house["objects"] if (o.get("asset") or {}).get("approximate")]
    assert n == len(flagged) >= 2 and any(f.startswith("suit of armo") for f in flagged)
    ev = subprocess.run([sys.executable, "-m", "anyhome", "eval", str(out), "--json"], capture_output=True, text=True, timeout=300)
    assert json.loads(ev.stdout)["metrics"]["n_stand_in_objects"] == n
