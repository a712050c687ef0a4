"""The report's first page: the verdict (what to use and why, whether it holds under the declared model
uncertainties and process scenarios, what to check first) and the decision table.

Filled from the facts (:func:`stackup.facts.facts`) and their rankings
(:func:`stackup.rank.ranked`, the study's and each scenario's); nothing here
computes a number the facts do not hold beyond comparing them.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..rank import COST, RULE, differs
from . import format as fmt
from . import templates as words

#: A best share outside the window at or above this [ppm] (1 %) means that no scheme meets the window.
MEETS_WINDOW_PPM = 10_000
#: A share of blocks, crankshafts, bearings or shells lost above this [-] (1 %) is said on the first page.
LOSS_SHARE = 0.01
#: Share of the computed bearings whose journal edge touches its shell from which the first page says so [-].
EDGE_SHARE = 0.5


def _share(row):
    """A scheme's share outside the window as the first page writes it (with its interval and † if estimated)."""
    ci = row.outside_window_ppm_ci
    text = fmt.ppm(row.outside_window_ppm, ci)
    return text + ("" if row.get("outside_window_source", "counted") == "counted" else " †")


def _decider(ranking, chosen, runner):
    """The first metric of the rule on which ``chosen`` beats ``runner`` (None: they tie on every metric)."""
    for column, better, threshold in RULE:
        if column not in ranking:
            continue
        a, b = ranking.loc[chosen], ranking.loc[runner]
        if np.isnan(float(a[column])) or np.isnan(float(b[column])):
            continue
        t = ranking.attrs["negligible_ppm"] if threshold == "negligible" else threshold
        if differs(a, b, column, better, t):
            return column
    return None


def _cost_parts(ranking, chosen, runner, decider):
    """The decider's comparison, then every cost metric on which ``chosen`` is also cheaper, in words."""
    a, b = ranking.loc[chosen], ranking.loc[runner]
    columns = [decider] + [c for c in COST if c != decider and float(a[c]) < float(b[c])]
    return [words.COST_PARTS[c].format(a=a[c], b=b[c], runner=runner) for c in columns if c in words.COST_PARTS]


def _clearance(row):
    """A scheme's operating clearance as the verdict writes it beside the scheme's name."""
    return words.CLEARANCE_PART.format(mean=row.clearance_mean_um, std=row.clearance_std_um)


def _below(row):
    """A scheme's share of bearings below the minimum clearance at assembly or cold start, as the verdict writes it."""
    return fmt.ppm(row.below_minimum_ppm, row.below_minimum_ppm_ci)


def _use(facts, ranking, window):
    """The first paragraph: which scheme, and why (the clearance, or cost among schemes level on it)."""
    chosen = ranking.index[0]
    first = ranking.loc[chosen]
    window_text = words.WINDOW_PART.format(lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]))
    clearance = _clearance(first)
    if len(ranking) == 1:
        return words.USE_ONLY.format(scheme=chosen, share=_share(first), window=window_text, clearance=clearance)
    runner = ranking.index[1]
    second = ranking.loc[runner]
    decider = _decider(ranking, chosen, runner)
    if decider is None:
        tied = list(ranking.index[ranking["rank"] == first["rank"]])
        return words.TIE.format(names=words.bold_listed(tied), window=window_text)
    if decider == "below_minimum_ppm":
        return words.USE_INTERFERENCE.format(scheme=chosen, clearance=clearance, share=_below(first), runner=runner,
                                             runner_share=_below(second), runner_clearance=_clearance(second),
                                             window_share=_share(first), window=window_text)
    if decider == "outside_window_ppm":
        dearer = [words.COST_PARTS[c].format(a=first[c], b=second[c]) for c in COST[:3]
                  if float(first[c]) > float(second[c])]
        price = words.PRICE_PART.format(costs=words.listed(dearer)) if dearer else ""
        return words.USE_CLEARANCE.format(scheme=chosen, share=_share(first), window=window_text,
                                          runner=runner, runner_share=_share(second), clearance=clearance,
                                          runner_clearance=_clearance(second), price=price)
    reason = (words.LEVEL_NO_WINDOW_PART if not np.isfinite(window[1]) else
              words.LEVEL_PART.format(share=_share(first), runner=runner, runner_share=_share(second),
                                      window=window_text, negligible=fmt.general(ranking.attrs["negligible_ppm"])))
    decides = (words.COST_DECIDES_PART if decider in COST else
               words.METRIC_DECIDES_PART.format(metric=words.METRICS.get(decider, decider)))
    return words.USE_COST.format(scheme=chosen, reason=reason, decides=decides,
                                 costs=", ".join(_cost_parts(ranking, chosen, runner, decider)), clearance=clearance)


def interference(facts, ranking):
    """The schemes with bearings below the minimum clearance at assembly or cold start, each with its share and its
    cold-start clearance, and whether the recommended scheme is among them; None where no scheme has any (or the
    dataset has no such count)."""
    if "below_minimum_ppm" not in ranking or not (ranking.below_minimum_counted.fillna(0) > 0).any():
        return None
    chosen = ranking.index[0]
    below = ranking[ranking.below_minimum_counted.fillna(0) > 0]
    schemes = [words.INTERFERENCE_SCHEME_PART.format(
        scheme=name, share=(fmt.percent(row.below_minimum_ppm / 1e6) if row.below_minimum_ppm >= 1000 else
                            fmt.ppm(row.below_minimum_ppm)),
        cold=fmt.mean_std(row.clearance_cold_mean_um, row.clearance_cold_std_um, 1).replace("-", "−"))
        for name, row in below.iterrows()]
    limits = facts.limits
    chosen_text = (words.INTERFERENCE_CHOSEN_PART if chosen in below.index else
                   words.INTERFERENCE_NONE_PART).format(scheme=chosen)
    return words.INTERFERENCE.format(minimum=fmt.general(limits.minimum_clearance * fmt.UM),
                                     cold=_degrees(limits.cold_start_temperature), schemes=words.listed(schemes),
                                     chosen=chosen_text)


def window_at_cold_start(facts, ranking, window):
    """The operating window moved to the cold start by the recommended scheme's mean change of clearance, where its
    lower edge falls below the minimum clearance there (a window that does not suit the housing's material); else
    None."""
    first = ranking.loc[ranking.index[0]]
    minimum = facts.limits.minimum_clearance
    if "clearance_cold_mean_um" not in ranking or not np.isfinite(window[1]) or not np.isfinite(minimum):
        return None
    shift = float(first.clearance_mean_um - first.clearance_cold_mean_um) / fmt.UM  # operating less cold [m]
    if not window[0] - shift < minimum:
        return None
    return words.WINDOW_COLD.format(material=facts.press_fit.housing_material, lo=fmt.um_edge(window[0]),
                                    hi=fmt.um_edge(window[1]),
                                    cold_lo=fmt.fixed((window[0] - shift) * fmt.UM).replace("-", "−"),
                                    cold_hi=fmt.fixed((window[1] - shift) * fmt.UM).replace("-", "−"),
                                    cold=_degrees(facts.limits.cold_start_temperature))


def _degrees(value):
    """A temperature [degC] as the verdict writes it, with a true minus sign."""
    return fmt.general(value).replace("-", "−")


def scenario_groups(facts):
    """Scenario labels by kind: ``{"process": [...], "model": {input: [labels]}}`` in the comparison's order."""
    process, model = [], {}
    for label, about in facts.scenario_about.items():
        if about.kind == "model":
            model.setdefault(about.input, []).append(label)
        else:
            process.append(label)
    return process, model


def clearance_level(other, negligible):
    """The schemes of the ranking ``other`` whose share outside the window cannot be told from the lowest (95 %
    intervals overlapping, or less than ``negligible`` ppm apart)."""
    shares = other["outside_window_ppm"].astype(float)
    if shares.isna().all():
        return set(other.index)
    best = other.loc[shares.idxmin()]
    return {s for s in other.index if not differs(best, other.loc[s], "outside_window_ppm", "lower", negligible)}


def more_below_minimum(ranking, scheme, chosen, negligible):
    """``scheme`` puts more bearings below the minimum clearance than ``chosen`` (by the ranking's rule): fewer
    outside the window does not make it better."""
    return "below_minimum_ppm" in ranking and differs(ranking.loc[chosen], ranking.loc[scheme], "below_minimum_ppm",
                                                      "lower", negligible)


def _flips(labels, scenario_rankings, chosen, negligible):
    """(label, schemes) of the scenarios among ``labels`` under which other schemes put fewer bearings outside the
    window than ``chosen`` by the ranking's rule (a difference the scenario's counts cannot resolve is no flip:
    the scenarios count, they carry no tail estimate), the best of those schemes by the scenario's ranking."""
    out = []
    for label in labels:
        other = scenario_rankings[label]
        if chosen not in other.index:
            continue
        better = [s for s in other.index if s != chosen and differs(other.loc[s], other.loc[chosen],
                                                                   "outside_window_ppm", "lower", negligible)
                  and not more_below_minimum(other, s, chosen, negligible)]
        if better:
            first = other.loc[better, "rank"].min()
            out.append((label, [s for s in better if other.loc[s, "rank"] == first]))
    return out


def _model(facts, scenario_rankings, chosen, negligible):
    """Whether the chosen scheme stays first under the declared model uncertainties; if not, what to measure."""
    _, model = scenario_groups(facts)
    if not model:
        return words.NO_MODEL
    inputs = list(model)
    sources = {facts.scenario_about[labels[0]].assumed for labels in model.values()}
    ranges = (words.ASSUMED_PART if sources == {True} else
              words.MEASURED_PART if sources == {False} else words.SOME_ASSUMED_PART)
    broken = {name: _flips(labels, scenario_rankings, chosen, negligible) for name, labels in model.items()}
    broken = {name: flips for name, flips in broken.items() if flips}
    if not broken:
        return words.MODEL_HOLDS.format(inputs=words.listed(inputs), ranges=ranges)
    clauses, measures = [], []
    for name, flips in broken.items():
        label, winners = flips[0]
        other = scenario_rankings[label]
        clauses.append(words.MODEL_FLIP_PART.format(
            scenario=label, winners=words.bold_listed(winners), s=words.plural(len(winners), "", "es"),
            share=fmt.ppm(other.loc[chosen, "outside_window_ppm"]),
            winner_share=fmt.ppm(other.loc[winners[0], "outside_window_ppm"])))
        measures.append(facts.scenario_about[label].measure)
    return words.MODEL_BREAKS.format(flips="; ".join(clauses), measure=words.listed(measures), ranges=ranges)


def _process(facts, ranking, scenario_rankings, chosen, negligible):
    """Whether the chosen scheme stays first under the process scenarios, and the worst of them for it."""
    process, _ = scenario_groups(facts)
    if not process:
        return None
    flips = _flips(process, scenario_rankings, chosen, negligible)
    worst = _worst_scenario(facts, ranking, process).get(chosen)
    worst_text = "" if worst is None else words.PROCESS_WORST_PART.format(scenario=worst[0], share=fmt.ppm(worst[1]))
    if not flips:
        return words.PROCESS_HOLDS.format(worst=worst_text)
    names = "; ".join(words.UNDER_PART.format(scenario=label, names=words.bold_listed(winners),
                                              s=words.plural(len(winners), "", "s"))
                      for label, winners in flips[:2])
    more = words.MORE_PART.format(count=len(flips) - 2) if len(flips) > 2 else ""
    return words.PROCESS_BREAKS.format(flips=names, more=more, worst=worst_text)


def _worst_scenario(facts, ranking, labels):
    """Scheme -> (scenario, its counted share outside the window [ppm]) of the worst of ``labels`` for it."""
    out = {}
    for scheme in ranking.index:
        shares = [(label, facts.ranking.scenarios[label][0][scheme]["outside_window_ppm"]) for label in labels
                  if scheme in facts.ranking.scenarios[label][0]]
        if shares:
            out[scheme] = max(shares, key=lambda pair: pair[1])
    return out


def check_first(facts, ranking, window):
    """What makes the result less trustworthy, each in a few words: no window, a window nobody meets, losses
    above :data:`LOSS_SHARE`, stages that failed or did not run, the chosen scheme failing Levanov's operability
    criteria at some position, journal edges in contact."""
    notes = []
    if not np.isfinite(window[1]):
        notes.append(words.NO_WINDOW)
    elif np.nanmin(ranking.outside_window_ppm) >= MEETS_WINDOW_PPM:
        notes.append(words.NOT_MET.format(lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]),
                                          best=fmt.ppm(np.nanmin(ranking.outside_window_ppm))))
    scrap = facts.scrap
    for (share, scheme), template in ((scrap.blocks, words.BLOCKS_LOST), (scrap.crankshafts, words.CRANKS_LOST),
                                      (scrap.not_graded, words.NOT_GRADED_LOST), (scrap.stockouts, words.STOCKOUTS_LOST),
                                      (scrap.shells, words.SHELLS_LOST)):
        if share > LOSS_SHARE:
            notes.append(template.format(share=fmt.percent(share), scheme=scheme))
    notes += run_notes(facts.run)
    chosen = ranking.loc[ranking.index[0]]
    for column, template in (("alpha_over_limit_pct", words.SCUFFING_NOTE), ("life_below_target_pct",
                                                                            words.SHORT_LIFE_NOTE)):
        if float(chosen.get(column, 0.0)) > 0:  # Levanov's operability criteria, at the worst position
            notes.append(template.format(bearing=chosen[column.replace("_pct", "_position")], scheme=ranking.index[0],
                                         share=fmt.interval(chosen[column], chosen[f"{column}_ci"], 1),
                                         target=fmt.whole(facts.limits.life_target / 3600),
                                         checked=words.CHECKED_PART if len(facts.corrected) else ""))
    edge = facts.edge
    if edge is not None and edge.computed and edge.touching >= EDGE_SHARE * edge.computed:
        note = (words.EDGE_SURFACE_NOTE if edge.surface else words.EDGE_COUNTED_NOTE if edge.counted
                else words.EDGE_NOTE)
        notes.append(note.format(share=fmt.percent(edge.touching / edge.computed)))
    return notes


def verdict(facts, ranking, scenario_rankings):
    """The verdict as markdown lines, between ``<!-- verdict -->`` markers (at most about 150 words).

    ``ranking`` is the study's (:func:`stackup.rank.ranked` of ``facts.ranking``), ``scenario_rankings`` maps
    each declared scenario to the ranking of the schemes under it.
    """
    window = ranking.attrs["window_m"]
    chosen = ranking.index[0]
    negligible = ranking.attrs["negligible_ppm"]
    paragraphs = [_use(facts, ranking, window), interference(facts, ranking),
                  window_at_cold_start(facts, ranking, window), _model(facts, scenario_rankings, chosen, negligible),
                  _process(facts, ranking, scenario_rankings, chosen, negligible)]
    notes = check_first(facts, ranking, window)
    if notes:
        paragraphs.append(words.CHECK_FIRST.format(notes=" ".join(notes)))
    return ["<!-- verdict -->", *[x for p in paragraphs if p for x in (p, "")], "<!-- /verdict -->"]


def decision_table(facts, ranking):
    """The first page's table: per scheme in ranking order, its share outside the window, its cost and the worst
    process and model-uncertainty scenario for it."""
    process, model = scenario_groups(facts)
    table = pd.DataFrame({
        "rank": ranking["rank"],
        "scheme": ranking.index,
        **({words.BELOW_MINIMUM_COLUMN: ["0" if n == 0 else fmt.ppm_interval(v, ci) for v, ci, n in
                                         zip(ranking.below_minimum_ppm, ranking.below_minimum_ppm_ci,
                                             ranking.below_minimum_counted)]}
           if "below_minimum_ppm" in ranking else {}),
        "outside window [ppm]": [fmt.ppm_interval(v, ci) + ("" if s == "counted" else " †")
                                 for v, ci, s in zip(ranking.outside_window_ppm, ranking.outside_window_ppm_ci,
                                                     ranking.outside_window_source)],
        "shell grades": ranking.shell_grades,
        "bore + journal grades": ["—" if np.isnan(v) else f"{v:.0f}" for v in ranking.part_grades.astype(float)],
        "stock-outs [ppm]": [fmt.fixed(v, 0) for v in ranking.stockout_ppm],
        "surplus [%]": [fmt.fixed(v, 1) for v in ranking.surplus_pct],
    })
    for title, labels in ((words.WORST_PROCESS, process), (words.WORST_MODEL, [x for v in model.values() for x in v])):
        if labels:
            worst = _worst_scenario(facts, ranking, labels)
            table[title] = [words.WORST_CELL.format(share=fmt.ppm_number(worst[s][1]), scenario=worst[s][0])
                            if s in worst else "—" for s in ranking.index]
    return table


def run_notes(run):
    """Stages that failed on some engines, or did not run, said in words (``run``: a :class:`stackup.facts.Run`)."""
    notes = []
    if run.failures:
        notes.append(words.FAILURES_NOTE.format(lines="; ".join(run.failures)))
    if run.mechanics_engines_used == 0:
        reason = words.NONE_ASKED_PART if run.mechanics_engines_asked == 0 else words.NO_CRANK_PART
        notes.append(words.NO_MECHANICS_NOTE.format(reason=reason))
    return notes
