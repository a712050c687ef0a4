"""Monte Carlo intervals: coverage on cases with a known answer."""

import numpy as np
import pytest
from scipy import stats

from stackup.stats import proportion_ci, quantile_ci, control_variate_mean, control_variate_quantile


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


def _two_models(rng, n, big_n):
    """A skewed accurate model Y (lognormal, mean e^{0.5·0.3²}) and a cheap one X = 1.3 Y + noise: biased, correlated."""
    y_all = rng.lognormal(0.0, 0.3, big_n)
    x_all = 1.3 * y_all + rng.normal(0.0, 0.08, big_n)
    shared = rng.choice(big_n, n, replace=False)
    return y_all[shared], x_all[shared], x_all, y_all


def test_control_variate_mean_covers_the_accurate_mean_and_removes_the_cheap_bias():
    true = np.exp(0.5 * 0.3**2)
    hits, widths, plain = 0, [], []
    for seed in range(200):
        y, x, x_all, _ = _two_models(np.random.default_rng(seed), 60, 6000)
        e = control_variate_mean(y, x, x_all)
        hits += e.lower <= true <= e.upper
        widths.append(e.upper - e.lower)
        plain.append(2 * 1.96 * y.std(ddof=1) / np.sqrt(y.size))
        assert e.cheap == pytest.approx(1.3 * true, rel=0.03)  # the cheap mean is 30 % off
    assert hits / 200 >= 0.90
    assert np.mean(widths) < 0.4 * np.mean(plain)  # rho ~ 0.97: the subsample is worth >6x its size


def test_control_variate_quantile_covers_the_accurate_median():
    true = 1.0  # the lognormal's median
    hits = 0
    for seed in range(200):
        y, x, x_all, _ = _two_models(np.random.default_rng(1000 + seed), 80, 4000)
        e = control_variate_quantile(y, x, x_all, 0.5)
        hits += e.lower <= true <= e.upper
        assert e.cheap == pytest.approx(1.3, rel=0.05)
    assert hits / 200 >= 0.90


def test_control_variate_with_an_uncorrelated_cheap_model_is_the_subsample_mean():
    rng = np.random.default_rng(3)
    y, x_all = rng.normal(5.0, 1.0, 50), rng.normal(0.0, 1.0, 500)
    e = control_variate_mean(y, x_all[:50] * 0 + rng.normal(0, 1, 50), x_all)
    assert abs(e.estimate - y.mean()) < 0.1
    assert e.standard_error == pytest.approx(y.std(ddof=1) / np.sqrt(50), rel=0.05)


def test_control_variate_drops_failed_solves_and_refuses_too_few_pairs():
    y = np.array([1.0, np.nan, 2.0, 3.0, 4.0])
    x = np.array([1.1, 2.0, np.nan, 3.2, 4.1])
    e = control_variate_mean(y, x, np.r_[x, 5.0, 6.0])
    assert e.n_accurate == 3 and e.n_cheap == 6
    with pytest.raises(ValueError, match="at least 3 finite pairs"):
        control_variate_mean(y[:2], x[:2], x)
    with pytest.raises(ValueError, match="same samples"):
        control_variate_mean(y, x[:4], x)


def test_control_variate_mean_with_a_handful_of_pairs_still_covers():
    # a study checks a few engines per scheme and position: Student's interval on n - 2 degrees of freedom holds
    true = np.exp(0.5 * 0.3**2)
    hits = 0
    for seed in range(400):
        y, x, x_all, _ = _two_models(np.random.default_rng(1000 + seed), 5, 300)
        e = control_variate_mean(y, x, x_all)
        hits += e.lower <= true <= e.upper
    assert hits / 400 >= 0.92
