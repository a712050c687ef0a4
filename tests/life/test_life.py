"""Levanov et al. (2015) resource methods: hand-computed values, the paper's orders, step independence, hard cases."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import integrate

from stackup.life import (ALPHA_SCUFFING, LEVANOV_2015, alpha, critical_film, cycle_film, engine_life, levanov_method1,
                          levanov_method2, levanov_method2_field, life_summary)

PAPER = dict(h_lim_cr=1.9e-6, wear_limit=30e-6, wear_rate=1e-13)  # Levanov et al. 2015, sec. 4


def test_parameter_set_holds_the_papers_constants():
    # Levanov et al. 2015: sec. 4 (30 um, 1e-13 m/s, 1.9 um, n_I -2.0..-2.5, k = 7e-12 1/Pa, m = 0.0511), sec. 2 (20 %)
    p = LEVANOV_2015
    assert (p.wear_limit, p.wear_rate, p.critical_film, p.k, p.m) == (30e-6, 1e-13, 1.9e-6, 7e-12, 0.0511)
    assert -2.5 <= p.n <= -2.0 and ALPHA_SCUFFING == p.alpha_scuffing == 0.2


def test_method1_against_hand_computation():
    # h = 5.3 um, n = -2: beta = 1 + (1.9/5.3)^2 = 1.1285155; R = exp(ln(3e8)/beta) = exp(17.296433) s = 9025 h
    r = levanov_method1(5.3e-6, **PAPER)
    assert float(r.beta) == pytest.approx(1 + (5.3 / 1.9) ** -2, rel=1e-14)
    assert float(r.beta) == pytest.approx(1.1285155, rel=1e-7)
    assert float(r.life) == pytest.approx(math.exp(17.296433), rel=1e-6)
    assert float(r.life_hours) == pytest.approx(9025, rel=1e-3)


def test_method1_paper_range_of_n():
    r = levanov_method1(3.5e-6, n=-2.5, **PAPER)
    assert float(r.beta) == pytest.approx(1 + (3.5 / 1.9) ** -2.5)
    assert float(r.life) == pytest.approx(math.exp(math.log(3e8) / float(r.beta)))


def test_healthy_films_of_the_paper_give_thousands_of_hours():
    # the paper's healthy bearings: mean minimum films 5.3-8.6 um, lives of the order of 10^3-10^4 h (its text and
    # Table 2's method-2 lives of about 1000 h); across n_I of -2.0..-2.5 method 1 stays within 10^3..10^5 h
    for n in (-2.0, -2.5):
        hours = levanov_method1(np.array([5.3e-6, 8.6e-6]), n=n, **PAPER).life_hours
        assert np.all((hours > 1e3) & (hours < 1e5)) and hours[1] > hours[0]


def test_cycle_mean_film_not_cycle_minimum_is_the_default_input():
    # a bearing in boundary friction for 10 % of the cycle at 1.5 um, 7.5 um otherwise
    h = np.where(np.arange(720) < 72, 1.5e-6, 7.5e-6)
    assert float(cycle_film(h)) == pytest.approx(0.1 * 1.5e-6 + 0.9 * 7.5e-6)
    assert float(cycle_film(h, statistic="cycle-minimum")) == 1.5e-6
    mean_life = levanov_method1(cycle_film(h), **PAPER).life_hours
    minimum_life = levanov_method1(cycle_film(h, statistic="cycle-minimum"), **PAPER).life_hours
    assert mean_life > 5000 and minimum_life < 100
    assert float(alpha(h, h_lim_cr=1.9e-6)) == pytest.approx(0.1)


def test_method1_monotone_in_h_min_and_bounded():
    h = np.geomspace(0.05e-6, 100e-6, 200)
    r = levanov_method1(h, **PAPER)
    assert np.all(np.diff(r.life) > 0) and np.all(np.diff(r.beta) < 0)
    assert r.life[-1] < 30e-6 / 1e-13 and r.life[-1] > 0.99 * 30e-6 / 1e-13


def test_method1_vanishing_and_zero_film():
    r = levanov_method1(np.array([0.0, 1e-300, 1e-30]), **PAPER)
    assert np.all(np.isfinite(r.life)) and np.all(r.life >= 1.0)
    assert float(r.life[0]) == 1.0


def test_critical_film_is_the_sum_of_the_roughnesses():
    assert float(critical_film(0.8e-6, 1.1e-6)) == pytest.approx(1.9e-6)
    with pytest.raises(ValueError, match="shell_roughness: 0.0 is not valid; must be > 0"):
        critical_film(1e-6, 0.0)


@pytest.mark.parametrize("kw, message", [
    (dict(h_min=-1e-6), "h_min: -1e-06 is not valid; must be >= 0"),
    (dict(h_min=1e-6, wear_rate=0.0), "wear_rate: 0.0 is not valid; must be > 0"),
    (dict(h_min=np.nan), "h_min: nan is not a finite number"),
    (dict(h_min=1e-6, n=0.5), "n: 0.5 is not valid; must be < 0"),
])
def test_method1_bad_input(kw, message):
    h = kw.pop("h_min")
    with pytest.raises(ValueError, match=message):
        levanov_method1(h, **{**PAPER, **kw})


def test_cycle_film_unknown_statistic():
    with pytest.raises(ValueError, match="statistic: 'minimum' is not one of 'cycle-mean', 'cycle-minimum'"):
        cycle_film(np.ones(4), statistic="minimum")


def test_alpha_share_of_cycle_below_critical():
    h = np.array([[1.0, 2.0, 3.0, 1.5], [5.0, 5.0, 5.0, 5.0]]) * 1e-6
    np.testing.assert_allclose(alpha(h, h_lim_cr=1.9e-6), [0.5, 0.0])
    np.testing.assert_allclose(alpha(h, h_lim_cr=np.array([1.9e-6, 6e-6])), [0.5, 1.0])


def test_life_summary_quantiles_and_share_below_target():
    life = np.arange(1, 1001, dtype=float) * 3600.0  # 1..1000 h
    s = life_summary(np.append(life, np.nan), target=100 * 3600.0)
    assert s.count == 1000
    assert s.b10[0] == pytest.approx(np.quantile(life, 0.1)) and s.b10[1] <= s.b10[0] <= s.b10[2]
    assert s.median[0] == pytest.approx(np.quantile(life, 0.5))
    assert s.share_below_target[0] == pytest.approx(0.099) and s.share_below_target[1] < 0.099 < s.share_below_target[2]
    np.testing.assert_allclose(engine_life(np.array([[5.0, 2.0, np.inf], [np.nan, 1.0, 3.0]])), [2.0, np.nan])
    # method 2 gives bearings that never wear an infinite life: quantiles among them are infinite, not NaN
    worn = life_summary(np.array([1.0, 2.0, np.inf, np.inf, np.inf]) * 3600, target=1.5 * 3600)
    assert worn.median[0] == np.inf and worn.b10[0] == pytest.approx(1.4 * 3600) and worn.share_below_target[0] == 0.2


# ---- method 2 -----------------------------------------------------------------------------------------------------

C = 25e-6
SURFACES = dict(h_lim_cr=1.9e-6, roughness=0.3e-6, contact_modulus=6e10, wear_limit=30e-6, journal_radius=0.023)


def f52(lam):
    """Independent reference: F_5/2 by quadrature."""
    return integrate.quad(lambda s: (s - lam) ** 2.5 * np.exp(-s * s / 2), lam, np.inf, epsrel=1e-12)[0] / np.sqrt(2 * np.pi)


def orbit(steps, *, h_low=1.2e-6, direction=0.0):
    """Journal centre over a cycle: film h_low at crank angle 0, thickening to 8 um, line of centres turning."""
    phi = np.radians(np.arange(steps) * 720.0 / steps)
    h = h_low + (8e-6 - h_low) * 0.5 * (1 - np.cos(phi))
    psi = direction + 0.6 * np.sin(phi / 2)
    e = C - h
    return np.stack([e * np.cos(psi), e * np.sin(psi)], axis=-1), np.arange(steps) * 720.0 / steps


def test_method2_hand_computed_constant_contact():
    # the journal sits still at e = c - 1.0 um along 0 deg: every step has the same contact arc
    e = C - 1.0e-6
    x = np.tile([e, 0.0], (720, 1))
    chart = levanov_method2(x, radial_clearance=C, crank_angle=np.arange(720.0), speed=400.0, points=14400, **SURFACES)
    beta_c = math.acos((C - 1.9e-6) / e)
    p = 16 * math.sqrt(2) / 15 * math.pi * 0.04**2 * math.sqrt(1e-3) * 6e10 * f52(1.0e-6 / 0.3e-6)
    per_cycle = 7e-12 * p**0.0511 * 2 * beta_c * 0.023 * 2.0  # eq. 6 times two revolutions per cycle
    assert float(chart.wear_per_cycle[0]) == pytest.approx(per_cycle, rel=2e-3)  # beta_c counted on 14400 points
    assert float(chart.contact_pressure_max) == pytest.approx(p, rel=1e-9)
    assert float(chart.wear_rate) == pytest.approx(chart.wear_per_cycle.max() / (4 * np.pi / 400.0))
    assert float(chart.life) == pytest.approx(30e-6 / float(chart.wear_rate))
    assert float(chart.deepest_angle) == pytest.approx(0.0, abs=1e-12) and float(chart.alpha) == pytest.approx(1.0)


def test_method2_does_not_depend_on_the_crank_angle_step():
    lives = []
    for steps in (360, 720, 1440):
        x, angle = orbit(steps)
        lives.append(float(levanov_method2(x, radial_clearance=C, crank_angle=angle, speed=419.0, **SURFACES).life))
    # eq. 6 added per step would make the life proportional to the step (x4 from 360 to 1440 steps); per
    # revolution it is the integral over the cycle, and the three step sizes agree within its quadrature error
    assert max(lives) / min(lives) - 1 < 0.01
    assert 1e3 * 3600 < lives[2] < 1e7 * 3600  # hours of the paper's order, not seconds


def test_method2_field_equals_method2_from_the_orbit():
    x, angle = orbit(180)
    points = 720
    theta = 2 * np.pi * np.arange(points) / points
    field = C - x @ np.stack([np.cos(theta), np.sin(theta)])
    a = levanov_method2(x, radial_clearance=C, crank_angle=angle, speed=419.0, points=points, **SURFACES)
    b = levanov_method2_field(field, crank_angle=angle, speed=419.0, **SURFACES)
    np.testing.assert_allclose(b.wear_per_cycle, a.wear_per_cycle, rtol=1e-12)
    assert float(b.life) == pytest.approx(float(a.life), rel=1e-12)


def test_method2_wears_where_the_film_is_thinnest():
    x, angle = orbit(360, direction=np.radians(200.0))
    chart = levanov_method2(x, radial_clearance=C, crank_angle=angle, speed=419.0, **SURFACES)
    # the line of centres sweeps 200 +- 34 deg; the thinnest film (crank angle 0) is at 200 deg
    assert np.degrees(float(chart.deepest_angle)) == pytest.approx(200.0, abs=3.0)
    assert np.all(chart.wear_per_cycle[np.abs(np.degrees(chart.position_angle) - 200) > 90] == 0)


def test_method2_broadcasts_and_never_wears_above_the_critical_film():
    x, angle = orbit(90)
    thick, _ = orbit(90, h_low=3e-6)
    chart = levanov_method2(np.stack([x, thick]), radial_clearance=C, crank_angle=angle, speed=419.0, **SURFACES)
    assert chart.life.shape == (2,) and chart.wear_per_cycle.shape == (2, 720)
    assert np.isfinite(chart.life[0]) and np.isinf(chart.life[1]) and np.isnan(chart.deepest_angle[1])
    assert chart.alpha[1] == 0 and chart.contact_pressure_max[1] == 0 and not chart.wear_per_cycle[1].any()
    # alpha is the share of the cycle below h_lim,cr
    h_min = C - np.linalg.norm(x, axis=-1)
    assert float(chart.alpha[0]) == pytest.approx(float(alpha(h_min, h_lim_cr=1.9e-6)))


@given(st.floats(1.0, 4.0))
def test_method2_life_falls_as_the_surfaces_get_rougher(scale):
    x, angle = orbit(90)
    kw = {**SURFACES, "h_lim_cr": 1.9e-6 * scale}
    rough = levanov_method2(x, radial_clearance=C, crank_angle=angle, speed=419.0, **kw)
    smooth = levanov_method2(x, radial_clearance=C, crank_angle=angle, speed=419.0, **SURFACES)
    assert float(rough.life) <= float(smooth.life)


@pytest.mark.parametrize("kw, message", [
    (dict(crank_angle=np.arange(0.0, 800.0, 10.0)), "crank_angle: must be 1-D, increase and span less than 720 deg"),
    (dict(roughness=0.0), "roughness: 0.0 is not valid; must be > 0"),
    (dict(radial_clearance=-1.0), "radial_clearance: -1.0 is not valid; must be > 0"),
])
def test_method2_bad_input(kw, message):
    x, angle = orbit(72)
    args = dict(radial_clearance=C, crank_angle=angle, speed=419.0, **SURFACES)
    args.update(kw)
    with pytest.raises(ValueError, match=message):
        levanov_method2(x, **args)


def test_method2_bearing_radius_is_the_deprecated_name_of_journal_radius():
    x, angle = orbit(72)
    args = dict(radial_clearance=C, crank_angle=angle, speed=419.0,
                **{k: v for k, v in SURFACES.items() if k != "journal_radius"})
    new = levanov_method2(x, **args, journal_radius=0.023)
    with pytest.warns(DeprecationWarning, match="bearing_radius= is deprecated; use journal_radius="):
        old = levanov_method2(x, **args, bearing_radius=0.023)
    np.testing.assert_array_equal(new.wear_per_cycle, old.wear_per_cycle)
    np.testing.assert_array_equal(new.life, old.life)
    field = np.full((1, angle.size, 8), 1e-6)
    del args["radial_clearance"]
    new = levanov_method2_field(field, **args, journal_radius=0.023)
    with pytest.warns(DeprecationWarning, match="bearing_radius= is deprecated; use journal_radius="):
        old = levanov_method2_field(field, **args, bearing_radius=0.023)
    np.testing.assert_array_equal(new.wear_per_cycle, old.wear_per_cycle)
