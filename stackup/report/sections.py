"""The report's sections on the clearance side: ranking, designed scheme, drivers, clearance, press fit, stock.

Each builder takes the facts (:class:`stackup.facts.Facts`; the ranking
where it needs the order) and returns the section's markdown lines; the
numbers are written by :mod:`~stackup.report.format`, the words come from
:mod:`~stackup.report.templates`.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..assembly import STATUS
from ..facts import MIN_COUNTED, PLAN_SERVICE_LEVEL, PLAN_VOLUME, TAIL_SOURCES, separates
from . import format as fmt
from . import templates as words


def markdown_table(frame):
    """A DataFrame as a pipe table (index dropped: put what matters in columns)."""
    head = "| " + " | ".join(frame.columns) + " |"
    rule = "|" + "|".join("---" for _ in frame.columns) + "|"
    body = ["| " + " | ".join(str(v) for v in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join([head, rule, *body])


def section(title, *lines):
    """A section: its heading, its lines and a blank line."""
    return [words.SECTION.format(title=title), "", *lines, ""]


def image(alt, file):
    return words.IMAGE.format(alt=alt, file=file)


def _column(ranking, name):
    """A ranking column, or '—' cells where the study has no film stage."""
    return ranking[name] if name in ranking else pd.Series(np.nan, index=ranking.index, dtype=object)


def _ranking_table(ranking, scenarios):
    table = pd.DataFrame({
        "rank": ranking["rank"],
        "scheme": ranking.index,
        "operating mean ± std [µm]": [fmt.mean_std(m, v) for m, v in zip(ranking.clearance_mean_um,
                                                                          ranking.clearance_std_um)],
        "outside window [ppm]": [fmt.interval(v, ci, fmt.ppm_digits(v)) + ("" if src == "counted" else " †")
                                 for v, ci, src in zip(ranking.outside_window_ppm, ranking.outside_window_ppm_ci,
                                                       ranking.outside_window_source)],
        "α > 20 % [%]": [fmt.interval(v, ci, 1) if isinstance(ci, tuple) else "—"
                         for v, ci in zip(_column(ranking, "alpha_over_limit_pct"),
                                          _column(ranking, "alpha_over_limit_pct_ci"))],
        "bearing life median [h]": [fmt.significant_triple((v, *ci)) if isinstance(ci, tuple) else "—"
                                    for v, ci in zip(_column(ranking, "life_median_h"),
                                                     _column(ranking, "life_median_h_ci"))],
        "shell grades": ranking.shell_grades,
        "stock-outs [ppm]": [fmt.fixed(v, 0) for v in ranking.stockout_ppm],
        "surplus [%]": [fmt.fixed(v, 1) for v in ranking.surplus_pct],
    })
    if scenarios:
        table["worst scenario: Δ outside window [ppm]"] = [
            words.WORST_PART.format(change=fmt.fixed(v, 0, sign=True), scenario=name)
            for v, name in zip(ranking.worst_outside_window_ppm, ranking.worst_outside_window_ppm_scenario)]
        if "worst_life_median_h" in ranking:
            table["worst scenario: Δ bearing life median [h]"] = [
                words.WORST_PART.format(change=fmt.general(v, sign=True), scenario=name) if isinstance(name, str)
                else "—" for v, name in zip(ranking.worst_life_median_h, ranking.worst_life_median_h_scenario)]
    return table


def _rule_in_words(rule):
    """The ranking's rule with its metrics named in words (:data:`templates.METRICS`) instead of column names."""
    for column, metric in words.METRICS.items():
        rule = rule.replace(column, metric)
    return rule


def _estimated_note(ranking):
    """The † note where the ranking took shares from the tail estimates: how, and what the study counted."""
    if not (ranking.outside_window_source != "counted").any():
        return []
    conditional = (ranking.outside_window_source == TAIL_SOURCES["conditional"]).any()
    counted = ", ".join(words.COUNTED_PART.format(count=c, scheme=n)
                        for n, c in zip(ranking.index, ranking.outside_window_counted))
    return [words.ESTIMATED_NOTE.format(fewest=MIN_COUNTED, counted=counted,
                                        how=words.CONDITIONAL_HOW if conditional else words.SPLITTING_HOW)]


def non_discriminating(ranking):
    """Sentences naming the ranking metrics that do not separate the schemes here."""
    out = []
    for column, metric in words.METRICS.items():
        if column not in ranking or f"{column}_ci" not in ranking:
            continue
        bounds = [ci if isinstance(ci, tuple) else (np.nan, np.nan) for ci in ranking[f"{column}_ci"]]
        low, high = zip(*bounds)
        if not separates(low, high):
            values = ranking[column].astype(float)
            same = (words.SAME_VALUE_PART.format(value=values.iloc[0]) if np.allclose(values, values.iloc[0])
                    else "")
            out.append(words.NON_DISCRIMINATING.format(metric=metric, same=same))
    return out


def ranking_section(facts, ranking):
    window, scenarios = ranking.attrs["window_m"], list(facts.ranking.scenarios)
    robustness = words.ROBUSTNESS_PART.format(scenarios=", ".join(scenarios)) if scenarios else ""
    rule = words.RANKING_RULE.format(
        lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]), rule=_rule_in_words(ranking.attrs["rule"]),
        whose=words.STUDY_WINDOW_PART if facts.study.window else words.ENGINE_WINDOW_PART, robustness=robustness)
    return section("Ranking", rule, "", markdown_table(_ranking_table(ranking, scenarios)), "",
                   *_estimated_note(ranking), *non_discriminating(ranking))


def _grades_um(grades):
    """A dimension's grades as 'label lo…hi' in µm from its lower limit, or 'ungraded'."""
    if grades is None:
        return words.UNGRADED
    return ", ".join(words.GRADE_PART.format(label=label, lo=lo * fmt.UM, hi=hi * fmt.UM) for label, lo, hi in grades)


def _design_outcome(ranking, scheme):
    row = ranking.loc[scheme]
    share = fmt.interval(row.outside_window_ppm, row.outside_window_ppm_ci,
                         fmt.ppm_digits(row.outside_window_ppm, row.outside_window_ppm_ci[1]))
    return words.DESIGN_OUTCOME_PART.format(rank=row["rank"], share=share,
                                            estimated="" if row.outside_window_source == "counted" else " †")


def design_section(facts, ranking):
    """The designed scheme beside the ISO scheme it started from: what changed, why, and how it did."""
    if facts.design is None:
        return []
    name, record = facts.design.name, facts.design.record
    start = record.start
    grades = pd.DataFrame([{"dimension": label, f"{start} (start)": _grades_um(started), name: _grades_um(designed)}
                           for label, (started, designed) in facts.design.grades.items()])
    samples = list(record.outside)
    shares = pd.DataFrame({
        "design sample": samples,
        f"{start} [ppm]": [fmt.ppm_number(1e6 * record.start_outside.get(k, np.nan)) for k in samples],
        f"{name} [ppm]": [fmt.ppm_number(1e6 * record.outside[k]) for k in samples],
    })
    against = (words.DESIGN_AGAINST_PART.format(outcome=_design_outcome(ranking, start), start=start)
               if start in ranking.index else words.DESIGN_START_ABSENT_PART.format(start=start))
    return section(
        "Designed scheme",
        words.DESIGNED.format(name=name, evaluations=fmt.count(record.evaluations), seconds=record.seconds,
                              start=start, outcome=_design_outcome(ranking, name), against=against), "",
        words.DESIGN_CHANGED, "", markdown_table(grades), "",
        words.DESIGN_SHARES, "", markdown_table(shares), "",
        words.DESIGN_WHY, "", "```text", *record.notes, "```")


def tighten_first(drivers, ranking):
    """One sentence per analysed output of the recommended scheme: which input to tighten first."""
    chosen = ranking.index[0]
    out = []
    for output, frames in drivers.items():
        scheme = chosen if chosen in frames else next(iter(frames), None)
        if scheme is None:
            continue
        d = frames[scheme]
        top, second = d.iloc[0], d.iloc[1]
        gauges = d[d.index.str.contains("gauge")]
        listed = ", ".join(words.GAUGE_INDEX_PART.format(name=name, st=row.ST) for name, row in gauges.iterrows()
                           if row.ST >= 0.05)
        out += [words.TIGHTEN_FIRST.format(
            scheme=scheme, output=words.OUTPUTS.get(output, output), first=d.index[0], st=top.ST, st_lo=top.ST_lo,
            st_hi=top.ST_hi, s1=top.S1, second=d.index[1], second_st=second.ST,
            gauges=words.GAUGES_PART.format(gauges=listed) if len(gauges) and gauges.ST.max() >= 0.05 else ""), ""]
    return out[:-1]


def sensitivity_section(facts, ranking):
    if facts.drivers is None:
        return section("What drives the spread", words.NO_SENSITIVITY)
    return section("What drives the spread", *tighten_first(facts.drivers, ranking), "", words.SOBOL_EXPLAINED, "",
                   image("What drives the spread", "sensitivity.png"))


def read_out_notes(facts):
    """Why a scheme's worst case goes beyond its stated range: readings rounded to the scheme's read-out."""
    out = []
    for name, row in facts.clearance.iterrows():
        step = facts.reading_resolution[name]
        if step > 0 and (row.worst_case_min_um < row.stated_min_um - 1e-6
                         or row.worst_case_max_um > row.stated_max_um + 1e-6):
            out.append(words.READ_OUT.format(scheme=name, step=fmt.um(step, 0), worst_lo=row.worst_case_min_um,
                                             worst_hi=row.worst_case_max_um, stated_lo=row.stated_min_um,
                                             stated_hi=row.stated_max_um))
    return out


def clearance_section(facts):
    summary = facts.clearance
    table = pd.DataFrame({
        "scheme": summary.index,
        "stated [µm]": [fmt.um_range(a, b, 0) if np.isfinite(a) else words.NONE_STATED
                        for a, b in zip(summary.stated_min_um, summary.stated_max_um)],
        "worst case [µm]": [fmt.um_range(a, b) for a, b in zip(summary.worst_case_min_um, summary.worst_case_max_um)],
        "mean [µm]": [fmt.fixed(v, 2) for v in summary.mean_um],
        "std [µm]": [fmt.fixed(v, 2) for v in summary.std_um],
        "P0.135 % [µm]": [fmt.interval(v, ci) for v, ci in zip(summary.p00135_um, summary.p00135_ci_um)],
        "median [µm]": [fmt.fixed(v, 1) for v in summary.median_um],
        "P99.865 % [µm]": [fmt.interval(v, ci) for v, ci in zip(summary.p99865_um, summary.p99865_ci_um)],
        "outside stated [ppm]": [fmt.interval(v, ci, 0) for v, ci in zip(summary.outside_stated_ppm,
                                                                          summary.outside_stated_ci_ppm)],
    })
    return section("Clearance per scheme", words.CLEARANCE_INTRO, "", markdown_table(table), "",
                   *read_out_notes(facts), "",
                   image("Nominal and operating clearance per scheme, with the stated ranges and the design window",
                         "clearance_histogram.png"))


def _fit_table(facts):
    fit, limits = facts.fit, facts.limits
    return pd.DataFrame({
        "scheme": fit.index,
        "nominal mean ± std [µm]": [fmt.mean_std(m, v) for m, v in zip(fit.nominal_mean_um, fit.nominal_std_um)],
        "operating mean ± std [µm]": [fmt.mean_std(m, v) for m, v in zip(fit.operating_mean_um, fit.operating_std_um)],
        "operating P0.135–P99.865 % [µm]": [fmt.um_range(a, b) for a, b in zip(fit.operating_p00135_um,
                                                                               fit.operating_p99865_um)],
        "swell [µm]": [fmt.fixed(v, 2) for v in fit.swell_mean_um],
        "min p, all temperatures [MPa]": [fmt.fixed(v, 1) for v in fit.contact_pressure_min_mpa],
        "max σ, all temperatures [MPa]": [fmt.fixed(v, 0) for v in fit.shell_stress_max_mpa],
        f"p < {limits.contact_pressure_min / 1e6:.0f} MPa [ppm]": [
            fmt.interval(v, ci, 0) for v, ci in zip(fit.low_pressure_ppm, fit.low_pressure_ci_ppm)],
        f"σ > {limits.shell_stress_max / 1e6:.0f} MPa [ppm]": [
            fmt.interval(v, ci, 0) for v, ci in zip(fit.high_stress_ppm, fit.high_stress_ci_ppm)],
        "loss of fit [ppm]": [fmt.fixed(v, 0) for v in fit.loss_of_fit_ppm],
    })


def _source(text):
    """A source as a list item's end: its own final full stop left to the list's punctuation."""
    return text.rstrip(".") if text else words.NO_SOURCE


def fit_section(facts):
    limits, sources = facts.limits, facts.sources
    window = [edge * fmt.UM for edge in limits.clearance_window]
    lines = [words.PRESS_FIT_LIMITS_SOURCE.format(pressure=limits.contact_pressure_min / 1e6,
                                                  stress=limits.shell_stress_max / 1e6,
                                                  source=_source(sources.press_fit_limits)),
             words.CRUSH_SOURCE.format(lo=limits.crush_height[0] * 1e3, hi=limits.crush_height[1] * 1e3,
                                       source=_source(sources.crush_height)),
             words.WINDOW_SOURCE.format(lo=window[0], hi=window[1], source=_source(sources.clearance_window))]
    temperatures = ", ".join(fmt.fixed(t, 0) for t in limits.press_fit_temperatures)
    return section("Operating clearance: press fit, housing swell and temperature",
                   words.FIT_INTRO.format(temperatures=temperatures), "", *lines, "", markdown_table(_fit_table(facts)))


def assembly_section(facts):
    summary = facts.clearance
    table = pd.DataFrame({
        "scheme": summary.index,
        "bearings": summary.bearings,
        "assembled": summary.assembled,
        **{reason: summary[reason] for reason in STATUS if reason != "assembled"},
        "substituted pairs": ["—" if np.isnan(v) else fmt.fixed(v, 0) for v in summary.substituted],
        "shells made": summary.shells_made,
        "shells scrapped [%]": [fmt.fixed(v, 2) for v in summary.shells_scrapped_pct],
    })
    return section("Assembly, scrap and stock", words.ASSEMBLY, "", markdown_table(table))


def plan_section(facts):
    if facts.plan is None:
        return section("Planning: shells per grade", words.PLAN_NEEDS_ENGINES)
    volume, level = fmt.spaced(PLAN_VOLUME), f"{100 * PLAN_SERVICE_LEVEL:g}"
    rows = [{"scheme": scheme, "grade": grade,
             "demand per 1000 engines": fmt.interval(r.demand_per_1000, (r.demand_per_1000_lo, r.demand_per_1000_hi),
                                                     0),
             "production share [%]": fmt.fixed(100 * r.production_share, 2),
             f"surplus for {volume} engines": fmt.fixed(r.surplus, 0, sign=True),
             f"safety stock per lot ({level} %)": fmt.fixed(r.safety_stock, 0),
             "order-up-to per lot": fmt.fixed(r.order_up_to, 0)} for (scheme, grade), r in facts.plan.iterrows()]
    return section("Planning: shells per grade",
                   words.PLAN.format(volume=volume, lot=facts.about.lot_engines, level=100 * PLAN_SERVICE_LEVEL), "",
                   markdown_table(pd.DataFrame(rows)))


def usage_section(facts):
    usage = facts.usage.reset_index()[["scheme", "shell_grade", "shells_made", "shells_used", "shells_left",
                                       "used_share_pct"]]
    usage["used_share_pct"] = [fmt.fixed(v, 2) for v in usage["used_share_pct"]]
    usage.columns = ["scheme", "grade", "made", "fitted", "left in stock", "share of fitted [%]"]
    return section("Shell grade usage", image("Shell grades fitted and made per scheme", "grade_usage.png"), "",
                   markdown_table(usage))
