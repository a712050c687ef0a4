"""Processes, gauges and dimensions: closed forms, inversions and bad input."""

import numpy as np
import pytest
from scipy import integrate, special, stats

from stackup.tolerances import (
    Dimension, FormError, Gauge, Mixture, Normal, ToolWear, TruncatedNormal, Uniform, form_from_spec,
    process_from_spec, quantize,
)

UM = 1e-6


def test_normal_from_capability_centred_and_shifted():
    p = Normal.from_capability(50.000e-3, 50.018e-3, cpk=1.33)
    assert p.sigma == pytest.approx(18 * UM / (6 * 1.33))
    assert p.mean == pytest.approx(50.009e-3)
    q = Normal.from_capability(50.000e-3, 50.018e-3, cpk=1.0, cp=1.5, side="lower")
    # Cpk = (mean - lo) / (3 sigma) on the near side
    assert (q.mean - 50.000e-3) / (3 * q.sigma) == pytest.approx(1.0)
    assert (50.018e-3 - 50.000e-3) / (6 * q.sigma) == pytest.approx(1.5)


@pytest.mark.parametrize("cpk", [0.0, -1.0])
def test_cpk_not_positive_is_rejected(cpk):
    with pytest.raises(ValueError, match=r"cpk: .* is not valid; must be > 0"):
        Normal.from_capability(0.0, 1.0, cpk=cpk)


def test_cp_below_cpk_is_rejected():
    with pytest.raises(ValueError, match="cp: 1.0 is below cpk 1.33"):
        Normal.from_capability(0.0, 1.0, cpk=1.33, cp=1.0)


def test_tool_wear_cdf_matches_numerical_integral():
    p = ToolWear(start=46.004e-3, end=46.012e-3, sigma=1.5 * UM)
    for x in np.linspace(46.000e-3, 46.018e-3, 7):
        exact, _ = integrate.quad(lambda t: stats.norm.cdf(x, p.start + t * (p.end - p.start), p.sigma), 0, 1)
        assert p.cdf(x) == pytest.approx(exact, abs=1e-9)


@pytest.mark.parametrize(
    "process",
    [
        ToolWear(46.004e-3, 46.012e-3, 1.5e-6),
        ToolWear(46.012e-3, 46.004e-3, 1.5e-6),
        Mixture((Normal(50.006e-3, 1.5e-6), Normal(50.011e-3, 2e-6)), (0.4, 0.6)),
    ],
)
def test_tabulated_quantile_inverts_cdf_to_1e_5_sigma(process):
    u = np.linspace(1e-6, 1 - 1e-6, 2001)
    x = process.ppf(u)
    np.testing.assert_allclose(process.cdf(x), u, atol=2e-6)
    sigma_min = min(getattr(c, "sigma", np.inf) for c in getattr(process, "components", (process,)))
    # invert back: the quantile of cdf(x) returns x
    xs = np.linspace(process.mean - 3 * process.std, process.mean + 3 * process.std, 101)
    np.testing.assert_allclose(process.ppf(process.cdf(xs)), xs, atol=1e-5 * sigma_min)


def test_mixture_moments_match_samples():
    p = Mixture((Normal(1.0, 0.1), Normal(2.0, 0.2)), (0.3, 0.7))
    z = np.random.default_rng(0).standard_normal(400_000)
    x = p.from_normal(z)
    assert x.mean() == pytest.approx(p.mean, abs=3e-3)
    assert x.std() == pytest.approx(p.std, rel=5e-3)


def test_mixture_weights_must_sum_to_one():
    with pytest.raises(ValueError, match="mixture weights: they sum to 0.9"):
        Mixture((Normal(0, 1), Normal(1, 1)), (0.4, 0.5))


def test_truncated_normal_and_uniform_stay_inside():
    z = np.random.default_rng(1).standard_normal(10_000) * 3
    t = TruncatedNormal(0.0, 1.0, -0.5, 2.0).from_normal(z)
    u = Uniform(-1.0, 1.0).from_normal(z)
    assert t.min() >= -0.5 and t.max() <= 2.0
    assert u.min() >= -1.0 and u.max() <= 1.0
    assert abs(u.mean()) < 0.03


def test_mean_shift_moves_every_process():
    for p in (Normal(1.0, 0.1), Uniform(0.0, 1.0), ToolWear(0.0, 1.0, 0.1), TruncatedNormal(0.0, 1.0, -1, 1),
              Mixture((Normal(0, 1), Normal(1, 1)), (0.5, 0.5))):
        z = np.linspace(-2, 2, 9)
        np.testing.assert_allclose(p.shifted(0.25).from_normal(z), p.from_normal(z) + 0.25, atol=1e-9)


def test_gauge_rounds_to_nearest_step_and_adds_bias():
    g = Gauge(bias=0.2 * UM, resolution=1 * UM)
    read = g.read(np.array([50.0004e-3, 50.0002e-3, 50.0012e-3]), np.zeros(3))
    np.testing.assert_allclose(read, [50.001e-3, 50.000e-3, 50.001e-3], atol=1e-12)


def test_gauge_repeatability_is_the_reading_spread():
    g = Gauge(repeatability=0.5 * UM)
    z = np.random.default_rng(2).standard_normal(100_000)
    assert np.std(g.read(np.full(z.size, 46e-3), z)) == pytest.approx(0.5 * UM, rel=0.01)


def test_gauge_temperature_error():
    g = Gauge(temperature=30.0, expansion_mismatch=11.5e-6)
    assert g.read(50e-3, 0.0) - 50e-3 == pytest.approx(50e-3 * 11.5e-6 * 10)


def test_negative_repeatability_is_rejected():
    with pytest.raises(ValueError, match=r"gauge repeatability: -1e-06 is not valid; must be >= 0"):
        Gauge(repeatability=-1e-6)


def test_quantize_zero_step_is_identity():
    x = np.array([1.23456789])
    assert quantize(x, 0.0) is x


def test_shared_share_is_the_intra_group_correlation():
    dim = Dimension("housing_bore", 50.000e-3, 50.018e-3, Normal(50.009e-3, 2.25e-6), shared=0.3)
    rng = np.random.default_rng(3)
    x = dim.true_sizes(rng.standard_normal(50_000), rng.standard_normal((50_000, 2)))
    assert np.corrcoef(x[:, 0], x[:, 1])[0, 1] == pytest.approx(0.3, abs=0.015)
    assert x.std() == pytest.approx(2.25e-6, rel=0.01)


def test_inverted_drawing_limits_are_rejected():
    with pytest.raises(ValueError, match=r"shell_wall: upper limit 0.001491 m is below lower limit 0.001497 m"):
        Dimension("shell_wall", 1.497e-3, 1.491e-3, Normal(1.494e-3, 1e-6))


@pytest.mark.parametrize(
    "spec, message",
    [
        ({"distribution": "normal", "mean": 50.009, "sigma": -0.001}, r"housing_bore.sigma: -0.001 is not valid; must be > 0"),
        ({"distribution": "normal", "cpk": 0}, r"housing_bore.cpk: 0 is not valid; must be > 0"),
        ({"distribution": "normal", "mean": float("nan"), "sigma": 0.001}, r"housing_bore.mean: nan is not a finite number"),
        ({"distribution": "lognormal"}, r"housing_bore.distribution: 'lognormal' is not one of 'normal'"),
        ({"distribution": "normal", "cpk": 1.33, "colour": "red"}, r"housing_bore: unknown key\(s\) \['colour'\]"),
        ({"distribution": "tool-wear", "start": 50.004, "sigma": 0.001}, r"housing_bore: missing key 'end'"),
    ],
)
def test_bad_process_spec(spec, message):
    with pytest.raises(ValueError, match=message):
        process_from_spec(spec, lo=50.000e-3, hi=50.018e-3, scale=1e-3, field="housing_bore")


def test_larger_of_two_readings_has_the_closed_form_moments():
    # the largest of two independent standard normals: CDF Phi(x)^2, mean 1/sqrt(pi), variance 1 - 1/pi
    g = Gauge(repeatability=1.0, readings=2, combine="max")
    z = np.random.default_rng(0).standard_normal(400_000)
    noise = g.noise(z)
    assert noise.mean() == pytest.approx(1 / np.sqrt(np.pi), abs=0.005)
    assert noise.var() == pytest.approx(1 - 1 / np.pi, abs=0.005)
    x = np.array([-1.0, 0.0, 0.5, 1.5])
    np.testing.assert_allclose([np.mean(noise <= v) for v in x], special.ndtr(x) ** 2, atol=0.003)
    np.testing.assert_allclose(g.noise_moments(), (1 / np.sqrt(np.pi), np.sqrt(1 - 1 / np.pi)), rtol=1e-6)
    # part by part the larger reading is never below the single reading of the same normal
    assert np.all(noise >= Gauge(repeatability=1.0).noise(z) - 1e-12)


def test_mean_of_readings_divides_the_repeatability():
    g = Gauge(repeatability=2e-6, readings=4)
    assert g.noise(np.array([1.0])) == pytest.approx(1e-6)
    assert g.noise_moments() == (0.0, pytest.approx(1e-6))


def test_single_reading_sees_ovality_two_directions_cancel_it():
    z = np.random.default_rng(1).standard_normal((200_000, 3))
    one = FormError(ovality=3e-6, taper=0.0).reading_error(z)
    # o uniform on [0, 3 um], angle uniform: e = o/2 cos(2 phi), std = 3 um / sqrt(24)
    assert one.std() == pytest.approx(3e-6 / np.sqrt(24), rel=0.01)
    assert np.abs(one).max() <= 1.5e-6
    assert np.abs(FormError(ovality=3e-6, taper=0.0, directions=2).reading_error(z)).max() < 1e-18


def test_off_centre_plane_sees_taper_symmetric_planes_cancel_it():
    z = np.random.default_rng(2).standard_normal((100_000, 3))
    off = FormError(ovality=0.0, taper=3e-6, planes=(0.25,)).reading_error(z)
    # taper uniform on [-3, 3] um, read a quarter of the width off centre: e = -tau / 4
    assert np.abs(off).max() == pytest.approx(0.75e-6, rel=0.01)
    assert np.abs(FormError(ovality=0.0, taper=3e-6, planes=(0.25, 0.75)).reading_error(z)).max() < 1e-18


def test_form_and_gauge_specs_are_checked():
    with pytest.raises(ValueError, match=r"gauge combine: 'median' is not one of 'mean', 'max'"):
        Gauge(readings=2, combine="median")
    with pytest.raises(ValueError, match=r"key journal_d.form: form planes: 1.5 is outside the valid range"):
        form_from_spec({"planes": [1.5]}, scale=1e-3, field="key journal_d.form")
    with pytest.raises(ValueError, match=r"unknown key\(s\) \['lobes'\]"):
        form_from_spec({"lobes": 3}, scale=1e-3, field="form")


def test_capability_side_is_declared_and_a_file_names_its_key():
    with pytest.raises(ValueError, match=r"side: 'middle' is not one of 'upper', 'lower'"):
        Normal.from_capability(0.0, 1.0, cpk=1.0, cp=1.33, side="middle")
    with pytest.raises(ValueError, match=r"housing_bore.side: 'middle' is not one of 'upper', 'lower'"):
        process_from_spec({"cpk": 1.0, "cp": 1.33, "side": "middle"}, lo=50.000e-3, hi=50.018e-3, scale=1e-3,
                          field="housing_bore")
    with pytest.raises(ValueError, match=r"housing_bore.sigma: 0 is not valid; must be > 0"):
        process_from_spec({"distribution": "tool-wear", "start": 50.004, "end": 50.01, "sigma": 0},
                          lo=50.000e-3, hi=50.018e-3, scale=1e-3, field="housing_bore")


def test_form_spec_names_each_key_once():
    with pytest.raises(ValueError, match=r"^form.directions: 2.0 is not a whole number$"):
        form_from_spec({"directions": 2.0}, scale=1e-3, field="form")
    with pytest.raises(ValueError, match=r"^form.ovality: 1 is not a plausible gauge or form error"):
        form_from_spec({"ovality": 1.0}, scale=1e-3, field="form")
