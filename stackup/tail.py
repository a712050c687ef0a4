r"""ppm-level tails of the operating clearance by importance sampling.

A plain Monte Carlo estimate of a share :math:`p` needs about :math:`100/p`
bearings for a 20 % error: 10^8 for 1 ppm. Here each bearing's own bore and
journal normals are drawn from shifted densities :math:`N(t, 1)` (towards the
tail: a larger bore and a smaller journal for the upper tail), and each
bearing is weighted by its likelihood ratio

.. math:: w = \prod_k \frac{\varphi(z_k)}{\varphi(z_k - t_k)} = \prod_k \exp\left(-t_k z_k + t_k^2/2\right)

so :math:`\hat p = \overline{w\,\mathbf 1[C \notin \text{window}]}` is unbiased
with the standard error of that mean. The model is the study's clearance chain
without shell stock: block and crankshaft shares, gauges (untilted),
grading and pairing by the scheme, shells drawn at random from a large pool
made to the scheme's plan and conditioned on the grade the pair asks for (the
same conditional under both densities, so it cancels from the ratio), and the
press fit. Stock-outs are the study's business, not this estimator's.

References
----------
.. [1] Rubinstein, R. Y., Kroese, D. P., *Simulation and the Monte Carlo
   Method*, 3rd ed., Wiley, 2017, sec. 5.7 (importance sampling).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import _validate as check
from ._random import PILOT_KEY, as_generator, lot_generator, seed_sequence
from .engines import load_engine
from .fit import press_fit
from .parts import ShellNormals
from .schemes import load as load_scheme
from .stats import Z95
from .study.pilot import pilot_parts, shell_plan

#: Shells in the pool the estimator draws from, per scheme.
POOL = 400_000


@dataclass(frozen=True)
class TailEstimate:
    """A share with its standard error and 95 % interval (normal approximation)."""

    share: float
    standard_error: float
    interval: tuple
    bearings: int
    effective_bearings: float  # Kish's effective sample size of the weights


def _pool(engine, scheme, seed, pilot_engines):
    aim = shell_plan(engine, scheme, pilot_parts(engine, seed, pilot_engines)).aim
    rng = lot_generator(seed_sequence(seed), PILOT_KEY - 1)
    normals = ShellNormals(*(rng.standard_normal(POOL) for _ in range(3)))
    shells = engine.shell_wall.make(scheme, normals, aim)
    return [np.flatnonzero(shells.grade == g) for g in range(len(scheme.shell.labels))], shells


def clearance_tail(engine, scheme, *, n_bearings, side="upper", threshold=None, tilt=0.0, seed=0,
                   pilot_engines=20_000):
    """Share of bearings whose operating clearance is beyond ``threshold``, by importance sampling.

    Parameters
    ----------
    engine, scheme : str or object
        Built-in names, files or loaded objects.
    n_bearings : int
        Bearings to sample (each from its own engine, so bearings are independent).
    side : {"upper", "lower"}
        Share above or below ``threshold``.
    threshold : float, optional
        Clearance [m]; default the engine's design window edge on that side.
    tilt : float
        Shift :math:`t` of the bore and journal own normals towards the tail
        [standard deviations]; 0 is plain Monte Carlo on the same model.
    seed : int
    """
    engine = load_engine(engine)
    scheme = load_scheme(scheme)
    n = check.integer("n_bearings", n_bearings, minimum=1)
    check.one_of("side", side, ("upper", "lower"))
    tilt = float(check.in_range("tilt", tilt, 0.0, 8.0))
    if threshold is None:
        threshold = engine.clearance_window[1 if side == "upper" else 0]
    sign = 1.0 if side == "upper" else -1.0
    pools, shells = _pool(engine, scheme, seed, pilot_engines)
    rng = as_generator(seed_sequence(seed).spawn(1)[0])
    hb, jd = engine.housing_bore, engine.journal_d
    # own normals drawn from N(t, 1) towards the tail: bore up and journal down for the upper tail
    t_bore, t_journal = sign * tilt, -sign * tilt
    z_bore = rng.standard_normal(n) + t_bore
    z_journal = rng.standard_normal(n) + t_journal
    log_w = -t_bore * z_bore + t_bore**2 / 2 - t_journal * z_journal + t_journal**2 / 2
    bore = hb.true_sizes(rng.standard_normal(n), z_bore[:, None])[:, 0]
    journal = jd.true_sizes(rng.standard_normal(n), z_journal[:, None])[:, 0]
    h_read, j_read = scheme.read(hb.gauge.read(bore, rng.standard_normal(n)), jd.gauge.read(journal, rng.standard_normal(n)))
    upper, lower = scheme.pair_indices(*scheme.classify(h_read, j_read))
    ok = (upper >= 0) & ~hb.outside(h_read) & ~jd.outside(j_read)

    def take(grades):
        index = np.zeros(n, np.int64)
        for g, members in enumerate(pools):
            mine = ok & (grades == g)
            if mine.any():
                if members.size == 0:
                    raise ValueError(f"scheme {scheme.name}: the shell pool has no grade {scheme.shell.labels[g]}")
                index[mine] = members[rng.integers(0, members.size, mine.sum())]
        return index

    up_i, lo_i = take(upper), take(lower)
    fit = press_fit(housing_bore=bore[ok], shell_wall=0.5 * (shells.wall[up_i[ok]] + shells.wall[lo_i[ok]]),
                    crush_height=0.5 * (shells.crush[up_i[ok]] + shells.crush[lo_i[ok]]), journal_d=journal[ok],
                    **engine.press_fit.kwargs())
    beyond = np.zeros(n, bool)
    beyond[ok] = sign * (fit.clearance - threshold) > 0
    w = np.exp(log_w)
    values = np.where(beyond, w, 0.0)
    share = values.mean()
    se = values.std(ddof=1) / np.sqrt(n)
    ess = w.sum() ** 2 / np.sum(w**2)
    return TailEstimate(float(share), float(se), (float(max(share - Z95 * se, 0.0)), float(share + Z95 * se)), n,
                        float(ess))
