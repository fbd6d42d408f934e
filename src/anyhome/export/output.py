"""Writing one export file: atomic, with a one-line ExportError on failure."""

from __future__ import annotations

from anyhome.outdir import write_file

__all__ = ["write_file"]
