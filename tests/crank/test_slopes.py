"""Support slopes of the crankshaft beam: closed forms and rigid-body motion."""

import numpy as np
import pytest

from stackup.crank import reactions, support_slopes


def test_two_span_beam_with_a_load_on_one_span_has_the_textbook_end_slopes():
    # spans l, l on rigid supports, P at mid-span 1: hogging moment 3Pl/32 over the middle support
    # (three-moment equation); each span simply supported under its loads and end moments (w along P)
    p, l, ei = 1000.0, 0.1, 1e4
    loads = np.array([[p, 0.0], [0.0, 0.0]])
    r = reactions(loads, spans=[l, l], EI=ei, law=None)
    slope = support_slopes(loads, r.displacements, spans=[l, l], EI=ei)[:, 0]
    m = 3 * p * l / 32  # hogging moment over the middle support
    # span 1 simply supported with P at mid-span and M at its right end; span 2 with M at its left end
    theta_a = p * l**2 / (16 * ei) - m * l / (6 * ei)
    theta_b = -p * l**2 / (16 * ei) + m * l / (3 * ei)
    theta_c = m * l / (6 * ei)  # span 2 bows against P under the hogging moment and rises back to C
    np.testing.assert_allclose(slope, [theta_a, theta_b, theta_c], rtol=1e-10)
    assert theta_a == pytest.approx(3 * p * l**2 / (64 * ei))


def test_rigid_body_tilt_of_an_unloaded_beam_is_its_slope_everywhere():
    spans = np.array([0.085, 0.09, 0.085])
    z = np.concatenate([[0.0], np.cumsum(spans)])
    w = np.stack([2e-6 + 3e-4 * z, -1e-6 - 5e-5 * z], axis=-1)
    slope = support_slopes(np.zeros((3, 2)), w, spans=spans, EI=[[1e4, 2e4]] * 3)
    np.testing.assert_allclose(slope, np.tile([3e-4, -5e-5], (4, 1)), rtol=1e-9, atol=1e-15)


def test_slopes_broadcast_over_engines_and_angles():
    rng = np.random.default_rng(2)
    loads = rng.normal(0, 1e4, (3, 7, 4, 2))
    w = rng.normal(0, 1e-5, (3, 7, 5, 2))
    spans = [0.085] * 4
    out = support_slopes(loads, w, spans=spans, EI=1e4)
    one = support_slopes(loads[1, 2], w[1, 2], spans=spans, EI=1e4)
    assert out.shape == (3, 7, 5, 2)
    np.testing.assert_allclose(out[1, 2], one)
