"""Input checks at the public boundary, so every message reads the same way.

Each check names the field, the offending value and what is valid, e.g.::

    ValueError: shell_wall: upper limit 1.491e-03 m is below lower limit 1.497e-03 m

A public function declares what its parameters must be, beside its
signature, in the spirit of scikit-learn's parameter constraints::

    @validated(housing_bore=Positive(), method=OneOf(METHODS))
    def press_fit(*, housing_bore, ..., method="lame"): ...

The checks run once, where a user's call enters the package: inside a
validated function, and in the study's chain (:func:`trusted`), the
functions it calls skip them, so a model function's body and its hot paths
never check and need no unchecked twin. :func:`renamed` keeps an old keyword
working, with a :class:`DeprecationWarning`, where the naming glossary
renamed it (docs/names.md).
"""

from __future__ import annotations

import contextlib
import contextvars
import functools
import inspect
import math
import warnings
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np


def finite(field, value):
    """Return ``value`` as a float array; reject text, true/false, NaN and inf."""
    if type(value) is float or type(value) is int:  # the common scalar, without numpy's round trips (bool excluded)
        if not math.isfinite(value):
            raise ValueError(f"{field}: {float(value)!r} is not a finite number")
        return np.asarray(float(value))
    raw = np.asarray(value)
    if raw.dtype.kind in "USOb":  # "0.3" from a file is text: never converted silently
        bad = [v for v in np.ravel(raw) if isinstance(v, (str, bytes, bool, np.bool_)) or v is None]
        if bad or raw.dtype.kind in "USb":
            shown = bad[0] if bad else value
            raise ValueError(f"{field}: {shown!r} is not a number")
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        bad = float(arr[~np.isfinite(arr)].flat[0])
        raise ValueError(f"{field}: {bad!r} is not a finite number")
    return arr


def angle_vectors(field, value):
    """Return ``value`` as a finite float array of 2-vectors over a cycle's angles, shape (..., angles, 2)."""
    arr = finite(field, value)
    if arr.ndim < 2 or arr.shape[-1] != 2:
        raise ValueError(f"{field}: shape {arr.shape} is not valid; expected (..., angles, 2)")
    return arr


def positive(field, value, *, allow_zero=False):
    """Return ``value`` as a finite float array that is > 0 (or >= 0)."""
    arr = finite(field, value)
    what = ">= 0" if allow_zero else "> 0"
    if arr.ndim == 0:  # a scalar compared as a float: a tenth of the array path's cost
        number = float(arr)
        if number < 0 or number == 0 and not allow_zero:
            raise ValueError(f"{field}: {number!r} is not valid; must be {what}")
        return arr
    bad = arr < 0 if allow_zero else arr <= 0
    if np.any(bad):
        raise ValueError(f"{field}: {float(arr[bad].flat[0])!r} is not valid; must be {what}")
    return arr


def in_range(field, value, lo, hi, *, lo_open=False, hi_open=False, unit=""):
    """Return ``value`` as a finite float array inside [lo, hi] (ends open if asked)."""
    arr = finite(field, value)
    below = arr <= lo if lo_open else arr < lo
    above = arr >= hi if hi_open else arr > hi
    bad = below | above
    if np.any(bad):
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise ValueError(
            f"{field}: {float(arr[bad].flat[0])!r}{unit} is outside the valid range {lb}{lo}, {hi}{rb}"
        )
    return arr


def limits(field, lo, hi, *, unit="m"):
    """Check a pair of drawing limits (a tolerance wider than zero) and return them as floats."""
    lo = float(finite(f"{field} lower limit", lo))
    hi = float(finite(f"{field} upper limit", hi))
    if hi < lo:
        raise ValueError(f"{field}: upper limit {hi:.6g} {unit} is below lower limit {lo:.6g} {unit}")
    if hi == lo:
        raise ValueError(f"{field}: [{lo:.6g}, {hi:.6g}] {unit} is a tolerance of zero width; give the lower and "
                         "the upper limit")
    return lo, hi


def one_of(field, value, options: Iterable[str]):
    """Check that a string option is one of the legal ones."""
    options = list(options)
    if value not in options:
        listed = ", ".join(repr(o) for o in options)
        raise ValueError(f"{field}: {value!r} is not one of {listed}")
    return value


def integer(field, value, *, minimum=None):
    """Return ``value`` as an int, optionally with a lower bound."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        if isinstance(value, float) and math.isfinite(value) and value.is_integer():
            value = int(value)
        else:
            raise ValueError(f"{field}: {value!r} is not an integer")
    value = int(value)
    if minimum is not None and value < minimum:
        raise ValueError(f"{field}: {value} is not valid; must be >= {minimum}")
    return value


def clearance_window(field, window):
    """A design window of the operating clearance as (lower, upper) in m, or a ValueError saying why not."""
    try:
        lo, hi = (float(v) for v in window)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: {window!r} is not a (lower, upper) pair of clearances in m") from None
    if not 0.0 < lo < hi < 1e-3:
        raise ValueError(f"{field}: ({lo!r}, {hi!r}) m is not a clearance window; give 0 < lower < upper < 1 mm "
                         "in metres, e.g. (45e-6, 65e-6)")
    return lo, hi


# --- declared constraints -------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Finite:
    """A finite number or array of numbers (returned as a float array)."""

    def __call__(self, field, value):
        return finite(field, value)


@dataclass(frozen=True)
class Positive:
    """A finite number > 0 (>= 0 with ``zero=True``), or an array of them."""

    zero: bool = False

    def __call__(self, field, value):
        return positive(field, value, allow_zero=self.zero)


@dataclass(frozen=True)
class InRange:
    """A finite number in [lo, hi] (ends open if asked), or an array of them."""

    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False
    unit: str = ""

    def __call__(self, field, value):
        return in_range(field, value, self.lo, self.hi, lo_open=self.lo_open, hi_open=self.hi_open, unit=self.unit)


#: Poisson's ratio of an isotropic elastic material [-]: its strain energy is positive definite only for
#: -1 < nu < 1/2.
POISSON = InRange(-1.0, 0.5, lo_open=True, hi_open=True)


@dataclass(frozen=True)
class OneOf:
    """One of the legal option strings."""

    options: tuple

    def __call__(self, field, value):
        return one_of(field, value, self.options)


@dataclass(frozen=True)
class Integer:
    """An integer, at least ``minimum`` if given."""

    minimum: int | None = None

    def __call__(self, field, value):
        return integer(field, value, minimum=self.minimum)


@dataclass(frozen=True)
class AngleVectors:
    """A finite array of 2-vectors over a cycle's angles, shape (..., angles, 2)."""

    def __call__(self, field, value):
        return angle_vectors(field, value)


@dataclass(frozen=True)
class Window:
    """A design window of the operating clearance (lower, upper) in m."""

    def __call__(self, field, value):
        return clearance_window(field, value)


@dataclass(frozen=True)
class OrNone:
    """None, or a value that passes ``constraint``."""

    constraint: object

    def __call__(self, field, value):
        return None if value is None else self.constraint(field, value)


def fields(instance, constraints, *, prefix=""):
    """Check a frozen dataclass's fields against a declared table, in its ``__post_init__``; values unchanged.

    ``constraints`` maps a field name to a check, or to ``(label, check)`` where the message names the field
    otherwise (``prefix`` + the field name by default). The fields keep the values given (a dataclass that is
    a cache key stays hashable), so this checks what :func:`validated` would convert.
    """
    for name, constraint in constraints.items():
        label, constraint = constraint if isinstance(constraint, tuple) else (f"{prefix}{name}", constraint)
        constraint(label, getattr(instance, name))


_TRUSTED = contextvars.ContextVar("stackup_inputs_checked", default=False)


@contextlib.contextmanager
def trusted():
    """Within this block validated functions skip their checks: the caller checked its inputs at the boundary.

    The study's chain runs in it (its engine and schemes were checked when read, its parameters when the
    study was made).
    """
    token = _TRUSTED.set(True)
    try:
        yield
    finally:
        _TRUSTED.reset(token)


def validated(relations=(), **constraints):
    """Declare the checks of a public function's parameters; they run on a call from outside the package.

    ``constraints`` map parameter names to checks (:class:`Positive`, :class:`OneOf`, ...; any callable
    ``check(field, value) -> value``); ``None`` is not checked where it is the parameter's default (an
    optional input left out), and is checked, so refused, everywhere else.
    ``relations`` are callables given the checked arguments by name that raise ``ValueError`` where
    parameters disagree with each other. The checked (converted) values are what the function receives.
    Calls made inside a validated function, or in a :func:`trusted` block, skip the checks.
    """
    def decorate(function):
        signature = inspect.signature(function)
        unknown = set(constraints) - set(signature.parameters)
        if unknown:
            raise TypeError(f"{function.__qualname__}: constraints for unknown parameters {sorted(unknown)}")

        @functools.wraps(function)
        def checked(*args, **kwargs):
            if _TRUSTED.get():
                return function(*args, **kwargs)
            bound = signature.bind(*args, **kwargs)
            bound.apply_defaults()
            values = bound.arguments
            for name, constraint in constraints.items():
                if values[name] is not None or signature.parameters[name].default is not None:
                    values[name] = constraint(name, values[name])
            for relation in relations:
                relation(values)
            token = _TRUSTED.set(True)
            try:
                return function(*bound.args, **bound.kwargs)
            finally:
                _TRUSTED.reset(token)

        checked.constraints = dict(constraints)
        return checked

    return decorate


def renamed(**old_to_new):
    """Accept the keywords' old names (``old="new"``) with a DeprecationWarning; both at once is an error."""
    def decorate(function):
        @functools.wraps(function)
        def call(*args, **kwargs):
            for old, new in old_to_new.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(f"{function.__name__}: give {new}= (the old name {old}= is deprecated), "
                                        "not both")
                    warnings.warn(f"{function.__name__}: {old}= is deprecated; use {new}= (same value)",
                                  DeprecationWarning, stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return function(*args, **kwargs)

        return call

    return decorate


# --- plausible sizes of physical inputs -----------------------------------------------------------------------

@dataclass(frozen=True)
class Plausible:
    """The range [lo, hi] a physical input can have, in ``unit``, and why; a value outside is refused as a slip.

    ``hint`` says which slip a value outside most likely is (grams for kg, MPa for Pa, ...).
    """

    lo: float
    hi: float
    unit: str
    what: str
    hint: str

    def check(self, field, value, *, scale=1.0, of="", unit=None):
        """``value`` if inside, else a one-line refusal naming ``field``, the value, the range and the hint.

        ``scale`` times the value is compared, in :attr:`unit` (a length in a file's ``unit``, or a ratio to
        another input: a mass per bore cubed); ``of`` is said after the quantity's name (" for a 76 mm
        cylinder bore").
        """
        number = float(value)
        unit = unit or self.unit
        if not self.lo <= number * scale <= self.hi:
            raise ValueError(f"{field}: {number:g} {unit} is not a plausible {self.what}{of} "
                             f"({self.lo / scale:.3g} to {self.hi / scale:.3g} {unit}); {self.hint}")
        return value


def _length(lo, hi, what):
    return Plausible(lo, hi, "m", what, "is `units` right?")


#: What a physical input of an engine file or of measured data can be: the one table of plausible ranges (the
#: lengths of engine files, [m], are :data:`stackup.engines.PLAUSIBLE` as (lo, hi) pairs). Each range is wide
#: enough for every engine from a motorcycle to a marine diesel and narrow enough that the slips users make
#: (grams for kg, Pa for MPa, kelvin for degC, um for mm, radians for degrees) fall outside it.
PLAUSIBLE = {
    # Lengths an engine file gives [m]: a part's size from a 5 mm bore to a 2 m one, a housing ring to 5 m, a
    # shell's crush height 5 um to 1 mm, a crankshaft's spans and throws 20 mm to 2 m (5 m for its train), a
    # bearing 2 mm to 0.5 m wide; errors of form and position (misalignment, law transition, roughness, wear) of
    # micrometres, a window of the operating clearance 2 um to 2 mm. A length in the wrong unit is 1000 times off.
    "bore": _length(5e-3, 2.0, "diameter"), "crush": _length(5e-6, 1e-3, "crush height"),
    "wall_sigma": _length(1e-9, 50e-6, "shell wall process standard deviation"),
    "ring": _length(5e-3, 5.0, "housing ring size"), "width": _length(2e-3, 0.5, "bearing width"),
    "lining": _length(0.0, 3e-3, "lining thickness"), "crank": _length(0.02, 5.0, "crank train length"),
    "span": _length(0.02, 2.0, "crankshaft span"), "misalignment": _length(0.0, 0.5e-3, "misalignment"),
    "law_dx": _length(0.0, 1e-3, "law transition"), "roughness": _length(10e-9, 20e-6, "surface roughness"),
    "wear": _length(1e-7, 1e-3, "limiting wear"), "groove": _length(0.0, 0.1, "oil feed size"),
    "window": _length(2e-6, 2e-3, "operating clearance"),
    # Kopeliovich (Crush height of engine bearings, sec. 3): the crush check's standard load is 100 MPa on the
    # steel-equivalent section; checks are made between a few tens and a few hundreds of MPa; no shell steel
    # holds 1 GPa. 100 (MPa written as Pa) is 1e6 times below.
    "check_stress": Plausible(10e6, 1e9, "Pa", "crush-check stress",
                              "give it in Pa, not MPa (100 MPa is 100e6)"),
    # The reciprocating (piston, pin, rings, small end) and rotating (big end) masses of one cylinder, per cubic
    # metre of its bore cubed: a motorcycle's 67 mm piston set of 0.3 kg is 1000 kg/m^3, the example engine's
    # 0.75 kg on 76 mm 1700, a truck diesel's 4.5 kg on 130 mm 2000, a medium-speed diesel's 150 kg on
    # 320 mm 4600; a solid steel cylinder as long as its bore is 6200. 200-20000 takes every engine in; a
    # mass written in grams is 1000 times above.
    "cylinder_mass": Plausible(200.0, 20000.0, "kg", "mass of one cylinder's parts",
                               "give it in kg (grams / 1000)"),
    # Peak cylinder pressure: 5-10 MPa in petrol engines, 15-25 MPa in diesels (Heywood, Internal Combustion
    # Engine Fundamentals, 1988, ch. 9); 1 MPa is a motored engine's compression, 50 MPa above any engine's.
    # Bar or MPa written as Pa fall below.
    "peak_pressure": Plausible(1e6, 5e7, "Pa", "peak cylinder pressure",
                               "give it in Pa (150 bar = 15 MPa is 15e6)"),
    # A bearing life asked for [h]: hundreds of hours (a test bed) to a few hundred thousand (a stationary
    # diesel's life between overhauls); 1e6 h is 114 years of running. A life in seconds is 3600 times above.
    "life_hours": Plausible(1.0, 1e6, "h", "bearing life target", "give it in hours (seconds / 3600)"),
    # The block's compliance at a main bearing [um/kN]: 0.2-2.5 in the built-in engines (Bellakhdhar et al.'s
    # 0.98 and 1.72 kN/um, an aluminium block's 2.4 um/kN); 0.01-100 takes any block in. A compliance in m/N or
    # mm/N falls below, a stiffness in N/um above.
    "support_compliance": Plausible(0.01, 100.0, "um/kN", "housing compliance",
                                    "give it in um/kN (the inverse of a stiffness in kN/um)"),
    # Gallery pressure of engine oil: 0.1-0.7 MPa hot in cars and trucks (relief valves open at 0.4-0.7 MPa),
    # a few MPa in large engines; 10 kPa is a pump barely turning. Bar or MPa written as Pa fall below.
    "oil_pressure": Plausible(1e4, 2e7, "Pa", "oil supply pressure",
                              "give it in Pa (0.35 MPa = 3.5 bar is 0.35e6)"),
    # Temperatures of an engine's housing, shells and journals: from a -60 degC cold start to the hottest
    # main bearing, below 200 degC (engine oil and aluminium-tin linings are rated to about 150-180 degC). Any
    # real temperature written in kelvin (-60 degC is 213 K) is above it.
    "engine_temperature": Plausible(-60.0, 200.0, "degC", "engine temperature",
                                    "give it in degC (kelvin - 273.15)"),
    # A process's standard deviation: below 1 nm no length gauge resolves it (the finest machining and gauges
    # work to 0.1 um); above 1 mm no main-bearing part is machined.
    "process_sigma": Plausible(1e-9, 1e-3, "m", "process standard deviation",
                               "a typing error, or is `units` right?"),
    # Width of the drawing tolerance of a main-bearing part: at least ISO 286-1's grade IT1, 0.8 um + 0.020 D
    # (:data:`IT1_PER_SIZE`; a gauge block's grade: no machined part is made finer), at most IT10 of a 3 m size,
    # 1.35 mm; main-bearing parts are made to 10-40 um. A tolerance written in the wrong one of mm and um is 1000
    # times off, one in inches read as mm 25 times too fine: both fall outside.
    "tolerance_width": Plausible(0.8e-6, 2e-3, "m", "drawing tolerance (upper - lower limit)",
                                 "are the units right?"),
}
#: How IT1 grows with the size D (ISO 286-1: IT1 = 0.8 um + 0.020 D) [-]: the lower end of a tolerance width is
#: ``PLAUSIBLE["tolerance_width"].lo + IT1_PER_SIZE * D``.
IT1_PER_SIZE = 0.020e-3
#: Angles are degrees throughout; a list of throw angles or a groove arc that fits within one radian turn
#: (2 pi = 6.28) is taken for radians: distinct throws of an engine of at most 29 cylinders lie at least
#: 360/29 = 12.4 deg apart (even firing), a groove spans tens of degrees.
RADIANS_TURN = 2.0 * math.pi


def degrees_not_radians(field, angles):
    """Refuse ``angles`` [deg] that are radians: not all equal and all within one radian turn (|a| <= 2 pi)."""
    arr = np.asarray(angles, dtype=float)
    if arr.size and np.ptp(arr) > 0 and np.abs(arr).max() <= RADIANS_TURN + 1e-9:
        shown = ", ".join(f"{a:g}" for a in np.ravel(angles))
        raise ValueError(f"{field}: [{shown}] look like radians (all within 2 pi = 6.28); give angles in degrees "
                         f"(e.g. [{', '.join(f'{np.degrees(a):.4g}' for a in np.ravel(angles))}])")
    return angles
