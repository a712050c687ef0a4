"""Monte Carlo estimates with their error: proportions, quantiles and two-fidelity (control-variate) means."""

from __future__ import annotations

from typing import NamedTuple

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


class ControlVariateEstimate(NamedTuple):
    """A two-fidelity estimate (:func:`control_variate_mean`, :func:`control_variate_quantile`).

    ``estimate`` with its 95 % interval ``[lower, upper]`` and ``standard_error``
    (NaN for a quantile); ``cheap`` the same statistic of the cheap model on all
    ``n_cheap`` samples (``cheap - estimate`` estimates the cheap model's bias);
    ``accurate_only`` the statistic of the accurate model on its ``n_accurate``
    samples alone; ``correlation`` that of the two models on the shared samples.
    """

    estimate: float
    lower: float
    upper: float
    standard_error: float
    cheap: float
    accurate_only: float
    correlation: float
    n_accurate: int
    n_cheap: int


def _paired(accurate, cheap_shared, cheap_all):
    """The samples as float arrays, the pairs with a NaN in either model dropped (a failed solve is not data)."""
    y = np.asarray(accurate, dtype=float).ravel()
    x = np.asarray(cheap_shared, dtype=float).ravel()
    x_all = np.asarray(cheap_all, dtype=float).ravel()
    if y.shape != x.shape:
        raise ValueError(f"accurate ({y.size}) and cheap_shared ({x.size}) must be the same samples")
    keep = np.isfinite(y) & np.isfinite(x)
    y, x, x_all = y[keep], x[keep], x_all[np.isfinite(x_all)]
    if y.size < 3 or x_all.size < y.size:
        raise ValueError(f"a control-variate estimate needs at least 3 finite pairs and at least as many cheap samples "
                         f"({y.size} pairs, {x_all.size} cheap samples)")
    return y, x, x_all


def control_variate_mean(accurate, cheap_shared, cheap_all, *, confidence=0.95):
    """Mean of an accurate model from a subsample, corrected by a cheap model run on every sample.

    With the accurate model :math:`Y` on ``n`` samples, the cheap model
    :math:`X` on the same ``n`` and on all ``N`` samples (the ``n`` among them,
    drawn at random):

    .. math::
        \\hat\\mu = \\bar Y_n + \\hat\\beta\\,(\\bar X_N - \\bar X_n), \\qquad
        \\hat\\beta = \\widehat{\\mathrm{cov}}(Y, X) / \\widehat{\\mathrm{var}}(X),

    the control-variate (two-model multifidelity Monte Carlo) estimator [1]_,
    [2]_, with variance :math:`\\sigma_Y^2 [(1 - \\rho^2)/n + \\rho^2/N]`: the
    accurate model's mean, unbiased for any bias of the cheap one, at the
    cost of ``n`` accurate runs and the error of about ``n / (1 - ρ²)`` of them.
    The interval is Student's with ``n - 2`` degrees of freedom (normal for many pairs); with a shares' indicator (a rare event) it
    needs enough events on the subsample.

    References
    ----------
    .. [1] Lavenberg, S. S., Welch, P. D., "A perspective on the use of control
       variables to increase the efficiency of Monte Carlo simulations",
       Management Science 27 (1981) 322-335.
    .. [2] Peherstorfer, B., Willcox, K., Gunzburger, M., "Optimal model management
       for multifidelity Monte Carlo estimation", SIAM J. Sci. Comput. 38 (2016) A3163-A3194.
    """
    y, x, x_all = _paired(accurate, cheap_shared, cheap_all)
    n, big_n = y.size, x_all.size
    var_x, var_y = x.var(ddof=1), y.var(ddof=1)
    cov = np.cov(y, x, ddof=1)[0, 1]
    beta = cov / var_x if var_x > 0 else 0.0
    rho2 = min(cov * cov / (var_x * var_y), 1.0) if var_x > 0 and var_y > 0 else 0.0
    estimate = y.mean() + beta * (x_all.mean() - x.mean())
    se = np.sqrt(var_y * ((1 - rho2) / n + rho2 / big_n))
    z = stats.t.ppf(0.5 + confidence / 2, n - 2)  # Student, the regression's n - 2 degrees of freedom (few pairs)
    return ControlVariateEstimate(float(estimate), float(estimate - z * se), float(estimate + z * se), float(se),
                                  float(x_all.mean()), float(y.mean()), float(np.sqrt(rho2)), n, big_n)


def control_variate_quantile(accurate, cheap_shared, cheap_all, q, *, confidence=0.95):
    """Quantile ``q`` of an accurate model from a subsample, through the control-variate estimate of its CDF.

    The accurate model's CDF at :math:`t` is the mean of the indicator
    :math:`[Y \\le t]`, estimated with the cheap model's indicator
    :math:`[X \\le t_X]` as control, where :math:`t_X` is the cheap model's
    quantile of the same level on the subsample, so that the two indicators
    stay correlated; the quantile is where the estimated CDF crosses ``q`` and
    its interval spans the :math:`t` whose CDF interval holds ``q`` [1]_.

    References
    ----------
    .. [1] Hesterberg, T. C., Nelson, B. L., "Control variates for probability and
       quantile estimation", Management Science 44 (1998) 1295-1312.
    """
    y, x, x_all = _paired(accurate, cheap_shared, cheap_all)
    ys = np.sort(y)
    z = stats.norm.ppf(0.5 + confidence / 2)
    cdf, half = np.empty(ys.size), np.empty(ys.size)
    for i, t in enumerate(ys):
        level = np.mean(y <= t)
        t_x = np.quantile(x, level)
        e = control_variate_mean((y <= t).astype(float), (x <= t_x).astype(float), (x_all <= t_x).astype(float))
        cdf[i], half[i] = e.estimate, z * e.standard_error
    cdf = np.maximum.accumulate(np.clip(cdf, 0.0, 1.0))  # a CDF does not fall
    estimate = ys[min(np.searchsorted(cdf, q), ys.size - 1)]
    # the interval: the t whose CDF interval holds q, out to the neighbouring order statistics (the CDF is a step
    # function: between two samples the true quantile may lie anywhere)
    inside = np.flatnonzero(np.abs(cdf - q) <= half)
    first, last = (inside[0], inside[-1]) if inside.size else (np.searchsorted(cdf, q),) * 2
    lower, upper = ys[max(first - 1, 0)], ys[min(last + 1, ys.size - 1)]
    return ControlVariateEstimate(float(estimate), float(min(lower, estimate)), float(max(upper, estimate)), np.nan,
                                  float(np.quantile(x_all, q)), float(np.quantile(y, q)),
                                  float(np.corrcoef(y, x)[0, 1]), y.size, x_all.size)
