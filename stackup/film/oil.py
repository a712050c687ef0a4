r"""Oil viscosity (Vogel, with an optional pressure term) and the isothermal heat balance.

.. math:: \mu(T, p) = C_1 \exp\left(\frac{C_2}{T + C_3} + \beta p\right)

with :math:`T` in degC (Vogel 1921; the pressure term as in Rozhdestvensky et
al. 2018, eq. 3). Built-in oils fit :math:`C_1, C_2, C_3` exactly through
three points per grade (``stackup/data/oils.toml``, with sources).

Effective film temperature (isothermal heat balance): the friction power
:math:`N = T_f\,\omega` is carried away by the side flow :math:`Q`,

.. math:: T_{eff} = T_{supply} + k\,\frac{N(\mu(T_{eff}))}{\rho\,c_p\,Q(\mu(T_{eff}))}

with :math:`k = 1/2` (mean of inlet and outlet), solved by damped fixed-point
iteration.

References
----------
.. [1] Vogel, H., "Das Temperaturabhängigkeitsgesetz der Viskosität von
   Flüssigkeiten", Physikalische Zeitschrift 22 (1921) 645-646.
.. [2] Rozhdestvensky et al. 2018, eq. 3 (pressure and temperature dependence).
.. [3] SAE J300 (2015), Engine Oil Viscosity Classification.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources

import numpy as np
from scipy import optimize

from .. import _validate as check

SPECIFIC_HEAT = 2000.0  # mineral engine oil [J/(kg K)]
THERMAL_EXPANSION = 6.5e-4  # volumetric, for the density [1/K]


@dataclass(frozen=True)
class Oil:
    """An oil: Vogel constants, density and the pressure-viscosity coefficient.

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
        :math:`\\beta` [1/Pa]; 0 ignores the pressure term.
    source : str
    """

    name: str
    c1: float
    c2: float
    c3: float
    density15: float
    pressure_coefficient: float = 0.0
    source: str = ""

    def viscosity(self, temperature, pressure=0.0):
        """Dynamic viscosity [Pa s] at temperature [degC] and pressure [Pa]."""
        t = check.in_range("temperature", temperature, -30.0, 300.0, unit=" degC")
        return self.c1 * np.exp(self.c2 / (t + self.c3) + self.pressure_coefficient * np.asarray(pressure))

    def density(self, temperature):
        """Density [kg/m^3] at temperature [degC]."""
        return self.density15 / (1.0 + THERMAL_EXPANSION * (np.asarray(temperature) - 15.0))


def fit_vogel(temperatures, viscosities):
    """Vogel constants (C1 [Pa s], C2, C3 [K]) through three (temperature [degC], viscosity [Pa s]) points."""
    t = np.asarray(temperatures, dtype=float)
    ln = np.log(np.asarray(viscosities, dtype=float))
    if t.shape != (3,) or not np.all(np.diff(t) > 0) or not np.all(np.diff(ln) < 0):
        raise ValueError("fit_vogel: give three increasing temperatures with decreasing viscosities")

    def mismatch(c3):
        ratio = (1 / (t[0] + c3) - 1 / (t[1] + c3)) / (1 / (t[1] + c3) - 1 / (t[2] + c3))
        return ratio - (ln[0] - ln[1]) / (ln[1] - ln[2])

    c3 = optimize.brentq(mismatch, -t[0] + 1e-3, 1e4)
    c2 = (ln[0] - ln[1]) / (1 / (t[0] + c3) - 1 / (t[1] + c3))
    c1 = np.exp(ln[0] - c2 / (t[0] + c3))
    return float(c1), float(c2), float(c3)


def _builtin():
    with open(resources.files("stackup") / "data" / "oils.toml", "rb") as f:
        table = tomllib.load(f)
    oils = {}
    for name, e in table.items():
        rho = np.array([e["density15"] / (1 + THERMAL_EXPANSION * (t - 15)) for t in (40.0, 100.0)])
        mu = [e["kv40"] * rho[0], e["kv100"] * rho[1], e["hths150"]]
        oils[name] = Oil(name, *fit_vogel([40.0, 100.0, 150.0], mu), e["density15"], source=e["source"])
    return oils


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


def effective_temperature(oil, supply_temperature, film, *, share=0.5, tolerance=1e-3, max_iterations=100):
    """Effective film temperature [degC] and viscosity [Pa s] from the isothermal heat balance.

    ``film(viscosity)`` returns (friction power [W], side flow [m^3/s]) for a
    viscosity [Pa s] (arrays broadcast). Damped fixed point on the temperature.
    """
    oil = get(oil)
    t_in = check.in_range("supply_temperature", supply_temperature, -30.0, 200.0, unit=" degC")
    t = np.array(t_in, dtype=float)
    for _ in range(max_iterations):
        mu = oil.viscosity(np.minimum(t, 299.0))
        power, flow = film(mu)
        rise = share * power / (oil.density(t) * SPECIFIC_HEAT * np.maximum(flow, 1e-12))
        t_new = t_in + rise
        if np.all(np.abs(t_new - t) < tolerance):
            return t_new, oil.viscosity(np.minimum(t_new, 299.0))
        t = 0.5 * (t + t_new)
    raise ValueError(f"effective_temperature: the heat balance did not converge in {max_iterations} iterations")
