r"""Engine oil viscosity: temperature (Vogel), shear thinning (Cross) and pressure (Barus).

Low-shear viscosity, Vogel (1921):

.. math:: \mu_0(T) = C_1 \exp\left(\frac{C_2}{T + C_3}\right), \qquad T \text{ in degC}

fitted to **low-shear points only**: the measured kinematic viscosities at
40 and 100 degC (KV40, KV100, times the density) and the ASTM D341 (Walther)
extrapolation of those two to 150 degC, the standard way to carry KV40/KV100
to other temperatures. :math:`C_3` is kept inside :data:`VOGEL_C3_RANGE` (a
Vogel temperature :math:`-C_3` of about 90-210 K; Cameron gives about 95
degC for mineral oils). Fitting the high-shear HTHS viscosity at 150 degC
together with the low-shear KV40 and KV100 of a multigrade oil, as this
module did before, mixes two flow curves and bends the fit: 10W-40 got
:math:`C_3` = 258 K, a Vogel temperature of 15 K.

Shear thinning of multigrade (polymer-thickened) oils, Cross (1965), with the
high-shear point HTHS (150 degC, 1e6 1/s, SAE J300 / ASTM D4683):

.. math:: \mu(T, \dot\gamma) = \mu_0(T)\left[r_\infty + \frac{1 - r_\infty}
          {1 + (\dot\gamma/\dot\gamma_c(T))^{m}}\right], \qquad
          \dot\gamma_c(T) = \dot\gamma_{c,150}\,\frac{\mu_0(150)}{\mu_0(T)}

:math:`m` and :math:`\dot\gamma_{c,150}` from :data:`CROSS_VII`; the
second-Newtonian share :math:`r_\infty` is solved so that the curve passes
through HTHS at 150 degC and 1e6 1/s; the critical shear rate moves with the
low-shear viscosity (time-temperature superposition). Monograde oils are
Newtonian (their HTHS is only checked against the low-shear curve).

Pressure (Barus 1893), an option: :math:`\mu(T, \dot\gamma, p) = \mu(T, \dot\gamma)\,e^{\alpha p}`
with the oil's pressure-viscosity coefficient :math:`\alpha`; the
Rozhdestvensky et al. (2018) form (eq. 3) is Vogel with this term.

Which points each fit uses: the Vogel fit KV40, KV100 (and D341 at 150 degC
from them): low shear only; the Cross fit adds HTHS150 at 1e6 1/s: high
shear; :data:`CROSS_VII` fixes the shape of the transition.

References
----------
.. [1] Vogel, H., "Das Temperaturabhängigkeitsgesetz der Viskosität von
   Flüssigkeiten", Physikalische Zeitschrift 22 (1921) 645-646.
.. [2] ASTM D341-20, Standard Practice for Viscosity-Temperature Equations and
   Charts for Liquid Petroleum or Hydrocarbon Products (Walther equation).
.. [3] Cameron, A., *Basic Lubrication Theory*, 3rd ed., Ellis Horwood, 1981,
   ch. 1 (Vogel's equation; constant about 95 degC for mineral oils).
.. [4] Cross, M. M., "Rheology of non-Newtonian fluids: a new flow equation for
   pseudoplastic systems", J. Colloid Sci. 20 (1965) 417-437 (exponent 2/3).
.. [5] SAE J300 (2015), Engine Oil Viscosity Classification (HTHS at 150 degC, 1e6 1/s).
.. [6] Barus, C., "Isothermals, isopiestics and isometrics relative to
   viscosity", Am. J. Sci. 45 (1893) 87-96.
.. [7] Rozhdestvensky et al. 2018, eq. 3 (pressure and temperature dependence).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from importlib import resources

import numpy as np
from scipy import optimize

from .._files import Table, parse_toml
from .._validate import Finite, InRange, Positive, validated

#: Specific heat of engine oil at film temperatures (80-150 degC) [J/(kg K)] (mineral oils 2.0-2.3 kJ/(kg K)).
SPECIFIC_HEAT = 2000.0
#: Volumetric thermal expansion for the density [1/K] (ASTM D1250 tables give 6-7e-4 1/K for lubricating oils).
THERMAL_EXPANSION = 6.5e-4
#: Admissible Vogel constant C3 [K] (Vogel temperature -C3 degC between about 90 K and 210 K).
VOGEL_C3_RANGE = (60.0, 180.0)
#: Temperature range of the viscosity model [degC].
TEMPERATURE_RANGE = (-30.0, 300.0)


@dataclass(frozen=True)
class CrossParameters:
    """Shape of the Cross shear-thinning curve of polymer-thickened (multigrade) oils.

    Attributes
    ----------
    exponent : float
        :math:`m` [-]; 2/3, Cross's value for a wide range of pseudoplastic systems.
    critical_shear_rate : float
        :math:`\\dot\\gamma_c` at 150 degC [1/s]; 3e5 1/s, the inverse of the
        Zimm relaxation time of an olefin-copolymer viscosity modifier
        (M about 1e5 g/mol) in a base oil of about 2.5 mPa s at 150 degC: an
        order-of-magnitude estimate, not a measurement. The viscosity at the
        HTHS condition is exact whatever this value.
    hths_shear_rate : float
        Shear rate of the HTHS test [1/s] (SAE J300, ASTM D4683: 1e6 1/s).
    hths_temperature : float
        [degC] (150).
    source : str
    """

    exponent: float = 2.0 / 3.0
    critical_shear_rate: float = 3e5
    hths_shear_rate: float = 1e6
    hths_temperature: float = 150.0
    source: str = ("Cross 1965 (m = 2/3); SAE J300 (HTHS at 150 degC, 1e6 1/s); critical shear rate 3e5 1/s at "
                   "150 degC estimated from the Zimm relaxation time of an OCP viscosity modifier")


#: Cross parameters of multigrade engine oils.
CROSS_VII = CrossParameters()


@dataclass(frozen=True)
class Oil:
    """An oil: low-shear Vogel constants, density, shear thinning and the pressure-viscosity coefficient.

    Attributes
    ----------
    name : str
    c1 : float
        [Pa s]
    c2, c3 : float
        [K] (with T in degC)
    density15 : float
        Density at 15 degC [kg/m^3].
    pressure_coefficient : float
        Barus :math:`\\alpha` [1/Pa] (applied only where a pressure is given).
    source : str
    second_newtonian : float
        :math:`r_\\infty`, high-shear over low-shear viscosity [-]; 1 for a Newtonian oil.
    critical_shear_rate : float
        :math:`\\dot\\gamma_c` at 150 degC [1/s].
    thinning_exponent : float
        Cross exponent :math:`m` [-].
    assumed : bool
        The numbers are typical of the grade, not one oil's data sheet.
    """

    name: str
    c1: float
    c2: float
    c3: float
    density15: float
    pressure_coefficient: float = 0.0
    source: str = ""
    second_newtonian: float = 1.0
    critical_shear_rate: float = CROSS_VII.critical_shear_rate
    thinning_exponent: float = CROSS_VII.exponent
    assumed: bool = False

    @validated(temperature=InRange(*TEMPERATURE_RANGE, unit=" degC"))
    def low_shear_viscosity(self, temperature):
        """Low-shear (Vogel) dynamic viscosity [Pa s] at temperature [degC]."""
        return self.c1 * np.exp(self.c2 / (np.asarray(temperature, dtype=float) + self.c3))

    @validated(temperature=InRange(*TEMPERATURE_RANGE, unit=" degC"), shear_rate=Positive(zero=True),
               pressure=Positive(zero=True))
    def viscosity(self, temperature, *, shear_rate=None, pressure=0.0):
        """Dynamic viscosity [Pa s] at temperature [degC], shear rate [1/s] and pressure [Pa].

        Without a shear rate the low-shear (Vogel) viscosity; with one, the
        Cross curve (a Newtonian oil is unchanged); the pressure term
        :math:`e^{\\alpha p}` where a pressure is given.
        """
        mu0 = self.low_shear_viscosity(temperature)
        if shear_rate is not None and self.second_newtonian < 1.0:
            rate = np.asarray(shear_rate, dtype=float)
            critical = self.critical_shear_rate * self.c1 * np.exp(self.c2 / (CROSS_VII.hths_temperature + self.c3)) / mu0
            r = self.second_newtonian
            mu0 = mu0 * (r + (1 - r) / (1 + (rate / critical) ** self.thinning_exponent))
        return mu0 * np.exp(self.pressure_coefficient * np.asarray(pressure, dtype=float))

    def density(self, temperature):
        """Density [kg/m^3] at temperature [degC]."""
        return self.density15 / (1.0 + THERMAL_EXPANSION * (np.asarray(temperature) - 15.0))


def _one_flow_curve(values):
    t, mu = values["temperatures"], values["viscosities"]
    if t.ndim != 1 or t.size < 3 or t.shape != mu.shape or not np.all(np.diff(t) > 0) or not np.all(np.diff(mu) < 0):
        raise ValueError("fit_vogel: give at least three increasing temperatures with decreasing viscosities")


@validated(temperatures=Finite(), viscosities=Positive(), relations=(_one_flow_curve,))
def fit_vogel(temperatures, viscosities, *, c3_range=VOGEL_C3_RANGE):
    """Vogel constants (C1 [Pa s], C2, C3 [K]) by least squares in ln(viscosity), C3 inside ``c3_range``.

    Parameters
    ----------
    temperatures : array_like
        At least three increasing temperatures [degC].
    viscosities : array_like
        Decreasing dynamic viscosities [Pa s] at those temperatures (one flow curve: all low-shear).
    c3_range : (float, float)
        Admissible C3 [K]; three points whose exact fit lies inside it are reproduced exactly.
    """
    t = np.asarray(temperatures, dtype=float)
    mu = np.asarray(viscosities, dtype=float)
    lo, hi = max(c3_range[0], -t[0] + 1e-3), c3_range[1]
    ln = np.log(mu)

    def linear(c3):
        a = np.stack([np.ones_like(t), 1.0 / (t + c3)], axis=-1)
        coef, *_ = np.linalg.lstsq(a, ln, rcond=None)
        return coef, float(np.sum((a @ coef - ln) ** 2))

    best = optimize.minimize_scalar(lambda c3: linear(c3)[1], bounds=(lo, hi), method="bounded",
                                    options={"xatol": 1e-10})
    c3 = min((float(best.x), lo, hi), key=lambda c: linear(c)[1])  # a bounded optimum may sit on a bound
    (ln_c1, c2), _ = linear(c3)
    return float(np.exp(ln_c1)), float(c2), c3


def walther_kinematic_viscosity(kv40, kv100, temperature):
    """Kinematic viscosity [m^2/s] at temperature [degC] through KV40 and KV100 [m^2/s] (ASTM D341).

    .. math:: \\log_{10}\\log_{10}(\\nu + 0.7) = A - B\\log_{10} T, \\qquad \\nu \\text{ in cSt},\\ T \\text{ in K}
    """
    z = [np.log10(np.log10(kv * 1e6 + 0.7)) for kv in (kv40, kv100)]
    b = (z[0] - z[1]) / (np.log10(373.15) - np.log10(313.15))
    a = z[0] + b * np.log10(313.15)
    return (10 ** 10 ** (a - b * np.log10(np.asarray(temperature, dtype=float) + 273.15)) - 0.7) * 1e-6


def _si(t, key, lo, hi, unit, data_sheet):
    """A required number of an oil's table in SI; the message says how a data sheet's unit converts."""
    try:
        return t.number(key, required=True, lo=lo, hi=hi, unit=f" {unit}")
    except ValueError as error:
        raise ValueError(f"{error}; oils files are in SI: give {unit}, a data sheet's {data_sheet}") from None


def _from_table(t):
    """An :class:`Oil` from its table of an oils file (SI: m^2/s, Pa s, kg/m^3, 1/Pa); every key checked."""
    name = t.path
    # cSt (62) or mPa s (3.1) instead of SI fall outside these ranges.
    e = {"kv40": _si(t, "kv40", 1e-6, 1e-2, "m^2/s", "cSt (mm^2/s) times 1e-6"),
         "kv100": _si(t, "kv100", 1e-6, 1e-3, "m^2/s", "cSt (mm^2/s) times 1e-6"),
         "hths150": _si(t, "hths150", 5e-4, 0.1, "Pa s", "mPa s (cP) times 1e-3"),
         "density15": t.number("density15", required=True, lo=600.0, hi=1200.0, unit=" kg/m^3"),
         "multigrade": t.flag("multigrade", required=True),
         "pressure_coefficient": t.number("pressure_coefficient", 0.0, lo=0.0, hi=1e-7, unit=" 1/Pa"),
         "source": t.text("source", required=True), "assumed": bool(t.flag("assumed"))}
    t.close()
    if e["kv100"] >= e["kv40"]:
        raise ValueError(f"{t.where}, key {name}.kv100: {e['kv100']!r} m^2/s is not below kv40 {e['kv40']!r} m^2/s")
    rho = lambda t: e["density15"] / (1 + THERMAL_EXPANSION * (t - 15))  # noqa: E731
    points = np.array([40.0, 100.0, CROSS_VII.hths_temperature])
    nu = [e["kv40"], e["kv100"], walther_kinematic_viscosity(e["kv40"], e["kv100"], points[2])]
    c1, c2, c3 = fit_vogel(points, np.array(nu) * rho(points))
    oil = Oil(name, c1, c2, c3, e["density15"], e["pressure_coefficient"], e["source"], assumed=e["assumed"])
    if not e["multigrade"]:
        return oil
    # r_inf from HTHS: mu(150, 1e6) = mu0(150) (r + (1 - r) s), s = 1 / (1 + (1e6 / rate_c)^m)
    ratio = e["hths150"] / float(oil.low_shear_viscosity(CROSS_VII.hths_temperature))
    s = 1 / (1 + (CROSS_VII.hths_shear_rate / CROSS_VII.critical_shear_rate) ** CROSS_VII.exponent)
    r = (ratio - s) / (1 - s)
    if not 0 < r < 1:
        raise ValueError(f"{t.where}, key {name}.hths150: HTHS {e['hths150']!r} Pa s over the low-shear viscosity at "
                         f"150 degC gives a second-Newtonian share {r:.3g}, outside (0, 1)")
    return replace(oil, second_newtonian=float(r))


def read_oils(text, *, name):
    """The oils of an oils file's ``text`` (``name``: the file's name in messages), by oil name.

    The format of ``stackup/data/oils.toml``: one table per oil, SI units
    (kv40, kv100 [m^2/s], hths150 [Pa s], density15 [kg/m^3], multigrade,
    optional pressure_coefficient [1/Pa] and assumed, a source). Every key is
    checked.
    """
    where = f"oils file {name!r}"
    top = Table(parse_toml(text, where=where), where)
    return {oil: _from_table(top.table(oil)) for oil in top.data}


def user_oils(text, *, name):
    """The oils of a user's oils file (:func:`read_oils`); a built-in oil's name is refused (one name, one oil)."""
    oils = read_oils(text, name=name)
    taken = sorted(set(oils) & set(_OILS))
    if taken:
        raise ValueError(f"oils file {name!r}, key {taken[0]}: is the name of a built-in oil; give the oil of this "
                         "file a name of its own (the built-in ones: " + ", ".join(available()) + ")")
    return oils


def _builtin():
    path = resources.files("stackup") / "data" / "oils.toml"
    return read_oils(path.read_text(encoding="utf-8"), name="oils.toml (built-in)")


_OILS = _builtin()


def available():
    """Names of the built-in oils."""
    return sorted(_OILS)


def get(oil):
    """An :class:`Oil` from its name (or the Oil itself)."""
    if isinstance(oil, Oil):
        return oil
    if oil not in _OILS:
        raise ValueError(f"oil: {oil!r} is not a known oil ({', '.join(available())})")
    return _OILS[oil]
