r"""Shares of a few ppm and below outside the window, with the shells integrated out.

A study counts the bearings outside the window; at a few ppm a study of
100,000 engines counts a handful and its interval spans an order of
magnitude. The designer's tier (:mod:`stackup.design.objective`) gives each
bearing the probability that the shells of its pair put it outside the window
(conditional Monte Carlo: the parts are sampled, the shells integrated out),
so its estimate moves smoothly and its variance comes from the parts alone.
The error is measured, not modelled: ``samples`` independent design samples
(their own seeds) give ``samples`` estimates, and the interval is Student's
on their mean,

.. math:: \bar p \pm t_{0.975,\,k-1}\, s / \sqrt{k}.

What the tier leaves out against a study: substitute pairs when a bin runs
out (it scores the preferred pairs; bearings that would wait for a shell are
not built) and the production order of a bin (it draws a bin's shells at
random). Its error against the study's counts is in reports/design_scheme.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import stats

from .. import _validate as check
from .._validate import Integer, Window, validated
from ..engines import load_engine
from ..schemes import load as load_scheme
from .objective import score
from .sample import draw_sample


@dataclass(frozen=True)
class OutsideShare:
    """Share of the assembled bearings below and above the window, from independent design samples.

    Attributes
    ----------
    below, above, outside : float
        Mean share over the samples below the window, above it and outside it (their sum) [-].
    below_error, above_error, outside_error : float
        Standard error of each mean: the spread of the samples' estimates over :math:`\\sqrt{k}` [-].
    below_interval, above_interval, outside_interval : (float, float)
        95 % Student interval of each share, clipped at 0 [-].
    samples, engines : int
        Independent design samples and engines per sample.
    """

    below: float
    above: float
    outside: float
    below_error: float
    above_error: float
    outside_error: float
    below_interval: tuple
    above_interval: tuple
    outside_interval: tuple
    samples: int
    engines: int


@validated(window=Window(), n_engines=Integer(minimum=100), samples=Integer(minimum=2), seed=Integer(minimum=0))
def outside_share(engine, scheme, *, window=None, n_engines=20_000, samples=10, seed=0, scenario=None):
    """:class:`OutsideShare` of ``scheme`` on ``engine`` with the shells integrated out (module docstring).

    Parameters
    ----------
    engine : str, path or Engine
    scheme : str, path or Scheme
    window : (float, float), optional
        Operating-clearance window [m]; default the engine's.
    n_engines : int
        Engines of each design sample.
    samples : int
        Independent design samples (at least 2).
    seed : int
        Sample k draws from ``SeedSequence(seed, spawn_key=(k,))``'s design stream: apart from the
        designer's own sample and from a study's lots and pilot with the same seed.
    scenario : dict, optional
        Declared scenario applied to the engine (:mod:`stackup.scenarios`).
    """
    engine = load_engine(engine)
    scheme = load_scheme(scheme)
    window = check.clearance_window("window", engine.clearance_window) if window is None else window
    shares = np.empty((samples, 3))
    for k in range(samples):
        stream = np.random.SeedSequence(seed, spawn_key=(k,))
        sample = draw_sample(engine, n_engines=n_engines, seed=stream, window=window, scenario=scenario)
        result = score(scheme, sample, window)
        shares[k] = result.below, result.above, result.outside
    mean = shares.mean(axis=0)
    error = shares.std(axis=0, ddof=1) / np.sqrt(samples)
    half = stats.t.ppf(0.975, samples - 1) * error
    low, high = np.maximum(mean - half, 0.0), mean + half
    return OutsideShare(*map(float, mean), *map(float, error), *((float(a), float(b)) for a, b in zip(low, high)),
                        samples, n_engines)
