"""Press fit, housing swell and temperature: the operating clearance of a main bearing.

Public entry points :func:`press_fit` (one temperature) and
:func:`press_fit_extremes` (the check over the declared temperatures: highest
shell stress, lowest contact pressure), both in :mod:`stackup.fit.interference`,
with tiers

- ``"lame"`` (default): closed-form thick rings of steel-equivalent wall,
  exact within linear plane-stress elasticity for unlined shells; numba kernel.
- ``"thin-ring"``: the shell as a thin ring (uniform hoop stress, wall
  unchanged), the classic shop formula; numba kernel.
- ``"fe"``: the reference, radial finite elements of both rings (the shell
  as bonded steel back and lining) with contact; slow, for validation.

Each tier's error against ``"fe"`` and its speed are measured in
``reports/press_fit_tiers.md`` (``studies/press_fit_tiers.py``).

The model (Kopeliovich, *Crush height of engine bearings*) and its
equations: :mod:`stackup.fit.tiers`. The design limits (least contact
pressure, largest shell stress) and the temperatures to check are engine
data with their source (``[press_fit]`` and ``[press_fit.limits]`` of an
engine file, :class:`stackup.engines.PressFitLimits`).
"""

from . import reference, tiers
from .interference import (CHECK_STRESS, METHODS, TEMPERATURE, TIER_NOTES, PressFit, PressFitExtremes, press_fit,
                           press_fit_extremes)

__all__ = ["CHECK_STRESS", "METHODS", "PressFit", "PressFitExtremes", "TEMPERATURE", "TIER_NOTES", "press_fit",
           "press_fit_extremes", "reference", "tiers"]
