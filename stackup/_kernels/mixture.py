r"""EM of two-normal mixtures, one row of readings at a time (numba): the bootstrap of a process fit refits a mixture
to each of a thousand resamples.

The readable statement is :class:`stackup.measure.models.MixtureModel`; ``tests/measure/test_mixture_kernel.py``
holds the numpy twin (every row at once) this kernel must match. Each row's parameters are
:math:`(w, \mu_1, \sigma_1, \mu_2, \sigma_2)`; an EM step gives the responsibilities
:math:`r_{1i} = w\,\phi_1(x_i) / (w\,\phi_1(x_i) + (1 - w)\,\phi_2(x_i))` and the weighted means, spreads (kept
above ``floor``) and share (kept within ``[min_weight, 1 - min_weight]``); SQUAREM (Varadhan and Roland 2008,
scheme S3) extrapolates two steps in the unconstrained parameters (logit weight, means, log spreads) and keeps
the step from the extrapolated point where the likelihood there is not below the first plain step's. A row stops when its
log-likelihood rises by less than ``tol`` (relative).
"""

import math

import numpy as np
from numba import njit

_LOG_SQRT_2PI = 0.5 * math.log(2.0 * math.pi)
#: Readings whose factors 1 + e (each at most 2) are multiplied before one log is taken.
BLOCK = 64


@njit(cache=True)
def _step(x, m, p, floor, min_weight, out, r1):
    """One EM step of one row ``x`` (mask ``m``) from ``p`` into ``out`` (``r1``: work, the first component's
    responsibilities); returns the log-likelihood at ``p``."""
    w, m1, s1, m2, s2 = p[0], p[1], p[2], p[3], p[4]
    c1 = math.log(w) - math.log(s1) - _LOG_SQRT_2PI
    c2 = math.log1p(-w) - math.log(s2) - _LOG_SQRT_2PI
    n1 = n2 = sx1 = sx2 = ll = 0.0
    # each reading's log-likelihood is the larger component's term plus log(1 + e), e = exp(-|l2 - l1|) <= 1: the
    # logs of (1 + e) are summed as the log of their product, taken every BLOCK readings (at most 2**BLOCK)
    product = 1.0
    for i in range(x.size):
        z1, z2 = (x[i] - m1) / s1, (x[i] - m2) / s2
        l1, l2 = c1 - 0.5 * z1 * z1, c2 - 0.5 * z2 * z2
        if l2 <= l1:
            e = math.exp(l2 - l1)
            share, larger = 1.0 / (1.0 + e), l1
        else:
            e = math.exp(l1 - l2)
            share, larger = e / (1.0 + e), l2
        r1[i] = share * m[i]
        n1 += r1[i]
        n2 += m[i] - r1[i]
        sx1 += r1[i] * x[i]
        sx2 += (m[i] - r1[i]) * x[i]
        if m[i] > 0.0:
            ll += larger * m[i]
            product *= 1.0 + e
        if i % BLOCK == BLOCK - 1:
            ll += math.log(product)
            product = 1.0
    ll += math.log(product)
    n1, n2 = max(n1, 1e-12), max(n2, 1e-12)
    mu1, mu2 = sx1 / n1, sx2 / n2
    v1 = v2 = 0.0
    for i in range(x.size):
        v1 += r1[i] * (x[i] - mu1) ** 2
        v2 += (m[i] - r1[i]) * (x[i] - mu2) ** 2
    out[0] = min(max(n1 / (n1 + n2), min_weight), 1.0 - min_weight)
    out[1], out[2] = mu1, max(math.sqrt(v1 / n1), floor)
    out[3], out[4] = mu2, max(math.sqrt(v2 / n2), floor)
    return ll


@njit(cache=True, inline="always")
def _free(p, q):
    """The unconstrained parameters of ``p``: logit weight, means, log spreads."""
    q[0] = math.log(p[0] / (1.0 - p[0]))
    q[1], q[2], q[3], q[4] = p[1], math.log(p[2]), p[3], math.log(p[4])


@njit(cache=True)
def _extrapolated(p, p1, p2, floor, min_weight, q0, q1, q2, jump):
    """SQUAREM's step (S3) from ``p`` along its two EM steps ``p1``, ``p2`` into ``jump``, back in the constrained
    parameters and within their bounds; False where it is not finite."""
    _free(p, q0)
    _free(p1, q1)
    _free(p2, q2)
    rr = vv = 0.0
    for k in range(5):
        r, v = q1[k] - q0[k], q2[k] - 2.0 * q1[k] + q0[k]
        rr += r * r
        vv += v * v
    alpha = min(-math.sqrt(rr / max(vv, 1e-300)), -1.0)
    for k in range(5):
        r, v = q1[k] - q0[k], q2[k] - 2.0 * q1[k] + q0[k]
        jump[k] = q0[k] - 2.0 * alpha * r + alpha * alpha * v
    jump[0] = 1.0 / (1.0 + math.exp(-jump[0]))
    jump[2], jump[4] = math.exp(jump[2]), math.exp(jump[4])
    finite = True
    for k in range(5):  # before the bounds, which would make a NaN finite
        finite = finite and math.isfinite(jump[k])
    jump[0] = min(max(jump[0], min_weight), 1.0 - min_weight)
    jump[2], jump[4] = max(jump[2], floor), max(jump[4], floor)
    return finite


@njit(cache=True)
def _squarem(x, m, p, floor, min_weight, iterations, tol):
    """SQUAREM iterations of one row from ``p`` (updated in place) until its likelihood stops rising."""
    p1, p2, p3, jump = np.empty(5), np.empty(5), np.empty(5), np.empty(5)
    q0, q1, q2, r1 = np.empty(5), np.empty(5), np.empty(5), np.empty(x.size)
    for _ in range(iterations):
        ll0 = _step(x, m, p, floor, min_weight, p1, r1)
        ll1 = _step(x, m, p1, floor, min_weight, p2, r1)
        ok = _extrapolated(p, p1, p2, floor, min_weight, q0, q1, q2, jump)
        if not ok:
            jump[:] = p2
        ll_jump = _step(x, m, jump, floor, min_weight, p3, r1)
        p[:] = p3 if ok and math.isfinite(ll_jump) and ll_jump >= ll1 else p2
        if not abs(ll1 - ll0) > tol * max(1.0, abs(ll1)):
            return


@njit(cache=True)
def em(x, m, p, floor, min_weight, iterations, tol):
    """EM of two-normal mixtures on every row of ``x`` (mask ``m``, 1 or 0) from ``p`` (rows, 5), updated in place;
    ``floor`` (rows,) the smallest spread of each row, ``min_weight`` the smallest share of a component."""
    for row in range(x.shape[0]):
        _squarem(x[row], m[row], p[row], floor[row], min_weight, iterations, tol)
