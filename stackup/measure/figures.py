"""Figures of a fitted process: histogram with the fitted densities, normal probability plot.

Drawn on a matplotlib ``Figure`` (the user's backend is left alone); units on every axis.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from scipy import special

from . import _data
from .models import BY_NAME


def _density(process, x):
    """Density of a process object on the grid ``x`` [1/m] (the derivative of its CDF)."""
    return np.gradient(process.cdf(x), x)


def _bins(x):
    """Histogram bin edges [m]: about 2 sqrt(n) bins, each a whole number of the read-out's steps (no aliasing)."""
    span = float(x.max() - x.min())
    width = span / max(10, min(60, 2 * int(np.sqrt(x.size))))
    steps = np.diff(np.unique(x))
    step = float(steps.min()) if steps.size else width
    if step > 1e-3 * span:  # readings on a read-out grid: bins of whole steps, edges between the steps
        width = max(1, round(width / step)) * step
        return np.arange(x.min() - 0.5 * step, x.max() + width, width)
    return np.linspace(x.min(), x.max(), int(span / width) + 1)


def process_figure(fit, *, units="mm", label=None):
    """Histogram of the readings with the fitted reading and process densities, and a normal probability plot."""
    scale, unit = _data.UNITS[units], _data.UNIT_NAMES[units]
    label = label or (fit.source or "reading")
    model = BY_NAME[fit.model]
    reading = model.process(np.array(fit.reading_params))
    x = fit.readings
    lo, hi = fit.limits
    span = max(x.max(), hi) - min(x.min(), lo)
    grid = np.linspace(min(x.min(), lo) - 0.1 * span, max(x.max(), hi) + 0.1 * span, 600)
    fig = Figure(figsize=(10, 4), layout="constrained")
    left, right = fig.subplots(1, 2)
    left.hist(x / scale, bins=_bins(x) / scale, density=True, color="0.8", edgecolor="0.5",
              label=f"{x.size} readings")
    left.plot(grid / scale, _density(reading, grid) * scale, color="C0", label=f"fitted {fit.model} (readings)")
    if fit.gauge_repeatability:
        left.plot(grid / scale, _density(fit.process, grid) * scale, color="C1", linestyle="--",
                  label="process (gauge removed)")
    for limit in (lo, hi):
        left.axvline(limit / scale, color="C3", linewidth=1)
    left.set_xlabel(f"{label} [{unit}]")
    left.set_ylabel(f"density [1/{unit}]")
    left.set_title(f"Cpk {fit.cpk:.2f} ({fit.cpk_ci[0]:.2f}-{fit.cpk_ci[1]:.2f}); drawing limits in red", fontsize=9)
    left.legend(fontsize=8)
    n = x.size
    q = special.ndtri((np.arange(1, n + 1) - 0.375) / (n + 0.25))  # Blom's plotting positions
    right.plot(q, np.sort(x) / scale, ".", markersize=3, color="0.3", label="readings")
    line = np.linspace(q[0], q[-1], 200)
    right.plot(line, reading.ppf(special.ndtr(line)) / scale, color="C0", label=f"fitted {fit.model}")
    right.set_xlabel("standard normal quantile [-]")
    right.set_ylabel(f"{label} [{unit}]")
    right.set_title(f"normal probability plot; Anderson-Darling p = {fit.goodness_of_fit.p_value:.2f}", fontsize=9)
    right.legend(fontsize=8)
    return fig
