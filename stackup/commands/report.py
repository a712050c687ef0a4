"""``stackup report``: the report of a saved comparison, written again from its dataset alone."""

from __future__ import annotations

from pathlib import Path

from ._options import Formatter, count, refused_in, share_ppm

#: The library's parameter names as this command's options, for its messages.
OPTIONS = {"negligible": "--negligible", "volume": "--volume", "out": "--out"}


def add_parser(subparsers):
    """Add ``report`` to the ``stackup`` subcommands; return its parser."""
    p = subparsers.add_parser("report", formatter_class=Formatter, help="write the report of a saved comparison again",
                              description="Write the report (report.md, report.html and its figures) from a dataset "
                              "`stackup compare` saved, and from nothing else: after an update of stackup's report, "
                              "or to look at a dataset someone sent.",
                              epilog="examples:\n  stackup report reports/compare/compare.nc\n"
                                     "  stackup report reports/compare/compare.nc --csv")
    p.add_argument("dataset", metavar="DATASET", help="compare.nc written by `stackup compare`")
    p.add_argument("--out", metavar="FOLDER", help="folder for the report (default: the dataset's folder)")
    p.add_argument("--negligible", type=share_ppm, metavar="PPM",
                   help="shares outside the window less than this apart do not separate schemes (default: the "
                        "comparison's)")
    p.add_argument("--volume", type=count(1, "engines"), default=10_000, metavar="ENGINES",
                   help="production volume the shell plan is for (default: 10000)")
    p.add_argument("--csv", action="store_true",
                   help="also write the ranking, film and life tables as CSV files beside the report (ranking.csv, "
                        "film_life.csv, film_life_per_bearing.csv; units in the column names)")
    p.set_defaults(func=run)
    return p


def run(args, state):
    """Write the report of the dataset of parsed ``args`` into its folder (staged, then moved into place)."""
    state.stage = "reading the dataset"
    state.saved = f"nothing was saved: {args.out or Path(args.dataset).parent} is as it was"
    from ..io import open_comparison
    from ..output import stage_report
    from ..report import write_report

    path = Path(args.dataset)
    if not path.is_file():
        raise ValueError(f"dataset: {str(path)!r} is not a file; give the compare.nc `stackup compare` wrote")
    try:
        saved = open_comparison(path)
    except (OSError, KeyError) as error:
        raise ValueError(f"dataset: {str(path)!r} is not a comparison `stackup compare` saved ({error})") from None
    if "study" not in saved.dataset.attrs:
        raise ValueError(f"dataset: {str(path)!r} is not a comparison `stackup compare` saved (no study attribute)")
    out = Path(args.out) if args.out else path.parent
    existed = out.is_dir()
    staged = stage_report(out)
    state.stage = "writing the report"
    state.saved = f"nothing was saved: {out}{' is as it was' if existed else ' holds no report'}"
    same = out.resolve() == path.parent.resolve()
    try:
        with refused_in(OPTIONS):
            write_report(saved.dataset, staged.staging, scenarios=saved.scenarios, sensitivity=saved.sensitivity,
                         tails=saved.tails, dataset_file=path.name if same else str(path.resolve()),
                         negligible=args.negligible, volume=args.volume, tables=args.csv)
        staged.commit()
    except BaseException:
        staged.discard()
        raise
    state.stage, state.saved = "", f"{out / 'report.md'} was written"
    print(f"report:  {out / 'report.md'} (and report.html)")
    if args.csv:
        from ..report.spreadsheets import FILES

        print(f"tables:  {', '.join(str(out / name) for name in FILES)} (CSV, units in the column names)")
    return 0
