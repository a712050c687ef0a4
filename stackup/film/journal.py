r"""The journal in its bearing over the engine cycle: what every tier shares.

The cycle tiers (:mod:`~stackup.film.quasi_static`, :mod:`~stackup.film.mobility`,
:mod:`~stackup.film.elrod`, :mod:`~stackup.film.transient`), the steady tiers
(:mod:`~stackup.film.steady`, :mod:`~stackup.film.reynolds`) and the tilt equilibrium
(:mod:`~stackup.film.tilt`) import this module and none of them another's internals: the
eccentricity limit, the status codes of an orbit and of the tilt equilibrium, the result
:class:`Orbit`, the finite-length correction's table, the edge film of a tilted journal and the
patch the fed tiers hold full.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np

#: Status codes of an orbit (CF flag_values 0..4 with these flag_meanings).
STATUS = ("periodic", "not_periodic", "collapsed", "failed", "edge_contact")
#: States of the tilt equilibrium at an angle (flag values 0..2).
STATES = ("equilibrium", "at_limit", "not_solved")
#: Largest eccentricity the film models go to: the thinnest film they resolve is 0.5 % of the radial clearance.
#: One limit for every tier: the steady Reynolds tier solves up to it and the finite tier's table ends there
#: (a steady film beyond it is returned with ``valid`` False, the short-bearing curve scaled past it); a cycle
#: tier's journal, or a tilted journal's edge, is held there (the film has collapsed, or the edge is at the
#: wall); the mobility tier's correction table is tabulated up to it.
ECCENTRICITY_LIMIT = 0.995
#: The engine cycle [deg] the cycle tiers' crank angles lie in (four strokes: two turns of the journal).
CYCLE = 720.0
#: The feed when none is given (:func:`feed_patch`): a patch on the block side (Theta = pi, opposite the cap), its
#: width around the bearing [rad] and its share of the bearing's width; a hole is a patch this wide too.
FEED_ANGLE = np.pi
FEED_WIDTH = np.radians(6.0)
FEED_LENGTH_SHARE = 0.3


def within_one_cycle(crank_angle):
    """A ValueError unless the crank angles (angles,) increase and span less than a cycle."""
    if np.any(np.diff(crank_angle) <= 0) or crank_angle[-1] - crank_angle[0] >= CYCLE:
        raise ValueError(f"crank_angle: must increase and span less than {CYCLE:g} deg")


def vector_length(vectors):
    """Length of the 2-vectors on the last axis: ``np.linalg.norm(vectors, axis=-1)`` to the bit, and cheaper.

    norm reduces over an axis of two, which numpy does slowly; an orbit's (bearings, angles, 2) arrays
    are reduced this way at every orbit the heat balance runs.
    """
    x, y = vectors[..., 0], vectors[..., 1]
    return np.sqrt(x * x + y * y)


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
        Index into :data:`STATES` (``at_limit``: the film cannot hold the
        journal, an edge at the limit).
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
        return vector_length(self.tilt).max(axis=-1)

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


def short_table():
    """A table of no correction, in :func:`mobility_table`'s layout: what the short-bearing kernels are given."""
    return np.array([1.0, 2.0]), np.array([0.0, 1.0]), np.zeros((1, 2, 2, 3))


def table_covers(length_over_diameter):
    """Whether :func:`mobility_table` covers every L/D given (its correction is not extrapolated)."""
    ld_nodes = mobility_table()[0]
    ld = np.asarray(length_over_diameter)
    return bool(np.all((ld >= ld_nodes[0]) & (ld <= ld_nodes[-1])))


def outside_table(field, length_over_diameter, what):
    """The ValueError for bearings whose L/D the finite correction's table does not cover."""
    ld_nodes = mobility_table()[0]
    ld = np.asarray(length_over_diameter)
    return ValueError(f"{field}: L/D {float(ld.min())!r}..{float(ld.max())!r} is outside {what} "
                      f"[{ld_nodes[0]}, {ld_nodes[-1]}]")


def edge_film(position, tilt, bearing_width, radial_clearance, h_min, status, at_limit=None):
    """Thinnest film over the width of a tilted journal (at an edge), held at the limit where an edge touches.

    ``at_limit`` (..., angles): the tilt equilibrium's state per angle
    (:data:`STATES`); an angle in state 1 has its edge at the limit.
    Returns (edge film (..., angles) [m], status with ``edge_contact`` where a periodic orbit's edge touched).
    """
    if tilt is None:
        return h_min, status
    c = radial_clearance
    half = 0.5 * bearing_width[..., None, None] * tilt
    reach = np.maximum(vector_length(position + half), vector_length(position - half))
    floor = (c * (1 - ECCENTRICITY_LIMIT))[..., None]
    touching = c[..., None] - reach < floor * (1 + 1e-9)
    if at_limit is not None:
        touching = touching | (at_limit == 1)
    status = np.where((status == 0) & touching.any(axis=-1), STATUS.index("edge_contact"), status).astype(np.int8)
    return np.maximum(np.minimum(h_min, c[..., None] - reach), floor), status


def feed_patch(feed, *, journal_radius, bearing_width, unit_pressure, angle=FEED_ANGLE, pressure=0.0):
    """Where the fed tiers hold their film full of oil, on their dimensionless grids.

    ``feed`` (:class:`stackup.film.heat.OilFeed`): its groove (arc, axial width) or its hole (a
    :data:`FEED_WIDTH` wide patch at the hole's angle, the hole's diameter long), at its supply pressure;
    None: a :data:`FEED_WIDTH` wide patch at ``angle`` [rad], :data:`FEED_LENGTH_SHARE` of the bearing's
    width long, at the gauge ``pressure`` [Pa]. The patch is centred on the mid-plane. ``journal_radius``,
    ``bearing_width`` [m] and ``unit_pressure`` (the pressure the grid's is a share of) [Pa] are one bearing's.

    Returns ``feed_arc`` (start, end) [rad], ``feed_half_width`` [journal radii] and ``feed_pressure`` [-].
    """
    if feed is None:
        arc, width = (angle - FEED_WIDTH / 2, angle + FEED_WIDTH / 2), FEED_LENGTH_SHARE * bearing_width
    elif feed.kind == "groove":
        arc, width, pressure = feed.groove_arc, feed.groove_width, feed.supply_pressure
    else:
        arc = (feed.hole_angle - FEED_WIDTH / 2, feed.hole_angle + FEED_WIDTH / 2)
        width, pressure = feed.hole_diameter, feed.supply_pressure
    return dict(feed_arc=arc, feed_half_width=width / 2 / journal_radius, feed_pressure=pressure / unit_pressure)
