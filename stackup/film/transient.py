r"""Reference cycle tier: the transient Reynolds equation with mass-conserving cavitation, journal orbit integrated.

The film of a bearing of radius :math:`R`, length :math:`L`, radial clearance
:math:`c`, journal turning at :math:`\omega`, bearing fixed, journal centre
:math:`\mathbf x(t)` and tilt :math:`\boldsymbol\gamma(t)` (slope of the journal axis
relative to the bearing axis):

.. math:: h(\Theta, z, t) = c - (\mathbf x + z\boldsymbol\gamma)\cdot\mathbf n(\Theta), \qquad
          z \in [-L/2, L/2]

Elrod-Adams form of the Jakobsson-Floberg-Olsson (JFO) mass-conserving
cavitation, dimensionless (:math:`\bar h = h/c`, :math:`\bar z = z/R`, :math:`\tau = \omega t`,
:math:`\bar p = p c^2/(\mu\omega R^2)`, fill fraction :math:`g`):

.. math:: \bar\nabla\cdot(\bar h^3\bar\nabla\bar p) = 6\,\partial_\Theta(g\bar h) + 12\,\partial_\tau(g\bar h),
          \qquad \bar p \ge 0,\; g \le 1,\; \bar p\,(1 - g) = 0

Finite volumes on a uniform grid (Couette flux with the fill upwind and the film at the face), BDF2 in time (backward
Euler for the first step), :math:`\bar p = 0, g = 1` at both ends and a feed hole held
at the supply pressure (full of oil), solved per step by Gauss-Seidel with the
Ausas et al. switching between pressure and fill. The journal is massless:
at each step its centre :math:`\mathbf x_{n+1}` is found by a Broyden iteration so that
the film force equals the load (each residual one field solve, warm-started);
the tilt is imposed. Cycles are repeated from the ``mobility-finite`` orbit's
position until the orbit closes. With ``cavitation="reynolds"`` the fill stays 1
and :math:`\bar p \ge 0` is a projection (Swift-Stieber, not mass-conserving): the
finite-length counterpart of the mobility tiers' film.

Outputs per angle: mid-plane and edge minimum films, the peak of the pressure
field, friction torque on the journal
:math:`T = \frac{\mu\omega R^4}{c}\iint (g/\bar h + \tfrac12\bar h\,\partial_\Theta\bar p)\,d\Theta\,d\bar z`
(shear of the oil present, plus the pressure term) and the side flow
:math:`Q = \frac{\omega R^2 c}{12}\sum_{ends}\int\bar h^3|\partial_{\bar z}\bar p|\,d\Theta`.

References
----------
.. [1] Elrod, H. G., "A cavitation algorithm", J. Lubr. Technol. 103 (1981) 350-354.
.. [2] Ausas, R. F., Jai, M., Buscaglia, G. C., "A mass-conserving algorithm for
   dynamical lubrication problems with cavitation", J. Tribol. 131 (2009) 031702.
.. [3] Booker, J. F., J. Basic Eng. 87 (1965) 537-546 (the massless journal's force balance).
.. [4] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), eq. 4 (film with skewed axes).
"""

from __future__ import annotations

import numpy as np

from .. import _validate as check
from .._kernels import mobility as _mobility
from .._kernels.reynolds import elrod_adams

CAVITATION = ("elrod-adams", "reynolds")
#: Grid: angles around the bearing and axial nodes over the width (ends included).
N_THETA = 180
N_Z = 21
RELAXATION = 1.7
#: Field solve: stop when a sweep changes p by less than this share of its peak (and the fill by less).
FIELD_TOLERANCE = 1e-9
MAX_SWEEPS = 20_000
#: Force balance: stop when the film force is within this share of the cycle's largest load.
FORCE_TOLERANCE = 1e-6
MAX_BROYDEN = 40
#: Periodic when the journal returns after a cycle to within this share of the thinnest film.
PERIODIC = 2e-3
#: Oil supply: hole on the block side (opposite the cap, Theta = pi), its width [rad] and share of the length.
FEED_ANGLE = np.pi
FEED_WIDTH = np.radians(6.0)
FEED_LENGTH_SHARE = 0.3


class _Film:
    """Grid and dimensionless film of one bearing."""

    def __init__(self, *, length_over_radius, clearance_over_radius, n_theta, n_z, feed_angle, feed_width,
                 feed_length_share, feed_pressure):
        self.theta = 2 * np.pi * np.arange(n_theta) / n_theta
        self.dtheta = 2 * np.pi / n_theta
        self.z = np.linspace(-length_over_radius / 2, length_over_radius / 2, n_z)
        self.dz = self.z[1] - self.z[0]
        self.n = np.stack([np.cos(self.theta), np.sin(self.theta)])  # (2, n_t)
        east = self.theta + 0.5 * self.dtheta
        self.n_east = np.stack([np.cos(east), np.sin(east)])
        self.z_north = self.z + 0.5 * self.dz
        self.tilt_scale = 1.0 / clearance_over_radius  # z is in R, h in c: z gamma / c = z_bar gamma R / c
        self.fixed = np.zeros((n_theta, n_z), bool)
        self.fixed[:, [0, -1]] = True
        self.p_fixed = np.zeros((n_theta, n_z))
        near = np.abs(np.angle(np.exp(1j * (self.theta - feed_angle)))) <= feed_width / 2 + 1e-12
        along = np.abs(self.z) <= feed_length_share * length_over_radius / 2 + 1e-12
        hole = near[:, None] & along[None, :]
        self.fixed |= hole
        self.p_fixed[hole] = feed_pressure
        self.weights = np.full(n_z, self.dz)
        self.weights[[0, -1]] = self.dz / 2

    def thickness(self, xi, gamma):
        """h at the nodes, h and h^3 at the east faces, h^3 at the north faces (centre xi [c], tilt gamma [rad])."""
        t = self.tilt_scale * gamma
        h = 1.0 - (xi @ self.n)[:, None] - (t @ self.n)[:, None] * self.z[None, :]
        h_e = 1.0 - (xi @ self.n_east)[:, None] - (t @ self.n_east)[:, None] * self.z[None, :]
        h_n = 1.0 - (xi @ self.n)[:, None] - (t @ self.n)[:, None] * self.z_north[None, :]
        return h, h_e, h_e**3, h_n**3

    def force(self, p):
        """Film force on the bearing (2,) per unit of mu omega R^4 / c^2."""
        return self.n @ (p @ self.weights) * self.dtheta


def transient_orbit(loads, crank_angle, *, radius, length, radial_clearance, viscosity, speed, tilt=None, cycles=8,
                    cavitation="elrod-adams", n_theta=N_THETA, n_z=N_Z, time_order=2, feed_pressure=0.0,
                    feed_angle=FEED_ANGLE, start=None):
    """Orbit of each bearing by the transient Reynolds tier (called by :func:`stackup.film.orbit.orbit`).

    Parameters as :func:`stackup.film.orbit.orbit` (arrays over the leading shape, SI), and
    cavitation : {"elrod-adams", "reynolds"}
    n_theta, n_z : int
        Grid around the bearing and over its width.
    time_order : {1, 2}
        Backward Euler or BDF2.
    feed_pressure : float
        Supply pressure at the feed hole [Pa] (gauge; 0 keeps it full at ambient pressure).
    feed_angle : float
        Angle of the feed hole from load axis 0 [rad].
    start : array_like (..., 2), optional
        Journal centre at the first angle [m]; default from the ``mobility-finite`` tier
        (``mobility`` where the table does not cover the L/D).

    Returns
    -------
    stackup.film.orbit.Orbit
    """
    from .orbit import ECCENTRICITY_LIMIT, Orbit, orbit

    check.one_of("cavitation", cavitation, CAVITATION)
    if time_order not in (1, 2):
        raise ValueError(f"time_order: {time_order!r} is not one of 1, 2")
    lead = loads.shape[:-2]
    n = crank_angle.size
    tau = np.radians(np.append(crank_angle, crank_angle[0] + 720.0) - crank_angle[0])
    if tilt is None:
        tilt = np.zeros(loads.shape)
    if start is None:
        try:
            seed = orbit(loads, crank_angle, diameter=2 * radius, length=length, clearance=2 * radial_clearance,
                         viscosity=viscosity, speed=speed, method="mobility-finite", tilt=tilt)
        except (ValueError, FileNotFoundError):
            seed = orbit(loads, crank_angle, diameter=2 * radius, length=length, clearance=2 * radial_clearance,
                         viscosity=viscosity, speed=speed, method="mobility", tilt=tilt)
        start = seed.position[..., 0, :]
    start = np.broadcast_to(start, (*lead, 2))
    out = {k: np.empty((*lead, n)) for k in ("peak", "torque", "flow")}
    position = np.empty((*lead, n, 2))
    status = np.empty(lead, np.int8)
    used = np.empty(lead)
    for idx in np.ndindex(lead):
        r, l, c, mu, w = (float(a[idx]) for a in (radius, length, radial_clearance, viscosity, speed))
        unit_force = mu * w * r**4 / c**2
        unit_pressure = mu * w * r**2 / c**2
        film = _Film(length_over_radius=l / r, clearance_over_radius=c / r, n_theta=n_theta, n_z=n_z,
                     feed_angle=feed_angle, feed_width=FEED_WIDTH, feed_length_share=FEED_LENGTH_SHARE,
                     feed_pressure=feed_pressure / unit_pressure)
        result = _bearing_orbit(film, loads[idx] / unit_force, tau, tilt[idx], start[idx] / c, cycles,
                                cavitation == "elrod-adams", time_order, ECCENTRICITY_LIMIT, l / r)
        xi, peak, friction, flow, status[idx], used[idx] = result
        position[idx] = xi * c
        out["peak"][idx] = peak * unit_pressure
        out["torque"][idx] = friction * mu * w * r**4 / c
        out["flow"][idx] = flow * w * r**2 * c / 12
    ecc = np.linalg.norm(position, axis=-1) / radial_clearance[..., None]
    h_min = radial_clearance[..., None] * (1 - ecc)
    half = 0.5 * length[..., None, None] * tilt
    reach = np.maximum(np.linalg.norm(position + half, axis=-1), np.linalg.norm(position - half, axis=-1))
    h_edge = np.minimum(h_min, radial_clearance[..., None] - reach)
    return Orbit(h_min, h_edge, ecc, position, out["peak"], out["torque"], out["flow"], status, used,
                 np.asarray(speed, dtype=float))


def _bearing_orbit(film, w, tau, tilt, xi0, cycles, mass_conserving, time_order, limit, length_over_radius):
    """Periodic orbit of one bearing; dimensionless loads w (n, 2). Returns per-angle arrays, status, cycles."""
    n = w.shape[0]
    shape = (film.theta.size, film.z.size)
    p = np.zeros(shape)
    fill = np.ones(shape)
    p[film.fixed] = film.p_fixed[film.fixed]
    scale = np.abs(w).max() + 1e-300
    xi = np.array(xi0, dtype=float)
    h = film.thickness(xi, tilt[0])[0]
    content = [fill * h]  # film content g h of the latest steps
    xi_hist = [xi.copy()]
    dtau_prev = None
    jac = None
    record = np.empty((n, 2))
    peak = np.empty(n)
    friction = np.empty(n)
    flow = np.empty(n)
    thinnest_last = None
    for cycle in range(1, cycles + 1):
        start = xi.copy()
        thinnest = 0.0
        collapsed = False
        for k in range(n):
            record[k] = xi
            peak[k], friction[k], flow[k] = _outputs(film, p, fill, h)
            thinnest = max(thinnest, float(np.hypot(*xi)))
            kn = (k + 1) % n
            dtau = tau[k + 1] - tau[k]
            if time_order == 2 and dtau_prev is not None and len(content) == 2:
                r = dtau / dtau_prev
                a0, a1, a2 = (1 + 2 * r) / (1 + r), 1 + r, r * r / (1 + r)
                history = 12 * (a1 * content[-1] - a2 * content[-2]) / dtau
                predicted = xi + (xi - xi_hist[-2]) * r
            else:
                a0 = 1.0
                history = 12 * content[-1] / dtau
                predicted = xi.copy()
            c_time = 12 * a0 / dtau
            gamma = tilt[kn]
            target = w[kn]

            def residual(x):
                hh, he, h3e, h3n = film.thickness(x, gamma)
                sweeps = elrod_adams(hh, he, h3e, h3n, history, c_time, p, fill, film.fixed, film.dtheta, film.dz,
                                     RELAXATION, FIELD_TOLERANCE, MAX_SWEEPS, mass_conserving)
                if sweeps < 0:
                    raise RuntimeError("field solve did not converge")
                return film.force(p) - target, hh

            if jac is None:
                jac = _short_jacobian(predicted, target, length_over_radius, a0 / dtau)
            x = _inside(predicted, limit)
            try:
                f, hh = residual(x)
                for _ in range(MAX_BROYDEN):
                    if np.linalg.norm(f) <= FORCE_TOLERANCE * scale:
                        break
                    step = -np.linalg.solve(jac, f)
                    x_new = _inside(x + step, limit)
                    step = x_new - x
                    f_new, hh = residual(x_new)
                    # Broyden's good update of the Jacobian (carried on to the next step)
                    jac = jac + np.outer(f_new - f - jac @ step, step) / max(step @ step, 1e-300)
                    x, f = x_new, f_new
                else:
                    return record, peak, friction, flow, 3, cycle
            except (RuntimeError, np.linalg.LinAlgError):
                return record, peak, friction, flow, 3, cycle
            if np.hypot(*x) >= limit * (1 - 1e-12):
                collapsed = True
            xi = x
            h = hh
            content = [content[-1], fill * h]
            xi_hist = [xi_hist[-1], xi.copy()]
            dtau_prev = dtau
        film_left = 1 - (limit if collapsed else thinnest)
        closure = float(np.hypot(*(xi - start)))
        if cycle > 1 and closure <= PERIODIC * film_left:
            return record, peak, friction, flow, (2 if collapsed else 0), cycle
        thinnest_last = thinnest
    return record, peak, friction, flow, (2 if collapsed else 1), cycles


def _inside(x, limit):
    e = float(np.hypot(*x))
    return x * (limit / e) if e > limit else x


def _short_jacobian(xi, load, length_over_radius, rate):
    """d force / d xi_{n+1} of the short bearing (a starting guess for Broyden): L^3 G (rate I - K/2)."""
    eps = min(float(np.hypot(*xi)), 0.99)
    e_r = xi / eps if eps > 0 else np.array([1.0, 0.0])
    e_t = np.array([-e_r[1], e_r[0]])
    w_r, w_t = load @ e_r, load @ e_t
    _, alpha, _ = _mobility.squeeze_velocity(eps, w_r, w_t, -0.5 * np.pi, np.zeros((2, 2, 3)), np.array([0.0, 1.0]),
                                             False)
    rr, rt, tt = _mobility.short_matrix(eps, alpha)
    frame = np.stack([e_r, e_t], axis=1)
    g = frame @ np.array([[rr, rt], [rt, tt]]) @ frame.T
    turn = np.array([[0.0, -1.0], [1.0, 0.0]])
    return length_over_radius**3 * g @ (rate * np.eye(2) - 0.5 * turn)


def _outputs(film, p, fill, h):
    """Peak pressure, friction integral and side-flow integral of a field (dimensionless)."""
    dp = (np.roll(p, -1, axis=0) - np.roll(p, 1, axis=0)) / (2 * film.dtheta)
    shear = fill / h + 0.5 * h * dp
    friction = float((shear @ film.weights).sum() * film.dtheta)
    dz = film.dz
    ends = (h[:, 0] ** 3 * (4 * p[:, 1] - p[:, 2]) + h[:, -1] ** 3 * (4 * p[:, -2] - p[:, -3])) / (2 * dz)
    flow = float(ends.sum() * film.dtheta)
    return float(p.max()), friction, flow
