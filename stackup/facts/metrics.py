"""What the ranking ranks: one row of metrics per scheme, with their 95 % intervals.

Operating clearance (mean, spread, share outside the design window with
where it comes from), the clearance at assembly and at the cold start (mean,
spread, share of bearings below the engine's minimum clearance at either), film and life (:func:`stackup.facts.tables.film_numbers`:
share of bearings below h_lim,cr; Levanov's operability criteria at the worst
bearing position, the share of its bearings with alpha above 20 % and the
share living less than the target; the engines' life, their weakest
bearing's, B10 and median) and shell stock (grades used, stock-outs, surplus); and, for
declared scenarios, each scenario's rows beside the study's on the same
engines. :func:`stackup.rank.ranked` orders them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..assembly import ASSEMBLED, SHELL_STOCKOUT
from ..stats import proportion_ci
from ..tail import share_interval
from ..study.inputs import load_inputs
from .declared import StudyParameters, parsed
from .tables import assembled, film_numbers, kept_summaries, operating_moments, soaked

#: Fewest bearings counted outside the window for the count to decide; below it a tail estimate does, if given.
MIN_COUNTED = 20
#: ``outside_window_source`` of a share the ranking took from the tail estimates, per tails method.
TAIL_SOURCES = {"conditional": "shells integrated out", "splitting": "generalized splitting"}
#: Default practical threshold of the share of bearings outside the window [ppm]: schemes whose shares differ
#: by less do not differ on the clearance (a comparison's ``negligible``; the dataset attribute ``negligible_ppm``).
NEGLIGIBLE_PPM = 1.0


@dataclass(frozen=True)
class RankingRows:
    """The metrics of every scheme of a study, which :func:`stackup.rank.ranked` orders.

    Attributes
    ----------
    rows : dict of str -> dict
        Scheme -> its metrics (the columns of :func:`stackup.rank.rank`), in the dataset's order.
    scenarios : dict of str -> (dict, dict)
        Scenario label -> (its rows, the study's rows on the same engines), counted shares both.
    window : (float, float)
        The design window of the operating clearance the shares are counted against [m].
    study : dict
        The study's parameters (its ``study`` attribute).
    negligible : float
        Shares outside the window that differ by less than this [ppm] do not separate schemes.
    """

    rows: dict
    scenarios: dict
    window: tuple
    study: dict
    negligible: float = NEGLIGIBLE_PPM


def _clearance_metrics(d, window):
    """Bearings, clearance mean and spread [m], bearings outside the window, assembled bearings, stock-outs."""
    mean, std = operating_moments(d)
    if kept_summaries(d):
        counts = d.status_count.values
        return (int(counts.sum()), mean, std, int(d.outside_window_count), int(counts[ASSEMBLED]),
                int(counts[SHELL_STOCKOUT]))
    c = assembled(d, "clearance_operating")
    return (int(d.status.size), mean, std, np.count_nonzero((c < window[0]) | (c > window[1])), c.size,
            np.count_nonzero(d.status.values == SHELL_STOCKOUT))


def _outside(counted, assembled_bearings, tail):
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
    share, lo, hi = proportion_ci(counted, assembled_bearings)
    return share * 1e6, (lo * 1e6, hi * 1e6), "counted"


def part_grades(ds):
    """Scheme -> the classes its housing bores and journals are graded into (0 where neither is graded).

    Read from the scheme texts the study stored (``input_files``); a scheme
    not among them (a dataset put together by hand) from the grade labels
    its bearings carry, where the dataset keeps every engine.
    """
    counts = {}
    files = parsed(ds, "input_files", required=False)
    if files is not None and "study" in ds.attrs:
        names = StudyParameters.of(ds).schemes
        try:
            counts = {s.name: sum(len(g.labels) for g in (s.housing, s.journal) if g.graded)
                      for s in load_inputs(files, names)[1]}
        except (KeyError, ValueError):  # texts of another layout: the labels below
            counts = {}
    for s in ds.scheme.values:
        if str(s) not in counts and "housing_grade" in ds:
            d = ds.sel(scheme=s)
            counts[str(s)] = sum(len(set(np.unique(d[v].values)) - {""}) for v in ("housing_grade", "journal_grade"))
    return counts


def scheme_metrics(d, window, h_lim_cr, tail=None, part_grades=np.nan):
    """One scheme's row of metrics (``d`` one scheme of a study dataset; ``tail`` its tail estimates or None;
    ``part_grades`` its housing and journal classes, :func:`part_grades`)."""
    bearings, mean, std, outside, assembled_bearings, stockouts = _clearance_metrics(d, window)
    outside_ppm, outside_ci, source = _outside(outside, assembled_bearings, tail)
    stockout = proportion_ci(stockouts, bearings)
    row = {
        "bearings": bearings,
        "clearance_mean_um": mean * 1e6,
        "clearance_std_um": std * 1e6,
        "outside_window_ppm": outside_ppm,
        "outside_window_ppm_ci": outside_ci,
        "outside_window_counted": int(outside),
        "outside_window_source": source,
        "stockout_ppm": 1e6 * stockout[0],
        "stockout_ppm_ci": (1e6 * stockout[1], 1e6 * stockout[2]),
        "shell_grades": int(d.grade_in_scheme.values.sum()),
        "part_grades": part_grades,
        "surplus_pct": 100.0 * float(d.shells_left.sum()) / max(float(d.shells_made.sum()), 1.0),
    }
    cold = soaked(d)
    if cold is not None:
        below = proportion_ci(cold.below_minimum, cold.assembled)
        row.update({"below_minimum_ppm": 1e6 * below[0], "below_minimum_ppm_ci": (1e6 * below[1], 1e6 * below[2]),
                    "below_minimum_counted": cold.below_minimum,
                    "clearance_assembly_mean_um": cold.assembly_mean * 1e6,
                    "clearance_assembly_std_um": cold.assembly_std * 1e6,
                    "clearance_cold_mean_um": cold.cold_mean * 1e6, "clearance_cold_std_um": cold.cold_std * 1e6})
    film = film_numbers(d, h_lim_cr)
    if film is not None:
        below, scuff, short = film.below_critical, film.alpha_over_limit, film.life_below_target
        b10, median = film.engine_life_b10_h, film.engine_life_median_h
        row.update({
            "film_bearings": int(film.h.size),
            "film_left_out": film.left_out,
            "h_min_below_critical_pct": 100 * below[0], "h_min_below_critical_pct_ci": (100 * below[1], 100 * below[2]),
            "alpha_over_limit_pct": 100 * scuff[0], "alpha_over_limit_pct_ci": (100 * scuff[1], 100 * scuff[2]),
            "alpha_over_limit_position": int(d.bearing.values[film.alpha_position]),
            "life_below_target_pct": 100 * short[0], "life_below_target_pct_ci": (100 * short[1], 100 * short[2]),
            "life_below_target_position": int(d.bearing.values[film.life_position]),
            "engine_life_b10_h": b10[0], "engine_life_b10_h_ci": b10[1:],
            "engine_life_median_h": median[0], "engine_life_median_h_ci": median[1:],
        })
    return row


def _rows(ds, window, h_lim_cr, tails=None):
    """Scheme -> :func:`scheme_metrics` of every scheme of ``ds``."""
    def tail(s):
        return tails.sel(scheme=s) if tails is not None and s in tails.scheme.values else None

    parts = part_grades(ds)
    return {str(s): scheme_metrics(ds.sel(scheme=s), window, h_lim_cr, tail(str(s)), parts.get(str(s), np.nan))
            for s in ds.scheme.values}


def _same_engines(ds, other, counted, window, h_lim_cr):
    """The study's rows on the engines a scenario ran its mechanical chain on (its first ones).

    A scenario may run the crankshaft, film and life on fewer engines than the
    study; its changes are taken against the study's same engines (the same
    parts: common random numbers), not against a larger sample.
    """
    m = other.sizes.get("mech_engine")
    if not m or "mech_engine" not in ds.sizes or m >= ds.sizes["mech_engine"]:
        return counted
    return _rows(ds.isel(mech_engine=slice(0, m)), window, h_lim_cr)


def counted_window(ds):
    """The dataset's design window (lower, upper) [m]; one window even where concatenation spread it over schemes."""
    window = ds.clearance_window
    spread = [d for d in window.dims if d != "bound"]
    first = window.isel({d: 0 for d in spread})
    if not bool((window == first).all()):
        raise ValueError("clearance_window: the schemes of this dataset were counted against different windows")
    return tuple(float(v) for v in first.values)


def counted_outside(ds):
    """Bearings the study counted outside its design window, per scheme: ``{scheme: count}``."""
    window = counted_window(ds)
    return {str(s): int(_clearance_metrics(ds.sel(scheme=s), window)[3]) for s in ds.scheme.values}


def ranking_window(ds, window=None, tails=None):
    """The window a ranking counts against [m]: ``window`` or the dataset's, checked against what was counted."""
    counted = counted_window(ds)
    window = counted if window is None else tuple(window)
    if len(window) != 2 or not window[0] < window[1]:
        raise ValueError(f"window: {window!r} is not a (lower, upper) clearance window in m")
    if kept_summaries(ds) and not np.allclose(window, counted, rtol=0, atol=1e-12):
        raise ValueError(f"window: {window!r} m differs from {counted!r} m, the window the summaries count; "
                         "rank a study that keeps every engine, or run the study with that window")
    if tails is not None and not np.allclose(tails.attrs["window"], window, rtol=0, atol=1e-12):
        raise ValueError(f"tails: estimated for the window {tails.attrs['window']!r} m, not {window!r} m")
    return window


def negligible_of(ds, negligible=None):
    """The practical threshold [ppm]: ``negligible``, or the dataset's ``negligible_ppm``, or :data:`NEGLIGIBLE_PPM`."""
    value = float(ds.attrs.get("negligible_ppm", NEGLIGIBLE_PPM) if negligible is None else negligible)
    if not np.isfinite(value) or value < 0:
        raise ValueError(f"negligible: {value!r} ppm is not a share of bearings >= 0")
    return value


def ranking_rows(ds, *, scenarios=None, tails=None, window=None, h_lim_cr=None, negligible=None):
    """The :class:`RankingRows` of a study dataset (the parameters are :func:`stackup.rank.rank`'s)."""
    negligible = negligible_of(ds, negligible)
    window = ranking_window(ds, window, tails)
    h_lim_cr = float(ds.critical_film.max()) if h_lim_cr is None else float(h_lim_cr)
    rows = _rows(ds, window, h_lim_cr, tails)
    pairs = {}
    if scenarios:
        counted = _rows(ds, window, h_lim_cr) if tails is not None else rows  # counted shares against counted
        pairs = {label: (_rows(other, window, h_lim_cr), _same_engines(ds, other, counted, window, h_lim_cr))
                 for label, other in scenarios.items()}
    return RankingRows(rows, pairs, window, dict(StudyParameters.of(ds).items), negligible)
