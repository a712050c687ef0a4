"""Selective assembly: grade the parts, pair them by a scheme, take shells from stock.

For each bearing in assembly order the scheme's preferred shell pair is taken
from the lot's per-grade bins; when a bin runs short the scheme's allowed
alternatives (e.g. A+C for B+B) are tried in order, and a bearing for which no
allowed pair is in stock is a stock-out. Grading uses the *readings*, the
clearance the *true* sizes, so gauge error turns into clearance spread.

The nominal diametral clearance (ISO 13778, no housing swell) is

.. math:: C = D_H - (s_{upper} + s_{lower} + D_J)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._kernels.stock import take_shells

#: Status of a bearing, stored as an int8 ``status`` with CF flag attributes.
STATUS = ("assembled", "block_scrapped", "crank_scrapped", "not_graded", "shell_stockout")
ASSEMBLED, BLOCK_SCRAPPED, CRANK_SCRAPPED, NOT_GRADED, SHELL_STOCKOUT = range(len(STATUS))


@dataclass(frozen=True)
class Assembly:
    """Bearings of a run of lots assembled by one scheme; arrays (engines, bearings) unless noted."""

    housing_grade: np.ndarray  # grade index, -1 where not graded
    journal_grade: np.ndarray
    upper_grade: np.ndarray  # shell grade index taken, -1 where none
    lower_grade: np.ndarray
    upper_wall: np.ndarray  # true wall [m], NaN where no shell (see status)
    lower_wall: np.ndarray
    upper_crush: np.ndarray  # crush height [m], NaN where no shell
    lower_crush: np.ndarray
    clearance: np.ndarray  # nominal diametral clearance [m], NaN where not assembled (see status)
    option: np.ndarray  # allowed pair used: 0 preferred, k > 0 alternative, -1 none
    status: np.ndarray  # int8 code into STATUS
    shells_made: np.ndarray  # (grades,) shells sorted into each grade
    shells_scrapped: int  # shells read outside every grade
    shells_used: np.ndarray  # (grades,)
    shells_left: np.ndarray  # (grades,) left in the bins at the ends of the lots


def shell_demand_per_engine(scheme, parts):
    """Shells of each grade each engine's preferred pairs ask for (engines, grades); built, gradable bearings only."""
    up, lo = scheme.pair_indices(*scheme.grade_indices(parts.housing_reading, parts.journal_reading))
    built = ~(parts.block_scrapped | parts.crank_scrapped)[:, None] & (up >= 0)
    grades = np.arange(len(scheme.shell.labels))
    return (np.sum(built[..., None] & (up[..., None] == grades), axis=1)
            + np.sum(built[..., None] & (lo[..., None] == grades), axis=1))


def shell_demand(scheme, parts):
    """Shells of each grade that ``scheme``'s preferred pairs ask for, for ``parts`` (grades,)."""
    return shell_demand_per_engine(scheme, parts).sum(axis=0)


def assemble(scheme, parts, shells, *, lot_engines):
    """Assemble the bearings of consecutive lots with ``scheme``.

    Parameters
    ----------
    scheme : Scheme
    parts : BlockParts
        Blocks and crankshafts of the lots, concatenated along engines.
    shells : list of Shells
        The shells made for ``scheme`` in each lot, in lot order.
    lot_engines : int
        Engines per lot (the last lot may be shorter).
    """
    n, b = parts.housing_bore.shape
    h_idx, j_idx = scheme.grade_indices(parts.housing_reading, parts.journal_reading)
    preferred = scheme.pair_code(h_idx, j_idx)

    status = np.full((n, b), ASSEMBLED, dtype=np.int8)
    status[(h_idx < 0) | (j_idx < 0)] = NOT_GRADED
    status[parts.crank_scrapped] = CRANK_SCRAPPED
    status[parts.block_scrapped] = BLOCK_SCRAPPED

    n_grades = len(scheme.shell.labels)
    code = np.where(status == ASSEMBLED, preferred, -1).ravel()
    lot_starts = np.append(np.arange(0, n, lot_engines), n) * b
    shell_starts = np.cumsum([0, *(s.grade.size for s in shells)])
    wall = np.concatenate([s.wall for s in shells])
    crush = np.concatenate([s.crush for s in shells])
    grade = np.concatenate([s.grade for s in shells]).astype(np.int64)
    up_i, lo_i, option, left = take_shells(
        code, lot_starts.astype(np.int64), scheme.option_table, grade,
        shell_starts.astype(np.int64), n_grades,
    )
    taken = up_i >= 0
    status.ravel()[(code >= 0) & ~taken] = SHELL_STOCKOUT

    def pick(index, values, fill):
        return np.where(index >= 0, values[np.maximum(index, 0)], fill).reshape(n, b)

    upper_wall = pick(up_i, wall, np.nan)
    lower_wall = pick(lo_i, wall, np.nan)
    clearance = np.where(
        status == ASSEMBLED, parts.housing_bore - (upper_wall + lower_wall + parts.journal_d), np.nan
    )
    made = np.bincount(grade[grade >= 0], minlength=n_grades)
    used_idx = np.concatenate([up_i[taken], lo_i[taken]])
    return Assembly(
        housing_grade=h_idx,
        journal_grade=j_idx,
        upper_grade=pick(up_i, grade, -1),
        lower_grade=pick(lo_i, grade, -1),
        upper_wall=upper_wall,
        lower_wall=lower_wall,
        upper_crush=pick(up_i, crush, np.nan),
        lower_crush=pick(lo_i, crush, np.nan),
        clearance=clearance,
        option=option.reshape(n, b),
        status=status,
        shells_made=made,
        shells_scrapped=int(np.count_nonzero(grade < 0)),
        shells_used=np.bincount(grade[used_idx], minlength=n_grades),
        shells_left=left.sum(axis=0),
    )
