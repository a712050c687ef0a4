r"""Steady-load film tiers in closed form: the short bearing (Ocvirk).

Short bearing, half-Sommerfeld film (Ocvirk 1952), radius :math:`R`, length
:math:`L`, radial clearance :math:`c`, surface speed :math:`U = \omega R`:

.. math:: W = \frac{\mu U L^3}{4 c^2}\,\frac{\varepsilon\sqrt{\pi^2(1-\varepsilon^2) + 16\varepsilon^2}}{(1-\varepsilon^2)^2},
          \qquad \tan\varphi = \frac{\pi\sqrt{1-\varepsilon^2}}{4\varepsilon}

friction torque on the journal (full-film shear plus the pressure couple)
:math:`T_f = \frac{2\pi\mu\omega R^3 L}{c\sqrt{1-\varepsilon^2}} + \frac{\varepsilon c W \sin\varphi}{2}`,
side flow :math:`Q = \varepsilon U c L`.

References
----------
.. [1] Ocvirk, F. W., "Short-bearing approximation for full journal bearings",
   NACA TN 2808, 1952.
.. [2] Hamrock, B. J., Schmid, S. R., Jacobson, B. O., *Fundamentals of Fluid
   Film Lubrication*, 2nd ed., Dekker, 2004, ch. 10.
"""

from __future__ import annotations

import numpy as np

from .._validate import renamed


def short_load_function(eps):
    """Dimensionless load :math:`\\varepsilon\\sqrt{\\pi^2(1-\\varepsilon^2)+16\\varepsilon^2}/(1-\\varepsilon^2)^2`."""
    return eps * np.sqrt(np.pi**2 * (1 - eps**2) + 16 * eps**2) / (1 - eps**2) ** 2


#: Largest eccentricity below 1 in floating point: the steady tiers never return a film of zero thickness.
ECCENTRICITY_CEILING = float(np.nextafter(1.0, 0.0))


def invert_monotone(function, target, *, iterations=200):
    """Eccentricity in [0, 1) where the increasing ``function(eps)`` (0 at 0) equals ``target`` (vectorised bisection).

    A zero target gives exactly 0; a target beyond what ``function`` reaches
    in floating point gives :data:`ECCENTRICITY_CEILING`.
    """
    target = np.asarray(target, dtype=float)
    lo = np.zeros(target.shape)
    hi = np.ones(target.shape)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        for _ in range(iterations):
            mid = 0.5 * (lo + hi)
            above = function(mid) > target
            hi = np.where(above, mid, hi)
            lo = np.where(above, lo, mid)
            if np.all(hi - lo < 1e-15):
                break
    return np.where(target > 0, np.minimum(0.5 * (lo + hi), ECCENTRICITY_CEILING), 0.0)


@renamed(radius="journal_radius", length="bearing_width")
def film_quantities(eps, attitude, load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """h_min [m], friction torque [N m], side flow [m^3/s] of a film at eccentricity ``eps`` (short-bearing forms)."""
    radius, length = journal_radius, bearing_width
    h_min = radial_clearance * (1 - eps)
    torque = (2 * np.pi * viscosity * speed * radius**3 * length / (radial_clearance * np.sqrt(1 - eps**2))
              + eps * radial_clearance * load * np.sin(attitude) / 2)
    flow = eps * speed * radius * radial_clearance * length
    return h_min, torque, flow


@renamed(radius="journal_radius", length="bearing_width")
def short(load, *, journal_radius, bearing_width, radial_clearance, viscosity, speed):
    """Eccentricity and attitude angle [rad] of a short bearing under a steady load [N] (>= 0).

    Zero load gives the concentric journal (attitude pi/2, the limit of the closed form).
    """
    scale = viscosity * speed * journal_radius * bearing_width**3 / (4 * radial_clearance**2)
    eps = invert_monotone(short_load_function, load / scale)
    attitude = np.arctan2(np.pi * np.sqrt(1 - eps**2), 4 * eps)
    return eps, attitude
