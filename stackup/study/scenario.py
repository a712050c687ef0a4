"""A study's scenario: the engine with its processes disturbed as a plant would see them.

A scenario is plain data (a dict), so it travels in a study's parameters:

``housing_shift``, ``journal_shift``
    Process mean shift of the housing bore or journal, in units of the
    process standard deviation [-].
``gauge_repeatability``
    Repeatability of every gauge (bore, journal, shell wall) [m].
``misalignment_scale``
    Factor on the bore coaxiality and journal run-out [-].

The declared sets a comparison runs are in :mod:`stackup.scenarios`.
"""

from __future__ import annotations

from dataclasses import replace

from .. import _validate as check

KEYS = ("housing_shift", "journal_shift", "gauge_repeatability", "misalignment_scale")


def apply(engine, scenario):
    """The engine with ``scenario`` applied (see module docstring); validates the keys."""
    if not scenario:
        return engine
    unknown = set(scenario) - set(KEYS)
    if unknown:
        raise ValueError(f"scenario: unknown key(s) {sorted(unknown)}; valid: {', '.join(KEYS)}")
    housing, journal, shells, crank = engine.housing_bore, engine.journal_d, engine.shell_wall, engine.crank
    if "housing_shift" in scenario:
        housing = housing.shifted(float(check.finite("scenario housing_shift", scenario["housing_shift"]))
                                  * housing.process.std)
    if "journal_shift" in scenario:
        journal = journal.shifted(float(check.finite("scenario journal_shift", scenario["journal_shift"]))
                                  * journal.process.std)
    if "gauge_repeatability" in scenario:
        r = float(check.positive("scenario gauge_repeatability", scenario["gauge_repeatability"], allow_zero=True))
        housing = replace(housing, gauge=replace(housing.gauge, repeatability=r))
        journal = replace(journal, gauge=replace(journal.gauge, repeatability=r))
        shells = replace(shells, gauge=replace(shells.gauge, repeatability=r))
    if "misalignment_scale" in scenario and crank is not None:
        k = float(check.positive("scenario misalignment_scale", scenario["misalignment_scale"], allow_zero=True))
        crank = replace(crank, coaxiality=k * crank.coaxiality, journal_runout=k * crank.journal_runout)
    return replace(engine, housing_bore=housing, journal_d=journal, shell_wall=shells, crank=crank)
