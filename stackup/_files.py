"""Reading the input files (engines, schemes, materials, oils): one path, one way of saying what is wrong.

Every message names the file, the key, the value and what is valid::

    ValueError: engine file 'my-engine.toml', key housing_bore: unknown key 'sharred'; valid keys: gauge, limits, process, shared
    ValueError: engine file 'my-engine.toml', key crank.spans: 0.085 mm is not a plausible crankshaft span (20 to 2000 mm); is `units` right?

:func:`read_toml` refuses what is not a readable TOML file (missing, a
folder, binary, empty, bad syntax); :class:`Table` reads a table key by key
with its type and range, and :meth:`Table.close` refuses the keys nobody
read, listing the valid ones, so a typo never runs silently with a default.
"""

from __future__ import annotations

import ast
import difflib
import math
import os
import re
import tomllib
from pathlib import Path

import numpy as np

from . import _validate as check

#: Length units a file may declare [m per unit]: the one table of their sizes (a format that accepts fewer keeps
#: its own list of the names it accepts, and reads their sizes here).
UNITS = {"mm": 1e-3, "um": 1e-6, "m": 1.0}


def locations(variable, builtin):
    """Where files are found by name: ``{name: path}`` of the ``*.toml`` files in the folders of the
    environment variable ``variable`` (``os.pathsep``-separated), then in ``builtin``; the user's first."""
    folders = [Path(p) for p in os.environ.get(variable, "").split(os.pathsep) if p]
    found = {}
    for folder in (*folders, builtin):
        if folder.is_dir():
            for path in sorted(folder.glob("*.toml")):
                found.setdefault(path.stem, path)
    return found


def read_toml(path, *, kind):
    """The parsed TOML of ``path``, a ``kind`` file ("engine", "scheme", ...), or a ValueError saying why not.

    Returns ``(data, text)``: the table and the file's text (which a study
    stores so a dataset reproduces itself without the file).
    """
    path = Path(path)
    where = f"{kind} file {str(path)!r}"
    try:
        str(path).encode("utf-8")
    except UnicodeEncodeError:  # a study stores its files' paths as UTF-8 text (its dataset, its report)
        raise ValueError(f"{where}: the path is not UTF-8 text (its bytes are not valid UTF-8); rename the file or "
                         "its folder with UTF-8 characters (or copy it to one)") from None
    if path.is_dir():
        raise ValueError(f"{where}: is a folder, not a file")
    if not path.is_file():
        raise ValueError(f"{where}: does not exist")
    raw = path.read_bytes()
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):  # what some editors save as "Unicode"
        raise ValueError(f"{where}: is UTF-16 text (its byte-order mark says so); save it as UTF-8")
    if b"\x00" in raw:
        raise ValueError(f"{where}: is a binary file, not TOML text")
    try:
        text = raw.decode("utf-8-sig")  # the byte-order mark some editors write first is no part of the TOML
    except UnicodeDecodeError as error:
        raise ValueError(f"{where}: is not UTF-8 text (byte {error.start}); save it as UTF-8 TOML") from None
    if path.suffix.lower() in (".csv", ".tsv", ".txt", ".xlsx", ".xls"):  # measured data given as a file to read
        raise ValueError(f"{where}: is a {path.suffix} file, not a TOML {kind} file; give the {kind}'s .toml file")
    return parse_toml(text, where=f"{kind} file {path.name!r}"), text


def parse_toml(text, *, where):
    """The table of a TOML text, or a ValueError naming ``where`` and the line."""
    text = text.removeprefix("\ufeff")  # a byte-order mark, as read_toml drops it (a text stored with it)
    if not text.strip():
        raise ValueError(f"{where}: is empty")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{where}: {_toml_error(str(error), text)}") from None


#: The TOML library's messages for a key or table given twice, and what they mean to whoever wrote the file.
_TWICE = re.compile(r"Cannot (?:overwrite a value|declare (?P<table>\(.*?\)) twice|mutate immutable namespace "
                    r"(?P<inline>\(.*?\)))(?: \(at line (?P<line>\d+), column \d+\))?")


def _toml_error(message, text):
    """The TOML library's message in the file's words: a key written twice is named, with its line."""
    match = _TWICE.fullmatch(message.strip())
    if match is None:
        return f"not valid TOML ({message})"
    line = int(match["line"]) if match["line"] else None
    shown = f" (line {line}: {text.splitlines()[line - 1].strip()!r})" if line and line <= len(text.splitlines()) else ""
    if match["table"]:
        return f"table [{_dotted(match['table'])}] is written twice{shown}; write each table once"
    if match["inline"]:
        table = _dotted(match["inline"])
        return (f"key {table} is written twice{shown}; write each key once (a table given whole, as "
                f"{table.rsplit('.', 1)[-1]} = {{ ... }}, cannot be added to later)")
    return f"a key is written twice{shown}; write each key once"


def _dotted(keys):
    """``('shell', 'grades')`` as the dotted key ``shell.grades``."""
    try:
        parts = ast.literal_eval(keys)
    except (ValueError, SyntaxError):
        return keys
    return ".".join(map(str, parts)) if isinstance(parts, tuple) else str(parts)


def did_you_mean(value, valid):
    """``"; did you mean 'x'?"`` for the valid name nearest to ``value`` (case and separators aside), or ``""``."""
    def plain(text):
        return re.sub(r"[\s_\-]+", "", str(text).lower())

    by_plain = {plain(v): v for v in valid}
    near = difflib.get_close_matches(plain(value), list(by_plain), n=1, cutoff=0.6)
    return f"; did you mean {by_plain[near[0]]!r}?" if near else ""


def _type_name(value):
    return {bool: "true/false", int: "a number", float: "a number", str: "text", list: "a list",
            dict: "a table"}.get(type(value), type(value).__name__)


class Table:
    """A TOML table read key by key (see the module docstring).

    Parameters
    ----------
    data : dict
        The table.
    where : str
        The file, as messages name it (``"engine file 'x.toml'"``).
    path : str
        Dotted key of this table within the file ("" for the top).
    """

    def __init__(self, data, where, path=""):
        if not isinstance(data, dict):
            raise ValueError(f"{where}, key {path}: {data!r} is {_type_name(data)}, not a table")
        self.data, self.where, self.path = data, where, path
        self.valid = []

    def key(self, name):
        """The full name of a key for messages."""
        return f"{self.path}.{name}" if self.path else name

    def _at(self, name):
        return f"{self.where}, key {self.key(name)}"

    def __contains__(self, name):
        return name in self.data

    def get(self, name, default=None, *, required=False):
        """The raw value of ``name`` (registered as valid), ``default`` where absent."""
        self.valid.append(name)
        if name not in self.data:
            if required:
                near = difflib.get_close_matches(name, [str(k) for k in self.data], n=1)
                hint = f" (is {near[0]!r} a misspelling of it?)" if near else ""
                raise ValueError(f"{self._at(name)}: missing{hint}")
            return default
        return self.data[name]

    def table(self, name, *, required=False):
        """The sub-table ``name`` as a Table (an empty one where absent and optional)."""
        value = self.get(name, required=required)
        return Table({} if value is None else value, self.where, self.key(name))

    def optional(self, name):
        """The sub-table ``name`` as a Table, or None where the file has none (a valid key either way)."""
        value = self.get(name)
        return None if value is None else Table(value, self.where, self.key(name))

    def source(self, name):
        """A required text saying where numbers come from; an empty one is refused."""
        value = self.text(name, required=True)
        if not value.strip():
            raise ValueError(f"{self._at(name)}: empty; say where the numbers come from")
        return value

    def text(self, name, default=None, *, required=False, options=None):
        """A text value, optionally one of ``options``."""
        value = self.get(name, default, required=required)
        if value is None:
            return None
        if not isinstance(value, str):
            raise ValueError(f"{self._at(name)}: {value!r} is {_type_name(value)}, not text")
        if options is not None and value not in options:
            raise ValueError(f"{self._at(name)}: {value!r} is not one of {', '.join(map(repr, options))}"
                             f"{did_you_mean(value, options)}")
        return value

    def number(self, name, default=None, *, required=False, lo=-math.inf, hi=math.inf, unit="",
               lo_open=False, hi_open=False):
        """A finite number within [lo, hi] (open ends where asked), as a float."""
        value = self.get(name, default, required=required)
        if value is None:
            return None
        return self._number(name, value, lo, hi, unit, lo_open, hi_open)

    def _number(self, name, value, lo, hi, unit, lo_open=False, hi_open=False):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"{self._at(name)}: {value!r} is {_type_name(value)}, not a number")
        value = float(value)
        if not math.isfinite(value):
            raise ValueError(f"{self._at(name)}: {value!r} is not a finite number")
        below = value <= lo if lo_open else value < lo
        above = value >= hi if hi_open else value > hi
        if below or above:
            lb, rb = "(" if lo_open else "[", ")" if hi_open else "]"
            raise ValueError(f"{self._at(name)}: {value:g}{unit} is outside the valid range {lb}{lo:g}, {hi:g}{rb}{unit}")
        return value

    def numbers(self, name, default=None, *, required=False, rows=False):
        """Finite numbers as a float array: a list of them (with ``rows``, also a list of such lists)."""
        value = self.get(name, default, required=required)
        if value is None:
            return None

        def number(v):
            return isinstance(v, (int, float)) and not isinstance(v, bool)

        def entry(v):
            return number(v) or rows and isinstance(v, list) and all(map(number, v))

        if not isinstance(value, list) or not all(map(entry, value)) or len({np.shape(v) for v in value}) > 1:
            raise ValueError(f"{self._at(name)}: {value!r} is not a list of numbers")
        return check.finite(self._at(name), value)

    def flag(self, name, default=None, *, required=False):
        """A true/false value (a number or the text "false" is refused, never read as true)."""
        value = self.get(name, default, required=required)
        if value is None:
            return None
        if not isinstance(value, bool):
            raise ValueError(f"{self._at(name)}: {value!r} is {_type_name(value)}, not true/false")
        return value

    def integer(self, name, default=None, *, required=False, lo=0, hi=10**12):
        """A whole number within [lo, hi]."""
        value = self.get(name, default, required=required)
        if value is None:
            return None
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"{self._at(name)}: {value!r} is {_type_name(value)}, not a whole number")
        if not lo <= value <= hi:
            raise ValueError(f"{self._at(name)}: {value} is outside the valid range [{lo}, {hi}]")
        return value

    def length(self, name, default=None, *, required=False, scale, units, plausible, what):
        """A length in the file's ``units`` (``scale`` m each), returned in m.

        ``plausible`` is the (lowest, highest) value [m] a ``what`` can have;
        a value outside it is refused with a hint about ``units`` (a bore of
        60 m or a span of 0.085 mm).
        """
        value = self.get(name, default, required=required)
        if value is None:
            return None
        return self._length(name, value, scale, units, plausible, what)

    def _length(self, name, value, scale, units, plausible, what):
        value = self._number(name, value, -math.inf, math.inf, "")
        lo, hi = plausible
        if not lo <= value * scale <= hi:
            raise ValueError(f"{self._at(name)}: {value:g} {units} is not a plausible {what} ({lo / scale:g} to "
                             f"{hi / scale:g} {units}); is `units` right?")
        return value * scale

    def lengths(self, name, *, count=None, required=False, scale, units, plausible, what, increasing=False):
        """A list of lengths [m] (``count`` of them where given), each plausible; strictly increasing if asked."""
        value = self.get(name, required=required)
        if value is None:
            return None
        if not isinstance(value, list):
            raise ValueError(f"{self._at(name)}: {value!r} is {_type_name(value)}, not a list")
        if count is not None and len(value) != count:
            raise ValueError(f"{self._at(name)}: {len(value)} values; give {count}")
        out = [self._length(name, v, scale, units, plausible, what) for v in value]
        if increasing and len(out) == 2:  # drawing limits: the messages every limit check gives
            check.limits(self._at(name), *value, unit=units)
        elif increasing and any(b <= a for a, b in zip(out, out[1:])):
            raise ValueError(f"{self._at(name)}: {value!r} {units} is not increasing")
        return out

    def close(self):
        """Refuse the keys of this table that nobody read, naming the valid ones."""
        unknown = [k for k in self.data if k not in self.valid]
        if unknown:
            where = f"{self.where}, key {self.path}" if self.path else self.where
            plural = "s" if len(unknown) > 1 else ""
            valid = sorted(set(self.valid))
            near = [m for k in unknown for m in difflib.get_close_matches(str(k), valid, n=1)]
            hint = f"; did you mean {', '.join(map(repr, near))}?" if near else ""
            raise ValueError(f"{where}: unknown key{plural} {', '.join(map(repr, unknown))}; valid keys: "
                             f"{', '.join(valid)}{hint}")


def units_of(table):
    """The length unit (name, scale [m]) a file declares in its top-level ``units`` key."""
    name = table.text("units", required=True, options=tuple(UNITS))
    return name, UNITS[name]
