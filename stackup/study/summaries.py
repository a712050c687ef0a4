"""Streaming summaries of a study: what a chunk reduces to, how chunks merge, and the summary dataset.

A study of 10^8 bearings cannot keep every engine. With
``Study.run(keep="summaries")`` each chunk is reduced at once to:

- histograms of the nominal and operating clearance on fixed bins
  (:data:`BIN_WIDTH` wide from :data:`BIN_START`), from which quantiles are read
  within half a bin;
- counts per assembly status and of bearings outside the design window (the
  ppm estimates, with exact binomial intervals);
- moments (count, sum, sum of squares) for means and spreads;
- the press fit: bearings that lose the fit, fall below the minimum contact
  pressure or exceed the maximum shell stress (:mod:`stackup.fit` limits),
  the lowest contact pressure and the highest shell stress, moments of the
  housing swell;
- the shell counters (made, used, left, scrapped per grade);
- the :data:`WORST` bearings with the smallest and the largest operating
  clearance, with their inputs;
- every per-bearing result of the mechanical chain (loads, film, life) on
  the engines it runs on (the first ``mechanics_engines``, a few hundred), on
  the ``mech_engine`` dimension with their operating clearance.

Histograms, counts and counters merge exactly, extremes by min and max; sums
are added in lot order, so the result is identical whatever the scheduler;
the worst lists merge by keeping the extremes (ties broken by engine number);
the mechanical sample is concatenated in engine order.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import xarray as xr

from ..assembly import ASSEMBLED, STATUS
from . import schema
from .schema import BIN_START, BIN_WIDTH, BINS, WORST
from .chain import MechanicsProgress, ShellCounts

CLEARANCES = ("clearance_nominal", "clearance_operating")
#: The clearances at one temperature (assembly, cold start), counted against the engine's minimum clearance.
SOAKED = ("clearance_assembly", "clearance_cold")
MOMENTS = (*CLEARANCES, *SOAKED, "housing_swell")
INPUTS = ("housing_bore", "journal_d", "shell_upper_wall", "shell_lower_wall")
#: What the summaries keep of each engine the mechanical chain ran on.
SAMPLED = (*schema.MECHANICS, "clearance_operating")


@dataclass
class Summary:
    """What some production lots reduce to, per scheme; merged by :meth:`add`.

    Attributes
    ----------
    counts : dict of str -> numpy.ndarray
        Added: bearings per status, outside the window, below or above the
        press-fit limits, histograms of the clearances, shell counters.
    sums : dict of str -> numpy.ndarray
        Added in lot order: sums and sums of squares (``name``, ``name_sq``)
        of :data:`MOMENTS` over assembled bearings.
    minima, maxima : dict of str -> numpy.ndarray
        Merged by min and max: the lowest contact pressure, the highest shell stress.
    worst : dict of str -> numpy.ndarray (schemes, WORST, fields)
        The bearings with the smallest (``"low"``) and largest (``"high"``)
        operating clearance: clearance, engine, bearing, then :data:`INPUTS`.
    """

    counts: dict
    sums: dict
    minima: dict
    maxima: dict
    worst: dict

    def copy(self):
        return Summary(**{k: {name: np.array(v, copy=True) for name, v in d.items()} for k, d in asdict(self).items()})

    def add(self, other):
        """Add ``other`` (the lots after these) in place; lots must come in lot order."""
        for name, v in other.counts.items():
            self.counts[name] = self.counts[name] + v
        for name, v in other.sums.items():
            self.sums[name] = self.sums[name] + v
        for name, v in other.minima.items():
            self.minima[name] = np.minimum(self.minima[name], v)
        for name, v in other.maxima.items():
            self.maxima[name] = np.maximum(self.maxima[name], v)
        for side, sign in (("low", 1.0), ("high", -1.0)):
            rows = np.concatenate([self.worst[side], other.worst[side]], axis=1)
            merged = np.full((rows.shape[0], WORST, rows.shape[2]), np.nan)
            for i in range(rows.shape[0]):
                r = rows[i][np.isfinite(rows[i, :, 0])]
                order = np.lexsort((r[:, 2], r[:, 1], sign * r[:, 0]))[:WORST]
                merged[i, :order.size] = r[order]
            self.worst[side] = merged
        return self

    def arrays(self):
        """As nested plain data (for a store)."""
        return asdict(self)


@dataclass
class ChunkSummary:
    """A chunk reduced on the worker: one :class:`Summary` per production lot and the mechanical sample."""

    first: int
    lots: list
    sample: dict  # SAMPLED variable -> (schemes, engines of the chain in the chunk, ...)
    progress: MechanicsProgress
    h_min_head: np.ndarray
    failures: object = None  # the chunk's FailureCount, set by Study.chunk


def reduce_chunk(result, *, lot_engines, window, limits, minimum_clearance):
    """Summary of a :class:`~stackup.study.chain.ChunkResult`, one per production lot.

    Lots are fixed units, so the sums do not depend on the chunking. The
    shell counters of the chunk go with its first lot.
    """
    lots = []
    e0 = result.engines.start
    for j, start in enumerate(range(e0, result.engines.stop, lot_engines)):
        rows = slice(start - e0, min(start + lot_engines, result.engines.stop) - e0)
        shells = result.shells if j == 0 else ShellCounts.zeros(*result.shells.made.shape)
        lots.append(_reduce(result.take(rows), shells, e0=start, window=window, limits=limits,
                            minimum_clearance=minimum_clearance))
    mechanical = result.h_min_head.shape[1]
    # a copy: a view would keep the whole chunk's arrays alive for as long as the sample is kept
    sample = {**{name: result.per_mech[name] for name in schema.MECHANICS},
              "clearance_operating": result.per_engine["clearance_operating"][:, :mechanical].copy()}
    return ChunkSummary(result.first, lots, sample, result.progress, result.h_min_head)


def _reduce(v, shells, *, e0, window, limits, minimum_clearance):
    """Summary of one lot's per-engine variables ``v`` and its shell counters."""
    status = v["status"]  # (schemes, engines, bearings)
    n_schemes = status.shape[0]
    ok = status == ASSEMBLED
    counts = {"status": np.stack([np.sum(status == k, axis=(1, 2)) for k in range(len(STATUS))], axis=-1)}
    sums = {}
    for name in MOMENTS:
        masked = np.where(ok, v[name], 0.0)
        sums[name], sums[f"{name}_sq"] = masked.sum(axis=(1, 2)), (masked**2).sum(axis=(1, 2))
    for name in CLEARANCES:
        masked = np.where(ok, v[name], 0.0)
        idx = np.clip(np.floor((masked - BIN_START) / BIN_WIDTH).astype(np.int64), 0, BINS - 1)
        hist = np.zeros((n_schemes, BINS), np.int64)
        for i in range(n_schemes):
            hist[i] = np.bincount(idx[i][ok[i]], minlength=BINS)
        counts[f"{name}_histogram"] = hist
    c = v["clearance_operating"]
    counts["outside_window"] = np.sum(ok & ((c < window[0]) | (c > window[1])), axis=(1, 2))
    counts["below_minimum_clearance"] = np.sum(ok & (np.fmin(*(v[name] for name in SOAKED)) < minimum_clearance),
                                               axis=(1, 2))
    pressure, stress = v["contact_pressure_lowest"], v["shell_stress_highest"]
    counts["loss_of_fit"] = np.sum(ok & v["loss_of_fit_any_temperature"], axis=(1, 2))
    counts["low_contact_pressure"] = np.sum(ok & (pressure < limits.contact_pressure_min), axis=(1, 2))
    counts["high_shell_stress"] = np.sum(ok & (stress > limits.shell_stress_max), axis=(1, 2))
    for name in ("made", "used", "left", "scrapped"):
        counts[f"shells_{name}"] = getattr(shells, name)
    engines = e0 + np.arange(status.shape[1])
    bearings = np.arange(status.shape[2])
    key_engine = np.broadcast_to(engines[:, None], status.shape[1:])
    key_bearing = np.broadcast_to(bearings[None, :], status.shape[1:])
    inputs = {"housing_bore": np.broadcast_to(v["housing_bore"], status.shape),
              "journal_d": np.broadcast_to(v["journal_d"], status.shape),
              "shell_upper_wall": v["shell_upper_wall"], "shell_lower_wall": v["shell_lower_wall"]}
    worst = {}
    for side, sign in (("low", 1.0), ("high", -1.0)):
        rows = np.full((n_schemes, WORST, 3 + len(INPUTS)), np.nan)
        for i in range(n_schemes):
            values = np.where(ok[i], sign * c[i], np.inf)
            order = np.lexsort((key_bearing.ravel(), key_engine.ravel(), values.ravel()))[:WORST]
            order = order[np.isfinite(values.ravel()[order])]
            rows[i, :order.size, 0] = c[i].ravel()[order]
            rows[i, :order.size, 1] = key_engine.ravel()[order]
            rows[i, :order.size, 2] = key_bearing.ravel()[order]
            for j, name in enumerate(INPUTS):
                rows[i, :order.size, 3 + j] = inputs[name][i].ravel()[order]
        worst[side] = rows
    return Summary(counts, sums, {"contact_pressure": np.where(ok, pressure, np.inf).min(axis=(1, 2))},
                   {"shell_stress": np.where(ok, stress, -np.inf).max(axis=(1, 2))}, worst)


def mean_std(total, name, n):
    """Mean and sample standard deviation per scheme of ``name`` from the moments of ``n`` values."""
    mean = total.sums[name] / n
    return mean, np.sqrt(np.maximum(total.sums[f"{name}_sq"] / n - mean**2, 0) * n / (n - 1))


def dataset(total, sample, *, schemes, grade_labels, attrs):
    """The summary dataset, every variable as :mod:`stackup.study.schema` declares it.

    ``sample`` holds the mechanical chain's :data:`SAMPLED` results of the
    engines it ran on, in engine order.
    """
    full, summary = schema.FULL, schema.SUMMARY
    centres = BIN_START + (np.arange(BINS) + 0.5) * BIN_WIDTH
    counts = total.counts
    data = {
        "status_count": summary["status_count"](counts["status"]),
        "outside_window_count": summary["outside_window_count"](counts["outside_window"]),
        **{f"shells_{k}": full[f"shells_{k}"](counts[f"shells_{k}"]) for k in ("made", "used", "left", "scrapped")},
        "loss_of_fit_count": summary["loss_of_fit_count"](counts["loss_of_fit"]),
        "low_contact_pressure_count": summary["low_contact_pressure_count"](counts["low_contact_pressure"]),
        "high_shell_stress_count": summary["high_shell_stress_count"](counts["high_shell_stress"]),
        "contact_pressure_min": summary["contact_pressure_min"](_finite(total.minima["contact_pressure"])),
        "shell_stress_max": summary["shell_stress_max"](_finite(total.maxima["shell_stress"])),
        "grade_in_scheme": full["grade_in_scheme"](
            np.array([[lab in s.shell.labels for lab in grade_labels] for s in schemes])),
        **schema.scheme_variables(schemes),
    }
    n = counts["status"][:, ASSEMBLED]
    for name in CLEARANCES:
        data[f"{name}_histogram"] = summary[f"{name}_histogram"](counts[f"{name}_histogram"])
        data[f"{name}_mean"], data[f"{name}_std"] = (summary[f"{name}_{k}"](v)
                                                     for k, v in zip(("mean", "std"), mean_std(total, name, n)))
    for name in ("housing_swell", *SOAKED):
        data[f"{name}_mean"], data[f"{name}_std"] = (summary[f"{name}_{k}"](v) for k, v in
                                                     zip(("mean", "std"), mean_std(total, name, n)))
    data["below_minimum_clearance_count"] = summary["below_minimum_clearance_count"](
        counts["below_minimum_clearance"])
    for name, var in schema.MECHANICS.items():
        data[name] = var(sample[name])
    data["clearance_operating_sampled"] = summary["clearance_operating_sampled"](sample["clearance_operating"])
    fields = ["clearance_operating", "engine", "bearing", *INPUTS]
    for side in ("low", "high"):
        data[f"worst_{side}"] = summary[f"worst_{side}"](total.worst[side])
    coords = schema.coords(scheme=[s.name for s in schemes], status=list(STATUS), shell_grade=grade_labels,
                           clearance_bin=centres, rank=np.arange(1, WORST + 1), field=fields, bound=schema.BOUNDS,
                           part=schema.PARTS, bearing=np.arange(1, sample["h_min"].shape[2] + 1),
                           mech_engine=np.arange(sample["crank_status"].shape[1]))
    return xr.Dataset(data, coords=coords, attrs={**attrs, "kept": "summaries"})


def _finite(values):
    """Extremes over no bearing (inf) as NaN."""
    return np.where(np.isfinite(values), values, np.nan)


def quantile_ci(hist, q, *, confidence=0.95):
    """Quantile ``q`` [m] of one scheme's clearance histogram with a distribution-free interval, to a bin.

    The interval is spanned by the order statistics whose ranks are the
    binomial ``(n, q)`` quantiles at ``alpha/2`` and ``1 - alpha/2``, as
    :func:`stackup.stats.quantile_ci` does for values; each is read as the
    centre of the bin that holds it. Returns ``(estimate, lower, upper)``.
    """
    from scipy import stats

    hist = np.asarray(hist)
    n = int(hist.sum())
    if n == 0:
        return np.nan, np.nan, np.nan
    cumulative = np.cumsum(hist)

    def centre(rank):  # of the bin holding the order statistic of this rank (1-based)
        if rank < 1:
            return -np.inf
        if rank > n:
            return np.inf
        return BIN_START + (np.searchsorted(cumulative, rank) + 0.5) * BIN_WIDTH

    alpha = 1.0 - confidence
    estimate = BIN_START + (np.searchsorted(cumulative / n, q) + 0.5) * BIN_WIDTH
    return (float(estimate), float(centre(int(stats.binom.ppf(alpha / 2, n, q)))),
            float(centre(int(stats.binom.ppf(1 - alpha / 2, n, q)) + 1)))


def share_beyond(hist, lo, hi):
    """Bearings of a histogram with a value below ``lo`` or above ``hi`` [m], both on the bin grid (exact)."""
    edges = BIN_START + np.arange(np.asarray(hist).size + 1) * BIN_WIDTH
    below = edges[1:] <= lo + 1e-3 * BIN_WIDTH  # bins wholly below lo
    above = edges[:-1] >= hi - 1e-3 * BIN_WIDTH  # bins from hi up: their values exceed hi (continuous values)
    return int(np.asarray(hist)[below | above].sum())
