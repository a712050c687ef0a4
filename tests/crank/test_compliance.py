"""Rotational compliance of the crankshaft at its supports: slope-deflection closed forms and the beam's own slopes."""

import numpy as np
import pytest

from stackup.crank import support_compliance, support_slopes


def test_single_span_turns_by_l_over_3ei_at_each_end():
    # a span pinned at both ends, moment M at one end: theta_near = M l/(3EI), theta_far = -M l/(6EI)
    l, ei = 0.1, 1e4
    c = support_compliance(spans=[l], EI=ei, coupled=True)[0]
    np.testing.assert_allclose(c, [[l / (3 * ei), -l / (6 * ei)], [-l / (6 * ei), l / (3 * ei)]], rtol=1e-10)


def test_two_equal_spans_by_slope_deflection():
    # moment at the end support A of spans AB, BC (supports held, B and C turn freely):
    # theta_A = 7 M l/(24 EI), theta_B = -theta_A/3.5, theta_C = -theta_B/2; at the middle support l/(6EI)
    l, ei = 0.085, 1.1e4
    c = support_compliance(spans=[l, l], EI=ei, coupled=True)[0]
    theta_a = 7 * l / (24 * ei)
    np.testing.assert_allclose(c[:, 0], [theta_a, -theta_a / 3.5, theta_a / 7], rtol=1e-10)
    assert c[1, 1] == pytest.approx(l / (6 * ei), rel=1e-10)
    np.testing.assert_allclose(support_compliance(spans=[l, l], EI=ei)[:, 0], np.diag(c), rtol=1e-12)


def test_compliance_is_symmetric_positive_and_per_plane():
    ei = [[1.0e4, 2.0e4], [1.2e4, 2.2e4], [0.9e4, 1.9e4]]
    c = support_compliance(spans=[0.08, 0.09, 0.085], EI=ei, load_positions=[0.4, 0.5, 0.6], coupled=True)
    for plane in c:
        np.testing.assert_allclose(plane, plane.T, rtol=1e-12)
        assert np.all(np.linalg.eigvalsh(plane) > 0)
    assert np.all(c[1].diagonal() < c[0].diagonal())  # the stiffer plane turns less


def test_a_support_moment_is_what_the_slopes_see():
    # a couple M at support j equals two opposite point loads on the span beside it, close to the support
    # (P d = M): the slope at j they give, with the supports held, tends to C_jj M
    l, ei, m = 0.1, 1e4, 5.0
    d = 1e-4 * l
    p = m / d
    c = support_compliance(spans=[l, l], EI=ei, coupled=True)[0]
    # loads at d and 2d from support 0 on span 0: the moment about support 0 is p (2d) - p d = m
    from stackup.crank import reactions
    slopes = []
    for position in (1e-4, 2e-4):
        loads = np.array([[p if position == 2e-4 else -p, 0.0], [0.0, 0.0]])
        r = reactions(loads, spans=[l, l], EI=ei, load_positions=[position, 0.5], law=None)
        slopes.append(support_slopes(loads, r.displacements, spans=[l, l], EI=ei, load_positions=[position, 0.5]))
    slope = slopes[0][0, 0] + slopes[1][0, 0]
    assert slope == pytest.approx(c[0, 0] * m, rel=1e-3)
