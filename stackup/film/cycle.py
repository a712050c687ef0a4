"""One stage of a study: each bearing's oil film over the engine cycle at its effective temperature.

The heat balance (:func:`stackup.film.heat.heat_balance`: friction power
against the oil the feed and the film carry away) sets each bearing's
effective temperature and viscosity; the film tier then gives the minimum
film and the journal centre at every crank angle. Life is not this stage's
business: the study's chain computes it from the film.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import journal_position, min_film_thickness
from .heat import heat_balance

#: Crank-angle spacing of the load history the heat balance reads [deg]: its cycle means barely change
#: below it (reports/bearing_life.md), at a quarter of the cost on a 1 deg grid.
HEAT_STEP = 4.0


@dataclass(frozen=True)
class BearingFilms:
    """Film of bearings over the cycle; arrays (engines, bearings) unless noted.

    Attributes
    ----------
    h_min : numpy.ndarray (engines, bearings, angles)
        Minimum film thickness at each crank angle [m].
    position : numpy.ndarray (engines, bearings, angles, 2)
        Journal centre relative to the bearing centre [m].
    valid : numpy.ndarray of bool
        The film tier was inside its checked range at every angle.
    temperature : numpy.ndarray
        Effective film temperature [degC].
    friction_power, oil_flow, feed_flow : numpy.ndarray
        Cycle means [W], [m^3/s], [m^3/s].
    heat_status : numpy.ndarray of int8
        Index into :data:`stackup.film.heat.STATUS`.
    """

    h_min: np.ndarray
    position: np.ndarray
    valid: np.ndarray
    temperature: np.ndarray
    friction_power: np.ndarray
    oil_flow: np.ndarray
    feed_flow: np.ndarray
    heat_status: np.ndarray


def bearing_films(spec, feed, reactions, crank_angle, *, clearance, journal_d, steady_method="finite"):
    """Film over the cycle for bearings with given reaction histories (quasi-static: each angle a steady load).

    Parameters
    ----------
    spec : CrankSpec
        Speed, bearing width and oil of the engine.
    feed : stackup.film.heat.OilFeed
        How the oil enters the bearing.
    reactions : array_like (engines, angles, bearings, 2)
        Bearing loads over the cycle [N] (from :func:`stackup.crank.cycle.engine_cycles`).
    crank_angle : array_like (angles,)
        Equal steps over the cycle [deg].
    clearance, journal_d : array_like (engines, bearings)
        Diametral operating clearance and journal diameter [m].
    steady_method : str
        Steady tier of :func:`stackup.film.min_film_thickness`.
    """
    loads = np.moveaxis(np.asarray(reactions, dtype=float), 1, 2)  # (engines, bearings, angles, 2)
    clearance, journal_d = np.asarray(clearance), np.asarray(journal_d)
    step = float(crank_angle[1] - crank_angle[0]) if len(crank_angle) > 1 else 720.0
    stride = max(1, int(round(HEAT_STEP / step)))
    heat = heat_balance(loads[..., ::stride, :], diameter=journal_d, length=spec.bearing_width, clearance=clearance,
                        speed=spec.speed, oil=spec.oil, supply_temperature=spec.oil_supply_temperature, feed=feed,
                        method=steady_method if steady_method in ("short", "finite") else "finite")
    film = min_film_thickness(np.linalg.norm(loads, axis=-1), diameter=journal_d[..., None],
                              length=spec.bearing_width, clearance=clearance[..., None],
                              viscosity=heat.viscosity[..., None], speed=spec.speed, method=steady_method)
    position = journal_position(loads, eccentricity=film.eccentricity, attitude_angle=film.attitude_angle,
                                clearance=clearance[..., None])
    return BearingFilms(film.h_min, position, film.valid.all(axis=-1), heat.temperature, heat.friction_power,
                        heat.flow, heat.feed_flow, heat.status)
