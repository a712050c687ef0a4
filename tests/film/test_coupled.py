"""Support moments of all bearings (stackup.film.coupled): kernels against numpy twins, hard cases, bad input."""

import numpy as np
import pytest
from scipy import optimize

from stackup._kernels import coupled as kernel
from stackup._kernels import tilt as tilt_kernel
from stackup._validate import trusted
from stackup.contact import layer_contact
from stackup.film.coupled import ElasticLayer, _contact_rule, support_moments
from stackup.film.tilt import quadrature, short_film

QUADRATURE = quadrature()
SIGMA, MODULUS, STIFFNESS = 0.32e-6, 6e10, 1.1e14
LAYER = ElasticLayer(STIFFNESS, SIGMA, MODULUS)


@pytest.mark.parametrize("xi, v, e, u", [
    ([0.6, 0.1], [0.2, 0.5], [0.1, -0.05], [0.3, 0.2]),
    ([-0.3, 0.7], [-0.4, 0.6], [0.0, 0.15], [-0.5, 0.1]),
    ([0.2, -0.5], [0.8, -0.2], [0.2, 0.1], [0.0, 0.0]),
])
def test_squeeze_moment_equals_its_numpy_twin_with_a_tilt_squeeze(xi, v, e, u):
    out = tilt_kernel.squeeze_moment(*xi, *v, *e, *u, QUADRATURE)
    force, moment = short_film(xi, v, e, tilt_squeeze=u, lines=8192)
    np.testing.assert_allclose(out[:2], force, rtol=2e-3, atol=2e-3 * np.abs(force).max())
    np.testing.assert_allclose(out[2:], moment, rtol=5e-3, atol=5e-3 * np.abs(moment).max())


def test_tilt_held_is_the_tilt_squeeze_of_the_film_moment():
    xi, v, e = [0.5, 0.2], [0.3, 0.4], [0.1, 0.05]
    held = [0.5 * e[1], -0.5 * e[0]]
    np.testing.assert_array_equal(tilt_kernel.film_moment(*xi, *v, *e, QUADRATURE),
                                  tilt_kernel.squeeze_moment(*xi, *v, *e, *held, QUADRATURE))
    _, twin = short_film(xi, v, e)
    _, mine = short_film(xi, v, e, tilt_squeeze=held, lines=4096)
    np.testing.assert_allclose(mine, twin, rtol=1e-10)


def test_a_tilt_closing_faster_meets_more_resistance():
    # the tilt's squeeze: a tilt growing (u along the tilt) is resisted by a larger moment against it
    xi, v, e = [0.5, 0.0], [0.0, 0.5], [0.2, 0.0]
    held = np.array([0.0, -0.1])
    slow = tilt_kernel.squeeze_moment(*xi, *v, *e, *held, QUADRATURE)[2]
    fast = tilt_kernel.squeeze_moment(*xi, *v, *e, *(held + [0.5, 0.0]), QUADRATURE)[2]
    assert fast > slow


def contact_twin(xi, e, roughness, unit, c=25e-6, lines=2048, axial=801):
    """Numpy twin of the asperities' force and moment: midpoint rule over the whole bearing, the layer exact
    (``roughness`` [m], films in clearances ``c``)."""
    theta = 2 * np.pi * (np.arange(lines) + 0.5) / lines
    zeta = -1 + 2 * (np.arange(axial) + 0.5) / axial
    n = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    rigid = 1 - n @ np.asarray(xi) - zeta[:, None] * (n @ np.asarray(e))[None, :]
    p = np.zeros_like(rigid)
    near = rigid * c < 8 * roughness
    p[near] = layer_contact(rigid[near] * c, roughness=roughness, contact_modulus=MODULUS,
                            stiffness=STIFFNESS).pressure
    dz, dt = 2 / axial, 2 * np.pi / lines
    line = p.sum(0) * dz
    line1 = (p * zeta[:, None]).sum(0) * dz
    return (0.5 * unit * (n * line[:, None]).sum(0) * dt, 0.25 * unit * (n * line1[:, None]).sum(0) * dt)


@pytest.mark.parametrize("xi, e", [
    ([0.9, 0.1], [0.1, 0.02]),       # an edge into the roughness
    ([0.5, -0.4], [0.25, -0.2]),     # an edge past the wall
    ([0.99, 0.0], [0.0, 0.0]),       # aligned, the whole width in contact
])
def test_contact_moment_equals_its_numpy_twin(xi, e):
    c = 25e-6
    sigma = SIGMA / c
    table = LAYER.table()
    unit = 1e-7  # c^2 / (mu omega L^2) [1/Pa]
    out = kernel.contact_moment(*xi, *e, sigma, unit, table, _contact_rule())
    force, moment = contact_twin(xi, e, SIGMA, unit)
    assert np.abs(force).max() > 0
    np.testing.assert_allclose(out[:2], force, rtol=0.03, atol=0.03 * np.abs(force).max())
    if np.abs(moment).max() > 1e-6 * np.abs(force).max():
        np.testing.assert_allclose(out[2:], moment, rtol=0.05, atol=0.05 * np.abs(moment).max())


def test_surface_film_is_the_layers_film_at_the_thinner_edge():
    sigma = SIGMA / 25e-6
    table = LAYER.table()
    # zero load: the journal centred and aligned, the film the clearance
    assert kernel.surface_film(0.0, 0.0, 0.0, 0.0, sigma, table) == pytest.approx(1.0)
    # full tilt: the edges at the wall, a computed film (not a floor) of the layer
    film = kernel.surface_film(0.0, 0.0, 1.0, 0.0, sigma, table)
    exact = float(layer_contact(0.0, roughness=SIGMA, contact_modulus=MODULUS, stiffness=STIFFNESS).film) / 25e-6
    assert film == pytest.approx(exact, rel=1e-3) and film > 0
    # past the wall: negative, and above the rigid overlap
    deep = kernel.surface_film(0.3, 0.0, 0.72, 0.0, sigma, table)
    assert -0.02 < deep < 0


def _case(b=2, n=72, eps=0.5, tilt=1e-3, c=25e-6, length=20e-3):
    """A steady journal (centre fixed, the load turning with the shaft) on every bearing, a constant free tilt."""
    angle = np.arange(n) * 720.0 / n
    position = np.zeros((1, b, n, 2))
    position[..., 0] = eps * c
    free = np.zeros((1, b, n, 2))
    free[..., 1] = tilt
    kw = dict(journal_radius=25e-3, bearing_width=length, radial_clearance=c, viscosity=0.01, speed=300.0,
              layer=LAYER, method="short")
    return position, free, angle, kw


def test_zero_compliance_keeps_the_free_tilt():
    position, free, angle, kw = _case()
    out = support_moments(position, free, angle, compliance=np.zeros((2, 2, 2)), **kw)
    np.testing.assert_allclose(out.tilt, free, atol=1e-15)
    assert np.all(out.state == 0)


def test_zero_load_and_no_free_tilt_keep_the_journal_centred_and_aligned():
    position, free, angle, kw = _case(eps=0.0, tilt=0.0)
    out = support_moments(position, free, angle, compliance=np.full((2, 2, 2), 1e-6), **kw)
    np.testing.assert_allclose(out.tilt, 0.0, atol=1e-12)
    np.testing.assert_allclose(out.film, 25e-6, rtol=1e-9)


def test_full_tilt_on_a_rigid_crank_gives_a_computed_negative_film():
    # the free tilt puts the edges 1.5 clearances over: held (zero compliance), the layer takes the overlap
    position, free, angle, kw = _case(eps=0.0, tilt=1.5 * 2 * 25e-6 / 20e-3)
    out = support_moments(position, free, angle, compliance=np.zeros((2, 2, 2)), **kw)
    assert np.all(np.isfinite(out.film)) and np.all(out.film < 0) and np.all(out.film > -25e-6)


def test_steady_balance_equals_a_numpy_root_of_the_film_force_and_moment():
    # one bearing, steady journal, the tilt held: the centre moves by d so that the tilted film carries the
    # untilted film's load, F(xi + d, e) = F(xi, 0), and e = free - kappa M(xi + d, e); F and M the short
    # film's (numpy twin), the squeeze velocity -(1/2) k x (xi + d) of a steady journal
    position, free, angle, kw = _case(b=1, eps=0.6, tilt=0.8e-3)
    compliance = np.zeros((2, 1, 1))
    compliance[:] = 20e-6
    out = support_moments(position, free, angle, compliance=compliance, tolerance=1e-4, **kw)
    c, length, r, mu, w = 25e-6, 20e-3, 25e-3, 0.01, 300.0
    unit = mu * w * r * length**4 / c**2
    scale = length / (2 * c)
    xi = np.array([0.6, 0.0])

    def film(centre, e):
        return short_film(centre, -0.5 * np.array([-centre[1], centre[0]]), e, lines=20000)

    load, _ = film(xi, np.zeros(2))

    def residual(z):
        force, moment = film(xi + z[:2], z[2:])
        return np.concatenate([(force - load) / (1 + np.linalg.norm(load)),
                               z[2:] - free[0, 0, 0] * scale + compliance[:, 0, 0] * scale * unit * moment])

    root = optimize.fsolve(residual, np.concatenate([np.zeros(2), free[0, 0, 0] * scale]), xtol=1e-12)
    assert np.linalg.norm(root[2:]) < np.linalg.norm(free[0, 0, 0] * scale)  # the film turns the journal back
    assert np.linalg.norm(root[:2]) > 1e-3  # and its centre moves: the tilted film does not carry the load where it was
    np.testing.assert_allclose(out.tilt[0, 0, 0] * scale, root[2:], atol=2e-3 * np.linalg.norm(root[2:]))
    np.testing.assert_allclose(out.centre[0, 0, 0] / c, xi + root[:2], atol=2e-3 * np.linalg.norm(root[:2]))
    np.testing.assert_allclose(out.tilt[0, 0], out.tilt[0, 0, :1].repeat(len(angle), 0), atol=1e-3 * np.abs(out.tilt).max())
    assert out.state[0, 0] == 0


def test_no_tilt_leaves_the_film_tiers_orbit_where_it_is():
    position, free, angle, kw = _case(eps=0.7, tilt=0.0)
    out = support_moments(position, free, angle, compliance=np.full((2, 2, 2), 2e-6) * np.eye(2), **kw)
    np.testing.assert_allclose(out.centre, position, atol=1e-9 * 25e-6)
    np.testing.assert_allclose(out.tilt, 0.0, atol=1e-12)


def test_more_compliance_turns_the_journal_back_further():
    position, free, angle, kw = _case(eps=0.7, tilt=1.2e-3)
    small = support_moments(position, free, angle, compliance=np.full((2, 2, 2), 0.5e-6) * np.eye(2), **kw)
    large = support_moments(position, free, angle, compliance=np.full((2, 2, 2), 5e-6) * np.eye(2), **kw)
    assert np.all(np.abs(large.tilt[..., 1]) < np.abs(small.tilt[..., 1]))
    assert np.all(large.film > small.film)


@pytest.mark.parametrize("change, message", [
    (dict(compliance=-np.ones((2, 2, 2)) * 1e-6), "compliance: a diagonal value -1e-06 is not valid"),
    (dict(compliance=np.zeros((2, 3, 3))), r"compliance: shape \(2, 3, 3\) is not valid; expected \(2, 2, 2\)"),
    (dict(layer="steel"), "layer: 'steel' is not an ElasticLayer"),
    (dict(layer=ElasticLayer(-1.0, SIGMA, MODULUS)), "layer.stiffness: -1.0 is not valid; must be > 0"),
    (dict(method="long"), "method: 'long' is not one of"),
])
def test_bad_input_is_named(change, message):
    position, free, angle, kw = _case()
    args = {**kw, "compliance": np.zeros((2, 2, 2)), **change}
    with pytest.raises(ValueError, match=message):
        support_moments(position, free, angle, **args)


def test_an_engine_with_an_orbit_not_a_number_is_failed_and_the_others_run():
    position, free, angle, kw = _case(eps=0.6, tilt=0.8e-3)
    position = np.concatenate([position, position])
    free = np.concatenate([free, free])
    position[1, 0, 5] = np.nan  # as the study's chain passes a failed orbit, its inputs trusted
    with trusted():
        out = support_moments(position, free, angle, compliance=np.full((2, 2, 2), 2e-6) * np.eye(2), **kw)
    assert list(out.state[1]) == [2, 2] and np.isnan(out.film[1]).all()
    np.testing.assert_array_equal(out.tilt[1], free[1])
    assert list(out.state[0]) == [0, 0] and np.isfinite(out.film[0]).all()


def test_mirror_bearings_of_a_symmetric_engine_get_the_same_film():
    """The heavy diesel coaxial with its block (the bulkhead web and the bore ring's own turn, about 5 times the web
    alone): bearings 2 and 4, and 1 and 5, mirror each other, and so must their films over the surface. A step that
    stopped short of the balance without saying so gave 0.68 against 1.06 um here (the web x5, as compliant); the
    march's convergence test (the full Newton step on a fresh matrix) holds them together."""
    from stackup.engines import load_engine
    from stackup.study.chain import mechanical_chain

    engine = load_engine("rozhdestvensky-4")
    assert engine.crank.supports.ring is not None
    n = engine.main_bearings
    zero = np.zeros((1, n, 2))
    clearance = np.full((1, n), 103e-6)
    journal_d = np.full(clearance.shape, 0.5 * (engine.journal_d.lo + engine.journal_d.hi))
    out = mechanical_chain(engine, clearance=clearance, journal_d=journal_d, bore_offset=zero,
                           journal_eccentricity=zero, crank_angle=np.arange(720.0), crank_method="bearing-law",
                           film_method="mobility-finite", tilt_method="coupled")
    film = out["h_min"][0]
    assert np.all(np.isfinite(film)) and film.min() > 0.3e-6  # of the paper's order with the compliant block
    np.testing.assert_allclose(film[1], film[3], atol=0.03e-6)
    np.testing.assert_allclose(film[0], film[4], atol=0.03e-6)
    unresolved = out["tilt_unresolved"][0]
    assert np.all((unresolved >= 0) & (unresolved < 0.5))
