"""What every chunk of a study needs that follows from its parameters alone, built once per process."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace

import numpy as np

from .._version import __version__
from .._random import seed_sequence
from ..film.cycle import cheapest_film_method
from .scenario import apply as apply_scenario
from .inputs import digest, load_inputs
from .pilot import pilot_parts, shell_plan


@dataclass(frozen=True)
class Context:
    """A study's engine, schemes, shell aims and sizes.

    Attributes
    ----------
    engine : Engine
        With the study's scenario applied.
    schemes : list of Scheme
    shares : list
        Per scheme, the share of each lot aimed at each shell grade (None for sorted shells).
    grade_labels : list of str
        Shell grade labels of all schemes, in dataset order.
    root : numpy.random.SeedSequence
    lot : int
        Engines per production lot.
    n_engines, n_lots : int
    mechanics : int
        Engines the mechanical chain may run on (0 without a crank section).
    film_method : str
        Film method used (``"auto"`` resolved, :data:`stackup.film.cycle.FILM_METHODS`).
    crank_angle : numpy.ndarray
        Crank-angle grid [deg].
    """

    engine: object
    schemes: list
    shares: list
    grade_labels: list
    root: object
    lot: int
    n_engines: int
    n_lots: int
    mechanics: int
    film_method: str
    crank_angle: np.ndarray

    def bounds(self, first, chunk_lots):
        """Lots of chunk ``first`` and the study numbers of its first and past-last engines."""
        lots = range(first, min(first + chunk_lots, self.n_lots))
        return lots, lots[0] * self.lot, min((lots[-1] + 1) * self.lot, self.n_engines)


def fingerprint(study):
    """The study's identity: its parameters, the texts of its input files and the package version."""
    return json.dumps({"study": study.parameters(), "inputs": digest(study.files), "version": __version__},
                      sort_keys=True)


#: The context of the study this process works on (one at a time).
_CACHE = {}


def context(study):
    """The :class:`Context` of ``study``, cached in this process (workers build it once)."""
    key = fingerprint(study)
    if key not in _CACHE:
        engine, schemes = load_inputs(study.files, study.schemes)
        engine = apply_scenario(engine, study.scenario)
        if study.window is not None:
            engine = replace(engine, clearance_window=study.window)
        names = [s.name for s in schemes]
        if len(set(names)) != len(names):
            raise ValueError(f"schemes: two files carry the same scheme name ({names})")
        pilot = pilot_parts(engine, study.seed, study.pilot_engines)
        shares = [shell_plan(engine, s, pilot).aim for s in schemes]
        lot = engine.shell_wall.lot_engines
        _CACHE.clear()
        _CACHE[key] = Context(
            engine=engine, schemes=schemes, shares=shares, grade_labels=_union_labels(schemes),
            root=seed_sequence(study.seed), lot=lot, n_engines=study.n_engines,
            n_lots=math.ceil(study.n_engines / lot),
            mechanics=min(study.mechanics_engines, study.n_engines) if engine.crank is not None else 0,
            film_method=cheapest_film_method(study.film_error) if study.film_method == "auto" else study.film_method,
            crank_angle=np.arange(0.0, 720.0, study.crank_angle_step))
    return _CACHE[key]


def _union_labels(schemes):
    labels = []
    for s in schemes:
        for lab in s.shell.labels:
            if lab not in labels:
                labels.append(lab)
    return sorted(labels, key=lambda x: (x != "-", x))
