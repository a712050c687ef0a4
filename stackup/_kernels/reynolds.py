"""Finite-difference Reynolds equation with Swift-Stieber cavitation, by projected SOR.

Dimensionless, unwrapped film: theta in [0, 2 pi) periodic from the thickest
film, z in [0, L/R] with ambient pressure at both ends. The readable statement
of the discretisation is in :mod:`stackup.film.reynolds`; the tests compare
this kernel with a direct sparse solve where no cavitation occurs.
"""

import math

import numpy as np
from numba import njit


@njit(cache=True)
def psor(h, rhs, dtheta, dz, pressure, omega, tolerance, max_sweeps):
    """Solve d/dth(h^3 dp/dth) + d/dz(h^3 dp/dz) = rhs with p >= 0 (projected SOR), in place.

    h (n_theta,) film at the nodes; rhs (n_theta,) source per node (same for every z);
    pressure (n_theta, n_z) with n_z including the two boundary rows (kept 0), and
    the column theta = 0 (the oil inlet at the thickest film) kept 0.
    Returns the number of sweeps; -1 if not converged.
    """
    n_t, n_z = pressure.shape
    h3 = h**3
    east = np.empty(n_t)
    for i in range(n_t):
        ip = (i + 1) % n_t
        east[i] = (0.5 * (h3[i] + h3[ip])) / (dtheta * dtheta)
    for sweep in range(max_sweeps):
        change = 0.0
        peak = 0.0
        for i in range(1, n_t):
            im = (i - 1) % n_t
            ip = (i + 1) % n_t
            a_e = east[i]
            a_w = east[im]
            a_z = h3[i] / (dz * dz)
            a_p = a_e + a_w + 2.0 * a_z
            for j in range(1, n_z - 1):
                gs = (a_e * pressure[ip, j] + a_w * pressure[im, j] + a_z * (pressure[i, j + 1] + pressure[i, j - 1])
                      - rhs[i]) / a_p
                new = (1.0 - omega) * pressure[i, j] + omega * gs
                if new < 0.0:
                    new = 0.0
                change = max(change, abs(new - pressure[i, j]))
                pressure[i, j] = new
                peak = max(peak, new)
        if change <= tolerance * max(peak, 1e-30):
            return sweep + 1
    return -1


@njit(cache=True)
def integrate(pressure, theta, dtheta, dz):
    """Force components (along the line of centres towards the thin film, and normal to it) and side flux terms."""
    n_t, n_z = pressure.shape
    f_r = 0.0
    f_t = 0.0
    for i in range(n_t):
        s = 0.0
        for j in range(n_z):
            w = 0.5 if (j == 0 or j == n_z - 1) else 1.0
            s += w * pressure[i, j]
        s *= dz
        f_r += -s * math.cos(theta[i]) * dtheta
        f_t += s * math.sin(theta[i]) * dtheta
    return f_r, f_t
