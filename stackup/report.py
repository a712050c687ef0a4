"""Scheme-comparison tables and report, from saved study datasets alone.

Every number comes from the study dataset (every engine kept, or its
streaming summaries), the scenario datasets and the sensitivity dataset of a
:class:`stackup.study.compare.Comparison`; nothing is sampled here. Figures
are drawn on matplotlib ``Figure`` objects, so the user's backend is never
changed.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from .assembly import STATUS
from .stats import mean_half_width, proportion_ci, quantile_ci
from .study import summaries
from .study.schema import flag

#: Tail quantiles reported: the +-3 sigma points of a normal distribution.
TAIL_LOW, TAIL_HIGH = 0.00135, 0.99865
UM = 1e6


def kept_summaries(ds):
    """The dataset holds streaming summaries (``Study(keep="summaries")``), not every engine."""
    return ds.attrs.get("kept") == "summaries"


def _assembled(d, name):
    """Values of ``name`` of one scheme's assembled bearings (a full dataset)."""
    return d[name].values[d.status.values == flag(d.status, "assembled")]


def fit_summary(ds):
    """One row per scheme: nominal against operating clearance [um], press-fit limits as shares with 95 % intervals.

    The design limits are the dataset's (``design_contact_pressure_min``,
    ``design_shell_stress_max``). From summaries, the operating
    quantiles are read from the 0.1 um histogram.
    """
    p_min, s_max = float(ds.design_contact_pressure_min), float(ds.design_shell_stress_max)
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        if kept_summaries(ds):
            n = int(d.status_count.sel(status="assembled"))
            counts = (int(d.low_contact_pressure_count), int(d.high_shell_stress_count), int(d.loss_of_fit_count))
            hist = d.clearance_operating_histogram.values
            row = {"nominal_mean_um": float(d.clearance_nominal_mean) * UM,
                   "nominal_std_um": float(d.clearance_nominal_std) * UM,
                   "operating_mean_um": float(d.clearance_operating_mean) * UM,
                   "operating_std_um": float(d.clearance_operating_std) * UM,
                   "operating_p00135_um": summaries.quantile_ci(hist, TAIL_LOW)[0] * UM,
                   "operating_p99865_um": summaries.quantile_ci(hist, TAIL_HIGH)[0] * UM,
                   "swell_mean_um": float(d.housing_swell_mean) * UM,
                   "contact_pressure_min_mpa": float(d.contact_pressure_min) / 1e6,
                   "shell_stress_max_mpa": float(d.shell_stress_max) / 1e6}
        else:
            nominal, operating = _assembled(d, "clearance_nominal"), _assembled(d, "clearance_operating")
            p, sigma = _assembled(d, "contact_pressure"), _assembled(d, "shell_stress")
            n = p.size
            counts = (np.count_nonzero(p < p_min), np.count_nonzero(sigma > s_max),
                      np.count_nonzero(_assembled(d, "loss_of_fit")))
            row = {"nominal_mean_um": nominal.mean() * UM, "nominal_std_um": nominal.std(ddof=1) * UM,
                   "operating_mean_um": operating.mean() * UM, "operating_std_um": operating.std(ddof=1) * UM,
                   "operating_p00135_um": quantile_ci(operating, TAIL_LOW)[0] * UM,
                   "operating_p99865_um": quantile_ci(operating, TAIL_HIGH)[0] * UM,
                   "swell_mean_um": _assembled(d, "housing_swell").mean() * UM,
                   "contact_pressure_min_mpa": p.min() / 1e6, "shell_stress_max_mpa": sigma.max() / 1e6}
        low_p, high_s, lost = (proportion_ci(k, n) for k in counts)
        rows.append({"scheme": str(name), **row,
                     "low_pressure_ppm": low_p[0] * 1e6, "low_pressure_ci_ppm": (low_p[1] * 1e6, low_p[2] * 1e6),
                     "high_stress_ppm": high_s[0] * 1e6, "high_stress_ci_ppm": (high_s[1] * 1e6, high_s[2] * 1e6),
                     "loss_of_fit_ppm": lost[0] * 1e6})
    return pd.DataFrame(rows).set_index("scheme")


def clearance_summary(ds):
    """One row per scheme: nominal clearance statistics [um], shares outside the stated range, stock.

    Quantiles and shares come with 95 % intervals (order statistics and
    Clopper-Pearson). From summaries they are read from the 0.1 um histogram
    of the nominal clearance (quantiles to a bin; the stated ranges lie on the
    bin grid, so the share outside them is exact); substitutions are not
    counted there (NaN).
    """
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        lo_stated, hi_stated = d.clearance_stated.values
        if kept_summaries(ds):
            counts = dict(zip(ds.status.values, d.status_count.values))
            hist = d.clearance_nominal_histogram.values
            n_bearings, n = int(sum(counts.values())), int(counts["assembled"])
            outside = summaries.share_beyond(hist, lo_stated, hi_stated)
            p_lo, p50, p_hi = (summaries.quantile_ci(hist, q) for q in (TAIL_LOW, 0.5, TAIL_HIGH))
            filled = np.flatnonzero(hist)
            extremes = (summaries.BIN_START + (filled[[0, -1]] + 0.5) * summaries.BIN_WIDTH if filled.size
                        else (np.nan, np.nan))
            mean, std = float(d.clearance_nominal_mean), float(d.clearance_nominal_std)
            substituted = np.nan
        else:
            status = d.status.values
            counts = {reason: np.count_nonzero(status == flag(d.status, reason)) for reason in STATUS}
            c = _assembled(d, "clearance_nominal")
            n_bearings, n = status.size, c.size
            outside = int(np.count_nonzero((c < lo_stated) | (c > hi_stated)))
            p_lo, p50, p_hi = (quantile_ci(c, q) for q in (TAIL_LOW, 0.5, TAIL_HIGH))
            extremes = (c.min(), c.max()) if c.size else (np.nan, np.nan)
            mean = float(c.mean()) if c.size else np.nan
            std = float(c.std(ddof=1)) if c.size > 1 else np.nan
            substituted = int(np.count_nonzero(d.shell_option.values > 0))
        share, share_lo, share_hi = proportion_ci(outside, n)
        made = int(d.shells_made.sum()) + int(d.shells_scrapped)
        row = {
            "scheme": str(name),
            "bearings": n_bearings,
            "assembled": n,
            "stated_min_um": lo_stated * UM,
            "stated_max_um": hi_stated * UM,
            "worst_case_min_um": float(d.clearance_limit.values[0]) * UM,
            "worst_case_max_um": float(d.clearance_limit.values[1]) * UM,
            "mean_um": mean * UM,
            "std_um": std * UM,
            "p00135_um": p_lo[0] * UM,
            "p00135_ci_um": (p_lo[1] * UM, p_lo[2] * UM),
            "median_um": p50[0] * UM,
            "p99865_um": p_hi[0] * UM,
            "p99865_ci_um": (p_hi[1] * UM, p_hi[2] * UM),
            "min_um": float(extremes[0]) * UM,
            "max_um": float(extremes[1]) * UM,
            "outside_stated_ppm": share * 1e6,
            "outside_stated_ci_ppm": (share_lo * 1e6, share_hi * 1e6),
            "shells_made": made,
            "shells_scrapped_pct": 100.0 * int(d.shells_scrapped) / made if made else np.nan,
            "substituted": substituted,
        }
        row.update({reason: int(counts[reason]) for reason in STATUS if reason != "assembled"})
        rows.append(row)
    return pd.DataFrame(rows).set_index("scheme")


def grade_usage(ds):
    """Shells made, fitted and left per scheme and grade (grades the scheme has)."""
    frame = ds[["shells_made", "shells_used", "shells_left"]].to_dataframe()
    frame = frame[ds.grade_in_scheme.to_series()]
    used = frame["shells_used"]
    frame["used_share_pct"] = 100.0 * used / used.groupby(level="scheme").transform("sum")
    return frame


def crank_summary(ds):
    """Per scheme and bearing: engines the beam ran on, and the cycle-maximum load [kN] with a 95 % interval of its mean."""
    rows = []
    status = ds.crank_status
    for i, name in enumerate(ds.scheme.values):
        codes = status.values[i]
        ok = codes == flag(status, "converged")
        failed = int(np.count_nonzero((codes == flag(status, "max_iterations")) | (codes == flag(status, "not_finite"))))
        for b, bearing in enumerate(ds.bearing.values):
            r = ds.reaction_max.values[i, ok, b] / 1e3
            rows.append({"scheme": str(name), "bearing": int(bearing), "engines": int(ok.sum()), "failed": failed,
                         "mean_kn": r.mean() if r.size else np.nan,
                         "ci_kn": mean_half_width(r) if r.size > 1 else np.nan,
                         "max_kn": r.max() if r.size else np.nan})
    return pd.DataFrame(rows).set_index(["scheme", "bearing"])


def _converged(ds, i):
    """Engines of scheme ``i`` whose crankshaft stage converged (the film and life were computed on them)."""
    return ds.crank_status.values[i] == flag(ds.crank_status, "converged")


def film_summary(ds):
    """Per scheme: cycle-minimum film, boundary-friction share and Levanov life, with 95 % intervals.

    The share of engines below the life target uses the engine's own target
    (``life_target``).
    """
    from .life import ALPHA_SCUFFING

    life_target_hours = float(ds.life_target) / 3600
    rows = []
    for i, name in enumerate(ds.scheme.values):
        done = _converged(ds, i)
        h = ds.h_min.values[i, done].ravel() * UM
        a = ds.alpha.values[i, done].ravel()
        life = ds.life.values[i, done].ravel() / 3600
        engine_life = ds.life.values[i, done].min(axis=1) / 3600 if done.any() else np.array([])
        if h.size == 0:
            continue
        scuff = proportion_ci(np.count_nonzero(a > ALPHA_SCUFFING), a.size)
        short = proportion_ci(np.count_nonzero(engine_life < life_target_hours), engine_life.size)
        rows.append({
            "scheme": str(name), "engines": int(done.sum()),
            "h_min_p05_um": quantile_ci(h, 0.05), "h_min_median_um": quantile_ci(h, 0.5),
            "alpha_mean": a.mean(), "alpha_over_20_pct": tuple(100 * v for v in scuff),
            "life_b10_h": quantile_ci(life, 0.10), "life_median_h": quantile_ci(life, 0.5),
            "engines_below_target_pct": tuple(100 * v for v in short),
        })
    return pd.DataFrame(rows).set_index("scheme") if rows else pd.DataFrame()


def film_histogram(ds, path):
    """Histograms of the cycle-minimum film and of the life per scheme; saved as PNG."""
    fig = Figure(figsize=(11, 3.6))
    ax_h, ax_l = fig.subplots(1, 2)
    for i, name in enumerate(ds.scheme.values):
        done = _converged(ds, i)
        h = ds.h_min.values[i, done].ravel() * UM
        life = ds.life.values[i, done].ravel() / 3600
        if h.size:
            ax_h.hist(h, bins=40, histtype="step", label=str(name))
            ax_l.hist(np.log10(life), bins=40, histtype="step", label=str(name))
    ax_h.set_xlabel("cycle-minimum film thickness h_min [µm]")
    ax_l.set_xlabel("log10 bearing life (Levanov method 1) [log10 h]")
    for ax in (ax_h, ax_l):
        ax.set_ylabel("bearings")
    ax_h.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    return path


def sensitivity_chart(sensitivity, path):
    """Contributor chart from a sensitivity dataset (:func:`stackup.study.compare.sensitivity_dataset`); PNG.

    Share of variance per input, per scheme and output, with 95 % bootstrap
    intervals. Returns the R² of each panel, by (output, scheme).
    """
    outputs, names = list(sensitivity.output.values), list(sensitivity.scheme.values)
    fig = Figure(figsize=(2.6 * len(names) + 1.5, 2.6 * len(outputs) + 0.5))
    axes = fig.subplots(len(outputs), len(names), sharex=True, squeeze=False)
    fits = {}
    inputs = list(reversed(sensitivity.input.values))  # the same order in every panel
    for r, output in enumerate(outputs):
        for c, name in enumerate(names):
            ax = axes[r, c]
            d = sensitivity.sel(output=output, scheme=name, input=inputs)
            if not np.isfinite(float(d.r2)):
                ax.set_axis_off()
                continue
            fits[(str(output), str(name))] = float(d.r2)
            keep = np.isfinite(d.share.values)
            share, lo, hi = (100 * d[k].values[keep] for k in ("share", "share_lo", "share_hi"))
            err = np.vstack([share - lo, hi - share]).clip(min=0)
            ax.barh(np.array(inputs)[keep], share, xerr=err, color="tab:blue", alpha=0.8)
            ax.set_title(f"{name}\n{output} (R² {float(d.r2):.2f})", fontsize=8)
            ax.tick_params(labelsize=7)
            if c:
                ax.set_yticklabels([])
        axes[r, 0].set_ylabel("input")
    for ax in axes[-1]:
        ax.set_xlabel("share of variance [%]")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    return fits


def _target_text(ds):
    target = json.loads(ds.attrs["study"]).get("target_error")
    return f", as many as a ±{100 * target:g} % interval of the mean film needs" if target else ""


def _fmt_ci(value, ci, digits=1):
    return f"{value:.{digits}f} [{ci[0]:.{digits}f}, {ci[1]:.{digits}f}]"


def _markdown_table(frame):
    head = "| " + " | ".join(frame.columns) + " |"
    rule = "|" + "|".join("---" for _ in frame.columns) + "|"
    body = ["| " + " | ".join(str(v) for v in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join([head, rule, *body])


def _clearance_histograms(ds, name):
    """(bin edges [um], nominal counts, operating counts) of one scheme, from values or the summary histograms."""
    d = ds.sel(scheme=name)
    if kept_summaries(ds):
        edges = (summaries.BIN_START + np.arange(summaries.BINS + 1) * summaries.BIN_WIDTH) * UM
        return edges, d.clearance_nominal_histogram.values, d.clearance_operating_histogram.values
    return None, _assembled(d, "clearance_nominal") * UM, _assembled(d, "clearance_operating") * UM


def clearance_histogram(ds, path):
    """Histograms of nominal and operating clearance per scheme, stated range shaded; saved as PNG."""
    names = list(ds.scheme.values)
    fig = Figure(figsize=(7.5, 1.6 * len(names) + 0.8))
    axes = np.atleast_1d(fig.subplots(len(names), 1, sharex=True))
    data = {name: _clearance_histograms(ds, name) for name in names}
    if kept_summaries(ds):
        filled = [np.flatnonzero(h) for _, nom, op in data.values() for h in (nom, op)]
        edges = data[names[0]][0]
        lo, hi = min(f[0] for f in filled if f.size), max(f[-1] for f in filled if f.size)
        bins = np.arange(np.floor(edges[lo]) - 1, np.ceil(edges[hi + 1]) + 2, 0.5)
    else:
        values = np.concatenate([np.concatenate([nom, op]) for _, nom, op in data.values()])
        bins = np.arange(np.floor(values.min()) - 1, np.ceil(values.max()) + 2, 0.5)
    for ax, name in zip(axes, names):
        edges, nominal, operating = data[name]
        lo, hi = ds.sel(scheme=name).clearance_stated.values * UM
        ax.axvspan(lo, hi, color="tab:green", alpha=0.12, label="stated range")
        if edges is None:
            ax.hist(nominal, bins=bins, color="tab:blue", alpha=0.75, label="nominal")
            ax.hist(operating, bins=bins, color="tab:red", alpha=0.55, label="operating")
        else:  # re-binned from the summaries' 0.1 um bins
            centres = 0.5 * (edges[1:] + edges[:-1])
            ax.hist(centres, bins=bins, weights=nominal, color="tab:blue", alpha=0.75, label="nominal")
            ax.hist(centres, bins=bins, weights=operating, color="tab:red", alpha=0.55, label="operating")
        ax.set_yscale("log")
        ax.set_ylabel("bearings")
        ax.set_title(str(name), fontsize=9, loc="left")
    axes[-1].set_xlabel("diametral clearance [µm]")
    axes[0].legend(loc="upper right", fontsize=8, ncols=3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path


def grade_usage_chart(ds, path):
    """Shells fitted per grade and scheme as shares of the scheme's fitted shells; saved as PNG."""
    usage = grade_usage(ds)
    names = list(ds.scheme.values)
    fig = Figure(figsize=(2.0 * len(names) + 1, 2.8))
    axes = np.atleast_1d(fig.subplots(1, len(names), sharey=True))
    for ax, name in zip(axes, names):
        u = usage.loc[name]
        made_share = 100.0 * u["shells_made"] / u["shells_used"].sum()
        x = np.arange(len(u))
        ax.bar(x - 0.2, u["used_share_pct"], width=0.4, label="fitted")
        ax.bar(x + 0.2, made_share, width=0.4, label="made (sorted)", alpha=0.6)
        ax.set_xticks(x, u.index)
        ax.set_title(str(name), fontsize=9)
        ax.set_xlabel("shell grade")
    axes[0].set_ylabel("share of fitted shells [%]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper right", ncols=2, fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    fig.savefig(path, dpi=110)
    return path


_HTML_STYLE = """body{font-family:system-ui,sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;font-size:.85em;margin:1em 0}th,td{border:1px solid #ccc;padding:.25em .5em;text-align:right}
th{background:#f3f3f3}td:first-child,th:first-child{text-align:left}img{max-width:100%}code{background:#f3f3f3;padding:0 .2em}"""


def _inline(text):
    """Escape and render the inline markdown the report uses: `code` and **bold**."""
    import html
    import re

    text = html.escape(text)
    text = re.sub(r"`([^`]+)`", r"<code>\1</code>", text)
    return re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", text)


def markdown_to_html(text, folder):
    """The report's markdown as one self-contained HTML page (figures embedded as base64 PNG).

    Handles exactly what :func:`write_report` writes: headings, paragraphs,
    pipe tables, bullet lists and images.
    """
    import base64
    import re

    body, table, items = [], [], []

    def flush():
        if table:
            head, *rows = [[_inline(c.strip()) for c in r.strip().strip("|").split("|")] for r in table if not set(r) <= set("|-: ")]
            body.append("<table><tr>" + "".join(f"<th>{c}</th>" for c in head) + "</tr>"
                        + "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows) + "</table>")
            table.clear()
        if items:
            body.append("<ul>" + "".join(f"<li>{_inline(i)}</li>" for i in items) + "</ul>")
            items.clear()

    for line in text.splitlines():
        if line.startswith("|"):
            table.append(line)
            continue
        if line.startswith("- "):
            items.append(line[2:])
            continue
        flush()
        image = re.fullmatch(r"!\[([^\]]*)\]\(([^)]+)\)", line.strip())
        if image:
            data = base64.b64encode((Path(folder) / image.group(2)).read_bytes()).decode()
            body.append(f'<p><img alt="{_inline(image.group(1))}" src="data:image/png;base64,{data}"></p>')
        elif line.startswith("#"):
            level = len(line) - len(line.lstrip("#"))
            body.append(f"<h{level}>{_inline(line[level:].strip())}</h{level}>")
        elif line.strip():
            body.append(f"<p>{_inline(line)}</p>")
    flush()
    title = _inline(text.splitlines()[0].lstrip("# ")) if text else "stackup report"
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{title}</title><style>{_HTML_STYLE}</style>"
            f"</head><body>{''.join(body)}</body></html>")


#: Names of the press-fit tiers in prose.
FIT_TIERS = {"lame": "Thick-ring (Lamé)", "thin-ring": "Thin-ring", "fe": "Finite-element reference"}


def write_report(ds, out_dir, *, scenarios=None, sensitivity=None, dataset_file=None):
    """Write ``report.md``, its self-contained twin ``report.html`` and the figures into ``out_dir``.

    Parameters
    ----------
    ds : xarray.Dataset
        A study dataset, every engine kept or its streaming summaries (then
        the sections that need every engine say so).
    scenarios : dict of str -> xarray.Dataset, optional
        The study under declared scenarios (:class:`stackup.study.compare.Comparison`).
    sensitivity : xarray.Dataset, optional
        Contributions of the inputs (:func:`stackup.study.compare.sensitivity_dataset`).
    dataset_file : str, optional
        Name of the saved dataset, quoted in the report.

    Returns
    -------
    pathlib.Path
        The markdown report.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    summary = clearance_summary(ds)
    usage = grade_usage(ds)
    clearance_histogram(ds, out / "clearance_histogram.png")
    grade_usage_chart(ds, out / "grade_usage.png")

    table = pd.DataFrame({
        "scheme": summary.index,
        "stated [µm]": [f"{a:.0f}–{b:.0f}" for a, b in zip(summary.stated_min_um, summary.stated_max_um)],
        "worst case [µm]": [f"{a:.1f}–{b:.1f}" for a, b in zip(summary.worst_case_min_um, summary.worst_case_max_um)],
        "mean [µm]": summary.mean_um.map("{:.2f}".format),
        "std [µm]": summary.std_um.map("{:.2f}".format),
        "P0.135 % [µm]": [_fmt_ci(v, ci) for v, ci in zip(summary.p00135_um, summary.p00135_ci_um)],
        "median [µm]": summary.median_um.map("{:.1f}".format),
        "P99.865 % [µm]": [_fmt_ci(v, ci) for v, ci in zip(summary.p99865_um, summary.p99865_ci_um)],
        "outside stated [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(summary.outside_stated_ppm, summary.outside_stated_ci_ppm)],
    })
    not_built = pd.DataFrame({
        "scheme": summary.index,
        "bearings": summary.bearings,
        "assembled": summary.assembled,
        **{reason: summary[reason] for reason in STATUS if reason != "assembled"},
        "substituted pairs": summary.substituted,
        "shells made": summary.shells_made,
        "shells scrapped [%]": summary.shells_scrapped_pct.map("{:.2f}".format),
    })
    fit = fit_summary(ds)
    p_min, s_max = float(ds.design_contact_pressure_min), float(ds.design_shell_stress_max)
    fit_table = pd.DataFrame({
        "scheme": fit.index,
        "nominal mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.nominal_mean_um, fit.nominal_std_um)],
        "operating mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.operating_mean_um, fit.operating_std_um)],
        "operating P0.135–P99.865 % [µm]": [f"{a:.1f}–{b:.1f}" for a, b in zip(fit.operating_p00135_um, fit.operating_p99865_um)],
        "swell [µm]": fit.swell_mean_um.map("{:.2f}".format),
        "min p [MPa]": fit.contact_pressure_min_mpa.map("{:.1f}".format),
        "max σ [MPa]": fit.shell_stress_max_mpa.map("{:.0f}".format),
        f"p < {p_min / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.low_pressure_ppm, fit.low_pressure_ci_ppm)],
        f"σ > {s_max / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.high_stress_ppm, fit.high_stress_ci_ppm)],
        "loss of fit [ppm]": fit.loss_of_fit_ppm.map("{:.0f}".format),
    })
    press = json.loads(ds.attrs["press_fit"])
    crank = crank_summary(ds)
    crank_lines = []
    if (crank.engines > 0).any():
        wide = crank.reset_index()
        cells = wide.assign(text=[f"{m:.2f} ± {c:.2f} (max {x:.1f})" for m, c, x in zip(wide.mean_kn, wide.ci_kn, wide.max_kn)])
        crank_table = cells.pivot(index="scheme", columns="bearing", values="text")
        crank_table.columns = [f"bearing {b} [kN]" for b in crank_table.columns]
        first = crank.groupby(level="scheme").first()
        crank_table.insert(0, "engines (failed)", [f"{e} ({f})" for e, f in zip(first.engines, first.failed)])
        crank_lines = [
            "## Bearing loads over the engine cycle",
            "",
            "Cycle-maximum load of each main bearing (mean ± 95 % interval of the mean, and the largest), from the "
            "crankshaft as a continuous beam on the Bellakhdhar et al. bearing law, with each engine's operating "
            "clearances and sampled bore and journal misalignment. The beam runs on the first engines sampled "
            f"({int(ds.attrs.get('mechanics_engines_used', json.loads(ds.attrs['study'])['mechanics_engines']))} per "
            f"scheme{_target_text(ds)}); engines with a bearing not "
            "assembled are skipped and marked in `crank_status`.",
            "",
            _markdown_table(crank_table.reset_index()),
            "",
        ]
    film = film_summary(ds)
    film_lines = []
    if len(film):
        film_histogram(ds, out / "film_life.png")
        study = json.loads(ds.attrs["study"])
        film_table = pd.DataFrame({
            "scheme": film.index, "engines": film.engines,
            "h_min P5 [µm]": [f"{q[0]:.2f} [{q[1]:.2f}, {q[2]:.2f}]" for q in film.h_min_p05_um],
            "h_min median [µm]": [f"{q[0]:.2f}" for q in film.h_min_median_um],
            "α mean [%]": (100 * film.alpha_mean).map("{:.1f}".format),
            "α > 20 % [% of bearings]": [f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]" for v in film.alpha_over_20_pct],
            "life B10 [h]": [f"{q[0]:.3g} [{q[1]:.3g}, {q[2]:.3g}]" for q in film.life_b10_h],
            "life median [h]": [f"{q[0]:.3g}" for q in film.life_median_h],
            f"engines < {float(ds.life_target) / 3600:.0f} h [%]": [f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]" for v in film.engines_below_target_pct],
        })
        film_lines = [
            "## Oil film and bearing life",
            "",
            f"Minimum film thickness over the cycle from each bearing's load history (quasi-static orbit on the "
            f"`{study.get('film_method', 'finite')}` tier; no squeeze film, so films are conservative), oil "
            "viscosity at the effective temperature of an isothermal heat balance; α is the share of the cycle "
            "with the film below h_lim,cr = 1.9 µm (above 20 % the risk of scuffing rises sharply); life by "
            "Levanov et al. (2015) method 1 with the cycle-minimum film and the paper's constants (n = −2, "
            "Δh_lim = 30 µm, γ = 1e-13 m/s), whose absolute values are calibrated to another engine: compare "
            "schemes, not hours. An engine's life is that of its weakest bearing.",
            "",
            _markdown_table(film_table),
            "",
            "![Film thickness and life per scheme](film_life.png)",
            "",
        ]
    plan_lines = ["## Planning: shells per grade", ""]
    if kept_summaries(ds):
        plan_lines += ["Planning needs each engine's shell demand: run the study with `keep=\"everything\"` "
                       "(the summaries keep only the totals in the grade usage below).", ""]
    else:
        from .plan import plan as plan_grades

        frame = plan_grades(ds, volume=10_000, service_level=0.99)
        plan_rows = [{"scheme": scheme, "grade": grade,
                      "demand per 1000 engines": f"{r.demand_per_1000:.0f} [{r.demand_per_1000_lo:.0f}, {r.demand_per_1000_hi:.0f}]",
                      "production share [%]": f"{100 * r.production_share:.2f}",
                      "surplus for 10 000 engines": f"{r.surplus:+.0f}",
                      "safety stock per lot (99 %)": f"{r.safety_stock:.0f}",
                      "order-up-to per lot": f"{r.order_up_to:.0f}"} for (scheme, grade), r in frame.iterrows()]
        plan_lines += [
            "From `stackup.plan` on this study's own engines and shell lots: expected demand per grade (95 % "
            "interval), the share of the shell production that landed in the grade when read and sorted, the "
            "surplus over 10 000 engines, and the safety stock per production lot "
            f"({ds.attrs['lot_engines']} engines) for a 99 % chance that the lot's demand is covered (checked by "
            "simulated lots in the tests). `stackup plan --scheme NAME --volume N` plans any volume and service "
            "level.",
            "",
            _markdown_table(pd.DataFrame(plan_rows)),
            "",
        ]
    usage_table = usage.reset_index()[["scheme", "shell_grade", "shells_made", "shells_used", "shells_left", "used_share_pct"]]
    usage_table["used_share_pct"] = usage_table["used_share_pct"].map("{:.2f}".format)
    usage_table.columns = ["scheme", "grade", "made", "fitted", "left in stock", "share of fitted [%]"]

    from .rank import rank as rank_schemes

    ranking = rank_schemes(ds, scenarios=scenarios or None)

    def column(name):
        """A ranking column, or '—' cells where the study has no film stage."""
        return ranking[name] if name in ranking else pd.Series(np.nan, index=ranking.index, dtype=object)

    rank_table = pd.DataFrame({
        "rank": ranking["rank"],
        "scheme": ranking.index,
        "operating mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(ranking.clearance_mean_um, ranking.clearance_std_um)],
        "outside window [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(ranking.outside_window_ppm, ranking.outside_window_ppm_ci)],
        "α > 20 % [%]": [_fmt_ci(v, ci, 1) if isinstance(ci, tuple) else "—"
                         for v, ci in zip(column("alpha_over_limit_pct"), column("alpha_over_limit_pct_ci"))],
        "life median [h]": [f"{v:.3g} [{ci[0]:.3g}, {ci[1]:.3g}]" if isinstance(ci, tuple) else "—"
                            for v, ci in zip(column("life_median_h"), column("life_median_h_ci"))],
        "shell grades": ranking.shell_grades,
        "stock-outs [ppm]": ranking.stockout_ppm.map("{:.0f}".format),
        "surplus [%]": ranking.surplus_pct.map("{:.1f}".format),
    })
    if scenarios:
        rank_table["worst scenario: Δ outside window [ppm]"] = [
            f"{v:+.0f} ({name})" for v, name in zip(ranking.worst_outside_window_ppm, ranking.worst_outside_window_ppm_scenario)]
        if "worst_life_median_h" in ranking:
            rank_table["worst scenario: Δ life median [h]"] = [
                f"{v:+.3g} ({name})" for v, name in zip(ranking.worst_life_median_h, ranking.worst_life_median_h_scenario)]
    if sensitivity is not None and sensitivity.sizes["output"]:
        fits = sensitivity_chart(sensitivity, out / "sensitivity.png")
        r2_text = "; ".join(f"{scheme} {output} R² {r2:.2f}" for (output, scheme), r2 in fits.items())
        sensitivity_lines = [
            "Share of the variance of the operating clearance and of the cycle-minimum film (within each bearing "
            "position) that each input explains, from standardised regression coefficients with 95 % bootstrap "
            "intervals. In selective assembly the shells are chosen from the measured sizes, so inputs are "
            "correlated: read the shares with the fit's R² (" + r2_text + ").",
            "",
            "![Contributions to the variance](sensitivity.png)",
        ]
    else:
        sensitivity_lines = ["The contributions of the inputs come with `stackup.compare` (its `sensitivity` "
                             "dataset, computed from a study that keeps every engine); none was given."]
    window = ranking.attrs["window_m"]
    study = json.loads(ds.attrs["study"])
    n_engines = study["n_engines"]
    lines = [
        f"# Scheme comparison: {ds.attrs['engine']}",
        "",
        f"{ds.attrs['title']}. stackup {ds.attrs['stackup_version']}, seed {ds.attrs['seed']}, "
        f"{n_engines:,} engines × {ds.sizes['bearing']} main bearings per scheme"
        + (" (streaming summaries: quantiles and histograms to 0.1 µm)." if kept_summaries(ds) else "."),
        "",
        "Nominal diametral clearance C = D_H − (s_upper + s_lower + D_J) of every assembled bearing, "
        "from true sizes; grading used gauge readings. No housing swell or temperature (as the "
        "standard's stated ranges). Intervals are 95 % (order statistics for quantiles, "
        "Clopper–Pearson for shares).",
        "",
        "## Ranking",
        "",
        f"Operating-clearance design window {window[0] * 1e6:.0f}–{window[1] * 1e6:.0f} µm (the engine's). "
        f"Rule: {ranking.attrs['rule']}. Tied schemes share a rank."
        + (f" Robustness: the worst change of the share outside the window over the declared scenarios "
           f"({', '.join(scenarios)}), each run with the same seed on the clearance stages; the misalignment "
           "scenario also runs the loads, film and life on 50 engines, whose change of the median life is shown."
           if scenarios else ""),
        "",
        _markdown_table(rank_table),
        "",
        "## What drives the spread",
        "",
        *sensitivity_lines,
        "",
        "## Clearance per scheme",
        "",
        _markdown_table(table),
        "",
        "![Nominal and operating clearance per scheme](clearance_histogram.png)",
        "",
        "## Operating clearance: press fit, housing swell and temperature",
        "",
        f"The shells are an interference fit (crush height {1e3 * float(ds.crush_height_limits[0]):.3f}–"
        f"{1e3 * float(ds.crush_height_limits[1]):.3f} mm per half shell, checked in a "
        f"{press['check_bore'] * 1e3:.3f} mm block at {press['check_stress'] / 1e6:.0f} MPa) in a "
        f"{press['housing_material']} housing ring of outer diameter {press['housing_outer'] * 1e3:.0f} mm; "
        f"assembled at {press['assembly_temperature']:.0f} °C, running at {press['temperature']:.0f} °C "
        f"({press['shell_material']} shells, {press['journal_material']} journal). "
        f"{FIT_TIERS.get(study['fit_method'], study['fit_method'])} tier. "
        f"Design limits: contact pressure at least {p_min / 1e6:.0f} MPa, shell compression at most "
        f"{s_max / 1e6:.0f} MPa.",
        "",
        _markdown_table(fit_table),
        "",
        *crank_lines,
        *film_lines,
        "## Assembly, scrap and stock",
        "",
        "Bearings not assembled are kept in the dataset with their reason (`status`); none are dropped.",
        "",
        _markdown_table(not_built),
        "",
        *plan_lines,
        "## Shell grade usage",
        "",
        "![Shell grades fitted and made per scheme](grade_usage.png)",
        "",
        _markdown_table(usage_table),
        "",
        "## Parameters",
        "",
        f"- study: `{json.dumps(study)}`",
        f"- engine source: {' '.join(ds.attrs['engine_source'].split())}",
        f"- shells: supply `{ds.attrs['shell_supply']}`, lots of {ds.attrs['lot_engines']} engines, "
        f"{100 * ds.attrs['shell_surplus']:.0f} % surplus, grade quantities planned from a pilot of "
        f"{ds.attrs['pilot_engines']:,} engines",
        *(f"- {k}: {v}" for k, v in json.loads(ds.attrs["scheme_sources"]).items()),
    ]
    if dataset_file:
        lines.append(f"- dataset: `{dataset_file}`")
    path = out / "report.md"
    text = "\n".join(lines) + "\n"
    path.write_text(text)
    (out / "report.html").write_text(markdown_to_html(text, out))
    return path
