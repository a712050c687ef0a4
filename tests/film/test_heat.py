"""Heat balance with pressure-fed oil: closed forms, a finite-difference check of the hole flow, hard cases."""

import math

import numpy as np
import pytest
from scipy import integrate, sparse
from scipy.sparse.linalg import spsolve

from stackup.film import oil
from stackup.film.heat import STATUS, TEMPERATURE_LIMIT, OilFeed, groove_feed_flow, heat_balance, hole_feed_flow

GROOVE = OilFeed("groove", 0.35e6, (0.5 * np.pi, 1.5 * np.pi), 3e-3)
BEARING = dict(journal_d=0.046, bearing_width=0.022, clearance=55e-6, speed=419.0, oil="SAE-5W-30", supply_temperature=90.0)


def test_groove_flow_is_the_cycle_mean_of_the_film_cubed_over_the_arc_by_quadrature():
    # Q = p_s R / (6 mu l') * mean over the positions of the integral of h^3 over the groove's arc
    c, mu, ps, r, length, b = 30e-6, 0.008, 0.3e6, 0.023, 0.022, 4e-3
    rng = np.random.default_rng(3)
    radius, angle = 0.97 * c * np.sqrt(rng.uniform(size=12)), rng.uniform(0, 2 * np.pi, size=12)
    position = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=-1)
    for start, end in ((0.0, 2 * np.pi), (1.0, 2.5), (-0.4, 5.0), (0.5 * np.pi, 1.5 * np.pi)):
        integrals = [integrate.quad(lambda t, x=x: (c - x[0] * np.cos(t) - x[1] * np.sin(t)) ** 3, start, end,
                                    epsrel=1e-12)[0] for x in position]
        reference = ps * r / (6 * mu * (length - b) / 2) * np.mean(integrals)
        q = groove_feed_flow(position, radial_clearance=c, supply_pressure=ps, viscosity=mu, journal_radius=r, bearing_width=length,
                             groove_width=b, groove_arc=(start, end))
        assert float(q) == pytest.approx(reference, rel=1e-10)


def test_full_groove_flow_is_the_classical_circumferential_groove_formula():
    # Shigley (10th ed., sec. 12-9): Q = pi p_s r c^3 (1 + 1.5 eps^2) / (3 mu l'), l' the land width
    c, eps, mu, ps, r, length, b = 30e-6, 0.6, 0.008, 0.3e6, 0.023, 0.022, 4e-3
    position = np.tile([0.0, eps * c], (10, 1))
    q = groove_feed_flow(position, radial_clearance=c, supply_pressure=ps, viscosity=mu, journal_radius=r, bearing_width=length,
                         groove_width=b, groove_arc=(0.0, 2 * np.pi))
    land = (length - b) / 2
    assert float(q) == pytest.approx(math.pi * ps * r * c**3 * (1 + 1.5 * eps**2) / (3 * mu * land), rel=1e-12)


def hele_shaw_hole(length_over_diameter, cells=160):
    """Independent reference: flow out of a hole in a strip of unit film, ambient at both ends, by finite differences.

    Returns Q 12 mu / (h^3 p_s), the dimensionless flow.
    """
    d = 1.0 / length_over_diameter
    n_z = cells + 1  # z in [0, L] with L = 1
    step = 1.0 / cells
    n_x = int(round(5.0 / step)) + 1  # x in [-2.5, 2.5]: the pressure decays as exp(-pi |x|)
    x = (np.arange(n_x) - (n_x - 1) / 2) * step
    z = np.arange(n_z) * step
    xx, zz = np.meshgrid(x, z, indexing="ij")
    hole = np.hypot(xx, zz - 0.5) <= d / 2
    edge = (zz == 0) | (zz >= 1 - 1e-12) | (np.abs(xx) >= x[-1] - 1e-12)
    fixed = hole | edge
    index = -np.ones(xx.shape, int)
    free = ~fixed
    index[free] = np.arange(free.sum())
    rows, cols, vals = [], [], []
    rhs = np.zeros(free.sum())
    for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        shifted = np.roll(np.roll(np.arange(xx.size).reshape(xx.shape), -di, 0), -dj, 1)
        me = index[free]
        nb = shifted[free]
        nb_free = free.ravel()[nb]
        rows += [me, me[nb_free]]
        cols += [me, index.ravel()[nb[nb_free]]]
        vals += [np.full(me.size, -1.0), np.ones(nb_free.sum())]
        rhs -= hole.ravel()[nb] * 1.0
    a = sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))))
    p = np.zeros(xx.shape)
    p[hole] = 1.0
    p[free] = spsolve(a, rhs)
    # net outflow of the hole nodes to their free neighbours (five-point flux, unit film)
    flux = 0.0
    for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        nb = np.roll(np.roll(p, -di, 0), -dj, 1)
        nb_hole = np.roll(np.roll(hole, -di, 0), -dj, 1)
        flux += np.sum((p - nb)[hole & ~nb_hole])
    return flux


def test_hole_flow_matches_a_finite_difference_hele_shaw_solution():
    for ld in (5.0, 8.0):  # hole diameter a fifth and an eighth of the bearing length
        reference = hele_shaw_hole(ld)
        formula = 2 * np.pi / math.log(4 * ld / np.pi)  # Q 12 mu / (h^3 p_s) of the closed form
        assert formula == pytest.approx(reference, rel=0.04), ld
    q = hole_feed_flow(np.zeros((4, 2)), radial_clearance=30e-6, supply_pressure=0.3e6, viscosity=0.01,
                       bearing_width=0.03, hole_diameter=5e-3, hole_angle=1.0)
    assert float(q) == pytest.approx(math.pi * 0.3e6 * (30e-6) ** 3 / (6 * 0.01 * math.log(4 * 6 / math.pi)))


def balance(loads, feed=GROOVE, **kw):
    return heat_balance(loads, **{**BEARING, **kw}, feed=feed)


def test_unloaded_bearing_converges_on_the_feed_flow():
    hb = balance(np.zeros((2, 360, 2)))
    assert np.all(hb.status == STATUS.index("balanced"))
    assert np.all(hb.side_flow == 0) and np.all(hb.feed_flow > 0)
    assert np.all((hb.temperature > 90.0) & (hb.temperature < 150.0))


@pytest.mark.parametrize("method", ["short", "finite"])
def test_balance_holds_at_the_returned_temperature(method):
    angle = np.radians(np.arange(0.0, 720.0, 4.0))
    loads = np.stack([8e3 + 6e3 * np.cos(angle), 3e3 * np.sin(angle)], axis=-1)
    hb = balance(np.stack([loads, 0.3 * loads]), method=method)
    assert np.all(hb.status == 0)
    o = oil.get("SAE-5W-30")
    rise = 0.5 * hb.friction_power / (o.density(hb.temperature) * oil.SPECIFIC_HEAT * hb.flow)
    np.testing.assert_allclose(hb.temperature, 90.0 + rise, atol=0.011)
    shear = 419.0 * 0.023 / 27.5e-6
    np.testing.assert_allclose(hb.viscosity, o.viscosity(hb.temperature, shear_rate=shear), rtol=1e-12)
    assert hb.temperature[0] > hb.temperature[1]  # the heavier bearing runs hotter


def test_more_supply_pressure_cools_the_bearing():
    loads = np.tile([1.5e4, 0.0], (90, 1))
    hot = balance(loads, feed=OilFeed("groove", 0.1e6, GROOVE.groove_arc, 3e-3))
    cool = balance(loads, feed=OilFeed("groove", 0.6e6, GROOVE.groove_arc, 3e-3))
    assert float(cool.temperature) < float(hot.temperature) and float(cool.feed_flow) > float(hot.feed_flow)


def test_no_balance_below_the_limit_is_a_status_not_an_exception():
    # an unloaded journal at 29 000 rpm fed a hair of oil through a pinhole: no balance below the limit
    feed = OilFeed("hole", 1e3, hole_angle=np.pi, hole_diameter=1e-4)
    hb = balance(np.zeros((36, 2)), feed=feed, speed=3000.0)
    assert STATUS[int(hb.status)] == "no_balance_below_limit" and float(hb.temperature) == TEMPERATURE_LIMIT
    extreme = balance(np.tile([1e12, 0.0], (36, 1)))
    assert np.isfinite(float(extreme.temperature)) and int(extreme.status) in (0, 1)


@pytest.mark.parametrize("feed, message", [
    (OilFeed("groove", 0.3e6, (0.0, np.pi), 0.03), "feed.groove_width: 0.03 m is not below the bearing length"),
    (OilFeed("hole", 0.3e6, hole_diameter=0.02), "feed.hole_diameter: 0.02 m is not below half the bearing length"),
    (OilFeed("slot", 0.3e6), "feed.kind: 'slot' is not one of 'groove', 'hole'"),
    (OilFeed("groove", 0.0, (0.0, np.pi), 3e-3), "feed.supply_pressure: 0.0 is not valid; must be > 0"),
])
def test_bad_feed(feed, message):
    with pytest.raises(ValueError, match=message):
        balance(np.ones((4, 2)), feed=feed)
