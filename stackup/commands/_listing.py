"""The listing ``stackup engines`` and ``stackup schemes`` print: built-in files, and those a user's folders add."""

from __future__ import annotations

import os
from pathlib import Path

from ._options import Formatter


def print_listing(what, variable, found, builtin, describe):
    """Print the built-in files and those a user's folder adds (or replaces), each with a line about it.

    ``what``: "engines" or "schemes"; ``variable``: the environment variable
    naming the user's folders; ``found``: name -> path as the library finds
    them; ``builtin``: the folder of the built-in files; ``describe``: path ->
    one line about the file.
    """
    folders = [p for p in os.environ.get(variable, "").split(os.pathsep) if p]

    def line(name, path, note=""):
        try:
            about = describe(path)
        except (ValueError, OSError) as error:
            about = f"cannot be read: {error}"
        return f"  {name:<20} {about}{note}"

    builtin_names = sorted(p.stem for p in builtin.glob("*.toml"))
    print(f"Built-in {what}:")
    for name in builtin_names:
        shadow = found[name].parent != builtin
        print(line(name, builtin / f"{name}.toml", f" (replaced by {found[name]})" if shadow else ""))
    if not folders:
        print(f"{variable} is not set: put your own {what} (TOML files) in a folder and name it in {variable} "
              f"(several folders separated by {os.pathsep!r}); they are then found by name like the built-in ones.")
        return
    for folder in folders:
        if not os.path.isdir(folder):
            print(f"From {variable}: {folder}: not a folder (ignored)")
            continue
        mine = sorted(Path(folder).glob("*.toml"))
        print(f"From {variable}: {folder}:" + ("" if mine else " (none)"))
        for path in mine:
            name = path.stem
            if not found[name].samefile(path):
                note = f" (replaced by {found[name]})"
            else:
                note = " (replaces the built-in one)" if name in builtin_names else ""
            print(line(name, path, note))


def add_listing_parser(subparsers, what, variable, run):
    """Add ``stackup engines`` or ``stackup schemes`` (``what``) running ``run``; return its parser."""
    p = subparsers.add_parser(what, formatter_class=Formatter, help=f"list the built-in {what} and the user's",
                              description=f"List the built-in {what} and those the folders in the environment "
                              f"variable {variable} add (a user's file of the same name replaces a built-in one). "
                              f"Any {what[:-1]} file also works by its path.")
    p.set_defaults(func=run)
    return p
