"""Output folders (anyhome.outdir): ownership by manifest, --out checks, the swap and the
recovery after a killed run. Real folders, real renames; no mocks."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from anyhome import outdir
from anyhome.errors import ExportError
from anyhome.outdir import MANIFEST_FILE, Staging, check_out, foreign_entry, recover, swap_in

HOUSE_JSON = '{\n "format": "anyhome.house",\n "version": 1\n}\n'


def make_house(folder, files=("house.json", "house.glb", "floorplan.svg"), manifest=True, text="old"):
    folder.mkdir(parents=True, exist_ok=True)
    for f in files:
        p = folder / f
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(HOUSE_JSON if f == "house.json" else f"{text} {f}")
    if manifest:
        outdir.write_manifest(folder)
    return folder


def dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def tree(folder):
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


# --------------------------------------------------------------- ownership
def test_a_folder_with_its_manifest_is_ours(tmp_path):
    make_house(tmp_path / "h", files=("house.json", "house.glb", "views/kitchen.png"))
    assert foreign_entry(tmp_path / "h") is None
    check_out(tmp_path / "h")


@pytest.mark.parametrize("extra, first", [
    ("notes.txt", "notes.txt"),
    ("photos/cat.jpg", "photos/"),
    ("views/my_drawing.psd", "views/my_drawing.psd"),
])  # fmt: skip
def test_a_foreign_file_next_to_a_house_is_refused_and_kept(tmp_path, extra, first):
    h = make_house(tmp_path / "h", files=("house.json", "house.glb", "views/kitchen.png"))
    (h / extra).parent.mkdir(exist_ok=True)
    (h / extra).write_text("keep me")
    before = tree(h)
    assert foreign_entry(h) == first
    with pytest.raises(ExportError, match="which AnyHome did not write"):
        check_out(h)
    with pytest.raises(ExportError):
        Staging(h)
    assert tree(h) == before


def test_legacy_folder_without_manifest_only_with_known_names(tmp_path):
    h = make_house(tmp_path / "h", files=("house.json", "house.glb", "floorplan.svg", "birdseye.png",
                                          "render.json", "views/bed_1.png", "views/bed_1.depth.npy"),
                   manifest=False)
    assert foreign_entry(h) is None
    (h / "views" / "notes.txt").write_text("x")
    assert foreign_entry(h) == "views/notes.txt"


def test_a_users_own_house_json_alone_is_refused(tmp_path):
    h = tmp_path / "h"
    h.mkdir()
    (h / "house.json").write_text('{"rooms": 3, "owner": "me"}')
    with pytest.raises(ExportError, match="'house.json'"):
        check_out(h)


def test_a_symlink_inside_a_house_folder_is_foreign(tmp_path):
    h = make_house(tmp_path / "h")
    (tmp_path / "precious.txt").write_text("x")
    (h / "house.glb").unlink()
    (h / "house.glb").symlink_to(tmp_path / "precious.txt")
    assert foreign_entry(h) == "house.glb"


def test_a_broken_manifest_makes_the_folder_foreign(tmp_path):
    h = make_house(tmp_path / "h")
    (h / MANIFEST_FILE).write_text("not json")
    with pytest.raises(ExportError, match="not an AnyHome manifest"):
        check_out(h)


_names = st.sampled_from(["a.txt", "b.png", "house.json", "c", "views", "x.npy"])


@settings(max_examples=60, deadline=None)
@given(files=st.sets(st.lists(_names, min_size=1, max_size=3).map("/".join), min_size=1, max_size=8),
       data=st.data())
def test_foreign_entry_is_none_exactly_when_every_file_is_listed(tmp_path_factory, files, data):
    """Property: with a manifest, a folder is ours iff each of its files is listed."""
    root = tmp_path_factory.mktemp("prop")
    made = set()
    for f in sorted(files, key=len):
        p = root / f
        if any(q.exists() and q.is_file() for q in [p, *p.parents] if q != root and root in q.parents):
            continue  # a prefix is already a file
        try:
            p.parent.mkdir(parents=True, exist_ok=True)
            if p.is_dir():
                continue
            p.write_text("x")
            made.add(f)
        except (FileExistsError, NotADirectoryError):
            continue
    listed = data.draw(st.sets(st.sampled_from(sorted(made)))) if made else set()
    (root / MANIFEST_FILE).write_text(json.dumps({"format": "anyhome.files", "version": 1,
                                                  "files": sorted(listed)}))
    assert (foreign_entry(root) is None) == (listed == made)


# -------------------------------------------------------------- --out checks
@pytest.mark.parametrize("bad, message", [
    ("", "is empty"), (".", "current folder"), ("..", "parent folder"), ("/", "root folder"),
    ("x/..", "parent folder"),
])  # fmt: skip
def test_names_that_cannot_be_replaced(tmp_path, monkeypatch, bad, message):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ExportError, match=message):
        check_out(bad)


def test_parent_is_a_file_and_out_is_a_file(tmp_path):
    (tmp_path / "afile.txt").write_text("x")
    with pytest.raises(ExportError, match="afile.txt is a file"):
        check_out(tmp_path / "afile.txt" / "sub")
    with pytest.raises(ExportError, match="exists and is not a folder"):
        check_out(tmp_path / "afile.txt")
    with pytest.raises(ExportError, match="exists and is not a folder"):
        check_out(tmp_path / "afile.txt", replace=False)


def test_symlink_loop_and_too_long_name(tmp_path):
    (tmp_path / "l1").symlink_to(tmp_path / "l2")
    (tmp_path / "l2").symlink_to(tmp_path / "l1")
    with pytest.raises(ExportError, match="loop of symbolic links"):
        check_out(tmp_path / "l1")
    with pytest.raises(ExportError, match="too long"):
        check_out(tmp_path / ("d" * 256))


def test_a_245_character_name_gets_short_temporary_names(tmp_path):
    dest = tmp_path / ("d" * 245)
    for _ in range(2):  # create, then replace
        with Staging(dest) as stage:
            assert len(os.fsencode(stage.path.name)) < 100
            (stage.path / "house.json").write_text(HOUSE_JSON)
            stage.commit()
    assert (dest / "house.json").exists() and sorted(os.listdir(tmp_path)) == [dest.name]


def test_a_symlinked_out_is_followed_and_stays_a_link(tmp_path):
    make_house(tmp_path / "target")
    (tmp_path / "link").symlink_to("target")
    with Staging(tmp_path / "link") as stage:
        (stage.path / "house.json").write_text(HOUSE_JSON.replace("1", "1 "))
        stage.commit()
    assert (tmp_path / "link").is_symlink() and os.readlink(tmp_path / "link") == "target"
    assert (tmp_path / "target" / "house.json").read_text() == HOUSE_JSON.replace("1", "1 ")
    assert sorted(os.listdir(tmp_path)) == ["link", "target"]


NOBODY = 65534
"""The unprivileged user (and group) a root test run checks permissions as."""


def _as_unprivileged(check) -> str:
    """``check()``'s ExportError message, run as this user or, under root (who may write
    anywhere), in a forked child that has dropped to :data:`NOBODY` first."""
    if os.geteuid() != 0:
        with pytest.raises(ExportError) as e:
            check()
        return str(e.value)
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: drop root, run the check, send back the message
        os.close(read)
        try:
            os.setgid(NOBODY)
            os.setuid(NOBODY)
            check()
            message = "no error"
        except ExportError as e:
            message = str(e)
        except BaseException as e:  # anything else is reported, not raised, in the child
            message = f"{type(e).__name__}: {e}"
        os.write(write, message.encode())
        os._exit(0)
    os.close(write)
    with os.fdopen(read, "rb") as f:
        message = f.read().decode()
    os.waitpid(pid, 0)
    return message


def test_read_only_parent_as_a_user():
    """A folder the user may not write into (permission, not a read-only file system: the
    tmpfs test of tests/e2e covers that) is one line before any work."""
    import shutil
    import tempfile

    base = Path(tempfile.mkdtemp(prefix="anyhome-ro-"))  # /tmp: an unprivileged user may enter it
    try:
        base.chmod(0o755)
        ro = base / "ro"
        ro.mkdir()
        ro.chmod(0o555)
        message = _as_unprivileged(lambda: check_out(ro / "house"))
        assert "cannot write into" in message and "permission denied" in message, message
    finally:
        shutil.rmtree(base)


# ----------------------------------------------------------------- the swap
@pytest.mark.parametrize("swap", ["exchange", "rename"])
def test_swap_replaces_and_removes_the_old_folder(tmp_path, monkeypatch, swap):
    if swap == "rename":
        monkeypatch.setenv(outdir.SWAP_ENV, "rename")
    old = make_house(tmp_path / "h", text="old")
    new = make_house(tmp_path / "new", text="new")
    swap_in(new, old)
    assert (old / "house.glb").read_text() == "new house.glb"
    assert sorted(os.listdir(tmp_path)) == ["h"]


def test_renameat2_exchange_is_available_here():
    """The machines this project runs on (Linux, glibc >= 2.28) have the atomic swap."""
    if not sys.platform.startswith("linux"):
        pytest.skip("renameat2 is Linux only")
    assert outdir._renameat2 is not None


def test_modes_are_ordinary_and_a_replaced_folder_keeps_its_mode(tmp_path):
    old_mask = os.umask(0o022)
    try:
        dest = tmp_path / "h"
        with Staging(dest) as stage:
            outdir.write_file(stage.path / "house.json", HOUSE_JSON.encode())
            stage.commit()
        assert stat.S_IMODE(dest.stat().st_mode) == 0o755
        assert stat.S_IMODE((dest / "house.json").stat().st_mode) == 0o644
        dest.chmod(0o750)
        with Staging(dest) as stage:
            outdir.write_file(stage.path / "house.json", HOUSE_JSON.encode())
            stage.commit()
        assert stat.S_IMODE(dest.stat().st_mode) == 0o750
    finally:
        os.umask(old_mask)


def test_a_failure_inside_the_stage_leaves_the_old_folder_and_no_temporary(tmp_path):
    dest = make_house(tmp_path / "h")
    before = tree(dest)
    with pytest.raises(ExportError, match=str(dest / "house.glb")):
        with Staging(dest) as stage:
            (stage.path / "house.glb").mkdir()  # writing the file then fails
            outdir.write_file(stage.path / "house.glb", b"x")
    assert tree(dest) == before and sorted(os.listdir(tmp_path)) == ["h"]


# ---------------------------------------------------------------- recovery
def test_recover_puts_back_a_folder_moved_aside_by_a_killed_run(tmp_path):
    pid = dead_pid()
    dest = tmp_path / "house"
    old = make_house(tmp_path / f".house.{outdir._name_hash('house')}.ah-old-{pid}-1-abc", text="old")
    new = make_house(tmp_path / f".house.{outdir._name_hash('house')}.ah-new-{pid}-1-abd", text="new")
    recover(dest)
    assert (dest / "house.glb").read_text() == "old house.glb"
    assert not old.exists() and not new.exists()


def test_recover_removes_the_replaced_folder_when_the_swap_finished(tmp_path):
    pid = dead_pid()
    make_house(tmp_path / "house", text="new")
    make_house(tmp_path / f".house.{outdir._name_hash('house')}.ah-old-{pid}-1-abc", text="old")
    recover(tmp_path / "house")
    assert sorted(os.listdir(tmp_path)) == ["house"]
    assert (tmp_path / "house" / "house.glb").read_text() == "new house.glb"


def test_recover_leaves_folders_of_live_runs_and_of_others(tmp_path):
    live = tmp_path / f".house.{outdir._name_hash('house')}.ah-new-{os.getpid()}-{outdir._OWN_START}-abc"
    live.mkdir()
    orphan = make_house(tmp_path / f".other.{outdir._name_hash('other')}.ah-old-{dead_pid()}-1-abc")
    user = tmp_path / ".house.ah-new-notes"
    user.mkdir()
    recover(tmp_path / "house")
    assert live.exists() and orphan.exists() and user.exists()


def test_stale_atomic_write_parts_are_not_foreign(tmp_path):
    h = make_house(tmp_path / "h")
    (h / f".house.glb.ah-{dead_pid()}-1-abcdef.part").write_bytes(b"half")
    assert foreign_entry(h) is None
    (h / f".house.glb.ah-{os.getpid()}-{outdir._OWN_START}-abcdef.part").write_bytes(b"live")
    assert foreign_entry(h) is not None


def test_an_empty_folder_anyhome_made_stays_ours(tmp_path):
    h = tmp_path / "h"
    (h / "views").mkdir(parents=True)
    (h / "house.json").write_text(HOUSE_JSON)
    outdir.write_manifest(h)
    assert json.loads((h / MANIFEST_FILE).read_text())["dirs"] == ["views"]
    assert foreign_entry(h) is None
    (h / "photos").mkdir()
    assert foreign_entry(h) == "photos/"
