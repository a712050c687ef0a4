"""Stages that fail on a share of engines: counted per chunk, and a run stopped when the share is too large.

A solver that fails on one engine marks it with a status code; a stage that
fails on many engines almost always means wrong input (a length in the wrong
unit, a scheme that does not fit the engine), and its results would be
misleading. :class:`FailureCount` adds up, per stage, the engines or bearings
a stage failed on; :func:`check` stops the run when a share exceeds the
study's ``failure_limit``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..assembly import BLOCK_SCRAPPED, CRANK_SCRAPPED, NOT_GRADED, STATUS
from ..crank.cycle import CYCLE_STATUS, NOT_COMPUTED
from ..film.cycle import FILM_STATUS, NOT_A_NUMBER

#: Failures of each stage, what they are counted among, and their likely cause.
STAGES = {
    "grading": ("bearings with parts inside their drawing limits",
                "the scheme's grade ranges do not cover the engine's bores and journals: check the units and "
                "limits of the engine's housing_bore and journal_d and the scheme's grades"),
    "crankshaft": ("engines of the mechanical chain",
                   "the crankshaft beam did not converge: check the engine's [crank] section (spans, section "
                   "inertias, loads, units) and its [bearing_law]"),
    "film": ("bearings of the mechanical chain",
             "the journal orbit did not become periodic, or the film collapsed (a load turning at half the shaft "
             "speed, or too little film for the load; those bearings' films and lives are NaN): check the engine's loads, speed, bearing width and "
             "clearance, and the oil"),
    "heat balance": ("bearings of the mechanical chain",
                     "no oil temperature balances the film's friction below 250 degC: check the engine's [oil] and "
                     "[oil_feed] (supply pressure, groove or hole) and the bearing's clearance and width"),
}
#: Fewest engines or bearings counted before a share can stop a run.
MIN_COUNTED = 20


@dataclass
class FailureCount:
    """Failed and counted items per stage, added over chunks."""

    failed: dict = field(default_factory=lambda: {stage: 0 for stage in STAGES})
    counted: dict = field(default_factory=lambda: {stage: 0 for stage in STAGES})

    def add(self, status_counts, crank_status, heat_status=None, film_status=None):
        """Add bearings per assembly status (:data:`stackup.assembly.STATUS` codes), crank, heat and film codes.

        ``heat_status`` and ``film_status`` (engines, bearings) of the engines the crankshaft stage ran on,
        or None. A film whose orbit touched an edge is a result, not a failure.
        """
        counts = np.asarray(status_counts)  # a stock-out is a result of the shell supply, not a failure
        self.failed["grading"] += int(counts[NOT_GRADED])
        self.counted["grading"] += int(counts.sum() - counts[BLOCK_SCRAPPED] - counts[CRANK_SCRAPPED])
        crank = np.asarray(crank_status)
        self.failed["crankshaft"] += int(np.count_nonzero(np.isin(crank, _CRANK_FAILED)))
        self.counted["crankshaft"] += int(np.count_nonzero(crank != NOT_COMPUTED))
        if heat_status is not None:
            heat = np.asarray(heat_status)[np.asarray(crank) != NOT_COMPUTED]
            self.failed["heat balance"] += int(np.count_nonzero(heat != 0))
            self.counted["heat balance"] += int(heat.size)
        if film_status is not None:
            film = np.asarray(film_status)[np.asarray(crank) != NOT_COMPUTED]
            self.failed["film"] += int(np.count_nonzero(np.isin(film, _FILM_FAILED)))
            self.counted["film"] += int(film.size)
        return self

    def merge(self, other):
        """Add another count to this one."""
        for stage in STAGES:
            self.failed[stage] += other.failed[stage]
            self.counted[stage] += other.counted[stage]
        return self

    @classmethod
    def of_chunk(cls, result):
        """The failures of a :class:`~stackup.study.chain.ChunkResult`."""
        counts = np.bincount(result.per_engine["status"].ravel(), minlength=len(STATUS))
        return cls().add(counts, result.per_mech["crank_status"], result.per_mech["heat_status"],
                         result.per_mech.get("film_status"))

    @classmethod
    def of_dataset(cls, ds):
        """The failures recorded in a study dataset (every engine kept, or summaries)."""
        if ds.attrs.get("kept") == "summaries":
            counts = ds.status_count.sum("scheme").values
        else:
            counts = np.bincount(ds.status.values.ravel(), minlength=len(STATUS))
        return cls().add(counts, ds.crank_status.values,
                         ds.heat_status.values if "heat_status" in ds else None,
                         ds.film_status.values if "film_status" in ds else None)

    def shares(self):
        """Share of failures per stage (NaN where nothing was counted)."""
        return {stage: self.failed[stage] / self.counted[stage] if self.counted[stage] else np.nan for stage in STAGES}

    def check(self, limit):
        """Raise StageFailure for the first stage whose share of failures exceeds ``limit``."""
        for stage, share in self.shares().items():
            if self.counted[stage] >= MIN_COUNTED and share > limit:
                among, cause = STAGES[stage]
                raise StageFailure(f"{stage}: failed on {self.failed[stage]:,} of {self.counted[stage]:,} "
                                   f"{among} ({100 * share:.1f} %, more than the study's failure_limit of "
                                   f"{100 * limit:g} %); likely cause: {cause}. Set failure_limit=1.0 to run anyway.")

    def lines(self):
        """One plain line per stage that failed anywhere, for logs and the report."""
        return [f"{stage}: failed on {self.failed[stage]:,} of {self.counted[stage]:,} {STAGES[stage][0]} "
                f"({100 * share:.2f} %)" for stage, share in self.shares().items() if self.failed[stage]]


class StageFailure(ValueError):
    """A stage failed on more engines than the study allows."""


_CRANK_FAILED = [CYCLE_STATUS.index("max_iterations"), CYCLE_STATUS.index("not_finite")]
_FILM_FAILED = [FILM_STATUS.index(s) for s in NOT_A_NUMBER]
