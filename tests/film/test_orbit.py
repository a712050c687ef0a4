"""Film over the cycle: quasi-static and mobility tiers, pure squeeze, load reversal, the study stage."""

import numpy as np
import pytest

from stackup.film import min_film_thickness
from stackup.film.orbit import _ShortFilm, orbit

GEOMETRY = dict(diameter=0.046, length=0.022, clearance=60e-6, viscosity=0.008, speed=419.0)


def test_constant_load_mobility_orbit_settles_on_the_steady_short_bearing():
    angle = np.arange(0.0, 720.0, 4.0)
    loads = np.tile([8e3, 0.0], (angle.size, 1))
    dyn = orbit(loads, angle, **GEOMETRY, method="mobility")
    steady = min_film_thickness(8e3, **GEOMETRY, method="short")
    assert dyn.converged
    assert dyn.h_min[-1] == pytest.approx(float(steady.h_min), rel=2e-3)


def test_pure_squeeze_at_zero_speed_closes_the_film_as_predicted():
    # zero rotation, constant load: short-bearing squeeze film, d eps/dt from the film force balance
    film = _ShortFilm(radius=0.023, length=0.022, radial_clearance=30e-6, viscosity=0.008, speed=0.0)
    x = np.array([10e-6, 0.0])
    v = film.velocity(x, np.array([1e3, 0.0]), np.zeros(2))
    f, _ = film.force(x, v)
    np.testing.assert_allclose(f, [1e3, 0.0], rtol=1e-8, atol=1e-6)
    assert v[0] > 0 and abs(v[1]) < 1e-12 * abs(v[0]) + 1e-18  # approaches along the load, no whirl
    # heavier load, faster approach; closer to the wall, slower approach
    v2 = film.velocity(x, np.array([2e3, 0.0]), np.zeros(2))
    v3 = film.velocity(np.array([25e-6, 0.0]), np.array([1e3, 0.0]), np.zeros(2))
    assert v2[0] == pytest.approx(2 * v[0], rel=1e-6) and v3[0] < v[0]


def test_squeeze_film_carries_load_peaks_better_than_quasi_static():
    angle = np.arange(0.0, 720.0, 2.0)
    peak = 3e4 * np.exp(-(((angle + 360) % 720 - 360) / 20.0) ** 2) + 1e3
    loads = np.stack([peak, 0.2 * peak], axis=-1)
    dyn = orbit(loads, angle, **GEOMETRY, method="mobility")
    qs = orbit(loads, angle, **GEOMETRY, method="quasi-static", steady_method="short")
    assert dyn.converged and dyn.h_min.min() > 1.2 * qs.h_min.min()


def test_load_reversal_is_followed():
    angle = np.arange(0.0, 720.0, 4.0)
    loads = np.stack([2e4 * np.cos(np.radians(angle)), np.zeros_like(angle)], axis=-1)
    dyn = orbit(loads, angle, **GEOMETRY, method="mobility")
    assert dyn.converged
    x = dyn.position[:, 0]
    assert x.max() > 0 > x.min()  # the journal crosses the bearing as the load reverses


def test_quasi_static_broadcasts_over_bearings():
    angle = np.arange(0.0, 720.0, 10.0)
    loads = np.random.default_rng(0).normal(0, 1e4, (3, 5, angle.size, 2))
    qs = orbit(loads, angle, **{**GEOMETRY, "clearance": np.full((3, 5), 60e-6)}, method="quasi-static")
    assert qs.h_min.shape == (3, 5, angle.size) and qs.converged.all()


@pytest.mark.parametrize("kw, message", [
    (dict(method="euler"), "method: 'euler' is not one of 'quasi-static', 'mobility'"),
    (dict(crank_angle=np.arange(0, 800.0, 10)), "crank_angle: must increase and span less than 720 deg"),
])
def test_bad_input(kw, message):
    angle = kw.pop("crank_angle", np.arange(0.0, 720.0, 10.0))
    with pytest.raises(ValueError, match=message):
        orbit(np.zeros((angle.size, 2)) + 1e3, angle, **GEOMETRY, **kw)


def test_study_stores_film_and_life_for_the_crank_engines():
    from stackup.study import Study

    ds = Study(n_engines=20, mechanics_engines=4, crank_angle_step=4.0, schemes=("iso13778-5",), seed=3,
               pilot_engines=2000, progress=False).run().sel(scheme="iso13778-5")
    h = ds.h_min.values
    assert np.all(np.isfinite(h[:4])) and np.all(np.isnan(h[4:]))
    assert np.all((h[:4] > 0.1e-6) & (h[:4] < 30e-6))
    assert np.all((ds.alpha.values[:4] >= 0) & (ds.alpha.values[:4] <= 1))
    assert np.all(ds.life.values[:4] > 0)
    for name in ("h_min", "h_min_mean", "alpha", "life", "film_temperature"):
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"]
    assert np.all(ds.film_temperature.values[:4] > 90.0)
