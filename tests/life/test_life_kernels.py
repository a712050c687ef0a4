"""The life kernel equals its numpy twin: the dense film over every chart point at every crank angle."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from stackup._kernels.life import contact_zones


def contact_zones_twin(x, c, critical, cos_p, sin_p, weights):
    """numpy twin of :func:`stackup._kernels.life.contact_zones`: the film at every point, then the points below."""
    below = c[:, None] - np.linalg.norm(x, axis=-1) < critical[:, None]  # (rows, steps)
    share = below @ weights
    rows, steps = np.nonzero(below)
    film = c[rows, None] - x[rows, steps] @ np.stack([cos_p, sin_p])  # (rows below, points)
    zone = film < critical[rows, None]
    i, p = np.nonzero(zone)
    return share, rows[i], steps[i], p, film[i, p], zone.sum(axis=1)[i]


@given(seed=st.integers(0, 2**32 - 1), rows=st.integers(1, 6), steps=st.integers(1, 50),
       points=st.sampled_from([8, 36, 720]), reach=st.floats(0.5, 1.2))
def test_contact_zones_equal_the_dense_numpy_twin(seed, rows, steps, points, reach):
    rng = np.random.default_rng(seed)
    c = rng.uniform(10e-6, 40e-6, rows)
    critical = rng.uniform(0.5e-6, 3e-6, rows)
    radius = reach * c[:, None] * np.sqrt(rng.uniform(size=(rows, steps)))  # up to beyond the clearance
    angle = rng.uniform(0, 2 * np.pi, (rows, steps))
    x = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=-1)
    theta = 2 * np.pi * np.arange(points) / points
    weights = rng.uniform(0.5, 1.5, steps)
    weights /= weights.sum()
    args = (x, c, critical, np.cos(theta), np.sin(theta), weights)
    got, want = contact_zones(*args), contact_zones_twin(*args)
    np.testing.assert_allclose(got[0], want[0], rtol=1e-12, atol=1e-15)
    for a, b in zip(got[1:], want[1:]):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-18)  # exact for the indices, the films to rounding


def test_no_contact_lists_nothing_and_a_touching_journal_lists_its_zone():
    c, critical = np.array([30e-6]), np.array([2e-6])
    theta = 2 * np.pi * np.arange(720) / 720
    weights = np.full(4, 0.25)
    centred = np.zeros((1, 4, 2))
    share, row, *_ = contact_zones(centred, c, critical, np.cos(theta), np.sin(theta), weights)
    assert share[0] == 0 and row.size == 0
    touching = np.zeros((1, 4, 2))
    touching[0, 1] = [29e-6, 0.0]  # film 1 um at theta = 0 at the second step only
    share, row, step, point, film, zone = contact_zones(touching, c, critical, np.cos(theta), np.sin(theta), weights)
    assert share[0] == 0.25 and set(step) == {1}
    assert abs(film.min() - 1e-6) < 1e-18
    # the zone is the arc where 30 - 29 cos(theta) < 2 um: |theta| < acos(28/29)
    half = np.arccos(28 / 29)
    assert abs(zone[0] * np.pi / 720 - half) <= np.pi / 720
