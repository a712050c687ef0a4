"""What the main job computes, in memory: the study, its declared scenarios, tails and Sobol indices.

The public face is :mod:`stackup.comparison` (:func:`stackup.comparison.compare`, and
:func:`stackup.comparison.run`, the main job into a folder); this module sits below the report and the
saved files, which read what it computes.
"""

from __future__ import annotations

import contextlib
import json
from dataclasses import dataclass, replace

import numpy as np
import xarray as xr
from tqdm.auto import tqdm

from . import _validate as check
from .design import design as design_scheme
from .design.estimate import outside_share
from .engines import load_engine
from .facts import MIN_COUNTED, NEGLIGIBLE_PPM, counted_outside
from .facts.declared import StudyParameters, parsed, plain
from .rank import rank
from .scenarios import DECLARED, MECHANICS_KEYS, model_uncertainties
from .schemes import load as load_scheme
from .sensitivity import sobol
from .study import ISO_SCHEMES, Study, schema
from .study.inputs import input_files, load_inputs, scheme_text
from .study.pilot import grading, pilot_parts
from .study.scenario import checked
from .study.schedule import local_cluster
from .tail import clearance_tail

#: Largest share of a pilot sample's bearings a scheme may leave ungraded in a comparison: the share of missing
#: samples its Sobol stage accepts (stackup.sensitivity.sobol_indices, max_missing).
UNGRADED_LIMIT = 0.01
#: Engines of the mechanical chain in a scenario that disturbs it (misalignment); the
#: clearance-only scenarios run no mechanics.
SCENARIO_MECHANICS_ENGINES = 50
#: Crank-angle step of the film and life Sobol samples [deg]: coarser than a study's, as ranking the inputs
#: needs the cycle's shape, not its last tenth of a micrometre.
SOBOL_CRANK_ANGLE_STEP = 4.0
#: Root bearings of each tail estimate (:func:`stackup.tail.clearance_tail`'s ``n_level``).
TAIL_ROOTS = 2_000
#: Independent samples and engines per sample of the conditional tail estimate (its error and time on the
#: example engine: reports/design_scheme.md).
TAIL_SAMPLES, TAIL_ENGINES = 10, 20_000


@dataclass(frozen=True)
class Comparison:
    """What the main job computes; every part is a dataset, so a report needs nothing else.

    Attributes
    ----------
    dataset : xarray.Dataset
        The study (every engine kept).
    scenarios : dict of str -> xarray.Dataset
        The same study under each declared scenario, with the same seed
        (common random numbers), as streaming summaries.
    sensitivity : xarray.Dataset
        Sobol indices of the root inputs per output and scheme (:func:`sensitivity_dataset`).
    tails : xarray.Dataset
        Shares of bearings beyond each edge of the design window by
        generalized splitting (:func:`tails_dataset`) for the schemes whose
        study counted too few bearings outside the window
        (:data:`stackup.facts.MIN_COUNTED`), which the ranking uses.
    """

    dataset: xr.Dataset
    scenarios: dict
    sensitivity: xr.Dataset
    tails: xr.Dataset


def compare(engine="iso-example", schemes=ISO_SCHEMES, n_engines=100_000, seed=0, *, scenarios=DECLARED,
            uncertainties="declared", negligible=NEGLIGIBLE_PPM, design=None, scheduler=None, progress=None, log=None,
            **study_options):
    """Compare selective-fitting schemes on an engine: the study, its scenarios and what drives the spread.

    Parameters
    ----------
    engine : str or path
        Built-in engine name or engine TOML file.
    schemes : sequence of str or path
    n_engines : int
    seed : int
    scenarios : dict of str -> dict
        Label -> process scenario (:mod:`stackup.scenarios`); each is run
        with the same seed on the clearance stages, and on
        :data:`SCENARIO_MECHANICS_ENGINES` engines of the mechanical chain
        where it disturbs that chain (misalignment). Empty for none.
    uncertainties : "declared", sequence of stackup.scenarios.Uncertainty, or None
        Model inputs over their declared ranges, run as scenarios like the
        process ones: "declared" runs the engine's
        (:func:`stackup.scenarios.model_uncertainties`: housing stiffness,
        crush height process, journal-housing temperature difference, and
        where the engine file assumes them the crankshaft's bending stiffness
        and, with ``tilt_method="coupled"``, the supports' angular
        compliance); None
        or empty runs none. Each scenario dataset says what it is in its
        attributes (``scenario_kind`` "process" or "model"; a model one its
        ``scenario_input``, ``scenario_source`` and ``scenario_measure``).
    negligible : float
        Shares of bearings outside the window differing by less than this
        [ppm] do not separate schemes (:func:`stackup.rank.rank`); stored in
        the dataset's ``negligible_ppm`` attribute.
    design : dict or None
        Design a scheme for the engine and its window first
        (:func:`stackup.design.design` with these keyword options, the
        comparison's seed and scenarios) and compare it beside ``schemes``;
        its choices are stored in the dataset's attributes
        (``designed_scheme``, ``design``). None designs nothing.
    scheduler : None, "processes" or dask.distributed.Client
        Where the study and its scenarios run (:meth:`stackup.study.Study.run`;
        "processes" starts one local worker per core for all of them). The
        numbers do not depend on it.
    progress : bool or None
        Progress bars (None: only on a terminal).
    log : callable or None
        Called with one line of text as each stage starts (the study, each
        scenario, the sensitivity), e.g. ``print`` for logs.
    **study_options
        Further :class:`~stackup.study.Study` parameters.

    Returns
    -------
    Comparison
    """
    runs = checked_runs(engine, schemes, seed, scenarios=scenarios, uncertainties=uncertainties,
                        tilt_method=study_options.get("tilt_method", "equilibrium"), negligible=negligible,
                        pilot_engines=study_options.get("pilot_engines", Study.pilot_engines))
    return compare_checked(runs, engine=engine, schemes=schemes, n_engines=n_engines, seed=seed, scenarios=scenarios,
                           negligible=negligible, design=design, scheduler=scheduler, progress=progress, log=log,
                           **study_options)


def checked_runs(engine, schemes, seed, *, scenarios, uncertainties, tilt_method, negligible,
                 pilot_engines=Study.pilot_engines):
    """A comparison's checks before anything is computed; its scenario runs (:func:`_scenario_runs`).

    The engine and scheme files are read; ``negligible`` and the scenarios
    are checked; each scheme is graded on the study's pilot sample as the
    study lays it on the engine's drawing, and one that leaves more than
    :data:`UNGRADED_LIMIT` of the bearings with parts inside the drawing
    limits ungraded is refused naming it (the study would mark them not
    graded, and the Sobol stage at the end refuses that many missing
    samples). A ValueError says what is wrong.
    """
    check.Positive(zero=True)("negligible", negligible)
    labels = [str(s) for s in schemes]
    for scheme in schemes:
        load_scheme(scheme)
    loaded_engine, loaded = load_inputs(input_files(engine, labels), labels)  # the schemes as the study lays them
    pilot = pilot_parts(loaded_engine, seed, pilot_engines)
    for label, scheme in zip(labels, loaded):
        graded = grading(scheme, pilot)
        if graded.ungraded > UNGRADED_LIMIT:
            raise ValueError(f"schemes: scheme {scheme.name}{f' ({label})' if label != scheme.name else ''} "
                             f"leaves {100 * graded.ungraded:.2g} % of {loaded_engine.name}'s bearings with parts "
                             f"inside the drawing limits ungraded: {graded.where(scheme, loaded_engine)}, in the "
                             f"study's pilot sample of {pilot_engines:,} engines; the main job needs at most "
                             f"{100 * UNGRADED_LIMIT:g} %: widen the scheme's grades to the engine's drawing limits")
    return _scenario_runs(scenarios, _uncertainties(uncertainties, engine, tilt_method))


def compare_checked(runs_asked, *, engine, schemes, n_engines, seed, scenarios, negligible, design, scheduler, progress,
                    log, **study_options):
    """:func:`compare` once :func:`checked_runs` passed (``runs_asked``: what it returned)."""
    log = log or (lambda line: None)
    designed = None
    if design is not None:
        log("design: a scheme for the engine and its window (stackup.design)")
        designed = design_scheme(engine, window=study_options.get("window"), scenarios=scenarios, seed=seed,
                                 **design)
        designed = replace(designed, scheme=replace(designed.scheme, name=_distinct_name(
            designed.scheme.name, [load_scheme(s).name for s in schemes])))
        schemes = (*schemes, designed.scheme)
    study = Study(engine=engine, schemes=tuple(schemes), n_engines=n_engines, seed=seed, progress=progress,
                  **study_options)
    with _client(scheduler) as where:
        log(f"study: {study.n_engines:,} engines x {len(study.schemes)} schemes")
        ds = study.run(where)
        ds.attrs["negligible_ppm"] = float(negligible)
        runs = {}
        for k, (label, change, about) in enumerate(runs_asked, start=1):
            log(f"scenario {k}/{len(runs_asked)} ({about['scenario_kind']}): {label}")
            mechanics = SCENARIO_MECHANICS_ENGINES if any(key in MECHANICS_KEYS for key in change) else 0
            runs[label] = replace(study, scenario=change, keep="summaries", mechanics_engines=mechanics,
                                  film_check_engines=0).run(where)  # the study's check corrects the study
            runs[label].attrs.update(about)
    if designed is not None:
        ds.attrs.update(designed_scheme=designed.scheme.name, design=json.dumps(design_record(designed)))
    engine_used, loaded = load_inputs(study.files, study.schemes)
    counted = counted_outside(ds)
    few = [s for s in loaded if counted[s.name] < MIN_COUNTED]
    log(f"tails: shares beyond the design window with the shells integrated out ({len(few)} schemes with fewer than "
        f"{MIN_COUNTED} bearings counted outside it)")
    tails = tails_dataset(engine_used, few, window=study_options.get("window"), seed=seed,
                          pilot_engines=study.pilot_engines, progress=progress)
    log("sensitivity: Sobol indices of the root inputs")
    sensitivity = sensitivity_dataset(ds, scenario=study_options.get("scenario"), seed=seed, tails=tails,
                                      progress=progress)
    ds.attrs["comparison"] = COMPARISON_NOTE
    return Comparison(ds, runs, sensitivity, tails)


#: The ``comparison`` attribute of a comparison's study dataset: how to read the whole comparison.
COMPARISON_NOTE = ("the study of a stackup.compare comparison; its scenarios, tail estimates and Sobol indices are "
                   "groups of the same file: open it with stackup.io.open_comparison(path) and rank it with "
                   "stackup.rank(that comparison)")


def _uncertainties(uncertainties, engine, tilt_method):
    """The model uncertainties a comparison runs: "declared" is the engine's (for a study with ``tilt_method``),
    None none, else as given."""
    if isinstance(uncertainties, str):
        if uncertainties != "declared":
            raise ValueError(f"uncertainties: {uncertainties!r} is not 'declared', None or a sequence of "
                             "stackup.scenarios.Uncertainty")
        return model_uncertainties(load_engine(engine), tilt_method)
    return list(uncertainties or ())


def _scenario_runs(scenarios, uncertainties):
    """(label, scenario, attributes) of every scenario run: the process ones, then each model input's ends."""
    runs = [(label, change, {"scenario_kind": "process"}) for label, change in (scenarios or {}).items()]
    for u in uncertainties:
        about = {"scenario_kind": "model", "scenario_input": u.input, "scenario_source": u.source,
                 "scenario_measure": u.measure}
        runs += [(label, change, about) for label, change in u.scenarios.items()]
    labels = [label for label, _, _ in runs]
    if len(set(labels)) < len(labels):
        raise ValueError(f"scenarios: labels repeat ({', '.join(sorted({x for x in labels if labels.count(x) > 1}))})")
    for label, change, _ in runs:
        checked(change)
    return runs


def _distinct_name(name, taken):
    """``name``, or ``name-this-run`` (then ``-2``, ``-3``, ...) where a scheme given beside it has that name
    (e.g. a scheme file an earlier ``stackup design`` wrote)."""
    if name not in taken:
        return name
    candidates = (f"{name}-this-run", *(f"{name}-this-run-{k}" for k in range(2, len(taken) + 3)))
    return next(c for c in candidates if c not in taken)


@contextlib.contextmanager
def _client(scheduler):
    """The scheduler for every study run of a comparison: "processes" becomes one local cluster for all of them."""
    if scheduler != "processes":
        yield scheduler
        return
    with local_cluster() as client:
        yield client


def design_record(designed):
    """What a :class:`~stackup.design.Design` found, as plain data for the dataset's ``design`` attribute.

    Both figures of the designed scheme: on the design sample it was optimised on (``outside``,
    ``objective``) and on the independent check sample no decision of the designer saw
    (``check_outside`` with ``check_interval`` per scenario, ``check_objective``); ``levels``: the
    ladder of shell grades (:mod:`stackup.design.ladder`): per number of grades asked, the grades and
    :math:`J` of the design kept and the :math:`J` of each candidate tried.
    """
    check = designed.check
    return {"start": designed.start, "objective": designed.objective, "start_objective": designed.start_objective,
            "outside": designed.outside, "start_outside": designed.start_outside, "iso_outside": designed.iso,
            "check_outside": check.outside, "check_interval": {k: list(v) for k, v in check.interval.items()},
            "check_objective": check.objective, "check_objective_interval": list(check.objective_interval),
            "check_samples": check.samples, "check_engines": check.engines,
            "levels": [{"asked": step.asked, "grades": step.grades, "objective": step.objective,
                        "kept": step.origin, "tried": step.candidates}
                       for step in designed.levels],
            "mean_clearance_m": designed.mean_clearance, "start_mean_clearance_m": designed.start_mean_clearance,
            "seconds": designed.seconds, "evaluations": designed.evaluations, "notes": list(designed.scheme.notes),
            "start_text": scheme_text(designed.start)}


def bar(steps, desc, unit, progress):
    """A progress bar over a stage's ``steps`` (an iterable, or how many), as the study's (tqdm: on a terminal
    where ``progress`` is None, always with True, never with False)."""
    iterable, total = (None, steps) if isinstance(steps, int) else (steps, None)
    return tqdm(iterable, total=total, desc=desc, unit=unit, disable=None if progress is None else not progress)


def sensitivity_dataset(ds, *, engine=None, scenario=None, seed=0, n_clearance=1024, n_film=64,
                        tails=None, progress=None):
    """Sobol indices of the root inputs (:func:`stackup.sensitivity.sobol`) for the comparison's schemes.

    The operating clearance (bearing 1; every position is alike) for every
    scheme; the engine's smallest mid-plane film and its life for the scheme the
    ranking puts first (one run of the mechanical chain gives both). Variables
    on (output, scheme, input): ``S1``, ``ST`` and their 95 % bootstrap
    bounds ``*_lo``, ``*_hi``; NaN where an output was not analysed. ``progress``: a bar over the Sobol runs
    (:func:`bar`).
    """
    params = StudyParameters.of(ds)
    stored_engine, loaded = load_inputs(parsed(ds, "input_files"), params.schemes)
    engine = stored_engine if engine is None else engine
    by_name = {s.name: s for s in loaded}
    schemes = [str(s) for s in ds.scheme.values]
    frames = {}
    film = bool(int(ds.attrs.get("mechanics_engines_used", 0)) and n_film)
    with bar(len(schemes) + film, "sensitivity", "run", progress) as runs:
        for scheme in schemes:
            frames[("clearance_operating", scheme)] = sobol(engine, by_name[scheme], n=n_clearance, seed=seed,
                                                            scenario=scenario, pilot_engines=params.pilot_engines)
            runs.update(1)
        if film:
            best = rank(ds, tails=tails).index[0]
            both = sobol(engine, by_name[best], output="h_min", n=n_film, seed=seed, scenario=scenario,
                         return_all=True, crank_angle_step=max(params.crank_angle_step, SOBOL_CRANK_ANGLE_STEP),
                         crank_method=params.crank_method, film_method=plain(ds, "film_method_used"),
                         pilot_engines=params.pilot_engines)
            frames.update({(output, best): frame for output, frame in both.items()})
            runs.update(1)
    outputs = list(dict.fromkeys(output for output, _ in frames))
    inputs = list(dict.fromkeys(i for frame in frames.values() for i in frame.index))
    values = {c: np.full((len(outputs), len(schemes), len(inputs)), np.nan) for c in schema.SOBOL_INDICES}
    evaluations = np.zeros((len(outputs), len(schemes)), np.int64)
    for (output, scheme), frame in frames.items():
        i, j = outputs.index(output), schemes.index(scheme)
        for c in schema.SOBOL_INDICES:
            values[c][i, j] = frame[c].reindex(inputs).to_numpy()
        evaluations[i, j] = frame.attrs["evaluations"]
    data = {name: var(evaluations if name == "evaluations" else values[name])
            for name, var in schema.SENSITIVITY.items()}
    return xr.Dataset(data, coords=schema.coords(output=outputs, scheme=schemes, input=inputs),
                      attrs={"method": "Sobol indices on root inputs through the assembly chain "
                                       "(stackup.sensitivity.sobol, SALib)", "seed": seed})


@check.validated(method=check.OneOf(("conditional", "splitting")), window=check.Window())
def tails_dataset(engine, schemes, *, window=None, seed=0, pilot_engines=20_000, n_level=TAIL_ROOTS,
                  method="conditional", progress=None):
    """Share of bearings below and above the design window per scheme, for the ranking's small shares.

    ``method="conditional"`` (default): the designer's conditional tier, the
    shells integrated out on :data:`TAIL_SAMPLES` independent samples of
    :data:`TAIL_ENGINES` engines, Student intervals
    (:func:`stackup.design.estimate.outside_share`); ``"splitting"``:
    generalized splitting through the assembly chain (:mod:`stackup.tail`).

    Variables on (scheme, side): ``tail_share``, its ``tail_standard_error``
    and 95 % interval (``tail_interval`` on ``bound``; where no sample reaches
    the tail the share is 0 with an upper bound), with the chain evaluations
    each estimate cost (``tail_bearings``); splitting adds the independent
    root bearings it rests on (``tail_roots_in_tail``), the conditional tier
    the share outside the window and its interval (``tail_outside_share``,
    ``tail_outside_interval``: the two edges from the same samples). ``progress``: a bar over the schemes
    (:func:`bar`).
    """
    engine = load_engine(engine)
    window = engine.clearance_window if window is None else window
    loaded = [load_scheme(s) for s in schemes]
    shares, errors, cost, roots = (np.full((len(loaded), 2), np.nan) for _ in range(4))
    interval = np.full((len(loaded), 2, 2), np.nan)
    outside, outside_interval = np.full(len(loaded), np.nan), np.full((len(loaded), 2), np.nan)
    for i, scheme in enumerate(bar(loaded, "tails", "scheme", progress)):
        if method == "conditional":
            r = outside_share(engine, scheme, window=window, seed=seed, samples=TAIL_SAMPLES, n_engines=TAIL_ENGINES)
            shares[i], errors[i] = (r.below, r.above), (r.below_error, r.above_error)
            interval[i] = r.below_interval, r.above_interval
            outside[i], outside_interval[i] = r.outside, r.outside_interval
            cost[i] = r.samples * r.engines * engine.main_bearings
            continue
        for j, side in enumerate(schema.SIDES):
            if not np.isfinite(window[j]) or (side == "lower" and window[j] <= 0):
                continue
            t = clearance_tail(engine, scheme, side=side, threshold=window[j], seed=seed,
                               pilot_engines=pilot_engines, n_level=n_level)
            shares[i, j], errors[i, j], cost[i, j], roots[i, j] = t.share, t.standard_error, t.bearings, \
                t.effective_bearings
            interval[i, j] = t.interval
    name = {"conditional": "the shells integrated out (stackup.design.estimate)",
            "splitting": "generalized splitting (stackup.tail)"}[method]
    values = {"tail_share": shares, "tail_standard_error": errors, "tail_interval": interval, "tail_bearings": cost}
    if method == "splitting":
        values["tail_roots_in_tail"] = roots
    else:
        values.update(tail_outside_share=outside, tail_outside_interval=outside_interval)
    data = {key: schema.TAILS[key](value, long_name=schema.TAILS[key].long_name.format(method=name))
            for key, value in values.items()}
    return xr.Dataset(
        data, coords=schema.coords(scheme=[s.name for s in loaded], side=schema.SIDES, bound=schema.BOUNDS),
        attrs={"window": list(map(float, window)), "method": name, "tail_method": method, "seed": seed})
