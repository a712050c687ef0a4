"""The mobility tiers' orbit (Booker's mobility method), compiled: ``"mobility"`` and ``"mobility-finite"``.

The equations are stated with the tiers in :mod:`stackup.film.orbit`; the kernels are
:mod:`stackup._kernels.mobility`. :func:`mobility_tier_orbit` turns this tier's orbit into an
:class:`~stackup.film.journal.Orbit` (eccentricity, films, tilt); the mass-conserving tiers start from it.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._kernels import mobility as _kernel
from .journal import ECCENTRICITY_LIMIT, mobility_table, outside_table, short_table, table_covers, vector_length
from .tilt import tilted_orbit

#: The orbit is periodic when the journal returns after a cycle to within this share of the thinnest film.
PERIODIC = 1e-3


class MobilityOrbit(NamedTuple):
    """A mobility tier's orbit; leading shape (...) of the loads, angles last."""

    position: np.ndarray  # (..., angles, 2) journal centre [m]
    p_max: np.ndarray  # (..., angles) peak film pressure [Pa]
    friction_torque: np.ndarray  # (..., angles) [N m]
    side_flow: np.ndarray  # (..., angles) [m^3/s]
    status: np.ndarray  # int8 (...): index into stackup.film.journal.STATUS
    cycles: np.ndarray  # (...) cycles integrated
    squeeze_velocity: np.ndarray  # (..., angles, 2) [m/s]


def mobility_orbit(loads, crank_angle, *, finite, cycles, start, journal_radius, bearing_width, radial_clearance,
                   viscosity, speed):
    """Periodic orbit of bearings by the mobility method, from ``start`` (..., 2) [m] or the bearing centre (None).

    ``loads`` (..., angles, 2) [N], ``crank_angle`` (angles,) [deg] as :func:`stackup.film.orbit.orbit` takes
    them; geometry (...) broadcast to the loads' leading shape, SI; ``finite``: the ``mobility-finite``
    tier's correction (its table must cover every bearing's L/D: a ValueError otherwise, the tier cannot
    compute those bearings). Returns a :class:`MobilityOrbit`.
    """
    lead = loads.shape[:-2]
    n = crank_angle.size
    radius, length, c, mu, w = journal_radius, bearing_width, radial_clearance, viscosity, speed
    scale = mu * w * radius * length**3 / c**2  # load of unit dimensionless force [N]
    w_bar = np.ascontiguousarray((loads / scale[..., None, None]).reshape(-1, n, 2))
    tau = np.radians(np.append(crank_angle, crank_angle[0] + 720.0) - crank_angle[0])
    ld = np.ascontiguousarray((length / (2 * radius)).reshape(-1), dtype=float)
    if finite and not table_covers(ld):
        # the tier's own range, not an input check: whoever calls it learns that it cannot compute these bearings
        raise outside_table("bearing_width", ld, "the mobility-finite table") from None
    ld_nodes, stretched, tables = mobility_table() if finite else short_table()
    m = w_bar.shape[0]
    xi = np.empty((m, n, 2))
    v = np.empty((m, n, 2))
    peak = np.empty((m, n))
    status = np.empty(m, np.int8)
    used = np.empty(m)
    warm = start is not None
    xi0 = np.ascontiguousarray((start / c[..., None]).reshape(-1, 2) if warm else np.zeros((m, 2)), dtype=float)
    _kernel.orbits(w_bar, tau, xi0, warm, ld, _kernel.Integration(ECCENTRICITY_LIMIT, PERIODIC, cycles),
                   _kernel.Correction(tables, ld_nodes, stretched, finite), (xi, v, peak, status, used))
    xi = xi.reshape(*lead, n, 2)
    v = v.reshape(*lead, n, 2)
    position = xi * c[..., None, None]
    squeeze = v * (c * w)[..., None, None]
    ecc = vector_length(xi)
    p_max = 1.5 * (mu * w * (length / c) ** 2)[..., None] * peak.reshape(*lead, n)
    torque = (2 * np.pi * mu * w * radius**3 * length / c)[..., None] / np.sqrt(1 - ecc**2) \
        + 0.5 * (position[..., 1] * loads[..., 0] - position[..., 0] * loads[..., 1])
    flow = (2 * radius * length * c * w)[..., None] * vector_length(v)
    return MobilityOrbit(position, p_max, torque, flow, status.reshape(lead), used.reshape(lead), squeeze)


def mobility_tier_orbit(loads, crank_angle, *, finite, journal_radius, bearing_width, radial_clearance, viscosity,
                        speed, tilt, tilt_compliance, cycles, start):
    """The :class:`~stackup.film.journal.Orbit` of a mobility tier (a tier's function, :mod:`stackup.film.registry`).

    :func:`mobility_orbit` (``finite``: the ``mobility-finite`` tier's correction, also in the tilt's moment),
    the tilt marched over the cycle on it (:func:`~stackup.film.tilt.tilted_orbit`).
    """
    geometry = dict(journal_radius=journal_radius, bearing_width=bearing_width, radial_clearance=radial_clearance,
                    viscosity=viscosity, speed=speed)
    position, p_max, torque, flow, status, used, squeeze = mobility_orbit(loads, crank_angle, finite=finite,
                                                                          cycles=cycles, start=start, **geometry)
    return tilted_orbit(position, squeeze, p_max, torque, flow, status, used, tilt, tilt_compliance, finite=finite,
                        crank_angle=crank_angle, **geometry)
