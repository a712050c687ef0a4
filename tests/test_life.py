"""Levanov et al. (2015) resource methods: hand-computed values, monotonicity, hard cases, errors."""

import math

import numpy as np
import pytest

from stackup.life import ALPHA_SCUFFING, alpha, levanov_method1, levanov_method2


def test_method1_against_hand_computation():
    # h_min = 2.5 um, h_cr = 1.9 um, n = -2: beta = 1 + (2.5/1.9)^-2 = 1.577600...
    r = levanov_method1(2.5e-6)
    beta = 1 + (2.5 / 1.9) ** -2
    assert float(r.beta) == pytest.approx(beta, rel=1e-14)
    assert float(r.life) == pytest.approx((30e-6 / 1e-13) ** (1 / beta), rel=1e-12)
    assert float(r.life) == pytest.approx(2.3628e5, rel=1e-3)  # exp(19.51929 / 1.5776) by hand


def test_method1_paper_range_of_n():
    # n = -2.5 at h_min = 3.5 um: beta = 1 + (3.5/1.9)^-2.5
    r = levanov_method1(3.5e-6, n=-2.5)
    assert float(r.beta) == pytest.approx(1 + (3.5 / 1.9) ** -2.5)
    assert float(r.life_hours) == pytest.approx(math.exp(math.log(3e8) / float(r.beta)) / 3600)


def test_method1_monotone_in_h_min_and_bounded():
    h = np.geomspace(0.05e-6, 100e-6, 200)
    r = levanov_method1(h)
    assert np.all(np.diff(r.life) > 0) and np.all(np.diff(r.beta) < 0)
    assert r.life[-1] < 30e-6 / 1e-13 and r.life[-1] > 0.99 * 30e-6 / 1e-13


def test_method1_vanishing_film_does_not_overflow():
    r = levanov_method1(np.array([1e-30, 1e-300]))
    assert np.all(np.isfinite(r.life)) and np.all(r.life >= 1.0)


@pytest.mark.parametrize("kw, message", [
    (dict(h_min=0.0), "h_min: 0.0 is not valid; must be > 0"),
    (dict(h_min=-1e-6), "h_min: -1e-06 is not valid; must be > 0"),
    (dict(h_min=1e-6, wear_rate=0.0), "wear_rate: 0.0 is not valid; must be > 0"),
    (dict(h_min=np.nan), "h_min: nan is not a finite number"),
])
def test_method1_bad_input(kw, message):
    h = kw.pop("h_min")
    with pytest.raises(ValueError, match=message):
        levanov_method1(h, **kw)


def test_alpha_share_of_cycle_below_critical():
    h = np.array([[1.0, 2.0, 3.0, 1.5], [5.0, 5.0, 5.0, 5.0]]) * 1e-6
    np.testing.assert_allclose(alpha(h), [0.5, 0.0])
    assert ALPHA_SCUFFING == 0.2


def test_method2_accumulates_only_below_critical():
    h = np.array([1.0, 3.0, 1.5, 4.0]) * 1e-6
    p = np.full(4, 50e6)
    beta_c = np.full(4, 0.2)
    r = levanov_method2(h, p, beta_c, bearing_radius=0.0475, cycle_time=0.06)
    per_step = 7e-12 * 50e6**0.0511 * 2 * 0.2 * 0.0475
    assert float(r.wear_rate) == pytest.approx(2 * per_step / 0.06, rel=1e-12)
    assert float(r.life) == pytest.approx(30e-6 / (2 * per_step / 0.06), rel=1e-12)
    never = levanov_method2(h + 10e-6, p, beta_c, bearing_radius=0.0475, cycle_time=0.06)
    assert np.isinf(never.life)
