"""Finite-difference Reynolds equation with Swift-Stieber cavitation, by projected SOR.

Dimensionless, unwrapped film: theta in [0, 2 pi) periodic from the thickest
film, z in [0, L/R] with ambient pressure at both ends. The readable statement
of the discretisation is in :mod:`stackup.film.reynolds`; the tests compare
this kernel with a direct sparse solve where no cavitation occurs.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit

#: The transient tier's grid: nodes that keep their pressure and fill (ends, feed), the steps in theta and z.
Grid = namedtuple("Grid", ("fixed", "dtheta", "dz"))
#: The field solve's sweeps: over-relaxation factor, tolerance on the change, most sweeps, and whether the
#: cavitation conserves mass (Elrod-Adams) or projects p >= 0 (Reynolds).
Sweeps = namedtuple("Sweeps", ("omega", "tolerance", "max_sweeps", "mass_conserving"))


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


@njit(cache=True)
def elrod_adams(film, history, c_time, p, fill, grid, sweeps):
    """One time step of the transient Reynolds equation with Elrod-Adams (JFO) cavitation, in place.

    Dimensionless, uniform grid periodic in theta (axis 0), z along axis 1:

        d/dth(h^3 dp/dth) + d/dz(h^3 dp/dz) = 6 d(g h)/dth + c_time g h - history

    with g the fill (film content) fraction, p >= 0, g <= 1, p (1 - g) = 0.
    ``c_time g h - history`` is the time derivative of the content (backward
    Euler or BDF2, history from earlier steps); the Couette flux through the
    face i + 1/2 is g_i h_(i+1/2): the fill upwind (the journal turns towards
    +theta), the film at the face, so a full film is second-order central.
    ``film`` = (h, h_east, h3_east, h3_north): h (n_t, n_z) at the nodes, h_east
    and h3_east at (i + 1/2, j), h3_north at (i, j + 1/2). Nodes with the grid's
    (:data:`Grid`) ``fixed`` keep p and g (ends, feed). Gauss-Seidel with
    over-relaxation ``omega`` (:data:`Sweeps`) on p; a node whose p would turn
    negative cavitates and solves for g instead; a cavitated node whose g would
    exceed 1 fills (Ausas, Jai, Buscaglia 2009). With ``mass_conserving``
    False, g stays 1 and p >= 0 is a projection (Reynolds condition, no content
    balance in the cavitated zone).
    Returns the number of sweeps; -1 if not converged.
    """
    h, h_east, h3_east, h3_north = film
    fixed, dtheta, dz = grid
    omega, tolerance, max_sweeps, mass_conserving = sweeps
    n_t, n_z = p.shape
    it2 = 1.0 / (dtheta * dtheta)
    iz2 = 1.0 / (dz * dz)
    couette = 6.0 / dtheta
    for sweep in range(max_sweeps):
        change = 0.0
        peak = 0.0
        fill_change = 0.0
        for i in range(n_t):
            im = i - 1 if i > 0 else n_t - 1
            ip = i + 1 if i + 1 < n_t else 0
            for j in range(n_z):
                if fixed[i, j]:
                    continue
                a_e = h3_east[i, j] * it2
                a_w = h3_east[im, j] * it2
                a_n = h3_north[i, j] * iz2
                a_s = h3_north[i, j - 1] * iz2
                neighbours = a_e * p[ip, j] + a_w * p[im, j] + a_n * p[i, j + 1] + a_s * p[i, j - 1]
                upstream = couette * fill[im, j] * h_east[im, j]
                carried = couette * h_east[i, j] + c_time * h[i, j]  # outflow and content of a full node
                if p[i, j] > 0.0 or fill[i, j] >= 1.0 or not mass_conserving:
                    gs = (neighbours + upstream + history[i, j] - carried) / (a_e + a_w + a_n + a_s)
                    new = (1.0 - omega) * p[i, j] + omega * gs
                    if new > 0.0:
                        change = max(change, abs(new - p[i, j]))
                        p[i, j] = new
                        peak = max(peak, new)
                        fill[i, j] = 1.0
                        continue
                    change = max(change, p[i, j])
                    p[i, j] = 0.0
                    if not mass_conserving:
                        continue
                g = (neighbours + upstream + history[i, j]) / carried
                if g >= 1.0:
                    g = 1.0
                elif g < 0.0:
                    g = 0.0
                fill_change = max(fill_change, abs(g - fill[i, j]))
                fill[i, j] = g
        if change <= tolerance * max(peak, 1e-30) and fill_change <= tolerance:
            return sweep + 1
    return -1
