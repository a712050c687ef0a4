r"""Bearing resource (wear life) from the oil film: the two methods of Levanov et al. (2015).

Method 1 (Rumb's dependence, eqs. 4-5) from the minimum film thickness:

.. math:: R = \left(\frac{\Delta h_{lim}}{\gamma}\right)^{1/\beta_1}, \qquad
          \beta_1 = 1 + \left(\frac{\bar h_{min}}{h_{lim,cr}}\right)^{n_I}

with limiting wear :math:`\Delta h_{lim}` [m], wear speed :math:`\gamma` [m/s]
and :math:`R` in seconds. Scale: the paper's method-1 results (its Table 1) are
reproduced, :math:`\beta_1` to 1e-4 with :math:`n_I = -2` and the life within 0.2 %
on every row, only with :math:`\Delta h_{lim}/\gamma` = 1.0e8 s
(:data:`METHOD1_SCALE`); its text's 30 um and 1e-13 m/s give 3e8 s and lives
2.65-2.85 times the table's. Method 1 is a correlation fitted to a 10,000 h
bearing (Rumb's dependence, the inverse task of sec. 4): it is used on the scale
its results support, :data:`LEVANOV_2015`'s ``method1_wear_limit`` (10 um) with
the text's 1e-13 m/s, and method 2 on the text's 30 um (its Table 2:
:math:`R_h = \Delta h_{lim}/\gamma` with 30 um on every row, to the rounding of
:math:`\gamma`). The film the paper feeds is :math:`\bar h_{min}`, the
average over the loading cycle of the minimum film thickness: the paper lists
both the minimum and the average minimum film among a bearing's
characteristics (sec. 2), and its results pair films of 5.3-8.6 um with
shares of the cycle in boundary friction of 5-17 % (Table 1; Table 2 pairs
5.7-8.1 um with 8.8-14.8 %). A film below :math:`h_{lim,cr}` = 1.9 um during
5-17 % of the cycle cannot have a cycle minimum of 5 um, so those films are
cycle averages. :func:`cycle_film` gives either statistic by name; the cycle
minimum (``"cycle-minimum"``) gives lives of hours for any bearing that
touches boundary friction at all and is kept only as a comparison.

The critical film comes from the surfaces (eq. 3): :math:`h_{lim,cr} > R_{z1} + R_{z2}`
(:func:`critical_film`).

Method 2 (molecular-mechanical friction and fatigue wear, eqs. 6-7) builds a
wear chart over the bearing surface where the film is below :math:`h_{lim,cr}`:
:func:`levanov_method2`. At each crank angle :math:`\varphi` the contact zone is
the arc where :math:`h < h_{lim,cr}`, of half-angle :math:`\beta_c`; inside it the
asperities carry the Greenwood-Tripp pressure :math:`p(\varphi, \beta)`
(:mod:`stackup.contact`) and wear with the linear intensity
:math:`I_h = k\,p^m` (eq. 7). Eq. 6,

.. math:: \delta(\varphi, \beta) = I_h(\varphi, \beta)\,2\beta_c R_b,

is the depth one pass of the contact arc (a sliding distance
:math:`2\beta_c R_b`) wears; the journal passes once per revolution, so a
crank-angle step :math:`\Delta\varphi` adds :math:`\delta\,\Delta\varphi/2\pi`
and the chart is the integral over the cycle, :math:`\oint \delta\,d\varphi/2\pi`:
it converges as the step shrinks instead of growing with the step count. The
wear speed is the deepest point's depth per cycle over the cycle time, and the
resource the time for it to reach :math:`\Delta h_{lim}`. Counting the sliding
of the journal past a fixed point of the bearing instead (a distance
:math:`2\pi R_b` per revolution) would make the wear larger by
:math:`\pi/\beta_c`; eq. 6 is kept as the paper writes it.

:math:`\alpha`, the share of the cycle with :math:`h_{min} < h_{lim,cr}`
(:func:`alpha`), flags scuffing risk above 20 %.

References
----------
.. [1] Levanov, I. G., Zadorozhnaya, E. A., Mukhortov, I. V., Eschiganov, M. O.,
   "Research of the Resource of Crankshaft Bearings of Internal Combustion
   Engines", Tribology in Industry 37 (2015) 360-365, eqs. 3-7.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._kernels import life as _kernel
from ._validate import AngleVectors, Finite, Integer, OneOf, Positive, finite, renamed, validated
from .contact import TYPICAL_ASPERITIES, greenwood_tripp
from .stats import proportion_ci, quantile_ci


@dataclass(frozen=True)
class LevanovParameters:
    """Constants of Levanov et al. (2015), with the paper's values.

    Attributes
    ----------
    n : float
        Exponent :math:`n_I` of eq. 5 [-]; the paper gives -2.0 to -2.5
        (obtained by the inverse task from a 10 000 h resource). -2.0, the
        end of the range that gives the shorter life, is taken.
    wear_limit : float
        Limiting wear :math:`\\Delta h_{lim}` of the paper's diesel [m] (sec. 4: 30e-6 m), the
        scale of method 2 (Table 2's lives are 30 um over its wear speeds).
    method1_wear_limit : float
        Limiting wear of method 1 [m]: with ``wear_rate`` the scale
        :math:`\\Delta h_{lim}/\\gamma` = :data:`METHOD1_SCALE` at which the paper's
        method-1 results (Table 1) are reproduced; the text's 30 um would give
        three times that.
    wear_rate : float
        Wear speed :math:`\\gamma` [m/s] (sec. 4: 1e-13 m/s, from its ref. [3]).
    critical_film : float
        :math:`h_{lim,cr}` of the paper's diesel connecting-rod bearing [m] (sec. 4: 1.9e-6 m).
    k : float
        Constant of the linear wear intensity :math:`I_h = k p^m`, eq. 7 [1/Pa] (7e-12).
    m : float
        Exponent of eq. 7 [-] (0.0511), from "roller-pad" tests.
    alpha_scuffing : float
        Share of the cycle in boundary friction above which the probability of
        scuffing rises sharply [-] (sec. 2: 20 %).
    source : str
    """

    n: float = -2.0
    wear_limit: float = 30e-6
    method1_wear_limit: float = 10e-6
    wear_rate: float = 1e-13
    critical_film: float = 1.9e-6
    k: float = 7e-12
    m: float = 0.0511
    alpha_scuffing: float = 0.20
    source: str = ("Levanov, Zadorozhnaya, Mukhortov, Eschiganov, Tribology in Industry 37 (2015) 360-365: "
                   "sec. 2 (20 %), sec. 4 (n_I, wear limit, wear speed, h_lim,cr, k, m)")


#: The one parameter set of Levanov et al. (2015).
LEVANOV_2015 = LevanovParameters()
#: Scale :math:`\Delta h_{lim}/\gamma` [s] of method 1 on which the paper's method-1 results (Table 1) are
#: reproduced (beta_1 to 1e-4 with n_I = -2, lives within 0.2 %); the text's 30 um / 1e-13 m/s give 3e8 s.
METHOD1_SCALE = LEVANOV_2015.method1_wear_limit / LEVANOV_2015.wear_rate
#: The scale the text's values give (30 um / 1e-13 m/s) [s], named where a report compares the two.
TEXT_SCALE = LEVANOV_2015.wear_limit / LEVANOV_2015.wear_rate
#: Above this share of the cycle in boundary friction the scuffing probability rises sharply.
ALPHA_SCUFFING = LEVANOV_2015.alpha_scuffing
#: Statistics of the minimum film over the cycle that :func:`cycle_film` gives.
FILM_STATISTICS = ("cycle-mean", "cycle-minimum")


@dataclass(frozen=True)
class Life:
    """Bearing resource by method 1.

    Attributes
    ----------
    beta : numpy.ndarray
        Index :math:`\\beta_1` [-].
    life : numpy.ndarray
        Resource [s].
    film : numpy.ndarray
        Film thickness the resource was computed from [m].
    """

    beta: np.ndarray
    life: np.ndarray
    film: np.ndarray

    @property
    def life_hours(self):
        """Resource [h]."""
        return self.life / 3600.0


@validated(journal_roughness=Positive(), shell_roughness=Positive())
def critical_film(journal_roughness, shell_roughness):
    """Critical film thickness [m] of eq. 3, :math:`h_{lim,cr} = R_{z1} + R_{z2}`.

    Parameters
    ----------
    journal_roughness, shell_roughness : array_like
        Roughness :math:`R_z` of the journal and of the shell's running surface [m].

    Returns
    -------
    numpy.ndarray
        The lower bound of eq. 3 (the film must be thicker than the sum of the
        roughnesses for the hydrodynamic regime) [m].
    """
    return np.asarray(journal_roughness, dtype=float) + np.asarray(shell_roughness, dtype=float)


@validated(statistic=OneOf(FILM_STATISTICS), h_min_history=Positive(zero=True))
def cycle_film(h_min_history, *, statistic="cycle-mean", axis=-1):
    """The film of method 1 from the minimum film at each step of one cycle.

    Parameters
    ----------
    h_min_history : array_like (..., steps, ...)
        Minimum film thickness at equal steps of one cycle [m].
    statistic : {"cycle-mean", "cycle-minimum"}
        ``"cycle-mean"``: :math:`\\bar h_{min}`, the film Levanov et al. feed
        method 1 (see the module notes); ``"cycle-minimum"``: the thinnest
        film of the cycle, a comparison only.
    axis : int
        Axis of the steps.

    Returns
    -------
    numpy.ndarray
        [m], the steps' axis removed.
    """
    h = np.asarray(h_min_history, dtype=float)
    return h.mean(axis=axis) if statistic == "cycle-mean" else h.min(axis=axis)


def _negative_exponent(values):
    if np.any(values["n"] >= 0):
        raise ValueError(f"n: {float(np.max(values['n']))!r} is not valid; must be < 0 (the paper: -2.0 to -2.5)")


@validated(h_min=Positive(zero=True), h_lim_cr=Positive(), wear_limit=Positive(), wear_rate=Positive(), n=Finite(),
           relations=(_negative_exponent,))
def levanov_method1(h_min, *, h_lim_cr, wear_limit, wear_rate, n=LEVANOV_2015.n):
    """Resource from the minimum film thickness (Levanov et al. 2015, method 1, eqs. 4-5).

    Parameters
    ----------
    h_min : array_like
        Film thickness [m], >= 0: :math:`\\bar h_{min}`, the cycle average of
        the minimum film, as the paper uses it (:func:`cycle_film`).
    h_lim_cr : array_like
        Critical film thickness [m] (:func:`critical_film`).
    wear_limit : array_like
        Limiting wear :math:`\\Delta h_{lim}` [m] of method 1: with ``wear_rate`` the
        scale :math:`\\Delta h_{lim}/\\gamma`; the paper's results support
        :data:`METHOD1_SCALE` (``LEVANOV_2015.method1_wear_limit`` with its
        ``wear_rate``), not its text's 30 um (see the module notes).
    wear_rate : array_like
        Wear speed :math:`\\gamma` [m/s].
    n : float
        Exponent :math:`n_I` [-], < 0.

    Returns
    -------
    Life
        ``beta`` and ``life`` [s], broadcast over the inputs. A thick film
        (:math:`\\beta_1 \\to 1`) gives :math:`\\Delta h_{lim}/\\gamma`; a
        vanishing film gives 1 s.

    Notes
    -----
    .. math:: R = \\left(\\frac{\\Delta h_{lim}}{\\gamma}\\right)^{1/\\beta_1}, \\qquad
              \\beta_1 = 1 + \\left(\\frac{h_{min}}{h_{lim,cr}}\\right)^{n_I}

    evaluated in log space, so neither a vanishing film nor a large exponent overflows.
    """
    h_min, h_lim_cr, wear_limit, wear_rate, n = (np.asarray(a, dtype=float)
                                                 for a in (h_min, h_lim_cr, wear_limit, wear_rate, n))
    with np.errstate(divide="ignore", over="ignore"):
        beta = 1.0 + np.exp(n * (np.log(h_min) - np.log(h_lim_cr)))
    life = np.exp((np.log(wear_limit) - np.log(wear_rate)) / beta)
    return Life(beta, life, np.broadcast_to(h_min, np.shape(life)))


@validated(h_min_history=Finite(), h_lim_cr=Positive())
def alpha(h_min_history, *, h_lim_cr, axis=-1):
    """Share of the cycle [-] with the film below ``h_lim_cr`` [m], over ``axis`` (equal steps)."""
    h = np.asarray(h_min_history, dtype=float)
    h_lim_cr = np.asarray(h_lim_cr, dtype=float)
    return np.mean(h < np.expand_dims(h_lim_cr, axis) if np.ndim(h_lim_cr) else h < h_lim_cr, axis=axis)


def engine_life(bearing_life, *, axis=-1):
    """Life of an engine [s]: that of its weakest bearing (minimum over ``axis``; NaN stays NaN)."""
    return np.min(np.asarray(bearing_life, dtype=float), axis=axis)


@dataclass(frozen=True)
class LifeSummary:
    """Life statistics of a sample of bearings or engines, each ``(estimate, lower, upper)``.

    Attributes
    ----------
    b10 : tuple
        10 % quantile of the life [s] with its 95 % interval.
    median : tuple
        Median life [s] with its 95 % interval.
    share_below_target : tuple
        Share of the sample with a life below the target [-] with its 95 %
        (Clopper-Pearson) interval.
    count : int
        Sample size (NaN values left out).
    """

    b10: tuple
    median: tuple
    share_below_target: tuple
    count: int


@validated(target=Positive())
def life_summary(life, *, target, confidence=0.95):
    """B10, median and the share below ``target`` of a sample of lives, with intervals.

    Parameters
    ----------
    life : array_like
        Lives [s] (any shape; NaN, e.g. engines the stage did not run on, are
        left out; an infinite life is a life without wear).
    target : float
        Life target [s] (the engine file's ``[targets] life_hours``).
    confidence : float
        Level of the intervals.

    Returns
    -------
    LifeSummary
    """
    x = np.asarray(life, dtype=float).ravel()
    x = x[~np.isnan(x)]
    target = float(target)
    below = proportion_ci(np.count_nonzero(x < target), x.size, confidence=confidence)
    # an infinite life (no wear) stands in as the largest float, so quantiles between two of them stay infinite
    top = np.finfo(float).max
    finite = np.minimum(x, top)

    def quantile(q):
        return tuple(np.inf if v >= top else v for v in quantile_ci(finite, q, confidence=confidence))

    return LifeSummary(quantile(0.10), quantile(0.5), below, int(x.size))


@dataclass(frozen=True)
class WearChart:
    """Wear chart of the bearing surface and the resource by method 2.

    Attributes
    ----------
    position_angle : numpy.ndarray (positions,)
        Angle of each point of the chart on the bearing surface, engine-fixed
        frame as the journal position (0 along the first axis) [rad].
    wear_per_cycle : numpy.ndarray (..., positions)
        Wear depth one cycle adds at each point [m].
    wear_rate : numpy.ndarray (...)
        Wear speed of the deepest point [m/s].
    deepest_angle : numpy.ndarray (...)
        Angle of the deepest point [rad] (NaN without wear).
    life : numpy.ndarray (...)
        Time for the deepest point to reach the limiting wear [s]; infinite
        where the film never drops below the critical film.
    alpha : numpy.ndarray (...)
        Share of the cycle with the minimum film below the critical film [-].
    contact_pressure_max : numpy.ndarray (...)
        Largest asperity contact pressure inside the contact zone over the cycle [Pa] (0 without contact).
    """

    position_angle: np.ndarray
    wear_per_cycle: np.ndarray
    wear_rate: np.ndarray
    deepest_angle: np.ndarray
    life: np.ndarray
    alpha: np.ndarray
    contact_pressure_max: np.ndarray

    @property
    def life_hours(self):
        """Resource [h]."""
        return self.life / 3600.0


#: Points of the wear chart around the bearing (0.5 deg apart).
CHART_POINTS = 720


def _one_cycle(field, crank_angle):
    """Constraint of the crank angles of one cycle: 1-D, increasing, spanning less than 720 deg."""
    a = finite(field, crank_angle)
    if a.ndim != 1 or a.size < 2 or np.any(np.diff(a) <= 0) or a[-1] - a[0] >= 720.0:
        raise ValueError(f"{field}: must be 1-D, increase and span less than 720 deg")
    return a


def _step_revolutions(crank_angle):
    """Journal revolutions each crank-angle sample stands for (periodic mid-point rule over 720 deg)."""
    a = np.asarray(crank_angle, dtype=float)
    after = np.diff(np.append(a, a[0] + 720.0))
    return 0.5 * (after + np.roll(after, 1)) / 360.0


def _angles_of(name):
    """Relation: the angles (the axis before the last) of ``name`` are those of ``crank_angle``."""
    def relation(values):
        angles, given = values[name].shape[-2], values["crank_angle"].size
        if angles != given:
            raise ValueError(f"{name}: {angles} angles, crank_angle has {given}")

    return relation


def _prepare(lead, crank_angle, speed, *per_bearing):
    """(revolutions per crank-angle step, each per-bearing input flattened over ``lead``, cycle time per bearing)."""
    revolutions = _step_revolutions(crank_angle)
    flat = [np.broadcast_to(np.asarray(value, dtype=float), lead).ravel() for value in per_bearing]
    cycle_time = np.broadcast_to(4 * np.pi / np.asarray(speed, dtype=float), lead).ravel()
    return revolutions, flat, cycle_time


#: The checks both forms of method 2 declare (the rest as each takes it).
_METHOD2 = dict(crank_angle=_one_cycle, speed=Positive(), journal_radius=Positive(), h_lim_cr=Positive(),
                roughness=Positive(), contact_modulus=Positive(), wear_limit=Positive())


def _wear(contacts, n_rows, points, *, revolutions, radius, sigma, modulus, k, m, asperities):
    """Eq. 6 summed over the cycle at each chart point: (wear per cycle (rows, points) [m], peak pressure (rows,) [Pa]).

    ``contacts``: (row, step, point, film, zone size) of every chart point in contact, as
    :func:`stackup._kernels.life.contact_zones` lists them.
    """
    r, steps, j, h, zone = contacts
    wear = np.zeros((n_rows, points))
    peak = np.zeros(n_rows)
    if r.size == 0:
        return wear, peak
    pressure = greenwood_tripp(h, roughness=sigma[r], contact_modulus=modulus[r], asperities=asperities)
    half_angle = zone * (np.pi / points)  # beta_c: half the arc below the critical film
    depth = k * pressure**m * 2.0 * half_angle * radius[r] * revolutions[steps]
    wear += np.bincount(r * points + j, weights=depth, minlength=wear.size).reshape(wear.shape)
    np.maximum.at(peak, r, pressure)
    return wear, peak


def _chart(wear, peak, share, lead, revolutions, cycle_time, wear_limit, angles):
    per_cycle = wear.reshape(*lead, angles.size)
    deepest = wear.max(axis=1)
    rate = deepest / cycle_time
    with np.errstate(divide="ignore"):
        life = np.where(rate > 0, wear_limit / np.where(rate > 0, rate, 1.0), np.inf)
    where = np.where(deepest > 0, angles[np.argmax(wear, axis=1)], np.nan)
    return WearChart(angles, per_cycle, rate.reshape(lead), where.reshape(lead), life.reshape(lead),
                     share.reshape(lead), peak.reshape(lead))


@renamed(bearing_radius="journal_radius")
@validated(position=AngleVectors(), **_METHOD2, radial_clearance=Positive(), points=Integer(minimum=8),
           relations=(_angles_of("position"),))
def levanov_method2(position, *, radial_clearance, crank_angle, speed, journal_radius, h_lim_cr, roughness,
                    contact_modulus, wear_limit, k=LEVANOV_2015.k, m=LEVANOV_2015.m, asperities=TYPICAL_ASPERITIES,
                    points=CHART_POINTS):
    r"""Wear chart and resource from the journal orbit (Levanov et al. 2015, method 2, eqs. 6-7).

    Parameters
    ----------
    position : array_like (..., angles, 2)
        Journal centre relative to the bearing centre at each crank angle [m]
        (:attr:`stackup.film.orbit.Orbit.position`, or
        :func:`stackup.film.journal_position` for a quasi-static film). The
        film around the bearing is :math:`h(\theta) = c - \mathbf x\cdot(\cos\theta, \sin\theta)`.
    radial_clearance : array_like (...)
        Radial clearance :math:`c` [m].
    crank_angle : array_like (angles,)
        Crank angles [deg] of one cycle (720 deg), increasing; steps may be unequal.
    speed : float or array_like (...)
        Crankshaft angular speed [rad/s]; the cycle lasts :math:`4\pi/\omega`.
    journal_radius : array_like (...)
        :math:`R_b` [m].
    h_lim_cr : array_like (...)
        Critical film [m] (:func:`critical_film`); the chart grows only where the film is thinner.
    roughness : array_like (...)
        Composite RMS roughness of journal and shell [m] (:func:`stackup.contact.composite_roughness`).
    contact_modulus : array_like (...)
        :math:`E^*` of journal and shell lining [Pa] (:func:`stackup.contact.contact_modulus`).
    wear_limit : array_like (...)
        Limiting wear :math:`\Delta h_{lim}` [m].
    k, m : float
        Wear intensity constants of eq. 7 [1/Pa], [-].
    asperities : stackup.contact.AsperityParameters
    points : int
        Points of the chart around the bearing.

    Returns
    -------
    WearChart
        The chart of eq. 6 summed over the cycle (see the module's notes on method 2).
    """
    x = np.asarray(position, dtype=float)
    lead, count = x.shape[:-2], int(np.prod(x.shape[:-2], dtype=int))
    revolutions, (radius, h_cr, sigma, modulus, limit, c), cycle_time = _prepare(
        lead, crank_angle, speed, journal_radius, h_lim_cr, roughness, contact_modulus, wear_limit, radial_clearance)
    x = np.ascontiguousarray(x.reshape(count, -1, 2))
    angles = 2 * np.pi * np.arange(points) / points
    share, *contacts = _kernel.contact_zones(x, np.ascontiguousarray(c, dtype=float),
                                             np.ascontiguousarray(h_cr, dtype=float), np.cos(angles), np.sin(angles),
                                             revolutions / revolutions.sum())
    wear, peak = _wear(contacts, count, points, revolutions=revolutions, radius=radius, sigma=sigma, modulus=modulus,
                       k=k, m=m, asperities=asperities)
    return _chart(wear, peak, share, lead, revolutions, cycle_time, limit, angles)


def _film_around_the_bearing(values):
    if values["film_thickness"].ndim < 2:
        raise ValueError(f"film_thickness: shape {values['film_thickness'].shape} is not valid; expected (..., angles, "
                         "points)")
    _angles_of("film_thickness")(values)


@renamed(bearing_radius="journal_radius")
@validated(film_thickness=Finite(), **_METHOD2, relations=(_film_around_the_bearing,))
def levanov_method2_field(film_thickness, *, crank_angle, speed, journal_radius, h_lim_cr, roughness,
                          contact_modulus, wear_limit, k=LEVANOV_2015.k, m=LEVANOV_2015.m,
                          asperities=TYPICAL_ASPERITIES):
    r"""Method 2 from a film thickness field around the bearing (e.g. a Reynolds tier's film).

    Parameters
    ----------
    film_thickness : array_like (..., angles, points)
        Film thickness at each crank angle and at ``points`` equally spaced
        angles :math:`2\pi j/\mathrm{points}` around the bearing [m].
    crank_angle, speed, journal_radius, h_lim_cr, roughness, contact_modulus, wear_limit, k, m, asperities :
        As :func:`levanov_method2`.

    Returns
    -------
    WearChart
    """
    h = np.asarray(film_thickness, dtype=float)
    lead, count, points = h.shape[:-2], int(np.prod(h.shape[:-2], dtype=int)), h.shape[-1]
    revolutions, (radius, h_cr, sigma, modulus, limit), cycle_time = _prepare(
        lead, crank_angle, speed, journal_radius, h_lim_cr, roughness, contact_modulus, wear_limit)
    h = h.reshape(count, revolutions.size, points)
    below = h.min(axis=-1) < h_cr[:, None]
    rows, steps = np.nonzero(below)
    zone = h[rows, steps] < h_cr[rows, None]
    i, j = np.nonzero(zone)
    contacts = (rows[i], steps[i], j, h[rows[i], steps[i], j], zone.sum(axis=1)[i])
    wear, peak = _wear(contacts, count, points, revolutions=revolutions, radius=radius, sigma=sigma, modulus=modulus,
                       k=k, m=m, asperities=asperities)
    share = below @ revolutions / revolutions.sum()
    return _chart(wear, peak, share, lead, revolutions, cycle_time, limit, 2 * np.pi * np.arange(points) / points)
