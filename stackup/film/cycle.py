"""One stage of a study: each bearing's oil film over the engine cycle at its effective temperature.

The heat balance (:func:`stackup.film.heat.heat_balance`: friction power
against the oil the feed and the film carry away) sets each bearing's
effective temperature and viscosity; the film tier then gives the minimum
film, the journal centre and the peak pressure at every crank angle. Life is
not this stage's business: the study's chain computes it from the film.

Film methods a study names (:data:`FILM_METHODS`):

- ``"short"``, ``"finite"``, ``"reynolds"``: quasi-static, each crank angle a
  steady load on that steady tier (no squeeze film);
- ``"mobility"``, ``"mobility-finite"``, ``"transient"``: the dynamic tiers of
  :func:`stackup.film.orbit.orbit` (``"transient"`` is its
  ``"reynolds-transient"`` reference, fed by the engine's groove or hole).

With a dynamic tier the heat balance closes on the orbit's own friction power,
side flow and feed flow (:func:`dynamic_heat_balance`): a secant iteration on coarse orbits
(:data:`DYNAMIC_HEAT_STEP`) from the supply temperature finds the balanced temperature,
and the orbit at full resolution runs at its viscosity.

Journal tilt (``tilt``, the slope of the journal against the bearing over the
cycle, :func:`stackup.crank.support_slopes`) gives the edge film: the
mid-plane film is the film tier's, the edge film the thinnest over the
bearing's width (geometric in every tier but the transient one, which carries
the tilt in its film).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import oil as oils
from .heat import STATUS as HEAT_STATUS
from .heat import TEMPERATURE_LIMIT, TEMPERATURE_SHARE, feed_flow, heat_balance
from .orbit import STATUS as ORBIT_STATUS
from .orbit import cheapest_cycle_tier, cycle_tier_errors, orbit

#: Crank-angle spacing of the load history the heat balance reads [deg]: its cycle means barely change
#: below it (reports/bearing_life.md), at a quarter of the cost on a 1 deg grid.
HEAT_STEP = 4.0
#: Crank-angle spacing of the dynamic heat balance's coarse orbits [deg]: their cycle means of friction power
#: and flow are within 0.5 % and 4 % of the 1-deg orbit's (iso-example), the temperature within 0.2 K.
DYNAMIC_HEAT_STEP = 8.0
#: Quasi-static film methods (the steady tiers' names) and the dynamic ones (study name -> orbit tier).
QUASI_STATIC = ("short", "finite", "reynolds")
DYNAMIC = {"mobility": "mobility", "mobility-finite": "mobility-finite", "transient": "reynolds-transient"}
FILM_METHODS = (*QUASI_STATIC, *DYNAMIC)
#: Orbit status per bearing in a study: the orbit's, then the quasi-static tiers' (no orbit to close).
FILM_STATUS = (*ORBIT_STATUS, "quasi_static")
#: The dynamic heat balance stops when a secant step moves the temperature less than this [K]: g(T) is
#: nearly linear, so the step's own error is a small fraction of it (hundredths of a kelvin).
HEAT_TOLERANCE = 0.5
HEAT_ITERATIONS = 8


def film_method_errors(method):
    """The measured errors of a study's film ``method`` against the transient reference (mass-conserving).

    ``{"seconds", "h_min", "h_min_mean", ...}`` from :func:`stackup.film.orbit.cycle_tier_errors`; the
    quasi-static methods are the tiers ``quasi-static-<method>``.
    """
    tier = DYNAMIC.get(method, f"quasi-static-{method}")
    return {k: v for k, v in cycle_tier_errors()[tier].items() if not isinstance(v, dict)}


def cheapest_film_method(max_error):
    """The cheapest dynamic film method whose measured cycle film errors are within ``max_error`` [-].

    From the measured table of :func:`stackup.film.orbit.cycle_tier_errors`
    (cycle minimum and cycle mean of the minimum film against the transient
    Reynolds tier with mass-conserving cavitation); ``"transient"`` when no
    cheaper dynamic tier qualifies.
    """
    tier = cheapest_cycle_tier(max_error, tiers=tuple(DYNAMIC.values()))
    return next(name for name, t in DYNAMIC.items() if t == tier)


@dataclass(frozen=True)
class BearingFilms:
    """Film of bearings over the cycle; arrays (engines, bearings) unless noted.

    Attributes
    ----------
    h_min : numpy.ndarray (engines, bearings, angles)
        Minimum film thickness in the bearing's mid-plane at each crank angle [m].
    h_min_edge : numpy.ndarray (engines, bearings, angles)
        Minimum film over the bearing's width, with the journal's tilt [m] (``h_min`` without tilt).
    position : numpy.ndarray (engines, bearings, angles, 2)
        Journal centre relative to the bearing centre [m].
    p_max : numpy.ndarray (engines, bearings, angles)
        Peak film pressure [Pa].
    status : numpy.ndarray of int8
        Index into :data:`FILM_STATUS`.
    valid : numpy.ndarray of bool
        The film tier was inside its checked range at every angle (a dynamic
        tier: its orbit closed, ``status`` periodic or edge_contact).
    temperature : numpy.ndarray
        Effective film temperature [degC].
    friction_power, oil_flow, feed_flow : numpy.ndarray
        Cycle means [W], [m^3/s], [m^3/s].
    heat_status : numpy.ndarray of int8
        Index into :data:`stackup.film.heat.STATUS`.
    tilt_max : numpy.ndarray
        Cycle maximum of the journal's tilt in the film [rad] (0 without tilt).
    """

    h_min: np.ndarray
    h_min_edge: np.ndarray
    position: np.ndarray
    p_max: np.ndarray
    status: np.ndarray
    valid: np.ndarray
    temperature: np.ndarray
    friction_power: np.ndarray
    oil_flow: np.ndarray
    feed_flow: np.ndarray
    heat_status: np.ndarray
    tilt_max: np.ndarray | None = None


def bearing_films(spec, feed, reactions, crank_angle, *, clearance, journal_d, method="finite", tilt=None,
                  tilt_compliance=None):
    """Film over the cycle for bearings with given reaction histories.

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
    method : str
        One of :data:`FILM_METHODS`.
    tilt : array_like (engines, angles, bearings, 2), optional
        Slope of the journal against the bearing axis [rad] (:func:`stackup.crank.support_slopes`).
    tilt_compliance : array_like (bearings, 2), optional
        Rotational compliance of the crankshaft at each bearing [rad/(N m)]
        (:func:`stackup.crank.support_compliance`): ``tilt`` is then the free slope
        and the tilt in the film balances the film's moment (:mod:`stackup.film.tilt`).
    """
    if method not in FILM_METHODS:
        raise ValueError(f"method: {method!r} is not one of {', '.join(FILM_METHODS)}")
    loads = np.moveaxis(np.asarray(reactions, dtype=float), 1, 2)  # (engines, bearings, angles, 2)
    if tilt is not None:
        tilt = np.moveaxis(np.asarray(tilt, dtype=float), 1, 2)
    clearance, journal_d = np.asarray(clearance, dtype=float), np.asarray(journal_d, dtype=float)
    crank_angle = np.asarray(crank_angle, dtype=float)
    step = float(crank_angle[1] - crank_angle[0]) if len(crank_angle) > 1 else 720.0
    stride = max(1, int(round(HEAT_STEP / step)))
    geometry = dict(diameter=journal_d, length=spec.bearing_width, clearance=clearance, speed=spec.speed)
    if method in QUASI_STATIC:
        heat = heat_balance(loads[..., ::stride, :], **geometry, oil=spec.oil,
                            supply_temperature=spec.oil_supply_temperature, feed=feed,
                            method="short" if method == "short" else "finite")
        film = orbit(loads, crank_angle, **geometry, viscosity=heat.viscosity, method="quasi-static",
                     steady_method=method, tilt=tilt, tilt_compliance=tilt_compliance)
        status = np.where(film.status == ORBIT_STATUS.index("edge_contact"), film.status,
                          FILM_STATUS.index("quasi_static")).astype(np.int8)
        valid = _steady_valid(film)
        return BearingFilms(film.h_min, film.h_min_edge, film.position, film.p_max, status, valid, heat.temperature,
                            heat.friction_power, heat.flow, heat.feed_flow, heat.status, film.tilt_max)
    tier = DYNAMIC[method]
    options = {"feed": feed} if tier == "reynolds-transient" else {}
    balance = dynamic_heat_balance(loads, crank_angle, tier=tier, oil=spec.oil,
                                   supply_temperature=spec.oil_supply_temperature, feed=feed,
                                   stride=max(1, int(round(DYNAMIC_HEAT_STEP / step))),
                                   options=options, **geometry)
    film = orbit(loads, crank_angle, **geometry, viscosity=balance.viscosity, method=tier, tilt=tilt,
                 tilt_compliance=tilt_compliance, start=balance.start, **options)
    fed = _feed_flow(film, feed, clearance, balance.viscosity, journal_d, spec.bearing_width)
    valid = np.isin(film.status, (ORBIT_STATUS.index("periodic"), ORBIT_STATUS.index("edge_contact")))
    return BearingFilms(film.h_min, film.h_min_edge, film.position, film.p_max, film.status, valid,
                        balance.temperature, film.friction_power_mean, film.side_flow_mean + fed, fed, balance.status,
                        film.tilt_max)


def _steady_valid(film):
    """The steady tier's checked range: eccentricity within :data:`stackup.film.ECCENTRICITY_VALID` at every angle."""
    from . import ECCENTRICITY_VALID

    return np.all(film.eccentricity <= ECCENTRICITY_VALID * (1 + 1e-12), axis=-1)


def _feed_flow(film, feed, clearance, viscosity, journal_d, length):
    return feed_flow(film.position, feed=feed, radial_clearance=clearance / 2, viscosity=viscosity,
                     radius=journal_d / 2, length=length)


@dataclass(frozen=True)
class DynamicHeat:
    """Heat balance closed on a dynamic tier's orbit; arrays over the bearings (...)."""

    temperature: np.ndarray  # [degC]
    viscosity: np.ndarray  # [Pa s]
    residual: np.ndarray  # T - T_supply - rise at the last temperature evaluated [K]
    status: np.ndarray  # int8 index into stackup.film.heat.STATUS
    evaluations: int  # coarse orbits run
    start: np.ndarray  # (..., 2) journal centre at the first angle of the last coarse orbit [m]


#: First secant step of the dynamic heat balance: dg/dT [-] (1.1-1.3 on the built-in engines' bearings: the
#: rise falls as the oil thins); the secant replaces it from the second step on.
SLOPE_GUESS = 1.2


def dynamic_heat_balance(loads, crank_angle, *, tier, diameter, length, clearance, speed, oil, supply_temperature,
                         feed, stride=4, options=None):
    r"""Effective temperature of bearings whose film is a dynamic tier's orbit.

    The balance of :mod:`stackup.film.heat`,

    .. math:: g(T) = T - T_{supply} - \tfrac12\,\frac{\bar N(T)}{\rho c_p\,(\bar Q_{side}(T) + \bar Q_{feed}(T))} = 0,

    with the cycle means :math:`\bar N`, :math:`\bar Q_{side}` of the orbit
    (squeeze film included) and the feed flow at the orbit's journal positions,
    solved by the secant method from the supply temperature (first slope
    :data:`SLOPE_GUESS`) on orbits of every ``stride``-th crank angle, until the
    temperature moves less than :data:`HEAT_TOLERANCE`. :math:`g` is nearly
    linear in :math:`T`: two or three orbits per bearing.

    Parameters
    ----------
    loads : numpy.ndarray (..., angles, 2)
        [N]
    crank_angle : numpy.ndarray (angles,)
        [deg]
    tier : str
        Dynamic tier of :func:`stackup.film.orbit.orbit`.
    diameter, length, clearance, speed :
        As :func:`stackup.film.orbit.orbit` [m], [rad/s].
    oil, supply_temperature, feed :
        As :func:`stackup.film.heat.heat_balance`.
    stride : int
        Crank angles between the coarse orbits' points.
    options : dict, optional
        Options of the tier (e.g. ``feed`` of the transient tier).
    """
    oil = oils.get(oil)
    options = options or {}
    lead = loads.shape[:-2]
    flat = loads.reshape(-1, *loads.shape[-2:])[:, ::stride]
    coarse_angle = np.asarray(crank_angle)[::stride]
    each = {k: np.broadcast_to(np.asarray(v, float), lead).ravel()
            for k, v in dict(diameter=diameter, length=length, clearance=clearance, speed=speed,
                             supply=supply_temperature).items()}
    shear_rate = each["speed"] * each["diameter"] / each["clearance"]

    start = np.zeros((flat.shape[0], 2))

    def g(t, rows, warm=True):
        mu = oil.viscosity(t, shear_rate=shear_rate[rows])
        geo = {k: each[k][rows] for k in ("diameter", "length", "clearance", "speed")}
        # each orbit starts where the last one began: it is near the periodic orbit, so no coarse laps
        film = orbit(flat[rows], coarse_angle, **geo, viscosity=mu, method=tier, start=start[rows] if warm else None,
                     **options)
        start[rows] = film.position[:, 0]
        fed = _feed_flow(film, feed, geo["clearance"], mu, geo["diameter"], geo["length"])
        rise = TEMPERATURE_SHARE * film.friction_power_mean / (oil.density(t) * oils.SPECIFIC_HEAT
                                                               * (film.side_flow_mean + fed))
        return t - each["supply"][rows] - rise

    n = flat.shape[0]
    everyone = np.arange(n)
    t0 = each["supply"].copy()
    g0 = g(t0, everyone, warm=False)
    t1 = np.clip(t0 - g0 / SLOPE_GUESS, each["supply"], TEMPERATURE_LIMIT)
    g1 = np.full(n, np.nan)
    done = np.zeros(n, bool)
    evaluations = 1
    while not done.all() and evaluations < HEAT_ITERATIONS:
        rows = np.flatnonzero(~done)
        g1[rows] = g(t1[rows], rows)
        evaluations += 1
        dt = t1[rows] - t0[rows]
        slope = np.where(np.abs(dt) > 1e-9, (g1[rows] - g0[rows]) / np.where(dt != 0, dt, 1.0), SLOPE_GUESS)
        slope = np.where(slope > 0.1, slope, SLOPE_GUESS)  # g rises with T; a flat or falling secant: first slope
        t2 = np.clip(t1[rows] - g1[rows] / slope, each["supply"][rows], TEMPERATURE_LIMIT)
        t0[rows], g0[rows] = t1[rows], g1[rows]
        done[rows] = np.abs(t2 - t1[rows]) < HEAT_TOLERANCE
        t1[rows] = t2
    status = np.where(done, HEAT_STATUS.index("balanced"), HEAT_STATUS.index("not_converged"))
    status = np.where((t1 >= TEMPERATURE_LIMIT) & (g0 < 0), HEAT_STATUS.index("no_balance_below_limit"), status)
    mu = oil.viscosity(t1, shear_rate=shear_rate)
    return DynamicHeat(t1.reshape(lead), mu.reshape(lead), g0.reshape(lead), status.astype(np.int8).reshape(lead),
                       evaluations, start.reshape(*lead, 2))
