"""The main job: a scheme comparison on an engine, from its input files to a folder with its dataset and report.

:func:`run` is what ``stackup compare`` runs and what a study script calls to get the same folder:

1. pre-flight, before any folder is touched: the engine and scheme files
   read, the scenarios checked, every scheme graded on the study's pilot
   sample (a scheme that leaves parts ungraded is refused naming them), the
   engines checked against this machine's memory; then the output folder
   claimed (:func:`stackup.output.prepare_folder`);
2. :func:`compare`: the study, its declared scenarios, tails and Sobol
   indices, in memory (:mod:`stackup._comparison`);
3. the comparison saved into one netCDF file, opened again, and the report
   written from what was saved and nothing else;
4. the folder written whole or not at all: an error or a Ctrl-C leaves it as
   it was.

Messages name the library's parameters (``n_engines``, ``schemes``, ``out``,
``force=True``); the command line says them as its options.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

import numpy as np

from . import _validate as check
from ._comparison import (COMPARISON_NOTE, SCENARIO_MECHANICS_ENGINES, SOBOL_CRANK_ANGLE_STEP, TAIL_ENGINES,  # noqa: F401
                          TAIL_ROOTS, TAIL_SAMPLES, UNGRADED_LIMIT, Comparison, checked_runs, compare, compare_checked,
                          design_record, sensitivity_dataset, tails_dataset)
from ._main_job import (COMPARE_ENGINES, COMPARE_MIN_ENGINES, COMPARE_OUT, FILM_CHECK_ENGINES,  # noqa: F401
                        QUICK_ENGINES, QUICK_OUT)
from .engines import load_engine
from .facts import NEGLIGIBLE_PPM, PLAN_VOLUME
from .io import open_comparison, save_comparison
from .output import DATASET, prepare_folder, run_identity
from .report import write_report
from .scenarios import DECLARED
from .study import ISO_SCHEMES, Study
from .study.schema import PER_ENGINE

#: Copies of a comparison's per-engine data in memory at once: the study, then the saved dataset the report reads.
COPIES_IN_MEMORY = 2
#: ``design`` of :func:`run` that designs a scheme with the designer's defaults.
DESIGN_DEFAULTS = MappingProxyType({})


@dataclass(frozen=True)
class Written:
    """A comparison :func:`run` wrote.

    Attributes
    ----------
    folder : pathlib.Path
        The output folder.
    comparison : Comparison
        The comparison as saved and opened again: what the report read.
    seconds : float
        Wall time of the run [s].
    """

    folder: Path
    comparison: Comparison
    seconds: float

    @property
    def dataset(self):
        """The saved comparison (``compare.nc``)."""
        return self.folder / DATASET

    @property
    def report(self):
        """The report (``report.md``; ``report.html`` and the figures beside it)."""
        return self.folder / "report.md"

    @property
    def verdict(self):
        """The report's first verdict paragraph (which scheme to use and why), without its Markdown emphasis."""
        return verdict_line(self.report)


def run(out, *, engine="iso-example", schemes=ISO_SCHEMES, n_engines=COMPARE_ENGINES, seed=0, window=None,
        scenarios=DECLARED, uncertainties="declared", design=DESIGN_DEFAULTS, negligible=NEGLIGIBLE_PPM,
        volume=PLAN_VOLUME, film_check_engines=FILM_CHECK_ENGINES, tilt_method="equilibrium", compact=False,
        force=False, scheduler=None, progress=None, log=None, **study_options):
    """Run the main job into the folder ``out``: pre-flight, compare, save, reopen, report.

    The defaults are ``stackup compare``'s: 100,000 engines of the built-in
    example engine, the six ISO 13778 schemes and one designed for the
    engine, the declared scenarios and model uncertainties.

    Parameters
    ----------
    out : str or path
        Output folder: created, or holding the same run (replaced), or with
        ``force`` another run (replaced); anything else is refused before
        anything is computed.
    engine : str or path
        Built-in engine name or engine TOML file.
    schemes : sequence of str or path
        Scheme names or scheme TOML files.
    n_engines : int
        Engines to sample, at least :data:`COMPARE_MIN_ENGINES`.
    seed : int
        Root seed (the same seed gives the same numbers).
    window : (float, float) or None
        Design window of the operating clearance [m] (default: the engine's).
    scenarios, uncertainties, negligible, scheduler, progress
        As :func:`compare`; ``scenarios={}`` with ``uncertainties=None`` runs
        no scenario.
    design : mapping or None
        Options of the designer (:func:`stackup.design.design`); the default
        designs a scheme with its defaults; None designs none.
    volume : int
        Production volume the report's shell plan is for [engines].
    film_check_engines : int
        Engines per scheme whose films run again with the mass-conserving
        tier (0: none).
    tilt_method : str
        The journal's tilt in its bearing (:class:`stackup.study.Study`).
    compact : bool
        Store the per-bearing values to 10 nm and 10 kPa
        (:func:`stackup.io.save_comparison`).
    force : bool
        Replace another run in ``out``.
    log : callable or None
        Called with one line of text as each stage starts (``print`` for logs).
    **study_options
        Further :class:`~stackup.study.Study` parameters (e.g. ``mechanics_engines``,
        ``crank_angle_step``), as :func:`compare` takes them; a folder holds
        the same run only where they are the same too.

    Returns
    -------
    Written

    Raises
    ------
    ValueError
        A bad input, a scheme that leaves parts ungraded, more engines than
        this machine's memory holds, or an output folder that must not be
        written (:class:`stackup.output.OutputRefused`): all before anything
        is computed.
    """
    start = time.perf_counter()
    log = log or (lambda line: None)
    n_engines = check.Integer(minimum=COMPARE_MIN_ENGINES)("n_engines", n_engines)
    schemes = tuple(schemes)
    design = None if design is None else dict(design)
    loaded = load_engine(engine)
    runs = checked_runs(engine, schemes, seed, scenarios=scenarios, uncertainties=uncertainties,
                        tilt_method=tilt_method, negligible=negligible,
                        pilot_engines=study_options.get("pilot_engines", Study.pilot_engines))
    check_memory(n_engines, loaded, len(schemes) + (design is not None))
    staged = prepare_folder(out, option="out", identity=run_identity(
        engine=engine, schemes=schemes, n_engines=n_engines, seed=seed, window=window, scenarios=scenarios,
        design=design is not None, tilt_method=tilt_method, **study_options), force=force)
    try:
        result = compare_checked(runs, engine=engine, schemes=schemes, n_engines=n_engines, seed=seed,
                                 scenarios=scenarios, negligible=negligible, design=design, log=log, window=window,
                                 scheduler=scheduler, progress=progress, film_check_engines=film_check_engines,
                                 tilt_method=tilt_method, **study_options)
        log(f"saving the dataset: {os.path.join(out, DATASET)}")
        data = save_comparison(result, staged.staging / DATASET, compact=compact)
        log(f"writing the report: {os.path.join(out, 'report.md')} and report.html")
        saved = open_comparison(data)  # the report reads what was saved, nothing else
        write_report(saved.dataset, staged.staging, scenarios=saved.scenarios, sensitivity=saved.sensitivity,
                     tails=saved.tails, dataset_file=data.name, volume=volume)
        folder = staged.commit()
    except BaseException:
        staged.discard()
        raise
    return Written(folder, saved, time.perf_counter() - start)


def check_memory(n_engines, engine, schemes):
    """Refuse a comparison whose engines cannot fit in this machine's memory, with what it needs and the way out.

    ``engine``: a loaded :class:`~stackup.engines.Engine`; ``schemes``: how many
    schemes the study runs.
    """
    per_engine = memory_per_engine(engine.main_bearings, schemes)
    need = COPIES_IN_MEMORY * per_engine * n_engines
    have = _physical_memory()
    if have is None or need <= have:
        return
    most = int(have / (COPIES_IN_MEMORY * per_engine))
    raise ValueError(f"n_engines: {n_engines:,} engines would need about {_bytes(need)} of memory "
                     f"({_bytes(per_engine)} per engine with {schemes} scheme{'s' if schemes > 1 else ''}, kept "
                     f"twice: the study and the saved dataset the report reads), and this machine has {_bytes(have)}; "
                     f"give n_engines at most {most:,}, or run the study in Python with Study(..., keep=\"summaries\") "
                     "(streaming summaries, memory that does not grow with the engines) or store=\"runs/big.zarr\" "
                     "(every engine on disk): docs/library.md, \"Running a study on several processes or a dask cluster\"")


def memory_per_engine(bearings, schemes):
    """Bytes one engine takes in a study that keeps every engine (its per-engine variables), for ``schemes``."""
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


def verdict_line(report):
    """The first verdict paragraph of the report ``report`` (a path), without its Markdown emphasis."""
    text = Path(report).read_text(encoding="utf-8")
    block = text.split("<!-- verdict -->", 1)[-1].split("<!-- /verdict -->", 1)[0]
    first = next((line for line in block.splitlines() if line.strip()), "")
    return first.replace("**", "").replace("`", "")
