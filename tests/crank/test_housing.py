"""The block's supports: the bulkhead web's angular compliance, the checked description, the engine file's table."""

import numpy as np
import pytest

from stackup.crank.housing import bulkhead_compliance, ring_tilt_compliance, supports
from stackup.crank.law import stiffness
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
        # the bore ring's own turn from the same deformation stiffness as the law's: at 0 deg (towards the cap)
        # in the cylinders' plane, at 90 deg across it
        law = e.crank.law_parameters
        k = [stiffness(a, law["k_lv"], law["k_hv"], law["theta0"], law["dtheta"])[0] for a in (0.0, np.pi / 2)]
        np.testing.assert_allclose(s.ring, 12 / (np.stack(k, -1) * e.crank.bearing_width**2), rtol=1e-12)
        np.testing.assert_allclose(s.tilt_compliance, s.angular + s.ring, rtol=1e-12)
    iron, alu = (load_engine(n).crank.supports for n in ("iso-example", "iso-example-aluminium"))
    assert np.all(alu.linear > iron.linear)


def test_zero_angular_compliance_is_a_block_rigid_against_tilt():
    s = supports(linear=[1e-9, 0.6e-9], angular=[0.0, 0.0])
    assert s.rigid and s.linear.shape == (1, 2)
    assert supports(linear=[1e-9, 0.6e-9], angular=[0.0, 0.0], ring=[0.0, 0.0]).rigid
    assert not supports(linear=[1e-9, 0.6e-9], angular=[0.0, 0.0], ring=[1e-6, 0.0]).rigid
    # one row of the block's compliances for every bearing beside a ring per bearing
    per_bearing = supports(linear=[1e-9, 0.6e-9], angular=[0.0, 0.0], ring=np.full((5, 2), 1e-6))
    assert per_bearing.linear.shape == per_bearing.angular.shape == per_bearing.ring.shape == (5, 2)


def test_ring_tilt_compliance_is_the_least_squares_turn_of_independent_slices():
    # the width as 2,000 slices, each with its share K dz / B of the deformation stiffness, under a load that
    # grows to one edge (the thin film's); its moment M about the mid-plane turns the slices' deflection by the
    # least-squares slope 12 M / (K B^2), whatever the load's shape
    k, width = 1.2e9, 0.03
    z = (np.arange(2000) + 0.5) / 2000 * width - width / 2
    dz = width / 2000
    load = 4e6 * np.exp(z / 0.004)  # [N/m]
    deflection = load * dz / (k * dz / width)
    moment = np.sum(load * z * dz)
    slope = np.sum(deflection * z) / np.sum(z * z)
    np.testing.assert_allclose(ring_tilt_compliance(stiffness=[k, k], bearing_width=width) * moment, [slope, slope],
                               rtol=1e-5)
    # a wider bearing turns less, as the square of its width
    np.testing.assert_allclose(ring_tilt_compliance(stiffness=[k, 2 * k], bearing_width=2 * width),
                               ring_tilt_compliance(stiffness=[4 * k, 8 * k], bearing_width=width), rtol=1e-12)


def test_supports_scaled_scales_the_bulkhead_and_the_ring():
    s = supports(linear=[1e-9, 0.6e-9], angular=[2e-6, 1e-6], ring=[20e-6, 15e-6]).scaled(0.5)
    np.testing.assert_allclose(s.tilt_compliance, [[11e-6, 8e-6]])
    np.testing.assert_allclose(s.linear, [[1e-9, 0.6e-9]])


@pytest.mark.parametrize("kwargs, message", [
    (dict(linear=[-1e-9, 1e-9], angular=[0.0, 0.0]), "linear: -1e-09 is not valid; must be > 0"),
    (dict(linear=[1e-9, 1e-9], angular=[-1e-6, 0.0]), "angular: -1e-06 is not valid; must be >= 0"),
    (dict(linear=[1e-9, 1e-9, 1e-9], angular=[0.0, 0.0]), r"linear: shape \(1, 3\) is not valid"),
    (dict(linear=[1e-9, 1e-9], angular=[0.0, 0.0], ring=[-1e-6, 0.0]), "ring: -1e-06 is not valid; must be >= 0"),
    (dict(linear=[1e-9, 1e-9], angular=[0.0, 0.0], ring=[1e-6, 0.0, 0.0]), r"ring: shape \(1, 3\) is not valid"),
])
def test_supports_reject_bad_compliances(kwargs, message):
    with pytest.raises(ValueError, match=message):
        supports(**kwargs)


def test_bulkhead_rejects_a_zero_thickness():
    with pytest.raises(ValueError, match="thickness: 0.0 is not valid; must be > 0"):
        bulkhead_compliance(thickness=[0.0], height=0.1, width=0.2, ring_height=0.07, modulus=1e11, poisson=0.3)


@pytest.mark.parametrize("kwargs, message", [
    (dict(stiffness=[1e9, 0.0], bearing_width=0.02), "stiffness: 0.0 is not valid; must be > 0"),
    (dict(stiffness=[1e9, 1e9], bearing_width=-0.02), "bearing_width: -0.02 is not valid; must be > 0"),
])
def test_ring_tilt_compliance_rejects_bad_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        ring_tilt_compliance(**kwargs)


def test_the_coupled_chain_turns_each_bore_by_its_bulkhead_and_its_ring():
    from stackup.crank import support_compliance
    from stackup.study.chain import _engine_constants

    e = load_engine("iso-example")
    coupled = _engine_constants(e).coupled
    crank = support_compliance(spans=e.crank.spans, EI=e.crank.ei, coupled=True)
    for plane in range(2):
        np.testing.assert_allclose(coupled[plane] - crank[plane], np.diag(e.crank.supports.tilt_compliance[:, plane]),
                                   rtol=1e-12, atol=1e-18)
