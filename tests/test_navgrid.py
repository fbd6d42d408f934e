"""The per-room walkway check: incremental walkable cells and reachability of objects."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from anyhome.geometry import AGENT_RADIUS_M
from anyhome.navgrid import WALKWAY_RADIUS_M, NavGrid
from anyhome.space import RoomSpace, rect_corners
from tests.layout.helpers import rect, single_room


def _grid(w=4.0, h=3.0):
    fp = single_room(rect(0, 0, w, h), door=((1.0, 0.0), (1.9, 0.0)))
    return NavGrid(fp, RoomSpace(fp, fp.rooms[0]))


def _box(x0, y0, x1, y1, yaw=0.0):
    return rect_corners([((x0 + x1) / 2, (y0 + y1) / 2)], (x1 - x0, y1 - y0), [yaw])[0]


def _walk_from_scratch(nav: NavGrid, radius: float) -> np.ndarray:
    """The walkable cells as a distance transform of the furnished room gives them."""
    blocked = np.zeros_like(nav.base_free)
    for o in nav.obstacles:
        blocked[o.cells.window] |= o.cells.mask
    return ndimage.distance_transform_edt(nav.base_free & ~blocked) * nav.cell > radius


@pytest.mark.parametrize("seed", range(6))
def test_walk_kept_up_to_date_equals_a_distance_transform(seed):
    rng = np.random.default_rng(seed)
    nav = _grid(5.0, 4.0)
    assert nav.radius == WALKWAY_RADIUS_M
    for i in range(8):
        x, y = rng.uniform(0.2, 4.8), rng.uniform(0.9, 3.8)
        w, d = rng.uniform(0.2, 1.5, 2)
        yaw = rng.uniform(-np.pi, np.pi) if i % 2 else 0.0  # square to the raster: a full block of cells
        corners = rect_corners([(x, y)], (w, d), [yaw])[0]
        nav.add(nav.obstacle(corners, reachable=True))
        assert np.array_equal(nav.walk, _walk_from_scratch(nav, WALKWAY_RADIUS_M))
        assert np.array_equal(nav.walk_a, _walk_from_scratch(nav, AGENT_RADIUS_M))


def test_set_blocked_starts_again_from_the_empty_room():
    nav = _grid()
    empty = nav.walk.copy()
    nav.add(nav.obstacle(_box(1.5, 1.0, 2.5, 2.0), reachable=True))
    assert not np.array_equal(nav.walk, empty)
    nav.set_blocked([])
    assert np.array_equal(nav.walk, empty) and nav.obstacles == []


def test_an_object_walled_in_is_reported_while_the_doors_stay_connected():
    nav = _grid()
    assert nav.radius is not None
    cabinet = nav.obstacle(_box(0.0, 2.5, 0.5, 3.0), reachable=True)  # top-left corner
    nav.add(cabinet)
    assert nav.unreached() == [] and nav.ok()
    nav.add(nav.obstacle(_box(0.0, 1.9, 1.2, 2.5), reachable=True))  # a wardrobe right below it
    assert nav.unreached() == [cabinet]  # the doors still share a component with the room
    assert not nav.ok()
    nav.waived.append(cabinet)
    assert nav.ok()


def test_an_object_out_of_reach_need_not_be_reached_when_not_asked():
    nav = _grid()
    nav.add(nav.obstacle(_box(0.0, 2.5, 0.5, 3.0), reachable=False))
    nav.add(nav.obstacle(_box(0.0, 1.9, 1.2, 2.5), reachable=True))
    assert nav.ok()


def test_a_room_cut_in_two_leaves_the_objects_beyond_out_of_reach():
    nav = _grid()
    desk = nav.obstacle(_box(1.5, 2.4, 2.7, 3.0), reachable=True)
    nav.add(desk)
    nav.add(nav.obstacle(_box(0.0, 1.3, 4.0, 1.6), reachable=False))  # a wall of shelves across
    assert nav.unreached() == [desk]  # the door alone still reaches the near half


def test_an_obstacle_in_the_doorway_blocks_the_door():
    nav = _grid()
    nav.add(nav.obstacle(_box(0.6, 0.0, 2.3, 0.4), reachable=False))
    assert nav.unreached() is None and not nav.ok()


def _partition(labels: np.ndarray, walk: np.ndarray) -> set[frozenset[int]]:
    """The components of the walkable cells as sets of flat cell indices."""
    flat = labels.ravel()
    cells = np.flatnonzero(walk)
    out: dict[int, set[int]] = {}
    for c in cells.tolist():
        out.setdefault(int(flat[c]), set()).add(c)
    assert 0 not in out  # a walkable cell always has a component
    return {frozenset(v) for v in out.values()}


def _random_obstacle(nav: NavGrid, rng: np.random.Generator, w: float, h: float):
    x, y = rng.uniform(0.0, w), rng.uniform(0.0, h)
    size = rng.uniform(0.2, 1.6, 2)
    yaw = rng.choice([0.0, np.pi / 2, rng.uniform(-np.pi, np.pi)])
    return nav.obstacle(rect_corners([(x, y)], size, [yaw])[0], reachable=bool(rng.random() < 0.8))


@pytest.mark.parametrize("seed", range(8))
def test_components_kept_up_to_date_equal_labelling_the_whole_raster(seed):
    """Obstacles added one by one (some taken back through state/load): the components kept on
    a window round each obstacle are those of the whole raster, and what is reported out of
    reach is what a grid rebuilt from scratch reports."""
    rng = np.random.default_rng(seed)
    w, h = 5.0, 4.0
    nav = _grid(w, h)
    for _ in range(25):
        before = nav.state()
        nav.add(_random_obstacle(nav, rng, w, h))
        got = nav.unreached()
        fresh = _grid(w, h)
        for o in nav.obstacles:
            fresh.add(o)
        fresh._labels = fresh._labels_a = None  # labelled whole
        want = fresh.unreached()
        assert (got is None) == (want is None)
        if got is not None and want is not None:
            assert set(got) == set(want)
        if nav._labels is not None:
            assert _partition(nav._labels, nav.walk) == _partition(ndimage.label(nav.walk)[0], nav.walk)
        if nav.walk_a is not None and nav._labels_a is not None:
            assert _partition(nav._labels_a, nav.walk_a) == _partition(ndimage.label(nav.walk_a)[0], nav.walk_a)
        if got is None or rng.random() < 0.3:  # taken back, as the layout does with a pose that fails
            nav.load(before)


@pytest.mark.parametrize("seed", range(6))
def test_an_object_sure_to_be_out_of_reach_is_out_of_reach_once_added(seed):
    rng = np.random.default_rng(seed)
    w, h = 5.0, 4.0
    nav = _grid(w, h)
    sure = 0
    for _ in range(40):
        obs = _random_obstacle(nav, rng, w, h)
        before = nav.state()
        said = nav.surely_unreached(obs)
        nav.add(obs)
        got = nav.unreached()
        if said:
            sure += 1
            assert got is None or obs in got
        if got is None or got:
            nav.load(before)
    assert sure  # the check was put to the test


def test_an_obstacle_made_again_for_the_same_footprint_is_the_same():
    nav = _grid()
    corners = _box(1.0, 1.0, 2.0, 1.5)
    assert nav.obstacle(corners, reachable=True) is nav.obstacle(corners.copy(), reachable=True)
    assert nav.obstacle(corners, reachable=False) is not nav.obstacle(corners, reachable=True)


def test_a_room_cut_in_two_on_the_window_round_the_obstacle_is_labelled_in_two():
    nav = _grid()
    desk = nav.obstacle(_box(1.5, 2.4, 2.7, 3.0), reachable=True)
    nav.add(desk)
    assert nav.unreached() == []  # the components labelled: the next obstacle updates them
    nav.add(nav.obstacle(_box(0.0, 1.3, 4.0, 1.6), reachable=False))
    assert nav._labels is None or _partition(nav._labels, nav.walk) == _partition(
        ndimage.label(nav.walk)[0], nav.walk)
    assert nav.unreached() == [desk]


def test_labels_looked_for_among_a_few_are_found_as_isin_finds_them():
    from anyhome.navgrid import SMALL_SET, _in

    rng = np.random.default_rng(0)
    a = rng.integers(0, 30, 500).astype(np.int32)
    for n in (0, 1, 2, SMALL_SET, SMALL_SET + 3):
        b = np.unique(rng.integers(0, 30, n)).astype(np.int32)
        assert np.array_equal(_in(a, b), np.isin(a, b))
