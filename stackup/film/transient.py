r"""Reference cycle tier: the transient Reynolds equation with mass-conserving cavitation, journal orbit integrated.

The film of a bearing of radius :math:`R`, length :math:`L`, radial clearance
:math:`c`, journal turning at :math:`\omega`, bearing fixed, journal centre
:math:`\mathbf x(t)` and tilt :math:`\boldsymbol\gamma(t)` (slope of the journal axis
relative to the bearing axis):

.. math:: h(\Theta, z, t) = c - (\mathbf x + z\boldsymbol\gamma)\cdot\mathbf n(\Theta), \qquad
          z \in [-L/2, L/2]

Elrod-Adams form of the Jakobsson-Floberg-Olsson (JFO) mass-conserving
cavitation, dimensionless (:math:`\bar h = h/c`, :math:`\bar z = z/R`, :math:`\tau = \omega t`,
:math:`\bar p = p c^2/(\mu\omega R^2)`, fill fraction :math:`g`):

.. math:: \bar\nabla\cdot(\bar h^3\bar\nabla\bar p) = 6\,\partial_\Theta(g\bar h) + 12\,\partial_\tau(g\bar h),
          \qquad \bar p \ge 0,\; g \le 1,\; \bar p\,(1 - g) = 0

Finite volumes on a uniform grid (Couette flux with the fill upwind and the film at the face), BDF2 in time (backward
Euler for the first step), :math:`\bar p = 0, g = 1` at both ends and a feed hole held
at the supply pressure (full of oil), solved per step by Gauss-Seidel with the
Ausas et al. switching between pressure and fill. The journal is massless:
at each step its centre :math:`\mathbf x_{n+1}` is found by a Broyden iteration so that
the film force equals the load (each residual one field solve, warm-started);
the tilt is imposed or, with ``tilt_compliance``, two more unknowns: the
journal's tilt balances the film's moment
:math:`\mathbf M = \iint p\,z\,\mathbf n\,dA` against the crankshaft,
:math:`\boldsymbol\gamma = \boldsymbol\gamma_{free} - C\mathbf M` (:mod:`stackup.film.tilt`), the
tilt's own squeeze in the film's content (``tilt_squeeze=False`` takes the
earlier steps' content at the current tilt: the cheap tiers' simplification,
measured); an edge that would pass the wall is held on it (force balance, the
edge on the limit, the moment's imbalance along the wall's normal only). Each
step starts from the ``mobility-finite`` tier's prediction. Cycles are
repeated from the ``mobility-finite`` orbit's position until the orbit closes.
With ``cavitation="reynolds"`` the fill stays 1 and :math:`\bar p \ge 0` is a
projection (Swift-Stieber, not mass-conserving): the finite-length counterpart
of the mobility tiers' film.

Outputs per angle: mid-plane and edge minimum films, the peak of the pressure
field, friction torque on the journal
:math:`T = \frac{\mu\omega R^4}{c}\iint (g/\bar h + \tfrac12\bar h\,\partial_\Theta\bar p)\,d\Theta\,d\bar z`
(shear of the oil present, plus the pressure term) and the side flow
:math:`Q = \frac{\omega R^2 c}{12}\sum_{ends}\int\bar h^3|\partial_{\bar z}\bar p|\,d\Theta`.

References
----------
.. [1] Elrod, H. G., "A cavitation algorithm", J. Lubr. Technol. 103 (1981) 350-354.
.. [2] Ausas, R. F., Jai, M., Buscaglia, G. C., "A mass-conserving algorithm for
   dynamical lubrication problems with cavitation", J. Tribol. 131 (2009) 031702.
.. [3] Booker, J. F., J. Basic Eng. 87 (1965) 537-546 (the massless journal's force balance).
.. [4] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), eq. 4 (film with skewed axes).
"""

from __future__ import annotations

import numpy as np
from scipy import optimize

from .._kernels import mobility as _mobility
from .._kernels.reynolds import Grid, Sweeps, elrod_adams
from .._kernels.tilt import wall_room
from .._validate import Finite, Integer, OneOf, Positive, renamed, validated
from .journal import (ECCENTRICITY_LIMIT, FEED_ANGLE, STATES, Orbit, edge_film, feed_patch, mobility_table,
                      table_covers)
from .mobility import mobility_orbit

CAVITATION = ("elrod-adams", "reynolds")
#: Grid: angles around the bearing and axial nodes over the width (ends included).
N_THETA = 180
N_Z = 21
RELAXATION = 1.7
#: Field solve: stop when a sweep changes p by less than this share of its peak (and the fill by less).
FIELD_TOLERANCE = 1e-9
MAX_SWEEPS = 20_000
#: Force balance: stop when the film force is within this share of the cycle's largest load.
FORCE_TOLERANCE = 1e-6
MAX_BROYDEN = 40
#: Periodic when the journal returns after a cycle to within this share of the thinnest film.
PERIODIC = 2e-3


class _Film:
    """Grid and dimensionless film of one bearing."""

    def __init__(self, *, length_over_radius, clearance_over_radius, n_theta, n_z, feed_arc, feed_half_width,
                 feed_pressure, limit):
        self.limit = limit
        self.theta = 2 * np.pi * np.arange(n_theta) / n_theta
        self.dtheta = 2 * np.pi / n_theta
        self.z = np.linspace(-length_over_radius / 2, length_over_radius / 2, n_z)
        self.dz = self.z[1] - self.z[0]
        self.n = np.stack([np.cos(self.theta), np.sin(self.theta)])  # (2, n_t)
        east = self.theta + 0.5 * self.dtheta
        self.n_east = np.stack([np.cos(east), np.sin(east)])
        self.z_north = self.z + 0.5 * self.dz
        self.tilt_scale = 1.0 / clearance_over_radius  # z is in R, h in c: z gamma / c = z_bar gamma R / c
        self.fixed = np.zeros((n_theta, n_z), bool)
        self.fixed[:, [0, -1]] = True
        self.p_fixed = np.zeros((n_theta, n_z))
        start, end = feed_arc
        near = np.mod(self.theta - start + 1e-12, 2 * np.pi) <= (end - start) + 2e-12
        along = np.abs(self.z) <= feed_half_width + 1e-12
        hole = near[:, None] & along[None, :]
        self.fixed |= hole
        self.p_fixed[hole] = feed_pressure
        self.weights = np.full(n_z, self.dz)
        self.weights[[0, -1]] = self.dz / 2

    def thickness(self, xi, gamma):
        """h at the nodes, h and h^3 at the east faces, h^3 at the north faces (centre xi [c], tilt gamma [rad]).

        Where a tilted journal's edge would pass the thinnest film the tiers
        allow, :math:`f = 1 - \\varepsilon_{lim}`, the film is
        :math:`f/(2 - h/f)` instead (continuous with its slope at :math:`h = f`):
        the overlap closes the film smoothly, so the balance stays smooth where the
        film cannot hold the journal (the orbit reports that as ``edge_contact``).
        """
        t = self.tilt_scale * gamma
        h = self._held(1.0 - (xi @ self.n)[:, None] - (t @ self.n)[:, None] * self.z[None, :])
        h_e = self._held(1.0 - (xi @ self.n_east)[:, None] - (t @ self.n_east)[:, None] * self.z[None, :])
        h_n = self._held(1.0 - (xi @ self.n)[:, None] - (t @ self.n)[:, None] * self.z_north[None, :])
        return h, h_e, h_e**3, h_n**3

    def _held(self, h):
        floor = 1.0 - self.limit
        return np.where(h >= floor, h, floor / (2.0 - np.minimum(h / floor, 1.0)))

    def force(self, p):
        """Film force on the bearing (2,) per unit of mu omega R^4 / c^2."""
        return self.n @ (p @ self.weights) * self.dtheta

    def moment(self, p):
        """Film moment on the bearing about the mid-plane, integral of p z n (2,), per unit of mu omega R^5 / c^2."""
        return self.n @ (p @ (self.weights * self.z)) * self.dtheta


@renamed(radius="journal_radius", length="bearing_width")
@validated(cavitation=OneOf(CAVITATION), n_theta=Integer(minimum=24), n_z=Integer(minimum=5),
           time_order=OneOf((1, 2)), feed_pressure=Positive(zero=True), feed_angle=Finite())
def transient_orbit(loads, crank_angle, *, journal_radius, bearing_width, radial_clearance, viscosity, speed, tilt=None,
                    tilt_compliance=None, tilt_squeeze=True, cycles=8, cavitation="elrod-adams", n_theta=N_THETA,
                    n_z=N_Z, time_order=2, feed_pressure=0.0, feed_angle=FEED_ANGLE, feed=None, start=None):
    """Orbit of each bearing by the transient Reynolds tier (called by :func:`stackup.film.orbit.orbit`).

    Parameters as :func:`stackup.film.orbit.orbit` (arrays over the leading shape, SI), and
    tilt_squeeze : bool
        With ``tilt_compliance``: the film's content changes with the tilt
        (True, the physics) or the earlier steps' content is taken at the
        current tilt (False: the tilt's squeeze neglected, as the cheap tiers do).
    cavitation : {"elrod-adams", "reynolds"}
    n_theta, n_z : int
        Grid around the bearing and over its width.
    time_order : {1, 2}
        Backward Euler or BDF2.
    feed_pressure : float
        Supply pressure at the feed hole [Pa] (gauge; 0 keeps it full at ambient pressure).
    feed_angle : float
        Angle of the feed hole from load axis 0 [rad].
    feed : stackup.film.heat.OilFeed, optional
        The engine's oil feed: its supply pressure and groove (arc and axial width)
        or hole replace ``feed_pressure`` and ``feed_angle`` (a hole is a
        :data:`~stackup.film.journal.FEED_WIDTH` wide patch at ``feed.hole_angle``, the hole's diameter
        long).
    start : array_like (..., 2), optional
        Journal centre at the first angle [m]; default from the ``mobility-finite`` tier
        (``mobility`` where the table does not cover the L/D).

    Returns
    -------
    stackup.film.orbit.Orbit
    """
    radius, length, c = journal_radius, bearing_width, radial_clearance
    n_theta, n_z = int(n_theta), int(n_z)  # checked integers (as given where orbit() checked them)
    lead = loads.shape[:-2]
    n = crank_angle.size
    tau = np.radians(np.append(crank_angle, crank_angle[0] + 720.0) - crank_angle[0])
    if tilt is None:
        tilt = np.zeros(loads.shape)
    if start is None:
        start = mobility_orbit(loads, crank_angle, finite=table_covers(length / (2 * radius)), cycles=20, start=None,
                               journal_radius=radius, bearing_width=length, radial_clearance=c, viscosity=viscosity,
                               speed=speed).position[..., 0, :]
    start = np.broadcast_to(start, (*lead, 2))
    out = {k: np.empty((*lead, n)) for k in ("peak", "torque", "flow")}
    film_tilt = np.array(tilt, dtype=float)
    position = np.empty((*lead, n, 2))
    status = np.empty(lead, np.int8)
    used = np.empty(lead)
    options = dict(mass_conserving=cavitation == "elrod-adams", time_order=time_order, tilt_squeeze=tilt_squeeze)
    for idx in np.ndindex(lead):
        r, l, c_b, mu, w = (float(a[idx]) for a in (radius, length, c, viscosity, speed))
        unit_force = mu * w * r**4 / c_b**2
        unit_pressure = mu * w * r**2 / c_b**2
        film = _Film(length_over_radius=l / r, clearance_over_radius=c_b / r, n_theta=n_theta, n_z=n_z,
                     **feed_patch(feed, journal_radius=r, bearing_width=l, unit_pressure=unit_pressure,
                                  angle=feed_angle, pressure=feed_pressure), limit=ECCENTRICITY_LIMIT)
        # the tilt equilibrium in edge offsets e = gamma L/(2c): e + kappa M = e_free, M per mu omega R^5/c^2
        kappa = None if tilt_compliance is None else (np.asarray(tilt_compliance[idx], float) * mu * w * r**5 * l
                                                      / (2 * c_b**3))
        result = _bearing_orbit(film, loads[idx] / unit_force, tau, tilt[idx], start[idx] / c_b, cycles,
                                mobility=_mobility_table_at(l / (2 * r)), kappa=kappa, edge_per_tilt=l / (2 * c_b),
                                **options)
        xi, peak, friction, flow, status[idx], used[idx], film_tilt[idx] = result
        position[idx] = xi * c_b
        out["peak"][idx] = peak * unit_pressure
        out["torque"][idx] = friction * mu * w * r**4 / c_b
        out["flow"][idx] = flow * w * r**2 * c_b / 12
    return _orbit_of(position, out, status, used, tilt, film_tilt, coupled=tilt_compliance is not None,
                     bearing_width=length, radial_clearance=c, speed=speed)


def _mobility_table_at(length_over_diameter):
    """(table at the bearing's L/D, its eccentricity nodes, whether it covers the L/D) of the mobility prediction."""
    ld_nodes, stretched, tables = mobility_table()
    table = _mobility.bearing_table(_mobility.Correction(tables, ld_nodes, stretched, True), length_over_diameter)
    return table, stretched, table_covers(length_over_diameter)


def _orbit_of(position, out, status, used, tilt, film_tilt, *, coupled, bearing_width, radial_clearance, speed):
    """The :class:`Orbit` of the bearings' orbits: films, and where a tilted journal's edge sits at the limit."""
    ecc = np.linalg.norm(position, axis=-1) / radial_clearance[..., None]
    h_min = radial_clearance[..., None] * (1 - ecc)
    tilt_state = None
    if coupled:
        # an edge past the limit sits on the film the tiers hold there: no film holds the journal
        half = 0.5 * bearing_width[..., None, None] * film_tilt
        reach = np.maximum(np.linalg.norm(position + half, axis=-1), np.linalg.norm(position - half, axis=-1))
        at_wall = reach >= radial_clearance[..., None] * ECCENTRICITY_LIMIT * (1 - 1e-6)
        tilt_state = np.where(at_wall, STATES.index("at_limit"), STATES.index("equilibrium")).astype(np.int8)
    h_edge, status = edge_film(position, film_tilt, bearing_width, radial_clearance, h_min, status,
                               at_limit=tilt_state)
    return Orbit(h_min, h_edge, ecc, position, out["peak"], out["torque"], out["flow"], status, used,
                 np.asarray(speed, dtype=float), film_tilt, tilt, tilt_state)


def _bearing_orbit(film, w, tau, tilt, xi0, cycles, *, mobility, kappa=None, edge_per_tilt=1.0, mass_conserving=True,
                   time_order=2, tilt_squeeze=True):
    """Periodic orbit of one bearing; dimensionless loads w (n, 2). Returns per-angle arrays, status, cycles, tilt.

    Each step (:class:`_March`): predict the centre with the mobility tier's rate
    (``mobility``: its table, eccentricity nodes and whether it is finite), then
    solve the force balance by damped Newton with Broyden updates. With
    ``kappa`` (2,) the tilt is solved too (:func:`_tilted_balance`): unknowns
    (centre, edge offset e = gamma * ``edge_per_tilt``), residual (force - load,
    scale (e + kappa M - e_free)); where that would take an edge past the
    limit, the edge is held on it (the film cannot hold the journal).
    """
    n = w.shape[0]
    limit = film.limit
    march = _March(film, w, tau, tilt, kappa=kappa, edge_per_tilt=edge_per_tilt, mass_conserving=mass_conserving,
                   time_order=time_order, tilt_squeeze=tilt_squeeze, mobility=mobility)
    xi, e = march.start(xi0)
    record = np.empty((n, 2))
    record_tilt = np.array(tilt, dtype=float)
    peak = np.empty(n)
    friction = np.empty(n)
    flow = np.empty(n)
    for cycle in range(1, cycles + 1):
        start = xi.copy()
        thinnest = 0.0
        collapsed = False
        for k in range(n):
            record[k] = xi
            if march.coupled:
                record_tilt[k] = e / edge_per_tilt
            peak[k], friction[k], flow[k] = _outputs(film, march.p, march.fill, march.h)
            thinnest = max(thinnest, float(np.hypot(*xi)))
            before = march.snapshot()
            x = None
            for parts in SUBSTEPS:
                try:
                    x = march.step(k, xi, e, parts)
                    break
                except (RuntimeError, np.linalg.LinAlgError):
                    march.restore(before)  # a step that fails is tried again from its start in sub-steps
            if x is None:
                return _failed(record, peak, friction, flow, k, cycle) + (record_tilt,)
            if march.coupled:
                e = x[2:].copy()
            if np.hypot(*x[:2]) >= limit * (1 - 1e-12):
                collapsed = True
            xi = x[:2].copy()
            march.taken(xi)
        film_left = 1 - (limit if collapsed else thinnest)
        closure = float(np.hypot(*(xi - start)))
        if cycle > 1 and closure <= PERIODIC * film_left:
            return record, peak, friction, flow, (2 if collapsed else 0), cycle, record_tilt
    return record, peak, friction, flow, (2 if collapsed else 1), cycles, record_tilt


class _March:
    """One bearing's journal marched from angle to angle: its field and fill, and the balance's memory.

    ``w`` (n, 2) dimensionless loads at the times ``tau`` (n + 1,); ``tilt`` (n, 2) the
    tilt imposed, or with ``kappa`` the free tilt of the equilibrium (:func:`_bearing_orbit`).
    """

    def __init__(self, film, w, tau, tilt, *, kappa, edge_per_tilt, mass_conserving, time_order, tilt_squeeze,
                 mobility):
        self.film, self.w, self.tau, self.tilt = film, w, tau, tilt
        self.kappa, self.edge_per_tilt, self.coupled = kappa, edge_per_tilt, kappa is not None
        self.mass_conserving, self.time_order, self.tilt_squeeze = mass_conserving, time_order, tilt_squeeze
        self.mobility = mobility
        shape = (film.theta.size, film.z.size)
        self.p = np.zeros(shape)
        self.fill = np.ones(shape)
        self.p[film.fixed] = film.p_fixed[film.fixed]
        self.scale = np.abs(w).max() + 1e-300
        self.free = tilt * edge_per_tilt  # (n, 2) edge offsets the beam alone would give
        self.dtau_prev = None
        self.jac = None
        self.held = False  # the tilt held with an edge at the limit (the film cannot hold the journal)
        self.alpha = -0.5 * np.pi

    def start(self, xi0):
        """The first angle's centre and edge offset (None without the equilibrium); sets its film."""
        xi = np.array(xi0, dtype=float)
        e = self.free[0].copy() if self.coupled else None
        if self.coupled:
            e = _edges_inside(xi, e, self.film.limit)
        gamma_now = e / self.edge_per_tilt if self.coupled else self.tilt[0]
        self.h = self.film.thickness(xi, gamma_now)[0]
        self.steps = [(self.fill.copy(), xi.copy(), self.h)]  # fill, centre and film of the latest steps (content)
        return xi, e

    def step(self, k, xi, e, parts=1):
        """The balanced unknowns at angle k + 1 from the centre ``xi`` and edge offset ``e`` at angle k, in
        ``parts`` sub-steps (load, free and imposed tilt linear between the two angles; each sub-step but the last
        taken into the content's history)."""
        kn = (k + 1) % self.w.shape[0]
        dtau = (self.tau[k + 1] - self.tau[k]) / parts

        def at(values, share):  # exact at the step's ends (share 0 and 1): a whole step is the step itself
            return (1 - share) * values[k] + share * values[kn]

        x = None
        for m in range(1, parts + 1):
            if m > 1:
                xi, e = x[:2].copy(), (x[2:].copy() if self.coupled else None)
                self.taken(xi)
            a, b = (m - 1) / parts, m / parts
            x = self._advance(xi, e, at(self.w, a), at(self.w, b), at(self.free, a), at(self.free, b),
                              at(self.tilt, b), dtau)
        return x

    def _advance(self, xi, e, w_from, w_to, free_from, free_to, tilt_to, dtau):
        """The balanced unknowns a time ``dtau`` on, the load going from ``w_from`` to ``w_to`` and the free (or
        imposed) tilt to ``free_to`` (``tilt_to``)."""
        self.dtau = dtau
        self.second_order = self.time_order == 2 and self.dtau_prev is not None and len(self.steps) == 2
        if self.second_order:
            r = dtau / self.dtau_prev
            a0, self.a1, self.a2 = (1 + 2 * r) / (1 + r), 1 + r, r * r / (1 + r)
        else:
            a0 = 1.0
        self.c_time = 12 * a0 / dtau
        self.target = w_to
        self.free_to, self.tilt_to = free_to, tilt_to
        self.fixed_history = self.history_at(None) if self.tilt_squeeze or not self.coupled else None
        limit, tolerance = self.film.limit, FORCE_TOLERANCE * self.scale
        predicted, self.alpha = _predict(xi, w_from, 0.5 * (w_from + w_to), dtau, self.alpha, limit, *self.mobility)
        if self.coupled:
            x, self.h, self.jac, self.held = _tilted_balance(self.residual, predicted, e + (free_to - free_from),
                                                             self.jac, self.held, limit, tolerance, self.film, self.p,
                                                             self.kappa, free_to)
        else:
            x, self.h, self.jac = _force_balance(self.residual, predicted, self.jac, limit, tolerance)
        return x

    def snapshot(self):
        """The march's state before a step (its field, fill, memory), for :meth:`restore`."""
        return (self.p.copy(), self.fill.copy(), self.jac, self.held, self.alpha, self.dtau_prev, list(self.steps))

    def restore(self, state):
        """The march back at a :meth:`snapshot` (a step's field solves leave the field and fill where they
        stopped)."""
        p, fill, self.jac, self.held, self.alpha, self.dtau_prev, steps = state
        self.p[:] = p
        self.fill[:] = fill
        self.steps = list(steps)

    def taken(self, xi):
        """The step to ``xi`` is taken: its content joins the history."""
        self.steps = [self.steps[-1], (self.fill.copy(), xi.copy(), self.h)]
        self.dtau_prev = self.dtau

    def history_at(self, gamma):
        """12 d(content)/dtau's part from earlier steps (at gamma where the tilt's squeeze is neglected)."""
        contents = [g * (hh if self.tilt_squeeze or not self.coupled else self.film.thickness(x_old, gamma)[0])
                    for g, x_old, hh in self.steps]
        if self.second_order:
            return 12 * (self.a1 * contents[-1] - self.a2 * contents[-2]) / self.dtau
        return 12 * contents[-1] / self.dtau

    def solve_field(self, centre, gamma):
        """Pressure and fill (in place) of the step's field with the journal at ``centre``, tilt ``gamma``; its film."""
        film, p, fill = self.film, self.p, self.fill
        thickness = film.thickness(centre, gamma)
        history = self.fixed_history if self.fixed_history is not None else self.history_at(gamma)
        grid = Grid(film.fixed, film.dtheta, film.dz)
        sweeps = elrod_adams(thickness, history, self.c_time, p, fill, grid,
                             Sweeps(RELAXATION, FIELD_TOLERANCE, MAX_SWEEPS, self.mass_conserving))
        if sweeps < 0:
            # over-relaxation can cycle between cavitated and full nodes in a thin, starved film;
            # plain Gauss-Seidel from where it stopped is slower but settles
            sweeps = elrod_adams(thickness, history, self.c_time, p, fill, grid,
                                 Sweeps(1.0, FIELD_TOLERANCE, 4 * MAX_SWEEPS, self.mass_conserving))
        if sweeps < 0:
            raise RuntimeError("field solve did not converge")
        return thickness[0]

    def residual(self, x, held=False):
        """Unknowns: the centre and, with the tilt, its edge offset; ``held``: an edge on the limit."""
        film, p, target = self.film, self.p, self.target
        centre = x[:2]
        if not self.coupled:
            hh = self.solve_field(centre, self.tilt_to)
            return film.force(p) - target, hh
        edge = x[2:]
        hh = self.solve_field(centre, edge / self.edge_per_tilt)
        balance = edge + self.kappa * film.moment(p) - self.free_to
        if not held:
            return np.concatenate([film.force(p) - target, self.scale * balance]), hh
        # held: the farther edge on the limit, the moment's imbalance only along the wall's normal
        normal = _wall_normal(centre, edge)
        reach = max(np.hypot(*(centre + edge)), np.hypot(*(centre - edge)))
        return np.concatenate([film.force(p) - target, self.scale * np.array(
            [balance[0] * normal[1] - balance[1] * normal[0], reach - film.limit])]), hh


def _wall_normal(centre, edge):
    """Outward normal of the limit in edge-offset space at ``edge`` (the farther edge's direction)."""
    plus, minus = centre + edge, centre - edge
    if np.hypot(*plus) >= np.hypot(*minus):
        return plus / np.hypot(*plus)
    return -minus / np.hypot(*minus)


def _tilted_balance(residual, centre, edge, jac, held, limit, tolerance, film, p, kappa, free):
    """Centre and edge offset of a step, the tilt free or held with an edge on the limit.

    Free: force and moment balance. Held (the film cannot hold the journal):
    force balance, the farther edge on the limit and the moment's imbalance
    (e + kappa M - e_free) along the wall's normal only (the contact takes it).
    Free first unless the last step was held; a free solution with an edge
    past the limit, or one that fails, is solved held; a held one whose film
    pushes the edge back inside (that imbalance along the outward normal > 0)
    is solved free. A held solution turned further than :data:`HELD_TURN`
    times both the beam's free offset and the step's starting offset is the
    held equations' second root (the journal centred in its bore, carried by
    its tilt's wedge: iso-example's bearing 3 was turned to 2.05 mrad against
    a free slope of 0.83 where the free solve failed from the predicted
    centre), not taken: the step fails and is tried in sub-steps
    (:data:`SUBSTEPS`). Returns (x (4,), film, Jacobian, held).
    """
    start = np.concatenate([centre, _edges_inside(centre, edge, limit)])

    def free_solve(j):
        x, h, j = _force_balance(residual, start, j, limit, tolerance)
        reach = max(np.hypot(*(x[:2] + x[2:])), np.hypot(*(x[:2] - x[2:])))
        return (x, h, j), reach <= limit * (1 + 1e-9)

    def turned_too_far(x):
        # the held equations' second root: the journal centred in its bore, carried by its tilt's wedge
        return np.hypot(*x[2:]) > HELD_TURN * max(np.hypot(*free), np.hypot(*edge))

    def held_solve(j):
        # nested: the tilt's direction by the secant method on the moment's imbalance across the wall's normal,
        # for each direction the centre by the force balance with the farther edge on the limit
        inner = {"jac": j if j is not None and j.shape == (2, 2) else None, "x": centre.copy()}

        def on_wall(angle):
            direction = np.array([np.cos(angle), np.sin(angle)])

            c, _, inner["jac"] = _force_balance(lambda y: _with_film(residual, y, direction, limit), inner["x"],
                                                inner["jac"], limit, tolerance)
            inner["x"] = c
            e = _edge_on_wall(c, direction, limit)
            f, h = residual(np.concatenate([c, e]), held=True)
            return f[2], np.concatenate([c, e]), h

        angle = np.arctan2(edge[1], edge[0])
        g0, x, h = on_wall(angle)
        step = 0.02
        a1 = angle + step
        for _ in range(HELD_STEPS):
            g1, x, h = on_wall(a1)
            if abs(g1) <= tolerance:
                break
            if g1 == g0:
                raise RuntimeError("tilt held at the wall: the moment does not turn with the tilt")
            a1, angle, g0 = a1 - g1 * (a1 - angle) / (g1 - g0), a1, g1
        else:
            raise RuntimeError("tilt held at the wall: the tilt's direction did not settle")
        balance = x[2:] + kappa * film.moment(p) - free
        return (x, h, inner["jac"]), balance @ _wall_normal(x[:2], x[2:]) <= 0.0

    order = ((held_solve, True), (free_solve, False)) if held else ((free_solve, False), (held_solve, True))
    found = []
    for attempt, mode in order:
        try:
            result, consistent = attempt(jac if mode == held else None)
        except (RuntimeError, np.linalg.LinAlgError):
            continue
        if mode and turned_too_far(result[0]):
            continue
        if consistent:
            return (*result, mode)
        found.append((result, mode))
    # at the switch both can be marginally inconsistent: the edge then sits at the limit either way
    for result, mode in sorted(found, key=lambda item: not item[1]):
        return (*result, mode)
    raise RuntimeError("tilt balance: neither free nor held at the limit")


#: Secant steps on the direction of a tilt held at the wall.
HELD_STEPS = 12
#: A tilt held at the wall further than this times the beam's free offset and the step's starting offset is the
#: held equations' second root, not the step's.
HELD_TURN = 1.5
#: Sub-steps a step that fails is tried in, in turn (the load and the free tilt linear across the step).
SUBSTEPS = (1, 2, 4, 8)


def _edge_on_wall(centre, direction, limit):
    """Edge offset along ``direction`` that puts the farther edge of a journal centred at ``centre`` on the limit."""
    return direction * wall_room(centre[0], centre[1], 0.0, 0.0, direction[0], direction[1], limit)


def _with_film(residual, centre, direction, limit):
    """The force residual (2,) and film of the journal at ``centre`` with its tilt along ``direction`` on the wall."""
    f, h = residual(np.concatenate([centre, _edge_on_wall(centre, direction, limit)]), held=True)
    return f[:2], h


def _edges_inside(xi, e, limit):
    """The edge offset e scaled down until both edges of a journal centred at xi are inside 0.99 ``limit``."""
    room = wall_room(xi[0], xi[1], 0.0, 0.0, e[0], e[1], 0.99 * limit)
    return e * room if room < 1.0 else e


def _predict(xi, w0, w_mid, dtau, alpha, limit, table, stretched, finite):
    """Centre at the end of the step by the mobility tier's midpoint rule (a starting point for the balance)."""
    a0, a1, _, _, alpha, _ = _mobility.rate(xi[0], xi[1], w0[0], w0[1], alpha, limit, table, stretched, finite)
    b0, b1, _, _, _, _ = _mobility.rate(xi[0] + 0.5 * dtau * a0, xi[1] + 0.5 * dtau * a1, w_mid[0], w_mid[1], alpha,
                                        limit, table, stretched, finite)
    return _inside(xi + dtau * np.array([b0, b1]), limit), alpha


def _force_balance(residual, x, jac, limit, tolerance):
    """Centre x where the film force balances the load: damped Newton with Broyden updates.

    Steps are damped by Deuflhard's natural monotonicity test (the next Newton
    correction, with the same Jacobian, must shrink), which is blind to the
    scaling of the force components: the film is far stiffer along the line
    of centres than across it. A stale Jacobian is replaced by differences;
    where even that makes no progress (the force has a kink where a starved
    film fills), Levenberg-Marquardt takes over. Returns (x, film thickness at x, Jacobian); the field is left at x.
    """
    f, h = residual(x)
    if jac is None:
        jac = _difference_jacobian(residual, x, f)
        f, h = residual(x)
    fresh = False  # the Jacobian is a difference Jacobian at x
    creeping = 0
    for _ in range(MAX_BROYDEN):
        if np.linalg.norm(f) <= tolerance:
            return x, h, jac
        try:
            step = -np.linalg.solve(jac, f)
        except np.linalg.LinAlgError:  # a film that carries nothing in one direction (starved): no Newton step
            return _least_squares_balance(residual, x, tolerance)
        size = np.linalg.norm(step)
        damping = _edge_room(x, step, limit)
        accepted = False
        while damping >= 1.0 / 32:
            trial = _inside(x + damping * step, limit)
            f_trial, h_trial = residual(trial)
            if np.linalg.norm(f_trial) <= tolerance or \
                    np.linalg.norm(np.linalg.solve(jac, f_trial)) <= (1 - damping / 4) * size:
                accepted = True
                break
            damping /= 2
        if accepted:
            taken = trial - x
            # Broyden's good update (the Jacobian carries on to the next step)
            jac = jac + np.outer(f_trial - f - jac @ taken, taken) / max(taken @ taken, 1e-300)
            x, f, h = trial, f_trial, h_trial
            fresh = False
            # with the tilt, steps that creep (an edge near the wall stiffens the moment fast) ask for differences
            creeping = creeping + 1 if x.size > 2 and damping < 0.25 else 0
            if creeping >= 2 and np.linalg.norm(f) > tolerance:
                jac = _difference_jacobian(residual, x, f)
                f, h = residual(x)
                fresh = True
                creeping = 0
        elif fresh:
            return _least_squares_balance(residual, x, tolerance)
        else:
            jac = _difference_jacobian(residual, x, f)
            f, h = residual(x)  # the field back at x
            fresh = True
    return _least_squares_balance(residual, x, tolerance)


#: A step of the tilt unknowns may take an edge this many thinnest films (1 - limit) past the limit, no further.
EDGE_OVERLAP = 0.0


def _edge_room(x, step, limit):
    """Largest share (<= 1) of the step that keeps both edges within EDGE_OVERLAP thinnest films past the limit."""
    if x.size == 2:
        return 1.0
    bound = limit + EDGE_OVERLAP * (1.0 - limit)
    # the centre and the edge offset move together: the edges x[:2] +/- x[2:] along step[:2] +/- step[2:]
    room = min(wall_room(x[0], x[1], x[2], x[3], step[0] + step[2], step[1] + step[3], bound),
               wall_room(x[0], x[1], -x[2], -x[3], step[0] - step[2], step[1] - step[3], bound))
    return min(1.0, room)


def _least_squares_balance(residual, x, tolerance):
    """Fallback where the force has a kink (a starved film filling up): Levenberg-Marquardt (MINPACK)."""
    solution = optimize.root(lambda y: residual(y)[0], x, method="lm", options={"xtol": 1e-12, "ftol": 1e-14})
    f, h = residual(solution.x)
    if not np.linalg.norm(f) <= tolerance:
        raise RuntimeError("force balance: Levenberg-Marquardt did not balance the load")
    return solution.x, h, _difference_jacobian(residual, solution.x, f)


def _failed(record, peak, friction, flow, k, cycle):
    """Status 'failed': angles from k on were not solved in this cycle and carry NaN (flagged by the status)."""
    for a in (record, peak, friction, flow):
        a[k:] = np.nan
    return record, peak, friction, flow, 3, cycle


def _difference_jacobian(residual, x, f):
    """Forward-difference Jacobian of the balance (a field solve per unknown)."""
    delta = 1e-4 * max(1 - float(np.hypot(*x[:2])), 1e-3)
    jac = np.empty((f.size, x.size))
    for i in range(x.size):
        e = np.zeros(x.size)
        e[i] = delta
        jac[:, i] = (residual(x + e)[0] - f) / delta
    return jac


#: Largest edge offset the tilt unknowns may take [c] (the journal's axis across the whole clearance).
EDGE_OFFSET_LIMIT = 2.0


def _inside(x, limit):
    """The centre (first two unknowns) within the limit eccentricity, an edge offset (the rest) within its limit."""
    x = np.array(x, dtype=float)
    e = float(np.hypot(*x[:2]))
    if e > limit:
        x[:2] *= limit / e
    if x.size > 2:
        t = float(np.hypot(*x[2:]))
        if t > EDGE_OFFSET_LIMIT:
            x[2:] *= EDGE_OFFSET_LIMIT / t
    return x


def _outputs(film, p, fill, h):
    """Peak pressure, friction integral and side-flow integral of a field (dimensionless)."""
    dp = (np.roll(p, -1, axis=0) - np.roll(p, 1, axis=0)) / (2 * film.dtheta)
    shear = fill / h + 0.5 * h * dp
    friction = float((shear @ film.weights).sum() * film.dtheta)
    dz = film.dz
    ends = (h[:, 0] ** 3 * (4 * p[:, 1] - p[:, 2]) + h[:, -1] ** 3 * (4 * p[:, -2] - p[:, -3])) / (2 * dz)
    flow = float(ends.sum() * film.dtheta)
    return float(p.max()), friction, flow
