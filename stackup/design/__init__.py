r"""Scheme designer: grade limits, shell grades and pairing that suit one engine.

ISO 13778's schemes are generic; :func:`scheme` designs one for a given
engine's processes, gauges, press fit and operating-clearance window.

Decision variables

- housing and journal grade limits, on the read-out grid (``readout``, or the
  gauge's resolution if coarser), each grade at least as wide as the gauge can
  sort (a part at the grade's centre is read into it with probability at
  least ``sort_share``);
- shell grade limits, contiguous, hence the aims of shells made to order
  (the grade centres); each grade at least as wide as the shell process and
  its gauge can sort (a shell aimed at the grade's centre is read into it
  with probability at least ``sort_share``);
- the pairing table: one shell pair per cell, a grade with itself or (with
  ``mixed_pairs``) with the next grade, the intermediate pairs of ISO 13778.

Objective (all on one fixed design sample, common random numbers)

.. math:: J = P_{out} + \lambda \max_s P^s_{out} + w_s\,\text{surplus} + w_o\,\text{shortfall}

:math:`P_{out}`: share of the bearings whose operating clearance (press fit,
housing swell and temperature by :func:`stackup.fit.press_fit` with the
engine's press-fit data) lies outside the window; :math:`P^s_{out}` the same
under each declared scenario that changes the clearance
(:data:`stackup.scenarios.DECLARED`: process mean shifts of one sigma, gauge
repeatability 2 um; the misalignment scenario changes loads and films, not
the clearance); surplus and shortfall: shells per bearing of the planned
shell supply left over and missing (:mod:`stackup.design.pairing`).

Solvers: housing and journal limits by differential evolution
(``scipy.optimize.differential_evolution``) on the read-out grid, polished
limit by limit; shell limits by bounded Nelder-Mead from the best of a few
starts (equal widths; the start scheme's grades); the pairing by a
mixed-integer programme (HiGHS through ``scipy.optimize.milp``). The shells
are integrated out on the sample (:mod:`stackup.design.objective`), so
shares of a few ppm are resolved by a few thousand engines.

References
----------
.. [1] Mease, D., Nair, V. N., Sudjianto, A., "Selective assembly in
   manufacturing: statistical issues and optimal binning strategies",
   Technometrics 46 (2004) 165-175.
.. [2] ISO 13778:2017, Plain bearings - High-precision half bearings -
   Selective fitting.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np
from scipy import special

from .. import __version__
from .. import _validate as check
from ..engines import load_engine
from ..scenarios import DECLARED
from ..schemes import from_dict
from ..schemes import load as load_scheme
from .objective import score
from .pairing import choose_pairs
from .sample import clearance_changes, draw_sample
from .search import Limits, score_limits, score_pairs, search_limits, search_shells, tie_break
from .tables import Binned, ReadoutGrid, allowed_pairs, cell_sums, cell_tables, nm, pair_demand

ISO_SCHEMES = tuple(f"iso13778-{k}" for k in range(1, 7))
#: Labels of designed grades, thinnest shell (smallest bore, journal) first, as ISO 13778 schemes 4 and 5.
LABELS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
#: Rounds of the final search of limits and pairs, each with the aims planned for the best design's demand.
FINAL_ROUNDS = 2
#: Nelder-Mead evaluations per shell grade limit after the differential evolution of the shell limits.
POLISH_PER_LIMIT = 10


@dataclass(frozen=True)
class Design:
    """A designed scheme with what the designer found on its way.

    Attributes
    ----------
    scheme : Scheme
        The designed scheme; its ``notes`` explain the choices (written as comments by ``to_toml``).
    objective : float
        :math:`J` of the designed scheme on the design sample [-].
    outside : dict of str -> float
        Share of bearings outside the window per sample ("nominal" and each scenario) [-].
    start : str
        The ISO scheme the design started from.
    start_objective : float
        Its :math:`J` on the same sample (preferred pairs, planned supply not counted) [-].
    iso : dict of str -> dict of str -> float
        Share outside the window of every ISO 13778 scheme per sample [-].
    mean_clearance : float
        Expected operating clearance of the designed scheme [m]; ``start_mean_clearance`` the start's.
    start_mean_clearance : float
    surplus, shortfall : numpy.ndarray (shell grades,)
        Planned shells per bearing left over and missing [-].
    aim_share : numpy.ndarray (shell grades,) or None
        Share of the shells made aimed at each grade (shells made to order).
    supply_mean : float
        Mean of one shell process sorted into the designed grades that minimises surplus and
        shortfall (:func:`stackup.plan.optimise_supply`) [m].
    supply_mean_objective, supply_centred_objective : float
        Surplus plus weighted shortfall per 10 000 engines at that mean and at the centred mean [shells].
    seconds : float
        Wall time of the design [s].
    evaluations : int
        Candidate sets of housing and journal limits scored.
    """

    scheme: object
    objective: float
    outside: dict
    start: str
    start_objective: float
    iso: dict
    mean_clearance: float
    start_mean_clearance: float
    surplus: np.ndarray
    shortfall: np.ndarray
    aim_share: np.ndarray | None
    supply_mean: float
    supply_mean_objective: float
    supply_centred_objective: float
    seconds: float
    evaluations: int


def scheme(engine="iso-example", **options):
    """A selective-fitting scheme designed for ``engine`` (see :func:`design` for the options)."""
    return design(engine, **options).scheme


def design(engine="iso-example", *, window=None, shell_grades=3, housing_grades=3, journal_grades=3,
           scenarios=DECLARED, seed=0, n_engines=4000, start=None, mixed_pairs=True, scenario_weight=0.1,
           surplus_weight=1e-5, shortfall_weight=1e-4, sort_share=0.5, readout=1e-7, generations=8, name=None,
           log=None):
    """Design a scheme for ``engine`` (module docstring: variables, objective, solvers).

    Parameters
    ----------
    engine : str, path or Engine
    window : (float, float), optional
        Operating-clearance window [m]; default the engine's.
    shell_grades, housing_grades, journal_grades : int
        Grades of each dimension (1: ungraded housing or journal).
    scenarios : dict of str -> dict
        Declared scenarios (:mod:`stackup.scenarios`); those that do not
        change the clearance are left out. Empty for none.
    seed : int
        Seed of the design sample (its own random stream, apart from a
        study's lots and pilot with the same seed).
    n_engines : int
        Engines of the design sample (per scenario, common random numbers).
    start : str, path or Scheme, optional
        Scheme to start from; default the ISO 13778 scheme with the lowest
        objective on the design sample. Its grades seed the search where
        the counts match.
    mixed_pairs : bool
        Allow a grade paired with the next one (upper of one, lower of the next).
    scenario_weight : float
        :math:`\\lambda`, weight of the worst scenario's share outside the window [-].
    surplus_weight, shortfall_weight : float
        Weights of the planned surplus and shortfall, per shell per bearing [-]
        (1e-4: 0.01 shells per bearing cost as much as 1 ppm outside the window).
    sort_share : float
        Smallest share of the parts (shells) at (aimed at) a grade's centre
        that must be read into that grade, in (0, 1): sets each dimension's
        narrowest grade.
    readout : float
        Step of the read-out grid grade limits lie on [m] (the gauge's
        resolution if coarser).
    name : str, optional
        Scheme name; default ``designed-<engine>``.
    log : callable, optional
        Called with one line of text per stage.

    Returns
    -------
    Design
    """
    t0 = time.perf_counter()
    log = log or (lambda line: None)
    engine = load_engine(engine)
    window = check.clearance_window("window", engine.clearance_window if window is None else window)
    k_s = check.integer("shell_grades", shell_grades, minimum=1)
    k_h = check.integer("housing_grades", housing_grades, minimum=1)
    k_j = check.integer("journal_grades", journal_grades, minimum=1)
    for field, k in (("shell_grades", k_s), ("housing_grades", k_h), ("journal_grades", k_j)):
        if k > len(LABELS):
            raise ValueError(f"{field}: {k} is not valid; at most {len(LABELS)} grades")
    n_engines = check.integer("n_engines", n_engines, minimum=100)
    sort_share = float(check.in_range("sort_share", sort_share, 0.0, 1.0, lo_open=True, hi_open=True))
    readout = float(check.positive("readout", readout))
    for field, value in (("scenario_weight", scenario_weight), ("surplus_weight", surplus_weight),
                         ("shortfall_weight", shortfall_weight)):
        check.positive(field, value, allow_zero=True)
    scenarios = dict(scenarios or {})

    log(f"design sample: {n_engines:,} engines, nominal and {len(scenarios)} declared scenarios")
    samples = [draw_sample(engine, n_engines=n_engines, seed=seed, window=window)]
    skipped = []
    for label, change in scenarios.items():
        if clearance_changes(engine, change):
            samples.append(draw_sample(engine, n_engines=n_engines, seed=seed, window=window, scenario=change,
                                       label=label))
        else:
            skipped.append(label)
    labels = [s.label for s in samples]

    def objective_of(shares):
        shares = np.asarray(shares, dtype=float)
        return float(shares[0] + (scenario_weight * shares[1:].max() if shares.size > 1 else 0.0))

    log("ISO 13778 schemes on the design sample")
    iso = {name_: {s.label: score(name_, s, window).outside for s in samples} for name_ in ISO_SCHEMES}
    if start is None:
        start_scheme = load_scheme(min(iso, key=lambda k: objective_of(list(iso[k].values()))))
    else:
        start_scheme = load_scheme(start)
    start_scores = [score(start_scheme, s, window) for s in samples]
    start_objective = objective_of([s.outside for s in start_scores])

    z = special.ndtri(0.5 * (1.0 + sort_share))
    nominal = samples[0].engine
    housing_grid = ReadoutGrid.over(nominal.housing_bore.lo, nominal.housing_bore.hi,
                                    max(readout, nominal.housing_bore.gauge.resolution))
    journal_grid = ReadoutGrid.over(nominal.journal_d.lo, nominal.journal_d.hi,
                                    max(readout, nominal.journal_d.gauge.resolution))
    housing = Limits(k_h, housing_grid.bins, housing_grid.min_bins(2 * z * nominal.housing_bore.gauge.repeatability))
    journal = Limits(k_j, journal_grid.bins, journal_grid.min_bins(2 * z * nominal.journal_d.gauge.repeatability))
    for field, limits in (("housing_grades", housing), ("journal_grades", journal)):
        if limits.grades * limits.min_bins > limits.bins:
            raise ValueError(f"{field}: {limits.grades} grades do not fit the drawing limits at the narrowest "
                             f"width the gauge can sort; use fewer grades or a smaller sort_share")
    supply = nominal.shell_wall
    spread = np.hypot(supply.sigma, supply.gauge.repeatability) if supply.mode == "to-order" \
        else supply.gauge.repeatability
    shell_step = max(readout, supply.gauge.resolution)
    min_width = max(2 * z * spread, shell_step)

    ideal = samples[0].ideal_wall_sum(0.5 * (window[0] + window[1]))
    design_matrix = np.column_stack([np.ones(ideal.size), samples[0].housing_reading, samples[0].journal_reading])
    coef = np.linalg.lstsq(design_matrix, ideal, rcond=None)[0]

    def ideal_at(h, j):
        return coef[0] + coef[1] * h + coef[2] * j

    centre = 0.5 * float(np.median(ideal))  # the wall of one shell that centres the median bearing
    span = float(np.diff(np.quantile(ideal, [1e-3, 1 - 1e-3]))[0])  # wall sums the levels must reach
    levels = 2 * k_s - 1 if mixed_pairs else k_s
    shells_per_bearing = 2.0 * (1.0 + supply.surplus)

    def shell_scheme(edges):
        grades = {LABELS[k]: [float(nm(edges[k])) / 1e6, float(nm(edges[k + 1])) / 1e6] for k in range(k_s)}
        return from_dict({"name": "shells", "units": "mm",
                          "housing": {"limits": [nominal.housing_bore.lo * 1e3, nominal.housing_bore.hi * 1e3]},
                          "journal": {"limits": [nominal.journal_d.lo * 1e3, nominal.journal_d.hi * 1e3]},
                          "shell": {"grades": grades}, "pairing": {"all": "A+A"}})

    def proxy_demand(edges):
        # shells each grade would supply if every bearing took the pair whose mean wall sum is nearest its ideal
        aims = 0.5 * (edges[:-1] + edges[1:]) + supply.target_offset
        up, lo = allowed_pairs(k_s, mixed_pairs)
        nearest = np.argmin(np.abs(ideal[:, None] - (aims[up] + aims[lo])[None]), axis=1)
        return np.bincount(up[nearest], minlength=k_s) + np.bincount(lo[nearest], minlength=k_s) + 1.0

    binned = Binned.of(samples, housing_grid, journal_grid, window)
    state = {"x": None, "evaluations": 0, "cache": {}, "best": np.inf, "demand": None, "design": None}

    def limits_for(tables, *, popsize=5, maxiter=30):
        """Best housing and journal limits on ``tables``, warm-started from the best so far, and their pairs."""
        result = search_limits(tables, housing, journal, housing_grid, journal_grid, ideal_at,
                               scenario_weight=scenario_weight, seed=seed, x0=state["x"], popsize=popsize,
                               maxiter=maxiter)
        state["evaluations"] += result.evaluations
        h, j = result.housing_edges[None], result.journal_edges[None]
        tie = tie_break(tables, housing_grid, journal_grid, h, j, ideal_at)
        pair = score_limits(tables, h, j, scenario_weight=scenario_weight, tie=tie).pair[0]
        return result, pair

    def evaluate(relative):
        """Objective of shell limits ``relative`` to ``centre``.

        Shells made to order are aimed by the plan for the demand of each
        sample (a study plans each scenario from its own pilot), so the
        limits and pairs are searched with the aims planned for the best
        design's demand so far, and the design found is scored with the aims
        planned for the demand it makes itself.
        """
        edges = _on_grid(centre + relative, shell_step, min_width)
        key = tuple(nm(edges))
        if key not in state["cache"]:
            shells = shell_scheme(edges)
            demand = proxy_demand(edges) if state["demand"] is None else state["demand"]
            tables = cell_tables(binned, shells, window, mixed=mixed_pairs, demand=demand)
            result, pair = limits_for(tables)
            own = pair_demand(tables, result.housing_edges, result.journal_edges, pair)
            tables = cell_tables(binned, shells, window, mixed=mixed_pairs, demand=own)
            objective, _ = score_pairs(tables, result.housing_edges, result.journal_edges, pair,
                                       scenario_weight=scenario_weight)
            if objective < state["best"]:
                encoded = [housing.encode(result.housing_edges), journal.encode(result.journal_edges)]
                if all(e is not None for e in encoded):
                    state["x"] = np.concatenate(encoded)
                state["best"], state["demand"], state["design"] = objective, own, (edges, result, pair, tables)
            state["cache"][key] = objective
        return state["cache"][key]

    x_start = _encode_start(start_scheme, housing, journal, housing_grid, journal_grid)
    if x_start is not None:
        state["x"] = x_start
    wide = max(2 * min_width, span / max(levels - 1, 1) * (1 if mixed_pairs else 2))
    starts = [(np.arange(k_s + 1) - 0.5 * k_s) * w for w in np.linspace(min_width, wide, 4)]
    start_edges = _start_shells(start_scheme, k_s, min_width)
    if start_edges is not None:
        starts.append(start_edges - centre)
    log(f"shell grades: differential evolution and Nelder-Mead over {k_s + 1} limits")
    lower = np.array([-0.5 * wide] + [min_width] * k_s)
    upper = np.array([0.5 * wide] + [2 * wide] * k_s)
    relative = search_shells(evaluate, starts, lower=lower, upper=upper, generations=generations,
                             polish=POLISH_PER_LIMIT * (k_s + 1), seed=seed)
    edges = _on_grid(centre + relative, shell_step, min_width)

    log("final limits and pairing (HiGHS)")
    shells = shell_scheme(edges)
    spill = supply.spill(shells) if supply.mode == "to-order" else None
    landing = None if supply.mode == "to-order" else _landing(shells, supply, samples[0])
    demand = proxy_demand(edges) if state["demand"] is None else state["demand"]
    def balance(demand):
        """Planned shells per bearing left over and missing per grade, and the aims, for a nominal demand."""
        if supply.mode == "to-order":
            aim = supply.aim_share(shells, demand)
            made = shells_per_bearing * spill @ aim
        else:
            aim, made = None, shells_per_bearing * landing
        return np.maximum(made - demand, 0.0), np.maximum(demand - made, 0.0), aim

    def candidate(objective, limits, pair, tables, own):
        surplus, shortfall, aim = balance(own[0])
        total = objective + surplus_weight * surplus.sum() + shortfall_weight * shortfall.sum()
        return (total, limits, pair, tables, own, surplus, shortfall, aim)

    best = None
    searched = state["design"]
    if searched is not None and np.array_equal(nm(searched[0]), nm(edges)):
        # the best design of the search, already scored with the aims planned for its own demand
        best = candidate(state["best"], searched[1], searched[2], searched[3], state["demand"])
    for _ in range(FINAL_ROUNDS):  # the aims of shells made to order follow the demand the design makes
        tables = cell_tables(binned, shells, window, mixed=mixed_pairs, demand=demand)
        limits, cheapest = limits_for(tables, popsize=10, maxiter=100)
        h_edges, j_edges = limits.housing_edges[None], limits.journal_edges[None]
        outside = cell_sums(tables.outside, h_edges, j_edges)[:, :, 0] / tables.bearings[:, None, None, None]
        count = cell_sums(tables.count[:1], h_edges, j_edges)[0, 0] / tables.bearings[0]
        tie = tie_break(tables, housing_grid, journal_grid, h_edges, j_edges, ideal_at)[:, 0]
        pairing = choose_pairs(outside, count, tables.pairs, k_s, scenario_weight=scenario_weight,
                               surplus_weight=surplus_weight, shortfall_weight=shortfall_weight,
                               shells_per_bearing=shells_per_bearing, spill=spill, landing=landing, tie=tie)
        for pair in (pairing.pair, cheapest):
            own = pair_demand(tables, limits.housing_edges, limits.journal_edges, pair)
            scored = cell_tables(binned, shells, window, mixed=mixed_pairs, demand=own)
            objective, shares = score_pairs(scored, limits.housing_edges, limits.journal_edges, pair,
                                            scenario_weight=scenario_weight)
            log(f"  candidate J {objective * 1e6:.4g} ppm (outside per sample {np.round(shares * 1e6, 1)} ppm)")
            found = candidate(objective, limits, pair, scored, own)
            if best is None or found[0] < best[0]:
                best = found
        demand = best[4]
    _, limits, pair, tables, _, surplus, shortfall, aim = best
    up, lo = tables.pairs.upper[pair], tables.pairs.lower[pair]

    designed = _build(name or f"designed-{engine.name}", engine, window, housing_grid, journal_grid,
                      limits.housing_edges, limits.journal_edges, edges, up, lo)
    scores = [score(designed, s, window) for s in samples]
    outside = {s.label: sc.outside for s, sc in zip(samples, scores)}
    objective = objective_of(list(outside.values())) + surplus_weight * surplus.sum() \
        + shortfall_weight * shortfall.sum()

    from ..plan import optimise_supply

    log("process mean of a sorted shell supply (stackup.plan.optimise_supply)")
    offer = optimise_supply(designed, engine, volume=10_000, sample_engines=n_engines, seed=seed)
    seconds = time.perf_counter() - t0
    result = Design(
        scheme=designed, objective=objective, outside=outside, start=start_scheme.name,
        start_objective=start_objective, iso=iso, mean_clearance=scores[0].mean_clearance,
        start_mean_clearance=start_scores[0].mean_clearance, surplus=surplus, shortfall=shortfall,
        aim_share=aim, supply_mean=offer["mean"], supply_mean_objective=offer["objective"],
        supply_centred_objective=offer["centred_objective"], seconds=seconds, evaluations=state["evaluations"])
    notes = _notes(result, engine=engine, window=window, start_scheme=start_scheme, chosen=start is None,
                   labels=labels, skipped=skipped,
                   weights=(scenario_weight, surplus_weight, shortfall_weight), n_engines=n_engines, seed=seed,
                   sort_share=sort_share, min_widths=(housing.min_bins, journal.min_bins, min_width),
                   readout=(housing_grid, journal_grid, shell_step))
    return replace(result, scheme=replace(designed, notes=tuple(notes)))


def _on_grid(edges, step, min_width):
    """Shell limits [m] moved to the read-out grid, no grade narrower than ``min_width`` [m]."""
    grid = max(int(nm(step)), 1)
    first = int(np.rint(nm(edges[0]) / grid)) * grid
    widths = np.maximum(np.rint(np.diff(nm(edges)) / grid), np.ceil(nm(min_width) / grid - 1e-9)) * grid
    return (first + np.concatenate(([0], np.cumsum(widths)))) * 1e-9


def _landing(shells, supply, sample):
    from .objective import wall_sums

    return wall_sums(shells, supply, sample.shell_normals).landing


def _encode_start(start, housing, journal, housing_grid, journal_grid):
    """The start scheme's housing and journal limits as a point of the search cube, where the counts match."""
    parts = []
    for grades, limits, grid in ((start.housing, housing, housing_grid), (start.journal, journal, journal_grid)):
        if grades.fine or len(grades.labels) != limits.grades:
            return None
        lo, hi = grades.bins()
        edges = np.append(np.sort(lo), hi.max())
        index = np.clip(np.searchsorted(grid.edges, nm(edges)), 0, grid.bins)
        index[0], index[-1] = 0, grid.bins
        point = limits.encode(index)
        if point is None:
            return None
        parts.append(point)
    return np.concatenate(parts)


def _start_shells(start, k, min_width):
    """The start scheme's shell limits [m] if it has ``k`` contiguous grades no narrower than ``min_width``."""
    if len(start.shell.labels) != k or not start.shell.graded:
        return None
    lo, hi = start.shell.bins()
    edges = np.append(np.sort(lo), hi.max())
    if np.any(np.diff(edges) < min_width - 1e-12):
        return None
    return edges


def _build(name, engine, window, housing_grid, journal_grid, h_edges, j_edges, shell_edges, upper, lower):
    """The designed scheme from grid indices of the limits, shell limits [m] and the pair of each cell."""
    def mm(value_m):
        return float(nm(value_m)) / 1e6

    def dimension(grid, edges, limits):
        if len(edges) == 2:
            return {"limits": [mm(limits[0]), mm(limits[1])]}
        metres = grid.metres(np.asarray(edges))
        return {"grades": {LABELS[k]: [mm(metres[k]), mm(metres[k + 1])] for k in range(len(edges) - 1)}}

    housing = dimension(housing_grid, h_edges, (engine.housing_bore.lo, engine.housing_bore.hi))
    journal = dimension(journal_grid, j_edges, (engine.journal_d.lo, engine.journal_d.hi))
    k_s = len(shell_edges) - 1
    shell = {"grades": {LABELS[k]: [mm(shell_edges[k]), mm(shell_edges[k + 1])] for k in range(k_s)}}
    h_labels = list(housing.get("grades", {"-": None}))
    j_labels = list(journal.get("grades", {"-": None}))
    table = {jl: {hl: f"{LABELS[upper[h, j]]}+{LABELS[lower[h, j]]}" for h, hl in enumerate(h_labels)}
             for j, jl in enumerate(j_labels)}
    k_h, k_j = len(h_edges) - 1, len(j_edges) - 1
    data = {"name": name,
            "title": f"Designed for {engine.name}: {k_h} x {k_j} matrix, {k_s} shell grades",
            "source": (f"stackup {__version__} stackup.design for engine {engine.name!r}, operating-clearance "
                       f"window {window[0] * 1e6:.4g}-{window[1] * 1e6:.4g} um"),
            "units": "mm", "housing": housing, "journal": journal, "shell": shell,
            "pairing": {"table": table}}
    return from_dict(data)


def _describe(grades):
    if grades.fine:
        return f"{len(grades.labels)} classes of {(grades.hi[0] - grades.lo[0]) * 1e6:.3g} um"
    if not grades.graded:
        return "ungraded"
    widths = ", ".join(f"{(b - a) * 1e6:.3g}" for a, b in zip(*grades.bins()))
    return f"{len(grades.labels)} grades ({widths} um wide)"


def _notes(result, *, engine, window, start_scheme, chosen, labels, skipped, weights, n_engines, seed, sort_share,
           min_widths, readout):
    """Lines explaining the design, written as comments at the top of the scheme file."""
    s = result.scheme
    ppm = 1e6
    scenario_weight, surplus_weight, shortfall_weight = weights
    lines = [
        f"Scheme designed by stackup {__version__} (stackup.design) for engine {engine.name!r},",
        f"operating-clearance window {window[0] * ppm:.4g}-{window[1] * ppm:.4g} um (press fit, housing swell and "
        f"temperature by stackup.fit.press_fit with the engine's press-fit data).",
        "",
        "What was optimised: housing and journal grade limits (on the read-out grid), shell grade limits",
        "(hence the aims of shells made to order), and the shell pair of every cell, to minimise",
        f"  J = P_out + {scenario_weight:g} * worst-scenario P_out + {surplus_weight:g} * surplus "
        f"+ {shortfall_weight:g} * shortfall",
        "(P_out: share of bearings outside the window; surplus, shortfall: planned shells per bearing).",
        f"Design sample: {n_engines:,} engines, seed {seed}, common random numbers for every candidate and scenario.",
        f"Scenarios: {', '.join(labels[1:]) or 'none'}"
        + (f" (left out, no effect on the clearance: {', '.join(skipped)})" if skipped else "") + ".",
        "Solvers: differential evolution (housing, journal limits), Nelder-Mead (shell limits),",
        "HiGHS MILP (pairing), all from scipy.",
        f"Narrowest grades: a part (shell) at (aimed at) a grade's centre is read into it with probability "
        f">= {sort_share:g}:",
        f"  housing {min_widths[0] * (readout[0].edges[1] - readout[0].edges[0]) * 1e-3:.3g} um, journal "
        f"{min_widths[1] * (readout[1].edges[1] - readout[1].edges[0]) * 1e-3:.3g} um, shell {min_widths[2] * ppm:.3g} um; "
        f"limits on a {readout[2] * ppm:.3g} um grid.",
        "",
        f"Result on the design sample: P_out {result.outside['nominal'] * ppm:.3g} ppm nominal, "
        + ", ".join(f"{k} {v * ppm:.3g} ppm" for k, v in list(result.outside.items())[1:]) + ";",
        f"  J = {result.objective * ppm:.4g} ppm; planned surplus {result.surplus.sum():.3f} and shortfall "
        f"{result.shortfall.sum():.4f} shells per bearing; mean operating clearance {result.mean_clearance * ppm:.2f} um.",
        f"Started from {start_scheme.name} ("
        + ("the ISO 13778 scheme with the lowest J on the design sample, " if chosen else "")
        + f"J = {result.start_objective * ppm:.4g} ppm with its preferred pairs).",
        "What changed against it:",
        f"  housing: {_describe(start_scheme.housing)} -> {_describe(s.housing)}",
        f"  journal: {_describe(start_scheme.journal)} -> {_describe(s.journal)}",
        f"  shells: {_describe(start_scheme.shell)} -> {_describe(s.shell)}",
        f"  mean operating clearance {result.start_mean_clearance * ppm:.2f} -> {result.mean_clearance * ppm:.2f} um "
        f"(window middle {0.5 * (window[0] + window[1]) * ppm:.4g} um); P_out nominal "
        f"{result.iso.get(start_scheme.name, {}).get('nominal', np.nan) * ppm:.3g} -> {result.outside['nominal'] * ppm:.3g} ppm.",
        "",
        "Shell supply offered with these grades:",
    ]
    if result.aim_share is not None:
        lines.append("  made to order: share of each lot aimed at each grade centre "
                     + ", ".join(f"{lab} {q:.3f}" for lab, q in zip(s.shell.labels, result.aim_share)) + ";")
    lines.append(f"  one process sorted into these grades: centre it at {result.supply_mean * 1e3:.5f} mm "
                 f"(surplus + 10 x shortfall {result.supply_mean_objective:.0f} shells per 10 000 engines, "
                 f"{result.supply_centred_objective:.0f} centred on the grades; stackup.plan.optimise_supply).")
    lines.append(f"Design time {result.seconds:.1f} s, {result.evaluations:,} candidate limit sets scored.")
    return lines
