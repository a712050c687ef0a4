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
from scipy import optimize, sparse
from scipy.sparse.linalg import spsolve

from .._kernels.reynolds import integrate, psor
from .journal import ECCENTRICITY_LIMIT

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
    """The field whose dimensionless load equals ``dimensionless_load`` (Brent on log load), at an eccentricity up to
    :data:`~stackup.film.journal.ECCENTRICITY_LIMIT` (a ValueError for a load beyond it)."""
    cache = {}

    def mismatch(eps):
        field = solve_field(eps, length_over_radius, n_theta=n_theta, n_z=n_z, start=cache.get("last"))
        cache["last"] = field.pressure
        cache[eps] = field
        return np.log(field.force) - np.log(dimensionless_load)

    lo, hi = 1e-4, ECCENTRICITY_LIMIT
    if mismatch(hi) < 0:
        raise ValueError(f"load: the Reynolds tier needs an eccentricity above {hi} for this load")
    if mismatch(lo) > 0:
        return solve_field(0.0, length_over_radius, n_theta=n_theta, n_z=n_z)
    eps = optimize.brentq(mismatch, lo, hi, xtol=1e-12, rtol=1e-10)
    return cache[eps] if eps in cache else solve_field(eps, length_over_radius, n_theta=n_theta, n_z=n_z)


# --- Squeeze film (journal moving at the squeeze velocity v_s), Reynolds cavitation condition ---

#: Grid of :func:`squeeze_field`: angles around the bearing, axial nodes on half the width.
N_THETA_SQUEEZE = 240
N_Z_SQUEEZE = 17
#: The angular grid is finest at the thinnest film: Sommerfeld's map of eccentricity min(eps, this).
STRETCH_LIMIT = 0.9


@dataclass(frozen=True)
class SqueezeField:
    """Pressure of a bearing squeezed at unit speed along ``alpha`` (line-of-centres frame).

    Dimensionless: :math:`\\bar p = p\\,c^2/(\\mu\\omega R^2)` for :math:`|\\mathbf v_s| = c\\,\\omega`,
    :math:`\\bar z = z/R` from the mid-plane (half the width solved, symmetric).
    """

    eps: float
    alpha: float
    theta: np.ndarray  # (n_theta,) angle from the thickest... from the thinnest film [rad]
    z: np.ndarray  # (n_z,) from the mid-plane to the end
    pressure: np.ndarray  # (n_theta, n_z)
    force: np.ndarray  # (2,) on the bearing, line-of-centres frame, integral of p n over the whole film
    peak: float
    iterations: int


def stretched_angles(eps, n):
    """Angles in [-pi, pi) from the thinnest film, spaced in proportion to the film of eccentricity min(eps, 0.9)."""
    k = min(eps, STRETCH_LIMIT)
    g = -np.pi + 2 * np.pi * np.arange(n) / n
    return 2 * np.arctan2(np.sqrt(1 - k) * np.sin(g / 2), np.sqrt(1 + k) * np.cos(g / 2))


def squeeze_field(eps, alpha, length_over_radius, *, n_theta=N_THETA_SQUEEZE, n_z=N_Z_SQUEEZE):
    r"""Finite-length Reynolds equation of a squeezed bearing with the Reynolds (Swift-Stieber) condition.

    .. math:: \bar\nabla\cdot(\bar h^3\bar\nabla\bar p) = -12\cos(\theta - \alpha), \qquad
              \bar p \ge 0, \qquad \bar h = 1 - \varepsilon\cos\theta

    (rotation and squeeze together act as a squeeze at :math:`\mathbf v_s`; see
    :mod:`stackup.film.orbit`), :math:`\bar p = 0` at the ends, periodic in
    :math:`\theta`, no feed groove. Finite volumes on a grid finest at the
    thinnest film; the complementarity (p >= 0, residual >= 0) by the
    primal-dual active-set method with a sparse direct solve per step
    (Hintermüller, Ito, Kunisch 2003), exact for the discrete problem.
    """
    theta = stretched_angles(eps, n_theta)
    half = length_over_radius / 2
    z = np.linspace(0.0, half, n_z)
    dz = z[1]
    nt, nz = n_theta, n_z - 1  # unknowns: all angles, axial nodes but the end (p = 0)
    nxt = np.roll(theta, -1) + np.where(np.arange(nt) == nt - 1, 2 * np.pi, 0.0)
    gap_east = nxt - theta  # theta[i+1] - theta[i]
    width = 0.5 * (gap_east + np.roll(gap_east, 1))  # control volume in theta
    h = 1 - eps * np.cos(theta)
    h_east = 1 - eps * np.cos(theta + 0.5 * gap_east)
    cell_z = np.full(nz, dz)
    cell_z[0] = dz / 2  # symmetry plane: half a cell
    idx = np.arange(nt * nz).reshape(nt, nz)
    a_e = (h_east**3 / gap_east)[:, None] * cell_z[None, :]
    a_z = (h**3 * width)[:, None] / dz * np.ones((1, nz))  # towards z+1 (the end row is p = 0)
    rows, cols, vals = [], [], []
    diag = np.zeros((nt, nz))
    # theta fluxes (periodic)
    east = np.roll(idx, -1, axis=0)
    rows += [idx.ravel(), east.ravel()]
    cols += [east.ravel(), idx.ravel()]
    vals += [-a_e.ravel(), -a_e.ravel()]
    diag += a_e + np.roll(a_e, 1, axis=0)
    # z fluxes between j and j+1; the last unknown row couples to the end (p = 0)
    inner = a_z[:, :-1]
    rows += [idx[:, :-1].ravel(), idx[:, 1:].ravel()]
    cols += [idx[:, 1:].ravel(), idx[:, :-1].ravel()]
    vals += [-inner.ravel(), -inner.ravel()]
    diag[:, :-1] += inner
    diag[:, 1:] += inner
    diag[:, -1] += a_z[:, -1]
    rows.append(idx.ravel())
    cols.append(idx.ravel())
    vals.append(diag.ravel())
    m = sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(nt * nz,) * 2)
    b = (12 * np.cos(theta - alpha) * width)[:, None] * cell_z[None, :]
    b = b.ravel()
    p, iteration = _cavitated_solve(m, b, f"squeeze_field: active set did not settle at eps = {eps}, alpha = {alpha}")
    pressure = np.concatenate([p.reshape(nt, nz), np.zeros((nt, 1))], axis=1)
    weights = np.full(n_z, dz)
    weights[[0, -1]] = dz / 2
    line = 2 * (pressure * weights).sum(axis=1)  # both halves of the width
    force = np.array([np.sum(line * np.cos(theta) * width), np.sum(line * np.sin(theta) * width)])
    return SqueezeField(eps, alpha, theta, z, pressure, force, float(pressure.max()), iteration)


# --- Tilted journal: film varying over the width, squeeze varying over the width, Reynolds cavitation condition ---

#: Grid of :func:`tilted_field`: angles around the bearing and axial nodes over the whole width (ends included).
N_THETA_TILTED = 360
N_Z_TILTED = 41


@dataclass(frozen=True)
class TiltedField:
    """Pressure under a tilted journal (:func:`tilted_field`), engine frame.

    Dimensionless as the mobility tiers: :math:`\\zeta = 2z/L \\in [-1, 1]`,
    pressure :math:`\\bar p = p\\,c^2/(\\mu\\omega R^2)`, force per
    :math:`\\mu\\omega R L^3/c^2`, moment per :math:`\\mu\\omega R L^4/c^2`.
    """

    theta: np.ndarray  # (n_theta,) angle of the film from axis 0 [rad]
    zeta: np.ndarray  # (n_z,) axial position over half the width [-]
    film: np.ndarray  # (n_theta, n_z) film thickness [c]
    pressure: np.ndarray  # (n_theta, n_z)
    force: np.ndarray  # (2,) film force on the bearing, integral of p n
    moment: np.ndarray  # (2,) integral of p z n: the film's moment on the bearing about the mid-plane
    iterations: int


def tilted_field(position, squeeze, edge_offset, length_over_radius, *, edge_squeeze=None, n_theta=N_THETA_TILTED,
                 n_z=N_Z_TILTED):
    r"""Finite-length Reynolds equation under a tilted journal, Reynolds (Swift-Stieber) cavitation condition.

    Journal centre at :math:`\zeta` (axial position over half the width) :math:`\boldsymbol\xi + \zeta\mathbf e`,
    its local squeeze velocity :math:`\bar{\mathbf v} + \zeta\bar{\mathbf u}` (rotation included, see
    :mod:`stackup.film.orbit`), all in clearances and :math:`c\omega`:

    .. math:: \bar\nabla\cdot(\bar h^3\bar\nabla\bar p) = -12\,(\bar{\mathbf v} + \zeta\bar{\mathbf u})\cdot\mathbf n,
              \qquad \bar h = 1 - (\boldsymbol\xi + \zeta\mathbf e)\cdot\mathbf n, \qquad \bar p \ge 0

    with :math:`\bar p = 0` at both ends, periodic in :math:`\theta`, no feed groove. The
    tilt without tilt squeeze (the journal's slope held) gives
    :math:`\bar{\mathbf u} = -\tfrac12\mathbf k\times\mathbf e` (``edge_squeeze`` default).
    Finite volumes on a grid finest where the film is thinnest, the complementarity
    by the primal-dual active-set method (as :func:`squeeze_field`).

    Parameters
    ----------
    position : array_like (2,)
        Journal centre in the mid-plane :math:`\boldsymbol\xi` [c].
    squeeze : array_like (2,)
        Squeeze velocity in the mid-plane :math:`\bar{\mathbf v}` [c omega].
    edge_offset : array_like (2,)
        The journal axis' offset at the bearing's end :math:`\mathbf e = \boldsymbol\gamma L/(2c)` [c].
    length_over_radius : float
    edge_squeeze : array_like (2,), optional
        :math:`\bar{\mathbf u}` [c omega].
    """
    xi = np.asarray(position, float)
    v = np.asarray(squeeze, float)
    e = np.asarray(edge_offset, float)
    u = -0.5 * np.array([-e[1], e[0]]) if edge_squeeze is None else np.asarray(edge_squeeze, float)
    theta = _angles_about_the_thinner_edge(xi, e, n_theta)
    zeta = np.linspace(-1.0, 1.0, n_z)

    def film(angle, z):
        return 1 - (xi[0] + z * e[0]) * np.cos(angle) - (xi[1] + z * e[1]) * np.sin(angle)

    if np.any(film(theta[:, None], zeta[None, :]) <= 0):
        raise ValueError("tilted_field: the journal touches the bearing")
    m, b, width = _tilted_system(film, theta, zeta, v, u, half_width=length_over_radius / 2)
    p, iteration = _cavitated_solve(m, b, "tilted_field: active set did not settle")
    pressure = np.zeros((n_theta, n_z))
    pressure[:, 1:-1] = p.reshape(n_theta, n_z - 2)
    dzeta = zeta[1] - zeta[0]
    weights = np.full(n_z, dzeta)
    weights[[0, -1]] = dzeta / 2
    line = pressure @ weights  # integral over zeta
    line_z = pressure @ (weights * zeta)
    # p_bar = p c^2/(mu omega R^2), dA = R dtheta (L/2) dzeta: force / (mu omega R L^3/c^2) = (R/L)^2/2 sum
    scale = 0.5 / length_over_radius**2
    normal = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    force = scale * (normal * (line * width)[:, None]).sum(axis=0)
    moment = 0.5 * scale * (normal * (line_z * width)[:, None]).sum(axis=0)
    return TiltedField(theta, zeta, film(theta[:, None], zeta[None, :]), pressure, force, moment, iteration)


def _angles_about_the_thinner_edge(xi, e, n_theta):
    """Angles around the bearing stretched (Sommerfeld's map) about the thinnest film over the width."""
    ends = np.stack([xi + e, xi - e])
    worst = ends[np.argmax(np.linalg.norm(ends, axis=1))]
    centre = np.arctan2(worst[1], worst[0])
    k = min(float(np.linalg.norm(worst)), STRETCH_LIMIT)
    g = -np.pi + 2 * np.pi * np.arange(n_theta) / n_theta
    return centre + 2 * np.arctan2(np.sqrt(1 - k) * np.sin(g / 2), np.sqrt(1 + k) * np.cos(g / 2))


def _tilted_system(film, theta, zeta, v, u, *, half_width):
    """Finite volumes of :func:`tilted_field`: (matrix, source, control-volume widths in theta).

    Unknowns the inner axial nodes of every angle (both ends p = 0), periodic in theta; ``film(angle, zeta)``
    the film thickness, ``half_width`` L/(2R) (z/R = half_width * zeta).
    """
    dzeta = zeta[1] - zeta[0]
    nt, nz = theta.size, zeta.size - 2  # unknowns: inner axial nodes
    gap_east = np.diff(np.append(theta, theta[0] + 2 * np.pi))
    width = 0.5 * (gap_east + np.roll(gap_east, 1))
    inner = zeta[1:-1]
    h_east = film((theta + 0.5 * gap_east)[:, None], inner[None, :])
    h_north = film(theta[:, None], (zeta[:-1] + 0.5 * dzeta)[None, :])  # faces between axial nodes j, j+1 (all)
    dz = half_width * dzeta  # axial step in R
    idx = np.arange(nt * nz).reshape(nt, nz)
    a_e = h_east**3 / gap_east[:, None] * dz
    a_n = h_north**3 * width[:, None] / dz  # (nt, n_z - 1): face j between node j and j+1 of the full grid
    rows, cols, vals = [], [], []
    diag = a_e + np.roll(a_e, 1, axis=0)
    east = np.roll(idx, -1, axis=0)
    rows += [idx.ravel(), east.ravel()]
    cols += [east.ravel(), idx.ravel()]
    vals += [-a_e.ravel(), -a_e.ravel()]
    # inner node j (full index j + 1) couples to j + 2 through face j + 1 and to j through face j
    diag += a_n[:, 1:] + a_n[:, :-1]
    link = a_n[:, 1:-1]  # faces between inner nodes
    rows += [idx[:, :-1].ravel(), idx[:, 1:].ravel()]
    cols += [idx[:, 1:].ravel(), idx[:, :-1].ravel()]
    vals += [-link.ravel(), -link.ravel()]
    rows.append(idx.ravel())
    cols.append(idx.ravel())
    vals.append(diag.ravel())
    m = sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(nt * nz,) * 2)
    normal = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    source = (normal @ v)[:, None] + inner[None, :] * (normal @ u)[:, None]
    return m, (12 * source * width[:, None] * dz).ravel(), width


def _cavitated_solve(m, b, message):
    """Pressure p >= 0 with m p = b where p > 0 (Swift-Stieber), by a primal-dual active set; (p, iterations)."""
    active = b <= 0
    p = np.zeros(b.size)
    for iteration in range(1, 200):
        free = ~active
        p[:] = 0.0
        if free.any():
            p[free] = spsolve(m[free][:, free].tocsc(), b[free])
        residual = m @ p - b
        new_active = residual > p  # primal-dual active set with c = 1
        if np.array_equal(new_active, active):
            return p, iteration
        active = new_active
    raise RuntimeError(message)
