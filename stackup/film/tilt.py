r"""The film under a tilted journal: its restoring moment and the journal's tilt equilibrium.

A journal whose axis is tilted against the bearing's by :math:`\boldsymbol\gamma`
(slope, engine frame) has the film (Rozhdestvensky et al. 2018, eq. 4)

.. math:: h(\theta, z) = c - (\mathbf x + z\boldsymbol\gamma)\cdot\mathbf n(\theta),
          \qquad z \in [-L/2, L/2]

thinnest at an edge. Its pressure pushes the edges back: the film's moment
on the bearing about the mid-plane, :math:`\mathbf M = \iint p\,z\,\mathbf n\,R\,d\theta\,dz`
(conjugate to the slope), turns the journal back against the crankshaft's
bending. With :math:`C` the crankshaft's rotational compliance at the support
(:func:`stackup.crank.support_compliance`, per bending plane) the tilt in the
film is

.. math:: \boldsymbol\gamma = \boldsymbol\gamma_{free} - C\,\mathbf M(\boldsymbol\gamma;\ \mathbf x, \mathbf v_s)

(:math:`\boldsymbol\gamma_{free}` the beam's slope without the film's moment,
:func:`stackup.crank.support_slopes`), solved at each crank angle.

Cheap tier (``"short"``): the short-bearing Reynolds equation line by line,
:math:`\partial_z(h^3\partial_z p) = -12\mu(\mathbf v_s + z\mathbf u_s)\cdot\mathbf n`,
:math:`p = 0` at both ends, with the local squeeze velocity of the tilted axis
:math:`\mathbf v_s + z\mathbf u_s`,
:math:`\mathbf u_s = \dot{\boldsymbol\gamma} - \tfrac\omega2\mathbf k\times\boldsymbol\gamma`
(:mod:`stackup.film.orbit`); with the film linear in :math:`z` its integrals over
the width are closed forms (:mod:`stackup._kernels.tilt`). A line carries
pressure where its pressure integral is positive (Gümbel's π-film, per line;
without tilt exactly the mobility tiers' film). ``"finite"``: that force and
moment scaled and turned by the finite-length correction the
``mobility-finite`` tier applies to the force at the same eccentricity and
squeeze direction (measured against the Reynolds tier with tilt in
``reports/film_speed_vs_error.md``).

The tilt's own squeeze, :math:`\dot{\boldsymbol\gamma}` in :math:`\mathbf u_s`: on the
orbit of a dynamic tier the tilt is marched from angle to angle with it
(:func:`march_tilt`, implicit Euler; the squeeze damps the tilt, so an edge
that the held tilt would put on the wall while the journal lingers at high
eccentricity and low load lags behind the beam and stays off it); on a
quasi-static tier it is held at each angle (:func:`cycle_tilt`: the tilt
follows the load, as the centre does there).

Simplifications (each measured against the transient Reynolds tier with the
tilt balanced in its film, the reference, ``reports/coupled_supports.md``):

- the mid-plane orbit is the film tier's without tilt (the tilt's share of
  the force does not move the journal centre);
- each bearing meets its own support's compliance only (the diagonal of
  :func:`stackup.crank.support_compliance`: a moment at a neighbour also turns
  the journal, by about a quarter, the other way).

Where no tilt with both edges off the wall balances the beam (the film's
moment grows only like the logarithm of the edge film, so a beam bent
further than the film can hold it brings the edge to the wall) the journal is
held with an edge at the limit eccentricity and the angle's state is
``at_limit`` (the orbit's status ``edge_contact``). The edge sits where a
contact force there closes the balance: the residual
:math:`\boldsymbol\gamma - \boldsymbol\gamma_{free} + C\mathbf M` equals
:math:`-\lambda C\mathbf n` with :math:`\lambda \ge 0` and :math:`\mathbf n` the outward
normal of the touching edge's wall (a variational inequality on the set of
tilts with both edges inside the limit; the film's moment is not monotone in
the tilt, so its residual can also have a minimum inside that set that is not
a root, which is not a balance either).

References
----------
.. [1] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), eqs. 1, 4-6
   (film with skewed axes; moments and angular compliances of the supports).
.. [2] Ocvirk, F. W., NACA TN 2808, 1952 (short bearing).
.. [3] Booker, J. F., J. Basic Eng. 87 (1965) 537-546 (rotation and squeeze as one squeeze velocity).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .._kernels import tilt as _kernel
from .._kernels.mobility import Correction, bearing_table, table_lookup
from .._validate import AngleVectors, Finite, OneOf, Positive, renamed, validated
from .journal import (CYCLE, ECCENTRICITY_LIMIT, STATES, Orbit, edge_film, mobility_table,  # noqa: F401
                      outside_table, short_table, table_covers, vector_length, within_one_cycle)

#: Gauss-Legendre nodes on the arc that carries pressure and on the rest of the bearing.
GAUSS_NODES = 12
DRY_NODES = 6
#: Largest eccentricity of the thinnest edge Sommerfeld's angle clusters the nodes for.
STRETCH_CAP = 0.95
#: The equilibrium stops when the Newton step is below this share of the edge film.
TOLERANCE = 1e-2
#: The continuation solves every STRIDE-th angle of a 720-angle cycle (the same crank angle on other grids, a power
#: of two); halving the spacing, each angle between two of the same state takes the mean of their film's turn-back
#: (free tilt minus tilt; the free tilt itself is known at every angle) where that turn-back differs between them by
#: less than INTERPOLATE times their thinner edge film (on the wall: times the tilt; the edge film is the limit's
#: there); the others are solved. The tilt tier's cost and its error against the reference, this continuation
#: included, are measured in ``reports/film_speed_vs_error.md`` (tilt section).
INTERPOLATE = 1.0
STRIDE = 8
METHODS = ("short", "finite")


def axial_moments(s):
    r"""Axial moments :math:`K_k(s) = \int_{-1}^{1}\zeta^k(1 - s\zeta)^{-3}d\zeta`, k = 0..4, for :math:`|s| < 1`.

    Closed forms through :math:`u = 1 - s\zeta` (:math:`K_0 = 2/(1-s^2)^2`, :math:`K_1 = sK_0`,
    the others with :math:`\ln\frac{1+s}{1-s}`), a series in :math:`s^2` where those cancel
    (:math:`|s| < 0.15`). Returns an array (5, ...).
    """
    s = np.asarray(s, dtype=float)
    q = s * s
    k0 = 2.0 / (1.0 - q) ** 2
    small = np.abs(s) < _kernel.SERIES_BELOW
    qs = np.where(small, q, 0.0)
    series = [np.polynomial.polynomial.polyval(qs, c) for c in (_kernel.K2_SERIES, _kernel.K3_SERIES,
                                                                  _kernel.K4_SERIES)]
    sl = np.where(small, 0.5, s)
    ql = sl * sl
    a2 = 2.0 / (1.0 - ql)
    a1 = np.log((1.0 + sl) / (1.0 - sl)) / sl
    k0l = 2.0 / (1.0 - ql) ** 2
    closed = [(k0l - 2 * a2 + a1) / ql, (k0l - 3 * a2 + 3 * a1 - 2) / (ql * sl), (k0l - 4 * a2 + 6 * a1 - 6) / ql**2]
    return np.stack([k0, s * k0, np.where(small, series[0], closed[0]), np.where(small, s * series[1], closed[1]),
                     np.where(small, series[2], closed[2])])


def short_film(position, squeeze, edge_offset, *, tilt_squeeze=None, lines=4096):
    r"""Force and moment of the short-bearing film under a tilted journal, dimensionless (the readable reference).

    Parameters
    ----------
    position : array_like (..., 2)
        Journal centre in the mid-plane :math:`\boldsymbol\xi = \mathbf x/c`.
    squeeze : array_like (..., 2)
        Squeeze velocity in the mid-plane :math:`\bar{\mathbf v} = \mathbf v_s/(c\omega)`.
    edge_offset : array_like (..., 2)
        :math:`\mathbf e = \boldsymbol\gamma L/(2c)` (the journal centre at the ends is
        :math:`\boldsymbol\xi \pm \mathbf e`).
    tilt_squeeze : array_like (..., 2), optional
        :math:`\bar{\mathbf u} = \dot{\mathbf e}/\omega - \tfrac12\mathbf k\times\mathbf e`; default
        :math:`-\tfrac12\mathbf k\times\mathbf e` (the tilt held).
    lines : int
        Lines of the midpoint rule around the bearing.

    Returns
    -------
    (force, moment) : numpy.ndarray (..., 2) each
        Film force on the bearing per :math:`\mu\omega R L^3/c^2` and its moment about the
        mid-plane per :math:`\mu\omega R L^4/c^2`.

    Notes
    -----
    Per line, :math:`\zeta = 2z/L`, :math:`\bar h = h_0 - g\zeta`, source :math:`a + b\zeta`
    (:mod:`stackup._kernels.tilt`): :math:`H_k = K_k(g/h_0)/h_0^3`,
    :math:`C = (aH_1 + bH_2/2)/H_0`, :math:`P_0 = aH_2 + bH_3/2 - CH_1`,
    :math:`P_1 = -\tfrac12[C(H_2 - H_0) - a(H_3 - H_1) - \tfrac b2(H_4 - H_2)]`, and
    :math:`\bar{\mathbf F} = \tfrac32\oint\mathbf n P_0^+ d\theta`,
    :math:`\bar{\mathbf M} = \tfrac34\oint_{P_0 > 0}\mathbf n P_1\,d\theta`.
    """
    xi, v, e = (np.asarray(a, dtype=float)[..., None, :] for a in (position, squeeze, edge_offset))
    theta = 2 * np.pi * (np.arange(lines) + 0.5) / lines
    n = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    h0 = 1 - (xi * n).sum(-1)
    g = (e * n).sum(-1)
    a = (v * n).sum(-1)
    if tilt_squeeze is None:
        b = 0.5 * (e[..., 1] * n[..., 0] - e[..., 0] * n[..., 1])
    else:
        b = (np.asarray(tilt_squeeze, dtype=float)[..., None, :] * n).sum(-1)
    k = axial_moments(g / h0) / h0**3
    c = (a * k[1] + 0.5 * b * k[2]) / k[0]
    p0 = a * k[2] + 0.5 * b * k[3] - c * k[1]
    p1 = -0.5 * (c * (k[2] - k[0]) - a * (k[3] - k[1]) - 0.5 * b * (k[4] - k[2]))
    wet = p0 > 0
    step = 2 * np.pi / lines
    force = 1.5 * step * (n * np.where(wet, p0, 0.0)[..., None]).sum(-2)
    moment = 0.75 * step * (n * np.where(wet, p1, 0.0)[..., None]).sum(-2)
    return force, moment


@functools.cache
def quadrature():
    """The film moment's quadrature (:data:`stackup._kernels.tilt.Quadrature`): Gauss-Legendre nodes and weights on
    the wet arc and on the rest (read-only; computed once), and :data:`STRETCH_CAP`."""
    out = (*np.polynomial.legendre.leggauss(GAUSS_NODES), *np.polynomial.legendre.leggauss(DRY_NODES))
    for array in out:
        array.setflags(write=False)
    return _kernel.Quadrature(*out, STRETCH_CAP)


@dataclass(frozen=True)
class TiltedFilm:
    """Film force and moment under a tilted journal.

    Attributes
    ----------
    force : numpy.ndarray (..., 2)
        Force of the film on the bearing [N].
    moment : numpy.ndarray (..., 2)
        Its moment about the bearing's mid-plane, :math:`\\iint p\\,z\\,\\mathbf n\\,dA` [N m]
        (conjugate to the slope: the journal receives :math:`-\\mathbf M`).
    """

    force: np.ndarray
    moment: np.ndarray


def _dimensionless(position, squeeze_velocity, tilt, *, journal_radius, bearing_width, radial_clearance, viscosity,
                   speed):
    """(leading shape, xi, v, e (m, 2), r, l, c, mu, w (m,)) of :func:`film_moment`'s inputs, flattened."""
    x, vs, gamma = (np.asarray(a, dtype=float) for a in (position, squeeze_velocity, tilt))
    lead = np.broadcast_shapes(x.shape[:-1], vs.shape[:-1], gamma.shape[:-1])
    r, l, c, mu, w = (np.broadcast_to(np.asarray(value, dtype=float), lead).ravel() for value in (
        journal_radius, bearing_width, radial_clearance, viscosity, speed))
    xi = np.broadcast_to(x, (*lead, 2)).reshape(-1, 2) / c[:, None]
    v = np.broadcast_to(vs, (*lead, 2)).reshape(-1, 2) / (c * w)[:, None]
    e = np.broadcast_to(gamma, (*lead, 2)).reshape(-1, 2) * (l / (2 * c))[:, None]
    return lead, xi, v, e, r, l, c, mu, w


def _edges_off_the_bearing(values):
    _, xi, _, e, *_ = _dimensionless(**{k: values[k] for k in ("position", "squeeze_velocity", "tilt", "journal_radius",
                                                               "bearing_width", "radial_clearance", "viscosity",
                                                               "speed")})
    reach = np.maximum(np.linalg.norm(xi + e, axis=-1), np.linalg.norm(xi - e, axis=-1))
    if np.any(reach >= 1.0):
        raise ValueError(f"tilt: an edge of the journal reaches the bearing (edge eccentricity {reach.max():.4g} >= 1)")


def _table_covers_the_bearing(values):
    """The finite correction's table covers the L/D of every bearing (``method="finite"``)."""
    if values["method"] == "finite":
        ld = values["bearing_width"] / (2 * values["journal_radius"])
        if not table_covers(ld):
            raise outside_table("bearing_width", ld, "the finite correction's table")


@renamed(radius="journal_radius", length="bearing_width")
@validated(method=OneOf(METHODS), position=Finite(), squeeze_velocity=Finite(), tilt=Finite(),
           journal_radius=Positive(), bearing_width=Positive(), radial_clearance=Positive(), viscosity=Positive(),
           speed=Positive(), relations=(_edges_off_the_bearing, _table_covers_the_bearing))
def film_moment(position, squeeze_velocity, tilt, *, journal_radius, bearing_width, radial_clearance, viscosity, speed,
                method="short"):
    r"""Force and moment of the film on a tilted journal (the cheap tier; compiled).

    Parameters
    ----------
    position : array_like (..., 2)
        Journal centre in the mid-plane relative to the bearing centre [m].
    squeeze_velocity : array_like (..., 2)
        :math:`\mathbf v_s = \dot{\mathbf x} - \tfrac\omega2\mathbf k\times\mathbf x` [m/s] (steady
        journal: :math:`-\tfrac\omega2\mathbf k\times\mathbf x`).
    tilt : array_like (..., 2)
        Slope of the journal axis against the bearing axis [rad] (held: no tilt squeeze).
    journal_radius, bearing_width, radial_clearance : float or array_like (...)
        [m].
    viscosity : float or array_like (...)
        [Pa s].
    speed : float or array_like (...)
        Journal angular speed [rad/s].
    method : {"short", "finite"}
        Short-bearing film, or scaled and turned by the ``mobility-finite``
        tier's finite-length correction (L/D 0.15-1).

    Returns
    -------
    TiltedFilm
    """
    lead, xi, v, e, r, l, c, mu, w = _dimensionless(position, squeeze_velocity, tilt, journal_radius=journal_radius,
                                                    bearing_width=bearing_width, radial_clearance=radial_clearance,
                                                    viscosity=viscosity, speed=speed)
    rule = quadrature()
    out = np.empty((xi.shape[0], 4))
    for i in range(xi.shape[0]):
        out[i] = _kernel.film_moment(xi[i, 0], xi[i, 1], v[i, 0], v[i, 1], e[i, 0], e[i, 1], rule)
    if method == "finite":
        _finite_correction(out, xi, v, l / (2 * r))
    unit = mu * w * r * l**3 / c**2
    force = (out[:, :2] * unit[:, None]).reshape(*lead, 2)
    moment = (out[:, 2:] * (unit * l)[:, None]).reshape(*lead, 2)
    return TiltedFilm(force, moment)


def _finite_correction(out, xi, v, ld):
    """Scale and turn the short film's force and moment ``out`` (m, 4) in place as the ``mobility-finite`` tier does."""
    ld_nodes, stretched, tables = mobility_table()
    correction = Correction(tables, ld_nodes, stretched, True)
    for i in range(xi.shape[0]):
        table = bearing_table(correction, ld[i])
        alpha = np.angle(np.exp(1j * (np.arctan2(v[i, 1], v[i, 0]) - np.arctan2(xi[i, 1], xi[i, 0]))))
        log_ratio, turn = table_lookup(table, stretched, min(np.hypot(*xi[i]), ECCENTRICITY_LIMIT), alpha)[:2]
        rotation = np.exp(log_ratio) * np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
        out[i, :2] = rotation @ out[i, :2]
        out[i, 2:] = rotation @ out[i, 2:]


@dataclass(frozen=True)
class TiltEquilibrium:
    """Tilt of journals in their films over a cycle (:func:`cycle_tilt`).

    Attributes
    ----------
    tilt : numpy.ndarray (..., angles, 2)
        Slope of the journal against the bearing axis in the film [rad].
    state : numpy.ndarray of int8 (..., angles)
        Index into :data:`STATES`.
    evaluations : numpy.ndarray of int (..., angles)
        Film moments computed at each angle (the cost).
    """

    tilt: np.ndarray
    state: np.ndarray
    evaluations: np.ndarray


@renamed(radius="journal_radius", length="bearing_width")
@validated(method=OneOf(METHODS), position=AngleVectors(), squeeze_velocity=Finite(), free_tilt=Finite(),
           compliance=Positive(zero=True), journal_radius=Positive(), bearing_width=Positive(),
           radial_clearance=Positive(), viscosity=Positive(), speed=Positive(), relations=(_table_covers_the_bearing,))
def cycle_tilt(position, squeeze_velocity, free_tilt, *, compliance, journal_radius, bearing_width, radial_clearance,
               viscosity, speed, method="short"):
    r"""The journal's tilt in its film at every angle of a cycle: the free tilt turned back by the film's moment.

    :math:`\boldsymbol\gamma = \boldsymbol\gamma_{free} - C\mathbf M(\boldsymbol\gamma)` on a given mid-plane orbit
    (:mod:`stackup.film.tilt`), solved by the kernel :func:`stackup._kernels.tilt.equilibria`.

    Parameters
    ----------
    position, squeeze_velocity : array_like (..., angles, 2)
        The mid-plane orbit: journal centre [m] and squeeze velocity [m/s] at each angle
        (a cycle tier's orbit is finite: its journal is held at the eccentricity limit at worst).
    free_tilt : array_like (..., angles, 2)
        Slope of the journal against the bearing axis without the film's moment [rad].
    compliance : array_like (..., 2)
        Rotational compliance of the journal at the bearing per component [rad/(N m)]
        (:func:`stackup.crank.support_compliance`); 0 holds the free tilt.
    journal_radius, bearing_width, radial_clearance, viscosity, speed : float or array_like (...)
        As :func:`film_moment`.
    method : {"short", "finite"}
        Film moment of :func:`film_moment`.

    Returns
    -------
    TiltEquilibrium
    """
    x = np.asarray(position, dtype=float)
    lead, n = x.shape[:-2], x.shape[-2]
    args = _kernel_inputs(x, squeeze_velocity, free_tilt, compliance, journal_radius, bearing_width, radial_clearance,
                          viscosity, speed, method)
    tilt = np.empty(args.orbits.xi.shape)
    state = np.empty(tilt.shape[:2], np.int8)
    evaluations = np.empty(tilt.shape[:2], np.int64)
    _kernel.equilibria(args.orbits, args.correction, _kernel.Solver(quadrature(), ECCENTRICITY_LIMIT, TOLERANCE),
                       INTERPOLATE, _stride(STRIDE, n), tilt, state, evaluations)
    c, l = args.radial_clearance, args.bearing_width
    gamma = tilt.reshape(*lead, n, 2) * (2 * c / l)[..., None, None]
    return TiltEquilibrium(gamma, state.reshape(*lead, n), evaluations.reshape(*lead, n))


def _stride(per_720, n):
    """The angles between two solved ones on a cycle of ``n`` angles, for ``per_720`` on a cycle of 720: the same
    crank angle on other grids, a power of two (1 on coarse grids)."""
    return 1 << max(0, int(np.floor(np.log2(per_720 * n / 720))))


@dataclass(frozen=True)
class _KernelInputs:
    """The tilt kernels' dimensionless orbits and finite correction, and the clearance and width (leading shape)."""

    orbits: _kernel.Orbits
    correction: Correction
    radial_clearance: np.ndarray
    bearing_width: np.ndarray


def _kernel_inputs(x, squeeze_velocity, free_tilt, compliance, journal_radius, bearing_width, radial_clearance,
                   viscosity, speed, method):
    """The orbit (..., angles, 2) in the kernels' units (:mod:`stackup._kernels.tilt`), flattened to bearings."""
    lead, n = x.shape[:-2], x.shape[-2]
    vs = np.broadcast_to(np.asarray(squeeze_velocity, dtype=float), x.shape)
    free = np.broadcast_to(np.asarray(free_tilt, dtype=float), x.shape)
    kappa = np.broadcast_to(np.asarray(compliance, dtype=float), (*lead, 2))
    r, l, c, mu, w = (np.broadcast_to(np.asarray(value, dtype=float), lead) for value in (
        journal_radius, bearing_width, radial_clearance, viscosity, speed))
    xi = np.ascontiguousarray((x / c[..., None, None]).reshape(-1, n, 2))
    v = np.ascontiguousarray((vs / (c * w)[..., None, None]).reshape(-1, n, 2))
    e_free = np.ascontiguousarray((free * (l / (2 * c))[..., None, None]).reshape(-1, n, 2))
    kappa = np.ascontiguousarray((kappa * (mu * w * r * l**5 / (2 * c**3))[..., None]).reshape(-1, 2))
    finite = method == "finite"
    ld_nodes, stretched, tables = mobility_table() if finite else short_table()
    ld = (l / (2 * r)).reshape(-1) if finite else np.ones(xi.shape[0])
    return _KernelInputs(_kernel.Orbits(xi, v, e_free, kappa, np.ascontiguousarray(ld, dtype=float)),
                         Correction(tables, ld_nodes, stretched, finite), c, l)


def _one_cycle_of_the_orbit(values):
    """The crank angles are one per angle of the orbit, increasing within a cycle (the march's steps close it)."""
    angle = np.asarray(values["crank_angle"], dtype=float)
    if angle.ndim != 1 or angle.size < 2:
        raise ValueError(f"crank_angle: shape {angle.shape} is not valid; expected (angles,), at least 2")
    within_one_cycle(angle)
    if np.asarray(values["position"]).shape[-2] != angle.size:
        raise ValueError(f"crank_angle: {angle.size} angles, the orbit has {np.asarray(values['position']).shape[-2]}")


@renamed(radius="journal_radius", length="bearing_width")
@validated(method=OneOf(METHODS), position=AngleVectors(), squeeze_velocity=Finite(), free_tilt=Finite(),
           crank_angle=Finite(), compliance=Positive(zero=True), journal_radius=Positive(), bearing_width=Positive(),
           radial_clearance=Positive(), viscosity=Positive(), speed=Positive(),
           relations=(_table_covers_the_bearing, _one_cycle_of_the_orbit))
def march_tilt(position, squeeze_velocity, free_tilt, crank_angle, *, compliance, journal_radius, bearing_width,
               radial_clearance, viscosity, speed, method="short"):
    r"""The journal's tilt in its film over a cycle, marched with the tilt's own squeeze (the dynamic tiers).

    :math:`\boldsymbol\gamma = \boldsymbol\gamma_{free} - C\mathbf M(\boldsymbol\gamma, \dot{\boldsymbol\gamma})`
    on a given mid-plane orbit: the film's moment with the squeeze of the tilting axis,
    :math:`\mathbf u_s = \dot{\boldsymbol\gamma} - \tfrac\omega2\mathbf k\times\boldsymbol\gamma`
    (:mod:`stackup.film.tilt`), by BDF2 steps of about 4 deg crank (the angles between
    take the film's turn-back interpolated), each step's balance solved by Newton inside
    the lens of tilts with both edges off the wall (an edge pressed onto it held there),
    from the aligned journal a quarter of a cycle before the first angle and on until the
    cycle closes (the kernel :func:`stackup._kernels.tilt.marches`). The squeeze damps the tilt:
    an edge approaching the wall meets a film that thickens its pressure like
    :math:`\dot h/h^3`, so where the held tilt puts an edge on the wall for the part
    of the cycle the journal spends there at low load, the marched one lags behind the
    beam and stays off it, as the transient Reynolds reference with the tilt in its
    balance does (``reports/coupled_supports.md``, its last table).

    Parameters
    ----------
    position, squeeze_velocity, free_tilt, compliance, journal_radius, bearing_width, radial_clearance, viscosity, speed, method
        As :func:`cycle_tilt`.
    crank_angle : array_like (angles,)
        Crank angles of the orbit [deg], increasing within one cycle of :data:`CYCLE` deg
        (the journal turns with the crank: a step of the march is the crank angle's, in rad).

    Returns
    -------
    TiltEquilibrium
        ``evaluations`` counts the film moments of every pass at each angle.
    """
    x = np.asarray(position, dtype=float)
    lead, n = x.shape[:-2], x.shape[-2]
    args = _kernel_inputs(x, squeeze_velocity, free_tilt, compliance, journal_radius, bearing_width, radial_clearance,
                          viscosity, speed, method)
    tau = np.ascontiguousarray(np.radians(np.asarray(crank_angle, dtype=float)))
    tilt = np.empty(args.orbits.xi.shape)
    state = np.empty(tilt.shape[:2], np.int8)
    evaluations = np.empty(tilt.shape[:2], np.int64)
    stride = _stride(_kernel.MARCH_STRIDE, n)
    steps = -(-n // stride)
    _kernel.marches(args.orbits, args.correction, _kernel.Solver(quadrature(), ECCENTRICITY_LIMIT, TOLERANCE), tau,
                    np.radians(CYCLE), stride, max(1, round(_kernel.WARMUP * steps)), _kernel.MARCH_CYCLES, tilt, state,
                    evaluations)
    c, l = args.radial_clearance, args.bearing_width
    gamma = tilt.reshape(*lead, n, 2) * (2 * c / l)[..., None, None]
    return TiltEquilibrium(gamma, state.reshape(*lead, n), evaluations.reshape(*lead, n))


def tilted_orbit(position, squeeze, p_max, torque, flow, status, used, tilt, tilt_compliance, *, finite, crank_angle,
                 journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """The :class:`~stackup.film.journal.Orbit` of a mid-plane orbit: its films, and the tilt in them.

    The mid-plane orbit of a cheap tier (journal centre (..., angles, 2) [m], its squeeze velocity [m/s], peak
    pressure, friction torque, side flow, status and cycles) with the ``tilt`` given (..., angles, 2) [rad] or
    None; where a ``tilt_compliance`` turns it back, the tilt in the film is the equilibrium with the film's
    moment (``finite``: finite-corrected where the table covers the bearing, as the mobility-finite tier),
    marched with its squeeze over the ``crank_angle`` of a dynamic tier (:func:`march_tilt`), held at each angle
    of a quasi-static one (``crank_angle`` None, :func:`cycle_tilt`). Geometry (...) radial, SI.
    """
    c = radial_clearance
    ecc = vector_length(position) / c[..., None]
    h_min = c[..., None] * (1 - ecc)
    film_tilt, tilt_state = tilt, None
    if tilt_compliance is not None:
        # the finite correction where its table covers the bearing (as the mobility-finite tier)
        covered = table_covers(bearing_width / (2 * journal_radius))
        film = dict(compliance=tilt_compliance, journal_radius=journal_radius, bearing_width=bearing_width,
                    radial_clearance=c, viscosity=viscosity, speed=speed,
                    method="finite" if finite and covered else "short")
        equilibrium = (cycle_tilt(position, squeeze, tilt, **film) if crank_angle is None
                       else march_tilt(position, squeeze, tilt, crank_angle, **film))
        film_tilt, tilt_state = equilibrium.tilt, equilibrium.state
    h_edge, status = edge_film(position, film_tilt, bearing_width, c, h_min, status, at_limit=tilt_state)
    return Orbit(h_min, h_edge, ecc, position, p_max, torque, flow, status, used, speed, film_tilt, tilt, tilt_state)
