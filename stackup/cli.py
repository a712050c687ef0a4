"""The ``stackup`` command: thin, it parses arguments and calls what a study script calls."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from . import __version__


def _compare(args):
    from .io import save_comparison
    from .report import clearance_summary, write_report
    from .scenarios import DECLARED
    from .study import ISO_SCHEMES
    from .study.compare import compare

    n = args.n if args.n is not None else (10_000 if args.quick else 100_000)
    t0 = time.perf_counter()
    result = compare(engine=args.engine, schemes=args.schemes or ISO_SCHEMES, n_engines=n, seed=args.seed,
                     scenarios={} if args.no_scenarios else DECLARED)
    elapsed = time.perf_counter() - t0
    out = Path(args.out)
    data = save_comparison(result, out / "compare.nc")
    report = write_report(result.dataset, out, scenarios=result.scenarios, sensitivity=result.sensitivity, tails=result.tails,
                          dataset_file=data.name)
    ds = result.dataset
    summary = clearance_summary(ds)
    print(f"{n:,} engines x {ds.sizes['bearing']} bearings x {ds.sizes['scheme']} schemes in {elapsed:.1f} s")
    for name, row in summary.iterrows():
        print(f"  {name:<14} mean {row.mean_um:6.2f} um  std {row.std_um:5.2f} um  "
              f"outside stated {row.outside_stated_ppm:9.0f} ppm")
    print(f"dataset: {data}\nreport:  {report}")
    return 0


def _plan(args):
    from .plan import plan

    frame = plan(args.scheme, args.engine, volume=args.volume, service_level=args.service_level,
                 lot_engines=args.lot, sample_engines=args.sample, seed=args.seed, part=args.part)
    a = frame.attrs
    if args.part != "shell":
        print(f"scheme {a['scheme']} on {a['engine']}: {args.part} grades for {a['volume']:,} engines "
              f"(ungradable share {a['ungradable_share']:.2e})")
        print(frame.round(4).to_string())
        return 0
    print(f"scheme {a['scheme']} on {a['engine']}: {a['volume']:,} engines, shells made {a['shells_made']:,} "
          f"({a['supply']}), lots of {a['lot_engines']} engines, service level {a['service_level']:.3g}")
    table = frame[["demand_per_1000", "demand_per_1000_lo", "demand_per_1000_hi", "production_share", "made",
                   "demanded", "surplus", "safety_stock", "order_up_to"]].round(1)
    table["production_share"] = frame["production_share"].round(4)
    print(table.to_string())
    print("(per grade: demand per 1000 engines with its 95 % interval; made, demanded and surplus for the volume; "
          "safety stock and order-up-to level per lot)")
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="stackup", description=__doc__)
    parser.add_argument("--version", action="version", version=f"stackup {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    cmp_ = sub.add_parser("compare", help="compare selective-fitting schemes on an engine")
    cmp_.add_argument("--engine", default="iso-example", help="built-in engine name or engine TOML file")
    cmp_.add_argument("--schemes", nargs="+", help="scheme names or files (default: iso13778-1 ... -6)")
    cmp_.add_argument("--n", type=int, help="engines to sample (default 100000; 10000 with --quick)")
    cmp_.add_argument("--seed", type=int, default=0)
    cmp_.add_argument("--out", default="reports/compare", help="output folder for dataset and report")
    cmp_.add_argument("--quick", action="store_true", help="a small, fast run")
    cmp_.add_argument("--no-scenarios", action="store_true", help="skip the robustness scenarios")
    cmp_.set_defaults(func=_compare)
    pln = sub.add_parser("plan", help="shell quantities per grade for a scheme")
    pln.add_argument("--scheme", required=True, help="scheme name or file")
    pln.add_argument("--engine", default="iso-example", help="built-in engine name or engine TOML file")
    pln.add_argument("--volume", type=int, required=True, help="engines to build")
    pln.add_argument("--service-level", type=float, default=0.99)
    pln.add_argument("--lot", type=int, help="engines per production lot (default: the engine's)")
    pln.add_argument("--sample", type=int, default=20_000, help="engines sampled to estimate the demand")
    pln.add_argument("--seed", type=int, default=0)
    pln.add_argument("--part", choices=("shell", "housing", "journal"), default="shell")
    pln.set_defaults(func=_plan)
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except ValueError as err:
        print(f"stackup: error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
