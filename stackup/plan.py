r"""Grade-quantity planning for shells (and graded housings and journals).

For a scheme and the engine's processes, :func:`plan` estimates from a sample
of engines, per grade:

- the expected demand per 1000 engines with its 95 % interval (per-engine
  demands are independent; the bearings of one engine are not, through the
  shared block and crankshaft components, so the interval uses the variance of
  the per-engine demand, not a multinomial per bearing);
- the share of the shell production that falls into the grade when sorted by
  the measured wall (the engine's supply: made to order, with spill into
  neighbouring grades, or one process sorted);
- for ``volume`` engines, the shells made, demanded and the surplus or
  shortfall;
- the safety stock for a production lot of ``lot_engines`` engines at the
  ``service_level``: the lot's demand for a grade is a sum of independent
  per-engine demands, so :math:`SS = z_{SL}\,\sigma_g\sqrt{L}` over the mean
  :math:`L\mu_g` (the order-up-to level is their sum). The tests check the
  service level by simulating lots.

References
----------
.. [1] Silver, E. A., Pyke, D. F., Thomas, D. J., *Inventory and Production
   Management in Supply Chains*, 4th ed., CRC Press, 2017, ch. 6 (safety stock
   for a cycle service level).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr
from scipy import stats

from . import _validate as check
from ._random import lot_generator, seed_sequence
from .assembly import shell_demand_per_engine
from .engines import load_engine
from .parts import draw_lot
from .schemes import load as load_scheme
from .stats import mean_half_width
from .study.pilot import pilot_parts, shell_plan


def plan(scheme, processes="iso-example", *, volume, service_level=0.99, lot_engines=None, sample_engines=20_000,
         seed=0, part="shell"):
    """Quantities per grade for a scheme: shells (demand, production share, surplus, safety stock), or graded parts.

    ``scheme`` may also be a study dataset (:class:`stackup.Study` result):
    then every scheme of it is planned from the study's own engines and shell
    lots (rows indexed by scheme and grade).

    Parameters
    ----------
    scheme : str, path or Scheme
    processes : str, path or Engine
        The engine whose part processes, gauges and shell supply are planned for.
    volume : int
        Engines to build, > 0.
    service_level : float
        Probability in (0, 1) that a lot's demand for a grade is covered.
    lot_engines : int, optional
        Engines per production lot of shells; default the engine's.
    sample_engines : int
        Engines sampled to estimate the demand.
    seed : int
    part : {"shell", "housing", "journal"}
        Shells, or the housing bores or journals the scheme grades: their
        share per grade (read by the gauge) and count per 1000 engines and
        for ``volume`` engines, with 95 % intervals.

    Returns
    -------
    pandas.DataFrame
        One row per grade.
    """
    volume = check.integer("volume", volume, minimum=1)
    service_level = float(check.in_range("service_level", service_level, 0.0, 1.0, lo_open=True, hi_open=True))
    if isinstance(scheme, xr.Dataset):
        return _from_dataset(scheme, volume=volume, service_level=service_level, lot_engines=lot_engines)
    engine = load_engine(processes)
    scheme = load_scheme(scheme)
    lot = engine.shell_wall.lot_engines if lot_engines is None else check.integer("lot_engines", lot_engines, minimum=1)
    n = check.integer("sample_engines", sample_engines, minimum=100)
    check.one_of("part", part, ("shell", "housing", "journal"))
    parts = pilot_parts(engine, seed, n)
    if part != "shell":
        return _graded_parts(scheme, engine, parts, part, volume)
    shells = shell_plan(engine, scheme, parts)
    per_engine = shells.demand_per_engine.astype(float)
    mean = per_engine.mean(axis=0)
    sd = per_engine.std(axis=0, ddof=1)
    half = mean_half_width(per_engine, axis=0)
    supply = engine.shell_wall
    landing = shells.landing  # share of production read into each grade (the rest is scrap)
    aim = shells.aim if shells.aim is not None else np.full(mean.shape, np.nan)
    made = supply.shells_per_lot(volume * engine.main_bearings)
    z = stats.norm.ppf(service_level)
    safety = z * sd * np.sqrt(lot)
    frame = pd.DataFrame({
        "grade": list(scheme.shell.labels),
        "demand_per_1000": 1000 * mean,
        "demand_per_1000_lo": 1000 * (mean - half),
        "demand_per_1000_hi": 1000 * (mean + half),
        "demand_share": mean / mean.sum(),
        "aim_share": aim,
        "production_share": landing,
        "made": made * landing,
        "demanded": volume * mean,
        "surplus": made * landing - volume * mean,
        "lot_demand_mean": lot * mean,
        "safety_stock": safety,
        "order_up_to": lot * mean + safety,
    }).set_index("grade")
    frame.attrs.update({"scheme": scheme.name, "engine": engine.name, "volume": volume, "service_level": service_level,
                        "lot_engines": lot, "sample_engines": n, "seed": seed, "supply": supply.mode,
                        "shells_made": made, "scrap_share": float(1 - landing.sum())})
    return frame


def _from_dataset(ds, *, volume, service_level, lot_engines):
    """Shell plan per scheme and grade from a study's assembled engines and shell lots."""
    lot = int(ds.attrs["lot_engines"]) if lot_engines is None else check.integer("lot_engines", lot_engines, minimum=1)
    z = stats.norm.ppf(service_level)
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        built = np.all(d.status.values == 0, axis=1)
        labels = [g for g, has in zip(d.shell_grade.values, d.grade_in_scheme.values) if has]
        made_total = float(d.shells_made.sum() + d.shells_scrapped)
        for g in labels:
            per_engine = (np.sum(d.shell_upper_grade.values[built] == g, axis=1)
                          + np.sum(d.shell_lower_grade.values[built] == g, axis=1))
            mean, sd = per_engine.mean(), per_engine.std(ddof=1)
            half = mean_half_width(per_engine)
            share = float(d.shells_made.sel(shell_grade=g)) / made_total
            made = made_total / d.sizes["engine"] * volume * share
            rows.append({"scheme": str(name), "grade": str(g), "demand_per_1000": 1000 * mean,
                         "demand_per_1000_lo": 1000 * (mean - half), "demand_per_1000_hi": 1000 * (mean + half),
                         "production_share": share, "made": made, "demanded": volume * mean,
                         "surplus": made - volume * mean, "lot_demand_mean": lot * mean,
                         "safety_stock": z * sd * np.sqrt(lot), "order_up_to": lot * mean + z * sd * np.sqrt(lot)})
    frame = pd.DataFrame(rows).set_index(["scheme", "grade"])
    frame.attrs.update({"volume": volume, "service_level": service_level, "lot_engines": lot,
                        "source": "study dataset", "engines": int(ds.sizes["engine"])})
    return frame


def _graded_parts(scheme, engine, parts, part, volume):
    """Share and counts of housing bores or journals read into each of the scheme's grades."""
    index = scheme.grade_indices(parts.housing_reading, parts.journal_reading)[0 if part == "housing" else 1]
    grades = scheme.housing if part == "housing" else scheme.journal
    if not grades.graded:
        raise ValueError(f"part: scheme {scheme.name} does not grade the {part}")
    per_engine = np.stack([np.sum(index == g, axis=1) for g in range(len(grades.labels))], axis=1).astype(float)
    n, b = index.shape
    mean = per_engine.mean(axis=0)
    half = mean_half_width(per_engine, axis=0)
    frame = pd.DataFrame({
        "grade": list(grades.labels),
        "share": mean / b,
        "per_1000": 1000 * mean,
        "per_1000_lo": 1000 * (mean - half),
        "per_1000_hi": 1000 * (mean + half),
        "for_volume": volume * mean,
    }).set_index("grade")
    frame.attrs.update({"scheme": scheme.name, "engine": engine.name, "volume": volume, "part": part,
                        "ungradable_share": float(np.mean(index < 0))})
    return frame


def simulate_lot_coverage(scheme, processes="iso-example", *, order_up_to, lot_engines, lots=400, seed=1):
    """Share of simulated lots whose demand for each grade is at most ``order_up_to`` (grades,)."""
    engine = load_engine(processes)
    scheme = load_scheme(scheme)
    root = seed_sequence(seed)
    covered = np.zeros(len(scheme.shell.labels))
    for k in range(lots):
        parts, _ = draw_lot(engine, lot_generator(root, k), lot_engines)
        covered += shell_demand_per_engine(scheme, parts).astype(float).sum(axis=0) <= np.asarray(order_up_to)
    return covered / lots


def _preferred_pair_demand(scheme, parts):
    """Bearings per preferred pair code (n_grades**2,), over gradable built bearings."""
    code = scheme.pair_code(*scheme.grade_indices(parts.housing_reading, parts.journal_reading))
    built = ~(parts.block_scrapped | parts.crank_scrapped)[:, None] & (code >= 0)
    return np.bincount(code[built], minlength=len(scheme.shell.labels) ** 2)


def allocate(scheme, pair_demand, supply, *, shortage_cost=10.0):
    """Least-cost use of the scheme's allowed pairs for given demand and shell supply (LP, HiGHS).

    Variables: bearings of each preferred pair served by each allowed option
    (``scheme.option_table``), and surplus and shortfall of each grade.
    Minimises ``sum(surplus) + shortage_cost * sum(shortfall)`` subject to
    every bearing being served and shells used = supply - surplus + shortfall.
    Returns (objective, allocation {(preferred, option): bearings}, surplus (grades,), shortfall (grades,)).
    """
    from scipy.optimize import linprog

    labels = scheme.shell.labels
    n = len(labels)
    options = scheme.option_table
    columns = [(p, k) for p in np.flatnonzero(pair_demand) for k in range(options.shape[1]) if options[p, k, 0] >= 0]
    n_y = len(columns)
    cost = np.concatenate([np.zeros(n_y), np.ones(n), np.full(n, shortage_cost)])
    a_eq, b_eq = [], []
    for p in np.flatnonzero(pair_demand):
        a_eq.append([1.0 if c[0] == p else 0.0 for c in columns] + [0.0] * 2 * n)
        b_eq.append(pair_demand[p])
    for g in range(n):
        row = [float(np.sum(options[p, k] == g)) for p, k in columns]
        row += [1.0 if j == g else 0.0 for j in range(n)] + [-1.0 if j == g else 0.0 for j in range(n)]
        a_eq.append(row)
        b_eq.append(supply[g])
    result = linprog(cost, A_eq=np.array(a_eq), b_eq=np.array(b_eq), bounds=(0, None), method="highs")
    if not result.success:
        raise ValueError(f"allocate: the LP failed ({result.message})")
    y = result.x[:n_y]
    allocation = {(labels[options[p, k, 0]] + "+" + labels[options[p, k, 1]] if k else "preferred",
                   labels[p // n] + "+" + labels[p % n]): v for (p, k), v in zip(columns, y) if v > 1e-9}
    return float(result.fun), allocation, result.x[n_y:n_y + n], result.x[n_y + n:]


def optimise_supply(scheme, processes="iso-example", *, volume, shortage_cost=10.0, sample_engines=20_000, seed=0):
    """Process mean of one shell process sorted into grades, and use of alternatives, that minimise surplus and shortfall.

    The shell process is the engine's sorted process (``shell_wall.process``,
    stated over the scheme's shell range) with its mean moved; shells made are
    two per bearing plus the engine's surplus. For each mean the allocation is
    the LP of :func:`allocate` on expected supply; the mean is found by a
    bounded scalar search over the scheme's shell range.

    Returns a dict: ``mean`` [m], ``objective``, ``centred_objective`` (the
    process centred on the shell range), ``allocation``, ``surplus`` and
    ``shortfall`` per grade.
    """
    from scipy.optimize import minimize_scalar

    engine = load_engine(processes)
    scheme = load_scheme(scheme)
    volume = check.integer("volume", volume, minimum=1)
    check.positive("shortage_cost", shortage_cost)
    parts = pilot_parts(engine, seed, check.integer("sample_engines", sample_engines, minimum=100))
    demand = _preferred_pair_demand(scheme, parts) * volume / parts.housing_bore.shape[0]
    supply_spec = engine.shell_wall
    dim = supply_spec.dimension(scheme)
    made = supply_spec.shells_per_lot(volume * engine.main_bearings)
    lo_bins, hi_bins = scheme.shell.bins()
    spread = np.hypot(dim.process.std, supply_spec.gauge.repeatability)

    def supply(mean):
        return made * (stats.norm.cdf(hi_bins, mean, spread) - stats.norm.cdf(lo_bins, mean, spread))

    def objective(mean):
        return allocate(scheme, demand, supply(mean), shortage_cost=shortage_cost)[0]

    lo, hi = scheme.shell.limits
    best = minimize_scalar(objective, bounds=(lo, hi), method="bounded", options={"xatol": 1e-9})
    value, allocation, surplus, shortfall = allocate(scheme, demand, supply(best.x), shortage_cost=shortage_cost)
    return {"mean": float(best.x), "objective": value, "centred_objective": objective(0.5 * (lo + hi)),
            "allocation": allocation, "surplus": dict(zip(scheme.shell.labels, surplus)),
            "shortfall": dict(zip(scheme.shell.labels, shortfall)), "demand": demand, "supply": supply}
