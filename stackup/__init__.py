"""stackup: Monte Carlo tolerance stack-up and selective assembly of engine main bearings.

The package is built in layers; each imports only the layers below it
(checked by import-linter, ``lint-imports``, with the contracts in
``pyproject.toml``):

application
    :mod:`~stackup.cli` over its subcommands (:mod:`~stackup.commands`, a
    module each), :mod:`~stackup.comparison` (the main job into a folder,
    :func:`stackup.comparison.run`), :mod:`~stackup.difference` (two saved
    comparisons compared), :mod:`~stackup.report`,
    :mod:`~stackup.io` and :mod:`~stackup.output`, and the comparison in
    memory (:func:`compare`, ``stackup._comparison``).
analysis
    in three sub-layers: :mod:`~stackup.rank`; over :mod:`~stackup.facts` (the
    numbers of a comparison, which the ranking and the report share) and
    :mod:`~stackup.design`; over :mod:`~stackup.plan`,
    :mod:`~stackup.sensitivity`, :mod:`~stackup.tail`,
    :mod:`~stackup.scenarios` and :mod:`~stackup.measure`.
study
    :mod:`~stackup.study`: the chain where the stages meet, the dataset
    schema, sinks, store, schedulers and the one bearing -> operating
    clearance core.
engine description
    :mod:`~stackup.engines`: an engine file read into the stages' inputs;
    :mod:`~stackup.patterns`: ISO 13778's schemes laid on an engine's drawing.
stages
    :mod:`~stackup.assembly`, :mod:`~stackup.crank`, :mod:`~stackup.film`,
    :mod:`~stackup.fit`, :mod:`~stackup.life`, :mod:`~stackup.loads`,
    :mod:`~stackup.parts`, :mod:`~stackup.schemes` (none imports another),
    over the shared models :mod:`~stackup.contact`,
    :mod:`~stackup.materials`, :mod:`~stackup.tolerances` and the numba
    kernels in ``stackup._kernels``.
base
    validation (``_validate``), file reading (``_files``), seeding
    (``_random``), :mod:`~stackup.stats`, the version and callable modules.

The public names of the package face: :class:`Study`, :func:`compare`
(:class:`Comparison`), :mod:`rank` and :mod:`plan` (modules that are also
called as their main function: ``stackup.rank(ds)``, ``stackup.plan(ds,
volume=...)``), :mod:`design`.
"""

import importlib

from ._version import __version__

__all__ = ["Comparison", "Study", "compare", "design", "plan", "rank", "__version__"]

#: The package face, imported on first use (PEP 562): ``import stackup`` and the command line start at once, so a
#: Ctrl-C in the first seconds reaches the command's handler rather than the middle of importing numba and xarray.
_FACE = {"Comparison": "._comparison", "compare": "._comparison", "Study": ".study", "design": None, "plan": None,
         "rank": None}


def __getattr__(name):
    if name not in _FACE:
        raise AttributeError(f"module 'stackup' has no attribute {name!r}")
    if _FACE[name] is None:
        return importlib.import_module(f".{name}", __name__)
    return getattr(importlib.import_module(_FACE[name], __name__), name)


def __dir__():
    return sorted(set(globals()) | set(__all__))
