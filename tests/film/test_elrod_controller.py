"""The ``elrod-coarse`` tier's step controller: a plain-Python twin of :func:`stackup._kernels.elrod.march`.

The twin states the controller as :mod:`stackup.film.elrod` describes it, in numpy and in the order a reader
follows it: each step predicted (BDF2's history term of the content, backward Euler at the first step; the centre
and the field extrapolated from the last two steps), balanced, accepted or redone at half the size, the next step
sized to the change of the centre from its prediction; a journal that crosses the clearance sought where the guide
(then the last cycle's orbit) puts it, then by leaps; cycles until the orbit closes. Each step's balance is the
kernel's field solve (:func:`~stackup._kernels.elrod.balance_step`, :func:`~stackup._kernels.elrod.leap`): what is
tested here is the control around it. The kernel's controller runs with floating-point shortcuts (its ``FAST``
flags) and the twin without, so a step whose error lies at a threshold may be taken by one and redone by the
other: the two agree to the tier's own step error, not bitwise.
"""

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from stackup._kernels import elrod as kernel
from stackup.film import elrod as tier
from stackup.film.heat import OilFeed
from stackup.film.journal import feed_patch
from stackup.film.mobility import mobility_orbit
from stackup.film.orbit import ECCENTRICITY_LIMIT, STATUS

STEPPING = kernel.Stepping(tier.STEP_TOLERANCE, *np.radians([tier.FIRST_STEP, tier.LARGEST_STEP, tier.SMALLEST_STEP,
                                                              tier.LEAP_STEP]))
NEWTON = kernel.Newton(tier.FORCE_TOLERANCE, tier.BALANCE_TOLERANCE, tier.MAX_NEWTON, tier.SMOOTHING)
GEOMETRY = dict(journal_d=0.046, bearing_width=0.022, clearance=46e-6, viscosity=0.0075, speed=419.0)
GROOVE = OilFeed("groove", 3.5e5, groove_arc=(0.5 * np.pi, 1.5 * np.pi), groove_width=0.003)
ANGLE = np.arange(0.0, 720.0, 4.0)
#: The twin's cycle minimum and cycle mean of the mid-plane film against the kernel's: relative to the kernel's,
#: about a tenth of what a step tolerance five times tighter moves them (tests/film/test_elrod.py: under 1 %).
FILM_TOLERANCE = 1e-3


def at(values, tau, t):
    """``values`` (n, 2) given at tau[:n], linear in between and periodic over tau[n], at time t."""
    period = tau[-1]
    closed = np.vstack([values, values[:1]])
    return np.array([np.interp(t % period, tau, closed[:, c]) for c in range(2)])


def solved_film(phi, centre, slope, g, work):
    """Film content g h and the outputs (peak, friction, flow) of the field ``phi`` at ``centre``."""
    kernel.film(centre, slope, g, work.h, work.dh, work.he, work.dhe, work.hn, work.dhn)
    kernel.fields(phi, g, NEWTON.smoothing, work.pressure, work.d_pressure, work.fill, work.d_fill)
    return work.fill * work.h, np.array(kernel.outputs(work.pressure, work.fill, work.h, g))


def predictor(m, h):
    """Step h: BDF2's rate coefficient and history term of the content (backward Euler at the first step), the
    centre extrapolated from the last two steps (held within the limit) and the field extrapolated as it is."""
    if m.steps == 0:
        c_time, history, guess, phi = 12 / h, 12 * m.content / h, m.centre.copy(), m.phi.copy()
    else:
        r = h / m.h_prev
        c_time = 12 * (1 + 2 * r) / (1 + r) / h
        history = 12 * ((1 + r) * m.content - r**2 / (1 + r) * m.content_old) / h
        guess = m.centre + r * (m.centre - m.centre_old)
        phi = np.where(m.grid.fixed, m.phi, m.phi + r * (m.phi - m.phi_old))
    size = np.hypot(*guess)
    if size > ECCENTRICITY_LIMIT:
        guess *= ECCENTRICITY_LIMIT / size
    return c_time, history, guess, phi


def crossing(m, balance, t):
    """A journal crossing the clearance: where the track puts it at t if a balance lies there, else by leaps from
    the last centre (Levenberg-Marquardt's, then Newton's). Returns (outcome, field, centre)."""
    phi, centre = m.phi.copy(), at(m.track, m.tau, t)
    done = -1
    if kernel.balance_step(phi, centre, balance, m.grid, NEWTON, ECCENTRICITY_LIMIT, m.work, False) >= 0:
        done = max(kernel.balance_step(phi, centre, balance, m.grid, NEWTON, ECCENTRICITY_LIMIT, m.work), -1)
    for damped in (True, False):
        if done != -1:
            break
        phi, centre = m.phi.copy(), m.centre.copy()
        done = kernel.leap(phi, centre, balance, m.grid, NEWTON, ECCENTRICITY_LIMIT, m.work, damped)
    return done, phi, centre


def next_step(h, error):
    """The step after one of h whose centre was ``error`` (per film left) from its prediction: the error grows
    as h^2; at most twice, at least half the step."""
    return h * (2.0 if error <= 0 else np.clip(0.9 * np.sqrt(STEPPING.tolerance / error), 0.5, 2.0))


def lap(m):
    """One cycle, step after step; returns (failed, collapsed, widest eccentricity, step ends (times, centres,
    outputs))."""
    period = m.tau[-1]
    widest, collapsed = np.hypot(*m.centre), False
    times, centres, outputs = [0.0], [m.centre.copy()], [m.outputs.copy()]
    t, h = 0.0, m.h
    while t < period:
        h = min(h, STEPPING.largest)
        if t + h > period - 1e-9 * period:
            h = period - t
        elif t + 2 * h > period:
            h = (period - t) / 2  # two even steps rather than a sliver at the cycle's end
        c_time, history, guess, phi = predictor(m, h)
        slope = at(m.slope, m.tau, t + h)
        balance = kernel.Balance(slope, history, c_time, at(m.loads, m.tau, t + h), m.scale)
        centre = guess.copy()
        done = kernel.balance_step(phi, centre, balance, m.grid, NEWTON, ECCENTRICITY_LIMIT, m.work)
        jumped = False
        if done == -1 and h <= STEPPING.leap:
            done, phi, centre = crossing(m, balance, t + h)
            jumped, m.leaps = done != -1, m.leaps + 1
        error = np.hypot(*(centre - guess)) / max(1 - max(widest, np.hypot(*centre)), 1 - ECCENTRICITY_LIMIT)
        if done == -1 or (not jumped and m.steps > 0 and error > 3 * STEPPING.tolerance and h > STEPPING.smallest):
            if h <= STEPPING.smallest:
                return True, collapsed, widest, (times, centres, outputs)
            h = max(h / 2, STEPPING.smallest)
            continue
        collapsed |= done == -2 or np.hypot(*centre) >= ECCENTRICITY_LIMIT * (1 - 1e-12)
        content, out = solved_film(phi, centre, slope, m.grid, m.work)
        m.phi_old, m.phi = (phi if jumped else m.phi), phi
        m.content_old, m.content = m.content, content
        m.centre_old, m.centre, m.outputs = (centre if jumped else m.centre), centre, out
        widest = max(widest, np.hypot(*centre))
        t, m.h_prev, m.steps = t + h, h, m.steps + 1
        h = STEPPING.first if jumped else next_step(h, error)  # after a crossing: start again short
        times.append(t)
        centres.append(centre.copy())
        outputs.append(out)
    m.h = h
    return False, collapsed, widest, (times, centres, outputs)


def twin_march(loads, tau, guide, start, g, periodic=tier.PERIODIC, max_cycles=8):
    """The orbit of one bearing (:func:`stackup._kernels.elrod.march`'s inputs, no tilt): (status, cycles,
    steps, leaps, centres (n, 2) at the times given of the last cycle)."""
    n = len(loads)
    phi = np.where(g.fixed, g.p_fixed, 0.0)
    m = SimpleNamespace(loads=loads, tau=tau, slope=np.zeros((n, 2)), track=guide.copy(), grid=g,
                        work=kernel.workspace(*g.fixed.shape, g.j0, 2), phi=phi, phi_old=phi,
                        centre=start.copy(), centre_old=start.copy(), h=STEPPING.first, h_prev=0.0, steps=0, leaps=0,
                        scale=max(kernel.SMALLEST_SCALE, np.abs(loads).sum(axis=1).max()))
    m.content, m.outputs = solved_film(phi, m.centre, m.slope[0], g, m.work)
    m.content_old = m.content
    for cycle in range(1, max_cycles + 1):
        first = m.centre.copy()
        failed, collapsed, widest, (times, centres, _) = lap(m)
        if failed:
            return "failed", cycle, m.steps, m.leaps, None
        centres = np.array(centres)
        record = np.stack([np.interp(tau[:n], times, centres[:, c]) for c in range(2)], axis=-1)
        m.track = record
        film_left = 1 - (ECCENTRICITY_LIMIT if collapsed else widest)
        if cycle > 1 and np.hypot(*(m.centre - first)) <= periodic * film_left:
            return ("collapsed" if collapsed else "periodic"), cycle, m.steps, m.leaps, record
    return ("collapsed" if collapsed else "not_periodic"), max_cycles, m.steps, m.leaps, record


def case(loads, angle, geometry, feed):
    """The kernel's inputs for one bearing: dimensionless loads, times, the mobility-finite orbit (guide, start)
    and the grid."""
    r, length, c = geometry["journal_d"] / 2, geometry["bearing_width"], geometry["clearance"] / 2
    mu, w = geometry["viscosity"], geometry["speed"]
    guide = mobility_orbit(loads[None], angle, finite=True, cycles=20, start=None, journal_radius=np.array([r]),
                           bearing_width=np.array([length]), radial_clearance=np.array([c]),
                           viscosity=np.array([mu]), speed=np.array([w])).position[0] / c
    g = tier.grid(length_over_radius=length / r, n_theta=tier.N_THETA, n_land=tier.N_LAND, half=True,
                  **feed_patch(feed, journal_radius=r, bearing_width=length, unit_pressure=mu * w * r**2 / c**2))
    tau = np.radians(np.append(angle, angle[0] + 720.0) - angle[0])
    return np.ascontiguousarray(loads / (mu * w * r**4 / c**2)), tau, np.ascontiguousarray(guide), g


def kernel_march(loads, tau, guide, g, periodic=tier.PERIODIC, max_cycles=8):
    n = len(loads)
    record, outs = np.empty((n, 2)), np.empty((n, 3))
    status, cycles, steps, _, leaps = kernel.march(
        kernel.Cycle(loads, tau, np.zeros((n, 2)), guide), guide[0].copy(), g,
        kernel.Control(NEWTON, STEPPING, ECCENTRICITY_LIMIT, periodic, max_cycles),
        kernel.workspace(*g.fixed.shape, g.j0, 2), (record, outs))
    return STATUS[status], cycles, steps, leaps, record


def steady():
    return np.tile([4000.0, 0.0], (ANGLE.size, 1)), ANGLE, GEOMETRY, GROOVE


def reversing():
    """A centre main bearing's load that reverses toward the grooved shell: the journal crosses the clearance."""
    a = np.radians(ANGLE)
    x = -(20000.0 * np.exp(-0.5 * ((ANGLE - 370.0) / 12.0) ** 2) - 1500.0 + 1300.0 * np.cos(a))
    return np.ascontiguousarray(np.stack([-x, -300.0 * np.sin(a)], axis=-1)), ANGLE, GEOMETRY, GROOVE


def inline6_bearing7():
    """Bearing 7 of ``tests/data/inline6.toml`` as the study sampled it: its loads, clearance, oil and groove."""
    data = np.load(Path(__file__).parents[1] / "data" / "inline6_bearing7_loads.npz")
    geometry = {k: float(data[k]) for k in ("journal_d", "bearing_width", "clearance", "speed", "viscosity")}
    feed = OilFeed(str(data["feed_kind"]), float(data["feed_supply_pressure"]),
                   groove_arc=tuple(data["feed_groove_arc"]), groove_width=float(data["feed_groove_width"]))
    return data["loads"], data["crank_angle"], geometry, feed


@pytest.mark.parametrize("history", [steady, reversing, inline6_bearing7])
def test_kernel_controller_matches_its_plain_python_twin(history):
    """Status, cycles and the mid-plane film's cycle minimum and mean as the twin's; steps within 5 %; a crossing
    load makes both leap."""
    loads, tau, guide, g = case(*history())
    status, cycles, steps, leaps, record = kernel_march(loads, tau, guide, g)
    twin_status, twin_cycles, twin_steps, twin_leaps, twin_record = twin_march(loads, tau, guide, guide[0], g)
    assert status == twin_status == "periodic" and cycles == twin_cycles
    assert abs(steps - twin_steps) <= 0.05 * twin_steps
    assert (leaps > 0) == (twin_leaps > 0)
    film, twin_film = 1 - np.hypot(*record.T), 1 - np.hypot(*twin_record.T)
    np.testing.assert_allclose([film.min(), film.mean()], [twin_film.min(), twin_film.mean()], rtol=FILM_TOLERANCE)


def test_the_twin_follows_a_tighter_closure_as_the_kernel_does():
    """Five times tighter periodicity: both take at least as many cycles and agree again."""
    loads, tau, guide, g = case(*reversing())
    _, cycles, _, _, record = kernel_march(loads, tau, guide, g, periodic=tier.PERIODIC / 5)
    _, twin_cycles, _, _, twin_record = twin_march(loads, tau, guide, guide[0], g, periodic=tier.PERIODIC / 5)
    assert cycles == twin_cycles
    film, twin_film = 1 - np.hypot(*record.T), 1 - np.hypot(*twin_record.T)
    np.testing.assert_allclose([film.min(), film.mean()], [twin_film.min(), twin_film.mean()], rtol=FILM_TOLERANCE)


def test_a_start_on_the_periodic_orbit_still_closes_only_after_a_second_cycle():
    """The closure compares a cycle with the one before: a journal started where the orbit closes runs two cycles
    (the first has no cycle before it), in the kernel as in the twin."""
    loads, tau, guide, g = case(*steady())
    *_, record = kernel_march(loads, tau, guide, g)
    n = len(loads)
    on_orbit = np.ascontiguousarray(record[0])
    out = np.empty((n, 2)), np.empty((n, 3))
    status, cycles, *_ = kernel.march(kernel.Cycle(loads, tau, np.zeros((n, 2)), guide), on_orbit.copy(), g,
                                      kernel.Control(NEWTON, STEPPING, ECCENTRICITY_LIMIT, tier.PERIODIC, 8),
                                      kernel.workspace(*g.fixed.shape, g.j0, 2), out)
    twin_status, twin_cycles, *_ = twin_march(loads, tau, guide, on_orbit, g)
    assert STATUS[status] == twin_status == "periodic" and cycles == twin_cycles == 2
