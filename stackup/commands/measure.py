"""``stackup measure``: a process fitted to measured data (``fit``), the housing calibrated on fitting tests
(``swell``), through :func:`stackup.measure.fit_csv` and :func:`stackup.measure.calibrate_housing`."""

from __future__ import annotations

from ._options import Formatter, refused_in

#: Library parameter names as these commands spell them, for the messages.
OPTIONS = {"limits": "--limits", "gauge_repeatability": "--gauge-repeatability", "units": "--units",
           "out": "--out", "confidence": "--confidence", "resamples": "--resamples"}


def add_parser(subparsers):
    """Add ``measure`` (with ``fit`` and ``swell``) to the ``stackup`` subcommands; return its parser."""
    p = subparsers.add_parser("measure", formatter_class=Formatter,
                              help="fit processes and the housing's stiffness to measured data",
                              description="Take measured data in: fit a process model to SPC readings of one "
                                          "dimension (stackup measure fit), or the housing's equivalent outer "
                                          "diameter to fitting tests (stackup measure swell); each prints the "
                                          "engine file's entry.")
    actions = p.add_subparsers(dest="action", required=True, metavar="ACTION", help="what to fit")
    fit = actions.add_parser("fit", formatter_class=Formatter, help="fit a process to a column of readings",
                             description="Fit normal, skew-normal, two-normal mixture (and, with --sequence, "
                                         "drifting-mean) models to the readings; choose by BIC with an "
                                         "Anderson-Darling test; remove the gauge's repeatability; print Cpk with "
                                         "its interval and the engine file's process entry (and shared, with "
                                         "--group).")
    fit.add_argument("file", metavar="FILE.csv", help="CSV file of readings (a header line; '#' lines are comments)")
    fit.add_argument("--column", required=True, help="column of the readings")
    fit.add_argument("--limits", required=True, type=float, nargs=2, metavar=("LO", "HI"),
                     help="drawing limits, in --units")
    fit.add_argument("--units", default="mm", choices=("mm", "um", "m"), help="units of readings and limits "
                     "(default mm)")
    fit.add_argument("--gauge-repeatability", type=float, metavar="R",
                     help="standard deviation of repeated readings of one part, in --units")
    fit.add_argument("--group", metavar="COLUMN", help="column of the group (block, crankshaft): gives shared")
    fit.add_argument("--sequence", metavar="COLUMN", help="column of the order or time of manufacture: adds the "
                     "drifting-mean (tool-wear) model")
    fit.add_argument("--drop-missing", action="store_true", help="leave out rows with an empty or NaN cell "
                     "(counted and reported) instead of refusing them")
    fit.add_argument("--figure", metavar="FILE.png", help="write the histogram and the normal probability plot")
    fit.add_argument("--confidence", type=float, default=0.95, help="level of the intervals (default 0.95)")
    fit.add_argument("--resamples", type=int, default=1000, help="bootstrap resamples (default 1000)")
    fit.add_argument("--seed", type=int, default=0, help="seed of the bootstrap (default 0)")
    fit.set_defaults(func=run_fit)
    swell = actions.add_parser("swell", formatter_class=Formatter,
                               help="calibrate the housing's outer diameter on fitting tests",
                               description="Fit the housing's equivalent outer diameter (press_fit.housing_outer) "
                                           "to fitting tests through the press fit, by least squares, with its "
                                           "profile-likelihood interval; with --out write a copy of the engine "
                                           "file with the calibrated value.")
    swell.add_argument("file", metavar="FILE.csv", help="CSV file of fitting tests, columns "
                       "housing_bore, shell_upper_wall, shell_lower_wall, shell_upper_crush, shell_lower_crush, "
                       "assembled_bore (m) and temperature (degC)")
    swell.add_argument("--engine", default="iso-example", help="built-in engine name or engine TOML file (default "
                       "iso-example)")
    swell.add_argument("--out", metavar="ENGINE.toml", help="write a copy of the engine file with the value")
    swell.add_argument("--name", help="engine name of the copy (default: the --out file's name)")
    swell.add_argument("--force", action="store_true", help="replace an existing --out FILE")
    swell.add_argument("--confidence", type=float, default=0.95, help="level of the interval (default 0.95)")
    swell.set_defaults(func=run_swell)
    return p


def run_fit(args, state):
    """Fit the process of parsed ``args``; print its summary and the engine file entry."""
    from pathlib import Path

    from ..measure import fit_csv

    folder = Path(args.figure).parent if args.figure else None
    if folder is not None and not folder.is_dir():  # refused before the fit runs, not after it printed
        raise ValueError(f"--figure: folder {str(folder)!r} of {args.figure!r} "
                         f"{'is a file' if folder.exists() else 'does not exist'}; create it or give another path")
    with refused_in(OPTIONS):
        fit = fit_csv(args.file, args.column, limits=args.limits, units=args.units,
                      gauge_repeatability=args.gauge_repeatability, group=args.group, sequence=args.sequence,
                      drop_missing=args.drop_missing, confidence=args.confidence, resamples=args.resamples,
                      seed=args.seed)
    print(fit.summary(args.units))
    print(f"\nengine file entry ([{args.column}] table, units = \"mm\"):")
    print(fit.to_toml("mm"), end="")
    if args.figure:
        fit.figure(args.units, label=args.column).savefig(args.figure, dpi=120)
        print(f"figure: {args.figure}")
    return 0


def run_swell(args, state):
    """Calibrate the housing of parsed ``args`` on its fitting tests; print it; write the engine copy if asked."""
    from pathlib import Path

    from ..measure import calibrate_housing

    if args.out and Path(args.out).exists() and not args.force:  # refused before the fit runs
        raise ValueError(f"--out: {args.out!r} exists; pass --force to replace it, or give another file name")
    with refused_in(OPTIONS, engine=args.engine):
        result = calibrate_housing(args.file, args.engine, confidence=args.confidence)
    print(result.summary())
    if args.out:
        with refused_in(OPTIONS):
            path = result.write_engine(args.out, name=args.name or Path(args.out).stem, force=args.force)
        print(f"engine file: {path}")
    return 0
