"""The film tiers the package ships, one :class:`~stackup.film.registry.Tier` record each, cheapest first.

Importing this module registers them (the package face and :mod:`stackup.film.orbit` do). A new tier is
its module (the function that runs it) and its record here; dispatch (:func:`stackup.film.orbit.orbit`),
the steady film (:func:`stackup.film.min_film_thickness`), the study's film stage
(:mod:`stackup.film.cycle`), the check, the report and the studies read it from the registry.
The equations of each tier are stated in :mod:`stackup.film.orbit` and in the tier's module; their
measured costs and errors in ``reports/film_speed_vs_error.md``.
"""

from __future__ import annotations

from functools import partial

from .elrod import elrod_orbit
from .mobility import mobility_tier_orbit
from .quasi_static import finite_films, quasi_static_orbit, short_films
from .registry import Tier, own_options, register
from .steady import finite_film, reynolds_film, reynolds_films, short_film
from .transient import transient_orbit

register(Tier(
    "short", "quasi-static", partial(quasi_static_orbit, films=short_films, finite=False),
    notes="quasi-static short-bearing film at each crank angle (no squeeze)",
    length_model="short", steady=short_film, error_row="quasi-static-short", aliases=("quasi-static-short",)))
register(Tier(
    "finite", "quasi-static", partial(quasi_static_orbit, films=finite_films, finite=True),
    notes="quasi-static finite-bearing film at each crank angle (no squeeze)",
    length_model="finite", steady=finite_film, error_row="quasi-static-finite", aliases=("quasi-static-finite",)))
register(Tier(
    "mobility", "dynamic", partial(mobility_tier_orbit, finite=False),
    notes="journal orbit over the cycle by the short-bearing mobility method (squeeze and rotation, Booker)",
    length_model="short", cycles=20, error_row="mobility", aliases=("mobility-short",)))
register(Tier(
    "mobility-finite", "dynamic", partial(mobility_tier_orbit, finite=True),
    notes="journal orbit over the cycle by the mobility method with a finite-length correction tabulated from the "
          "Reynolds equation (squeeze and rotation)",
    length_model="finite", cycles=20, error_row="mobility-finite"))
register(Tier(
    "elrod-coarse", "dynamic", elrod_orbit,
    notes="journal orbit over the cycle on the transient Reynolds equation with mass-conserving cavitation "
          "(Elrod's film content) on a coarse grid, Newton per time step (tilt imposed)",
    length_model="finite", options=own_options(elrod_orbit), cycles=8, fed=True, imposed_tilt=True,
    error_row="elrod-coarse", check=True))
register(Tier(
    "reynolds", "quasi-static", partial(quasi_static_orbit, films=reynolds_films, finite=True),
    notes="quasi-static Reynolds film at each crank angle (no squeeze)",
    length_model="finite", steady=reynolds_film, error_row="quasi-static-reynolds",
    aliases=("quasi-static-reynolds",)))
register(Tier(
    "reynolds-transient", "dynamic", transient_orbit,
    notes="journal orbit over the cycle on the transient Reynolds equation with mass-conserving cavitation "
          "(the reference)",
    length_model="finite", options=own_options(transient_orbit), cycles=8, fed=True, error_row="reynolds-transient",
    aliases=("transient",), reference=True))
