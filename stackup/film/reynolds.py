r"""Reference film tier: the finite-length Reynolds equation with Swift-Stieber cavitation.

Dimensionless on the unwrapped film, :math:`\theta` from the thickest film,
:math:`\bar h = 1 + \varepsilon\cos\theta`, :math:`\bar z = z/R \in [0, L/R]`,
:math:`\bar p = p\,c^2/(\mu\omega R^2)`:

.. math:: \frac{\partial}{\partial\theta}\left(\bar h^3\frac{\partial\bar p}{\partial\theta}\right)
          + \frac{\partial}{\partial\bar z}\left(\bar h^3\frac{\partial\bar p}{\partial\bar z}\right)
          = 6\frac{\partial\bar h}{\partial\theta}, \qquad \bar p \ge 0

with ambient pressure at both ends and at the oil inlet, the thickest film
(:math:`\theta = 0`), as Raimondi and Boyd set it; periodic in :math:`\theta`. The
Swift-Stieber (Reynolds) condition is the complementarity :math:`\bar p \ge 0`,
enforced by projected successive over-relaxation (Christopherson's method).
Conservative finite differences (film cubed at mid-nodes), nodes on both ends.

Outputs: load :math:`W = \mu\omega R^4/c^2\,|\bar F|`, attitude angle,
journal friction torque :math:`T = \mu\omega R^4/c\iint(1/\bar h + \bar h\,\partial_\theta\bar p/2)\,d\theta\,d\bar z`
(shear over the whole circumference) and side flow
:math:`Q = \omega R^2 c/12\sum_{ends}\int\bar h^3|\partial_{\bar z}\bar p|\,d\theta`.

References
----------
.. [1] Christopherson, D. G., "A new mathematical method for the solution of
   film lubrication problems", Proc. IMechE 146 (1941) 126-135.
.. [2] Raimondi, A. A., Boyd, J., "A solution for the finite journal bearing
   and its application to analysis and design", ASLE Trans. 1 (1958) 159-209.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import optimize

from .._kernels.reynolds import integrate, psor

N_THETA = 144
N_Z = 25
RELAXATION = 1.8
TOLERANCE = 1e-9
MAX_SWEEPS = 200_000


@dataclass
class Field:
    """Converged dimensionless pressure field of one eccentricity."""

    eps: float
    theta: np.ndarray
    z: np.ndarray
    h: np.ndarray
    pressure: np.ndarray
    force: float  # |F| dimensionless
    attitude: float  # [rad]
    sweeps: int


def solve_field(eps, length_over_radius, *, n_theta=N_THETA, n_z=N_Z, start=None):
    """Pressure field at eccentricity ``eps`` for a bearing of L/R ``length_over_radius``."""
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    dtheta = theta[1]
    z = np.linspace(0.0, length_over_radius, n_z)
    dz = z[1]
    h = 1.0 + eps * np.cos(theta)
    h_half = 1.0 + eps * np.cos(theta + 0.5 * dtheta)
    rhs = 6.0 * (h_half - np.roll(h_half, 1)) / dtheta
    pressure = np.zeros((n_theta, n_z)) if start is None else start.copy()
    sweeps = psor(h, rhs, dtheta, dz, pressure, RELAXATION, TOLERANCE, MAX_SWEEPS)
    if sweeps < 0:
        raise RuntimeError(f"Reynolds PSOR did not converge at eps = {eps}")
    f_r, f_t = integrate(pressure, theta, dtheta, dz)
    return Field(eps, theta, z, h, pressure, float(np.hypot(f_r, f_t)), float(np.arctan2(f_t, f_r)), sweeps)


def friction_and_flow(field):
    """Dimensionless friction integral and side-flow integral of a field."""
    dtheta = field.theta[1]
    dz = field.z[1]
    dp = (np.roll(field.pressure, -1, axis=0) - np.roll(field.pressure, 1, axis=0)) / (2 * dtheta)
    shear = (1.0 / field.h)[:, None] + 0.5 * field.h[:, None] * dp
    weights = np.ones(field.z.size)
    weights[[0, -1]] = 0.5
    friction = np.sum(shear * weights) * dtheta * dz
    p = field.pressure
    gradient = (4 * p[:, 1] - p[:, 2]) / (2 * dz) + (4 * p[:, -2] - p[:, -3]) / (2 * dz)
    flow = np.sum(field.h**3 * gradient) * dtheta
    return friction, flow


def eccentricity_for_load(dimensionless_load, length_over_radius, *, n_theta=N_THETA, n_z=N_Z):
    """The field whose dimensionless load equals ``dimensionless_load`` (Brent on log load)."""
    cache = {}

    def mismatch(eps):
        field = solve_field(eps, length_over_radius, n_theta=n_theta, n_z=n_z, start=cache.get("last"))
        cache["last"] = field.pressure
        cache[eps] = field
        return np.log(field.force) - np.log(dimensionless_load)

    lo, hi = 1e-4, 0.995
    if mismatch(hi) < 0:
        raise ValueError(f"load: the Reynolds tier needs an eccentricity above {hi} for this load")
    if mismatch(lo) > 0:
        return solve_field(0.0, length_over_radius, n_theta=n_theta, n_z=n_z)
    eps = optimize.brentq(mismatch, lo, hi, xtol=1e-12, rtol=1e-10)
    return cache[eps] if eps in cache else solve_field(eps, length_over_radius, n_theta=n_theta, n_z=n_z)
