r"""Bearing resource (wear life) from the oil film: the two methods of Levanov et al. (2015).

Method 1 (Rumb's dependence) from the minimum film thickness:

.. math:: R = \left(\frac{\Delta h_{lim}}{\gamma}\right)^{1/\beta_1}, \qquad
          \beta_1 = 1 + \left(\frac{h_{min}}{h_{lim,cr}}\right)^{n_I}

with limiting wear :math:`\Delta h_{lim}` [m], wear speed :math:`\gamma` [m/s],
critical film :math:`h_{lim,cr} = R_{z1} + R_{z2}` (1.9 um in the paper) and
:math:`n_I` between -2.0 and -2.5; :math:`R` in seconds as the paper's
formula gives it (a thick film, :math:`\beta_1 \to 1`, gives
:math:`\Delta h_{lim}/\gamma`; a vanishing film gives 1 s).

Method 2 (molecular-mechanical friction and fatigue wear) accumulates wear only
where :math:`h_{min} < h_{lim,cr}`: per step the conditional wear depth
:math:`\delta = I_h\,2\beta_c R_b` with the wear intensity :math:`I_h = k\,p^m`
(:math:`k = 7\cdot10^{-12}` 1/Pa, :math:`m = 0.0511`), the contact pressure
:math:`p` and the contact half-angle :math:`\beta_c`; the wear rate
:math:`\gamma` is the wear per cycle over the cycle time and
:math:`R = \Delta h_{lim}/\gamma`.

:math:`\alpha`, the share of the cycle with :math:`h_{min} < h_{lim,cr}`,
flags scuffing risk above 20 %.

References
----------
.. [1] Levanov, I. G., Zadorozhnaya, E. A., Mukhortov, I. V., Eschiganov, M. O.,
   "Research of the Resource of Crankshaft Bearings of Internal Combustion
   Engines", Tribology in Industry 37 (2015) 360-365, eqs. 3-7.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import _validate as check

#: Above this share of the cycle in boundary friction the scuffing probability rises sharply (Levanov et al.).
ALPHA_SCUFFING = 0.20


@dataclass(frozen=True)
class Life:
    """Bearing resource.

    Attributes
    ----------
    beta : numpy.ndarray
        Index :math:`\\beta_1` of method 1 [-] (NaN for method 2).
    life : numpy.ndarray
        Resource [s].
    wear_rate : numpy.ndarray
        Wear speed used [m/s].
    """

    beta: np.ndarray
    life: np.ndarray
    wear_rate: np.ndarray

    @property
    def life_hours(self):
        return self.life / 3600.0


def levanov_method1(h_min, *, h_lim_cr=1.9e-6, n=-2.0, wear_limit=30e-6, wear_rate=1e-13):
    """Resource from the minimum film thickness (Levanov et al. 2015, method 1, eqs. 4-5).

    Parameters
    ----------
    h_min : array_like
        Minimum film thickness [m], > 0 (e.g. the minimum over the engine cycle).
    h_lim_cr : float
        Critical film thickness, the sum of the surface roughnesses [m].
    n : float
        Exponent :math:`n_I` [-] (-2.0 to -2.5 in the paper).
    wear_limit : float
        Limiting wear :math:`\\Delta h_{lim}` [m].
    wear_rate : float
        Wear speed :math:`\\gamma` [m/s].

    Returns
    -------
    Life
        ``beta`` and ``life`` [s], broadcast over ``h_min``.
    """
    h_min = check.positive("h_min", h_min)
    h_lim_cr = check.positive("h_lim_cr", h_lim_cr)
    n = check.finite("n", n)
    wear_limit = check.positive("wear_limit", wear_limit)
    wear_rate = check.positive("wear_rate", wear_rate)
    # (h/h_cr)^n in log space: no overflow for a vanishing film
    with np.errstate(over="ignore"):
        beta = 1.0 + np.exp(n * (np.log(h_min) - np.log(h_lim_cr)))
    life = np.exp((np.log(wear_limit) - np.log(wear_rate)) / beta)
    return Life(beta, life, np.broadcast_to(wear_rate, np.shape(life)).astype(float))


def alpha(h_min_history, *, h_lim_cr=1.9e-6, axis=-1):
    """Share of the cycle [-] with the film below ``h_lim_cr`` [m], over ``axis`` (equal steps)."""
    h = check.finite("h_min_history", h_min_history)
    check.positive("h_lim_cr", h_lim_cr)
    return np.mean(h < h_lim_cr, axis=axis)


def levanov_method2(h_min_history, contact_pressure, contact_half_angle, *, bearing_radius, cycle_time,
                    h_lim_cr=1.9e-6, k=7e-12, m=0.0511, wear_limit=30e-6, axis=-1):
    """Resource from wear accumulated where the film is below the critical thickness (method 2, eqs. 6-7).

    Parameters
    ----------
    h_min_history : array_like (..., steps)
        Minimum film thickness at each step of one cycle [m].
    contact_pressure : array_like (..., steps)
        Asperity contact pressure at each step [Pa] (used where the film is below ``h_lim_cr``).
    contact_half_angle : array_like (..., steps)
        Contact half-angle :math:`\\beta_c` at each step [rad].
    bearing_radius : float
        Bearing radius :math:`R_b` [m].
    cycle_time : float
        Duration of one cycle [s] (a four-stroke cycle: 2 revolutions).
    h_lim_cr, k, m, wear_limit : float
        Critical film [m], wear constant [1/Pa], exponent [-], limiting wear [m].

    Returns
    -------
    Life
        ``life`` [s] and ``wear_rate`` [m/s]; an infinite life where the film never drops below ``h_lim_cr``.
    """
    h = check.finite("h_min_history", h_min_history)
    p = check.positive("contact_pressure", contact_pressure, allow_zero=True)
    beta_c = check.in_range("contact_half_angle", contact_half_angle, 0.0, np.pi)
    radius = check.positive("bearing_radius", bearing_radius)
    cycle_time = check.positive("cycle_time", cycle_time)
    check.positive("k", k)
    wear_limit = check.positive("wear_limit", wear_limit)
    boundary = h < h_lim_cr
    depth = np.where(boundary, k * p**m * 2.0 * beta_c * radius, 0.0)
    rate = np.sum(depth, axis=axis) / cycle_time
    with np.errstate(divide="ignore"):
        life = np.where(rate > 0, wear_limit / np.where(rate > 0, rate, 1.0), np.inf)
    return Life(np.full(np.shape(life), np.nan), life, rate)
