"""Engine definitions as data: the main-bearing parts and how they are made.

An engine file (TOML, lengths in mm) names its number of main bearings and,
per dimension, the drawing limits, the process, the gauge and the share of
variance common to one block or crankshaft (journals also their form error and
how it is read, housing bores their bolt-tension scatter). ``[press_fit]``
holds the housing ring, materials and shell lining, the checking block, the
temperatures the fit is checked at (``cold_temperature``,
``assembly_temperature``, ``temperature`` for the clearance,
``hot_temperature``), how much hotter the journal runs in service
(``journal_temperature_excess`` [K] with ``journal_temperature_source``), an
interval of the housing's outer diameter measured by fitting tests
(``housing_outer_interval``, optional) and the source of the crush height;
``[press_fit.limits]`` the design limits with their source; ``[targets]`` the
operating-clearance window (absolute, or ``relative_clearance`` C/D of the
journal) with its source; ``[crank]`` the crank train and its loads, an
inline engine or a V with two side-by-side rods on each pin
(``layout = "V"``, ``bank_angle``, and the maker's cylinder ``numbering`` and
``first_bank``). Built-in engines ship in ``stackup/data/engines``;
a user's file works the same way, by path or by name from a folder named in
the ``STACKUP_ENGINE_PATH`` environment variable (folders separated as in
``PATH``; a user's file replaces a built-in one of the same name).
"""

from __future__ import annotations

import io
import math
import os
import warnings
from dataclasses import asdict, dataclass, replace

import numpy as np
from importlib import resources
from pathlib import Path

from . import _validate as check
from . import materials
from .crank import BellakhdharLaw
from .crank.housing import Supports, bulkhead_compliance, ring_tilt_compliance
from .crank.law import stiffness as law_stiffness
from .film import oil as film_oil
from .film.heat import FEEDS, OilFeed
from .fit import CHECK_STRESS, TEMPERATURE
from .life import LEVANOV_2015, METHOD1_SCALE
from .loads import (BANKS, NUMBERINGS, Combustion, Kinematics, check_firing_order, cylinder_throw_angles,
                    firing_offsets, pin_loads, read_pressure_trace, v_cylinders)
from .parts import ShellSupply
from ._files import Table, did_you_mean, locations, parse_toml, read_toml, units_of
from .tolerances import Dimension, form_from_spec, gauge_from_spec, process_from_spec


@dataclass(frozen=True)
class PressFitLimits:
    """Design limits of the press fit, with their source.

    Attributes
    ----------
    contact_pressure_min : float
        Least contact pressure between shell backs and housing bore at any
        declared temperature [Pa] (no spinning, no fretting, heat transfer).
    shell_stress_max : float
        Largest steel-equivalent compression of the shell wall at any
        declared temperature [Pa] (no inward protrusion at the joint faces).
    source : str
    """

    contact_pressure_min: float
    shell_stress_max: float
    source: str


#: Limits of an engine file without ``[press_fit.limits]``: the lenient end
#: of Kopeliovich's pressure range and the middle of his stress range.
KOPELIOVICH_LIMITS = PressFitLimits(
    contact_pressure_min=8e6, shell_stress_max=450e6,
    source="Kopeliovich, Crush height of engine bearings, sec. 2: contact pressure commonly not less than "
           "8-10 MPa; compression stress not above 400-500 MPa depending on the application (defaults: 8 MPa, "
           "450 MPa)")


#: Cold start of an engine file without ``press_fit.cold_temperature`` [degC], and its source.
COLD_START = -25.0
COLD_START_SOURCE = ("assumed: SAE J300's cold-cranking temperature of a 10W engine oil (5W: -30 degC, 0W: "
                     "-35 degC); press_fit.cold_temperature sets the engine's own")
#: Least diametral clearance a bearing may have at assembly or a cold start [m], and its source: the smallest
#: standard main-bearing oil clearance found in a maker's service data, for a light-alloy block.
MINIMUM_CLEARANCE = 1e-6
MINIMUM_CLEARANCE_SOURCE = ("Nissan VK45DE (aluminium block) service data: main bearing oil clearance measured "
                            "at assembly, standard 0.001-0.011 mm at journals 1 and 5, 0.007-0.017 mm at 2-4 "
                            "(Ford 3.4 L SHO V8: 0.010-0.031 mm; Toyota 2ZR-FE: 0.016-0.039 mm): the smallest "
                            "clearance a maker accepts; applied at the cold start too (assumed)")


@dataclass(frozen=True)
class PressFitSpec:
    """How the shells sit in the housing, at which temperatures it is checked, and against which limits [SI].

    :meth:`kwargs` gives the keyword arguments of :func:`stackup.fit.press_fit`
    at the operating temperature (the clearance), :meth:`extremes_kwargs`
    those of :func:`stackup.fit.press_fit_extremes` over :attr:`temperatures`
    (the stress and pressure checks), :meth:`record` the same data in the
    engine file's words (a dataset's ``press_fit`` attribute).
    """

    housing_outer: float
    housing_material: str
    shell_material: str
    journal_material: str
    bearing_width: float  # axial width of the shells [m] (the file's press_fit.length)
    check_bore: float
    check_stress: float
    assembly_temperature: float
    temperature: float  # operating temperature: the clearance [degC]
    lining_thickness: float = 0.0
    lining_material: str | None = None
    cold_temperature: float | None = None  # coldest state checked (cold start) [degC]; None: the assembly's
    hot_temperature: float | None = None  # hottest state checked [degC]; None: the operating temperature
    limits: PressFitLimits = KOPELIOVICH_LIMITS
    crush_source: str = ""
    #: How much hotter the journal runs than the housing around it in service [K] (the file's
    #: ``journal_temperature_excess``; 0: journal and housing at ``temperature``), and where that comes from
    #: (``journal_temperature_source``; empty: not given, an assumption).
    journal_temperature_excess: float = 0.0
    journal_temperature_source: str = ""
    #: Interval of the housing's equivalent outer diameter measured by fitting tests [m]
    #: (``housing_outer_interval``, e.g. from :func:`stackup.measure.calibrate_housing`; the upper end may be
    #: ``inf``, a housing as stiff as a rigid ring); None: not measured, ``housing_outer`` is an assumption.
    housing_outer_interval: tuple | None = None

    _FIT = ("housing_outer", "housing_material", "shell_material", "journal_material", "bearing_width",
            "check_bore", "check_stress", "assembly_temperature", "lining_thickness", "lining_material")
    #: Names of the file's keys where they differ from the fit functions' arguments.
    _FILE_KEYS = {"bearing_width": "length"}

    @property
    def journal_temperature(self):
        """The journal's temperature in service [degC]: the operating temperature plus its excess."""
        return self.temperature + self.journal_temperature_excess

    def kwargs(self):
        """Keyword arguments of :func:`stackup.fit.press_fit` at the operating temperature (the journal at its own)."""
        return {**{name: getattr(self, name) for name in self._FIT}, "temperature": self.temperature,
                "journal_temperature": self.journal_temperature}

    def record(self):
        """The press-fit data under the engine file's key names (``length`` for the width), as datasets keep them."""
        fit = {self._FILE_KEYS.get(name, name): value for name, value in self.kwargs().items()
               if name != "journal_temperature"}
        interval = None if self.housing_outer_interval is None else list(self.housing_outer_interval)
        return {**fit, "journal_temperature_excess": self.journal_temperature_excess,
                "journal_temperature_source": self.journal_temperature_source, "housing_outer_interval": interval}

    @property
    def length(self):
        """Deprecated name of :attr:`bearing_width` [m]."""
        warnings.warn("PressFitSpec.length is deprecated; use bearing_width (same value)", DeprecationWarning,
                      stacklevel=2)
        return self.bearing_width

    @property
    def cold_start_temperature(self):
        """The coldest temperature the bearings are assembled or started at [degC]: ``cold_temperature``, else
        :data:`COLD_START` (or the assembly temperature, where that is colder)."""
        if self.cold_temperature is not None:
            return self.cold_temperature
        return min(COLD_START, self.assembly_temperature)

    @property
    def cold_start_source(self):
        """Where :attr:`cold_start_temperature` comes from: the engine file, or :data:`COLD_START_SOURCE`."""
        return "press_fit.cold_temperature" if self.cold_temperature is not None else COLD_START_SOURCE

    def soaked_kwargs(self, temperature):
        """Keyword arguments of :func:`stackup.fit.press_fit` with housing, shells and journal all at
        ``temperature`` [degC] (assembly, or a cold start before the journal warms)."""
        return {**{name: getattr(self, name) for name in self._FIT}, "temperature": temperature,
                "journal_temperature": temperature}

    @property
    def temperatures(self):
        """Temperatures the press fit is checked at [degC], coldest first: cold start, assembly, operating, hot."""
        declared = (self.cold_temperature, self.assembly_temperature, self.temperature, self.hot_temperature)
        return tuple(sorted({float(t) for t in declared if t is not None}))

    def extremes_kwargs(self):
        """Keyword arguments of :func:`stackup.fit.press_fit_extremes` over :attr:`temperatures`."""
        return {**{name: getattr(self, name) for name in self._FIT}, "temperatures": self.temperatures}


@dataclass(frozen=True)
class CrankSpec:
    """Crank train, loads and bearing law of an engine (SI; angles in degrees where named so).

    ``crank_angle`` grids are in degrees, 0 = firing TDC of the first cylinder fired.
    ``throw_angles`` are one per throw; a V engine's ``cylinder_throw`` and
    ``cylinder_axis`` say which throw each cylinder is on and along which
    axis it acts (:func:`stackup.loads.v_cylinders`; None: inline).
    """

    kinematics: Kinematics
    combustion: Combustion
    throw_angles: tuple
    firing_order: tuple
    speed: float  # [rad/s]
    spans: np.ndarray  # [m]
    ei: np.ndarray  # (N, 2) [N m^2]
    bearing_width: float  # [m]
    coaxiality: float  # diameter of the bore coaxiality zone [m]
    journal_runout: float  # total run-out of the main journals [m]
    clearance_ratio: float  # law clearance J per radial operating clearance [-]
    law_parameters: dict  # dx, k_lv, k_hv, theta0, dtheta in SI
    pressure_trace: tuple | None = None  # measured (cycle angles [deg], pressures [Pa]) replacing the model
    oil: str | film_oil.Oil = "SAE-5W-30"  # a built-in grade's name (stackup.film.oil), or the user's file's Oil
    oil_supply_temperature: float = 90.0  # [degC]
    supports: Supports | None = None  # the block's compliance at each main bearing (from the law without [supports])
    #: where the section inertias come from (``section_inertia_source``; empty: not given, an assumption)
    section_inertia_source: str = ""
    crank_modulus: float = 2.1e11  # Young's modulus of the crankshaft [Pa] (``crank_material``'s)
    layout: str = "inline"  # "inline" or "V" (the file's crank.layout)
    cylinder_throw: tuple | None = None  # each cylinder's throw, 0-based (a V engine's)
    cylinder_axis: tuple | None = None  # each cylinder's axis from the V's bisector, in the sense of rotation [deg]

    def pin_loads(self, crank_angle):
        """Crank-pin loads (angles, throws, 2) [N] at crank angles [deg]."""
        return pin_loads(crank_angle, kinematics=self.kinematics, combustion=self.combustion,
                         throw_angles=self.throw_angles, firing_order=self.firing_order, speed=self.speed,
                         pressure_trace=self.pressure_trace, cylinder_throw=self.cylinder_throw,
                         cylinder_axis=self.cylinder_axis)

    def law(self, clearance):
        """Bearing law with J from each bearing's diametral operating clearance [m] (array per bearing)."""
        return BellakhdharLaw(clearance=self.clearance_ratio * np.asarray(clearance) / 2, **self.law_parameters)

    def offsets(self, bore_offset, journal_eccentricity, crank_angle):
        """Bearing offsets seen by the journals (..., angles, N+1, 2) [m].

        ``bore_offset`` (..., N+1, 2): bore centres off the line; ``journal_eccentricity``
        (..., N+1, 2): journal centres off the crankshaft axis at crank angle 0,
        turning with the crankshaft. The journal surface sits at beam line +
        eccentricity, so the bearing sees the bore offset minus the eccentricity.
        """
        phi = np.radians(np.asarray(crank_angle, dtype=float))
        c, s = np.cos(phi)[:, None], np.sin(phi)[:, None]
        e0 = journal_eccentricity[..., None, :, 0]
        e1 = journal_eccentricity[..., None, :, 1]
        turned = np.stack([c * e0 - s * e1, s * e0 + c * e1], axis=-1)
        return bore_offset[..., None, :, :] - turned


@dataclass(frozen=True)
class WearSpec:
    """Surfaces and wear of the main bearings, for the resource of Levanov et al. (2015) [SI].

    ``critical_film`` is :math:`h_{lim,cr}`, at least the sum of the
    roughnesses :math:`R_{z1} + R_{z2}` (eq. 3; the sum unless the file gives a
    larger value); ``journal_rq`` and ``shell_rq`` are the RMS roughnesses of
    the asperity contact (method 2), ``lining_material`` the shell's running
    layer (:mod:`stackup.materials`).
    """

    journal_rz: float  # [m]
    shell_rz: float  # [m]
    journal_rq: float  # [m]
    shell_rq: float  # [m]
    critical_film: float  # h_lim,cr [m]
    wear_limit: float  # limiting wear [m]: method 2 (Levanov et al. 2015, sec. 4)
    wear_rate: float  # wear speed gamma [m/s]
    method1_wear_limit: float  # Delta h_lim of method 1 [m]: the scale its results support (stackup.life)
    lining_material: str
    roughness_source: str
    wear_source: str


#: Used when an engine file has no [wear] table: the paper's diesel (h_lim,cr = 1.9 um split between the surfaces).
DEFAULT_WEAR = WearSpec(
    journal_rz=0.8e-6, shell_rz=1.1e-6, journal_rq=0.2e-6, shell_rq=0.3e-6, critical_film=1.9e-6, wear_limit=30e-6,
    wear_rate=1e-13, method1_wear_limit=LEVANOV_2015.method1_wear_limit, lining_material="aluminium",
    roughness_source="default: h_lim,cr = 1.9 um of Levanov et al. 2015 split as journal Rz 0.8 um, shell Rz 1.1 um",
    wear_source="default: Levanov et al. 2015, sec. 4 (30 um, 1e-13 m/s); method 1 on 10 um, the scale of its results")


@dataclass(frozen=True)
class Engine:
    """An engine's main bearings: how many, and how their parts are made."""

    name: str
    title: str
    source: str
    main_bearings: int
    housing_bore: Dimension
    journal_d: Dimension
    shell_wall: ShellSupply
    press_fit: PressFitSpec
    crank: CrankSpec | None = None
    clearance_window: tuple = (0.0, np.inf)  # design window of the operating clearance [m]
    clearance_window_source: str = ""
    #: Least clearance at assembly or cold start [m] (the file's ``targets.minimum_clearance``) and its source.
    minimum_clearance: float = MINIMUM_CLEARANCE
    minimum_clearance_source: str = MINIMUM_CLEARANCE_SOURCE
    life_target: float = 1000.0 * 3600.0  # [s]
    wear: WearSpec = DEFAULT_WEAR  # surfaces and wear limits of the main bearings
    oil_feed: OilFeed | None = None  # how the oil enters each main bearing (stackup.film.heat)

    @property
    def press_fit_limits(self):
        """The engine's press-fit design limits with their source (:class:`PressFitLimits`)."""
        return self.press_fit.limits


def builtin_folder():
    """The folder of the built-in engine files."""
    return Path(str(resources.files("stackup") / "data" / "engines"))


def engine_locations():
    """Where :func:`load_engine` finds each engine by name: {name: path}, the user's folders first."""
    return locations("STACKUP_ENGINE_PATH", builtin_folder())


def available_engines():
    """Names of the engines :func:`load_engine` finds by name: built-in ones and the user's (``STACKUP_ENGINE_PATH``)."""
    return sorted(engine_locations())


def engine_path(name_or_path):
    """The file of a built-in engine name (``"iso-example"``) or of a path."""
    text = os.fspath(name_or_path)
    path = Path(text)
    if path.is_file() or path.suffix == ".toml" or os.sep in text:
        return path
    found = engine_locations().get(text)
    if found is None:
        raise ValueError(f"engine: {text!r} is not a built-in engine nor one in STACKUP_ENGINE_PATH "
                         f"({', '.join(available_engines())}) nor a file{did_you_mean(text, available_engines())}")
    return found


def engine_files(name_or_path):
    """The texts an engine is read from: ``{"name": ..., "text": ..., "extra": {file: text}}``.

    ``extra`` holds the files the engine file names (a measured pressure
    trace), so a study can store everything it read and run again without
    the files (:meth:`stackup.study.Study.from_dataset`).
    """
    path = engine_path(name_or_path)
    data, text = read_toml(path, kind="engine")
    extra = {}
    for table, key in (("crank", "pressure_trace"), ("oil", "file")):  # the files an engine file names
        named = data.get(table, {}).get(key) if isinstance(data.get(table), dict) else None
        if isinstance(named, str):
            named_path = path.parent / named
            if not named_path.is_file():
                raise ValueError(f"engine file {path.name!r}, key {table}.{key}: {named!r} does not exist "
                                 f"(looked in {str(path.parent)!r})")
            extra[named] = named_path.read_text(encoding="utf-8")
    return {"name": path.stem, "text": text, "extra": extra}


def load_engine(name_or_path, *, files=None):
    """Load an engine by built-in name (``"iso-example"``), from a TOML file path, or from its texts.

    ``files`` (what :func:`engine_files` returns) replaces reading the disk.
    Every key is checked: its type, its range, lengths against what such a
    part can measure (a hint about ``units`` otherwise), and a key nobody
    reads is refused with the valid ones listed.
    """
    if isinstance(name_or_path, Engine):
        return name_or_path
    files = engine_files(name_or_path) if files is None else files
    where = f"engine file {files['name'] + '.toml'!r}"
    return _engine(Table(parse_toml(files["text"], where=where), where), name=files["name"], extra=files["extra"])


def _dimension(top, key, *, scale, units, plausible, what, required=True):
    """A part's dimension: drawing limits, process, gauge, shared share, form error, bolt scatter, source."""
    t = top.table(key, required=required)
    lo, hi = t.lengths("limits", count=2, required=True, scale=scale, units=units, plausible=plausible, what=what,
                       increasing=True)
    field = f"{t.where}, key {t.path}"
    process = process_from_spec(t.get("process", required=True), lo=lo, hi=hi, scale=scale, field=f"{field}.process")
    _near_limits(f"{field}.process", process, lo, hi, scale=scale, units=units)
    gauge_table = t.get("gauge")
    gauge = gauge_from_spec(gauge_table, scale=scale, field=f"{field}.gauge")
    shared = t.number("shared", 0.0, lo=0.0, hi=1.0, hi_open=True)
    form = form_from_spec(t.get("form"), scale=scale, field=f"{field}.form")
    if form is not None:
        # the gauge's readings are those of the form's planes and directions, averaged
        if "readings" in (gauge_table or {}) and gauge.readings != form.readings:
            raise ValueError(f"{field}.gauge.readings: {gauge.readings} readings, but the form is read in "
                             f"{form.readings} (planes x directions)")
        gauge = replace(gauge, readings=form.readings, combine="mean")
    bolt = t.length("bolt_scatter", 0.0, scale=scale, units=units, plausible=(0.0, 50e-6), what="bolt scatter")
    source = t.text("source", "")
    t.close()
    return Dimension(key, lo, hi, process, gauge, shared, form=form, bolt_scatter=bolt, source=source)


#: Largest share of the shell wall a lining may take [-]: the steel back carries the crush and is most of the wall
#: (Kopeliovich's bimetal example: 0.3 mm of copper-lead on a 1.594 mm wall, 19 %; the built-in engines 0.3 mm on
#: about 2 mm); a lining of half the wall or more is no steel-backed shell.
LINING_SHARE = 0.5


#: Farthest a process's median may lie outside its drawing limits, in tolerance widths: one width out, more
#: than half the parts are scrap whatever the spread; farther, the mean is a typing or unit error, not a process.
FARTHEST_PROCESS = 1.0


def _near_limits(field, process, lo, hi, *, scale, units):
    """Refuse a process wider than its tolerance, or whose median lies more than :data:`FARTHEST_PROCESS`
    tolerance widths outside [lo, hi]."""
    median, width = float(process.ppf(0.5)), hi - lo
    if process.std > width:
        raise ValueError(f"{field}: its standard deviation {process.std / scale:.4g} {units} is wider than the "
                         f"tolerance {width / scale:.4g} {units}: fewer than 40 % of its parts within the limits is "
                         "no production process; is sigma in the file's units?")
    off = max(lo - median, median - hi)
    if off > FARTHEST_PROCESS * width:
        side = f"below the lower limit {lo / scale:g}" if median < lo else f"above the upper limit {hi / scale:g}"
        raise ValueError(f"{field}: its median {median / scale:.6g} {units} lies {off / scale:.4g} {units} "
                         f"({off / width:.3g} tolerance widths) {side} {units}; a process sits near its drawing "
                         f"limits (within {FARTHEST_PROCESS:g} tolerance width): is the mean mistyped?")


#: How much hotter than its housing a journal may run in service [K] (an engine file's
#: ``press_fit.journal_temperature_excess``, a scenario's): journals often run 10-20 K above their bulkheads
#: (physics.md sec. 3), a cooled or warming journal below; a plausibility bound, as :data:`PLAUSIBLE` is for
#: lengths.
JOURNAL_TEMPERATURE_EXCESS = check.InRange(-50.0, 100.0, unit=" K")
#: Sizes a length may have [m], for the plausibility checks of engine files: the lengths of the one table of
#: plausible ranges, :data:`stackup._validate.PLAUSIBLE`, as (lo, hi).
PLAUSIBLE = {name: (r.lo, r.hi) for name, r in check.PLAUSIBLE.items() if r.unit == "m"}


#: Top-level tables of a scheme file (:mod:`stackup.schemes`) that no engine file has.
_SCHEME_TABLES = ("housing", "journal", "shell", "pairing")


def _engine(top, *, name, extra):
    scheme_tables = [k for k in _SCHEME_TABLES if k in top]
    if scheme_tables and "main_bearings" not in top:
        raise ValueError(f"{top.where}: is a scheme file (it has {', '.join(f'[{k}]' for k in scheme_tables)}), not "
                         "an engine file; give it as a scheme (compare --schemes, plan --scheme)")
    if not any(k in top for k in ("main_bearings", "housing_bore", "journal_d")):
        has = ", ".join(list(top.data)[:6]) + (", ..." if len(top.data) > 6 else "")
        raise ValueError(f"{top.where}: is not an engine file (none of main_bearings, [housing_bore], [journal_d]; "
                         f"it has {has}); an engine file is described in docs/engine-file.md")
    units, scale = units_of(top)
    length = dict(scale=scale, units=units)
    bearings = top.integer("main_bearings", required=True, lo=1, hi=30)
    shell = top.table("shell_wall")
    mode = shell.text("supply", "to-order", options=("to-order", "sorted"))
    process = shell.table("process").data if "process" in shell else {"distribution": "normal", "cpk": 1.33}
    sigma = shell.length("sigma", 1e-6 / scale, **length, plausible=PLAUSIBLE["wall_sigma"],
                         what="shell wall process standard deviation")
    supply = ShellSupply(
        mode=mode,
        process=process,
        sigma=sigma if mode == "to-order" else None,
        target_offset=shell.number("target_offset", 0.0, lo=-0.1 / scale * 1e-3, hi=0.1 / scale * 1e-3) * scale,
        gauge=gauge_from_spec(shell.get("gauge"), scale=scale, field=f"{shell.where}, key shell_wall.gauge"),
        lot_engines=shell.integer("lot_engines", 1000, lo=1, hi=10**8),
        surplus=shell.number("surplus", 0.1, lo=0.0, hi=10.0),
        crush=_dimension(top, "crush_height", **length, plausible=PLAUSIBLE["crush"], what="crush height"),
        scale=scale,
    )
    shell.close()
    bore = _dimension(top, "housing_bore", **length, plausible=PLAUSIBLE["bore"], what="housing bore diameter")
    journal = _dimension(top, "journal_d", **length, plausible=PLAUSIBLE["bore"], what="journal diameter")
    if journal.hi >= bore.lo:
        raise ValueError(f"{top.where}, key journal_d.limits: the journal ({journal.lo / scale:g}-{journal.hi / scale:g} "
                         f"{units}) must be smaller than the housing bore ({bore.lo / scale:g}-{bore.hi / scale:g} {units})")
    spec = _press_fit(top, bore, **length)
    wall = 0.5 * (bore.lo - journal.hi)  # the thickest wall the tightest bore and largest journal leave room for
    if spec.lining_thickness >= LINING_SHARE * wall:
        raise ValueError(f"{top.where}, key press_fit.lining_thickness: {spec.lining_thickness / scale:g} {units} is not "
                         f"below {LINING_SHARE * wall / scale:.4g} {units}, {LINING_SHARE:g} of a shell wall of at most "
                         f"{wall / scale:.6g} {units} (half of housing bore {bore.lo / scale:g} - journal "
                         f"{journal.hi / scale:g} {units}); the steel back carries the crush and is most of the wall")
    if "crank" not in top:
        for table in ("bearing_law", "oil"):  # read only by the mechanical chain
            if table in top:
                raise ValueError(f"{top.where}: [{table}] needs a [crank] section (the mechanical chain); add "
                                 f"[crank] or remove [{table}]")
        top.get("crank")
    engine = Engine(
        name=top.text("name", name),
        title=top.text("title", ""),
        source=top.text("source", ""),
        main_bearings=bearings,
        housing_bore=bore,
        journal_d=journal,
        shell_wall=supply,
        press_fit=spec,
        crank=_crank(top, **length, bearings=bearings, extra=extra) if "crank" in top else None,
        **_targets(top, **length, journal=journal),
        wear=_wear(top, **length),
        oil_feed=_oil_feed(top, **length, bearing_width=spec.bearing_width),
    )
    top.close()
    return engine


def _press_fit(top, bore, *, scale, units):
    t = top.table("press_fit", required=True)
    length = dict(scale=scale, units=units)

    def temperature(name, default):  # the plausible range (kelvin named) inside the press fit's valid one
        value = t.number(name, default)
        if value is not None:
            check.PLAUSIBLE["engine_temperature"].check(t._at(name), value)
        return t.number(name, default, **asdict(TEMPERATURE))

    lining_thickness = t.length("lining_thickness", 0.0, **length, plausible=PLAUSIBLE["lining"],
                                what="lining thickness")
    lining_material = _material(t, "lining_material", None)
    if lining_thickness > 0 and lining_material is None:
        raise ValueError(f"{t.where}, key press_fit.lining_material: missing; a lining_thickness > 0 needs the "
                         "lining's material")
    spec = PressFitSpec(
        housing_outer=t.length("housing_outer", required=True, **length, plausible=PLAUSIBLE["ring"],
                               what="housing outer diameter"),
        housing_material=_material(t, "housing_material"),
        shell_material=_material(t, "shell_material"),
        journal_material=_material(t, "journal_material"),
        bearing_width=t.length("length", required=True, **length, plausible=PLAUSIBLE["width"], what="shell width"),
        check_bore=t.length("check_bore", bore.lo / scale, **length, plausible=PLAUSIBLE["bore"],
                            what="checking-block bore"),
        check_stress=check.PLAUSIBLE["check_stress"].check(t._at("check_stress"),
                                                           t.number("check_stress", 100e6, **asdict(CHECK_STRESS))),
        assembly_temperature=temperature("assembly_temperature", 20.0),
        temperature=temperature("temperature", 20.0),
        lining_thickness=lining_thickness,
        lining_material=lining_material,
        cold_temperature=temperature("cold_temperature", None),
        hot_temperature=temperature("hot_temperature", None),
        limits=_limits(t),
        crush_source=t.text("crush_height_source", ""),
        journal_temperature_excess=t.number("journal_temperature_excess", 0.0, **asdict(JOURNAL_TEMPERATURE_EXCESS)),
        journal_temperature_source=t.text("journal_temperature_source", ""),
        housing_outer_interval=_housing_outer_interval(t, bore, **length),
    )
    t.close()
    key = f"{t.where}, key press_fit"
    if spec.housing_outer <= bore.hi:
        raise ValueError(f"{key}.housing_outer: {spec.housing_outer / scale:g} {units} is not above the housing bore")
    if spec.cold_temperature is not None and spec.cold_temperature > spec.assembly_temperature:
        raise ValueError(f"{key}.cold_temperature: {spec.cold_temperature!r} degC is above the assembly temperature "
                         f"{spec.assembly_temperature!r} degC; the coldest state checked is the colder of the two")
    if spec.hot_temperature is not None and spec.hot_temperature < spec.temperature:
        raise ValueError(f"{key}.hot_temperature: {spec.hot_temperature!r} degC is below the operating temperature "
                         f"{spec.temperature!r} degC")
    return spec


def _housing_outer_interval(t, bore, *, scale, units):
    """``[press_fit] housing_outer_interval``: [lower, upper] measured outer diameter [m], upper maybe inf; or None."""
    value = t.get("housing_outer_interval")
    if value is None:
        return None
    at = t._at("housing_outer_interval")
    if not isinstance(value, list) or len(value) != 2:
        raise ValueError(f"{at}: {value!r} is not [lower, upper], the measured interval of housing_outer in {units}")
    lo = t._length("housing_outer_interval", value[0], scale, units, PLAUSIBLE["ring"], "housing outer diameter")
    upper = value[1]
    if isinstance(upper, bool) or not isinstance(upper, (int, float)) or np.isnan(upper):
        raise ValueError(f"{at}: upper end {upper!r} is not a number (inf: as stiff as a rigid ring)")
    hi = np.inf if np.isinf(upper) and upper > 0 else t._length("housing_outer_interval", upper, scale, units,
                                                               PLAUSIBLE["ring"], "housing outer diameter")
    if lo <= bore.hi or hi <= lo:
        raise ValueError(f"{at}: [{value[0]!r}, {upper!r}] {units} is not an interval above the housing bore "
                         f"({bore.hi / scale:g} {units}) with lower < upper")
    return (lo, hi)


#: The material of a part whose file names none (press fit, crankshaft, and the block the supports derive from).
DEFAULT_MATERIAL = "steel"


def _material(t, name, default=DEFAULT_MATERIAL):
    """The name of a known material (:mod:`stackup.materials`) at key ``name`` of table ``t``."""
    return t.text(name, default, options=tuple(materials.available()))


def _wear(top, *, scale, units):
    """The [wear] table: roughness (Rz, Rq) of journal and shell, lining, limiting wear and wear speed."""
    t = top.optional("wear")
    if t is None:
        return DEFAULT_WEAR
    key = f"{t.where}, key wear"
    rough = dict(scale=scale, units=units, plausible=PLAUSIBLE["roughness"], what="surface roughness")
    rz1, rz2, rq1, rq2 = (t.length(n, required=True, **rough) for n in ("journal_rz", "shell_rz", "journal_rq",
                                                                          "shell_rq"))
    for rz, rq, part in ((rz1, rq1, "journal"), (rz2, rq2, "shell")):
        if rq >= rz:
            raise ValueError(f"{key}.{part}_rq: {rq / scale!r} is not below {part}_rz {rz / scale!r}")
    critical = rz1 + rz2
    given = t.length("critical_film", None, **rough)
    if given is not None:
        if given < critical * (1 - 1e-12):
            raise ValueError(f"{key}.critical_film: {given / scale!r} is below journal_rz + shell_rz = "
                             f"{critical / scale!r} (Levanov et al. 2015, eq. 3: h_lim,cr > Rz1 + Rz2)")
        critical = given

    rate = t.number("wear_rate", required=True, lo=0.0, hi=1e-3 / scale, lo_open=True) * scale
    spec = WearSpec(journal_rz=rz1, shell_rz=rz2, journal_rq=rq1, shell_rq=rq2, critical_film=critical,
                    wear_limit=t.length("wear_limit", required=True, scale=scale, units=units,
                                        plausible=PLAUSIBLE["wear"], what="limiting wear"),
                    wear_rate=rate,
                    method1_wear_limit=t.length("method1_wear_limit", METHOD1_SCALE * rate / scale, scale=scale,
                                                units=units, plausible=PLAUSIBLE["wear"], what="method-1 limiting wear"),
                    lining_material=_material(t, "lining_material", "aluminium"),
                    roughness_source=t.source("roughness_source"), wear_source=t.source("wear_source"))
    t.close()
    return spec


#: Groove width of the default feed, as a share of the bearing length.
_DEFAULT_GROOVE_SHARE = 0.15


def _oil_feed(top, *, scale, units, bearing_width):
    """The [oil_feed] table: supply pressure [Pa] and the groove or hole (angles in deg, lengths in file units)."""
    t = top.optional("oil_feed")
    if t is None:
        return OilFeed("groove", 0.3e6, (0.5 * np.pi, 1.5 * np.pi), _DEFAULT_GROOVE_SHARE * bearing_width,
                       source="default: 0.3 MPa into a 180 deg groove in the upper shell, 15 % of the bearing wide")
    key = f"{t.where}, key oil_feed"
    kind = t.text("feed", required=True, options=FEEDS)
    pressure = check.PLAUSIBLE["oil_pressure"].check(
        t._at("supply_pressure"), t.number("supply_pressure", required=True, lo=0.0, hi=2e7, lo_open=True, unit=" Pa"))
    source = t.source("source")
    if kind == "groove":
        arc = check.degrees_not_radians(f"{key}.groove_arc", t.numbers("groove_arc", [90.0, 270.0]))
        if arc.shape != (2,) or not 0 < arc[1] - arc[0] <= 360:
            raise ValueError(f"{key}.groove_arc: {arc.tolist()!r} deg is not valid; need [start, end], "
                             f"start < end <= start + 360")
        width = t.length("groove_width", required=True, scale=scale, units=units, plausible=PLAUSIBLE["groove"],
                         what="groove width")
        if width >= bearing_width:
            raise ValueError(f"{key}.groove_width: {width / scale:g} {units} is not below the bearing width "
                             "(press_fit.length)")
        feed = OilFeed(kind, pressure, tuple(float(a) for a in np.radians(arc)), width, source=source)
    else:
        diameter = t.length("hole_diameter", required=True, scale=scale, units=units, plausible=PLAUSIBLE["groove"],
                            what="feed hole diameter")
        if diameter >= bearing_width / 2:
            raise ValueError(f"{key}.hole_diameter: {diameter / scale:g} {units} is not below half the bearing "
                             "width (press_fit.length)")
        angle = t.number("hole_angle", 180.0, lo=-360.0, hi=720.0, unit=" deg")
        feed = OilFeed(kind, pressure, hole_angle=float(np.radians(angle)), hole_diameter=diameter, source=source)
    t.close()
    return feed


def _limits(press_fit):
    """Press-fit design limits from ``[press_fit.limits]`` (Pa, with their source); Kopeliovich's if absent."""
    t = press_fit.optional("limits")
    if t is None:
        return KOPELIOVICH_LIMITS
    limits = PressFitLimits(
        contact_pressure_min=t.number("contact_pressure_min", required=True, lo=0.0, lo_open=True, unit=" Pa"),
        shell_stress_max=t.number("shell_stress_max", required=True, lo=0.0, lo_open=True, unit=" Pa"),
        source=t.text("source", required=True),
    )
    t.close()
    if not (1e5 <= limits.contact_pressure_min <= 100e6 and 10e6 <= limits.shell_stress_max <= 2e9):
        raise ValueError(f"{t.where}, key press_fit.limits: contact_pressure_min {limits.contact_pressure_min:g} Pa, "
                         f"shell_stress_max {limits.shell_stress_max:g} Pa; give the limits in Pa (e.g. 10e6 and 400e6)")
    return limits


def _targets(top, *, scale, units, journal):
    """Design window of the operating clearance (absolute, or relative to the journal) and life target."""
    t = top.table("targets")
    key = f"{t.where}, key targets"
    out = {}
    if "operating_clearance" in t and "relative_clearance" in t:
        raise ValueError(f"{key}: give either operating_clearance or relative_clearance, not both")
    window = t.lengths("operating_clearance", count=2, scale=scale, units=units, plausible=PLAUSIBLE["window"],
                       what="operating clearance", increasing=True)
    if window is not None:
        out["clearance_window"] = tuple(window)
    ratio = t.numbers("relative_clearance")
    if ratio is not None:
        # psi = C / D of the journal's nominal size (its lower drawing limit)
        if len(ratio) != 2:
            raise ValueError(f"{key}.relative_clearance: {ratio.tolist()!r} is not a [lower, upper] pair")
        lo, hi = check.limits(f"{key}.relative_clearance", *ratio, unit="")
        if lo <= 0 or hi >= 0.01:
            raise ValueError(f"{key}.relative_clearance: [{lo!r}, {hi!r}] is not a clearance ratio C/D in (0, 0.01) "
                             "(write 1 per mille as 0.001)")
        out["clearance_window"] = (lo * journal.lo, hi * journal.lo)
    source = t.text("clearance_source")
    if source is not None:
        out["clearance_window_source"] = source
    minimum = t.length("minimum_clearance", None, scale=scale, units=units, plausible=(0.0, 1e-4),
                       what="minimum clearance at assembly and cold start")
    minimum_source = t.text("minimum_clearance_source")
    if minimum is not None:
        out["minimum_clearance"] = minimum
        out["minimum_clearance_source"] = minimum_source or ""
    elif minimum_source is not None:
        raise ValueError(f"{key}.minimum_clearance_source: given without minimum_clearance; give both, or neither "
                         f"(default {MINIMUM_CLEARANCE * 1e6:g} um: {MINIMUM_CLEARANCE_SOURCE})")
    hours = t.number("life_hours", None, lo=0.0, hi=1e7, lo_open=True, unit=" h")
    if hours is not None:
        check.PLAUSIBLE["life_hours"].check(t._at("life_hours"), hours)
        out["life_target"] = hours * 3600.0
    t.close()
    return out


def _crank(top, *, scale, units, bearings, extra):
    """The [crank] table (crank train, loads, beam), with [bearing_law] and [oil]: the mechanical chain's data."""
    t = top.table("crank")
    key = f"{t.where}, key crank"
    length = dict(scale=scale, units=units)
    cylinders = t.integer("cylinders", required=True, lo=1, hi=58)
    layout = _layout(t, cylinders)
    n_throws = cylinders // (1 if layout["cylinder_throw"] is None else 2)
    if n_throws != bearings - 1:
        arrangement = ("in line (one a throw)" if layout["layout"] == "inline" else
                       f"in a V (two a throw, {n_throws} throws)")
        hint = ('; a V engine: crank.layout = "V" with bank_angle' if layout["layout"] == "inline" else "")
        raise ValueError(f"{key}.cylinders: {cylinders} cylinders {arrangement} need {n_throws + 1} main bearings, "
                         f"main_bearings is {bearings}{hint}")
    throws, order = _firing(t, cylinders, n_throws, layout)
    inertia = t.numbers("section_inertia", required=True, rows=True)
    inertia = check.positive(f"{key}.section_inertia", inertia) * scale**4
    if inertia.shape not in ((n_throws,), (n_throws, 2)):
        raise ValueError(f"{key}.section_inertia: shape {inertia.shape}; give ({n_throws},) or ({n_throws}, 2), "
                         "one per span")
    if np.any((inertia < 1e-10) | (inertia > 1e-1)):  # a 10 mm to a 1 m steel journal
        raise ValueError(f"{key}.section_inertia: {float(inertia.min() / scale**4):g} to "
                         f"{float(inertia.max() / scale**4):g} {units}^4 is not a plausible section inertia "
                         f"({1e-10 / scale**4:g} to {1e-1 / scale**4:g} {units}^4); is `units` right?")
    modulus = materials.get(_material(t, "crank_material")).modulus
    spec = CrankSpec(
        kinematics=_kinematics(t, **length),
        combustion=_named(t, Combustion, compression_ratio=t.number("compression_ratio", 16.0, lo=1.0, hi=40.0,
                                                                    lo_open=True),
                          peak_pressure=check.PLAUSIBLE["peak_pressure"].check(t._at("peak_pressure"),
                                                                               t.number("peak_pressure", 13e6))),
        throw_angles=throws, firing_order=order,
        speed=t.number("speed", required=True, lo=10.0, hi=3e4, unit=" rpm") * 2 * np.pi / 60,
        spans=np.array(t.lengths("spans", count=n_throws, required=True, **length, plausible=PLAUSIBLE["span"],
                                 what="crankshaft span")),
        ei=modulus * (inertia if inertia.ndim == 2 else np.stack([inertia, inertia], -1)),
        bearing_width=_one_width(t, top.table("press_fit").get("length"), **length),
        coaxiality=t.length("coaxiality", 0.0, **length, plausible=PLAUSIBLE["misalignment"], what="coaxiality"),
        journal_runout=t.length("journal_runout", 0.0, **length, plausible=PLAUSIBLE["misalignment"],
                                what="journal run-out"),
        clearance_ratio=1.0, law_parameters={}, pressure_trace=_pressure_trace(t, extra),
        section_inertia_source=t.text("section_inertia_source", ""), crank_modulus=modulus, **layout,
    )
    t.close()
    ratio, params = _bearing_law(top, **length)
    supports = _supports(top, **length, bearings=bearings, block=top.table("press_fit").get("housing_material"),
                         ring=top.table("press_fit").get("housing_outer"))
    if supports is not None:
        given = [k for k in ("k_lv", "k_hv") if k in top.table("bearing_law")]
        if given:
            raise ValueError(f"{top.where}, key bearing_law.{given[0]}: the housing's deformation stiffness is the "
                             "[supports] table's linear_compliance_um_per_kN (one description of the housing); "
                             f"remove bearing_law.{given[0]}")
        params = {**params, **supports.law_stiffness}
        supports = replace(supports, ring=_ring(params, spec.bearing_width))
    else:
        supports = _law_supports(params, bearings, spec.bearing_width)
    oil = top.table("oil")
    oils_file = oil.text("file")  # a user's oils file beside the engine file, read by engine_files
    if oils_file is not None and oils_file not in extra:
        raise ValueError(f"{oil.where}, key oil.file: {oils_file!r} was not read with the engine file")
    known = film_oil.user_oils(extra[oils_file], name=oils_file) if oils_file is not None else {}
    grade = oil.text("grade", "SAE-5W-30", options=(*film_oil.available(), *known))
    check.PLAUSIBLE["engine_temperature"].check(oil._at("supply_temperature"), oil.number("supply_temperature", 90.0))
    supply = oil.number("supply_temperature", 90.0, lo=-30.0, hi=200.0, unit=" degC")
    oil.close()
    return replace(spec, clearance_ratio=ratio, law_parameters=params, oil=known.get(grade, grade),
                   oil_supply_temperature=supply, supports=supports)


#: How far crank.bearing_width may differ from press_fit.length [-]: the same width written twice (22 and
#: 22.0, or rounded to the drawing's 0.1 mm on a 20 mm shell); more is two widths of one bearing.
SAME_WIDTH = 5e-3


def _one_width(t, shell_width, *, scale, units):
    """crank.bearing_width [m]: the shell's width ``press_fit.length`` (file units); given again, it must agree."""
    width = t.length("bearing_width", shell_width, scale=scale, units=units, plausible=PLAUSIBLE["width"],
                     what="bearing width")
    if "bearing_width" in t and isinstance(shell_width, (int, float)) and \
            abs(width - shell_width * scale) > SAME_WIDTH * shell_width * scale:
        raise ValueError(f"{t._at('bearing_width')}: {width / scale:g} {units} differs from press_fit.length "
                         f"{shell_width:g} {units}; a bearing has one width (the shells'): give it once as "
                         "press_fit.length and leave crank.bearing_width out")
    return width


def _per_bearing(t, name, *, bearings, required, lo=-math.inf, positive=False):
    """A [supports] key: one row of two numbers for every bearing, or one row for all -> (bearings, 2)."""
    value = t.numbers(name, required=required, rows=True)
    if value is None:
        return None
    where = f"{t.where}, key {t.key(name)}"
    if value.shape == (2,):
        value = np.broadcast_to(value, (bearings, 2)).copy()
    if value.shape != (bearings, 2):
        raise ValueError(f"{where}: shape {value.shape}; give [a, b] for every bearing or one row per bearing "
                         f"({bearings}, 2)")
    bad = value <= lo if positive else value < lo
    if np.any(bad):
        raise ValueError(f"{where}: {float(value[bad].flat[0]):g} is not valid; a compliance must be "
                         f"{'> 0' if positive else '>= 0'}")
    return value


def _supports(top, *, scale, units, bearings, block, ring):
    """The [supports] table: the block's linear and angular compliance at each main bearing, its thermal offsets."""
    if "supports" not in top:
        top.get("supports")
        return None
    t = top.table("supports")
    linear = _per_bearing(t, "linear_compliance_um_per_kN", bearings=bearings, required=True, lo=0.0, positive=True)
    for value in (linear.min(), linear.max()):
        check.PLAUSIBLE["support_compliance"].check(t._at("linear_compliance_um_per_kN"), value)
    angular = _per_bearing(t, "angular_compliance_urad_per_Nm", bearings=bearings, required=False, lo=0.0)
    bulkhead = t.optional("bulkhead")
    where = f"{t.where}, key {t.key('angular_compliance_urad_per_Nm')}"
    if (angular is None) == (bulkhead is None):
        raise ValueError(f"{where}: {'missing' if angular is None else 'given beside supports.bulkhead'}; give the "
                         "angular compliance [urad/(N m)] per bearing (vertical plane, transverse plane) or the "
                         "bulkhead's web ([supports.bulkhead]: thickness, height, width) it is derived from, one of "
                         "them")
    if bulkhead is not None:
        material = materials.get(block or DEFAULT_MATERIAL)  # press_fit.housing_material's own default
        plausible = dict(scale=scale, units=units, plausible=PLAUSIBLE["ring"])
        thickness = bulkhead.lengths("thickness", count=bearings, required=True, **plausible, what="bulkhead thickness")
        height = bulkhead.length("height", required=True, **plausible, what="bulkhead height")
        width = bulkhead.length("width", required=True, **plausible, what="bulkhead width")
        ring_height = bulkhead.length("ring_height", None if ring is None else ring, **plausible,
                                      what="housing ring height")
        if ring_height is None:
            raise ValueError(f"{bulkhead.where}, key {bulkhead.key('ring_height')}: missing (and no "
                             "press_fit.housing_outer to take it from)")
        bulkhead.close()
        angular = bulkhead_compliance(thickness=thickness, height=height, width=width, ring_height=ring_height,
                                      modulus=material.modulus, poisson=material.poisson)
    else:
        angular = angular * 1e-6
    thermal = _per_bearing(t, "thermal_offset_um", bearings=bearings, required=False)
    if thermal is not None and np.any(np.abs(thermal) > 500.0):
        raise ValueError(f"{t.where}, key {t.key('thermal_offset_um')}: {float(np.abs(thermal).max()):g} um is not a "
                         "plausible offset of a bore by the block's heat (0 to 500 um)")
    # [um/kN] -> [m/N] by a division: 1 / (c / 1e9) gives back the stiffness a file's digits came from
    out = Supports(linear / 1e9, angular, None if thermal is None else thermal * 1e-6, t.source("source"),
                   t.source("thermal_source") if thermal is not None else "", angular_derived=bulkhead is not None)
    t.close()
    return out


def _law_supports(law, bearings, bearing_width):
    """The supports of an engine file without a [supports] table: the bearing law's deformation stiffness as
    their linear compliance (one description of the housing), the bulkhead's web rigid against tilt (the file
    describes none) and the bore ring's own turn from the law (:func:`_ring`)."""
    linear = np.broadcast_to(1.0 / np.stack([np.asarray(law["k_lv"], float), np.asarray(law["k_hv"], float)],
                                            axis=-1), (bearings, 2)).copy()
    return Supports(linear, np.zeros((bearings, 2)),
                    source="no [supports] table: the linear compliance the bearing law's deformation stiffness "
                           "(bearing_law.k_lv, k_hv), the bulkhead's web rigid against tilt, the bore ring's own "
                           "turn derived from the law",
                    ring=np.broadcast_to(_ring(law, bearing_width), (bearings, 2)).copy())


def _ring(law, bearing_width):
    """The bores' own angular compliance (N+1, 2) [rad/(N m)] from the bearing law's deformation stiffness: in the
    cylinders' plane the law's towards the cap (0 deg), across it the law's at 90 deg
    (:func:`stackup.crank.housing.ring_tilt_compliance`)."""
    planes = [law_stiffness(angle, law["k_lv"], law["k_hv"], law["theta0"], law["dtheta"])[0]
              for angle in (0.0, 0.5 * np.pi)]
    return ring_tilt_compliance(stiffness=np.stack(planes, axis=-1), bearing_width=bearing_width)


def _kinematics(t, *, scale, units):
    """The slider-crank of table [crank]: bore, stroke, con-rod and masses; the counterweights' unbalance."""
    length = dict(scale=scale, units=units, plausible=PLAUSIBLE["crank"])
    stroke = t.length("stroke", required=True, **length, what="stroke")
    unbalance = t.number("counterweight_share", 0.0, lo=0.0, hi=2.0)
    bore = t.length("cylinder_bore", required=True, **length, what="cylinder bore")

    def mass(name):  # per cylinder, against its bore (grams for kg refused)
        value = t.number(name, required=True, lo=0.0, hi=1e4, unit=" kg")
        return check.PLAUSIBLE["cylinder_mass"].check(t._at(name), value, scale=bore**-3,
                                                      of=f" for a {bore / scale:g} {units} cylinder bore")

    rotating = mass("rotating_mass")
    return _named(
        t, Kinematics,
        cylinder_bore=bore,
        stroke=stroke,
        conrod=t.length("conrod", required=True, **length, what="connecting rod"),
        reciprocating_mass=mass("reciprocating_mass"),
        rotating_mass=rotating, counterweight_unbalance=unbalance * rotating * stroke / 2)


#: Engine layouts the load model does not cover, each with why (crank.layout, crank.rods).
NOT_COVERED = {
    "layout": {"W": "three or four banks", "VR": "narrow-angle staggered banks on one head",
               "boxer": "opposed cylinders each on its own throw", "flat": "opposed cylinders each on its own throw",
               "radial": "a master rod and articulated rods", "H": "two crankshafts", "U": "two crankshafts"},
    "rods": {"fork-and-blade": "the blade's big end runs on the fork's", "articulated": "a master rod carries "
             "the other", "master-and-slave": "a master rod carries the other", "split-pin": "each bank's pin at "
             "its own angle"},
}


def _layout(t, cylinders):
    """The [crank] table's layout: inline, or V with its bank angle and the maker's cylinder numbering.

    Returns the :class:`CrankSpec` fields ``layout``, ``cylinder_throw``, ``cylinder_axis``.
    """
    key = f"{t.where}, key crank"
    value = t.get("layout", "inline")
    if isinstance(value, str) and value in NOT_COVERED["layout"]:
        raise ValueError(f"{key}.layout: {value!r} is not covered ({NOT_COVERED['layout'][value]}); valid: "
                         "'inline', 'V' (two side-by-side rods on each pin, any bank angle)")
    layout = t.text("layout", "inline", options=("inline", "V"))
    v_keys = ("bank_angle", "numbering", "first_bank", "rods")
    if layout == "inline":
        given = [k for k in v_keys if k in t]
        if given:
            raise ValueError(f"{key}.{given[0]}: {t.get(given[0])!r} is for a V engine; add layout = \"V\" or "
                             f"remove {given[0]}")
        return {"layout": layout, "cylinder_throw": None, "cylinder_axis": None}
    rods = t.get("rods", "side-by-side")
    if isinstance(rods, str) and rods in NOT_COVERED["rods"]:
        raise ValueError(f"{key}.rods: {rods!r} is not covered ({NOT_COVERED['rods'][rods]}); valid: "
                         "'side-by-side' (two rods on one common pin)")
    t.text("rods", "side-by-side", options=("side-by-side",))
    if cylinders % 2:
        raise ValueError(f"{key}.cylinders: {cylinders} is odd; a V engine has two cylinders on each throw")
    # from the narrowest V with its banks apart (Lancia's 10-20 deg are staggered: VR) to a 180 deg V
    bank = t.number("bank_angle", required=True, lo=10.0, hi=180.0, unit=" deg")
    numbering = t.text("numbering", required=True, options=NUMBERINGS)
    first = t.text("first_bank", required=True, options=BANKS)
    throw, axis = v_cylinders(cylinders, bank_angle=bank, numbering=numbering, first_bank=first)
    return {"layout": layout, "cylinder_throw": tuple(int(i) for i in throw),
            "cylinder_axis": tuple(float(a) for a in axis)}


def _firing(t, cylinders, n_throws, layout):
    """Throw angles [deg] (one per throw) and firing order (one per cylinder) of table [crank], that fire one
    cylinder at a time."""
    key = f"{t.where}, key crank"
    throws = tuple(float(a) for a in check.degrees_not_radians(f"{key}.throw_angles",
                                                                t.numbers("throw_angles", required=True)))
    order = t.get("firing_order", required=True)
    if not isinstance(order, list) or not all(isinstance(c, int) and not isinstance(c, bool) for c in order):
        raise ValueError(f"{key}.firing_order: {order!r} is not a list of cylinder numbers")
    order = tuple(order)
    if len(throws) != n_throws:
        raise ValueError(f"{key}.throw_angles: {len(throws)} entries; give {n_throws}, one per throw")
    if len(order) != cylinders:
        raise ValueError(f"{key}.firing_order: {len(order)} entries; give {cylinders}, one per cylinder")
    # both checked here, the file's boundary, also where a caller trusts its inputs
    own = cylinder_throw_angles(throws, layout["cylinder_throw"], layout["cylinder_axis"])
    _named(t, check_firing_order, own, order)
    _named(t, firing_offsets, own, order)
    return throws, order


def _named(t, function, *args, **kwargs):
    """``function(*args, **kwargs)``, a refusal named with the file and table ``t`` (its message starts with the key)."""
    try:
        return function(*args, **kwargs)
    except ValueError as err:
        raise ValueError(f"{t.where}, key {t.path}.{err}") from None


def _pressure_trace(t, extra):
    """The measured cylinder pressure named by crank.pressure_trace, read from ``extra``; None without one."""
    trace_file = t.text("pressure_trace")
    if trace_file is None:
        return None
    if trace_file not in extra:
        raise ValueError(f"{t.where}, key crank.pressure_trace: {trace_file!r} was not read with the engine file")
    return read_pressure_trace(io.StringIO(extra[trace_file]), name=trace_file)


def _bearing_law(top, *, scale, units):
    """The [bearing_law] table: the law's clearance ratio and its parameters in SI (defaults: Bellakhdhar's)."""
    law = top.table("bearing_law")
    params = {
        "dx": law.length("dx", 0.00965e-3 / scale, scale=scale, units=units, plausible=PLAUSIBLE["law_dx"],
                         what="law transition"),
        "k_lv": law.number("k_lv", 0.98e9, lo=1e5, hi=1e13, unit=" N/m"),
        "k_hv": law.number("k_hv", 1.72e9, lo=1e5, hi=1e13, unit=" N/m"),
        "theta0": np.radians(law.number("theta0", 97.0, lo=0.0, hi=180.0, unit=" deg")),
        "dtheta": np.radians(law.number("dtheta", 15.0, lo=0.0, hi=180.0, lo_open=True, unit=" deg")),
    }
    ratio = law.number("clearance_ratio", 37.0 / 30.0, lo=0.0, hi=10.0, lo_open=True)
    law.close()
    return ratio, params
