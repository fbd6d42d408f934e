"""Dog-leg stairs (anyhome.floorplan.stairs): risers, goings and the box of two flights."""

from __future__ import annotations

import pytest

from anyhome.floorplan.stairs import (
    FLIGHT_WIDTH_M,
    GOING_M,
    RISER_MAX_M,
    STRIP_M,
    dogleg,
    dogleg_in_box,
    is_dogleg_box,
)

RISES_M = [2.6, 2.9, 3.0, 3.2, 3.5, 4.2, 4.7]
"""Floor-to-floor heights of storeys (rooms of 2.4 to 4.5 m and a 0.2 m slab)."""


@pytest.mark.parametrize("rise", RISES_M)
def test_risers_at_most_019_and_goings_at_least_025(rise):
    d = dogleg(rise)
    assert d.riser_m <= RISER_MAX_M + 1e-9 and d.riser_m <= 0.19 + 1e-9
    assert d.riser_m >= 0.15  # no more risers than the rise needs
    assert d.going_m >= 0.25 - 1e-9
    assert d.first_risers + d.second_risers == d.risers
    assert abs(d.risers * d.riser_m - rise) < 1e-9


@pytest.mark.parametrize("rise", RISES_M)
def test_box_holds_both_flights_and_the_half_landing(rise):
    d = dogleg(rise)
    assert d.width_m >= 2 * FLIGHT_WIDTH_M
    assert d.length_m >= (d.first_risers - 1) * d.going_m + d.landing_m - 1e-9
    assert d.length_m >= (d.second_risers - 1) * d.going_m + d.landing_m - 1e-9
    assert d.landing_m >= FLIGHT_WIDTH_M  # a half landing as deep as a flight is wide
    assert is_dogleg_box(d.length_m, d.width_m)


def test_a_storey_of_29_m_fits_a_compact_stairwell():
    """A 2.9 m storey: 16 risers of 0.181 m, a box of 2.6 x 1.75 m; with the strip at its
    foot the stairwell needs 3.5 x 1.75 m (6.1 m2), not the 12.5 m2 of a straight flight."""
    d = dogleg(2.9)
    assert d.risers == 16
    assert (d.length_m + STRIP_M) * d.width_m < 6.5


def test_a_longer_box_stretches_the_goings_never_shrinks_them():
    d = dogleg(2.9)
    assert dogleg_in_box(d.length_m, d.width_m, 2.9).going_m == pytest.approx(GOING_M)
    longer = dogleg_in_box(d.length_m + 0.35, d.width_m, 2.9)
    assert longer.going_m > GOING_M and longer.risers == d.risers
    assert dogleg_in_box(d.length_m - 0.3, d.width_m, 2.9).going_m == pytest.approx(GOING_M)


def test_a_narrow_box_is_a_straight_flight():
    assert not is_dogleg_box(3.2, 1.0)  # the objects.yaml staircase
    assert is_dogleg_box(2.6, 1.75)


def test_no_rise_is_refused():
    with pytest.raises(ValueError):
        dogleg(0.0)
