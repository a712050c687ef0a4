"""Oil film of a main bearing under a steady load: the minimum film thickness in tiers.

Tiers of :func:`min_film_thickness` (the quasi-static tiers of :mod:`stackup.film.registry`, each with
its steady film, :attr:`~stackup.film.registry.Tier.steady`):

- ``"short"``: Ocvirk's short-bearing closed form (:mod:`stackup.film.tiers`);
- ``"finite"``: Ocvirk's form times a load and attitude correction tabulated
  from the Reynolds tier over L/D 0.1-2 and eccentricity 0.02 up to the limit
  (``studies/film_finite_table.py``; its error is in ``reports/film_speed_vs_error.md``);
- ``"reynolds"``: finite-difference Reynolds equation with Swift-Stieber
  cavitation (:mod:`stackup.film.reynolds`), the reference tier.

The friction torque and side flow of every tier use the short-bearing forms at
the tier's eccentricity, except ``"reynolds"``, which integrates its own field.

Every tier is defined over the whole physical range of loads: zero load gives
the concentric journal (eccentricity 0, h_min = c), and any finite load a film
in (0, c]. Where a tier leaves the range on which it was checked against the
reference (eccentricity above :data:`~stackup.film.journal.ECCENTRICITY_LIMIT`, or an L/D
outside the finite tier's table) the film is still returned, with ``valid`` False:
the finite tier then holds its correction at the table's edge, the Reynolds
tier continues with the short-bearing load curve scaled to its own load at the limit.

The tiers are looked up in the registry at each call: the package face (``stackup/film/__init__.py``,
imported before any of its modules) has registered them.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from .._validate import Finite, OneOf, Positive, renamed, validated
from . import registry, reynolds, tiers
from .journal import ECCENTRICITY_LIMIT

#: The steady tiers (:func:`min_film_thickness`): every registered tier with a steady film, cheapest first
#: (:mod:`stackup.film.catalogue` registers the package's; the names are read at each use).
METHODS = registry.Names(steady=True)


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
    valid : numpy.ndarray of bool
        The tier is inside the range on which it was checked against the
        reference (eccentricity <= :data:`~stackup.film.journal.ECCENTRICITY_LIMIT`, L/D inside the
        finite tier's table).
    """

    eccentricity: np.ndarray
    h_min: np.ndarray
    attitude_angle: np.ndarray
    friction_torque: np.ndarray
    side_flow: np.ndarray
    valid: np.ndarray


def _table_coordinate(eps):
    # -ln(1 - eps): the log load ratio is close to linear in it up to the table's end near 1 (linear in eps it
    # bends there, and interpolating it in eps underestimates the film near the table's end; the finite tier's
    # error is in reports/film_speed_vs_error.md)
    return -np.log1p(-eps)


@lru_cache(maxsize=1)
def _finite_table():
    data = np.load(resources.files("stackup") / "data" / "film_finite_table.npz")
    grid = (np.log(data["length_over_diameter"]), _table_coordinate(data["eccentricity"]))
    ratio = RegularGridInterpolator(grid, np.log(data["load_ratio"]))
    attitude = RegularGridInterpolator(grid, data["attitude"])
    return ratio, attitude, (data["length_over_diameter"][[0, -1]], data["eccentricity"][[0, -1]])


def _finite(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """Eccentricity, attitude and validity of the finite tier; outside its table the correction is held at the edge."""
    radius, length = journal_radius, bearing_width
    ratio, attitude, (ld_range, eps_range) = _finite_table()
    ld = length / (2 * radius)
    inside = (ld >= ld_range[0]) & (ld <= ld_range[1])
    log_ld = np.log(np.clip(ld, *ld_range))

    def lookup(table, eps):
        pts = np.stack(np.broadcast_arrays(log_ld, _table_coordinate(np.clip(eps, *eps_range))), axis=-1)
        return table(pts).reshape(np.shape(eps))

    def load_function(eps):
        return tiers.short_load_function(eps) * np.exp(lookup(ratio, eps))

    scale = viscosity * speed * radius * length**3 / (4 * radial_clearance**2)
    eps = tiers.invert_monotone(load_function, load / scale)
    phi = lookup(attitude, eps)
    # below the first node the attitude runs linearly to pi/2, its limit for the concentric journal
    low = eps < eps_range[0]
    phi = np.where(low, np.pi / 2 + (phi - np.pi / 2) * eps / eps_range[0], phi)
    return eps, phi, inside & (eps <= eps_range[1])


@renamed(diameter="journal_d", length="bearing_width")
@validated(method=OneOf(METHODS), load=Positive(zero=True), journal_d=Positive(), bearing_width=Positive(),
           clearance=Positive(), viscosity=Positive(), speed=Positive())
def min_film_thickness(load, *, journal_d, bearing_width, clearance, viscosity, speed, method="short"):
    """Eccentricity, minimum film, attitude, friction torque and side flow under a steady load.

    Parameters
    ----------
    load : array_like
        Bearing load [N], >= 0.
    journal_d : array_like
        Journal diameter [m].
    bearing_width : array_like
        Bearing width [m].
    clearance : array_like
        Diametral clearance [m]; the radial clearance is half of it.
    viscosity : array_like
        Dynamic viscosity of the oil [Pa s].
    speed : array_like
        Journal angular speed [rad/s], > 0.
    method : str
        A steady tier (:data:`METHODS`: ``"short"``, ``"finite"``, ``"reynolds"``).

    Returns
    -------
    Film
        Zero load gives eccentricity 0 and h_min = c; every finite load a film
        in (0, c], flagged by ``valid`` where the tier leaves its checked range.
    """
    load, d, length, clearance, mu, omega = (np.asarray(a, dtype=float) for a in (load, journal_d, bearing_width,
                                                                                  clearance, viscosity, speed))
    load, radius, length, c, mu, omega = np.broadcast_arrays(load, d / 2, length, clearance / 2, mu, omega)
    return registry.tier(method).steady(load, journal_radius=radius, bearing_width=length, radial_clearance=c,
                                        viscosity=mu, speed=omega)


def short_film(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """The ``short`` tier's :class:`Film` (Ocvirk's closed form) on broadcast inputs, radial, SI."""
    kw = dict(journal_radius=journal_radius, bearing_width=bearing_width, radial_clearance=radial_clearance,
              viscosity=viscosity, speed=speed)
    eps, phi = tiers.short(load, **kw)
    h_min, torque, flow = tiers.film_quantities(eps, phi, load, **kw)
    return Film(eps, h_min, phi, torque, flow, eps <= ECCENTRICITY_LIMIT)


def finite_film(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """The ``finite`` tier's :class:`Film` (Ocvirk's form, corrected from the table) on broadcast inputs, radial, SI."""
    kw = dict(journal_radius=journal_radius, bearing_width=bearing_width, radial_clearance=radial_clearance,
              viscosity=viscosity, speed=speed)
    eps, phi, inside = _finite(load, **kw)
    h_min, torque, flow = tiers.film_quantities(eps, phi, load, **kw)
    return Film(eps, h_min, phi, torque, flow, inside & (eps <= ECCENTRICITY_LIMIT))


def reynolds_film(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """The ``reynolds`` tier's :class:`Film` (:func:`reynolds_films` without the peak pressure)."""
    return reynolds_films(load, journal_radius=journal_radius, bearing_width=bearing_width,
                          radial_clearance=radial_clearance, viscosity=viscosity, speed=speed)[0]


def reynolds_films(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """The Reynolds tier's steady film under each load, and the peak of its pressure field.

    One Reynolds solve per load (:func:`stackup.film.reynolds.eccentricity_for_load`); inputs broadcast
    together, radial, SI. Zero load gives the concentric journal (its attitude the limit pi/2); a load the
    film carries only beyond :data:`~stackup.film.journal.ECCENTRICITY_LIMIT` the short-bearing load curve
    scaled to the Reynolds load there (:func:`_beyond_reynolds`), ``valid`` False, with the pressure field at
    the limit (the film is held there, as the cycle tiers hold it).

    Returns
    -------
    (Film, numpy.ndarray)
        The film and the peak film pressure [Pa], shaped as the broadcast inputs.
    """
    load, journal_radius, bearing_width, radial_clearance, viscosity, speed = np.broadcast_arrays(
        load, journal_radius, bearing_width, radial_clearance, viscosity, speed)
    out = {k: np.empty(load.shape) for k in ("eps", "phi", "torque", "flow", "peak")}
    valid = np.ones(load.shape, bool)
    for idx in np.ndindex(load.shape):
        r, l, c, mu, w = (float(a[idx]) for a in (journal_radius, bearing_width, radial_clearance, viscosity, speed))
        unit = mu * w * r**4 / c**2  # load of a unit dimensionless force [N]
        if load[idx] == 0:
            field = reynolds.solve_field(0.0, l / r)
            field.attitude = np.pi / 2  # the concentric film carries no load; its attitude is the limit pi/2
        elif load[idx] / unit > _reynolds_edge(l / r).force:
            eps, phi, torque, flow = _beyond_reynolds(float(load[idx]), r, l, c, mu, w)
            out["eps"][idx], out["phi"][idx], out["torque"][idx], out["flow"][idx] = eps, phi, torque, flow
            out["peak"][idx] = mu * w * r**2 / c**2 * _reynolds_edge(l / r).pressure.max()
            valid[idx] = False
            continue
        else:
            field = reynolds.eccentricity_for_load(float(load[idx]) / unit, l / r)
        friction, flow = reynolds.friction_and_flow(field)
        out["eps"][idx] = field.eps
        out["phi"][idx] = field.attitude
        out["torque"][idx] = mu * w * r**4 / c * friction
        out["flow"][idx] = w * r**2 * c / 12 * flow
        out["peak"][idx] = mu * w * r**2 / c**2 * field.pressure.max()
    film = Film(out["eps"], radial_clearance * (1 - out["eps"]), out["phi"], out["torque"], out["flow"], valid)
    return film, out["peak"]


@lru_cache(maxsize=64)
def _reynolds_edge(length_over_radius):
    """The Reynolds field at :data:`~stackup.film.journal.ECCENTRICITY_LIMIT` for an L/R."""
    return reynolds.solve_field(ECCENTRICITY_LIMIT, length_over_radius)


def _beyond_reynolds(load, radius, length, c, mu, speed):
    """Above the Reynolds tier's range: the short-bearing load curve scaled to the Reynolds load at its edge."""
    edge = _reynolds_edge(length / radius)
    short_edge = (length / radius) ** 3 / 4 * tiers.short_load_function(ECCENTRICITY_LIMIT)
    scale = mu * speed * radius * length**3 / (4 * c**2) * edge.force / short_edge
    eps = float(tiers.invert_monotone(tiers.short_load_function, np.array(load / scale)))
    kw = dict(journal_radius=radius, bearing_width=length, radial_clearance=c, viscosity=mu, speed=speed)
    _, torque, flow = tiers.film_quantities(eps, edge.attitude, load, **kw)
    return eps, edge.attitude, float(torque), float(flow)


@validated(load=Finite())
def journal_position(load, *, eccentricity, attitude_angle, clearance):
    """Journal centre relative to the bearing centre [m] under a steady load.

    Parameters
    ----------
    load : array_like (..., 2)
        Load on the bearing (force of the journal on the bearing) [N], the frame of
        :func:`stackup.film.orbit.orbit`.
    eccentricity, attitude_angle : array_like (...)
        Of the film under that load (:class:`Film`) [-], [rad].
    clearance : array_like (...)
        Diametral clearance [m].

    Returns
    -------
    numpy.ndarray (..., 2)
        The journal centre lies along the load turned by the attitude angle in
        the sense of rotation (positive angles), as the mobility tier finds it.
    """
    f = np.asarray(load, dtype=float)
    direction = np.arctan2(f[..., 1], f[..., 0]) + np.asarray(attitude_angle)
    e = np.asarray(eccentricity) * np.asarray(clearance) / 2
    return np.stack([e * np.cos(direction), e * np.sin(direction)], axis=-1)


#: Steady tiers from cheapest to dearest (the order they are registered in).
BY_COST = METHODS
#: Grid on which :func:`tier_errors` measures the cheaper tiers against the reference: it spans the finite
#: tier's whole table (L/D 0.1-2, eccentricity 0.02 up to the limit, and below its first node) and lies between the
#: table's nodes, where its interpolation error is largest.
ERROR_GRID = {"length_over_diameter": (0.12, 0.175, 0.225, 0.35, 0.55, 0.85, 1.4, 1.8),
              "eccentricity": (0.01, 0.03, 0.33, 0.55, 0.77, 0.89, 0.905, 0.935, 0.975, 0.9875, 0.99375)}


@lru_cache(maxsize=1)
def tier_errors():
    """Largest relative h_min error of each steady tier against the Reynolds tier over :data:`ERROR_GRID`.

    For each L/D and reference eccentricity, the load the Reynolds tier
    carries there is handed to each tier (R = 1, c = 1e-3, mu = omega = 1);
    the Reynolds tier is the reference (error 0).
    """
    cases = []
    for ld in ERROR_GRID["length_over_diameter"]:
        for eps in ERROR_GRID["eccentricity"]:
            field = reynolds.solve_field(eps, 2 * ld)
            cases.append((ld, field.force * 1e6, 1e-3 * (1 - eps)))  # load of unit viscosity and speed, h_min
    errors = {}
    for method in METHODS:
        worst = 0.0
        if registry.tier(method).steady is not reynolds_film:
            for ld, load, h_ref in cases:
                f = min_film_thickness(load, journal_d=2.0, bearing_width=2.0 * ld, clearance=2e-3, viscosity=1.0,
                                       speed=1.0, method=method)
                worst = max(worst, abs(float(f.h_min) / h_ref - 1))
        errors[method] = worst
    return errors


@validated(max_error=Positive(zero=True))
def cheapest_tier(max_error):
    """The cheapest steady tier whose h_min error against ``reynolds`` is at most ``max_error`` [-]."""
    max_error = float(max_error)
    errors = tier_errors()
    return next(m for m in BY_COST if errors[m] <= max_error)
