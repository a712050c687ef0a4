"""``stackup compare``: the main job (:func:`stackup.comparison.run`) with its options, and what it prints."""

from __future__ import annotations

import os
import time

from .._main_job import (COMPARE_ENGINES, COMPARE_MIN_ENGINES, COMPARE_OUT, FILM_CHECK_ENGINES, QUICK_ENGINES,
                         QUICK_OUT)
from ._options import Formatter, Log, count, refused_in, share_ppm, window_option

#: The library's parameter names as this command's options, for its messages.
OPTIONS = {"n_engines": "--n", "schemes": "--schemes", "out": "--out", "engine": "--engine", "seed": "--seed",
           "window": "--window",
           "negligible": "--negligible", "volume": "--volume", "film_check_engines": "--film-check-engines"}


def add_parser(subparsers):
    """Add ``compare`` to the ``stackup`` subcommands; return its parser."""
    p = subparsers.add_parser("compare", formatter_class=Formatter,
                              help="compare selective-fitting schemes on an engine",
                              description="Compare selective-fitting schemes on an engine: a study of sampled "
                              "engines, the declared robustness scenarios and what drives the spread; writes the "
                              "dataset (compare.nc) and the report (report.md, report.html) into the output folder. "
                              "One line per stage is printed as it starts.",
                              epilog="examples:\n  stackup compare --quick\n  stackup compare --schemes "
                                     "iso13778-4 my-scheme.toml --window 45 65 --out runs/a")
    p.add_argument("--engine", default="iso-example", help="engine name (see `stackup engines`) or engine TOML file")
    p.add_argument("--schemes", nargs="+", metavar="SCHEME",
                   help="scheme names (see `stackup schemes`) or scheme TOML files (default: iso13778-1 ... -6)")
    p.add_argument("--n", type=count(COMPARE_MIN_ENGINES, "engines"), metavar="ENGINES",
                   help=f"engines to sample, at least {COMPARE_MIN_ENGINES} (default: {COMPARE_ENGINES}; "
                        f"{QUICK_ENGINES} with --quick)")
    p.add_argument("--seed", type=int, default=0, help="root seed of the random numbers (same seed, same numbers)")
    p.add_argument("--window", type=float, nargs=2, metavar=("LO", "HI"),
                   help="design window of the operating clearance in micrometres, instead of the engine's "
                        "(default: the engine's)")
    p.add_argument("--out", metavar="FOLDER",
                   help=f"output folder for the dataset and the report (default: {COMPARE_OUT}; {QUICK_OUT} "
                        "with --quick)")
    p.add_argument("--quick", action="store_true",
                   help=f"a smaller run: {QUICK_ENGINES} engines, written to {QUICK_OUT} (the designer, tails and "
                        "Sobol stages do not shrink with it: add --no-design to skip the designer)")
    p.add_argument("--no-scenarios", action="store_true",
                   help="skip the robustness scenarios (process and model uncertainty)")
    p.add_argument("--negligible", type=share_ppm, default=1.0, metavar="PPM",
                   help="shares of bearings outside the window less than this apart do not separate schemes; "
                        "cost decides between them (default: 1 ppm)")
    p.add_argument("--volume", type=count(1, "engines"), default=10_000, metavar="ENGINES",
                   help="production volume the report's shell plan is for (default: 10000)")
    p.add_argument("--film-check-engines", type=count(0, "engines"), default=FILM_CHECK_ENGINES, metavar="ENGINES",
                   help="engines per scheme whose films run again with the mass-conserving elrod-coarse tier, "
                        "which corrects the film and life means of the report by control variates (0: none; "
                        f"default: {FILM_CHECK_ENGINES})")
    p.add_argument("--tilt-method", choices=("equilibrium", "coupled", "free"), default="equilibrium",
                   help="the journal's tilt in its bearing: balanced at each bearing against the crankshaft "
                        "and the block at its support, with the tilt's squeeze, the film, alpha and lives read "
                        "over the width (default); 'coupled', the support moments of all bearings balanced "
                        "together over the cycle, each journal's centre moved with its tilt, on an elastic "
                        "layer (several times the chain's cost: "
                        "reports/bench_chain.md, reports/coupled_supports.md); 'free', the crankshaft's slope "
                        "held, the film read at the mid-plane")
    p.add_argument("--processes", action="store_true",
                   help="run the study and its scenarios on one local worker process per core (dask; the same "
                        "numbers, faster on a large run)")
    p.add_argument("--no-design", action="store_true",
                   help="compare only the schemes given, without a scheme designed for the engine and window "
                        "(`stackup design`)")
    p.add_argument("--compact", action="store_true",
                   help="store the per-bearing values to 10 nm and 10 kPa (a dataset about a quarter of the size; "
                        "a study rebuilt from it then differs by up to half that; default: every value as "
                        "computed, so the dataset rebuilds itself identically)")
    p.add_argument("--force", action="store_true",
                   help="replace another run in the output folder (the same run again is always replaced)")
    p.set_defaults(func=run)
    return p


def run(args, state):
    """Run the main job of parsed ``args`` into its folder; print the clearance summary, notes and the verdict."""
    import numpy as np

    from .. import comparison
    from ..engines import load_engine
    from ..facts import Run, clearance_summary
    from ..report.verdict import run_notes
    from ..scenarios import DECLARED
    from ..study import ISO_SCHEMES

    n = args.n if args.n is not None else (QUICK_ENGINES if args.quick else COMPARE_ENGINES)
    out = args.out if args.out is not None else (QUICK_OUT if args.quick else COMPARE_OUT)
    state.saved = f"nothing was saved: {out} {'is as it was' if os.path.isdir(out) else 'was not created'}"
    log = Log(state)
    with refused_in(OPTIONS, engine=args.engine):
        window = window_option(args.window, load_engine(args.engine))  # LO HI in um
        written = comparison.run(out, engine=args.engine, schemes=tuple(args.schemes or ISO_SCHEMES), n_engines=n,
                                 seed=args.seed, window=window, scenarios={} if args.no_scenarios else DECLARED,
                                 uncertainties=None if args.no_scenarios else "declared",
                                 design=None if args.no_design else comparison.DESIGN_DEFAULTS,
                                 negligible=args.negligible, volume=args.volume,
                                 film_check_engines=args.film_check_engines, tilt_method=args.tilt_method,
                                 compact=args.compact, force=args.force,
                                 scheduler="processes" if args.processes else None, log=log)
    state.stage, state.saved = "", f"{out} was written"
    ds = written.comparison.dataset
    print(f"{n:,} engines x {ds.sizes['bearing']} bearings x {ds.sizes['scheme']} schemes in "
          f"{time.perf_counter() - log.start:.1f} s")
    for name, row in clearance_summary(ds).iterrows():
        stated = (f"{row.outside_stated_ppm:9.0f} ppm" if np.isfinite(row.outside_stated_ppm) else
                  "        — (no stated range)")
        print(f"  {name:<20} nominal (no swell) mean {row.mean_um:6.2f} µm  std {row.std_um:5.2f} µm  "
              f"outside stated {stated}")
    for note in run_notes(Run.of(ds)):  # stages that failed on some engines, or did not run: said here too
        print(f"note: {note}")
    print(f"dataset: {written.dataset}\nreport:  {written.report} (and report.html)")
    print(f"verdict: {written.verdict}")
    return 0
