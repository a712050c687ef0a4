"""The designer's entry points: :func:`design` (a :class:`Design`, with what it found) and :func:`scheme`.

The stages in order: the design sample (:mod:`~stackup.design.problem`), the
ISO 13778 schemes on the engine's drawing as starts, the ladder of shell
grades (:mod:`~stackup.design.ladder`), the check sample
(:mod:`~stackup.design.assess`), the supply's process mean
(:func:`stackup.plan.optimise_supply`) and the notes
(:mod:`~stackup.design.explain`). The variables, objective and solvers:
:mod:`stackup.design`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np

from .. import _validate as check
from .._validate import InRange, Integer, Positive, Window, validated
from ..engines import load_engine
from ..patterns import ISO_SCHEMES, adapt
from ..plan import optimise_supply
from ..scenarios import DECLARED
from ..schemes import load as load_scheme
from .assess import CHECK_SAMPLES
from .assess import check as check_design
from .explain import notes
from .ladder import climb
from .objective import score
from .problem import LABELS, Weights, build_problem

#: Engines the optimal process mean of a sorted shell supply is stated for (stackup.plan.optimise_supply).
SUPPLY_VOLUME = 10_000


@dataclass(frozen=True)
class Design:
    """A designed scheme with what the designer found on its way.

    Attributes
    ----------
    scheme : Scheme
        The designed scheme; its ``notes`` explain the choices (written as comments by ``to_toml``).
    objective : float
        :math:`J` of the designed scheme on the design sample [-].
    outside : dict of str -> float
        Share of bearings outside the window per sample ("nominal" and each scenario) [-].
    check : Check
        The designed scheme on the check sample, which decided nothing: share outside the window per
        scenario with 95 % intervals, and :math:`J` (:class:`~stackup.design.assess.Check`).
    start : str
        Name of the scheme the design started from.
    start_objective : float
        Its :math:`J` with its preferred pairs, supply terms included (:meth:`Problem.expected_objective`) [-].
    start_outside : dict of str -> float
        Its share outside the window per sample [-].
    iso : dict of str -> dict of str -> float
        Share outside the window of every ISO 13778 scheme per sample [-].
    mean_clearance, start_mean_clearance : float
        Expected operating clearance of the designed and the start scheme [m].
    surplus, shortfall : numpy.ndarray (shell grades,)
        Planned shells per bearing left over and missing [-].
    aim_share : numpy.ndarray (shell grades,) or None
        Share of the shells made aimed at each grade, as the plan aims them for the design's
        demand (shells made to order).
    supply_mean : float
        Mean of one shell process sorted into the designed grades that minimises surplus and
        shortfall (:func:`stackup.plan.optimise_supply`) [m].
    supply_mean_objective, supply_centred_objective : float
        Surplus plus 10 x shortfall for :data:`SUPPLY_VOLUME` engines at that mean and with the
        process centred on the grades [shells].
    seconds : float
        Wall time of the design [s].
    evaluations : int
        Sets of housing and journal limits scored.
    levels : tuple of Step
        The ladder: the design of each number of shell grades up to this one
        (:class:`~stackup.design.ladder.Step`).
    """

    scheme: object
    objective: float
    outside: dict
    check: object
    start: str
    start_objective: float
    start_outside: dict
    iso: dict
    mean_clearance: float
    start_mean_clearance: float
    surplus: np.ndarray
    shortfall: np.ndarray
    aim_share: np.ndarray | None
    supply_mean: float
    supply_mean_objective: float
    supply_centred_objective: float
    seconds: float
    evaluations: int
    levels: tuple


def scheme(engine="iso-example", **options):
    """A selective-fitting scheme designed for ``engine`` (options: :func:`design`); its notes explain it."""
    return design(engine, **options).scheme


def _at_most_labels(values):
    """Each dimension has at most as many grades as there are grade labels."""
    for field in ("shell_grades", "housing_grades", "journal_grades"):
        if values[field] > len(LABELS):
            raise ValueError(f"{field}: {values[field]} is not valid; at most {len(LABELS)} grades")


@validated(window=Window(), shell_grades=Integer(minimum=1), housing_grades=Integer(minimum=1),
           journal_grades=Integer(minimum=1), n_engines=Integer(minimum=100),
           sort_share=InRange(0.0, 1.0, lo_open=True, hi_open=True), readout=Positive(),
           generations=Integer(minimum=0), relations=(_at_most_labels,))
def design(engine="iso-example", *, window=None, shell_grades=4, housing_grades=3, journal_grades=3,
           scenarios=DECLARED, seed=0, n_engines=4000, start=None, mixed_pairs=True, weights=Weights(),
           sort_share=0.5, readout=1e-7, generations=8, name=None, log=None):
    """Design a scheme for ``engine`` (:mod:`stackup.design`: variables, objective, solvers).

    Parameters
    ----------
    engine : str, path or Engine
    window : (float, float), optional
        Operating-clearance window [m]; default the engine's.
    shell_grades, housing_grades, journal_grades : int
        Grades of each dimension (1: ungraded housing or journal). Four
        shell grades by default: on the example engine the fewest that keep
        the worst declared scenario (gauge repeatability 2 um) below ISO
        13778 scheme 4's, the most robust ISO scheme, with 95 % intervals
        apart (reports/design_scheme.md).
    scenarios : dict of str -> dict
        Declared scenarios (:mod:`stackup.scenarios`); those that do not
        change the clearance are left out. Empty for none.
    seed : int
        Seed of the design sample (its own random stream, apart from a
        study's lots and pilot with the same seed).
    n_engines : int
        Engines of the design sample (per scenario, common random numbers).
    start : str, path or Scheme, optional
        Scheme to start from; default the ISO 13778 scheme with the lowest
        objective on the design sample. Its grades seed the search where
        the counts match.
    mixed_pairs : bool
        Allow a grade paired with the next one (upper of one, lower of the
        next: the intermediate pairs of ISO 13778).
    weights : Weights
        Weights of the worst scenario and of the planned surplus and shortfall.
    sort_share : float
        Smallest share of the parts (shells) at (aimed at) a grade's centre
        that must be read into that grade, in (0, 1): sets each dimension's
        narrowest grade (0.5: half-width 0.67 reading spreads).
    readout : float
        Step of the grid grade limits lie on [m] (the gauge's resolution if coarser).
    generations : int
        Generations of the differential evolution of the shell limits (0: Nelder-Mead from the best start only).
    name : str, optional
        Scheme name; default ``designed-<engine>``.
    log : callable, optional
        Called with one line of text per stage.

    Returns
    -------
    Design
    """
    t0 = time.perf_counter()
    log = log or (lambda line: None)
    engine = load_engine(engine)
    window = check.clearance_window("window", engine.clearance_window) if window is None else window
    scenarios = dict(scenarios or {})
    log(f"design sample: {n_engines:,} engines, nominal and {len(scenarios)} declared scenarios")
    problem = build_problem(engine, window=window, shell_grades=shell_grades, housing_grades=housing_grades,
                            journal_grades=journal_grades, scenarios=scenarios, seed=seed, n_engines=n_engines,
                            sort_share=float(sort_share), readout=float(readout), mixed=bool(mixed_pairs),
                            weights=weights)
    log("ISO 13778 schemes, laid on the engine's drawing, on the design sample")
    patterns = {k: adapt(k, engine) for k in ISO_SCHEMES}
    iso = {k: problem.expected(scheme) for k, scheme in patterns.items()}
    start_scheme = min(patterns.values(), key=problem.expected_objective) if start is None else load_scheme(start)
    name = name or f"designed-{engine.name}"
    levels = climb(problem, start_scheme, generations=generations, seed=seed, log=log, name=name)
    top = levels[-1]
    log(f"check sample: the designed scheme on {CHECK_SAMPLES} x {n_engines:,} engines no decision saw")
    checked = check_design(problem, top.scheme, seed=seed, n_engines=n_engines)
    log("process mean of a sorted shell supply (stackup.plan.optimise_supply)")
    offer = optimise_supply(top.scheme, engine, volume=SUPPLY_VOLUME, sample_engines=n_engines, seed=seed)
    result = _design(problem, top.scheme, start_scheme, top, iso=iso, check=checked, offer=offer, t0=t0,
                     levels=levels)
    lines = notes(result, problem=problem, start_scheme=start_scheme, chosen=start is None, seed=seed,
                  n_engines=n_engines)
    return replace(result, scheme=replace(top.scheme, notes=tuple(lines)))


def _design(problem, designed, start_scheme, top, *, iso, check, offer, t0, levels):
    """The :class:`Design` of the scheme ``designed`` (the ladder's ``top`` rung): its scores and the start
    scheme's on the design sample (``t0``: :func:`time.perf_counter` when the design began)."""
    nominal, window = problem.samples[0], problem.window
    start_outside = problem.expected(start_scheme)
    return Design(
        scheme=designed, objective=top.objective, outside=problem.expected(designed),
        check=check, start=start_scheme.name,
        start_objective=problem.expected_objective(start_scheme), start_outside=start_outside, iso=iso,
        mean_clearance=score(designed, nominal, window).mean_clearance,
        start_mean_clearance=score(start_scheme, nominal, window).mean_clearance,
        surplus=top.surplus, shortfall=top.shortfall, aim_share=top.aim, supply_mean=offer["mean"],
        supply_mean_objective=offer["objective"], supply_centred_objective=offer["centred_objective"],
        seconds=time.perf_counter() - t0, evaluations=sum(level.evaluations for level in levels),
        levels=tuple(level.step(k) for k, level in enumerate(levels, start=1)))
