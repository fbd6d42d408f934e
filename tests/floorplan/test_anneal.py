"""The annealing of slicing trees: it stops once its patience runs out."""

from __future__ import annotations

import dataclasses

import numpy as np

from anyhome.floorplan.anneal import anneal
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.slicing import Cut, tree_rects
from anyhome.floorplan.tune import TuneRooms, layout_cost


def _rooms(opts: FloorplanOptions) -> TuneRooms:
    """Four rooms on a 10 x 10 cell rectangle whose every room must reach the outline and
    be 6 cells wide: no tree meets that, so the cost never reaches 0."""
    n = 4
    return TuneRooms(target_cells=np.full(n, 25.0), min_side_m=np.full(n, 6.0), corridor=np.zeros(n, bool),
                     exterior=np.ones(n, bool), void=None, edges=((0, 1), (1, 2), (2, 3), (0, 3)), cell_m=1.0, opts=opts,
                     max_aspect=np.full(n, 2.0))


def _tree() -> Cut:
    return Cut(0, 0, Cut(1, 0, 0, 1), Cut(1, 0, 2, 3))


def _run(patience: float) -> tuple[float, float]:
    """(cost of the annealed tree, the generator's next draw afterwards)."""
    opts = dataclasses.replace(FloorplanOptions(), anneal_patience_frac=patience)
    rooms, rect, rng = _rooms(opts), (0, 0, 10, 10), np.random.default_rng(3)
    out = anneal(_tree(), rect, rooms, rng, opts)
    return layout_cost(tree_rects(out, rect), rect, rooms), float(rng.random())


def test_anneal_never_ends_worse_than_it_started() -> None:
    rect = (0, 0, 10, 10)
    start = layout_cost(tree_rects(_tree(), rect), rect, _rooms(FloorplanOptions()))
    for patience in (0.0, 0.25, 1.0):
        assert _run(patience)[0] <= start + 1e-9


def test_anneal_stops_early_without_progress() -> None:
    short, full = _run(0.0), _run(1.0)
    assert short[0] > 0 and full[0] > 0  # the cost cannot reach 0: only patience ends it early
    assert short[1] != full[1]  # the full schedule drew more numbers from the generator


def test_room_swap_draws_the_rooms_choice_of_the_leaves_drew() -> None:
    """A move draws its two rooms by their rank among the leaves (cheaper than choosing
    from the leaves' list): the same rooms, and the generator left as it was before."""
    from anyhome.floorplan.anneal import _move

    expr = [0, 1, "V", 2, "H", 3, 4, "V", "H"]
    leaves = [i for i, t in enumerate(expr) if not isinstance(t, str)]
    ours, theirs = np.random.default_rng(7), np.random.default_rng(7)
    for _ in range(300):
        moved = _move(expr, ours)
        if theirs.integers(3) == 0:
            i, j = theirs.choice(leaves, size=2, replace=False)
            swapped = list(expr)
            swapped[i], swapped[j] = swapped[j], swapped[i]
            assert moved == swapped
        else:
            theirs.bit_generator.state = ours.bit_generator.state  # other moves: not this test's
