"""The steady film's load-displacement curve: what the crankshaft's bearing law is fitted to.

:func:`stackup.crank.law.fit_bellakhdhar` takes plain arrays (the crank
package does not import the film); this module makes them from the film API,
at the engine's speed, each bearing's effective viscosity and clearance.
"""

from __future__ import annotations

import numpy as np

from .._validate import Integer, OneOf, Positive, renamed, validated
from .steady import METHODS, min_film_thickness

#: Share of the loads spaced geometrically from max_load / 1000 (the journal floating in its clearance);
#: the rest linearly up to max_load (the stiff end that carries the firing loads).
GEOMETRIC_SHARE = 0.5


@renamed(diameter="journal_d", length="bearing_width")
@validated(max_load=Positive(), samples=Integer(minimum=4), journal_d=Positive(), bearing_width=Positive(),
           clearance=Positive(), viscosity=Positive(), speed=Positive(), method=OneOf(METHODS))
def load_displacement(*, max_load, journal_d, bearing_width, clearance, viscosity, speed, samples=40, method="finite"):
    """Loads and the journal-centre displacement the steady film takes under each.

    Parameters
    ----------
    max_load : array_like (...)
        Largest load of the curve [N] (e.g. 1.5 times the bearing's cycle peak).
    journal_d, bearing_width, clearance : array_like (...)
        Journal diameter, bearing width, diametral clearance [m].
    viscosity : array_like (...)
        Effective viscosity [Pa s].
    speed : array_like (...)
        Journal angular speed [rad/s].
    samples : int
        Points of the curve.
    method : str
        Steady tier of :func:`stackup.film.min_film_thickness`.

    Returns
    -------
    load, displacement : numpy.ndarray (..., samples)
        [N] and [m]: eccentricity times the radial clearance.
    """
    max_load = np.asarray(max_load, dtype=float)
    n_geo = int(GEOMETRIC_SHARE * samples)
    share = np.concatenate([np.geomspace(1e-3, 0.3, n_geo, endpoint=False), np.linspace(0.3, 1.0, samples - n_geo)])
    inputs = dict(journal_d=journal_d, bearing_width=bearing_width, clearance=clearance, viscosity=viscosity,
                  speed=speed)
    shape = np.broadcast_shapes(np.shape(max_load), *(np.shape(v) for v in inputs.values()))
    column = {k: np.broadcast_to(np.asarray(v, dtype=float), shape)[..., None] for k, v in inputs.items()}
    load = np.broadcast_to(max_load, shape)[..., None] * share
    film = min_film_thickness(load, **column, method=method)
    return load, film.eccentricity * column["clearance"] / 2
