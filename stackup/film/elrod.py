r"""Mass-conserving cycle tier on a coarse grid: ``"elrod-coarse"``.

Between the mobility tiers (no film content: they cannot see the film short of
oil downstream of a moving load) and the fine transient reference
(:mod:`stackup.film.transient`, minutes per bearing-cycle), this tier solves the
same transient Reynolds equation with the Jakobsson-Floberg-Olsson (JFO)
mass-conserving cavitation in Elrod's form, on a coarse grid, with a direct
Newton solve per time step. Its speed and error against the reference are
measured in ``reports/film_speed_vs_error.md`` (``studies/film_speed_vs_error.py``).

Film of a bearing of radius :math:`R`, length :math:`L`, radial clearance :math:`c`,
journal turning at :math:`\omega`, bearing fixed, journal centre :math:`\mathbf x(t)`
and tilt :math:`\boldsymbol\gamma(t)`, dimensionless
(:math:`\bar h = h/c`, :math:`\xi = \mathbf x/c`, :math:`\bar z = z/R`, :math:`\tau = \omega t`,
:math:`\bar p = p c^2/(\mu\omega R^2)`):

.. math:: \bar h(\Theta, \bar z, \tau) = 1 - (\xi + \bar z\,\mathbf s)\cdot\mathbf n(\Theta),
          \qquad \mathbf s = \boldsymbol\gamma R/c

Elrod's universal equation [1]_ for the film content :math:`g\bar h` (:math:`g` the fill,
the share of the gap that holds oil), with the JFO conditions:

.. math:: \bar\nabla\cdot(\bar h^3\bar\nabla\bar p) = 6\,\partial_\Theta(g\bar h) + 12\,\partial_\tau(g\bar h),
          \qquad \bar p \ge 0,\; 0 \le g \le 1,\; \bar p\,(1 - g) = 0

written with one unknown per node, the universal variable :math:`\phi`
(:math:`\bar p = \max(\phi, 0)`, :math:`g = \min(1 + \phi, 1)`), as Vijayaraghavan and
Keith [2]_ do: a full node carries pressure, a cavitated one only its content,
and the switch between them is part of the unknown.

Discretisation: finite volumes on a grid of ``n_theta`` angles (uniform, periodic)
by an axial grid that puts nodes on the feed groove's edges and spaces ``n_land``
nodes evenly over each land between the groove and the bearing's end; Poiseuille
flux through a face with :math:`\bar h^3` at the face, Couette flux
:math:`6 g_W \bar h_w`, the fill upwind (the reference kernel's stencil,
:func:`stackup._kernels.reynolds.elrod_adams`); ambient pressure and a full film
at both ends, the engine's groove (or hole) held full at its supply pressure.
Without tilt the film is symmetric about the mid-plane and only half the width
is solved. Time: BDF2 on the content (variable step, backward Euler at the first
step), the step sized to the change of the journal centre from its prediction
(:data:`STEP_TOLERANCE`); loads and tilt linear between the crank angles given,
the outputs linear between steps onto every angle.

Each step is one nonlinear system: the nodes' :math:`\phi` and the journal centre
:math:`\xi` (massless journal, Booker [3]_: the film force equals the load). The node
balances are piecewise linear in :math:`\phi`; semismooth Newton on them bordered by
the force balance :math:`\bar{\mathbf F}(\phi) = \bar{\mathbf W}`, from a field and a centre
extrapolated from the last two steps, converges in a few iterations. The
field's Jacobian is block cyclic tridiagonal (a block per angle: the nodes over the
width) and is factored directly; the force balance enters through its Schur
complement (2 x 2). The orbit is repeated from the ``mobility-finite`` tier's
position until it closes within :data:`PERIODIC` of the thinnest film, as the
reference does.

Where the load turns onto a film short of oil, the massless journal crosses the
clearance within a step and no balance lies near the prediction. The journal is
then sought where the ``mobility-finite`` orbit (first cycle) or the last cycle's
orbit is at that time (a balance there, not the wall), and failing that by a
leap: Levenberg-Marquardt on the centre alone, each trial centre's field solved
with the centre held, then Newton's step on it if that fails. Along a film
that barely carries, that search stalls with the force balanced to about 1e-3 of
the cycle's largest load; a leap within
:data:`stackup._kernels.elrod.LEAP_FORCE` of it that stalls is taken as it is (a
film that barely carries meets a load that is a small part of the cycle's).

Outputs per angle as the reference: mid-plane minimum film :math:`c(1 - |\xi|)`,
the peak of the pressure field, friction torque
:math:`T = \frac{\mu\omega R^4}{c}\iint (g/\bar h + \tfrac12\bar h\,\partial_\Theta\bar p)\,d\Theta\,d\bar z`,
side flow :math:`Q = \frac{\omega R^2 c}{12}\sum_{ends}\int\bar h^3|\partial_{\bar z}\bar p|\,d\Theta`.

Hard cases: zero load (the journal settles where the feed pressure and the
rotation balance, near the centre); an eccentricity near 1 (the centre is held
at :data:`~stackup.film.journal.ECCENTRICITY_LIMIT`, status ``collapsed``); a load
that swings fast (the step is solved implicitly: no step-size limit, the film
content carries the starved film over). A Newton step that fails gives the
status ``failed`` and NaN from that angle on, never a silent NaN.

References
----------
.. [1] Elrod, H. G., "A cavitation algorithm", J. Lubr. Technol. 103 (1981) 350-354.
.. [2] Vijayaraghavan, D., Keith, T. G., "Development and evaluation of a cavitation
   algorithm", STLE Tribol. Trans. 32 (1989) 225-233.
.. [3] Booker, J. F., "Dynamically loaded journal bearings: mobility method of
   solution", J. Basic Eng. 87 (1965) 537-546.
.. [4] Ausas, R. F., Jai, M., Buscaglia, G. C., "A mass-conserving algorithm for
   dynamical lubrication problems with cavitation", J. Tribol. 131 (2009) 031702
   (the reference tier's scheme, whose stencil this tier shares).
"""

from __future__ import annotations

import numpy as np

from .._kernels import elrod as _kernel
from .._validate import Finite, Integer, Positive, integer, renamed, validated
from .journal import ECCENTRICITY_LIMIT, Orbit, edge_film, feed_patch, table_covers
from .mobility import mobility_orbit

#: Grid: angles around the bearing, nodes on each land between the feed groove and the bearing's end.
N_THETA = 48
N_LAND = 2
#: Time steps: the change of the journal centre from its prediction allowed per step, as a share of the film left
#: (the local error the steps are sized to), the largest step and the first and smallest [deg of crank angle].
STEP_TOLERANCE = 0.05
LARGEST_STEP = 12.0
FIRST_STEP = 1.0
SMALLEST_STEP = 1.0 / 64
#: A step this short [deg] that finds no balance near its prediction leaps (the journal crosses the clearance).
LEAP_STEP = 1.0
#: Newton's stopping rule: force within this share of the cycle's largest load, node balances within this share
#: of the content rate of a full film, at most this many iterations per step.
FORCE_TOLERANCE = 1e-6
BALANCE_TOLERANCE = 1e-6
MAX_NEWTON = 25
#: Width of the band of the universal variable over which the switch between pressure and fill is smoothed
#: (pressure per mu omega R^2 / c^2, fill): p (1 - g) = SMOOTHING^2 / 4.
SMOOTHING = 1e-2
#: Periodic when the journal returns after a cycle to within this share of the thinnest film. The orbit contracts
#: fast from its second cycle on: a tighter closure moves the cycle's minimum and mean film far less than the
#: tier's error against the converged solution (``reports/film_speed_vs_error.md``), at a cycle's cost each.
PERIODIC = 1e-2


def axial_nodes(half_length, feed_half_width, n_land):
    """Axial nodes of half the width [R]: the mid-plane, the feed's edge, ``n_land`` nodes on the land, the end."""
    land = np.linspace(feed_half_width, half_length, n_land + 2)
    if feed_half_width <= 0.0:
        return land
    return np.concatenate([[0.0], land])


def newton_cotes(n_points):
    """Weights of the closed Newton-Cotes rule on ``n_points`` even nodes over [0, 1] (exact for polynomials of
    degree n_points - 1; positive up to 8 points)."""
    x = np.linspace(0.0, 1.0, n_points)
    powers = np.vander(x, increasing=True).T  # row k: x^k at the nodes
    return np.linalg.solve(powers, 1.0 / np.arange(1, n_points + 1))


def axial_weights(z_half, feed_half_width):
    """Weights integrating over the half width [R]: trapezoid over the feed's half, Newton-Cotes over the land.

    The land's pressure is near a parabola (the short bearing's), which the trapezoid rule would underestimate
    by a share of about (1/intervals)^2; Newton-Cotes on the land's even nodes integrates it exactly.
    """
    weights = np.zeros(z_half.size)
    first = 1 if feed_half_width > 0.0 else 0
    if first:
        weights[:2] += 0.5 * (z_half[1] - z_half[0])
    land = z_half[first:]
    weights[first:] += (land[-1] - land[0]) * newton_cotes(land.size)
    return weights


def grid(*, length_over_radius, n_theta, n_land, feed_arc, feed_half_width, feed_pressure, half,
         limit=ECCENTRICITY_LIMIT):
    """The kernel's :class:`stackup._kernels.elrod.Grid` for a bearing (lengths in R, pressure dimensionless).

    ``feed_arc`` (start, end) [rad] and ``feed_half_width`` [R]: the nodes held full at ``feed_pressure``;
    ``half``: only the half width z >= 0 (the film symmetric about the mid-plane).
    """
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    dtheta = 2 * np.pi / n_theta
    z_half = axial_nodes(length_over_radius / 2, feed_half_width, n_land)
    z = z_half if half else np.concatenate([-z_half[:0:-1], z_half])
    n_z = z.size
    width = np.empty(n_z)
    width[1:-1] = 0.5 * (z[2:] - z[:-2])
    width[0] = 0.5 * (z[1] - z[0])
    width[-1] = 0.5 * (z[-1] - z[-2])
    w_half = axial_weights(z_half, feed_half_width)
    # the force of the whole width: the half grid's weights doubled, or mirrored (the mid-plane node shared)
    weight = 2.0 * w_half if half else np.concatenate([w_half[:0:-1], [2.0 * w_half[0]], w_half[1:]])
    fixed = np.zeros((n_theta, n_z), bool)
    fixed[:, -1] = True
    if not half:
        fixed[:, 0] = True
    start, end = feed_arc
    near = np.mod(theta - start + 1e-12, 2 * np.pi) <= (end - start) + 2e-12
    along = np.abs(z) <= feed_half_width + 1e-12
    hole = near[:, None] & along[None, :]
    fixed |= hole
    p_fixed = np.where(hole, feed_pressure, 0.0)
    east = theta + 0.5 * dtheta
    return _kernel.Grid(dtheta, np.ascontiguousarray(np.stack([np.cos(theta), np.sin(theta)])),
                        np.ascontiguousarray(np.stack([np.cos(east), np.sin(east)])), z,
                        0.5 * (z[1:] + z[:-1]), width, weight, 0 if half else 1, fixed, p_fixed, 1.0 - limit)


def _land_nodes(field, value):
    """Nodes on a land: 1 to 6 (Newton-Cotes weights stay positive up to 8 points, the land's ends included)."""
    value = integer(field, value, minimum=1)
    if value > 6:
        raise ValueError(f"{field}: {value!r} is not valid; 1 to 6 nodes on each land")
    return value


@renamed(radius="journal_radius", length="bearing_width")
@validated(n_theta=Integer(minimum=12), n_land=_land_nodes, step_tolerance=Positive(), largest_step=Positive(),
           cycles=Integer(minimum=1), start=Finite(), journal_radius=Positive(), bearing_width=Positive(),
           radial_clearance=Positive(), viscosity=Positive(), speed=Positive())
def elrod_orbit(loads, crank_angle, *, journal_radius, bearing_width, radial_clearance, viscosity, speed, tilt=None,
                cycles=8, start=None, feed=None, n_theta=N_THETA, n_land=N_LAND, step_tolerance=STEP_TOLERANCE,
                largest_step=LARGEST_STEP):
    """Orbit of each bearing by the ``elrod-coarse`` tier (called by :func:`stackup.film.orbit.orbit`).

    Parameters as :func:`stackup.film.orbit.orbit` (arrays over the leading shape, SI), and
    feed : stackup.film.heat.OilFeed, optional
        The engine's oil feed: its groove (arc and axial width) or hole held
        full at its supply pressure; default a patch at ambient pressure on the
        block side (as the reference's default).
    n_theta : int
        Angles around the bearing.
    n_land : int
        Axial nodes on each land between the feed and the bearing's end.
    step_tolerance : float
        Change of the journal centre from its prediction allowed per time step,
        as a share of the film left [-] (the steps are sized to it).
    largest_step : float
        Largest time step [deg of crank angle].

    Returns
    -------
    stackup.film.journal.Orbit
    """
    radius, length, c = journal_radius, bearing_width, radial_clearance
    lead = loads.shape[:-2]
    n = crank_angle.size
    tau = np.radians(np.append(crank_angle, crank_angle[0] + 720.0) - crank_angle[0])
    stepping = _kernel.Stepping(float(step_tolerance), np.radians(FIRST_STEP), np.radians(float(largest_step)),
                                np.radians(SMALLEST_STEP), np.radians(LEAP_STEP))
    # the mobility-finite orbit: where the march starts (unless told) and where a journal that crosses the
    # clearance is first sought (a film that carries the load there, before the slower leap)
    guide = mobility_orbit(loads, crank_angle, finite=table_covers(length / (2 * radius)), cycles=20, start=None,
                           journal_radius=radius, bearing_width=length, radial_clearance=c, viscosity=viscosity,
                           speed=speed).position
    start = guide[..., 0, :] if start is None else np.broadcast_to(start, (*lead, 2))
    position = np.empty((*lead, n, 2))
    out = {k: np.empty((*lead, n)) for k in ("peak", "torque", "flow")}
    status = np.empty(lead, np.int8)
    used = np.empty(lead)
    control = _kernel.Control(_kernel.Newton(FORCE_TOLERANCE, BALANCE_TOLERANCE, MAX_NEWTON, SMOOTHING), stepping,
                              ECCENTRICITY_LIMIT, PERIODIC, int(cycles))
    for idx in np.ndindex(lead):
        r, l, c_b, mu, w = (float(a[idx]) for a in (radius, length, c, viscosity, speed))
        unit_force = mu * w * r**4 / c_b**2
        unit_pressure = mu * w * r**2 / c_b**2
        half = tilt is None
        g = grid(length_over_radius=l / r, n_theta=int(n_theta), n_land=int(n_land), half=half,
                 **feed_patch(feed, journal_radius=r, bearing_width=l, unit_pressure=unit_pressure))
        slope = np.zeros((n, 2)) if tilt is None else np.ascontiguousarray(tilt[idx] * r / c_b)
        work = _kernel.workspace(g.fixed.shape[0], g.fixed.shape[1], g.j0, 2)
        record, outs = np.empty((n, 2)), np.empty((n, 3))
        cycle = _kernel.Cycle(np.ascontiguousarray(loads[idx] / unit_force), tau, slope,
                              np.ascontiguousarray(guide[idx] / c_b))
        status[idx], used[idx], _, _, _ = _kernel.march(cycle, np.array(start[idx] / c_b, dtype=float), g, control,
                                                        work, (record, outs))
        position[idx] = record * c_b
        out["peak"][idx] = outs[:, 0] * unit_pressure
        out["torque"][idx] = outs[:, 1] * mu * w * r**4 / c_b
        out["flow"][idx] = outs[:, 2] * w * r**2 * c_b / 12
    ecc = np.linalg.norm(position, axis=-1) / c[..., None]
    h_min = c[..., None] * (1 - ecc)
    h_edge, status = edge_film(position, tilt, length, c, h_min, status)
    return Orbit(h_min, h_edge, ecc, position, out["peak"], out["torque"], out["flow"], status, used,
                 np.asarray(speed, dtype=float), tilt, tilt, None)

