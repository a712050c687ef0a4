"""Film over the cycle: quasi-static and mobility tiers, pure squeeze, load reversal, the study stage."""

import json

import numpy as np
import pytest

from stackup.film import min_film_thickness
from scipy import integrate

from stackup._kernels import mobility as kernel
from stackup.film.orbit import ECCENTRICITY_LIMIT, PERIODIC, STATUS, orbit

GEOMETRY = dict(journal_d=0.046, bearing_width=0.022, clearance=60e-6, viscosity=0.008, speed=419.0)


def test_constant_load_mobility_orbit_settles_on_the_steady_short_bearing():
    angle = np.arange(0.0, 720.0, 4.0)
    loads = np.tile([8e3, 0.0], (angle.size, 1))
    dyn = orbit(loads, angle, **GEOMETRY, method="mobility")
    steady = min_film_thickness(8e3, **GEOMETRY, method="short")
    qs = orbit(loads, angle, **GEOMETRY, method="short")
    assert dyn.converged
    assert dyn.h_min[-1] == pytest.approx(float(steady.h_min), rel=2e-3)
    # the journal sits where the quasi-static short tier puts it, with Ocvirk's torque and flow
    np.testing.assert_allclose(dyn.position[-1], qs.position[-1], rtol=1e-3, atol=1e-3 * 30e-6)
    for name in ("p_max", "friction_torque", "side_flow"):
        assert getattr(dyn, name)[-1] == pytest.approx(getattr(qs, name)[-1], rel=1e-3), name
    assert qs.friction_torque[-1] == pytest.approx(float(steady.friction_torque), rel=1e-12)


def test_pure_squeeze_along_the_line_of_centres_equals_the_quadrature_of_the_short_bearing():
    # no rotation (v_s = approach velocity), load along the line of centres: by symmetry the squeeze is
    # along it too, and F = mu R L^3 / c^3 * v * integral over |phi| < pi/2 of cos^2 phi / (1 - eps cos phi)^3
    eps = 0.6
    quad = integrate.quad(lambda p: np.cos(p) ** 2 / (1 - eps * np.cos(p)) ** 3, -np.pi / 2, np.pi / 2)[0]
    speed, alpha, ok = kernel.squeeze_velocity(eps, 2.0, 0.0, 1.0, np.zeros((2, 2, 3)), np.array([0.0, 1.0]), False)
    assert ok and alpha == pytest.approx(0.0, abs=1e-6)
    assert speed == pytest.approx(2.0 / quad, rel=1e-9)


def test_squeeze_film_carries_load_peaks_better_than_quasi_static():
    angle = np.arange(0.0, 720.0, 2.0)
    peak = 3e4 * np.exp(-(((angle + 360) % 720 - 360) / 20.0) ** 2) + 1e3
    loads = np.stack([peak, 0.2 * peak], axis=-1)
    dyn = orbit(loads, angle, **GEOMETRY, method="mobility")
    qs = orbit(loads, angle, **GEOMETRY, method="short")
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
    qs = orbit(loads, angle, **{**GEOMETRY, "clearance": np.full((3, 5), 60e-6)}, method="finite")
    assert qs.h_min.shape == (3, 5, angle.size) and qs.converged.all()


@pytest.mark.parametrize("kw, message", [
    (dict(method="euler"), "method: 'euler' is not one of 'short', 'finite', 'mobility', 'mobility-finite', "
                           "'elrod-coarse', 'reynolds', 'reynolds-transient'"),
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
    # the film over the width: no thinner than the wall's film (0.5 % of a radial clearance of 17 um or more)
    assert np.all((h[:4] > 0.08e-6) & (h[:4] < 30e-6))
    assert np.all(ds.h_min_midplane.values[:4] > 0.5e-6) and np.all(h[:4] <= ds.h_min_midplane.values[:4])
    assert np.all((ds.alpha.values[:4] >= 0) & (ds.alpha.values[:4] <= 1))
    assert np.all(ds.life.values[:4] > 0)
    for name in ("h_min", "h_min_mean", "alpha", "life", "film_temperature"):
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"]
    assert np.all(ds.film_temperature.values[:4] > 90.0)
    assert ds.attrs["film_method_used"] in ("mobility", "mobility-finite", "reynolds-transient")


def test_study_stores_the_film_status_tilt_and_peak_pressure_with_their_flags():
    from stackup.study import Study
    from stackup.study.schema import flag

    ds = Study(n_engines=10, mechanics_engines=3, crank_angle_step=4.0, schemes=("iso13778-5",), seed=3,
               pilot_engines=2000, progress=False, film_method="mobility-finite",
               bearing_law="fitted").run().sel(scheme="iso13778-5")
    computed = slice(0, 3)
    status = ds.film_status.values[computed]
    closed = (flag(ds.film_status, "periodic"), flag(ds.film_status, "edge_contact"))
    assert np.all(np.isin(status, closed))  # the engines' orbits closed; the flag says how
    assert np.all(ds.film_status.values[3:] == flag(ds.film_status, "not_computed"))
    assert set(ds.film_status.attrs["flag_meanings"].split()) >= {"not_periodic", "collapsed", "failed"}
    h, edge = ds.h_min.values[computed], ds.h_min_edge.values[computed]
    assert np.all(edge <= h) and np.all(edge > 0)
    mid = ds.h_min_midplane.values[computed]
    np.testing.assert_array_equal(h, edge)  # the study reads the film over the width
    np.testing.assert_allclose(ds.tilt_loss.values[computed], mid - edge)
    assert np.all((ds.tilt_max.values[computed] > 0) & (ds.tilt_max.values[computed] < 0.01))
    assert np.all((ds.p_max.values[computed] > 10e6) & (ds.p_max.values[computed] < 1e9))
    # the law fitted per bearing follows the film within a small share of the clearance
    assert np.all(ds.law_fit_error.values[computed] < 0.1 * ds.clearance_operating.values[computed])
    for name in ("h_min_edge", "tilt_loss", "tilt_max", "p_max", "film_status", "law_fit_error"):
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"]



def test_tilt_method_free_holds_the_beams_slope_and_changes_only_the_edge_film():
    from stackup.study import Study

    common = dict(n_engines=10, mechanics_engines=2, crank_angle_step=4.0, schemes=("iso13778-5",), seed=3,
                  pilot_engines=2000, progress=False, film_method="mobility-finite")
    balanced = Study(**common).run().sel(scheme="iso13778-5").isel(mech_engine=slice(0, 2))
    held = Study(**common, tilt_method="free").run().sel(scheme="iso13778-5").isel(mech_engine=slice(0, 2))
    assert json.loads(held.attrs["study"])["tilt_method"] == "free"
    # the free tilt is the beam's slope: the film holds it exactly, the equilibrium turns it back
    np.testing.assert_allclose(held.tilt_max.values, held.tilt_free_max.values, rtol=1e-12)
    np.testing.assert_array_equal(balanced.tilt_free_max.values, held.tilt_free_max.values)
    assert np.all(balanced.tilt_max.values < balanced.tilt_free_max.values)
    assert np.all((balanced.tilt_free_max.values > 1e-5) & (balanced.tilt_free_max.values < 0.01))
    for ds in (balanced, held):
        share = ds.edge_contact_share.values
        assert np.all((share >= 0) & (share <= 1))
        assert ds.edge_contact_share.attrs["units"] == "1" and ds.tilt_free_max.attrs["units"] == "rad"
    # the mid-plane film does not depend on the tilt; the free slope's lives read it, the balanced tilt's the film
    # over the width, thinner
    for name in ("h_min_midplane", "p_max"):
        np.testing.assert_array_equal(balanced[name].values, held[name].values)
    np.testing.assert_array_equal(held.h_min.values, held.h_min_midplane.values)
    assert np.all(balanced.h_min.values <= held.h_min.values) and np.all(balanced.life.values <= held.life.values)
    assert np.nanmean(held.edge_contact_share.values) >= np.nanmean(balanced.edge_contact_share.values)


def test_study_rejects_an_unknown_tilt_method():
    from stackup.study import Study

    with pytest.raises(ValueError, match="tilt_method.*'rigid'.*equilibrium"):
        Study(tilt_method="rigid")

# Hard cases. A load of constant size turning at the rate Omega: in the frame turning with it the
# journal stands still, v_s = (Omega - omega/2) k x x, so the film is the steady film at the speed
# omega - 2 Omega (Booker 1965): the same as a steady load when the load turns with the shaft, three
# times the speed against it, and no film at all at half the shaft speed (half-frequency whirl).
ANGLE = np.arange(0.0, 720.0, 2.0)


def turning_load(size, rate):
    phase = rate * np.radians(ANGLE)
    return size * np.stack([np.cos(phase), np.sin(phase)], axis=-1)


@pytest.mark.parametrize("method", ["mobility", "mobility-finite"])
@pytest.mark.parametrize("rate, equivalent_speed", [(1.0, 1.0), (-1.0, 3.0)])
def test_load_turning_with_or_against_the_shaft_has_the_steady_film_at_the_equivalent_speed(method, rate,
                                                                                             equivalent_speed):
    dyn = orbit(turning_load(8e3, rate), ANGLE, **GEOMETRY, method=method)
    steady_tier = "short" if method == "mobility" else "finite"
    steady = orbit(np.array([[8e3, 0.0]]), np.array([0.0]), **{**GEOMETRY, "speed": equivalent_speed * 419.0},
                   method=steady_tier)
    assert dyn.status == STATUS.index("periodic")
    rel = 2e-3 if method == "mobility" else 0.03  # the finite tier's steady table is the steady Reynolds tier
    np.testing.assert_allclose(dyn.h_min, steady.h_min[0], rtol=rel)


def test_load_turning_at_half_the_shaft_speed_collapses_the_film():
    dyn = orbit(turning_load(8e3, 0.5), ANGLE, **GEOMETRY, method="mobility")
    # pure squeeze: the journal approaches the wall cycle after cycle and never settles
    assert dyn.status == STATUS.index("collapsed")
    assert np.all((dyn.h_min > 0) & (dyn.h_min < 0.05 * 30e-6))


def test_zero_load_over_part_of_the_cycle_keeps_the_journal_whirling_at_half_speed():
    load = turning_load(6e3, 0.0)
    off = (ANGLE > 300) & (ANGLE < 500)
    load[off] = 0.0
    dyn = orbit(load, ANGLE, **GEOMETRY, method="mobility")
    assert dyn.status == STATUS.index("periodic")
    ecc = dyn.eccentricity[off]
    np.testing.assert_allclose(ecc, ecc[0], rtol=1e-5)  # no film force: the centre circles at omega/2
    turned = np.unwrap(np.arctan2(dyn.position[off, 1], dyn.position[off, 0]))
    np.testing.assert_allclose(np.diff(turned), 0.5 * np.radians(2.0), rtol=1e-4)  # midpoint rule: h^2/24


def test_zero_load_over_the_whole_cycle_leaves_the_journal_centred():
    dyn = orbit(np.zeros((ANGLE.size, 2)), ANGLE, **GEOMETRY, method="mobility")
    assert dyn.status == STATUS.index("periodic")
    np.testing.assert_array_equal(dyn.eccentricity, 0.0)
    np.testing.assert_allclose(dyn.h_min, 30e-6)
    np.testing.assert_array_equal(dyn.p_max, 0.0)


def test_overload_drives_the_eccentricity_to_the_limit_and_is_flagged():
    dyn = orbit(turning_load(5e6, 0.0), ANGLE, **GEOMETRY, method="mobility")
    assert dyn.status == STATUS.index("collapsed")
    np.testing.assert_allclose(dyn.h_min[-10:], 30e-6 * (1 - ECCENTRICITY_LIMIT))


def test_an_orbit_that_has_not_settled_is_flagged_not_periodic():
    # a light load hardly damps the half-speed whirl: two cycles are not enough to settle
    dyn = orbit(turning_load(50.0, 0.0) + [0.0, 30.0], ANGLE, **GEOMETRY, method="mobility", cycles=2)
    assert dyn.status == STATUS.index("not_periodic")
    assert np.all((dyn.h_min > 0) & (dyn.h_min < 30e-6)) and dyn.cycles < 4


def test_cheapest_cycle_tier_follows_the_measured_errors():
    from stackup.film.orbit import cheapest_cycle_tier, cycle_tier_errors

    errors = cycle_tier_errors()
    fastest = min(errors, key=lambda t: errors[t]["seconds"])
    assert cheapest_cycle_tier(10.0) == fastest
    assert cheapest_cycle_tier(0.0) == "reynolds-transient"
    seconds = [errors[cheapest_cycle_tier(e)]["seconds"] for e in (0.0, 0.01, 0.03, 0.1, 0.3, 1.0)]
    assert seconds == sorted(seconds, reverse=True)  # a looser tolerance never costs more
    for e in (0.02, 0.05, 0.2):
        for reference in ("mass-conserving", "swift-stieber"):
            tier = cheapest_cycle_tier(e, reference=reference)
            table = errors[tier] if reference == "mass-conserving" else errors[tier]["swift-stieber"]
            assert tier == "reynolds-transient" or (table["h_min"] <= e and table["h_min_mean"] <= e)
    for method in errors:  # every measured tier is a method of orbit
        orbit(np.tile([1e3, 0.0], (4, 1)), np.arange(0.0, 720.0, 180.0), **GEOMETRY, method=method,
              **({"n_theta": 24, "n_z": 5, "cycles": 1} if method == "reynolds-transient" else {}))


@pytest.mark.parametrize("method", ["mobility", "mobility-finite"])
def test_a_warm_start_reaches_the_same_periodic_orbit_in_fewer_laps(method):
    load = turning_load(6e3, 0.0) * (1 + 2.5 * np.exp(-((ANGLE - 370) / 25) ** 2))[:, None]
    cold = orbit(load, ANGLE, **GEOMETRY, method=method)
    coarse = orbit(load[::2], ANGLE[::2], **GEOMETRY, method=method)
    warm = orbit(load, ANGLE, **GEOMETRY, method=method, start=coarse.position[0])
    assert cold.status == warm.status == STATUS.index("periodic")
    np.testing.assert_allclose(warm.h_min, cold.h_min, rtol=0, atol=3 * PERIODIC * cold.h_min.min())
    assert warm.cycles < cold.cycles
