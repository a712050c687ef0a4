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
  a ``sampled_engine`` dimension with their operating clearance.

Histograms, counts and counters merge exactly, extremes by min and max; sums
are added in lot order, so the result is identical whatever the scheduler;
the worst lists merge by keeping the extremes (ties broken by engine number);
the mechanical sample is concatenated in engine order.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from .assembly import ASSEMBLED, STATUS
from .crank.cycle import CYCLE_STATUS
from .fit import CONTACT_PRESSURE_MIN, SHELL_STRESS_MAX

BIN_START = 0.0  # [m]
BIN_WIDTH = 0.1e-6  # [m]
BINS = 3000  # up to 300 um
WORST = 20
CLEARANCES = ("clearance_nominal", "clearance_operating")
INPUTS = ("housing_bore", "journal_d", "shell_upper_wall", "shell_lower_wall")

#: Per-bearing results of the mechanical chain: name -> (units, long name).
MECHANICS_VARIABLES = {
    "reaction_max": ("N", "maximum bearing load over the engine cycle (NaN where crank_status is not_computed)"),
    "h_min": ("m", "minimum oil film thickness over the engine cycle (quasi-static)"),
    "h_min_mean": ("m", "cycle mean of the minimum oil film thickness"),
    "alpha": ("1", "share of the cycle with the film below h_lim_cr (boundary friction)"),
    "life": ("s", "bearing resource, Levanov et al. 2015 method 1 with the cycle-minimum film"),
    "film_temperature": ("degC", "effective oil film temperature (isothermal heat balance)"),
}


def reduce_chunk(state, *, e0, window, n_schemes):
    """Summary of one chunk from its state (see ``_Output.chunk_state``)."""
    status = state["status"]  # (schemes, engines, bearings)
    ok = status == ASSEMBLED
    out = {"count.status": np.stack([np.sum(status == k, axis=(1, 2)) for k in range(len(STATUS))], axis=-1)}
    for name in CLEARANCES:
        masked = np.where(ok, state[f"floats.{name}"], 0.0)
        idx = np.clip(np.floor((masked - BIN_START) / BIN_WIDTH).astype(np.int64), 0, BINS - 1)
        hist = np.zeros((n_schemes, BINS), np.int64)
        for i in range(n_schemes):
            hist[i] = np.bincount(idx[i][ok[i]], minlength=BINS)
        out[f"hist.{name}"] = hist
        out.update(_moments(name, masked))
    c = state["floats.clearance_operating"]
    out["count.outside_window"] = np.sum(ok & ((c < window[0]) | (c > window[1])), axis=(1, 2))
    pressure, stress = state["floats.contact_pressure"], state["floats.shell_stress"]
    out["count.loss_of_fit"] = np.sum(ok & state["loss_of_fit"], axis=(1, 2))
    out["count.low_contact_pressure"] = np.sum(ok & (pressure < CONTACT_PRESSURE_MIN), axis=(1, 2))
    out["count.high_shell_stress"] = np.sum(ok & (stress > SHELL_STRESS_MAX), axis=(1, 2))
    out["min.contact_pressure"] = np.where(ok, pressure, np.inf).min(axis=(1, 2))
    out["max.shell_stress"] = np.where(ok, stress, -np.inf).max(axis=(1, 2))
    out.update(_moments("housing_swell", np.where(ok, state["floats.housing_swell"], 0.0)))
    for k in ("made", "used", "left", "scrapped"):
        out[f"count.{k}"] = state[f"count.{k}"]
    engines = e0 + np.arange(status.shape[1])
    bearings = np.arange(status.shape[2])
    key_engine = np.broadcast_to(engines[:, None], status.shape[1:])
    key_bearing = np.broadcast_to(bearings[None, :], status.shape[1:])
    inputs = {"housing_bore": np.broadcast_to(state["parts.housing_bore"], status.shape),
              "journal_d": np.broadcast_to(state["parts.journal_d"], status.shape),
              "shell_upper_wall": state["floats.shell_upper_wall"], "shell_lower_wall": state["floats.shell_lower_wall"]}
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
        out[f"worst.{side}"] = rows
    return out


def _moments(name, masked):
    """Sum and sum of squares per scheme of values zeroed where not assembled."""
    return {f"sum.{name}": masked.sum(axis=(1, 2)), f"sumsq.{name}": (masked**2).sum(axis=(1, 2))}


def _mean_std(total, name, n):
    """Mean and sample standard deviation per scheme from the moments of ``n`` values."""
    mean = total[f"sum.{name}"] / n
    return mean, np.sqrt(np.maximum(total[f"sumsq.{name}"] / n - mean**2, 0) * n / (n - 1))


def add(total, summary):
    """Add one lot's summary to the running ``total`` (None to start); lots must come in lot order."""
    if total is None:
        return {k: np.array(v, copy=True) for k, v in summary.items()}
    for k, v in summary.items():
        if k.startswith("min."):
            total[k] = np.minimum(total[k], v)
        elif k.startswith("max."):
            total[k] = np.maximum(total[k], v)
        elif not k.startswith("worst."):
            total[k] = total[k] + v
    for side, sign in (("low", 1.0), ("high", -1.0)):
        rows = np.concatenate([total[f"worst.{side}"], summary[f"worst.{side}"]], axis=1)
        merged = np.full((rows.shape[0], WORST, rows.shape[2]), np.nan)
        for i in range(rows.shape[0]):
            r = rows[i][np.isfinite(rows[i, :, 0])]
            order = np.lexsort((r[:, 2], r[:, 1], sign * r[:, 0]))[:WORST]
            merged[i, :order.size] = r[order]
        total[f"worst.{side}"] = merged
    return total


def split_state(state, lots, lot_engines):
    """A chunk state cut into the states of its production lots (the shell counters go with the first)."""
    engine_axis = {name: (0 if name.startswith(("parts.", "offsets.")) or name in ("block_scrapped", "crank_scrapped")
                          else 1) for name in state}
    pieces = []
    for j, _ in enumerate(lots):
        rows = slice(j * lot_engines, (j + 1) * lot_engines)
        piece = {}
        for name, value in state.items():
            if name.startswith("count."):
                piece[name] = value if j == 0 else np.zeros_like(value)
            elif name.startswith("mechanics.progress"):
                continue
            else:
                piece[name] = value[(slice(None),) * engine_axis[name] + (rows,)]
        pieces.append(piece)
    return pieces


def mechanics_sample(state, engines):
    """The mechanical chain's results of the chunk's first ``engines`` engines (a chunk state's slice)."""
    names = {f"sample.{name}": f"mechanics.{name}" for name in MECHANICS_VARIABLES}
    names.update({"sample.crank_status": "crank_status", "sample.clearance_operating": "floats.clearance_operating"})
    # copies: a view would keep the whole chunk's arrays alive for as long as the sample is kept
    return {key: state[name][:, :engines].copy() for key, name in names.items()}


def dataset(total, sample, *, schemes, grade_labels, attrs):
    """The summary dataset, units and long names on every variable.

    ``sample`` holds the mechanical chain's results (:func:`mechanics_sample`,
    without the ``sample.`` prefix) of the engines it ran on, in engine order.
    """
    def var(dims, data, units, long_name, **extra):
        return xr.Variable(dims, data, {"units": units, "long_name": long_name, **extra})

    centres = BIN_START + (np.arange(BINS) + 0.5) * BIN_WIDTH
    data = {
        "status_count": var(("scheme", "status"), total["count.status"], "1", "bearings per assembly status"),
        "outside_window_count": var("scheme", total["count.outside_window"], "1",
                                    "assembled bearings with the operating clearance outside the design window"),
        "shells_made": var(("scheme", "shell_grade"), total["count.made"], "1", "shells made and sorted into the grade"),
        "shells_used": var(("scheme", "shell_grade"), total["count.used"], "1", "shells of the grade fitted"),
        "shells_left": var(("scheme", "shell_grade"), total["count.left"], "1", "shells left at the ends of the lots"),
        "shells_scrapped": var("scheme", total["count.scrapped"], "1", "shells read outside every grade"),
        "loss_of_fit_count": var("scheme", total["count.loss_of_fit"], "1",
                                 "assembled bearings whose shells have no interference left in service"),
        "low_contact_pressure_count": var("scheme", total["count.low_contact_pressure"], "1",
                                          "assembled bearings with contact pressure below the design minimum",
                                          limit=CONTACT_PRESSURE_MIN),
        "high_shell_stress_count": var("scheme", total["count.high_shell_stress"], "1",
                                       "assembled bearings with shell stress above the design maximum",
                                       limit=SHELL_STRESS_MAX),
        "contact_pressure_min": var("scheme", _finite(total["min.contact_pressure"]), "Pa",
                                    "lowest contact pressure of an assembled bearing"),
        "shell_stress_max": var("scheme", _finite(total["max.shell_stress"]), "Pa",
                                "highest shell stress of an assembled bearing"),
    }
    data["grade_in_scheme"] = var(("scheme", "shell_grade"),
                                  np.array([[lab in s.shell.labels for lab in grade_labels] for s in schemes]),
                                  "1", "the scheme has this shell grade")
    n = total["count.status"][:, ASSEMBLED]
    for name in CLEARANCES:
        label = name.replace("clearance_", "")
        data[f"{name}_histogram"] = var(("scheme", "clearance_bin"), total[f"hist.{name}"], "1",
                                        f"assembled bearings per {BIN_WIDTH * 1e6:g} um bin of the {label} clearance")
        mean, std = _mean_std(total, name, n)
        data[f"{name}_mean"] = var("scheme", mean, "m", f"mean {label} diametral clearance")
        data[f"{name}_std"] = var("scheme", std, "m", f"standard deviation of the {label} diametral clearance")
    mean, std = _mean_std(total, "housing_swell", n)
    data["housing_swell_mean"] = var("scheme", mean, "m", "mean elastic growth of the housing bore from the press fit")
    data["housing_swell_std"] = var("scheme", std, "m",
                                    "standard deviation of the growth of the housing bore from the press fit")
    sed = ("scheme", "sampled_engine", "bearing")
    for name, (units, long_name) in MECHANICS_VARIABLES.items():
        data[name] = var(sed, sample[name], units, long_name)
    data["clearance_operating_sampled"] = var(sed, sample["clearance_operating"], "m",
                                              "diametral operating clearance of the bearings of the mechanical chain")
    data["crank_status"] = var(("scheme", "sampled_engine"), sample["crank_status"], "1",
                               "status of the crankshaft beam stage",
                               flag_values=np.arange(len(CYCLE_STATUS), dtype=np.int8),
                               flag_meanings=" ".join(CYCLE_STATUS))
    fields = ["clearance_operating", "engine", "bearing", *INPUTS]
    for side in ("low", "high"):
        data[f"worst_{side}"] = var(("scheme", "rank", "field"), total[f"worst.{side}"], "mixed",
                                    f"the {WORST} bearings with the {'smallest' if side == 'low' else 'largest'} "
                                    "operating clearance and their inputs (see field; lengths in m)")
    coords = {
        "scheme": ("scheme", [s.name for s in schemes], {"long_name": "selective-fitting scheme"}),
        "status": ("status", list(STATUS), {"long_name": "assembly status"}),
        "shell_grade": ("shell_grade", grade_labels, {"long_name": "shell grade label"}),
        "clearance_bin": ("clearance_bin", centres, {"units": "m", "long_name": "clearance bin centre"}),
        "rank": ("rank", np.arange(1, WORST + 1), {"long_name": "rank among the extremes"}),
        "field": ("field", fields, {"long_name": "recorded quantity"}),
        "bearing": ("bearing", np.arange(1, sample["h_min"].shape[2] + 1), {"long_name": "main bearing position"}),
        "sampled_engine": ("sampled_engine", np.arange(sample["crank_status"].shape[1]),
                           {"long_name": "engine of the mechanical chain (its number in the study)"}),
    }
    return xr.Dataset(data, coords=coords, attrs={**attrs, "kept": "summaries"})


def _finite(values):
    """Extremes over no bearing (inf) as NaN."""
    return np.where(np.isfinite(values), values, np.nan)


def quantile(ds, name, q):
    """Quantile [m] of a clearance from its histogram, within half a bin (BIN_WIDTH / 2)."""
    hist = ds[f"{name}_histogram"].values
    cdf = np.cumsum(hist, axis=-1) / hist.sum(axis=-1, keepdims=True)
    index = np.array([np.searchsorted(row, q) for row in cdf])
    return BIN_START + (index + 0.5) * BIN_WIDTH
