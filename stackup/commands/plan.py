"""``stackup plan``: shells (or graded parts) per grade for a production volume (:func:`stackup.plan.plan`)."""

from __future__ import annotations

import sys

from ._options import Formatter, count, refused_in, share

#: The library's parameter names as this command's options, for its messages.
OPTIONS = {"volume": "--volume", "service_level": "--service-level", "lot_engines": "--lot",
           "sample_engines": "--sample", "seed": "--seed", "part": "--part"}


def add_parser(subparsers):
    """Add ``plan`` to the ``stackup`` subcommands; return its parser."""
    p = subparsers.add_parser("plan", formatter_class=Formatter, help="shells (or graded parts) per grade for a volume",
                              description="How many shells of each grade to make and stock for a production volume "
                              "(whole shells, rounded up where stock must cover demand), or with --part how many "
                              "housing bores or journals of each grade the volume gives. Prints the table with a "
                              "title saying what it answers; --csv writes the same table for a spreadsheet.",
                              epilog="examples:\n  stackup plan --scheme iso13778-5 --volume 10000\n"
                                     "  stackup plan --scheme iso13778-5 --volume 10000 --lot 500 --service-level "
                                     "0.995 --csv shells.csv\n"
                                     "  stackup plan --scheme iso13778-4 --volume 10000 --part journal")
    p.add_argument("--scheme", required=True, help="scheme name (see `stackup schemes`) or scheme TOML file")
    p.add_argument("--engine", default="iso-example",
                   help="engine name (see `stackup engines`) or engine TOML file: its processes, gauges and shell "
                        "supply")
    p.add_argument("--volume", type=count(1, "engines"), required=True, metavar="ENGINES", help="engines to build")
    p.add_argument("--service-level", type=share, metavar="P",
                   help="shells only: share of lots whose demand for a grade the stock per lot covers "
                        "(default: 0.99)")
    p.add_argument("--lot", type=count(1, "engines"), metavar="ENGINES",
                   help="shells only: engines per production lot, at most --volume (default: the engine's lot, or "
                        "the whole volume when it is smaller)")
    p.add_argument("--sample", type=count(100, "engines"), default=20_000, metavar="ENGINES",
                   help="engines sampled to estimate the demand")
    p.add_argument("--seed", type=int, default=0, help="seed of the sampled engines")
    p.add_argument("--part", choices=("shell", "housing", "journal"), default="shell",
                   help="plan shells, or count the housing bores or journals of each grade")
    p.add_argument("--csv", metavar="FILE", help="also write the table as CSV to FILE ('-': only the CSV, to stdout)")
    p.add_argument("--force", action="store_true", help="replace an existing --csv FILE")
    p.set_defaults(func=run)
    return p


def run(args, state):
    """Plan the parts of parsed ``args``; print the table, write it as CSV if asked."""
    from ..output import prepare_file, write_file
    from ..plan import plan, planner_table, planner_text

    if args.force and args.csv in (None, "-"):
        raise ValueError("--force: replaces an existing --csv FILE; without --csv FILE nothing is replaced")
    csv = prepare_file(args.csv, force=args.force) if args.csv not in (None, "-") else None
    state.stage = f"planning {args.part}s"
    if csv is not None:
        state.saved = f"nothing was saved: {csv} {'is as it was' if csv.exists() else 'was not created'}"
    with refused_in(OPTIONS, engine=args.engine):
        frame = plan(args.scheme, args.engine, volume=args.volume, service_level=args.service_level,
                     lot_engines=args.lot, sample_engines=args.sample, seed=args.seed, part=args.part)
    table = planner_table(frame)
    if args.csv == "-":
        sys.stdout.write(table.to_csv())
        return 0
    print(planner_text(table))
    if csv is not None:
        write_file(csv, table.to_csv())
        print(f"\nThe table is in {csv} (CSV, one row per grade).")
    return 0
