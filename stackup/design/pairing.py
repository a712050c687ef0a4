"""The pairing table as a mixed-integer programme (HiGHS through scipy.optimize.milp).

Each cell (housing grade x journal grade) takes one shell pair. The
programme minimises

.. math:: \\sum_{c,p} x_{cp} P^0_{cp} + \\lambda\\,t + w_s \\sum_g u_g + w_o \\sum_g o_g,
          \\qquad t \\ge \\sum_{c,p} x_{cp} P^s_{cp} \\;\\forall s

with :math:`x_{cp} \\in \\{0, 1\\}`, one pair per cell; :math:`P^s_{cp}` the
share of sample *s*'s bearings that are in cell *c* and outside the window
with pair *p* (*s* = 0 nominal, the others the declared scenarios), so *t*
is the worst scenario's share; and the planned shell supply per bearing
against the demand the pairing makes, :math:`\\text{supply}_g - D_g(x) = u_g - o_g`
(surplus *u*, shortfall *o*). Shells made to order are planned by the aim
shares *q* (continuous, :math:`\\sum q = 1`) through the supply's spill
matrix, :math:`\\text{supply} = M\\,S\\,q` with *M* shells made per bearing;
shells of one process sorted into grades land in fixed shares.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy import optimize, sparse


@dataclass(frozen=True)
class PairingResult:
    """The chosen pair of every cell and the terms of the objective.

    Attributes
    ----------
    pair : numpy.ndarray (housing grades, journal grades)
        Index into the allowed pairs.
    share : numpy.ndarray (samples,)
        Share of each sample's bearings outside the window [-].
    surplus, shortfall : numpy.ndarray (grades,)
        Planned shells per bearing left over and missing [-].
    aim_share : numpy.ndarray (grades,) or None
        Share of the shells made aimed at each grade (made to order).
    objective : float
    """

    pair: np.ndarray
    share: np.ndarray
    surplus: np.ndarray
    shortfall: np.ndarray
    aim_share: np.ndarray | None
    objective: float


def choose_pairs(outside, count, pairs, n_grades, *, scenario_weight, surplus_weight, shortfall_weight,
                 shells_per_bearing, spill=None, landing=None, tie=None):
    """Solve the pairing programme (module docstring) for fixed grades.

    Parameters
    ----------
    outside : numpy.ndarray (samples, pairs, housing grades, journal grades)
        Share of each sample's bearings in the cell and outside the window with the pair [-].
    count : numpy.ndarray (housing grades, journal grades)
        Share of the nominal sample's bearings in each cell [-].
    pairs : Pairs
        Allowed pairs (``upper``, ``lower`` grade indices).
    n_grades : int
    scenario_weight, surplus_weight, shortfall_weight : float
        Weights of the worst scenario's share, of the planned surplus and of the shortfall [-].
    shells_per_bearing : float
        Shells made per bearing (two plus the planned surplus) [-].
    spill : numpy.ndarray (grades, grades), optional
        Probability that a shell aimed at grade g is read into grade g' (g', g): shells made to order.
    landing : numpy.ndarray (grades,), optional
        Share of the shells made that land in each grade: one process sorted into grades.
    tie : numpy.ndarray like ``outside[0]``, optional
        Tie-break cost added to the nominal share.
    """
    n_samples, n_pairs, nh, nj = outside.shape
    to_order = spill is not None
    columns = _Columns.of(n_pairs, nh * nj, n_grades, to_order)
    nx, i_t, i_q, i_u, i_o, nv = columns
    cost = np.zeros(nv)
    cost[:nx] = (outside[0] + (0.0 if tie is None else tie)).reshape(n_pairs, nh * nj).ravel()
    cost[i_t] = scenario_weight if n_samples > 1 else 0.0
    cost[i_u:i_o] = surplus_weight
    cost[i_o:] = shortfall_weight
    a, lb, ub = _constraints(columns, outside, count, pairs, n_grades, shells_per_bearing, spill, landing)
    integrality = np.zeros(nv)
    integrality[:nx] = 1
    upper = np.full(nv, np.inf)
    upper[:nx] = 1.0
    result = optimize.milp(cost, constraints=optimize.LinearConstraint(a, lb, ub),
                           integrality=integrality, bounds=optimize.Bounds(np.zeros(nv), upper))
    if not result.success:
        raise RuntimeError(f"pairing: the HiGHS MILP did not solve ({result.message})")
    x = result.x[:nx].reshape(n_pairs, nh * nj)
    pair = np.argmax(x, axis=0).reshape(nh, nj)
    per_sample = np.take_along_axis(outside, pair[None, None], axis=1)[:, 0].sum(axis=(-2, -1))
    return PairingResult(pair, per_sample, result.x[i_u:i_o], result.x[i_o:],
                         result.x[i_q:i_u] if to_order else None, float(result.fun))


class _Columns(NamedTuple):
    """Where the programme's variables sit: x (pair-major, ``nx``), t, [q], surplus, shortfall; ``nv`` in all."""

    nx: int
    t: int
    q: int
    surplus: int
    shortfall: int
    nv: int

    @classmethod
    def of(cls, n_pairs, cells, n_grades, to_order):
        nx = n_pairs * cells
        i_u = nx + 1 + (n_grades if to_order else 0)
        return cls(nx, nx, nx + 1, i_u, i_u + n_grades, i_u + 2 * n_grades)


def _constraints(columns, outside, count, pairs, n_grades, shells_per_bearing, spill, landing):
    """The programme's constraint matrix (CSR) and its lower and upper bounds (module docstring)."""
    n_samples, n_pairs, nh, nj = outside.shape
    cells = nh * nj
    nx, i_t, i_q, i_u, i_o, nv = columns
    rows, lb, ub = [], [], []

    def row(entries, lo, hi):
        rows.append(entries)
        lb.append(lo)
        ub.append(hi)

    pair_of = np.repeat(np.arange(n_pairs), cells)
    cell_of = np.tile(np.arange(cells), n_pairs)
    for c in range(cells):  # one pair per cell
        row({k: 1.0 for k in np.flatnonzero(cell_of == c)}, 1.0, 1.0)
    for s in range(1, n_samples):  # t above every scenario's share
        entries = dict(enumerate(outside[s].reshape(n_pairs, cells).ravel()))
        entries[i_t] = -1.0
        row(entries, -np.inf, 0.0)
    uses = np.zeros((n_pairs, n_grades))
    np.add.at(uses, (np.arange(n_pairs), pairs.upper), 1.0)
    np.add.at(uses, (np.arange(n_pairs), pairs.lower), 1.0)
    share = count.ravel()
    for g in range(n_grades):  # supply - demand = surplus - shortfall
        entries = {k: -uses[pair_of[k], g] * share[cell_of[k]] for k in range(nx) if uses[pair_of[k], g]}
        entries[i_u + g] = -1.0
        entries[i_o + g] = 1.0
        if spill is not None:
            for h in range(n_grades):
                entries[i_q + h] = shells_per_bearing * spill[g, h]
            row(entries, 0.0, 0.0)
        else:
            row(entries, -shells_per_bearing * landing[g], -shells_per_bearing * landing[g])
    if spill is not None:
        row({i_q + h: 1.0 for h in range(n_grades)}, 1.0, 1.0)
    a = sparse.lil_array((len(rows), nv))
    for r, entries in enumerate(rows):
        for k, v in entries.items():
            a[r, k] = v
    return a.tocsr(), lb, ub
