"""Writing one export file: atomic, with a one-line ExportError on failure."""

from __future__ import annotations

from pathlib import Path

from anyhome.errors import AnyHomeError, ExportError
from anyhome.house import atomic_write_bytes


def write_file(path: Path, data: bytes, error: type[AnyHomeError] = ExportError) -> Path:
    """Write ``data`` to ``path`` atomically (creating its folder); return the path.
    A failure raises ``error`` (ExportError unless the caller says otherwise) in one line."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_bytes(path, data)
    except OSError as e:
        raise error(f"could not write {path}: {e.strerror}") from None
    return path
