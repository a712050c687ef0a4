"""Scheme-comparison tables and report, from a saved study dataset alone."""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .assembly import ASSEMBLED, STATUS  # noqa: E402
from .fit import CONTACT_PRESSURE_MIN, SHELL_STRESS_MAX  # noqa: E402
from .stats import proportion_ci, quantile_ci  # noqa: E402

#: Tail quantiles reported: the +-3 sigma points of a normal distribution.
TAIL_LOW, TAIL_HIGH = 0.00135, 0.99865
UM = 1e6


def fit_summary(ds, *, contact_pressure_min=CONTACT_PRESSURE_MIN, shell_stress_max=SHELL_STRESS_MAX):
    """One row per scheme: nominal against operating clearance [um], press-fit limits as shares with 95 % intervals."""
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        ok = d.status.values == ASSEMBLED
        nominal = d.clearance_nominal.values[ok]
        operating = d.clearance_operating.values[ok]
        p = d.contact_pressure.values[ok]
        sigma = d.shell_stress.values[ok]
        low_p = proportion_ci(np.count_nonzero(p < contact_pressure_min), p.size)
        high_s = proportion_ci(np.count_nonzero(sigma > shell_stress_max), sigma.size)
        lost = proportion_ci(np.count_nonzero(d.loss_of_fit.values[ok]), p.size)
        rows.append({
            "scheme": str(name),
            "nominal_mean_um": nominal.mean() * UM,
            "nominal_std_um": nominal.std(ddof=1) * UM,
            "operating_mean_um": operating.mean() * UM,
            "operating_std_um": operating.std(ddof=1) * UM,
            "operating_p00135_um": quantile_ci(operating, TAIL_LOW)[0] * UM,
            "operating_p99865_um": quantile_ci(operating, TAIL_HIGH)[0] * UM,
            "swell_mean_um": d.housing_swell.values[ok].mean() * UM,
            "contact_pressure_min_mpa": p.min() / 1e6,
            "shell_stress_max_mpa": sigma.max() / 1e6,
            "low_pressure_ppm": low_p[0] * 1e6,
            "low_pressure_ci_ppm": (low_p[1] * 1e6, low_p[2] * 1e6),
            "high_stress_ppm": high_s[0] * 1e6,
            "high_stress_ci_ppm": (high_s[1] * 1e6, high_s[2] * 1e6),
            "loss_of_fit_ppm": lost[0] * 1e6,
        })
    return pd.DataFrame(rows).set_index("scheme")


def clearance_summary(ds):
    """One row per scheme: nominal clearance statistics [um], shares outside the stated range, stock.

    Quantiles and shares come with 95 % intervals (order statistics and
    Clopper-Pearson).
    """
    rows = []
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        status = d.status.values
        c = d.clearance_nominal.values[status == ASSEMBLED]
        n_bearings = status.size
        lo_stated, hi_stated = d.clearance_stated.values
        outside = int(np.count_nonzero((c < lo_stated) | (c > hi_stated)))
        share, share_lo, share_hi = proportion_ci(outside, c.size)
        p_lo = quantile_ci(c, TAIL_LOW)
        p50 = quantile_ci(c, 0.5)
        p_hi = quantile_ci(c, TAIL_HIGH)
        made = int(d.shells_made.sum()) + int(d.shells_scrapped)
        row = {
            "scheme": str(name),
            "bearings": n_bearings,
            "assembled": c.size,
            "stated_min_um": lo_stated * UM,
            "stated_max_um": hi_stated * UM,
            "worst_case_min_um": float(d.clearance_limit.values[0]) * UM,
            "worst_case_max_um": float(d.clearance_limit.values[1]) * UM,
            "mean_um": float(c.mean()) * UM if c.size else np.nan,
            "std_um": float(c.std(ddof=1)) * UM if c.size > 1 else np.nan,
            "p00135_um": p_lo[0] * UM,
            "p00135_ci_um": (p_lo[1] * UM, p_lo[2] * UM),
            "median_um": p50[0] * UM,
            "p99865_um": p_hi[0] * UM,
            "p99865_ci_um": (p_hi[1] * UM, p_hi[2] * UM),
            "min_um": float(c.min()) * UM if c.size else np.nan,
            "max_um": float(c.max()) * UM if c.size else np.nan,
            "outside_stated_ppm": share * 1e6,
            "outside_stated_ci_ppm": (share_lo * 1e6, share_hi * 1e6),
            "shells_made": made,
            "shells_scrapped_pct": 100.0 * int(d.shells_scrapped) / made if made else np.nan,
            "substituted": int(np.count_nonzero(d.shell_option.values > 0)),
        }
        for code, reason in enumerate(STATUS):
            if code != ASSEMBLED:
                row[reason] = int(np.count_nonzero(status == code))
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
    converged = ds.crank_status.values == 0
    for i, name in enumerate(ds.scheme.values):
        ok = converged[i]
        failed = int(np.count_nonzero((ds.crank_status.values[i] > 0) & (ds.crank_status.values[i] < 3)))
        for b, bearing in enumerate(ds.bearing.values):
            r = ds.reaction_max.values[i, ok, b] / 1e3
            half = 1.96 * r.std(ddof=1) / np.sqrt(r.size) if r.size > 1 else np.nan
            rows.append({"scheme": str(name), "bearing": int(bearing), "engines": int(ok.sum()), "failed": failed,
                         "mean_kn": r.mean() if r.size else np.nan, "ci_kn": half,
                         "max_kn": r.max() if r.size else np.nan})
    return pd.DataFrame(rows).set_index(["scheme", "bearing"])


#: Life target of the report [h] (Levanov et al. set 10 000 h for their diesel bearing; this is a design choice).
LIFE_TARGET_HOURS = 1000.0


def film_summary(ds, *, life_target_hours=LIFE_TARGET_HOURS):
    """Per scheme: cycle-minimum film, boundary-friction share and Levanov life, with 95 % intervals."""
    from .life import ALPHA_SCUFFING

    rows = []
    for i, name in enumerate(ds.scheme.values):
        done = ds.crank_status.values[i] == 0
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
    fig, (ax_h, ax_l) = plt.subplots(1, 2, figsize=(11, 3.6))
    for i, name in enumerate(ds.scheme.values):
        done = ds.crank_status.values[i] == 0
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
    plt.close(fig)
    return path


def sensitivity_chart(ds, path, *, outputs=("clearance_operating", "h_min")):
    """Contributor chart: share of variance per input, per scheme and output (95 % bootstrap intervals); PNG."""
    from .sensitivity import INPUTS, contributions

    outputs = [o for o in outputs if np.isfinite(ds[o].values).any()]
    names = list(ds.scheme.values)
    fig, axes = plt.subplots(len(outputs), len(names), figsize=(2.6 * len(names) + 1.5, 2.6 * len(outputs) + 0.5),
                             sharex=True, squeeze=False)
    fits = {}
    for r, output in enumerate(outputs):
        for c, name in enumerate(names):
            ax = axes[r, c]
            try:
                frame = contributions(ds, name, output=output, bootstrap=100)
            except ValueError:
                ax.set_axis_off()
                continue
            fits[(output, str(name))] = frame
            frame = frame.reindex([k for k in reversed(INPUTS) if k in frame.index])  # same order in every panel
            err = np.vstack([frame.share - frame.share_lo, frame.share_hi - frame.share]).clip(min=0) * 100
            ax.barh(frame.index, 100 * frame.share, xerr=err, color="tab:blue", alpha=0.8)
            ax.set_title(f"{name}\n{output} (R² {frame.attrs['r2']:.2f})", fontsize=8)
            ax.tick_params(labelsize=7)
            if c:
                ax.set_yticklabels([])
        axes[r, 0].set_ylabel("input")
    for ax in axes[-1]:
        ax.set_xlabel("share of variance [%]")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
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


def clearance_histogram(ds, path):
    """Histograms of nominal and operating clearance per scheme, stated range shaded; saved as PNG."""
    names = list(ds.scheme.values)
    fig, axes = plt.subplots(len(names), 1, figsize=(7.5, 1.6 * len(names) + 0.8), sharex=True)
    axes = np.atleast_1d(axes)
    ok = ds.status.values == ASSEMBLED
    c_all = np.concatenate([ds.clearance_nominal.values[ok], ds.clearance_operating.values[ok]]) * UM
    bins = np.arange(np.floor(c_all.min()) - 1, np.ceil(c_all.max()) + 2, 0.5)
    for ax, name in zip(axes, names):
        d = ds.sel(scheme=name)
        ok = d.status.values == ASSEMBLED
        lo, hi = d.clearance_stated.values * UM
        ax.axvspan(lo, hi, color="tab:green", alpha=0.12, label="stated range")
        ax.hist(d.clearance_nominal.values[ok] * UM, bins=bins, color="tab:blue", alpha=0.75, label="nominal")
        ax.hist(d.clearance_operating.values[ok] * UM, bins=bins, color="tab:red", alpha=0.55, label="operating")
        ax.set_yscale("log")
        ax.set_ylabel("bearings")
        ax.set_title(str(name), fontsize=9, loc="left")
    axes[-1].set_xlabel("diametral clearance [µm]")
    axes[0].legend(loc="upper right", fontsize=8, ncols=3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def grade_usage_chart(ds, path):
    """Shells fitted per grade and scheme as shares of the scheme's fitted shells; saved as PNG."""
    usage = grade_usage(ds)
    names = list(ds.scheme.values)
    fig, axes = plt.subplots(1, len(names), figsize=(2.0 * len(names) + 1, 2.8), sharey=True)
    axes = np.atleast_1d(axes)
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
    plt.close(fig)
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


def write_report(ds, out_dir, *, dataset_file=None, scenarios=None):
    """Write ``report.md``, its self-contained twin ``report.html`` and the figures into ``out_dir``; return the markdown path."""
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
    fit_table = pd.DataFrame({
        "scheme": fit.index,
        "nominal mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.nominal_mean_um, fit.nominal_std_um)],
        "operating mean ± std [µm]": [f"{m:.2f} ± {v:.2f}" for m, v in zip(fit.operating_mean_um, fit.operating_std_um)],
        "operating P0.135–P99.865 % [µm]": [f"{a:.1f}–{b:.1f}" for a, b in zip(fit.operating_p00135_um, fit.operating_p99865_um)],
        "swell [µm]": fit.swell_mean_um.map("{:.2f}".format),
        "min p [MPa]": fit.contact_pressure_min_mpa.map("{:.1f}".format),
        "max σ [MPa]": fit.shell_stress_max_mpa.map("{:.0f}".format),
        f"p < {CONTACT_PRESSURE_MIN / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.low_pressure_ppm, fit.low_pressure_ci_ppm)],
        f"σ > {SHELL_STRESS_MAX / 1e6:.0f} MPa [ppm]": [_fmt_ci(v, ci, 0) for v, ci in zip(fit.high_stress_ppm, fit.high_stress_ci_ppm)],
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
            f"engines < {LIFE_TARGET_HOURS:.0f} h [%]": [f"{v[0]:.1f} [{v[1]:.1f}, {v[2]:.1f}]" for v in film.engines_below_target_pct],
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
    from .plan import plan as plan_grades

    study_params = json.loads(ds.attrs["study"])
    plan_rows = []
    for name in ds.scheme.values:
        try:
            frame = plan_grades(str(name), study_params["engine"], volume=10_000, service_level=0.99,
                                sample_engines=20_000, seed=study_params["seed"])
        except ValueError:
            continue
        for grade, r in frame.iterrows():
            plan_rows.append({"scheme": str(name), "grade": grade,
                              "demand per 1000 engines": f"{r.demand_per_1000:.0f} [{r.demand_per_1000_lo:.0f}, {r.demand_per_1000_hi:.0f}]",
                              "production share [%]": f"{100 * r.production_share:.2f}",
                              "surplus for 10 000 engines": f"{r.surplus:+.0f}",
                              "safety stock per lot (99 %)": f"{r.safety_stock:.0f}",
                              "order-up-to per lot": f"{r.order_up_to:.0f}"})
    plan_lines = []
    if plan_rows:
        plan_lines = [
            "## Planning: shells per grade",
            "",
            "From `stackup.plan`: expected demand per grade (95 % interval), the share of the shell production "
            "that lands in the grade when read and sorted, the surplus over 10 000 engines, and the safety stock "
            f"per production lot ({ds.attrs['lot_engines']} engines) for a 99 % chance that the lot's demand is "
            "covered (checked by simulated lots in the tests). `stackup plan --scheme NAME --volume N` prints "
            "the same for any volume and service level.",
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
    fits = sensitivity_chart(ds, out / "sensitivity.png")
    r2_text = "; ".join(f"{scheme} {output} R² {frame.attrs['r2']:.2f}" for (output, scheme), frame in fits.items())
    window = ranking.attrs["window_m"]
    study = json.loads(ds.attrs["study"])
    lines = [
        f"# Scheme comparison: {ds.attrs['engine']}",
        "",
        f"{ds.attrs['title']}. stackup {ds.attrs['stackup_version']}, seed {ds.attrs['seed']}, "
        f"{ds.sizes['engine']:,} engines × {ds.sizes['bearing']} main bearings per scheme.",
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
        "Share of the variance of the operating clearance and of the cycle-minimum film (within each bearing "
        "position) that each input explains, from standardised regression coefficients with 95 % bootstrap "
        "intervals. In selective assembly the shells are chosen from the measured sizes, so inputs are "
        "correlated: read the shares with the fit's R² (" + r2_text + ").",
        "",
        "![Contributions to the variance](sensitivity.png)",
        "",
        "## Clearance per scheme",
        "",
        _markdown_table(table),
        "",
        "![Nominal and operating clearance per scheme](clearance_histogram.png)",
        "",
        "## Operating clearance: press fit, housing swell and temperature",
        "",
        f"The shells are an interference fit (crush height {1e3 * ds.attrs['crush_height_limits'][0]:.3f}–"
        f"{1e3 * ds.attrs['crush_height_limits'][1]:.3f} mm per half shell, checked in a "
        f"{press['check_bore'] * 1e3:.3f} mm block at {press['check_stress'] / 1e6:.0f} MPa) in a "
        f"{press['housing_material']} housing ring of outer diameter {press['housing_outer'] * 1e3:.0f} mm; "
        f"assembled at {press['assembly_temperature']:.0f} °C, running at {press['temperature']:.0f} °C "
        f"({press['shell_material']} shells, {press['journal_material']} journal). Thick-ring (Lamé) tier. "
        f"Design limits: contact pressure at least {CONTACT_PRESSURE_MIN / 1e6:.0f} MPa, shell compression at most "
        f"{SHELL_STRESS_MAX / 1e6:.0f} MPa.",
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
