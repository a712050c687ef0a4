"""Robustness scenarios: the declared set a comparison runs beside its study.

A scenario is plain data (a dict of the keys :data:`KEYS`, explained in
:mod:`stackup.study.scenario`), applied to an engine by :func:`apply`.
"""

from __future__ import annotations

from .study.scenario import KEYS, apply

#: The declared scenario set of the comparison report: process mean shift +-1 sigma,
#: gauge error up to 2 um, doubled misalignment.
DECLARED = {
    "bore mean +1σ": {"housing_shift": 1.0},
    "bore mean −1σ": {"housing_shift": -1.0},
    "journal mean +1σ": {"journal_shift": 1.0},
    "journal mean −1σ": {"journal_shift": -1.0},
    "gauge repeatability 2 µm": {"gauge_repeatability": 2e-6},
    "misalignment ×2": {"misalignment_scale": 2.0},
}

__all__ = ["DECLARED", "KEYS", "apply"]
