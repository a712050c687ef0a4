"""Measured data in: processes from SPC measurements, the housing's stiffness from fitting tests.

Every engine file declares its processes (often "normal, Cpk 1.33") and its
housing as a ring of assumed outer diameter; the verdict depends on both.
This package replaces the assumptions with measurements:

:func:`fit_process` (:func:`fit_csv` for a CSV column)
    Fits candidate models (normal, skew-normal, two-normal mixture, drifting
    mean over a sequence column) to readings of one dimension, chooses one by
    BIC with an Anderson-Darling goodness-of-fit test, removes the gauge's
    repeatability, gives Cpk with its interval and, with a group column, the
    share of variance common to a block's or crankshaft's parts (the engine
    file's ``shared``). ``.to_toml()`` is the engine file's ``process = {...}``
    entry. Methods: :mod:`stackup.measure.process`.
:func:`calibrate_housing`
    Fits the housing's equivalent outer diameter to fitting tests through
    :func:`stackup.fit.press_fit`, with its profile-likelihood interval and
    residuals, and writes it into a copy of the engine file. Methods:
    :mod:`stackup.measure.housing`.
:func:`write_engine`
    A copy of an engine file with measured entries set, comments kept.

Bad data are refused naming the file, the column, the row and what is valid
(:mod:`stackup.measure._data`). The intervals' coverage and the share of right
model choices are measured in ``reports/measured_data.md``
(``studies/measured_data.py``).
"""

from .engine_file import write_engine
from .housing import TEST_COLUMNS, HousingCalibration, calibrate_housing
from .process import Estimate, ProcessFit, fit_csv, fit_process

__all__ = ["Estimate", "HousingCalibration", "ProcessFit", "TEST_COLUMNS", "calibrate_housing", "fit_csv",
           "fit_process", "write_engine"]
