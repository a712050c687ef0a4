"""The report written: :func:`write_report` puts ``report.md``, ``report.html`` and the figures in a folder.

The sections in report order (:data:`SECTIONS`), each filled from the facts
by its own module; :func:`report_lines` joins them into the markdown text.
"""

from __future__ import annotations

from pathlib import Path

from ..facts import PLAN_VOLUME, facts
from ..rank import ranked
from . import figures
from . import format as fmt
from . import templates as words
from .html import anchor, markdown_to_html
from .mechanics import film_section
from .methods import limits_of_validity, methods, parameters_table, parameters_text
from .sections import (assembly_section, clearance_section, design_section, fit_section, markdown_table,
                       plan_section, ranking_section, scenarios_section, section, sensitivity_section)
from .spreadsheets import write_tables
from .verdict import decision_table, verdict

#: Sections in report order (their headings; the verdict and the decision table come before them).
SECTIONS = ("Ranking", "Scenarios", "Designed scheme", "What drives the spread", "Clearance per scheme",
            "Operating clearance: press fit, housing swell and temperature", "Loads, oil film and bearing life",
            "Assembly, scrap and stock", "Planning: shells per grade",
            "Methods and assumptions", "Limits of validity", "Parameters")


def write_report(ds, out_dir, *, scenarios=None, sensitivity=None, tails=None, dataset_file=None, negligible=None,
                 volume=PLAN_VOLUME, tables=False):
    """Write ``report.md``, its self-contained twin ``report.html`` and the figures into ``out_dir``.

    Parameters
    ----------
    ds : xarray.Dataset
        A study dataset, every engine kept or its streaming summaries (then
        the sections that need every engine say so).
    scenarios : dict of str -> xarray.Dataset, optional
        The study under declared scenarios (:class:`stackup.comparison.Comparison`).
    sensitivity : xarray.Dataset, optional
        Contributions of the inputs (:func:`stackup.comparison.sensitivity_dataset`).
    tails : xarray.Dataset, optional
        Tail estimates beyond the window (:func:`stackup.comparison.tails_dataset`),
        used by the ranking where too few bearings are counted outside.
    dataset_file : str, optional
        Name of the saved dataset, quoted in the report.
    negligible : float, optional
        Shares outside the window less than this apart do not separate
        schemes [ppm]; default the comparison's (:func:`stackup.rank.rank`).
    volume : int
        Engines the shell plan is for.
    tables : bool
        Also write the ranking, film and life tables as CSV files beside the
        report (:mod:`~stackup.report.spreadsheets`).

    Returns
    -------
    pathlib.Path
        The markdown report.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    known = facts(ds, scenarios=scenarios, sensitivity=sensitivity, tails=tails, negligible=negligible,
                  volume=volume)
    order = list(ranked(known.ranking).index)
    _draw(ds.sel(scheme=order), None if sensitivity is None else _in_order(sensitivity, order), known, out)
    text = "\n".join(report_lines(known, dataset_file=dataset_file)) + "\n"
    path = out / "report.md"
    path.write_text(text)
    (out / "report.html").write_text(markdown_to_html(text, out))
    if tables:
        write_tables(known, out)
    return path


def _in_order(sensitivity, order):
    """The sensitivity dataset with its schemes in the ranking's order."""
    return sensitivity.sel(scheme=[s for s in order if s in sensitivity.scheme.values])


def _draw(ds, sensitivity, known, out):
    """The figures the report shows, drawn from the datasets into ``out``."""
    if known.drivers is not None:
        figures.sensitivity_chart(sensitivity, out / "sensitivity.png")
    figures.clearance_histogram(ds, out / "clearance_histogram.png")
    if len(known.film):
        figures.film_by_bearing(ds, out / "film_life.png")
        figures.film_life_by_clearance(ds, out / "film_life_clearance.png")
    figures.grade_usage_chart(ds, out / "grade_usage.png")


def _header(known):
    about = known.about
    kept = words.SUBTITLE_SUMMARIES_PART if about.summaries else ""
    return [words.TITLE.format(engine=about.engine), "",
            words.SUBTITLE.format(title=about.title, version=about.version, seed=about.seed,
                                  n_engines=fmt.count(known.study.n_engines), bearings=about.bearings, kept=kept,
                                  negligible=fmt.general(known.ranking.negligible)),
            ""]


def _contents(known):
    """The line of links to the sections (the designed scheme's only where there is one)."""
    titles = [title for title in SECTIONS if title != "Designed scheme" or known.design is not None]
    return words.CONTENTS.format(links=" · ".join(
        words.CONTENTS_LINK.format(title=words.CONTENTS_SHORT.get(title, title), anchor=anchor(title))
        for title in titles))


def report_lines(known, *, dataset_file=None):
    """The report's markdown lines from the :class:`~stackup.facts.Facts` ``known`` (figures drawn apart)."""
    ranking = ranked(known.ranking)
    scenario_rankings = {label: ranked(rows) for label, rows in known.scenario_rankings.items()}
    return [
        *_header(known),
        *verdict(known, ranking, scenario_rankings),
        "",
        markdown_table(decision_table(known, ranking)),
        "",
        _contents(known),
        "",
        *ranking_section(known, ranking),
        *scenarios_section(known, ranking, scenario_rankings),
        *design_section(known, ranking),
        *sensitivity_section(known, ranking),
        *clearance_section(known, ranking),
        *fit_section(known, ranking),
        *film_section(known, ranking),
        *assembly_section(known, ranking),
        *plan_section(known, ranking),
        *section("Methods and assumptions", *methods(known)),
        *section("Limits of validity", *limits_of_validity(known)),
        *section("Parameters", parameters_text(parameters_table(known)) + " " + words.PARAMETERS_DEFAULTS,
                 *(["", words.DATASET.format(file=dataset_file)] if dataset_file else [])),
    ]

