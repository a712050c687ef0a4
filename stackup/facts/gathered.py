"""The facts of a comparison gathered into one record: :func:`facts` gives :class:`Facts`.

The study's own facts are here (:class:`About`, :class:`Limits`,
:class:`Run`, :class:`Scrap`, the designed scheme, the drivers of the
spread); the rest come from the sibling modules the package face lists.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..plan import plan
from ..schemes import from_dict
from ..study.failures import FailureCount
from ..study.inputs import load_inputs
from .declared import (DesignRecord, FilmErrors, PressFit, Processes, ScenarioAbout, Sources, StudyParameters, Wear,
                       parsed, plain)
from .iso import iso_caveats
from .mechanics import (ClearanceTrends, EdgeContact, FilmOutcomes, HeatBalance, LifeBias, Positions,
                        clearance_trends, edge_contact, film_detail, film_outcomes, heat_balance, life_bias, positions)
from .metrics import RankingRows, ranking_rows
from .tables import (bearing_summary, centred, clearance_summary, crank_summary, film_summary, fit_summary,
                     grade_usage, kept_summaries, multi_fidelity, paired_life_changes)

#: Production volume [engines] and service level of the shell plan a comparison reports.
PLAN_VOLUME, PLAN_SERVICE_LEVEL = 10_000, 0.99


@dataclass(frozen=True)
class About:
    """What the study was: its dataset's plain attributes and sizes."""

    engine: str
    title: str
    version: str
    seed: int
    bearings: int                # main bearings per engine
    summaries: bool              # streaming summaries, not every engine
    mechanics_engines: int       # engines the crankshaft, film and life ran on per scheme
    pilot_engines: int
    lot_engines: int
    film_method: str             # the film tier used

    @classmethod
    def of(cls, ds):
        return cls(plain(ds, "engine"), plain(ds, "title"), plain(ds, "stackup_version"), plain(ds, "seed"),
                   ds.sizes["bearing"], kept_summaries(ds), int(plain(ds, "mechanics_engines_used", 0)),
                   plain(ds, "pilot_engines"), plain(ds, "lot_engines"), plain(ds, "film_method_used", ""))


@dataclass(frozen=True)
class Limits:
    """The engine's design data the dataset carries as variables [m, Pa, degC, s]."""

    clearance_window: tuple
    contact_pressure_min: float
    shell_stress_max: float
    press_fit_temperatures: tuple
    crush_height: tuple
    life_target: float
    critical_film: float
    #: Least clearance at assembly or cold start [m] and the cold start [degC]; NaN in a dataset without them.
    minimum_clearance: float = np.nan
    cold_start_temperature: float = np.nan

    @classmethod
    def of(cls, ds):
        def optional(name):
            return float(ds[name]) if name in ds else np.nan

        return cls(tuple(ds.clearance_window.values), float(ds.design_contact_pressure_min),
                   float(ds.design_shell_stress_max), tuple(ds.press_fit_temperatures.values),
                   tuple(ds.crush_height_limits.values), float(ds.life_target), float(ds.critical_film.max()),
                   optional("minimum_clearance"), optional("cold_start_temperature"))


@dataclass(frozen=True)
class Run:
    """Stages that failed on some engines (one line each, :meth:`FailureCount.lines`) or did not run."""

    failures: list
    mechanics_engines_used: int
    mechanics_engines_asked: object   # the study's ``mechanics_engines`` (None: the engine file's default)

    @classmethod
    def of(cls, ds):
        return cls(FailureCount.of_dataset(ds).lines(), int(plain(ds, "mechanics_engines_used", 0)),
                   StudyParameters.of(ds).mechanics_engines)


@dataclass(frozen=True)
class Scrap:
    """What the study could not use, as shares, each the largest over the schemes [-] with that scheme.

    ``blocks``, ``crankshafts``: bearings whose block (a housing bore read
    outside its drawing limits) or crankshaft (a journal) was scrapped;
    ``not_graded``: bearings with a part read outside every grade;
    ``stockouts``: bearings left waiting for a shell; ``shells``: shells
    made that were scrapped (read outside every grade, or a crush height
    outside its limits). Each value is a (share, scheme) pair.
    """

    blocks: tuple
    crankshafts: tuple
    not_graded: tuple
    stockouts: tuple
    shells: tuple

    @classmethod
    def of(cls, clearance):
        """From a :func:`clearance_summary` (counts per status and scheme, shells scrapped in per cent)."""
        def worst(share):
            return (float(share.max()), str(share.idxmax())) if len(share) else (0.0, "")

        per_bearing = {reason: worst(clearance[reason] / clearance.bearings)
                       for reason in ("block_scrapped", "crank_scrapped", "not_graded", "shell_stockout")}
        return cls(per_bearing["block_scrapped"], per_bearing["crank_scrapped"], per_bearing["not_graded"],
                   per_bearing["shell_stockout"], worst(clearance.shells_scrapped_pct.fillna(0.0) / 100))


@dataclass(frozen=True)
class Design:
    """The scheme designed for the engine before the study, beside the ISO scheme it started from.

    ``grades`` maps each dimension ("housing bore", "journal", "shell wall") to the grades of the start
    and of the designed scheme, each a list of (label, lower, upper) [m] from the dimension's lower limit,
    or None where the dimension is not graded.
    """

    name: str
    record: DesignRecord
    grades: dict


def _grades(gradeset):
    if not gradeset.graded:
        return None
    lo0 = gradeset.limits[0]
    return [(label, lo - lo0, hi - lo0) for label, lo, hi in zip(gradeset.labels, gradeset.lo, gradeset.hi)]


def designed(ds):
    """The :class:`Design` of a comparison that designed a scheme, else None (schemes read from the dataset)."""
    record = DesignRecord.of(ds)
    if record is None:
        return None
    name = plain(ds, "designed_scheme")
    _, loaded = load_inputs(parsed(ds, "input_files"), StudyParameters.of(ds).schemes)
    designed = {s.name: s for s in loaded}[name]
    started = from_dict(tomllib.loads(record.start_text), path=record.start)
    grades = {label: (_grades(getattr(started, dim)), _grades(getattr(designed, dim)))
              for label, dim in (("housing bore", "housing"), ("journal", "journal"), ("shell wall", "shell"))}
    return Design(name, record, grades)


def drivers(sensitivity):
    """Output -> scheme -> the inputs of its Sobol indices, largest total index first (schemes analysed only)."""
    if sensitivity is None or not sensitivity.sizes.get("output"):
        return None
    out = {}
    for output in sensitivity.output.values:
        schemes = [s for s in sensitivity.scheme.values
                   if np.isfinite(sensitivity.ST.sel(output=output, scheme=s).values).any()]
        out[str(output)] = {str(s): sensitivity.sel(output=output, scheme=s).to_dataframe().dropna(subset=["ST"])
                            .sort_values("ST", ascending=False) for s in schemes}
    return out


@dataclass(frozen=True)
class Facts:
    """Everything a comparison's report states, as plain data (see the module docstring).

    Per scheme (and position) the numbers are pandas DataFrames indexed by scheme (and bearing), in the
    units their column names say; the rest is in SI units unless a name says otherwise.
    """

    about: About
    study: StudyParameters
    press_fit: PressFit
    processes: Processes
    wear: Wear                   # None where the mechanical chain did not run
    film_errors: FilmErrors      # None where the study measured none
    sources: Sources
    limits: Limits
    run: Run
    ranking: RankingRows         # the study's, with the scenarios' changes
    scenario_rankings: dict      # label -> each scenario's own RankingRows
    scenario_about: dict         # label -> ScenarioAbout (process or model, and a model range's source)
    scrap: Scrap
    clearance: pd.DataFrame      # clearance_summary
    fit: pd.DataFrame            # fit_summary
    usage: pd.DataFrame          # grade_usage
    centred: pd.DataFrame        # per scheme: what centring its clearance in the window would give
    reading_resolution: dict     # scheme -> its coarsest gauge read-out [m]
    plan: pd.DataFrame           # shells per grade for ``plan.attrs["volume"]`` engines (None from summaries)
    crank: pd.DataFrame          # crank_summary (empty where the crankshaft did not run)
    film: pd.DataFrame           # film_summary (empty where the film did not run)
    bearings: pd.DataFrame       # bearing_summary
    detail: pd.DataFrame         # film_detail
    positions: Positions
    outcomes: FilmOutcomes
    heat: HeatBalance
    edge: EdgeContact
    life_bias: LifeBias
    drivers: dict                # drivers(sensitivity), None without one
    design: Design
    life_changes: dict           # scenario -> paired_life_changes (scenarios that ran the mechanical chain)
    trends: ClearanceTrends      # film and life against the operating clearance per position (None: not computed)
    corrected: pd.DataFrame      # multi_fidelity: film and life means corrected by the check tier (empty: no check)
    misalignment: tuple = None   # (label, factor) of the first scenario that scales the drawing's misalignment
                                 # and ran the mechanical chain (its paired changes in life_changes), or None
    iso: tuple = ((), None)      # iso_caveats: the standard's schemes on this drawing (caveats, re-centring anchor)


def _centred(ds, window):
    """Scheme -> the shift [m] that centres its operating clearance in ``window``, then bearings outside, assembled."""
    if not np.all(np.isfinite(window)):  # no window to centre in
        return pd.DataFrame(columns=["shift", "outside", "bearings"])
    rows = {}
    for scheme in ds.scheme.values:
        shift, outside, bearings = centred(ds, scheme, window)
        rows[str(scheme)] = {"shift": shift, "outside": outside, "bearings": bearings}
    return pd.DataFrame.from_dict(rows, orient="index")


def _film_facts(ds):
    """The mechanical chain's tables and facts (crank, film, bearings, detail, positions, outcomes, heat, edge)."""
    crank = crank_summary(ds)
    film = film_summary(ds)
    bearings = bearing_summary(ds) if len(film) else pd.DataFrame()
    return dict(crank=crank, film=film, bearings=bearings, detail=film_detail(ds),
                positions=positions(ds, bearings) if len(film) else None, outcomes=film_outcomes(ds),
                heat=heat_balance(ds), edge=edge_contact(ds))


def facts(source, *, scenarios=None, sensitivity=None, tails=None, window=None, h_lim_cr=None, negligible=None,
          volume=PLAN_VOLUME):
    """The :class:`Facts` of a comparison.

    Parameters
    ----------
    source : stackup.comparison.Comparison or xarray.Dataset
        The comparison (its ``dataset``, ``scenarios``, ``sensitivity`` and
        ``tails``), or the study dataset alone with the others as keywords.
    scenarios, sensitivity, tails : optional
        As :class:`~stackup.comparison.Comparison` holds them (ignored when
        ``source`` is a comparison).
    window, h_lim_cr, negligible : optional
        The ranking's design window [m], critical film [m] and practical
        threshold of the share outside the window [ppm]
        (:func:`stackup.rank.rank`); default the engine's and the comparison's.
    volume : int
        Engines the shell plan is for.
    """
    if hasattr(source, "dataset"):
        source, scenarios, sensitivity, tails = source.dataset, source.scenarios, source.sensitivity, source.tails
    ds, scenarios = source, scenarios or {}
    about = About.of(ds)
    ranking = ranking_rows(ds, scenarios=scenarios or None, tails=tails, window=window, h_lim_cr=h_lim_cr,
                           negligible=negligible)
    clearance = clearance_summary(ds)
    return Facts(
        about=about, study=StudyParameters.of(ds), press_fit=PressFit.of(ds), processes=Processes.of(ds),
        wear=Wear.of(ds) if about.mechanics_engines else None, film_errors=FilmErrors.of(ds),
        sources=Sources.of(ds), limits=Limits.of(ds), run=Run.of(ds), ranking=ranking,
        scenario_rankings={label: ranking_rows(other, window=window, h_lim_cr=h_lim_cr,
                                               negligible=ranking.negligible)
                           for label, other in scenarios.items()},
        scenario_about={label: ScenarioAbout.of(other) for label, other in scenarios.items()},
        scrap=Scrap.of(clearance), clearance=clearance, fit=fit_summary(ds), usage=grade_usage(ds),
        centred=_centred(ds, ranking.window),
        reading_resolution={str(s): float(ds.reading_resolution.sel(scheme=s).max()) for s in ds.scheme.values},
        plan=None if about.summaries else plan(ds, volume=volume, service_level=PLAN_SERVICE_LEVEL),
        **_film_facts(ds), life_bias=life_bias(ds), drivers=drivers(sensitivity),
        design=designed(ds), life_changes=(changes := _life_changes(ds, scenarios)),
        trends=clearance_trends(ds) if about.mechanics_engines else None, corrected=multi_fidelity(ds),
        misalignment=_misalignment(scenarios, changes), iso=iso_caveats(ds))


def _misalignment(scenarios, changes):
    """(label, factor) of the first scenario in ``changes`` whose only key scales the misalignment, or None."""
    for label in changes:
        scenario = StudyParameters.of(scenarios[label]).scenario
        if set(scenario) == {"misalignment_scale"}:
            return label, float(scenario["misalignment_scale"])
    return None


def _life_changes(ds, scenarios):
    """Scenario -> :func:`~stackup.facts.tables.paired_life_changes` (per position, per engine), where it ran the
    mechanical chain."""
    changes = {label: paired_life_changes(ds, other) for label, other in scenarios.items()}
    return {label: pair for label, pair in changes.items() if pair[0] is not None}

