"""Mobility kernels against their numpy twins: the closed-form film force, the squeeze velocity, the orbit."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy import integrate, optimize

from stackup._kernels import mobility as kernel
from stackup.film.orbit import ECCENTRICITY_LIMIT, PERIODIC


def matrix_by_quadrature(eps, alpha):
    """G = integral over the squeezed half of n n^T / (1 - eps cos phi)^3 (adaptive quadrature)."""
    def part(f):
        return integrate.quad(lambda p: f(p) / (1 - eps * np.cos(p)) ** 3, alpha - np.pi / 2, alpha + np.pi / 2,
                              epsabs=0, epsrel=1e-10, limit=200)[0]
    return (part(lambda p: np.cos(p) ** 2), part(lambda p: np.cos(p) * np.sin(p)), part(lambda p: np.sin(p) ** 2))


NODES, WEIGHTS = np.polynomial.legendre.leggauss(400)


def force_twin(eps, alpha):
    """Film force per unit squeeze speed, line-of-centres frame: Gauss-Legendre over the squeezed half."""
    phi = alpha + 0.5 * np.pi * NODES
    n = np.stack([np.cos(phi), np.sin(phi)])
    return 0.5 * np.pi * (n * (WEIGHTS * np.cos(phi - alpha) / (1 - eps * np.cos(phi)) ** 3)).sum(axis=1)


def squeeze_velocity_twin(eps, load, guess=None):
    """Squeeze velocity carrying ``load`` (line-of-centres frame): root of the force's direction by brentq.

    The root is bracketed near ``guess`` first, else on a grid over the circle.
    """
    if not np.any(load):
        return np.zeros(2)
    target = np.arctan2(load[1], load[0])

    def gap(alpha):
        f = force_twin(eps, alpha)
        return np.angle(np.exp(1j * (np.arctan2(f[1], f[0]) - target)))

    grid = np.linspace(-np.pi, np.pi, 33)
    brackets = list(zip(grid[:-1], grid[1:]))
    if guess is not None:
        brackets.insert(0, (guess - 0.05, guess + 0.05))
    for a, b in brackets:
        ga, gb = gap(a), gap(b)
        if ga <= 0 <= gb and gb - ga < np.pi:
            alpha = optimize.brentq(gap, a, b, xtol=1e-13)
        elif abs(ga) < 1e-12:  # a root on a grid point at the circle's seam (+-pi), where rounding flips the sign
            alpha = a
        else:
            continue
        return np.linalg.norm(load) / np.linalg.norm(force_twin(eps, alpha)) * np.array([np.cos(alpha), np.sin(alpha)])
    raise AssertionError("no squeeze direction found")


def rate_twin(xi, load, guess=None):
    """d xi / d tau = v_s + (1/2) k x xi, engine frame; and the squeeze direction (line-of-centres frame)."""
    eps = np.linalg.norm(xi)
    e_r = xi / eps if eps > 0 else np.array([1.0, 0.0])
    e_t = np.array([-e_r[1], e_r[0]])
    v = squeeze_velocity_twin(min(eps, ECCENTRICITY_LIMIT), np.array([load @ e_r, load @ e_t]), guess)
    alpha = np.arctan2(v[1], v[0]) if np.any(v) else guess
    return v[0] * e_r + v[1] * e_t + 0.5 * np.array([-xi[1], xi[0]]), alpha


def orbit_twin(loads, cycles):
    """Explicit midpoint rule at every angle over whole cycles from the centre; the last cycle's positions."""
    n = len(loads)
    h = 4 * np.pi / n
    xi = np.zeros(2)
    alpha = None
    out = np.empty((n, 2))
    for _ in range(cycles):
        for k in range(n):
            out[k] = xi
            a, alpha = rate_twin(xi, loads[k], alpha)
            b, _ = rate_twin(xi + 0.5 * h * a, 0.5 * (loads[k] + loads[(k + 1) % n]), alpha)
            xi = xi + h * b
    return out


@settings(max_examples=60, deadline=None)
@given(st.floats(0.0, 0.995), st.floats(-np.pi, np.pi))
def test_closed_form_matrix_equals_quadrature(eps, alpha):
    got = np.array(kernel.short_matrix(eps, alpha))
    want = np.array(matrix_by_quadrature(eps, alpha))
    np.testing.assert_allclose(got, want, rtol=1e-8, atol=1e-9 * np.abs(want).max())


@settings(max_examples=40, deadline=None)
@given(st.floats(0.0, 0.99), st.floats(-np.pi, np.pi), st.floats(-3.0, 3.0))
def test_squeeze_velocity_carries_the_load(eps, direction, log_size):
    load = 10**log_size * np.array([np.cos(direction), np.sin(direction)])
    table, nodes = np.zeros((2, 2, 3)), np.array([0.0, 1.0])
    speed, alpha, ok = kernel.squeeze_velocity(eps, load[0], load[1], 0.3, table, nodes, False)
    assert ok
    v = speed * np.array([np.cos(alpha), np.sin(alpha)])
    # the kernel stops Newton once a step is below 1e-3 rad: the balance holds to about 1e-5
    np.testing.assert_allclose(v, squeeze_velocity_twin(eps, load), rtol=1e-4, atol=1e-9 * np.linalg.norm(v))
    np.testing.assert_allclose(speed * force_twin(eps, alpha), load, rtol=1e-4, atol=1e-5 * np.linalg.norm(load))


def test_force_turns_monotonically_with_the_squeeze_direction():
    for eps in (0.0, 0.5, 0.9, 0.99):
        alpha = np.linspace(-np.pi, np.pi, 721)
        f = np.array([np.array(kernel.short_matrix(eps, a)) for a in alpha])
        angle = np.unwrap(np.arctan2(f[:, 1] * np.cos(alpha) + f[:, 2] * np.sin(alpha),
                                     f[:, 0] * np.cos(alpha) + f[:, 1] * np.sin(alpha)))
        assert np.all(np.diff(angle) > 0)
        assert angle[-1] - angle[0] == pytest.approx(2 * np.pi)


def test_peak_factor_is_the_largest_mid_plane_pressure():
    for eps, alpha in ((0.0, 0.3), (0.6, -1.5), (0.95, -0.4), (0.99, 2.0), (0.8, np.pi)):
        phi = np.linspace(alpha - np.pi / 2, alpha + np.pi / 2, 200_001)[1:-1]
        brute = np.max(np.cos(phi - alpha) / (1 - eps * np.cos(phi)) ** 3)
        assert kernel.peak_factor(eps, alpha, 0.0)[0] == pytest.approx(brute, rel=1e-7)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.0, 0.995), st.floats(-np.pi, np.pi), st.floats(-np.pi, np.pi))
@example(0.96875, -3.0, 2.0)  # two peaks on the arc, the start on the lower one (found by hypothesis)
def test_peak_factor_from_any_start_is_the_maximum(eps, alpha, start):
    # the orbit starts each angle's search from the last angle's peak: any start must end at the maximum
    def minus_log(phi):
        return -(np.log(np.cos(phi - alpha)) - 3 * np.log1p(-eps * np.cos(phi)))

    phi = np.linspace(alpha - np.pi / 2, alpha + np.pi / 2, 4001)[1:-1]
    best = phi[np.argmin(minus_log(phi))]
    bounds = (max(best - np.pi / 4000, alpha - np.pi / 2 + 1e-12), min(best + np.pi / 4000, alpha + np.pi / 2 - 1e-12))
    found = optimize.minimize_scalar(minus_log, bounds=bounds, method="bounded", options={"xatol": 1e-10})
    factor, where = kernel.peak_factor(eps, alpha, start)
    assert factor == pytest.approx(np.exp(-found.fun), rel=1e-12)
    assert np.cos(where - alpha) / (1 - eps * np.cos(where)) ** 3 == pytest.approx(factor, rel=1e-12)


@given(st.floats(-np.pi, np.pi), st.floats(-kernel.STEP_DONE, kernel.STEP_DONE))
def test_small_turn_equals_the_cosine_and_sine_of_the_turned_angle(angle, step):
    c, s = kernel._turned(np.cos(angle), np.sin(angle), step)
    assert c == pytest.approx(np.cos(angle + step), abs=4e-16)
    assert s == pytest.approx(np.sin(angle + step), abs=4e-16)


@pytest.mark.parametrize("engine_like", ["light", "heavy"])
def test_orbit_kernel_equals_numpy_twin(engine_like):
    n = 180
    angle = np.arange(n) * 720.0 / n
    phase = np.radians(angle)
    size = 0.3 if engine_like == "light" else 30.0
    w = size * np.stack([1.0 + 2.5 * np.exp(-((angle - 370) / 25) ** 2) + 0.4 * np.cos(2 * phase),
                         0.6 * np.sin(phase) + 0.3 * np.sin(2 * phase)], axis=-1)
    tau = np.radians(np.append(angle, 720.0))
    xi = np.empty((1, n, 2))
    v = np.empty((1, n, 2))
    peak = np.empty((1, n))
    status = np.empty(1, np.int8)
    cycles = np.empty(1)
    short = kernel.Correction(np.zeros((1, 2, 2, 3)), np.array([1.0, 2.0]), np.array([0.0, 1.0]), False)
    kernel.orbits(w[None], tau, np.zeros((1, 2)), False, np.array([0.5]),
                  kernel.Integration(ECCENTRICITY_LIMIT, PERIODIC, 20), short, (xi, v, peak, status, cycles))
    assert status[0] == kernel.PERIODIC
    twin = orbit_twin(w, cycles=6)
    film = 1 - np.linalg.norm(twin, axis=-1)
    np.testing.assert_allclose(1 - np.linalg.norm(xi[0], axis=-1), film, rtol=0, atol=3 * PERIODIC * film.min())
