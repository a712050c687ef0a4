"""The pilot sample a study plans its shells from: per-engine demand, the lot's aim and where shells land.

Shells are made per lot before the lot's engines are known, so their grade
quantities are planned from a pilot sample of engines drawn from its own
random stream (:data:`stackup._random.PILOT_KEY`). The study, the planner
(:mod:`stackup.plan`) and the tail estimator (:mod:`stackup.tail`) all plan
through :func:`shell_plan`; :func:`grading` says how much of the pilot a scheme grades, so a
scheme that leaves parts ungraded is refused before a study starts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import stats

from .._random import PILOT_KEY, lot_generator, seed_sequence
from ..assembly import shell_demand_per_engine
from ..parts import draw_lot


@dataclass(frozen=True)
class ShellPlan:
    """A scheme's shell plan from a pilot sample.

    Attributes
    ----------
    demand_per_engine : numpy.ndarray (engines, grades)
        Shells of each grade each pilot engine's preferred pairs ask for.
    aim : numpy.ndarray (grades,) or None
        Share of a lot aimed at each grade (shells made to order); None for
        one process sorted into grades.
    landing : numpy.ndarray (grades,)
        Share of the shell production read into each grade (the rest is scrap).
    """

    demand_per_engine: np.ndarray
    aim: np.ndarray | None
    landing: np.ndarray

    @property
    def demand(self):
        """Shells of each grade the whole pilot asks for (grades,)."""
        return self.demand_per_engine.sum(axis=0)


def pilot_parts(engine, seed, engines):
    """The pilot sample of ``engines`` engines of a study with root ``seed``."""
    parts, _ = draw_lot(engine, lot_generator(seed_sequence(seed), PILOT_KEY), engines)
    return parts


def shell_plan(engine, scheme, pilot):
    """Demand, aim and landing share of ``scheme``'s shell grades for ``engine``, from the ``pilot`` parts.

    Raises ValueError when no pilot bearing can be graded (the scheme's ranges
    miss the engine's drawing limits).
    """
    per_engine = shell_demand_per_engine(scheme, pilot)
    demand = per_engine.sum(axis=0)
    if demand.sum() == 0:
        raise ValueError(f"scheme {scheme.name}: no bearing of the pilot sample could be graded; "
                         "do the scheme's ranges match the engine's drawing limits?")
    supply = engine.shell_wall
    if supply.mode == "to-order":
        aim = supply.aim_share(scheme, demand)
        landing = supply.spill(scheme) @ aim
    else:
        aim = None
        dim = supply.dimension(scheme)
        lo, hi = scheme.shell.bins()
        spread = np.hypot(dim.process.std, supply.gauge.repeatability)
        landing = stats.norm.cdf(hi, dim.process.mean, spread) - stats.norm.cdf(lo, dim.process.mean, spread)
    return ShellPlan(per_engine, aim, landing)


@dataclass(frozen=True)
class Grading:
    """How much of a pilot sample a scheme grades: shares of the bearings whose parts are inside their drawing
    limits (the others are scrapped, not graded) that no grade of the scheme takes [-].

    Attributes
    ----------
    ungraded : float
        Share of those bearings not graded (housing or journal read outside every grade).
    housing, journal : float
        Share whose housing bore, or journal, is read outside every grade.
    """

    ungraded: float
    housing: float
    journal: float

    def where(self, scheme, engine):
        """In words: which readings the scheme's grades miss, against the engine's drawing limits."""
        parts = []
        for name, share, drawing in (("housing bores", self.housing, engine.housing_bore),
                                     ("journals", self.journal, engine.journal_d)):
            if share > 0:
                grades = scheme.housing if name == "housing bores" else scheme.journal
                lo, hi = grades.bins()
                parts.append(f"{100 * share:.2g} % of the {name} read outside its grades {lo.min() * 1e3:.4f}-"
                             f"{hi.max() * 1e3:.4f} mm (the engine's drawing: {drawing.lo * 1e3:.4f}-"
                             f"{drawing.hi * 1e3:.4f} mm)")
        return "; ".join(parts)


def grading(scheme, pilot):
    """The :class:`Grading` of ``scheme`` on the ``pilot`` parts (what a study's grading stage will fail on)."""
    housing, journal = scheme.grade_indices(pilot.housing_reading, pilot.journal_reading)
    built = np.broadcast_to(~(pilot.block_scrapped | pilot.crank_scrapped)[:, None], housing.shape)
    count = max(int(built.sum()), 1)
    return Grading(ungraded=float(np.sum(built & ((housing < 0) | (journal < 0))) / count),
                   housing=float(np.sum(built & (housing < 0)) / count),
                   journal=float(np.sum(built & (journal < 0)) / count))
