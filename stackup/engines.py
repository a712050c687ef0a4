"""Engine definitions as data: the main-bearing parts and how they are made.

An engine file (TOML, lengths in mm) names its number of main bearings and,
per dimension, the drawing limits, the process, the gauge and the share of
variance common to one block or crankshaft (journals also their form error and
how it is read, housing bores their bolt-tension scatter). ``[press_fit]``
holds the housing ring, materials and shell lining, the checking block, the
temperatures the fit is checked at (``cold_temperature``,
``assembly_temperature``, ``temperature`` for the clearance,
``hot_temperature``) and the source of the crush height;
``[press_fit.limits]`` the design limits with their source; ``[targets]`` the
operating-clearance window (absolute, or ``relative_clearance`` C/D of the
journal) with its source. Built-in engines ship in ``stackup/data/engines``;
a user's file works the same way, by path.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, replace

import numpy as np
from importlib import resources
from pathlib import Path

from . import _validate as check
from . import materials
from .crank import BellakhdharLaw
from .film import oil as film_oil
from .film.heat import FEEDS, OilFeed
from .loads import Combustion, Kinematics, firing_offsets, pin_loads, read_pressure_trace
from .parts import ShellSupply
from .tolerances import Dimension, form_from_spec, gauge_from_spec, process_from_spec

_UNITS = {"mm": 1e-3, "m": 1.0}


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


@dataclass(frozen=True)
class PressFitSpec:
    """How the shells sit in the housing, at which temperatures it is checked, and against which limits [SI].

    :meth:`kwargs` gives the keyword arguments of :func:`stackup.fit.press_fit`
    at the operating temperature (the clearance), :meth:`extremes_kwargs`
    those of :func:`stackup.fit.press_fit_extremes` over :attr:`temperatures`
    (the stress and pressure checks).
    """

    housing_outer: float
    housing_material: str
    shell_material: str
    journal_material: str
    length: float
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

    _FIT = ("housing_outer", "housing_material", "shell_material", "journal_material", "length", "check_bore",
            "check_stress", "assembly_temperature", "lining_thickness", "lining_material")

    def kwargs(self):
        """Keyword arguments of :func:`stackup.fit.press_fit` at the operating temperature."""
        return {**{name: getattr(self, name) for name in self._FIT}, "temperature": self.temperature}

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
    oil: str = "SAE-5W-30"  # stackup.film.oil grade
    oil_supply_temperature: float = 90.0  # [degC]

    def pin_loads(self, crank_angle):
        """Crank-pin loads (angles, cylinders, 2) [N] at crank angles [deg]."""
        return pin_loads(crank_angle, kinematics=self.kinematics, combustion=self.combustion,
                         throw_angles=self.throw_angles, firing_order=self.firing_order, speed=self.speed,
                         pressure_trace=self.pressure_trace)

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
    wear_limit: float  # limiting wear [m]
    wear_rate: float  # wear speed gamma [m/s]
    lining_material: str
    roughness_source: str
    wear_source: str


#: Used when an engine file has no [wear] table: the paper's diesel (h_lim,cr = 1.9 um split between the surfaces).
DEFAULT_WEAR = WearSpec(
    journal_rz=0.8e-6, shell_rz=1.1e-6, journal_rq=0.2e-6, shell_rq=0.3e-6, critical_film=1.9e-6, wear_limit=30e-6,
    wear_rate=1e-13, lining_material="aluminium",
    roughness_source="default: h_lim,cr = 1.9 um of Levanov et al. 2015 split as journal Rz 0.8 um, shell Rz 1.1 um",
    wear_source="default: Levanov et al. 2015, sec. 4 (30 um, 1e-13 m/s)")


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
    life_target: float = 1000.0 * 3600.0  # [s]
    wear: WearSpec = DEFAULT_WEAR  # surfaces and wear limits of the main bearings
    oil_feed: OilFeed | None = None  # how the oil enters each main bearing (stackup.film.heat)

    @property
    def press_fit_limits(self):
        """The engine's press-fit design limits with their source (:class:`PressFitLimits`)."""
        return self.press_fit.limits


def _builtin_dir():
    return Path(str(resources.files("stackup") / "data" / "engines"))


def available_engines():
    """Names of the built-in engines."""
    return sorted(p.stem for p in _builtin_dir().glob("*.toml"))


def load_engine(name_or_path):
    """Load an engine by built-in name (``"iso-example"``) or from a TOML file path."""
    if isinstance(name_or_path, Engine):
        return name_or_path
    text = os.fspath(name_or_path)
    path = Path(text)
    if not path.is_file():
        path = _builtin_dir() / f"{text}.toml"
        if not path.is_file():
            raise ValueError(f"engine: {text!r} is not a built-in engine ({', '.join(available_engines())}) nor a file")
    where = f"engine file {path.name!r}"
    with open(path, "rb") as f:
        data = tomllib.load(f)
    units = data.get("units")
    if units not in _UNITS:
        raise ValueError(f"{where}, key units: {units!r} is not one of {', '.join(map(repr, _UNITS))}")
    scale = _UNITS[units]
    bearings = check.integer(f"{where}, key main_bearings", data.get("main_bearings"), minimum=1)

    def dimension(key):
        table = data.get(key)
        if table is None:
            raise ValueError(f"{where}: missing key '{key}'")
        if "limits" not in table:
            raise ValueError(f"{where}, key {key}.limits: missing")
        lo, hi = check.limits(f"{where}, key {key}.limits", *table["limits"], unit=units)
        lo, hi = lo * scale, hi * scale
        process = process_from_spec(table.get("process", {}), lo=lo, hi=hi, scale=scale, field=f"{where}, key {key}.process")
        gauge = gauge_from_spec(table.get("gauge"), scale=scale, field=f"{where}, key {key}.gauge")
        shared = float(check.in_range(f"{where}, key {key}.shared", table.get("shared", 0.0), 0.0, 1.0, hi_open=True))
        form = form_from_spec(table.get("form"), scale=scale, field=f"{where}, key {key}.form")
        if form is not None:
            # the gauge's readings are those of the form's planes and directions, averaged
            if "readings" in (table.get("gauge") or {}) and gauge.readings != form.readings:
                raise ValueError(f"{where}, key {key}.gauge.readings: {gauge.readings} readings, but the form is read "
                                 f"in {form.readings} (planes x directions)")
            gauge = replace(gauge, readings=form.readings, combine="mean")
        bolt = float(check.positive(f"{where}, key {key}.bolt_scatter", table.get("bolt_scatter", 0.0),
                                    allow_zero=True)) * scale
        return Dimension(key, lo, hi, process, gauge, shared, form=form, bolt_scatter=bolt,
                         source=str(table.get("source", "")))

    shell = dict(data.get("shell_wall", {}))
    key = f"{where}, key shell_wall"
    mode = check.one_of(f"{key}.supply", shell.pop("supply", "to-order"), ("to-order", "sorted"))
    process = dict(shell.pop("process", {"distribution": "normal", "cpk": 1.33}))
    sigma = shell.pop("sigma", None)
    if mode == "to-order":
        sigma = float(check.positive(f"{key}.sigma", 1e-6 / scale if sigma is None else sigma)) * scale
    supply = ShellSupply(
        mode=mode,
        process=process,
        sigma=sigma,
        target_offset=float(check.finite(f"{key}.target_offset", shell.pop("target_offset", 0.0))) * scale,
        gauge=gauge_from_spec(shell.pop("gauge", None), scale=scale, field=f"{key}.gauge"),
        lot_engines=check.integer(f"{key}.lot_engines", shell.pop("lot_engines", 1000), minimum=1),
        surplus=float(check.in_range(f"{key}.surplus", shell.pop("surplus", 0.1), 0.0, 10.0)),
        crush=dimension("crush_height"),
        scale=scale,
    )
    if shell:
        raise ValueError(f"{key}: unknown key(s) {sorted(shell)}")
    bore = dimension("housing_bore")
    fit_table = dict(data.get("press_fit", {}))
    key = f"{where}, key press_fit"

    def length(name, default=None):
        if name not in fit_table and default is None:
            raise ValueError(f"{key}: missing '{name}'")
        value = fit_table.pop(name, None)
        return default if value is None else float(check.positive(f"{key}.{name}", value)) * scale

    def temperature(name, default=20.0):
        value = fit_table.pop(name, default)
        return None if value is None else float(check.in_range(f"{key}.{name}", value, -60.0, 300.0, unit=" degC"))

    def material(name, default="steel"):
        value = fit_table.pop(name, default)
        return None if value is None else materials.get(value).name

    lining_thickness = float(check.positive(f"{key}.lining_thickness", fit_table.pop("lining_thickness", 0.0),
                                            allow_zero=True)) * scale
    lining_material = material("lining_material", None)
    if lining_thickness > 0 and lining_material is None:
        raise ValueError(f"{key}.lining_material: missing; a lining_thickness > 0 needs the lining's material")
    spec = PressFitSpec(
        housing_outer=length("housing_outer"),
        housing_material=material("housing_material"),
        shell_material=material("shell_material"),
        journal_material=material("journal_material"),
        length=length("length"),
        check_bore=length("check_bore", bore.lo),
        check_stress=float(check.in_range(f"{key}.check_stress", fit_table.pop("check_stress", 100e6), 0.0, 2e9,
                                          lo_open=True, unit=" Pa")),
        assembly_temperature=temperature("assembly_temperature"),
        temperature=temperature("temperature"),
        lining_thickness=lining_thickness,
        lining_material=lining_material,
        cold_temperature=temperature("cold_temperature", None),
        hot_temperature=temperature("hot_temperature", None),
        limits=_limits(fit_table.pop("limits", None), f"{key}.limits"),
        crush_source=str(fit_table.pop("crush_height_source", "")),
    )
    if fit_table:
        raise ValueError(f"{key}: unknown key(s) {sorted(fit_table)}")
    if spec.housing_outer <= bore.hi:
        raise ValueError(f"{key}.housing_outer: {spec.housing_outer / scale!r} {units} is not above the housing bore")
    if spec.cold_temperature is not None and spec.cold_temperature > spec.assembly_temperature:
        raise ValueError(f"{key}.cold_temperature: {spec.cold_temperature!r} degC is above the assembly temperature "
                         f"{spec.assembly_temperature!r} degC; the coldest state checked is the colder of the two")
    if spec.hot_temperature is not None and spec.hot_temperature < spec.temperature:
        raise ValueError(f"{key}.hot_temperature: {spec.hot_temperature!r} degC is below the operating temperature "
                         f"{spec.temperature!r} degC")
    journal = dimension("journal_d")
    return Engine(
        name=str(data.get("name", path.stem)),
        title=str(data.get("title", "")),
        source=str(data.get("source", "")),
        main_bearings=bearings,
        housing_bore=bore,
        journal_d=journal,
        shell_wall=supply,
        press_fit=spec,
        crank=_crank(data, where, scale, bearings, path.parent) if "crank" in data else None,
        **_targets(data, where, scale, units, journal),
        wear=_wear(data, where, scale),
        oil_feed=_oil_feed(data, where, scale, spec.length),
    )


def _wear(data, where, scale):
    """The [wear] table: roughness (Rz, Rq) of journal and shell, lining, limiting wear and wear speed."""
    if "wear" not in data:
        return DEFAULT_WEAR
    table = dict(data["wear"])
    key = f"{where}, key wear"

    def length(name):
        if name not in table:
            raise ValueError(f"{key}: missing '{name}'")
        return float(check.positive(f"{key}.{name}", table.pop(name))) * scale

    def text(name):
        value = table.pop(name, "")
        if not isinstance(value, str) or not value.strip():
            raise ValueError(f"{key}: missing '{name}' (where the numbers come from)")
        return value

    rz1, rz2, rq1, rq2 = (length(n) for n in ("journal_rz", "shell_rz", "journal_rq", "shell_rq"))
    for rz, rq, part in ((rz1, rq1, "journal"), (rz2, rq2, "shell")):
        if rq >= rz:
            raise ValueError(f"{key}.{part}_rq: {rq / scale!r} is not below {part}_rz {rz / scale!r}")
    critical = rz1 + rz2
    if "critical_film" in table:
        given = length("critical_film")
        if given < critical * (1 - 1e-12):
            raise ValueError(f"{key}.critical_film: {given / scale!r} is below journal_rz + shell_rz = "
                             f"{critical / scale!r} (Levanov et al. 2015, eq. 3: h_lim,cr > Rz1 + Rz2)")
        critical = given
    spec = WearSpec(journal_rz=rz1, shell_rz=rz2, journal_rq=rq1, shell_rq=rq2, critical_film=critical,
                    wear_limit=length("wear_limit"), wear_rate=length("wear_rate"),
                    lining_material=materials.get(table.pop("lining_material", "aluminium")).name,
                    roughness_source=text("roughness_source"), wear_source=text("wear_source"))
    if table:
        raise ValueError(f"{key}: unknown key(s) {sorted(table)}")
    return spec


#: Groove width of the default feed, as a share of the bearing length.
_DEFAULT_GROOVE_SHARE = 0.15


def _oil_feed(data, where, scale, bearing_length):
    """The [oil_feed] table: supply pressure [Pa] and the groove or hole (angles in deg, lengths in file units)."""
    if "oil_feed" not in data:
        return OilFeed("groove", 0.3e6, (0.5 * np.pi, 1.5 * np.pi), _DEFAULT_GROOVE_SHARE * bearing_length,
                       source="default: 0.3 MPa into a 180 deg groove in the upper shell, 15 % of the bearing wide")
    table = dict(data["oil_feed"])
    key = f"{where}, key oil_feed"
    kind = check.one_of(f"{key}.feed", table.pop("feed", None), FEEDS)
    pressure = float(check.in_range(f"{key}.supply_pressure", table.pop("supply_pressure", None) or 0.0, 0.0, 2e7,
                                    lo_open=True, unit=" Pa"))
    source = table.pop("source", "")
    if not isinstance(source, str) or not source.strip():
        raise ValueError(f"{key}: missing 'source' (where the numbers come from)")
    if kind == "groove":
        arc = check.finite(f"{key}.groove_arc", table.pop("groove_arc", [90.0, 270.0]))
        if arc.shape != (2,) or not 0 < arc[1] - arc[0] <= 360:
            raise ValueError(f"{key}.groove_arc: {arc.tolist()!r} deg is not valid; need [start, end], "
                             f"start < end <= start + 360")
        width = float(check.positive(f"{key}.groove_width", table.pop("groove_width", 0.0))) * scale
        if width >= bearing_length:
            raise ValueError(f"{key}.groove_width: {width / scale!r} is not below the bearing length")
        feed = OilFeed(kind, pressure, tuple(float(a) for a in np.radians(arc)), width, source=source)
    else:
        diameter = float(check.positive(f"{key}.hole_diameter", table.pop("hole_diameter", 0.0))) * scale
        if diameter >= bearing_length / 2:
            raise ValueError(f"{key}.hole_diameter: {diameter / scale!r} is not below half the bearing length")
        angle = float(check.finite(f"{key}.hole_angle", table.pop("hole_angle", 180.0)))
        feed = OilFeed(kind, pressure, hole_angle=float(np.radians(angle)), hole_diameter=diameter, source=source)
    if table:
        raise ValueError(f"{key}: unknown key(s) {sorted(table)}")
    return feed


def _limits(table, key):
    """Press-fit design limits from ``[press_fit.limits]`` (Pa, with their source); Kopeliovich's if absent."""
    if table is None:
        return KOPELIOVICH_LIMITS
    table = dict(table)
    for name in ("contact_pressure_min", "shell_stress_max", "source"):
        if name not in table:
            raise ValueError(f"{key}: missing '{name}' (limits in Pa, with the source they come from)")
    limits = PressFitLimits(
        contact_pressure_min=float(check.positive(f"{key}.contact_pressure_min", table.pop("contact_pressure_min"))),
        shell_stress_max=float(check.positive(f"{key}.shell_stress_max", table.pop("shell_stress_max"))),
        source=str(table.pop("source")),
    )
    if table:
        raise ValueError(f"{key}: unknown key(s) {sorted(table)}")
    if not (1e5 <= limits.contact_pressure_min <= 100e6 and 10e6 <= limits.shell_stress_max <= 2e9):
        raise ValueError(f"{key}: contact_pressure_min {limits.contact_pressure_min!r} Pa, shell_stress_max "
                         f"{limits.shell_stress_max!r} Pa; give the limits in Pa (e.g. 10e6 and 400e6)")
    return limits


def _targets(data, where, scale, units, journal):
    """Design window of the operating clearance (absolute, or relative to the journal) and life target."""
    table = dict(data.get("targets", {}))
    key = f"{where}, key targets"
    out = {}
    forms = [k for k in ("operating_clearance", "relative_clearance") if k in table]
    if len(forms) > 1:
        raise ValueError(f"{key}: give either operating_clearance or relative_clearance, not both")
    if "operating_clearance" in table:
        lo, hi = check.limits(f"{key}.operating_clearance", *table.pop("operating_clearance"), unit=units)
        out["clearance_window"] = (lo * scale, hi * scale)
    if "relative_clearance" in table:
        # psi = C / D of the journal's nominal size (its lower drawing limit)
        lo, hi = check.limits(f"{key}.relative_clearance", *table.pop("relative_clearance"), unit="")
        if lo <= 0 or hi >= 0.01:
            raise ValueError(f"{key}.relative_clearance: [{lo!r}, {hi!r}] is not a clearance ratio C/D in (0, 0.01) "
                             "(write 1 per mille as 0.001)")
        out["clearance_window"] = (lo * journal.lo, hi * journal.lo)
    if "clearance_source" in table:
        out["clearance_window_source"] = str(table.pop("clearance_source"))
    if "life_hours" in table:
        out["life_target"] = float(check.positive(f"{key}.life_hours", table.pop("life_hours"))) * 3600.0
    if table:
        raise ValueError(f"{key}: unknown key(s) {sorted(table)}")
    return out


def _crank(data, where, scale, bearings, folder):
    table = dict(data["crank"])
    key = f"{where}, key crank"

    def pop(name, default=None):
        if name not in table:
            if default is None:
                raise ValueError(f"{key}: missing '{name}'")
            return default
        return table.pop(name)

    def length(name, default=None):
        return float(check.positive(f"{key}.{name}", pop(name, default))) * scale

    cylinders = check.integer(f"{key}.cylinders", pop("cylinders"), minimum=1)
    if cylinders != bearings - 1:
        raise ValueError(f"{key}.cylinders: {cylinders} cylinders need {cylinders + 1} main bearings, "
                         f"the engine has {bearings} (inline engines only)")
    stroke = length("stroke")
    unbalance = float(check.in_range(f"{key}.counterweight_share", pop("counterweight_share", 0.0), 0.0, 2.0))
    rotating = float(check.positive(f"{key}.rotating_mass", pop("rotating_mass"), allow_zero=True))
    kinematics = Kinematics(
        cylinder_bore=length("cylinder_bore"), stroke=stroke, conrod=length("conrod"),
        reciprocating_mass=float(check.positive(f"{key}.reciprocating_mass", pop("reciprocating_mass"), allow_zero=True)),
        rotating_mass=rotating, counterweight_unbalance=unbalance * rotating * stroke / 2)
    trace_file = table.pop("pressure_trace", None)
    trace = read_pressure_trace(folder / trace_file) if trace_file else None
    combustion = Combustion(compression_ratio=float(pop("compression_ratio", 16.0)),
                            peak_pressure=float(pop("peak_pressure", 13e6)))
    throws = tuple(float(a) for a in pop("throw_angles"))
    order = tuple(int(c) for c in pop("firing_order"))
    if len(throws) != cylinders or len(order) != cylinders:
        raise ValueError(f"{key}: throw_angles and firing_order need {cylinders} entries each")
    spans = check.positive(f"{key}.spans", pop("spans")) * scale
    inertia = check.positive(f"{key}.section_inertia", pop("section_inertia")) * scale**4
    if spans.shape != (cylinders,) or inertia.shape not in ((cylinders,), (cylinders, 2)):
        raise ValueError(f"{key}: spans need shape ({cylinders},), section_inertia ({cylinders},) or ({cylinders}, 2)")
    modulus = materials.get(pop("crank_material", "steel")).modulus
    spec = CrankSpec(
        kinematics=kinematics, combustion=combustion, throw_angles=throws, firing_order=order,
        speed=float(check.positive(f"{key}.speed", pop("speed"))) * 2 * np.pi / 60,
        spans=spans, ei=modulus * (inertia if inertia.ndim == 2 else np.stack([inertia, inertia], -1)),
        bearing_width=length("bearing_width"),
        coaxiality=float(check.positive(f"{key}.coaxiality", pop("coaxiality", 0.0), allow_zero=True)) * scale,
        journal_runout=float(check.positive(f"{key}.journal_runout", pop("journal_runout", 0.0), allow_zero=True)) * scale,
        clearance_ratio=1.0, law_parameters={}, pressure_trace=trace,
    )
    if table:
        raise ValueError(f"{key}: unknown key(s) {sorted(table)}")
    firing_offsets(throws, order)
    law = dict(data.get("bearing_law", {}))
    lkey = f"{where}, key bearing_law"
    params = {
        "dx": float(check.positive(f"{lkey}.dx", law.pop("dx", 0.00965e-3 / scale), allow_zero=True)) * scale,
        "k_lv": float(check.positive(f"{lkey}.k_lv", law.pop("k_lv", 0.98e9))),
        "k_hv": float(check.positive(f"{lkey}.k_hv", law.pop("k_hv", 1.72e9))),
        "theta0": np.radians(float(check.finite(f"{lkey}.theta0", law.pop("theta0", 97.0)))),
        "dtheta": np.radians(float(check.positive(f"{lkey}.dtheta", law.pop("dtheta", 15.0)))),
    }
    ratio = float(check.positive(f"{lkey}.clearance_ratio", law.pop("clearance_ratio", 37.0 / 30.0)))
    if law:
        raise ValueError(f"{lkey}: unknown key(s) {sorted(law)}")
    oil_table = dict(data.get("oil", {}))
    okey = f"{where}, key oil"
    grade = film_oil.get(oil_table.pop("grade", "SAE-5W-30")).name
    supply = float(check.in_range(f"{okey}.supply_temperature", oil_table.pop("supply_temperature", 90.0), -30.0, 200.0,
                                  unit=" degC"))
    if oil_table:
        raise ValueError(f"{okey}: unknown key(s) {sorted(oil_table)}")
    return replace(spec, clearance_ratio=ratio, law_parameters=params, oil=grade, oil_supply_temperature=supply)
