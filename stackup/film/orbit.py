r"""Dynamically loaded bearings over the engine cycle: the journal orbit, its film and pressure.

Tiers of :func:`orbit` (``method``), each a record in :mod:`stackup.film.registry` (the package's in
:mod:`stackup.film.catalogue`); their measured costs and errors are in
``reports/film_speed_vs_error.md`` and :func:`cheapest_cycle_tier` picks from them:

``"short"``, ``"finite"``, ``"reynolds"``
    Quasi-static: each crank angle as a steady load on that steady tier
    (:func:`stackup.film.min_film_thickness`, :mod:`stackup.film.quasi_static`): no squeeze film.
``"mobility"``
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
``"elrod-coarse"``
    The same equation as the reference (squeeze, mass-conserving cavitation in
    Elrod's universal variable, the feed held full, an imposed tilt) on a coarse
    grid with a Newton solve per adaptive time step (:mod:`stackup.film.elrod`):
    the film content the mobility tiers lack, at a fraction of the reference's cost.
``"reynolds-transient"``
    The reference: the finite-difference Reynolds equation with squeeze and
    mass-conserving (Elrod-Adams, JFO) cavitation, the journal centre integrated
    over the cycle (:mod:`stackup.film.transient`).

The names before issue 30 stay accepted, with a DeprecationWarning (:data:`ALIASES`, each tier's
:attr:`~stackup.film.registry.Tier.aliases`): ``"quasi-static"`` with ``steady_method``,
``"quasi-static-<steady tier>"``, ``"mobility-short"`` and the study's ``"transient"``.

Mobility tiers (:mod:`stackup.film.mobility`). In the engine-fixed frame, journal centre :math:`\mathbf x`
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
rule's step error is part of the tier's error measured in ``reports/film_speed_vs_error.md``). Per
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
solves it on its own mid-plane orbit (the short-bearing moment,
finite-corrected in the ``finite`` tiers), the mobility tiers marching the tilt
with its squeeze from angle to angle, the quasi-static ones holding it at each
angle; the
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

import functools
import tomllib
import warnings
from functools import lru_cache
from importlib import resources

import numpy as np

from .._validate import Finite, Integer, OneOf, Positive, one_of, renamed, validated
from . import catalogue  # noqa: F401 (registers the package's tiers)
from . import registry
from .journal import ECCENTRICITY_LIMIT, STATES, STATUS, Orbit, mobility_table  # noqa: F401 (API)
from .journal import within_one_cycle
from .mobility import PERIODIC  # noqa: F401 (API)

#: Cycle tiers :func:`orbit` runs (``method``), cheapest first; the study's film methods are the same names
#: (the registry's, read at each use).
METHODS = registry.Names()
#: Quasi-static tiers (a steady tier at each angle) and dynamic ones (an orbit integrated over cycles).
QUASI_STATIC = registry.Names(kind="quasi-static")
DYNAMIC = registry.Names(kind="dynamic")
#: Tiers that fill their film from the engine's oil feed (``feed``: groove or hole held at the supply pressure);
#: the others take the film as full wherever its pressure is positive.
FED = registry.Names(fed=True)
#: Deprecated names of the tiers -> their names (``"quasi-static"`` takes its tier from ``steady_method``).
ALIASES = registry.ALIASES
#: Measures of a cycle tier's error (:func:`cycle_tier_errors`).
MEASURES = ("h_min", "h_min_mean", "p_max", "p_max_mean", "friction_power")


def canonical_tier(method, steady_method=None, *, stacklevel=2):
    """The tier's name for one of its deprecated names (:data:`ALIASES`), with a DeprecationWarning; else ``method``.

    ``"quasi-static"`` names the steady tier ``steady_method`` (default ``"finite"``).
    """
    if method == "quasi-static":
        tier = "finite" if steady_method is None else steady_method
        warnings.warn(f"method='quasi-static' with steady_method={tier!r} is deprecated; use method={tier!r}",
                      DeprecationWarning, stacklevel=stacklevel + 1)
        return tier
    if steady_method is not None:
        warnings.warn("steady_method= is deprecated and read only with method='quasi-static'; name the steady tier "
                      "as the method", DeprecationWarning, stacklevel=stacklevel + 1)
    if method in ALIASES:
        warnings.warn(f"method={method!r} is deprecated; use {ALIASES[method]!r} (same tier)", DeprecationWarning,
                      stacklevel=stacklevel + 1)
        return ALIASES[method]
    return method


def tier_names(wrapped_by=0):
    """Decorator: accept the deprecated tier names in ``method`` (and ``steady_method``) (:func:`canonical_tier`).

    ``wrapped_by``: decorators applied over this one (the warning names the caller's line).
    """
    def decorate(function):
        @functools.wraps(function)
        def call(*args, **kwargs):
            method = kwargs.get("method")
            if "steady_method" in kwargs or method == "quasi-static" or method in ALIASES:
                kwargs["method"] = canonical_tier(kwargs.get("method", "mobility"), kwargs.pop("steady_method", None),
                                                  stacklevel=2 + wrapped_by)
            return function(*args, **kwargs)

        return call

    return decorate


@lru_cache(maxsize=1)
def cycle_tier_errors():
    """Measured cost and film error of each cycle tier against ``reynolds-transient``, by tier name.

    From ``stackup/data/film_cycle_errors.toml``, written by
    ``studies/film_speed_vs_error.py`` on the built-in engines' main bearings: per
    tier ``seconds`` (one bearing's cycle on one core) and the largest relative
    error of the cycle minimum (``h_min``) and cycle mean (``h_min_mean``) of the
    minimum film, the peak pressure's maximum and mean and the mean friction
    power, against the mass-conserving reference, and in ``"swift-stieber"``
    against the same reference with the Reynolds cavitation condition. Each
    registered tier reads its row (:attr:`~stackup.film.registry.Tier.error_row`);
    a tier without one is not measured.
    """
    with open(resources.files("stackup") / "data" / "film_cycle_errors.toml", "rb") as f:
        rows = tomllib.load(f)["tiers"]
    return {tier.name: rows[tier.error_row] for tier in registry.tiers() if tier.error_row in rows}


def _each_measure(field, names):
    for name in names:
        one_of(field, name, MEASURES)
    return names


@validated(max_error=Positive(zero=True), measures=_each_measure,
           reference=OneOf(("mass-conserving", "swift-stieber")))
def cheapest_cycle_tier(max_error, *, measures=("h_min", "h_min_mean"), reference="mass-conserving", tiers=None):
    """The cheapest cycle tier whose measured errors (``measures``) are all within ``max_error`` [-].

    Like :func:`stackup.film.cheapest_tier` for the steady tiers. ``reference``:
    ``"mass-conserving"`` (Elrod-Adams, the physical reference) or
    ``"swift-stieber"`` (the same transient tier with the Reynolds condition, the
    cavitation model of every cheaper tier: it measures their numerical error
    only). ``tiers``: the tiers to choose from (default every measured one). Falls
    back to the reference (``reynolds-transient``, :func:`~stackup.film.registry.reference_tier`)
    when no cheaper tier qualifies.
    """
    max_error = float(max_error)
    errors = cycle_tier_errors()
    # a tier not measured against the Swift-Stieber run (it has no such table) is not chosen against it
    ranked = sorted((t for t in errors if (tiers is None or t in tiers)
                     and (reference == "mass-conserving" or "swift-stieber" in errors[t])),
                    key=lambda t: errors[t]["seconds"])

    def error(tier, name):
        table = errors[tier] if reference == "mass-conserving" else errors[tier]["swift-stieber"]
        return table[name]

    return next((t for t in ranked if all(error(t, m) <= max_error for m in measures)), registry.reference_tier().name)


def one_cycle(loads_name):
    """Relation of :func:`~stackup._validate.validated`: loads ``loads_name`` (..., angles, 2) over ``crank_angle``
    (angles,) that increase over less than a cycle."""
    def relation(values):
        loads, angle = values[loads_name], values["crank_angle"]
        if angle.ndim != 1 or loads.ndim < 2 or loads.shape[-1] != 2 or loads.shape[-2] != angle.size:
            raise ValueError(f"{loads_name}: shape {loads.shape} is not valid; expected (..., {angle.size}, 2)")
        within_one_cycle(angle)

    return relation


def compliance_with_tilt(values):
    """Relation: a tilt compliance comes with the free tilt it turns back."""
    if values["tilt_compliance"] is not None and values["tilt"] is None:
        raise ValueError("tilt_compliance: given without tilt (the journal's free slope)")


def tier_options(method, options, tilt_compliance=None):
    """A ValueError unless ``options`` (a dict) are options of the tier ``method`` (its record's
    :attr:`~stackup.film.registry.Tier.options`), each as the tier checks it, and the tier balances the tilt
    where a ``tilt_compliance`` is given."""
    tier = registry.tier(method)
    for name, value in options.items():
        if name not in tier.options:
            taken = ", ".join(tier.options) or "none"
            raise ValueError(f"{name}: not an option of method={method!r} (its options: {taken})")
        if value is not None and tier.options[name] is not None:
            tier.options[name](name, value)
    if tier.imposed_tilt and tilt_compliance is not None:
        turned = ", ".join(repr(t.name) for t in registry.tiers() if t.kind == "dynamic" and not t.imposed_tilt)
        raise ValueError(f"tilt_compliance: not valid with method={method!r}, which takes the tilt as imposed "
                         f"(give the tilt in the film, or use one of {turned})")


def _own_options(values):
    """Relation: the tier's own options (``**options`` of :func:`orbit`), checked as its record declares them."""
    tier_options(values["method"], values["options"], values["tilt_compliance"])


@renamed(diameter="journal_d", length="bearing_width")
@tier_names(wrapped_by=1)
@validated(method=OneOf(METHODS), load_history=Finite(), crank_angle=Finite(), journal_d=Positive(),
           bearing_width=Positive(), clearance=Positive(), viscosity=Positive(), speed=Positive(),
           cycles=Integer(minimum=1), tilt=Finite(), tilt_compliance=Positive(zero=True), start=Finite(),
           relations=(one_cycle("load_history"), compliance_with_tilt, _own_options))
def orbit(load_history, crank_angle, *, journal_d, bearing_width, clearance, viscosity, speed, method="mobility",
          tilt=None, tilt_compliance=None, cycles=None, start=None, **options):
    """Film over the engine cycle of dynamically loaded bearings.

    Parameters
    ----------
    load_history : array_like (..., angles, 2)
        Load on each bearing over one cycle [N] (force of the journal on the
        bearing, engine-fixed frame).
    crank_angle : array_like (angles,)
        Crank angles [deg], increasing, covering one cycle (720 deg).
    journal_d, bearing_width, clearance : float or array_like (...)
        Journal diameter, bearing width, diametral clearance [m].
    viscosity : float or array_like (...)
        Effective oil viscosity [Pa s].
    speed : float or array_like (...)
        Journal angular speed [rad/s] (positive: from load axis 0 towards axis 1).
    method : str
        A tier of :data:`METHODS` (deprecated names: :data:`ALIASES`); its record in
        :mod:`stackup.film.registry` runs it.
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
        (:mod:`stackup.film.tilt`); not valid with a tier that takes the tilt as imposed.
    cycles : int, optional
        Most cycles a dynamic tier integrates to reach a periodic orbit
        (default the tier's, :attr:`~stackup.film.registry.Tier.cycles`: 20 for the mobility
        tiers, 8 for ``"elrod-coarse"`` and ``"reynolds-transient"``).
    start : array_like (..., 2), optional
        Journal centre at the first crank angle [m] to start a dynamic tier
        from (e.g. the ``position[..., 0, :]`` of a coarser orbit); default the
        bearing centre (the mobility tiers) or the ``mobility-finite`` orbit's
        (the transient tier). A start near the periodic orbit saves laps; the
        orbit reached is the same.
    **options
        The tier's own options (:attr:`~stackup.film.registry.Tier.options`), e.g. the oil
        feed and the grid of ``"reynolds-transient"`` (:func:`stackup.film.transient.transient_orbit`)
        and of ``"elrod-coarse"`` (:func:`stackup.film.elrod.elrod_orbit`).

    Returns
    -------
    Orbit
    """
    loads = np.asarray(load_history, dtype=float)
    lead = loads.shape[:-2]
    geometry = {name: np.broadcast_to(np.asarray(value, dtype=float), lead) for name, value in (
        ("journal_radius", np.asarray(journal_d, dtype=float) / 2), ("bearing_width", bearing_width),
        ("radial_clearance", np.asarray(clearance, dtype=float) / 2), ("viscosity", viscosity), ("speed", speed))}
    if tilt is not None:
        tilt = np.broadcast_to(np.asarray(tilt, dtype=float), loads.shape)
    if tilt_compliance is not None:
        tilt_compliance = np.broadcast_to(np.asarray(tilt_compliance, dtype=float), (*lead, 2))
    if start is not None:
        start = np.broadcast_to(np.asarray(start, dtype=float), (*lead, 2))
    tier = registry.tier(method)
    inputs = dict(tilt=tilt, cycles=tier.cycles if cycles is None else cycles, start=start, **options)
    if not tier.imposed_tilt:
        inputs["tilt_compliance"] = tilt_compliance
    return tier.run(loads, np.asarray(crank_angle, dtype=float), **geometry, **inputs)
