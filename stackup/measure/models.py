r"""The candidate process models a measured dimension is fitted with, and what each needs.

Each model fits the *readings* (process plus gauge error) by maximum
likelihood, on every row of a padded array at once (``mask`` marking the
values: the data, or its bootstrap resamples or simulated samples), giving
the parameters and the log-likelihood of each row; it turns its reading parameters into
the *process* parameters by removing the gauge's repeatability :math:`R`, and
gives the process as a :mod:`stackup.tolerances` object and as the engine
file's ``process`` table.

====================  ====================================  ==================================
model                 reading parameters                    process (gauge removed)
====================  ====================================  ==================================
``normal``            mean, sigma                           :math:`\sigma_p^2 = \sigma^2 - R^2`
``skew-normal``       mean, sigma, skewness (centred)       :math:`\sigma_p^2 = \sigma^2 - R^2`,
                                                            :math:`\gamma_p = \gamma\,\sigma^3/\sigma_p^3`
``mixture``           weight, mean1, sigma1, mean2, sigma2  :math:`\sigma_{k,p}^2 = \sigma_k^2 - R^2`
``drift``             start, end, sigma                     :math:`\sigma_p^2 = \sigma^2 - R^2`
====================  ====================================  ==================================

The removal is exact for each family: a skew-normal plus an independent
normal error is a skew-normal with the same mean and third central moment
(Azzalini 2014, sec. 2.1), a normal mixture plus a normal error is a normal
mixture with each component widened, and the drift's error adds to its noise.
Where the gauge's error is larger than the spread a model sees, its process
parameters are NaN (the caller says why).

The drift is the engine file's ``tool-wear`` process: the mean moves
linearly over the sequence (or time) column, rescaled to the tool life
:math:`t \in [0, 1]` between its first and last value, ``start`` and ``end``
the means at both ends; its likelihood is that of the readings given their
place in the sequence.
"""

from __future__ import annotations

import numpy as np
from scipy import special

from .._kernels import mixture as _mixture
from ..tolerances import MAX_SKEWNESS, Mixture, Normal, SkewNormal, ToolWear

_LOG_SQRT_2PI = 0.5 * np.log(2.0 * np.pi)
#: Smallest component weight and process spread of the two-normal mixture, as shares of the values and of
#: their standard deviation: without them the likelihood grows without bound on one value, and a "machine" making
#: less than 5 % of the parts is not what the model stands for.
MIXTURE_MIN_WEIGHT, MIXTURE_MIN_SPREAD = 0.05, 0.05
#: Largest skewness the skew-normal fit starts from (its maximum likelihood lies inside the family's range).
_SKEW_START = 0.95 * MAX_SKEWNESS


def _masked(x, mask):
    x = np.atleast_2d(np.asarray(x, dtype=float))
    mask = np.ones(x.shape, bool) if mask is None else np.atleast_2d(mask)
    return np.where(mask, x, 0.0), mask.astype(float)


def _row_moments(x, m):
    n = m.sum(axis=1)
    mean = (x * m).sum(axis=1) / n
    dev = (x - mean[:, None]) * m
    return n, mean, dev


# --- skew-normal helpers -----------------------------------------------------------------------------------

def skew_direct(mean, sigma, skewness):
    """Direct parameters (alpha, xi, omega) of skew-normals given by mean, sigma, skewness (arrays)."""
    r = np.cbrt(2.0 * np.asarray(skewness, dtype=float) / (4.0 - np.pi))
    mu_z = r / np.sqrt(1.0 + r * r)
    delta = mu_z / np.sqrt(2.0 / np.pi)
    omega = sigma / np.sqrt(1.0 - mu_z * mu_z)
    return delta / np.sqrt(1.0 - delta * delta), mean - omega * mu_z, omega


def skew_centred(alpha, xi, omega):
    """Centred parameters (mean, sigma, skewness) of skew-normals given by alpha, xi, omega (arrays)."""
    delta = alpha / np.sqrt(1.0 + alpha * alpha)
    mu_z = np.sqrt(2.0 / np.pi) * delta
    sd_z = np.sqrt(1.0 - mu_z * mu_z)
    return xi + omega * mu_z, omega * sd_z, 0.5 * (4.0 - np.pi) * mu_z**3 / sd_z**3


def _skew_terms(x, m, theta):
    """Log-likelihood, gradient and Hessian of skew-normals theta = (xi, log omega, alpha) on rows of ``x``."""
    xi, eta, alpha = (theta[:, k:k + 1] for k in range(3))
    omega = np.exp(eta)
    z = (x - xi) / omega
    t = alpha * z
    log_cdf = special.log_ndtr(t)
    w = np.exp(-0.5 * t * t - _LOG_SQRT_2PI - log_cdf)  # phi(t) / Phi(t)
    dw = -w * (t + w)
    ll = np.sum(m * (np.log(2.0) - eta - _LOG_SQRT_2PI - 0.5 * z * z + log_cdf), axis=1)
    grad = np.stack([np.sum(m * (z - alpha * w), 1) / omega[:, 0], np.sum(m * (z * z - 1.0 - t * w), 1),
                     np.sum(m * z * w, 1)], axis=-1)
    a2 = alpha * alpha
    h = np.empty((x.shape[0], 3, 3))
    h[:, 0, 0] = np.sum(m * (a2 * dw - 1.0), 1) / omega[:, 0] ** 2
    h[:, 0, 1] = np.sum(m * (-2.0 * z + a2 * z * dw + alpha * w), 1) / omega[:, 0]
    h[:, 0, 2] = np.sum(m * (-w - t * dw), 1) / omega[:, 0]
    h[:, 1, 1] = np.sum(m * (-2.0 * z * z + t * w + t * t * dw), 1)
    h[:, 1, 2] = np.sum(m * (-z * w - t * z * dw), 1)
    h[:, 2, 2] = np.sum(m * z * z * dw, 1)
    h[:, 1, 0], h[:, 2, 0], h[:, 2, 1] = h[:, 0, 1], h[:, 0, 2], h[:, 1, 2]
    return ll, grad, h


#: Largest skew-normal shape the fit goes to (skewness 0.9949 of the family's 0.9953: a half-normal in practice).
_ALPHA_MAX = 40.0
#: Largest Newton step of the skew-normal fit in (xi, log omega, alpha) of standardised data.
_STEP_MAX = np.array([0.5, 0.5, 2.0])


def _newton_rows(u, m, theta, iterations):
    """Damped Newton ascent of the skew-normal log-likelihood, on the rows not yet converged only."""
    ll, grad, hess = _skew_terms(u, m, theta)
    active = np.arange(u.shape[0])
    for _ in range(iterations):
        th, g, h = theta[active], grad[active], hess[active]
        # modified Newton: -H shifted until positive definite, so every step climbs
        size = np.abs(np.diagonal(h, axis1=1, axis2=2)).max(axis=1)
        lowest = np.linalg.eigvalsh(np.where(np.isfinite(h), -h, 0.0))[:, 0]
        lam = np.maximum(0.0, -lowest) + 1e-6 * size + 1e-12
        step = np.linalg.solve(-h + lam[:, None, None] * np.eye(3), g[..., None])[..., 0]
        bad = ~np.all(np.isfinite(step), axis=1)
        step[bad] = 1e-2 * g[bad] / np.maximum(np.abs(g[bad]).max(axis=1, keepdims=True), 1e-300)
        step /= np.maximum(1.0, np.abs(step / _STEP_MAX).max(axis=1, keepdims=True))
        moved = np.zeros(active.size, bool)
        converged = np.zeros(active.size, bool)
        for _half in range(30):
            todo = np.flatnonzero(~moved)
            trial = th[todo] + step[todo]
            trial[:, 2] = np.clip(trial[:, 2], -_ALPHA_MAX, _ALPHA_MAX)
            rows = active[todo]
            ll_t, g_t, h_t = _skew_terms(u[rows], m[rows], trial)
            up = np.isfinite(ll_t) & (ll_t >= ll[rows] - 1e-12 * np.abs(ll[rows]))
            keep = rows[up]
            gain = ll_t[up] - ll[keep]
            theta[keep], ll[keep], grad[keep], hess[keep] = trial[up], ll_t[up], g_t[up], h_t[up]
            moved[todo[up]] = True
            converged[todo[up]] = gain < 1e-10 * np.maximum(1.0, np.abs(ll[keep]))
            if moved.all():
                break
            step[~moved] *= 0.5
        active = active[moved & ~converged]
        if active.size == 0:
            break
    return theta, ll


def _skew_fit(x, m, starts=(1.0,), iterations=60):
    """Maximum-likelihood skew-normals of the rows of ``x`` (mask ``m``) by damped Newton steps.

    Each row is standardised, started from its moments (the sample skewness
    times each of ``starts``), and the best start kept. Returns centred
    (mean, sigma, skewness) rows and the log-likelihoods.
    """
    n, centre, dev = _row_moments(x, m)
    scale = np.sqrt((dev * dev).sum(axis=1) / n)
    u = (x - centre[:, None]) / scale[:, None] * m
    skew = np.clip((dev**3).sum(axis=1) / n / scale**3, -_SKEW_START, _SKEW_START)
    best_theta, best_ll = None, None
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        for share in starts:
            alpha, xi, omega = skew_direct(0.0, 1.0, share * skew)
            theta, ll = _newton_rows(u, m, np.stack([xi, np.log(omega), alpha], axis=-1), iterations)
            if best_theta is None:
                best_theta, best_ll = theta, ll
            else:
                keep = ll > best_ll
                best_theta, best_ll = np.where(keep[:, None], theta, best_theta), np.maximum(ll, best_ll)
    xi, eta, alpha = best_theta.T
    mean, sd, skewness = skew_centred(alpha, centre + scale * xi, scale * np.exp(eta))
    return np.stack([mean, sd, skewness], axis=-1), best_ll - n * np.log(scale)


# --- the models ----------------------------------------------------------------------------------------------

class NormalModel:
    """Normal readings: mean and standard deviation (maximum likelihood; ``sigma`` reported with n - 1)."""

    name, n_params, min_values, needs_sequence = "normal", 2, 25, False
    parameters = ("mean", "sigma")
    lengths = (True, True)

    def refit(self, x, t=None, mask=None, start=None, repeatability=0.0):
        x, m = _masked(x, mask)
        n, mean, dev = _row_moments(x, m)
        ssr = (dev * dev).sum(axis=1)
        return np.stack([mean, np.sqrt(ssr / (n - 1))], axis=-1), _normal_loglik(ssr, n)

    def conditional_cdf(self, x, t, p):
        return special.ndtr((x - p[..., 0:1]) / p[..., 1:2])

    def process_params(self, p, r):
        p = np.array(p, dtype=float)
        p[..., 1] = _less(p[..., 1], r)
        return p

    def process(self, p):
        return Normal(float(p[0]), float(p[1]))

    def ppf(self, u, p):
        return p[..., 0:1] + p[..., 1:2] * special.ndtri(u)

    def spec(self, p, scale):
        return {"distribution": "normal", "mean": p[0] / scale, "sigma": p[1] / scale}


class SkewNormalModel:
    """Skew-normal readings (Azzalini), maximum likelihood in the direct parameters, reported centred."""

    name, n_params, min_values, needs_sequence = "skew-normal", 3, 50, False
    parameters = ("mean", "sigma", "skewness")
    lengths = (True, True, False)

    def refit(self, x, t=None, mask=None, start=None, repeatability=0.0):
        x, m = _masked(x, mask)
        return _skew_fit(x, m, starts=(1.0,) if start is not None else (1.0, 0.5, 0.0))

    def conditional_cdf(self, x, t, p):
        alpha, xi, omega = skew_direct(p[..., 0:1], p[..., 1:2], p[..., 2:3])
        z = (x - xi) / omega
        return np.clip(special.ndtr(z) - 2.0 * special.owens_t(z, alpha), 0.0, 1.0)

    def process_params(self, p, r):
        p = np.array(p, dtype=float)
        sd = _less(p[..., 1], r)
        skew = p[..., 2] * (p[..., 1] / sd) ** 3
        p[..., 1], p[..., 2] = sd, np.where(np.abs(skew) < MAX_SKEWNESS, skew, np.nan)
        return p

    def process(self, p):
        return SkewNormal(float(p[0]), float(p[1]), float(p[2]))

    def ppf(self, u, p):
        lo, hi = p[..., 0:1] - 10.0 * p[..., 1:2], p[..., 0:1] + 10.0 * p[..., 1:2]
        return _bisect(lambda x: self.conditional_cdf(x, None, p), u, lo, hi)

    def spec(self, p, scale):
        return {"distribution": "skew-normal", "mean": p[0] / scale, "sigma": p[1] / scale, "skewness": p[2]}


class MixtureModel:
    """Two normals in shares ``weight`` and 1 - ``weight`` (two machines), by EM; components ordered by mean."""

    name, n_params, min_values, needs_sequence = "mixture", 5, 100, False
    parameters = ("weight", "mean1", "sigma1", "mean2", "sigma2")
    lengths = (False, True, True, True, True)

    def refit(self, x, t=None, mask=None, start=None, repeatability=0.0):
        x, m = _masked(x, mask)
        if start is not None:
            return _em(x, m, np.broadcast_to(start, (x.shape[0], 5)).copy(), repeatability)
        best, best_ll = None, None
        for guess in _mixture_starts(x, m):
            p, ll = _em(x, m, guess, repeatability)
            if best is None:
                best, best_ll = p, ll
            else:
                better = ll > best_ll
                best, best_ll = np.where(better[:, None], p, best), np.where(better, ll, best_ll)
        return best, best_ll

    def conditional_cdf(self, x, t, p):
        w, m1, s1, m2, s2 = (p[..., k:k + 1] for k in range(5))
        return w * special.ndtr((x - m1) / s1) + (1.0 - w) * special.ndtr((x - m2) / s2)

    def process_params(self, p, r):
        p = np.array(p, dtype=float)
        p[..., 2], p[..., 4] = _less(p[..., 2], r), _less(p[..., 4], r)
        return p

    def process(self, p):
        return Mixture((Normal(float(p[1]), float(p[2])), Normal(float(p[3]), float(p[4]))),
                       (float(p[0]), 1.0 - float(p[0])))

    def ppf(self, u, p):
        lo = np.minimum(p[..., 1:2] - 10 * p[..., 2:3], p[..., 3:4] - 10 * p[..., 4:5])
        hi = np.maximum(p[..., 1:2] + 10 * p[..., 2:3], p[..., 3:4] + 10 * p[..., 4:5])
        return _bisect(lambda x: self.conditional_cdf(x, None, p), u, lo, hi)

    def spec(self, p, scale):
        return {"distribution": "mixture", "components": [
            {"weight": p[0], "distribution": "normal", "mean": p[1] / scale, "sigma": p[2] / scale},
            {"weight": 1.0 - p[0], "distribution": "normal", "mean": p[3] / scale, "sigma": p[4] / scale}]}


class DriftModel:
    """Mean drifting linearly over the sequence (tool wear): least squares of the readings on the sequence."""

    name, n_params, min_values, needs_sequence = "drift", 3, 25, True
    parameters = ("start", "end", "sigma")
    lengths = (True, True, True)

    def refit(self, x, t=None, mask=None, start=None, repeatability=0.0):
        x, m = _masked(x, mask)
        t, _ = _masked(t, mask)
        n, x_bar, dx = _row_moments(x, m)
        _, t_bar, dt = _row_moments(t, m)
        slope = (dx * dt).sum(axis=1) / np.maximum((dt * dt).sum(axis=1), 1e-300)
        resid = (dx - slope[:, None] * dt) * m
        ssr = (resid * resid).sum(axis=1)
        first = x_bar - slope * t_bar
        return np.stack([first, first + slope, np.sqrt(ssr / (n - 2))], axis=-1), _normal_loglik(ssr, n)

    def conditional_cdf(self, x, t, p):
        return special.ndtr((x - p[..., 0:1] - (p[..., 1:2] - p[..., 0:1]) * t) / p[..., 2:3])

    def marginal_cdf(self, x, p):
        """CDF of the readings over the whole tool life (parts made evenly over it)."""
        return ToolWear(float(p[0]), float(p[1]), float(p[2])).cdf(x)

    def process_params(self, p, r):
        p = np.array(p, dtype=float)
        p[..., 2] = _less(p[..., 2], r)
        return p

    def process(self, p):
        return ToolWear(float(p[0]), float(p[1]), float(p[2]))

    def ppf(self, u, p):
        first, last, sigma = p[..., 0:1], p[..., 1:2], p[..., 2:3]
        d = last - first
        w = d / sigma

        def cdf(x):
            v = (x - first) / sigma
            g = lambda v: v * special.ndtr(v) + np.exp(-0.5 * v * v) / np.sqrt(2.0 * np.pi)  # noqa: E731
            flat = np.abs(w) < 1e-9
            safe_w = np.where(flat, 1.0, w)
            return np.where(flat, special.ndtr(v), np.clip((g(v) - g(v - w)) / safe_w, 0.0, 1.0))

        lo = np.minimum(first, last) - 10.0 * sigma
        hi = np.maximum(first, last) + 10.0 * sigma
        return _bisect(cdf, u, lo, hi)

    def spec(self, p, scale):
        return {"distribution": "tool-wear", "start": p[0] / scale, "end": p[1] / scale, "sigma": p[2] / scale}


MODELS = (NormalModel(), SkewNormalModel(), MixtureModel(), DriftModel())
BY_NAME = {m.name: m for m in MODELS}


def _normal_loglik(ssr, n):
    """Log-likelihood of normal errors at their maximum (variance ssr / n), rows."""
    return -0.5 * n * (np.log(2.0 * np.pi * ssr / n) + 1.0)


def _less(sigma, r):
    """sqrt(sigma^2 - r^2), NaN where the gauge's repeatability is not below the spread."""
    sigma = np.asarray(sigma, dtype=float)
    if not r:
        return sigma
    diff = sigma * sigma - r * r
    return np.where(diff > 0, np.sqrt(np.where(diff > 0, diff, 1.0)), np.nan)


def _bisect(cdf, u, lo, hi, iterations=60):
    """x with cdf(x) = u, by bisection on every row (``cdf`` vectorised, rows broadcast with ``u``)."""
    u = np.asarray(u, dtype=float)
    lo, hi = np.broadcast_arrays(lo + 0.0 * u, hi + 0.0 * u)
    lo, hi = lo.copy(), hi.copy()
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        below = cdf(mid) < u
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    return 0.5 * (lo + hi)


def _normal_logpdf(x, mean, sigma):
    return -0.5 * ((x - mean) / sigma) ** 2 - np.log(sigma) - _LOG_SQRT_2PI


def _mixture_logpdf(x, p):
    w, m1, s1, m2, s2 = (p[..., k:k + 1] for k in range(5))
    return np.logaddexp(np.log(w) + _normal_logpdf(x, m1, s1), np.log1p(-w) + _normal_logpdf(x, m2, s2))


def _mixture_starts(x, m):
    """Starting points of EM per row: splits at the median and at the quartiles, and two means 1 sd apart."""
    n, mean, dev = _row_moments(x, m)
    sd = np.sqrt((dev * dev).sum(axis=1) / n)
    filled = np.where(m > 0, x, np.nan)
    starts = []
    for share in (0.5, 0.25, 0.75):
        cut = np.nanquantile(filled, share, axis=1)
        low = (x <= cut[:, None]) * m
        high = m - low
        m1 = (x * low).sum(1) / np.maximum(low.sum(1), 1)
        m2 = (x * high).sum(1) / np.maximum(high.sum(1), 1)
        s1 = np.sqrt(((x - m1[:, None]) ** 2 * low).sum(1) / np.maximum(low.sum(1), 1))
        s2 = np.sqrt(((x - m2[:, None]) ** 2 * high).sum(1) / np.maximum(high.sum(1), 1))
        starts.append(np.stack([np.full_like(mean, share), m1, np.maximum(s1, 0.3 * sd), m2,
                                np.maximum(s2, 0.3 * sd)], axis=-1))
    starts.append(np.stack([np.full_like(mean, 0.5), mean - 0.5 * sd, 0.8 * sd, mean + 0.5 * sd, 0.8 * sd], -1))
    return starts


def _em(x, m, p, repeatability=0.0, iterations=300, tol=1e-9):
    """EM of two-normal mixtures on every row of ``x`` (mask ``m``) from ``p`` (rows, 5); returns (p, loglik).

    A component's spread is kept above the gauge's ``repeatability`` by
    :data:`MIXTURE_MIN_SPREAD` of the row's standard deviation (in quadrature):
    a reading's spread cannot be less than the gauge's.

    Accelerated by SQUAREM (Varadhan and Roland 2008, scheme S3): two EM
    steps, an extrapolation along them in the unconstrained parameters, one EM
    step from there, kept where the likelihood at the extrapolated point is
    not below the first plain step's (the second plain step otherwise). Rows stop when the log-likelihood rises
    by less than ``tol`` (relative); components ordered by mean. The iterations
    run row by row in :func:`stackup._kernels.mixture.em`.
    """
    n, _, dev = _row_moments(x, m)
    floor = np.hypot(MIXTURE_MIN_SPREAD * np.sqrt((dev * dev).sum(axis=1) / n), repeatability)
    p = np.array(p, dtype=float)
    _mixture.em(np.ascontiguousarray(x, dtype=float), np.ascontiguousarray(m, dtype=float), p, floor,
                MIXTURE_MIN_WEIGHT, iterations, tol)
    swap = p[:, 1] > p[:, 3]
    p[swap] = np.stack([1.0 - p[swap, 0], p[swap, 3], p[swap, 4], p[swap, 1], p[swap, 2]], axis=-1)
    return p, (_mixture_logpdf(x, p) * m).sum(axis=1)
