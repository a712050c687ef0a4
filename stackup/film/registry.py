"""The film tiers, one record each, in one registry that dispatch, the film stage, the check and the report read.

After xarray's backend entry points (``xarray/backends/plugins.py``, each backend's ``BackendEntrypoint``):
a tier is a frozen :class:`Tier` record (its name, kind, the function that runs it, its own options,
default cycles, notes, error row, deprecated names, whether it checks the others) and :func:`register`
puts it here under its name. The package's tiers are registered by :mod:`stackup.film.catalogue`,
cheapest first; adding one is its module and its record there, and nothing else names it. A tier
registered from outside (a test, a study) is :func:`registered` for a block and gone after it.

The names are read at each use (:class:`Names`, :data:`ALIASES`, :data:`NOTES`): a check written as
``OneOf(Names())`` at import accepts a tier registered later.
"""

from __future__ import annotations

import contextlib
import inspect
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

#: Kinds of tiers: a steady film at each crank angle (no squeeze), or the journal's orbit integrated over cycles.
KINDS = ("quasi-static", "dynamic")
#: How a tier's side models (the tilt's moment, the quasi-static heat balance, the crankshaft's support moments)
#: treat the bearing's length: Ocvirk's short bearing, or its correction tabulated from the Reynolds tier.
LENGTH_MODELS = ("short", "finite")
#: What the dispatcher gives every tier's function besides the loads and crank angles
#: (:func:`stackup.film.orbit.orbit`'s inputs broadcast to the loads' leading shape, radial, SI).
INPUTS = ("journal_radius", "bearing_width", "radial_clearance", "viscosity", "speed", "tilt", "tilt_compliance",
          "cycles", "start")


@dataclass(frozen=True)
class Tier:
    """One film tier over the engine cycle.

    Attributes
    ----------
    name : str
        The tier's one name, in every layer (``method=`` of :func:`stackup.film.orbit.orbit`, a study's
        ``film_method``, the dataset, the report).
    kind : {"quasi-static", "dynamic"}
        A steady film at each crank angle, or an orbit integrated over cycles (:data:`KINDS`).
    run : callable
        The orbit: ``run(loads, crank_angle, *, journal_radius, bearing_width, radial_clearance, viscosity,
        speed, tilt, tilt_compliance, cycles, start, **options)`` -> :class:`stackup.film.journal.Orbit`, loads
        (..., angles, 2) [N], crank angles (angles,) [deg], the rest as :func:`stackup.film.orbit.orbit` takes
        them, broadcast to the loads' leading shape, radial, SI (``tilt_compliance`` left out where
        ``imposed_tilt``).
    notes : str
        What the tier solves and leaves out, in one sentence without figures: the report's methods section
        prints it (measured errors and costs live in ``reports/film_speed_vs_error.md``).
    length_model : {"short", "finite"}
        How the side models stand in for the tier's film (:data:`LENGTH_MODELS`).
    steady : callable, optional
        A quasi-static tier's film under a steady load, ``steady(load, *, journal_radius, bearing_width,
        radial_clearance, viscosity, speed)`` -> :class:`stackup.film.steady.Film` on broadcast inputs
        (:func:`stackup.film.min_film_thickness` runs it).
    options : mapping
        The tier's own keyword options (beyond :data:`INPUTS`) and the check of each (None: any value),
        e.g. from its function's declared checks (:func:`own_options`).
    cycles : int, optional
        Most cycles a dynamic tier integrates when not told (None for a quasi-static tier).
    fed : bool
        The tier fills its film from the engine's oil feed (its ``feed`` option: groove or hole held at the
        supply pressure); the others take the film as full wherever its pressure is positive.
    imposed_tilt : bool
        The tier takes the journal's tilt as imposed: a tilt compliance is refused where a call enters the
        package, and not handed to ``run``.
    error_row : str, optional
        The tier's key in ``stackup/data/film_cycle_errors.toml`` (its measured cost and errors against the
        reference; None: not measured).
    aliases : tuple of str
        Deprecated names that still select the tier, with a DeprecationWarning.
    check : bool
        The tier that checks a study's film on some of its engines (multi-fidelity); one tier at most.
    reference : bool
        The tier the others' cycle errors are measured against; one tier at most.
    """

    name: str
    kind: str
    run: Callable
    notes: str
    length_model: str
    steady: Callable | None = None
    options: Mapping = field(default_factory=dict)
    cycles: int | None = None
    fed: bool = False
    imposed_tilt: bool = False
    error_row: str | None = None
    aliases: tuple = ()
    check: bool = False
    reference: bool = False

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind: {self.kind!r} is not one of {', '.join(map(repr, KINDS))}")
        if self.length_model not in LENGTH_MODELS:
            raise ValueError(f"length_model: {self.length_model!r} is not one of "
                             f"{', '.join(map(repr, LENGTH_MODELS))}")
        if (self.kind == "dynamic") != (self.cycles is not None):
            raise ValueError(f"cycles: {self.cycles!r} is not valid for a {self.kind} tier (a dynamic tier has its "
                             "default cycles, a quasi-static one none)")
        if self.kind == "quasi-static" and self.steady is None:
            raise ValueError(f"steady: a quasi-static tier ({self.name!r}) is a steady film at each angle; give it")
        clash = set(self.options) & set(INPUTS)
        if clash:
            raise ValueError(f"options: {sorted(clash)} are inputs of every tier, not options of {self.name!r}")


_TIERS: dict[str, Tier] = {}


def register(tier):
    """Add ``tier`` (a :class:`Tier`) to the registry, after those registered before it; returns it."""
    taken = set(_TIERS) | set(ALIASES)
    for name in (tier.name, *tier.aliases):
        if name in taken:
            raise ValueError(f"name: {name!r} already names a film tier")
    for flag in ("check", "reference"):
        held = [t.name for t in _TIERS.values() if getattr(t, flag)]
        if getattr(tier, flag) and held:
            raise ValueError(f"{flag}: {held[0]!r} is already the {flag} tier")
    _TIERS[tier.name] = tier
    return tier


def unregister(name):
    """Remove the tier ``name`` from the registry; returns its record."""
    return _TIERS.pop(name)


@contextlib.contextmanager
def registered(tier):
    """Within this block ``tier`` is registered; after it, whatever happened, it is not."""
    register(tier)
    try:
        yield tier
    finally:
        unregister(tier.name)


def tier(name):
    """The record of the tier ``name`` (its current name; a KeyError for any other)."""
    return _TIERS[name]


def find(name):
    """The record of the tier ``name`` or of the tier it is a deprecated name of; None for any other name."""
    return _TIERS.get(ALIASES.get(name, name))


def tiers():
    """The registered tiers' records, in the order they were registered (the package's: cheapest first)."""
    return tuple(_TIERS.values())


def _flagged(flag):
    found = [t for t in _TIERS.values() if getattr(t, flag)]
    if not found:
        raise LookupError(f"no film tier is registered as the {flag} tier")
    return found[0]


def check_tier():
    """The record of the tier that checks a study's film (:attr:`Tier.check`)."""
    return _flagged("check")


def reference_tier():
    """The record of the tier the others' cycle errors are measured against (:attr:`Tier.reference`)."""
    return _flagged("reference")


def own_options(function):
    """A tier function's own keyword options (its keyword parameters beyond :data:`INPUTS`) and the check each
    declares with :func:`~stackup._validate.validated` (None where it declares none)."""
    declared = getattr(function, "constraints", {})
    return {name: declared.get(name) for name, p in inspect.signature(function).parameters.items()
            if p.kind == p.KEYWORD_ONLY and name not in INPUTS}


class _Live:
    """A read-only container made from the registry at each use by ``make()``."""

    def __init__(self, make):
        self._make = make

    def __getitem__(self, key):
        return self._make()[key]

    def __iter__(self):
        return iter(self._make())

    def __len__(self):
        return len(self._make())

    def __repr__(self):
        return repr(self._make())


class Names(_Live, Sequence):
    """The registered tiers' names, in registration order, read at each use; optionally only those of one
    ``kind``, only the ``fed`` (or unfed) ones, only those with a ``steady`` film, and then the names ``also``.

    Equal to any sequence of the same names (``Names() == ("short", ...)``).
    """

    def __init__(self, *, kind=None, fed=None, steady=None, also=()):
        def names():
            return tuple(t.name for t in _TIERS.values()
                         if (kind is None or t.kind == kind) and (fed is None or t.fed == fed)
                         and (steady is None or (t.steady is not None) == steady)) + tuple(also)

        super().__init__(names)

    def __eq__(self, other):
        return isinstance(other, Sequence) and not isinstance(other, str) and tuple(self) == tuple(other)

    __hash__ = None


class _Table(_Live, Mapping):
    """A read-only mapping made from the registry at each use."""


#: Deprecated names of the tiers -> their names (:attr:`Tier.aliases`).
ALIASES = _Table(lambda: {alias: t.name for t in _TIERS.values() for alias in t.aliases})
#: Each tier's notes by name (:attr:`Tier.notes`), the sentence a report's methods section prints.
NOTES = _Table(lambda: {t.name: t.notes for t in _TIERS.values()})
