"""One design problem: the engine's design sample, the grids and narrowest grades, the weights.

Everything here follows from the designer's options alone and stays fixed
during the search.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import special

from .. import _validate as check
from ..schemes import from_dict
from .objective import wall_sums
from .sample import DESIGN_KEY, clearance_changes, draw_readings, draw_sample
from .search import Limits
from .tables import Binned, ReadoutGrid, allowed_pairs, cell_tables, expected_outside, nm

#: Engines of the reading sample (:func:`~stackup.design.sample.draw_readings`) per engine of the design sample.
READINGS_FACTOR = 25
#: Labels of designed grades, thinnest shell (smallest bore, journal) first, as ISO 13778 schemes 4 and 5.
LABELS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"


@dataclass(frozen=True)
class Weights:
    """Weights of the stated secondary terms of the objective.

    Attributes
    ----------
    scenario : float
        Weight of the worst declared scenario's share outside the window [-]
        (0.1: a bearing outside the window under the worst scenario counts a
        tenth of one under nominal conditions).
    surplus, shortfall : float
        Weights of the planned shells per bearing left over and missing [-]
        (1e-4: 0.01 shells per bearing cost as much as 1 ppm outside the window).
    """

    scenario: float = 0.1
    surplus: float = 1e-5
    shortfall: float = 1e-4

    def __post_init__(self):
        check.fields(self, dict.fromkeys(("scenario", "surplus", "shortfall"), check.Positive(zero=True)),
                     prefix="weights.")


@dataclass(frozen=True)
class Problem:
    """What the search needs that does not change during it.

    Attributes
    ----------
    engine : Engine
    window : (float, float)
        Operating-clearance window [m].
    binned : Binned
        The design samples (nominal first, then each scenario that changes the
        clearance) binned on the read-out grids.
    skipped : list of str
        Declared scenarios left out because they do not change the clearance.
    changes : dict of str -> dict
        The scenario of each sample after the nominal one, by label (:mod:`stackup.scenarios`).
    housing_grid, journal_grid : ReadoutGrid
    housing, journal : Limits
        Grades and narrowest grade (in grid bins) of each dimension.
    shell_grades : int
    mixed : bool
        Whether a grade may be paired with the next one.
    shell_step, min_width : float
        Grid of the shell limits and narrowest shell grade [m].
    ideal : numpy.ndarray (3,)
        Wall sum that centres a bearing in the window as ``a + b * housing + c * journal`` reading
        (least squares on the nominal sample) [m, -, -].
    centre : float
        Shell wall that centres the median bearing of the nominal sample [m].
    span : float
        Range of wall sums (0.1 % to 99.9 %) that centre the bearings [m].
    weights : Weights
    sort_share : float
    """

    engine: object
    window: tuple
    binned: Binned
    skipped: list
    changes: dict
    housing_grid: ReadoutGrid
    journal_grid: ReadoutGrid
    housing: Limits
    journal: Limits
    shell_grades: int
    mixed: bool
    shell_step: float
    min_width: float
    ideal: np.ndarray
    centre: float
    span: float
    weights: Weights
    sort_share: float

    @property
    def samples(self):
        return self.binned.samples

    @property
    def supply(self):
        return self.engine.shell_wall

    @property
    def shells_per_bearing(self):
        """Shells made per bearing: two plus the engine's planned surplus."""
        return 2.0 * (1.0 + self.supply.surplus)

    @property
    def levels(self):
        """Distinct pairs along the wall-sum scale: every grade with itself, and with the next if mixed."""
        return 2 * self.shell_grades - 1 if self.mixed else self.shell_grades

    def ideal_at(self, housing, journal):
        """Wall sum [m] that centres a bearing with these housing and journal readings [m] in the window."""
        return self.ideal[0] + self.ideal[1] * housing + self.ideal[2] * journal

    def objective(self, shares):
        """Share outside the window, nominal plus the weighted worst scenario, of shares per sample [-]."""
        shares = np.asarray(shares, dtype=float)
        return float(shares[0] + (self.weights.scenario * shares[1:].max() if shares.size > 1 else 0.0))

    def expected(self, scheme):
        """Expected share outside the window of a complete ``scheme`` per design sample, label -> share [-]
        (:func:`~stackup.design.tables.expected_outside`: the tier the search minimises)."""
        return {sample.label: expected_outside(scheme, self.binned, s)[0] for s, sample in enumerate(self.samples)}

    def expected_objective(self, scheme):
        """:math:`J` of a complete ``scheme`` on the design samples, supply terms included: its
        :meth:`expected` shares and the planned surplus and shortfall for the demand its preferred pairs
        make on the nominal sample [-]."""
        shares = self.expected(scheme)
        demand = expected_outside(scheme, self.binned, 0)[1]
        surplus, shortfall, _ = self.balance(scheme, demand)
        return self.objective(list(shares.values())) + self.supply_cost(surplus, shortfall)

    def on_grid(self, edges):
        """Shell limits [m] moved to the shell grid, no grade narrower than the narrowest sortable one."""
        grid = max(int(nm(self.shell_step)), 1)
        first = int(np.rint(nm(edges[0]) / grid)) * grid
        widths = np.maximum(np.rint(np.diff(nm(edges)) / grid), np.ceil(nm(self.min_width) / grid - 1e-9)) * grid
        return (first + np.concatenate(([0], np.cumsum(widths)))) * 1e-9

    def shell_scheme(self, edges):
        """A scheme holding only the shell grades with limits ``edges`` [m] (what the supply needs)."""
        grades = {LABELS[k]: [float(nm(edges[k])) / 1e6, float(nm(edges[k + 1])) / 1e6]
                  for k in range(self.shell_grades)}
        e = self.engine
        return from_dict({"name": "shells", "units": "mm",
                          "housing": {"limits": [e.housing_bore.lo * 1e3, e.housing_bore.hi * 1e3]},
                          "journal": {"limits": [e.journal_d.lo * 1e3, e.journal_d.hi * 1e3]},
                          "shell": {"grades": grades}, "pairing": {"all": "A+A"}})

    def proxy_demand(self, edges):
        """Shells per grade if every nominal bearing took the pair whose aims sum nearest its centring wall
        sum (a first guess of the demand the aims of shells made to order are planned for)."""
        aims = 0.5 * (edges[:-1] + edges[1:]) + self.supply.target_offset
        up, lo = allowed_pairs(self.shell_grades, self.mixed)
        ideal = self.samples[0].ideal_wall_sum(0.5 * (self.window[0] + self.window[1]))
        nearest = np.argmin(np.abs(ideal[:, None] - (aims[up] + aims[lo])[None]), axis=1)
        k = self.shell_grades
        return (np.bincount(up[nearest], minlength=k) + np.bincount(lo[nearest], minlength=k) + 1.0) / ideal.size

    def balance(self, shells, demand, normals=None):
        """Planned shells per bearing left over and missing for ``demand`` (grades,) with the shell grades of
        ``shells``: (surplus, shortfall, aim share or None).

        Shells made to order are aimed by the plan for the demand (:meth:`ShellSupply.aim_share`) and land
        in the grades by the supply's spill matrix; one process sorted into grades lands in the shares its
        shells (drawn from ``normals``, default the nominal design sample's) fall into.
        """
        supply = self.supply
        if supply.mode == "to-order":
            aim = supply.aim_share(shells, demand)
            made = self.shells_per_bearing * supply.spill(shells) @ aim
        else:
            aim = None
            normals = self.samples[0].shell_normals if normals is None else normals
            made = self.shells_per_bearing * wall_sums(shells, supply, normals).landing
        return np.maximum(made - demand, 0.0), np.maximum(demand - made, 0.0), aim

    def supply_cost(self, surplus, shortfall):
        """The supply terms of the objective for planned ``surplus`` and ``shortfall`` shells per bearing [-]."""
        return self.weights.surplus * float(np.sum(surplus)) + self.weights.shortfall * float(np.sum(shortfall))

    def tables(self, shells, demand):
        """Cell tables of the shell grades of ``shells`` with aims planned for ``demand``."""
        return cell_tables(self.binned, shells, self.window, mixed=self.mixed, demand=demand)


def draw_samples(engine, changes, *, n_engines, seed, window, key=DESIGN_KEY):
    """The nominal sample and one per scenario of ``changes`` (label -> scenario), all from one random stream
    (``key`` under ``seed``: :func:`~stackup.design.sample.draw_sample`)."""
    return [draw_sample(engine, n_engines=n_engines, seed=seed, window=window, key=key)] + [
        draw_sample(engine, n_engines=n_engines, seed=seed, window=window, scenario=change, label=label, key=key)
        for label, change in changes.items()]


def build_problem(engine, *, window, shell_grades, housing_grades, journal_grades, scenarios, seed, n_engines,
                  sort_share, readout, mixed, weights):
    """The :class:`Problem` of the designer's (validated) options."""
    changes = {label: change for label, change in scenarios.items() if clearance_changes(engine, change)}
    skipped = [label for label in scenarios if label not in changes]
    samples = draw_samples(engine, changes, n_engines=n_engines, seed=seed, window=window)
    readings = [draw_readings(engine, n_engines=READINGS_FACTOR * n_engines, seed=seed, scenario=change)
                for change in [None, *changes.values()]]
    z = special.ndtri(0.5 * (1.0 + sort_share))  # half-width of the sortable grade in reading spreads
    housing_grid = ReadoutGrid.over(engine.housing_bore.lo, engine.housing_bore.hi,
                                    max(readout, engine.housing_bore.gauge.resolution))
    journal_grid = ReadoutGrid.over(engine.journal_d.lo, engine.journal_d.hi,
                                    max(readout, engine.journal_d.gauge.resolution))
    housing = Limits(housing_grades, housing_grid.bins,
                     housing_grid.min_bins(2 * z * engine.housing_bore.gauge.repeatability))
    journal = Limits(journal_grades, journal_grid.bins,
                     journal_grid.min_bins(2 * z * engine.journal_d.gauge.repeatability))
    for field, limits in (("housing_grades", housing), ("journal_grades", journal)):
        if limits.grades * limits.min_bins > limits.bins:
            raise ValueError(f"{field}: {limits.grades} grades do not fit the drawing limits at the narrowest width "
                             f"the gauge can sort; use fewer grades or a smaller sort_share")
    supply = engine.shell_wall
    spread = np.hypot(supply.sigma, supply.gauge.repeatability) if supply.mode == "to-order" \
        else supply.gauge.repeatability
    shell_step = max(readout, supply.gauge.resolution)
    nominal = samples[0]
    ideal = nominal.ideal_wall_sum(0.5 * (window[0] + window[1]))
    design_matrix = np.column_stack([np.ones(ideal.size), nominal.housing_reading, nominal.journal_reading])
    coef = np.linalg.lstsq(design_matrix, ideal, rcond=None)[0]
    return Problem(
        engine=engine, window=window, binned=Binned.of(samples, readings, housing_grid, journal_grid, window),
        skipped=skipped, changes=changes, housing_grid=housing_grid, journal_grid=journal_grid, housing=housing,
        journal=journal,
        shell_grades=shell_grades, mixed=mixed, shell_step=shell_step, min_width=max(2 * z * spread, shell_step),
        ideal=coef, centre=0.5 * float(np.median(ideal)),
        span=float(np.diff(np.quantile(ideal, [1e-3, 1 - 1e-3]))[0]), weights=weights, sort_share=sort_share)
