"""The shell grades one at a time: each number of grades starts from the design with one grade fewer.

A design with ``k`` shell grades is found on a ladder: one grade, two, ...,
``k``, each rung searched as the module :mod:`stackup.design` describes,
with the rung below's design among its starts (the nested start): that
design with one grade split in two at its middle (every grade wide enough
to split, and a grade of the narrowest width added below or above the
range), the housing and journal limits of the rung below among the limits
tried. The rung's design is the search's result or the nested start,
whichever has the lower objective :math:`J` on the design sample.

More grades are never worse on :math:`J`: where a rung's best design does
worse on the design sample than the design kept below it (splitting a grade
need not help: the shells made to order are aimed anew, and a cell's pair
must name one of the two halves), the design kept below is kept again, with
fewer grades than asked, and the design's notes say so. Asked for ``k``
grades, the designer returns the best design of at most ``k`` grades it
found, never one worse than a design of fewer.

Why: the shell search is local (a short differential evolution from a few
starts); with five grades and a 3 x 3 matrix it found designs worse on its
own objective than the four-grade design (issue 31).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .._version import __version__
from ..schemes import from_dict
from .problem import LABELS
from .search import search_shells
from .session import Search
from .tables import nm

#: Nelder-Mead evaluations per shell grade limit after the differential evolution of the shell limits.
POLISH_PER_LIMIT = 10


@dataclass(frozen=True)
class Level:
    """The design of one rung of the ladder (``grades`` shell grades).

    Attributes
    ----------
    grades : int
        Shell grades of the design (fewer than the rung's where the design below was kept).
    found : Found
        The design (:class:`~stackup.design.session.Found`, without its cell tables).
    scheme : Scheme
        It as a scheme.
    surplus, shortfall : numpy.ndarray (grades,)
        Planned shells per bearing left over and missing on the design sample [-].
    aim : numpy.ndarray or None
        Share of the shells made aimed at each grade (shells made to order).
    objective : float
        :math:`J` on the design sample, supply terms included [-].
    origin : str
        "search", "nested start" (the rung's candidate kept) or "kept from N grades".
    candidates : dict of str -> float
        :math:`J` on the design sample of each candidate of the rung [-].
    evaluations : int
        Sets of housing and journal limits scored on the rung.
    """

    grades: int
    found: object
    scheme: object
    surplus: np.ndarray
    shortfall: np.ndarray
    aim: np.ndarray | None
    objective: float
    origin: str
    candidates: dict
    evaluations: int

    def step(self, asked):
        """What the rung of ``asked`` grades kept, without the search's tables: a :class:`Step`."""
        return Step(asked, self.grades, self.scheme, self.objective, self.origin, self.candidates)


@dataclass(frozen=True)
class Step:
    """One rung of the ladder as a design reports it.

    Attributes
    ----------
    asked : int
        Shell grades the rung searched.
    grades : int
        Shell grades of the design it kept (``asked`` unless the design below was kept).
    scheme : Scheme
    objective : float
        :math:`J` on the design sample [-].
    origin : str
    candidates : dict of str -> float
        :math:`J` of each of the rung's candidates on the design sample [-].
    """

    asked: int
    grades: int
    scheme: object
    objective: float
    origin: str
    candidates: dict


def climb(problem, start_scheme, *, generations, seed, log, name="designed"):
    """The rungs 1 to ``problem.shell_grades``: the design kept at each (list of :class:`Level`, :math:`J`
    never rising), each rung started from the rung below's own design."""
    kept, own = [], None
    for k in range(1, problem.shell_grades + 1):
        log(f"{k} shell grade{'s' if k > 1 else ''}: differential evolution and Nelder-Mead over {k + 1} limits"
            + (f", the {k - 1}-grade design split as a start" if own else ""))
        own = rung(replace(problem, shell_grades=k), start_scheme, own, generations=generations, seed=seed, log=log,
                   name=name)
        if kept and own.objective > kept[-1].objective:
            log(f"  {k} grades do worse than {kept[-1].grades} ({own.objective * 1e6:.4g} against "
                f"{kept[-1].objective * 1e6:.4g} ppm): the {kept[-1].grades}-grade design is kept")
            kept.append(replace(kept[-1], origin=f"kept from {kept[-1].grades} grades", candidates=own.candidates,
                                evaluations=own.evaluations))
        else:
            kept.append(own)
    return kept


def rung(problem, start_scheme, parent, *, generations, seed, log, name):
    """The :class:`Level` of ``problem.shell_grades`` grades, with the nested starts of ``parent`` (or None)."""
    x0 = _encode_start(start_scheme, problem) if parent is None else _encode_limits(parent.found, problem)
    search = Search(problem, seed=seed, x0=x0)
    nested = [] if parent is None else nested_starts(parent.found.edges, problem)
    relative = _search_shells(search, start_scheme, nested, generations=generations, seed=seed)
    candidates = {"search": search.finish(problem.on_grid(problem.centre + relative), log)}
    if nested:
        best = min(nested, key=lambda edges: search.evaluate(edges - problem.centre))
        if not np.array_equal(nm(best), nm(candidates["search"][0].edges)):
            search.x = _encode_limits(parent.found, problem)
            limits = [(parent.found.housing_edges, parent.found.journal_edges)]
            candidates["nested start"] = search.finish(best, log, limits=limits)
    total = {o: found.objective + problem.supply_cost(surplus, shortfall)
             for o, (found, surplus, shortfall, _) in candidates.items()}
    origin = min(total, key=total.get)
    found, surplus, shortfall, aim = candidates[origin]
    k = problem.shell_grades
    log(f"  {k} grade{'s' if k > 1 else ''}: J " + ", ".join(f"{o} {j * 1e6:.4g} ppm" for o, j in total.items())
        + f" on the design sample; kept: {origin}")
    return Level(problem.shell_grades, replace(found, tables=None), to_scheme(name, problem, found), surplus,
                 shortfall, aim, total[origin], origin, total, search.evaluations)


def nested_starts(edges, problem):
    """Shell limits [m] of ``problem.shell_grades`` grades from the limits ``edges`` of one grade fewer: each
    grade at least twice the narrowest split at its middle (on the shell grid), and a grade of the narrowest
    width added below and above the range."""
    grid = max(int(nm(problem.shell_step)), 1)
    narrowest = int(np.ceil(nm(problem.min_width) / grid - 1e-9)) * grid
    e = nm(edges)
    starts = []
    for g in range(e.size - 1):
        middle = int(np.rint(0.5 * (e[g] + e[g + 1]) / grid)) * grid
        if middle - e[g] >= narrowest and e[g + 1] - middle >= narrowest:
            starts.append(np.insert(e, g + 1, middle))
    starts += [np.concatenate(([e[0] - narrowest], e)), np.concatenate((e, [e[-1] + narrowest]))]
    return [s * 1e-9 for s in starts]


def _search_shells(search, start_scheme, nested, *, generations, seed):
    """Shell limits relative to the centring wall [m] from the differential evolution and Nelder-Mead of
    :func:`search_shells`: starts of equal grades from the narrowest sortable width to a wide one, the
    start scheme's grades where their count matches, and the ``nested`` starts [m]."""
    problem = search.problem
    k_s = problem.shell_grades
    wide = max(2 * problem.min_width, problem.span / max(problem.levels - 1, 1) * (1 if problem.mixed else 2))
    starts = [(np.arange(k_s + 1) - 0.5 * k_s) * w for w in np.linspace(problem.min_width, wide, 4)]
    start_edges = _start_shells(start_scheme, k_s, problem.min_width)
    if start_edges is not None:
        starts.append(start_edges - problem.centre)
    starts += [edges - problem.centre for edges in nested]
    return search_shells(search.evaluate, starts, lower=np.array([-0.5 * wide] + [problem.min_width] * k_s),
                         upper=np.array([0.5 * wide] + [2 * wide] * k_s), generations=generations,
                         polish=POLISH_PER_LIMIT * (k_s + 1), seed=seed)


def _encode_limits(found, problem):
    """The housing and journal limits of ``found`` as a point of the search cube (None if a grade is too narrow)."""
    parts = [problem.housing.encode(found.housing_edges), problem.journal.encode(found.journal_edges)]
    return None if any(p is None for p in parts) else np.concatenate(parts)


def _encode_start(start, problem):
    """The start scheme's housing and journal limits as a point of the search cube, where the counts match."""
    parts = []
    for grades, limits, grid in ((start.housing, problem.housing, problem.housing_grid),
                                 (start.journal, problem.journal, problem.journal_grid)):
        if grades.fine or len(grades.labels) != limits.grades:
            return None
        lo, hi = grades.bins()
        index = np.clip(np.searchsorted(grid.edges, nm(np.append(np.sort(lo), hi.max()))), 0, grid.bins)
        index[0], index[-1] = 0, grid.bins
        point = limits.encode(index)
        if point is None:
            return None
        parts.append(point)
    return np.concatenate(parts)


def _start_shells(start, k, min_width):
    """The start scheme's shell limits [m] if it has ``k`` grades no narrower than ``min_width`` (overlaps split)."""
    if len(start.shell.labels) != k or not start.shell.graded:
        return None
    lo, hi = start.shell.bins()
    edges = np.append(np.sort(lo), hi.max())
    if np.any(np.diff(edges) < min_width - 1e-12):
        return None
    return edges


def to_scheme(name, problem, found):
    """The designed scheme of a :class:`~stackup.design.session.Found` design."""
    engine, window = problem.engine, problem.window

    def mm(value_m):
        return float(nm(value_m)) / 1e6

    def dimension(grid, edges, limits):
        if len(edges) == 2:
            return {"limits": [mm(limits[0]), mm(limits[1])]}
        metres = grid.metres(np.asarray(edges))
        return {"grades": {LABELS[k]: [mm(metres[k]), mm(metres[k + 1])] for k in range(len(edges) - 1)}}

    housing = dimension(problem.housing_grid, found.housing_edges, (engine.housing_bore.lo, engine.housing_bore.hi))
    journal = dimension(problem.journal_grid, found.journal_edges, (engine.journal_d.lo, engine.journal_d.hi))
    k_s = len(found.edges) - 1
    shell = {"grades": {LABELS[k]: [mm(found.edges[k]), mm(found.edges[k + 1])] for k in range(k_s)}}
    h_labels = list(housing.get("grades", {"-": None}))
    j_labels = list(journal.get("grades", {"-": None}))
    up, lo = found.upper, found.lower
    table = {jl: {hl: f"{LABELS[up[h, j]]}+{LABELS[lo[h, j]]}" for h, hl in enumerate(h_labels)}
             for j, jl in enumerate(j_labels)}
    data = {"name": name,
            "title": f"Designed for {engine.name}: {len(h_labels)} x {len(j_labels)} matrix, {k_s} shell grades",
            "source": (f"stackup {__version__} stackup.design for engine {engine.name!r}, operating-clearance "
                       f"window {window[0] * 1e6:.4g}-{window[1] * 1e6:.4g} um"),
            "units": "mm", "housing": housing, "journal": journal, "shell": shell, "pairing": {"table": table}}
    return from_dict(data)
