"""``stackup engines``: the built-in engine files and those the user's folders add."""

from __future__ import annotations

from ._listing import add_listing_parser, print_listing


def add_parser(subparsers):
    """Add ``engines`` to the ``stackup`` subcommands; return its parser."""
    return add_listing_parser(subparsers, "engines", "STACKUP_ENGINE_PATH", run)


def run(args, state):
    """Print the engines, each with its title."""
    from ..engines import builtin_folder, engine_locations, load_engine

    def describe(path):
        engine = load_engine(path)
        return engine.title or engine.name

    print_listing("engines", "STACKUP_ENGINE_PATH", engine_locations(), builtin_folder(), describe)
    return 0
