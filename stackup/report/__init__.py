"""The scheme-comparison report, from saved study datasets alone.

Every number comes from the study dataset (every engine kept, or its
streaming summaries), the scenario datasets and the sensitivity dataset of a
:class:`stackup.comparison.Comparison`; nothing is sampled here.

- :mod:`~stackup.report.tables`: numbers per scheme (and bearing), with intervals;
- :mod:`~stackup.report.figures`: the figures;
- :mod:`~stackup.report.prose`: the verdict, methods, limits and parameters in words;
- :mod:`~stackup.report.html`: the self-contained HTML page.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd

from ..assembly import STATUS
from ..film.cycle import NOT_A_NUMBER
from ..plan import plan as plan_grades
from ..rank import MIN_COUNTED, TAIL_SOURCES
from ..rank import rank as rank_schemes
from ..schemes import from_dict
from ..study.inputs import load_inputs
from ..study.schema import flag
from . import figures, prose
from .html import anchor, markdown_to_html
from .tables import (UM, bearing_summary, converged_engines, clearance_summary, crank_summary, film_summary, fit_summary, grade_usage,
                     kept_summaries)

#: Sections in report order (their headings; the verdict comes before them).
SECTIONS = ("Methods and assumptions", "Limits of validity", "Ranking", "Designed scheme", "What drives the spread",
            "Clearance per scheme", "Operating clearance: press fit, housing swell and temperature",
            "Bearing loads over the engine cycle", "Oil film and bearing life per bearing position",
            "Assembly, scrap and stock", "Planning: shells per grade", "Shell grade usage", "Parameters")


def _fmt_ci(value, ci, digits=1):
    if not np.isfinite(value):
        return "—"
    return f"{value:.{digits}f} [{ci[0]:.{digits}f}, {ci[1]:.{digits}f}]"


def _sig(value, digits=3):
    """A number to ``digits`` significant digits, written out with thousands separators (26,500, not 2.65e+04)."""
    if not np.isfinite(value):
        return "∞" if value > 0 else ("−∞" if value < 0 else "—")
    if value == 0:
        return "0"
    rounded = float(f"{value:.{digits}g}")
    decimals = max(0, digits - 1 - int(np.floor(np.log10(abs(rounded)))))
    return f"{rounded:,.{decimals}f}"


def _fmt_q(q, digits=3):
    """A (value, lower, upper) triple as 'value [lower, upper]' with significant digits."""
    return f"{_sig(q[0], digits)} [{_sig(q[1], digits)}, {_sig(q[2], digits)}]"


def markdown_table(frame):
    """A DataFrame as a pipe table (index dropped: put what matters in columns)."""
    head = "| " + " | ".join(frame.columns) + " |"
    rule = "|" + "|".join("---" for _ in frame.columns) + "|"
    body = ["| " + " | ".join(str(v) for v in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join([head, rule, *body])


def _section(title, *lines):
    return [f"## {title}", "", *lines, ""]


def write_report(ds, out_dir, *, scenarios=None, sensitivity=None, tails=None, dataset_file=None):
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

    Returns
    -------
    pathlib.Path
        The markdown report.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    scenarios = scenarios or {}
    ranking = rank_schemes(ds, scenarios=scenarios or None, tails=tails)
    scenario_rankings = {label: rank_schemes(other) for label, other in scenarios.items()}
    summary = clearance_summary(ds)
    study = json.loads(ds.attrs["study"])
    n_mech = int(ds.attrs.get("mechanics_engines_used", 0))
    lines = [
        f"# Scheme comparison: {ds.attrs['engine']}",
        "",
        f"{ds.attrs['title']}. stackup {ds.attrs['stackup_version']}, seed {ds.attrs['seed']}, "
        f"{study['n_engines']:,} engines × {ds.sizes['bearing']} main bearings per scheme"
        + (" (streaming summaries: quantiles and histograms to 0.1 µm)." if kept_summaries(ds) else "."),
        "",
        *prose.verdict(ds, ranking, scenario_rankings),
        "Contents: " + " · ".join(f"[{title}](#{anchor(title)})" for title in SECTIONS
                                  if title != "Designed scheme" or "design" in ds.attrs),
        "",
        *_section("Methods and assumptions", *prose.methods(ds)),
        *_section("Limits of validity", *prose.limits_of_validity(ds)),
        *_ranking_section(ds, ranking, scenarios),
        *_design_section(ds, ranking),
        *_sensitivity_section(sensitivity, ranking, out),
        *_clearance_section(ds, summary, out),
        *_fit_section(ds),
        *_crank_section(ds, n_mech),
        *_film_section(ds, out),
        *_assembly_section(summary),
        *_plan_section(ds),
        *_usage_section(ds, out),
        *_section("Parameters", markdown_table(prose.parameters_table(ds)),
                  *([f"Dataset: `{dataset_file}`; the study's parameters are also in its `study` attribute "
                     "(JSON)."] if dataset_file else [])),
    ]
    path = out / "report.md"
    text = "\n".join(lines) + "\n"
    path.write_text(text)
    (out / "report.html").write_text(markdown_to_html(text, out))
    return path


def _grades_um(gradeset):
    """A dimension's grades as 'label lo–hi' in µm, or 'ungraded'."""
    if not gradeset.graded:
        return "ungraded"
    lo0 = gradeset.limits[0]
    return ", ".join(f"{lab} {(lo - lo0) * UM:+.1f}…{(hi - lo0) * UM:+.1f}"
                     for lab, lo, hi in zip(gradeset.labels, gradeset.lo, gradeset.hi))


def _design_section(ds, ranking):
    """The designed scheme beside the ISO scheme it started from: what changed, why, and how it did."""
    if "design" not in ds.attrs:
        return []
    record = json.loads(ds.attrs["design"])
    name, start = ds.attrs["designed_scheme"], record["start"]
    params = json.loads(ds.attrs["study"])
    _, loaded = load_inputs(json.loads(ds.attrs["input_files"]), params["schemes"])
    designed = {s.name: s for s in loaded}[name]
    started = from_dict(tomllib.loads(record["start_text"]), path=start)
    rows = [{"dimension": label, f"{start} (start)": _grades_um(getattr(started, dim)), name: _grades_um(getattr(designed, dim))}
            for label, dim in (("housing bore", "housing"), ("journal", "journal"), ("shell wall", "shell"))]
    samples = list(record["outside"])
    shares = pd.DataFrame({
        "design sample": samples,
        f"{start} [ppm]": [_ppm_text(1e6 * record['start_outside'].get(k, np.nan)) for k in samples],
        f"{name} [ppm]": [_ppm_text(1e6 * record['outside'][k]) for k in samples],
    })

    def outcome(scheme):
        row = ranking.loc[scheme]
        digits = prose.ppm_digits(row.outside_window_ppm, row.outside_window_ppm_ci[1])
        return (f"rank {row['rank']}, {_fmt_ci(row.outside_window_ppm, row.outside_window_ppm_ci, digits)} ppm outside "
                f"the window{'' if row.outside_window_source == 'counted' else ' †'}")

    lines = [
        f"`{name}` was designed for this engine and window by `stackup.design` before the study "
        f"({record['evaluations']:,} candidate limit sets, {record['seconds']:.0f} s), starting from `{start}`, the "
        "ISO scheme with the lowest objective on the design sample. The study above then judged it on its own "
        f"engines like every other scheme: {outcome(name)}"
        + (f", against {outcome(start)} for `{start}`." if start in ranking.index else
           f" (`{start}` is not among the schemes compared here)."),
        "",
        "What changed (grade limits in µm from the lower drawing limit of each dimension):", "",
        markdown_table(pd.DataFrame(rows)), "",
    ]
    lines += ["Share outside the window on the design sample (the designer's own engines, common random numbers), "
              "nominal and under each declared scenario:", "", markdown_table(shares), "",
              "Why, in the designer's words (also the comments of the scheme text stored in the dataset's "
              "`input_files`):", "", "```text", *record["notes"], "```"]
    return _section("Designed scheme", *lines)


def _ranking_section(ds, ranking, scenarios):
    window = ranking.attrs["window_m"]

    def column(name):
        """A ranking column, or '—' cells where the study has no film stage."""
        return ranking[name] if name in ranking else pd.Series(np.nan, index=ranking.index, dtype=object)

    table = pd.DataFrame({
        "rank": ranking["rank"],
        "scheme": ranking.index,
        "operating mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(ranking.clearance_mean_um, ranking.clearance_std_um)],
        "outside window [ppm]": [_fmt_ci(v, ci, prose.ppm_digits(v)) + ("" if src == "counted" else " †")
                                 for v, ci, src in zip(ranking.outside_window_ppm, ranking.outside_window_ppm_ci,
                                                       ranking.outside_window_source)],
        "α > 20 % [%]": [_fmt_ci(v, ci, 1) if isinstance(ci, tuple) else "—"
                         for v, ci in zip(column("alpha_over_limit_pct"), column("alpha_over_limit_pct_ci"))],
        "bearing life median [h]": [_fmt_q((v, *ci)) if isinstance(ci, tuple) else "—"
                            for v, ci in zip(column("life_median_h"), column("life_median_h_ci"))],
        "shell grades": ranking.shell_grades,
        "stock-outs [ppm]": ranking.stockout_ppm.map("{:.0f}".format),
        "surplus [%]": ranking.surplus_pct.map("{:.1f}".format),
    })
    if scenarios:
        table["worst scenario: Δ outside window [ppm]"] = [
            f"{v:+.0f} ({name})" for v, name in zip(ranking.worst_outside_window_ppm, ranking.worst_outside_window_ppm_scenario)]
        if "worst_life_median_h" in ranking:
            table["worst scenario: Δ bearing life median [h]"] = [
                f"{v:+.3g} ({name})" if isinstance(name, str) else "—"
                for v, name in zip(ranking.worst_life_median_h, ranking.worst_life_median_h_scenario)]
    whose = "the study's" if json.loads(ds.attrs["study"]).get("window") else "the engine's"
    rule = (f"Operating-clearance design window {prose._um_edge(window[0])}–{prose._um_edge(window[1])} µm ({whose}). "
            f"Rule: {_rule_in_words(ranking.attrs['rule'])}. Tied schemes share a rank.")
    if scenarios:
        rule += (f" Robustness: the worst change of each metric over the declared scenarios ({', '.join(scenarios)}), "
                 "each run with the same seed (counted shares); the lives change only under the scenarios that run "
                 "the mechanical chain, on their first engines against the study's same engines.")
    notes = []
    if (ranking.outside_window_source != "counted").any():
        how = ("estimated with the shells integrated out (`stackup.design.estimate.outside_share`: each "
               "bearing's probability of ending outside the window with the shells its pair's grades hold, on "
               "independent samples of the scheme's parts, aims and grading; its 95 % interval is Student's on "
               "the samples' spread, which leaves out that the estimate sees no lots, stock-outs or "
               "substitutions: against a study's counts see reports/design_scheme.md, against plain Monte Carlo "
               "of the whole study chain on 10^8 bearings reports/tails_vs_peers.md)"
               if (ranking.outside_window_source == TAIL_SOURCES["conditional"]).any() else
               "estimated by generalized splitting through the same assembly chain (`stackup.tail`; bins never "
               "run short there), its 95 % interval from the spread of the estimate's independent root bearings, "
               "as wide as the equivalent count")
        notes.append(f"† Fewer than {MIN_COUNTED} bearings of the study fell outside the window, too few for a tight "
                     f"interval: the share is {how}; the study counted " + ", ".join(f"{c} ({n})" for n, c in zip(ranking.index, ranking.outside_window_counted))
                     + ".")
    return _section("Ranking", rule, "", markdown_table(table), "", *notes, *prose.non_discriminating(ranking))


def _sensitivity_section(sensitivity, ranking, out):
    if sensitivity is None or not sensitivity.sizes.get("output"):
        return _section("What drives the spread", "The Sobol indices come with `stackup.compare` (its `sensitivity` "
                        "dataset); none was given.")
    figures.sensitivity_chart(sensitivity, out / "sensitivity.png")
    return _section(
        "What drives the spread",
        *prose.tighten_first(sensitivity, ranking), "",
        "Sobol indices of the root inputs: each sample engine is built from its own sizes, gauge errors, the shells "
        "taken from their grades' bins and crush heights, and goes through grading, pairing and the press fit (and "
        "for the film and the life through the crankshaft and the oil film). The first-order index S_1 is the share "
        "of the output's variance an input explains alone; the total index S_T adds its interactions. The gap "
        "between them, and a sum of S_1 below one, is the grading: a reading near a grade boundary sends a part "
        "to another pair. Process mean shifts are not inputs here: the declared scenarios shift them. Every "
        "index is an estimate from a finite sample: an S_1 above its S_T, or an interval reaching below 0 or "
        "above 1, is that sample's error (the film and life use far fewer engines than the clearance), not a "
        "share; read the intervals.", "",
        "![What drives the spread](sensitivity.png)")


def _clearance_section(ds, summary, out):
    figures.clearance_histogram(ds, out / "clearance_histogram.png")
    table = pd.DataFrame({
        "scheme": summary.index,
        "stated [µm]": [f"{a:.0f}–{b:.0f}" if np.isfinite(a) else "— (none stated)"
                        for a, b in zip(summary.stated_min_um, summary.stated_max_um)],
        "worst case [µm]": [f"{a:.1f}–{b:.1f}" for a, b in zip(summary.worst_case_min_um, summary.worst_case_max_um)],
        "mean [µm]": summary.mean_um.map("{:.2f}".format),
        "std [µm]": summary.std_um.map("{:.2f}".format),
        "P0.135 % [µm]": [_fmt_ci(v, ci) for v, ci in zip(summary.p00135_um, summary.p00135_ci_um)],
        "median [µm]": summary.median_um.map("{:.1f}".format),
        "P99.865 % [µm]": [_fmt_ci(v, ci) for v, ci in zip(summary.p99865_um, summary.p99865_ci_um)],
        "outside stated [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(summary.outside_stated_ppm, summary.outside_stated_ci_ppm)],
    })
    return _section(
        "Clearance per scheme",
        "Nominal diametral clearance of every assembled bearing (no swell or temperature, as the standard's stated "
        "ranges), against each scheme's stated range and its worst case over the allowed combinations.", "",
        markdown_table(table), "", *prose.read_out_notes(ds, summary), "",
        "![Nominal and operating clearance per scheme, with the stated ranges and the design window]"
        "(clearance_histogram.png)")


def _fit_section(ds):
    fit = fit_summary(ds)
    p_min, s_max = float(ds.design_contact_pressure_min), float(ds.design_shell_stress_max)
    table = pd.DataFrame({
        "scheme": fit.index,
        "nominal mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.nominal_mean_um, fit.nominal_std_um)],
        "operating mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.operating_mean_um, fit.operating_std_um)],
        "operating P0.135–P99.865 % [µm]": [f"{a:.1f}–{b:.1f}" for a, b in zip(fit.operating_p00135_um, fit.operating_p99865_um)],
        "swell [µm]": fit.swell_mean_um.map("{:.2f}".format),
        "min p, all temperatures [MPa]": fit.contact_pressure_min_mpa.map("{:.1f}".format),
        "max σ, all temperatures [MPa]": fit.shell_stress_max_mpa.map("{:.0f}".format),
        f"p < {p_min / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.low_pressure_ppm, fit.low_pressure_ci_ppm)],
        f"σ > {s_max / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.high_stress_ppm, fit.high_stress_ci_ppm)],
        "loss of fit [ppm]": fit.loss_of_fit_ppm.map("{:.0f}".format),
    })
    temperatures = ", ".join(f"{t:.0f}" for t in ds.press_fit_temperatures.values)
    crush = ds.crush_height_limits.values * 1e3
    window = ds.clearance_window.values * UM
    def source(key):
        return " ".join(str(ds.attrs.get(key, "")).split()) or "no source given"

    sources = [f"- contact pressure at least {p_min / 1e6:.0f} MPa and shell compression at most "
               f"{s_max / 1e6:.0f} MPa: {source('press_fit_limits_source')};",
               f"- crush height {crush[0]:.3f}–{crush[1]:.3f} mm: {source('crush_height_source')};",
               f"- operating-clearance window {window[0]:.1f}–{window[1]:.1f} µm: {source('clearance_window_source')}."]
    return _section(
        "Operating clearance: press fit, housing swell and temperature",
        "The shells' crush height presses them into the housing; the housing bore swells and the clearance "
        "changes with temperature. The clearance is that at the operating temperature; the two press-fit checks "
        f"are made at every declared temperature ({temperatures} °C: cold start, assembly, operating, hot), "
        "because they bite at different ends: the shell stress where the housing has shrunk most onto the steel "
        "backs (cold for a light-alloy housing), the contact pressure where it has grown most (hot for aluminium, "
        "cold for a cast iron that expands less than steel). The limits and where they come from:", "",
        *sources, "", markdown_table(table))


def _crank_section(ds, n_mech):
    crank = crank_summary(ds)
    if not n_mech or not (crank.engines > 0).any():
        return _section("Bearing loads over the engine cycle", "The crankshaft stage did not run (see the verdict's "
                        "note).")
    wide = crank.reset_index()
    cells = wide.assign(text=[f"{m:.2f} ± {c:.2f} (max {x:.1f})" for m, c, x in zip(wide.mean_kn, wide.ci_kn, wide.max_kn)])
    table = cells.pivot(index="scheme", columns="bearing", values="text")
    table.columns = [f"bearing {b} [kN]" for b in table.columns]
    first = crank.groupby(level="scheme").first()
    table.insert(0, "engines (failed)", [f"{e} ({f})" for e, f in zip(first.engines, first.failed)])
    target = json.loads(ds.attrs["study"]).get("target_error")
    return _section(
        "Bearing loads over the engine cycle",
        f"Cycle-maximum load of each main bearing (mean ± 95 % interval of the mean, and the largest) on the first "
        f"{n_mech:,} engines of each scheme"
        + (f", as many as a ±{100 * target:g} % interval of the mean film needs" if target else "")
        + "; engines with a bearing not assembled are skipped and marked in `crank_status`.", "",
        markdown_table(table.reset_index()))


def _film_section(ds, out):
    film = film_summary(ds)
    if not len(film):
        return _section("Oil film and bearing life per bearing position", "The film and life stages did not run "
                        "(see the verdict's note).")
    figures.film_by_bearing(ds, out / "film_life.png")
    target = float(ds.life_target) / 3600
    overall = pd.DataFrame({
        "scheme": film.index, "engines": film.engines,
        "h_min P5 [µm]": [f"{q[0]:.2f} [{q[1]:.2f}, {q[2]:.2f}]" for q in film.h_min_p05_um],
        "h_min median [µm]": [f"{q[0]:.2f}" for q in film.h_min_median_um],
        "cycle-mean film median [µm] (the life's)": [f"{q[0]:.2f}" for q in film.h_min_mean_median_um],
        "α mean [%]": (100 * film.alpha_mean).map("{:.1f}".format),
        "α > 20 % [% of bearings]": [f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]" for v in film.alpha_over_20_pct],
        "bearing life B10 [h]": [_fmt_q(q) for q in film.life_b10_h],
        "bearing life median [h]": [_sig(q[0]) for q in film.life_median_h],
        "engine life B10 [h] (weakest bearing)": [_fmt_q(q) for q in film.engine_life_b10_h],
        "method 2 life B10 [h] (∞: never below h_lim,cr)": [_fmt_q(q) for q in film.wear_chart_b10_h],
        f"engines < {target:.0f} h [%]": [f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]" for v in film.engines_below_target_pct],
    })
    per_bearing = bearing_summary(ds).reset_index()
    h_table = per_bearing.assign(text=[f"{q[0]:.2f}" for q in per_bearing.h_min_median_um]).pivot(
        index="scheme", columns="bearing", values="text")
    life_table = per_bearing.assign(text=[_sig(q[0]) for q in per_bearing.life_median_h]).pivot(
        index="scheme", columns="bearing", values="text")
    both = pd.concat([h_table.add_prefix("h_min median [µm], bearing "),
                      life_table.add_prefix("bearing life median [h], bearing ")], axis=1).reset_index()
    return _section(
        "Oil film and bearing life per bearing position",
        f"Minimum film thickness of each bearing over the cycle (`{ds.attrs['film_method_used']}` tier) at its "
        "effective oil temperature; α is the share of the cycle with the film below the critical film h_lim,cr = "
        f"{float(ds.critical_film) * 1e6:.2f} µm (above 20 % the risk of scuffing rises sharply); life by Levanov et "
        "al. (2015): method 1 on the film the methods section names, and method 2's wear chart. Bearing lives pool "
        "every bearing of the engines; an engine's life is that of its weakest bearing (its B10 and the share of "
        f"engines below the life target, {target:,.0f} h, the engine's).", "",
        markdown_table(overall), "",
        _positions_text(ds), "",
        markdown_table(both), "",
        *_film_detail(ds),
        "![Oil film and life per bearing position](film_life.png)")


def _rule_in_words(rule):
    """The ranking's rule with its metrics named in words (:data:`prose.METRICS`) instead of column names."""
    for column, words in prose.METRICS.items():
        rule = rule.replace(column, words)
    return rule


def _ppm_text(value):
    """A share in ppm to its precision (:func:`prose.ppm_digits`: two significant digits below 1 ppm)."""
    return f"{value:,.{prose.ppm_digits(value)}f}"


def _film_detail(ds):
    """Tilt, edge contact, edge film and peak film pressure per position; orbits that did not close."""
    if "film_status" not in ds:  # a study without the mechanical chain's film
        return []
    status = ds.film_status
    rows = []
    for i, scheme in enumerate(ds.scheme.values):
        done = converged_engines(ds, i)
        if not done.any():
            continue
        contact = status.values[i, done] == flag(status, "edge_contact")
        for b, bearing in enumerate(ds.bearing.values):
            number = ds.film_valid.values[i, done, b]  # films that are not a number are NaN: left out
            if not number.any():
                continue
            edge, touching = ds.h_min_edge.values[i, done, b][number], contact[number, b]
            film = "edge contact" if touching.mean() >= 0.5 else f"{np.nanmedian(edge[~touching]) * UM:.2f} µm"
            tilt = np.nanmedian(ds.tilt_max.values[i, done, b])
            peak, mean_peak = (np.nanmedian(ds[name].values[i, done, b]) for name in ("p_max", "p_max_mean"))
            touch = f"{100 * touching.mean():.0f} %"
            if "edge_contact_share" in ds and touching.any():  # datasets before it have no share of the cycle
                touch += f" ({100 * np.nanmedian(ds.edge_contact_share.values[i, done, b][number][touching]):.0f} %)"
            rows.append({"scheme": str(scheme), "bearing": int(bearing),
                         "text": f"{tilt * 1e3:.2f} / {touch} / {film} / {peak / 1e6:.0f} / {mean_peak / 1e6:.0f}"})
    lines = []
    if rows:
        table = pd.DataFrame(rows).pivot(index="scheme", columns="bearing", values="text")
        table.columns = [f"bearing {b}" for b in table.columns]
        lines += ["Misalignment reaches the film: the journal tilts in its bearing by the crankshaft's slope at "
                  "the support (the beam bent by the loads and by the engine's sampled bore coaxiality and "
                  "journal run-out), so the film is thinnest at an edge. Per position: largest tilt over the cycle "
                  "[mrad, median over engines] / engines whose journal edge touches the bearing (in brackets the "
                  "share of the cycle it touches, median over those engines) / median edge film (where most do "
                  "not touch) / peak film pressure over the cycle and its cycle mean "
                  "[MPa, medians]:", "",
                  markdown_table(table.reset_index()), ""]
    ran = status.values != flag(status, "not_computed")

    def count(meaning):
        return int(np.count_nonzero(ran & (status.values == flag(status, meaning))))

    failed = {m: count(m) for m in NOT_A_NUMBER if count(m)}
    total, edge = int(np.count_nonzero(ran)), count("edge_contact")
    text = []
    if failed:
        lost = sum(failed.values())
        engines = int(np.count_nonzero(np.any(ran & ~ds.film_valid.values, axis=-1)))
        text.append(f"Films that are not a number, of {total:,} bearing-cycles: "
                    + ", ".join(f"{k:,} {m.replace('_', ' ')}" for m, k in failed.items())
                    + f". Their films and lives are NaN in the dataset (the reason in `film_status`, `film_valid` "
                    f"false) and left out of every film and life statistic above and of the ranking ({lost:,} "
                    f"bearing{'s' if lost != 1 else ''}); the {engines:,} engine{'s' if engines != 1 else ''} with such a bearing "
                    f"{'have' if engines != 1 else 'has'} no engine life and {'are' if engines != 1 else 'is'} left "
                    "out of the share of engines below the life target.")
    elif total and (count("periodic") or edge):
        text.append(f"Every one of the {total:,} bearing-cycles reached a periodic orbit (`film_status` periodic, "
                    "or edge_contact: periodic, with an edge at the wall).")
    if edge:
        text.append(f"In {edge:,} of them ({100 * edge / max(total, 1):.0f} %) the tilted journal reaches the "
                    "bearing's edge at some crank angle (`edge_contact`): the tilt balances the film's restoring "
                    "moment (short-bearing, tilt squeeze neglected) against the crankshaft's rotational "
                    "compliance at the support, and where the film cannot hold the beam's slope the edge film is "
                    "held at the eccentricity limit's floor, not a computed film (boundary contact at the edge); "
                    "α and the lives use the mid-plane film.")
    if text:
        lines += [" ".join(text), ""]
    return lines + _heat_text(ds, ran)


def _heat_text(ds, ran):
    """The heat balance's film temperatures, friction powers and oil flows over the bearings whose film is a number."""
    if not {"film_temperature", "friction_power", "oil_flow"} <= set(ds.data_vars):
        return []
    valid = ran & ds.film_valid.values
    if not valid.any():
        return []

    def spread(name, scale=1.0, digits=0):
        v = ds[name].values[valid] * scale
        lo, mid, hi = np.nanpercentile(v, [5, 50, 95])
        return f"{lo:.{digits}f}-{hi:.{digits}f}", f"{mid:.{digits}f}"

    (t, t_mid), (n, n_mid), (q, q_mid) = (spread("film_temperature"), spread("friction_power"),
                                          spread("oil_flow", 6e4, 2))
    crank = json.loads(ds.attrs.get("engine_processes", "{}")).get("crank", {})
    supply = (f", oil supplied at {crank['oil_supply_temperature_degC']:.0f} °C"
              if "oil_supply_temperature_degC" in crank else "")
    return [f"The heat balance puts the films at {t} °C (5-95 % of the bearings; median {t_mid} °C{supply}), "
            f"with {n} W of friction power per bearing (median {n_mid} W) and {q} L/min of oil through it (median "
            f"{q_mid} L/min, feed and side flow; `film_temperature`, `friction_power`, `oil_flow`).", ""]


def _positions_text(ds):
    """Why film and life differ by bearing position, from the loads the positions carry in this study."""
    load = crank_summary(ds).groupby(level="bearing").mean_kn.mean()
    film = bearing_summary(ds).reset_index()
    film = film.assign(h=[q[0] for q in film.h_min_median_um]).groupby("bearing").h.mean()
    heavy = sorted(load.index[load >= load.max() - 0.15 * (load.max() - load.min())])
    thin = sorted(film.index[film <= film.min() + 0.15 * (film.max() - film.min())])
    def listed(items):
        items = [str(i) for i in items]
        return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]

    names = listed(heavy)
    return (f"The bearing positions carry different loads: bearing{'s' if len(heavy) > 1 else ''} {names} carr"
            f"{'y' if len(heavy) > 1 else 'ies'} the largest cycle-maximum load here ({load.max():.1f} kN on average "
            f"against {load.min():.1f} kN at the least loaded), and the thinnest films are at bearing"
            f"{'s' if len(thin) > 1 else ''} {listed(thin)}, so the film and life pooled over positions "
            "are multimodal. Per position (median over engines):")


def _assembly_section(summary):
    table = pd.DataFrame({
        "scheme": summary.index,
        "bearings": summary.bearings,
        "assembled": summary.assembled,
        **{reason: summary[reason] for reason in STATUS if reason != "assembled"},
        "substituted pairs": summary.substituted.map(lambda v: "—" if np.isnan(v) else f"{v:.0f}"),
        "shells made": summary.shells_made,
        "shells scrapped [%]": summary.shells_scrapped_pct.map("{:.2f}".format),
    })
    return _section("Assembly, scrap and stock", "Bearings not assembled are kept in the dataset with their reason "
                    "(`status`); none are dropped.", "", markdown_table(table))


def _plan_section(ds):
    if kept_summaries(ds):
        return _section("Planning: shells per grade", "Planning needs each engine's shell demand: run the study with "
                        "`keep=\"everything\"` (the summaries keep only the totals in the grade usage below).")
    frame = plan_grades(ds, volume=10_000, service_level=0.99)
    rows = [{"scheme": scheme, "grade": grade,
             "demand per 1000 engines": f"{r.demand_per_1000:.0f} [{r.demand_per_1000_lo:.0f}, {r.demand_per_1000_hi:.0f}]",
             "production share [%]": f"{100 * r.production_share:.2f}",
             "surplus for 10 000 engines": f"{r.surplus:+.0f}",
             "safety stock per lot (99 %)": f"{r.safety_stock:.0f}",
             "order-up-to per lot": f"{r.order_up_to:.0f}"} for (scheme, grade), r in frame.iterrows()]
    return _section(
        "Planning: shells per grade",
        "From `stackup.plan` on this study's own engines and shell lots: expected demand per grade (95 % interval), "
        "the share of the shell production that landed in the grade when read and sorted, the surplus over 10 000 "
        f"engines, and the safety stock per production lot ({ds.attrs['lot_engines']} engines) for a 99 % chance "
        "that the lot's demand is covered. `stackup plan --scheme NAME --volume N` plans any volume and service "
        "level.", "", markdown_table(pd.DataFrame(rows)))


def _usage_section(ds, out):
    figures.grade_usage_chart(ds, out / "grade_usage.png")
    usage = grade_usage(ds).reset_index()[["scheme", "shell_grade", "shells_made", "shells_used", "shells_left",
                                          "used_share_pct"]]
    usage["used_share_pct"] = usage["used_share_pct"].map("{:.2f}".format)
    usage.columns = ["scheme", "grade", "made", "fitted", "left in stock", "share of fitted [%]"]
    return _section("Shell grade usage", "![Shell grades fitted and made per scheme](grade_usage.png)", "",
                    markdown_table(usage))


__all__ = ["bearing_summary", "clearance_summary", "crank_summary", "film_summary", "fit_summary", "grade_usage",
           "markdown_table", "markdown_to_html", "write_report"]
