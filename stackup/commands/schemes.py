"""``stackup schemes``: the built-in scheme files and the user's; with ``--engine``, ISO 13778's laid on its drawing."""

from __future__ import annotations

import os

from ._listing import add_listing_parser, print_listing


def add_parser(subparsers):
    """Add ``schemes`` to the ``stackup`` subcommands; return its parser."""
    p = add_listing_parser(subparsers, "schemes", "STACKUP_SCHEME_PATH", run)
    p.add_argument("--engine", metavar="ENGINE", help="show ISO 13778's schemes 1-6 laid on this engine's drawing "
                   "(a built-in name or an engine file), as `stackup compare` uses them")
    p.add_argument("--out", metavar="DIR", help="with --engine: write them there as scheme files")
    p.add_argument("--force", action="store_true", help="with --out: replace files of the same names")
    return p


def run(args, state):
    """Print the schemes, each with its stated clearance and shell grades (or the ISO schemes on an engine)."""
    from ..output import OutputRefused
    from ..schemes import builtin_folder, files, load

    if args.engine is not None:
        return _on_engine(args)
    if args.out is not None:
        raise OutputRefused(f"--out {args.out!r} writes the schemes laid on an engine's drawing: give --engine "
                            "NAME too")

    def describe(path):
        scheme = load(path)
        text = scheme.title or scheme.name
        if scheme.stated_clearance:
            lo, hi = scheme.stated_clearance
            text += f"; stated clearance {lo * 1e6:g}-{hi * 1e6:g} um"
        return text + f"; shell grades {', '.join(scheme.shell.labels)}"

    print_listing("schemes", "STACKUP_SCHEME_PATH", files(), builtin_folder(), describe)
    return 0


def _on_engine(args):
    """``stackup schemes --engine NAME [--out DIR]``: ISO 13778's schemes laid on the engine's drawing."""
    from ..engines import load_engine
    from ..output import prepare_file, write_file
    from ..patterns import ISO_SCHEMES, anchor, caveats, iso_schemes
    from ..report.methods import iso_parts

    engine = load_engine(args.engine)
    schemes = iso_schemes(engine)
    found = tuple(caveats(name, engine) for name in ISO_SCHEMES)
    where, _ = iso_parts(found, anchor() if any(c.adapted for c in found) else None)
    print(f"ISO 13778 schemes 1-6 laid on {engine.name}'s drawing (housing bore "
          f"{engine.housing_bore.lo * 1e3:.3f}-{engine.housing_bore.hi * 1e3:.3f} mm, journal "
          f"{engine.journal_d.lo * 1e3:.3f}-{engine.journal_d.hi * 1e3:.3f} mm); `stackup compare --engine "
          f"{args.engine}` uses these:")
    for scheme, said in zip(schemes, found):
        lo, hi = scheme.clearance_limits()
        grades = "/".join(str(len(getattr(scheme, d).labels)) for d in ("housing", "journal", "shell"))
        print(f"  {scheme.name:<12} {scheme.title}; nominal clearance {lo * 1e6:.1f}-{hi * 1e6:.1f} um; "
              f"grades housing/journal/shell {grades}")
        for item in iso_parts((said,), None)[1]:
            print(f"    warning: {item}")
    print(f"Laid on the drawing: {where}." if where else "On the standard's own drawing and window: the standard's "
          "tables, not re-centred.")
    if args.out is None:
        print("Write them as scheme files to read, keep and edit with --out DIR.")
        return 0
    paths = [prepare_file(os.path.join(args.out, f"{scheme.name}-{engine.name}.toml"), force=args.force,
                          option="--out") for scheme in schemes]  # every file checked before one is written
    for scheme, path in zip(schemes, paths):
        write_file(path, scheme.to_toml_text())
        print(f"wrote {path}")
    return 0
