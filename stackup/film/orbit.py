r"""Dynamically loaded bearings over the engine cycle: the journal orbit and its minimum film.

Tiers of :func:`orbit`:

``"quasi-static"``
    Each crank angle as a steady load on a steady tier (``steady_method``):
    no squeeze film; cheap.
``"mobility"``
    The journal centre moves so that the film force balances the load at
    every instant (massless journal, Booker's mobility method). The film
    force comes from the short-bearing Reynolds equation with journal
    rotation and squeeze, with Gümbel (π-film) cavitation, written in the
    engine-fixed frame for a journal centre :math:`\mathbf x` moving at
    :math:`\dot{\mathbf x}`, :math:`h(\Theta) = c - \mathbf x\cdot\mathbf n(\Theta)`:

    .. math:: \frac{\partial}{\partial z}\left(h^3\frac{\partial p}{\partial z}\right)
              = 6\mu\omega\,\frac{\partial h}{\partial\Theta} + 12\mu\,\frac{\partial h}{\partial t}
              \equiv Q(\Theta), \qquad
              \int p\,dz = \frac{L^3\max(0, -Q)}{12\,h^3}

    and the force on the bearing :math:`\mathbf F = \int\!\!\int p\,\mathbf n\,R\,d\Theta\,dz`.
    :math:`\mathbf F` is piecewise linear in :math:`\dot{\mathbf x}` with a
    positive-definite Jacobian, so Newton finds the velocity (the mobility
    inverse) in a few steps; the orbit is integrated with classical RK4 over
    the cycle and repeated until it is periodic.

References
----------
.. [1] Booker, J. F., "Dynamically loaded journal bearings: mobility method of
   solution", J. Basic Eng. 87 (1965) 537-546.
.. [2] Booker, J. F., "Squeeze films and bearing dynamics", CRC Handbook of
   Lubrication Vol. II, 1983, pp. 121-137.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate as check

METHODS = ("quasi-static", "mobility")
#: Quadrature points around the bearing for the short-bearing film force.
N_THETA = 360
#: The orbit is periodic when the cycle-minimum film changes by less than this share.
PERIODIC = 1e-3
#: Largest eccentricity the integrator lets the journal reach; beyond it the film is marked as collapsed.
ECCENTRICITY_LIMIT = 0.995


@dataclass(frozen=True)
class Orbit:
    """Film over a cycle.

    Attributes
    ----------
    h_min : numpy.ndarray (..., angles)
        Minimum film thickness at each crank angle [m].
    eccentricity : numpy.ndarray (..., angles)
        Eccentricity ratio [-].
    position : numpy.ndarray (..., angles, 2) or None
        Journal centre relative to the bearing centre [m] (``"mobility"``).
    converged : numpy.ndarray of bool (...)
        The orbit became periodic (``"mobility"``), or every angle solved.
    cycles : int
        Cycles integrated (``"mobility"``); 0 for ``"quasi-static"``.
    """

    h_min: np.ndarray
    eccentricity: np.ndarray
    position: np.ndarray | None
    converged: np.ndarray
    cycles: int


class _ShortFilm:
    """Film force of a short bearing with π-film cavitation, in the engine-fixed frame."""

    def __init__(self, *, radius, length, radial_clearance, viscosity, speed):
        self.r, self.l, self.c, self.mu, self.w = radius, length, radial_clearance, viscosity, speed
        theta = 2 * np.pi * (np.arange(N_THETA) + 0.5) / N_THETA
        self.n = np.stack([np.cos(theta), np.sin(theta)], axis=-1)  # (N, 2)
        self.t = np.stack([-np.sin(theta), np.cos(theta)], axis=-1)
        self.dtheta = 2 * np.pi / N_THETA

    def force(self, x, v):
        """Force on the bearing (2,) [N] and d force / d velocity (2, 2) for position x and velocity v."""
        h = self.c - self.n @ x
        dh_dtheta = -(self.t @ x)
        q = 6 * self.mu * self.w * dh_dtheta - 12 * self.mu * (self.n @ v)
        active = q < 0
        weight = self.l**3 / (12 * h**3) * self.r * self.dtheta
        f = ((-q * active * weight)[:, None] * self.n).sum(axis=0)
        jac = 12 * self.mu * np.einsum("k,ki,kj->ij", active * weight, self.n, self.n)
        return f, jac

    def velocity(self, x, load, v0):
        """Journal centre velocity [m/s] at which the film carries ``load`` [N] (Newton)."""
        v = v0.copy()
        scale = max(np.linalg.norm(load), 1e-9)
        for _ in range(60):
            f, jac = self.force(x, v)
            r = f - load
            if np.linalg.norm(r) <= 1e-10 * scale:
                return v
            jac = jac + np.eye(2) * 1e-12 * max(np.trace(jac), 1e-30)
            step = np.linalg.solve(jac, -r)
            t = 1.0
            while t > 1e-6:
                if np.linalg.norm(self.force(x, v + t * step)[0] - load) < np.linalg.norm(r):
                    break
                t *= 0.5
            v = v + t * step
        return v


def _mobility(loads, crank_angle, film, cycles):
    """Integrate one bearing's orbit over repeated cycles; loads (angles, 2) on the bearing."""
    n = len(crank_angle)
    dt = np.radians(np.diff(np.append(crank_angle, crank_angle[0] + 720.0))) / film.w
    limit = ECCENTRICITY_LIMIT * film.c
    x = np.zeros(2)
    v = np.zeros(2)
    previous = None
    positions = np.empty((n, 2))
    collapsed = False
    for cycle in range(1, cycles + 1):
        for k in range(n):
            positions[k] = x
            load0 = loads[k]
            load1 = loads[(k + 1) % n]
            mid = 0.5 * (load0 + load1)
            # classical RK4 on dx/dt = velocity(x, load(t))
            k1 = film.velocity(x, load0, v)
            k2 = film.velocity(x + 0.5 * dt[k] * k1, mid, k1)
            k3 = film.velocity(x + 0.5 * dt[k] * k2, mid, k2)
            k4 = film.velocity(x + dt[k] * k3, load1, k3)
            x = x + dt[k] / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            v = k4
            e = np.linalg.norm(x)
            if e > limit:
                x *= limit / e
                collapsed = True
        h_min = film.c - np.linalg.norm(positions, axis=1)
        if previous is not None and abs(h_min.min() - previous) <= PERIODIC * previous:
            return positions, not collapsed, cycle
        previous = h_min.min()
    return positions, False, cycles


def orbit(load_history, crank_angle, *, diameter, length, clearance, viscosity, speed, method="mobility",
          steady_method="finite", cycles=12):
    """Minimum oil film over the engine cycle of a dynamically loaded bearing.

    Parameters
    ----------
    load_history : array_like (..., angles, 2)
        Load on the bearing over one cycle [N] (force of the journal on the
        bearing, engine-fixed frame).
    crank_angle : array_like (angles,)
        Crank angles [deg], increasing, covering one cycle (720 deg).
    diameter, length, clearance : float or array_like (...)
        Journal diameter, bearing length, diametral clearance [m].
    viscosity : float or array_like (...)
        Effective oil viscosity [Pa s].
    speed : float
        Crankshaft angular speed [rad/s].
    method : {"quasi-static", "mobility"}
    steady_method : str
        Steady tier of ``"quasi-static"`` (see :func:`stackup.film.min_film_thickness`).
    cycles : int
        Most cycles ``"mobility"`` integrates to reach a periodic orbit.

    Returns
    -------
    Orbit
    """
    from . import min_film_thickness

    check.one_of("method", method, METHODS)
    loads = check.finite("load_history", load_history)
    angle = check.finite("crank_angle", crank_angle)
    if loads.ndim < 2 or loads.shape[-1] != 2 or loads.shape[-2] != angle.size:
        raise ValueError(f"load_history: shape {loads.shape} is not valid; expected (..., {angle.size}, 2)")
    if np.any(np.diff(angle) <= 0) or angle[-1] - angle[0] >= 720.0:
        raise ValueError("crank_angle: must increase and span less than 720 deg")
    lead = loads.shape[:-2]
    radius = np.broadcast_to(check.positive("diameter", diameter) / 2, lead)
    length = np.broadcast_to(check.positive("length", length), lead)
    c = np.broadcast_to(check.positive("clearance", clearance) / 2, lead)
    mu = np.broadcast_to(check.positive("viscosity", viscosity), lead)
    omega = float(check.positive("speed", speed))
    magnitude = np.linalg.norm(loads, axis=-1)

    if method == "quasi-static":
        film = min_film_thickness(np.maximum(magnitude, 1e-6), diameter=2 * radius[..., None], length=length[..., None],
                                  clearance=2 * c[..., None], viscosity=mu[..., None], speed=omega, method=steady_method)
        return Orbit(film.h_min, film.eccentricity, None, np.ones(loads.shape[:-2], bool), 0)

    h_min = np.empty(loads.shape[:-1])
    position = np.empty(loads.shape)
    converged = np.empty(loads.shape[:-2], bool)
    used = 0
    for idx in np.ndindex(loads.shape[:-2]):
        film = _ShortFilm(radius=float(radius[idx]), length=float(length[idx]), radial_clearance=float(c[idx]),
                          viscosity=float(mu[idx]), speed=omega)
        pos, ok, n_cycles = _mobility(loads[idx], angle, film, cycles)
        position[idx] = pos
        h_min[idx] = c[idx] - np.linalg.norm(pos, axis=-1)
        converged[idx] = ok
        used = max(used, n_cycles)
    return Orbit(h_min, 1 - h_min / c[..., None], position, converged, used)
