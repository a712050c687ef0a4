"""ISO 13778 selective-fitting schemes as data: grading and pairing.

A scheme file (TOML, lengths in mm as the standard writes them) gives the
grades of the housing bore, the journal and the shell wall, and the rule that
pairs a housing grade and a journal grade with an upper and a lower shell
grade. Six files ship with the package, ``iso13778-1`` ... ``iso13778-6``; a
user's own file works the same way, by path or from a folder named in the
``STACKUP_SCHEME_PATH`` environment variable.

File layout::

    name = "my-scheme"
    units = "mm"                        # or "m"
    source = "where the numbers come from"
    stated_clearance = [0.026, 0.044]   # optional, as the standard states it

    [housing]                           # and [journal]
    limits = [50.000, 50.018]           # ungraded: one class "-"
    grades = { A = [50.000, 50.006], B = [50.006, 50.012] }   # or graded
    classes = { start = 50.000, stop = 50.018, step = 0.001 } # or fine classes "0".."18"
    resolution = 0.001                  # optional read-out step for this scheme
    overlap = false                     # true where grades overlap on purpose

    [shell]
    grades = { A = [...], B = [...] }

    [pairing]                           # one of:
    all = "B+B"                         # every cell the same pair ("upper+lower")
    table = { A = { A = "C+C", B = "D+D" } }    # journal grade -> housing grade -> pair
    matrix = ["dd...", ...]             # rows: journal classes, columns: housing classes
    letters = { d = "B+C" }             # with the meaning of each matrix letter

    [pairing.alternatives]
    "B+B" = ["A+C"]                     # allowed replacements, used when stock runs out

Grade ``[lo, hi]`` holds readings ``lo <= x < hi``; the last grade also holds
``x == hi``. Fine classes hold ``[x, x + step)``. Readings are compared in whole
nanometres, so a reading such as 50.018e-3 m lands in its own class although
its binary floating-point value is slightly below 50.018 mm.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from functools import cached_property
from importlib import resources
from pathlib import Path

import numpy as np

from ._validate import Finite, OneOf, validated
from ._files import UNITS, Table, did_you_mean, locations, read_toml
from .tolerances import quantize

#: Length units a scheme file may declare (ISO 13778 writes mm); their sizes: :data:`stackup._files.UNITS`.
_UNIT_NAMES = ("mm", "m")
#: Readings are snapped to this grid before comparison with grade limits [m].
_SNAP = 1e-9
UNGRADED = "-"
_OUT_OF_RANGE = ("raise", "mark")


def _snap(value):
    return np.rint(np.asarray(value, dtype=float) / _SNAP).astype(np.int64)


@dataclass(frozen=True, eq=False)
class GradeSet:
    """The grades of one dimension within a scheme.

    Attributes
    ----------
    labels : tuple of str
        Grade labels in file order ("-" for an ungraded dimension).
    lo, hi : numpy.ndarray
        Limits of each grade [m] (fine classes: clipped to ``limits``).
    limits : tuple of float
        Range of sizes the scheme accepts for this dimension [m].
    resolution : float
        Step the scheme reads this dimension to [m]; 0 for continuous.
    fine : bool
        True for fine classes ``[x, x + step)``.
    """

    labels: tuple
    lo: np.ndarray
    hi: np.ndarray
    limits: tuple
    resolution: float
    fine: bool
    _edges: np.ndarray  # lower edges of the sorted, non-overlapping classes [nm]
    _order: np.ndarray  # label index of each sorted class
    _top: int  # upper end of the accepted range [nm]
    _top_closed: bool

    @property
    def graded(self):
        return self.labels != (UNGRADED,)

    def as_dict(self):
        return {lab: (float(a), float(b)) for lab, a, b in zip(self.labels, self.lo, self.hi)}

    def true_bounds(self):
        """True sizes read into each grade, (lo, hi) per label in whole nanometres.

        Rounding the reading to the nearest ``resolution`` moves a class's
        true sizes down by half a step; both ends are clipped to ``limits``.
        """
        half = int(_snap(self.resolution)) // 2
        lo_limit, hi_limit = _snap(self.limits[0]), _snap(self.limits[1])
        if self.fine:  # class k is [edge_k, edge_k + step) before clipping
            lo = self._edges
            hi = np.append(self._edges[1:], self._top)
        else:
            lo, hi = _snap(self.lo), _snap(self.hi)
        return np.clip(lo - half, lo_limit, hi_limit), np.clip(hi - half, lo_limit, hi_limit)

    def bins(self):
        """Range of readings [m] sorted into each grade, (lo, hi) per label: overlaps split."""
        ends = np.append(self._edges[1:], self._top) * _SNAP
        lo = np.empty(len(self.labels))
        hi = np.empty(len(self.labels))
        lo[self._order] = self._edges * _SNAP
        hi[self._order] = ends
        return lo, hi

    @cached_property
    def _lookup(self):
        # Sorted class edges with the end of the range appended; position p of
        # searchsorted(..., "right") - 1 maps to lut[p + 1]: -1 below, -1 above.
        edges = np.append(self._edges, self._top + (1 if self._top_closed else 0))
        lut = np.concatenate(([-1], self._order, [-1])).astype(np.int64)
        return edges, lut

    def classify(self, reading):
        """Grade index of each reading [m]; -1 where the scheme has no grade for it."""
        edges, lut = self._lookup
        return lut[np.searchsorted(edges, _snap(reading), side="right")]


#: Sizes a scheme's lengths may have [m], for the plausibility checks (a bore of 50 m or a wall of
#: 0.002 mm is a file written in the wrong ``units``).
PLAUSIBLE = {"housing": (5e-3, 2.0), "journal": (5e-3, 2.0), "shell": (0.3e-3, 30e-3),
             "stated_clearance": (0.0, 2e-3), "resolution": (0.0, 0.1e-3), "step": (0.1e-6, 0.1e-3)}
_WHAT = {"housing": "housing bore diameter", "journal": "journal diameter", "shell": "shell wall thickness"}


def _grade_set(top, *, scale, units, dim):
    """The grades of dimension ``dim`` of a scheme file: one of 'classes', 'grades' or only 'limits'."""
    t = top.table(dim, required=True)
    field = f"{t.where}, key {dim}"
    size = dict(scale=scale, units=units, plausible=PLAUSIBLE[dim], what=_WHAT[dim])
    forms = [k for k in ("grades", "classes") if k in t]
    if len(forms) > 1:
        raise ValueError(f"{field}: give either 'grades' or 'classes', not both")
    resolution = t.length("resolution", 0.0, scale=scale, units=units, plausible=PLAUSIBLE["resolution"],
                          what="read-out step")
    overlap = t.flag("overlap", False)
    limits = t.lengths("limits", count=2, **size, increasing=True)
    limits = None if limits is None else tuple(limits)
    grades_table = t.table("grades") if "grades" in t else t.get("grades")
    classes_table = t.table("classes") if "classes" in t else t.get("classes")
    t.close()
    if classes_table is not None:
        return _fine_classes(classes_table, field, size, limits, resolution)
    if grades_table is not None:
        return _grades(grades_table, field, size, limits, resolution, overlap=overlap, dim=dim)
    if limits is None:
        raise ValueError(f"{field}: give 'limits', 'grades' or 'classes'")
    lo_nm = _snap(limits[0])
    return GradeSet((UNGRADED,), np.array([limits[0]]), np.array([limits[1]]), limits, resolution, False,
                    np.array([lo_nm]), np.array([0]), int(_snap(limits[1])), True)


def _fine_classes(c, field, size, limits, resolution):
    """Fine classes ``[x, x + step)`` from ``start`` to ``stop`` (table ``c``), clipped to ``limits`` if given."""
    scale = size["scale"]
    c.length("start", required=True, **size)
    c.length("stop", required=True, **size)
    c.length("step", required=True, scale=scale, units=size["units"], plausible=PLAUSIBLE["step"], what="class width")
    c.close()
    start, stop, step = (float(c.data[k]) for k in ("start", "stop", "step"))  # in file units, as written
    if stop < start:
        raise ValueError(f"{field}.classes: stop {stop!r} is below start {start!r}")
    count = int(round((stop - start) / step)) + 1
    if abs(start + (count - 1) * step - stop) > 1e-9 * max(1.0, abs(stop)):
        raise ValueError(f"{field}.classes: stop {stop!r} is not start plus a whole number of steps")
    start_nm = int(_snap(start * scale))
    step_nm = int(_snap(step * scale))
    edges = start_nm + step_nm * np.arange(count, dtype=np.int64)
    if limits is None:
        limits = (start * scale, stop * scale)
    lo = np.maximum(edges * _SNAP, limits[0])
    hi = np.minimum((edges + step_nm) * _SNAP, limits[1])
    labels = tuple(str(k) for k in range(count))
    return GradeSet(labels, lo, hi, limits, resolution, True, edges, np.arange(count), int(edges[-1] + step_nm), False)


def _grades(g, field, size, limits, resolution, *, overlap, dim):
    """Named grades ``label = [lower, upper]`` (table ``g``): no gaps, overlaps only where declared."""
    if not g.data:
        raise ValueError(f"{field}.grades: needs at least one grade as label = [lower, upper]")
    scale = size["scale"]
    labels = tuple(g.data)
    for lab in labels:
        if not lab or len(lab) > 2:
            raise ValueError(f"{field}.grades.{lab}: grade labels are one or two characters")
    bounds = [g.lengths(lab, count=2, required=True, **size, increasing=True) for lab in labels]
    lo = np.array([b[0] for b in bounds])
    hi = np.array([b[1] for b in bounds])
    order = np.argsort(lo, kind="stable")
    lo_nm, hi_nm = _snap(lo[order]), _snap(hi[order])
    edges = lo_nm.copy()
    for a, b in zip(range(len(order) - 1), range(1, len(order))):
        la, lb = labels[order[a]], labels[order[b]]
        if lo_nm[b] > hi_nm[a]:
            raise ValueError(
                f"{field}.grades: gap between grade {la} (up to {hi[order[a]] / scale:.6g}) "
                f"and grade {lb} (from {lo[order[b]] / scale:.6g})"
            )
        if lo_nm[b] < hi_nm[a]:
            if not overlap:
                raise ValueError(
                    f"{field}.grades: grades {la} and {lb} overlap "
                    f"({lo[order[b]] / scale:.6g} < {hi[order[a]] / scale:.6g}); "
                    f"set {dim}.overlap = true if that is intended"
                )
            if hi_nm[b] <= hi_nm[a] or lo_nm[b] <= lo_nm[a]:
                raise ValueError(f"{field}.grades: grade {lb} lies inside grade {la}")
            # A reading in the overlap goes to the grade whose centre is nearest.
            edges[b] = (lo_nm[b] + hi_nm[a]) // 2
    span = (float(lo.min()), float(hi.max()))
    if limits is not None and (limits[0] > span[0] or limits[1] < span[1]):
        raise ValueError(f"{field}.limits: grades reach outside the limits "
                         f"[{limits[0] / scale:.6g}, {limits[1] / scale:.6g}] {size['units']}")
    limits = span if limits is None else limits
    return GradeSet(labels, lo, hi, limits, resolution, False, edges, order, int(hi_nm.max()), True)


@dataclass(frozen=True, eq=False)
class Scheme:
    """A selective-fitting scheme: grades of housing, journal and shell, and the pairing rule.

    Use :func:`load` to build one. ``upper``/``lower`` shells of a pair are
    written ``"upper+lower"`` in the file.
    """

    name: str
    title: str
    source: str
    path: str
    stated_clearance: tuple | None
    housing: GradeSet
    journal: GradeSet
    shell: GradeSet
    cell_pairs: np.ndarray  # (journal grades, housing grades, 2): preferred (upper, lower) shell indices
    alternatives: dict  # (upper, lower) -> tuple of (upper, lower), in order of preference
    notes: tuple = ()  # lines :meth:`to_toml` writes as comments at the top of the file (not data)

    def __repr__(self):
        return f"Scheme({self.name!r}, {self.title!r})"

    @property
    def grades(self):
        """Grade limits [m] of each dimension: ``{"housing": {"A": (lo, hi), ...}, "journal": ..., "shell": ...}``."""
        return {"housing": self.housing.as_dict(), "journal": self.journal.as_dict(), "shell": self.shell.as_dict()}

    def options(self, upper, lower):
        """Allowed shell pairs for a preferred pair, preferred first: list of (upper, lower) labels."""
        lab = self.shell.labels
        key = (lab.index(upper), lab.index(lower))
        return [(lab[u], lab[l]) for u, l in (key, *self.alternatives.get(key, ()))]

    @cached_property
    def option_table(self):
        """Options per preferred pair code ``u * n + l``: int array (n*n, k, 2), -1 padded."""
        n = len(self.shell.labels)
        width = 1 + max((len(v) for v in self.alternatives.values()), default=0)
        table = np.full((n * n, width, 2), -1, dtype=np.int64)
        for u in range(n):
            for l in range(n):
                for k, pair in enumerate(((u, l), *self.alternatives.get((u, l), ()))):
                    table[u * n + l, k] = pair
        return table

    @cached_property
    def _cell_code(self):
        n = len(self.shell.labels)
        code = (self.cell_pairs[..., 0] * n + self.cell_pairs[..., 1]).ravel()
        return np.append(code, -1).astype(np.int64)

    def read(self, housing_reading, journal_reading):
        """Readings rounded to the scheme's read-out steps (scheme 6: the nearest micrometre) [m]."""
        return quantize(housing_reading, self.housing.resolution), quantize(journal_reading, self.journal.resolution)

    def classify(self, housing_d, journal_d):
        """Housing and journal grade indices of readings [m]; -1 where out of the scheme's range."""
        return self.housing.classify(housing_d), self.journal.classify(journal_d)

    def grade_indices(self, housing_reading, journal_reading):
        """Housing and journal grade indices of gauge readings [m]: read out at the scheme's steps
        (:meth:`read`), then classified (:meth:`classify`); -1 where out of range."""
        return self.classify(*self.read(housing_reading, journal_reading))

    def pair_code(self, housing_index, journal_index):
        """Preferred pair code ``upper * n_shell_grades + lower`` of graded parts; -1 where either index is -1."""
        nj, nh = self.cell_pairs.shape[:2]
        cell = np.where((housing_index >= 0) & (journal_index >= 0), journal_index * nh + housing_index, nj * nh)
        return self._cell_code[cell]

    def pair_indices(self, housing_index, journal_index):
        """Preferred (upper, lower) shell grade indices of graded parts; -1 where either index is -1."""
        code = self.pair_code(housing_index, journal_index)
        n = len(self.shell.labels)
        return np.where(code >= 0, code // n, -1), np.where(code >= 0, code % n, -1)

    @validated(housing_d=Finite(), journal_d=Finite(), out_of_range=OneOf(_OUT_OF_RANGE))
    def pair(self, housing_d, journal_d, *, out_of_range="raise"):
        """Shell grades for measured housing bores and journals.

        Parameters
        ----------
        housing_d, journal_d : array_like
            Measured housing bore and journal diameters [m], broadcast together.
        out_of_range : {"raise", "mark"}
            What to do with a reading outside the scheme's range: raise
            ValueError, or return ``""`` as its grades.

        Returns
        -------
        upper, lower : numpy.ndarray of str
            Preferred upper and lower shell grade of each bearing ("-" for
            ungraded shells). Allowed alternatives: :meth:`options`.
        """
        h, j = np.broadcast_arrays(np.asarray(housing_d, dtype=float), np.asarray(journal_d, dtype=float))
        hi, ji = self.classify(h, j)
        if out_of_range == "raise":
            for field, idx, val, gs in (("housing_d", hi, h, self.housing), ("journal_d", ji, j, self.journal)):
                if np.any(idx < 0):
                    bad = val[idx < 0].flat[0]
                    raise ValueError(
                        f"{field}: {float(bad)!r} m is outside scheme {self.name}'s range "
                        f"[{gs.limits[0]!r}, {gs.limits[1]!r}] m; pass out_of_range='mark' to mark it"
                    )
        u, l = self.pair_indices(hi, ji)
        labels = np.array((*self.shell.labels, ""))
        return labels[u], labels[l]

    def to_toml(self, path):
        """Write the scheme as a TOML file that :func:`load` reads back identically.

        Lengths are written in mm to the nanometre (the step at which schemes
        compare readings), so every grade limit, class, read-out step and
        pairing comes back as the same number; the pairing is written from
        the resolved cells (a ``table``, or a ``matrix`` with ``letters`` for
        fine classes), whatever form the scheme was read from. ``notes`` are
        written as comments at the top; comments are not data, so a scheme
        read back has none. Returns the path.
        """
        path = Path(path)
        path.write_text(_toml_text(self))
        return path

    def to_toml_text(self):
        """The text :meth:`to_toml` writes."""
        return _toml_text(self)

    def clearance_limits(self):
        r"""Worst-case nominal diametral clearance (c_min, c_max) [m], without housing swell.

        :math:`C = D_H - (s_{upper} + s_{lower} + D_J)` over every housing and
        journal grade and every shell pair the scheme allows there. A class
        holds the true sizes the scheme reads into it: with a read-out step
        :math:`r` (scheme 6: 1 um, rounded to the nearest) the class
        :math:`[x, x + 1\,\mu m)` holds true sizes :math:`[x - r/2, x + 1\,\mu m - r/2)`,
        clipped to the scheme's range. Computed in whole nanometres.
        """
        h_lo, h_hi = self.housing.true_bounds()
        j_lo, j_hi = self.journal.true_bounds()
        s_lo, s_hi = _snap(self.shell.lo), _snap(self.shell.hi)
        c_min, c_max = None, None
        for j in range(len(self.journal.labels)):
            for h in range(len(self.housing.labels)):
                u, l = self.cell_pairs[j, h]
                for pu, pl in ((u, l), *self.alternatives.get((u, l), ())):
                    lo = int(h_lo[h] - j_hi[j] - s_hi[pu] - s_hi[pl])
                    hi = int(h_hi[h] - j_lo[j] - s_lo[pu] - s_lo[pl])
                    c_min = lo if c_min is None else min(c_min, lo)
                    c_max = hi if c_max is None else max(c_max, hi)
        return c_min * _SNAP, c_max * _SNAP


def _parse_pair(text, shells, where, key):
    if not isinstance(text, str) or text.count("+") != 1:
        raise ValueError(f"{where}, key {key}: {text!r} is not a shell pair written 'upper+lower'")
    out = []
    for label in text.split("+"):
        label = label.strip()
        if label not in shells:
            raise ValueError(
                f"{where}, key {key}: unknown shell grade {label!r} (grades: {', '.join(shells)})"
            )
        out.append(shells.index(label))
    return tuple(out)


def _pairing(top, housing, journal, shells):
    t = top.table("pairing", required=True)
    where, field = t.where, f"{t.where}, key pairing"
    given = {k: t.get(k) for k in ("all", "table", "matrix", "letters", "alternatives")}
    t.close()
    forms = [k for k in ("all", "table", "matrix") if given[k] is not None]
    if len(forms) != 1:
        raise ValueError(f"{field}: give exactly one of 'all', 'table' or 'matrix' (found {forms or 'none'})")
    if given["letters"] is not None and "matrix" not in forms:
        raise ValueError(f"{field}.letters: letters give the meaning of a matrix's letters; there is no matrix")
    nj, nh = len(journal.labels), len(housing.labels)
    cells = np.full((nj, nh, 2), -1, dtype=np.int64)
    if "all" in forms:
        cells[:, :] = _parse_pair(given["all"], shells, where, "pairing.all")
    elif "table" in forms:
        rows = t.table("table")
        for jl in rows.data:
            if jl not in journal.labels:
                raise ValueError(f"{field}.table.{jl}: unknown journal grade {jl!r} (grades: {', '.join(journal.labels)})")
            row = rows.table(jl)
            for hl in row.data:
                if hl not in housing.labels:
                    raise ValueError(f"{field}.table.{jl}.{hl}: unknown housing grade {hl!r} (grades: {', '.join(housing.labels)})")
                key = f"pairing.table.{jl}.{hl}"
                cells[journal.labels.index(jl), housing.labels.index(hl)] = _parse_pair(row.get(hl), shells, where, key)
    else:
        if given["letters"] is None:
            raise ValueError(f"{field}.letters: missing; a matrix needs its letters, e.g. letters = {{ a = 'A+A' }}")
        letters = t.table("letters")
        if not letters.data:
            raise ValueError(f"{field}.letters: empty; a matrix needs its letters, e.g. letters = {{ a = 'A+A' }}")
        meaning = {k: _parse_pair(v, shells, where, f"pairing.letters.{k}") for k, v in letters.data.items()}
        rows = given["matrix"]
        if not isinstance(rows, list) or not all(isinstance(r, str) for r in rows):
            raise ValueError(f"{field}.matrix: {rows!r} is not a list of rows of letters, one text per journal class")
        if len(rows) != nj:
            raise ValueError(f"{field}.matrix: {len(rows)} rows for {nj} journal classes")
        for j, row in enumerate(rows):
            if len(row) != nh:
                raise ValueError(f"{field}.matrix[{j}]: {len(row)} letters for {nh} housing classes")
            for h, letter in enumerate(row):
                if letter not in meaning:
                    raise ValueError(f"{field}.matrix[{j}][{h}]: letter {letter!r} is not in pairing.letters")
                cells[j, h] = meaning[letter]
    missing = np.argwhere(cells[..., 0] < 0)
    if len(missing):
        j, h = missing[0]
        raise ValueError(
            f"{field}: no pairing for journal grade {journal.labels[j]!r} "
            f"with housing grade {housing.labels[h]!r}"
        )
    alternatives = {}
    alts_table = t.table("alternatives")
    for pref, alts in alts_table.data.items():
        key = _parse_pair(pref, shells, where, f"pairing.alternatives.{pref}")
        if not isinstance(alts, list):
            raise ValueError(f"{field}.alternatives.{pref}: {alts!r} is not a list of pairs")
        alternatives[key] = tuple(_parse_pair(a, shells, where, f"pairing.alternatives.{pref}") for a in alts)
    return cells, alternatives


def builtin_folder():
    """The folder of the built-in scheme files (inside the package when installed)."""
    packaged = resources.files("stackup") / "_scheme_files"
    if packaged.is_dir():
        return Path(str(packaged))
    # Running from a source checkout: the files at the top of the repository.
    return Path(__file__).resolve().parent.parent / "schemes"


def files():
    """Where :func:`load` finds each scheme by name: {name: path}, the user's folders first."""
    return locations("STACKUP_SCHEME_PATH", builtin_folder())


def available():
    """Names of the schemes that :func:`load` finds by name, shipped ones and the user's."""
    return sorted(files())


def scheme_path(name_or_path):
    """The file of a scheme name (``"iso13778-4"``, shipped or the user's) or of a path."""
    text = os.fspath(name_or_path)
    path = Path(text)
    if path.suffix == ".toml" or os.sep in text or path.exists():
        return path
    found = files().get(text) or _named_in_file(text)
    if found is None:
        raise ValueError(f"scheme: {text!r} is not a known scheme (available: {', '.join(available())}) nor a file"
                         f"{did_you_mean(text, available())}")
    return found


def _named_in_file(name):
    """The scheme file whose ``name`` key is ``name`` (the name a study and its report give the scheme), or None.

    A user's file ``my-scheme.toml`` saying ``name = "mine"`` is found as
    ``"my-scheme"`` and, as the report calls it, ``"mine"``.
    """
    for path in files().values():
        try:
            data, _ = read_toml(path, kind="scheme")
        except ValueError:
            continue
        if data.get("name") == name:
            return path
    return None


def load(name_or_path):
    """Load a scheme by name (``"iso13778-4"``) or from a TOML file path."""
    if isinstance(name_or_path, Scheme):
        return name_or_path
    path = scheme_path(name_or_path)
    data, _ = read_toml(path, kind="scheme")
    return _from_dict(data, where=f"scheme file {path.name!r}", path=str(path))


def from_dict(data, *, path=""):
    """A scheme from the table a scheme file holds (see the module docstring), e.g. built by a program."""
    name = data.get("name", path or "table") if isinstance(data, dict) else path or "table"
    return _from_dict(data, where=f"scheme {name!r}", path=str(path))


def _mm(value):
    """A length [m] as the shortest decimal of whole nanometres in mm (exact on read-back)."""
    return repr(int(_snap(value)) / 1e6)


def _toml_text(scheme):
    """The TOML text of ``scheme`` (lengths in mm); see :meth:`Scheme.to_toml`."""
    import json

    def text(value):
        return json.dumps(str(value), ensure_ascii=False)  # a JSON string is a valid TOML basic string

    lines = [f"# {line}".rstrip() for note in scheme.notes for line in str(note).splitlines()]
    lines += [f"name = {text(scheme.name)}", f"title = {text(scheme.title)}", f"source = {text(scheme.source)}",
              'units = "mm"']
    if scheme.stated_clearance is not None:
        lines.append(f"stated_clearance = [{_mm(scheme.stated_clearance[0])}, {_mm(scheme.stated_clearance[1])}]")
    for dim in ("housing", "journal", "shell"):
        grades = getattr(scheme, dim)
        lines += ["", f"[{dim}]", f"limits = [{_mm(grades.limits[0])}, {_mm(grades.limits[1])}]"]
        if grades.fine:
            start, step = int(grades._edges[0]), int(grades._edges[1] - grades._edges[0]) if len(grades._edges) > 1 \
                else int(grades._top - grades._edges[0])
            lines.append(f"classes = {{ start = {start / 1e6!r}, stop = {int(grades._edges[-1]) / 1e6!r}, "
                         f"step = {step / 1e6!r} }}")
        elif grades.graded:
            cells = ", ".join(f"{text(lab)} = [{_mm(lo)}, {_mm(hi)}]" for lab, lo, hi in zip(grades.labels, grades.lo, grades.hi))
            lines.append(f"grades = {{ {cells} }}")
            lo, hi = _snap(grades.lo[grades._order]), _snap(grades.hi[grades._order])
            if np.any(lo[1:] < hi[:-1]):
                lines.append("overlap = true")
        if grades.resolution:
            lines.append(f"resolution = {_mm(grades.resolution)}")
    shells = scheme.shell.labels

    def pair(code):
        return text(f"{shells[code[0]]}+{shells[code[1]]}")

    lines += ["", "[pairing]"]
    if (scheme.housing.fine or scheme.journal.fine) and len(set(map(tuple, scheme.cell_pairs.reshape(-1, 2)))) <= len(_LETTERS):
        letters = {}
        for code in map(tuple, scheme.cell_pairs.reshape(-1, 2)):
            letters.setdefault(code, _LETTERS[len(letters)])
        lines.append("matrix = [")
        lines += [f'    "{"".join(letters[tuple(c)] for c in row)}",' for row in scheme.cell_pairs]
        lines += ["]", "", "[pairing.letters]"]
        lines += [f"{letter} = {pair(code)}" for code, letter in letters.items()]
    elif scheme.cell_pairs.shape[:2] == (1, 1):
        lines.append(f"all = {pair(scheme.cell_pairs[0, 0])}")
    else:
        lines[-1] = "[pairing.table]"
        for j, jl in enumerate(scheme.journal.labels):
            cells = ", ".join(f"{text(hl)} = {pair(scheme.cell_pairs[j, h])}" for h, hl in enumerate(scheme.housing.labels))
            lines.append(f"{text(jl)} = {{ {cells} }}")
    if scheme.alternatives:
        lines += ["", "[pairing.alternatives]"]
        lines += [f"{pair(key)} = [{', '.join(pair(a) for a in alts)}]" for key, alts in scheme.alternatives.items()]
    return "\n".join(lines) + "\n"


#: Letters of the pairs of a matrix written by :meth:`Scheme.to_toml`, in order of first use.
_LETTERS = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"


#: Top-level keys of an engine file (:mod:`stackup.engines`) that no scheme file has.
_ENGINE_KEYS = ("main_bearings", "housing_bore", "journal_d", "press_fit", "shell_wall", "crush_height")


def _from_dict(data, *, where, path):
    """The scheme of a table, every key read through :class:`stackup._files.Table` (unknown keys refused)."""
    top = Table(data, where)
    engine_keys = [k for k in _ENGINE_KEYS if k in top]
    if engine_keys and not any(k in top for k in ("housing", "journal", "shell", "pairing")):
        raise ValueError(f"{where}: is an engine file (it has {', '.join(engine_keys)}), not a scheme file; give it "
                         "as the engine (--engine)")
    if isinstance(data, dict) and not any(k in data for k in ("housing", "journal", "shell", "pairing")):
        has = ", ".join(list(data)[:6]) + (", ..." if len(data) > 6 else "")
        raise ValueError(f"{where}: is not a scheme file (none of [housing], [journal], [shell], [pairing]; it has "
                         f"{has}); a scheme file is described in the docstring of stackup.schemes")
    units = top.text("units", required=True, options=_UNIT_NAMES)
    scale = UNITS[units]
    name = top.text("name", Path(path).stem)
    title = top.text("title", "")
    source = top.text("source", "")
    # Optional: a scheme without it has no stated range (None), never a range of zero width.
    stated = top.lengths("stated_clearance", count=2, scale=scale, units=units, plausible=PLAUSIBLE["stated_clearance"],
                         what="stated clearance", increasing=True)
    housing = _grade_set(top, scale=scale, units=units, dim="housing")
    journal = _grade_set(top, scale=scale, units=units, dim="journal")
    shell = _grade_set(top, scale=scale, units=units, dim="shell")
    cells, alternatives = _pairing(top, housing, journal, shell.labels)
    top.close()
    return Scheme(
        name=name,
        title=title,
        source=source,
        path=path,
        stated_clearance=None if stated is None else tuple(stated),
        housing=housing,
        journal=journal,
        shell=shell,
        cell_pairs=cells,
        alternatives=alternatives,
    )
