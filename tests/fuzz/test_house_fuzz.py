"""Malformed house.json files: every one is refused at load in one line, or it loads and
eval, the SVG and the GLB handle it (a result, or one AnyHomeError). Nothing else.

The mutants come from two valid houses (a hand-built two-room house and a generated
studio apartment) with one to three fields corrupted (see house_mutants.py).
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from functools import lru_cache
from pathlib import Path

import pytest
from house_mutants import mutant, odd_geometry
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from anyhome.errors import AnyHomeError, HouseFormatError
from anyhome.evaluate import evaluate_house
from anyhome.export import write_glb, write_svg
from anyhome.house import House, HouseObject, load

SVG_ATTRIBUTES = {
    "xmlns", "width", "height", "viewBox", "font-family", "font-size", "font-weight", "x", "y",
    "fill", "fill-opacity", "stroke", "stroke-width", "stroke-linecap", "stroke-dasharray",
    "text-anchor", "dominant-baseline", "id", "class", "points", "x1", "y1", "x2", "y2", "d",
}


def two_rooms() -> House:
    from two_rooms import two_room_house

    return two_room_house([
        HouseObject(id="ct", room="living", name="coffee table", category="coffee_table",
                    position=(2.5, 2.2, 0), size=(1.1, 0.6, 0.42), group="lounge-0"),
        HouseObject(id="sofa1", room="living", name="grey sofa", category="sofa", position=(2.5, 3.5, 0),
                    size=(2.0, 0.9, 0.85), yaw=3.141592653589793, anchor="ct", group="lounge-0"),
        HouseObject(id="vase1", room="living", name="vase", category="vase", position=(2.5, 2.2, 0.42),
                    size=(0.2, 0.2, 0.4), support="ct"),
        HouseObject(id="art", room="living", name="painting", category="wall_art",
                    position=(0.02, 2.0, 1.3), size=(1.0, 0.04, 0.7), yaw=-1.5707963267948966,
                    support="wall"),
        HouseObject(id="bed1", room="bed", name="double bed", category="bed", position=(7.0, 1.05, 0),
                    size=(1.6, 2.1, 1.1), material="dark walnut"),
    ])


@lru_cache(maxsize=None)
def base(name: str) -> dict:
    """A valid house.json document (generated once per session)."""
    if name == "two_rooms":
        house = two_rooms()
    else:
        from anyhome.pipeline import generate

        house = generate("a studio apartment", seed=0)
    return json.loads(house.to_json())


def one_line(e: BaseException) -> None:
    msg = str(e)
    assert msg and "\n" not in msg and "\r" not in msg, repr(msg)
    assert "Traceback" not in msg


def check_loaded(house: House, out: Path) -> list[str]:
    """Run eval, the SVG and the GLB on a loaded house; return what happened."""
    seen = []
    again = House.from_json(house.to_json())  # saving never writes what load refuses
    assert again.to_json() == house.to_json()
    for step in ("eval", "svg", "glb"):
        try:
            if step == "eval":
                evaluate_house(house)
            elif step == "svg":
                root = ET.parse(write_svg(house, out / "floorplan.svg")).getroot()
                for el in root.iter():
                    assert set(el.attrib) <= SVG_ATTRIBUTES, el.attrib
            else:
                write_glb(house, out / "house.glb", texture_px=16)
            seen.append(f"{step}: ok")
        except AnyHomeError as e:
            one_line(e)
            seen.append(f"{step}: {type(e).__name__}")
    return seen


def run_mutant(text: str, out: Path) -> str:
    try:
        house = House.from_json(text)
    except HouseFormatError as e:
        one_line(e)
        assert str(e).startswith("house.json: "), str(e)
        event("refused at load")
        return "refused"
    for outcome in check_loaded(house, out):
        event(outcome)
    return "loaded"


FUZZ = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@FUZZ
@given(data=st.data())
def test_malformed_two_room_house(data) -> None:
    text, _ = data.draw(mutant(base("two_rooms")))
    with tempfile.TemporaryDirectory() as tmp:
        run_mutant(text, Path(tmp))


@FUZZ
@given(data=st.data())
def test_malformed_generated_house(data) -> None:
    text, _ = data.draw(mutant(base("studio")))
    with tempfile.TemporaryDirectory() as tmp:
        run_mutant(text, Path(tmp))


@settings(max_examples=300, deadline=None)
@given(data=st.data())
def test_load_of_malformed_house_is_a_house_or_one_line(data) -> None:
    """Load only (fast): many more mutants, five mutations at most."""
    text, _ = data.draw(mutant(base("studio"), max_mutations=5))
    try:
        House.from_json(text)
    except HouseFormatError as e:
        one_line(e)


@settings(max_examples=40, deadline=None)
@given(raw=st.binary(max_size=200) | st.text(max_size=200).map(lambda s: s.encode("utf-8", "surrogatepass")))
def test_arbitrary_bytes_load_or_refuse(raw, tmp_path_factory) -> None:
    path = tmp_path_factory.mktemp("bytes") / "house.json"
    path.write_bytes(raw)
    with pytest.raises(HouseFormatError) as e:
        load(path)
    one_line(e.value)


# ------------------------------------------------------------------ the real CLI
def _write(tmp: Path, name: str, doc: dict | bytes) -> Path:
    d = tmp / name
    d.mkdir()
    data = doc if isinstance(doc, bytes) else json.dumps(doc).encode("utf-8")
    (d / "house.json").write_bytes(data)
    return d


def _cli_cases() -> list[tuple[str, str, object]]:
    """(name, command, corrupt(doc) -> doc or bytes) for the CLI runs."""

    def nan_height(d):
        d["rooms"][0]["height"] = float("nan")
        return d

    def km_room(d):
        d["rooms"][0]["polygon"] = [[0, 0], [1000, 0], [1000, 1000], [0, 1000]]
        return d

    def quote_id(d):
        d["objects"][0]["id"] = 'x" onmouseover="alert(1)'
        return d

    def lost_anchor(d):
        d["objects"][1]["anchor"] = "nowhere"
        return d

    def lost_room(d):
        d["doors"][0]["rooms"] = ["living", "attic"]
        return d

    def not_utf8(d):
        return json.dumps(d).encode("utf-8").replace(b'"living room"', b'"living \xff room"')

    def deep(d):
        return b'{"format": "anyhome.house", "version": 1, "plan": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"

    def hostile_names(d):
        for o in d["objects"]:
            o["name"] = "\x1b]0;pwned\x07<b>\"bold\"</b>\u202e"
        return d

    return [("nan-height", "eval", nan_height), ("km-room", "eval", km_room),
            ("quote-id", "export", quote_id), ("lost-anchor", "render", lost_anchor),
            ("lost-room", "export", lost_room), ("not-utf8", "eval", not_utf8),
            ("deep", "export", deep), ("hostile-names", "export", hostile_names)]


@pytest.mark.parametrize("name, command, corrupt", _cli_cases(), ids=[c[0] for c in _cli_cases()])
def test_cli_on_malformed_house(tmp_path, name, command, corrupt) -> None:
    folder = _write(tmp_path, name, corrupt(json.loads(json.dumps(base("two_rooms")))))
    args = {"eval": ["eval", str(folder), "--strict"],
            "export": ["export", str(folder), "--format", "svg,glb"],
            "render": ["render", str(folder), "--size", "32", "--view-size", "16"]}[command]
    proc = subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True, text=True,
                          errors="replace", timeout=60)
    assert "Traceback" not in proc.stderr, proc.stderr
    if name == "hostile-names":  # names are free text: the house loads and exports cleanly
        assert proc.returncode == 0, proc.stderr
        root = ET.parse(folder / "floorplan.svg").getroot()
        assert all(set(el.attrib) <= SVG_ATTRIBUTES for el in root.iter())
        assert "\x1b" not in (folder / "floorplan.svg").read_text(encoding="utf-8")
        return
    assert proc.returncode == 2, (proc.returncode, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr
    assert "house.json" in lines[0]


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_odd_geometry_that_loads(data) -> None:
    """Numbers within the load limits and swapped references: most of these load, so
    eval, the SVG and the GLB see zero sills, 50 m ceilings, far-away objects, doors
    off every wall..."""
    text, _ = data.draw(odd_geometry(base("studio")))
    with tempfile.TemporaryDirectory() as tmp:
        run_mutant(text, Path(tmp))
