"""The report's sections on the mechanical chain: bearing loads, and oil film and life per bearing position.

Filled from the facts (:class:`stackup.facts.Facts`) like
:mod:`~stackup.report.sections`.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from . import format as fmt
from . import templates as words
from .sections import image, markdown_table, section


def crank_section(facts):
    crank, engines = facts.crank, facts.about.mechanics_engines
    if not engines or not (crank.engines > 0).any():
        return section("Bearing loads over the engine cycle", words.NO_CRANK)
    wide = crank.reset_index()
    cells = wide.assign(text=[f"{fmt.mean_std(m, c)} (max {fmt.fixed(x)})"
                              for m, c, x in zip(wide.mean_kn, wide.ci_kn, wide.max_kn)])
    table = cells.pivot(index="scheme", columns="bearing", values="text")
    table.columns = [f"bearing {b} [kN]" for b in table.columns]
    first = crank.groupby(level="scheme").first()
    table.insert(0, "engines (failed)", [f"{e} ({f})" for e, f in zip(first.engines, first.failed)])
    target = facts.study.target_error
    return section("Bearing loads over the engine cycle",
                   words.CRANK_INTRO.format(engines=fmt.count(engines),
                                            target=words.TARGET_PART.format(target=100 * target) if target else ""),
                   "", markdown_table(table.reset_index()))


def _film_table(facts):
    film, target = facts.film, facts.limits.life_target / 3600
    return pd.DataFrame({
        "scheme": film.index, "engines": film.engines,
        "h_min P5 [µm]": [fmt.triple(q, 2) for q in film.h_min_p05_um],
        "h_min median [µm]": [fmt.fixed(q[0], 2) for q in film.h_min_median_um],
        "cycle-mean film median [µm] (the life's)": [fmt.fixed(q[0], 2) for q in film.h_min_mean_median_um],
        "α mean [%]": [fmt.fixed(100 * v, 1) for v in film.alpha_mean],
        "α > 20 % [% of bearings]": [fmt.triple(v, 1) for v in film.alpha_over_20_pct],
        "bearing life B10 [h]": [fmt.significant_triple(q) for q in film.life_b10_h],
        "bearing life median [h]": [fmt.significant(q[0]) for q in film.life_median_h],
        "engine life B10 [h] (weakest bearing)": [fmt.significant_triple(q) for q in film.engine_life_b10_h],
        "method 2 life B10 [h] (∞: never below h_lim,cr)": [fmt.significant_triple(q) for q in film.wear_chart_b10_h],
        f"engines < {target:.0f} h [%]": [fmt.triple(v, 1) for v in film.engines_below_target_pct],
    })


def _positions_table(facts):
    per_bearing = facts.bearings.reset_index()
    h_table = per_bearing.assign(text=[fmt.fixed(q[0], 2) for q in per_bearing.h_min_median_um]).pivot(
        index="scheme", columns="bearing", values="text")
    life_table = per_bearing.assign(text=[fmt.significant(q[0]) for q in per_bearing.life_median_h]).pivot(
        index="scheme", columns="bearing", values="text")
    return pd.concat([h_table.add_prefix("h_min median [µm], bearing "),
                      life_table.add_prefix("bearing life median [h], bearing ")], axis=1).reset_index()


def _positions_text(positions):
    """Why film and life differ by bearing position, from the loads the positions carry in this study."""
    heavy, thin, load = positions.heaviest, positions.thinnest, positions.load_kn
    return words.POSITIONS.format(s="s" if len(heavy) > 1 else "", heaviest=words.listed(heavy),
                                  verb="y" if len(heavy) > 1 else "ies", most=load.max(), least=load.min(),
                                  thin_s="s" if len(thin) > 1 else "", thinnest=words.listed(thin))


def film_section(facts):
    if not len(facts.film):
        return section("Oil film and bearing life per bearing position", words.NO_FILM)
    intro = words.FILM_INTRO.format(method=facts.about.film_method, critical=fmt.um(facts.limits.critical_film, 2),
                                    target=fmt.whole(facts.limits.life_target / 3600))
    return section("Oil film and bearing life per bearing position", intro, "",
                   markdown_table(_film_table(facts)), "",
                   _positions_text(facts.positions), "",
                   markdown_table(_positions_table(facts)), "",
                   *_film_detail(facts),
                   image("Oil film and life per bearing position", "film_life.png"))


def _detail_cell(row):
    touching = words.TOUCHING_PART.format(share=100 * row.touching)
    if np.isfinite(row.edge_share):  # datasets before it have no share of the cycle
        touching += words.TOUCHING_SHARE_PART.format(share=100 * row.edge_share)
    edge_film = (words.EDGE_CONTACT_CELL if row.touching >= 0.5 else
                 words.EDGE_FILM_CELL.format(film=row.edge_film * fmt.UM))
    return words.DETAIL_CELL.format(tilt=row.tilt_max * 1e3, touching=touching, edge_film=edge_film,
                                    peak=row.p_max / 1e6, mean_peak=row.p_max_mean / 1e6)


def _outcomes_text(outcomes):
    """How the films ended: those that are not a number and what that leaves out, or all periodic; edge contact."""
    text = []
    total, edge = outcomes.computed, outcomes.edge_contact
    if outcomes.not_a_number:
        lost, engines = sum(outcomes.not_a_number.values()), outcomes.engines_not_a_number
        counts = ", ".join(words.NOT_A_NUMBER_COUNT_PART.format(count=fmt.count(k), status=m.replace("_", " "))
                           for m, k in outcomes.not_a_number.items())
        text.append(words.NOT_A_NUMBER.format(
            total=fmt.count(total), counts=counts, lost=fmt.count(lost), lost_s=words.plural(lost),
            engines=fmt.count(engines), engines_s=words.plural(engines), have=words.plural(engines, "have", "has"),
            are=words.plural(engines, "are", "is")))
    elif total and (outcomes.periodic or edge):
        text.append(words.ALL_PERIODIC.format(total=fmt.count(total)))
    if edge:
        text.append(words.EDGE_CYCLES.format(edge=fmt.count(edge), share=100 * edge / max(total, 1)))
    return [" ".join(text), ""] if text else []


def _heat_text(heat, crank):
    """The heat balance's film temperatures, friction powers and oil flows over the bearings whose film is a number."""
    if heat is None:
        return []
    (t, t_mid), (n, n_mid), (q, q_mid) = (fmt.spread(heat.film_temperature), fmt.spread(heat.friction_power),
                                          fmt.spread(heat.oil_flow_l_min, 2))
    supply = "" if crank is None else words.SUPPLY_PART.format(supply=crank.oil_supply_temperature_degC)
    return [words.HEAT.format(temperature=t, temperature_median=t_mid, supply=supply, power=n, power_median=n_mid,
                              flow=q, flow_median=q_mid), ""]


def _film_detail(facts):
    """Tilt, edge contact, edge film and peak film pressure per position; films that are not a number; heat."""
    if facts.outcomes is None:  # a study without the mechanical chain's film
        return []
    lines = []
    if len(facts.detail):
        table = facts.detail.assign(text=[_detail_cell(row) for row in facts.detail.itertuples()]).reset_index()
        table = table.pivot(index="scheme", columns="bearing", values="text")
        table.columns = [f"bearing {b}" for b in table.columns]
        lines += [words.FILM_DETAIL, "", markdown_table(table.reset_index()), ""]
    return lines + _outcomes_text(facts.outcomes) + _heat_text(facts.heat, facts.processes.crank)
