"""A study: one scenario (engine, schemes, size, seed) run into one xarray Dataset.

The package is split by job:

- :mod:`~stackup.study.study`: the :class:`Study`, its parameters and its run;
- :mod:`~stackup.study.chain`: what is computed, the one place where the
  stages meet (parts -> assembly -> press fit -> crankshaft -> film -> life)
  for a chunk of production lots;
- :mod:`~stackup.study.schema`: how results are shaped, every dataset
  variable declared once;
- :mod:`~stackup.study.sinks`, :mod:`~stackup.study.summaries`,
  :mod:`~stackup.study.store`: where results go (memory, a Zarr store,
  streaming summaries);
- :mod:`~stackup.study.schedule`: where chunks run (this process, local
  processes, a dask cluster);
- :mod:`~stackup.study.context` and :mod:`~stackup.study.pilot`: what every
  chunk needs that follows from the parameters (engine, schemes, shell aims
  from the pilot sample).
"""

from ..patterns import ISO_SCHEMES
from .schedule import WORKER_MALLOC
from .store import open_study
from .study import MECHANICS_ENGINES, PARAMETERS, Study

__all__ = ["ISO_SCHEMES", "MECHANICS_ENGINES", "PARAMETERS", "Study", "WORKER_MALLOC", "open_study"]
