"""Monte Carlo intervals: coverage on cases with a known answer."""

import numpy as np
import pytest
from scipy import stats

from stackup.stats import proportion_ci, quantile_ci


def test_ppm_interval_covers_a_known_tail_probability():
    # share of a normal clearance beyond 3 sigma: p = 1.35e-3 exactly; 400 repeated studies of 20 000 bearings
    rng = np.random.default_rng(7)
    p = stats.norm.sf(3.0)
    hits = 0
    for _ in range(400):
        k = np.count_nonzero(rng.standard_normal(20_000) > 3.0)
        _, lo, hi = proportion_ci(k, 20_000)
        hits += lo <= p <= hi
    assert hits / 400 >= 0.93  # nominal 95 %, Clopper-Pearson is conservative


def test_quantile_interval_covers_a_known_quantile():
    rng = np.random.default_rng(8)
    q = stats.norm.ppf(0.00135)
    hits = 0
    for _ in range(300):
        x = rng.standard_normal(20_000)
        _, lo, hi = quantile_ci(x, 0.00135)
        hits += lo <= q <= hi
    assert hits / 300 >= 0.93


def test_zero_count_and_empty_sample():
    est, lo, hi = proportion_ci(0, 1000)
    assert est == 0 and lo == 0 and hi == pytest.approx(1 - 0.025 ** (1 / 1000), rel=1e-6)
    assert all(np.isnan(v) for v in proportion_ci(0, 0))
    assert all(np.isnan(v) for v in quantile_ci([], 0.5))
