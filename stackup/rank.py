"""Ranking schemes by robustness, then cost, with confidence, from study datasets.

:func:`rank` gives one row per scheme: operating clearance (mean, spread, share
outside the design window with a 95 % interval), film and life (share of
bearings below h_lim,cr, share with alpha above 20 %, life B10 and median with
intervals), cost (shell grades, housing and journal grades, stock-outs,
surplus) and, where scenario datasets are given, the worst-case degradation
of each metric over them.

Film and life metrics read the bearings whose film is a number: a bearing
whose film collapsed, did not become periodic or failed is NaN in the dataset
(``film_status`` says why), is left out of every metric and counted in
``film_left_out``.

Ranking rule (:data:`RULE`, stated in the table's attrs): the metrics are
taken in order. On each, the schemes still level are split into groups: the
best one (lowest share, fewest grades, ...) and every scheme that does not
differ from it, then the best of the rest and those level with it, and so
on; the next metric orders the schemes within each group. Two schemes differ
on a metric when their 95 % intervals do not overlap and their values differ
by at least the metric's practical threshold: ``negligible`` [ppm] for the
share outside the window (default :data:`stackup.facts.NEGLIGIBLE_PPM`), so
two shares of a fraction of a ppm do not separate schemes and cost decides
between them. Schemes level on every metric tie and share a rank; a rank is
one plus the number of schemes ranked before, and the result does not depend
on the order of schemes.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ._module import callable_module
from .facts import ranking_rows

#: (column, better, practical threshold) in order of precedence: bearings below the minimum clearance at assembly
#: or the cold start first (a bearing in interference is worse than one outside the operating window), then the
#: window. The threshold is the least difference that
#: separates two schemes (beyond their 95 % intervals, where the column has them): "negligible" is the
#: ranking's share of bearings outside the window that does not matter [ppm]; the surplus [% of the shells made]
#: moves by about a percentage point with the rounding of lots.
RULE = (("below_minimum_ppm", "lower", "negligible"),
        ("outside_window_ppm", "lower", "negligible"),
        ("alpha_over_limit_pct", "lower", 0.0),
        ("life_below_target_pct", "lower", 0.0),
        ("shell_grades", "lower", 0.0),
        ("part_grades", "lower", 0.0),
        ("stockout_ppm", "lower", 0.0),
        ("surplus_pct", "lower", 1.0),
        ("engine_life_median_h", "higher", 0.0))
#: The metrics of the rule that are the scheme's cost.
COST = ("shell_grades", "part_grades", "stockout_ppm", "surplus_pct")
#: The metrics whose worst change over the scenarios the ranking gives (``worst_<column>``).
WORST = (("outside_window_ppm", "lower"), ("alpha_over_limit_pct", "lower"), ("life_below_target_pct", "lower"),
         ("engine_life_median_h", "higher"))


def _value(row, column):
    value = row.get(column, np.nan)
    return float(value) if value is not None and np.isfinite(value) else np.nan


def _interval(row, column):
    """The 95 % interval of a metric, or the value itself for an exact one (grades, surplus)."""
    ci = row.get(f"{column}_ci")
    return tuple(map(float, ci)) if isinstance(ci, tuple) else (_value(row, column),) * 2


def differs(best, other, column, better, threshold):
    """``other`` is worse than ``best`` on ``column``: 95 % intervals apart and values ``threshold`` or more apart."""
    sign = 1.0 if better == "lower" else -1.0
    (lo_b, hi_b), (lo_o, hi_o) = _interval(best, column), _interval(other, column)
    apart = hi_b < lo_o if better == "lower" else lo_b > hi_o
    gap = sign * (_value(other, column) - _value(best, column))
    return bool(apart and gap > 0 and gap >= threshold)


def _groups(names, rows, rule, negligible):
    """The schemes ``names`` in ordered groups of ties (lists), by the metrics of ``rule`` in turn."""
    if len(names) <= 1 or not rule:
        return [sorted(names)]
    (column, better, threshold), rest = rule[0], rule[1:]
    if any(np.isnan(_value(rows[n], column)) for n in names):  # a metric some lack (no film): it cannot decide
        return _groups(names, rows, rest, negligible)
    threshold = negligible if threshold == "negligible" else threshold
    sign = 1.0 if better == "lower" else -1.0
    remaining = sorted(names, key=lambda n: (sign * _value(rows[n], column), n))
    out = []
    while remaining:
        best = rows[remaining[0]]
        level = [n for n in remaining if not differs(best, rows[n], column, better, threshold)]
        remaining = [n for n in remaining if n not in level]
        out += _groups(level, rows, rest, negligible)
    return out


def rule_text(negligible):
    """The rule in words with column names, as the table's attrs state it."""
    parts = [f"{c} ({b} is better{f', by {negligible:g} or more' if t == 'negligible' else ''})"
             for c, b, t in RULE]
    return ("in turn on " + ", then ".join(parts) + "; schemes differ on a metric where their 95 % intervals "
            "do not overlap and their values differ by at least its threshold; the best scheme and those not "
            "different from it are ranked on the next metric; schemes level on every metric tie")


def _worst(frame, scenarios):
    """Per metric of the rule, the worst change over the scenarios and the scenario that gives it, as columns."""
    names = list(frame.index)
    for column, better in WORST:
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
    order, place = [], {}
    for group in _groups(list(frame.index), rows, RULE, ranking.negligible):
        place.update({name: 1 + len(order) for name in group})
        order += group
    frame["rank"] = [place[n] for n in frame.index]
    frame = frame.loc[order]
    if ranking.scenarios:
        _worst(frame, ranking.scenarios)
    frame.attrs["rule"] = rule_text(ranking.negligible)
    frame.attrs["negligible_ppm"] = ranking.negligible
    frame.attrs["window_m"] = ranking.window
    frame.attrs["study"] = ranking.study
    return frame


def _rank_source(ds, scenarios, tails):
    """The dataset, scenarios and tails to rank: a comparison's parts, or a study dataset that is no comparison's."""
    if hasattr(ds, "dataset"):  # a stackup.comparison.Comparison
        return ds.dataset, ds.scenarios if scenarios is None else scenarios, ds.tails if tails is None else tails
    if "comparison" in ds.attrs and tails is None:
        raise ValueError("ds: the study of a comparison `stackup.compare` saved, without its tail estimates and "
                         "scenarios (groups of the same file, which xarray.open_dataset does not read), so its "
                         "ranking would not be the report's; rank the comparison: "
                         "stackup.rank(stackup.io.open_comparison(path))")
    return ds, scenarios, tails


def rank(ds, *, scenarios=None, tails=None, window=None, h_lim_cr=None, negligible=None):
    """Schemes of a study dataset, or of a comparison, ranked by robustness, then cost.

    Parameters
    ----------
    ds : xarray.Dataset or stackup.comparison.Comparison
        A :class:`stackup.Study` result, every engine kept or its streaming
        summaries (``keep="summaries"``; then ``window`` is the engine's, the
        one the summaries count); or a comparison
        (:func:`stackup.compare`, or a saved one:
        ``stackup.rank(stackup.io.open_comparison(path))``), ranked with its
        scenarios and tail estimates as its report ranks it. The study
        dataset of a saved comparison read alone (``xarray.open_dataset``)
        is refused: its ranking needs the tail estimates.
    scenarios : dict of str -> xarray.Dataset, optional
        The same schemes under declared scenarios (process mean shift, gauge
        error, misalignment, model inputs, ...); adds, per metric, the worst
        change over the scenarios against ``ds`` (``worst_<metric>``) and the
        scenario that gives it (counted shares against counted shares).
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
    negligible : float, optional
        Shares of bearings outside the window that differ by less than this
        do not separate schemes [ppm]; default the comparison's
        (``negligible_ppm`` attribute), else :data:`~stackup.facts.NEGLIGIBLE_PPM`.

    Returns
    -------
    pandas.DataFrame
        One row per scheme, sorted by rank; ``rank`` (ties share a rank) and
        the metrics with their 95 % intervals (``*_ci`` columns), computed by
        :func:`stackup.facts.ranking_rows`; the rule in ``attrs["rule"]``.
    """
    ds, scenarios, tails = _rank_source(ds, scenarios, tails)
    return ranked(ranking_rows(ds, scenarios=scenarios or None, tails=tails, window=window, h_lim_cr=h_lim_cr,
                               negligible=negligible))


callable_module(__name__, rank)
