"""The facts of a scheme comparison: every number a report states, computed once from the saved datasets.

:func:`facts` reads a study dataset (every engine kept, or its streaming
summaries) with its scenarios, sensitivity and tail estimates (a
:class:`stackup.comparison.Comparison`, or the datasets) and returns
:class:`Facts`: plain data, per scheme and per bearing position the numbers
with their 95 % intervals, the rows the ranking ranks
(:func:`stackup.rank.ranked` orders them; :func:`stackup.rank.rank` uses
the same rows), and the study's parameters, each dataset attribute parsed
in one place (:mod:`~stackup.facts.declared`). Nothing is sampled.

- :mod:`~stackup.facts.gathered`: :func:`facts` and the study's own facts, gathered into :class:`Facts`;
- :mod:`~stackup.facts.declared`: the dataset attributes, with the keys they must hold;
- :mod:`~stackup.facts.tables`: numbers per scheme (and bearing position), with intervals;
- :mod:`~stackup.facts.metrics`: the ranking's metrics per scheme;
- :mod:`~stackup.facts.mechanics`: loads, film, heat balance, edge contact and life of the mechanical chain;
- :mod:`~stackup.facts.iso`: the standard's schemes laid on the engine's drawing, their caveats and anchor.
"""

from .declared import (DesignRecord, FilmErrors, PressFit, Processes, ScenarioAbout, Sources, StudyParameters, Wear,
                       parsed, plain)
from .gathered import (PLAN_SERVICE_LEVEL, PLAN_VOLUME, About, Design, Facts, Limits, Run, Scrap, designed, drivers,
                       facts)
from .mechanics import (ClearanceTrends, EdgeContact, FilmOutcomes, HeatBalance, LifeBias, Positions,
                        clearance_trends, edge_contact, film_detail, film_outcomes, heat_balance, life_bias, positions)
from .metrics import (MIN_COUNTED, NEGLIGIBLE_PPM, TAIL_SOURCES, RankingRows, counted_outside, part_grades,
                      ranking_rows)
from .tables import (UM, bearing_summary, centred, clearance_summary, converged_engines, crank_summary,
                     film_summary, fit_summary, grade_usage, kept_summaries, multi_fidelity, paired_life_changes,
                     position_risks, separates)

__all__ = ["About", "ClearanceTrends", "Design", "DesignRecord", "EdgeContact", "Facts", "FilmErrors", "FilmOutcomes",
           "HeatBalance", "LifeBias", "Limits", "MIN_COUNTED", "NEGLIGIBLE_PPM", "PLAN_SERVICE_LEVEL", "PLAN_VOLUME",
           "Positions", "PressFit", "Processes", "RankingRows", "Run", "ScenarioAbout", "Scrap", "Sources",
           "StudyParameters", "TAIL_SOURCES", "UM", "Wear", "bearing_summary", "centred", "clearance_summary",
           "clearance_trends", "converged_engines", "counted_outside", "crank_summary", "designed", "drivers",
           "edge_contact", "facts", "film_detail", "film_outcomes", "film_summary", "fit_summary", "grade_usage",
           "heat_balance", "kept_summaries", "life_bias", "multi_fidelity", "paired_life_changes", "parsed",
           "part_grades", "plain", "position_risks", "positions", "ranking_rows", "separates"]
