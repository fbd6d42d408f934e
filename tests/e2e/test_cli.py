"""End to end: the real CLI in a subprocess, on temporary folders."""

import json
import os
import subprocess
import sys

import pytest
import trimesh

HAUNTED = "A one-bedroom, one-bathroom haunted house featuring dark wood and antique furnishings."


def anyhome(*args, check=True, **kwargs):
    proc = subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True,
                          text=True, timeout=120, **kwargs)
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
    assert sorted(p.name for p in out.iterdir()) == [".anyhome-files.json", "floorplan.svg", "house.glb", "house.json"]
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


# ------------------------------------------------------------ output folders
def one_error_line(proc, *, before_work=False):
    """Exit 2, exactly one ``error:`` line, on its own line and last, no traceback; with
    ``before_work``, not a single stage started (the check cost no generation)."""
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.splitlines()
    errors = [line for line in lines if "error:" in line]
    assert len(errors) == 1 and errors[0].startswith("error: ") and lines[-1] == errors[0], proc.stderr
    assert "Traceback" not in proc.stderr
    if before_work:
        assert "[1/5]" not in proc.stderr
    return errors[0]


def tree(folder):
    return {str(p.relative_to(folder)): (p.read_bytes() if p.is_file() else None)
            for p in sorted(folder.rglob("*"))}


@pytest.fixture
def house_copy(haunted, tmp_path):
    """A copy of the haunted house folder, written by AnyHome (manifest included)."""
    import shutil

    out, _ = haunted
    dest = tmp_path / "house"
    shutil.copytree(out, dest)
    return dest


@pytest.fixture(scope="module")
def egl(gl_available):
    """Renders need moderngl and EGL (tests/conftest.py: gl_available)."""


def _mount_tmpfs(path, options):
    """Mount a small tmpfs (root only); False where that is not possible."""
    import os

    path.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0:
        return False
    return subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(path)],
                          capture_output=True).returncode == 0


@pytest.fixture
def tmpfs(tmp_path):
    """A function mounting a tmpfs at a path with options; unmounted after the test."""
    mounted = []

    def mount(path, options):
        if not _mount_tmpfs(path, options):
            pytest.skip("mounting a tmpfs needs root")
        mounted.append(path)
        return path

    yield mount
    for path in reversed(mounted):
        subprocess.run(["umount", "-l", str(path)], capture_output=True)


def _fsize_limit(n_bytes):
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (n_bytes, n_bytes))

    return limit


def test_outputs_carry_a_manifest_of_what_was_written(haunted):
    out, _ = haunted
    listed = json.loads((out / ".anyhome-files.json").read_text())["files"]
    assert listed == ["floorplan.svg", "house.glb", "house.json"]


@pytest.mark.parametrize("extra", ["notes.txt", "photos/cat.jpg"])
def test_files_next_to_a_house_are_never_deleted(house_copy, extra):
    (house_copy / extra).parent.mkdir(exist_ok=True)
    (house_copy / extra).write_text("keep me")
    before = tree(house_copy)
    proc = anyhome("generate", "A bedroom.", "--out", str(house_copy), check=False)
    line = one_error_line(proc, before_work=True)
    assert extra.split("/")[0] in line and "did not write" in line
    assert tree(house_copy) == before


def test_a_users_own_house_json_is_not_replaced(tmp_path):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "house.json").write_text('{"my": "house"}')
    proc = anyhome("generate", "A bedroom.", "--out", str(mine), check=False)
    assert "house.json" in one_error_line(proc, before_work=True)
    assert (mine / "house.json").read_text() == '{"my": "house"}'


@pytest.mark.parametrize("bad", ["", ".", "..", "/", "afile.txt/sub", "afile.txt", "d" * 256, "loop"])
def test_bad_out_is_one_line_before_any_work(tmp_path, bad):
    (tmp_path / "afile.txt").write_text("x")
    (tmp_path / "loop").symlink_to("loop2")
    (tmp_path / "loop2").symlink_to("loop")
    proc = anyhome("generate", "A bedroom.", "--out", bad, check=False, cwd=tmp_path)
    one_error_line(proc, before_work=True)
    assert (tmp_path / "afile.txt").read_text() == "x"


def test_read_only_parent_is_one_line_before_any_work(tmp_path, tmpfs):
    ro = tmpfs(tmp_path / "ro", "size=64k,ro")
    proc = anyhome("generate", "A bedroom.", "--out", str(ro / "house"), check=False)
    assert "read-only" in one_error_line(proc, before_work=True)
    for cmd in (["export", str(tmp_path / "nothing"), "--out", str(ro)],
                ["render", str(tmp_path / "nothing"), "--out", str(ro / "r")]):
        assert "read-only" in one_error_line(anyhome(*cmd, check=False))


def test_a_symlinked_out_updates_the_target_and_stays_a_link(house_copy, tmp_path):
    link = tmp_path / "link"
    link.symlink_to(house_copy.name)
    anyhome("generate", "A bedroom.", "--out", str(link), "--no-glb", "-q")
    assert link.is_symlink()
    assert json.loads((house_copy / "house.json").read_text())["prompt"] == "A bedroom."
    assert not (house_copy / "house.glb").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["house", "link"]


def test_full_disk_leaves_the_old_house(tmp_path, tmpfs):
    """A real full disk (a 200 KB tmpfs): the GLB does not fit."""
    disk = tmpfs(tmp_path / "disk", "size=200k")
    anyhome("generate", "A bedroom.", "--out", str(disk / "h"), "--no-glb", "-q")
    before = tree(disk / "h")
    proc = anyhome("generate", "A bedroom.", "--out", str(disk / "h"), check=False)
    line = one_error_line(proc)
    assert "no space left" in line and str(disk / "h" / "house.glb") in line
    assert tree(disk / "h") == before and sorted(p.name for p in disk.iterdir()) == ["h"]


def test_full_disk_while_writing_house_json(tmp_path, tmpfs):
    disk = tmpfs(tmp_path / "disk", "size=64k")
    anyhome("generate", "A bedroom.", "--out", str(disk / "h"), "--no-glb", "--no-svg", "-q")
    before = tree(disk / "h")
    proc = anyhome("generate", "A house with three bedrooms, two bathrooms, a kitchen, a study and a garage.",
                   "--out", str(disk / "h"), "--no-glb", "--no-svg", check=False)
    assert "house.json: no space left" in one_error_line(proc)
    assert tree(disk / "h") == before and sorted(p.name for p in disk.iterdir()) == ["h"]


def test_file_size_limit_error_starts_its_own_line(house_copy):
    """A write that fails (RLIMIT_FSIZE: 100 KB, so the GLB cannot be written) ends the
    open progress line and prints the error on a line of its own; the old house stays."""
    before = tree(house_copy)
    proc = anyhome("generate", "A bedroom.", "--out", str(house_copy), check=False,
                   preexec_fn=_fsize_limit(100_000))
    one_error_line(proc)
    assert "[out] writing files ... failed" in proc.stderr
    assert tree(house_copy) == before
    assert sorted(p.name for p in house_copy.parent.iterdir()) == ["house"]


def test_modes_follow_the_umask_and_a_folder_keeps_its_mode(house_copy):
    import stat

    house_copy.chmod(0o750)
    anyhome("generate", "A bedroom.", "--out", str(house_copy), "--no-glb", "-q",
            preexec_fn=lambda: os.umask(0o022))
    assert stat.S_IMODE(house_copy.stat().st_mode) == 0o750
    assert stat.S_IMODE((house_copy / "house.json").stat().st_mode) == 0o644
    new = house_copy.parent / "new"
    anyhome("generate", "A bedroom.", "--out", str(new / "h"), "--no-glb", "-q",
            preexec_fn=lambda: os.umask(0o027))
    assert stat.S_IMODE((new / "h").stat().st_mode) == 0o750
    assert stat.S_IMODE((new / "h" / "floorplan.svg").stat().st_mode) == 0o640


def test_invalid_utf8_text_is_one_line(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "anyhome", "generate", b"a \xff bedroom",
                           "--out", str(tmp_path / "h")], capture_output=True, timeout=120)
    assert proc.returncode == 2
    err = proc.stderr.decode("utf-8")
    assert err.startswith("error: ") and err.count("\n") == 1 and "UTF-8" in err
    assert not (tmp_path / "h").exists()


@pytest.mark.parametrize("flags", [["--size", "8192"], ["--size", "0"], ["--view-size", "-3"],
                                   ["--view-size", "5000"]])
def test_render_sizes_are_checked_before_any_work(house_copy, flags):
    before = tree(house_copy)
    one_error_line(anyhome("render", str(house_copy), *flags, check=False))
    one_error_line(anyhome("generate", "A bedroom.", "--out", str(house_copy), "--render", *flags,
                           check=False), before_work=True)
    assert tree(house_copy) == before


def test_export_refuses_a_file_and_keeps_a_foreign_folder(haunted, tmp_path):
    out, _ = haunted
    (tmp_path / "afile.txt").write_text("x")
    one_error_line(anyhome("export", str(out), "--out", str(tmp_path / "afile.txt"), check=False))
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "house.glb").write_text("my own model")
    (mine / "notes.txt").write_text("x")
    assert "house.glb" in one_error_line(anyhome("export", str(out), "--out", str(mine), check=False))
    assert (mine / "house.glb").read_text() == "my own model"
    anyhome("export", str(out), "--format", "svg", "--out", str(mine))  # a new file is fine
    assert (mine / "floorplan.svg").exists() and not (mine / ".anyhome-files.json").exists()


def test_export_into_a_house_folder_keeps_it_ours(tmp_path):
    h = tmp_path / "h"
    anyhome("generate", "A bedroom.", "--out", str(h), "--no-glb", "-q")
    anyhome("export", str(h), "--format", "glb")
    assert "house.glb" in json.loads((h / ".anyhome-files.json").read_text())["files"]
    anyhome("generate", "A bedroom.", "--out", str(h), "--no-glb", "-q")  # still replaceable
    assert not (h / "house.glb").exists()


def test_render_failure_leaves_the_old_house(house_copy, egl):
    """No EGL driver (Mesa told to load one that does not exist): generate --render fails
    after generating, and the old house is still whole."""
    import os

    before = tree(house_copy)
    env = {**os.environ, "MESA_LOADER_DRIVER_OVERRIDE": "nonexistent", "LIBGL_DRIVERS_PATH": "/nonexistent"}
    proc = anyhome("generate", "A bedroom.", "--out", str(house_copy), "--render", "--size", "64",
                   "--view-size", "32", check=False, env=env)
    if proc.returncode == 0:
        pytest.skip("this machine's EGL does not come from Mesa")
    one_error_line(proc)
    assert tree(house_copy) == before
    assert sorted(p.name for p in house_copy.parent.iterdir()) == ["house"]


def test_render_write_failure_leaves_the_old_house(house_copy, egl):
    """The bird's-eye PNG cannot be written (RLIMIT_FSIZE 60 KB, the house files fit)."""
    before = tree(house_copy)
    proc = anyhome("generate", "A bedroom.", "--out", str(house_copy), "--render", "--no-glb",
                   "--size", "1024", "--no-views", check=False, preexec_fn=_fsize_limit(60_000))
    assert "birdseye.png" in one_error_line(proc)
    assert tree(house_copy) == before


def test_rerender_drops_views_of_rooms_that_no_longer_exist(tmp_path, egl):
    h = tmp_path / "h"
    anyhome("generate", "A bedroom and a kitchen.", "--out", str(h), "--render", "--size", "48",
            "--view-size", "24", "-q")
    assert (h / "views" / "kitchen.png").exists()
    one = tmp_path / "one"
    anyhome("generate", "A bedroom.", "--out", str(one), "--no-glb", "--no-svg", "-q")
    (h / "house.json").write_bytes((one / "house.json").read_bytes())  # the user edits the house
    glb = (h / "house.glb").read_bytes()
    proc = anyhome("render", str(h), "--size", "48", "--view-size", "24")
    assert sorted(p.name for p in (h / "views").iterdir()) == ["bedroom.png"]
    assert (h / "house.glb").read_bytes() == glb and (h / "house.json").read_bytes() == (one / "house.json").read_bytes()
    assert f"{h}/views/bedroom.png" in proc.stdout
    listed = json.loads((h / ".anyhome-files.json").read_text())["files"]
    assert sorted(listed) == sorted(str(p.relative_to(h)) for p in h.rglob("*")
                                    if p.is_file() and p.name != ".anyhome-files.json")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["h", "one"]


def test_render_out_other_folder_follows_the_folder_rules(haunted, tmp_path, egl):
    out, _ = haunted
    other = tmp_path / "other"
    other.mkdir()
    (other / "notes.txt").write_text("x")
    one_error_line(anyhome("render", str(out), "--out", str(other), "--size", "32", "--view-size", "16",
                           check=False))
    assert sorted(p.name for p in other.iterdir()) == ["notes.txt"]
    anyhome("render", str(out), "--out", str(tmp_path / "r"), "--size", "32", "--no-views")
    anyhome("render", str(out), "--out", str(tmp_path / "r"), "--size", "32", "--no-views")  # ours now
    assert sorted(p.name for p in (tmp_path / "r").iterdir()) == [".anyhome-files.json", "birdseye.png",
                                                                   "render.json"]


def test_the_summary_prints_no_escape_sequences(capsys):
    """Names, style, warnings and dropped items from a house (an LLM or a house.json) and
    the model and URL reach the terminal without control characters or credentials."""
    from anyhome import cli
    from anyhome.house import Dropped
    from anyhome.pipeline import generate

    evil = "\x1b]0;pwned\x07\x1b[31mred\x1b[0m\x07\r"
    house = generate("A bedroom.", seed=0)
    house.rooms[0].name = f"bed{evil}room"
    house.style = f"modern{evil}"
    house.warnings = [f"careful{evil}"]
    house.dropped = [Dropped(room=house.rooms[0].id, name=f"rug{evil}", reason=f"no room{evil}")]
    cli._print_summary(house, [], {"plan": 0.1}, 0.1)
    cli._print_llm({"model": f"qwen{evil}", "base_url": "http://user:SECRETKEY@host:8080/v1", "calls": 1,
                    "cache_hits": 0, "prompt_tokens": 1, "completion_tokens": 1, "call_latency_s": 0.1,
                    "stages": {f"program{evil}": "offline"}})
    out = capsys.readouterr().out
    assert "bedred room" in out and "modernred" in out and "carefulred" in out and "rugred" in out
    assert "\x1b" not in out and "\x07" not in out and "\r" not in out and "pwned" not in out
    assert "SECRETKEY" not in out and "qwenred  at http://host:8080/v1" in out


def test_output_piped_into_a_reader_that_stops_early(tmp_path):
    """`anyhome eval DIR | head -1`: the reader closes the pipe; no traceback."""
    out = tmp_path / "h"
    anyhome("generate", "a bedroom", "--out", str(out), "--no-glb", "-q")
    proc = subprocess.Popen([sys.executable, "-m", "anyhome", "eval", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()  # like `head` exiting before anything was read
    _, err = proc.communicate(timeout=60)
    assert b"Traceback" not in err, err.decode()[-2000:]
    assert proc.returncode == 141


@pytest.mark.parametrize("value", ["100000", "abc", "-5", "4"])
def test_bad_texture_size_is_one_line_before_any_work(tmp_path, value):
    out = tmp_path / "h"
    proc = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a bedroom", "--out", str(out)],
                          capture_output=True, text=True, timeout=60,
                          env={**os.environ, "ANYHOME_TEXTURE_PX": value})
    assert proc.returncode == 2, proc.stderr[-2000:]
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: $ANYHOME_TEXTURE_PX"), proc.stderr
    assert not out.exists()
