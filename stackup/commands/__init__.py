"""The ``stackup`` subcommands, one module each.

Each module declares its subcommand with ``add_parser(subparsers)``, which
adds it to an ``argparse`` subparsers object and sets the function that runs
it (``run(args, state)``, returning the exit code; ``state`` is the
:class:`~stackup.commands._options.State` a Ctrl-C message reads), and
parses only: what it computes is a call of the library, as a study script
makes it. The modules import the library inside ``run``, so ``stackup``
starts at once. :data:`COMMANDS` lists them in the order ``stackup --help``
shows them; :mod:`stackup.cli` builds its parser from it, so a new
subcommand is one module and one entry here.
"""

from . import compare, design, diff, engines, measure, plan, report, schemes, store

#: The subcommands in the order of ``stackup --help``.
COMMANDS = (compare, report, diff, plan, engines, schemes, design, measure, store)

__all__ = ["COMMANDS"]
