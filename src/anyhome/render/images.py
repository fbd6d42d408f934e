"""Writing images and arrays: PNG (encoded here with zlib, no imaging library) and
``.npy``, each written atomically."""

from __future__ import annotations

import io
import struct
import zlib
from pathlib import Path

import numpy as np

from anyhome.errors import RenderError
from anyhome.export.output import write_file

PNG_COMPRESSION = 6
"""zlib level of the PNG data."""
_COLOR_TYPES = {1: 0, 3: 2, 4: 6}  # channels -> PNG colour type


def _chunk(tag: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))


def encode_png(image: np.ndarray) -> bytes:
    """PNG bytes of an 8-bit image.

    Parameters
    ----------
    image : (h, w) or (h, w, c) uint8, c in 1, 3, 4; row 0 is the top
    """
    img = np.asarray(image)
    if img.dtype != np.uint8:
        raise RenderError(f"PNG needs uint8 pixels, got {img.dtype}")
    if img.ndim == 2:
        img = img[..., None]
    h, w, c = img.shape
    if c not in _COLOR_TYPES:
        raise RenderError(f"PNG needs 1, 3 or 4 channels, got {c}")
    # filter "Sub" (1): each byte minus the same channel of the pixel to its left
    rows = img.reshape(h, w * c)
    sub = rows.copy()
    sub[:, c:] = rows[:, c:] - rows[:, :-c]
    raw = np.column_stack([np.ones(h, dtype=np.uint8), sub]).tobytes()
    header = struct.pack(">IIBBBBB", w, h, 8, _COLOR_TYPES[c], 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header)
            + _chunk(b"IDAT", zlib.compress(raw, PNG_COMPRESSION)) + _chunk(b"IEND", b""))


def write_bytes(path: Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (creating its folder); RenderError on failure."""
    return write_file(path, data, error=RenderError)


def write_png(path: Path, image: np.ndarray) -> Path:
    """Write ``image`` (see :func:`encode_png`) to ``path`` atomically."""
    return write_bytes(Path(path), encode_png(image))


def write_npy(path: Path, array: np.ndarray) -> Path:
    """Write ``array`` as a ``.npy`` file atomically."""
    buf = io.BytesIO()
    np.save(buf, np.ascontiguousarray(array), allow_pickle=False)
    return write_bytes(Path(path), buf.getvalue())
