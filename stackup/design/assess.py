r"""A finished design scored on parts the search never saw: the check sample.

The search minimises the objective :math:`J` on one design sample, trying
hundreds of thousands of candidate limits on it; the candidate it keeps is
the one whose sample happened to suit it best, so its :math:`J` there is
biased low (over-fitting: the fewer the bearings in a cell, the more a
pair can be tuned to the few that are there). The check sample, its own
random stream (:data:`~stackup.design.sample.CHECK_KEY`), decides nothing:
the designer reports the designed scheme's share outside the window on it
per scenario, with a 95 % Student interval over ``k`` independent
sub-samples, :math:`\bar p \pm t_{0.975,k-1} s/\sqrt{k}`, beside the design
sample's figure.

It scores a complete scheme exactly as :func:`stackup.design.objective.score`
does (its preferred pairs, the shells integrated out, made-to-order shells
aimed for the demand the scheme makes on that sample).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import stats

from .._random import seed_sequence
from .objective import demand_share, score
from .problem import draw_samples
from .sample import CHECK_KEY

#: Independent sub-samples of the check sample, each as large as the design sample.
CHECK_SAMPLES = 5


@dataclass(frozen=True)
class Assessment:
    """A scheme's objective on one set of samples (nominal first, then each scenario).

    Attributes
    ----------
    outside : dict of str -> float
        Share of the bearings outside the window per sample [-].
    objective : float
        :math:`J` on these samples: nominal share, the weighted worst scenario and the supply terms [-].
    surplus, shortfall : numpy.ndarray (shell grades,)
        Planned shells per bearing left over and missing for the scheme's demand on the nominal sample [-].
    """

    outside: dict
    objective: float
    surplus: np.ndarray
    shortfall: np.ndarray


def assess(problem, scheme, samples):
    """:class:`Assessment` of a complete ``scheme`` on ``samples`` (drawn as ``problem``'s design sample, from
    another stream)."""
    outside = {s.label: score(scheme, s, problem.window).outside for s in samples}
    surplus, shortfall, _ = problem.balance(scheme, demand_share(scheme, samples[0]), samples[0].shell_normals)
    objective = problem.objective(list(outside.values())) + problem.supply_cost(surplus, shortfall)
    return Assessment(outside, objective, surplus, shortfall)


@dataclass(frozen=True)
class Check:
    """A designed scheme on the check sample: parts no decision of the designer saw.

    Attributes
    ----------
    outside : dict of str -> float
        Mean share of the bearings outside the window over the sub-samples, per scenario [-].
    interval : dict of str -> (float, float)
        Its 95 % Student interval, clipped at 0 [-].
    objective : float
        Mean :math:`J` over the sub-samples [-].
    objective_interval : (float, float)
        Its 95 % Student interval [-].
    samples, engines : int
        Sub-samples and engines per sub-sample.
    """

    outside: dict
    interval: dict
    objective: float
    objective_interval: tuple
    samples: int
    engines: int


def check(problem, scheme, *, seed, n_engines, samples=CHECK_SAMPLES):
    """:class:`Check` of ``scheme`` on ``samples`` sub-samples of ``n_engines`` engines (module docstring)."""
    root, runs = seed_sequence(seed), []
    for k in range(samples):
        stream = np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, k), pool_size=root.pool_size)
        drawn = draw_samples(problem.engine, problem.changes, n_engines=n_engines, seed=stream,
                             window=problem.window, key=CHECK_KEY)
        runs.append(assess(problem, scheme, drawn))
    labels = list(runs[0].outside)
    shares = np.array([[r.outside[label] for label in labels] for r in runs])
    objectives = np.array([r.objective for r in runs])
    half = stats.t.ppf(0.975, samples - 1) / np.sqrt(samples)
    mean, spread = shares.mean(axis=0), shares.std(axis=0, ddof=1) * half
    j_mean, j_spread = float(objectives.mean()), float(objectives.std(ddof=1) * half)
    return Check(dict(zip(labels, map(float, mean))),
                 {label: (float(max(m - d, 0.0)), float(m + d)) for label, m, d in zip(labels, mean, spread)},
                 j_mean, (max(j_mean - j_spread, 0.0), j_mean + j_spread), samples, n_engines)
