r"""Asperity contact of two rough surfaces across a thin film: Greenwood and Tripp (1970).

Nominal contact pressure carried by the asperities at a mean separation
(film thickness) :math:`h` of two Gaussian rough surfaces with composite RMS
roughness :math:`\sigma = \sqrt{R_{q1}^2 + R_{q2}^2}`:

.. math:: p_c(h) = \frac{16\sqrt 2}{15}\,\pi\,(\eta\beta\sigma)^2\sqrt{\frac{\sigma}{\beta}}\;
          E^*\,F_{5/2}\!\left(\frac{h}{\sigma}\right),
          \qquad \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}

with the asperity density :math:`\eta`, asperity tip radius :math:`\beta` and
the Gaussian height integral

.. math:: F_n(\lambda) = \frac{1}{\sqrt{2\pi}}\int_\lambda^\infty (s-\lambda)^n e^{-s^2/2}\,ds
          = \frac{\Gamma(n+1)}{\sqrt{2\pi}}\,e^{-\lambda^2/4}\,D_{-n-1}(\lambda)

(:math:`D_\nu` the parabolic cylinder function; exact, so no polynomial fit
and no cut-off at :math:`\lambda = 4`).

References
----------
.. [1] Greenwood, J. A., Tripp, J. H., "The contact of two nominally flat rough
   surfaces", Proc. IMechE 185 (1970) 625-633.
.. [2] Greenwood, J. A., Williamson, J. B. P., "Contact of nominally flat
   surfaces", Proc. R. Soc. Lond. A 295 (1966) 300-319 (:math:`\eta\beta\sigma`
   of 0.03-0.05 for a wide range of engineering surfaces).
.. [3] Gradshteyn, I. S., Ryzhik, I. M., *Table of Integrals, Series, and
   Products*, 7th ed., 2007, 3.462.1 (the integral in closed form).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import special
from scipy.interpolate import CubicSpline

from ._validate import POISSON, Finite, Positive, validated


@dataclass(frozen=True)
class AsperityParameters:
    """Asperity statistics of the Greenwood-Tripp model.

    Attributes
    ----------
    roughness_parameter : float
        :math:`\\eta\\beta\\sigma` [-].
    slope_parameter : float
        :math:`\\sigma/\\beta` [-].
    source : str
    """

    roughness_parameter: float = 0.04
    slope_parameter: float = 1e-3
    source: str = ("Greenwood & Williamson 1966: eta beta sigma 0.03-0.05 for engineering surfaces (0.04 taken); "
                   "sigma/beta 1e-3, the value commonly used with Greenwood & Tripp 1970 for ground steel "
                   "(the contact pressure scales with its square root)")


#: Typical asperity statistics of ground and fine-bored bearing surfaces.
TYPICAL_ASPERITIES = AsperityParameters()


@validated(separation=Finite())
def gaussian_height_integral(order, separation):
    """:math:`F_n(\\lambda)` of a Gaussian height distribution [-].

    Parameters
    ----------
    order : float
        :math:`n` (> -1; 5/2 for the pressure, 2 for the real area).
    separation : array_like
        :math:`\\lambda = h/\\sigma` [-]; any real value (negative: surfaces
        pushed into each other).
    """
    lam = np.asarray(separation, dtype=float)
    with np.errstate(under="ignore", over="ignore", invalid="ignore"):
        d = special.pbdv(-order - 1.0, lam)[0]
        value = special.gamma(order + 1.0) / np.sqrt(2 * np.pi) * np.exp(-0.25 * lam**2) * d
    # far out of contact the product underflows to 0 (or 0 * inf): there is no contact
    return np.where(np.isfinite(value) & (lam < 40.0), value, np.where(lam < 0, np.inf, 0.0))


#: Separations covered by the table of ln F_5/2 that :func:`greenwood_tripp` interpolates (outside: exact form or 0).
_TABLE_RANGE = (-8.0, 38.0)


@lru_cache(maxsize=1)
def _log_f52_table():
    """Cubic spline of ln F_5/2 on 0.005 steps: the exact form is slow per point, the spline cheap."""
    lam = np.arange(_TABLE_RANGE[0], _TABLE_RANGE[1] + 1e-9, 0.005)
    return CubicSpline(lam, np.log(gaussian_height_integral(2.5, lam)))


def _f52(lam):
    inside = (lam >= _TABLE_RANGE[0]) & (lam < _TABLE_RANGE[1])
    out = np.where(lam >= _TABLE_RANGE[1], 0.0, np.nan)
    out[inside] = np.exp(_log_f52_table()(lam[inside]))
    deep = lam < _TABLE_RANGE[0]
    if deep.any():
        out[deep] = gaussian_height_integral(2.5, lam[deep])
    return out


@validated(modulus_1=Positive(), modulus_2=Positive(), poisson_1=POISSON, poisson_2=POISSON)
def contact_modulus(modulus_1, poisson_1, modulus_2, poisson_2):
    """Contact modulus :math:`E^*` [Pa] of two elastic bodies (moduli [Pa], Poisson's ratios [-])."""
    e1, n1, e2, n2 = (np.asarray(a, dtype=float) for a in (modulus_1, poisson_1, modulus_2, poisson_2))
    return 1.0 / ((1 - n1**2) / e1 + (1 - n2**2) / e2)


@validated(rq_1=Positive(), rq_2=Positive())
def composite_roughness(rq_1, rq_2):
    """Composite RMS roughness :math:`\\sigma = \\sqrt{R_{q1}^2 + R_{q2}^2}` [m]."""
    return np.hypot(np.asarray(rq_1, dtype=float), np.asarray(rq_2, dtype=float))


@validated(film_thickness=Finite(), roughness=Positive(), contact_modulus=Positive())
def greenwood_tripp(film_thickness, *, roughness, contact_modulus, asperities=TYPICAL_ASPERITIES):
    """Nominal asperity contact pressure [Pa] at a film thickness (Greenwood & Tripp 1970).

    Parameters
    ----------
    film_thickness : array_like
        Mean separation of the surfaces [m].
    roughness : array_like
        Composite RMS roughness :math:`\\sigma` [m] (:func:`composite_roughness`).
    contact_modulus : array_like
        :math:`E^*` [Pa] (:func:`contact_modulus`).
    asperities : AsperityParameters

    Returns
    -------
    numpy.ndarray
        [Pa]; positive for every finite film (the Gaussian tail), 0 beyond 38 sigma.

    Notes
    -----
    :math:`F_{5/2}` is interpolated (cubic spline of its logarithm on steps of
    0.005) from the exact form of :func:`gaussian_height_integral`, within
    1e-8 of it (``tests/test_contact.py`` holds it there).
    """
    h = np.asarray(film_thickness, dtype=float)
    sigma = np.asarray(roughness, dtype=float)
    modulus = np.asarray(contact_modulus, dtype=float)
    scale = (16 * np.sqrt(2) / 15 * np.pi * asperities.roughness_parameter**2
             * np.sqrt(asperities.slope_parameter) * modulus)
    return scale * _f52(np.atleast_1d(h / sigma)).reshape(np.shape(h / sigma))


@validated(thickness=Positive(), modulus=Positive(), poisson=POISSON)
def column_stiffness(thickness, modulus, poisson):
    r"""Stiffness of an elastic layer as columns in series (Winkler foundation) [Pa/m].

    Parameters
    ----------
    thickness : array_like (layers,)
        Thickness of each layer under the film, in the order met [m].
    modulus : array_like (layers,)
        Young's modulus of each layer [Pa].
    poisson : array_like (layers,)
        Poisson's ratio of each layer [-].

    Returns
    -------
    float
        :math:`k` with the pressure :math:`p = k\,u` per deflection :math:`u` [Pa/m].

    Notes
    -----
    Each layer a column in uniaxial strain (laterally held by the material
    around it) with the constrained modulus :math:`E' = E(1-\nu)/((1+\nu)(1-2\nu))`,
    the layers in series:

    .. math:: \frac1k = \sum_i \frac{t_i}{E'_i}

    The column model of a thin bearing lining and shell back (Bonneau et al.
    2014, ch. 3: the "elastic foundation" form of the lining's compliance). It
    has no spreading: a column deflects under its own pressure only, which
    over-states the local deflection of a thick layer under a narrow patch and
    leaves out the housing's bending (the support's linear compliance carries
    that, :class:`stackup.engines.Supports`).

    References
    ----------
    .. [1] Bonneau, D., Fatu, A., Souchet, D., *Hydrodynamic Bearings*, ISTE/Wiley, 2014
       (elastic foundation model of the lining).
    .. [2] Johnson, K. L., *Contact Mechanics*, Cambridge University Press, 1985, sec. 5.9
       (the Winkler foundation and its constrained modulus).
    """
    t, e, nu = (np.atleast_1d(np.asarray(a, dtype=float)) for a in (thickness, modulus, poisson))
    constrained = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    return float(1.0 / np.sum(t / constrained))


@dataclass(frozen=True)
class LayerContact:
    """Film and asperity pressure on an elastic layer (:func:`layer_contact`).

    Attributes
    ----------
    film : numpy.ndarray
        Separation of the mean planes with the layer deflected [m].
    pressure : numpy.ndarray
        Asperity contact pressure [Pa].
    """

    film: np.ndarray
    pressure: np.ndarray


#: Bisection steps of :func:`layer_contact` (the bracket shrinks 2^-60).
LAYER_BISECTIONS = 60


@validated(rigid_film=Finite(), roughness=Positive(), contact_modulus=Positive(), stiffness=Positive())
def layer_contact(rigid_film, *, roughness, contact_modulus, stiffness, asperities=TYPICAL_ASPERITIES):
    r"""Film and asperity pressure where a rigid film is closed by the asperities on an elastic layer.

    Parameters
    ----------
    rigid_film : array_like
        Film the rigid surfaces would leave [m]; negative where they would overlap.
    roughness : float
        Composite RMS roughness :math:`\sigma` [m].
    contact_modulus : float
        :math:`E^*` of the asperities [Pa] (:func:`contact_modulus`).
    stiffness : float
        The layer's stiffness :math:`k` [Pa/m] (:func:`column_stiffness`).
    asperities : AsperityParameters

    Returns
    -------
    LayerContact

    Notes
    -----
    The layer deflects by :math:`u = p_c/k` under the asperity pressure of
    Greenwood and Tripp (:func:`greenwood_tripp`), which opens the film:

    .. math:: h = h_r + \frac{p_c(h)}{k}

    with :math:`p_c` falling with :math:`h`, so one root, found by bisection in
    :math:`[h_r, h_r + p_c(h_r)/k]`. Where the rigid surfaces overlap by much
    more than the roughness the layer takes the overlap, :math:`p_c \to k(-h_r)`.
    The film pressure is left out: at a bearing's edge it is ambient.
    """
    h_r = np.asarray(rigid_film, dtype=float)

    def pressure(h):
        return greenwood_tripp(h, roughness=roughness, contact_modulus=contact_modulus, asperities=asperities)

    lo = h_r.copy()
    hi = h_r + pressure(h_r) / stiffness
    for _ in range(LAYER_BISECTIONS):
        mid = 0.5 * (lo + hi)
        above = mid - h_r - pressure(mid) / stiffness > 0
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    h = 0.5 * (lo + hi)
    return LayerContact(h, stiffness * (h - h_r))
