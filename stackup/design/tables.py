r"""Cell costs on the read-out grid: every candidate's share outside the window by prefix sums.

The bearings are integrated out as well as the shells. Housing and journal
readings are binned on the read-out grid (the step at which grade limits may
lie). Each bin gets the bearings it expects from the reading distributions
(the product of the housing and the journal readings of a reading sample of
many engines, :func:`stackup.design.sample.draw_readings`), and the wall
sums that put a bearing read there at the window's upper and lower clearance
from the design sample's least-squares line in the readings,
:math:`t = a + b\,h + c\,j`. What the readings do not tell (gauge error,
crush height, press fit) scatters the bearings about that line by
:math:`r`, independently of the shells, so it is folded into the
distribution of the pair's wall sum :math:`S` (:meth:`WallSums.cdf`):

.. math:: P_{out} = P(S - r_{thin} < t_{thin}) + P(S - r_{thick} > t_{thick}).

Why not the sample's own bearings: at shares of a few ppm, the bearings
outside the window sit in the rare corners of the cells (a large bore with a
small journal in one grade of each), where a design sample of thousands of
engines holds a handful of bearings or none; a search scoring those bearings
tunes its pairs to the few it has (issue 31: a 5-grade design promised
0.22 ppm on its sample and showed 1.5 ppm in a comparison). Weighting every
bin by its probability gives each corner its due however few bearings the
sample puts there; the line and the scatter need hundreds of bearings, not
millions. Every design states this tier's figure beside the conditional
tier's on sampled parts it never saw (the check, :mod:`stackup.design.assess`);
the tier's error over designs is for studies/design_scheme.py to measure in
reports/design_scheme.md (its tables predate this tier).

For fixed shell grades the expected number of bearings outside the window
of any rectangle of readings and any pair is then a difference of four
entries of a two-dimensional prefix sum: a candidate set of housing and
journal grade limits is evaluated in microseconds, independently of the
sample size, and a whole population of candidates in one array operation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..study.clearance import preferred_pairs
from .objective import Scatter, wall_sums

NM = 1e-9


def nm(value):
    """Lengths [m] in whole nanometres (the step at which schemes compare readings)."""
    return np.rint(np.asarray(value, dtype=float) / NM).astype(np.int64)


@dataclass(frozen=True)
class ReadoutGrid:
    """Grade limits a dimension may take: ``lo + k * step`` within the drawing limits ``[lo, hi]``.

    Attributes
    ----------
    edges : numpy.ndarray of int
        Grid points in nanometres, both drawing limits included.
    """

    edges: np.ndarray

    @classmethod
    def over(cls, lo, hi, step):
        lo_nm, hi_nm, step_nm = int(nm(lo)), int(nm(hi)), int(nm(step))
        inner = np.arange(lo_nm, hi_nm, step_nm, dtype=np.int64)
        return cls(np.append(inner, hi_nm))

    @property
    def bins(self):
        return self.edges.size - 1

    def index(self, reading):
        """Grid bin of each reading [m] (readings at the top limit in the last bin)."""
        k = np.searchsorted(self.edges, nm(reading), side="right") - 1
        return np.clip(k, 0, self.bins - 1)

    def metres(self, k):
        """Grid point(s) ``k`` [m]."""
        return self.edges[k] * NM

    def min_bins(self, width):
        """Fewest bins that make a grade at least ``width`` [m] wide (the first and last bins may be short)."""
        step = int(self.edges[1] - self.edges[0]) if self.bins > 1 else int(self.edges[-1] - self.edges[0])
        return max(1, int(np.ceil(nm(width) / step - 1e-9)))


@dataclass(frozen=True)
class Pairs:
    """Shell pairs a cell may take: (upper, lower) grade indices and their mean wall sums [m]."""

    upper: np.ndarray
    lower: np.ndarray
    level: np.ndarray


def allowed_pairs(grades, mixed):
    """Pairs of ``grades`` shell grades: each grade with itself and, if ``mixed``, with the next (ISO 13778 6.1 b)."""
    upper = [g for g in range(grades)] + ([g for g in range(grades - 1)] if mixed else [])
    lower = [g for g in range(grades)] + ([g + 1 for g in range(grades - 1)] if mixed else [])
    return np.array(upper), np.array(lower)


@dataclass(frozen=True)
class Binned:
    """What the cell tables need of the samples, computed once: per read-out grid bin, the expected
    bearings and the wall sums that put them at the window's edges.

    Attributes
    ----------
    samples : list of DesignSample
    weight : numpy.ndarray (samples, housing bins, journal bins)
        Expected bearings of each sample in each bin: the sample's bearings times the product of the
        housing and the journal reading distribution (:class:`~stackup.design.sample.Readings`).
    housing_mean, journal_mean : numpy.ndarray (samples, bins)
        Mean reading of each bin [m] (its middle where no reading falls in it).
    thin, thick : numpy.ndarray (samples, housing bins, journal bins)
        Wall sum that puts a bearing read at the bin's mean readings at the window's upper and lower
        clearance, the sample's least-squares line in the readings [m].
    scatter : list of (Scatter, Scatter)
        Per sample, the scatter of the bearings' thin and thick wall sums about that line.
    count : numpy.ndarray (samples, housing bins + 1, journal bins + 1)
        Prefix sums of ``weight``.
    bearings : numpy.ndarray (samples,)
    shape : (int, int)
        Housing and journal grid bins.
    """

    samples: list
    weight: np.ndarray
    housing_mean: np.ndarray
    journal_mean: np.ndarray
    thin: np.ndarray
    thick: np.ndarray
    scatter: list
    count: np.ndarray
    bearings: np.ndarray
    shape: tuple

    @classmethod
    def of(cls, samples, readings, housing_grid, journal_grid, window):
        """The samples with the :class:`~stackup.design.sample.Readings` of each, on the grids, for ``window``."""
        weight, h_mean, j_mean, thin, thick, scatter = [], [], [], [], [], []
        for sample, read in zip(samples, readings):
            wh, hm = _marginal(housing_grid, read.housing)
            wj, jm = _marginal(journal_grid, read.journal)
            weight.append(sample.bearings * np.outer(wh, wj))
            h_mean.append(hm)
            j_mean.append(jm)
            x = np.column_stack([np.ones(sample.bearings), sample.housing_reading, sample.journal_reading])
            sides = []
            for edge, out in ((window[1], thin), (window[0], thick)):
                value = sample.ideal_wall_sum(edge)
                coef = np.linalg.lstsq(x, value, rcond=None)[0]
                out.append(coef[0] + coef[1] * hm[:, None] + coef[2] * jm[None, :])
                sides.append(Scatter.of(value - x @ coef))
            scatter.append(tuple(sides))
        weight = np.stack(weight)
        return cls(list(samples), weight, np.stack(h_mean), np.stack(j_mean), np.stack(thin), np.stack(thick),
                   scatter, _prefix(weight), np.array([s.bearings for s in samples], float),
                   (housing_grid.bins, journal_grid.bins))

    def outside(self, s, sums, upper, lower):
        """Expected bearings of sample ``s`` outside the window in each bin (housing bins, journal bins) with
        shells of grades ``upper`` + ``lower`` (:class:`WallSums` ``sums``); None if a grade holds no shell.

        The bearings of one bin differ in what their readings do not tell (gauge error, crush, the
        press fit); that scatter is independent of the shells, so it is folded into the distribution of
        the wall sum (:meth:`WallSums.cdf`):
        :math:`P_{out} = P(S - r_{thin} < t_{thin}) + P(S - r_{thick} > t_{thick})`.
        """
        low = sums.cdf(upper, lower, self.scatter[s][0])
        if low is None:
            return None
        high = sums.cdf(upper, lower, self.scatter[s][1])
        share = np.interp(self.thin[s], *low) + 1.0 - np.interp(self.thick[s], *high)
        return self.weight[s] * np.clip(share, 0.0, 1.0)


def _marginal(grid, readings):
    """Share of ``readings`` [m] in each bin of ``grid`` and their mean reading per bin [m]."""
    index = grid.index(readings)
    count = np.bincount(index, minlength=grid.bins).astype(float)
    middle = 0.5 * (grid.metres(np.arange(grid.bins)) + grid.metres(np.arange(1, grid.bins + 1)))
    total = np.bincount(index, weights=readings, minlength=grid.bins)
    return count / count.sum(), np.where(count > 0, total / np.maximum(count, 1.0), middle)


@dataclass(frozen=True)
class CellTables:
    """Prefix sums over the read-out grid of one set of shell grades, for every sample.

    Attributes
    ----------
    outside : numpy.ndarray (samples, pairs, housing bins + 1, journal bins + 1)
        Expected bearings outside the window with each pair, summed over readings below each grid point.
    count : numpy.ndarray (samples, housing bins + 1, journal bins + 1)
        Bearings, likewise.
    bearings : numpy.ndarray (samples,)
    pairs : Pairs
    """

    outside: np.ndarray
    count: np.ndarray
    bearings: np.ndarray
    pairs: Pairs


def _prefix(values):
    out = np.zeros(values.shape[:-2] + (values.shape[-2] + 1, values.shape[-1] + 1))
    out[..., 1:, 1:] = values.cumsum(axis=-2).cumsum(axis=-1)
    return out


def cell_tables(binned, shell_scheme, window, *, mixed, demand=None):
    """:class:`CellTables` of ``shell_scheme``'s shell grades on the ``binned`` samples (the first nominal).

    ``demand`` (grades,) or (samples, grades) is the shell demand the
    supply's aim shares are planned for (made-to-order shells), for every
    sample or per sample (a study plans each scenario from its own pilot);
    None plans for equal shares.
    """
    n_grades = len(shell_scheme.shell.labels)
    upper, lower = allowed_pairs(n_grades, mixed)
    nh, nj = binned.shape
    outside = np.zeros((len(binned.samples), upper.size, nh, nj))
    level = None
    for s, sample in enumerate(binned.samples):
        supply = sample.engine.shell_wall
        aim = None
        if supply.mode == "to-order":
            wanted = np.ones(n_grades) if demand is None else np.asarray(demand, dtype=float)
            aim = supply.aim_share(shell_scheme, wanted[s] if wanted.ndim == 2 else wanted)
        sums = wall_sums(shell_scheme, supply, sample.shell_normals, aim)
        if level is None:
            level = sums.mean[upper] + sums.mean[lower]
        for p, (u, lo) in enumerate(zip(upper, lower)):
            expected = binned.outside(s, sums, u, lo)
            # a grade no shell lands in: its bearings are counted as lost
            outside[s, p] = binned.weight[s] if expected is None else expected
    return CellTables(_prefix(outside), binned.count, binned.bearings, Pairs(upper, lower, level))


def expected_outside(scheme, binned, s):
    """Expected share of sample ``s``'s graded bearings outside the window with a complete ``scheme``
    (its preferred pairs at each bin's mean readings; shells made to order aimed for the demand it
    makes), and the shells of each grade it asks for per bearing: (share, demand (grades,))."""
    sample = binned.samples[s]
    h, j = np.meshgrid(binned.housing_mean[s], binned.journal_mean[s], indexing="ij")
    up, lo = preferred_pairs(scheme, h.ravel(), j.ravel())
    weight = binned.weight[s].ravel()
    graded = up >= 0
    n = len(scheme.shell.labels)
    demand = (np.bincount(up[graded], weights=weight[graded], minlength=n)
              + np.bincount(lo[graded], weights=weight[graded], minlength=n)) / binned.bearings[s]
    supply = sample.engine.shell_wall
    aim = supply.aim_share(scheme, demand) if supply.mode == "to-order" else None
    sums = wall_sums(scheme, supply, sample.shell_normals, aim)
    code = np.where(graded, up * n + lo, -1)
    total = 0.0
    for c in np.unique(code[graded]):
        expected = binned.outside(s, sums, c // n, c % n)
        total += weight[code == c].sum() if expected is None else expected.ravel()[code == c].sum()
    return total / max(weight[graded].sum(), 1e-300), demand


def cell_sums(table, housing_edges, journal_edges):
    """Sums of ``table`` (..., H + 1, J + 1) over the cells of candidate limits.

    ``housing_edges`` (candidates, housing grades + 1) and ``journal_edges``
    (candidates, journal grades + 1) are grid indices; returns
    (..., candidates, housing grades, journal grades).
    """
    corners = table[..., housing_edges[:, :, None], journal_edges[:, None, :]]
    return np.diff(np.diff(corners, axis=-2), axis=-1)


def pair_demand(tables, housing_edges, journal_edges, pair):
    """Shells of each grade per bearing that the pairs ``pair`` (housing grades, journal grades) of one set of
    limits ask for, per sample (samples, grades)."""
    count = cell_sums(tables.count, housing_edges[None], journal_edges[None])[:, 0] / tables.bearings[:, None, None]
    n_grades = int(max(tables.pairs.upper.max(), tables.pairs.lower.max())) + 1
    uses = np.zeros((len(tables.pairs.upper), n_grades))
    np.add.at(uses, (np.arange(uses.shape[0]), tables.pairs.upper), 1.0)
    np.add.at(uses, (np.arange(uses.shape[0]), tables.pairs.lower), 1.0)
    return np.einsum("shj,hjg->sg", count, uses[pair])
