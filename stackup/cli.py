"""The ``stackup`` command: thin, it parses arguments and calls what a study script calls.

Every output location is checked before anything is computed, and written
whole or not at all (:mod:`stackup.output`). Exit codes: 0 done, 1 a store
check found damage, 2 refused (bad input or output location), 130
interrupted (Ctrl-C).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

from ._interrupt import held_during_imports
from ._version import __version__
from .design_cli import window_option

#: Engines of ``stackup compare``, of ``stackup compare --quick`` and the fewest it runs: the report's 95 %
#: intervals, the plan's safety stock and the sensitivity regression need about a hundred engines.
COMPARE_ENGINES, QUICK_ENGINES, COMPARE_MIN_ENGINES = 100_000, 10_000, 100
#: Engines per scheme whose films ``stackup compare`` checks with the mass-conserving tier (control variates).
FILM_CHECK_ENGINES = 5
#: Output folders of ``stackup compare`` and ``stackup compare --quick`` (relative to the working folder).
COMPARE_OUT, QUICK_OUT = "reports/compare", "reports/compare-quick"
EXIT_DAMAGED, EXIT_REFUSED, EXIT_INTERRUPTED = 1, 2, 130
#: Largest share of a pilot sample's bearings a scheme may leave ungraded in the main job: the share of missing
#: samples its Sobol stage accepts (stackup.sensitivity.sobol_indices, max_missing).
UNGRADED_LIMIT = 0.01
#: Copies of a comparison's per-engine data in memory at once: the study, then the saved dataset the report reads.
COPIES_IN_MEMORY = 2
#: Library parameter names as the command line spells them, for the messages.
OPTIONS = {"n_engines": "--n", "volume": "--volume", "service_level": "--service-level", "lot_engines": "--lot",
           "sample_engines": "--sample", "seed": "--seed", "part": "--part", "window": "--window"}


class _State:
    """The stage under way and what a Ctrl-C now leaves behind, in words (each command keeps them current)."""

    stage = ""
    saved = "nothing was saved"

    def interrupted(self):
        return f"stackup: interrupted{f' during {self.stage}' if self.stage else ''}; {self.saved}"


class _Log:
    """One plain line per stage on stdout, with the time since the start (for logs and terminals alike)."""

    def __init__(self, state):
        self.start, self.state = time.perf_counter(), state

    def __call__(self, line):
        self.state.stage = line.split(":")[0]
        print(f"[{time.perf_counter() - self.start:7.1f} s] {line}", flush=True)


def _compare(args, state):
    import numpy as np

    import stackup

    from .facts import Run, clearance_summary
    from .io import open_comparison, save_comparison
    from .output import prepare_folder, run_identity
    from .report import write_report
    from .report.verdict import run_notes
    from .scenarios import DECLARED
    from .study import ISO_SCHEMES

    n = args.n if args.n is not None else (QUICK_ENGINES if args.quick else COMPARE_ENGINES)
    out = args.out if args.out is not None else (QUICK_OUT if args.quick else COMPARE_OUT)
    schemes = tuple(args.schemes or ISO_SCHEMES)
    scenarios = {} if args.no_scenarios else DECLARED
    design = None if args.no_design else {}
    # what the run cannot do is said before any folder is touched: bad files, a window in mm, too many engines
    engine, window = _checked_inputs(args, schemes, n, design)
    identity = run_identity(engine=args.engine, schemes=schemes, n_engines=n, seed=args.seed, window=window,
                            scenarios=scenarios, design=design is not None, tilt_method=args.tilt_method)
    existed = os.path.isdir(out)
    staged = prepare_folder(out, identity=identity, force=args.force)
    state.saved = f"nothing was saved: {out} {'is as it was' if existed else 'was not created'}"
    log = _Log(state)
    try:
        result = stackup.compare(engine=args.engine, schemes=schemes, n_engines=n, seed=args.seed,
                                 scenarios=scenarios, uncertainties=None if args.no_scenarios else "declared",
                                 negligible=args.negligible, design=design, log=log, window=window,
                                 scheduler="processes" if args.processes else None,
                                 film_check_engines=args.film_check_engines, tilt_method=args.tilt_method)
        log(f"saving the dataset: {os.path.join(out, 'compare.nc')}")
        data = save_comparison(result, staged.staging / "compare.nc", compact=args.compact)
        log(f"writing the report: {os.path.join(out, 'report.md')} and report.html")
        saved = open_comparison(data)  # the report reads what was saved, nothing else
        write_report(saved.dataset, staged.staging, scenarios=saved.scenarios, sensitivity=saved.sensitivity,
                     tails=saved.tails, dataset_file=data.name, volume=args.volume)
        folder = staged.commit()
    except BaseException:
        staged.discard()
        raise
    state.stage, state.saved = "", f"{out} was written"
    ds = saved.dataset
    print(f"{n:,} engines x {ds.sizes['bearing']} bearings x {ds.sizes['scheme']} schemes in "
          f"{time.perf_counter() - log.start:.1f} s")
    for name, row in clearance_summary(ds).iterrows():
        stated = (f"{row.outside_stated_ppm:9.0f} ppm" if np.isfinite(row.outside_stated_ppm) else
                  "        — (no stated range)")
        print(f"  {name:<20} mean {row.mean_um:6.2f} µm  std {row.std_um:5.2f} µm  outside stated {stated}")
    for note in run_notes(Run.of(ds)):  # stages that failed on some engines, or did not run: said here too
        print(f"note: {note}")
    print(f"dataset: {folder / 'compare.nc'}\nreport:  {folder / 'report.md'} (and report.html)")
    print(f"verdict: {_verdict_line(folder / 'report.md')}")
    return 0


def _checked_inputs(args, schemes, n, design):
    """(engine, window in m) of a comparison, after the checks that need no folder (a ValueError says why not).

    The engine and scheme files are read; the window is checked against the
    engine's journal (a window in mm is refused, naming it); the schemes are
    graded on the study's pilot sample (a scheme that leaves too many parts
    ungraded is refused naming it, before the study, not after); the engines
    are checked against the machine's memory.
    """
    from .engines import load_engine
    from .schemes import load as load_scheme

    engine = load_engine(args.engine)
    for scheme in schemes:
        load_scheme(scheme)
    window = window_option(args.window, engine)
    _check_grading(args.engine, schemes, args.seed)
    _check_memory(n, engine, len(schemes) + (design is not None))
    return engine, window


def _verdict_line(report):
    """The report's first verdict paragraph (which scheme to use and why), without its Markdown emphasis."""
    text = report.read_text(encoding="utf-8")
    block = text.split("<!-- verdict -->", 1)[-1].split("<!-- /verdict -->", 1)[0]
    first = next((line for line in block.splitlines() if line.strip()), "")
    return first.replace("**", "").replace("`", "")


def _report(args, state):
    state.stage = "reading the dataset"
    state.saved = f"nothing was saved: {args.out or Path(args.dataset).parent} is as it was"
    from .io import open_comparison
    from .output import stage_report
    from .report import write_report

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
        write_report(saved.dataset, staged.staging, scenarios=saved.scenarios, sensitivity=saved.sensitivity,
                     tails=saved.tails, dataset_file=path.name if same else str(path.resolve()),
                     negligible=args.negligible, volume=args.volume)
        staged.commit()
    except BaseException:
        staged.discard()
        raise
    state.stage, state.saved = "", f"{out / 'report.md'} was written"
    print(f"report:  {out / 'report.md'} (and report.html)")
    return 0


def _check_grading(engine, schemes, seed):
    """Refuse a scheme that leaves more of the study's pilot sample ungraded than the main job can use.

    The study's grading stage would mark those bearings not graded, and the
    Sobol stage at the end of the main job refuses more than
    :data:`UNGRADED_LIMIT` of its samples missing: said now, naming the
    scheme and the readings its grades miss.
    """
    from .study import Study
    from .study.inputs import input_files, load_inputs
    from .study.pilot import grading, pilot_parts

    labels = [str(s) for s in schemes]
    loaded_engine, loaded = load_inputs(input_files(engine, labels), labels)  # the schemes as the study lays them
    pilot = pilot_parts(loaded_engine, seed, Study.pilot_engines)
    for label, scheme in zip(labels, loaded):
        graded = grading(scheme, pilot)
        if graded.ungraded > UNGRADED_LIMIT:
            raise ValueError(f"--schemes: scheme {scheme.name}{f' ({label})' if label != scheme.name else ''} "
                             f"leaves {100 * graded.ungraded:.2g} % of {loaded_engine.name}'s bearings with parts "
                             f"inside the drawing limits ungraded: {graded.where(scheme, loaded_engine)}, in the "
                             f"study's pilot sample of {Study.pilot_engines:,} engines; the main job needs at most "
                             f"{100 * UNGRADED_LIMIT:g} %: widen the scheme's grades to the engine's drawing limits")


def _check_memory(n, engine, schemes):
    """Refuse a comparison whose engines cannot fit in this machine's memory, with what it needs and the way out."""
    per_engine = memory_per_engine(engine.main_bearings, schemes)
    need = COPIES_IN_MEMORY * per_engine * n
    have = _physical_memory()
    if have is None or need <= have:
        return
    most = int(have / (COPIES_IN_MEMORY * per_engine))
    raise ValueError(f"--n: {n:,} engines would need about {_bytes(need)} of memory ({_bytes(per_engine)} per engine "
                     f"with {schemes} scheme{'s' if schemes > 1 else ''}, kept twice: the study and the saved "
                     f"dataset the report reads), and this machine has {_bytes(have)}; give --n at most "
                     f"{most:,}, or run the study in Python with Study(..., keep=\"summaries\") (streaming summaries, "
                     "memory that does not grow with the engines) or store=\"runs/big.zarr\" (every engine on disk): "
                     "README, \"Running a study on several processes or a dask cluster\"")


def memory_per_engine(bearings, schemes):
    """Bytes one engine takes in a study that keeps every engine (its per-engine variables), for ``schemes``."""
    import numpy as np

    from .study.schema import PER_ENGINE

    sizes = {"scheme": schemes, "bearing": bearings, "axis": 2, "engine": 1}
    return sum(int(np.prod([sizes[d] for d in var.dims])) * np.dtype(var.dtype).itemsize
               for var in PER_ENGINE.values())


def _physical_memory():
    """This machine's memory [bytes], or None where the system does not say."""
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):
        return None


def _bytes(count):
    for unit, size in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if count >= size:
            return f"{count / size:.3g} {unit}"
    return f"{count:.0f} B"


def _plan(args, state):
    from .output import prepare_file, write_file
    from .plan import plan, planner_table, planner_text

    if args.force and args.csv in (None, "-"):
        raise ValueError("--force: replaces an existing --csv FILE; without --csv FILE nothing is replaced")
    csv = prepare_file(args.csv, force=args.force) if args.csv not in (None, "-") else None
    state.stage = f"planning {args.part}s"
    if csv is not None:
        state.saved = f"nothing was saved: {csv} {'is as it was' if csv.exists() else 'was not created'}"
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


def _engines(args, state):
    from .engines import _builtin_dir, engine_locations, load_engine

    def describe(path):
        engine = load_engine(path)
        return engine.title or engine.name

    _listing("engines", "STACKUP_ENGINE_PATH", engine_locations(), _builtin_dir(), describe)
    return 0


def _schemes(args, state):
    from .output import OutputRefused
    from .schemes import _builtin_dir, files, load

    if args.engine is not None:
        return _engine_schemes(args)
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

    _listing("schemes", "STACKUP_SCHEME_PATH", files(), _builtin_dir(), describe)
    return 0


def _engine_schemes(args):
    """``stackup schemes --engine NAME [--out DIR]``: ISO 13778's schemes laid on the engine's drawing."""
    from .engines import load_engine
    from .output import prepare_file, write_file
    from .patterns import iso_schemes

    engine = load_engine(args.engine)
    schemes = iso_schemes(engine)
    print(f"ISO 13778 schemes 1-6 laid on {engine.name}'s drawing (housing bore "
          f"{engine.housing_bore.lo * 1e3:.3f}-{engine.housing_bore.hi * 1e3:.3f} mm, journal "
          f"{engine.journal_d.lo * 1e3:.3f}-{engine.journal_d.hi * 1e3:.3f} mm); `stackup compare --engine "
          f"{args.engine}` uses these:")
    for scheme in schemes:
        lo, hi = scheme.clearance_limits()
        grades = "/".join(str(len(getattr(scheme, d).labels)) for d in ("housing", "journal", "shell"))
        print(f"  {scheme.name:<12} {scheme.title}; nominal clearance {lo * 1e6:.1f}-{hi * 1e6:.1f} um; "
              f"grades housing/journal/shell {grades}")
    if args.out is None:
        print("Write them as scheme files to read, keep and edit with --out DIR.")
        return 0
    paths = [prepare_file(os.path.join(args.out, f"{scheme.name}-{engine.name}.toml"), force=args.force,
                          option="--out") for scheme in schemes]  # every file checked before one is written
    for scheme, path in zip(schemes, paths):
        write_file(path, scheme.to_toml_text())
        print(f"wrote {path}")
    return 0


def _listing(what, variable, found, builtin, describe):
    """Print the built-in files and those a user's folder adds (or replaces), each with a line about it."""
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


def _store_check(args, state):
    from .study.damage import check, status

    state.saved = "nothing was changed"
    print(_store_status(args.path, status(args.path)))
    damages = check(args.path)
    if not damages:
        print("Every chunk was read: no damage found.")
        return 0
    print(f"{len(damages)} damaged chunk{'s' if len(damages) > 1 else ''}:")
    for damage in damages:
        print(f"  {damage.where()}: {damage.error}")
    for remedy in dict.fromkeys(d.remedy(args.path) for d in damages):
        print(f"To recover: {remedy}.")
    return EXIT_DAMAGED


def _store_repair(args, state):
    from .study.damage import repair

    state.saved = f"the repair may be partial: run `stackup store repair {args.path}` again"
    damages = repair(args.path)
    if not damages:
        print(f"{args.path}: every chunk was read, no damage found; nothing to repair.")
        return 0
    for damage in damages:
        done = (f"study chunk {damage.study_chunk:06d} marked to be computed again" if damage.recovery == "recompute"
                else {"coordinate": "engine numbers rewritten",
                      "restart": "saved running total dropped"}.get(damage.recovery, "left as it is"))
        print(f"  {damage.where()}: {done}")
    kinds = {d.recovery for d in damages}
    if kinds & {"recompute", "restart", "rerun"}:
        print(f"Now run the same study with store={args.path!r} again: it computes what was marked and keeps the "
              "rest.")
    if "none" in kinds:
        print("This store was saved whole, not streamed by a study: save the dataset again.")
    return 0


def _store_status(path, st):
    if st.study is None:
        return f"{path}: a Zarr store not streamed by a study ({'complete' if st.finished else 'no dataset attributes'})"
    s = st.study
    kept = "every engine kept" if s.get("keep") == "everything" else "streaming summaries"
    text = f"{path}: a study of {s['n_engines']:,} engines x {len(s['schemes'])} schemes ({kept}); "
    if st.chunks_total is not None and st.chunks_done == st.chunks_total and st.finished:
        return text + f"all {st.chunks_total} chunks computed."
    of = f" of {st.chunks_total}" if st.chunks_total is not None else ""
    return text + (f"{st.chunks_done}{of} chunks computed; running the same study with store={path!r} computes "
                   "the rest and keeps these.")


class _Formatter(argparse.ArgumentDefaultsHelpFormatter, argparse.RawDescriptionHelpFormatter):
    """Defaults shown where there is one to show (not for flags, nor where the help says it)."""

    def _get_help_string(self, action):
        if action.default is None or action.default is False or action.default is argparse.SUPPRESS or "default" in (action.help or ""):
            return action.help
        return super()._get_help_string(action)


def _share_ppm(text):
    """A share of bearings in ppm, zero or more."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of ppm") from None
    if not value >= 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"{text} ppm is not a share of bearings >= 0")
    return value


def _count(minimum, what):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of {what}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"{value} {what if value != 1 else what[:-1]} is too few; give at least "
                                             f"{minimum}")
        return value

    return parse


def _share(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0.0 < value < 1.0:
        raise argparse.ArgumentTypeError(f"{value:g} is not a probability between 0 and 1 (e.g. 0.99)")
    return value


def _compare_parser(sub):
    """``stackup compare``: the main job."""
    cmp_ = sub.add_parser("compare", formatter_class=_Formatter, help="compare selective-fitting schemes on an engine",
                          description="Compare selective-fitting schemes on an engine: a study of sampled engines, "
                          "the declared robustness scenarios and what drives the spread; writes the dataset "
                          "(compare.nc) and the report (report.md, report.html) into the output folder. One line "
                          "per stage is printed as it starts.",
                          epilog="examples:\n  stackup compare --quick\n"
                                 "  stackup compare --schemes iso13778-4 my-scheme.toml --window 45 65 --out runs/a")
    cmp_.add_argument("--engine", default="iso-example",
                      help="engine name (see `stackup engines`) or engine TOML file")
    cmp_.add_argument("--schemes", nargs="+", metavar="SCHEME",
                      help="scheme names (see `stackup schemes`) or scheme TOML files (default: iso13778-1 ... -6)")
    cmp_.add_argument("--n", type=_count(COMPARE_MIN_ENGINES, "engines"), metavar="ENGINES",
                      help=f"engines to sample, at least {COMPARE_MIN_ENGINES} (default: {COMPARE_ENGINES}; "
                           f"{QUICK_ENGINES} with --quick)")
    cmp_.add_argument("--seed", type=int, default=0, help="root seed of the random numbers (same seed, same numbers)")
    cmp_.add_argument("--window", type=float, nargs=2, metavar=("LO", "HI"),
                      help="design window of the operating clearance in micrometres, instead of the engine's "
                           "(default: the engine's)")
    cmp_.add_argument("--out", metavar="FOLDER",
                      help=f"output folder for the dataset and the report (default: {COMPARE_OUT}; {QUICK_OUT} "
                           "with --quick)")
    cmp_.add_argument("--quick", action="store_true",
                      help=f"a smaller run: {QUICK_ENGINES} engines, written to {QUICK_OUT} (the designer, tails and "
                           "Sobol stages do not shrink with it: add --no-design to skip the designer)")
    cmp_.add_argument("--no-scenarios", action="store_true",
                      help="skip the robustness scenarios (process and model uncertainty)")
    cmp_.add_argument("--negligible", type=_share_ppm, default=1.0, metavar="PPM",
                      help="shares of bearings outside the window less than this apart do not separate schemes; "
                           "cost decides between them (default: 1 ppm)")
    cmp_.add_argument("--volume", type=_count(1, "engines"), default=10_000, metavar="ENGINES",
                      help="production volume the report's shell plan is for (default: 10000)")
    cmp_.add_argument("--film-check-engines", type=_count(0, "engines"), default=FILM_CHECK_ENGINES,
                      metavar="ENGINES",
                      help="engines per scheme whose films run again with the mass-conserving elrod-coarse tier, "
                           "which corrects the film and life means of the report by control variates (0: none; "
                           f"default: {FILM_CHECK_ENGINES})")
    cmp_.add_argument("--tilt-method", choices=("equilibrium", "coupled", "free"), default="equilibrium",
                      help="the journal's tilt in its bearing: balanced at each bearing against the crankshaft "
                           "and the block at its support, with the tilt's squeeze, the film, alpha and lives read "
                           "over the width (default); 'coupled', the support moments of all bearings balanced "
                           "together over the cycle, each journal's centre moved with its tilt, on an elastic "
                           "layer (several times the chain's cost: "
                           "reports/bench_chain.md, reports/coupled_supports.md); 'free', the crankshaft's slope "
                           "held, the film read at the mid-plane")
    cmp_.add_argument("--processes", action="store_true",
                      help="run the study and its scenarios on one local worker process per core (dask; the same "
                           "numbers, faster on a large run)")
    cmp_.add_argument("--no-design", action="store_true",
                      help="compare only the schemes given, without a scheme designed for the engine and window "
                           "(`stackup design`)")
    cmp_.add_argument("--compact", action="store_true",
                      help="store the per-bearing values to 10 nm and 10 kPa (a dataset about a quarter of the size; "
                           "a study rebuilt from it then differs by up to half that; default: every value as "
                           "computed, so the dataset rebuilds itself identically)")
    cmp_.add_argument("--force", action="store_true",
                      help="replace another run in the output folder (the same run again is always replaced)")
    cmp_.set_defaults(func=_compare)


def _report_parser(sub):
    """``stackup report``: the report of a saved comparison, again."""
    rpt = sub.add_parser("report", formatter_class=_Formatter, help="write the report of a saved comparison again",
                         description="Write the report (report.md, report.html and its figures) from a dataset "
                         "`stackup compare` saved, and from nothing else: after an update of stackup's report, or "
                         "to look at a dataset someone sent.",
                         epilog="example:\n  stackup report reports/compare/compare.nc")
    rpt.add_argument("dataset", metavar="DATASET", help="compare.nc written by `stackup compare`")
    rpt.add_argument("--out", metavar="FOLDER", help="folder for the report (default: the dataset's folder)")
    rpt.add_argument("--negligible", type=_share_ppm, metavar="PPM",
                     help="shares outside the window less than this apart do not separate schemes (default: the "
                          "comparison's)")
    rpt.add_argument("--volume", type=_count(1, "engines"), default=10_000, metavar="ENGINES",
                     help="production volume the shell plan is for (default: 10000)")
    rpt.set_defaults(func=_report)


def _plan_parser(sub):
    """``stackup plan``: shells (or graded parts) per grade for a volume."""
    pln = sub.add_parser("plan", formatter_class=_Formatter, help="shells (or graded parts) per grade for a volume",
                         description="How many shells of each grade to make and stock for a production volume (whole "
                         "shells, rounded up where stock must cover demand), or with --part how many housing bores "
                         "or journals of each grade the volume gives. Prints the table with a title saying what it "
                         "answers; --csv writes the same table for a spreadsheet.",
                         epilog="examples:\n  stackup plan --scheme iso13778-5 --volume 10000\n"
                                "  stackup plan --scheme iso13778-5 --volume 10000 --lot 500 --service-level 0.995 "
                                "--csv shells.csv\n  stackup plan --scheme iso13778-4 --volume 10000 --part journal")
    pln.add_argument("--scheme", required=True, help="scheme name (see `stackup schemes`) or scheme TOML file")
    pln.add_argument("--engine", default="iso-example",
                     help="engine name (see `stackup engines`) or engine TOML file: its processes, gauges and shell "
                          "supply")
    pln.add_argument("--volume", type=_count(1, "engines"), required=True, metavar="ENGINES", help="engines to build")
    pln.add_argument("--service-level", type=_share, metavar="P",
                     help="shells only: share of lots whose demand for a grade the stock per lot covers "
                          "(default: 0.99)")
    pln.add_argument("--lot", type=_count(1, "engines"), metavar="ENGINES",
                     help="shells only: engines per production lot, at most --volume (default: the engine's lot, or "
                          "the whole volume when it is smaller)")
    pln.add_argument("--sample", type=_count(100, "engines"), default=20_000, metavar="ENGINES",
                     help="engines sampled to estimate the demand")
    pln.add_argument("--seed", type=int, default=0, help="seed of the sampled engines")
    pln.add_argument("--part", choices=("shell", "housing", "journal"), default="shell",
                     help="plan shells, or count the housing bores or journals of each grade")
    pln.add_argument("--csv", metavar="FILE", help="also write the table as CSV to FILE ('-': only the CSV, to stdout)")
    pln.add_argument("--force", action="store_true", help="replace an existing --csv FILE")
    pln.set_defaults(func=_plan)


def _listing_parsers(sub):
    """``stackup engines`` and ``stackup schemes``: the built-in files and the user's."""
    for name, variable, func in (("engines", "STACKUP_ENGINE_PATH", _engines),
                                 ("schemes", "STACKUP_SCHEME_PATH", _schemes)):
        lst = sub.add_parser(name, formatter_class=_Formatter, help=f"list the built-in {name} and the user's",
                             description=f"List the built-in {name} and those the folders in the environment "
                             f"variable {variable} add (a user's file of the same name replaces a built-in one). "
                             f"Any {name[:-1]} file also works by its path.")
        lst.set_defaults(func=func)
        if name == "schemes":
            lst.add_argument("--engine", metavar="ENGINE", help="show ISO 13778's schemes 1-6 laid on this "
                             "engine's drawing (a built-in name or an engine file), as `stackup compare` uses them")
            lst.add_argument("--out", metavar="DIR", help="with --engine: write them there as scheme files")
            lst.add_argument("--force", action="store_true", help="with --out: replace files of the same names")


def _store_parser(sub):
    """``stackup store check`` and ``stackup store repair``."""
    store = sub.add_parser("store", formatter_class=_Formatter, help="check or repair a study's Zarr store",
                           description="A study streamed into a Zarr store (Study(store=PATH)) can be checked for "
                           "chunks that cannot be read, and repaired: the study chunks that wrote them are marked "
                           "to be computed again, and running the same study with the same store recomputes them "
                           "and keeps the rest.")
    actions = store.add_subparsers(dest="action", required=True, metavar="ACTION", help="what to do with the store")
    chk = actions.add_parser("check", formatter_class=_Formatter, help="read every chunk; exit 1 if any is damaged",
                             description="Say what the store holds and read every chunk once; list the damaged "
                             "ones with the variable, the file, the engines and the recovery. Exit 0 if sound, 1 if "
                             "damaged.")
    chk.add_argument("path", metavar="PATH", help="the store (a folder)")
    chk.set_defaults(func=_store_check)
    rep = actions.add_parser("repair", formatter_class=_Formatter, help="mark damaged chunks to be computed again",
                             description="Mark the study chunks that wrote a damaged chunk to be computed again "
                             "(their files stay until rewritten, so nothing reads as zeros), rewrite damaged engine "
                             "numbers and drop a damaged running total of summaries; then run the same study with "
                             "the same store.")
    rep.add_argument("path", metavar="PATH", help="the store (a folder)")
    rep.set_defaults(func=_store_repair)


def parser():
    """The ``stackup`` argument parser."""
    from .design_cli import add_parser as add_design_parser
    from .measure_cli import add_parser as add_measure_parser

    top = argparse.ArgumentParser(prog="stackup", formatter_class=_Formatter, description=(
        "Monte Carlo tolerance stack-up and ISO 13778 selective assembly of engine main bearings."),
        epilog="Run `stackup COMMAND --help` for a command's options.")
    top.add_argument("--version", action="version", version=f"stackup {__version__}")
    sub = top.add_subparsers(dest="command", required=True, metavar="COMMAND", help="what to do")
    _compare_parser(sub)
    _report_parser(sub)
    _plan_parser(sub)
    _listing_parsers(sub)
    add_design_parser(sub).formatter_class = _Formatter
    add_measure_parser(sub).formatter_class = _Formatter
    _store_parser(sub)
    return top


def _message(error):
    """The error's message with the library's parameter names spelled as the options."""
    text = str(error)
    for name, option in OPTIONS.items():
        if text.startswith(f"{name}:"):
            return option + text[len(name):]
    return text


def main(argv=None):
    """Run the command; return its exit code (the console script exits with it)."""
    state = _State()
    try:
        with held_during_imports():
            try:
                args = parser().parse_args(argv)
            except SystemExit as done:  # --help, --version, or a usage error argparse has already printed
                return done.code
            return args.func(args, state)
    except KeyboardInterrupt:
        print(state.interrupted(), file=sys.stderr)
        return EXIT_INTERRUPTED
    except SystemError as error:
        if not _interrupt(error):
            raise
        print(state.interrupted(), file=sys.stderr)
        return EXIT_INTERRUPTED
    except ValueError as error:  # bad input, a refused output location, a damaged store: said, not a traceback
        print(f"stackup: error: {_message(error)}", file=sys.stderr)
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
