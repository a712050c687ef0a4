"""The ``stackup`` command: a thin face over the subcommands of :mod:`stackup.commands`.

Each subcommand parses its options and calls what a study script calls
(:func:`stackup.comparison.run`, :func:`stackup.plan.plan`,
:func:`stackup.design.design`, ...). Every output location is checked
before anything is computed, and written whole or not at all
(:mod:`stackup.output`). Exit codes: 0 done, 1 a store check found damage,
2 refused (bad input or output location), 130 interrupted (Ctrl-C), 141 the
reader of its output stopped reading (``stackup plan | head``), as a shell
reports a tool ended by SIGPIPE.
"""

from __future__ import annotations

import argparse
import os
import sys

from ._interrupt import held_during_imports
from ._version import __version__
from .commands import COMMANDS
from .commands._options import EXIT_INTERRUPTED, EXIT_REFUSED, Formatter, State

#: Exit code when the output's reader closed the pipe: 128 + SIGPIPE, what a shell reports for a tool it ended.
EXIT_PIPE_CLOSED = 141


def parser():
    """The ``stackup`` argument parser."""
    top = argparse.ArgumentParser(prog="stackup", formatter_class=Formatter, description=(
        "Monte Carlo tolerance stack-up and ISO 13778 selective assembly of engine main bearings."),
        epilog="Run `stackup COMMAND --help` for a command's options.")
    top.add_argument("--version", action="version", version=f"stackup {__version__}")
    sub = top.add_subparsers(dest="command", required=True, metavar="COMMAND", help="what to do")
    for command in COMMANDS:
        command.add_parser(sub)
    return top


def main(argv=None):
    """Run the command; return its exit code (the console script exits with it)."""
    state = State()
    try:
        with held_during_imports():
            try:
                args = parser().parse_args(argv)
            except SystemExit as done:  # --help, --version, or a usage error argparse has already printed
                return done.code
            code = args.func(args, state)
            sys.stdout.flush()  # a pipe closed by its reader is met here, inside the handlers, not at exit
            return code
    except BrokenPipeError:  # `stackup plan | head`: the reader had what it wanted
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # Python's own flush at exit writes nowhere
        return EXIT_PIPE_CLOSED
    except KeyboardInterrupt:
        print(state.interrupted(), file=sys.stderr)
        return EXIT_INTERRUPTED
    except SystemError as error:
        if not _interrupt(error):
            raise
        print(state.interrupted(), file=sys.stderr)
        return EXIT_INTERRUPTED
    except ValueError as error:  # bad input, a refused output location, a damaged store: said, not a traceback
        print(f"stackup: error: {error}", file=sys.stderr)
        return EXIT_REFUSED
    except MemoryError:  # what --n refuses up front; a machine short of free memory can still end here
        where = f" during {state.stage}" if state.stage else ""
        print(f"stackup: error: out of memory{where}; {state.saved}; run fewer engines (--n) or close other "
              "programs", file=sys.stderr)
        return EXIT_REFUSED


def _interrupt(error):
    """Whether ``error`` is a Ctrl-C in disguise.

    A Ctrl-C that arrives while a numba kernel runs raises KeyboardInterrupt
    inside the compiled call, which then returns with the exception set:
    Python turns that into ``SystemError: CPUDispatcher(...) returned a result
    with an exception set`` whose context is the KeyboardInterrupt.
    """
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, KeyboardInterrupt):
            return True
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return False


if __name__ == "__main__":
    sys.exit(main())
