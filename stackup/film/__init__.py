"""Oil film of a main bearing: minimum film thickness in tiers, and the film over the engine cycle.

The package's face: the names below are importable from ``stackup.film``; the models live in its modules.

- :mod:`~stackup.film.steady`: the film under a steady load (:func:`min_film_thickness`, :class:`Film`,
  :func:`cheapest_tier`, :func:`tier_errors`, :func:`journal_position`), its tiers' closed forms in
  :mod:`~stackup.film.tiers` and the Reynolds solver in :mod:`~stackup.film.reynolds`;
- :mod:`~stackup.film.registry`: one record per film tier (:data:`TIER_NOTES` reads their notes), the
  package's tiers in :mod:`~stackup.film.catalogue`;
- :mod:`~stackup.film.orbit`: the film over the cycle, its tiers in :mod:`~stackup.film.quasi_static`,
  :mod:`~stackup.film.mobility`, :mod:`~stackup.film.elrod`, :mod:`~stackup.film.transient`, the tilt in
  :mod:`~stackup.film.tilt` and :mod:`~stackup.film.coupled`, what they share in :mod:`~stackup.film.journal`;
- :mod:`~stackup.film.cycle` (the study's film stage), :mod:`~stackup.film.heat` (heat balance with the oil
  feed), :mod:`~stackup.film.oil` (viscosity), :mod:`~stackup.film.bearing_law` (the steady film's
  load-displacement curve).
"""

from __future__ import annotations

from . import catalogue  # noqa: F401 (registers the package's tiers, which min_film_thickness runs)
from . import oil, reynolds, tiers
# the steady tiers' checked range is the one eccentricity limit of every tier, under the name it had here
from .journal import ECCENTRICITY_LIMIT as ECCENTRICITY_VALID
from .registry import NOTES as TIER_NOTES
from .steady import (BY_COST, ERROR_GRID, METHODS, Film, cheapest_tier, journal_position, min_film_thickness,
                     tier_errors)

__all__ = ["BY_COST", "ECCENTRICITY_VALID", "ERROR_GRID", "cheapest_tier", "tier_errors", "METHODS", "Film",
           "journal_position", "min_film_thickness", "oil", "reynolds", "tiers", "TIER_NOTES"]
