"""One stage of a study: each bearing's oil film over the engine cycle at its effective temperature."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import oil as oils
from . import tiers
from .orbit import orbit


@dataclass(frozen=True)
class BearingFilms:
    """Film of bearings over the cycle.

    Attributes
    ----------
    h_min : numpy.ndarray (engines, bearings, angles)
        Minimum film thickness at each crank angle [m].
    temperature : numpy.ndarray (engines, bearings)
        Effective film temperature [degC].
    """

    h_min: np.ndarray
    temperature: np.ndarray


def bearing_films(spec, reactions, crank_angle, *, clearance, journal_d, method="quasi-static",
                  steady_method="finite"):
    """Film over the cycle for bearings with given reaction histories.

    Parameters
    ----------
    spec : CrankSpec
        Speed, bearing width and oil of the engine.
    reactions : array_like (engines, angles, bearings, 2)
        Bearing loads over the cycle [N] (from :func:`stackup.crank.cycle.engine_cycles`).
    crank_angle : array_like (angles,)
        [deg]
    clearance, journal_d : array_like (engines, bearings)
        Diametral operating clearance and journal diameter [m].
    method, steady_method : str
        Tiers of :func:`stackup.film.orbit.orbit`.

    Notes
    -----
    Effective temperature and viscosity per bearing from the isothermal heat
    balance (:func:`stackup.film.oil.effective_temperature`) at the cycle-mean
    load magnitude, with the short-bearing friction and side flow.
    """
    loads = np.moveaxis(np.asarray(reactions, dtype=float), 1, 2)  # (engines, bearings, angles, 2)
    mean_load = np.linalg.norm(loads, axis=-1).mean(axis=-1)
    radius = np.asarray(journal_d) / 2
    c = np.asarray(clearance) / 2
    kw = dict(radius=radius, length=spec.bearing_width, radial_clearance=c, speed=spec.speed)

    def heat(mu):
        eps, phi = tiers.short(mean_load, viscosity=mu, **kw)
        _, torque, flow = tiers.film_quantities(eps, phi, mean_load, viscosity=mu, **kw)
        return torque * spec.speed, flow

    temperature, mu = oils.effective_temperature(spec.oil, np.full(mean_load.shape, spec.oil_supply_temperature), heat)
    film = orbit(loads, crank_angle, diameter=journal_d, length=spec.bearing_width, clearance=clearance,
                 viscosity=mu, speed=spec.speed, method=method, steady_method=steady_method)
    return BearingFilms(film.h_min, temperature)
