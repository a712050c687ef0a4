"""Oil film of a main bearing: minimum film thickness in tiers, and the film over the engine cycle.

Tiers of :func:`min_film_thickness` (steady load):

- ``"short"``: Ocvirk's short-bearing closed form (:mod:`stackup.film.tiers`);
- ``"finite"``: Ocvirk's form times a load and attitude correction tabulated
  from the Reynolds tier over L/D 0.1-2 and eccentricity 0.02-0.98
  (``studies/film_finite_table.py``; its error is in ``reports/film_speed_vs_error.md``);
- ``"reynolds"``: finite-difference Reynolds equation with Swift-Stieber
  cavitation (:mod:`stackup.film.reynolds`), the reference tier.

The friction torque and side flow of every tier use the short-bearing forms at
the tier's eccentricity, except ``"reynolds"``, which integrates its own field.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from .. import _validate as check
from . import oil, reynolds, tiers

METHODS = ("short", "finite", "reynolds")


@dataclass(frozen=True)
class Film:
    """Steady film of a journal bearing; arrays broadcast over the inputs.

    Attributes
    ----------
    eccentricity : numpy.ndarray
        Eccentricity ratio [-].
    h_min : numpy.ndarray
        Minimum film thickness [m].
    attitude_angle : numpy.ndarray
        Angle between the load line and the line of centres [rad].
    friction_torque : numpy.ndarray
        Friction torque on the journal [N m].
    side_flow : numpy.ndarray
        Oil leaving both ends of the bearing [m^3/s].
    """

    eccentricity: np.ndarray
    h_min: np.ndarray
    attitude_angle: np.ndarray
    friction_torque: np.ndarray
    side_flow: np.ndarray


@lru_cache(maxsize=1)
def _finite_table():
    data = np.load(resources.files("stackup") / "data" / "film_finite_table.npz")
    grid = (np.log(data["length_over_diameter"]), data["eccentricity"])
    ratio = RegularGridInterpolator(grid, np.log(data["load_ratio"]), bounds_error=False, fill_value=None)
    attitude = RegularGridInterpolator(grid, data["attitude"], bounds_error=False, fill_value=None)
    return ratio, attitude, (data["length_over_diameter"][[0, -1]], data["eccentricity"][[0, -1]])


def _finite(load, *, radius, length, radial_clearance, viscosity, speed):
    ratio, attitude, (ld_range, _) = _finite_table()
    ld = length / (2 * radius)
    if np.any((ld < ld_range[0]) | (ld > ld_range[1])):
        raise ValueError(f"length: L/D {float(np.min(ld))!r}..{float(np.max(ld))!r} is outside the finite tier's "
                         f"table [{ld_range[0]}, {ld_range[1]}]; use method='reynolds'")
    log_ld = np.log(ld)

    def load_function(eps):
        pts = np.stack(np.broadcast_arrays(log_ld, eps), axis=-1)
        return tiers.short_load_function(eps) * np.exp(ratio(pts).reshape(np.shape(eps)))

    scale = viscosity * speed * radius * length**3 / (4 * radial_clearance**2)
    eps = tiers.invert_monotone(load_function, load / scale)
    phi = attitude(np.stack(np.broadcast_arrays(log_ld, eps), axis=-1)).reshape(np.shape(eps))
    return eps, phi


def min_film_thickness(load, *, diameter, length, clearance, viscosity, speed, method="short"):
    """Eccentricity, minimum film, attitude, friction torque and side flow under a steady load.

    Parameters
    ----------
    load : array_like
        Bearing load [N], > 0.
    diameter : array_like
        Journal diameter [m].
    length : array_like
        Bearing length (width) [m].
    clearance : array_like
        Diametral clearance [m]; the radial clearance is half of it.
    viscosity : array_like
        Dynamic viscosity of the oil [Pa s].
    speed : array_like
        Journal angular speed [rad/s], > 0.
    method : {"short", "finite", "reynolds"}

    Returns
    -------
    Film
    """
    check.one_of("method", method, METHODS)
    load = check.positive("load", load)
    radius = check.positive("diameter", diameter) / 2
    length = check.positive("length", length)
    c = check.positive("clearance", clearance) / 2
    mu = check.positive("viscosity", viscosity)
    omega = check.positive("speed", speed)
    load, radius, length, c, mu, omega = np.broadcast_arrays(load, radius, length, c, mu, omega)
    kw = dict(radius=radius, length=length, radial_clearance=c, viscosity=mu, speed=omega)
    if method == "reynolds":
        return _reynolds(load, **kw)
    eps, phi = (tiers.short if method == "short" else _finite)(load, **kw)
    h_min, torque, flow = tiers.film_quantities(eps, phi, load, **kw)
    return Film(eps, h_min, phi, torque, flow)


def _reynolds(load, *, radius, length, radial_clearance, viscosity, speed):
    out = {k: np.empty(load.shape) for k in ("eps", "phi", "torque", "flow")}
    for idx in np.ndindex(load.shape):
        r, l, c, mu, w = (float(a[idx]) for a in (radius, length, radial_clearance, viscosity, speed))
        unit = mu * w * r**4 / c**2  # load of a unit dimensionless force [N]
        field = reynolds.eccentricity_for_load(float(load[idx]) / unit, l / r)
        friction, flow = reynolds.friction_and_flow(field)
        out["eps"][idx] = field.eps
        out["phi"][idx] = field.attitude
        out["torque"][idx] = mu * w * r**4 / c * friction
        out["flow"][idx] = w * r**2 * c / 12 * flow
    return Film(out["eps"], radial_clearance * (1 - out["eps"]), out["phi"], out["torque"], out["flow"])


#: Steady tiers from cheapest to dearest.
BY_COST = ("short", "finite", "reynolds")
#: Grid on which :func:`tier_errors` measures the cheaper tiers against the reference; it lies
#: between the nodes of the finite tier's table, where its interpolation error is largest.
ERROR_GRID = {"length_over_diameter": (0.33, 0.55, 0.85, 1.6), "eccentricity": (0.33, 0.55, 0.77, 0.87, 0.935)}


@lru_cache(maxsize=1)
def tier_errors():
    """Largest relative h_min error of each steady tier against ``reynolds`` over :data:`ERROR_GRID`.

    For each L/D and reference eccentricity, the load the Reynolds tier
    carries there is handed to each tier (R = 1, c = 1e-3, mu = omega = 1).
    """
    errors = {"reynolds": 0.0}
    cases = []
    for ld in ERROR_GRID["length_over_diameter"]:
        for eps in ERROR_GRID["eccentricity"]:
            field = reynolds.solve_field(eps, 2 * ld)
            cases.append((ld, field.force * 1e6, 1e-3 * (1 - eps)))  # load of unit viscosity and speed, h_min
    for method in ("short", "finite"):
        worst = 0.0
        for ld, load, h_ref in cases:
            f = min_film_thickness(load, diameter=2.0, length=2.0 * ld, clearance=2e-3, viscosity=1.0, speed=1.0,
                                   method=method)
            worst = max(worst, abs(float(f.h_min) / h_ref - 1))
        errors[method] = worst
    return errors


def cheapest_tier(max_error):
    """The cheapest steady tier whose h_min error against ``reynolds`` is at most ``max_error`` [-]."""
    max_error = float(check.positive("max_error", max_error, allow_zero=True))
    errors = tier_errors()
    return next(m for m in BY_COST if errors[m] <= max_error)


__all__ = ["BY_COST", "ERROR_GRID", "cheapest_tier", "tier_errors", "METHODS", "Film", "min_film_thickness", "oil", "reynolds", "tiers"]
