"""Room polygons built defensively: a malformed outline must be reported, not crash."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon

CHUNK_PAIRS = 1_000_000
"""Most candidate pairs one STRtree query may return. A bulk query of every geometry
against every other returns n^2 pairs when they all overlap, and shapely crashes the
process (exit 139, no MemoryError) when that array cannot be allocated: 20,000 identical
boxes under a 6 GB limit, 100,000 on this machine. Queries are therefore chunked."""


def room_polygon(points: Sequence[Sequence[float]]) -> Polygon:
    """The shapely polygon of an outline; an empty polygon if it has fewer than 3 points."""
    return Polygon(points) if len(points) >= 3 else Polygon()


def is_usable(poly: Polygon) -> bool:
    """A polygon the geometric checks can run on: non-empty, valid, positive area."""
    return not poly.is_empty and poly.is_valid and poly.area > 0


def overlapping_pairs(geoms: np.ndarray, chunk_pairs: int = CHUNK_PAIRS
                      ) -> Iterator[tuple[int, np.ndarray, np.ndarray]]:
    """Pairs ``i < j`` of geometries whose bounding boxes overlap, chunk by chunk.

    Yields ``(stop, left, right)``: every pair with ``left`` in ``[start, stop)``, sorted
    by ``(left, right)``; each chunk holds at most about ``chunk_pairs`` pairs, so the
    caller can stop early and memory stays bounded.
    """
    n = len(geoms)
    if n < 2:
        return
    tree = shapely.STRtree(geoms)
    chunk = max(1, chunk_pairs // n)
    for start in range(0, n, chunk):
        stop = min(n, start + chunk)
        src, dst = tree.query(geoms[start:stop])
        left = src + start
        keep = left < dst
        left, right = left[keep], dst[keep]
        order = np.lexsort((right, left))
        yield stop, left[order], right[order]
