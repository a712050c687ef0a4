"""How many engines the mechanical chain needs for the main job's life B10 and h_min P1 per scheme to ±5 %.

Runs the main job's study (``stackup compare``: ``iso-example``, the six ISO
schemes and the scheme the designer makes for the engine, seed 0, default film
method) with a large mechanical sample and reports, per scheme, the relative
95 % half-width (larger side) of life B10 and of the cycle-minimum film's P1
over the bearings of the first n engines, the statistics of the report's
per-scheme film table (every engine's bearings pooled), against n. Two
intervals:

- the distribution-free order-statistic interval of the report
  (:func:`stackup.stats.quantile_ci`), which takes the pooled bearings as
  independent;
- an engine bootstrap (engines resampled with their bearings): the bearings of
  one engine share its crankshaft, misalignment and loads, and each engine has
  one bearing at each position, so the bearings are neither independent nor
  identically distributed. This is the interval the sample size is read from.

Bearings whose film is not a number (NaN) are left out, as everywhere.

    python studies/mechanics_sample_size.py [--engines 1500] [--no-design]

Writes reports/mechanics_sample_size.md.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from _common import environment, write_report

from stackup.film.cycle import NOT_A_NUMBER
from stackup.stats import quantile_ci
from stackup.study import ISO_SCHEMES, Study
from stackup.study.schema import flag

TARGET = 0.05
#: Label -> (variable, quantile, scale, unit, engine-level): the report's pooled bearing statistics, and the B10 of
#: the engine's life (its weakest bearing's) for comparison.
QUANTITIES = {"life B10": ("life", 0.10, 1 / 3600, "h", False), "h_min P1": ("h_min", 0.01, 1e6, "µm", False),
              "engine life B10": ("life", 0.10, 1 / 3600, "h", True)}
#: The quantities the sample size is chosen for: the report's film table's (the engine's life for comparison).
TARGETED = ("life B10", "h_min P1")
SIZES = (50, 100, 200, 250, 300, 400, 500, 600, 800, 1000, 1200, 1500, 2000, 3000)
BOOTSTRAP = 1000


def pooled(values):
    """Flat, NaN (a film that is not a number) left out."""
    v = np.asarray(values, dtype=float).ravel()
    return v[~np.isnan(v)]


def order_statistic_width(values, q):
    """Larger distance of the order-statistic 95 % interval's ends from the estimate, relative to it."""
    est, lo, hi = quantile_ci(pooled(values), q)
    return max(est - lo, hi - est) / abs(est)


def bootstrap_width(values, q, rng):
    """Larger distance of the engine-bootstrap 95 % percentile interval's ends from the estimate, relative to it.

    ``values`` (engines, bearings); engines are resampled with their bearings.
    """
    est = np.quantile(pooled(values), q)
    picks = rng.integers(0, values.shape[0], size=(BOOTSTRAP, values.shape[0]))
    resampled = values[picks].reshape(BOOTSTRAP, -1)
    qs = np.nanquantile(resampled, q, axis=1) if np.isnan(resampled).any() else np.quantile(resampled, q, axis=1)
    lo, hi = np.quantile(qs, [0.025, 0.975])
    return max(est - lo, hi - est) / abs(est)


def scenario_section(schemes, args):
    """The misalignment scenario of the main job: its mechanical sample and the half-widths it gives."""
    from stackup.scenarios import DECLARED
    from stackup.comparison import SCENARIO_MECHANICS_ENGINES

    label, change = next((k, v) for k, v in DECLARED.items() if "misalignment_scale" in v)
    n = args.scenario_engines
    ds = Study(schemes=schemes, n_engines=n, mechanics_engines=n, seed=args.seed, scenario=change,
               progress=False).run()
    names = [str(s) for s in ds.scheme.values]
    rng = np.random.default_rng(args.seed)
    lines = ["", f"## The scenario '{label}'", "",
             f"The main job runs its misalignment scenario on {SCENARIO_MECHANICS_ENGINES} engines of the "
             "mechanical chain (`stackup.comparison.SCENARIO_MECHANICS_ENGINES`); the ranking reads the change "
             "of the median life under it. Engine-bootstrap half-widths of that scenario's life median and life "
             f"B10 (pooled bearings), {n} engines run:", "",
             "| quantity | engines | " + " | ".join(names) + " |", "|---|---|" + "---|" * len(names)]
    for quantity, q in (("life median", 0.5), ("life B10", 0.1)):
        for m in sorted({SCENARIO_MECHANICS_ENGINES, *(k for k in (100, 200, 400) if k <= n)}):
            widths = [bootstrap_width(ds.life.values[i, :m] / 3600, q, rng) for i in range(len(names))]
            lines.append(f"| {quantity} | {m} | " + " | ".join(f"{100 * w:.1f} %" for w in widths) + " |")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", type=int, default=1500)
    parser.add_argument("--no-design", action="store_true", help="the six ISO schemes only")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--scenario-engines", type=int, default=400,
                        help="engines of the misalignment scenario's mechanical sample (0: skip it)")
    parser.add_argument("--out", default="reports/mechanics_sample_size.md")
    args = parser.parse_args(argv)
    schemes = ISO_SCHEMES
    if not args.no_design:
        from stackup.design import design

        t0 = time.perf_counter()
        schemes = (*ISO_SCHEMES, design("iso-example", seed=args.seed).scheme)
        print(f"designed a scheme in {time.perf_counter() - t0:.0f} s")
    t0 = time.perf_counter()
    ds = Study(schemes=schemes, n_engines=args.engines, mechanics_engines=args.engines, seed=args.seed,
               progress=False).run()
    seconds = time.perf_counter() - t0
    names = [str(s) for s in ds.scheme.values]
    default = Study.__dataclass_fields__["mechanics_engines"].default
    sizes = sorted({n for n in (*SIZES, default) if n <= args.engines})
    at_default = []  # (half-width, scheme, quantity) at the default
    rng = np.random.default_rng(args.seed)
    status = ds.film_status
    lost = int(np.count_nonzero(np.isin(status.values, [flag(status, m) for m in NOT_A_NUMBER])))
    computed = int(np.count_nonzero(status.values != flag(status, "not_computed")))
    lines = ["# Engines the mechanical chain needs: life B10 and h_min P1 per scheme to ±5 %", "",
             f"{environment()}. The main job's study (`iso-example`, {len(names)} schemes: the six ISO ones"
             + ("" if args.no_design else " and the one the designer makes for the engine")
             + f", seed {args.seed}, film method `{ds.attrs['film_method_used']}`) with {args.engines} engines "
             f"through the mechanical chain, in {seconds:.0f} s on this machine. Per scheme and quantity, the "
             "relative 95 % half-width (larger side) over the bearings of the first n engines, pooled as in the "
             f"report's film table; {lost} of the {computed:,} bearings with a film that is not a number (NaN, "
             "`film_status`) left out. Each cell: engine bootstrap (engines resampled with their five bearings, "
             f"{BOOTSTRAP} resamples) / order-statistic interval taking the bearings as independent (the "
             "report's).", ""]
    need = {}
    for label, (name, q, scale, unit, per_engine) in QUANTITIES.items():
        values = ds[name].values * scale  # (schemes, engines, bearings)
        if per_engine:
            values = values.min(axis=-1, keepdims=True)  # NaN where a bearing's film is not a number
        lines += [f"## {label}", "", "| engines | " + " | ".join(names) + " |", "|---|" + "---|" * len(names)]
        for n in sizes:
            row = []
            for i in range(len(names)):
                boot = bootstrap_width(values[i, :n], q, rng)
                iid = order_statistic_width(values[i, :n], q)
                row.append(f"{100 * boot:.1f} / {100 * iid:.1f} %")
                if n == default and label in TARGETED:
                    at_default.append((boot, names[i], label))
                if boot <= TARGET and (label, i) not in need:
                    need[(label, i)] = n
                elif boot > TARGET:
                    need.pop((label, i), None)  # the target must hold from n on
            lines.append(f"| {n} | " + " | ".join(row) + " |")
        estimates = [f"{np.quantile(pooled(values[i]), q):.3g}" for i in range(len(names))]
        lines += ["", f"Estimate at {args.engines} engines [{unit}]: " + ", ".join(estimates) + ".", ""]
    lines += ["## Engines needed for ±5 % (engine bootstrap)", "",
              "The smallest n of the table from which on the half-width stays within 5 %:", "",
              "| quantity | " + " | ".join(names) + " |", "|---|" + "---|" * len(names)]
    for label in QUANTITIES:
        lines.append(f"| {label} | " + " | ".join(str(need.get((label, i), f"> {args.engines}"))
                                                  for i in range(len(names))) + " |")
    worst = max((need.get((label, i), np.inf) for label in TARGETED for i in range(len(names))))
    lines += ["", f"Every scheme's {', '.join(TARGETED)} within ±5 % from {worst:.0f} engines on."
              if np.isfinite(worst) else f"Not every quantity reaches ±5 % within {args.engines} engines."]
    if at_default:
        width, scheme, label = max(at_default)
        lines += ["", f"At the default of {default} engines (`Study.mechanics_engines`, the main job's) the widest "
                  f"half-width is {100 * width:.1f} % ({label}, {scheme})."]
    engine_need = max(need.get(("engine life B10", i), np.inf) for i in range(len(names)))
    lines += ["", f"The engine's life B10 (its weakest bearing) needs {engine_need:.0f} engines for ±5 % in every "
              "scheme." if np.isfinite(engine_need) else
              f"The engine's life B10 does not reach ±5 % in every scheme within {args.engines} engines."]
    if args.scenario_engines:
        lines += scenario_section(schemes, args)
    lines += ["", "Reproduce: `python studies/mechanics_sample_size.py`."]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
