r"""ppm-level tails of the operating clearance through the assembly chain, with errors that can be trusted.

A plain Monte Carlo estimate of a share :math:`p` needs about :math:`100/p`
bearings for a 10 % error: 10^6 for 100 ppm. Here a bearing is a
deterministic function of its root inputs in standard normal space
(:mod:`stackup.study.roots`: sizes, gauge errors, the shell taken from its
grade's bin, crush heights; grading, pairing and the press fit as in a
study), and three estimators sample it:

``"splitting"`` (the default, the one the ranking uses)
    Generalized splitting (Botev and Kroese 2012) on levels that a pilot
    subset simulation places (Au and Beck 2001): the margin's
    :math:`p_0`-quantiles of successive conditional samples,
    :math:`\gamma_1 < \dots < \gamma_{T-1} < \gamma_T = 0`. Then, fixed
    levels: ``n_level`` root bearings drawn from the nominal density; each
    bearing above :math:`\gamma_t` grows a Markov chain of
    :math:`s_t \approx 1/\rho_t` steps that keeps the nominal density within
    :math:`\{\text{score} \ge \gamma_t\}` (conditional sampling,
    :math:`\sqrt{1 - \sigma_j^2}\,z_j + \sigma_j\,\xi_j`, accepted where it
    stays above the level, with the step sizes :math:`\sigma_j` the pilot's
    chains adapted to an acceptance of 0.25 at that level as in Papaioannou
    et al. 2015, and then frozen so that the roots stay independent), and every
    state beyond :math:`\gamma_{t+1}` becomes a bearing of the next level.
    Root :math:`i` ends with :math:`C_i` bearings in the tail, and

    .. math:: \hat p = \frac{1}{N}\sum_i \frac{C_i}{\prod_t s_t}, \qquad
              \widehat{\mathrm{SE}} = \frac{s(C / \textstyle\prod_t s_t)}{\sqrt N}

    is unbiased for any levels and any such chain, and the roots' trees are
    independent, so the standard error is that of a mean of :math:`N`
    independent values, whatever the chains do between the separate tail
    regions that grading creates. That error is honest only where enough
    roots reach the tail for the mean of their counts to be normal: below a
    few ppm on graded schemes the counts are heavy-tailed (a few rare roots
    enter the regions that hold most of the tail and then carry most of
    it), so a run whose tail rests on a handful of roots understates both
    the share and its error (``effective_bearings`` says how many roots it
    rests on; the diagnosis and the numbers are in
    reports/tails_vs_peers.md). So where a trial on
    the same levels, then thrown away, says fewer than ``min_roots`` of
    ``n_level`` roots would reach the tail, the estimate draws as many as
    twice that needs (at most ``MAX_ROOTS_SHARE`` times ``n_level``); its
    roots are fresh, so their number does not depend on them and the
    estimate stays unbiased.
    Subset simulation alone states its error from within-chain correlations
    (Au and Beck, eqs. 28-32), which misses exactly that: its stated error
    falls short of the real spread, the more so the deeper the tail
    (reports/tails_vs_peers.md).
``"cross-entropy"``
    Importance sampling from a normal density moved towards the tail by the
    cross-entropy method (Rubinstein and Kroese 2017), in a defensive
    mixture with the nominal density (Hesterberg 1995). One normal density
    covers one tail region: where the scheme pairs different shells in
    different cells (graded schemes), the tail has several regions, the
    density misses some and the stated error is understated (measured in
    reports/tails_vs_peers.md); the estimator warns there, and the ranking
    does not use it.
``"mc"``
    Plain Monte Carlo on the same model.

Every estimate comes with a 95 % interval from its share and standard error
as for the equivalent count of a plain Monte Carlo sample
(:func:`share_interval`), so a share resting on a few independent roots
gets the asymmetric width of a few counted bearings. Stock-outs are the
study's business: the bins never run short here.

References
----------
.. [1] Botev, Z. I., Kroese, D. P., "Efficient Monte Carlo simulation via the
   generalized splitting method", Stat. Comput. 22 (2012) 1-16.
.. [2] Au, S.-K., Beck, J. L., "Estimation of small failure probabilities in
   high dimensions by subset simulation", Probab. Eng. Mech. 16 (2001) 263-277.
.. [3] Papaioannou, I., Betz, W., Zwirglmaier, K., Straub, D., "MCMC
   algorithms for Subset Simulation", Probab. Eng. Mech. 41 (2015) 89-103.
.. [4] Rubinstein, R. Y., Kroese, D. P., *Simulation and the Monte Carlo
   Method*, 3rd ed., Wiley, 2017, sec. 5.7 and ch. 8 (importance sampling,
   the cross-entropy method).
.. [5] Hesterberg, T., "Weighted average importance sampling and defensive
   mixture distributions", Technometrics 37 (1995) 185-194.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace

import numba
import numpy as np
from scipy import special, stats

from . import _validate as check
from ._validate import Finite, InRange, Integer, OneOf, validated
from ._random import as_generator
from .engines import load_engine
from .schemes import load as load_scheme
from .study.pilot import pilot_parts, shell_plan
from .study.roots import RootModel

#: Root inputs a bearing's clearance does not depend on, or that are the scenarios' business.
NOT_TAIL_GROUPS = ("bore process mean", "journal process mean", "misalignment")
METHODS = ("splitting", "cross-entropy", "mc")
SIDES = ("upper", "lower")
#: Acceptance rate the pilot's chains adapt their steps to, and the first step's scale (Papaioannou et al. 2015
#: adapt to 0.44; near the 0.23 of random-walk Metropolis in many dimensions, Roberts, Gelman and Gilks 1997,
#: the steps are larger and the roots' counts less heavy-tailed, so the intervals hold the plain-MC share more
#: often for the same evaluations: measured in reports/tails_vs_peers.md).
TARGET_ACCEPTANCE, INITIAL_SCALE = 0.25, 0.6
#: Bearings per level of the pilot subset simulation that places the levels, as a share of ``n_level``.
PILOT_SHARE = 0.25
#: Fewest roots in the tail an estimate should rest on (where ``n_level`` roots would leave fewer, it draws
#: enough for twice as many), and the most roots it may draw, as a multiple of ``n_level``: below a few ppm on
#: graded schemes the roots' counts are heavy-tailed and a mean of a few is not normal (module docstring; stated
#: and real errors in reports/tails_vs_peers.md).
MIN_ROOTS, MAX_ROOTS_SHARE = 10, 16
#: Roots of the trial that sets the estimate's count of roots, as a share of ``n_level``.
TRIAL_SHARE = 0.1


def _max_roots(values):
    """``max_roots``, where given, is at least ``n_level``: the estimate never draws fewer roots than that."""
    if values["max_roots"] is not None and values["max_roots"] < values["n_level"]:
        raise ValueError(f"max_roots: {values['max_roots']} is not valid; must be >= {values['n_level']}")


#: The checks of the estimators' options (:func:`tail_share`, and :func:`clearance_tail`, which passes them on).
ESTIMATOR_OPTIONS = dict(method=OneOf(METHODS), n_bearings=Integer(minimum=2), n_level=Integer(minimum=100),
                         elite=InRange(0.0, 0.5, lo_open=True), defensive=InRange(0.0, 1.0, lo_open=True),
                         max_levels=Integer(minimum=1), min_roots=Integer(minimum=0), max_roots=Integer())
#: The checks of the margin's options (:func:`clearance_margin`, and :func:`clearance_tail`).
MARGIN_OPTIONS = dict(side=OneOf(SIDES), threshold=Finite())


@dataclass(frozen=True)
class TailEstimate:
    """A share with its standard error and 95 % interval (:func:`share_interval`).

    ``bearings`` counts every evaluation of the chain, the pilot's or the
    adaptation's included; ``levels`` the intermediate levels (splitting) or
    cross-entropy steps before the final sample. ``effective_bearings``:
    the independent units the error rests on (splitting: roots whose
    bearings reached the tail; importance sampling: Kish's effective sample
    size of the final weights; plain Monte Carlo: bearings in the tail).
    """

    share: float
    standard_error: float
    interval: tuple
    bearings: int
    effective_bearings: float
    levels: int


@validated(**ESTIMATOR_OPTIONS, **MARGIN_OPTIONS, relations=(_max_roots,))
def clearance_tail(engine, scheme, *, side="upper", threshold=None, method="splitting", n_bearings=20_000,
                   n_level=2_000, elite=0.1, defensive=0.1, seed=0, pilot_engines=20_000, max_levels=14,
                   min_roots=MIN_ROOTS, max_roots=None):
    """Share of bearings whose operating clearance is beyond ``threshold``, through the assembly chain.

    Parameters
    ----------
    engine, scheme : str, path or loaded object
    side : {"upper", "lower"}
        Share above or below ``threshold``.
    threshold : float, optional
        Clearance [m]; default the engine's design window edge on that side.
    method : {"splitting", "cross-entropy", "mc"}
        Generalized splitting on levels placed by a pilot subset simulation
        (default; unbiased, with an honest error where the tail has several
        separate regions, as graded schemes' tails do), cross-entropy
        importance sampling (one tail region only: warns for a scheme that
        pairs different shells in different cells), or plain Monte Carlo on
        the same model. See the module docstring.
    n_bearings : int
        Bearings of the final estimate (cross-entropy, plain Monte Carlo).
    n_level : int
        Root bearings (splitting; about as many per later level, and
        ``PILOT_SHARE`` of them per level of its pilot) or bearings per
        cross-entropy step.
    elite : float
        Conditional probability between levels (splitting) or share of a
        step's bearings the next density is fitted to (cross-entropy) [-].
    defensive : float
        Weight of the nominal density in the final mixture (cross-entropy) [-].
    seed : int
    pilot_engines : int
        Pilot sample of the shell plan, as in a study.
    max_levels : int
        Most levels (splitting) or cross-entropy steps.
    min_roots : int
        Fewest roots in the tail the splitting should rest on: a trial of
        ``TRIAL_SHARE`` of ``n_level`` roots on the same levels, then thrown
        away, gives the roots in the tail per root; where ``n_level`` roots
        would leave fewer than ``min_roots`` there, the estimate draws as
        many as that rate needs for ``2 * min_roots`` (0: ``n_level``, no
        trial).
    max_roots : int, optional
        Most roots of the estimate (default ``MAX_ROOTS_SHARE * n_level``).

    Returns
    -------
    TailEstimate
    """
    engine = load_engine(engine)
    scheme = load_scheme(scheme)
    score, dim = clearance_margin(engine, scheme, side=side, threshold=threshold, seed=seed,
                                  pilot_engines=pilot_engines)
    if method == "cross-entropy" and _several_pairs(scheme):
        warnings.warn(f"cross-entropy: {scheme.name} pairs different shells in different cells, so its tail has "
                      "several separate regions that one normal density does not cover; the stated error is "
                      "understated there (use method='splitting')", UserWarning, stacklevel=3)
    return tail_share(score, dim, method=method, n_bearings=n_bearings, n_level=n_level, elite=elite,
                      defensive=defensive, seed=seed, max_levels=max_levels, min_roots=min_roots,
                      max_roots=max_roots)


@validated(**ESTIMATOR_OPTIONS, dim=Integer(minimum=1), relations=(_max_roots,))
def tail_share(margin, dim, *, method="splitting", n_bearings=20_000, n_level=2_000, elite=0.1, defensive=0.1,
               seed=0, max_levels=14, min_roots=MIN_ROOTS, max_roots=None):
    """Probability that ``margin(z) > 0`` for ``z`` standard normal in ``dim`` dimensions.

    The estimators of :func:`clearance_tail` (see the module docstring) for
    any vectorised ``margin`` ((n, dim) -> (n,)); same parameters.
    ``bearings`` of the result counts every evaluation of ``margin``.

    Returns
    -------
    TailEstimate
    """
    rng = as_generator(np.random.SeedSequence(seed).spawn(1)[0])
    threads = numba.get_num_threads()
    # the chains evaluate a few hundred bearings per call, where starting the kernels' threads costs more
    # than it saves
    numba.set_num_threads(1)
    count = _Counted(margin)
    try:
        estimate = _estimator(count, dim, rng, method=method, n=n_bearings, n_level=n_level, elite=float(elite),
                              defensive=float(defensive), max_levels=max_levels, min_roots=min_roots,
                              max_roots=max_roots)
    finally:
        numba.set_num_threads(threads)
    return replace(estimate, bearings=count.rows)


class _Counted:
    """A margin that counts the bearings it evaluates."""

    def __init__(self, margin):
        self.margin, self.rows = margin, 0

    def __call__(self, z):
        self.rows += len(z)
        return self.margin(z)


def _estimator(margin, dim, rng, *, method, n, n_level, elite, defensive, max_levels, min_roots, max_roots):
    if method == "mc":
        hit = (margin(rng.standard_normal((n, dim))) > 0).astype(float)
        return _estimate(hit, n, float(hit.sum()), 0)
    if method == "splitting":
        pilot = max(100, int(round(PILOT_SHARE * n_level)))
        levels, kernels, last = _subset_levels(margin, dim, rng, n_level=pilot, p0=elite, max_levels=max_levels)
        # chain steps per level: about as many bearings at every level as roots above the first
        splits = [int(round(1 / elite))] * (len(levels) - 1) + [max(1, int(round(1 / last)))] * bool(levels)
        plan = dict(levels=levels, kernels=kernels, splits=splits, p0=elite, reached=len(levels) < max_levels)
        n_roots = n_level
        if levels and min_roots:
            # a trial on the same levels, thrown away, says how many roots reach the tail per root; the estimate's
            # roots are then drawn afresh, so their number does not depend on them (unbiased)
            n_trial = max(100, int(round(TRIAL_SHARE * n_level)))
            trial = _splitting(margin, dim, rng, n_roots=n_trial, **plan)
            # none in the trial's tail: taken as half a root (a trial of a few hundred roots can miss a tail of a
            # few hundred ppm)
            rate = max(trial.effective_bearings, 0.5) / n_trial
            if rate * n_level < min_roots:  # aim at twice as many: the trial's rate rests on a few roots
                n_roots = int(np.clip(np.ceil(2 * min_roots / rate), n_level, max_roots or MAX_ROOTS_SHARE * n_level))
        return _splitting(margin, dim, rng, n_roots=n_roots, **plan)
    return _cross_entropy(margin, dim, rng, n=n, n_level=n_level, elite=elite, defensive=defensive,
                          max_levels=max_levels)


def share_interval(share, standard_error, confidence=0.95):
    """Interval of a share from its estimate and standard error, as for the equivalent plain Monte Carlo count.

    A plain Monte Carlo share :math:`k/n` has variance :math:`p(1-p)/n`; an
    estimate :math:`\\hat p` with standard error :math:`s` carries as much
    information as :math:`n_e = \\hat p(1-\\hat p)/s^2` bearings of which
    :math:`k_e = \\hat p\\,n_e` in the tail, and gets their Clopper-Pearson
    interval (a beta interval, :math:`k_e` need not be whole). Where the
    estimate rests on a few independent units its interval is as wide and
    as skewed as a count of a few bearings, which a normal interval is not.

    Returns ``(lower, upper)``; ``(0, nan)`` for a zero share (the caller
    knows its resolution) and NaN where the error is unknown.
    """
    share, se = float(share), float(standard_error)
    if not (np.isfinite(share) and np.isfinite(se)):
        return (np.nan, np.nan)
    if share <= 0.0 or se <= 0.0:
        return (share, share) if share > 0 else (0.0, np.nan)
    n_e = share * (1.0 - share) / se**2
    k_e = share * n_e
    alpha = 1.0 - confidence
    lower = float(stats.beta.ppf(alpha / 2, k_e, n_e - k_e + 1))
    upper = float(stats.beta.ppf(1 - alpha / 2, k_e + 1, n_e - k_e)) if n_e - k_e > 0 else 1.0
    return (lower, upper)


@validated(**MARGIN_OPTIONS)
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
    if threshold is None:  # the engine's window edge, checked as a threshold given would be
        threshold = check.finite("threshold", engine.clearance_window[1 if side == "upper" else 0])
    threshold = float(threshold)
    sign = 1.0 if side == "upper" else -1.0
    model = RootModel(engine, scheme, shell_plan(engine, scheme, pilot_parts(engine, seed, pilot_engines)).aim,
                      bearings=1)

    groups = tuple(g for g in model.groups if g not in NOT_TAIL_GROUPS)

    def margin(z):
        c = model.engines(special.ndtr(z), groups=groups)["clearance_operating"][:, 0]
        return np.where(np.isfinite(c), sign * (c - threshold), -np.inf)

    return margin, len(model.columns(groups)[0])


def _several_pairs(scheme):
    """Whether the scheme pairs different shells in different cells (its clearance jumps between cells)."""
    return np.unique(scheme.cell_pairs.reshape(-1, 2), axis=0).shape[0] > 1


def _estimate(values, bearings, effective, levels):
    """A share as the mean of independent ``values`` with its standard error and interval."""
    share = float(values.mean())
    se = float(values.std(ddof=1) / np.sqrt(values.size))
    interval = share_interval(share, se)
    if share == 0.0:  # nothing reached the tail: the rule of three, as if the run were plain Monte Carlo
        interval = (0.0, 3.0 / values.size)
    return TailEstimate(share, se, interval, int(bearings), float(effective), levels)


def _move(score, state, state_s, level, rng, sigma):
    r"""One conditional-sampling step of each chain: keeps the standard normal density above ``level``.

    Coordinate j moves to :math:`\rho_j z_j + \sigma_j \xi_j`, :math:`\rho_j = \sqrt{1 - \sigma_j^2}`
    (each marginal stays standard normal whatever ``sigma``), accepted where the score stays above ``level``.
    Returns the new states, their scores and which moved.
    """
    rho = np.sqrt(1.0 - sigma**2)
    candidate = rho * state + sigma * rng.standard_normal(state.shape)
    candidate_s = score(candidate)
    move = candidate_s >= level
    return np.where(move[:, None], candidate, state), np.where(move, candidate_s, state_s), move


def _subset_levels(score, dim, rng, *, n_level, p0, max_levels):
    r"""Levels of a subset simulation, each the :math:`p_0` upper quantile of the previous level's chains, and
    the chains' kernel at each level.

    Level 0 is plain Monte Carlo; each level keeps the ``p0`` share of its
    bearings deepest towards the tail and grows Markov chains from them that
    stay above that level's threshold, until the threshold passes 0. The
    chains are adaptive conditional sampling (Papaioannou et al. 2015, alg.
    5): coordinate j's step :math:`\sigma_j = \min(1, \lambda\,\hat\sigma_j)`
    with :math:`\hat\sigma_j` the spread of the level's seeds in j and
    :math:`\lambda` driven towards :data:`TARGET_ACCEPTANCE` after every
    step. Returns the thresholds below 0 (``max_levels`` of them where the
    tail lies deeper), each level's final step sizes, the share of the last
    level's bearings in the tail (Au and Beck 2001).
    """
    n_seeds = max(2, int(round(p0 * n_level)))
    steps = max(1, n_level // n_seeds)
    z = rng.standard_normal((n_level, dim))
    s = score(z)
    levels, kernels, scale = [], [], INITIAL_SCALE
    while len(levels) < max_levels:
        order = np.argsort(s)
        threshold = s[order[-n_seeds]]
        if threshold > 0.0:
            break
        levels.append(float(threshold))
        state, state_s = z[order[-n_seeds:]], s[order[-n_seeds:]]
        spread = np.maximum(state.std(axis=0, ddof=1), 1e-3)
        zs, ss = [], []
        for k in range(steps):
            state, state_s, moved = _move(score, state, state_s, threshold, rng, np.minimum(1.0, scale * spread))
            scale *= np.exp((moved.mean() - TARGET_ACCEPTANCE) / np.sqrt(k + 1))
            zs.append(state)
            ss.append(state_s)
        kernels.append(np.minimum(1.0, scale * spread))
        z, s = np.concatenate(zs), np.concatenate(ss)
    return levels, kernels, max(float(np.mean(s > 0.0)), p0)


def _splitting(score, dim, rng, *, n_roots, levels, kernels, splits, p0, reached=True):
    """Generalized splitting on fixed ``levels`` (< 0, increasing) with ``splits`` chain steps per level.

    Each root's bearings descend from it alone, so the roots' counts in the
    tail are independent and their mean's standard error is honest (module
    docstring). Where a level holds more than twice the bearings expected
    (``n_roots * p0``; the pilot's levels are estimates) each is kept with
    probability :math:`q` and weighs :math:`1/q` from then on (Russian
    roulette: unbiased, and the cost stays bounded). Tail: margin > 0.

    Where no bearing reaches the tail (or the pilot did not, ``reached``
    False: the last level is then the deepest place sampled), the share is 0
    and its upper bound is that of the deepest level reached, whose share
    the same roots estimate: the tail lies inside every level.
    """
    z = rng.standard_normal((n_roots, dim))
    s = score(z)
    spent = n_roots
    if not levels:  # the pilot found the tail beyond its first quantile: plain Monte Carlo
        hit = (s > 0.0).astype(float)
        return _estimate(hit, spent, float(hit.sum()), 0)
    bounds = [*levels, 0.0] if reached else list(levels)
    alive = s >= bounds[0]
    state, state_s, root = z[alive], s[alive], np.flatnonzero(alive)
    weight, scale = np.ones(root.size), 1.0
    # each level's share as the roots' mean count of bearings arriving there
    arrived = [np.bincount(root, minlength=n_roots).astype(float)]
    expected = max(1.0, n_roots * p0)
    for t in range(len(bounds) - 1):
        if root.size > 2 * expected:
            q = expected / root.size
            kept = rng.random(root.size) < q
            state, state_s, root, weight = state[kept], state_s[kept], root[kept], weight[kept] / q
        found = []
        for _ in range(splits[t]):
            if not root.size:
                break
            state, state_s, _ = _move(score, state, state_s, bounds[t], rng, kernels[t])
            spent += root.size
            beyond = state_s > 0.0 if bounds[t + 1] == 0.0 else state_s >= bounds[t + 1]
            found.append((state[beyond], state_s[beyond], root[beyond], weight[beyond]))
        scale *= splits[t]
        if not found:
            break
        state, state_s, root, weight = (np.concatenate(parts) for parts in zip(*found))
        arrived.append(np.bincount(root, weights=weight, minlength=n_roots) / scale)
    if reached and len(arrived) == len(bounds) and arrived[-1].any():
        return _estimate(arrived[-1], spent, float(np.count_nonzero(arrived[-1])), len(levels))
    deepest = next(a for a in reversed(arrived) if a.any()) if any(a.any() for a in arrived) else None
    upper = (share_interval(deepest.mean(), deepest.std(ddof=1) / np.sqrt(n_roots))[1] if deepest is not None
             else 3.0 / n_roots)
    return TailEstimate(0.0, float("nan"), (0.0, float(upper)), int(spent), 0.0, len(levels))


def _cross_entropy(score, dim, rng, *, n, n_level, elite, defensive, max_levels):
    r"""Cross-entropy importance sampling with a defensive mixture (module docstring).

    Starting from the nominal density, each step draws ``n_level`` bearings
    from :math:`q_k = N(\mu_k, \mathrm{diag}\,\sigma_k^2)`, keeps the
    ``elite`` share closest to the tail (or every bearing in it once the tail
    is reached) and refits :math:`\mu, \sigma` to them by weighted maximum
    likelihood with the likelihood ratios as weights. The final ``n``
    bearings come from :math:`q = \alpha\,\varphi + (1 - \alpha)\,q_K`
    (weights bounded by :math:`1/\alpha`).
    """
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
    nominal = rng.random(n) < defensive
    z = np.where(nominal[:, None], rng.standard_normal((n, dim)), mu + sd * rng.standard_normal((n, dim)))
    log_q = np.logaddexp(np.log(defensive) + _log_normal(z), np.log1p(-defensive) + _log_normal((z - mu) / sd)
                         - np.log(sd).sum())
    w = np.exp(_log_normal(z) - log_q)
    hit = (score(z) > 0).astype(float)
    return _estimate(hit * w, spent + n, float(w.sum() ** 2 / np.sum(w**2)), levels)


def _log_normal(z):
    """Log density of the standard normal in ``z``'s dimensions (constant dropped: it cancels in ratios)."""
    return -0.5 * np.sum(z**2, axis=1)


def _log_ratio(z, mu, sd):
    """log of phi(z) / N(z; mu, sd^2) per row."""
    return _log_normal(z) - (_log_normal((z - mu) / sd) - np.log(sd).sum())
