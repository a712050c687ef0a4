"""Materials as data: Young's modulus, Poisson's ratio and thermal expansion.

Built-in entries live in ``stackup/data/materials.toml`` with their sources;
:func:`load` adds or overrides entries from a user file of the same layout,
and :func:`get` also accepts a :class:`Material` directly.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from . import _validate as check


@dataclass(frozen=True)
class Material:
    """Linear-elastic, isotropic material.

    Attributes
    ----------
    name : str
    modulus : float
        Young's modulus [Pa].
    poisson : float
        Poisson's ratio [-].
    expansion : float
        Linear thermal expansion coefficient [1/K].
    source : str
    """

    name: str
    modulus: float
    poisson: float
    expansion: float
    source: str = ""

    def __post_init__(self):
        check.positive(f"material {self.name!r} modulus", self.modulus)
        check.in_range(f"material {self.name!r} poisson", self.poisson, -1.0, 0.5, lo_open=True, hi_open=True)
        check.finite(f"material {self.name!r} expansion", self.expansion)


def _read(path):
    with open(path, "rb") as f:
        data = tomllib.load(f)
    if data.pop("units", "SI") != "SI":
        raise ValueError(f"materials file {Path(path).name!r}, key units: only 'SI' is supported")
    out = {}
    for name, entry in data.items():
        missing = {"modulus", "poisson", "expansion"} - set(entry)
        if missing:
            raise ValueError(f"materials file {Path(path).name!r}, key {name}: missing {sorted(missing)}")
        out[name] = Material(name, float(entry["modulus"]), float(entry["poisson"]), float(entry["expansion"]),
                             str(entry.get("source", "")))
    return out


_REGISTRY = _read(resources.files("stackup") / "data" / "materials.toml")


def available():
    """Names of the known materials."""
    return sorted(_REGISTRY)


def load(path):
    """Add or override materials from a TOML file; return the names it defined."""
    entries = _read(path)
    _REGISTRY.update(entries)
    return sorted(entries)


def get(material):
    """A :class:`Material` from its name (or the Material itself)."""
    if isinstance(material, Material):
        return material
    if material not in _REGISTRY:
        raise ValueError(f"material: {material!r} is not a known material ({', '.join(available())})")
    return _REGISTRY[material]
