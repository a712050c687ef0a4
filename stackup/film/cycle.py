"""One stage of a study: each bearing's oil film over the engine cycle at its effective temperature.

The heat balance (:func:`stackup.film.heat.heat_balance`: friction power
against the oil the feed and the film carry away) sets each bearing's
effective temperature and viscosity; the film tier then gives the minimum
film, the journal centre and the peak pressure at every crank angle. Life is
not this stage's business: the study's chain computes it from the film.

Film methods a study names (:data:`FILM_METHODS`) are the cycle tiers of
:func:`stackup.film.orbit.orbit`, by the same names (the records of :mod:`stackup.film.registry`;
this stage reads each tier's kind, feed, side models and options there):

- ``"short"``, ``"finite"``, ``"reynolds"``: quasi-static, each crank angle a
  steady load on that steady tier (no squeeze film);
- ``"mobility"``, ``"mobility-finite"``, ``"elrod-coarse"``, ``"reynolds-transient"``:
  the dynamic tiers (the mass-conserving ``"elrod-coarse"`` and the reference
  ``"reynolds-transient"`` fed by the engine's groove or hole, :data:`stackup.film.orbit.FED`; the
  study's former name ``"transient"`` is a deprecated alias,
  :func:`stackup.film.orbit.canonical_tier`).

With a dynamic tier the heat balance closes on the orbit's own friction power,
side flow and feed flow (:func:`balanced_orbit`): the temperature rise of a coarse
orbit (:data:`DYNAMIC_HEAT_STEP`) at the supply temperature, extrapolated as an
exponential in the temperature, gives the temperature of the full orbit, which is kept
where the balance holds on it within :data:`HEAT_TOLERANCE`.

Journal tilt (``tilt``, the slope of the journal against the bearing over the
cycle, :func:`stackup.crank.support_slopes`) gives the edge film: the
mid-plane film is the film tier's, the edge film the thinnest over the
bearing's width (geometric in every tier but the transient one, which carries
the tilt in its film).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.special import lambertw

from .._validate import Finite, InRange, Integer, OneOf, Positive, renamed, validated
from . import oil as oils
from . import registry
from .heat import STATUS as HEAT_STATUS
from .heat import TEMPERATURE_LIMIT, TEMPERATURE_SHARE, check_feed, feed_flow, heat_balance
from .journal import ECCENTRICITY_LIMIT, Orbit, within_one_cycle
from .journal import STATUS as ORBIT_STATUS
from .orbit import (ALIASES, DYNAMIC, METHODS, cheapest_cycle_tier, compliance_with_tilt, cycle_tier_errors,
                    one_cycle, orbit, tier_names, tier_options)
from .orbit import canonical_tier  # noqa: F401 (the study resolves its film_method's deprecated names with it)

#: Crank-angle spacing of the load history the heat balance reads [deg]: its cycle means barely change
#: below it (reports/bearing_life.md), on a quarter of a 1 deg grid's angles.
HEAT_STEP = 4.0
#: Crank-angle spacing of the dynamic heat balance's coarse orbit [deg]: fine enough to catch the load peaks, whose
#: temperature rise the balance extrapolates (the balance's accuracy on the full orbit: reports/bench_chain.md).
DYNAMIC_HEAT_STEP = 8.0
#: Film methods a study names: the cycle tiers of :func:`stackup.film.orbit.orbit` (the registry's, read at each
#: use; quasi-static ones :data:`stackup.film.orbit.QUASI_STATIC`, dynamic ones :data:`DYNAMIC`).
FILM_METHODS = METHODS
#: Orbit status per bearing in a study: the orbit's, then the quasi-static tiers' (no orbit to close).
FILM_STATUS = (*ORBIT_STATUS, "quasi_static")
#: Statuses whose film is not a number: the orbit did not become periodic, the film collapsed (the journal held
#: at the eccentricity limit, or a quasi-static tier's steady film beyond it) or the solve failed. The film
#: stage still returns the film where it was held; a study stores NaN for these bearings' films and lives.
NOT_A_NUMBER = ("not_periodic", "collapsed", "failed")
#: The dynamic heat balance keeps an orbit whose residual T - T_supply - rise is below this [K]: the temperature
#: is then within it of the balance on that orbit (the residual grows faster than T; measured: reports/bench_chain.md).
HEAT_TOLERANCE = 0.5
#: Most orbits per bearing (the coarse one, then full ones).
HEAT_ITERATIONS = 6


def film_method_errors(method):
    """The measured errors of a study's film ``method`` against the transient reference (mass-conserving).

    ``{"seconds", "h_min", "h_min_mean", ...}`` from :func:`stackup.film.orbit.cycle_tier_errors`.
    """
    tier = ALIASES.get(method, method)  # a deprecated name was warned about where it entered
    return {k: v for k, v in cycle_tier_errors()[tier].items() if not isinstance(v, dict)}


def cheapest_film_method(max_error):
    """The cheapest dynamic film method whose measured cycle film errors are within ``max_error`` [-].

    From the measured table of :func:`stackup.film.orbit.cycle_tier_errors`
    (cycle minimum and cycle mean of the minimum film against the transient
    Reynolds tier with mass-conserving cavitation); ``"reynolds-transient"`` when no
    cheaper dynamic tier qualifies.
    """
    return cheapest_cycle_tier(max_error, tiers=DYNAMIC)


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
        The film is a number: ``status`` is none of :data:`NOT_A_NUMBER` (a
        dynamic tier's orbit closed; a quasi-static tier's steady film stayed
        within :data:`~stackup.film.journal.ECCENTRICITY_LIMIT` at every angle).
    temperature : numpy.ndarray
        Effective film temperature [degC].
    friction_power, oil_flow, feed_flow : numpy.ndarray
        Cycle means [W], [m^3/s], [m^3/s].
    heat_status : numpy.ndarray of int8
        Index into :data:`stackup.film.heat.STATUS`.
    tilt_max : numpy.ndarray
        Cycle maximum of the journal's tilt in the film [rad] (0 without tilt).
    edge_contact_share : numpy.ndarray
        Share of the crank angles at which the film over the width is at its
        limit, :math:`c(1 - \varepsilon_{lim})` (an edge, or the journal, at the wall) [-].
    viscosity : numpy.ndarray
        Effective oil viscosity of the heat balance [Pa s].
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
    edge_contact_share: np.ndarray | None = None
    viscosity: np.ndarray | None = None


def _cycle_of_reactions(values):
    """Reactions (engines, angles, bearings, 2) over crank angles that increase over less than a cycle."""
    reactions, angle = values["reactions"], values["crank_angle"]
    if angle.ndim != 1 or reactions.ndim < 3 or reactions.shape[-1] != 2 or reactions.shape[1] != angle.size:
        raise ValueError(f"reactions: shape {reactions.shape} is not valid; expected (engines, {angle.size}, "
                         "bearings, 2)")
    within_one_cycle(angle)


def _feed_of_the_heat_balance(values):
    """The oil feed fits the bearing (the quasi-static tiers' heat balance reads it as :func:`heat_balance` does)."""
    if registry.tier(values["method"]).kind == "quasi-static":
        check_feed(values["feed"], values["spec"].bearing_width)


@tier_names()
@validated(method=OneOf(FILM_METHODS), reactions=Finite(), crank_angle=Finite(), clearance=Positive(),
           journal_d=Positive(), tilt=Finite(), tilt_compliance=Positive(zero=True),
           relations=(_cycle_of_reactions, compliance_with_tilt, _feed_of_the_heat_balance))
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
        One of :data:`FILM_METHODS` (deprecated names: :data:`stackup.film.orbit.ALIASES`).
    tilt : array_like (engines, angles, bearings, 2), optional
        Slope of the journal against the bearing axis [rad] (:func:`stackup.crank.support_slopes`).
    tilt_compliance : array_like (bearings, 2), optional
        Rotational compliance of the crankshaft at each bearing [rad/(N m)]
        (:func:`stackup.crank.support_compliance`): ``tilt`` is then the free slope
        and the tilt in the film balances the film's moment (:mod:`stackup.film.tilt`).
    """
    loads = np.moveaxis(np.asarray(reactions, dtype=float), 1, 2)  # (engines, bearings, angles, 2)
    if tilt is not None:
        tilt = np.moveaxis(np.asarray(tilt, dtype=float), 1, 2)
    clearance, journal_d = np.asarray(clearance, dtype=float), np.asarray(journal_d, dtype=float)
    crank_angle = np.asarray(crank_angle, dtype=float)
    step = float(crank_angle[1] - crank_angle[0]) if len(crank_angle) > 1 else 720.0
    geometry = dict(journal_d=journal_d, bearing_width=spec.bearing_width, clearance=clearance, speed=spec.speed)
    tier = registry.tier(method)
    if tier.kind == "quasi-static":
        # the heat balance on the tier's side model (the steady Reynolds film is too dear to iterate on)
        stride = max(1, int(round(HEAT_STEP / step)))
        heat = heat_balance(loads[..., ::stride, :], **geometry, oil=spec.oil,
                            supply_temperature=spec.oil_supply_temperature, feed=feed, method=tier.length_model)
        film = orbit(loads, crank_angle, **geometry, viscosity=heat.viscosity, method=method, tilt=tilt,
                     tilt_compliance=tilt_compliance)
        status = np.where(film.status == ORBIT_STATUS.index("edge_contact"), film.status,
                          FILM_STATUS.index("quasi_static"))
        # a load the steady film carries only beyond the eccentricity limit: the film has collapsed
        status = np.where(_steady_valid(film), status, FILM_STATUS.index("collapsed")).astype(np.int8)
        return BearingFilms(film.h_min, film.h_min_edge, film.position, film.p_max, status, _is_number(status),
                            heat.temperature, heat.friction_power, heat.flow, heat.feed_flow, heat.status,
                            film.tilt_max, _at_limit_share(film.h_min_edge, clearance), heat.viscosity)
    options = {"feed": feed} if tier.fed else {}
    balance, film, fed = balanced_orbit(loads, crank_angle, tier=method, oil=spec.oil,
                                        supply_temperature=spec.oil_supply_temperature, feed=feed,
                                        stride=max(1, int(round(DYNAMIC_HEAT_STEP / step))), tilt=tilt,
                                        tilt_compliance=tilt_compliance, options=options, **geometry)
    return BearingFilms(film.h_min, film.h_min_edge, film.position, film.p_max, film.status, _is_number(film.status),
                        balance.temperature, film.friction_power_mean, film.side_flow_mean + fed, fed, balance.status,
                        film.tilt_max, _at_limit_share(film.h_min_edge, clearance), balance.viscosity)


def checked_film(spec, feed, reactions, crank_angle, *, viscosity, clearance, journal_d, method, check=None):
    """The mid-plane film over the cycle of the same bearings by the study's tier and by a more accurate one,
    both on the aligned journal at the viscosity of the bearings' heat balance.

    The bearings of a :func:`bearing_films` result (by tier ``method``, its
    heat balance's ``viscosity`` [Pa s]) run again with ``method`` and with ``check`` (default the
    registry's check tier, :func:`stackup.film.registry.check_tier`: the mass-conserving
    ``elrod-coarse``; a fed tier fed by the engine's oil ``feed``),
    without the journal's tilt: the accurate tier takes a tilt only as
    imposed and fails where a tilted edge reaches the wall (an edge the rigid
    block makes touch), so the two tiers are compared where both hold; the
    study takes the check's error, a share of its own mid-plane film, off the
    film it reads (:func:`stackup.study.chain.mechanical_chain`), an assumption
    that the tiers' ratio does not depend on the tilt. Arguments as
    :func:`bearing_films`.
    Returns the two films [m] (engines, bearings, angles): the study's tier's,
    the check tier's.
    """
    loads = np.moveaxis(np.asarray(reactions, dtype=float), 1, 2)
    geometry = dict(journal_d=np.asarray(journal_d, dtype=float), bearing_width=spec.bearing_width,
                    clearance=np.asarray(clearance, dtype=float), speed=spec.speed, viscosity=viscosity)
    angle = np.asarray(crank_angle, dtype=float)
    check = registry.check_tier().name if check is None else check

    def fed(tier):
        return {"feed": feed} if registry.tier(tier).fed else {}

    return (orbit(loads, angle, **geometry, method=method, **fed(method)).h_min,
            orbit(loads, angle, **geometry, method=check, **fed(check)).h_min)


def wall_film(clearance):
    """The film the cycle tiers hold an edge, or the journal, at when it reaches the wall: :math:`c(1 -
    \varepsilon_{lim})` [m] at diametral ``clearance`` [m]."""
    return 0.5 * np.asarray(clearance, dtype=float) * (1 - ECCENTRICITY_LIMIT)


def at_wall(h_min_edge, clearance):
    """Where the film over the width is held at the wall (:func:`wall_film`): ``h_min_edge`` (..., angles) [m] at
    diametral ``clearance`` (...) [m] -> bool."""
    return h_min_edge <= wall_film(clearance)[..., None] * (1 + 1e-9)


def _at_limit_share(h_min_edge, clearance):
    """Share of the angles whose film over the width is held at the limit film (:func:`at_wall`)."""
    return at_wall(h_min_edge, clearance).mean(axis=-1)


def _is_number(status):
    return ~np.isin(status, [FILM_STATUS.index(s) for s in NOT_A_NUMBER])


def _steady_valid(film):
    """The steady tier's checked range: eccentricity within :data:`~stackup.film.journal.ECCENTRICITY_LIMIT` at every
    angle."""
    return np.all(film.eccentricity <= ECCENTRICITY_LIMIT * (1 + 1e-12), axis=-1)


@dataclass(frozen=True)
class DynamicHeat:
    """Heat balance closed on a dynamic tier's orbit; arrays over the bearings (...)."""

    temperature: np.ndarray  # [degC]
    viscosity: np.ndarray  # [Pa s]
    residual: np.ndarray  # T - T_supply - rise of the orbit at the temperature [K]
    status: np.ndarray  # int8 index into stackup.film.heat.STATUS
    orbits: np.ndarray  # int: orbits run for each bearing (the coarse one and the full ones)


#: First step's guess of how fast the temperature rise falls with the temperature, per the oil's viscosity:
#: d ln(rise)/dT = this times d ln(mu)/dT, as measured on iso-example's bearings (friction power grows with the
#: viscosity, the feed flow falls with it); the full orbit's rise replaces it by the measured decay.
RISE_DECAY_GUESS = 1.3


def _balanced_rise(anchor_t, anchor_rise, decay, supply):
    r"""Root of :math:`T - T_s = R_a e^{-k (T - T_a)}` [degC]: :math:`T = T_s + W(k A)/k`, :math:`A = R_a e^{-k (T_s - T_a)}`.

    ``decay`` :math:`k \ge 0` [1/K]; :math:`k \to 0` gives the fixed-point step :math:`T_s + R_a`.
    """
    a = anchor_rise * np.exp(-decay * (supply - anchor_t))
    small = decay * np.abs(a) < 1e-9
    k = np.where(small, 1.0, decay)
    x = np.where(small, a, np.real(lambertw(np.where(small, 0.0, k * a))) / k)
    return supply + x


def _tier_options(values):
    """The tier's options: ``cycles`` and the tier's own (:func:`stackup.film.orbit.tier_options`)."""
    options = dict(values["options"] or {})
    if options.get("cycles") is not None:
        Integer(minimum=1)("cycles", options["cycles"])
    options.pop("cycles", None)
    tier_options(values["tier"], options, values["tilt_compliance"])


@renamed(diameter="journal_d", length="bearing_width")
@validated(tier=OneOf(METHODS), loads=Finite(), crank_angle=Finite(), journal_d=Positive(), bearing_width=Positive(),
           clearance=Positive(), speed=Positive(), supply_temperature=InRange(-30.0, 200.0, unit=" degC"),
           tilt=Finite(), tilt_compliance=Positive(zero=True), relations=(one_cycle("loads"), compliance_with_tilt, _tier_options))
def balanced_orbit(loads, crank_angle, *, tier, journal_d, bearing_width, clearance, speed, oil, supply_temperature,
                   feed, stride=8, tilt=None, tilt_compliance=None, options=None, tolerance=HEAT_TOLERANCE):
    r"""The orbit of bearings at the effective temperature where their heat balance closes on that orbit.

    The balance of :mod:`stackup.film.heat`,

    .. math:: g(T) = T - T_{supply} - R(T) = 0, \qquad
              R(T) = \tfrac12\,\frac{\bar N(T)}{\rho c_p\,(\bar Q_{side}(T) + \bar Q_{feed}(T))},

    with the cycle means :math:`\bar N`, :math:`\bar Q_{side}` of the orbit
    (squeeze film included) and the feed flow at the orbit's journal positions.
    The rise :math:`R` falls nearly exponentially with the temperature
    (friction power with the viscosity, the feed flow against it, the Vogel
    viscosity exponential); through two rises :math:`R_a`, :math:`R_b`,

    .. math:: R(T) = R_b\,e^{-k (T - T_b)}, \qquad k = \ln(R_a/R_b)/(T_b - T_a),

    and the balance is :math:`T = T_s + W(kA)/k`, :math:`A = R_b e^{-k(T_s - T_b)}`
    (:math:`W` Lambert's function). One orbit of every ``stride``-th crank
    angle at the supply temperature gives :math:`R_a` and a start near the
    periodic orbit; the orbit at full resolution runs at the root with
    :math:`k` guessed from the viscosity (:data:`RISE_DECAY_GUESS`), and is
    kept where its own residual :math:`|g|` is below ``tolerance``;
    elsewhere it runs again at the root through the last two rises. So the
    temperature is within ``tolerance`` / :math:`g'` (:math:`g' > 1`)
    of the balance on the returned orbit itself (measured against the balance
    closed tightly in ``reports/bench_chain.md``). An orbit whose film is not a
    number (:data:`NOT_A_NUMBER`) is not run again.

    Parameters
    ----------
    loads : numpy.ndarray (..., angles, 2)
        [N]
    crank_angle : numpy.ndarray (angles,)
        [deg]
    tier : str
        Cycle tier of :func:`stackup.film.orbit.orbit` (a dynamic one).
    journal_d, bearing_width, clearance, speed :
        As :func:`stackup.film.orbit.orbit` [m], [rad/s].
    oil, supply_temperature, feed :
        As :func:`stackup.film.heat.heat_balance`.
    stride : int
        Crank angles between the points of the first, coarse orbit.
    tilt : numpy.ndarray (..., angles, 2), optional
        As :func:`stackup.film.orbit.orbit`.
    tilt_compliance : array_like (..., 2), optional
        As :func:`stackup.film.orbit.orbit` (the coarse orbit runs without tilt).
    options : dict, optional
        Options of the tier (``cycles``, and e.g. ``feed`` of the transient tier).
    tolerance : float
        On the residual [K] (:data:`HEAT_TOLERANCE`).

    Returns
    -------
    (DynamicHeat, stackup.film.orbit.Orbit, numpy.ndarray)
        The balance, the orbit at its temperature and the feed flow [m^3/s] (...).
    """
    loads = np.asarray(loads, dtype=float)
    heated = _HeatedOrbits(loads, np.asarray(crank_angle, dtype=float), tier=tier, oil=oils.get(oil), feed=feed,
                           tilt=tilt, tilt_compliance=tilt_compliance, options=options, journal_d=journal_d,
                           bearing_width=bearing_width, clearance=clearance, speed=speed,
                           supply_temperature=supply_temperature)
    heat, film, fed = _close_balance(heated, stride=stride, tolerance=tolerance)
    lead = loads.shape[:-2]
    shaped = {name: (v.reshape(lead + v.shape[1:]) if v is not None and np.ndim(v) else v)
              for name, v in film.items()}
    return (DynamicHeat(*(np.asarray(v).reshape(lead) for v in heat)), Orbit(**shaped), fed.reshape(lead))


class _HeatedOrbits:
    """Orbits of bearings (flattened) at given temperatures, each with its feed flow and temperature rise."""

    def __init__(self, loads, crank_angle, *, tier, oil, feed, tilt, tilt_compliance, options, supply_temperature,
                 **geometry):
        lead = loads.shape[:-2]
        self.flat = loads.reshape(-1, *loads.shape[-2:])
        self.angle, self.tier, self.oil, self.feed = crank_angle, tier, oil, feed
        self.options = dict(options or {})
        self.each = {k: np.broadcast_to(np.asarray(v, dtype=float), lead).ravel() for k, v in geometry.items()}
        self.supply = np.broadcast_to(np.asarray(supply_temperature, float), lead).ravel()
        self.tilt = None if tilt is None else np.broadcast_to(np.asarray(tilt, dtype=float), loads.shape).reshape(
            self.flat.shape)
        self.compliance = None if tilt_compliance is None else np.broadcast_to(
            np.asarray(tilt_compliance, dtype=float), (*lead, 2)).reshape(self.flat.shape[0], 2)
        self.shear_rate = self.each["speed"] * self.each["journal_d"] / self.each["clearance"]
        self.viscosity = np.empty(self.flat.shape[0])

    def run(self, t, rows, start, step=1):
        """Orbit, feed flow and rise of bearings ``rows`` at temperatures ``t``, every ``step``-th angle."""
        oil = self.oil
        mu = self.viscosity[rows] = oil.viscosity(t, shear_rate=self.shear_rate[rows])
        geo = {k: self.each[k][rows] for k in ("journal_d", "bearing_width", "clearance", "speed")}
        film = orbit(self.flat[rows, ::step], self.angle[::step], **geo, viscosity=mu, method=self.tier, start=start,
                     tilt=None if self.tilt is None or step > 1 else self.tilt[rows],
                     tilt_compliance=None if self.compliance is None or step > 1 else self.compliance[rows],
                     **self.options)
        fed = feed_flow(film.position, feed=self.feed, radial_clearance=geo["clearance"] / 2, viscosity=mu,
                        journal_radius=geo["journal_d"] / 2, bearing_width=geo["bearing_width"])
        rise = TEMPERATURE_SHARE * film.friction_power_mean / (oil.density(t) * oils.SPECIFIC_HEAT
                                                               * (film.side_flow_mean + fed))
        return film, fed, rise


def _close_balance(heated, *, stride, tolerance):
    """The secant steps of :func:`balanced_orbit` on the rise: ((temperature, viscosity, residual, status, orbits),
    the orbit's fields at the temperature (flat), feed flow), each over the flattened bearings."""
    supply, oil = heated.supply, heated.oil
    n = supply.size
    # the coarse orbit starts at the bearing centre with whole-angle steps (on a coarse grid the cold start's laps
    # at two angles per step cost more than they save); the full orbit where the coarse one began
    coarse, _, r_a = heated.run(supply, slice(None), np.zeros((n, 2)), stride)
    t_a = supply.copy()
    decay = RISE_DECAY_GUESS * np.log(heated.viscosity / oil.viscosity(supply + 1.0, shear_rate=heated.shear_rate))
    t_b = np.clip(_balanced_rise(t_a, r_a, decay, supply), supply, TEMPERATURE_LIMIT)
    film, fed, r_b = heated.run(t_b, slice(None), coarse.position[:, 0])
    # every field an array (copied, so reruns fill their rows) except those the orbit leaves None (no tilt)
    fields = {name: None if getattr(film, name) is None else np.array(getattr(film, name))
              for name in film.__dataclass_fields__}
    residual = t_b - supply - r_b
    orbits = np.full(n, 2)
    done = (np.abs(residual) < tolerance) | ~_is_number(fields["status"])  # no balance on a film that is not one
    while not done.all() and orbits.max() < HEAT_ITERATIONS:
        rows = np.flatnonzero(~done)
        dt = t_b[rows] - t_a[rows]
        with np.errstate(divide="ignore", invalid="ignore"):
            k = np.log(r_a[rows] / r_b[rows]) / dt
        # a rise that does not fall (or an orbit without friction) gives no decay: a fixed-point step
        k = np.where(np.isfinite(k) & (k > 0) & (np.abs(dt) > 1e-9), k, 0.0)
        t_c = np.clip(_balanced_rise(t_b[rows], r_b[rows], k, supply[rows]), supply[rows], TEMPERATURE_LIMIT)
        again, fed_c, r_c = heated.run(t_c, rows, fields["position"][rows, 0])
        orbits[rows] += 1
        for name in fields:
            if fields[name] is not None and np.ndim(fields[name]):
                fields[name][rows] = getattr(again, name)
        fed[rows] = fed_c
        t_a[rows], r_a[rows], t_b[rows], r_b[rows] = t_b[rows], r_b[rows], t_c, r_c
        residual[rows] = t_c - supply[rows] - r_c
        # no balance below the limit: the limit's film, flagged below
        done[rows] = ((np.abs(residual[rows]) < tolerance) | ((t_c >= TEMPERATURE_LIMIT) & (residual[rows] < 0))
                      | ~_is_number(again.status))
    status = np.where(np.abs(residual) < tolerance, HEAT_STATUS.index("balanced"),
                      HEAT_STATUS.index("not_converged"))
    status = np.where((t_b >= TEMPERATURE_LIMIT) & (residual < 0), HEAT_STATUS.index("no_balance_below_limit"), status)
    # the viscosity of the last orbit of each bearing, at t_b
    return (t_b, heated.viscosity, residual, status.astype(np.int8), orbits), fields, fed
