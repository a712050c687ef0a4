"""Monte Carlo estimates with their error: proportions and quantiles with intervals."""

from __future__ import annotations

import numpy as np
from scipy import stats


def proportion_ci(k, n, *, confidence=0.95):
    """Exact (Clopper-Pearson) interval of a proportion ``k / n``.

    Returns ``(estimate, lower, upper)``; with ``n == 0`` all three are NaN.

    References
    ----------
    .. [1] Clopper, C. J., Pearson, E. S., "The use of confidence or fiducial
       limits illustrated in the case of the binomial", Biometrika 26 (1934) 404-413.
    """
    k, n = int(k), int(n)
    if n == 0:
        return np.nan, np.nan, np.nan
    alpha = 1.0 - confidence
    lower = 0.0 if k == 0 else stats.beta.ppf(alpha / 2, k, n - k + 1)
    upper = 1.0 if k == n else stats.beta.ppf(1 - alpha / 2, k + 1, n - k)
    return k / n, float(lower), float(upper)


def quantile_ci(values, q, *, confidence=0.95):
    """Sample quantile ``q`` of ``values`` with a distribution-free interval.

    The interval is spanned by the order statistics whose ranks are the
    binomial ``(n, q)`` quantiles at ``alpha/2`` and ``1 - alpha/2``.
    Returns ``(estimate, lower, upper)``; NaN values are ignored.

    References
    ----------
    .. [1] Hahn, G. J., Meeker, W. Q., *Statistical Intervals*, Wiley, 1991, sec. 5.2.
    """
    x = np.sort(np.asarray(values, dtype=float).ravel())
    x = x[~np.isnan(x)]
    n = x.size
    if n == 0:
        return np.nan, np.nan, np.nan
    alpha = 1.0 - confidence
    lo_rank = int(stats.binom.ppf(alpha / 2, n, q))
    hi_rank = int(stats.binom.ppf(1 - alpha / 2, n, q)) + 1
    lower = x[lo_rank - 1] if lo_rank >= 1 else -np.inf
    upper = x[hi_rank - 1] if hi_rank <= n else np.inf
    with np.errstate(invalid="ignore"):  # between a finite value and inf (a life never reached) the mean is NaN
        estimate = np.quantile(x, q)
    if np.isnan(estimate):  # then the order statistic above: inf where the quantile falls among the infinities
        estimate = np.quantile(x, q, method="higher")
    return float(estimate), float(lower), float(upper)


#: Two-sided 95 % quantile of the standard normal, as the project has always rounded it.
Z95 = 1.96


def mean_half_width(values, axis=None):
    """Half-width [units of ``values``] of the normal-approximation 95 % interval of a mean.

    :math:`1.96\\,s/\\sqrt{n}` with the sample standard deviation :math:`s`
    of the ``n`` values along ``axis`` (all values if None).
    """
    values = np.asarray(values, dtype=float)
    n = values.size if axis is None else values.shape[axis]
    return Z95 * values.std(axis=axis, ddof=1) / np.sqrt(n)
