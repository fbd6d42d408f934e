"""Output folders: what AnyHome may replace, and how it replaces a folder safely.

A house folder is written all or nothing. Every file goes into a temporary sibling
folder first; a manifest (:data:`MANIFEST_FILE`, a small hidden JSON file) lists what
was written; then the temporary folder is swapped into place and the old folder deleted.

Rules (:func:`check_out`, :func:`foreign_entry`):

- a folder is replaced only when it holds nothing but the files its manifest lists
  (plus the manifest); a folder written before manifests existed is accepted only when
  every entry is a name AnyHome writes (:data:`LEGACY_FILES`, ``views/<stem>.png`` ...)
  and its house.json is an AnyHome house. Anything else is a *foreign* folder and is
  refused, with the first foreign entry named; nothing is touched;
- ``--out`` is checked before any work: empty, ``.``, ``..`` and ``/`` are refused, as
  are a parent that is a file, a read-only parent, a too-long name and a symlink loop.
  A symlink is followed: the house lands in the link's target, the link stays;
- the swap uses ``renameat2(RENAME_EXCHANGE)`` where the system has it (Linux, glibc >=
  2.28, a file system that supports it), so the folder's name holds the old or the new
  house at every instant. Elsewhere it falls back to two renames; a run killed between
  them leaves the old folder as ``.<name>.<hash>.ah-old-...``, and the next run that
  writes into the same parent folder puts it back (:func:`recover`);
- temporary folders and files carry the writer's PID and process start time in their
  names; the next run removes those of processes that are gone;
- outputs get ordinary modes (0666 / 0777 less the umask); a replaced folder keeps its
  mode.

Test hooks (environment variables, read only here):

- ``ANYHOME_KILL_AT=<point>``: the process SIGKILLs itself at that named point
  (:func:`kill_point`), for the kill tests of the swap window;
- ``ANYHOME_SWAP=rename``: use the two-rename fallback even where renameat2 works.
"""

from __future__ import annotations

import ctypes
import errno
import hashlib
import json
import os
import re
import secrets
import shutil
import signal
import stat
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from anyhome.errors import AnyHomeError, ExportError

MANIFEST_FILE = ".anyhome-files.json"
"""The manifest in every folder AnyHome writes: the files it wrote there."""
MANIFEST_FORMAT = "anyhome.files"
HOUSE_FILE = "house.json"
RENDER_FILES = frozenset({
    "birdseye.png", "birdseye.depth.npy", "birdseye.ids.npy", "render.json",
})  # fmt: skip
"""Top-level files a render writes (besides ``views/``)."""
VIEWS_DIR = "views"
LEGACY_FILES = frozenset({HOUSE_FILE, "house.glb", "floorplan.svg"}) | RENDER_FILES
"""Top-level names a house folder without a manifest may hold."""
_LEVEL_SVG_RE = re.compile(r"floorplan-b?[0-9]{1,2}\.svg")
"""The floorplan of a storey other than the ground floor (anyhome.export.svg.level_svg_name)."""
_LEVEL_RENDER_RE = re.compile(r"birdseye-b?[0-9]{1,2}\.(?:png|depth\.npy|ids\.npy)")
"""The bird's-eye of a storey other than the ground floor (anyhome.render.api.level_suffix)."""
_LEGACY_VIEW_RE = re.compile(r"[A-Za-z0-9_.-]+\.(?:png|depth\.npy|ids\.npy)")
_HOUSE_FORMAT_RE = re.compile(rb'"format"\s*:\s*"anyhome\.house"')
NAME_MAX = 255
"""Longest file name in bytes (Linux, macOS)."""
STEM_CHARS = 24
"""Characters of the folder's name kept in temporary names (they stay short)."""

KILL_ENV = "ANYHOME_KILL_AT"
SWAP_ENV = "ANYHOME_SWAP"

_TEMP_DIR_RE = re.compile(
    r"\.(?P<stem>.{0,%d})\.(?P<hash>[0-9a-f]{8})\.ah-(?P<kind>new|old)-(?P<pid>\d+)-(?P<start>\d+)-[0-9a-f]+"
    % STEM_CHARS, re.DOTALL,
)
_TEMP_FILE_RE = re.compile(r"\..{0,%d}\.ah-(?P<pid>\d+)-(?P<start>\d+)-[0-9a-f]+\.part" % STEM_CHARS, re.DOTALL)


# ------------------------------------------------------------------ test hook
def kill_point(name: str) -> None:
    """Test hook: SIGKILL this process if ``ANYHOME_KILL_AT`` names this point."""
    if os.environ.get(KILL_ENV) == name:
        os.kill(os.getpid(), signal.SIGKILL)


# ------------------------------------------------------------------ processes
def _start_time(pid: int) -> str | None:
    """The start time of process ``pid`` (clock ticks since boot, Linux), None if unknown."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
        return fields[19].decode()
    except (OSError, IndexError):
        return None


_OWN_START = _start_time(os.getpid()) or "0"


def _alive(pid: int, start: str) -> bool:
    """Is the process that wrote a temporary name still running?"""
    if pid == os.getpid():
        return start == _OWN_START
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass
    now = _start_time(pid)
    return now is None or start == "0" or now == start  # a reused PID is another process


def _tag() -> str:
    return f"{os.getpid()}-{_OWN_START}-{secrets.token_hex(3)}"


def _name_hash(name: str) -> str:
    return hashlib.sha1(os.fsencode(name)).hexdigest()[:8]


def _temp_dir_name(name: str, kind: str) -> str:
    return f".{name[:STEM_CHARS]}.{_name_hash(name)}.ah-{kind}-{_tag()}"


def is_stale_temp(name: str) -> bool:
    """True for a temporary file or folder name of ours whose writer is gone."""
    m = _TEMP_DIR_RE.fullmatch(name) or _TEMP_FILE_RE.fullmatch(name)
    return m is not None and not _alive(int(m["pid"]), m["start"])


# --------------------------------------------------------------- atomic files
def atomic_write_bytes(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` so readers see the old file or the new one, never a
    part. The file gets mode 0666 less the umask, like any ordinary new file."""
    path = Path(path)
    tmp = path.with_name(f".{path.name[:STEM_CHARS]}.ah-{_tag()}.part")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o666)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    return path


def write_file(path: str | os.PathLike[str], data: bytes, error: type[AnyHomeError] = ExportError) -> Path:
    """:func:`atomic_write_bytes`, creating the folder; an OSError becomes one ``error``."""
    path = Path(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        return atomic_write_bytes(path, data)
    except OSError as e:
        raise error(f"could not write {path}: {_reason(e)}") from None


def _reason(e: OSError) -> str:
    if e.errno == errno.ENOSPC:
        return "no space left on the device"
    return e.strerror or str(e)


# ------------------------------------------------------------------ manifest
def read_manifest(folder: Path) -> set[str] | None:
    """The relative paths the manifest of ``folder`` lists (folders end in ``/``); None
    without a manifest. An unreadable or malformed manifest raises ExportError (the
    folder is not ours)."""
    path = folder / MANIFEST_FILE
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        return None
    except OSError as e:
        raise ExportError(f"could not read {path}: {_reason(e)}") from None
    try:
        data = json.loads(raw.decode("utf-8"))
        ok = isinstance(data, dict) and data.get("format") == MANIFEST_FORMAT
        files, dirs = (data["files"], data.get("dirs", [])) if ok else (None, None)
    except (UnicodeDecodeError, ValueError, KeyError, RecursionError):
        files = dirs = None
    if not (isinstance(files, list) and isinstance(dirs, list) and all(isinstance(f, str) for f in files + dirs)):
        raise ExportError(f"{path} is not an AnyHome manifest; choose another --out")
    return set(files) | {d.rstrip("/") + "/" for d in dirs}


def walk_files(folder: Path, rel: str = "", dirs: bool = False) -> Iterator[str]:
    """Relative paths of the regular files under ``folder`` (sorted, symlinks skipped);
    with ``dirs`` also its folders, ending in ``/``."""
    with os.scandir(folder / rel if rel else folder) as it:
        entries = sorted(it, key=lambda e: e.name)
    for e in entries:
        r = f"{rel}{e.name}"
        if e.is_dir(follow_symlinks=False):
            if dirs:
                yield r + "/"
            yield from walk_files(folder, r + "/", dirs)
        elif e.is_file(follow_symlinks=False):
            yield r


def write_manifest(folder: Path, extra: set[str] | None = None) -> Path:
    """Write the manifest of ``folder``: every file and folder under it (and ``extra``)."""
    entries = {f for f in walk_files(folder, dirs=True)
               if f != MANIFEST_FILE and not is_stale_temp(f.rstrip("/").rsplit("/", 1)[-1])}
    entries |= extra or set()
    data = {"format": MANIFEST_FORMAT, "version": 1,
            "files": sorted(f for f in entries if not f.endswith("/")),
            "dirs": sorted(f.rstrip("/") for f in entries if f.endswith("/"))}
    return write_file(folder / MANIFEST_FILE, (json.dumps(data, indent=1) + "\n").encode("utf-8"))


# --------------------------------------------------------------- ownership
def foreign_entry(folder: Path) -> str | None:
    """The first entry of ``folder`` (relative path, sorted order) AnyHome did not write;
    None if the folder holds only AnyHome's files. ``folder`` must be a folder."""
    listed = read_manifest(folder)
    if listed is None:
        return _legacy_foreign(folder)
    dirs = {p.rsplit("/", i)[0] for p in listed for i in range(1, p.count("/") + 1)}
    dirs |= {p.rstrip("/") for p in listed if p.endswith("/")}
    return _first_foreign(folder, "", lambda rel, is_dir: rel in (dirs if is_dir else listed))


def _legacy_foreign(folder: Path) -> str | None:
    def ours(rel: str, is_dir: bool) -> bool:
        if is_dir:
            return rel == VIEWS_DIR
        if rel.startswith(VIEWS_DIR + "/"):
            return _LEGACY_VIEW_RE.fullmatch(rel[len(VIEWS_DIR) + 1:]) is not None
        if rel == HOUSE_FILE:
            return _is_anyhome_house(folder / rel)
        return rel in LEGACY_FILES or _LEVEL_SVG_RE.fullmatch(rel) is not None or _LEVEL_RENDER_RE.fullmatch(rel) is not None

    return _first_foreign(folder, "", ours)


def _is_anyhome_house(path: Path) -> bool:
    try:
        with open(path, "rb") as f:
            head = f.read(4096)
    except OSError:
        return False
    return _HOUSE_FORMAT_RE.search(head) is not None


def _first_foreign(folder: Path, rel: str, ours) -> str | None:
    try:
        with os.scandir(folder / rel if rel else folder) as it:
            entries = sorted(it, key=lambda e: e.name)
    except OSError as e:
        raise ExportError(f"could not read {folder / rel}: {_reason(e)}") from None
    for entry in entries:
        r = f"{rel}{entry.name}"
        if not rel and entry.name == MANIFEST_FILE:
            continue
        if is_stale_temp(entry.name):
            continue  # a file or folder left by a killed run of ours
        if entry.is_dir(follow_symlinks=False):
            if not ours(r, True):
                return r + "/"
            found = _first_foreign(folder, r + "/", ours)
            if found:
                return found
        elif not entry.is_file(follow_symlinks=False) or not ours(r, False):
            return r
    return None


def check_ours(folder: Path) -> None:
    """Raise ExportError unless ``folder`` (an existing folder) may be replaced."""
    if not (folder / MANIFEST_FILE).exists() and not (folder / HOUSE_FILE).exists():
        try:
            empty = not any(n for n in os.listdir(folder) if not is_stale_temp(n))
        except OSError as e:
            raise ExportError(f"could not read {folder}: {_reason(e)}") from None
        if empty:
            return
        raise ExportError(f"{folder} is a non-empty folder without a house.json; choose another --out")
    found = foreign_entry(folder)
    if found:
        raise ExportError(
            f"{folder} holds {found!r}, which AnyHome did not write; choose another --out "
            "(nothing was changed)"
        )


# ----------------------------------------------------------------- --out
def check_out(out: str | os.PathLike[str], what: str = "--out", replace: bool = True) -> Path:
    """Check an output folder before any work; return its real path (symlinks followed).

    Cheap checks only: the name, the parent (a folder, writable), a symlink loop, and,
    with ``replace`` (the folder will be swapped), that an existing folder is ours. Every
    problem raises ExportError in one line. Nothing is created or changed, except what
    :func:`prepare` repairs first (what killed runs left next to the folder).
    """
    s = os.fspath(out)
    if isinstance(s, bytes):
        s = os.fsdecode(s)
    if s.strip() == "":
        raise ExportError(f"{what} is empty; give a folder such as out/house")
    if "\x00" in s:
        raise ExportError(f"{what} holds a NUL character")
    base = os.path.basename(s.rstrip("/" + os.sep))
    if replace and base in ("", ".", ".."):
        which = {"": "the root folder", ".": "the current folder", "..": "a parent folder"}[base]
        raise ExportError(f"{what} {s!r} names {which}, which AnyHome does not replace; "
                          "give a folder name such as out/house")
    for part in Path(s).parts:
        if len(os.fsencode(part)) > NAME_MAX:
            raise ExportError(f"{what}: the name {part[:40]!r}... is too long "
                              f"({len(os.fsencode(part))} bytes; at most {NAME_MAX})")
    try:
        os.stat(s)
    except FileNotFoundError:
        pass
    except NotADirectoryError:
        raise ExportError(f"{what} {s!r}: {_file_ancestor(Path(s))} is a file, not a folder") from None
    except OSError as e:
        if e.errno == errno.ELOOP:
            raise ExportError(f"{what} {s!r}: a loop of symbolic links") from None
        raise ExportError(f"{what} {s!r}: {_reason(e)}") from None
    real = Path(os.path.realpath(s))
    prepare(real)
    if replace and real == Path(real.anchor):
        raise ExportError(f"{what} {s!r} is the root folder, which AnyHome does not replace")
    if real.exists():
        if not real.is_dir():
            raise ExportError(f"{what} {s!r} exists and is not a folder")
        if replace:
            check_ours(real)
        else:
            _check_writable(real, what, s)
    if replace or not real.exists():
        _check_writable(real.parent, what, s)
    return real


def _file_ancestor(p: Path) -> Path:
    for a in [p, *p.parents]:
        if a.exists() and not a.is_dir():
            return a
    return p


def _check_writable(folder: Path, what: str, s: str) -> None:
    """The nearest existing folder at or above ``folder`` must be writable."""
    existing = next(a for a in [folder, *folder.parents] if os.path.lexists(a))
    if not existing.is_dir():
        raise ExportError(f"{what} {s!r}: {existing} is a file, not a folder")
    if not os.access(existing, os.W_OK | os.X_OK):
        why = "permission denied"
        try:
            if os.statvfs(existing).f_flag & os.ST_RDONLY:
                why = "read-only file system"
        except (OSError, AttributeError):
            pass
        raise ExportError(f"{what} {s!r}: cannot write into {existing} ({why})")


# ---------------------------------------------------------------------- swap
_RENAME_EXCHANGE = 2
_RENAME_NOREPLACE = 1
_AT_FDCWD = -100


def _load_renameat2():
    if not sys.platform.startswith("linux"):
        return None
    try:
        fn = ctypes.CDLL(None, use_errno=True).renameat2
    except (OSError, AttributeError):
        return None
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    fn.restype = ctypes.c_int
    return fn


_renameat2 = _load_renameat2()
_UNSUPPORTED = {errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP, errno.ENOTSUP}


def _rename2(src: Path, dst: Path, flags: int) -> bool:
    """renameat2(src, dst, flags); False where the system or file system lacks it."""
    if _renameat2 is None or os.environ.get(SWAP_ENV) == "rename":
        return False
    if _renameat2(_AT_FDCWD, os.fsencode(src), _AT_FDCWD, os.fsencode(dst), flags) == 0:
        return True
    err = ctypes.get_errno()
    if err in _UNSUPPORTED:
        return False
    raise OSError(err, os.strerror(err), str(dst))


@contextmanager
def _locked(parent: Path) -> Iterator[None]:
    """An exclusive flock on the parent folder: one swap at a time per parent."""
    try:
        import fcntl

        fd = os.open(parent, os.O_RDONLY)
    except (ImportError, OSError):
        yield
        return
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def prepare(folder: str | os.PathLike[str]) -> None:
    """:func:`recover` next to ``folder`` (symlinks followed), under the parent's lock;
    call it before reading or writing a house folder. Never raises."""
    real = Path(os.path.realpath(folder))
    if real.parent != real and real.parent.is_dir():
        try:
            with _locked(real.parent):
                recover(real)
        except OSError:
            pass


def recover(dest: Path) -> None:
    """Undo what killed runs left next to ``dest``: put back a folder moved aside by an
    interrupted two-rename swap, and remove temporary folders of finished processes."""
    parent = dest.parent
    try:
        entries = sorted(os.listdir(parent))
    except OSError:
        return
    stale = []
    for name in entries:
        m = _TEMP_DIR_RE.fullmatch(name)
        if m and not _alive(int(m["pid"]), m["start"]):
            stale.append((m, parent / name))
    if not stale:
        return
    for m, path in stale:  # first put our own folder back if a swap left it aside
        if m["kind"] == "old" and m["hash"] == _name_hash(dest.name) and not os.path.lexists(dest):
            try:
                os.rename(path, dest)
            except OSError:
                pass
    names = set(os.listdir(parent))
    hashes = {_name_hash(n) for n in names}
    for m, path in stale:
        if path.name not in names:
            continue
        if m["kind"] == "new":
            shutil.rmtree(path, ignore_errors=True)
        elif m["hash"] in hashes:  # the swap finished; this is the replaced folder
            shutil.rmtree(path, ignore_errors=True)
        # an "old" folder whose destination is gone and is not ours to name: left alone


def _remove_tree(path: Path) -> None:
    """Delete a replaced folder (after the swap, it holds the old house)."""
    for i, rel in enumerate(walk_files(path)):
        if i == 1:
            kill_point("removing-old")
        try:
            os.unlink(path / rel)
        except OSError:
            pass
    shutil.rmtree(path, ignore_errors=True)


def swap_in(new: Path, dest: Path) -> None:
    """Put folder ``new`` at ``dest`` (replacing a folder there); delete the old one.

    With renameat2 the name ``dest`` holds the old or the new folder at every instant;
    the fallback's window between its two renames is covered by :func:`recover`.
    """
    if not os.path.lexists(dest):
        if not _rename2(new, dest, _RENAME_NOREPLACE):
            os.rename(new, dest)
        return
    if _rename2(new, dest, _RENAME_EXCHANGE):
        kill_point("exchanged")
        _remove_tree(new)
        return
    backup = dest.with_name(_temp_dir_name(dest.name, "old"))
    os.rename(dest, backup)
    kill_point("moved-aside")
    try:
        os.rename(new, dest)
    except BaseException:
        os.rename(backup, dest)
        raise
    kill_point("renamed")
    _remove_tree(backup)


# ------------------------------------------------------------------ staging
class Staging:
    """A temporary folder next to ``dest`` that becomes ``dest`` on :meth:`commit`.

    Use as a context manager: files written into :attr:`path` inside the ``with`` block
    are swapped in by ``commit()`` (with a manifest); on an exception, or without a
    commit, the temporary folder is deleted and ``dest`` is left as it was.
    """

    def __init__(self, dest: str | os.PathLike[str], what: str = "--out") -> None:
        self.dest = check_out(dest, what)
        self.path = self.dest.with_name(_temp_dir_name(self.dest.name, "new"))
        self.committed = False

    def __enter__(self) -> Staging:
        parent = self.dest.parent
        try:
            parent.mkdir(parents=True, exist_ok=True)
            with _locked(parent):
                recover(self.dest)
            os.mkdir(self.path, 0o777)
        except OSError as e:
            raise ExportError(f"could not write {self.dest}: {_reason(e)}") from None
        return self

    def commit(self) -> None:
        """Write the manifest and swap the folder in, if ``dest`` is still ours."""
        kill_point("staged")
        write_manifest(self.path)
        kill_point("manifest")
        try:
            with _locked(self.dest.parent):
                if os.path.lexists(self.dest):
                    if not self.dest.is_dir() or self.dest.is_symlink():
                        raise ExportError(f"{self.dest} is no longer a folder; nothing was changed")
                    check_ours(self.dest)
                    os.chmod(self.path, stat.S_IMODE(self.dest.stat().st_mode))  # keep its mode
                swap_in(self.path, self.dest)
        except OSError as e:
            raise ExportError(f"could not replace {self.dest}: {_reason(e)}") from None
        self.committed = True

    def __exit__(self, kind: object, error: BaseException | None, tb: object) -> None:
        if not self.committed:
            shutil.rmtree(self.path, ignore_errors=True)
        if isinstance(error, AnyHomeError) and str(self.path) in str(error):
            # name the file as the user will know it, not its temporary folder
            raise type(error)(str(error).replace(str(self.path), str(self.dest))) from None


def link_or_copy(src: Path, dst: Path) -> None:
    """Hard-link ``src`` to ``dst`` (copy where links are not possible)."""
    dst.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.link(src, dst)
    except OSError:
        shutil.copyfile(src, dst)  # a new file: mode 0666 less the umask


def is_ours(folder: Path) -> bool:
    """True if ``folder`` is missing, empty, or holds only what AnyHome wrote."""
    if not folder.exists():
        return True
    try:
        check_ours(folder)
    except ExportError:
        return False
    return True


def is_render_output(rel: str) -> bool:
    """True for files a render writes (bird's-eye, render.json, anything in views/)."""
    return rel in RENDER_FILES or rel.startswith(VIEWS_DIR + "/") or _LEVEL_RENDER_RE.fullmatch(rel) is not None
