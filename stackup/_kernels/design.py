"""The designer's hot loop: expected bearings outside the window per cell, for every shell pair."""

import numpy as np
from numba import njit


@njit(cache=True)
def cell_outside(cdf, start, size, step, thin, thick, cell, n_cells):
    """Expected bearings outside the window in each cell, for each shell pair.

    A bearing is inside the window when the wall sum of its pair lies between
    ``thin`` (the wall sum that brings it to the window's upper clearance) and
    ``thick`` (its lower clearance); the probability of that is read from the
    pair's cumulative distribution by linear interpolation on its evenly spaced
    points, clipped to its range.

    Parameters
    ----------
    cdf : float64 (pairs, points)
        Cumulative distribution of each pair's wall sum, padded past ``size``.
    start : float64 (pairs,)
        Wall sum of each distribution's first point [m].
    size : int64 (pairs,)
        Points of each distribution (>= 2).
    step : float
        Spacing of the points [m].
    thin, thick : float64 (bearings,)
        Wall sums that put each bearing at the window's upper and lower clearance [m].
    cell : int64 (bearings,)
        Cell of each bearing, in [0, n_cells).

    Returns
    -------
    float64 (pairs, n_cells)
        Sum over each cell's bearings of the probability of being outside the window.
    """
    n_pairs = cdf.shape[0]
    out = np.zeros((n_pairs, n_cells))
    for p in range(n_pairs):
        f = cdf[p]
        last = size[p] - 1.0
        for b in range(thin.shape[0]):
            inside = _interp(thick[b], start[p], step, f, last) - _interp(thin[b], start[p], step, f, last)
            out[p, cell[b]] += min(max(1.0 - inside, 0.0), 1.0)
    return out


@njit(cache=True, inline="always")
def _interp(t, start, step, f, last):
    u = min(max((t - start) / step, 0.0), last)
    i = min(int(u), int(last) - 1)
    return f[i] + (u - i) * (f[i + 1] - f[i])
