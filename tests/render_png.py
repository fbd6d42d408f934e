"""Reading back the PNGs anyhome.render writes, for the render tests (a module of its own:
tests/render/conftest.py cannot be imported by name beside tests/export/conftest.py)."""

import struct
import zlib
from pathlib import Path

import numpy as np

SIZE_PX = 128
VIEW_PX = 96


def read_png(path: Path) -> np.ndarray:
    """Decode the 8-bit PNGs that anyhome.render writes (one IDAT, filter Sub)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, {}
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        tag = data[pos + 4:pos + 8]
        chunks[tag] = chunks.get(tag, b"") + data[pos + 8:pos + 8 + n]
        pos += 12 + n
    w, h, depth, ctype = struct.unpack(">IIBB", chunks[b"IHDR"][:10])
    assert depth == 8
    c = {0: 1, 2: 3, 6: 4}[ctype]
    raw = np.frombuffer(zlib.decompress(chunks[b"IDAT"]), dtype=np.uint8).reshape(h, 1 + w * c)
    assert (raw[:, 0] == 1).all()
    rows = raw[:, 1:].reshape(h, w, c).astype(np.int64)
    return (np.cumsum(rows, axis=1) % 256).astype(np.uint8)
