"""The report's sections on the clearance side: ranking, scenarios, designed scheme, drivers, clearance, press fit,
assembly and planning.

Each builder takes the facts (:class:`stackup.facts.Facts`) and the ranking
(:func:`stackup.rank.ranked`, whose order every per-scheme table follows) and
returns the section's markdown lines; the numbers are written by
:mod:`~stackup.report.format`, the words come from
:mod:`~stackup.report.templates`.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..assembly import STATUS
from ..facts import MIN_COUNTED, PLAN_SERVICE_LEVEL, TAIL_SOURCES, separates
from ..plan import planner_table
from ..rank import RULE
from ..scenarios import is_assumed
from ..stats import proportion_ci
from . import format as fmt
from . import templates as words
from .verdict import clearance_level, more_below_minimum, scenario_groups


def markdown_table(frame):
    """A DataFrame as a pipe table (index dropped: put what matters in columns)."""
    head = "| " + " | ".join(map(str, frame.columns)) + " |"
    rule = "|" + "|".join("---" for _ in frame.columns) + "|"
    body = ["| " + " | ".join("" if pd.isna(v) else str(v) for v in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join([head, rule, *body])


def section(title, *lines):
    """A section: its heading, its lines and a blank line."""
    return [words.SECTION.format(title=title), "", *lines, ""]


def image(alt, file):
    return words.IMAGE.format(alt=alt, file=file)


def in_order(frame, order):
    """``frame`` (indexed by scheme, or by scheme and another level) with its schemes in ``order``."""
    if isinstance(frame.index, pd.MultiIndex):
        present = [s for s in order if s in frame.index.get_level_values(0)]
        return pd.concat({s: frame.xs(s, level=0) for s in present}, names=frame.index.names) if present else frame
    return frame.loc[[s for s in order if s in frame.index]]


def _column(ranking, name):
    """A ranking column, or '—' cells where the study has no film stage."""
    return ranking[name] if name in ranking else pd.Series(np.nan, index=ranking.index, dtype=object)


def _bounds(ranking, column):
    """The 95 % interval bounds of a ranking column per scheme, (NaN, NaN) where a scheme has none."""
    return [ci if isinstance(ci, tuple) else (np.nan, np.nan) for ci in ranking[f"{column}_ci"]]


def _estimated_note(ranking):
    """The † note where the ranking took shares from the tail estimates: how, and what the study counted of
    those schemes."""
    if not (ranking.outside_window_source != "counted").any():
        return []
    conditional = (ranking.outside_window_source == TAIL_SOURCES["conditional"]).any()
    counted = ", ".join(words.COUNTED_PART.format(count=c, scheme=n)
                        for n, c, source in zip(ranking.index, ranking.outside_window_counted,
                                                ranking.outside_window_source) if source != "counted")
    return [words.ESTIMATED_NOTE.format(fewest=MIN_COUNTED, counted=counted,
                                        how=words.CONDITIONAL_HOW if conditional else words.SPLITTING_HOW), ""]


def non_discriminating(ranking):
    """One sentence naming the film and life metrics that do not separate the schemes here (none: no sentence)."""
    items, columns = [], []
    for column in ("alpha_over_limit_pct", "life_below_target_pct", "engine_life_median_h"):
        if column not in ranking or f"{column}_ci" not in ranking:
            continue
        low, high = zip(*_bounds(ranking, column))
        if not separates(low, high):
            values = ranking[column].astype(float)
            same = (words.NONE_PART if np.all(values == 0) else
                    words.SAME_VALUE_PART.format(value=values.iloc[0], unit=words.METRIC_UNITS[column])
                    if np.allclose(values, values.iloc[0]) else "")
            items.append(words.NON_DISCRIMINATING_NAMES[column] + same)
            columns.append(column)
    if not items:
        return []
    metrics = words.listed(items)
    singular = len(columns) == 1 and columns[0] not in words.NON_DISCRIMINATING_PLURAL
    return [words.NON_DISCRIMINATING.format(metrics=metrics[0].upper() + metrics[1:],
                                            verb="does" if singular else "do")]


def centring(facts, ranking):
    """The scheme with the narrowest clearance, centred in the window, where it would beat the chosen one."""
    chosen = ranking.index[0]
    narrowest = ranking.clearance_std_um.idxmin()
    if narrowest == chosen or narrowest not in facts.centred.index:  # no window to centre in
        return []
    if more_below_minimum(ranking, narrowest, chosen, ranking.attrs["negligible_ppm"]):
        return []  # centring it in the window leaves its bearings below the minimum clearance cold: no case for it
    shift, outside, bearings = facts.centred.loc[narrowest, ["shift", "outside", "bearings"]]
    share, _, upper = proportion_ci(outside, bearings)
    if outside and 1e6 * share > ranking.loc[chosen].outside_window_ppm_ci[1]:
        return []  # centred, it would still put more outside than the chosen scheme: no case for it
    result = (words.CENTRED_SOME_PART.format(share=fmt.ppm(1e6 * share)) if outside else
              words.CENTRED_NONE_PART.format(bearings=fmt.count(int(bearings)), upper=fmt.ppm(1e6 * upper)))
    return [words.CENTRED.format(
        scheme=narrowest, std=ranking.loc[narrowest, "clearance_std_um"],
        chosen_std=ranking.loc[chosen, "clearance_std_um"], shift=fmt.um(abs(shift)),
        side="below" if shift > 0 else "above", half=fmt.um(abs(shift) / 2), verb="thinner" if shift > 0 else "thicker",
        result=result), ""]


def ranking_section(facts, ranking):
    window = ranking.attrs["window_m"]
    metrics = ", ".join(words.METRICS[c] for c, _, _ in RULE)
    rule = words.RANKING_RULE.format(
        lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]), metrics=metrics,
        negligible=fmt.general(ranking.attrs["negligible_ppm"]),
        whose=words.STUDY_WINDOW_PART if facts.study.window else words.ENGINE_WINDOW_PART)
    # the decision table on the first page is the ranking's table; the film and life metrics are the film section's
    return section("Ranking", rule, "", *_estimated_note(ranking), *centring(facts, ranking),
                   *non_discriminating(ranking))


def scenarios_section(facts, ranking, scenario_rankings):
    """Every scenario's share outside the window per scheme (ranking order), the lowest and those level with it in
    bold, and the
    model-uncertainty ranges with their sources."""
    if not scenario_rankings:
        return section("Scenarios", words.NO_SCENARIOS)
    process, model = scenario_groups(facts)
    study = {s: fmt.ppm_number(1e6 * c / max(b, 1)) for s, c, b in
             zip(ranking.index, ranking.outside_window_counted, _assembled(facts, ranking))}
    rows, same = [], []
    for label in [*process, *(x for labels in model.values() for x in labels)]:
        other = scenario_rankings[label]
        values = {s: fmt.ppm_number(other.loc[s, "outside_window_ppm"]) if s in other.index else "—"
                  for s in ranking.index}
        if values == study:  # it acts on the films only: named below the table, not a row
            same.append(label)
            continue
        firsts = clearance_level(other, ranking.attrs["negligible_ppm"])
        rows.append({"scenario": label, **{s: f"**{v}**" if s in firsts else v for s, v in values.items()}})
    rows.append({"scenario": "none (the study, counted)", **study})
    lines = [words.SCENARIOS_INTRO, "", markdown_table(pd.DataFrame(rows)), ""]
    if same:
        named = words.listed(same)
        lines += [words.SCENARIOS_SAME.format(labels=named[0].upper() + named[1:],
                                              verb=words.plural(len(same), "leave", "leaves")), ""]
    if facts.life_changes:
        chosen = ranking.index[0]
        table = pd.DataFrame([_life_change_row(label, positions, engines, chosen)
                              for label, (positions, engines) in facts.life_changes.items()])
        pairs = int(min(p.xs(chosen, level="scheme").pairs.min() for p, _ in facts.life_changes.values()))
        lines += [words.SCENARIO_LIVES_INTRO.format(pairs=pairs, scheme=chosen), "", markdown_table(table), ""]
    if model:
        lines += [words.MODEL_RANGES, ""]
        for name, labels in model.items():
            about = facts.scenario_about[labels[0]]
            lines.append(words.MODEL_RANGE.format(input=name, source=about.source, measure=about.measure))
    return section("Scenarios", *lines)


def _life_change_row(label, positions, engines, chosen):
    """What a scenario that ran the mechanical chain does to the chosen scheme's lives per position and engine, and
    where any scheme's life at a position rises beyond its 95 % interval (paired on the same engines): one row."""
    mine = positions.xs(chosen, level="scheme")
    if all(v == (0.0, 0.0, 0.0) for v in positions.life_change_h):  # e.g. doubled misalignment of an engine with none
        return {"scenario": label, words.LIVES_POSITION_COLUMN: words.LIVES_SAME, words.LIVES_ENGINE_COLUMN: "0",
                words.LIVES_RISE_COLUMN: words.LIVES_NONE_RISE}
    changes = [v[0] for v in mine.life_change_h]
    rises = [(scheme, bearing, row) for (scheme, bearing), row in positions.iterrows() if row.life_change_h[1] > 0]
    # a life that rises with its film is the film's doing: counted; one that rises without it is named
    thicker = [row for _, _, row in rises if row.h_min_mean_change_um[0] > 0]
    odd = [(scheme, bearing, row) for scheme, bearing, row in rises if not row.h_min_mean_change_um[0] > 0]
    parts = []
    if thicker:
        life, film = ([row[name][0] for row in thicker] for name in ("life_change_h", "h_min_mean_change_um"))
        # the film contact and wear depend on may thin meanwhile: say so, it is method 1's reading, not the bearing's
        thinner = [row.h_min_change_um[0] for row in thicker if row.h_min_change_um[2] < 0]
        minimum = words.LIVES_RISE_THINNER_MINIMUM.format(
            span=fmt.signed_span(thinner),
            where="" if len(thinner) == len(thicker) else words.LIVES_RISE_THINNER_AT.format(count=len(thinner))
        ) if thinner else ""
        parts.append(words.LIVES_RISE_WITH_FILM.format(
            count=len(thicker), total=len(positions), lo=fmt.signed(min(life)), hi=fmt.signed(max(life)),
            film_lo=fmt.signed(min(film), 2), film_hi=fmt.signed(max(film), 2), minimum=minimum))
    if odd:
        parts.append(words.LIVES_RISE.format(where=words.listed(
            words.LIFE_RISE_PART.format(bearing=bearing, scheme=scheme, change=fmt.signed(row.life_change_h[0]),
                                        film=fmt.signed(row.h_min_mean_change_um[0], 2))
            for scheme, bearing, row in odd)))
    return {"scenario": label,
            words.LIVES_POSITION_COLUMN: words.LIVES_SPAN.format(lo=fmt.signed(min(changes)),
                                                                 bearing=mine.index[int(np.argmin(changes))],
                                                                 hi=fmt.signed(max(changes))),
            words.LIVES_ENGINE_COLUMN: fmt.signed(engines.loc[chosen, "engine_life_change_h"][0]),
            words.LIVES_RISE_COLUMN: "; ".join(parts) if parts else words.LIVES_NONE_RISE}


def _assembled(facts, ranking):
    """Assembled bearings of each scheme, in ranking order."""
    return [int(facts.clearance.loc[s, "assembled"]) for s in ranking.index]


def _grades_um(grades):
    """A dimension's grades as 'label lo…hi' in µm from its lower limit, or 'ungraded'."""
    if grades is None:
        return words.UNGRADED
    return ", ".join(words.GRADE_PART.format(label=label, lo=lo * fmt.UM, hi=hi * fmt.UM) for label, lo, hi in grades)


def _design_outcome(ranking, scheme):
    """A scheme's rank in words (its share outside the window is in the decision table)."""
    return words.DESIGN_OUTCOME_PART.format(rank=ranking.loc[scheme, "rank"])


def design_section(facts, ranking):
    """The designed scheme beside the ISO scheme it started from: what changed, and how it did."""
    if facts.design is None:
        return []
    name, record = facts.design.name, facts.design.record
    start = record.start
    grades = pd.DataFrame([{"dimension": label, f"{start} (start)": _grades_um(started), name: _grades_um(designed)}
                           for label, (started, designed) in facts.design.grades.items()])
    against = (words.DESIGN_AGAINST_PART.format(outcome=_design_outcome(ranking, start), start=start)
               if start in ranking.index else words.DESIGN_START_ABSENT_PART.format(start=start))
    return section(
        "Designed scheme",
        words.DESIGNED.format(name=name, evaluations=fmt.count(record.evaluations), seconds=record.seconds,
                              start=start, outcome=_design_outcome(ranking, name), against=against), "",
        markdown_table(grades))


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


def read_out_notes(facts, order):
    """Why a scheme's worst case goes beyond its stated range: readings rounded to the scheme's read-out."""
    out = []
    for name, row in in_order(facts.clearance, order).iterrows():
        step = facts.reading_resolution[name]
        if step > 0 and (row.worst_case_min_um < row.stated_min_um - 1e-6
                         or row.worst_case_max_um > row.stated_max_um + 1e-6):
            out.append(words.READ_OUT.format(scheme=name, step=fmt.um(step, 0), worst_lo=row.worst_case_min_um,
                                             worst_hi=row.worst_case_max_um, stated_lo=row.stated_min_um,
                                             stated_hi=row.stated_max_um))
    return out


def clearance_section(facts, ranking):
    summary = in_order(facts.clearance, ranking.index)
    table = pd.DataFrame({
        "scheme": summary.index,
        "stated (worst case) [µm]": [_stated_and_worst(*row) for row in zip(
            summary.stated_min_um, summary.stated_max_um, summary.worst_case_min_um, summary.worst_case_max_um)],
        "mean [µm]": [fmt.fixed(v, 2) for v in summary.mean_um],
        "std [µm]": [fmt.fixed(v, 2) for v in summary.std_um],
        "P0.135–P99.865 % [µm]": [fmt.um_range(a, b) for a, b in zip(summary.p00135_um, summary.p99865_um)],
        "outside stated [ppm]": [fmt.interval(v, ci, 0) for v, ci in zip(summary.outside_stated_ppm,
                                                                          summary.outside_stated_ci_ppm)],
    })
    return section("Clearance per scheme", words.CLEARANCE_INTRO, "", markdown_table(table), "",
                   *read_out_notes(facts, ranking.index), "",
                   image("Nominal and operating clearance per scheme, stated ranges and window",
                         "clearance_histogram.png"))


def _stated_and_worst(stated_lo, stated_hi, worst_lo, worst_hi):
    """A scheme's stated range, with its worst case over the allowed combinations in brackets where it differs."""
    worst = fmt.um_range(worst_lo, worst_hi)
    if not np.isfinite(stated_lo):
        return words.NONE_STATED.format(worst=worst)
    stated = fmt.um_range(stated_lo, stated_hi, 0)
    same = abs(worst_lo - stated_lo) < 0.05 and abs(worst_hi - stated_hi) < 0.05
    return stated if same else f"{stated} ({worst})"


def _soaked_columns(facts, ranking, order):
    """The mean clearance at assembly and at the cold start per scheme [µm] (their spread is the operating one's
    within a few hundredths; none for a dataset without them)."""
    if "clearance_cold_mean_um" not in ranking:
        return {}
    rows = ranking.loc[list(order)]
    title = words.SOAKED_COLUMN.format(assembly=fmt.general(facts.press_fit.assembly_temperature),
                                       cold=fmt.general(facts.limits.cold_start_temperature))
    return {title: [f"{fmt.fixed(a)} / {fmt.fixed(c)}" for a, c in zip(rows.clearance_assembly_mean_um,
                                                                       rows.clearance_cold_mean_um)]}


def _fit_table(facts, order, ranking):
    fit, limits = in_order(facts.fit, order), facts.limits
    return pd.DataFrame({
        "scheme": fit.index,
        "operating mean ± std [µm]": [fmt.mean_std(m, v)
                                      for m, v in zip(fit.operating_mean_um, fit.operating_std_um)],
        **_soaked_columns(facts, ranking, fit.index),
        "operating P0.135–P99.865 % [µm]": [fmt.um_range(a, b) for a, b in zip(fit.operating_p00135_um,
                                                                               fit.operating_p99865_um)],
        "swell [µm]": [fmt.fixed(v, 2) for v in fit.swell_mean_um],
        "min p [MPa]": [fmt.fixed(v, 1) for v in fit.contact_pressure_min_mpa],
        "max σ [MPa]": [fmt.fixed(v, 0) for v in fit.shell_stress_max_mpa],
        f"p < {limits.contact_pressure_min / 1e6:.0f} MPa [ppm]": [
            _count_share(v, ci) for v, ci in zip(fit.low_pressure_ppm, fit.low_pressure_ci_ppm)],
        f"σ > {limits.shell_stress_max / 1e6:.0f} MPa [ppm]": [
            _count_share(v, ci) for v, ci in zip(fit.high_stress_ppm, fit.high_stress_ci_ppm)],
        "loss of fit [ppm]": [fmt.fixed(v, 0) for v in fit.loss_of_fit_ppm],
    })


def _count_share(value, ci):
    """A share [ppm] with its interval, or '0' where nothing was counted (the interval's width is the sample's)."""
    return "0" if value == 0 else fmt.interval(value, ci, 0)


def _source(text):
    """A source as a list item's end, cited in short (:func:`~stackup.report.format.cited`), its own final full
    stop left to the list's punctuation."""
    return fmt.cited(text) if text and text.strip() else words.NO_SOURCE


def _window_source(window, source):
    """The window's list item: its source's own question or exclamation mark ends it, else a full stop."""
    cited = _source(source)
    return words.WINDOW_SOURCE.format(lo=window[0], hi=window[1], source=cited,
                                      end="" if cited.endswith(("?", "!")) else ".")


def fit_section(facts, ranking):
    limits, sources, press = facts.limits, facts.sources, facts.press_fit
    window = [edge * fmt.UM for edge in limits.clearance_window]
    journal = (words.NOT_GIVEN_JOURNAL if not press.journal_temperature_excess and not press.journal_temperature_source
               else _source(press.journal_temperature_source))
    lines = [words.PRESS_FIT_LIMITS_SOURCE.format(pressure=limits.contact_pressure_min / 1e6,
                                                  stress=limits.shell_stress_max / 1e6,
                                                  source=_source(sources.press_fit_limits)),
             words.CRUSH_SOURCE.format(lo=limits.crush_height[0] * 1e3, hi=limits.crush_height[1] * 1e3,
                                       source=_source(sources.crush_height)),
             words.JOURNAL_SOURCE.format(excess=press.journal_temperature_excess, source=journal),
             _window_source(window, sources.clearance_window)]
    temperatures = ", ".join(fmt.fixed(t, 0) for t in limits.press_fit_temperatures)
    if np.isfinite(limits.minimum_clearance):
        lines.insert(3, words.MINIMUM_SOURCE.format(
            minimum=fmt.general(limits.minimum_clearance * fmt.UM), assembly=fmt.general(press.assembly_temperature),
            cold=fmt.general(limits.cold_start_temperature), source=_source(sources.minimum_clearance),
            cold_source=words.COLD_SOURCE_PART.format(source=_source(sources.cold_start))
            if is_assumed(sources.cold_start) else ""))
    table = _fit_table(facts, ranking.index, ranking)
    checks = {f"p < {limits.contact_pressure_min / 1e6:.0f} MPa [ppm]": words.FIT_LOW_PRESSURE,
              f"σ > {limits.shell_stress_max / 1e6:.0f} MPa [ppm]": words.FIT_HIGH_STRESS,
              "loss of fit [ppm]": words.FIT_LOST}
    passed = [column for column in checks if (table[column] == "0").all()]  # said once, not as columns of zeros
    after = ([words.FIT_ALL_PASS.format(checks=words.listed(checks[c].format(
        pressure=limits.contact_pressure_min / 1e6, stress=limits.shell_stress_max / 1e6) for c in passed), last="or")]
        if passed else [])
    return section("Operating clearance: press fit, housing swell and temperature",
                   words.FIT_INTRO.format(temperatures=temperatures), "", *lines, "",
                   markdown_table(table.drop(columns=passed)), *([""] + after if after else []))


def assembly_section(facts, ranking):
    summary = in_order(facts.clearance, ranking.index)
    lost = [reason for reason in STATUS if reason != "assembled" and summary[reason].any()]
    # losses every scheme shares (scrapped blocks and crankshafts: the same parts) are said once, not as a column
    shared = [reason for reason in lost if len(summary) > 1 and (summary[reason] == summary[reason].iloc[0]).all()]
    table = pd.DataFrame({
        "scheme": summary.index,
        "assembled": summary.assembled,
        **{reason.replace("_", " "): summary[reason] for reason in lost if reason not in shared},
        **({} if not np.nansum(summary.substituted) else
           {"substituted pairs": ["—" if np.isnan(v) else fmt.fixed(v, 0) for v in summary.substituted]}),
        "shells scrapped [%]": [fmt.fixed(v, 2) for v in summary.shells_scrapped_pct],
    })
    intro = words.ASSEMBLY.format(bearings=fmt.count(int(summary.bearings.max())),
                                  shells=fmt.count(int(summary.shells_made.max())))
    if shared:
        intro += " " + words.ASSEMBLY_SHARED.format(losses=words.listed(
            words.LOSSES[reason].format(count=fmt.count(int(summary[reason].iloc[0]))) for reason in shared))
    return section("Assembly, scrap and stock", intro, "", markdown_table(table), "",
                   image("Shell grades fitted and made per scheme", "grade_usage.png"))


def _intervals_merged(table):
    """The planner's table with each column "X, 95 % low [u]" and "X, 95 % high [u]" written into "X [u]" as
    "value [low, high]" (one column instead of three; the planner's own table keeps them apart for spreadsheets)."""
    table = table.copy()
    for low in [c for c in table.columns if ", 95 % low" in str(c)]:
        value, high = low.replace(", 95 % low", ""), low.replace(", 95 % low", ", 95 % high")
        if value in table and high in table:
            table[value] = [v if pd.isna(lo) or pd.isna(hi) else f"{v} [{lo}, {hi}]"
                            for v, lo, hi in zip(table[value], table[low], table[high])]
            table = table.drop(columns=[low, high])
    return table


def plan_section(facts, ranking):
    """The shells to make and stock per grade for the scheme to use (:func:`stackup.plan.planner_table`)."""
    if facts.plan is None:
        return section("Planning: shells per grade", words.PLAN_NEEDS_ENGINES)
    chosen = ranking.index[0]
    frame = facts.plan.loc[[chosen]]
    frame.attrs = dict(facts.plan.attrs)
    table = planner_table(frame)
    a = frame.attrs
    scrapped = table.xs("scrapped", level="grade")["share of shells made [%]"].iloc[0]
    summary = words.PLAN.format(
        scheme=chosen, ordered=a["shells_per_lot"], lot=a["lot_engines"], surplus=100 * a["shell_surplus"],
        how=words.PLAN_TO_ORDER if a["supply"] == "to-order" else words.PLAN_SORTED,
        scrap=0.0 if pd.isna(scrapped) else float(scrapped), level=100 * a["service_level"])
    # The order's explanation is `stackup plan`'s; the report keeps what the order does not cover, whole.
    body = _intervals_merged(table.reset_index())
    # the shells needed are the made less the surplus: `stackup plan` keeps that column
    body = body.drop(columns=[c for c in body if c == "scheme" or c.startswith("needed")])
    return section("Planning: shells per grade", " ".join([summary, *table.attrs["warnings"]]), "",
                   markdown_table(body))


__all__ = ["PLAN_SERVICE_LEVEL", "assembly_section", "centring", "clearance_section", "design_section",
           "fit_section", "in_order", "markdown_table", "non_discriminating", "plan_section", "ranking_section",
           "read_out_notes", "scenarios_section", "section", "sensitivity_section", "tighten_first"]
