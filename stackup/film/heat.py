r"""Isothermal heat balance of a main bearing over the engine cycle, with the oil fed under pressure.

The friction power averaged over the cycle leaves with the oil flowing
through the bearing (Levanov et al. 2015, sec. 3: "equality of average values
of the warmth dissipated in a lubricant film, and the warmth which is taken
away by the lubricant escaping in butts"), the film at one effective
temperature:

.. math:: T_{eff} = T_{supply} + \tfrac12\,\frac{\bar N(T_{eff})}{\rho\,c_p\,\bar Q(T_{eff})},
          \qquad \bar Q = \bar Q_{side} + \bar Q_{feed}

with the mean of inlet and outlet temperature as the effective one (the
factor 1/2, Raimondi and Boyd). :math:`\bar N` and the hydrodynamic side flow
:math:`\bar Q_{side}` are cycle means of the steady film tier at each crank
angle (quasi-static). The feed flow :math:`\bar Q_{feed}` is driven by the
supply pressure :math:`p_s` through the feed groove or hole into the
clearance and out over the lands; it exists at zero load, so an unloaded
bearing has a finite temperature rise (a balance on the side flow alone has
none: at zero eccentricity the side flow vanishes).

Feed flow, film :math:`h(\theta) = c - \mathbf x\cdot(\cos\theta, \sin\theta)`
from the journal position :math:`\mathbf x`, cycle mean over the positions:

- groove of axial width :math:`b` over the arc :math:`\theta_1..\theta_2`,
  axial Poiseuille flow over both lands of width :math:`l' = (L - b)/2`:

  .. math:: Q_{groove} = \frac{p_s R}{6\mu l'}\int_{\theta_1}^{\theta_2} h^3\,d\theta

  (the integral in closed form); for a full 360 deg groove at eccentricity
  ratio :math:`\varepsilon` this is the classical
  :math:`\pi p_s R c^3 (1 + 1.5\varepsilon^2)/(3\mu l')`. The flow out of
  the ends of a partial groove into the clearance is left out (a lower bound:
  the balance is on the hot side).
- single hole of diameter :math:`d_H` in the middle of a bearing of length
  :math:`L`, film :math:`h_H` at the hole: a source in a Hele-Shaw strip with
  ambient pressure at both ends, solved by the conformal map
  :math:`\zeta = e^{\pi z/L}` and an image source,

  .. math:: Q_{hole} = \frac{\pi p_s h_H^3}{6\mu\,\ln\left(4L/(\pi d_H)\right)}

  (uniform film near the hole, :math:`d_H \ll L`; checked against a
  finite-difference solution in the tests).

The balance is solved per bearing for the temperature by bracketed false
position (Illinois) between the supply temperature and
:data:`TEMPERATURE_LIMIT`; the residual rises monotonically with the
temperature (friction falls, flow rises). A bearing that has no balance
below the limit gets status ``no_balance_below_limit`` and the limit's
values, never an exception.

References
----------
.. [1] Levanov et al. 2015, Tribology in Industry 37, sec. 3 (isothermal heat balance).
.. [2] Raimondi, A. A., Boyd, J., ASLE Trans. 1 (1958) 159-209 (effective temperature T1 + dT/2).
.. [3] Budynas, R. G., Nisbett, J. K., *Shigley's Mechanical Engineering
   Design*, 10th ed., McGraw-Hill, 2015, sec. 12-9 (pressure-fed bearing with
   a circumferential groove: side flow and temperature rise).
.. [4] Milne-Thomson, L. M., *Theoretical Hydrodynamics*, 5th ed., 1968, ch. 8
   (sources, images and conformal maps of plane potential flow; the
   Hele-Shaw film obeys the same Laplace equation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate as check
from .._validate import AngleVectors, InRange, OneOf, Positive, renamed, validated
from .steady import journal_position, min_film_thickness
from . import oil as oils

FEEDS = ("groove", "hole")
#: Steady tiers the balance evaluates at every crank angle.
METHODS = ("short", "finite")
#: Highest effective temperature the balance looks for [degC]; above every engine oil's service limit.
TEMPERATURE_LIMIT = 250.0
#: Effective temperature = supply + this share of the rise (mean of inlet and outlet, Raimondi and Boyd).
TEMPERATURE_SHARE = 0.5
#: Status per bearing: the balance holds / no balance below TEMPERATURE_LIMIT / not converged in the iterations.
STATUS = ("balanced", "no_balance_below_limit", "not_converged")


@dataclass(frozen=True)
class OilFeed:
    """How the oil enters a main bearing.

    Attributes
    ----------
    kind : {"groove", "hole"}
    supply_pressure : float
        Gauge pressure of the oil at the feed [Pa], > 0.
    groove_arc : tuple of float
        Start and end of the groove [rad], engine-fixed frame of the journal
        position, counted in the sense of rotation (end > start, span <= 2 pi).
    groove_width : float
        Axial width of the groove [m].
    hole_angle : float
        Position of the hole [rad].
    hole_diameter : float
        [m]
    source : str
    """

    kind: str
    supply_pressure: float
    groove_arc: tuple = (0.5 * np.pi, 1.5 * np.pi)
    groove_width: float = 0.0
    hole_angle: float = np.pi
    hole_diameter: float = 0.0
    source: str = ""


def _arc_trig_integrals(start, end):
    """Integrals over start..end of cos^i sin^j, i + j <= 3 (closed forms), by (i, j)."""
    def antiderivatives(t):
        c, s = np.cos(t), np.sin(t)
        return {(0, 0): t, (1, 0): s, (0, 1): -c, (2, 0): t / 2 + s * c / 2, (1, 1): s * s / 2,
                (0, 2): t / 2 - s * c / 2, (3, 0): s - s**3 / 3, (2, 1): -c**3 / 3, (1, 2): s**3 / 3,
                (0, 3): -c + c**3 / 3}

    a, b = antiderivatives(start), antiderivatives(end)
    return {k: b[k] - a[k] for k in a}


@renamed(radius="journal_radius", length="bearing_width")
def groove_feed_flow(position, *, radial_clearance, supply_pressure, viscosity, journal_radius, bearing_width,
                     groove_width, groove_arc):
    """Pressure-driven flow out of a feed groove over both lands [m^3/s], cycle mean.

    Parameters
    ----------
    position : array_like (..., angles, 2)
        Journal centre over the cycle [m].
    radial_clearance, viscosity, journal_radius, bearing_width : array_like (...)
        [m], [Pa s], [m], [m].
    supply_pressure : float or array_like (...)
        [Pa]
    groove_width : float
        Axial width [m], below ``bearing_width``.
    groove_arc : (float, float)
        Start and end angle [rad].

    Returns
    -------
    numpy.ndarray (...)
    """
    x = np.asarray(position, dtype=float)
    c = np.asarray(radial_clearance, dtype=float)
    # (c - x0 cos - x1 sin)^3 expanded: the arc integrals of the trigonometric monomials times the cycle means
    # of the position's monomials (exact, and one pass over the angles instead of trigonometry at each)
    s = _arc_trig_integrals(*groove_arc)
    x0, x1 = x[..., 0], x[..., 1]
    x00, x01, x11 = x0 * x0, x0 * x1, x1 * x1

    def mean(a):
        return a.mean(axis=-1)

    integral = (c**3 * s[0, 0] - 3 * c**2 * (mean(x0) * s[1, 0] + mean(x1) * s[0, 1])
                + 3 * c * (mean(x00) * s[2, 0] + 2 * mean(x01) * s[1, 1] + mean(x11) * s[0, 2])
                - (mean(x00 * x0) * s[3, 0] + 3 * mean(x00 * x1) * s[2, 1] + 3 * mean(x01 * x1) * s[1, 2]
                   + mean(x11 * x1) * s[0, 3]))
    land = (np.asarray(bearing_width) - groove_width) / 2
    return np.asarray(supply_pressure) * np.asarray(journal_radius) / (6 * np.asarray(viscosity) * land) * integral


@renamed(length="bearing_width")
def hole_feed_flow(position, *, radial_clearance, supply_pressure, viscosity, bearing_width, hole_diameter,
                   hole_angle):
    """Pressure-driven flow out of a single feed hole in the middle of the bearing [m^3/s], cycle mean.

    Parameters as :func:`groove_feed_flow`; ``hole_diameter`` [m] (well below
    ``bearing_width``), ``hole_angle`` [rad].
    """
    x = np.asarray(position, dtype=float)
    h = np.asarray(radial_clearance, dtype=float)[..., None] - x @ np.array([np.cos(hole_angle), np.sin(hole_angle)])
    mean_h3 = (h**3).mean(axis=-1)
    log = np.log(4 * np.asarray(bearing_width) / (np.pi * hole_diameter))
    return np.pi * np.asarray(supply_pressure) * mean_h3 / (6 * np.asarray(viscosity) * log)


@renamed(radius="journal_radius", length="bearing_width")
def feed_flow(position, *, feed, radial_clearance, viscosity, journal_radius, bearing_width):
    """Feed flow [m^3/s] of an :class:`OilFeed`, cycle mean (:func:`groove_feed_flow` or :func:`hole_feed_flow`)."""
    if feed.kind == "groove":
        return groove_feed_flow(position, radial_clearance=radial_clearance, supply_pressure=feed.supply_pressure,
                                viscosity=viscosity, journal_radius=journal_radius, bearing_width=bearing_width,
                                groove_width=feed.groove_width, groove_arc=feed.groove_arc)
    return hole_feed_flow(position, radial_clearance=radial_clearance, supply_pressure=feed.supply_pressure,
                          viscosity=viscosity, bearing_width=bearing_width, hole_diameter=feed.hole_diameter,
                          hole_angle=feed.hole_angle)


@dataclass(frozen=True)
class HeatBalance:
    """Thermal state of bearings over the cycle; arrays over the bearings (...).

    Attributes
    ----------
    temperature : numpy.ndarray
        Effective film temperature [degC].
    viscosity : numpy.ndarray
        Oil viscosity at that temperature and the film's shear rate [Pa s]: the
        viscosity the film tiers should use.
    friction_power : numpy.ndarray
        Friction power, cycle mean [W].
    side_flow : numpy.ndarray
        Hydrodynamic side flow, cycle mean [m^3/s].
    feed_flow : numpy.ndarray
        Pressure-driven feed flow, cycle mean [m^3/s].
    status : numpy.ndarray of int8
        Index into :data:`STATUS`.
    """

    temperature: np.ndarray
    viscosity: np.ndarray
    friction_power: np.ndarray
    side_flow: np.ndarray
    feed_flow: np.ndarray
    status: np.ndarray

    @property
    def flow(self):
        """Oil flow through the bearing, cycle mean [m^3/s]."""
        return self.side_flow + self.feed_flow


def check_feed(feed, bearing_width):
    """A ValueError where ``feed`` does not fit bearings of ``bearing_width`` [m] (the narrowest one)."""
    check.one_of("feed.kind", feed.kind, FEEDS)
    check.positive("feed.supply_pressure", feed.supply_pressure)
    short = float(np.min(bearing_width))
    if feed.kind == "groove":
        width = float(check.positive("feed.groove_width", feed.groove_width))
        if width >= short:
            raise ValueError(f"feed.groove_width: {width!r} m is not below the bearing length {short!r} m")
        start, end = (float(a) for a in check.finite("feed.groove_arc", feed.groove_arc))
        if not 0 < end - start <= 2 * np.pi:
            raise ValueError(f"feed.groove_arc: ({start!r}, {end!r}) rad is not valid; need start < end <= start + 2 pi")
    else:
        diameter = float(check.positive("feed.hole_diameter", feed.hole_diameter))
        if diameter >= short / 2:
            raise ValueError(f"feed.hole_diameter: {diameter!r} m is not below half the bearing length {short / 2!r} m")
        check.finite("feed.hole_angle", feed.hole_angle)


def _feed_fits(values):
    check_feed(values["feed"], values["bearing_width"])


@renamed(diameter="journal_d", length="bearing_width")
@validated(method=OneOf(METHODS), load_history=AngleVectors(), journal_d=Positive(), bearing_width=Positive(),
           clearance=Positive(), speed=Positive(), supply_temperature=InRange(-30.0, 200.0, unit=" degC"),
           relations=(_feed_fits,))
def heat_balance(load_history, *, journal_d, bearing_width, clearance, speed, oil, supply_temperature, feed,
                 method="short", shear_thinning=True, tolerance=0.01, max_iterations=60):
    """Effective temperature, viscosity, friction power and oil flow of bearings over the cycle.

    Parameters
    ----------
    load_history : array_like (..., angles, 2)
        Load on each bearing at equal crank-angle steps of one cycle [N] (the
        frame of :func:`stackup.film.orbit.orbit`); a coarser subsample of the
        cycle gives nearly the same means at a fraction of the cost.
    journal_d, clearance : array_like (...)
        Journal diameter and diametral clearance [m].
    bearing_width : float or array_like (...)
        Bearing width [m].
    speed : float
        Journal angular speed [rad/s].
    oil : str or stackup.film.oil.Oil
    supply_temperature : float or array_like (...)
        Oil supply temperature [degC].
    feed : OilFeed
    method : {"short", "finite"}
        Steady tier evaluated at each crank angle.
    shear_thinning : bool
        Viscosity at the film's shear rate :math:`\\omega R/c` (Cross curve of
        multigrade oils) instead of the low-shear viscosity.
    tolerance : float
        On the effective temperature [K].
    max_iterations : int

    Returns
    -------
    HeatBalance
    """
    loads = np.asarray(load_history, dtype=float)
    lead = loads.shape[:-2]
    radius = np.broadcast_to(np.asarray(journal_d, dtype=float) / 2, lead).ravel()
    width = np.broadcast_to(np.asarray(bearing_width, dtype=float), lead).ravel()
    c = np.broadcast_to(np.asarray(clearance, dtype=float) / 2, lead).ravel()
    t_in = np.broadcast_to(np.asarray(supply_temperature, dtype=float), lead).ravel().astype(float)
    state = _CycleHeat(loads.reshape(-1, loads.shape[-2], 2), oils.get(oil), feed, method=method, omega=float(speed),
                       radius=radius, width=width, c=c, t_in=t_in, shear_thinning=shear_thinning)
    t, status, (mu, power, side, fed) = _false_position(state, t_in, tolerance=tolerance,
                                                        max_iterations=max_iterations)
    shape = lambda a: np.asarray(a).reshape(lead)  # noqa: E731
    return HeatBalance(shape(t), shape(mu), shape(power), shape(side), shape(fed), shape(status))


class _CycleHeat:
    """The balance's residual g(T) = T - T_supply - rise of flattened bearings, and what it reads on the way."""

    def __init__(self, loads, oil, feed, *, method, omega, radius, width, c, t_in, shear_thinning):
        self.f, self.oil, self.feed, self.method, self.omega = loads, oil, feed, method, omega
        self.radius, self.width, self.c, self.t_in = radius, width, c, t_in
        self.magnitude = np.linalg.norm(loads, axis=-1)
        self.shear_rate = omega * radius / c if shear_thinning else None

    def __call__(self, t, rows):
        """(g at temperatures ``t`` of bearings ``rows``, (viscosity, friction power, side flow, feed flow))."""
        oil, omega, radius, c = self.oil, self.omega, self.radius, self.c
        mu = oil.viscosity(t, shear_rate=None if self.shear_rate is None else self.shear_rate[rows])
        col = (radius[rows, None], self.width[rows, None], c[rows, None], mu[:, None])
        film = min_film_thickness(self.magnitude[rows], journal_d=2 * col[0], bearing_width=col[1],
                                  clearance=2 * col[2], viscosity=col[3], speed=omega, method=self.method)
        x = journal_position(self.f[rows], eccentricity=film.eccentricity, attitude_angle=film.attitude_angle,
                             clearance=2 * col[2])
        fed = feed_flow(x, feed=self.feed, radial_clearance=c[rows], viscosity=mu, journal_radius=radius[rows],
                        bearing_width=self.width[rows])
        power = omega * film.friction_torque.mean(axis=-1)
        side = film.side_flow.mean(axis=-1)
        rise = TEMPERATURE_SHARE * power / (oil.density(t) * oils.SPECIFIC_HEAT * (side + fed))
        return t - self.t_in[rows] - rise, (mu, power, side, fed)


def _false_position(state, t_in, *, tolerance, max_iterations):
    """Root of ``state`` per bearing between the supply temperature and the limit: (T, status, values there).

    Bracketed false position with the Illinois halving of an end kept twice in a row.
    """
    n = t_in.size
    everyone = np.arange(n)
    lo, hi = t_in.copy(), np.full(n, TEMPERATURE_LIMIT)
    g_lo, _ = state(lo, everyone)
    g_hi, out_hi = state(hi, everyone)
    t = hi.copy()
    out = [a.copy() for a in out_hi]
    status = np.where(g_hi < 0, 1, 2).astype(np.int8)
    done = g_hi < 0
    done |= g_lo >= 0  # no rise at all (cannot happen with friction), the supply temperature holds
    t[g_lo >= 0] = lo[g_lo >= 0]
    status[g_lo >= 0] = 0
    last = np.zeros(n, np.int8)  # side replaced last (Illinois): -1 low, +1 high
    for _ in range(max_iterations):
        rows = np.flatnonzero(~done)
        if rows.size == 0:
            break
        a, b, ga, gb = lo[rows], hi[rows], g_lo[rows], g_hi[rows]
        trial = np.clip(b - gb * (b - a) / (gb - ga), a, b)
        g, values = state(trial, rows)
        t[rows] = trial
        for target, value in zip(out, values):
            target[rows] = value
        converged = (np.abs(g) < tolerance) | (b - a < tolerance)
        below = g < 0
        # false position with the Illinois halving of the end kept twice in a row
        lo[rows] = np.where(below, trial, a)
        g_lo[rows] = np.where(below, g, np.where(last[rows] == 1, 0.5 * ga, ga))
        hi[rows] = np.where(below, b, trial)
        g_hi[rows] = np.where(below, np.where(last[rows] == -1, 0.5 * gb, gb), g)
        last[rows] = np.where(below, -1, 1)
        status[rows[converged]] = 0
        done[rows[converged]] = True
    return t, status, out
