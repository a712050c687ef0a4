"""Measured data in: reading a CSV table and refusing bad data with the file, the column, the row and what is valid.

A message names where the data came from (:class:`Where`): the file and the
column and the file's line of each value when they were read from a CSV file
(:func:`read_csv`), ``values`` and an index when a program passed an array::

    ValueError: 'bores.csv', column 'bore', line 17: 'n/a' is not a number (text in a numeric column)
    ValueError: 'bores.csv', column 'bore': 3 values look like um, not mm like the limits (lines 5, 9, 40: 50009, ...)
"""

from __future__ import annotations

import csv
import difflib
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .._files import UNITS as LENGTH_UNITS
from .._validate import IT1_PER_SIZE, PLAUSIBLE

#: Spellings of a missing reading in a CSV cell (compared in lower case).
MISSING = ("", "nan", "na", "n/a", "null", "none", "-")
#: Farthest a reading may lie from its drawing limits, in tolerance widths, before it is taken for a typing
#: or unit error (a scrapped part lies a few widths out at most).
FARTHEST = 10.0
#: Fewest different readings a fit needs: fewer means a gauge resolution as coarse as the spread.
MIN_DISTINCT = 4
#: Length units measured data may be written in, in the order a unit slip is looked for, and how messages spell
#: them.
UNIT_NAMES = {"m": "m", "mm": "mm", "um": "µm"}
#: Their sizes [m per unit], from the one table of length units.
UNITS = {unit: LENGTH_UNITS[unit] for unit in UNIT_NAMES}
#: An inch [m]: not a unit measured data may be written in, but one they are found in.
INCH = 25.4e-3


@dataclass(frozen=True)
class Where:
    """Where values came from, for messages: file (or None), column, and the file line of each value."""

    file: str | None = None
    column: str = "values"
    lines: np.ndarray | None = None

    def __str__(self):
        return f"{self.file!r}, column {self.column!r}" if self.file else self.column

    def rows(self, index, most=5):
        """The rows of ``index`` (array of positions) as text: file lines, or indices into the array."""
        index = np.asarray(index)
        shown = [str(int(self.lines[i])) if self.lines is not None else str(int(i)) for i in index[:most]]
        more = f" and {index.size - most} more" if index.size > most else ""
        noun = ("line", "lines") if self.lines is not None else ("index", "indices")
        return f"{noun[index.size > 1]} {', '.join(shown)}{more}"

    def sub(self, column):
        """The same source, another column."""
        return Where(self.file, column, self.lines)


@dataclass(frozen=True)
class Columns:
    """Columns read from a CSV file: ``values[name]`` arrays, the file ``lines`` of the rows, rows ``dropped``."""

    file: str
    values: dict
    lines: np.ndarray
    dropped: int = 0
    dropped_lines: tuple = ()

    def where(self, column):
        return Where(self.file, column, self.lines)


def read_csv(path, *, numeric=(), text=(), drop_missing=False):
    """Read the named columns of a CSV file (comma, semicolon or tab separated; ``#`` lines are comments).

    Parameters
    ----------
    path : str or path
    numeric : sequence of str
        Columns of numbers (returned as float arrays).
    text : sequence of str
        Columns of labels (group names; returned as arrays of str).
    drop_missing : bool
        Leave out rows with an empty or NaN cell in a numeric column (counted
        in :attr:`Columns.dropped`); otherwise they are refused.

    Returns
    -------
    Columns
    """
    path = Path(path)
    name = path.name
    if not path.is_file():
        raise ValueError(f"{str(path)!r}: {'is a folder' if path.is_dir() else 'does not exist'}; give a CSV file")
    if path.suffix.lower() == ".toml":  # an engine or scheme file given where the readings go
        raise ValueError(f"{name!r}: is a TOML file (an engine or scheme file?), not a CSV file of readings")
    raw = path.read_bytes()
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):  # what spreadsheets save as "Unicode text"
        raise ValueError(f"{name!r}: is UTF-16 text (its byte-order mark says so); save it as UTF-8 CSV")
    try:
        body = raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise ValueError(f"{name!r}: is not UTF-8 text (byte {error.start}); save it as UTF-8 CSV") from None
    rows = [(k, line) for k, line in enumerate(body.splitlines(), start=1)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise ValueError(f"{name!r}: holds no header line and no data")
    delimiter = _delimiter(rows[0][1])
    parsed = list(csv.reader([line for _, line in rows], delimiter=delimiter))
    header = [h.strip() for h in parsed[0]]
    twice = sorted({h for h in header if h and header.count(h) > 1})
    if twice:
        raise ValueError(f"{name!r}: column {twice[0]!r} is given {header.count(twice[0])} times in the header "
                         f"(line {rows[0][0]}); name each column once")
    # a row's cells beyond the header's: refused unless empty (a trailing delimiter, as some exports write)
    long = [(rows[i][0], len(row)) for i, row in enumerate(parsed[1:], start=1)
            if any(cell.strip() for cell in row[len(header):])]
    if long:
        line, cells = long[0]
        shown = f" (and {len(long) - 1} more rows)" if len(long) > 1 else ""
        comma = " (a decimal comma?)" if delimiter == "," else ""
        raise ValueError(f"{name!r}, line {line}: {cells} cells, the header has {len(header)}{shown}; a cell too "
                         f"many{comma} or a header column missing")
    wanted = list(numeric) + list(text)
    for column in wanted:
        if column not in header:
            close = difflib.get_close_matches(column, header, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise ValueError(f"{name!r}: no column {column!r}{hint}; its columns: {', '.join(header)}")
    data_lines = np.array([k for k, _ in rows[1:]], dtype=int)
    if data_lines.size == 0:
        raise ValueError(f"{name!r}: has a header but no data rows")
    cells = {c: [row[header.index(c)].strip() if header.index(c) < len(row) else "" for row in parsed[1:]]
             for c in wanted}
    values = {c: _numbers(name, c, cells[c], data_lines, delimiter) for c in numeric}
    missing = np.zeros(data_lines.size, bool)
    for c in numeric:
        missing |= np.isnan(values[c])
    for c in text:
        empty = np.array([v == "" for v in cells[c]])
        missing |= empty
        values[c] = np.array(cells[c], dtype=str)
    if missing.any() and not drop_missing:
        bad = np.flatnonzero(missing)
        raise ValueError(f"{name!r}: {bad.size} row{'s' if bad.size > 1 else ''} with an empty or NaN cell in "
                         f"{', '.join(repr(c) for c in wanted)} ({Where(name, '', data_lines).rows(bad)}); fill "
                         f"them, or leave those rows out (--drop-missing)")
    keep = ~missing
    return Columns(name, {c: v[keep] for c, v in values.items()}, data_lines[keep], int(missing.sum()),
                   tuple(int(k) for k in data_lines[missing]))


def _delimiter(header):
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    best = max(counts, key=counts.get)
    return best if counts[best] else ","


def _numbers(name, column, cells, lines, delimiter):
    """Floats of a column's cells; NaN where missing; text refused naming the line."""
    out = np.empty(len(cells))
    for i, cell in enumerate(cells):
        if cell.lower() in MISSING:
            out[i] = np.nan
            continue
        try:
            out[i] = float(cell)
        except ValueError:
            hint = " (write decimals with a point: 50.009, not 50,009)" if delimiter != "," and "," in cell else ""
            raise ValueError(f"{name!r}, column {column!r}, line {lines[i]}: {cell!r} is not a number (text in a "
                             f"numeric column){hint}") from None
        if not math.isfinite(out[i]):
            raise ValueError(f"{name!r}, column {column!r}, line {lines[i]}: {cell!r} is not a finite number")
    return out


# --- checks of a measured sample --------------------------------------------------------------------------

def finite_values(values, where):
    """``values`` as a 1-D float array; NaN, inf and text refused with their rows."""
    raw = np.asarray(values)
    if raw.dtype.kind in "USOb":
        for i, v in enumerate(raw.ravel()):
            if isinstance(v, (str, bytes, bool, np.bool_)) or v is None:
                raise ValueError(f"{where}, {where.rows([i])}: {v!r} is not a number")
    x = np.asarray(values, dtype=float)
    if x.ndim != 1:
        raise ValueError(f"{where}: shape {x.shape} is not valid; give one value per part (a 1-D array)")
    bad = np.flatnonzero(~np.isfinite(x))
    if bad.size:
        raise ValueError(f"{where}: {bad.size} NaN or infinite value{'s' if bad.size > 1 else ''} "
                         f"({where.rows(bad)}); remove or fill them")
    return x


def drawing_limits(limits, *, field, units):
    """(lo, hi) from a pair, refused when not two finite numbers in increasing order."""
    try:
        lo, hi = (float(v) for v in limits)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: {limits!r} is not a (lower, upper) pair of drawing limits") from None
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise ValueError(f"{field}: ({lo!r}, {hi!r}) are not finite numbers")
    if hi < lo:
        raise ValueError(f"{field}: upper limit {hi:g} {units} is below lower limit {lo:g} {units}; give the lower "
                         "limit first")
    if hi == lo:
        raise ValueError(f"{field}: [{lo:g}, {hi:g}] {units} is a tolerance of zero width; give both limits")
    return lo, hi


def plausible(x, lo, hi, where, units):
    """Refuse readings far off the drawing limits: a unit slip (mm read as um, m) or a typing error."""
    width = hi - lo
    far = np.flatnonzero((x < lo - FARTHEST * width) | (x > hi + FARTHEST * width))
    if not far.size:
        return
    shown = ", ".join(f"{x[i]:g}" for i in far[:3])
    for unit, size in UNITS.items():
        factor = UNITS.get(units, 1.0) / size  # a length written in `unit` reads `factor` times larger
        scaled = x[far] / factor
        if unit != units and np.all((scaled >= lo - FARTHEST * width) & (scaled <= hi + FARTHEST * width)):
            raise ValueError(f"{where}: {far.size} value{'s' if far.size > 1 else ''} look{'s' if far.size == 1 else ''}"
                             f" like {UNIT_NAMES[unit]}, not {UNIT_NAMES.get(units, units)} like the limits "
                             f"[{lo:g}, {hi:g}] ({where.rows(far)}: {shown}); give every value and the limits in "
                             "one unit")
    inches = x[far] * INCH / UNITS.get(units, 1.0)
    if np.all((inches >= lo - FARTHEST * width) & (inches <= hi + FARTHEST * width)):
        raise ValueError(f"{where}: {far.size} value{'s' if far.size > 1 else ''} look{'s' if far.size == 1 else ''} "
                         f"like inches, not {UNIT_NAMES.get(units, units)} like the limits [{lo:g}, {hi:g}] "
                         f"({where.rows(far)}: {shown}); give them in {UNIT_NAMES.get(units, units)} (inches x 25.4)")
    raise ValueError(f"{where}: {far.size} value{'s' if far.size > 1 else ''} more than {FARTHEST:g} tolerance widths "
                     f"off the limits [{lo:g}, {hi:g}] {UNIT_NAMES.get(units, units)} ({where.rows(far)}: {shown}); "
                     "a typing error, another dimension's column, or wrong limits?")


def tolerance_in_units(lo, hi, units):
    """Refuse drawing limits [lo, hi] (in ``units``) whose tolerance no part is made to: a unit slip (mm readings
    given with --units um), naming the unit that makes it one."""
    plausible = PLAUSIBLE["tolerance_width"]

    def fits(size):  # the limits read in a unit of `size` m: a tolerance no finer than IT1 of that size
        width, big = (hi - lo) * size, max(abs(lo), abs(hi)) * size
        return plausible.lo + IT1_PER_SIZE * big <= width <= plausible.hi

    if fits(UNITS[units]):
        return
    # the likelier slips first: um and mm swapped, inches, then metres (a part of metres is rare)
    likely = [u for u in ("um", "mm", "in", "m") if u != units and fits(INCH if u == "in" else UNITS[u])]
    hint = "are the limits right?"
    if likely and likely[0] == "in":
        hint = "are the readings and limits in inches? give them in mm (inches x 25.4)"
    elif likely:
        hint = f"are the readings and limits in {UNIT_NAMES[likely[0]]} (units = {likely[0]!r})?"
    size = max(abs(lo), abs(hi)) * UNITS[units]
    raise ValueError(f"limits: [{lo:g}, {hi:g}] {UNIT_NAMES[units]} is a tolerance of {(hi - lo) * UNITS[units]:.3g} "
                     f"m; a drawing tolerance of a part of {size:.3g} m is {plausible.lo + IT1_PER_SIZE * size:.2g} m "
                     f"(ISO 286-1's IT1) to {plausible.hi * 1e3:g} mm wide: {hint}")


def enough(x, where, *, needed, units, model="a fit"):
    """Refuse too few values and readings without spread."""
    if x.size < needed:
        raise ValueError(f"{where}: {x.size} value{'s' if x.size != 1 else ''}; {model} needs at least {needed}")
    distinct = np.unique(x).size
    if distinct == 1:
        raise ValueError(f"{where}: all {x.size} readings are equal ({x[0]:g} {UNIT_NAMES.get(units, units)}): no "
                         "spread to fit (a copied column, or a gauge resolution coarser than the process spread?)")
    if distinct < MIN_DISTINCT:
        raise ValueError(f"{where}: only {distinct} different readings in {x.size}: the gauge's resolution is "
                         f"as coarse as the spread; a fit needs at least {MIN_DISTINCT} different readings")
