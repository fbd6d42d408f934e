"""Free space of one room: the vectorized pose check against a plain reference, kept up
to date as objects are placed and taken back."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from anyhome.geometry import footprint_corners
from anyhome.house import HouseObject
from anyhome.space import (
    CEILING_GAP_M,
    DOOR_MARGIN_M,
    EPS_COLLIDE_M,
    INSIDE_TOL_M,
    VIEW_CLEAR_M,
    Placed,
    RoomSpace,
    overlap_above,
    rect_corners,
    sat_overlap,
)
from tests.layout.helpers import l_shape, rect, single_room


def _reference_valid(sp: RoomSpace, corners, z0, z1, floor, doors=True, layer=False) -> np.ndarray:
    """RoomSpace.valid written plainly: every test on every pose."""
    n = len(corners)
    z0, z1 = np.broadcast_to(z0, (n,)).astype(float), np.broadcast_to(z1, (n,)).astype(float)
    lo, hi = corners.min(1), corners.max(1)
    ok = np.all(lo >= sp.bmin - INSIDE_TOL_M, 1) & np.all(hi <= sp.bmax + INSIDE_TOL_M, 1)
    ok &= z1 <= (sp.height if floor else sp.height - CEILING_GAP_M) + 1e-9
    pin = shapely.contains_xy(sp.buf, corners[..., 0], corners[..., 1]).all(1)
    if not sp.convex:
        pin &= ~sp._vertex_inside(corners)
    ok &= pin
    if doors and len(sp.door_zones):
        ok &= ~overlap_above(corners, sp.door_zones, -DOOR_MARGIN_M, inclusive=True).any(1)
    if floor and not layer and sp.keep_clear:
        ok &= ~((z1 > VIEW_CLEAR_M) & overlap_above(corners, np.stack(sp.keep_clear), EPS_COLLIDE_M).any(1))
    placed = [p for p in sp.placed if p.layer == layer]
    if placed:
        pz0, pz1 = np.array([p.z0 for p in placed]), np.array([p.z1 for p in placed])
        zov = np.minimum(z1[:, None], pz1[None]) - np.maximum(z0[:, None], pz0[None])
        ok &= ~overlap_above(corners, np.stack([p.corners for p in placed]), EPS_COLLIDE_M,
                             pairs=zov > EPS_COLLIDE_M).any(1)
    return ok


def _placed(corners, z0, z1, layer=False) -> Placed:
    obj = HouseObject(id=f"r1-o-{np.random.default_rng().integers(1e9)}", room="r1", name="o", category="table",
                      position=(0.0, 0.0, float(z0)), size=(1.0, 1.0, float(z1 - z0)), yaw=0.0, support="floor")
    return Placed(obj, corners, float(z0), float(z1), True, None, layer)


def _poses(rng, n, w, h, size):
    xy = rng.uniform(-0.3, max(w, h) + 0.3, (n, 2))
    xy[: n // 3] = np.round(xy[: n // 3] / 0.05) * 0.05  # on a grid: bounds touching others exactly
    yaw = rng.choice([0.0, np.pi / 2, np.pi, -np.pi / 2, rng.uniform(-np.pi, np.pi)], n)
    return rect_corners(xy, size, yaw)


@pytest.mark.parametrize("outline", [rect(0, 0, 5, 4), l_shape(6, 5, 2.5, 2)])
@pytest.mark.parametrize("seed", range(3))
def test_valid_and_clearance_equal_the_plain_reference_as_objects_come_and_go(outline, seed):
    rng = np.random.default_rng(seed)
    fp = single_room(outline)
    sp = RoomSpace(fp, fp.rooms[0])
    for step in range(30):
        size = rng.uniform(0.3, 1.8, 2)
        corners = _poses(rng, 400, 6.0, 5.0, size)
        z0 = rng.choice([0.0, 0.0, 1.2])
        z1 = z0 + rng.uniform(0.3, 2.0)
        for floor, doors, layer in ((True, True, False), (False, True, False), (True, False, False),
                                    (True, True, True)):
            got = sp.valid(corners, z0, z1, floor, doors=doors, layer=layer)
            assert np.array_equal(got, _reference_valid(sp, corners, z0, z1, floor, doors, layer))
        others = [p.corners for p in sp.placed if p.floor and not p.layer] + list(sp.door_zones)
        for cap in (0.5, 1.0):
            want = np.minimum(cap, np.maximum(0.0, -sat_overlap(corners, np.stack(others)).max(1)))
            assert np.array_equal(sp.clearance(corners, cap), want)
        free = np.flatnonzero(sp.valid(corners, z0, z1, True))
        if free.size and rng.random() < 0.7:
            sp.placed.append(_placed(corners[free[0]], z0, z1, layer=bool(rng.random() < 0.2)))
        elif sp.placed:
            del sp.placed[int(rng.integers(len(sp.placed))):]  # taken back, as a restore does
        if step == 10:
            sp.keep_clear.append(rect_corners([(2.0, 2.0)], (0.6, 3.0), [0.3])[0])


def test_near_follows_the_objects_placed_and_taken_back():
    fp = single_room(rect(0, 0, 5, 4))
    sp = RoomSpace(fp, fp.rooms[0])
    a = _placed(rect_corners([(1.0, 1.0)], (0.5, 0.5), [0.0])[0], 0.0, 1.0)
    b = _placed(rect_corners([(3.0, 3.0)], (0.5, 0.5), [0.0])[0], 0.0, 1.0)
    sp.placed.append(a)
    assert sp.near(np.array([0.5, 0.5]), np.array([1.5, 1.5])) == [a]
    sp.placed.append(b)
    assert sp.near(np.array([0.0, 0.0]), np.array([5.0, 4.0])) == [a, b]
    sp.placed[:] = [b]  # a different object first: nothing kept from before applies
    assert sp.near(np.array([0.5, 0.5]), np.array([1.5, 1.5])) == []
    assert sp.near(np.array([2.5, 2.5]), np.array([3.5, 3.5])) == [b]


def test_rect_corners_of_one_size_or_many_or_one_box_are_the_same_and_match_the_contract():
    rng = np.random.default_rng(0)
    xy = rng.uniform(0, 5, (50, 2))
    yaw = rng.uniform(-np.pi, np.pi, 50)
    one = rect_corners(xy, (1.2, 0.7), yaw)
    many = rect_corners(xy, np.tile([1.2, 0.7], (50, 1)), yaw)
    assert np.array_equal(one, many)
    assert np.array_equal(rect_corners(xy[3], (1.2, 0.7), [yaw[3]])[0], one[3])
    for k in range(50):  # one box of one size (the scalar path) as among many, bit for bit
        alone = rect_corners(xy[k][None], (1.2, 0.7), [float(yaw[k])])
        assert alone.shape == (1, 4, 2) and np.array_equal(alone[0], one[k])
    for k in range(50):
        assert np.allclose(one[k], footprint_corners((*xy[k], 0.0), (1.2, 0.7, 1.0), yaw[k]), atol=1e-12)


def test_a_placed_objects_table_row_is_made_once_and_stacks_as_the_objects_do():
    from anyhome.space import (
        _ALIGNED,
        _HI,
        _INCL,
        _LO,
        _NEAR,
        _PAIR_SLACK_M,
        _SIGHT,
        _THR,
        _Z0,
        _Z1,
        _ZONE,
        EPS_COLLIDE_M,
        _aligned,
        _blocker_rows,
    )

    a = _placed(rect_corners([(1.0, 1.0)], (0.5, 0.8), [0.0])[0], 0.0, 1.0)
    b = _placed(rect_corners([(3.0, 2.0)], (0.5, 0.8), [0.4])[0], 0.5, 1.5)
    assert a.rows() is a.rows()
    c = np.stack([a.corners, b.corners])
    corners, f, flags = _blocker_rows([a, b])
    assert np.array_equal(corners, c)
    assert np.array_equal(f[:, _LO:_LO + 2], c.min(1)) and np.array_equal(f[:, _HI:_HI + 2], c.max(1))
    assert np.array_equal(flags[:, _ALIGNED], _aligned(c)) and flags[:, _ALIGNED].tolist() == [True, False]
    assert f[:, _Z0].tolist() == [0.0, 0.5] and f[:, _Z1].tolist() == [1.0, 1.5]
    assert f[:, _THR].tolist() == [EPS_COLLIDE_M] * 2 and not flags[:, [_INCL, _ZONE, _SIGHT]].any()
    g = _PAIR_SLACK_M - EPS_COLLIDE_M  # bounds this close overlap by the collision tolerance, less the slack
    assert np.array_equal(f[:, _NEAR:], np.stack([c.min(1)[:, 0] - g, c.max(1)[:, 0] + g,
                                                  c.min(1)[:, 1] - g, c.max(1)[:, 1] + g], 1))
    assert all(np.array_equal(x, y[:1]) for x, y in zip(_blocker_rows([a]), (corners, f, flags), strict=True))
