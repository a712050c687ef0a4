"""Numbers of a study dataset per scheme (and bearing position), with their 95 % intervals.

Each function reads a study dataset (every engine kept, or its streaming
summaries) and returns a pandas DataFrame or plain numbers; nothing is
sampled. The film and life numbers of a scheme (:func:`film_numbers`) are
the ones the ranking ranks and the film table shows, computed by one
function.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..assembly import STATUS
from ..life import ALPHA_SCUFFING
from ..stats import control_variate_mean, mean_half_width, proportion_ci, quantile_ci
from ..study import summaries
from ..study.schema import flag

#: Tail quantiles reported: the +-3 sigma points of a normal distribution.
TAIL_LOW, TAIL_HIGH = 0.00135, 0.99865
UM = 1e6


def kept_summaries(ds):
    """The dataset holds streaming summaries (``Study(keep="summaries")``), not every engine."""
    return ds.attrs.get("kept") == "summaries"


def assembled(d, name):
    """Values of ``name`` of one scheme's assembled bearings (a full dataset)."""
    return d[name].values[d.status.values == flag(d.status, "assembled")]


def operating_moments(d):
    """Mean and standard deviation [m] of one scheme's assembled operating clearances (full or summaries)."""
    if kept_summaries(d):
        return float(d.clearance_operating_mean), float(d.clearance_operating_std)
    c = assembled(d, "clearance_operating")
    return float(c.mean()), float(c.std(ddof=1))


@dataclass(frozen=True)
class Soaked:
    """One scheme's clearance with housing, shells and journal at one temperature: at assembly and at the cold
    start [m] (means and standard deviations), and its bearings below the engine's minimum clearance at either."""

    assembly_mean: float
    assembly_std: float
    cold_mean: float
    cold_std: float
    below_minimum: int
    assembled: int


def soaked(d):
    """The :class:`Soaked` numbers of one scheme (full dataset or summaries); None for a dataset without them (a
    study saved before the clearance at assembly and cold start was computed)."""
    if "minimum_clearance" not in d:
        return None
    if kept_summaries(d):
        return Soaked(*(float(d[f"clearance_{t}_{s}"]) for t in ("assembly", "cold") for s in ("mean", "std")),
                      int(d.below_minimum_clearance_count), int(d.status_count.sel(status="assembled")))
    at_assembly, cold = assembled(d, "clearance_assembly"), assembled(d, "clearance_cold")
    below = np.count_nonzero(np.fmin(at_assembly, cold) < float(d.minimum_clearance))
    moments = [f(c) if c.size > 1 else np.nan for c in (at_assembly, cold) for f in (np.mean, lambda x: x.std(ddof=1))]
    return Soaked(*map(float, moments), int(below), int(cold.size))


def fit_summary(ds):
    """One row per scheme: nominal against operating clearance [um], press-fit limits as shares with 95 % intervals.

    The design limits are the dataset's (``design_contact_pressure_min``,
    ``design_shell_stress_max``). From summaries, the operating
    quantiles are read from the 0.1 um histogram.
    """
    p_min, s_max = float(ds.design_contact_pressure_min), float(ds.design_shell_stress_max)
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        if kept_summaries(ds):
            n = int(d.status_count.sel(status="assembled"))
            counts = (int(d.low_contact_pressure_count), int(d.high_shell_stress_count), int(d.loss_of_fit_count))
            hist = d.clearance_operating_histogram.values
            row = {"nominal_mean_um": float(d.clearance_nominal_mean) * UM,
                   "nominal_std_um": float(d.clearance_nominal_std) * UM,
                   "operating_p00135_um": summaries.quantile_ci(hist, TAIL_LOW)[0] * UM,
                   "operating_p99865_um": summaries.quantile_ci(hist, TAIL_HIGH)[0] * UM,
                   "swell_mean_um": float(d.housing_swell_mean) * UM,
                   "contact_pressure_min_mpa": float(d.contact_pressure_min) / 1e6,
                   "shell_stress_max_mpa": float(d.shell_stress_max) / 1e6}
        else:
            nominal, operating = assembled(d, "clearance_nominal"), assembled(d, "clearance_operating")
            p, sigma = assembled(d, "contact_pressure_lowest"), assembled(d, "shell_stress_highest")
            n = p.size
            counts = (np.count_nonzero(p < p_min), np.count_nonzero(sigma > s_max),
                      np.count_nonzero(assembled(d, "loss_of_fit_any_temperature")))
            row = {"nominal_mean_um": nominal.mean() * UM, "nominal_std_um": nominal.std(ddof=1) * UM,
                   "operating_p00135_um": quantile_ci(operating, TAIL_LOW)[0] * UM,
                   "operating_p99865_um": quantile_ci(operating, TAIL_HIGH)[0] * UM,
                   "swell_mean_um": assembled(d, "housing_swell").mean() * UM,
                   "contact_pressure_min_mpa": p.min() / 1e6, "shell_stress_max_mpa": sigma.max() / 1e6}
        low_p, high_s, lost = (proportion_ci(k, n) for k in counts)
        mean, std = operating_moments(d)
        rows.append({"scheme": str(name), **row, "operating_mean_um": mean * UM, "operating_std_um": std * UM,
                     "low_pressure_ppm": low_p[0] * 1e6, "low_pressure_ci_ppm": (low_p[1] * 1e6, low_p[2] * 1e6),
                     "high_stress_ppm": high_s[0] * 1e6, "high_stress_ci_ppm": (high_s[1] * 1e6, high_s[2] * 1e6),
                     "loss_of_fit_ppm": lost[0] * 1e6})
    return pd.DataFrame(rows).set_index("scheme")


def clearance_summary(ds):
    """One row per scheme: nominal clearance statistics [um], shares outside the stated range, stock.

    Quantiles and shares come with 95 % intervals (order statistics and
    Clopper-Pearson). From summaries they are read from the 0.1 um histogram
    of the nominal clearance (quantiles to a bin; the stated ranges lie on the
    bin grid, so the share outside them is exact); substitutions are not
    counted there (NaN).
    """
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        lo_stated, hi_stated = d.clearance_stated.values
        if kept_summaries(ds):
            counts = dict(zip(ds.status.values, d.status_count.values))
            hist = d.clearance_nominal_histogram.values
            n_bearings, n = int(sum(counts.values())), int(counts["assembled"])
            outside = summaries.share_beyond(hist, lo_stated, hi_stated)
            p_lo, p50, p_hi = (summaries.quantile_ci(hist, q) for q in (TAIL_LOW, 0.5, TAIL_HIGH))
            filled = np.flatnonzero(hist)
            extremes = (summaries.BIN_START + (filled[[0, -1]] + 0.5) * summaries.BIN_WIDTH if filled.size
                        else (np.nan, np.nan))
            mean, std = float(d.clearance_nominal_mean), float(d.clearance_nominal_std)
            substituted = np.nan
        else:
            status = d.status.values
            counts = {reason: np.count_nonzero(status == flag(d.status, reason)) for reason in STATUS}
            c = assembled(d, "clearance_nominal")
            n_bearings, n = status.size, c.size
            outside = int(np.count_nonzero((c < lo_stated) | (c > hi_stated)))
            p_lo, p50, p_hi = (quantile_ci(c, q) for q in (TAIL_LOW, 0.5, TAIL_HIGH))
            extremes = (c.min(), c.max()) if c.size else (np.nan, np.nan)
            mean = float(c.mean()) if c.size else np.nan
            std = float(c.std(ddof=1)) if c.size > 1 else np.nan
            substituted = int(np.count_nonzero(d.shell_option.values > 0))
        share, share_lo, share_hi = proportion_ci(outside, n)
        if not (np.isfinite(lo_stated) and np.isfinite(hi_stated)):  # the scheme states no range: nothing to count
            share = share_lo = share_hi = np.nan
        made = int(d.shells_made.sum()) + int(d.shells_scrapped)
        row = {
            "scheme": str(name),
            "bearings": n_bearings,
            "assembled": n,
            "stated_min_um": lo_stated * UM,
            "stated_max_um": hi_stated * UM,
            "worst_case_min_um": float(d.clearance_limit.values[0]) * UM,
            "worst_case_max_um": float(d.clearance_limit.values[1]) * UM,
            "mean_um": mean * UM,
            "std_um": std * UM,
            "p00135_um": p_lo[0] * UM,
            "p00135_ci_um": (p_lo[1] * UM, p_lo[2] * UM),
            "median_um": p50[0] * UM,
            "p99865_um": p_hi[0] * UM,
            "p99865_ci_um": (p_hi[1] * UM, p_hi[2] * UM),
            "min_um": float(extremes[0]) * UM,
            "max_um": float(extremes[1]) * UM,
            "outside_stated_ppm": share * 1e6,
            "outside_stated_ci_ppm": (share_lo * 1e6, share_hi * 1e6),
            "shells_made": made,
            "shells_scrapped_pct": 100.0 * int(d.shells_scrapped) / made if made else np.nan,
            "substituted": substituted,
        }
        row.update({reason: int(counts[reason]) for reason in STATUS if reason != "assembled"})
        rows.append(row)
    return pd.DataFrame(rows).set_index("scheme")


def grade_usage(ds):
    """Shells made, fitted and left per scheme and grade (grades the scheme has)."""
    frame = ds[["shells_made", "shells_used", "shells_left"]].to_dataframe()
    frame = frame[ds.grade_in_scheme.to_series()]
    used = frame["shells_used"]
    frame["used_share_pct"] = 100.0 * used / used.groupby(level="scheme").transform("sum")
    return frame


def crank_summary(ds):
    """Per scheme and bearing: engines the beam ran on, and the cycle-maximum load [kN] with a 95 % interval of its mean."""
    rows = []
    status = ds.crank_status
    for i, name in enumerate(ds.scheme.values):
        codes = status.values[i]
        ok = codes == flag(status, "converged")
        failed = int(np.count_nonzero((codes == flag(status, "max_iterations")) | (codes == flag(status, "not_finite"))))
        for b, bearing in enumerate(ds.bearing.values):
            r = ds.reaction_max.values[i, ok, b] / 1e3
            rows.append({"scheme": str(name), "bearing": int(bearing), "engines": int(ok.sum()), "failed": failed,
                         "mean_kn": r.mean() if r.size else np.nan,
                         "ci_kn": mean_half_width(r) if r.size > 1 else np.nan,
                         "max_kn": r.max() if r.size else np.nan})
    return pd.DataFrame(rows).set_index(["scheme", "bearing"])


def converged_engines(ds, i):
    """Engines of scheme ``i`` whose crankshaft stage converged (the film and life were computed on them)."""
    return ds.crank_status.values[i] == flag(ds.crank_status, "converged")


def numbers(values):
    """The values that are numbers, flat: a bearing whose film is not a number is NaN and left out."""
    values = np.asarray(values, dtype=float).ravel()
    return values[~np.isnan(values)]


@dataclass(frozen=True)
class FilmNumbers:
    """Film and life of one scheme's bearings on the engines whose crankshaft converged.

    The films, boundary-friction shares and lives that are numbers (a bearing whose film is NaN:
    collapsed, not periodic, failed, is left out and counted in ``left_out``); shares and quantiles as
    (value, lower, upper) with their 95 % intervals. Lives are never pooled over bearing positions (their
    loads differ, so a pooled life is a mixture no bearing has): Levanov's operability criteria are read per
    position, and the scheme's figure is its worst position's (``alpha_position``, ``life_position``: index
    into the positions); a life for the scheme is the engine's, its weakest bearing's.
    """

    done: np.ndarray            # engines of the mechanical chain whose crankshaft converged
    h: np.ndarray               # cycle-minimum films [m]
    alpha: np.ndarray           # shares of the cycle below the critical film [-]
    left_out: int
    below_critical: tuple       # share of films below the critical film [-] (None without one)
    alpha_over_limit: tuple     # at the worst position: share of its bearings with alpha over the scuffing limit
    alpha_position: int
    life_below_target: tuple    # at the worst position: share of its bearings living less than the target [-]
    life_position: int
    engine_life_h: np.ndarray   # each engine's life, its weakest bearing's [h] (an engine with a NaN left out)
    engine_life_b10_h: tuple
    engine_life_median_h: tuple
    engines_below_target: tuple  # share of engines living less than the target [-]


#: The study's film and life variables whose means the check tier corrects, and their check twins.
CHECKED = {"h_min": "h_min_check", "h_min_mean": "h_min_mean_check", "life": "life_check"}


def checked_lives(d, done):
    """Bearing lives [h] of one scheme ``d`` on the engines ``done`` (engines, positions), on the check tier's scale.

    Where the study ran the mass-conserving check (``film_check_engines``,
    at least 3 engines at a position), each position's lives are scaled by
    the ratio of the control-variate estimate of the check tier's mean life
    to the study tier's mean (:func:`multi_fidelity`): every engine's life
    carries the accurate tier's mean, on the assumption that the tiers'
    ratio is the same for every engine at a position. Elsewhere the study
    tier's lives.
    """
    life = d.life.values[done] / 3600
    for b in range(life.shape[-1]):
        e = checked_mean(d, done, "life", b)
        if e is not None:
            life[:, b] *= e.estimate / e.cheap
    return life


def checked_mean(d, done, name, b):
    """The control-variate estimate (:func:`stackup.stats.control_variate_mean`) of the check tier's mean of
    ``name`` (a key of :data:`CHECKED`) at position index ``b`` of one scheme ``d``, over the engines ``done``;
    None where the check ran on fewer than 3 of them."""
    if CHECKED[name] not in d:
        return None
    cheap, check = d[name].values[done, b], d[CHECKED[name]].values[done, b]
    shared = np.isfinite(cheap) & np.isfinite(check)
    if np.count_nonzero(shared) < 3:
        return None
    return control_variate_mean(check[shared], cheap[shared], cheap[np.isfinite(cheap)])


def position_risks(d, life_target_h, done=None, lives=None):
    """Per main-bearing position of one scheme ``d``: Levanov's operability criteria and the life.

    Over the engines whose crankshaft converged (``done``, else found), each
    position's bearings whose film is a number: ``alpha_over_limit`` (share with
    the boundary-friction share alpha above :data:`~stackup.life.ALPHA_SCUFFING`,
    Levanov et al. 2015's scuffing risk), ``life_below_target`` (share living
    less than ``life_target_h``), ``life_b10_h`` and ``life_median_h``; each a
    list over positions of (value, lower, upper) 95 % intervals
    (Clopper-Pearson for shares, order statistics for quantiles). Lives on
    the check tier's scale where the study ran it: ``lives``, else
    :func:`checked_lives`.
    """
    done = d.crank_status.values == flag(d.crank_status, "converged") if done is None else done
    alpha, life = d.alpha.values[done], checked_lives(d, done) if lives is None else lives
    out = {"alpha_over_limit": [], "life_below_target": [], "life_b10_h": [], "life_median_h": []}
    for b in range(alpha.shape[-1]):
        a, hours = numbers(alpha[:, b]), numbers(life[:, b])
        out["alpha_over_limit"].append(proportion_ci(np.count_nonzero(a > ALPHA_SCUFFING), a.size))
        out["life_below_target"].append(proportion_ci(np.count_nonzero(hours < life_target_h), hours.size))
        out["life_b10_h"].append(quantile_ci(hours, 0.10))
        out["life_median_h"].append(quantile_ci(hours, 0.5))
    return out


def _worst(shares):
    """The position with the largest share (the first of equals) and its (value, lower, upper)."""
    k = int(np.nanargmax([v[0] for v in shares])) if np.isfinite([v[0] for v in shares]).any() else 0
    return k, shares[k]


def film_numbers(d, h_lim_cr=None):
    """The :class:`FilmNumbers` of one scheme ``d`` of a study dataset, or None where no crankshaft converged."""
    done = d.crank_status.values == flag(d.crank_status, "converged")
    if not done.any() or "h_min" not in d:
        return None
    h, a = (numbers(d[name].values[done]) for name in ("h_min", "alpha"))
    target = float(d.life_target) / 3600
    lives = checked_lives(d, done)
    risks = position_risks(d, target, done, lives)
    alpha_position, alpha_over = _worst(risks["alpha_over_limit"])
    life_position, short = _worst(risks["life_below_target"])
    engine_life = lives.min(axis=1)  # NaN stays NaN: left out
    lived = engine_life[~np.isnan(engine_life)]
    return FilmNumbers(done, h, a, int(np.count_nonzero(np.isnan(d.h_min.values[done]))),
                       None if h_lim_cr is None else proportion_ci(np.count_nonzero(h < h_lim_cr), h.size),
                       alpha_over, alpha_position, short, life_position, lived, quantile_ci(lived, 0.10),
                       quantile_ci(lived, 0.5), proportion_ci(np.count_nonzero(lived < target), lived.size))


def film_summary(ds):
    """Per scheme: cycle-minimum film, Levanov's operability criteria at the worst position and the engine's life.

    Engines live as long as their weakest bearing; the share of engines
    below the life target uses the engine's own target (``life_target``).
    Bearings whose film is not a number (NaN: collapsed, not periodic,
    failed) are left out and counted (``left_out``); so are the engines with
    one of them (``engines_left_out``).
    """
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        film = film_numbers(d)
        if film is None or film.h.size == 0:
            continue
        done = film.done
        rows.append({
            "scheme": str(name), "engines": int(done.sum()), "left_out": film.left_out,
            "engines_left_out": int(done.sum() - film.engine_life_h.size),
            "h_min_p05_um": quantile_ci(film.h * UM, 0.05), "h_min_median_um": quantile_ci(film.h * UM, 0.5),
            "h_min_mean_median_um": quantile_ci(numbers(d.h_min_mean.values[done] * UM), 0.5),
            "alpha_mean": film.alpha.mean(),
            "alpha_over_20_pct": tuple(100 * v for v in film.alpha_over_limit),
            "alpha_over_20_position": int(d.bearing.values[film.alpha_position]),
            "life_below_target_pct": tuple(100 * v for v in film.life_below_target),
            "life_below_target_position": int(d.bearing.values[film.life_position]),
            "wear_chart_b10_h": quantile_ci(numbers(d.life_wear_chart.values[done] / 3600), 0.10),
            "engine_life_b10_h": film.engine_life_b10_h, "engine_life_median_h": film.engine_life_median_h,
            "engines_below_target_pct": tuple(100 * v for v in film.engines_below_target),
        })
    return pd.DataFrame(rows).set_index("scheme") if rows else pd.DataFrame()


def bearing_summary(ds):
    """Per scheme and main-bearing position: film and life of the engines the mechanical chain ran on.

    Columns: ``engines`` (whose film at the position is a number: NaN left
    out), ``h_min_p05_um`` and ``h_min_median_um`` (cycle minimum), ``h_min_mean_median_um`` (cycle mean), Levanov's
    operability criteria ``alpha_over_20_pct`` and ``life_below_target_pct``
    (:func:`position_risks`), ``life_b10_h`` and ``life_median_h``, each a
    (value, lower, upper) 95 % interval.
    """
    rows = []
    for i, name in enumerate(ds.scheme.values):
        done = converged_engines(ds, i)
        if not done.any():
            continue
        d = ds.isel(scheme=i)
        risks = position_risks(d, float(ds.life_target) / 3600, done)
        for b, bearing in enumerate(ds.bearing.values):
            h = numbers(ds.h_min.values[i, done, b] * UM)
            rows.append({"scheme": str(name), "bearing": int(bearing), "engines": int(h.size),
                         "h_min_p05_um": quantile_ci(h, 0.05), "h_min_median_um": quantile_ci(h, 0.5),
                         "h_min_mean_median_um": quantile_ci(numbers(ds.h_min_mean.values[i, done, b] * UM), 0.5),
                         "alpha_over_20_pct": tuple(100 * v for v in risks["alpha_over_limit"][b]),
                         "life_below_target_pct": tuple(100 * v for v in risks["life_below_target"][b]),
                         "life_b10_h": risks["life_b10_h"][b], "life_median_h": risks["life_median_h"][b]})
    return pd.DataFrame(rows).set_index(["scheme", "bearing"]) if rows else pd.DataFrame()


def centred(ds, scheme, window):
    """What centring a scheme's operating clearance in the window would give: (shift [m], bearings outside, assembled).

    The shift moves every assembled bearing's clearance by the distance from
    its mean to the window's middle, as shells aimed ``shift / 2`` thinner
    each would; the shape of the distribution is kept. From summaries the
    histogram is moved by whole bins.
    """
    d = ds.sel(scheme=scheme)
    middle = 0.5 * (window[0] + window[1])
    if kept_summaries(ds):
        hist = d.clearance_operating_histogram.values
        shift_bins = int(round((middle - float(d.clearance_operating_mean)) / summaries.BIN_WIDTH))
        moved = np.zeros_like(hist)
        src = slice(max(0, -shift_bins), hist.size - max(0, shift_bins))
        moved[max(0, shift_bins):hist.size + min(0, shift_bins)] = hist[src]
        return shift_bins * summaries.BIN_WIDTH, summaries.share_beyond(moved, *window), int(hist.sum())
    c = assembled(d, "clearance_operating")
    shift = middle - c.mean()
    moved = c + shift
    return shift, int(np.count_nonzero((moved < window[0]) | (moved > window[1]))), c.size


def separates(low, high):
    """Whether a metric separates the schemes: some scheme's 95 % interval lies clear of another's.

    ``low`` and ``high`` are the interval bounds per scheme.
    """
    low, high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    ok = np.isfinite(low) & np.isfinite(high)
    return bool(ok.sum() > 1 and np.min(high[ok]) < np.max(low[ok]))


def paired_life_changes(ds, other):
    """What a scenario does to the lives, on the same engines: per scheme and position, and per engine.

    ``other`` is the scenario's study dataset (the same seed, so its first
    engines are the study's first engines with one change: common random
    numbers). Where both ran the mechanical chain, each engine's change is
    taken against itself, which leaves only the scenario's effect; the
    median change has a distribution-free 95 % interval (order statistics
    of the paired differences). Returns two DataFrames, or (None, None)
    where the scenario did not run the mechanical chain:

    - indexed by (scheme, bearing): ``pairs``, ``life_change_h``,
      ``h_min_change_um`` (cycle minimum), ``h_min_mean_change_um``
      (cycle mean, the film method 1 reads) and ``edge_share_change_pts``
      (the share of the cycle with an edge in contact, percentage points;
      NaN for a study before it), each (median, lower, upper);
    - indexed by scheme: ``pairs`` and ``engine_life_change_h`` (the
      engine's life, its weakest bearing's).
    """
    if "life" not in other or "life" not in ds or not other.sizes.get("mech_engine"):
        return None, None
    m = min(other.sizes["mech_engine"], ds.sizes["mech_engine"])
    positions, engines = [], []
    for name in other.scheme.values:
        if name not in ds.scheme.values:
            continue
        base, alt = ds.sel(scheme=name).isel(mech_engine=slice(0, m)), other.sel(scheme=name).isel(
            mech_engine=slice(0, m))
        both = ((base.crank_status.values == flag(base.crank_status, "converged"))
                & (alt.crank_status.values == flag(alt.crank_status, "converged")))
        life = (alt.life.values[both] - base.life.values[both]) / 3600
        h = (alt.h_min.values[both] - base.h_min.values[both]) * UM
        h_mean = (alt.h_min_mean.values[both] - base.h_min_mean.values[both]) * UM
        edge = (100 * (alt.edge_contact_share.values[both] - base.edge_contact_share.values[both])
                if "edge_contact_share" in alt and "edge_contact_share" in base else np.full(h.shape, np.nan))
        for b, bearing in enumerate(ds.bearing.values):
            positions.append({"scheme": str(name), "bearing": int(bearing), "pairs": int(numbers(life[:, b]).size),
                              "life_change_h": quantile_ci(life[:, b], 0.5),
                              "h_min_change_um": quantile_ci(h[:, b], 0.5),
                              "h_min_mean_change_um": quantile_ci(h_mean[:, b], 0.5),
                              "edge_share_change_pts": quantile_ci(edge[:, b], 0.5)})
        engine = (alt.life.values[both].min(axis=1) - base.life.values[both].min(axis=1)) / 3600
        engines.append({"scheme": str(name), "pairs": int(numbers(engine).size),
                        "engine_life_change_h": quantile_ci(engine, 0.5)})
    return (pd.DataFrame(positions).set_index(["scheme", "bearing"]),
            pd.DataFrame(engines).set_index("scheme"))


def multi_fidelity(ds):
    """Per scheme and position, the means of the film and life corrected by the check tier (control variates).

    The study's tier ran on every engine of the mechanical chain, the check
    tier (``film_check_engines``) on its first ones: the control-variate
    estimator (:func:`stackup.stats.control_variate_mean`) gives the check
    tier's mean over all those engines, unbiased for the study tier's error,
    with a 95 % interval. Columns per variable of :data:`CHECKED` (SI):
    ``<name>_cheap`` (the study tier's mean) and ``<name>_corrected``
    (estimate, lower, upper); ``pairs`` and ``engines``. Empty without a
    check (fewer than 3 pairs at a position).
    """
    if "h_min_check" not in ds or not np.isfinite(ds.h_min_check.values).any():
        return pd.DataFrame()
    rows = []
    for i, name in enumerate(ds.scheme.values):
        d, done = ds.isel(scheme=i), converged_engines(ds, i)
        for b, bearing in enumerate(ds.bearing.values):
            row = {"scheme": str(name), "bearing": int(bearing)}
            for cheap in CHECKED:
                e = checked_mean(d, done, cheap, b)
                if e is None:
                    break
                row.update({f"{cheap}_cheap": e.cheap, f"{cheap}_corrected": (e.estimate, e.lower, e.upper),
                            "pairs": e.n_accurate, "engines": e.n_cheap})
            else:
                rows.append(row)
    return pd.DataFrame(rows).set_index(["scheme", "bearing"]) if rows else pd.DataFrame()
