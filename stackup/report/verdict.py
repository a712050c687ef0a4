"""The report's verdict: what to use and why, what it costs, what it is fragile to, when another would win.

Filled from the facts (:func:`stackup.facts.facts`) and their ranking
(:func:`stackup.rank.ranked`); nothing here computes a number the facts do
not hold beyond comparing them.
"""

from __future__ import annotations

import numpy as np

from ..stats import proportion_ci
from . import format as fmt
from . import templates as words

#: A best share outside the window at or above this [ppm] (1 %) means that no scheme meets the window.
MEETS_WINDOW_PPM = 10_000
#: Schemes whose shares of bearings with edge contact lie within this many percentage points are alike.
ALIKE_PCT = 5


def _source(row):
    """' (estimated: ... †)' where the ranking took the share from the tails, else ''."""
    source = row.get("outside_window_source", "counted")
    return "" if source == "counted" else words.ESTIMATED_PART.format(source=source)


def _window_lines(ranking, window):
    """Said first where the window cannot judge the schemes: none given, or none meets it."""
    lines = []
    if not np.isfinite(window[1]):
        lines.append(words.NO_WINDOW)
    if np.isfinite(window[1]) and np.nanmin(ranking.outside_window_ppm) >= MEETS_WINDOW_PPM:
        lines.append(words.NOT_MET.format(lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]),
                                          best=fmt.ppm(np.nanmin(ranking.outside_window_ppm))))
    return lines


def _use(engine, ranking, best, window):
    """The one scheme ranked first: why, against the next."""
    first = ranking.loc[best]
    others = ranking.drop(index=[best])
    why = words.WHY_PART.format(share=fmt.ppm(first.outside_window_ppm, first.outside_window_ppm_ci),
                                source=_source(first), lo=fmt.um_edge(window[0]), hi=fmt.um_edge(window[1]))
    if len(others):
        runner = others.index[0]
        r = ranking.loc[runner]
        why += words.NEXT_PART.format(share=fmt.ppm(r.outside_window_ppm, r.outside_window_ppm_ci), runner=runner)
    return words.USE.format(scheme=best, engine=engine, why=why, mean=first.clearance_mean_um,
                            std=first.clearance_std_um, middle=fmt.um(0.5 * (window[0] + window[1])))


def _tie(ranking, best):
    """Schemes that tie for first: the one with the fewest grades, then the least surplus; its sentence."""
    cheapest = min(best, key=lambda n: (ranking.loc[n, "shell_grades"], ranking.loc[n, "surplus_pct"]))
    c = ranking.loc[cheapest]
    others = [n for n in best if n != cheapest]
    versus = ", ".join(words.TIE_VERSUS_PART.format(grades=ranking.loc[n, "shell_grades"],
                                                    surplus=ranking.loc[n, "surplus_pct"], scheme=n) for n in others)
    fewer = [n for n in others if ranking.loc[n, "stockout_ppm"] < c.stockout_ppm]
    stockouts = "" if not fewer else words.TIE_STOCKOUTS_PART.format(
        stockouts=c.stockout_ppm, others=", ".join(words.TIE_STOCKOUT_PART.format(
            stockouts=ranking.loc[n, "stockout_ppm"], scheme=n) for n in fewer))
    return cheapest, words.TIE.format(names=words.bold_listed(best), cheapest=cheapest, grades=c.shell_grades,
                                      surplus=c.surplus_pct, versus=versus, stockouts=stockouts)


def _fragile(ranking, first):
    """What the chosen scheme is fragile to: the declared scenarios that make it worse, or None without them."""
    if "worst_outside_window_ppm" not in ranking:
        return None
    # the worst change of each metric over the declared scenarios; a change for the better is no fragility
    change = first.worst_outside_window_ppm
    fragile = ([words.FRAGILE_WINDOW_PART.format(scenario=first.worst_outside_window_ppm_scenario,
                                                 share=fmt.ppm(change))] if change > 0 else [])
    life = first.get("worst_life_median_h", np.nan)
    if "worst_life_median_h" in ranking and np.isfinite(life) and life < 0:
        fragile.append(words.FRAGILE_LIFE_PART.format(scenario=first.worst_life_median_h_scenario,
                                                      hours=fmt.general(-life)))
    return words.FRAGILE.format(what="; ".join(fragile) if fragile else words.NOT_FRAGILE_PART)


def verdict(facts, ranking, scenario_rankings):
    """The opening summary as markdown lines, between ``<!-- verdict -->`` markers.

    ``ranking`` is the study's (:func:`stackup.rank.ranked` of ``facts.ranking``), ``scenario_rankings`` maps
    each declared scenario to the ranking of the schemes under it.
    """
    window = ranking.attrs["window_m"]
    best = list(ranking.index[ranking["rank"] == 1])
    lines = _window_lines(ranking, window)
    if len(best) == 1:
        lines.append(_use(facts.about.engine, ranking, best[0], window))
    else:
        cheapest, text = _tie(ranking, best)
        lines.append(text)
        best = [cheapest]
    first = ranking.loc[best[0]]
    lines.append(words.COSTS.format(grades=int(first.shell_grades), s="s" if first.shell_grades > 1 else "",
                                    surplus=first.surplus_pct, stockouts=fmt.ppm(first.stockout_ppm)))
    fragile = _fragile(ranking, first)
    if fragile:
        lines.append(fragile)
    lines.append(words.WOULD_WIN.format(text=_would_win(facts, ranking, scenario_rankings, best[0], window)))
    contact = _edge_contact(facts.edge)
    if contact:
        lines.append(contact)
    notes = run_notes(facts.run)
    if notes:
        lines.append(words.NOTE.format(notes=" ".join(notes)))
    return ["<!-- verdict -->", *[x for line in lines for x in (line, "")], "<!-- /verdict -->"]


def _edge_contact(edge):
    """Where most bearings' journal edges touch their shells: how much of the cycle, and whether the scheme matters."""
    if edge is None or not edge.computed or edge.touching < 0.5 * edge.computed:
        return None
    alike = max(edge.per_scheme_pct) - min(edge.per_scheme_pct) <= ALIKE_PCT
    return words.EDGE_CONTACT.format(schemes=fmt.percent_span(edge.per_scheme_pct),
                                     cycle=fmt.percent_span([100 * p for p in edge.per_position_share]),
                                     alike=words.EDGE_ALIKE_PART if alike else "", floor=100 * edge.floor)


def _scenario_winners(scenario_rankings, chosen):
    """Under which scenarios other schemes rank first while the chosen one does not."""
    parts = []
    for scenario, other in scenario_rankings.items():
        firsts = other.index[other["rank"] == 1]
        winners = [n for n in firsts if n != chosen]
        if winners and chosen not in firsts:
            parts.append(words.UNDER_SCENARIO_PART.format(scenario=scenario, names=words.bold_listed(winners),
                                                          s=words.plural(len(winners), "", "s")))
    return parts


def _centring(facts, ranking, chosen):
    """The scheme with the narrowest clearance, centred in the window, where it would beat the chosen one."""
    narrowest = ranking.clearance_std_um.idxmin()
    if narrowest == chosen or narrowest not in facts.centred.index:  # no window to centre in
        return []
    shift, outside, bearings = facts.centred.loc[narrowest, ["shift", "outside", "bearings"]]
    share, _, upper = proportion_ci(outside, bearings)
    chosen_row = ranking.loc[chosen]
    if outside and 1e6 * share > chosen_row.outside_window_ppm_ci[1]:
        return []  # centred, it would still put more outside than the chosen scheme: no case for it
    doubt = ("" if 1e6 * upper <= chosen_row.outside_window_ppm else
             words.CENTRED_DOUBT_PART.format(chosen=chosen, share=fmt.ppm(chosen_row.outside_window_ppm)))
    result = (words.CENTRED_SOME_PART.format(share=fmt.ppm(1e6 * share)) if outside else
              words.CENTRED_NONE_PART.format(bearings=fmt.count(int(bearings)), upper=fmt.ppm(1e6 * upper),
                                             doubt=doubt))
    return [words.CENTRED_PART.format(
        scheme=narrowest, std=ranking.loc[narrowest, "clearance_std_um"], chosen_std=chosen_row.clearance_std_um,
        shift=fmt.um(abs(shift)), side="below" if shift > 0 else "above", half=fmt.um(abs(shift) / 2),
        verb="thinner" if shift > 0 else "thicker", result=result)]


def _would_win(facts, ranking, scenario_rankings, chosen, window):
    """When another scheme would be the better choice: under a scenario, or with its clearance centred."""
    parts = _scenario_winners(scenario_rankings, chosen)
    if np.isfinite(window[1]):
        parts += _centring(facts, ranking, chosen)
    if parts:
        return "; ".join(parts) + "."
    why = (words.ALSO_NARROWEST_PART.format(chosen=chosen) if ranking.clearance_std_um.idxmin() == chosen else
           words.NO_CENTRING_PART)
    return words.NO_WIN_PART.format(why=why)


def run_notes(run):
    """Stages that failed on some engines, or did not run, said in words (``run``: a :class:`stackup.facts.Run`)."""
    notes = []
    if run.failures:
        notes.append(words.FAILURES_NOTE.format(lines="; ".join(run.failures)))
    if run.mechanics_engines_used == 0:
        reason = words.NONE_ASKED_PART if run.mechanics_engines_asked == 0 else words.NO_CRANK_PART
        notes.append(words.NO_MECHANICS_NOTE.format(reason=reason))
    return notes
