"""kill -9 of the real CLI while it writes a house folder: at many times spread over a
measured run of ``generate``, ``generate --render`` and ``render``, and at each named
point of the swap (the ANYHOME_KILL_AT test hook of anyhome.outdir). After every kill
the folder holds the old house whole or the new one whole (byte for byte one of the
two reference folders), and the next run succeeds and leaves no temporary folder."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from anyhome.outdir import KILL_ENV, MANIFEST_FILE, SWAP_ENV

OLD = "A bedroom."
NEW = "A bedroom and a kitchen."
PLAIN = ["--no-glb", "-q"]
RENDER = ["--no-glb", "-q", "--render", "--size", "48", "--view-size", "24"]
RERENDER = ["--size", "40", "--view-size", "20"]
HANG_GUARD_S = 60


def cli(*args, env=None, check=True):
    proc = subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True, text=True,
                          timeout=HANG_GUARD_S, env={**os.environ, **(env or {})})
    if check and proc.returncode != 0:
        raise AssertionError(f"anyhome {args} failed ({proc.returncode}):\n{proc.stderr}")
    return proc


def tree(folder):
    """Every file under ``folder`` with its bytes (None if the folder is missing)."""
    if not folder.exists():
        return None
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def timed_run(*args):
    t0 = time.perf_counter()
    cli(*args)
    return time.perf_counter() - t0


@pytest.fixture(scope="module")
def plain(tmp_path_factory):
    """Reference folders of the old and the new house (no renders), and the seconds a run takes."""
    base = tmp_path_factory.mktemp("ref")
    timed_run("generate", OLD, "--out", str(base / "old"), *PLAIN)
    seconds = timed_run("generate", NEW, "--out", str(base / "new"), *PLAIN)
    return base, tree(base / "old"), tree(base / "new"), seconds


@pytest.fixture(scope="module")
def rendered(gl_available, tmp_path_factory):
    """The same with renders, plus the old house re-rendered at other sizes."""
    base = tmp_path_factory.mktemp("ref_render")
    timed_run("generate", OLD, "--out", str(base / "old"), *RENDER)
    seconds = timed_run("generate", NEW, "--out", str(base / "new"), *RENDER)
    shutil.copytree(base / "old", base / "rerendered")
    render_s = timed_run("render", str(base / "rerendered"), *RERENDER)
    return base, {k: tree(base / k) for k in ("old", "new", "rerendered")}, seconds, render_s


def assert_whole(folder, *houses):
    got = tree(folder)
    assert got is not None, f"{folder} is missing"
    assert any(got == h for h in houses), f"{folder} is neither house: {sorted(got)}"
    assert MANIFEST_FILE in got


def assert_clean(parent, *names):
    assert sorted(os.listdir(parent)) == sorted(names), os.listdir(parent)


def killed_after(delay_s, *args, env=None):
    proc = subprocess.Popen([sys.executable, "-m", "anyhome", *args], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, env={**os.environ, **(env or {})})
    try:
        proc.wait(timeout=delay_s)  # finished before the kill: a whole run
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=HANG_GUARD_S)
    return proc.returncode


# ------------------------------------------------------------ named points
POINTS = [
    ("exchange", "manifest"), ("exchange", "exchanged"), ("exchange", "removing-old"),
    ("rename", "renamed"), ("rename", "removing-old"),
]  # fmt: skip


@pytest.mark.parametrize("swap, point", POINTS)
def test_kill_inside_the_swap_leaves_a_whole_house(plain, tmp_path, swap, point):
    base, old, new, _ = plain
    d = tmp_path / "h"
    shutil.copytree(base / "old", d)
    env = {KILL_ENV: point, SWAP_ENV: swap}
    assert cli("generate", NEW, "--out", str(d), *PLAIN, env=env, check=False).returncode == -signal.SIGKILL
    assert_whole(d, old if point in ("staged", "manifest") else new)
    cli("generate", NEW, "--out", str(d), *PLAIN, env={SWAP_ENV: swap})
    assert tree(d) == new
    assert_clean(tmp_path, "h")


def test_kill_between_the_two_renames_is_recovered(plain, tmp_path):
    """The fallback swap (no renameat2): a kill between its renames leaves the old folder
    aside; the next command on that folder (eval, render, export, generate) puts it back
    before anything else."""
    base, old, new, _ = plain
    d = tmp_path / "h"
    shutil.copytree(base / "old", d)
    env = {SWAP_ENV: "rename"}
    assert cli("generate", NEW, "--out", str(d), *PLAIN, env={**env, KILL_ENV: "moved-aside"},
               check=False).returncode == -signal.SIGKILL
    assert not d.exists() and len(os.listdir(tmp_path)) == 2  # old aside, new staged
    # the next command that reads or writes the folder puts it back first
    cli("eval", str(d / "house.json"))
    assert tree(d) == old
    assert_clean(tmp_path, "h")
    assert cli("generate", NEW, "--out", str(d), *PLAIN, env={**env, KILL_ENV: "moved-aside"},
               check=False).returncode == -signal.SIGKILL
    # and a generate recovers it before its own checks; killed right after, the old house stays
    assert cli("generate", NEW, "--out", str(d), *PLAIN, env={**env, KILL_ENV: "staged"},
               check=False).returncode == -signal.SIGKILL
    assert tree(d) == old
    cli("generate", NEW, "--out", str(d), *PLAIN, env=env)
    assert tree(d) == new
    assert_clean(tmp_path, "h")


def test_kill_inside_the_swap_of_render(rendered, tmp_path):
    base, refs, _, _ = rendered
    d = tmp_path / "h"
    for point in ("manifest", "exchanged"):
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(base / "old", d)
        assert cli("render", str(d), *RERENDER, env={KILL_ENV: point}, check=False).returncode == -signal.SIGKILL
        assert_whole(d, refs["old"] if point == "manifest" else refs["rerendered"])
    cli("render", str(d), *RERENDER)
    assert tree(d) == refs["rerendered"]
    assert_clean(tmp_path, "h")


# ------------------------------------------------------------- timed kills
def _spread(seconds, n):
    """``n`` kill times from 15 % to 110 % of a measured run."""
    return [seconds * (0.15 + 0.95 * i / (n - 1)) for i in range(n)]


def test_kills_spread_over_generate(plain, tmp_path):
    base, old, new, seconds = plain
    d = tmp_path / "h"
    shutil.copytree(base / "old", d)
    for delay in _spread(seconds, 5):
        killed_after(delay, "generate", NEW, "--out", str(d), *PLAIN)
        assert_whole(d, old, new)
    cli("generate", NEW, "--out", str(d), *PLAIN)
    assert tree(d) == new
    assert_clean(tmp_path, "h")


def test_kills_spread_over_generate_render(rendered, tmp_path):
    base, refs, seconds, _ = rendered
    d = tmp_path / "h"
    shutil.copytree(base / "old", d)
    for delay in _spread(seconds, 5):
        killed_after(delay, "generate", NEW, "--out", str(d), *RENDER)
        assert_whole(d, refs["old"], refs["new"])
    cli("generate", NEW, "--out", str(d), *RENDER)
    assert tree(d) == refs["new"]
    assert_clean(tmp_path, "h")


def test_kills_spread_over_render(rendered, tmp_path):
    base, refs, _, render_s = rendered
    d = tmp_path / "h"
    shutil.copytree(base / "old", d)
    for delay in _spread(render_s, 4):
        killed_after(delay, "render", str(d), *RERENDER)
        assert_whole(d, refs["old"], refs["rerendered"])
    cli("render", str(d), *RERENDER)
    assert tree(d) == refs["rerendered"]
    assert_clean(tmp_path, "h")


# ------------------------------------------------------------- concurrency
@pytest.mark.parametrize("existing", [False, True])
def test_concurrent_writers_end_with_one_whole_house(plain, tmp_path, existing):
    base, old, new, _ = plain
    d = tmp_path / "h"
    if existing:
        shutil.copytree(base / "old", d)
    procs = [subprocess.Popen([sys.executable, "-m", "anyhome", "generate", text, "--out", str(d), *PLAIN],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
             for text in (NEW, OLD)]
    for p in procs:
        _, err = p.communicate(timeout=HANG_GUARD_S)
        assert p.returncode == 0, err
    assert_whole(d, old, new)
    assert_clean(tmp_path, "h")
