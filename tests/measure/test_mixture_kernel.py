"""The mixture EM kernel (stackup._kernels.mixture) equals its numpy twin: every row at once, as the process fit's
bootstrap ran it before the kernel, on resampled readings of one and of two machines, masked rows, a component at
its smallest share and a spread at the gauge's floor."""

import numpy as np
import pytest
from scipy import special

from stackup.measure.models import MIXTURE_MIN_SPREAD, MIXTURE_MIN_WEIGHT, _em, _mixture_logpdf
from stackup.measure.models import _row_moments as row_moments

LOG_SQRT_2PI = 0.5 * np.log(2.0 * np.pi)


def normal_logpdf(x, mean, sigma):
    return -0.5 * ((x - mean) / sigma) ** 2 - np.log(sigma) - LOG_SQRT_2PI


def em_step(x, m, p, floor):
    """One EM step of two-normal mixtures on rows of ``x`` (mask ``m``): new parameters, log-likelihood before."""
    w, m1, s1, m2, s2 = (p[:, k:k + 1] for k in range(5))
    l1 = np.log(w) + normal_logpdf(x, m1, s1)
    l2 = np.log1p(-w) + normal_logpdf(x, m2, s2)
    total = np.logaddexp(l1, l2)
    r1 = np.exp(l1 - total) * m
    r2 = m - r1
    n1 = np.maximum(r1.sum(axis=1, keepdims=True), 1e-12)
    n2 = np.maximum(r2.sum(axis=1, keepdims=True), 1e-12)
    mu1, mu2 = (r1 * x).sum(1, keepdims=True) / n1, (r2 * x).sum(1, keepdims=True) / n2
    sd1 = np.maximum(np.sqrt((r1 * (x - mu1) ** 2).sum(1, keepdims=True) / n1), floor)
    sd2 = np.maximum(np.sqrt((r2 * (x - mu2) ** 2).sum(1, keepdims=True) / n2), floor)
    share = np.clip(n1 / (n1 + n2), MIXTURE_MIN_WEIGHT, 1.0 - MIXTURE_MIN_WEIGHT)
    return np.concatenate([share, mu1, sd1, mu2, sd2], axis=1), (total * m).sum(axis=1)


def to_free(p):
    """Mixture parameters in unconstrained form: logit weight, means, log spreads."""
    return np.stack([special.logit(p[:, 0]), p[:, 1], np.log(p[:, 2]), p[:, 3], np.log(p[:, 4])], axis=-1)


def from_free(q):
    return np.stack([special.expit(q[:, 0]), q[:, 1], np.exp(q[:, 2]), q[:, 3], np.exp(q[:, 4])], axis=-1)


def em_twin(x, m, p, repeatability=0.0, iterations=300, tol=1e-9):
    """:func:`stackup.measure.models._em` in numpy, every row at once (the rows still rising stepped together)."""
    n, _, dev = row_moments(x, m)
    floor = np.hypot(MIXTURE_MIN_SPREAD * np.sqrt((dev * dev).sum(axis=1) / n), repeatability)[:, None]
    p = np.array(p, dtype=float)
    active = np.arange(x.shape[0])
    for _ in range(iterations):
        xa, ma, fa = x[active], m[active], floor[active]
        p1, ll0 = em_step(xa, ma, p[active], fa)
        p2, ll1 = em_step(xa, ma, p1, fa)
        q0, q1, q2 = to_free(p[active]), to_free(p1), to_free(p2)
        r, v = q1 - q0, q2 - 2.0 * q1 + q0
        alpha = -np.sqrt((r * r).sum(axis=1) / np.maximum((v * v).sum(axis=1), 1e-300))
        alpha = np.minimum(alpha, -1.0)[:, None]
        jump = from_free(q0 - 2.0 * alpha * r + alpha * alpha * v)
        jump[:, 0] = np.clip(jump[:, 0], MIXTURE_MIN_WEIGHT, 1.0 - MIXTURE_MIN_WEIGHT)
        jump[:, 2], jump[:, 4] = np.maximum(jump[:, 2], fa[:, 0]), np.maximum(jump[:, 4], fa[:, 0])
        ok = np.all(np.isfinite(jump), axis=1)
        jump[~ok] = p2[~ok]
        p3, ll_jump = em_step(xa, ma, jump, fa)
        keep = ok & np.isfinite(ll_jump) & (ll_jump >= ll1)
        p[active] = np.where(keep[:, None], p3, p2)
        moving = np.abs(ll1 - ll0) > tol * np.maximum(1.0, np.abs(ll1))
        active = active[moving]
        if active.size == 0:
            break
    swap = p[:, 1] > p[:, 3]
    p[swap] = np.stack([1.0 - p[swap, 0], p[swap, 3], p[swap, 4], p[swap, 1], p[swap, 2]], axis=-1)
    return p, (_mixture_logpdf(x, p) * m).sum(axis=1)


def resampled(readings, rows, rng, *, width=None):
    """``rows`` bootstrap resamples of ``readings`` (padded to ``width`` with masked zeros), as the fit draws them."""
    n = readings.size
    width = width or n
    x, m = np.zeros((rows, width)), np.zeros((rows, width))
    x[:, :n] = readings[rng.integers(0, n, size=(rows, n))]
    m[:, :n] = 1.0
    return x, m


def start(x, m):
    """A start as the fit gives one: the halves of each row split at its median."""
    n, mean, dev = row_moments(x, m)
    sd = np.sqrt((dev * dev).sum(axis=1) / n)
    return np.stack([np.full_like(mean, 0.5), mean - 0.5 * sd, 0.8 * sd, mean + 0.5 * sd, 0.8 * sd], -1)


RNG = np.random.default_rng(35)
CASES = {
    "one machine": RNG.normal(50.0095e-3, 2.0e-6, 300),  # the mixture's slowest case: two components alike
    "two machines": np.concatenate([RNG.normal(50.0065e-3, 1.4e-6, 165), RNG.normal(50.0115e-3, 1.6e-6, 135)]),
    "a few outliers": np.concatenate([RNG.normal(50.0095e-3, 1.0e-6, 290), RNG.normal(50.016e-3, 0.2e-6, 10)]),
}


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("repeatability", [0.0, 0.5e-6, 3e-6])  # the last puts the spreads at the gauge's floor
def test_kernel_em_equals_its_numpy_twin(case, repeatability):
    x, m = resampled(CASES[case], 40, np.random.default_rng(1), width=320)
    m[::7, 250:] = 0.0  # rows of fewer readings
    x = np.where(m > 0, x, 0.0)
    p, ll = _em(x, m, start(x, m), repeatability)
    twin, twin_ll = em_twin(x, m, start(x, m), repeatability)
    np.testing.assert_allclose(ll, twin_ll, rtol=1e-9)
    scale = np.array([1.0, 1e-6, 1e-6, 1e-6, 1e-6])  # the weight, and lengths to a thousandth of a micrometre
    swapped = np.stack([1.0 - twin[:, 0], twin[:, 3], twin[:, 4], twin[:, 1], twin[:, 2]], axis=-1)
    off = np.minimum(np.abs(p - twin) / scale, np.abs(p - swapped) / scale).max(axis=1)  # two alike components
    assert np.all(off < 1e-3), off                                                         # come in either order
    floor = np.hypot(MIXTURE_MIN_SPREAD * np.sqrt((row_moments(x, m)[2] ** 2).sum(1) / m.sum(1)), repeatability)
    assert np.all(p[:, [2, 4]] >= floor[:, None] * (1 - 1e-12))
    assert np.all((p[:, 0] >= MIXTURE_MIN_WEIGHT) & (p[:, 0] <= 1 - MIXTURE_MIN_WEIGHT))


def test_a_start_at_a_component_of_the_smallest_share_stays_within_the_bounds():
    x, m = resampled(CASES["a few outliers"], 10, np.random.default_rng(2))
    s = start(x, m)
    s[:, 0] = MIXTURE_MIN_WEIGHT
    p, ll = _em(x, m, s.copy())
    twin, twin_ll = em_twin(x, m, s.copy())
    np.testing.assert_allclose(ll, twin_ll, rtol=1e-9)
    assert np.all(np.isfinite(p)) and np.all(p[:, 1] <= p[:, 3])  # components ordered by mean
