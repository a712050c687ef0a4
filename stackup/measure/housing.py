r"""The housing's equivalent outer diameter from fitting tests (ISO 13778 clause 4: measure the swell).

An engine file stands for its bulkhead and bolted cap by a ring of outer
diameter ``press_fit.housing_outer``: an assumption the swell, hence the
operating clearance, moves with. A fitting test measures what the ring must
explain: the housing bore before assembly, both shell walls and both crush
heights, then the bore inside the fitted shells (``assembled_bore``), at a
known temperature. :func:`calibrate_housing` finds the outer diameter whose
press fit (:func:`stackup.fit.press_fit`, Lamé rings with the crush height's
free shell ring, Kopeliovich) reproduces the assembled bores.

Model of one test
-----------------
The shell pair is one ring of the mean wall :math:`\bar t = (t_u + t_l)/2`
and the mean crush height :math:`\bar h = (h_u + h_l)/2` (the excess length of
the closed ring is the sum of both halves'; the geometry of the bore is exact,
:math:`D + \text{swell} - t_u - t_l`; the ring's stiffness uses the mean wall).
The bore and walls are read at the test's temperature :math:`T` and referred to
the engine's assembly temperature by the housing's and the steel back's
expansion; the crush heights are those of the checking block. The model's
assembled bore is ``press_fit(...).shell_bore`` at :math:`T` with the engine's
other press-fit parameters (:meth:`stackup.engines.PressFitSpec.kwargs`).

Estimate and interval
---------------------
Least squares over the outer diameter :math:`b`:
:math:`S(b) = \sum_i (d_i - \hat d_i(b))^2`, minimised on a grid over
:math:`b/D` in [1.02, 40] then refined. The interval is the profile-likelihood
(likelihood-ratio) interval of a one-parameter least-squares fit with the
noise estimated (Bates and Watts 1988, sec. 6.1):

.. math:: \{b : S(b) \le S(\hat b)\,(1 + F_{1,n-1}(c)/(n - 1))\},

exact for a model linear in its parameter and invariant to how the parameter
is written (an outer diameter, its ratio to the bore, or the housing's
radial stiffness give the same interval). The swell flattens as the ring
stiffens, so the upper end can be unbounded: tests whose swell is that of a
rigid ring cannot put an upper bound on the diameter (``inf``).

References
----------
.. [1] ISO 13778:2017, clause 4 (housing swell; fitting tests).
.. [2] Kopeliovich, D., *Crush height of engine bearings* (press fit, crush check).
.. [3] Bates, D. M., Watts, D. G., *Nonlinear Regression Analysis and Its Applications*, Wiley, 1988, sec. 6.1.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize, stats

from .. import materials
from .._validate import PLAUSIBLE, InRange, OneOf, validated
from ..engines import engine_path, load_engine
from ..fit import press_fit
from . import _data
from .engine_file import file_units, write_engine

#: Columns of a fitting-test table: lengths (in the table's unit, m by default), temperature in degC.
TEST_COLUMNS = ("housing_bore", "shell_upper_wall", "shell_lower_wall", "shell_upper_crush", "shell_lower_crush",
                "assembled_bore", "temperature")
#: Fewest tests: one parameter and the noise, with a degree of freedom left for the interval.
MIN_TESTS = 3
#: Outer diameters searched, as ratios to the largest housing bore: from a thin ring to a rigid one.
RATIO_RANGE = (1.02, 40.0)
_GRID = 240
#: Farthest an assembled bore may lie from the housing bore minus both walls [m]; swell is micrometres.
ASSEMBLED_OFF = 0.2e-3


@dataclass(frozen=True)
class HousingCalibration:
    """What :func:`calibrate_housing` found; lengths in m.

    Attributes
    ----------
    housing_outer : float
        Equivalent outer diameter of the housing ring [m].
    housing_outer_ci : (float, float)
        Its profile-likelihood interval [m]; the upper end is ``inf`` when the
        tests cannot tell the housing from a rigid one.
    residuals : numpy.ndarray
        Measured minus fitted assembled bore, per test [m].
    swell : numpy.ndarray
        Fitted housing swell per test [m].
    residual_sigma : float
        Standard deviation of the residuals (n - 1 degrees of freedom) [m].
    assumed_outer : float
        The engine file's ``housing_outer`` [m].
    """

    housing_outer: float
    housing_outer_ci: tuple
    residuals: np.ndarray = field(repr=False)
    swell: np.ndarray = field(repr=False)
    residual_sigma: float
    assumed_outer: float
    confidence: float
    engine: str
    engine_file: str | None
    source: str

    @property
    def n_tests(self):
        return int(self.residuals.size)

    def summary(self):
        """A few lines of plain text: the diameter, its interval, the swell and the residuals."""
        lo, hi = self.housing_outer_ci
        upper = "unbounded (as stiff as a rigid ring)" if np.isinf(hi) else f"{hi * 1e3:.1f} mm"
        return "\n".join([
            f"{self.source or 'fitting tests'}: {self.n_tests} tests on engine {self.engine}",
            f"  housing_outer = {self.housing_outer * 1e3:.1f} mm ({self.confidence:.0%} profile-likelihood interval "
            f"{lo * 1e3:.1f} mm to {upper}); the engine file assumed {self.assumed_outer * 1e3:.1f} mm",
            f"  swell {np.mean(self.swell) * 1e6:.1f} um on average ({np.min(self.swell) * 1e6:.1f}-"
            f"{np.max(self.swell) * 1e6:.1f} um); residuals {self.residual_sigma * 1e6:.2f} um standard deviation, "
            f"largest {np.max(np.abs(self.residuals)) * 1e6:.2f} um"])

    def value(self, which="estimate"):
        """The outer diameter [m]: the ``"estimate"``, or the ``"lower"`` or ``"upper"`` end of its interval."""
        options = {"estimate": self.housing_outer, "lower": self.housing_outer_ci[0],
                   "upper": self.housing_outer_ci[1]}
        if which not in options:
            raise ValueError(f"which: {which!r} is not one of 'estimate', 'lower', 'upper'")
        if not np.isfinite(options[which]):
            raise ValueError(f"which: the {which} end of the interval is unbounded (the tests see a rigid housing); "
                             "write the estimate, or add tests")
        return float(options[which])

    def entry(self, which="estimate", units="mm"):
        """The change of :func:`stackup.measure.write_engine` setting ``[press_fit] housing_outer`` (``units``: the
        engine file's), with a comment giving the interval, the tests and the value it replaces."""
        value = self.value(which)
        scale = _data.UNITS[units]
        lo, hi = self.housing_outer_ci
        hi_text = "unbounded" if np.isinf(hi) else f"{hi / scale:.6g}"
        comment = (f"housing_outer {'' if which == 'estimate' else f'({which} end of the interval) '}calibrated by "
                   f"stackup.measure.calibrate_housing from {self.n_tests} fitting tests"
                   f"{f' in {self.source}' if self.source else ''}:\n{self.housing_outer / scale:.6g} "
                   f"({self.confidence:.0%} profile-likelihood interval {lo / scale:.6g} to {hi_text}, residuals "
                   f"{self.residual_sigma * 1e6:.2f} um); the file assumed {self.assumed_outer / scale:.6g}")
        return ("press_fit", "housing_outer", value / scale, comment)

    def write_engine(self, out, *, which="estimate", name=None, force=False):
        """Write a copy of the engine file with ``[press_fit] housing_outer`` calibrated; return its path.

        The line is marked with a comment giving the interval, the tests and
        the value it replaces; every other line stays. ``which`` writes an end
        of the interval instead of the estimate (for the model-uncertainty
        check of a verdict). The engine's own file is never replaced unless
        ``force``.
        """
        if self.engine_file is None:
            raise ValueError("engine: calibrated on an Engine object; give calibrate_housing the engine's name or "
                             "file to write a copy of it")
        units = file_units(self.engine_file)
        return write_engine(self.engine_file, out, [self.entry(which, units)], name=name, force=force)


@validated(confidence=InRange(0.5, 1.0, lo_open=True, hi_open=True), units=OneOf(tuple(_data.UNITS)))
def calibrate_housing(tests, engine, *, units="m", confidence=0.95):
    """The housing's equivalent outer diameter from fitting tests, by least squares through the press fit.

    Parameters
    ----------
    tests : str, path, mapping or pandas.DataFrame
        A CSV file or a table with the columns :data:`TEST_COLUMNS` (lengths
        in ``units``, ``temperature`` in degC), one row per fitting test.
    engine : str, path or Engine
        The engine whose press fit is calibrated (its materials, shell width,
        lining, checking block, assembly temperature).
    units : {"m", "mm", "um"}
        The lengths' unit (``stackup measure swell --units``: mm, the engine
        file's, by default).
    confidence : float
        Level of the interval.

    Returns
    -------
    HousingCalibration

    Notes
    -----
    Model and interval in the module docstring of :mod:`stackup.measure.housing`.
    """
    eng = load_engine(engine)
    columns, source = _tests(tests, eng, units)
    model = _Model(eng, columns)
    ods, ssr = model.profile()
    best = int(np.argmin(ssr))
    lo_b, hi_b = ods[max(best - 1, 0)], ods[min(best + 1, ods.size - 1)]
    found = optimize.minimize_scalar(model.ssr, bounds=(lo_b, hi_b), method="bounded",
                                     options={"xatol": 1e-9 * ods[best]})
    outer = float(found.x) if found.fun <= ssr[best] else float(ods[best])
    s_min = model.ssr(outer)
    n = model.n
    level = s_min * (1.0 + stats.f.ppf(confidence, 1, n - 1) / (n - 1))
    lower = _crossing(model.ssr, level, ods[0], outer)
    upper = _crossing(model.ssr, level, outer, ods[-1])
    fitted = model.predict(outer)
    residuals = columns["assembled_bore"] - fitted.shell_bore
    return HousingCalibration(
        outer, (lower if lower is not None else float(ods[0]), upper if upper is not None else np.inf),
        residuals, np.asarray(fitted.housing_swell), float(np.sqrt(s_min / (n - 1))), eng.press_fit.housing_outer,
        confidence, eng.name, None if not isinstance(engine, (str, Path)) else str(engine_path(engine)), source)


def _crossing(f, level, a, b):
    """Where ``f`` crosses ``level`` between a and b (f(inner end) < level), or None if it stays below."""
    fa, fb = f(a) - level, f(b) - level
    if fa > 0 > fb or fa < 0 < fb:
        return float(optimize.brentq(lambda x: f(x) - level, a, b, xtol=1e-9 * b))
    return None


class _Model:
    """Assembled bores of the tests for an outer diameter (press fit with the engine's parameters)."""

    def __init__(self, engine, columns):
        spec = engine.press_fit
        self.kwargs = {k: v for k, v in spec.kwargs().items() if k not in ("housing_outer", "temperature")}
        housing = materials.get(spec.housing_material)
        back = materials.get(spec.shell_material)
        dt = columns["temperature"] - spec.assembly_temperature
        self.bore = columns["housing_bore"] / (1.0 + housing.expansion * dt)
        self.wall = 0.5 * (columns["shell_upper_wall"] + columns["shell_lower_wall"]) / (1.0 + back.expansion * dt)
        self.crush = 0.5 * (columns["shell_upper_crush"] + columns["shell_lower_crush"])
        self.temperature = columns["temperature"]
        self.measured = columns["assembled_bore"]
        self.n = self.measured.size

    def predict(self, outer):
        return press_fit(housing_bore=self.bore, housing_outer=outer, shell_wall=self.wall, crush_height=self.crush,
                         temperature=self.temperature, **self.kwargs)

    def ssr(self, outer):
        return float(np.sum((self.measured - self.predict(np.asarray(outer, dtype=float)).shell_bore) ** 2))

    def profile(self):
        """The outer diameters of the search grid and the sums of squares there."""
        top = float(np.max(self.bore))
        ods = top * np.geomspace(*RATIO_RANGE, _GRID)
        fit = self.predict(ods[:, None])
        return ods, np.sum((self.measured - fit.shell_bore) ** 2, axis=1)


def _tests(tests, engine, units):
    """The test table's columns as float arrays [m, degC] (lengths read in ``units``), checked; and its name for
    messages."""
    if isinstance(tests, (str, Path)):
        table = _data.read_csv(tests, numeric=TEST_COLUMNS)
        columns, where, source = table.values, table.where, table.file
    else:
        missing = [c for c in TEST_COLUMNS if c not in tests]
        if missing:
            raise ValueError(f"tests: no column {', '.join(map(repr, missing))}; a fitting-test table has "
                             f"{', '.join(TEST_COLUMNS)} (lengths in {units}, temperature in degC)")
        where = lambda c: _data.Where(None, f"tests[{c!r}]")  # noqa: E731
        columns = {c: _data.finite_values(np.asarray(tests[c]).ravel(), where(c)) for c in TEST_COLUMNS}
        source = ""
    n = columns["housing_bore"].size
    if n < MIN_TESTS:
        raise ValueError(f"{source or 'tests'}: {n} fitting test{'s' if n != 1 else ''}; the calibration needs at "
                         f"least {MIN_TESTS}")
    _plausible(columns, where, engine, units)
    scale = _data.UNITS[units]
    return {c: v if c == "temperature" else v * scale for c, v in columns.items()}, source


def _plausible(columns, where, engine, units):
    """Lengths in ``units`` near the engine's drawing (a unit slip named), temperatures in the press fit's range."""
    k, unit = _data.UNITS[units], _data.UNIT_NAMES[units]  # the drawing in the tests' unit
    bore = engine.housing_bore
    _data.plausible(columns["housing_bore"], bore.lo / k, bore.hi / k, where("housing_bore"), units)
    crush = engine.shell_wall.crush
    for name in ("shell_upper_crush", "shell_lower_crush"):
        _data.plausible(columns[name], crush.lo / k, crush.hi / k, where(name), units)
    wall_guess = 0.5 * (bore.lo - engine.journal_d.hi) / k
    for name in ("shell_upper_wall", "shell_lower_wall"):
        _data.plausible(columns[name], 0.9 * wall_guess, 1.1 * wall_guess, where(name), units)
    _data.plausible(columns["assembled_bore"], engine.journal_d.lo / k, bore.hi / k, where("assembled_bore"), units)
    expected = columns["housing_bore"] - columns["shell_upper_wall"] - columns["shell_lower_wall"]
    off = np.flatnonzero(np.abs(columns["assembled_bore"] - expected) > ASSEMBLED_OFF / k)
    if off.size:
        w, i = where("assembled_bore"), off[0]
        raise ValueError(f"{w}, {w.rows(off)}: {columns['assembled_bore'][i]:.6g} {unit} is not the bore inside the "
                         f"shells: housing_bore - both walls is {expected[i]:.6g} {unit} there, and the swell is "
                         f"micrometres (valid: within {ASSEMBLED_OFF * 1e3:g} mm of it)")
    t = columns["temperature"]
    valid = PLAUSIBLE["engine_temperature"]
    bad = np.flatnonzero((t < valid.lo) | (t > valid.hi))
    if bad.size:
        w = where("temperature")
        kelvin = np.all((t - 273.15 >= valid.lo) & (t - 273.15 <= valid.hi))
        hint = "; these look like kelvin: give degC (kelvin - 273.15)" if kelvin else ""
        raise ValueError(f"{w}, {w.rows(bad)}: {t[bad[0]]:g} degC is not a plausible {valid.what} ({valid.lo:g} to "
                         f"{valid.hi:g} degC){hint}")
