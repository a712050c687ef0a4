"""Engine definitions as data: the main-bearing parts and how they are made.

An engine file (TOML, lengths in mm) names its number of main bearings and,
per dimension, the drawing limits, the process, the gauge and the share of
variance common to one block or crankshaft. Built-in engines ship in
``stackup/data/engines``; a user's file works the same way, by path.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from . import _validate as check
from . import materials
from .parts import ShellSupply
from .tolerances import Dimension, gauge_from_spec, process_from_spec

_UNITS = {"mm": 1e-3, "m": 1.0}


@dataclass(frozen=True)
class PressFitSpec:
    """How the shells sit in the housing: keyword arguments of :func:`stackup.fit.press_fit` [SI]."""

    housing_outer: float
    housing_material: str
    shell_material: str
    journal_material: str
    length: float
    check_bore: float
    check_stress: float
    assembly_temperature: float
    temperature: float

    def kwargs(self):
        return dict(self.__dict__)


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
        return Dimension(key, lo, hi, process, gauge, shared)

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

    def temperature(name):
        return float(check.in_range(f"{key}.{name}", fit_table.pop(name, 20.0), -60.0, 300.0, unit=" degC"))

    def material(name):
        return materials.get(fit_table.pop(name, "steel")).name

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
    )
    if fit_table:
        raise ValueError(f"{key}: unknown key(s) {sorted(fit_table)}")
    if spec.housing_outer <= bore.hi:
        raise ValueError(f"{key}.housing_outer: {spec.housing_outer / scale!r} {units} is not above the housing bore")
    return Engine(
        name=str(data.get("name", path.stem)),
        title=str(data.get("title", "")),
        source=str(data.get("source", "")),
        main_bearings=bearings,
        housing_bore=bore,
        journal_d=dimension("journal_d"),
        shell_wall=supply,
        press_fit=spec,
    )
