"""The report's ranking, film and life tables as CSV files for a spreadsheet (``stackup report --csv``).

The numbers the report's tables write as text, from the same facts
(:func:`stackup.facts.facts` of the saved datasets): one row per scheme (in
the ranking's order) or per scheme and main-bearing position, one column
per number, the unit in the column's name (``clearance_std [um]``), a 95 %
interval as two more columns (``... 95 % low [unit]``, ``... 95 % high
[unit]``). Nothing is rounded or sampled.

- ``ranking.csv``: :func:`stackup.rank.rank`'s table (rank, metrics with
  intervals, the worst change over the scenarios);
- ``film_life.csv``: per scheme, the film and life table of the report's
  "Loads, oil film and bearing life" (films, Levanov's criteria at the worst
  position, the engines' life);
- ``film_life_per_bearing.csv``: per scheme and position, the load, film and
  life (empty where the mechanical chain did not run).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..rank import ranked
from .sections import in_order

#: The CSV files :func:`write_tables` writes, in order.
FILES = ("ranking.csv", "film_life.csv", "film_life_per_bearing.csv")
#: A name's unit suffix and the unit its column names (ASCII: a spreadsheet opens the file in any code page).
SUFFIX_UNITS = {"_um": "um", "_ppm": "ppm", "_pct": "%", "_h": "h", "_kn": "kN"}
#: Columns whose name carries no unit suffix: their unit.
COUNT_UNITS = {"rank": "-", "bearings": "bearings", "outside_window_counted": "bearings", "shell_grades": "grades",
               "part_grades": "grades", "film_bearings": "bearings", "film_left_out": "bearings",
               "engines": "engines", "left_out": "bearings", "engines_left_out": "engines", "alpha_mean": "-",
               "bearing": "position", "alpha_over_limit_position": "position",
               "alpha_over_20_position": "position", "life_below_target_position": "position"}
#: Per-position load columns (facts.crank_summary) as this file names them.
LOAD_COLUMNS = {"mean_kn": "load_cycle_max_mean_kn", "ci_kn": "load_cycle_max_mean_half_width_kn",
                "max_kn": "load_cycle_max_highest_kn"}


def _named(column):
    """``(name, unit)``: a column's name without its unit suffix, and the unit (None for text)."""
    for suffix, unit in SUFFIX_UNITS.items():
        if column.endswith(suffix):
            return column[: -len(suffix)], unit
    return column, COUNT_UNITS.get(column)


def numbers(frame):
    """``frame``'s columns as CSV columns: units in the names; an interval (``*_ci``, a (low, high) pair) or a
    (value, low, high) triple as separate columns; text columns as they are."""
    out = {}
    for column in frame.columns:
        values = list(frame[column])
        if column.endswith("_ci"):
            name, unit = _named(column[:-3])
            parts = {"95 % low": 0, "95 % high": 1}
        elif any(isinstance(v, tuple) and len(v) == 3 for v in values):
            name, unit = _named(column)
            parts = {"": 0, "95 % low": 1, "95 % high": 2}
        else:
            name, unit = _named(column)
            out[f"{name} [{unit}]" if unit else name] = values
            continue
        for part, k in parts.items():
            label = f"{name} {part}".rstrip()
            out[f"{label} [{unit}]"] = [v[k] if isinstance(v, tuple) else np.nan for v in values]
    return pd.DataFrame(out, index=frame.index)


def tables(known):
    """``{file name: DataFrame}`` of :data:`FILES` from the :class:`~stackup.facts.Facts` ``known``."""
    ranking = ranked(known.ranking)
    ranking = ranking[["rank", *(c for c in ranking.columns if c != "rank")]]
    order = list(ranking.index)
    film = in_order(known.film, order) if len(known.film) else pd.DataFrame(index=pd.Index([], name="scheme"))
    if len(known.bearings):
        loads = known.crank.rename(columns=LOAD_COLUMNS)[list(LOAD_COLUMNS.values())]
        positions = in_order(known.bearings.join(loads), order)
    else:
        positions = pd.DataFrame(index=pd.MultiIndex.from_arrays([[], []], names=["scheme", "bearing"]))
    return {"ranking.csv": numbers(ranking), "film_life.csv": numbers(film),
            "film_life_per_bearing.csv": numbers(positions)}


def write_tables(known, folder):
    """Write :data:`FILES` into ``folder``; return their paths."""
    paths = []
    for name, frame in tables(known).items():
        path = folder / name
        frame.to_csv(path, encoding="utf-8")
        paths.append(path)
    return paths
