"""The words of the comparison report: the verdict, methods and assumptions, limits of validity, parameters.

Each function reads saved datasets (and tables made from them) and returns
markdown lines; nothing here computes a model.
"""

from __future__ import annotations

import json

import numpy as np
import pandas as pd

from ..film.orbit import ECCENTRICITY_LIMIT
from ..life import levanov_method1
from ..stats import proportion_ci
from ..study.failures import FailureCount
from ..study.schema import flag
from .tables import UM, centred, kept_summaries, separates

#: Press-fit tiers in words; their errors against the finite-element reference are measured by
#: ``python studies/press_fit_tiers.py`` (reports/press_fit_tiers.md).
FIT_TIERS = {
    "lame": "thick-ring (Lamé) tier, exact within linear plane-stress elasticity",
    "thin-ring": "thin-ring tier (a shop formula: ignores the shell's radial stress)",
    "fe": "finite-element reference tier",
}
#: Crankshaft support tiers in words (reports/bench_crank.md).
CRANK_TIERS = {
    "bearing-law": "continuous beam on the nonlinear bearing law of Bellakhdhar et al. (2013)",
    "linear": "continuous beam on linear springs (the bearing law's low stiffness)",
    "rigid": "continuous beam on rigid supports",
}
#: A best share outside the window at or above this [ppm] (1 %) means that no scheme meets the window.
MEETS_WINDOW_PPM = 10_000
#: Names of the ranking metrics in words.
METRICS = {"outside_window_ppm": "share outside the design window",
           "alpha_over_limit_pct": "share of bearings with more than 20 % of the cycle in boundary friction",
           "life_median_h": "median bearing life"}


def _um(value, digits=1):
    return f"{value * UM:.{digits}f}"


def _um_edge(value):
    """A window edge in µm: whole micrometres unless it has a fraction (34.5, not 34)."""
    if not np.isfinite(value):
        return "∞" if value > 0 else "−∞"
    um = round(value * UM, 3)
    return f"{um:.0f}" if um == round(um) else f"{um:g}"


def ppm_digits(value, upper=None):
    """Decimals of a share in ppm: none from 10 ppm, a tenth below, two significant digits below 1 (0.05 is not 0)."""
    if abs(value) >= 10 or (upper is not None and abs(upper) >= 10):
        return 0
    if not np.isfinite(value) or abs(value) >= 1 or value == 0:
        return 1
    return int(min(3, max(1, 1 - np.floor(np.log10(abs(value))))))


def _ppm(value, ci=None):
    """A share in ppm with its interval, to the value's precision (:func:`ppm_digits`)."""
    digits = ppm_digits(value, None if ci is None else ci[1])
    text = f"{value:,.{digits}f} ppm"
    return text + (f" [{ci[0]:,.{digits}f}, {ci[1]:,.{digits}f}]" if ci is not None else "")


def _source(row):
    """' (estimated ... †)' where the ranking took the share from the tails, else ''."""
    source = row.get("outside_window_source", "counted")
    return "" if source == "counted" else f" (estimated: {source} †)"


def _names(names):
    names = [f"**{n}**" for n in names]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def verdict(ds, ranking, scenario_rankings):
    """The opening summary: what to use and why, what it costs, what it is fragile to, when another would win.

    ``scenario_rankings`` maps each declared scenario to the ranking of the
    schemes under it.
    """
    window = ranking.attrs["window_m"]
    middle = 0.5 * (window[0] + window[1])
    best = list(ranking.index[ranking["rank"] == 1])
    first = ranking.loc[best[0]]
    lines = []
    if not np.isfinite(window[1]):
        lines.append("The engine file gives no operating-clearance design window (`[targets] operating_clearance`), "
                     "so no scheme can be judged by the share of bearings outside it; give one in the engine file "
                     "or with `stackup compare --window LO HI`. The ranking below uses the other metrics only.")
    if np.isfinite(window[1]) and np.nanmin(ranking.outside_window_ppm) >= MEETS_WINDOW_PPM:
        lo_um, hi_um = _um_edge(window[0]), _um_edge(window[1])
        lines.append(f"**No scheme meets the window {lo_um}–{hi_um} µm:** the best puts "
                     f"{_ppm(np.nanmin(ranking.outside_window_ppm))} of its bearings outside it. Check the window "
                     "against the operating clearances below (nominal clearance plus the housing's swell) before "
                     "choosing a scheme; the ranking orders the schemes all the same.")
    if len(best) == 1:
        others = ranking.drop(index=best)
        runner = others.index[0] if len(others) else None
        why = (f"{_ppm(first.outside_window_ppm, first.outside_window_ppm_ci)}{_source(first)} of its bearings "
               f"fall outside the operating-clearance window {_um_edge(window[0])}–{_um_edge(window[1])} µm")
        if runner is not None:
            r = ranking.loc[runner]
            why += f", against {_ppm(r.outside_window_ppm, r.outside_window_ppm_ci)} for the next, {runner}"
        lines.append(f"**Use {best[0]}** for {ds.attrs['engine']}: {why}. Its operating clearance is "
                     f"{first.clearance_mean_um:.1f} ± {first.clearance_std_um:.1f} µm (mean ± standard deviation; "
                     f"the window's middle is {_um(middle)} µm).")
    else:
        cheapest = min(best, key=lambda n: (ranking.loc[n, "shell_grades"], ranking.loc[n, "surplus_pct"]))
        c = ranking.loc[cheapest]
        others = [n for n in best if n != cheapest]
        versus = ", ".join(f"{ranking.loc[n, 'shell_grades']} and {ranking.loc[n, 'surplus_pct']:.1f} % for {n}"
                           for n in others)
        text = (f"{_names(best)} tie: their 95 % intervals overlap on every ranking metric. Of these, "
                f"**{cheapest}** needs the fewest shell grades, then the least surplus ({c.shell_grades} grades, "
                f"{c.surplus_pct:.1f} % of the shells left over, against {versus}): use it unless another reason "
                "decides")
        more_stockouts = [n for n in others if ranking.loc[n, "stockout_ppm"] < c.stockout_ppm]
        if more_stockouts:
            text += (f"; it has more stock-outs, though ({c.stockout_ppm:.0f} ppm of bearings waiting for a shell "
                     "against " + ", ".join(f"{ranking.loc[n, 'stockout_ppm']:.0f} ppm for {n}" for n in more_stockouts)
                     + ")")
        lines.append(text + ".")
        first = ranking.loc[cheapest]
        best = [cheapest]
    lines.append(f"**What it costs:** {int(first.shell_grades)} shell grade{'s' if first.shell_grades > 1 else ''} "
                 f"to make and stock, {first.surplus_pct:.1f} % of the shells made left over at the ends of the lots, "
                 f"{_ppm(first.stockout_ppm)} of bearings waiting for a shell (stock-outs); the planning section "
                 "gives the quantities per grade.")
    if "worst_outside_window_ppm" in ranking:
        # the worst change of each metric over the declared scenarios; a change for the better is no fragility
        change, scenario = first.worst_outside_window_ppm, first.worst_outside_window_ppm_scenario
        fragile = [f"{scenario}, which adds {_ppm(change)} outside the window"] if change > 0 else []
        life = first.get("worst_life_median_h", np.nan)
        if "worst_life_median_h" in ranking and np.isfinite(life) and life < 0:
            fragile.append(f"{first.worst_life_median_h_scenario}, which shortens its median bearing life by "
                           f"{-life:.3g} h (on the engines the scenario ran its crankshaft and film on)")
        lines.append("**What it is fragile to:** " + ("; ".join(fragile) if fragile else
                     "none of the declared scenarios makes it worse on the window or the life") + ".")
    lines.append("**When another scheme would win:** " + _would_win(ds, ranking, scenario_rankings, best[0], window))
    contact = _edge_contact(ds)
    if contact:
        lines.append("**Edge contact:** " + contact)
    notes = run_notes(ds)
    if notes:
        lines.append("**Note:** " + " ".join(notes))
    return ["<!-- verdict -->", *[x for line in lines for x in (line, "")], "<!-- /verdict -->"]


def _edge_contact(ds):
    """Where most bearings' journal edges touch their shells: how much of the cycle, and whether the scheme matters."""
    if "edge_contact_share" not in ds or "film_status" not in ds:
        return None
    status = ds.film_status.values
    ran = (status != flag(ds.film_status, "not_computed")) & ds.film_valid.values
    touching = ran & (status == flag(ds.film_status, "edge_contact"))
    if not ran.any() or touching.sum() < 0.5 * ran.sum():
        return None
    share = ds.edge_contact_share.values
    per_position = [np.nanmedian(share[..., b][touching[..., b]]) for b in range(share.shape[-1])
                    if touching[..., b].any()]
    per_scheme = [100 * touching[i].sum() / ran[i].sum() for i in range(len(ds.scheme)) if ran[i].any()]
    alike = max(per_scheme) - min(per_scheme) <= 5

    def span(values):
        lo, hi = f"{min(values):.0f}", f"{max(values):.0f}"
        return lo if lo == hi else f"{lo}-{hi}"

    return (f"the journal's edge touches its shell in {span(per_scheme)} % of each scheme's bearings whose film "
            f"was computed, over {span([100 * p for p in per_position])} % of the cycle (median per bearing "
            "position): the crankshaft's slope "
            "at the supports, bent by the loads and the bores' and journals' misalignment, is more than the film's "
            "moment can turn back. "
            + ("The choice of scheme hardly changes it. " if alike else "")
            + f"There the rigid film has no film left to give: the edge is held at a floor of "
            f"{100 * (1 - ECCENTRICITY_LIMIT):.1f} % of the radial clearance (no elastic shell edge, no EHD), which is "
            "boundary contact at the edge; α, the lives and the wear chart read the mid-plane film and do not count "
            "it (oil film section).")


def _would_win(ds, ranking, scenario_rankings, chosen, window):
    """When another scheme would be the better choice: under a scenario, or with its clearance centred."""
    parts = []
    for scenario, other in scenario_rankings.items():
        winners = [n for n in other.index[other["rank"] == 1] if n != chosen]
        if winners and chosen not in other.index[other["rank"] == 1]:
            parts.append(f"under {scenario}, {_names(winners)} rank{'s' if len(winners) == 1 else ''} first")
    narrowest = ranking.clearance_std_um.idxmin()
    if narrowest != chosen and np.isfinite(window[1]):
        shift, outside, bearings = centred(ds, narrowest, window)
        share, _, upper = proportion_ci(outside, bearings)
        n = ranking.loc[narrowest]
        verb = "thinner" if shift > 0 else "thicker"
        chosen_hi = ranking.loc[chosen, "outside_window_ppm_ci"][1]
        if outside and 1e6 * share > chosen_hi:
            narrowest = None  # centred, it would still put more outside than the chosen scheme: no case for it
    if narrowest not in (None, chosen) and np.isfinite(window[1]):
        doubt = ("" if 1e6 * upper <= ranking.loc[chosen, "outside_window_ppm"] else
                 f", too few to tell it from {chosen}'s {_ppm(ranking.loc[chosen, 'outside_window_ppm'])}")
        parts.append(f"{narrowest} has the narrowest operating clearance ({n.clearance_std_um:.2f} µm standard "
                     f"deviation against {ranking.loc[chosen, 'clearance_std_um']:.2f} µm) but its mean sits "
                     f"{abs(shift) * UM:.1f} µm {'below' if shift > 0 else 'above'} the window's middle: with "
                     f"shells aimed {abs(shift) * UM / 2:.1f} µm {verb} each it would put "
                     + (f"about {_ppm(1e6 * share)} outside" if outside else
                        f"none of its {bearings:,} bearings outside (below {_ppm(1e6 * upper)} at 95 %{doubt})")
                     + "; `stackup design` designs such a scheme")
    if not parts:
        return ("no declared scenario changes the choice, and "
                + (f"{chosen} also has the narrowest clearance." if ranking.clearance_std_um.idxmin() == chosen else
                   "centring a scheme with a narrower clearance would not put fewer bearings outside the window."))
    return "; ".join(parts) + "."


def run_notes(ds):
    """Stages that failed on some engines, or did not run, said in words."""
    notes = []
    failures = FailureCount.of_dataset(ds).lines()
    if failures:
        notes.append("Some stages failed on part of the engines (marked in the dataset, left out of the "
                     "statistics): " + "; ".join(failures) + ".")
    study = json.loads(ds.attrs["study"])
    if int(ds.attrs.get("mechanics_engines_used", 0)) == 0:
        reason = ("the study asked for none (`mechanics_engines=0`)" if study.get("mechanics_engines") == 0
                  else "the engine file has no `[crank]` section")
        notes.append(f"The crankshaft, oil film and life stages did not run: {reason}; the ranking uses the "
                     "clearance only.")
    return notes


def non_discriminating(ranking):
    """Sentences naming the ranking metrics that do not separate the schemes here."""
    out = []
    for column, label in METRICS.items():
        if column not in ranking or f"{column}_ci" not in ranking:
            continue
        bounds = [ci if isinstance(ci, tuple) else (np.nan, np.nan) for ci in ranking[f"{column}_ci"]]
        low, high = zip(*bounds)
        if not separates(low, high):
            values = ranking[column].astype(float)
            same = f" ({values.iloc[0]:.3g} for every scheme)" if np.allclose(values, values.iloc[0]) else ""
            out.append(f"The {label}{same} does not separate the schemes here: every pair of 95 % intervals "
                       "overlaps, so it does not decide the ranking.")
    return out


def tighten_first(sensitivity, ranking):
    """One sentence per analysed output of the recommended scheme: which input to tighten first."""
    chosen = ranking.index[0]
    labels = {"clearance_operating": "operating clearance", "h_min": "smallest film", "life": "life"}
    out = []
    for output in sensitivity.output.values:
        schemes = [s for s in sensitivity.scheme.values
                   if np.isfinite(sensitivity.ST.sel(output=output, scheme=s).values).any()]
        scheme = chosen if chosen in schemes else (schemes[0] if schemes else None)
        if scheme is None:
            continue
        d = sensitivity.sel(output=output, scheme=scheme).to_dataframe().dropna(subset=["ST"])
        d = d.sort_values("ST", ascending=False)
        top, second = d.iloc[0], d.iloc[1]
        text = (f"**Tighten first ({scheme}, {labels.get(str(output), output)}):** the {d.index[0]}, with a total "
                f"index of {top.ST:.2f} [{top.ST_lo:.2f}, {top.ST_hi:.2f}] of the variance "
                f"(first-order {top.S1:.2f}), then the {d.index[1]} ({second.ST:.2f}).")
        gauges = d[d.index.str.contains("gauge")]
        if len(gauges) and gauges.ST.max() >= 0.05:
            text += (" The gauges matter through misgrading: " + ", ".join(
                f"{name} {row.ST:.2f}" for name, row in gauges.iterrows() if row.ST >= 0.05) + " (total indices).")
        out += [text, ""]
    return out[:-1]


def read_out_notes(ds, summary):
    """Why a scheme's worst case goes beyond its stated range: readings rounded to the scheme's read-out."""
    out = []
    for name in ds.scheme.values:
        resolution = ds.reading_resolution.sel(scheme=name).values
        row = summary.loc[str(name)]
        if np.any(resolution > 0) and (row.worst_case_min_um < row.stated_min_um - 1e-6
                                       or row.worst_case_max_um > row.stated_max_um + 1e-6):
            step = _um(float(resolution.max()), 0)
            out.append(f"{name} reads housing bores and journals to {step} µm: a reading rounded to the nearest "
                       f"{step} µm lands in its class, so a part up to half a step outside the class is paired as "
                       f"if inside it. That is why its worst case, {row.worst_case_min_um:.1f}–"
                       f"{row.worst_case_max_um:.1f} µm, reaches beyond the stated {row.stated_min_um:.0f}–"
                       f"{row.stated_max_um:.0f} µm; the share outside the stated range counts those bearings.")
    return out


def methods(ds):
    """Methods and assumptions, in one place: processes, gauges, press fit, temperatures, tiers, sample sizes."""
    study = json.loads(ds.attrs["study"])
    press = json.loads(ds.attrs["press_fit"])
    proc = json.loads(ds.attrs["engine_processes"])

    def dimension(label, d):
        lo, hi = d["limits_m"]
        text = (f"{label} {lo * 1e3:.3f}–{hi * 1e3:.3f} mm, {d['distribution'].lower()} process, "
                f"C_pk {d['cpk']:.2f} (σ {d['std_m'] * UM:.2f} µm)")
        if d["shared"]:
            text += f", {100 * d['shared']:.0f} % of the variance common to one part's bearings"
        gauge = d["gauge_repeatability_m"] * UM
        if gauge or d["gauge_resolution_m"]:
            text += f"; gauge repeatability {gauge:.2f} µm"
            if d["gauge_resolution_m"]:
                text += f", read-out {d['gauge_resolution_m'] * UM:g} µm"
        return text

    shell = proc["shell_wall"]
    crush = proc["crush_height"]
    n_mech = int(ds.attrs.get("mechanics_engines_used", 0))
    lines = [
        f"- **Parts:** {dimension('housing bore', proc['housing_bore'])}; "
        f"{dimension('journal', proc['journal_d'])}. Parts read outside their drawing limits are scrapped.",
        f"- **Shells:** made to order per lot of {shell['lot_engines']} engines with {100 * shell['surplus']:.0f} % "
        f"surplus, each grade aimed at its centre (wall σ {shell['sigma_m'] * UM:.2f} µm), read (repeatability "
        f"{shell['gauge_repeatability_m'] * UM:.2f} µm) and sorted into grades; quantities planned from a pilot of "
        f"{ds.attrs['pilot_engines']:,} engines. Crush height {crush['limits_m'][0] * 1e3:.3f}–"
        f"{crush['limits_m'][1] * 1e3:.3f} mm, C_pk {crush['cpk']:.2f}."
        if shell["supply"] == "to-order" else
        f"- **Shells:** one process sorted into grades (supply `{shell['supply']}`), lots of {shell['lot_engines']} "
        f"engines with {100 * shell['surplus']:.0f} % surplus.",
        f"- **Press fit:** {press['housing_material']} housing (equivalent outer diameter "
        f"{press['housing_outer'] * 1e3:.0f} mm), {press['shell_material']} shells {press['length'] * 1e3:.0f} mm "
        f"wide, crush height checked in a {press['check_bore'] * 1e3:.3f} mm block at "
        f"{press['check_stress'] / 1e6:.0f} MPa; {FIT_TIERS.get(study['fit_method'], study['fit_method'])} "
        "(its error against the finite-element reference: reports/press_fit_tiers.md).",
        f"- **Temperatures:** assembled at {press['assembly_temperature']:.0f} °C, running at "
        f"{press['temperature']:.0f} °C (housing, shells and journal)"
        + (f"; oil {proc['crank']['oil']} supplied at {proc['crank']['oil_supply_temperature_degC']:.0f} °C, "
           "film temperature from the bearing's heat balance." if "crank" in proc else "."),
        f"- **Clearance:** nominal C = D_H − (s_upper + s_lower + D_J) from true sizes, grading by the readings; "
        f"operating clearance with press fit, housing swell and temperature, on all {study['n_engines']:,} engines "
        f"× {ds.sizes['bearing']} bearings per scheme.",
    ]
    if n_mech:
        crank = proc["crank"]
        lines += [
            f"- **Crankshaft and loads:** {CRANK_TIERS.get(study['crank_method'], study['crank_method'])} at "
            f"{crank['speed_rpm']:.0f} rpm over the cycle in {study['crank_angle_step']:g}° steps, with each engine's "
            f"operating clearances and its sampled bore coaxiality (drawing {crank['coaxiality_m'] * UM:.0f} µm) and "
            f"journal run-out ({crank['journal_runout_m'] * UM:.0f} µm); on the first {n_mech:,} engines of each "
            "scheme (a random sample: lots are independent).",
            _film_method(ds),
            _life_method(ds, study),
        ]
    lines += [
        "- **Statistics:** 95 % intervals: order statistics for quantiles, Clopper–Pearson for shares, normal "
        "approximation for means. Scenarios reuse the study's seed (common random numbers), so their changes are "
        "differences on the same parts.",
    ]
    if kept_summaries(ds):
        lines.append("- **Summaries:** this dataset keeps streaming summaries: quantiles and histograms to "
                     "0.1 µm, exact counts.")
    return lines


def _film_method(ds):
    """The film tier, what it solves and its measured error against the transient reference, in one bullet."""
    method = ds.attrs["film_method_used"]
    what = {"mobility": "journal orbit over the cycle by the short-bearing mobility method (squeeze and rotation, "
                        "Booker)",
            "mobility-finite": "journal orbit over the cycle by the mobility method with a finite-length "
                               "correction tabulated from the Reynolds equation (squeeze and rotation)",
            "transient": "journal orbit over the cycle on the transient Reynolds equation with mass-conserving "
                         "cavitation (the reference)",
            "short": "quasi-static short-bearing film at each crank angle (no squeeze)",
            "finite": "quasi-static finite-bearing film at each crank angle (no squeeze)",
            "reynolds": "quasi-static Reynolds film at each crank angle (no squeeze)"}.get(method, method)
    text = f"- **Oil film:** `{method}` tier, {what}, with the bearing's heat balance (feed and side flow)"
    if "film_method_errors" in ds.attrs:
        e = json.loads(ds.attrs["film_method_errors"])
        text += (f"; its largest error against the transient Reynolds reference with mass-conserving cavitation "
                 f"on the built-in engines' bearings: {100 * e['h_min']:.0f} % on the cycle-minimum film, "
                 f"{100 * e['h_min_mean']:.0f} % on its cycle mean, at {1e3 * e['seconds']:.1f} ms per bearing-cycle "
                 "for the orbit alone (reports/film_speed_vs_error.md; the film stage with its heat balance and the "
                 "tilt equilibrium against the crankshaft cycle: reports/bench_chain.md)")
    return text + "."


def _life_method(ds, study):
    """The life methods, their film and constants with sources, in one bullet."""
    wear = json.loads(ds.attrs["wear"])
    film = study.get("life_film", "cycle-mean")
    return (f"- **Life:** Levanov et al. (2015) method 1 (eqs. 4-5) on the {film.replace('-', ' ')} of the minimum "
            "film over the cycle"
            + (" (the paper's Table 1 pairs films of 5-9 µm with 5-17 % of the cycle in boundary friction, which only "
               "the cycle mean allows)" if film == "cycle-mean" else " (a comparison: the paper implies the cycle mean)")
            + f"; critical film h_lim,cr = {wear['critical_film_m'] * UM:.2f} µm from the journal's and the shell's "
            f"roughness (Rz {wear['journal_rz_m'] * UM:.2f} + {wear['shell_rz_m'] * UM:.2f} µm, eq. 3; "
            f"{' '.join(wear['roughness_source'].split())}), limiting wear {wear['wear_limit_m'] * UM:.0f} µm and wear speed "
            f"{wear['wear_rate_m_per_s']:.0e} m/s ({' '.join(wear['wear_source'].split())}). Method 2 (eqs. 6-7): a wear chart "
            "over the bearing surface where the film is below h_lim,cr, with the asperity contact pressure of "
            "Greenwood and Tripp. An engine's life is that of its weakest bearing.")


def _life_bias(ds):
    """What the film tier's error on the cycle-mean film does to method 1's life, at the study's median film.

    The tier's largest error on the cycle mean (always thick, reports/film_speed_vs_error.md) taken off the
    median cycle-mean film of the bearings the chain ran; life by the study's own method 1 and constants.
    """
    if "film_method_errors" not in ds.attrs or "wear" not in ds.attrs or "h_min_mean" not in ds:
        return ""
    error = json.loads(ds.attrs["film_method_errors"])["h_min_mean"]
    films = ds.h_min_mean.values
    films = films[np.isfinite(films)]
    if not films.size or error <= 0:
        return ""
    wear = json.loads(ds.attrs["wear"])
    h = float(np.median(films))
    lives = levanov_method1(np.array([h, h / (1 + error)]), h_lim_cr=wear["critical_film_m"],
                            wear_limit=wear["wear_limit_m"], wear_rate=wear["wear_rate_m_per_s"]).life / 3600
    cap = wear["wear_limit_m"] / wear["wear_rate_m_per_s"] / 3600
    return (f"Method 1 reads the cycle-mean film, which the film tier puts up to {100 * error:.0f} % thicker than "
            f"the transient reference (Methods): at this study's median cycle-mean film, {h * UM:.1f} µm, that "
            f"makes a life {lives[0] / lives[1]:.1f} times as long ({round(lives[0], -2):,.0f} h against "
            f"{round(lives[1], -2):,.0f} h at "
            f"{h / (1 + error) * UM:.1f} µm), and the method caps a life at Δh_lim/γ = {cap:,.0f} h. ")


def limits_of_validity(ds):
    """What the models leave out, said plainly."""
    return [
        "- Housing bores are round and straight: no distortion from bolt tension, no thermal distortion of the "
        "block, no form error of the journals unless the engine file samples one.",
        "- The press fit is plane-stress linear elasticity of rings: no plastic deformation of the lining, no "
        "fretting, no relaxation of the crush over the engine's life.",
        "- The crankshaft is a beam on point supports at the main bearings; the block is rigid; the loads come "
        "from the engine file's pressure model, not a measured cylinder pressure, unless the file gives one.",
        "- The oil film is isothermal at the bearing's effective temperature; no elastic deformation of the "
        "bearing (EHD), no surface texture beyond the roughness in the critical film. The cheap dynamic film "
        "tiers carry no film content: they cannot see the oil short downstream of a moving load, which is most "
        "of their error against the mass-conserving transient reference (the feed groove they leave out moves "
        "that reference by a few per cent; reports/film_speed_vs_error.md).",
        "- The journal's tilt in its bearing balances the film's restoring moment (short-bearing, tilt squeeze "
        "neglected) against the crankshaft's rotational compliance at its support, a beam on point supports: "
        "where the film cannot hold the slope the edge is held at the eccentricity limit's floor (no elastic "
        "deformation of the shell edge): boundary contact at the edge, which α, the lives and the wear chart, "
        "reading the mid-plane film, do not count. The tilt follows the load "
        "quasi-statically (an edge stays on the wall while a contact there balances the journal, and leaves it "
        "when none does): the share of the cycle at the wall differs from the transient reference's, both ways "
        "(reports/film_speed_vs_error.md).",
        "- " + _life_bias(ds) + "Life follows Levanov et al. (2015), whose constants were fitted to another "
        "engine: compare schemes rather than read the hours as a guarantee.",
        "- Each scheme is judged on its preferred and allowed pairs as written in its file; the shell supply is "
        "planned from a pilot sample and lots are independent.",
    ]


def parameters_table(ds):
    """The study's parameters and the data it used, as rows of (parameter, value) for a readable table."""
    study = json.loads(ds.attrs["study"])
    rows = [(key, "—" if value is None else (", ".join(map(str, value)) if isinstance(value, list) else str(value)))
            for key, value in study.items()]
    rows += [("engine source", " ".join(ds.attrs["engine_source"].split())),
             ("stackup version", ds.attrs["stackup_version"])]
    rows += [(f"scheme {k}", v) for k, v in json.loads(ds.attrs["scheme_sources"]).items()]
    return pd.DataFrame(rows, columns=["parameter", "value"])
