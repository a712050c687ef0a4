"""The block's supports: the bulkhead web's angular compliance, the checked description, the engine file's table."""

import numpy as np
import pytest

from stackup.crank.housing import bulkhead_compliance, supports
from stackup.engines import load_engine


def test_bulkhead_compliance_is_roarks_plate_strips():
    # a strip clamped at one end under an end couple: phi = M H / (E' I), I = W t^3 / 12, E' = E / (1 - nu^2);
    # clamped at both ends under a couple at mid-span: phi = M W / (16 E' I), I = d t^3 / 12 (Roark 8th ed., 8.1)
    e, nu, t, h, w, d = 110e9, 0.26, 0.024, 0.09, 0.16, 0.07
    stiff = e / (1 - nu**2)
    out = bulkhead_compliance(thickness=[t], height=h, width=w, ring_height=d, modulus=e, poisson=nu)
    np.testing.assert_allclose(out, [[h / (stiff * w * t**3 / 12), w / (16 * stiff * d * t**3 / 12)]], rtol=1e-12)
    # a web twice as thick is eight times as stiff
    twice = bulkhead_compliance(thickness=[2 * t], height=h, width=w, ring_height=d, modulus=e, poisson=nu)
    np.testing.assert_allclose(out / twice, 8.0, rtol=1e-12)


def test_builtin_engines_have_one_housing_for_the_law_and_the_tilt():
    for name in ("iso-example", "iso-example-aluminium", "rozhdestvensky-4", "nef-6"):
        e = load_engine(name)
        s = e.crank.supports
        assert s is not None and s.source and not s.rigid
        assert s.linear.shape == s.angular.shape == (e.main_bearings, 2)
        np.testing.assert_allclose(e.crank.law_parameters["k_lv"], 1 / s.linear[:, 0])
        # a bulkhead turns by micro-radians per N m: between 0.05 and 20 urad/(N m)
        assert np.all((s.angular > 0.05e-6) & (s.angular < 20e-6))
    iron, alu = (load_engine(n).crank.supports for n in ("iso-example", "iso-example-aluminium"))
    assert np.all(alu.linear > iron.linear)


def test_zero_angular_compliance_is_a_block_rigid_against_tilt():
    s = supports(linear=[1e-9, 0.6e-9], angular=[0.0, 0.0])
    assert s.rigid and s.linear.shape == (1, 2)


@pytest.mark.parametrize("kwargs, message", [
    (dict(linear=[-1e-9, 1e-9], angular=[0.0, 0.0]), "linear: -1e-09 is not valid; must be > 0"),
    (dict(linear=[1e-9, 1e-9], angular=[-1e-6, 0.0]), "angular: -1e-06 is not valid; must be >= 0"),
    (dict(linear=[1e-9, 1e-9, 1e-9], angular=[0.0, 0.0]), r"linear: shape \(1, 3\) is not valid"),
])
def test_supports_reject_bad_compliances(kwargs, message):
    with pytest.raises(ValueError, match=message):
        supports(**kwargs)


def test_bulkhead_rejects_a_zero_thickness():
    with pytest.raises(ValueError, match="thickness: 0.0 is not valid; must be > 0"):
        bulkhead_compliance(thickness=[0.0], height=0.1, width=0.2, ring_height=0.07, modulus=1e11, poisson=0.3)
