"""A film tier is one record in the registry: a tier registered from a test runs through every layer that names
tiers (the orbit's dispatch, the steady film, the study's film stage and parameters, the report's notes), and is
gone after it."""

import dataclasses

import numpy as np
import pytest

from stackup.engines import load_engine
from stackup.film import TIER_NOTES, min_film_thickness, registry
from stackup.film.cycle import FILM_METHODS, bearing_films
from stackup.film.orbit import ALIASES, DYNAMIC, METHODS, orbit
from stackup.film.registry import Tier, registered
from stackup.film.steady import short_film
from stackup.study import Study

ENGINE = load_engine("iso-example")
ANGLE = np.arange(0.0, 720.0, 8.0)
GEOMETRY = dict(journal_d=0.046, bearing_width=0.022, clearance=60e-6, viscosity=0.008, speed=419.0)
SHIPPED = ("short", "finite", "mobility", "mobility-finite", "elrod-coarse", "reynolds", "reynolds-transient")
SHARE = 0.9


def engine_like_load():
    """(angles, 2): a steady 3 kN plus a 25 kN peak, swinging about the cap [N]."""
    size = 3e3 + 25e3 * np.exp(-0.5 * ((ANGLE - 370.0) / 20.0) ** 2)
    direction = np.radians(40.0) * np.sin(np.radians(ANGLE))
    return size[:, None] * np.stack([np.cos(direction), np.sin(direction)], axis=-1)


def thinner_mobility(loads, crank_angle, **inputs):
    """The toy tier's orbit: the ``mobility`` tier's, its films SHARE as thick (torque, flow, journal unchanged)."""
    film = registry.tier("mobility").run(loads, crank_angle, **inputs)
    return dataclasses.replace(film, h_min=SHARE * film.h_min, h_min_edge=SHARE * film.h_min_edge)


def thinner_short(load, **geometry):
    """The quasi-static toy's steady film: the ``short`` tier's, SHARE as thick."""
    film = short_film(load, **geometry)
    return dataclasses.replace(film, h_min=SHARE * film.h_min)


@pytest.fixture
def toy():
    """A dynamic tier registered for the test (a scaled copy of ``mobility``) and unregistered after it."""
    tier = Tier("mobility-thin", "dynamic", thinner_mobility, notes="the mobility orbit with a thinner film",
                length_model="short", cycles=20, aliases=("thin",))
    with registered(tier):
        yield tier
    assert tuple(METHODS) == SHIPPED and "thin" not in ALIASES  # nothing left behind


def test_the_shipped_tiers_are_registered_cheapest_first():
    assert METHODS == SHIPPED and FILM_METHODS == SHIPPED
    assert registry.check_tier().name == "elrod-coarse" and registry.reference_tier().name == "reynolds-transient"
    assert set(TIER_NOTES) == set(SHIPPED)


def test_a_registered_tier_runs_through_the_orbit(toy):
    loads = engine_like_load()
    mine = orbit(loads, ANGLE, **GEOMETRY, method="mobility-thin")
    theirs = orbit(loads, ANGLE, **GEOMETRY, method="mobility")
    np.testing.assert_array_equal(mine.h_min, SHARE * theirs.h_min)
    np.testing.assert_array_equal(mine.position, theirs.position)
    assert "mobility-thin" in METHODS and "mobility-thin" in DYNAMIC and "mobility-thin" in FILM_METHODS
    assert TIER_NOTES["mobility-thin"] == toy.notes and registry.find("mobility-thin") is toy


def test_a_registered_tier_runs_through_the_study_film_stage(toy):
    reactions = engine_like_load()[None, :, None, :]
    geometry = dict(clearance=np.full((1, 1), 60e-6), journal_d=np.full((1, 1), 0.046))
    mine = bearing_films(ENGINE.crank, ENGINE.oil_feed, reactions, ANGLE, **geometry, method="mobility-thin")
    theirs = bearing_films(ENGINE.crank, ENGINE.oil_feed, reactions, ANGLE, **geometry, method="mobility")
    # the heat balance reads friction, flow and the journal's position, which the toy leaves as they are
    np.testing.assert_array_equal(mine.temperature, theirs.temperature)
    np.testing.assert_array_equal(mine.h_min, SHARE * theirs.h_min)
    assert Study(film_method="mobility-thin", n_engines=10).film_method == "mobility-thin"


def test_a_registered_tier_keeps_its_deprecated_name(toy):
    loads = engine_like_load()
    with pytest.warns(DeprecationWarning, match="'thin' is deprecated; use 'mobility-thin'"):
        old = orbit(loads, ANGLE, **GEOMETRY, method="thin")
    np.testing.assert_array_equal(old.h_min, orbit(loads, ANGLE, **GEOMETRY, method="mobility-thin").h_min)


def test_a_registered_quasi_static_tier_is_a_steady_tier_too():
    tier = Tier("short-thin", "quasi-static", registry.tier("short").run, notes="a thinner short bearing",
                length_model="short", steady=thinner_short)
    with registered(tier):
        mine = min_film_thickness(2e4, **GEOMETRY, method="short-thin")
        theirs = min_film_thickness(2e4, **GEOMETRY, method="short")
        assert float(mine.h_min) == SHARE * float(theirs.h_min)
    with pytest.raises(ValueError, match="method: 'short-thin' is not one of 'short', 'finite', 'reynolds'"):
        min_film_thickness(2e4, **GEOMETRY, method="short-thin")


def test_a_tier_once_unregistered_is_refused_with_the_list_of_tiers(toy):
    registry.unregister(toy.name)
    try:
        listed = ", ".join(repr(name) for name in SHIPPED)
        with pytest.raises(ValueError, match=f"method: 'mobility-thin' is not one of {listed}$"):
            orbit(engine_like_load(), ANGLE, **GEOMETRY, method="mobility-thin")
    finally:
        registry.register(toy)  # the fixture unregisters it


def test_a_name_or_an_alias_is_registered_once():
    shipped = registry.tier("mobility")
    with pytest.raises(ValueError, match="name: 'mobility' already names a film tier"):
        registry.register(dataclasses.replace(shipped, aliases=()))
    with pytest.raises(ValueError, match="name: 'transient' already names a film tier"):
        registry.register(dataclasses.replace(shipped, name="other", aliases=("transient",)))
    with pytest.raises(ValueError, match="check: 'elrod-coarse' is already the check tier"):
        registry.register(dataclasses.replace(shipped, name="other", aliases=(), check=True))
    assert METHODS == SHIPPED


@pytest.mark.parametrize("fields, message", [
    (dict(kind="steady"), "kind: 'steady' is not one of 'quasi-static', 'dynamic'"),
    (dict(length_model="long"), "length_model: 'long' is not one of 'short', 'finite'"),
    (dict(cycles=None), "cycles: None is not valid for a dynamic tier"),
    (dict(options={"tilt": None}), r"options: \['tilt'\] are inputs of every tier"),
])
def test_a_record_says_what_it_lacks(fields, message):
    with pytest.raises(ValueError, match=message):
        dataclasses.replace(registry.tier("mobility"), name="other", aliases=(), **fields)


def test_an_option_the_tier_does_not_take_is_named():
    with pytest.raises(ValueError, match=r"n_theta: not an option of method='mobility' \(its options: none\)"):
        orbit(engine_like_load(), ANGLE, **GEOMETRY, method="mobility", n_theta=24)
