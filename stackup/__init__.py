"""stackup: Monte Carlo tolerance stack-up and selective assembly of engine main bearings.

The package is built in layers; each imports only the layers below it
(checked by import-linter, ``lint-imports``, with the contracts in
``pyproject.toml``):

application
    :mod:`~stackup.comparison` (the main job, :func:`compare`),
    :mod:`~stackup.io`, :mod:`~stackup.report`, :mod:`~stackup.cli`
    (with :mod:`~stackup.design_cli` and :mod:`~stackup.output`).
analysis
    :mod:`~stackup.facts` (the numbers of a comparison, which the ranking and
    the report share), :mod:`~stackup.rank`, :mod:`~stackup.plan`,
    :mod:`~stackup.sensitivity`, :mod:`~stackup.tail`, :mod:`~stackup.design`,
    :mod:`~stackup.scenarios`.
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

from . import design, plan, rank
from ._version import __version__
from .comparison import Comparison, compare
from .study import Study

__all__ = ["Comparison", "Study", "compare", "design", "plan", "rank", "__version__"]
