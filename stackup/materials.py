"""Materials as data: Young's modulus, Poisson's ratio and thermal expansion.

Built-in entries live in ``stackup/data/materials.toml`` with their sources;
:func:`load` adds or overrides entries from a user file of the same layout,
and :func:`get` also accepts a :class:`Material` directly.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from importlib import resources
from pathlib import Path

from . import _validate as check
from ._files import Table, read_toml


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
        check.fields(self, {"modulus": check.Positive(), "poisson": check.POISSON,
                            "expansion": check.Finite()}, prefix=f"material {self.name!r} ")


def _read(path):
    """The materials of a file: ``units = "SI"`` and one table per material (see the built-in file)."""
    data, _ = read_toml(path, kind="materials")
    top = Table(data, f"materials file {Path(path).name!r}")
    top.text("units", "SI", options=("SI",))
    out = {}
    for name in [k for k in data if k != "units"]:
        t = top.table(name)
        t.text("title", "")  # a description for the reader of the file
        # SI only: a modulus in GPa (210) or an expansion in um/(m K) (11.5) is refused as implausible.
        out[name] = Material(name,
                             t.number("modulus", required=True, lo=1e8, hi=1e13, unit=" Pa"),
                             t.number("poisson", required=True, **asdict(check.POISSON)),
                             t.number("expansion", required=True, lo=-1e-4, hi=1e-4, unit=" 1/K"),
                             t.text("source", ""))
        t.close()
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


def get(material, *, field="material"):
    """A :class:`Material` from its name (or the Material itself); ``field`` names the argument in messages."""
    if isinstance(material, Material):
        return material
    if material not in _REGISTRY:
        raise ValueError(f"{field}: {material!r} is not a known material ({', '.join(available())})")
    return _REGISTRY[material]


@dataclass(frozen=True)
class Known:
    """A declared check (:func:`stackup._validate.validated`): a known material's name, or a Material.

    Gives the Material.
    """

    def __call__(self, field, value):
        return get(value, field=field)
