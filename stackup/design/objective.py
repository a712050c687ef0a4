"""Share of bearings outside the operating-clearance window, for any scheme, on the design sample.

The parts are the sample's (their readings choose the cell, hence the shell
pair); the shells are integrated out: for each shell grade the walls of the
shells the engine's supply sorts into it (:meth:`ShellSupply.make` on the
sample's shell normals) give a histogram, two histograms convolved give the
distribution of a pair's wall sum, and each bearing contributes the
probability that its operating clearance
:math:`C_{op} = A - \\beta S` falls outside the window,

.. math:: P_{out} = 1 - [F_S((A - c_{lo})/\\beta) - F_S((A - c_{hi})/\\beta)].

Averaging probabilities instead of counting bearings (conditional Monte
Carlo) estimates shares of a few ppm from tens of thousands of bearings, and
the share moves smoothly with the shell grades.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import schemes as schemes_mod
from .._kernels import design as _kernel
from ..study.clearance import preferred_pairs

#: Step of the wall and wall-sum histograms [m].
WALL_BIN = 2e-8


@dataclass(frozen=True)
class WallSums:
    """Distributions of the wall sum of shell pairs of one scheme's shell grades.

    ``pmf[g]`` is the histogram of the true wall of the shells sorted into
    grade g (sums to 1, or 0 for a grade no shell lands in) on bins of width
    :data:`WALL_BIN` starting at ``origin`` [m].
    """

    origin: float
    pmf: np.ndarray  # (grades, bins)
    mean: np.ndarray  # (grades,) mean true wall [m]
    landing: np.ndarray  # (grades,) share of the shells made that land in each grade

    def cdf(self, upper, lower, scatter=None):
        """Cumulative distribution of ``s_upper + s_lower``, or of ``s_upper + s_lower - r`` with ``r``
        distributed as ``scatter`` (a :class:`Scatter`), independent of the shells: (points [m],
        probabilities) for np.interp; None if a grade holds no shell."""
        a, b = self.pmf[upper], self.pmf[lower]
        ia, ib = np.flatnonzero(a), np.flatnonzero(b)
        if ia.size == 0 or ib.size == 0:
            return None
        conv = np.convolve(a[ia[0]:ia[-1] + 1], b[ib[0]:ib[-1] + 1])
        # the sum of two values in bins i and j lies in [i + j, i + j + 2) bins above twice the origin;
        # its mass is placed at the middle of that range and the CDF interpolated between mass points
        start = 2 * self.origin + (ia[0] + ib[0] + 1) * WALL_BIN
        if scatter is not None:
            # r in bin k sits at origin_r + (k + 0.5) step: the difference's mass points stay on the same step
            conv = np.convolve(conv, scatter.pmf[::-1])
            start = start - scatter.origin - (scatter.pmf.size - 0.5) * WALL_BIN
        x = start + WALL_BIN * np.arange(conv.size + 1) - 0.5 * WALL_BIN
        return x, np.concatenate(([0.0], np.cumsum(conv)))


@dataclass(frozen=True)
class Scatter:
    """Histogram of a quantity on bins of :data:`WALL_BIN` from ``origin`` [m] (``pmf`` sums to 1): here what
    a bearing's readings leave unexplained of the wall sum that puts it at an edge of the window."""

    origin: float
    pmf: np.ndarray

    @classmethod
    def of(cls, values):
        origin = float(np.min(values)) - WALL_BIN
        index = np.floor((np.asarray(values) - origin) / WALL_BIN).astype(np.int64)
        return cls(origin, np.bincount(index) / index.size)


def wall_sums(scheme, supply, normals, aim_share=None):
    """:class:`WallSums` of ``scheme``'s shell grades made by ``supply`` from the sample's shell ``normals``."""
    shells = supply.make(scheme, normals, aim_share)
    ok = shells.grade >= 0
    wall = shells.wall[ok]
    origin = float(wall.min()) - WALL_BIN
    index = np.floor((wall - origin) / WALL_BIN).astype(np.int64)
    n = len(scheme.shell.labels)
    width = int(index.max()) + 2
    counts = np.bincount(shells.grade[ok] * width + index, minlength=n * width).reshape(n, width).astype(float)
    total = counts.sum(axis=1)
    pmf = counts / np.maximum(total, 1.0)[:, None]
    mean = np.bincount(shells.grade[ok], weights=wall, minlength=n) / np.maximum(total, 1.0)
    return WallSums(origin, pmf, mean, total / shells.wall.size)


def outside_sums(sums, upper, lower, thin, thick, cell, n_cells):
    """Expected bearings outside the window per cell, for shells of grades ``upper[p]`` + ``lower[p]``.

    ``thin``, ``thick`` (bearings,) are the wall sums that put each bearing
    at the window's upper and lower clearance [m]
    (:meth:`DesignSample.ideal_wall_sum`), ``cell`` (bearings,) its cell in
    ``[0, n_cells)``. Returns (pairs, n_cells): the sum over each cell's
    bearings of :math:`P_{out}`; NaN rows for a pair with a grade no shell
    lands in (every bearing needing it is a stock-out, not a clearance).
    """
    tables = [sums.cdf(u, l) for u, l in zip(upper, lower)]
    made = [p for p, t in enumerate(tables) if t is not None]
    out = np.full((len(tables), n_cells), np.nan)
    if not made:
        return out
    points = max(tables[p][1].size for p in made)
    cdf = np.zeros((len(made), points))
    for row, p in enumerate(made):
        f = tables[p][1]
        cdf[row, :f.size] = f
    start = np.array([tables[p][0][0] for p in made])
    size = np.array([tables[p][1].size for p in made], np.int64)
    out[made] = _kernel.cell_outside(cdf, start, size, WALL_BIN, np.ascontiguousarray(thin, dtype=float),
                                     np.ascontiguousarray(thick, dtype=float),
                                     np.ascontiguousarray(cell, dtype=np.int64), int(n_cells))
    return out


@dataclass(frozen=True)
class SchemeScore:
    """A scheme's share outside the window on one scenario's design sample.

    Attributes
    ----------
    outside : float
        Expected share of the assembled bearings outside the window [-].
    below, above : float
        The part of it below the window's lower clearance and above its upper one [-].
    demand : numpy.ndarray
        Shells of each grade the sample's preferred pairs ask for, per bearing (grades,).
    ungraded : float
        Share of built bearings the scheme has no grade for [-].
    """

    outside: float
    demand: np.ndarray
    ungraded: float
    mean_clearance: float
    below: float
    above: float


def demand_share(scheme, sample):
    """Shells of each grade per bearing that ``scheme``'s preferred pairs ask for on ``sample`` (grades,)."""
    up, lo = preferred_pairs(scheme, sample.housing_reading, sample.journal_reading)
    n = len(scheme.shell.labels)
    ok = up >= 0
    return (np.bincount(up[ok], minlength=n) + np.bincount(lo[ok], minlength=n)) / sample.bearings


def score(scheme, sample, window):
    """:class:`SchemeScore` of a complete scheme (its preferred pairs; no stock-outs) on ``sample``."""
    scheme = schemes_mod.load(scheme)
    supply = sample.engine.shell_wall
    demand = demand_share(scheme, sample)
    aim = supply.aim_share(scheme, demand) if supply.mode == "to-order" else None
    sums = wall_sums(scheme, supply, sample.shell_normals, aim)
    up, lo = preferred_pairs(scheme, sample.housing_reading, sample.journal_reading)
    n = len(scheme.shell.labels)
    code = np.where(up >= 0, up * n + lo, -1)
    thin, thick = sample.ideal_wall_sum(window[1]), sample.ideal_wall_sum(window[0])
    # one side at a time: a wall sum past the end of every distribution reads 0 (thin) or 1 (thick)
    never = np.full(thin.size, np.inf)
    total, below, above, count, clearance = 0.0, 0.0, 0.0, 0, 0.0
    for c in np.unique(code[code >= 0]):
        rows = code == c
        m = int(rows.sum())
        sides = [outside_sums(sums, [c // n], [c % n], a, b, np.zeros(m, np.int64), 1)[0, 0]
                 for a, b in ((thin[rows], thick[rows]), (-never[:m], thick[rows]), (thin[rows], never[:m]))]
        if np.isnan(sides[0]):
            continue
        total, below, above = total + sides[0], below + sides[1], above + sides[2]
        count += m
        level = sums.mean[c // n] + sums.mean[c % n]
        clearance += sample.operating_clearance(level)[rows].sum()
    count = max(count, 1)
    return SchemeScore(total / count, demand, float(np.mean(code < 0)), clearance / count, below / count,
                       above / count)
