"""Ranking schemes by robustness, with confidence, from study datasets.

:func:`rank` gives one row per scheme: operating clearance (mean, spread, share
outside the design window with a 95 % interval), film and life (share of
bearings below h_lim,cr, share with alpha above 20 %, life B10 and median with
intervals), shell stock (grades used, stock-outs, surplus) and, where
scenario datasets are given, the worst-case degradation of each metric over
them.

Film and life metrics read the bearings whose film is a number: a bearing
whose film collapsed, did not become periodic or failed is NaN in the dataset
(``film_status`` says why), is left out of every metric and counted in
``film_left_out``.

Ranking rule (stated in the table's attrs): schemes are compared pairwise on
the metrics in :data:`RULE`, in order; the first metric whose 95 % intervals
do not overlap decides; if every metric's intervals overlap the two schemes
tie. A scheme's rank is one plus the number of schemes that beat it, so tied
schemes share a rank and the result does not depend on the order of schemes.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ._module import callable_module
from .facts import ranking_rows

#: (column, better) in order of precedence: share outside the clearance window,
#: share of bearings in boundary friction above the scuffing limit, median life.
RULE = (("outside_window_ppm", "lower"), ("alpha_over_limit_pct", "lower"), ("life_median_h", "higher"))


def _beats(a, b):
    """+1 if row a beats row b on the first metric of RULE whose intervals separate, -1 if b beats a, 0 tie."""
    for column, better in RULE:
        if column not in a or column not in b or pd.isna(a[column]) or pd.isna(b[column]):
            continue
        lo_a, hi_a = a[f"{column}_ci"]
        lo_b, hi_b = b[f"{column}_ci"]
        if hi_a < lo_b:
            return 1 if better == "lower" else -1
        if hi_b < lo_a:
            return -1 if better == "lower" else 1
    return 0


def _worst(frame, scenarios):
    """Per metric of the rule, the worst change over the scenarios and the scenario that gives it, as columns."""
    names = list(frame.index)
    for column, better in RULE:
        if column not in frame:
            continue
        changes = {label: pd.Series({s: alt[s].get(column, np.nan) - base[s].get(column, np.nan) for s in names})
                   for label, (alt, base) in scenarios.items()}
        table = pd.DataFrame(changes).dropna(axis=1, how="all")  # scenarios without this metric
        if table.empty:
            continue
        worse = table if better == "lower" else -table
        frame[f"worst_{column}"] = table.to_numpy()[np.arange(len(names)), worse.to_numpy().argmax(axis=1)]
        frame[f"worst_{column}_scenario"] = worse.idxmax(axis=1)


def ranked(ranking):
    """The rows of a :class:`stackup.facts.RankingRows` ranked by :data:`RULE`, as :func:`rank` returns them."""
    rows = ranking.rows
    frame = pd.DataFrame.from_dict(rows, orient="index")
    frame.index.name = "scheme"
    names = list(frame.index)
    frame["rank"] = [1 + sum(_beats(rows[o], rows[s]) == 1 for o in names if o != s) for s in names]
    if ranking.scenarios:
        _worst(frame, ranking.scenarios)
    frame = frame.sort_values(["rank", *[c for c, _ in RULE if c in frame]])
    frame.attrs["rule"] = ("pairwise on " + ", then ".join(f"{c} ({b} is better)" for c, b in RULE)
                           + "; the first metric whose 95 % intervals do not overlap decides; otherwise a tie")
    frame.attrs["window_m"] = ranking.window
    frame.attrs["study"] = ranking.study
    return frame


def rank(ds, *, scenarios=None, tails=None, window=None, h_lim_cr=None):
    """Schemes of a study dataset ranked by robustness.

    Parameters
    ----------
    ds : xarray.Dataset
        A :class:`stackup.Study` result, every engine kept or its streaming
        summaries (``keep="summaries"``; then ``window`` is the engine's,
        the one the summaries count).
    scenarios : dict of str -> xarray.Dataset, optional
        The same schemes under declared scenarios (process mean shift, gauge
        error, misalignment, ...); adds, per metric, the worst change over the
        scenarios against ``ds`` (``worst_<metric>``) and the scenario that
        gives it (counted shares against counted shares).
    tails : xarray.Dataset, optional
        Tail estimates of the shares beyond each window edge
        (:func:`stackup.comparison.tails_dataset`, for the dataset's
        window): a scheme with fewer than :data:`~stackup.facts.MIN_COUNTED`
        bearings counted outside the window is ranked on them
        (``outside_window_source``).
    window : (float, float), optional
        Design window of the operating clearance [m]; default the engine's
        (the dataset's ``clearance_window``).
    h_lim_cr : float, optional
        Critical film thickness [m]; default the engine's (the dataset's ``critical_film``).

    Returns
    -------
    pandas.DataFrame
        One row per scheme, sorted by rank; ``rank`` (ties share a rank) and
        the metrics with their 95 % intervals (``*_ci`` columns), computed by
        :func:`stackup.facts.ranking_rows`.
    """
    return ranked(ranking_rows(ds, scenarios=scenarios, tails=tails, window=window, h_lim_cr=h_lim_cr))


callable_module(__name__, rank)
