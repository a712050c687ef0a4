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

import json

import numpy as np
import pandas as pd

from ._module import callable_module
from .assembly import ASSEMBLED, SHELL_STOCKOUT
from .life import ALPHA_SCUFFING
from .stats import proportion_ci, quantile_ci
from .study.schema import flag
from .tail import share_interval

#: (column, better) in order of precedence: share outside the clearance window,
#: share of bearings in boundary friction above the scuffing limit, median life.
RULE = (("outside_window_ppm", "lower"), ("alpha_over_limit_pct", "lower"), ("life_median_h", "higher"))


def _clearance_metrics(d, window):
    """Bearings, clearance mean and spread [m], bearings outside the window, assembled bearings, stock-outs."""
    if d.attrs.get("kept") == "summaries":
        counts = d.status_count.values
        return (int(counts.sum()), float(d.clearance_operating_mean), float(d.clearance_operating_std),
                int(d.outside_window_count), int(counts[ASSEMBLED]), int(counts[SHELL_STOCKOUT]))
    ok = d.status.values == ASSEMBLED
    c = d.clearance_operating.values[ok]
    return (int(ok.size), float(c.mean()), float(c.std(ddof=1)),
            np.count_nonzero((c < window[0]) | (c > window[1])), c.size,
            np.count_nonzero(d.status.values == SHELL_STOCKOUT))


#: Fewest bearings counted outside the window for the count to decide; below it a tail estimate does, if given.
MIN_COUNTED = 20
#: ``outside_window_source`` of a share the ranking took from the tail estimates, per tails method.
TAIL_SOURCES = {"conditional": "shells integrated out", "splitting": "generalized splitting"}


def _outside(counted, assembled, tail):
    """Share outside the window [ppm] with its 95 % interval and where it comes from.

    From the tail estimates where the study counted fewer than
    :data:`MIN_COUNTED`: the conditional tier's share outside the window and
    its Student interval, or generalized splitting's two edges (independent
    runs, so shares add and variances add) with the interval of the
    equivalent count (:func:`stackup.tail.share_interval`); an edge whose
    estimate found no bearing adds its upper bound.
    """
    if counted < MIN_COUNTED and tail is not None and "tail_outside_share" in tail:
        share, (lo, hi) = float(tail.tail_outside_share), tail.tail_outside_interval.values
        return share * 1e6, (float(lo) * 1e6, float(hi) * 1e6), TAIL_SOURCES["conditional"]
    if counted < MIN_COUNTED and tail is not None and np.all(np.isfinite(tail.tail_share.values)):
        shares, errors = tail.tail_share.values, tail.tail_standard_error.values
        share = float(shares.sum())
        lo, hi = share_interval(share, float(np.hypot(*np.where(shares > 0, errors, 0.0))))
        hi = (0.0 if share == 0 else hi) + float(tail.tail_interval.values[shares == 0, 1].sum())
        return share * 1e6, (lo * 1e6, hi * 1e6), TAIL_SOURCES["splitting"]
    share, lo, hi = proportion_ci(counted, assembled)
    return share * 1e6, (lo * 1e6, hi * 1e6), "counted"


def _scheme_metrics(d, window, h_lim_cr, tail=None):
    bearings, mean, std, outside, assembled, stockouts = _clearance_metrics(d, window)
    outside_ppm, outside_ci, source = _outside(outside, assembled, tail)
    row = {
        "bearings": bearings,
        "clearance_mean_um": mean * 1e6,
        "clearance_std_um": std * 1e6,
        "outside_window_ppm": outside_ppm,
        "outside_window_ppm_ci": outside_ci,
        "outside_window_counted": int(outside),
        "outside_window_source": source,
        "stockout_ppm": 1e6 * float(stockouts) / bearings,
        "shell_grades": int(d.grade_in_scheme.values.sum()),
        "surplus_pct": 100.0 * float(d.shells_left.sum()) / max(float(d.shells_made.sum()), 1.0),
    }
    done = d.crank_status.values == flag(d.crank_status, "converged")
    if done.any() and "h_min" in d:
        # a bearing whose film is not a number (collapsed, not periodic, failed: NaN) is left out and counted
        h, a, life = (_numbers(d[name].values[done]) for name in ("h_min", "alpha", "life"))
        life = life / 3600
        below = proportion_ci(np.count_nonzero(h < h_lim_cr), h.size)
        scuff = proportion_ci(np.count_nonzero(a > ALPHA_SCUFFING), a.size)
        b10 = quantile_ci(life, 0.10)
        median = quantile_ci(life, 0.5)
        row.update({
            "film_bearings": int(h.size),
            "film_left_out": int(np.count_nonzero(np.isnan(d.h_min.values[done]))),
            "h_min_below_critical_pct": 100 * below[0], "h_min_below_critical_pct_ci": (100 * below[1], 100 * below[2]),
            "alpha_over_limit_pct": 100 * scuff[0], "alpha_over_limit_pct_ci": (100 * scuff[1], 100 * scuff[2]),
            "life_b10_h": b10[0], "life_b10_h_ci": b10[1:],
            "life_median_h": median[0], "life_median_h_ci": median[1:],
        })
    return row


def _same_engines(ds, other, counted, window, h_lim_cr):
    """The study's metrics on the engines a scenario ran its mechanical chain on (its first ones).

    A scenario may run the crankshaft, film and life on fewer engines than the
    study; its changes are taken against the study's same engines (the same
    parts: common random numbers), not against a larger sample.
    """
    m = other.sizes.get("mech_engine")
    if not m or "mech_engine" not in ds.sizes or m >= ds.sizes["mech_engine"]:
        return counted
    same = ds.isel(mech_engine=slice(0, m))
    return {str(s): _scheme_metrics(same.sel(scheme=s), window, h_lim_cr) for s in ds.scheme.values}


def _numbers(values):
    """The values that are numbers (NaN left out), flat."""
    values = np.asarray(values, dtype=float).ravel()
    return values[~np.isnan(values)]


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


def _counted_window(ds):
    """The dataset's design window (lower, upper) [m]; one window even where concatenation spread it over schemes."""
    window = ds.clearance_window
    spread = [d for d in window.dims if d != "bound"]
    first = window.isel({d: 0 for d in spread})
    if not bool((window == first).all()):
        raise ValueError("clearance_window: the schemes of this dataset were counted against different windows")
    return tuple(float(v) for v in first.values)


def counted_outside(ds):
    """Bearings the study counted outside its design window, per scheme: ``{scheme: count}``."""
    window = _counted_window(ds)
    return {str(s): int(_clearance_metrics(ds.sel(scheme=s), window)[3]) for s in ds.scheme.values}


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
        window): a scheme with fewer than :data:`MIN_COUNTED` bearings counted
        outside the window is ranked on them (``outside_window_source``).
    window : (float, float), optional
        Design window of the operating clearance [m]; default the engine's
        (the dataset's ``clearance_window``).
    h_lim_cr : float, optional
        Critical film thickness [m]; default the engine's (the dataset's ``critical_film``).

    Returns
    -------
    pandas.DataFrame
        One row per scheme, sorted by rank; ``rank`` (ties share a rank) and
        the metrics with their 95 % intervals (``*_ci`` columns).
    """
    counted = _counted_window(ds)
    h_lim_cr = float(ds.critical_film.max()) if h_lim_cr is None else float(h_lim_cr)
    window = counted if window is None else tuple(window)
    if len(window) != 2 or not window[0] < window[1]:
        raise ValueError(f"window: {window!r} is not a (lower, upper) clearance window in m")
    if ds.attrs.get("kept") == "summaries" and not np.allclose(window, counted, rtol=0, atol=1e-12):
        raise ValueError(f"window: {window!r} m differs from {counted!r} m, the window the summaries count; "
                         "rank a study that keeps every engine, or run the study with that window")
    if tails is not None and not np.allclose(tails.attrs["window"], window, rtol=0, atol=1e-12):
        raise ValueError(f"tails: estimated for the window {tails.attrs['window']!r} m, not {window!r} m")

    def tail(s):
        return tails.sel(scheme=s) if tails is not None and s in tails.scheme.values else None

    rows = {str(s): _scheme_metrics(ds.sel(scheme=s), window, h_lim_cr, tail(str(s))) for s in ds.scheme.values}
    counted = {str(s): _scheme_metrics(ds.sel(scheme=s), window, h_lim_cr) for s in ds.scheme.values}
    frame = pd.DataFrame.from_dict(rows, orient="index")
    frame.index.name = "scheme"
    names = list(frame.index)
    frame["rank"] = [1 + sum(_beats(rows[o], rows[s]) == 1 for o in names if o != s) for s in names]
    if scenarios:
        # each scenario's metrics and the study's on the same engines, once for every metric of the rule
        pairs = {label: ({str(s): _scheme_metrics(other.sel(scheme=s), window, h_lim_cr) for s in other.scheme.values},
                         _same_engines(ds, other, counted, window, h_lim_cr)) for label, other in scenarios.items()}
        for column, _ in RULE:
            if column not in frame:
                continue
            changes = {label: pd.Series({s: alt[s].get(column, np.nan) - base[s].get(column, np.nan) for s in names})
                       for label, (alt, base) in pairs.items()}
            table = pd.DataFrame(changes).dropna(axis=1, how="all")  # scenarios without this metric
            if table.empty:
                continue
            worse = table if dict(RULE)[column] == "lower" else -table
            frame[f"worst_{column}"] = table.to_numpy()[np.arange(len(names)), worse.to_numpy().argmax(axis=1)]
            frame[f"worst_{column}_scenario"] = worse.idxmax(axis=1)
    frame = frame.sort_values(["rank", *[c for c, _ in RULE if c in frame]])
    frame.attrs["rule"] = ("pairwise on " + ", then ".join(f"{c} ({b} is better)" for c, b in RULE)
                           + "; the first metric whose 95 % intervals do not overlap decides; otherwise a tie")
    frame.attrs["window_m"] = window
    frame.attrs["study"] = json.loads(ds.attrs["study"])
    return frame


callable_module(__name__, rank)
