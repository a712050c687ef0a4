"""One stage of a study: each bearing's oil film over the engine cycle, and its wear life."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..life import alpha as boundary_share
from ..life import levanov_method1
from . import oil as oils
from . import tiers
from .orbit import orbit


@dataclass(frozen=True)
class BearingFilms:
    """Film and life of bearings (engines, bearings)."""

    h_min: np.ndarray  # minimum over the cycle [m]
    h_min_mean: np.ndarray  # mean of the minimum film over the cycle [m]
    alpha: np.ndarray  # share of the cycle below h_lim_cr [-]
    life: np.ndarray  # Levanov method 1 with the cycle-minimum film [s]
    temperature: np.ndarray  # effective film temperature [degC]
    history: np.ndarray  # minimum film at each crank angle (engines, bearings, angles) [m]


def bearing_films(spec, reactions, crank_angle, *, clearance, journal_d, method="quasi-static",
                  steady_method="finite", h_lim_cr=1.9e-6, n=-2.0, wear_limit=30e-6, wear_rate=1e-13):
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
    h_lim_cr, n, wear_limit, wear_rate :
        Parameters of :func:`stackup.life.levanov_method1` and the boundary share.

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
    h_min = film.h_min.min(axis=-1)
    life = levanov_method1(np.maximum(h_min, 1e-12), h_lim_cr=h_lim_cr, n=n, wear_limit=wear_limit, wear_rate=wear_rate)
    return BearingFilms(h_min, film.h_min.mean(axis=-1), boundary_share(film.h_min, h_lim_cr=h_lim_cr), life.life,
                        temperature, film.h_min)
