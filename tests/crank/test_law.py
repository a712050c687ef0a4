"""Bearing law: overflow-free form, derivatives, kernel twin."""

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from stackup._kernels.crank import _bearing, _softplus
from stackup.crank.law import REST, BellakhdharLaw, force, gap_function, stiffness


def direct_form(u, clearance, dx):
    """The paper's eq. 6 written literally (overflows for large u/dx)."""
    e = np.exp(-clearance / dx)
    return dx * (1 + e) * np.log((1 + np.exp((u - clearance) / dx)) / (1 + e)) - u * e


def test_gap_function_equals_the_papers_form_where_that_does_not_overflow():
    u = np.linspace(0, 200e-6, 401)
    g, _ = gap_function(u, 37e-6, 9.65e-6)
    np.testing.assert_allclose(g, direct_form(u, 37e-6, 9.65e-6), rtol=1e-12, atol=1e-18)


def test_no_overflow_for_huge_displacement():
    g, dg = gap_function(np.array([1.0, 1e3]), 37e-6, 1e-9)
    assert np.all(np.isfinite(g)) and np.all(np.isfinite(dg))
    np.testing.assert_allclose(g, [1.0 - 37e-6, 1e3 - 37e-6], rtol=1e-9)


def test_law_has_no_stiffness_at_rest_and_full_stiffness_far_out():
    g, dg = gap_function(np.array([0.0, 500e-6]), 37e-6, 9.65e-6)
    assert g[0] == 0 and dg[0] == pytest.approx(0, abs=1e-15)
    assert dg[1] == pytest.approx(1, abs=1e-12)


def test_bilinear_limit():
    g, dg = gap_function(np.array([10e-6, 37e-6, 50e-6]), 37e-6, 0.0)
    np.testing.assert_allclose(g, [0, 0, 13e-6], atol=1e-18)
    np.testing.assert_array_equal(dg, [0, 0, 1])


def test_stiffness_sigmoid_ends():
    kd, _ = stiffness(np.radians([0.0, 97.0, 180.0]), 0.98e9, 1.72e9, np.radians(97), np.radians(15))
    assert kd[0] == pytest.approx(0.98e9, rel=2e-3)
    assert kd[1] == pytest.approx(0.5 * (0.98e9 + 1.72e9))
    assert kd[2] == pytest.approx(1.72e9, rel=2e-3)


law = BellakhdharLaw()
params = law.arrays(())


@given(st.floats(-150e-6, 150e-6), st.floats(-150e-6, 150e-6))
def test_jacobian_matches_finite_differences(u0, u1):
    u = np.array([u0, u1])
    assume(np.hypot(u0, u1) >= 1e-7 and abs(u1) >= 1e-8)  # theta's kink on the axis and the rest point: checked apart
    f, jac = force(u, params)
    h = 1e-11
    for k in range(2):
        e = np.zeros(2)
        e[k] = h
        numeric = (force(u + e, params)[0] - force(u - e, params)[0]) / (2 * h)
        np.testing.assert_allclose(jac[:, k], numeric, rtol=2e-5, atol=1e-3 * np.abs(jac).max() + 1.0)


# a subnormal transition width (5e-324 m) overflows clearance / dx; below 1e-300 m the law is bilinear to the last bit
@given(st.floats(-300e-6, 300e-6), st.floats(-300e-6, 300e-6), st.floats(0, 60e-6),
       st.floats(0, 20e-6, allow_subnormal=False))
def test_kernel_bearing_equals_numpy_law(u0, u1, clearance, dx):
    p = BellakhdharLaw(clearance=clearance, dx=dx).arrays(())
    f, jac = force(np.array([u0, u1]), p)
    e = np.exp(-clearance / dx) if dx > 0 else 0.0
    sp0 = _softplus(-clearance / dx) if dx > 0 else 0.0
    got = _bearing(u0, u1, clearance, dx, e, sp0, *(float(x) for x in p[2:]), REST)
    np.testing.assert_allclose(got[:2], f, rtol=1e-10, atol=1e-6)
    np.testing.assert_allclose(got[2:], jac.ravel(), rtol=1e-9, atol=1e-3)


def test_force_points_along_the_displacement_and_grows_with_it():
    u = np.array([[10e-6, 0], [50e-6, 0], [100e-6, 0], [0, 100e-6], [-100e-6, 0]])
    f, _ = force(u, params)
    assert np.all(np.diff(f[:3, 0]) > 0)
    assert f[4, 0] < 0 and abs(f[4, 0]) > abs(f[2, 0])  # towards the block is stiffer (k_hv)
    np.testing.assert_allclose(u[:, 0] * f[:, 1] - u[:, 1] * f[:, 0], 0, atol=1e-9)


def test_bad_law_parameters():
    with pytest.raises(ValueError, match="law dx: -1e-06 is not valid"):
        BellakhdharLaw(dx=-1e-6)
    with pytest.raises(ValueError, match="law k_lv: 0.0 is not valid"):
        BellakhdharLaw(k_lv=0.0)


def test_law_displacement_inverts_the_law():
    from stackup.crank.law import displacement

    load = np.geomspace(1.0, 1e5, 50)
    u = displacement(load, 37e-6, 9.65e-6, 0.98e9)
    g, _ = gap_function(u, 37e-6, 9.65e-6)
    np.testing.assert_allclose(0.98e9 * g, load, rtol=1e-10)


def test_fit_recovers_the_law_that_made_the_curve():
    from stackup.crank.law import displacement, fit_bellakhdhar

    # a "film" curve built from a known law: U_film = U_law(R) - R / K_d (per direction: use k_lv = k_hv)
    load = np.geomspace(10.0, 8e4, 40)
    j, dx, k = np.array([25e-6, 40e-6]), np.array([4e-6, 12e-6]), 1.2e9
    film = displacement(load, j[:, None], dx[:, None], k) - load / k
    fit = fit_bellakhdhar(np.tile(load, (2, 1)), film, k_lv=k, k_hv=k, theta0=np.radians(97.0),
                          dtheta=np.radians(15.0), radial_clearance=np.array([30e-6, 30e-6]))
    assert fit.converged.all()
    np.testing.assert_allclose(fit.law.clearance, j, rtol=1e-6)
    np.testing.assert_allclose(fit.law.dx, dx, rtol=1e-5)
    assert np.all(fit.rms_error < 1e-10)


def test_fit_rejects_mismatched_samples():
    from stackup.crank.law import fit_bellakhdhar

    with pytest.raises(ValueError, match="film_displacement: shape"):
        fit_bellakhdhar(np.ones((2, 5)), np.ones((2, 4)), k_lv=1e9, k_hv=1e9, theta0=1.0, dtheta=0.3,
                        radial_clearance=30e-6)


def test_fit_clearance_guess_is_the_deprecated_name_of_radial_clearance():
    from stackup.crank.law import displacement, fit_bellakhdhar

    load = np.geomspace(10.0, 8e4, 20)
    film = displacement(load, 30e-6, 8e-6, 1.2e9) - load / 1.2e9
    kw = dict(k_lv=1.2e9, k_hv=1.2e9, theta0=np.radians(97.0), dtheta=np.radians(15.0))
    new = fit_bellakhdhar(load, film, **kw, radial_clearance=30e-6)
    with pytest.warns(DeprecationWarning, match="clearance_guess= is deprecated; use radial_clearance="):
        old = fit_bellakhdhar(load, film, **kw, clearance_guess=30e-6)
    np.testing.assert_array_equal(new.law.clearance, old.law.clearance)
    np.testing.assert_array_equal(new.law.dx, old.law.dx)
