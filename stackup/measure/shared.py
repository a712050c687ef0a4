r"""The share of variance common to the parts of one group (an engine file's ``shared``), by one-way ANOVA.

An engine file's ``shared`` is the correlation of the standard normals its
processes are drawn from (a Gaussian copula, :meth:`stackup.tolerances.Dimension.true_sizes`):
the bores of one block are :math:`F^{-1}(\Phi(\sqrt{s}\,z_g + \sqrt{1-s}\,z_p))`. It does not depend
on the marginal distribution, so it is estimated on the readings' normal
scores (van der Waerden's :math:`\Phi^{-1}(\mathrm{rank}/(n+1))`, ties
averaged), whatever model the readings follow, by the one-way
random-effects analysis of variance of those scores over the groups:

.. math:: F = \frac{MS_B}{MS_W}, \qquad \hat\rho = \frac{F - 1}{F - 1 + n_0}, \qquad
          n_0 = \frac{N - \sum n_i^2/N}{a - 1}

with the interval of Searle (1971), exact for balanced normal groups
(:math:`n_0` the group size; approximate for unbalanced ones):
:math:`F_L = F/F_{1-\alpha/2}(a-1, N-a)`, :math:`F_U = F/F_{\alpha/2}(a-1, N-a)`,
:math:`\rho = (F_\cdot - 1)/(F_\cdot - 1 + n_0)`, clipped to [0, 1).

The gauge's repeatability :math:`R` adds independent noise to every
reading, which the group does not share: the readings' correlation is
:math:`\rho_r = s\,\sigma_p^2/(\sigma_p^2 + R^2)`, so the process's share is
:math:`s = \rho_r (\sigma_p^2 + R^2)/\sigma_p^2` (exact for a normal process,
to first order for others), with the same factor on the interval.

References
----------
.. [1] Searle, S. R., *Linear Models*, Wiley, 1971, sec. 9.7 (intraclass correlation, its interval).
.. [2] Burdick, R. K., Graybill, F. A., *Confidence Intervals on Variance Components*, Dekker, 1992, ch. 3.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import special, stats

#: Fewest groups, and fewest degrees of freedom within groups, the analysis of variance needs.
MIN_GROUPS, MIN_WITHIN = 5, 5
#: Largest share an engine file accepts (``shared`` lies in [0, 1)).
MAX_SHARED = 0.999


@dataclass(frozen=True)
class SharedShare:
    """Share of the process variance common to a group's parts, with its interval and the design it came from."""

    value: float
    lo: float
    hi: float
    groups: int
    mean_size: float
    readings_share: float  # the readings' intraclass correlation, before the gauge's noise is removed


def normal_scores(x):
    """Van der Waerden normal scores of ``x`` (ties get their mean rank)."""
    return special.ndtri(stats.rankdata(x) / (x.size + 1.0))


def group_codes(groups, where):
    """Integer codes of the group labels, refused when there are too few groups or too few parts per group."""
    labels, codes = np.unique(np.asarray(groups).astype(str), return_inverse=True)
    a = labels.size
    if a < MIN_GROUPS:
        raise ValueError(f"{where}: {a} group{'s' if a != 1 else ''}; the shared share needs at least {MIN_GROUPS} "
                         "groups (blocks or crankshafts)")
    if codes.size - a < MIN_WITHIN:
        raise ValueError(f"{where}: {codes.size} parts in {a} groups; the shared share needs groups of two or more "
                         f"parts (at least {MIN_WITHIN} more parts than groups)")
    return codes


def shared_share(x, codes, *, gauge_factor=1.0, confidence=0.95):
    """The engine file's ``shared`` from readings ``x`` in groups ``codes`` (see the module docstring).

    ``gauge_factor`` is :math:`(\\sigma_p^2 + R^2)/\\sigma_p^2` (1 without a gauge's repeatability).
    """
    z = normal_scores(x)
    sizes = np.bincount(codes).astype(float)
    a, n = sizes.size, float(z.size)
    means = np.bincount(codes, weights=z) / sizes
    ms_between = np.sum(sizes * (means - z.mean()) ** 2) / (a - 1)
    ms_within = np.sum((z - means[codes]) ** 2) / (n - a)
    n0 = (n - np.sum(sizes**2) / n) / (a - 1)
    ratio = ms_between / ms_within
    alpha = 1.0 - confidence

    def rho(f):
        return (f - 1.0) / (f - 1.0 + n0)

    f_lo = ratio / stats.f.ppf(1.0 - alpha / 2, a - 1, n - a)
    f_hi = ratio / stats.f.ppf(alpha / 2, a - 1, n - a)

    def share(r):
        return float(np.clip(r * gauge_factor, 0.0, MAX_SHARED))

    return SharedShare(share(rho(ratio)), share(rho(f_lo)), share(rho(f_hi)), a, n / a, float(max(rho(ratio), 0.0)))
