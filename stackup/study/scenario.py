"""A study's scenario: the engine with its processes or its model inputs disturbed.

A scenario is plain data (a dict), so it travels in a study's parameters.
Process scenarios, what a plant would see:

``housing_shift``, ``journal_shift``
    Process mean shift of the housing bore or journal, in units of the
    process standard deviation [-].
``gauge_repeatability``
    Repeatability of every gauge (bore, journal, shell wall) [m].
``misalignment_scale``
    Factor on the bore coaxiality and journal run-out [-].

Model inputs, what the engine file assumes and nobody may have measured:

``housing_outer``
    Equivalent outer diameter of the housing ring [m] (its stiffness: the
    housing swell), instead of the engine file's ``housing_outer``; it must
    exceed the housing bore.
``crush_shift``
    Mean shift of the shells' crush height process, in units of its
    standard deviation [-].
``journal_temperature_excess``
    How much hotter the journal runs than its housing in service [K],
    instead of the engine file's.
``crank_stiffness_scale``
    Factor on the crankshaft's section inertias (its bending stiffness) [-].
``support_angular_scale``
    Factor on the supports' angular compliance [-], the bulkhead's and the
    bore ring's own (:meth:`stackup.crank.housing.Supports.scaled`; read where
    the journals' tilt is turned back at the supports, ``tilt_method``
    "equilibrium" or "coupled").

The declared sets a comparison runs are in :mod:`stackup.scenarios`.
"""

from __future__ import annotations

from dataclasses import replace

from .. import _validate as check
from ..engines import JOURNAL_TEMPERATURE_EXCESS

#: The keys a scenario may hold and what each must be (see the module docstring).
CHECKS = {"housing_shift": check.Finite(), "journal_shift": check.Finite(),
          "gauge_repeatability": check.Positive(zero=True), "misalignment_scale": check.Positive(zero=True),
          "housing_outer": check.Positive(), "crush_shift": check.Finite(),
          "journal_temperature_excess": JOURNAL_TEMPERATURE_EXCESS,
          "crank_stiffness_scale": check.InRange(0.01, 100.0), "support_angular_scale": check.Positive(zero=True)}
KEYS = tuple(CHECKS)


def checked(scenario):
    """``scenario`` with its values as floats, or a ValueError naming the key, the value and what is valid."""
    if not scenario:
        return {}
    unknown = set(scenario) - set(KEYS)
    if unknown:
        raise ValueError(f"scenario: unknown key(s) {sorted(unknown)}; valid: {', '.join(KEYS)}")
    return {key: float(CHECKS[key](f"scenario {key}", value)) for key, value in scenario.items()}


def _press_fit(engine, scenario):
    """The engine's press-fit data with the scenario's housing ring and journal temperature."""
    spec = engine.press_fit
    if "housing_outer" in scenario:
        outer = scenario["housing_outer"]
        if outer <= engine.housing_bore.hi:
            raise ValueError(f"scenario housing_outer: {outer!r} m is not above the housing bore's upper limit "
                             f"{engine.housing_bore.hi!r} m")
        spec = replace(spec, housing_outer=outer)
    if "journal_temperature_excess" in scenario:
        spec = replace(spec, journal_temperature_excess=scenario["journal_temperature_excess"])
    return spec


def apply(engine, scenario):
    """The engine with ``scenario`` applied (see module docstring); checks the scenario first."""
    scenario = checked(scenario)
    if not scenario:
        return engine
    housing, journal, shells, crank = engine.housing_bore, engine.journal_d, engine.shell_wall, engine.crank
    if "housing_shift" in scenario:
        housing = housing.shifted(scenario["housing_shift"] * housing.process.std)
    if "journal_shift" in scenario:
        journal = journal.shifted(scenario["journal_shift"] * journal.process.std)
    if "gauge_repeatability" in scenario:
        r = scenario["gauge_repeatability"]
        housing = replace(housing, gauge=replace(housing.gauge, repeatability=r))
        journal = replace(journal, gauge=replace(journal.gauge, repeatability=r))
        shells = replace(shells, gauge=replace(shells.gauge, repeatability=r))
    if "crush_shift" in scenario:
        shells = replace(shells, crush=shells.crush.shifted(scenario["crush_shift"] * shells.crush.process.std))
    if "misalignment_scale" in scenario and crank is not None:
        k = scenario["misalignment_scale"]
        crank = replace(crank, coaxiality=k * crank.coaxiality, journal_runout=k * crank.journal_runout)
    if "crank_stiffness_scale" in scenario and crank is not None:
        crank = replace(crank, ei=crank.ei * scenario["crank_stiffness_scale"])
    if "support_angular_scale" in scenario and crank is not None and crank.supports is not None:
        crank = replace(crank, supports=crank.supports.scaled(scenario["support_angular_scale"]))
    return replace(engine, housing_bore=housing, journal_d=journal, shell_wall=shells, crank=crank,
                   press_fit=_press_fit(engine, scenario))
