"""The scheme-comparison report, from saved study datasets alone.

Every number comes from the facts of the comparison (:func:`stackup.facts.facts`:
the study dataset, every engine kept or its streaming summaries, the
scenario datasets, the sensitivity dataset and the tail estimates of a
:class:`stackup.comparison.Comparison`); nothing is sampled or modelled here.

- :mod:`~stackup.report.write`: :func:`write_report`, the report and its figures into a folder;
- :mod:`~stackup.report.templates`: every sentence, as templates;
- :mod:`~stackup.report.format`: how numbers, intervals and units are written;
- :mod:`~stackup.report.verdict`, :mod:`~stackup.report.methods`,
  :mod:`~stackup.report.sections`, :mod:`~stackup.report.mechanics`: the
  sections, filled from the facts;
- :mod:`~stackup.report.figures`: the figures (drawn from the datasets);
- :mod:`~stackup.report.html`: the self-contained HTML page.
"""

from ..facts import bearing_summary, clearance_summary, crank_summary, film_summary, fit_summary, grade_usage
from .html import markdown_to_html
from .sections import markdown_table
from .write import SECTIONS, report_lines, write_report

__all__ = ["SECTIONS", "bearing_summary", "clearance_summary", "crank_summary", "film_summary", "fit_summary",
           "grade_usage", "markdown_table", "markdown_to_html", "report_lines", "write_report"]
