"""Film tiers: Raimondi & Boyd, closed forms, limits, mass conservation, hard cases, oils."""

import math

import numpy as np
import pytest

from stackup.film import ECCENTRICITY_VALID, ERROR_GRID, journal_position, min_film_thickness, oil, reynolds, tiers

# Raimondi & Boyd (1958), full journal bearing with Swift-Stieber film ends, as tabulated in
# Shigley's Mechanical Engineering Design: Sommerfeld number S at eccentricity eps.
RAIMONDI_BOYD = {
    1.0: {0.1: 1.33, 0.2: 0.631, 0.4: 0.264, 0.6: 0.121, 0.8: 0.0446, 0.9: 0.0188},
    0.5: {0.1: 4.31, 0.2: 2.03, 0.4: 0.779, 0.6: 0.319, 0.8: 0.0923, 0.9: 0.0313},
    0.25: {0.1: 16.2, 0.2: 7.57, 0.4: 2.83, 0.6: 1.07, 0.8: 0.261, 0.9: 0.0736},
}


def sommerfeld(field, ld):
    # S = mu N L D / W (R/c)^2 with W = mu w R^4 F / c^2 and N = w / 2 pi
    return (2 * ld) * 2 / (2 * np.pi * field.force)


@pytest.mark.parametrize("ld", [1.0, 0.5, 0.25])
def test_reynolds_tier_reproduces_raimondi_and_boyd_within_3_percent(ld):
    for eps, s in RAIMONDI_BOYD[ld].items():
        field = reynolds.solve_field(eps, 2 * ld)
        assert sommerfeld(field, ld) == pytest.approx(s, rel=0.03), (ld, eps)


def test_reynolds_grid_convergence():
    for eps in (0.3, 0.8, 0.95):
        coarse = reynolds.solve_field(eps, 1.0)
        fine = reynolds.solve_field(eps, 1.0, n_theta=2 * reynolds.N_THETA, n_z=2 * reynolds.N_Z - 1)
        assert coarse.force == pytest.approx(fine.force, rel=0.01), eps


def test_short_tier_equals_ocvirk_closed_form():
    f = min_film_thickness(2e4, journal_d=0.05, bearing_width=0.02, clearance=60e-6, viscosity=0.01, speed=400.0)
    eps = float(f.eccentricity)
    load = 0.01 * 400.0 * 0.025 * 0.02**3 / (4 * 30e-6**2) * eps * np.sqrt(np.pi**2 * (1 - eps**2) + 16 * eps**2) / (1 - eps**2) ** 2
    assert load == pytest.approx(2e4, rel=1e-10)
    assert np.tan(float(f.attitude_angle)) == pytest.approx(np.pi * np.sqrt(1 - eps**2) / (4 * eps), rel=1e-10)
    assert float(f.h_min) == pytest.approx(30e-6 * (1 - eps))


def test_reynolds_approaches_the_short_bearing_for_small_l_over_d():
    eps = 0.5
    field = reynolds.solve_field(eps, 2 * 0.1)
    short_force = (2 * 0.1) ** 3 / 4 * tiers.short_load_function(eps)
    assert field.force == pytest.approx(short_force, rel=0.05)


def long_bearing(eps, n=720):
    """Independent 1-D reference: infinitely long bearing, p = 0 at the inlet (thickest film), p >= 0 (numpy PSOR)."""
    theta = 2 * np.pi * np.arange(n) / n
    d = theta[1]
    h_half = 1 + eps * np.cos(theta + d / 2)
    rhs = 6 * (h_half - np.roll(h_half, 1)) / d
    a_e = h_half**3 / d**2
    a_w = np.roll(a_e, 1)
    p = np.zeros(n)
    for _ in range(100_000):
        old = p.copy()
        for i in range(1, n):
            gauss_seidel = (a_e[i] * p[(i + 1) % n] + a_w[i] * p[i - 1] - rhs[i]) / (a_e[i] + a_w[i])
            p[i] = max(0.0, -0.9 * p[i] + 1.9 * gauss_seidel)
        if np.abs(p - old).max() < 1e-10 * p.max():
            break
    f_r, f_t = -np.sum(p * np.cos(theta)) * d, np.sum(p * np.sin(theta)) * d
    return np.hypot(f_r, f_t), np.arctan2(f_t, f_r)


@pytest.mark.slow
def test_reynolds_approaches_the_long_bearing_for_large_l_over_d():
    force, attitude = long_bearing(0.5)
    # axial grid fine enough for the end zones (about one radius wide) of a long bearing
    per_length = [reynolds.solve_field(0.5, 2 * ld, n_z=97).force / (2 * ld) for ld in (8.0, 16.0, 32.0)]
    assert per_length[0] < per_length[1] < per_length[2] < force
    assert per_length[2] == pytest.approx(force, rel=0.04)
    assert np.degrees(reynolds.solve_field(0.5, 64.0, n_z=97).attitude) == pytest.approx(np.degrees(attitude), abs=1.0)


def test_side_flow_conserves_mass():
    # side leakage = net circumferential inflow into the pressurised zone
    field = reynolds.solve_field(0.6, 1.0)
    _, side = reynolds.friction_and_flow(field)
    dtheta, dz = field.theta[1], field.z[1]
    p = field.pressure
    dp = (np.roll(p, -1, axis=0) - p) / dtheta
    h_half = 1 + 0.6 * np.cos(field.theta + dtheta / 2)
    weights = np.ones(field.z.size)
    weights[[0, -1]] = 0.5
    # circumferential flow through each cell face (dimensionless, x12): 6 h - h^3 dp/dtheta, integrated over z
    q = np.sum((6 * h_half[:, None] - h_half[:, None] ** 3 * dp) * weights, axis=1) * dz
    pressurised = p[:, field.z.size // 2] > 0
    start = np.argmax(pressurised & ~np.roll(pressurised, 1))
    end = np.argmax(pressurised & ~np.roll(pressurised, -1))
    inflow, outflow = q[start - 1], q[end]
    assert side == pytest.approx(inflow - outflow, rel=0.03)


@pytest.mark.parametrize("method", ["short", "finite", "reynolds"])
def test_hard_cases(method):
    kw = dict(journal_d=0.046, bearing_width=0.022, clearance=50e-6, viscosity=0.01, speed=419.0, method=method)
    near_zero = min_film_thickness(1e-3, **kw)
    assert float(near_zero.eccentricity) < 1e-3
    heavy = min_film_thickness(2e5 if method != "reynolds" else 6e4, **kw)
    assert 0.9 < float(heavy.eccentricity) < 1 and float(heavy.h_min) > 0


def test_eccentricity_0_99_and_monotone_load():
    eps = np.array([0.5, 0.9, 0.97, 0.99])
    forces = [reynolds.solve_field(e, 1.0).force for e in eps[:3]]
    assert np.all(np.diff(forces) > 0)
    assert np.all(np.diff(tiers.short_load_function(eps)) > 0)
    assert np.isfinite(tiers.short_load_function(np.array([0.99, 0.999999])).all())


@pytest.mark.parametrize("method", ["short", "finite", "reynolds"])
def test_zero_load_gives_the_concentric_journal(method):
    kw = dict(journal_d=0.046, bearing_width=0.022, clearance=50e-6, viscosity=0.01, speed=419.0, method=method)
    film = min_film_thickness(np.array([0.0, 0.0]), **kw)
    np.testing.assert_array_equal(film.eccentricity, 0.0)
    np.testing.assert_array_equal(film.h_min, 25e-6)
    assert film.valid.all() and np.all(film.side_flow == 0)
    np.testing.assert_allclose(film.attitude_angle, np.pi / 2)
    # Petroff: the concentric film's torque 2 pi mu omega R^3 L / c
    np.testing.assert_allclose(film.friction_torque, 2 * np.pi * 0.01 * 419.0 * 0.023**3 * 0.022 / 25e-6, rtol=2e-3)


@pytest.mark.parametrize("method", ["short", "finite", "reynolds"])
def test_extreme_loads_give_a_thin_flagged_film_not_an_exception(method):
    kw = dict(journal_d=0.046, bearing_width=0.022, clearance=50e-6, viscosity=0.01, speed=419.0, method=method)
    loads = np.array([3e7, 1e9, 1e15, 1e300])
    film = min_film_thickness(loads, **kw)
    assert np.all((film.h_min > 0) & (film.h_min < 25e-6 * (1 - ECCENTRICITY_VALID)))
    assert np.all(np.diff(film.h_min) <= 0) and not film.valid.any()
    assert np.all(np.isfinite(film.friction_torque)) and np.all(np.isfinite(film.side_flow))
    assert min_film_thickness(1e4, **kw).valid


def test_finite_tier_outside_its_l_over_d_is_flagged_and_held_at_the_edge():
    kw = dict(clearance=50e-6, viscosity=0.01, speed=419.0, method="finite")
    wide = min_film_thickness(1e4, journal_d=0.046, bearing_width=0.2, **kw)  # L/D 4.3, above the table's 2
    edge = min_film_thickness(1e4, journal_d=0.046, bearing_width=0.092, **kw)  # L/D 2
    assert not wide.valid and edge.valid
    assert 0 < float(wide.h_min) < 25e-6 and float(wide.h_min) > float(edge.h_min)


def test_finite_tier_follows_reynolds_up_to_the_end_of_its_table():
    # above the old table end (0.98) the tier no longer extrapolates: within 2 % of the reference at 0.985-0.995
    for eps in (0.985, 0.99, 0.9937):
        field = reynolds.solve_field(eps, 1.0)
        film = min_film_thickness(field.force * 1e6, journal_d=2.0, bearing_width=1.0, clearance=2e-3, viscosity=1.0,
                                  speed=1.0, method="finite")
        assert float(film.h_min) == pytest.approx(1e-3 * (1 - eps), rel=0.02) and film.valid


def test_error_grid_spans_the_finite_table():
    data = np.load(str(resources_table()))
    ld, eps = data["length_over_diameter"], data["eccentricity"]
    grid_ld, grid_eps = ERROR_GRID["length_over_diameter"], ERROR_GRID["eccentricity"]
    assert min(grid_ld) < ld[1] and max(grid_ld) > ld[-2]
    # below the first node, inside the last interval, and between the nodes added above the old end (0.98)
    assert min(grid_eps) < eps[0] and eps[-2] < max(grid_eps) < eps[-1] == ECCENTRICITY_VALID
    assert sum(0.98 < g < ECCENTRICITY_VALID for g in grid_eps) >= 2 and not set(grid_eps) & set(eps)


def resources_table():
    from importlib import resources

    return resources.files("stackup") / "data" / "film_finite_table.npz"


def test_journal_position_matches_the_mobility_tiers_steady_orbit():
    from stackup.film.orbit import orbit

    geometry = dict(journal_d=0.046, bearing_width=0.022, clearance=60e-6, viscosity=0.008, speed=419.0)
    load = np.array([3e3, 7e3])
    angle = np.arange(0.0, 720.0, 4.0)
    settled = orbit(np.tile(load, (angle.size, 1)), angle, **geometry, method="mobility").position[-1]
    film = min_film_thickness(np.linalg.norm(load), **geometry, method="short")
    x = journal_position(load, eccentricity=film.eccentricity, attitude_angle=film.attitude_angle, clearance=60e-6)
    np.testing.assert_allclose(x, settled, rtol=5e-3, atol=5e-9)


def test_tiers_agree_where_they_should():
    kw = dict(journal_d=0.046, bearing_width=0.022, clearance=50e-6, viscosity=0.01, speed=419.0)
    load = np.array([2e3, 1e4, 3e4])
    ref = min_film_thickness(load, **kw, method="reynolds")
    fin = min_film_thickness(load, **kw, method="finite")
    np.testing.assert_allclose(fin.h_min, ref.h_min, rtol=0.02)


@pytest.mark.parametrize("kw, message", [
    (dict(load=-1.0), "load: -1.0 is not valid; must be >= 0"),
    (dict(speed=0.0), "speed: 0.0 is not valid; must be > 0"),
    (dict(clearance=np.nan), "clearance: nan is not a finite number"),
    (dict(method="reynold"), "method: 'reynold' is not one of 'short', 'finite', 'reynolds'"),
])
def test_bad_input(kw, message):
    args = dict(load=1e4, journal_d=0.046, bearing_width=0.022, clearance=50e-6, viscosity=0.01, speed=419.0, method="finite")
    args.update(kw)
    with pytest.raises(ValueError, match=message):
        min_film_thickness(args.pop("load"), **args)


def walther(kv40, kv100, t):
    """ASTM D341 written out here: log10 log10(nu + 0.7) = A - B log10 T (cSt, K)."""
    z40, z100 = (math.log10(math.log10(kv * 1e6 + 0.7)) for kv in (kv40, kv100))
    b = (z40 - z100) / (math.log10(373.15) - math.log10(313.15))
    return (10 ** 10 ** (z40 + b * math.log10(313.15) - b * math.log10(t + 273.15)) - 0.7) * 1e-6


def test_low_shear_vogel_passes_through_kv40_and_kv100_and_follows_astm_d341():
    o = oil.get("SAE-10W-40")
    rho = lambda t: 865.0 / (1 + oil.THERMAL_EXPANSION * (t - 15))  # noqa: E731
    assert float(o.low_shear_viscosity(40.0)) == pytest.approx(95e-6 * rho(40.0), rel=1e-8)
    assert float(o.low_shear_viscosity(100.0)) == pytest.approx(14.5e-6 * rho(100.0), rel=1e-8)
    for t in (20.0, 60.0, 120.0, 150.0, 200.0):
        assert float(o.low_shear_viscosity(t)) == pytest.approx(walther(95e-6, 14.5e-6, t) * rho(t), rel=0.02), t


@pytest.mark.parametrize("name", oil.available())
def test_vogel_constant_is_physical_for_every_builtin_oil(name):
    # Vogel temperature -C3 degC between about 90 and 210 K (the old fit through HTHS gave 10W-40 C3 = 258 K)
    assert oil.VOGEL_C3_RANGE[0] < oil.get(name).c3 < oil.VOGEL_C3_RANGE[1]


def test_fit_vogel_keeps_c3_inside_its_range():
    # three points that an exact fit would only pass with C3 = 258 K (the old 10W-40 mix of low and high shear)
    t = np.array([40.0, 100.0, 150.0])
    c = (5e-7, 3408.76, 257.98)
    mu = c[0] * np.exp(c[1] / (t + c[2]))
    c1, c2, c3 = oil.fit_vogel(t, mu)
    assert c3 == pytest.approx(oil.VOGEL_C3_RANGE[1], abs=1e-6)
    exact = oil.fit_vogel(t, 0.01 * np.exp(900.0 / (t + 110.0)))
    np.testing.assert_allclose(exact, (0.01, 900.0, 110.0), rtol=1e-7)


@pytest.mark.parametrize("name", ["SAE-5W-30", "SAE-10W-40", "SAE-15W-40"])
def test_multigrade_shear_thinning_passes_through_hths(name):
    o = oil.get(name)
    hths = {"SAE-5W-30": 3.1e-3, "SAE-10W-40": 3.7e-3, "SAE-15W-40": 4.1e-3}[name]
    assert float(o.viscosity(150.0, shear_rate=1e6)) == pytest.approx(hths, rel=1e-10)
    rates = np.geomspace(1e-1, 1e12, 30)
    mu = o.viscosity(100.0, shear_rate=rates)
    assert np.all(np.diff(mu) < 0)
    assert mu[0] == pytest.approx(float(o.low_shear_viscosity(100.0)), rel=1e-3)
    assert mu[-1] == pytest.approx(o.second_newtonian * float(o.low_shear_viscosity(100.0)), rel=2e-3)
    assert float(o.viscosity(100.0, shear_rate=0.0)) == float(o.low_shear_viscosity(100.0))


def test_monograde_is_newtonian():
    o = oil.get("SAE-30")
    assert o.second_newtonian == 1.0
    assert float(o.viscosity(120.0, shear_rate=1e7)) == float(o.low_shear_viscosity(120.0))


def test_pressure_term_raises_viscosity():
    from dataclasses import replace

    o = replace(oil.get("SAE-5W-30"), pressure_coefficient=2e-8)
    assert float(o.viscosity(100.0, pressure=50e6)) == pytest.approx(float(o.viscosity(100.0)) * np.exp(1.0))


def test_unknown_oil():
    with pytest.raises(ValueError, match="oil: 'SAE-99' is not a known oil"):
        oil.get("SAE-99")


def test_cheapest_tier_within_error():
    from stackup.film import cheapest_tier, tier_errors

    errors = tier_errors()
    assert errors["finite"] < 0.02 < errors["short"]
    assert cheapest_tier(0.05) == "finite"
    assert cheapest_tier(errors["short"] + 1e-9) == "short"
    assert cheapest_tier(0.0) == "reynolds"


def test_reynolds_at_eccentricity_0_99():
    field = reynolds.solve_field(0.99, 1.0)
    assert np.isfinite(field.force) and field.force > reynolds.solve_field(0.97, 1.0).force
    assert field.pressure.min() >= 0 and np.degrees(field.attitude) < 15
    film = min_film_thickness(field.force * 1e6, journal_d=2.0, bearing_width=1.0, clearance=2e-3, viscosity=1.0, speed=1.0,
                              method="reynolds")
    assert float(film.eccentricity) == pytest.approx(0.99, abs=1e-6)
