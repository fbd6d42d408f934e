"""End to end: the real CLI in a subprocess, on temporary folders."""

import json
import subprocess
import sys

import pytest
import trimesh

HAUNTED = "A one-bedroom, one-bathroom haunted house featuring dark wood and antique furnishings."


def anyhome(*args, check=True):
    proc = subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True,
                          text=True, timeout=120)
    if check and proc.returncode != 0:
        raise AssertionError(f"anyhome {args} failed ({proc.returncode}):\n{proc.stderr}")
    return proc


@pytest.fixture(scope="module")
def haunted(tmp_path_factory):
    out = tmp_path_factory.mktemp("e2e") / "haunted"
    proc = anyhome("generate", HAUNTED, "--seed", "0", "--out", str(out))
    return out, proc


def test_generate_writes_the_three_outputs(haunted):
    out, proc = haunted
    assert sorted(p.name for p in out.iterdir()) == ["floorplan.svg", "house.glb", "house.json"]
    data = json.loads((out / "house.json").read_text())
    assert data["format"] == "anyhome.house" and data["prompt"] == HAUNTED
    assert any("bed" == o["category"] for o in data["objects"])
    # progress per stage on stderr, summary on stdout
    for label in ("[1/5]", "[3/5]", "[5/5]"):
        assert label in proc.stderr
    assert "rooms" in proc.stdout and "Files:" in proc.stdout and "Time:" in proc.stdout


def test_glb_has_named_nodes(haunted):
    out, _ = haunted
    data = json.loads((out / "house.json").read_text())
    scene = trimesh.load(out / "house.glb")
    names = set(scene.graph.nodes)
    for o in data["objects"]:
        assert f"object:{o['id']}" in names
    for r in data["rooms"]:
        assert f"room:{r['id']}:floor" in names


def test_eval_strict_passes_and_reports_coverage(haunted, tmp_path):
    out, _ = haunted
    expect = tmp_path / "expect.jsonl"
    expect.write_text(json.dumps({"id": "h", "prompt": HAUNTED, "expect": {
        "rooms": [{"any": ["bedroom"], "count": 1}], "objects": [{"any": ["bed"]}]}}) + "\n")
    proc = anyhome("eval", str(out), "--strict", "--expect", str(expect), "--json")
    report = json.loads(proc.stdout)
    assert report["violations"] == []
    assert report["coverage"]["score"] == 1.0


def test_same_seed_gives_byte_identical_house(haunted, tmp_path):
    out, _ = haunted
    anyhome("generate", HAUNTED, "--seed", "0", "--out", str(tmp_path / "again"), "-q")
    assert (tmp_path / "again" / "house.json").read_bytes() == (out / "house.json").read_bytes()


def test_bad_input_is_one_line_and_overwrites_nothing(haunted):
    out, _ = haunted
    before = (out / "house.json").read_bytes()
    proc = anyhome("generate", "   ", "--out", str(out), check=False)
    assert proc.returncode == 2
    errors = [line for line in proc.stderr.splitlines() if line.startswith("error: ")]
    assert len(errors) == 1 and proc.stderr.rstrip().endswith(errors[0])
    assert "Traceback" not in proc.stderr
    assert (out / "house.json").read_bytes() == before


def test_refuses_to_write_into_a_foreign_folder(tmp_path):
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("keep me")
    proc = anyhome("generate", "A bedroom.", "--out", str(foreign), check=False)
    assert proc.returncode == 2 and "non-empty folder" in proc.stderr
    assert (foreign / "notes.txt").read_text() == "keep me"


def test_eval_refuses_other_formats(tmp_path):
    (tmp_path / "house.json").write_text(json.dumps({"format": "x"}))
    proc = anyhome("eval", str(tmp_path), check=False)
    assert proc.returncode == 2 and "not an AnyHome house" in proc.stderr


def test_export_rederives_files(haunted, tmp_path):
    out, _ = haunted
    proc = anyhome("export", str(out / "house.json"), "--out", str(tmp_path / "x"))
    assert (tmp_path / "x" / "house.glb").stat().st_size > 1000
    assert "floorplan.svg" in proc.stdout


def test_assets_lists_the_families_as_json():
    names = json.loads(anyhome("assets", "--json").stdout)
    assert isinstance(names, list) and len(names) >= 60 and all(isinstance(n, str) for n in names)
    assert {"bed", "sofa", "piano", "toilet"} <= set(names)
    assert names == sorted(names) and len(set(names)) == len(names)


def test_render_writes_birdseye_and_one_view_per_room(haunted, tmp_path):
    out, _ = haunted
    proc = anyhome("render", str(out), "--out", str(tmp_path), "--size", "96", "--view-size", "64")
    rooms = json.loads((out / "house.json").read_text())["rooms"]
    assert (tmp_path / "birdseye.png").stat().st_size > 0
    assert sorted(p.stem for p in (tmp_path / "views").glob("*.png")) == sorted(r["id"] for r in rooms)
    assert "birdseye.png" in proc.stdout


def test_render_of_a_missing_house_is_one_line(tmp_path):
    proc = anyhome("render", str(tmp_path / "nothing"), check=False)
    assert proc.returncode != 0 and proc.stderr.strip().count("\n") == 0 and "error:" in proc.stderr
