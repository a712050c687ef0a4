"""``stackup measure``: a process fitted to measured data (``fit``), the housing calibrated on fitting tests
(``swell``), through :func:`stackup.measure.fit_csv` and :func:`stackup.measure.calibrate_housing`."""

from __future__ import annotations

from ._options import Formatter, refused_in

#: Library parameter names as these commands spell them, for the messages.
OPTIONS = {"limits": "--limits", "gauge_repeatability": "--gauge-repeatability", "units": "--units",
           "out": "--out", "confidence": "--confidence", "resamples": "--resamples"}
#: The engine file's tables a fitted process goes into (``measure fit --out``).
DIMENSIONS = ("housing_bore", "journal_d", "shell_wall", "crush_height")


def _units(parser, what):
    """The one ``--units`` option of both measure commands: the engine file's unit, mm, by default."""
    parser.add_argument("--units", default="mm", choices=("mm", "um", "m"),
                        help=f"units of {what} (default mm, as engine files are written)")


def _engine_copy(parser, what):
    """``--engine``, ``--out``, ``--name`` and ``--force``: the engine file a measured value is written into."""
    parser.add_argument("--engine", default="iso-example", help="built-in engine name or engine TOML file (default "
                        "iso-example)")
    parser.add_argument("--out", metavar="ENGINE.toml", help=f"write a copy of the engine file with {what}")
    parser.add_argument("--name", help="engine name of the copy (default: the --out file's name)")
    parser.add_argument("--force", action="store_true", help="replace an existing --out FILE")


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
                                         "--group); with --out write them into a copy of the engine file.")
    fit.add_argument("file", metavar="FILE.csv", help="CSV file of readings (a header line; '#' lines are comments)")
    fit.add_argument("--column", required=True, help="column of the readings")
    fit.add_argument("--limits", required=True, type=float, nargs=2, metavar=("LO", "HI"),
                     help="drawing limits, in --units")
    _units(fit, "the readings, the limits and the gauge repeatability")
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
    _engine_copy(fit, "the fitted process (and shared) in the --dimension table")
    fit.add_argument("--dimension", choices=DIMENSIONS,
                     help="with --out: the engine file's table the process goes into (default: --column, where it "
                          "names one)")
    fit.set_defaults(func=run_fit)
    swell = actions.add_parser("swell", formatter_class=Formatter,
                               help="calibrate the housing's outer diameter on fitting tests",
                               description="Fit the housing's equivalent outer diameter (press_fit.housing_outer) "
                                           "to fitting tests through the press fit, by least squares, with its "
                                           "profile-likelihood interval; with --out write a copy of the engine "
                                           "file with the calibrated value.")
    swell.add_argument("file", metavar="FILE.csv", help="CSV file of fitting tests, columns "
                       "housing_bore, shell_upper_wall, shell_lower_wall, shell_upper_crush, shell_lower_crush, "
                       "assembled_bore (in --units) and temperature (degC)")
    _units(swell, "the tests' lengths")
    _engine_copy(swell, "the calibrated housing_outer")
    swell.add_argument("--confidence", type=float, default=0.95, help="level of the interval (default 0.95)")
    swell.set_defaults(func=run_swell)
    return p


def run_fit(args, state):
    """Fit the process of parsed ``args``; print its summary and the engine file entry; write the engine copy if
    asked."""
    from pathlib import Path

    from ..measure import fit_csv, write_engine
    from ..measure.engine_file import file_units

    folder = Path(args.figure).parent if args.figure else None
    if folder is not None and not folder.is_dir():  # refused before the fit runs, not after it printed
        raise ValueError(f"--figure: folder {str(folder)!r} of {args.figure!r} "
                         f"{'is a file' if folder.exists() else 'does not exist'}; create it or give another path")
    dimension = args.dimension or (args.column if args.column in DIMENSIONS else None)
    if args.out is not None:
        _refuse_existing(args)
        if dimension is None:
            raise ValueError(f"--dimension: --column {args.column!r} names no table of an engine file; give the "
                             f"table the process goes into ({', '.join(DIMENSIONS)})")
    elif args.dimension is not None or args.name is not None or args.force:
        raise ValueError("--dimension, --name and --force: they say how --out writes the engine file; give --out "
                         "ENGINE.toml too")
    units = file_units(args.engine)
    with refused_in(OPTIONS):
        fit = fit_csv(args.file, args.column, limits=args.limits, units=args.units,
                      gauge_repeatability=args.gauge_repeatability, group=args.group, sequence=args.sequence,
                      drop_missing=args.drop_missing, confidence=args.confidence, resamples=args.resamples,
                      seed=args.seed)
    print(fit.summary(args.units))
    print(f"\nengine file entry ([{dimension or args.column}] table, units = \"{units}\"):")
    print(fit.to_toml(units), end="")
    if args.figure:
        fit.figure(args.units, label=args.column).savefig(args.figure, dpi=120)
        print(f"figure: {args.figure}")
    if args.out is not None:
        from pathlib import Path

        with refused_in(OPTIONS):
            path = write_engine(args.engine, args.out, fit.entries(dimension, units),
                                name=args.name or Path(args.out).stem, force=args.force)
        print(f"engine file: {path}")
    return 0


def _refuse_existing(args):
    """An --out file that exists is refused before anything is fitted (unless --force)."""
    from pathlib import Path

    if args.out and Path(args.out).exists() and not args.force:
        raise ValueError(f"--out: {args.out!r} exists; pass --force to replace it, or give another file name")


def run_swell(args, state):
    """Calibrate the housing of parsed ``args`` on its fitting tests; print it; write the engine copy if asked."""
    from pathlib import Path

    from ..measure import calibrate_housing

    _refuse_existing(args)  # before the fit runs
    with refused_in(OPTIONS, engine=args.engine):
        result = calibrate_housing(args.file, args.engine, units=args.units, confidence=args.confidence)
    print(result.summary())
    if args.out:
        with refused_in(OPTIONS):
            path = result.write_engine(args.out, name=args.name or Path(args.out).stem, force=args.force)
        print(f"engine file: {path}")
    return 0
