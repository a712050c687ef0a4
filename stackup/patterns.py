r"""ISO 13778's schemes as patterns laid on any engine's drawing.

ISO 13778:2017 gives its six selective-fitting schemes for one example
bearing, a housing bore of 50.000-50.018 mm and a journal of 46.000-46.018 mm,
and says they "are examples only" (6.1). What an engineer takes from a scheme
is its pattern: which dimensions are graded, into how many grades of what
width, and which shell pair each housing and journal grade gets. Here that
pattern is laid on an engine's own drawing limits:

- **Housing and journal grades** keep their number and their place in the
  tolerance: a grade limit at a share :math:`u` of the standard's tolerance
  sits at the share :math:`u` of the engine's,
  :math:`x' = x'_{lo} + (x - x_{lo})\,f`, :math:`f = T'/T` (the standard's
  widths where the engine's tolerance is the standard's 18 um). Widths in
  proportion, not the standard's widths, because the pairing table covers
  the whole tolerance with a fixed number of grades: a wider tolerance with
  6 um grades would need grades the table has no pairs for. Fine classes
  (scheme 6) keep the standard's read-out step (a gauge reading to the
  micrometre) and so grow in number with the tolerance.
- **Pairing** is the standard's: each cell of the engine's grades takes the
  pair of the standard's cell its middle falls in when mapped back,
  :math:`x = x_{lo} + (x' - x'_{lo})/f` (for grades the same table; for
  fine classes the same rule of :math:`k = h - j`, on the scaled sizes).
- **Shell grades** keep their labels and their steps in proportion,
  :math:`f_s = (f_H + f_J)/2`, the mean of the housing and journal scales, so
  that a pair one step thicker still makes up one housing or journal grade.
  They are then moved together (re-centred) so that the scheme's smallest
  nominal clearance sits where the standard's sits in its own design window:
  the standard puts all six schemes' smallest clearance at one value (26 um on
  the example), and that value's operating clearance (nominal plus the
  housing's swell and the thermal change, :func:`clearance_offset`) keeps its
  place in the engine's operating-clearance window,

  .. math:: \frac{c'_{min} + \Delta' - W'_{lo}}{W'_{hi} - W'_{lo}}
            = \frac{c_{min} + \Delta - W_{lo}}{W_{hi} - W_{lo}},

  with the standard's side taken on the built-in ``iso-example`` engine (the
  standard's drawing, :data:`REFERENCE_ENGINE`). An engine without a window
  keeps the relative clearance :math:`(c_{min} + \Delta)/D_J` instead. The
  smallest nominal clearance is never below the standard's in proportion to
  the journal, :math:`c_{min} D'_J / D_J`: the shells must go in cold, and a
  light-alloy block whose bore grows more than the journal when hot (the
  ``iso-example-aluminium`` engine) would otherwise be given a clearance the
  journal cannot be assembled with. Limits are rounded to 0.1 um.

On the standard's own drawing every scale is 1 and the shift is zero, so the
adapted schemes are the standard's tables exactly. The adapted scheme is data:
:func:`adapt` returns a :class:`~stackup.schemes.Scheme` whose
:meth:`~stackup.schemes.Scheme.to_toml` a user can read, keep and edit
(``stackup schemes --engine NAME --out DIR``). :func:`laid_on` decides, for every job, which schemes
are laid on the drawing: the standard's named by their names.

References
----------
.. [1] ISO 13778:2017, Plain bearings -- Quality assurance of thin-walled half
   bearings -- Selective assembly of bearings to achieve a narrow clearance
   range, clauses 4 (housing swell) and 6 (schemes 1-6, "examples only").
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cache

import numpy as np

from .engines import load_engine
from .fit import press_fit
from .schemes import from_dict
from .schemes import load as load_scheme

#: The standard's schemes by name, in the standard's order.
ISO_SCHEMES = tuple(f"iso13778-{k}" for k in range(1, 7))
#: The engine that carries the standard's example drawing (50/46 mm): the standard's side of the pattern.
REFERENCE_ENGINE = "iso-example"
#: Step the adapted grade limits are rounded to [m] (0.1 um).
ROUND = 1e-7


@dataclass(frozen=True)
class Adaptation:
    """How a scheme's pattern was laid on an engine's drawing.

    Attributes
    ----------
    housing_scale, journal_scale, shell_scale : float
        :math:`f_H, f_J, f_s`: the engine's tolerance over the standard's
        (shell steps: the mean of the other two) [-].
    shell_shift : float
        How much thicker each shell grade is than the standard's grade scaled and placed at the engine's
        nominal wall (the wall that gives the standard's clearance between the middles of the drawing) [m].
    clearance_min : float
        The adapted scheme's smallest nominal clearance [m].
    """

    housing_scale: float
    journal_scale: float
    shell_scale: float
    shell_shift: float
    clearance_min: float


def clearance_offset(engine, *, clearance=None):
    """Operating minus nominal diametral clearance of ``engine``'s bearing at the middle of its drawing [m].

    The housing's swell under the shells' crush (at the middle of the crush
    limits) and the thermal change from assembly to the operating
    temperature, by :func:`stackup.fit.press_fit` with the engine's press fit;
    ``clearance`` is the nominal clearance the shells are sized for (default:
    the middle of the engine's window less nothing, or 0.1 % of the journal).
    """
    bore = 0.5 * (engine.housing_bore.lo + engine.housing_bore.hi)
    journal = 0.5 * (engine.journal_d.lo + engine.journal_d.hi)
    crush = 0.5 * (engine.shell_wall.crush.lo + engine.shell_wall.crush.hi)
    if clearance is None:
        window = engine.clearance_window
        clearance = 0.5 * (window[0] + window[1]) if np.isfinite(window[1]) else 1e-3 * journal
    wall = 0.5 * (bore - journal - clearance)
    fit = press_fit(housing_bore=bore, shell_wall=wall, crush_height=crush, journal_d=journal,
                    **engine.press_fit.kwargs())
    return float(fit.clearance) - clearance


def _round(value):
    return np.round(np.asarray(value, dtype=float) / ROUND) * ROUND


def _mm(value):
    return float(np.round(value * 1e3, 7))


def _grades(gradeset, lo, hi, reference_lo, scale):
    """The table of a housing or journal grade set laid on the drawing ``lo``-``hi`` [m] (mm in the table)."""
    table = {"limits": [_mm(lo), _mm(hi)]}
    if gradeset.resolution:
        table["resolution"] = _mm(gradeset.resolution)
    if gradeset.fine:
        step = float(gradeset._edges[1] - gradeset._edges[0]) * 1e-9
        count = int(np.ceil((hi - lo) / step - 1e-6))
        table["classes"] = {"start": _mm(lo), "stop": _mm(lo + count * step), "step": _mm(step)}
    elif gradeset.graded:
        a = _round(lo + (gradeset.lo - reference_lo) * scale)
        b = _round(lo + (gradeset.hi - reference_lo) * scale)
        a[np.isclose(gradeset.lo, gradeset.limits[0], rtol=0, atol=1e-10)] = lo
        b[np.isclose(gradeset.hi, gradeset.limits[1], rtol=0, atol=1e-10)] = hi
        table["grades"] = {lab: [_mm(x), _mm(y)] for lab, x, y in zip(gradeset.labels, a, b)}
    return table


def _middles(gradeset):
    """A size [m] inside each grade of a grade set: the grade's middle (a fine class's middle reading)."""
    if gradeset.fine:
        return (gradeset._edges + 0.5 * (gradeset._edges[1] - gradeset._edges[0])) * 1e-9
    return 0.5 * (gradeset.lo + gradeset.hi)


def _pairing(reference, housing, journal, drawing, reference_drawing, scales):
    """The standard's pairing on the adapted grades: each cell takes the pair of the standard's cell it maps to."""
    (h_lo, _), (j_lo, _) = drawing
    (h0_lo, h0_hi), (j0_lo, j0_hi) = reference_drawing
    fh, fj = scales
    h0 = np.clip(h0_lo + (_middles(housing) - h_lo) / fh, h0_lo, h0_hi)
    j0 = np.clip(j0_lo + (_middles(journal) - j_lo) / fj, j0_lo, j0_hi)
    hi = reference.housing.classify(h0)
    ji = reference.journal.classify(j0)
    shells = reference.shell.labels
    pairs = reference.cell_pairs[ji[:, None], hi[None, :]]
    text = np.vectorize(lambda u, l: f"{shells[u]}+{shells[l]}")(pairs[..., 0], pairs[..., 1])
    table = {}
    if housing.fine or journal.fine:
        letters = {}
        for pair in text.ravel():
            letters.setdefault(pair, "abcdefghijklmnopqrstuvwxyz"[len(letters)])
        table["matrix"] = ["".join(letters[p] for p in row) for row in text]
        table["letters"] = {letter: pair for pair, letter in letters.items()}
    elif text.shape == (1, 1):
        table["all"] = str(text[0, 0])
    else:
        table["table"] = {jl: {hl: str(text[j, h]) for h, hl in enumerate(housing.labels)}
                          for j, jl in enumerate(journal.labels)}
    alternatives = {f"{shells[u]}+{shells[l]}": [f"{shells[a]}+{shells[b]}" for a, b in alts]
                    for (u, l), alts in reference.alternatives.items()}
    if alternatives:
        table["alternatives"] = alternatives
    return table


def _shells(reference, scale, centre, shift):
    """The shell grade table: the standard's grades scaled about their middle, placed at ``centre`` + ``shift``."""
    middle = 0.5 * (reference.shell.limits[0] + reference.shell.limits[1])
    lo = _round(centre + shift + (reference.shell.lo - middle) * scale)
    hi = _round(centre + shift + (reference.shell.hi - middle) * scale)
    table = {"grades": {lab: [_mm(a), _mm(b)] for lab, a, b in zip(reference.shell.labels, lo, hi)}}
    if len(lo) > 1 and np.any(np.sort(lo)[1:] < np.sort(hi)[:-1] - 1e-12):
        table["overlap"] = True
    return table


@cache
def _reference_offset():
    """The reference engine: its operating-clearance window [m], journal diameter [m] and clearance offset [m]."""
    engine = load_engine(REFERENCE_ENGINE)
    return engine.clearance_window, engine.journal_d.lo, clearance_offset(engine)


def target_clearance_min(engine, reference_min):
    """The smallest nominal clearance [m] of a scheme on ``engine`` whose standard's smallest is ``reference_min``.

    Its operating clearance keeps the standard's place in the design window (module docstring); without a
    window, the standard's relative clearance.
    """
    (lo0, hi0), journal0, offset0 = _reference_offset()
    operating0 = reference_min + offset0
    lo, hi = engine.clearance_window
    if np.isfinite(hi):
        operating = lo + (operating0 - lo0) / (hi0 - lo0) * (hi - lo)
    else:
        operating = operating0 / journal0 * engine.journal_d.lo
    floor = reference_min / journal0 * engine.journal_d.lo
    return max(operating - clearance_offset(engine), floor)


def adapt(scheme, engine):
    """``scheme``'s pattern laid on ``engine``'s drawing: a :class:`~stackup.schemes.Scheme` (module docstring).

    Parameters
    ----------
    scheme : str, path or Scheme
        A scheme written for the standard's drawing (one of :data:`ISO_SCHEMES`, or a user's scheme whose
        housing and journal limits are the standard's drawing).
    engine : str, path or Engine

    Returns
    -------
    Scheme
        Same name and title; on another drawing its ``source`` and ``notes`` say how it was laid on it.
    """
    reference = load_scheme(scheme)
    engine = load_engine(engine)
    reference_drawing = (reference.housing.limits, reference.journal.limits)
    drawing = ((engine.housing_bore.lo, engine.housing_bore.hi), (engine.journal_d.lo, engine.journal_d.hi))
    fh, fj = ((b - a) / (b0 - a0) for (a, b), (a0, b0) in zip(drawing, reference_drawing))
    fs = 0.5 * (fh + fj)
    table = {"name": reference.name, "title": reference.title, "units": "mm",
             "housing": _grades(reference.housing, *drawing[0], reference_drawing[0][0], fh),
             "journal": _grades(reference.journal, *drawing[1], reference_drawing[1][0], fj)}
    # the standard's shells scaled about their middle and placed where they give the engine the standard's
    # clearance between the middles of the drawing; then moved together to the target smallest clearance
    reference_wall = 0.5 * (reference.shell.limits[0] + reference.shell.limits[1])
    middle_gap = np.mean(reference_drawing[0]) - np.mean(reference_drawing[1]) - 2 * reference_wall
    centre = 0.5 * (np.mean(drawing[0]) - np.mean(drawing[1]) - middle_gap)
    first = reference.shell.labels[0]
    grades = from_dict({**table, "shell": _shells(reference, fs, centre, 0.0), "pairing": {"all": f"{first}+{first}"}})
    table["pairing"] = _pairing(reference, grades.housing, grades.journal, drawing, reference_drawing, (fh, fj))
    probe = from_dict({**table, "shell": _shells(reference, fs, centre, 0.0)})
    reference_min = reference.clearance_limits()[0]
    shift = 0.5 * (probe.clearance_limits()[0] - target_clearance_min(engine, reference_min))
    table["shell"] = _shells(reference, fs, centre, shift)
    c_min, c_max = from_dict(table).clearance_limits()
    exact = max(abs(fh - 1), abs(fj - 1)) < 1e-9 and abs(shift) < 0.5 * ROUND
    if exact:  # the standard's own drawing: its tables, as the standard states them
        return from_dict({**table, "source": reference.source,
                          "stated_clearance": [_mm(v) for v in reference.stated_clearance or (c_min, c_max)]},
                         path=reference.path)
    how = Adaptation(fh, fj, fs, float(shift), c_min)
    adapted = from_dict({**table, "source": _source(reference, engine, how),
                         "stated_clearance": [_mm(c_min), _mm(c_max)]})
    return replace(adapted, notes=_notes(reference, engine, how))


def _source(reference, engine, how):
    return (f"{reference.source}; its pattern laid on the drawing of engine {engine.name!r} (stackup.patterns)")


def _notes(reference, engine, how):
    """What :meth:`Scheme.to_toml` writes as comments at the top of the adapted scheme's file."""
    return (f"ISO 13778:2017 {reference.name} ({reference.title}) laid on the drawing of engine {engine.name!r} by "
            "stackup.patterns:",
            f"housing grades x{how.housing_scale:.4f} and journal grades x{how.journal_scale:.4f} of the standard's "
            "(the engine's tolerance over the standard's 18 um), pairing as the standard's,",
            f"shell steps x{how.shell_scale:.4f}, every shell grade {how.shell_shift * 1e6:+.1f} um against the "
            "standard's at the engine's nominal wall, so that the smallest nominal clearance,",
            f"{how.clearance_min * 1e6:.1f} um, keeps the standard's place in the engine's operating-clearance "
            "window (the housing's swell and the thermal change included).")


def iso_schemes(engine):
    """The six ISO 13778 schemes laid on ``engine``'s drawing (:func:`adapt`), in the standard's order."""
    return [adapt(name, engine) for name in ISO_SCHEMES]


def laid_on(scheme, engine):
    """``scheme`` as every job runs it on ``engine``: the one place that decides which schemes are adapted.

    One of :data:`ISO_SCHEMES` named by its name is the standard's pattern laid on the engine's drawing
    (:func:`adapt`); a scheme given by a file path or as a :class:`~stackup.schemes.Scheme` is the user's
    own, already written for a drawing, and is taken as it is. ``stackup compare`` (through the study's
    stored scheme texts), ``stackup plan`` and ``stackup schemes --engine`` all lay schemes through here.
    """
    if isinstance(scheme, str) and scheme in ISO_SCHEMES:
        return adapt(scheme, engine)
    return load_scheme(scheme)


#: Grades narrower than this many standard deviations of the gauge that reads them (or of the process that makes
#: shells into them) are flagged: within a grade of 3 sigma a part near a limit is read (or made) into the
#: neighbouring grade about one time in seven at the limit (ISO 13778 does not tabulate its own gauge).
NARROW_SIGMAS = 3.0


@dataclass(frozen=True)
class NarrowGrade:
    """A dimension whose narrowest grade (or fine class) is under :data:`NARROW_SIGMAS` of a spread.

    Attributes
    ----------
    part : str
        "housing", "journal" or "shell".
    width : float
        The narrowest grade or class [m].
    sigma : float
        The spread it is compared with [m].
    of : str
        "gauge" (the repeatability of the gauge that reads the part into its grade) or "process" (the shell
        wall process that makes shells into a grade, for shells made to order).
    """

    part: str
    width: float
    sigma: float
    of: str


@dataclass(frozen=True)
class Caveats:
    """What the user should know of a scheme of the standard on an engine: :func:`caveats`.

    Attributes
    ----------
    scheme : str
    narrow : tuple of NarrowGrade
        Dimensions graded finer than :data:`NARROW_SIGMAS` of their gauge or shell process.
    adapted : bool
        The pattern was laid on the drawing with other grades or shells than the standard's tables.
    held : bool
        The engine's window asked for a smallest nominal clearance below the standard's in proportion to the
        journal, so the shells were held there and the window moved nothing (:func:`target_clearance_min`); on
        the standard's drawing the tables then stay the standard's.
    window_target, floor : float
        The smallest nominal clearance the window asked for and the floor that held it [m].
    """

    scheme: str
    narrow: tuple
    adapted: bool
    held: bool
    window_target: float
    floor: float


@dataclass(frozen=True)
class Anchor:
    """The standard's side of the re-centring (module docstring): where every adapted scheme's shells are placed from.

    Attributes
    ----------
    engine : str
        :data:`REFERENCE_ENGINE`.
    window : (float, float)
        Its operating-clearance window [m] (a rule of thumb, the engine file's ``clearance_window_source``).
    housing_outer : float
        Its housing's equivalent outer diameter [m], which sets its swell (assumed in the engine file).
    clearance_min : float
        The standard's smallest nominal clearance [m] (26 um for all six schemes).
    operating_min : float
        That clearance in operation on the reference engine (swell and thermal change added) [m].
    place : float
        Its place in the reference window, (operating_min - lo) / (hi - lo) [-], which adapted schemes keep.
    """

    engine: str
    window: tuple
    housing_outer: float
    clearance_min: float
    operating_min: float
    place: float


def anchor():
    """The :class:`Anchor` of the re-centring (the same for every scheme of the standard)."""
    (lo, hi), _, offset = _reference_offset()
    c_min = load_scheme(ISO_SCHEMES[0]).clearance_limits()[0]
    operating = c_min + offset
    return Anchor(REFERENCE_ENGINE, (lo, hi), load_engine(REFERENCE_ENGINE).press_fit.housing_outer, c_min, operating,
                  (operating - lo) / (hi - lo))


def _narrowest(gradeset):
    """The narrowest grade (or fine class step) of a graded dimension [m]; None where it is not graded."""
    if gradeset.fine:
        return float(gradeset._edges[1] - gradeset._edges[0]) * 1e-9
    if not gradeset.graded:
        return None
    return float(np.min(gradeset.hi - gradeset.lo))


def caveats(scheme, engine):
    """:class:`Caveats` of one of :data:`ISO_SCHEMES` (by name) laid on ``engine``'s drawing (:func:`laid_on`).

    A grade is flagged where it is narrower than :data:`NARROW_SIGMAS` of the gauge that reads parts into it
    (housing, journal, shells) or, for shells made to order, of the wall process that makes them into it; a
    window is flagged where the floor of :func:`target_clearance_min` held the shells (it moved nothing).
    """
    engine = load_engine(engine)
    laid = laid_on(scheme, engine)
    narrow = []
    for part, gradeset, dimension in (("housing", laid.housing, engine.housing_bore),
                                      ("journal", laid.journal, engine.journal_d),
                                      ("shell", laid.shell, engine.shell_wall)):
        width = _narrowest(gradeset)
        if width is None:
            continue
        spreads = [("gauge", dimension.gauge.repeatability)]
        if part == "shell" and engine.shell_wall.mode == "to-order":
            spreads.append(("process", engine.shell_wall.sigma))
        # a tenth of a nanometre below: a 3 um grade is not flagged against a 1 um sigma for its float noise
        narrow += [NarrowGrade(part, width, sigma, of) for of, sigma in spreads
                   if width < NARROW_SIGMAS * sigma - 1e-10]
    reference = load_scheme(scheme)
    (lo0, hi0), journal0, offset0 = _reference_offset()
    reference_min = reference.clearance_limits()[0]
    floor = reference_min / journal0 * engine.journal_d.lo
    lo, hi = engine.clearance_window
    operating = (lo + (reference_min + offset0 - lo0) / (hi0 - lo0) * (hi - lo) if np.isfinite(hi) else
                 (reference_min + offset0) / journal0 * engine.journal_d.lo)
    target = operating - clearance_offset(engine)
    return Caveats(laid.name, tuple(narrow), bool(laid.notes), bool(target < floor), float(target), float(floor))
