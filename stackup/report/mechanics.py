"""The report's section on the mechanical chain: loads, oil film and life per bearing position.

Filled from the facts (:class:`stackup.facts.Facts`) like
:mod:`~stackup.report.sections`, schemes in the ranking's order; the
per-position detail is the chosen scheme's (the schemes hardly differ there).
"""

from __future__ import annotations

from functools import partial

import numpy as np
import pandas as pd

from ..film.registry import check_tier
from . import format as fmt
from . import templates as words
from .sections import image, in_order, markdown_table, section


def _film_table(facts, order):
    """Per scheme: films, Levanov's operability criteria at the worst position (where any bearing fails one) and
    the engines' life (their weakest bearing's); lives are never pooled over positions."""
    film, target = in_order(facts.film, order), facts.limits.life_target / 3600
    table = pd.DataFrame({
        "scheme": film.index,
        "h_min P5 [µm]": [fmt.triple(q, 2) for q in film.h_min_p05_um],
        "h_min median [µm]": [fmt.fixed(q[0], 2) for q in film.h_min_median_um],
        words.ALPHA_COLUMN: [words.AT_POSITION.format(share=fmt.triple(v, 1), bearing=b)
                             for v, b in zip(film.alpha_over_20_pct, film.alpha_over_20_position)],
        words.SHORT_COLUMN.format(target=target): [
            words.AT_POSITION.format(share=fmt.triple(v, 1), bearing=b)
            for v, b in zip(film.life_below_target_pct, film.life_below_target_position)],
        "engine life B10 [h]": [fmt.significant_triple(q) for q in film.engine_life_b10_h],
        "engine life median [h]": [fmt.significant_triple(q) for q in film.engine_life_median_h],
    })
    for column, shares in ((words.ALPHA_COLUMN, film.alpha_over_20_pct),
                           (words.SHORT_COLUMN.format(target=target), film.life_below_target_pct)):
        if all(v[0] == 0 for v in shares):  # none anywhere: the intro says so
            table = table.drop(columns=column)
    if _same_scuffing(film) is not None:  # every scheme alike: the intro says so
        table = table.drop(columns=words.ALPHA_COLUMN)
    return table


def _same_scuffing(film):
    """(share [%], bearing) where every scheme has the same share of bearings over the scuffing limit at the same
    worst position, above zero; else None."""
    shares = [v[0] for v in film.alpha_over_20_pct]
    positions = set(film.alpha_over_20_position)
    if len(shares) > 1 and shares[0] > 0 and np.allclose(shares, shares[0]) and len(positions) == 1:
        return shares[0], positions.pop()
    return None


def _none_text(film):
    """What the film table leaves out because it is zero for every scheme."""
    scuffing = all(v[0] == 0 for v in film.alpha_over_20_pct)
    short = all(v[0] == 0 for v in film.life_below_target_pct)
    return (words.NO_SCUFFING_PART if scuffing else "") + (words.NONE_SHORT_PART if short else "")


def _same_text(film):
    """The share over the scuffing limit that every scheme has alike ('' where they differ)."""
    same = _same_scuffing(film)
    return "" if same is None else words.SAME_SCUFFING_PART.format(share=fmt.fixed(same[0], 1), bearing=same[1])


def _positions_table(facts, scheme):
    """Per position of ``scheme``: load, film, life, tilt, edge contact and peak film pressure (medians)."""
    bearings = facts.bearings.xs(scheme, level="scheme")
    rows = []
    for bearing, row in bearings.iterrows():
        cells = {"bearing": bearing, "load [kN]": fmt.fixed(facts.crank.loc[(scheme, bearing), "mean_kn"], 1),
                 "h_min median [µm]": fmt.fixed(row.h_min_median_um[0], 2),
                 "bearing life median [h]": fmt.significant(row.life_median_h[0])}
        if len(facts.detail) and (scheme, bearing) in facts.detail.index:
            d = facts.detail.loc[(scheme, bearing)]
            touching = words.TOUCHING_PART.format(share=100 * d.touching)
            if np.isfinite(d.edge_share):
                touching += words.TOUCHING_SHARE_PART.format(share=100 * d.edge_share)
            cells.update({"tilt [mrad]": fmt.fixed(1e3 * d.tilt_max, 2), "edge touches": touching,
                          "peak film pressure [MPa]": fmt.fixed(d.p_max / 1e6, 0)})
        rows.append(cells)
    return pd.DataFrame(rows)


def _positions_text(positions, scheme):
    """Which positions carry the largest loads and the thinnest films in this study."""
    heavy, thin = positions.heaviest, positions.thinnest
    return words.POSITIONS.format(scheme=scheme, s="s" if len(heavy) > 1 else "", heaviest=words.listed(heavy),
                                  verb="y" if len(heavy) > 1 else "ies", thin_s="s" if len(thin) > 1 else "",
                                  thinnest=words.listed(thin))


def film_section(facts, ranking):
    if not len(facts.film):
        return section("Loads, oil film and bearing life", words.NO_FILM)
    crank = facts.crank[facts.crank.engines > 0]
    spread = crank.mean_kn.groupby(level="bearing").agg(lambda v: v.max() - v.min()).max()
    failed = int(crank.failed.groupby(level="scheme").first().sum())
    surface = facts.edge is not None and facts.edge.surface
    width = facts.edge is not None and facts.edge.counted and facts.study.tilt_method == "equilibrium"
    where = words.SURFACE_PART if surface else words.WIDTH_PART if width else ""
    intro = words.FILM_INTRO.format(where=where, method=facts.about.film_method,
                                    critical=fmt.um(facts.limits.critical_film, 2),
                                    target=fmt.whole(facts.limits.life_target / 3600),
                                    engines=fmt.count(facts.about.mechanics_engines), spread=fmt.fixed(spread, 1),
                                    failed=words.FAILED_PART.format(failed=failed) if failed else "",
                                    scaled=words.SCALED_PART if len(facts.corrected) else "",
                                    none=_none_text(facts.film), same=_same_text(facts.film))
    lines = [intro, "", markdown_table(_film_table(facts, ranking.index)), ""]
    scheme = next((s for s in ranking.index if s in facts.bearings.index.get_level_values("scheme")), None)
    if scheme is not None:
        lines += [_positions_text(facts.positions, scheme), "", markdown_table(_positions_table(facts, scheme)), ""]
    return section("Loads, oil film and bearing life", *lines,
                   *_outcomes_text(facts.outcomes, facts.edge, _tolerance_text(facts, ranking.index)),
                   *_heat_text(facts.heat, facts.processes.crank), *_corrected_text(facts.corrected, scheme),
                   *_method1_range_text(facts, scheme),
                   *_trends_text(facts.trends),
                   image("Oil film and life per bearing position", "film_life.png"),
                   *([] if facts.about.summaries else
                     ["", image("Oil film and life against operating clearance per position",
                                "film_life_clearance.png")]))


def _corrected_text(corrected, scheme):
    """The chosen scheme's film and life means corrected by the check tier, over the positions, against the study
    tier's (multi-fidelity control variates)."""
    if not len(corrected) or scheme not in corrected.index.get_level_values("scheme"):
        return []
    mine = corrected.xs(scheme, level="scheme")

    def span(column, scale, write):
        values, lows, highs = (np.array([q[k] for q in mine[f"{column}_corrected"]]) * scale for k in range(3))
        cheap = mine[f"{column}_cheap"].to_numpy() * scale
        return words.CORRECTED_SPAN.format(lo=write(values.min()), hi=write(values.max()),
                                           half=write(np.max(np.maximum(values - lows, highs - values))),
                                           cheap_lo=write(cheap.min()), cheap_hi=write(cheap.max()))

    film = partial(fmt.fixed, digits=2)
    return [words.CORRECTED.format(method=check_tier().name, pairs=int(mine.pairs.min()), engines=int(mine.engines.max()),
                                   scheme=scheme, h_min=span("h_min", fmt.UM, film),
                                   h_min_mean=span("h_min_mean", fmt.UM, film),
                                   life=span("life", 1 / 3600, fmt.significant)), ""]


def _method1_range_text(facts, scheme):
    """Where the film Levanov's method 1 reads (the check's scale where the study checked) is below h_lim,cr for
    ``scheme``: there his law gives lives of hours, outside the films his constants were fitted on."""
    statistic = "h_min_mean" if facts.study.life_film == "cycle-mean" else "h_min"
    if len(facts.corrected) and scheme in facts.corrected.index.get_level_values("scheme"):
        films = {int(b): q[0] for b, q in facts.corrected.xs(scheme, level="scheme")[f"{statistic}_corrected"].items()}
    elif len(facts.bearings) and scheme in facts.bearings.index.get_level_values("scheme"):
        films = {int(b): q[0] / fmt.UM for b, q in facts.bearings.xs(scheme, level="scheme")[
            f"{statistic}_median_um"].items()}
    else:
        return []
    critical = facts.limits.critical_film
    low = {b: h for b, h in films.items() if np.isfinite(h) and h < critical}
    if not low:
        return []
    return [words.METHOD1_RANGE.format(
        s=words.plural(len(low)), bearings=words.listed(list(low)), scheme=scheme,
        statistic=statistic.replace("h_min_mean", "cycle-mean film").replace("h_min", "cycle-minimum film"),
        films=" / ".join(fmt.fixed(1e6 * h, 2) for h in low.values()), critical=fmt.um(critical, 2)), ""]


def _trends_text(trends):
    """Where method 1's life and the cycle-minimum film follow the clearance in opposite directions (figure)."""
    if trends is None or not trends.opposed:
        return []
    every = len(trends.opposed) == len(trends.film)
    where = words.EVERY_POSITION if every else words.AT_POSITIONS.format(bearings=words.listed(trends.opposed))
    return [words.OPPOSED_TRENDS.format(where=where, film=fmt.signed_span(trends.film[trends.opposed]),
                                        life=fmt.signed_span(trends.life[trends.opposed]),
                                        pairs=fmt.count(trends.pairs)), ""]


def _tolerance_text(facts, order):
    """Whether the tolerances change the edge contact: the first-ranked scheme's paired change of the share of the
    cycle below h_lim,cr under the scenario that scales the misalignment ('' without one, or without the data)."""
    if facts.misalignment is None or facts.edge is None or facts.edge.per_position is None:
        return ""
    label, factor = facts.misalignment
    positions, _ = facts.life_changes[label]
    scheme = next((s for s in order if s in positions.index.get_level_values("scheme")), None)
    if scheme is None:
        return ""
    mine = positions.xs(scheme, level="scheme")
    changes = np.round([v[0] for v in mine.edge_share_change_pts], 1) + 0.0  # + 0.0: no "−0.0"
    if not np.all(np.isfinite(changes)):
        return ""
    beyond = [int(b) for b, v in mine.edge_share_change_pts.items() if v[1] > 0 or v[2] < 0]
    lo, hi = (fmt.signed(v, 1) for v in (changes.min(), changes.max()))
    spread = (words.EDGE_TOLERANCE_NONE if not np.any(changes) else f"changes by {lo} points" if lo == hi else
              f"changes by {lo} to {hi} points")
    return words.EDGE_TOLERANCE.format(
        factor=f"{factor:g}", label=label, pairs=int(mine.pairs.min()), scheme=scheme, changes=spread,
        contact=words.BELOW_CRITICAL if facts.edge.surface else words.AT_WALL,
        first=int(mine.index.min()), last=int(mine.index.max()),
        beyond=(words.EDGE_TOLERANCE_BEYOND.format(s=words.plural(len(beyond)), bearings=words.listed(beyond))
                if beyond else words.EDGE_TOLERANCE_WITHIN))


#: Positions where fewer of the bearings than this [%] have an edge at the wall are counted, not described.
FEW_TOUCHING_PCT = 5.0


def _outcomes_text(outcomes, edge_contact, tolerance=""):
    """How the films ended: those that are not a number and what that leaves out, or all periodic; edge contact."""
    if outcomes is None:
        return []
    text = []
    total, edge = outcomes.computed, outcomes.edge_contact
    if outcomes.not_a_number:
        engines = outcomes.engines_not_a_number
        counts = ", ".join(words.NOT_A_NUMBER_COUNT_PART.format(count=fmt.count(k), status=m.replace("_", " "))
                           for m, k in outcomes.not_a_number.items())
        text.append(words.NOT_A_NUMBER.format(total=fmt.count(total), counts=counts, engines=fmt.count(engines),
                                              engines_s=words.plural(engines), have=words.plural(engines, "have", "has")))
    elif total and (outcomes.periodic or edge):
        text.append(words.ALL_PERIODIC.format(total=fmt.count(total)))
    if edge and edge_contact is not None and edge_contact.surface:
        text.append(words.EDGE_SURFACE.format(edge=fmt.count(edge), share=100 * edge / max(total, 1),
                                              critical=fmt.fixed(1e6 * edge_contact.critical, 2),
                                              positions="; ".join(_edge_positions(edge_contact.per_position)),
                                              periodic=fmt.percent(edge_contact.periodic)))
    elif edge:
        floor = 100 * edge_contact.floor if edge_contact is not None else np.nan
        if edge_contact is not None and edge_contact.per_position is not None:
            rows = edge_contact.per_position
            few = rows.touching_pct < FEW_TOUCHING_PCT  # named as a count: a stray bearing or two
            counted = dict(count=int(few.sum()), s=words.plural(int(few.sum())), share=f"{FEW_TOUCHING_PCT:g} %")
            if few.all():
                positions, others = words.EDGE_FEW_PART.format(**counted), ""
            else:
                positions = "; ".join(_edge_positions(rows[~few]))
                others = words.EDGE_OTHERS_PART.format(**counted) if few.any() else ""
            text.append(words.EDGE_COUNTED.format(edge=fmt.count(edge), share=fmt.percent(edge / max(total, 1)),
                                                  floor=floor, positions=positions, others=others))
        else:
            text.append(words.EDGE_CYCLES.format(edge=fmt.count(edge), share=100 * edge / max(total, 1), floor=floor))
    if edge_contact is not None and edge_contact.per_position is not None:
        # also where no edge touches in the study: the tolerances may make some, and the march's convergence is
        # the march's, not the contact's
        median, high = edge_contact.unresolved
        unresolved = (words.EDGE_UNRESOLVED.format(median=fmt.percent(median), high=fmt.percent(high))
                      if edge_contact.surface and np.isfinite(median) and high > 0 else "")
        if (tolerance + unresolved).strip():
            text.append((tolerance + unresolved).strip())
    return [" ".join(text), ""] if text else []


def _edge_positions(rows):
    """Per position with an edge in contact: over how much of the cycle (5-95 % over the engines; the share of
    bearings and the median share are the positions table's), how thin, at what load and where."""
    return [words.EDGE_POSITION_PART.format(bearing=b, lo=fmt.percent(r.cycle_lo), hi=fmt.percent(r.cycle_hi),
                                            film=fmt.fixed(1e6 * r.film, 2), load=fmt.fixed(r.load / 1e3, 1),
                                            angle=fmt.whole(r.angle))
            for b, r in rows.iterrows()]


def _heat_text(heat, crank):
    """The heat balance's film temperatures, friction powers and oil flows over the bearings whose film is a number."""
    if heat is None:
        return []
    (t, t_mid), (n, _), (q, _) = (fmt.spread(heat.film_temperature), fmt.spread(heat.friction_power),
                                  fmt.spread(heat.oil_flow_l_min, 2))
    supply = "" if crank is None else words.SUPPLY_PART.format(supply=crank.oil_supply_temperature_degC)
    return [words.HEAT.format(temperature=t, temperature_median=t_mid, supply=supply, power=n, flow=q), ""]
