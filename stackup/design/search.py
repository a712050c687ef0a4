"""The search: housing and journal grade limits by differential evolution on the read-out grid, polished
edge by edge; shell grades over a grid of widths and positions; pairs per cell by the cheapest choice.

Every candidate is scored on the cell tables of :mod:`stackup.design.tables`
(one array operation per population), so the whole search runs on the same
design sample (common random numbers) and a seed makes it reproducible.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import optimize

from .tables import cell_sums

#: Tie-break cost of a pair per micrometre between its mean wall sum and the wall sum the cell's
#: centre asks for [share / um]: far below any share a bearing contributes, so it only decides
#: between pairs that no bearing of the sample tells apart (e.g. in cells the sample leaves empty).
TIE_BREAK = 1e-13


@dataclass(frozen=True)
class Limits:
    """Candidate grade limits of one dimension: ``grades`` grades of at least ``min_bins`` grid bins over ``bins``."""

    grades: int
    bins: int
    min_bins: int

    @property
    def variables(self):
        return self.grades if self.grades > 1 else 0

    def edges(self, x):
        """Grid indices (candidates, grades + 1) of the limits encoded by ``x`` (variables, candidates) in [0, 1].

        Each grade gets ``min_bins`` bins and a share ``x_k / sum(x)`` of the
        remaining bins, so every point of the unit cube is a feasible set of
        limits and the equal-width limits are the centre of the cube.
        """
        x = np.asarray(x, dtype=float)
        c = x.shape[1] if x.ndim == 2 else 1
        if self.grades == 1:
            return np.tile([0, self.bins], (c, 1))
        x = x.reshape(self.grades, c)
        total = x.sum(axis=0)
        share = np.where(total > 0, np.cumsum(x, axis=0) / np.where(total > 0, total, 1.0),
                         np.arange(1, self.grades + 1)[:, None] / self.grades)
        slack = self.bins - self.grades * self.min_bins
        inner = np.arange(1, self.grades)[:, None] * self.min_bins + np.floor(slack * share[:-1] + 1e-9).astype(np.int64)
        return np.concatenate([np.zeros((1, c), np.int64), inner, np.full((1, c), self.bins)]).T

    def encode(self, edges):
        """The point of the unit cube for grid-index ``edges`` (grades + 1,), or None if a grade is too narrow."""
        widths = np.diff(np.asarray(edges)) - self.min_bins
        slack = self.bins - self.grades * self.min_bins
        if self.grades == 1 or np.any(widths < 0) or slack <= 0:
            return None if self.grades > 1 else np.zeros(0)
        return widths / slack


@dataclass(frozen=True)
class Candidate:
    """Scores of candidate limits: total objective, share outside per sample, and the pair chosen per cell."""

    objective: np.ndarray  # (candidates,)
    share: np.ndarray  # (samples, candidates)
    pair: np.ndarray  # (candidates, housing grades, journal grades) index into the tables' pairs


def score_limits(tables, housing_edges, journal_edges, *, scenario_weight, tie):
    """Score candidate limits on ``tables``: each cell takes its cheapest pair.

    The objective is the nominal share outside the window plus
    ``scenario_weight`` times the largest share over the scenario samples;
    a cell's pair minimises its nominal share plus ``scenario_weight`` times
    its mean share over the scenarios, plus the tie-break ``tie(pairs,
    candidates, housing grades, journal grades)``.
    """
    share = cell_sums(tables.outside, housing_edges, journal_edges) / tables.bearings[:, None, None, None, None]
    choice = share[0] + tie
    if share.shape[0] > 1:
        choice = choice + scenario_weight * share[1:].mean(axis=0)
    pair = np.argmin(choice, axis=0)
    per_sample = np.take_along_axis(share, pair[None, None], axis=1)[:, 0].sum(axis=(-2, -1))
    objective = per_sample[0] + (scenario_weight * per_sample[1:].max(axis=0) if share.shape[0] > 1 else 0.0)
    return Candidate(objective, per_sample, pair)


def score_pairs(tables, housing_edges, journal_edges, pair, *, scenario_weight):
    """Objective and share outside the window per sample (samples,) of one design with fixed pairs
    ``pair`` (housing grades, journal grades), on ``tables``."""
    share = cell_sums(tables.outside, housing_edges[None], journal_edges[None])[:, :, 0] \
        / tables.bearings[:, None, None, None]
    per_sample = np.take_along_axis(share, pair[None, None], axis=1)[:, 0].sum(axis=(-2, -1))
    objective = per_sample[0] + (scenario_weight * per_sample[1:].max() if per_sample.size > 1 else 0.0)
    return float(objective), per_sample


def tie_break(tables, housing_grid, journal_grid, housing_edges, journal_edges, ideal):
    """Tie-break cost (pairs, candidates, housing grades, journal grades): distance of each pair's mean wall
    sum from the wall sum ``ideal(housing, journal)`` [m] asks for at the cell's centre, times :data:`TIE_BREAK`."""
    hm = housing_grid.metres(housing_edges)
    jm = journal_grid.metres(journal_edges)
    hc = 0.5 * (hm[:, :-1] + hm[:, 1:])
    jc = 0.5 * (jm[:, :-1] + jm[:, 1:])
    wanted = ideal(hc[:, :, None], jc[:, None, :])
    return TIE_BREAK * 1e6 * np.abs(tables.pairs.level[:, None, None, None] - wanted[None])


@dataclass(frozen=True)
class LimitsResult:
    housing_edges: np.ndarray  # (housing grades + 1,) grid indices
    journal_edges: np.ndarray
    objective: float
    evaluations: int


def search_limits(tables, housing, journal, housing_grid, journal_grid, ideal, *, scenario_weight, seed,
                  x0=None, popsize=8, maxiter=60):
    """Housing and journal limits that minimise the objective on ``tables``.

    Differential evolution (scipy) over the unit-cube encoding of both sets
    of limits (:meth:`Limits.edges`), the whole population scored at once;
    then each limit in turn is moved to its best grid point between its
    neighbours until no move improves (exact line searches on the grid).
    ``x0`` (a point of the cube, e.g. the best limits so far) joins the
    first population.
    """
    nh = housing.variables
    evaluations = 0

    def split(x):
        return housing.edges(x[:nh]), journal.edges(x[nh:])

    def score(h, j):
        nonlocal evaluations
        evaluations += h.shape[0]
        tie = tie_break(tables, housing_grid, journal_grid, h, j, ideal)
        return score_limits(tables, h, j, scenario_weight=scenario_weight, tie=tie).objective

    dims = nh + journal.variables
    if dims == 0:
        h, j = split(np.zeros((0, 1)))
        return LimitsResult(h[0], j[0], float(score(h, j)[0]), evaluations)
    result = optimize.differential_evolution(
        lambda x: score(*split(x if x.ndim == 2 else x[:, None])), [(0.0, 1.0)] * dims, popsize=popsize,
        maxiter=maxiter, tol=1e-6, seed=seed, polish=False, vectorized=True, updating="deferred", x0=x0,
        init="sobol")
    h, j = split(result.x[:, None])
    h, j = h[0].copy(), j[0].copy()
    best = float(score(h[None], j[None])[0])
    improved = True
    while improved:
        improved = False
        for edges, other, limits, is_housing in ((h, j, housing, True), (j, h, journal, False)):
            for k in range(1, limits.grades):
                positions = np.arange(edges[k - 1] + limits.min_bins, edges[k + 1] - limits.min_bins + 1)
                trial = np.repeat(edges[None], positions.size, axis=0)
                trial[:, k] = positions
                fixed = np.repeat(other[None], positions.size, axis=0)
                values = score(trial, fixed) if is_housing else score(fixed, trial)
                i = int(np.argmin(values))
                if values[i] < best - 1e-15:
                    best, edges[k], improved = float(values[i]), positions[i], True
    return LimitsResult(h, j, best, evaluations)


def search_shells(evaluate, starts, *, lower, upper, generations, polish, seed):
    """Shell grade limits (relative, [m]) that minimise ``evaluate``: differential evolution, then Nelder-Mead.

    The variables are the middle of the shell range and the width of each
    grade, bounded by ``lower`` and ``upper`` (so widths never fall below
    the sorting limit), widened to hold every start. Differential evolution (scipy; ``generations`` generations of
    four candidates per variable, the best of ``starts`` in the first)
    explores the shell grades; bounded Nelder-Mead with at most ``polish``
    evaluations refines the best.
    """
    def to_edges(v):
        edges = np.concatenate(([0.0], np.cumsum(v[1:])))
        return v[0] + edges - 0.5 * edges[-1]

    def from_edges(edges):
        edges = np.asarray(edges, dtype=float)
        return np.concatenate(([0.5 * (edges[0] + edges[-1])], np.diff(edges)))

    def f(v):
        return evaluate(to_edges(v))

    raw = np.array([from_edges(e) for e in starts])
    lower, upper = np.minimum(lower, raw.min(axis=0)), np.maximum(upper, raw.max(axis=0))  # every start inside
    points = list(raw)
    values = [f(v) for v in points]
    best = points[int(np.argmin(values))]
    bounds = list(zip(lower, upper))
    if generations:
        # a start on a bound can scale to just above 1 in scipy's unit cube and be refused: start a hair inside
        margin = 1e-9 * (upper - lower)
        result = optimize.differential_evolution(f, bounds, popsize=4, maxiter=generations, seed=seed, polish=False,
                                                 init="sobol", x0=np.clip(best, lower + margin, upper - margin), tol=0.0)
        best = result.x
    if polish:
        result = optimize.minimize(f, best, method="Nelder-Mead", bounds=bounds,
                                   options={"maxfev": polish, "xatol": 2e-8, "fatol": 1e-9,
                                            "initial_simplex": np.vstack([best] + [
                                                np.clip(best + 0.5e-6 * np.eye(best.size)[k], lower, upper)
                                                for k in range(best.size)])})
        if result.fun <= f(best):
            best = result.x
    return to_edges(best)
