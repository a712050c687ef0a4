r"""Dynamically loaded bearings over the engine cycle: the journal orbit, its film and pressure.

Tiers of :func:`orbit` (``method``); their measured costs and errors are in
``reports/film_speed_vs_error.md`` and :func:`cheapest_cycle_tier` picks from them:

``"quasi-static"`` (``"quasi-static-short"``, ``"quasi-static-finite"``, ``"quasi-static-reynolds"``)
    Each crank angle as a steady load on a steady tier (``steady_method``):
    no squeeze film.
``"mobility"`` (alias ``"mobility-short"``)
    The journal centre moves so that the film force balances the load at
    every instant (massless journal, Booker's mobility method), with the
    short-bearing film force in closed form.
``"mobility-finite"``
    The same orbit with the short-bearing force scaled and turned by a
    finite-length correction tabulated from the Reynolds tier with squeeze
    (``stackup/data/film_mobility_table.npz``, ``studies/film_mobility_table.py``:
    L/D 0.15-1, eccentricity up to the limit, every squeeze direction; the
    peak pressure corrected the same way). The quasi-static ``finite`` tier's
    peak pressure uses the same table at the steady squeeze direction.
``"reynolds-transient"``
    The reference: the finite-difference Reynolds equation with squeeze and
    mass-conserving (Elrod-Adams, JFO) cavitation, the journal centre integrated
    over the cycle (:mod:`stackup.film.transient`).

Mobility tiers. In the engine-fixed frame, journal centre :math:`\mathbf x`
(from the bearing centre), journal speed :math:`\omega` (positive from axis 0 to
axis 1), bearing fixed, :math:`h(\Theta) = c - \mathbf x\cdot\mathbf n(\Theta)`, the
Reynolds equation's source is

.. math:: 6\mu\omega\,\partial_\Theta h + 12\mu\,\partial_t h = -12\mu\,\mathbf v_s\cdot\mathbf n,
          \qquad \mathbf v_s = \dot{\mathbf x} - \tfrac{\omega}{2}\,\mathbf k\times\mathbf x

so rotation and squeeze act together as a pure squeeze at :math:`\mathbf v_s`
(Booker 1965). The short bearing (:math:`\partial_z(h^3\partial_z p) = -12\mu\,\mathbf v_s\cdot\mathbf n`,
:math:`p = 0` at both ends, π-film: no pressure where :math:`\mathbf v_s\cdot\mathbf n < 0`) gives

.. math:: \mathbf F = \frac{\mu R L^3}{c^3}\,G(\varepsilon, \alpha)\,\mathbf v_s, \qquad
          G = \int_{\alpha-\pi/2}^{\alpha+\pi/2}\frac{\mathbf n\mathbf n^T\,d\phi}{(1-\varepsilon\cos\phi)^3}

(line-of-centres frame, :math:`\alpha` the direction of :math:`\mathbf v_s`), in closed form
through Sommerfeld's substitution. Given the load, Newton on :math:`\alpha` finds
:math:`\mathbf v_s` (the mobility inverse: the force turns monotonically with :math:`\alpha`);
:math:`\dot{\mathbf x}` is integrated by the explicit midpoint rule over repeated cycles
from the bearing centre, two angles per step until the orbit nearly closes, then
every angle until it closes within :data:`PERIODIC` of the thinnest film (the
midpoint rule at 1 deg steps is within 0.07 % of RK4 at 1/8 deg on the built-in
engines' bearings). Per
angle: mid-plane peak pressure :math:`p_{max} = \tfrac32\mu\,(L/c)^2\max_\phi\,\mathbf v_s\cdot\mathbf n/\bar h^3`,
friction torque on the journal :math:`T = \frac{2\pi\mu\omega R^3 L}{c\sqrt{1-\varepsilon^2}} - \tfrac12(\mathbf x\times\mathbf W)_z`
(full-film shear plus the pressure couple, as the steady tiers) and side flow
:math:`Q = 2RL|\mathbf v_s|` (both reduce to Ocvirk's steady forms).

Journal tilt (``tilt``, the slope :math:`\boldsymbol\gamma` of the journal axis relative to
the bearing axis) makes the film :math:`h = c - (\mathbf x + z\boldsymbol\gamma)\cdot\mathbf n`,
:math:`z \in [-L/2, L/2]`. With ``tilt_compliance`` (the crankshaft's rotational
compliance at the bearing, :func:`stackup.crank.support_compliance`) ``tilt`` is
the beam's free slope and the tilt in the film is the equilibrium
:math:`\boldsymbol\gamma = \boldsymbol\gamma_{free} - C\,\mathbf M_{film}` with the film's
restoring moment (:mod:`stackup.film.tilt`): every tier but the transient one
solves it at each angle on its own mid-plane orbit (the short-bearing moment,
finite-corrected in the ``finite`` tiers; tilt squeeze neglected), the
transient tier carries the tilt as two more unknowns of its balance (force
and moment, tilt squeeze included). Without ``tilt_compliance`` the tilt is
imposed as given. The edge film is then
:math:`h_{edge} = c - \max_\pm|\mathbf x \pm \tfrac L2\boldsymbol\gamma|`.

Status per bearing (:data:`STATUS`): ``periodic``; ``not_periodic`` (the orbit had not
closed within ``cycles``); ``collapsed`` (the journal reached :data:`ECCENTRICITY_LIMIT`,
or its film thinned cycle after cycle: a film collapse, e.g. a load turning at
half the shaft speed; the film is reported where it was held); ``failed`` (the
film solve failed; angles not solved are NaN); ``edge_contact`` (a periodic
orbit whose tilted journal brings an edge to the limit at some angle, where the
film cannot hold the beam's slope: the edge film is held at
:math:`c(1 - \varepsilon_{lim})`). Never a silent NaN.

References
----------
.. [1] Booker, J. F., "Dynamically loaded journal bearings: mobility method of
   solution", J. Basic Eng. 87 (1965) 537-546.
.. [2] Booker, J. F., "Squeeze films and bearing dynamics", CRC Handbook of
   Lubrication Vol. II, 1983, pp. 121-137.
.. [3] Ocvirk, F. W., NACA TN 2808, 1952 (short bearing).
.. [4] Rozhdestvensky, Y. et al., Tribology in Industry 40 (2018), eq. 4 (film with skewed axes).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np

from .. import _validate as check
from .._kernels import mobility as _kernel

#: Tier names :func:`orbit` accepts, cheapest first, and what each runs: (method, steady tier).
TIERS = {
    "quasi-static-short": ("quasi-static", "short"),
    "quasi-static-finite": ("quasi-static", "finite"),
    "mobility": ("mobility", None),
    "mobility-short": ("mobility", None),
    "mobility-finite": ("mobility-finite", None),
    "quasi-static-reynolds": ("quasi-static", "reynolds"),
    "reynolds-transient": ("reynolds-transient", None),
}
METHODS = ("quasi-static", *TIERS)
#: Status codes of an orbit (CF flag_values 0..4 with these flag_meanings).
STATUS = ("periodic", "not_periodic", "collapsed", "failed", "edge_contact")
#: The orbit is periodic when the journal returns after a cycle to within this share of the thinnest film.
PERIODIC = 1e-3
#: Largest eccentricity a journal reaches; a film held there has collapsed.
ECCENTRICITY_LIMIT = 0.995


@dataclass(frozen=True)
class Orbit:
    """Film of bearings over a cycle; leading shape (...) of the loads, angles last.

    Attributes
    ----------
    h_min : numpy.ndarray (..., angles)
        Minimum film thickness in the bearing's mid-plane [m].
    h_min_edge : numpy.ndarray (..., angles)
        Minimum film thickness over the bearing width, with the journal's tilt [m]
        (equals ``h_min`` without tilt).
    eccentricity : numpy.ndarray (..., angles)
        Eccentricity ratio of the mid-plane journal centre [-].
    position : numpy.ndarray (..., angles, 2)
        Journal centre relative to the bearing centre [m].
    p_max : numpy.ndarray (..., angles)
        Peak film pressure [Pa].
    friction_torque : numpy.ndarray (..., angles)
        Friction torque on the journal [N m].
    side_flow : numpy.ndarray (..., angles)
        Oil leaving both ends of the bearing [m^3/s].
    status : numpy.ndarray of int8 (...)
        Index into :data:`STATUS`.
    cycles : numpy.ndarray of int (...)
        Cycles integrated (0 for the quasi-static tiers).
    speed : numpy.ndarray (...)
        Journal angular speed [rad/s] (for the friction power).
    tilt : numpy.ndarray (..., angles, 2) or None
        Slope of the journal against the bearing axis in the film [rad] (the
        equilibrium with ``tilt_compliance``, else the tilt given).
    free_tilt : numpy.ndarray (..., angles, 2) or None
        The tilt given: the beam's slope without the film's moment [rad].
    tilt_state : numpy.ndarray of int8 (..., angles) or None
        Index into :data:`stackup.film.tilt.STATES` (``at_limit``: the film cannot
        hold the journal, an edge at the limit).
    """

    h_min: np.ndarray
    h_min_edge: np.ndarray
    eccentricity: np.ndarray
    position: np.ndarray
    p_max: np.ndarray
    friction_torque: np.ndarray
    side_flow: np.ndarray
    status: np.ndarray
    cycles: np.ndarray
    speed: np.ndarray
    tilt: np.ndarray | None = None
    free_tilt: np.ndarray | None = None
    tilt_state: np.ndarray | None = None

    @property
    def converged(self):
        """The orbit is periodic with a film (status 0)."""
        return self.status == 0

    @property
    def h_min_cycle(self):
        """Cycle minimum of the mid-plane minimum film (inf h_min) [m]."""
        return self.h_min.min(axis=-1)

    @property
    def h_min_mean(self):
        """Cycle average of the mid-plane minimum film (h*_min) [m] (equal angle steps)."""
        return self.h_min.mean(axis=-1)

    @property
    def h_min_edge_cycle(self):
        """Cycle minimum of the film over the bearing width, with tilt [m]."""
        return self.h_min_edge.min(axis=-1)

    @property
    def tilt_max(self):
        """Cycle maximum of the journal's tilt in the film [rad] (0 without tilt)."""
        if self.tilt is None:
            return np.zeros(self.status.shape)
        return _vector_length(self.tilt).max(axis=-1)

    @property
    def edge_contact_share(self):
        """Share of the cycle's angles with an edge at the limit [-] (0 without tilt)."""
        if self.tilt_state is None:
            return np.zeros(self.status.shape)
        return np.mean(self.tilt_state == 1, axis=-1)

    @property
    def p_max_cycle(self):
        """Cycle maximum of the peak film pressure (sup p_max) [Pa]."""
        return self.p_max.max(axis=-1)

    @property
    def p_max_mean(self):
        """Cycle average of the peak film pressure (p*_max) [Pa]."""
        return self.p_max.mean(axis=-1)

    @property
    def friction_power(self):
        """Friction power at each angle [W]."""
        return self.friction_torque * self.speed[..., None]

    @property
    def friction_power_mean(self):
        """Cycle average of the friction power (N*) [W]."""
        return self.friction_power.mean(axis=-1)

    @property
    def side_flow_mean(self):
        """Cycle average of the side flow (Q*) [m^3/s]."""
        return self.side_flow.mean(axis=-1)


@lru_cache(maxsize=1)
def mobility_table():
    """The finite-length correction of the short-bearing squeeze force (see ``studies/film_mobility_table.py``).

    Returns (length_over_diameter (n_ld,), -ln(1 - eccentricity) (n_eps,), table (n_ld, n_eps, n_alpha, 3)):
    log force ratio, turn [rad] and log peak-pressure ratio of the Reynolds tier to the
    short bearing, over squeeze directions alpha in [0, pi] (uniform).
    """
    path = resources.files("stackup") / "data" / "film_mobility_table.npz"
    with np.load(path) as data:
        table = np.stack([data["log_force_ratio"], data["turn"], data["log_peak_ratio"]], axis=-1)
        return (np.ascontiguousarray(data["length_over_diameter"]), -np.log1p(-data["eccentricity"]),
                np.ascontiguousarray(table))


@lru_cache(maxsize=1)
def cycle_tier_errors():
    """Measured cost and film error of each cycle tier against ``reynolds-transient``.

    From ``stackup/data/film_cycle_errors.toml``, written by
    ``studies/film_speed_vs_error.py`` on the built-in engines' main bearings: per
    tier ``seconds`` (one bearing's cycle on one core) and the largest relative
    error of the cycle minimum (``h_min``) and cycle mean (``h_min_mean``) of the
    minimum film, the peak pressure's maximum and mean and the mean friction
    power, against the mass-conserving reference, and in ``"swift-stieber"``
    against the same reference with the Reynolds cavitation condition.
    """
    import tomllib

    with open(resources.files("stackup") / "data" / "film_cycle_errors.toml", "rb") as f:
        return tomllib.load(f)["tiers"]


def cheapest_cycle_tier(max_error, *, measures=("h_min", "h_min_mean"), reference="mass-conserving", tiers=None):
    """The cheapest cycle tier whose measured errors (``measures``) are all within ``max_error`` [-].

    Like :func:`stackup.film.cheapest_tier` for the steady tiers. ``reference``:
    ``"mass-conserving"`` (Elrod-Adams, the physical reference) or
    ``"swift-stieber"`` (the same transient tier with the Reynolds condition, the
    cavitation model of every cheaper tier: it measures their numerical error
    only). ``tiers``: the tiers to choose from (default every measured one). Falls
    back to ``reynolds-transient`` when no cheaper tier qualifies.
    """
    max_error = float(check.positive("max_error", max_error, allow_zero=True))
    check.one_of("reference", reference, ("mass-conserving", "swift-stieber"))
    for name in measures:
        check.one_of("measures", name, ("h_min", "h_min_mean", "p_max", "p_max_mean", "friction_power"))
    errors = cycle_tier_errors()
    ranked = sorted((t for t in errors if tiers is None or t in tiers), key=lambda t: errors[t]["seconds"])

    def error(tier, name):
        table = errors[tier] if reference == "mass-conserving" else errors[tier]["swift-stieber"]
        return table[name]

    return next((t for t in ranked if all(error(t, m) <= max_error for m in measures)), "reynolds-transient")


def _short_table():
    return np.array([1.0, 2.0]), np.array([0.0, 1.0]), np.zeros((1, 2, 2, 3))


def _vector_length(vectors):
    """Length of the 2-vectors on the last axis: ``np.linalg.norm(vectors, axis=-1)`` to the bit, at a sixth of its cost.

    norm reduces over an axis of two, which numpy does slowly; on the (bearings, angles, 2) arrays of an orbit its
    calls cost as much as a tenth of the film stage's Python around the kernels.
    """
    x, y = vectors[..., 0], vectors[..., 1]
    return np.sqrt(x * x + y * y)


def resolve(method, steady_method="finite"):
    """(kernel method, steady tier) of a tier name."""
    check.one_of("method", method, METHODS)
    if method == "quasi-static":
        return "quasi-static", steady_method
    return TIERS[method]


def orbit(load_history, crank_angle, *, diameter, length, clearance, viscosity, speed, method="mobility",
          steady_method="finite", tilt=None, tilt_compliance=None, cycles=None, start=None, **transient_options):
    """Film over the engine cycle of dynamically loaded bearings.

    Parameters
    ----------
    load_history : array_like (..., angles, 2)
        Load on each bearing over one cycle [N] (force of the journal on the
        bearing, engine-fixed frame).
    crank_angle : array_like (angles,)
        Crank angles [deg], increasing, covering one cycle (720 deg).
    diameter, length, clearance : float or array_like (...)
        Journal diameter, bearing length, diametral clearance [m].
    viscosity : float or array_like (...)
        Effective oil viscosity [Pa s].
    speed : float or array_like (...)
        Journal angular speed [rad/s] (positive: from load axis 0 towards axis 1).
    method : str
        A tier of :data:`TIERS`, or ``"quasi-static"`` with ``steady_method``.
    steady_method : {"short", "finite", "reynolds"}
        Steady tier of ``"quasi-static"``.
    tilt : array_like (..., angles, 2), optional
        Slope of the journal axis relative to the bearing axis [rad], per
        component of the engine frame (the journal centre at axial position
        :math:`z` from the mid-plane is :math:`\\mathbf x + z\\boldsymbol\\gamma`): with
        ``tilt_compliance`` the slope without the film's moment (the beam's free
        slope, :func:`stackup.crank.support_slopes`), else the tilt imposed.
    tilt_compliance : array_like (..., 2), optional
        Rotational compliance of the journal at the bearing per component of the
        engine frame [rad/(N m)] (:func:`stackup.crank.support_compliance`): the
        tilt in the film balances the film's moment against it
        (:mod:`stackup.film.tilt`).
    cycles : int, optional
        Most cycles a dynamic tier integrates to reach a periodic orbit
        (default 20 for the mobility tiers, 8 for ``"reynolds-transient"``).
    start : array_like (..., 2), optional
        Journal centre at the first crank angle [m] to start a dynamic tier
        from (e.g. the ``position[..., 0, :]`` of a coarser orbit); default the
        bearing centre (the mobility tiers) or the ``mobility-finite`` orbit's
        (the transient tier). A start near the periodic orbit saves laps; the
        orbit reached is the same.
    **transient_options
        Grid and cavitation options of ``"reynolds-transient"``
        (:func:`stackup.film.transient.transient_orbit`).

    Returns
    -------
    Orbit
    """
    kind, steady = resolve(method, steady_method)
    loads, angle = _checked_cycle(load_history, crank_angle)
    lead = loads.shape[:-2]
    radius = np.broadcast_to(check.positive("diameter", diameter) / 2, lead)
    width = np.broadcast_to(check.positive("length", length), lead)
    c = np.broadcast_to(check.positive("clearance", clearance) / 2, lead)
    mu = np.broadcast_to(check.positive("viscosity", viscosity), lead)
    omega = np.broadcast_to(check.positive("speed", speed), lead)
    cycles = _checked_cycles(cycles, kind)
    tilt, tilt_compliance = _checked_tilt(tilt, tilt_compliance, loads.shape)
    return _orbit(loads, angle, kind, steady, radius=radius, length=width, radial_clearance=c, viscosity=mu,
                  speed=omega, cycles=cycles, tilt=tilt, tilt_compliance=tilt_compliance, start=start,
                  **transient_options)


def _checked_cycle(load_history, crank_angle):
    """:func:`orbit`'s checks of the loads and crank angles: (loads (..., angles, 2), angles), float arrays."""
    loads = check.finite("load_history", load_history)
    angle = check.finite("crank_angle", crank_angle)
    if angle.ndim != 1 or loads.ndim < 2 or loads.shape[-1] != 2 or loads.shape[-2] != angle.size:
        raise ValueError(f"load_history: shape {loads.shape} is not valid; expected (..., {angle.size}, 2)")
    if np.any(np.diff(angle) <= 0) or angle[-1] - angle[0] >= 720.0:
        raise ValueError("crank_angle: must increase and span less than 720 deg")
    return loads, angle


def _checked_cycles(cycles, kind):
    """:func:`orbit`'s ``cycles``: its default for the tier ``kind`` (:func:`resolve`), checked."""
    if cycles is None:
        cycles = 8 if kind == "reynolds-transient" else 20
    return check.integer("cycles", cycles, minimum=1)


def _checked_tilt(tilt, tilt_compliance, shape):
    """:func:`orbit`'s checks of the tilt and the compliance, broadcast to the loads' ``shape`` (None stays None)."""
    if tilt is not None:
        tilt = np.broadcast_to(check.finite("tilt", tilt), shape)
    if tilt_compliance is not None:
        if tilt is None:
            raise ValueError("tilt_compliance: given without tilt (the journal's free slope)")
        tilt_compliance = np.broadcast_to(check.positive("tilt_compliance", tilt_compliance, allow_zero=True),
                                          (*shape[:-2], 2))
    return tilt, tilt_compliance


def _orbit(loads, angle, kind, steady, *, radius, length, radial_clearance, viscosity, speed, cycles, tilt,
           tilt_compliance, start, **transient_options):
    """:func:`orbit` on checked inputs: geometry (...) and tilts broadcast to the loads (:func:`_checked_cycle`,
    :func:`_checked_tilt`), ``cycles`` an int (``start`` is checked here).

    For callers that run orbits over and over on inputs checked once (:func:`stackup.film.cycle.balanced_orbit`).
    """
    lead = loads.shape[:-2]
    width, c, omega = length, radial_clearance, speed
    geometry = dict(radius=radius, length=length, radial_clearance=radial_clearance, viscosity=viscosity,
                    speed=speed)

    if kind == "quasi-static":
        position, p_max, torque, flow = _quasi_static(loads, steady, **geometry)
        status, used = np.zeros(lead, np.int8), np.zeros(lead, int)
        squeeze = -0.5 * omega[..., None, None] * np.stack([-position[..., 1], position[..., 0]], axis=-1)
        finite = steady != "short"
    elif kind == "reynolds-transient":
        from .transient import transient_orbit

        result = transient_orbit(loads, angle, tilt=tilt, tilt_compliance=tilt_compliance, cycles=cycles,
                                 start=start, **geometry, **transient_options)
        return result
    else:
        if start is not None:
            start = np.broadcast_to(check.finite("start", start), (*lead, 2))
        finite = kind == "mobility-finite"
        position, p_max, torque, flow, status, used, squeeze = _mobility(loads, angle, finite=finite, cycles=cycles,
                                                                         start=start, **geometry)
    ecc = _vector_length(position) / c[..., None]
    h_min = c[..., None] * (1 - ecc)
    film_tilt, tilt_state = tilt, None
    if tilt_compliance is not None:
        film_tilt, tilt_state = _tilt_in_film(position, squeeze, tilt, tilt_compliance, finite=finite, **geometry)
    h_edge, status = edge_film(position, film_tilt, width, c, h_min, status, at_limit=tilt_state)
    return Orbit(h_min, h_edge, ecc, position, p_max, torque, flow, status, used, omega, film_tilt, tilt, tilt_state)


def _tilt_in_film(position, squeeze, free_tilt, compliance, *, finite, radius, length, radial_clearance, viscosity,
                  speed):
    """Tilt equilibrium on a mid-plane orbit (:func:`stackup.film.tilt.cycle_tilt`): (tilt, state)."""
    from .tilt import _cycle_tilt

    ld_nodes = mobility_table()[0]
    ld = length / (2 * radius)
    # the finite correction where its table covers the bearing (as the mobility-finite tier)
    covered = bool(np.all((ld >= ld_nodes[0]) & (ld <= ld_nodes[-1])))
    # orbit() checked the inputs, and its orbit is finite (held at the eccentricity limit at worst)
    result = _cycle_tilt(position, squeeze, free_tilt, compliance, radius=radius, length=length,
                         radial_clearance=radial_clearance, viscosity=viscosity, speed=speed,
                         finite=finite and covered)
    return result.tilt, result.state


def edge_film(position, tilt, width, c, h_min, status, at_limit=None):
    """Thinnest film over the width of a tilted journal (at an edge), held at the limit where an edge touches.

    ``at_limit`` (..., angles): the tilt equilibrium's state per angle
    (:data:`stackup.film.tilt.STATES`); an angle in state 1 has its edge at the limit.
    Returns (edge film (..., angles) [m], status with ``edge_contact`` where a periodic orbit's edge touched).
    """
    if tilt is None:
        return h_min, status
    half = 0.5 * width[..., None, None] * tilt
    reach = np.maximum(_vector_length(position + half), _vector_length(position - half))
    floor = (c * (1 - ECCENTRICITY_LIMIT))[..., None]
    touching = c[..., None] - reach < floor * (1 + 1e-9)
    if at_limit is not None:
        touching = touching | (at_limit == 1)
    status = np.where((status == 0) & touching.any(axis=-1), STATUS.index("edge_contact"), status).astype(np.int8)
    return np.maximum(np.minimum(h_min, c[..., None] - reach), floor), status


def _mobility(loads, angle, *, finite, cycles, start, radius, length, radial_clearance, viscosity, speed):
    lead = loads.shape[:-2]
    n = angle.size
    c, mu, w = radial_clearance, viscosity, speed
    scale = mu * w * radius * length**3 / c**2  # load of unit dimensionless force [N]
    w_bar = np.ascontiguousarray((loads / scale[..., None, None]).reshape(-1, n, 2))
    tau = np.radians(np.append(angle, angle[0] + 720.0) - angle[0])
    ld = np.ascontiguousarray((length / (2 * radius)).reshape(-1), dtype=float)
    if finite:
        ld_nodes, stretched, tables = mobility_table()
        if np.any((ld < ld_nodes[0]) | (ld > ld_nodes[-1])):
            raise ValueError(f"length: L/D {float(ld.min())!r}..{float(ld.max())!r} is outside the mobility-finite "
                             f"table [{ld_nodes[0]}, {ld_nodes[-1]}]; use method='reynolds-transient'")
    else:
        ld_nodes, stretched, tables = _short_table()
    m = w_bar.shape[0]
    xi = np.empty((m, n, 2))
    v = np.empty((m, n, 2))
    peak = np.empty((m, n))
    status = np.empty(m, np.int8)
    used = np.empty(m)
    warm = start is not None
    xi0 = np.ascontiguousarray((start / c[..., None]).reshape(-1, 2) if warm else np.zeros((m, 2)), dtype=float)
    _kernel.orbits(w_bar, tau, ECCENTRICITY_LIMIT, PERIODIC, cycles, tables, ld_nodes, stretched, ld, finite,
                   xi, v, peak, status, used, xi0, warm)
    xi = xi.reshape(*lead, n, 2)
    v = v.reshape(*lead, n, 2)
    position = xi * c[..., None, None]
    squeeze = v * (c * w)[..., None, None]
    ecc = _vector_length(xi)
    p_max = 1.5 * (mu * w * (length / c) ** 2)[..., None] * peak.reshape(*lead, n)
    torque = (2 * np.pi * mu * w * radius**3 * length / c)[..., None] / np.sqrt(1 - ecc**2) \
        + 0.5 * (position[..., 1] * loads[..., 0] - position[..., 0] * loads[..., 1])
    flow = (2 * radius * length * c * w)[..., None] * _vector_length(v)
    return position, p_max, torque, flow, status.reshape(lead), used.reshape(lead), squeeze


def _quasi_static(loads, steady, *, radius, length, radial_clearance, viscosity, speed):
    """Steady film at each angle; the journal sits at the attitude angle ahead of the load, in the turning direction."""
    from . import min_film_thickness

    c, mu, w = (a[..., None] for a in (radial_clearance, viscosity, speed))
    r, l = radius[..., None], length[..., None]
    magnitude = np.linalg.norm(loads, axis=-1)
    kw = dict(diameter=2 * r, length=l, clearance=2 * c, viscosity=mu, speed=w)
    if steady == "reynolds":
        film, field_peak = _steady_reynolds(np.maximum(magnitude, 1e-6), **kw)
    else:
        film = min_film_thickness(np.maximum(magnitude, 1e-6), **kw, method=steady)
        eps = np.minimum(film.eccentricity, ECCENTRICITY_LIMIT)
        ld_nodes, stretched, tables = mobility_table() if steady == "finite" else _short_table()
        flat_eps = np.ascontiguousarray(eps, dtype=float).ravel()
        factor = np.empty(flat_eps.size)
        _kernel.steady_peak_factors(flat_eps, np.ascontiguousarray(np.broadcast_to(l / (2 * r), eps.shape),
                                                                   dtype=float).ravel(),
                                    tables, ld_nodes, stretched, steady == "finite", factor)
        # v_s = (1/2) k x xi: |v| = eps/2
        field_peak = 1.5 * mu * w * (l / c) ** 2 * 0.5 * eps * factor.reshape(eps.shape)
    direction = np.arctan2(loads[..., 1], loads[..., 0]) + film.attitude_angle
    ecc = np.where(magnitude > 0, film.eccentricity, 0.0)
    position = (c * ecc)[..., None] * np.stack([np.cos(direction), np.sin(direction)], axis=-1)
    return position, field_peak, film.friction_torque, film.side_flow


def _steady_reynolds(load, *, diameter, length, clearance, viscosity, speed):
    """Steady Reynolds tier at each angle, with the peak of its pressure field."""
    from . import ECCENTRICITY_VALID, Film, reynolds

    load, diameter, length, clearance, viscosity, speed = np.broadcast_arrays(load, diameter, length, clearance,
                                                                             viscosity, speed)
    out = {k: np.empty(load.shape) for k in ("eps", "phi", "torque", "flow", "peak")}
    for idx in np.ndindex(load.shape):
        r, l, c, mu, w = (float(a[idx]) for a in (diameter / 2, length, clearance / 2, viscosity, speed))
        unit = mu * w * r**4 / c**2
        field = reynolds.eccentricity_for_load(float(load[idx]) / unit, l / r)
        friction, flow = reynolds.friction_and_flow(field)
        out["eps"][idx] = field.eps
        out["phi"][idx] = field.attitude
        out["torque"][idx] = mu * w * r**4 / c * friction
        out["flow"][idx] = w * r**2 * c / 12 * flow
        out["peak"][idx] = mu * w * r**2 / c**2 * field.pressure.max()
    c = clearance / 2
    return Film(out["eps"], c * (1 - out["eps"]), out["phi"], out["torque"], out["flow"],
                out["eps"] <= ECCENTRICITY_VALID), out["peak"]
