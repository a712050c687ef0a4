"""Greenwood-Tripp asperity contact: closed forms, quadrature, the published fit, hard cases."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import integrate

from stackup.contact import (TYPICAL_ASPERITIES, composite_roughness, contact_modulus, gaussian_height_integral,
                             greenwood_tripp)


def quadrature(order, lam):
    """Independent reference: F_n(lambda) by adaptive quadrature."""
    value = integrate.quad(lambda s: (s - lam) ** order * np.exp(-s * s / 2), lam, np.inf, epsabs=0, epsrel=1e-12)[0]
    return value / math.sqrt(2 * math.pi)


@pytest.mark.parametrize("order", [2.0, 2.5])
def test_height_integral_equals_quadrature(order):
    lam = np.array([-2.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 10.0])
    expected = [quadrature(order, x) for x in lam]
    np.testing.assert_allclose(gaussian_height_integral(order, lam), expected, rtol=1e-8)


def test_height_integral_at_zero_separation_closed_form():
    # F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi)  (half-moment of the standard normal)
    for n in (2.0, 2.5):
        closed = 2 ** ((n - 1) / 2) * math.gamma((n + 1) / 2) / math.sqrt(2 * math.pi)
        assert float(gaussian_height_integral(n, 0.0)) == pytest.approx(closed, rel=1e-12)


def test_pressure_interpolation_stays_within_1e_8_of_the_exact_form():
    lam = np.random.default_rng(0).uniform(-10.0, 37.0, 20000)
    exact = gaussian_height_integral(2.5, lam)
    p = greenwood_tripp(lam * 1e-6, roughness=1e-6, contact_modulus=1.0, asperities=TYPICAL_ASPERITIES)
    k = 16 * math.sqrt(2) / 15 * math.pi * 0.04**2 * math.sqrt(1e-3)
    np.testing.assert_allclose(p, k * exact, rtol=1e-8)
    assert float(greenwood_tripp(38e-6, roughness=1e-6, contact_modulus=1e11)) == 0.0


def test_published_polynomial_fit_of_f52_agrees_where_it_is_used():
    # Hu et al. 1994 (used by Arcoumanis et al. 1997): F_5/2(lambda) ~ 4.4086e-5 (4 - lambda)^6.804; within
    # 13 % up to lambda = 2 (the fit was made for piston-ring contacts, lambda < 2)
    lam = np.linspace(0.0, 2.0, 9)
    fit = 4.4086e-5 * (4 - lam) ** 6.804
    np.testing.assert_allclose(gaussian_height_integral(2.5, lam), fit, rtol=0.13)


def test_far_separation_underflows_to_zero_without_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        values = gaussian_height_integral(2.5, np.array([38.0, 40.0, 1e3, 1e300]))
    assert values[0] >= 0 and np.all(values[1:] == 0)


@given(st.floats(-3.0, 30.0), st.floats(0.01, 3.0))
def test_pressure_falls_as_the_film_thickens(lam, step):
    sigma = 0.3e-6
    p = greenwood_tripp(np.array([lam, lam + step]) * sigma, roughness=sigma, contact_modulus=6e10)
    assert p[0] >= p[1] >= 0 and p[0] > 0


def test_pressure_scale_and_composites():
    # steel on steel: E* = E / (2 (1 - nu^2))
    assert float(contact_modulus(210e9, 0.3, 210e9, 0.3)) == pytest.approx(210e9 / (2 * 0.91))
    assert float(composite_roughness(0.3e-6, 0.4e-6)) == pytest.approx(0.5e-6)
    p = greenwood_tripp(0.0, roughness=0.5e-6, contact_modulus=1e11)
    k = 16 * math.sqrt(2) / 15 * math.pi * 0.04**2 * math.sqrt(1e-3)
    assert float(p) == pytest.approx(k * 1e11 * quadrature(2.5, 0.0), rel=1e-10)
    assert TYPICAL_ASPERITIES.roughness_parameter == 0.04


@pytest.mark.parametrize("call, message", [
    (lambda: greenwood_tripp(1e-6, roughness=0.0, contact_modulus=1e11), "roughness: 0.0 is not valid; must be > 0"),
    (lambda: contact_modulus(2e11, 0.5, 7e10, 0.3), r"poisson_1: 0.5 is outside the valid range \(-1.0, 0.5\)"),
    (lambda: greenwood_tripp(np.nan, roughness=1e-6, contact_modulus=1e11), "film_thickness: nan is not a finite"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
