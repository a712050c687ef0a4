"""Importance-sampled clearance tails against plain Monte Carlo on the same model."""

import pytest

from stackup.tail import clearance_tail


def test_importance_sampling_agrees_with_plain_mc_where_mc_reaches():
    mc = clearance_tail("iso-example", "iso13778-3", n_bearings=300_000, threshold=57e-6, tilt=0.0, seed=3)
    isamp = clearance_tail("iso-example", "iso13778-3", n_bearings=300_000, threshold=57e-6, tilt=1.5, seed=4)
    assert abs(mc.share - isamp.share) < 2.5 * (mc.standard_error**2 + isamp.standard_error**2) ** 0.5


def test_importance_sampling_shrinks_the_error_of_a_ppm_tail():
    mc = clearance_tail("iso-example", "iso13778-3", n_bearings=200_000, threshold=61e-6, tilt=0.0, seed=5)
    isamp = clearance_tail("iso-example", "iso13778-3", n_bearings=200_000, threshold=61e-6, tilt=1.5, seed=6)
    assert isamp.standard_error < 0.5 * mc.standard_error
    assert abs(mc.share - isamp.share) < 2.5 * (mc.standard_error**2 + isamp.standard_error**2) ** 0.5


def test_lower_tail_and_bad_input():
    low = clearance_tail("iso-example", "iso13778-4", n_bearings=50_000, side="lower", tilt=1.0, seed=1)
    assert 0 < low.share < 1
    with pytest.raises(ValueError, match="side: 'middle' is not one of 'upper', 'lower'"):
        clearance_tail("iso-example", "iso13778-4", n_bearings=10, side="middle")
    with pytest.raises(ValueError, match="tilt: -1.0 is outside"):
        clearance_tail("iso-example", "iso13778-4", n_bearings=10, tilt=-1.0)
