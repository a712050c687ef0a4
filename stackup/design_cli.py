"""The ``stackup design`` subcommand: a scheme designed for an engine, written as a scheme file.

Kept apart from :mod:`stackup.cli` so the command line stays thin: this
module parses the arguments and calls :func:`stackup.design.design`, as a
study script would. ``stackup.cli`` wires it in with::

    from .design_cli import add_parser as add_design_parser
    add_design_parser(sub)
"""

from __future__ import annotations

import sys
import time


def add_parser(subparsers):
    """Add ``design`` to the ``stackup`` subcommands (an ``argparse`` subparsers object)."""
    p = subparsers.add_parser("design", help="design a selective-fitting scheme for an engine",
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


def run(args, state=None):
    """Design the scheme of parsed ``args``, write it, print its explanation."""
    from .design import design
    from .output import prepare_file, write_file
    from .scenarios import DECLARED

    out = prepare_file(args.out, force=args.force, option="--out")  # refused before the design runs
    t0 = time.perf_counter()
    terminal = sys.stdout.isatty()

    def log(line):
        print(f"[{time.perf_counter() - t0:5.1f} s] {line}" if not terminal else line, flush=True)

    window = None if args.window is None else (args.window[0] * 1e-6, args.window[1] * 1e-6)
    result = design(args.engine, window=window, shell_grades=args.grades, housing_grades=args.housing_grades,
                    journal_grades=args.journal_grades, scenarios={} if args.no_scenarios else DECLARED,
                    seed=args.seed, n_engines=args.n, start=args.start, generations=args.generations,
                    name=args.name, log=log)
    write_file(out, result.scheme.to_toml_text())
    print("\n".join(result.scheme.notes))
    print(f"scheme: {out}")
    return 0
