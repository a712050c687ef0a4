"""Names before issue 30 stay accepted, each with a DeprecationWarning, and give the same result as the new ones."""

import warnings

import numpy as np
import pytest

from stackup.engines import load_engine
from stackup.film import min_film_thickness, tiers
from stackup.film.bearing_law import load_displacement
from stackup.film.cycle import FILM_METHODS, balanced_orbit, bearing_films
from stackup.film.heat import OilFeed, feed_flow, groove_feed_flow, heat_balance, hole_feed_flow
from stackup.film.orbit import ALIASES, METHODS, canonical_tier, orbit
from stackup.film.tilt import cycle_tilt, film_moment
from stackup.film.transient import transient_orbit

ANGLE = np.arange(0.0, 720.0, 10.0)
LOADS = np.stack([1e4 + 5e3 * np.cos(np.radians(ANGLE)), 2e3 * np.sin(np.radians(ANGLE))], axis=-1)
DIAMETRAL = dict(journal_d=0.046, bearing_width=0.022, clearance=60e-6)
OLD_DIAMETRAL = dict(diameter=0.046, length=0.022, clearance=60e-6)
RADIAL = dict(journal_radius=0.023, bearing_width=0.022, radial_clearance=30e-6)
OLD_RADIAL = dict(radius=0.023, length=0.022, radial_clearance=30e-6)
FEED = OilFeed("groove", 0.35e6, (0.5 * np.pi, 1.5 * np.pi), 3e-3)


def same(new, old):
    """Results equal to the bit: dataclasses field by field, tuples item by item."""
    if hasattr(new, "__dataclass_fields__"):
        for name in new.__dataclass_fields__:
            same(getattr(new, name), getattr(old, name))
    elif isinstance(new, tuple):
        for a, b in zip(new, old, strict=True):
            same(a, b)
    elif new is None:
        assert old is None
    else:
        np.testing.assert_array_equal(new, old)


def deprecated(call, *names):
    """``call()`` warns that each of ``names`` (a keyword, or a fragment of the warning) is deprecated; its result."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    said = " ".join(str(w.message) for w in caught if issubclass(w.category, DeprecationWarning))
    for name in names:
        assert f"{name}= is deprecated" in said or name in said, (name, said)
    assert all(w.filename == __file__ for w in caught if issubclass(w.category, DeprecationWarning)), \
        [w.filename for w in caught]
    return result


def test_min_film_thickness_diameter_and_length():
    new = min_film_thickness(2e4, **DIAMETRAL, viscosity=0.01, speed=419.0, method="finite")
    same(new, deprecated(lambda: min_film_thickness(2e4, **OLD_DIAMETRAL, viscosity=0.01, speed=419.0,
                                                    method="finite"), "diameter", "length"))


def test_old_and_new_name_at_once_is_an_error():
    with pytest.raises(TypeError, match="not both"):
        min_film_thickness(2e4, **DIAMETRAL, diameter=0.046, viscosity=0.01, speed=419.0)


def test_steady_tiers_closed_forms_radius_and_length():
    kw = dict(radial_clearance=30e-6, viscosity=0.01, speed=419.0)
    new = tiers.short(np.array([1e3, 2e4]), journal_radius=0.023, bearing_width=0.022, **kw)
    same(new, deprecated(lambda: tiers.short(np.array([1e3, 2e4]), radius=0.023, length=0.022, **kw),
                         "radius", "length"))
    new = tiers.film_quantities(0.5, 1.0, 2e4, journal_radius=0.023, bearing_width=0.022, **kw)
    same(new, deprecated(lambda: tiers.film_quantities(0.5, 1.0, 2e4, radius=0.023, length=0.022, **kw),
                         "radius", "length"))


def test_orbit_diameter_and_length():
    new = orbit(LOADS, ANGLE, **DIAMETRAL, viscosity=0.008, speed=419.0, method="mobility")
    same(new, deprecated(lambda: orbit(LOADS, ANGLE, **OLD_DIAMETRAL, viscosity=0.008, speed=419.0,
                                       method="mobility"), "diameter", "length"))


@pytest.mark.parametrize("old, kw", [
    ("quasi-static-short", {}), ("quasi-static-finite", {}), ("quasi-static-reynolds", {}), ("mobility-short", {}),
    ("quasi-static", {"steady_method": "short"}), ("quasi-static", {}),
])
def test_orbit_tier_names_before_issue_30(old, kw):
    tier = {"quasi-static-short": "short", "quasi-static-finite": "finite", "quasi-static-reynolds": "reynolds",
            "mobility-short": "mobility", "quasi-static": kw.get("steady_method", "finite")}[old]
    assert tier in METHODS and (old == "quasi-static" or ALIASES[old] == tier)
    loads, angle = (LOADS[::12], ANGLE[::12]) if tier == "reynolds" else (LOADS, ANGLE)
    new = orbit(loads, angle, **DIAMETRAL, viscosity=0.008, speed=419.0, method=tier)
    same(new, deprecated(lambda: orbit(loads, angle, **DIAMETRAL, viscosity=0.008, speed=419.0, method=old, **kw),
                         f"method={old!r}"))


def test_steady_method_beside_a_dynamic_tier_is_deprecated_and_ignored():
    new = orbit(LOADS, ANGLE, **DIAMETRAL, viscosity=0.008, speed=419.0, method="mobility")
    same(new, deprecated(lambda: orbit(LOADS, ANGLE, **DIAMETRAL, viscosity=0.008, speed=419.0, method="mobility",
                                       steady_method="short"), "steady_method= is deprecated and read only"))


def test_the_study_and_the_orbit_name_the_tiers_alike_and_transient_is_deprecated():
    assert FILM_METHODS == METHODS
    assert ALIASES["transient"] == "reynolds-transient"
    with pytest.warns(DeprecationWarning, match="'transient' is deprecated"):
        assert canonical_tier("transient") == "reynolds-transient"
    assert canonical_tier("mobility-finite") == "mobility-finite"


def test_bearing_films_transient_is_the_reynolds_transient_tier():
    engine = load_engine("iso-example")
    loads = np.zeros((1, 4, 1, 2))
    with pytest.warns(DeprecationWarning, match="'transient' is deprecated"):
        with pytest.raises(ValueError, match="crank_angle"):  # the name is resolved before the inputs are checked
            bearing_films(engine.crank, engine.oil_feed, loads, np.array([0.0, 10.0, 5.0, 20.0]),
                          clearance=np.full((1, 1), 60e-6), journal_d=np.full((1, 1), 0.046), method="transient")


def test_tilt_radius_and_length():
    x, v, g = np.array([[6e-6, 3e-6]]), np.array([[1e-3, -4e-3]]), np.array([[2e-4, 1e-4]])
    kw = dict(viscosity=0.008, speed=419.0)
    same(film_moment(x, v, g, **RADIAL, **kw),
         deprecated(lambda: film_moment(x, v, g, **OLD_RADIAL, **kw), "radius", "length"))
    position = np.tile(x, (8, 1))
    same(cycle_tilt(position, np.tile(v, (8, 1)), np.tile(g, (8, 1)), compliance=1e-6, **RADIAL, **kw),
         deprecated(lambda: cycle_tilt(position, np.tile(v, (8, 1)), np.tile(g, (8, 1)), compliance=1e-6,
                                       **OLD_RADIAL, **kw), "radius", "length"))


def test_transient_orbit_radius_and_length():
    geometry = {k: np.asarray(v) for k, v in dict(radial_clearance=30e-6, viscosity=0.008, speed=419.0).items()}
    kw = dict(cycles=1, n_theta=24, n_z=5, start=np.zeros(2))
    loads, angle = LOADS[::6], ANGLE[::6]
    new = transient_orbit(loads, angle, journal_radius=np.asarray(0.023), bearing_width=np.asarray(0.022),
                          **geometry, **kw)
    same(new, deprecated(lambda: transient_orbit(loads, angle, radius=np.asarray(0.023), length=np.asarray(0.022),
                                                 **geometry, **kw), "radius", "length"))


def test_heat_balance_and_feed_flows_diameter_radius_and_length():
    kw = dict(clearance=55e-6, speed=419.0, oil="SAE-5W-30", supply_temperature=90.0, feed=FEED)
    same(heat_balance(LOADS, journal_d=0.046, bearing_width=0.022, **kw),
         deprecated(lambda: heat_balance(LOADS, diameter=0.046, length=0.022, **kw), "diameter", "length"))
    x = np.array([[5e-6, -3e-6], [1e-5, 2e-6]])
    kw = dict(radial_clearance=30e-6, supply_pressure=0.3e6, viscosity=0.01)
    groove = dict(groove_width=3e-3, groove_arc=(1.0, 4.0))
    same(groove_feed_flow(x, **kw, journal_radius=0.023, bearing_width=0.022, **groove),
         deprecated(lambda: groove_feed_flow(x, **kw, radius=0.023, length=0.022, **groove), "radius", "length"))
    hole = dict(hole_diameter=5e-3, hole_angle=1.0)
    same(hole_feed_flow(x, **kw, bearing_width=0.022, **hole),
         deprecated(lambda: hole_feed_flow(x, **kw, length=0.022, **hole), "length"))
    same(feed_flow(x, feed=FEED, radial_clearance=30e-6, viscosity=0.01, journal_radius=0.023, bearing_width=0.022),
         deprecated(lambda: feed_flow(x, feed=FEED, radial_clearance=30e-6, viscosity=0.01, radius=0.023,
                                      length=0.022), "radius", "length"))


def test_load_displacement_and_balanced_orbit_diameter_and_length():
    kw = dict(max_load=3e4, clearance=60e-6, viscosity=0.01, speed=419.0)
    same(load_displacement(**kw, journal_d=0.046, bearing_width=0.022),
         deprecated(lambda: load_displacement(**kw, diameter=0.046, length=0.022), "diameter", "length"))
    kw = dict(tier="mobility", clearance=60e-6, speed=419.0, oil="SAE-5W-30", supply_temperature=90.0, feed=FEED)
    same(balanced_orbit(LOADS, ANGLE, **kw, journal_d=0.046, bearing_width=0.022),
         deprecated(lambda: balanced_orbit(LOADS, ANGLE, **kw, diameter=0.046, length=0.022), "diameter", "length"))
