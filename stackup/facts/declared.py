"""The attributes of a study dataset that the facts read, each parsed in one place with the keys it expects.

A study writes its parameters and the engine data a report quotes into the
dataset's attributes (:func:`stackup.study.sinks.attributes`), several as
JSON. Each is read here once, into a frozen record whose fields name the
keys it needs; a missing attribute or key is a :class:`ValueError` naming
the dataset attribute, not a ``KeyError`` deep in a report.
"""

from __future__ import annotations

import json
from dataclasses import MISSING, dataclass, fields, replace

from ..scenarios import is_assumed
from ..scenarios import kind as scenario_kind


def _missing(attribute, what):
    return ValueError(f"dataset attribute {attribute!r}: {what} (not a dataset a stackup.Study of this version "
                      "wrote)")


def plain(ds, name, default=MISSING):
    """The dataset attribute ``name`` as stored; a missing one is ``default``, or an error without one."""
    if name in ds.attrs:
        return ds.attrs[name]
    if default is MISSING:
        raise _missing(name, "missing")
    return default


def parsed(ds, name, *, required=True):
    """The JSON dataset attribute ``name`` as Python data; None if it is absent and not ``required``."""
    if name not in ds.attrs:
        if required:
            raise _missing(name, "missing")
        return None
    try:
        return json.loads(ds.attrs[name])
    except (TypeError, ValueError) as error:
        raise _missing(name, f"not JSON ({error})") from None


def _record(cls, attribute, data, where=""):
    """A record of ``cls`` from the mapping ``data``: its fields are the keys expected, the rest are left."""
    if not isinstance(data, dict):
        raise _missing(attribute, f"{where or 'the value'} is not a mapping")
    required = [f.name for f in fields(cls) if f.default is MISSING]
    absent = [name for name in required if name not in data]
    if absent:
        raise _missing(attribute, f"no key {', '.join(repr(where + n) for n in absent)} (it needs "
                                  f"{', '.join(where + n for n in required)})")
    return cls(**{f.name: data[f.name] for f in fields(cls) if f.name in data})


class _Attribute:
    """A record of the JSON dataset attribute ``ATTRIBUTE``; an ``OPTIONAL`` one may be absent (then None)."""

    ATTRIBUTE, OPTIONAL = "", False

    @classmethod
    def of(cls, ds):
        data = parsed(ds, cls.ATTRIBUTE, required=not cls.OPTIONAL)
        return None if data is None else _record(cls, cls.ATTRIBUTE, data)


@dataclass(frozen=True)
class StudyParameters:
    """The ``study`` attribute: the parameters that reproduce the study (``items``, in their order)."""

    n_engines: int
    schemes: list
    pilot_engines: int
    crank_angle_step: float
    fit_method: str
    crank_method: str
    mechanics_engines: object = None
    target_error: object = None
    life_film: object = None
    window: object = None
    items: tuple = ()

    @classmethod
    def of(cls, ds):
        data = parsed(ds, "study")
        record = _record(cls, "study", data)
        return replace(record, items=tuple(data.items()), life_film=data.get("life_film") or "cycle-mean")

    @property
    def scenario(self):
        """The scenario the study ran (:mod:`stackup.study.scenario`), {} for the study itself."""
        return dict(self.items).get("scenario") or {}

    @property
    def tilt_method(self):
        """The journal's tilt method of the study ("equilibrium" for a study saved before the key)."""
        return dict(self.items).get("tilt_method") or "equilibrium"


@dataclass(frozen=True)
class PressFit(_Attribute):
    """The ``press_fit`` attribute: the engine's press-fit data the methods quote [m, Pa, degC]."""

    ATTRIBUTE = "press_fit"
    housing_material: str
    housing_outer: float
    shell_material: str
    length: float
    check_bore: float
    check_stress: float
    assembly_temperature: float
    temperature: float
    journal_temperature_excess: float = 0.0   # a dataset before the key: journal and housing at one temperature
    journal_temperature_source: str = ""
    housing_outer_interval: object = None


@dataclass(frozen=True)
class Dimension:
    """One sampled dimension of ``engine_processes`` [m]."""

    limits_m: list
    distribution: str
    cpk: float
    std_m: float
    shared: float
    gauge_repeatability_m: float
    gauge_resolution_m: float


@dataclass(frozen=True)
class ShellSupply:
    """The shell supply of ``engine_processes`` [m]."""

    supply: str
    lot_engines: int
    surplus: float
    sigma_m: float
    gauge_repeatability_m: float


@dataclass(frozen=True)
class CrankData:
    """The crankshaft and oil data of ``engine_processes`` (an engine with a ``[crank]`` section)."""

    speed_rpm: float
    coaxiality_m: float
    journal_runout_m: float
    oil: str
    oil_supply_temperature_degC: float  # noqa: N815 (the attribute's key)


@dataclass(frozen=True)
class Processes:
    """The ``engine_processes`` attribute: the sampled processes, the shell supply and the crankshaft's data."""

    housing_bore: Dimension
    journal_d: Dimension
    shell_wall: ShellSupply
    crush_height: Dimension
    crank: CrankData = None

    @classmethod
    def of(cls, ds):
        data = parsed(ds, "engine_processes")
        top = _record(cls, "engine_processes", data)
        crank = data.get("crank")
        return cls(*(_record(Dimension, "engine_processes", data[key], f"{key}.")
                     for key in ("housing_bore", "journal_d")),
                   _record(ShellSupply, "engine_processes", top.shell_wall, "shell_wall."),
                   _record(Dimension, "engine_processes", top.crush_height, "crush_height."),
                   None if crank is None else _record(CrankData, "engine_processes", crank, "crank."))


@dataclass(frozen=True)
class Wear(_Attribute):
    """The ``wear`` attribute: roughness, critical film and Levanov's wear constants [m, m/s] with sources."""

    ATTRIBUTE = "wear"
    critical_film_m: float
    journal_rz_m: float
    shell_rz_m: float
    wear_limit_m: float
    wear_rate_m_per_s: float
    roughness_source: str
    wear_source: str
    method1_wear_limit_m: float = None  # absent from datasets written before method 1 had its own scale

    @property
    def method1_limit_m(self):
        """Method 1's limiting wear [m] (the method-2 one in datasets that did not distinguish them)."""
        return self.wear_limit_m if self.method1_wear_limit_m is None else self.method1_wear_limit_m


@dataclass(frozen=True)
class FilmErrors(_Attribute):
    """The ``film_method_errors`` attribute: the film tier's largest errors against the transient reference.

    Shares of the reference [-] on the cycle-minimum film and on its cycle mean, and the orbit's time per
    bearing-cycle [s], as measured for the built-in engines (reports/film_speed_vs_error.md).
    """

    ATTRIBUTE, OPTIONAL = "film_method_errors", True
    h_min: float
    h_min_mean: float
    seconds: float


@dataclass(frozen=True)
class DesignRecord(_Attribute):
    """The ``design`` attribute (:func:`stackup.comparison.design_record`): what the designer found."""

    ATTRIBUTE, OPTIONAL = "design", True
    start: str
    start_text: str
    evaluations: int
    seconds: float
    outside: dict
    start_outside: dict
    notes: list


@dataclass(frozen=True)
class Sources:
    """Where the engine's data come from: plain-text attributes, whitespace folded (empty when not given); the
    engine's own source is in its file (the dataset's ``input_files``)."""

    press_fit_limits: str
    crush_height: str
    clearance_window: str
    schemes: dict
    minimum_clearance: str = ""
    cold_start: str = ""

    @classmethod
    def of(cls, ds):
        def text(name):
            return " ".join(str(ds.attrs.get(name, "")).split())

        return cls(text("press_fit_limits_source"), text("crush_height_source"), text("clearance_window_source"),
                   parsed(ds, "scheme_sources"), text("minimum_clearance_source"), text("cold_start_source"))


@dataclass(frozen=True)
class ScenarioAbout:
    """What one scenario of a comparison is, from its dataset's attributes (:func:`stackup.compare` writes them).

    ``kind`` is "process" (what a plant would see) or "model" (a model input over its declared range); a model
    scenario names its ``input``, the range's ``source`` (beginning "assumed" where nobody measured it) and what
    to ``measure`` to narrow it. A scenario dataset without these attributes is classed by its keys
    (:func:`stackup.scenarios.kind`).
    """

    kind: str
    input: str = ""
    source: str = ""
    measure: str = ""

    @classmethod
    def of(cls, ds):
        from_keys = scenario_kind(StudyParameters.of(ds).scenario)
        return cls(str(ds.attrs.get("scenario_kind", from_keys)), str(ds.attrs.get("scenario_input", "")),
                   str(ds.attrs.get("scenario_source", "")), str(ds.attrs.get("scenario_measure", "")))

    @property
    def assumed(self):
        """The range is an assumption (as :attr:`stackup.scenarios.Uncertainty.assumed` reads its source)."""
        return is_assumed(self.source)
