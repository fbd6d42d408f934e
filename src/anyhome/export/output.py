"""Writing one export file: atomic, with a one-line ExportError on failure."""

from __future__ import annotations

from pathlib import Path

from anyhome.errors import ExportError
from anyhome.house import atomic_write_bytes


def write_file(path: Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (creating its folder); return the path."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_bytes(path, data)
    except OSError as e:
        raise ExportError(f"could not write {path}: {e.strerror}") from None
    return path
