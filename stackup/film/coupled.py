r"""The crankshaft's support moments over the cycle: every main bearing's tilt, with the block, as one system.

Rozhdestvensky et al. (2018) solve the crankshaft as a statically indeterminate
beam whose unknowns include the moments at its supports (their eq. 5), each
support a film (linear and angular compliance :math:`K_L^\lambda`, :math:`K_L^\varphi`,
their eq. 6) in series with the block (:math:`K_s^\lambda`, :math:`K_s^\varphi`). Here the
crankshaft's linear part is the film tier's mid-plane orbit (the crankshaft on its
bearing law, the support's linear compliance in the law's stiffness, the journal
aligned); each journal's centre then moves by :math:`\boldsymbol\delta_j` from that orbit so
that its tilted film carries the same load,

.. math:: \mathbf F_j(\mathbf x_j + \boldsymbol\delta_j, \mathbf v_j + \mathbf v_{\delta,j},
          \boldsymbol\gamma_j, \dot{\boldsymbol\gamma}_j) = \mathbf F_j(\mathbf x_j, \mathbf v_j, 0, 0)

(a tilt makes one edge's film thinner and the film stronger: at a held centre
the tilted film of the paper's diesel carries up to twice the load), and the moments
:math:`\mathbf M_i` the films pass to the supports satisfy, per bending plane :math:`c` and at
every crank angle,

.. math:: \gamma_{j,c} = \gamma^{free}_{j,c} - \sum_i \left(C^{crank}_{c,ji} + \delta_{ji}K^\varphi_{s,j,c}\right) M_{i,c}(\boldsymbol\xi_i, \boldsymbol\gamma_i, \dot{\boldsymbol\gamma}_i)

with :math:`\boldsymbol\gamma_j` the journal's tilt against its bore,
:math:`\boldsymbol\gamma^{free}` the beam's slope without support moments
(:func:`stackup.crank.support_slopes`), :math:`C^{crank}` the crankshaft's
rotational compliance between its supports, deflections held
(:func:`stackup.crank.support_compliance` with ``coupled=True``: a moment at one
support turns the others) and :math:`K^\varphi_s` the support's angular compliance
(the bore turns with the bulkhead and by its ring's own deformation across the
width, :attr:`stackup.crank.housing.Supports.tilt_compliance`). The
film's moment :math:`\mathbf M = \iint p\,z\,\mathbf n\,dA` is the short-bearing film's
(:mod:`stackup.film.tilt`, finite-corrected in the ``finite`` method) with the tilt's
own squeeze, :math:`\mathbf u_s = \dot{\boldsymbol\gamma} - \tfrac\omega2\mathbf k\times\boldsymbol\gamma`,
plus the asperities' on an elastic layer:

- **elastic layer**: lining and shell back as columns in series
  (:func:`stackup.contact.column_stiffness`); where the rigid film at a point
  falls towards the roughness the asperities carry a pressure
  (Greenwood-Tripp) that deflects the layer, :math:`h = h_r + p_c(h)/k`
  (:func:`stackup.contact.layer_contact`). At the bearing's edge the film
  pressure is ambient, so there the layer's deflection is the asperities':
  the thinnest film over the surface is that of the thinnest rigid film (an
  edge) through the layer, a computed number, negative where the mean planes
  pass each other (heavy asperity contact);
- the film's moment is taken with both edges inside the eccentricity limit
  (beyond, held there): the asperities on the layer carry the rest.

Time: backward Euler in the centre's move and the tilt (their squeeze) at every
``stride``-th crank angle, all bearings of an engine in one Newton (:math:`4B`
unknowns; the force rows :math:`\partial\bar{\mathbf F}_j/\partial(\boldsymbol\delta_j, \mathbf e_j)`, the
turn-back rows :math:`I + \bar\kappa\,\partial\bar{\mathbf M}/\partial(\boldsymbol\delta, \mathbf e)`, each
bearing's block by differences), from the quasi-static balance at the first angle,
cycle after cycle until the state repeats within :data:`PERIODIC` of the thinnest
film; the angles between take the centre's move and the film's turn-back (free
minus tilt) interpolated.

Simplifications (their error against the transient reference, which carries
the tilt with its squeeze in its own film but a rigid layer, is measured in
``reports/coupled_supports.md``):

- the load is the film tier's own film force on its untilted orbit (the same
  short-bearing film, finite-corrected at the orbit's state, on both sides), and
  the reactions the moments add (:math:`\Delta R \sim M/l`) are left out of it;
  the centre's move has its own squeeze velocity (backward Euler) on top of the
  orbit's;
- the elastic layer deflects under the asperities' pressure only, not under
  the film's (no EHD inside the bearing);
- the supports' thermal offsets and the tolerances enter through the beam's
  free slope.

References
----------
.. [1] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), eqs. 4-6.
.. [2] Greenwood, J. A., Tripp, J. H., Proc. IMechE 185 (1970) 625-633.
.. [3] Booker, J. F., J. Basic Eng. 87 (1965) 537-546 (rotation and squeeze as one squeeze velocity).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._kernels import coupled as _kernel
from .._kernels.mobility import Correction
from .._validate import AngleVectors, Finite, InRange, Integer, OneOf, Positive, validated
from ..contact import TYPICAL_ASPERITIES, layer_contact
from .journal import ECCENTRICITY_LIMIT, mobility_table, short_table, table_covers
from .tilt import quadrature

#: States of a bearing's support moments over the cycle (flag values 0..2).
STATES = ("periodic", "not_periodic", "failed")
METHODS = ("short", "finite")
#: Crank angles between the solved ones (a 720-angle cycle; the same crank angle on other grids).
STRIDE = 8
#: Most cycles of the march, Newton tolerance and periodicity tolerance (shares of the thinnest film).
CYCLES = 8
TOLERANCE = 1e-2
PERIODIC = 2e-2
#: Most Newton iterations per solved angle.
CHORDS = 30
#: Gauss-Legendre nodes of the asperity patch: around the bearing, along a line.
CONTACT_NODES = (12, 8)
#: The elastic layer's table: rigid films from LAYER_RANGE[0] to LAYER_RANGE[1] composite roughnesses, this step.
LAYER_RANGE = (-400.0, 8.0)
LAYER_STEP = 0.02


@dataclass(frozen=True)
class ElasticLayer:
    """The bearing's surface under the film: its stiffness and the asperities on it.

    Attributes
    ----------
    stiffness : float
        Column stiffness of lining and shell back [Pa/m] (:func:`stackup.contact.column_stiffness`).
    roughness : float
        Composite RMS roughness [m].
    contact_modulus : float
        :math:`E^*` of journal and lining [Pa].
    asperities : stackup.contact.AsperityParameters
    """

    stiffness: float
    roughness: float
    contact_modulus: float
    asperities: object = TYPICAL_ASPERITIES

    def table(self):
        """The layer's :data:`stackup._kernels.coupled.Layer` in units of the roughness (computed once per layer)."""
        return _layer_table(self.stiffness, self.roughness, self.contact_modulus, self.asperities)

    def film(self, rigid_film):
        """The film over the layer [m] at rigid films [m] (the table the kernels read, interpolated)."""
        lo, step, film, _ = self.table()
        lam = np.asarray(rigid_film, dtype=float) / self.roughness
        grid = lo + step * np.arange(film.size)
        return np.where(lam >= grid[-1], lam, np.interp(lam, grid, film)) * self.roughness


@lru_cache(maxsize=16)
def _layer_table(stiffness, roughness, modulus, asperities):
    grid = np.arange(LAYER_RANGE[0], LAYER_RANGE[1] + 0.5 * LAYER_STEP, LAYER_STEP)
    out = layer_contact(grid * roughness, roughness=roughness, contact_modulus=modulus, stiffness=stiffness,
                        asperities=asperities)
    film, pressure = out.film / roughness, out.pressure
    # the top is the rigid film itself, without contact: continuous into the kernel's "above the table"
    film[-1], pressure[-1] = grid[-1], 0.0
    for a in (film, pressure):
        a.setflags(write=False)
    return _kernel.Layer(float(grid[0]), LAYER_STEP, film, pressure)


@lru_cache(maxsize=1)
def _contact_rule():
    around, along = (np.polynomial.legendre.leggauss(n) for n in CONTACT_NODES)
    return _kernel.ContactRule(*around, *along)


@dataclass(frozen=True)
class SupportMoments:
    """Tilt of every journal in its bearing over the cycle, with the support moments balanced (:func:`support_moments`).

    Attributes
    ----------
    tilt : numpy.ndarray (engines, bearings, angles, 2)
        Slope of the journal against its bore [rad].
    centre : numpy.ndarray (engines, bearings, angles, 2)
        Journal centre at the mid-plane against the bearing's [m]: the film tier's orbit moved so that the
        tilted journal's film carries the same load.
    film : numpy.ndarray (engines, bearings, angles)
        Thinnest film over the bearing surface, on the elastic layer [m].
    state : numpy.ndarray of int8 (engines, bearings)
        Index into :data:`STATES`; ``failed`` with the film NaN and the free tilt for every bearing of an engine
        whose orbit is not a number at some bearing (its bearings are one system).
    evaluations : numpy.ndarray (engines, bearings)
        Sweeps of every bearing's film moment (the cost).
    unresolved : numpy.ndarray (engines, bearings)
        Share of the last cycle's solved crank angles whose Newton ended on short steps without its full step on a
        fresh matrix within the tolerance (the force and turn-back balance not resolved there; the same for every
        bearing of an engine); NaN where the march did not run.
    """

    tilt: np.ndarray
    centre: np.ndarray
    film: np.ndarray
    state: np.ndarray
    evaluations: np.ndarray
    unresolved: np.ndarray


def squeeze_velocity(position, crank_angle, speed):
    r"""Squeeze velocity of an orbit, :math:`\mathbf v_s = \dot{\mathbf x} - \tfrac\omega2\mathbf k\times\mathbf x` [m/s].

    ``position`` (..., angles, 2) [m] over one cycle of equal steps ``crank_angle`` [deg], ``speed`` (...)
    [rad/s]: :math:`\dot{\mathbf x}` by central differences around the closed cycle.
    """
    x = np.asarray(position, dtype=float)
    w = np.asarray(speed, dtype=float)[..., None, None]
    step = np.radians(float(crank_angle[1] - crank_angle[0])) if len(crank_angle) > 1 else 4 * np.pi
    rate = (np.roll(x, -1, axis=-2) - np.roll(x, 1, axis=-2)) / (2 * step) * w
    return rate - 0.5 * w * np.stack([-x[..., 1], x[..., 0]], axis=-1)


def _shapes(values):
    """Relation: positions and free tilts (engines, bearings, angles, 2), compliance (2, B, B) or (engines, 2, B, B),
    the per-bearing inputs broadcasting to (engines, bearings)."""
    x, free, kappa = values["position"], values["free_tilt"], values["compliance"]
    if x.ndim != 4 or free.shape != x.shape:
        raise ValueError(f"position {x.shape} and free_tilt {free.shape}: expected one shape (engines, bearings, "
                         "angles, 2)")
    b = x.shape[1]
    if kappa.shape[-3:] != (2, b, b) or kappa.ndim not in (3, 4):
        raise ValueError(f"compliance: shape {kappa.shape} is not valid; expected (2, {b}, {b}) or (engines, 2, "
                         f"{b}, {b})")
    diagonal = np.diagonal(kappa, axis1=-2, axis2=-1)
    if np.any(diagonal < 0):
        raise ValueError(f"compliance: a diagonal value {float(diagonal.min())!r} is not valid; a support's own "
                         "compliance must be >= 0")
    if values["crank_angle"].shape != (x.shape[2],):
        raise ValueError(f"crank_angle: {values['crank_angle'].shape} does not match the {x.shape[2]} angles")


def _layer(field, layer):
    if not isinstance(layer, ElasticLayer):
        raise ValueError(f"{field}: {layer!r} is not an ElasticLayer")
    Positive()(f"{field}.stiffness", layer.stiffness)
    Positive()(f"{field}.roughness", layer.roughness)
    Positive()(f"{field}.contact_modulus", layer.contact_modulus)
    return layer


@validated(position=AngleVectors(), free_tilt=Finite(), crank_angle=Finite(), compliance=Finite(),
           journal_radius=Positive(), bearing_width=Positive(), radial_clearance=Positive(), viscosity=Positive(),
           speed=Positive(), layer=_layer, method=OneOf(METHODS), stride=Integer(minimum=1),
           cycles=Integer(minimum=1), tolerance=InRange(0.0, 1.0, lo_open=True), relations=(_shapes,))
def support_moments(position, free_tilt, crank_angle, *, compliance, journal_radius, bearing_width, radial_clearance,
                    viscosity, speed, layer, method="finite", stride=None, cycles=CYCLES, tolerance=TOLERANCE):
    r"""Every journal's tilt over the cycle with the support moments balanced, all bearings of an engine together.

    Parameters
    ----------
    position : array_like (engines, bearings, angles, 2)
        The film tier's mid-plane orbit: journal centre against the bearing's [m].
    free_tilt : array_like (engines, bearings, angles, 2)
        The beam's slope at each support without support moments [rad] (:func:`stackup.crank.support_slopes`).
    crank_angle : array_like (angles,)
        Equal steps over one cycle [deg].
    compliance : array_like (2, bearings, bearings) or (engines, 2, bearings, bearings)
        Per bending plane, the turn of the journal against its bore at j per unit moment at i [rad/(N m)]:
        the crankshaft's rotational compliance between its supports plus, on the diagonal, the support's
        angular compliance (0 everywhere: a rigid crankshaft and block, the free tilt held).
    journal_radius, bearing_width, radial_clearance, viscosity, speed : float or array_like (engines, bearings)
        [m], [m], [m], [Pa s], [rad/s].
    layer : ElasticLayer
    method : {"short", "finite"}
        The film's moment: short bearing, or finite-corrected as the ``mobility-finite`` tier (L/D 0.15-1).
    stride : int, optional
        Crank angles between the solved ones (default :data:`STRIDE` on a 720-angle cycle).
    cycles : int
        Most cycles of the march.
    tolerance : float
        Newton's, a share of the thinnest film.

    Returns
    -------
    SupportMoments
    """
    x = np.asarray(position, dtype=float)
    n_e, n_b, n = x.shape[:3]
    angle = np.asarray(crank_angle, dtype=float)
    each = {k: np.broadcast_to(np.asarray(v, dtype=float), (n_e, n_b)) for k, v in (
        ("r", journal_radius), ("l", bearing_width), ("c", radial_clearance), ("mu", viscosity), ("w", speed))}
    r, l, c, mu, w = (each[k] for k in ("r", "l", "c", "mu", "w"))
    v = squeeze_velocity(x, angle, w)
    xi = np.ascontiguousarray(x / c[..., None, None])
    vbar = np.ascontiguousarray(v / (c * w)[..., None, None])
    free = np.ascontiguousarray(np.asarray(free_tilt, dtype=float) * (l / (2 * c))[..., None, None])
    kappa = np.broadcast_to(np.asarray(compliance, dtype=float), (n_e, 2, n_b, n_b))
    # edge offset of j per unit dimensionless moment of i: (L_j / 2 c_j) C_ji (mu_i omega R_i L_i^4 / c_i^2)
    unit = mu * w * r * l**4 / c**2
    kbar = np.ascontiguousarray(kappa * (l / (2 * c))[:, None, :, None] * unit[:, None, None, :])
    finite = method == "finite" and table_covers(l / (2 * r))
    ld_nodes, stretched, tables = mobility_table() if finite else short_table()
    step = np.radians(float(angle[1] - angle[0])) if n > 1 else 4 * np.pi
    if stride is None:
        stride = max(1, int(round(STRIDE * n / 720)))
    engines = _kernel.Engines(xi, vbar, free, kbar, np.ascontiguousarray(layer.roughness / c),
                              np.ascontiguousarray(c**2 / (mu * w * l**2)), np.ascontiguousarray(l / (2 * r)))
    march = _kernel.March(step, int(stride), int(cycles), float(tolerance), CHORDS, ECCENTRICITY_LIMIT, PERIODIC)
    tilt = np.zeros((n_e, n_b, n, 2))
    shift = np.zeros((n_e, n_b, n, 2))
    film = np.full((n_e, n_b, n), np.nan)
    state = np.full((n_e, n_b), STATES.index("failed"), np.int8)
    evaluations = np.zeros((n_e, n_b), np.int64)
    unresolved = np.full((n_e, n_b), np.nan)
    # an engine with a film that is not a number (an orbit that failed, a collapsed film: NaN centres) cannot be
    # balanced, its bearings being one system: its tilt is the free one, its film NaN, its state failed
    ok = np.isfinite(xi).all(axis=(1, 2, 3)) & np.isfinite(vbar).all(axis=(1, 2, 3)) & np.isfinite(kbar).all(
        axis=(1, 2, 3)) & np.isfinite(free).all(axis=(1, 2, 3))
    tilt[~ok] = free[~ok]
    if ok.any():
        run = _kernel.Engines(*(np.ascontiguousarray(a[ok]) for a in engines))
        parts = [np.empty((int(ok.sum()), *a.shape[1:]), a.dtype) for a in (tilt, shift, film, state, evaluations,
                                                                                unresolved)]
        _kernel.march_engines(run, Correction(tables, ld_nodes, stretched, finite), layer.table(), quadrature(),
                              _contact_rule(), march, *parts)
        for whole, part in zip((tilt, shift, film, state, evaluations, unresolved), parts):
            whole[ok] = part
    cc = c[..., None, None]
    return SupportMoments(tilt * (2 * c / l)[..., None, None], x + shift * cc, film * c[..., None], state,
                          evaluations, unresolved)
