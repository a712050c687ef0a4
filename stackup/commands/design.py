"""``stackup design``: a scheme designed for an engine (:func:`stackup.design.design`), written as a scheme file."""

from __future__ import annotations

import sys
import time

from ._options import Formatter, refused_in, window_option

#: Fewest engines of a design sample (stackup.design.design's n_engines).
MIN_ENGINES = 100


def add_parser(subparsers):
    """Add ``design`` to the ``stackup`` subcommands (an ``argparse`` subparsers object)."""
    p = subparsers.add_parser("design", formatter_class=Formatter,
                              help="design a selective-fitting scheme for an engine",
                              description="Design housing, journal and shell grades and the pairing table that "
                                          "keep the operating clearance in the engine's window; write the scheme "
                                          "file (its comments explain the choices).")
    p.add_argument("--engine", default="iso-example", help="built-in engine name or engine TOML file")
    p.add_argument("--grades", type=int, default=4, help="shell grades (default 4)")
    p.add_argument("--housing-grades", type=int, default=3, help="housing bore grades (1: ungraded; default 3)")
    p.add_argument("--journal-grades", type=int, default=3, help="journal grades (1: ungraded; default 3)")
    p.add_argument("--window", type=float, nargs=2, metavar=("LO", "HI"),
                   help="operating-clearance window in um (default: the engine's)")
    p.add_argument("--start", help="scheme to start from (default: the best ISO 13778 scheme on the design sample)")
    p.add_argument("--n", type=int, default=4000, help="engines of the design sample (default 4000)")
    p.add_argument("--seed", type=int, default=0, help="root seed of the design sample (default 0)")
    p.add_argument("--generations", type=int, default=8,
                   help="generations of the differential evolution of the shell limits (default 8; 0 is quicker)")
    p.add_argument("--no-scenarios", action="store_true", help="leave the declared scenarios out of the objective")
    p.add_argument("--name", help="scheme name (default designed-<engine>)")
    p.add_argument("--out", required=True, help="scheme file to write (TOML)")
    p.add_argument("--force", action="store_true", help="replace an existing --out FILE")
    p.set_defaults(func=run)
    return p


#: The library's parameter names as the options that set them, for messages in the command's words.
OPTIONS = {"shell_grades": "--grades", "housing_grades": "--housing-grades", "journal_grades": "--journal-grades",
           "n_engines": "--n", "seed": "--seed", "generations": "--generations", "start": "--start",
           "engine": "--engine", "name": "--name"}


def checked(args):
    """The options of parsed ``args`` checked in the command's words (``ValueError`` naming the option and
    what is valid); returns the window in m or None."""
    from ..design.problem import LABELS

    for option, value in (("--grades", args.grades), ("--housing-grades", args.housing_grades),
                          ("--journal-grades", args.journal_grades)):
        if not 1 <= value <= len(LABELS):
            raise ValueError(f"{option}: {value} is not valid; give a number of grades from 1 to {len(LABELS)}"
                             + (" (1: ungraded)" if option != "--grades" else ""))
    if args.n < MIN_ENGINES:
        raise ValueError(f"--n: {args.n} is not valid; the design sample needs at least {MIN_ENGINES} engines")
    for option, value in (("--seed", args.seed), ("--generations", args.generations)):
        if value < 0:
            raise ValueError(f"{option}: {value} is not valid; give a whole number >= 0")
    if args.window is None:
        return None
    from ..engines import load_engine

    return window_option(args.window, load_engine(args.engine))


def run(args, state):
    """Design the scheme of parsed ``args``, write it, print its explanation."""
    from ..design import design
    from ..output import prepare_file, write_file
    from ..scenarios import DECLARED

    window = checked(args)
    out = prepare_file(args.out, force=args.force, option="--out")  # refused before the design runs
    t0 = time.perf_counter()
    terminal = sys.stdout.isatty()

    def log(line):
        print(f"[{time.perf_counter() - t0:5.1f} s] {line}" if not terminal else line, flush=True)

    with refused_in(OPTIONS, engine=args.engine):
        result = design(args.engine, window=window, shell_grades=args.grades, housing_grades=args.housing_grades,
                        journal_grades=args.journal_grades, scenarios={} if args.no_scenarios else DECLARED,
                        seed=args.seed, n_engines=args.n, start=args.start, generations=args.generations,
                        name=args.name, log=log)
    write_file(out, result.scheme.to_toml_text())
    print("\n".join(result.scheme.notes))
    check = result.check
    print(f"share outside the window, nominal: {result.outside['nominal'] * 1e6:.3g} ppm on the design sample, "
          f"{check.outside['nominal'] * 1e6:.3g} [{check.interval['nominal'][0] * 1e6:.3g}, "
          f"{check.interval['nominal'][1] * 1e6:.3g}] ppm on the independent check sample")
    print(f"scheme: {out}")
    return 0
