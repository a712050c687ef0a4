"""Cell costs on the read-out grid: every candidate's share outside the window by prefix sums.

Housing and journal readings are binned on the read-out grid (the step at
which grade limits may lie). For fixed shell grades, the probability that a
bearing ends outside the window is known for every shell pair
(:mod:`stackup.design.objective`), so the expected number of bearings
outside the window of any rectangle of readings and any pair is a
difference of four entries of a two-dimensional prefix sum. A candidate set
of housing and journal grade limits is then evaluated in microseconds,
independently of the sample size, and a whole population of candidates in
one array operation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .objective import outside_sums, wall_sums

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
    """What the cell tables need of the samples, computed once: grid cell and window of each bearing.

    Attributes
    ----------
    samples : list of DesignSample
    cell : list of numpy.ndarray
        Grid cell ``housing bin * journal bins + journal bin`` of each bearing, per sample.
    wall_sums : list of (numpy.ndarray, numpy.ndarray)
        Smallest and largest wall sum [m] that keep each bearing in the window, per sample.
    count : numpy.ndarray (samples, housing bins + 1, journal bins + 1)
        Prefix sums of the bearings.
    bearings : numpy.ndarray (samples,)
    shape : (int, int)
        Housing and journal grid bins.
    """

    samples: list
    cell: list
    wall_sums: list
    count: np.ndarray
    bearings: np.ndarray
    shape: tuple

    @classmethod
    def of(cls, samples, housing_grid, journal_grid, window):
        nh, nj = housing_grid.bins, journal_grid.bins
        cells = [housing_grid.index(s.housing_reading) * nj + journal_grid.index(s.journal_reading) for s in samples]
        count = np.stack([np.bincount(c, minlength=nh * nj).reshape(nh, nj) for c in cells]).astype(float)
        return cls(list(samples), cells, [(s.ideal_wall_sum(window[1]), s.ideal_wall_sum(window[0])) for s in samples],
                   _prefix(count), np.array([s.bearings for s in samples], float), (nh, nj))


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
    outside = np.zeros((len(binned.samples), upper.size, nh * nj))
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
        thin, thick = binned.wall_sums[s]
        expected = outside_sums(sums, upper, lower, thin, thick, binned.cell[s], nh * nj)
        # a grade no shell lands in: its bearings are counted as lost
        outside[s] = np.where(np.isnan(expected), np.bincount(binned.cell[s], minlength=nh * nj), expected)
    return CellTables(_prefix(outside.reshape(len(binned.samples), upper.size, nh, nj)), binned.count,
                      binned.bearings, Pairs(upper, lower, level))


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
