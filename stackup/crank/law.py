r"""Main-bearing behaviour law of Bellakhdhar et al. (2013), in overflow-free form.

The force a journal displaced by :math:`\mathbf U` from its bearing centre
exerts on the bearing acts along :math:`\mathbf U` with magnitude

.. math:: R(U, \theta) = K_d(\theta)\, g(U), \qquad
          K_d(\theta) = k_{lv} + \frac{k_{hv} - k_{lv}}{1 + \exp\frac{\theta_0 - \theta}{\Delta\theta}}

.. math:: g(U) = dx\,(1 + e^{-J/dx}) \ln\frac{1 + e^{(U - J)/dx}}{1 + e^{-J/dx}} - U e^{-J/dx}

(their eqs. 4-7): clearance parameter :math:`J`, transition width :math:`dx`,
deformation stiffness :math:`K_d` between :math:`k_{lv}` (load towards the cap,
:math:`\theta = 0`) and :math:`k_{hv}` (:math:`\theta = 180°`). The logarithm
is written with the softplus :math:`\ln(1 + e^x)` and the stiffness
:math:`g'(U) = 1 - (1 + e^{-J/dx})/(1 + e^{(U-J)/dx})` with the logistic
function, so neither overflows for :math:`U \gg dx`; :math:`dx = 0` is the
bilinear limit :math:`g = \max(U - J, 0)`. :math:`g'(0) = 0`: the law has no
stiffness at rest, which the solver must handle.

Frame: component 0 points from the crank axis towards the bearing cap (the
direction gas loads push the journal), component 1 is transverse; :math:`\theta`
is the angle of :math:`\mathbf U` from component 0, in :math:`[0, \pi]`
(the law is taken symmetric left/right).

References
----------
.. [1] Bellakhdhar, B., Dogui, A., Ligier, J.-L., "A simplified coupled
   crankshaft-engine block model", C. R. Mecanique 341 (2013) 743-754.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import radians

import numpy as np
from scipy import special

from .. import _validate as check
from .._validate import Positive, renamed, validated

#: Displacement below which a journal is at rest: no force, no stiffness [m].
REST = 1e-150


@dataclass(frozen=True)
class BellakhdharLaw:
    """Parameters of the bearing law; each may be an array per bearing (broadcast).

    Parameters
    ----------
    clearance : array_like
        Clearance parameter :math:`J` [m] (37 um identified for 30 um radial clearance).
    dx : array_like
        Transition width [m] (9.65 um); 0 gives the bilinear limit.
    k_lv, k_hv : array_like
        Deformation stiffness towards the cap and towards the block [N/m].
    theta0, dtheta : array_like
        Centre and width of the stiffness transition [rad].
    """

    clearance: object = 37e-6
    dx: object = 9.65e-6
    k_lv: object = 0.98e9
    k_hv: object = 1.72e9
    theta0: object = radians(97.0)
    dtheta: object = radians(15.0)

    def __post_init__(self):
        check.fields(self, {"clearance": check.Positive(zero=True), "dx": check.Positive(zero=True),
                            "k_lv": check.Positive(), "k_hv": check.Positive(), "theta0": check.Finite(),
                            "dtheta": check.Positive()}, prefix="law ")

    def arrays(self, shape):
        """The six parameters broadcast to ``shape`` (float arrays)."""
        return [np.broadcast_to(np.asarray(getattr(self, k), dtype=float), shape)
                for k in ("clearance", "dx", "k_lv", "k_hv", "theta0", "dtheta")]


def gap_function(u, clearance, dx):
    """:math:`g(U)` [m] and :math:`g'(U)` [-] of the law, overflow-free."""
    u = np.asarray(u, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        bilinear = dx == 0
        safe_dx = np.where(bilinear, 1.0, dx)
        e = np.where(bilinear, 0.0, np.exp(-clearance / safe_dx))
        sp = np.logaddexp(0.0, (u - clearance) / safe_dx) - np.logaddexp(0.0, -clearance / safe_dx)
        g = np.where(bilinear, np.maximum(u - clearance, 0.0), safe_dx * (1.0 + e) * sp - u * e)
        dg = np.where(bilinear, (u > clearance).astype(float), 1.0 - (1.0 + e) * special.expit(-(u - clearance) / safe_dx))
    return g, dg


def stiffness(theta, k_lv, k_hv, theta0, dtheta):
    """:math:`K_d(\\theta)` [N/m] and :math:`dK_d/d\\theta` [N/m/rad]."""
    s = special.expit((theta - theta0) / dtheta)
    return k_lv + (k_hv - k_lv) * s, (k_hv - k_lv) * s * (1.0 - s) / dtheta


def force(u_vec, law_arrays):
    """Bearing force (..., 2) [N] and its Jacobian d F / d U (..., 2, 2) [N/m] for displacements (..., 2) [m]."""
    clearance, dx, k_lv, k_hv, theta0, dtheta = law_arrays
    u0, u1 = u_vec[..., 0], u_vec[..., 1]
    mag = np.hypot(u0, u1)
    tiny = mag < REST
    safe = np.where(tiny, 1.0, mag)
    c = np.where(tiny, 1.0, u0 / safe)
    s_abs = np.where(tiny, 0.0, np.abs(u1) / safe)
    sign = np.where(u1 >= 0, 1.0, -1.0)
    theta = np.arctan2(s_abs, c)
    g, dg = gap_function(mag, clearance, dx)
    kd, dkd = stiffness(theta, k_lv, k_hv, theta0, dtheta)
    unit = np.stack([c, sign * s_abs], axis=-1)
    tangent = np.stack([-s_abs, sign * c], axis=-1)
    f = np.where(tiny, 0.0, kd * g)[..., None] * unit  # at rest: no force, no stiffness
    radial = np.where(tiny, 0.0, kd * dg)[..., None, None] * unit[..., :, None] * unit[..., None, :]
    hoop = np.where(tiny, 0.0, kd * g / safe)[..., None, None] * tangent[..., :, None] * tangent[..., None, :]
    turn = np.where(tiny, 0.0, g * dkd / safe)[..., None, None] * unit[..., :, None] * tangent[..., None, :]
    return f, radial + hoop + turn


#: The law as Bellakhdhar et al. identified it (one bearing, 30 um radial clearance, 4000 rpm, 5 mPa s).
PAPER_LAW = BellakhdharLaw()


@dataclass(frozen=True)
class LawFit:
    """Bearing law fitted to a film's load-displacement curve (arrays over the bearings fitted).

    Attributes
    ----------
    law : BellakhdharLaw
        Fitted ``clearance`` (J) and ``dx`` per bearing [m], the given stiffnesses and sigmoid.
    rms_error, max_error : numpy.ndarray
        Root-mean-square and largest difference between the law's displacement and
        the film's plus the structure's, over the samples and both load directions [m].
    converged : numpy.ndarray of bool
    """

    law: BellakhdharLaw
    rms_error: np.ndarray
    max_error: np.ndarray
    converged: np.ndarray


def displacement(load, clearance, dx, stiffness):
    """Displacement U [m] at which the law carries ``load`` [N] with deformation stiffness ``stiffness`` [N/m].

    Inverse of :math:`K_d\\,g(U) = R`: Newton from above the root (g is convex and
    increasing, so the iterates fall monotonically onto it).
    """
    target = np.asarray(load, dtype=float) / stiffness
    u = target + clearance + 10.0 * dx
    for _ in range(100):
        g, dg = gap_function(u, clearance, dx)
        step = (g - target) / np.maximum(dg, 1e-12)
        u = np.maximum(u - step, 0.0)
        if np.all(np.abs(step) <= 1e-15 + 1e-12 * u):
            break
    return u


def _one_curve(values):
    load, film = values["load"], values["film_displacement"]
    if load.shape != film.shape:
        raise ValueError(f"film_displacement: shape {film.shape} is not that of load {load.shape}")


@renamed(clearance_guess="radial_clearance")
@validated(load=Positive(), film_displacement=Positive(zero=True), radial_clearance=Positive(),
           relations=(_one_curve,))
def fit_bellakhdhar(load, film_displacement, *, k_lv, k_hv, theta0, dtheta, radial_clearance):
    r"""Clearance parameter J and transition dx of the bearing law from a film's load-displacement curve.

    As Bellakhdhar et al. (2013, sec. 4.3) built their law: the journal's
    displacement under a load :math:`R` is the film's eccentric displacement plus
    the structure's, :math:`U = U_h(R) + R/K_d(\theta)`; J and dx minimise the
    squared difference between the law's displacement :math:`U` (the root of
    :math:`K_d\,g(U) = R`) and that sum, over the samples and both vertical load
    directions (:math:`\theta = 0`, towards the cap, and :math:`\pi`), by
    Levenberg-Marquardt vectorised over the bearings. The stiffnesses and the
    sigmoid stay as given (they are the structure's, from a finite-element model).

    Parameters
    ----------
    load : array_like (..., samples)
        Bearing loads [N], > 0 (e.g. from :func:`stackup.film.bearing_law.load_displacement`).
    film_displacement : array_like (..., samples)
        Journal centre displacement of the steady film under each load [m]
        (eccentricity times the radial clearance).
    k_lv, k_hv, theta0, dtheta : float or array_like (...)
        Deformation stiffnesses [N/m] and the sigmoid's centre and width [rad].
    radial_clearance : array_like (...)
        Radial clearance of the bearings [m]: the starting J and dx scale with it as
        in the paper (37 and 9.65 um for 30 um).

    Returns
    -------
    LawFit
    """
    load = np.asarray(load, dtype=float)
    film = np.asarray(film_displacement, dtype=float)
    lead = load.shape[:-1]
    c = np.broadcast_to(np.asarray(radial_clearance, dtype=float), lead)
    k_lv, k_hv, theta0, dtheta = (np.broadcast_to(np.asarray(a, dtype=float), lead)
                                  for a in (k_lv, k_hv, theta0, dtheta))
    kd = np.stack([stiffness(np.zeros(lead), k_lv, k_hv, theta0, dtheta)[0],
                   stiffness(np.full(lead, np.pi), k_lv, k_hv, theta0, dtheta)[0]], axis=-1)  # (..., 2)
    loads = np.concatenate([load, load], axis=-1)
    k_each = np.repeat(kd, load.shape[-1], axis=-1)
    target = np.concatenate([film, film], axis=-1) + loads / k_each

    def residual(params):
        j, dx = (params[..., i : i + 1] for i in range(2))
        return displacement(loads, j, dx, k_each) - target

    params = np.stack([c * 37.0 / 30.0, c * 9.65 / 30.0], axis=-1)
    params, r, converged = _levenberg_marquardt(residual, params, floor=1e-3 * c[..., None], small=1e-10 * c)
    law = BellakhdharLaw(clearance=params[..., 0], dx=params[..., 1], k_lv=k_lv, k_hv=k_hv, theta0=theta0,
                         dtheta=dtheta)
    return LawFit(law, np.sqrt((r**2).mean(axis=-1)), np.abs(r).max(axis=-1), converged)


def _levenberg_marquardt(residual, params, *, floor, small, iterations=100):
    """Least squares of ``residual(params)`` (..., samples) over params (..., 2), vectorised over the leading axes.

    Forward-difference Jacobian, Marquardt's diagonal damping; params held above ``floor``; a fit has converged
    once a step that does not worsen it is below ``small``. Returns (params, residual there, converged).
    """
    lead = params.shape[:-1]
    damping = np.full(lead, 1e-3)
    r = residual(params)
    cost = (r**2).sum(axis=-1)
    converged = np.zeros(lead, bool)
    for _ in range(iterations):
        jac = np.empty((*r.shape, 2))
        for i in range(2):
            h = 1e-6 * params[..., i : i + 1]
            shifted = params.copy()
            shifted[..., i : i + 1] += h
            jac[..., i] = (residual(shifted) - r) / h
        jtj = np.einsum("...ki,...kj->...ij", jac, jac)
        jtr = np.einsum("...ki,...k->...i", jac, r)
        diag = np.einsum("...ii->...i", jtj)
        step = -np.linalg.solve(jtj + (damping[..., None] * diag)[..., None] * np.eye(2), jtr[..., None])[..., 0]
        trial = np.maximum(params + step, floor)  # J and dx stay positive
        r_trial = residual(trial)
        cost_trial = (r_trial**2).sum(axis=-1)
        better = cost_trial < cost
        converged |= (np.abs(trial - params).max(axis=-1) <= small) & (better | (cost_trial == cost))
        params = np.where(better[..., None], trial, params)
        r = np.where(better[..., None], r_trial, r)
        cost = np.where(better, cost_trial, cost)
        damping = np.where(better, damping / 3, damping * 4)
        if np.all(converged):
            break
    return params, r, converged
