r"""ppm-level tails of the operating clearance by adaptive importance sampling through the assembly chain.

A plain Monte Carlo estimate of a share :math:`p` needs about :math:`100/p`
bearings for a 10 % error: 10^6 for 100 ppm. Here a bearing is a
deterministic function of its root inputs in standard normal space
(:mod:`stackup.study.roots`: sizes, gauge errors, the shell taken from its
grade's bin, crush heights; grading, pairing and the press fit as in a
study), and the sampling density is moved towards the tail by the
cross-entropy method: starting from the nominal density, each step draws
``n_level`` bearings from :math:`q_k = N(\mu_k, \mathrm{diag}\,\sigma_k^2)`,
keeps the ``elite`` share closest to the tail (or every bearing in it once the
tail is reached) and refits :math:`\mu, \sigma` to them by weighted maximum
likelihood, with the likelihood ratios :math:`w = \varphi(z)/q_k(z)` as
weights. The estimate uses the defensive mixture
:math:`q = \alpha\,\varphi + (1 - \alpha)\,q_K` (weights bounded by
:math:`1/\alpha`, so a region of the tail the fitted density misses is still
sampled at the nominal rate and the estimate stays unbiased):

.. math:: \hat p = \frac{1}{M}\sum_i w_i\,\mathbf 1[C_i \notin W], \qquad
          \widehat{\mathrm{SE}} = \frac{s(w\,\mathbf 1)}{\sqrt M}

No tilt is tuned by hand. Stock-outs are the study's business: the bins never
run short here.

References
----------
.. [1] Rubinstein, R. Y., Kroese, D. P., *Simulation and the Monte Carlo
   Method*, 3rd ed., Wiley, 2017, sec. 5.7 and ch. 8 (importance sampling,
   the cross-entropy method).
.. [2] Hesterberg, T., "Weighted average importance sampling and defensive
   mixture distributions", Technometrics 37 (1995) 185-194.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import special

from . import _validate as check
from ._random import as_generator
from .engines import load_engine
from .schemes import load as load_scheme
from .stats import Z95
from .study.pilot import pilot_parts, shell_plan
from .study.roots import RootModel

#: Root inputs a bearing's clearance does not depend on, or that are the scenarios' business.
NOT_TAIL_GROUPS = ("bore process mean", "journal process mean", "misalignment")
METHODS = ("subset", "cross-entropy", "mc")


@dataclass(frozen=True)
class TailEstimate:
    """A share with its standard error and 95 % interval (normal approximation, clipped at 0).

    ``bearings`` counts every evaluation of the chain, the adaptation's included.
    """

    share: float
    standard_error: float
    interval: tuple
    bearings: int
    effective_bearings: float  # Kish's effective sample size of the final weights
    levels: int  # cross-entropy steps before the final sample


def clearance_tail(engine, scheme, *, side="upper", threshold=None, method="subset", n_bearings=20_000,
                   n_level=2_000, elite=0.1, defensive=0.1, seed=0, pilot_engines=20_000, max_levels=12):
    """Share of bearings whose operating clearance is beyond ``threshold``, through the assembly chain.

    Parameters
    ----------
    engine, scheme : str, path or loaded object
    side : {"upper", "lower"}
        Share above or below ``threshold``.
    threshold : float, optional
        Clearance [m]; default the engine's design window edge on that side.
    method : {"subset", "cross-entropy", "mc"}
        Subset simulation (default: robust where the tail has several
        separate regions, as graded schemes' tails do), cross-entropy
        importance sampling, or plain Monte Carlo on the same model.
    n_bearings : int
        Bearings of the final estimate (cross-entropy, plain Monte Carlo).
    n_level : int
        Bearings per level (subset simulation) or per cross-entropy step.
    elite : float
        Share of a level's bearings kept as the next level's seeds, or the
        next density is fitted to [-].
    defensive : float
        Weight of the nominal density in the final mixture [-].
    seed : int
    pilot_engines : int
        Pilot sample of the shell plan, as in a study.
    max_levels : int
        Most cross-entropy steps.

    Returns
    -------
    TailEstimate
    """
    engine = load_engine(engine)
    scheme = load_scheme(scheme)
    check.one_of("side", side, ("upper", "lower"))
    check.one_of("method", method, METHODS)
    n = check.integer("n_bearings", n_bearings, minimum=2)
    n_level = check.integer("n_level", n_level, minimum=100)
    elite = float(check.in_range("elite", elite, 0.0, 0.5, lo_open=True))
    defensive = float(check.in_range("defensive", defensive, 0.0, 1.0, lo_open=True))
    score, dim = clearance_margin(engine, scheme, side=side, threshold=threshold, seed=seed,
                                  pilot_engines=pilot_engines)
    rng = as_generator(np.random.SeedSequence(seed).spawn(1)[0])

    if method == "mc":
        z = rng.standard_normal((n, dim))
        hit = (score(z) > 0).astype(float)
        return _estimate(hit, np.ones(n), n, 0)
    if method == "subset":
        return _subset(score, dim, rng, n_level=n_level, p0=elite, max_levels=max_levels)

    mu, sd = np.zeros(dim), np.ones(dim)
    spent, levels = 0, 0
    for levels in range(1, max_levels + 1):
        z = mu + sd * rng.standard_normal((n_level, dim))
        s = score(z)
        spent += n_level
        level = min(0.0, np.quantile(s, 1.0 - elite))
        keep = s >= level
        w = np.exp(_log_ratio(z, mu, sd)[keep])
        mu = np.average(z[keep], axis=0, weights=w)
        sd = np.sqrt(np.average((z[keep] - mu) ** 2, axis=0, weights=w))
        sd = np.clip(sd, 0.2, 2.0)  # a degenerate fit to few elite bearings must not collapse the density
        if level >= 0.0:
            break
    # final sample from the defensive mixture
    nominal = rng.random(n) < defensive
    z = np.where(nominal[:, None], rng.standard_normal((n, dim)), mu + sd * rng.standard_normal((n, dim)))
    log_q = np.logaddexp(np.log(defensive) + _log_normal(z), np.log1p(-defensive) + _log_normal((z - mu) / sd)
                         - np.log(sd).sum())
    w = np.exp(_log_normal(z) - log_q)
    hit = (score(z) > 0).astype(float)
    return _estimate(hit * w, w, spent + n, levels)


def clearance_margin(engine, scheme, *, side="upper", threshold=None, seed=0, pilot_engines=20_000):
    """A bearing's distance into the tail as a function of its root inputs in standard normal space.

    Returns ``(margin, dim)``: ``margin(z)`` for ``z`` (bearings, dim) is
    the operating clearance beyond ``threshold`` [m] towards ``side``
    (> 0 in the tail; -inf where not assembled), through grading, pairing,
    the shell taken from its grade's bin and the press fit
    (:class:`~stackup.study.roots.RootModel` of one bearing). The function a
    reliability library sees.
    """
    engine = load_engine(engine)
    scheme = load_scheme(scheme)
    check.one_of("side", side, ("upper", "lower"))
    if threshold is None:
        threshold = engine.clearance_window[1 if side == "upper" else 0]
    threshold = float(check.finite("threshold", threshold))
    sign = 1.0 if side == "upper" else -1.0
    model = RootModel(engine, scheme, shell_plan(engine, scheme, pilot_parts(engine, seed, pilot_engines)).aim,
                      bearings=1)

    groups = tuple(g for g in model.groups if g not in NOT_TAIL_GROUPS)

    def margin(z):
        c = model.engines(special.ndtr(z), groups=groups)["clearance_operating"][:, 0]
        return np.where(np.isfinite(c), sign * (c - threshold), -np.inf)

    return margin, len(model.columns(groups)[0])


def _log_normal(z):
    """Log density of the standard normal in ``z``'s dimensions (constant dropped: it cancels in ratios)."""
    return -0.5 * np.sum(z**2, axis=1)


def _log_ratio(z, mu, sd):
    """log of phi(z) / N(z; mu, sd^2) per row."""
    return _log_normal(z) - (_log_normal((z - mu) / sd) - np.log(sd).sum())


def _estimate(values, weights, bearings, levels):
    m = values.size
    share = float(values.mean())
    se = float(values.std(ddof=1) / np.sqrt(m))
    ess = float(weights.sum() ** 2 / np.sum(weights**2))
    return TailEstimate(share, se, (max(share - Z95 * se, 0.0), share + Z95 * se), int(bearings), ess, levels)


#: Correlation of a conditional-sampling step with its seed (Papaioannou et al. 2015 recommend 0.8 or adapt it).
SUBSET_RHO = 0.8


def _subset(score, dim, rng, *, n_level, p0, max_levels):
    r"""Subset simulation with conditional sampling in standard normal space.

    Level 0 is plain Monte Carlo; each level keeps the ``p0`` share of its
    bearings deepest towards the tail as seeds and grows Markov chains from
    them that stay above the level's threshold (a candidate
    :math:`\rho z + \sqrt{1 - \rho^2}\,\xi` replaces the state only if it is
    as deep), until the threshold reaches the tail. The coefficient of
    variation follows Au and Beck (2001), eqs. 28-32, with each level's
    chain correlation estimated from its own chains.

    References
    ----------
    .. [1] Au, S.-K., Beck, J. L., "Estimation of small failure probabilities in
       high dimensions by subset simulation", Probab. Eng. Mech. 16 (2001) 263-277.
    .. [2] Papaioannou, I., Betz, W., Zwirglmaier, K., Straub, D., "MCMC
       algorithms for Subset Simulation", Probab. Eng. Mech. 41 (2015) 89-103.
    """
    n_seeds = max(1, int(round(p0 * n_level)))
    steps = n_level // n_seeds
    z = rng.standard_normal((n_level, dim))
    s = score(z)
    spent, log_p, cov2 = n_level, 0.0, 0.0
    chains = None  # (steps, seeds) indicators of the previous level's chains, for their correlation
    for level in range(1, max_levels + 1):
        threshold = np.sort(s)[-n_seeds]
        if threshold > 0.0 or level == max_levels:
            hits = s > 0.0
            p = hits.mean()
            if p == 0:  # the tail lies beyond the last level: an upper bound by the rule of three
                upper = float(np.exp(log_p) * 3.0 / s.size)
                return TailEstimate(0.0, float("nan"), (0.0, upper), int(spent), float("nan"), level)
            gamma = _chain_correlation(chains, hits) if chains is not None else 0.0
            cov2 += (1 - p) / (p * s.size) * (1 + gamma)
            log_p += np.log(p)
            break
        keep = np.argsort(s)[-n_seeds:]
        gamma = _chain_correlation(chains, s >= threshold) if chains is not None else 0.0
        cov2 += (1 - p0) / (p0 * s.size) * (1 + gamma)
        log_p += np.log(n_seeds / s.size)
        state, state_s = z[keep], s[keep]
        zs, ss = [], []
        for _ in range(steps):
            candidate = SUBSET_RHO * state + np.sqrt(1 - SUBSET_RHO**2) * rng.standard_normal(state.shape)
            candidate_s = score(candidate)
            spent += candidate.shape[0]
            move = candidate_s >= threshold
            state = np.where(move[:, None], candidate, state)
            state_s = np.where(move, candidate_s, state_s)
            zs.append(state)
            ss.append(state_s)
        z, s = np.concatenate(zs), np.concatenate(ss)
        chains = np.stack(ss)  # (steps, seeds): rows are steps along each chain
    share = float(np.exp(log_p))
    se = share * float(np.sqrt(cov2))
    return TailEstimate(share, se, (max(share - Z95 * se, 0.0), share + Z95 * se), int(spent), float("nan"), level)


def _chain_correlation(chains_s, indicator):
    """Au and Beck's correlation factor gamma of a level's chains for an indicator of their states."""
    steps, seeds = chains_s.shape if chains_s is not None else (0, 0)
    if steps < 2:
        return 0.0
    ind = indicator.reshape(steps, seeds).astype(float)
    p = ind.mean()
    var = p * (1 - p)
    if var == 0:
        return 0.0
    gamma = 0.0
    for lag in range(1, steps):
        r = np.mean(ind[:-lag] * ind[lag:]) - p**2
        gamma += 2 * (1 - lag / steps) * r / var
    return max(gamma, 0.0)
