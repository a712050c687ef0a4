"""The search of one design: shell limits outside, housing and journal limits and pairs inside.

Shells made to order are aimed by the plan for the demand of each sample
(a study plans each scenario from its own pilot, :meth:`ShellSupply.aim_share`),
and the demand follows from the limits and pairs being searched. So for
given shell limits the housing and journal limits and pairs are searched
with the aims planned for the best design's demand so far, and the design
found is then scored with the aims planned for the demand it makes itself:
every objective value the shell search sees is the design's own.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .objective import wall_sums
from .pairing import choose_pairs
from .search import score_limits, score_pairs, search_limits, tie_break
from .tables import cell_sums, nm, pair_demand

#: Rounds of the final search of limits and pairs, each with the aims planned for the best design's demand.
FINAL_ROUNDS = 2


@dataclass(frozen=True)
class Found:
    """One complete design on the grids.

    Attributes
    ----------
    edges : numpy.ndarray
        Shell limits [m].
    housing_edges, journal_edges : numpy.ndarray
        Grid indices of the housing and journal limits.
    pair : numpy.ndarray (housing grades, journal grades)
        Index into the allowed pairs of every cell.
    objective : float
        Share outside the window plus the weighted worst scenario, aims planned for its own demand [-].
    shares : numpy.ndarray (samples,)
        Share outside the window per sample [-].
    demand : numpy.ndarray (samples, grades)
        Shells per bearing of each grade the design asks for, per sample.
    tables : CellTables
        With the aims planned for ``demand``.
    """

    edges: np.ndarray
    housing_edges: np.ndarray
    journal_edges: np.ndarray
    pair: np.ndarray
    objective: float
    shares: np.ndarray
    demand: np.ndarray
    tables: object

    @property
    def upper(self):
        return self.tables.pairs.upper[self.pair]

    @property
    def lower(self):
        return self.tables.pairs.lower[self.pair]


class Search:
    """The memory of one design's search: best design so far, its demand, the limits to warm-start from.

    A class because the shell search calls :meth:`evaluate` as a plain
    function of the shell limits while this memory carries over between calls.
    """

    def __init__(self, problem, *, seed, x0=None):
        self.problem = problem
        self.seed = seed
        self.x = x0  # point of the limits cube the inner search starts from
        self.best = None  # Found
        self.evaluations = 0
        self.cache = {}

    def limits(self, tables, *, popsize=5, maxiter=30):
        """Best housing and journal limits on ``tables`` and the cheapest pair of each cell."""
        p = self.problem
        result = search_limits(tables, p.housing, p.journal, p.housing_grid, p.journal_grid, p.ideal_at,
                               scenario_weight=p.weights.scenario, seed=self.seed, x0=self.x, popsize=popsize,
                               maxiter=maxiter)
        self.evaluations += result.evaluations
        h, j = result.housing_edges[None], result.journal_edges[None]
        tie = tie_break(tables, p.housing_grid, p.journal_grid, h, j, p.ideal_at)
        return result, score_limits(tables, h, j, scenario_weight=p.weights.scenario, tie=tie).pair[0]

    def score(self, edges, shells, housing_edges, journal_edges, pair, tables):
        """The design's :class:`Found`, scored with the aims planned for the demand it makes itself."""
        p = self.problem
        own = pair_demand(tables, housing_edges, journal_edges, pair)
        scored = p.tables(shells, own)
        objective, shares = score_pairs(scored, housing_edges, journal_edges, pair, scenario_weight=p.weights.scenario)
        found = Found(edges, housing_edges, journal_edges, pair, objective, shares, own, scored)
        if self.best is None or objective < self.best.objective:
            encoded = [p.housing.encode(housing_edges), p.journal.encode(journal_edges)]
            if all(e is not None for e in encoded):
                self.x = np.concatenate(encoded)
            self.best = found
        return found

    def demand(self, edges):
        return self.problem.proxy_demand(edges) if self.best is None else self.best.demand

    def evaluate(self, relative):
        """Objective of shell limits ``relative`` to the centring wall [m] (on the shell grid)."""
        p = self.problem
        edges = p.on_grid(p.centre + relative)
        key = tuple(nm(edges))
        if key not in self.cache:
            shells = p.shell_scheme(edges)
            tables = p.tables(shells, self.demand(edges))
            result, pair = self.limits(tables)
            self.cache[key] = self.score(edges, shells, result.housing_edges, result.journal_edges, pair,
                                         tables).objective
        return self.cache[key]

    def finish(self, edges, log, limits=()):
        """The best design with shell limits ``edges`` [m]: the search's, or one of a final, longer search of
        the limits with the cheapest pairs or the pairs of the MILP (:func:`choose_pairs`), or one of the
        housing and journal ``limits`` given (pairs (grid indices, grid indices), e.g. a nested start's),
        whichever has the lowest objective with the planned surplus and shortfall added. Returns
        (Found, surplus, shortfall, aim share)."""
        p = self.problem
        shells = p.shell_scheme(edges)
        supply = p.supply
        spill = supply.spill(shells) if supply.mode == "to-order" else None
        landing = None if spill is not None else wall_sums(shells, supply, p.samples[0].shell_normals).landing

        def balance(found):
            surplus, shortfall, aim = p.balance(shells, found.demand[0])
            return found.objective + p.supply_cost(surplus, shortfall), found, surplus, shortfall, aim

        best = None
        if self.best is not None and np.array_equal(nm(self.best.edges), nm(edges)):
            best = balance(self.best)
        rounds = [None] * FINAL_ROUNDS + [tuple(map(np.asarray, pair)) for pair in limits]
        for given in rounds:
            tables = p.tables(shells, self.demand(edges))
            if given is None:
                found_limits, cheapest = self.limits(tables, popsize=10, maxiter=100)
                h, j = found_limits.housing_edges, found_limits.journal_edges
            else:
                h, j = given
                tie = tie_break(tables, p.housing_grid, p.journal_grid, h[None], j[None], p.ideal_at)
                cheapest = score_limits(tables, h[None], j[None], scenario_weight=p.weights.scenario, tie=tie).pair[0]
            outside = cell_sums(tables.outside, h[None], j[None])[:, :, 0] / tables.bearings[:, None, None, None]
            count = cell_sums(tables.count[:1], h[None], j[None])[0, 0] / tables.bearings[0]
            tie = tie_break(tables, p.housing_grid, p.journal_grid, h[None], j[None], p.ideal_at)[:, 0]
            milp = choose_pairs(outside, count, tables.pairs, p.shell_grades, scenario_weight=p.weights.scenario,
                                surplus_weight=p.weights.surplus, shortfall_weight=p.weights.shortfall,
                                shells_per_bearing=p.shells_per_bearing, spill=spill, landing=landing, tie=tie)
            for pair in (milp.pair, cheapest):
                found = self.score(edges, shells, h, j, pair, tables)
                log(f"  limits and pairs: J {found.objective * 1e6:.4g} ppm "
                    f"(outside per sample {np.round(found.shares * 1e6, 1)} ppm)")
                candidate = balance(found)
                if best is None or candidate[0] < best[0]:
                    best = candidate
        return best[1:]
