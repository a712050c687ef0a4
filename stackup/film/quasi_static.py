r"""The quasi-static cycle tiers ``"short"``, ``"finite"``, ``"reynolds"``: each crank angle a steady load.

The steady tier's film (:mod:`stackup.film.steady`) at every crank angle, no squeeze film; the journal
sits at the attitude angle ahead of the load, in the turning direction. The peak pressure of the
short and finite tiers is the mobility tiers' at the steady squeeze
(:math:`\mathbf v_s = \tfrac12\mathbf k\times\xi`, the finite one corrected by the same table), the
Reynolds tier's the peak of its own field. The equations and the tilt are stated with the tiers in
:mod:`stackup.film.orbit`.
"""

from __future__ import annotations

import numpy as np

from .._kernels import mobility as _kernel
from .journal import ECCENTRICITY_LIMIT, mobility_table, short_table
from .steady import finite_film, short_film
from .tilt import tilted_orbit


def quasi_static_orbit(loads, crank_angle, *, films, finite, journal_radius, bearing_width, radial_clearance,
                       viscosity, speed, tilt, tilt_compliance, cycles=None, start=None):
    """The :class:`~stackup.film.journal.Orbit` of a quasi-static tier (its function in :mod:`stackup.film.registry`).

    ``films(load, **geometry)`` -> (:class:`~stackup.film.steady.Film`, peak pressure [Pa]): the tier's steady
    film at each angle (:func:`short_films`, :func:`finite_films`, :func:`~stackup.film.steady.reynolds_films`);
    ``finite``: the tilt's moment with the finite-length correction. ``cycles`` and ``start`` are not read (no
    orbit to integrate: status periodic, 0 cycles). The tilt is held at each angle (:func:`tilted_orbit`).
    """
    geometry = dict(journal_radius=journal_radius, bearing_width=bearing_width, radial_clearance=radial_clearance,
                    viscosity=viscosity, speed=speed)
    position, p_max, torque, flow = _steady_at_each_angle(loads, films, **geometry)
    lead = loads.shape[:-2]
    status, used = np.zeros(lead, np.int8), np.zeros(lead, int)
    squeeze = -0.5 * speed[..., None, None] * np.stack([-position[..., 1], position[..., 0]], axis=-1)
    return tilted_orbit(position, squeeze, p_max, torque, flow, status, used, tilt, tilt_compliance, finite=finite,
                        crank_angle=None, **geometry)


def _steady_at_each_angle(loads, films, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """Journal centre, peak pressure, friction torque and side flow of the steady film at each angle."""
    c, mu, w = (a[..., None] for a in (radial_clearance, viscosity, speed))
    r, l = journal_radius[..., None], bearing_width[..., None]
    magnitude = np.linalg.norm(loads, axis=-1)
    # the steady tier under a micronewton where the load is zero (that journal is put at the centre below)
    load, r, l, c, mu, w = np.broadcast_arrays(np.maximum(magnitude, 1e-6), r, l, c, mu, w)
    film, field_peak = films(load, journal_radius=r, bearing_width=l, radial_clearance=c, viscosity=mu, speed=w)
    direction = np.arctan2(loads[..., 1], loads[..., 0]) + film.attitude_angle
    ecc = np.where(magnitude > 0, film.eccentricity, 0.0)
    position = (c * ecc)[..., None] * np.stack([np.cos(direction), np.sin(direction)], axis=-1)
    return position, field_peak, film.friction_torque, film.side_flow


def short_films(load, **geometry):
    """The ``short`` tier's steady film and its peak pressure (short bearing) [Pa] on broadcast inputs."""
    film = short_film(load, **geometry)
    return film, _steady_peak(film.eccentricity, finite=False, **geometry)


def finite_films(load, **geometry):
    """The ``finite`` tier's steady film and its peak pressure (finite-corrected) [Pa] on broadcast inputs."""
    film = finite_film(load, **geometry)
    return film, _steady_peak(film.eccentricity, finite=True, **geometry)


def _steady_peak(eccentricity, *, finite, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """Mid-plane peak pressure [Pa] of the steady film, as the mobility tiers find it at the steady squeeze."""
    r, l, c = journal_radius, bearing_width, radial_clearance
    eps = np.minimum(eccentricity, ECCENTRICITY_LIMIT)
    ld_nodes, stretched, tables = mobility_table() if finite else short_table()
    flat_eps = np.ascontiguousarray(eps, dtype=float).ravel()
    factor = np.empty(flat_eps.size)
    ld = np.ascontiguousarray(np.broadcast_to(l / (2 * r), eps.shape), dtype=float).ravel()
    _kernel.steady_peak_factors(flat_eps, ld, _kernel.Correction(tables, ld_nodes, stretched, finite), factor)
    # v_s = (1/2) k x xi: |v| = eps/2
    return 1.5 * viscosity * speed * (l / c) ** 2 * 0.5 * eps * factor.reshape(eps.shape)
