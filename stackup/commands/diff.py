"""``stackup diff``: what changed between two saved comparisons (:func:`stackup.difference.between`)."""

from __future__ import annotations

from ._options import Formatter


def add_parser(subparsers):
    """Add ``diff`` to the ``stackup`` subcommands; return its parser."""
    p = subparsers.add_parser("diff", formatter_class=Formatter, help="what changed between two saved comparisons",
                              description="Compare two runs `stackup compare` saved, from their datasets alone: "
                              "the verdict of each, per scheme the share outside the window and the lives with "
                              "their 95 % intervals (and whether the intervals are apart), and every input that "
                              "differs (study parameters, each key of the engine and scheme files as the runs "
                              "stored them, scenarios, version).",
                              epilog="example:\n  stackup diff runs/before runs/after")
    p.add_argument("run_a", metavar="RUN_A", help="a folder `stackup compare` wrote, or its compare.nc")
    p.add_argument("run_b", metavar="RUN_B", help="the run to compare it with")
    p.set_defaults(func=run)
    return p


def run(args, state):
    """Print what differs between the runs of parsed ``args``."""
    from ..difference import between, lines

    state.stage, state.saved = "reading the runs", "nothing is written"
    print("\n".join(lines(between(args.run_a, args.run_b))))
    return 0
