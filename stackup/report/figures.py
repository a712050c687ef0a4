"""Figures of the comparison report, drawn on matplotlib ``Figure`` objects (the user's backend is left alone).

Every figure has a title and units on its axes, and is sized to be legible
at the page width of the HTML report (1200 px).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..study import summaries
from ..facts.tables import UM, assembled, checked_lives, converged_engines, grade_usage, kept_summaries, numbers

#: Width of a full-page figure [in] at DPI: the HTML page is 1200 px wide.
WIDTH, DPI = 11.0, 110


def _save(fig, path):
    fig.savefig(path, dpi=DPI)
    return path


def _clearance_histograms(ds, name):
    """(bin edges [um], nominal counts, operating counts) of one scheme, from values or the summary histograms."""
    d = ds.sel(scheme=name)
    if kept_summaries(ds):
        edges = (summaries.BIN_START + np.arange(summaries.BINS + 1) * summaries.BIN_WIDTH) * UM
        return edges, d.clearance_nominal_histogram.values, d.clearance_operating_histogram.values
    return None, assembled(d, "clearance_nominal") * UM, assembled(d, "clearance_operating") * UM


def clearance_histogram(ds, path):
    """Nominal clearance against each scheme's stated range, operating clearance against the design window; PNG."""
    names = list(ds.scheme.values)
    fig = Figure(figsize=(WIDTH, 1.5 * len(names) + 1.2), layout="constrained")
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
    window = ds.clearance_window.values * UM
    for ax, name in zip(axes, names):
        edges, nominal, operating = data[name]
        lo, hi = ds.sel(scheme=name).clearance_stated.values * UM
        if np.isfinite(lo) and np.isfinite(hi):  # a scheme may state no range
            ax.axvspan(lo, hi, color="tab:blue", alpha=0.10, label="stated range (nominal)")
        if np.all(np.isfinite(window)):  # an engine file may give no window
            ax.axvspan(*window, color="tab:red", alpha=0.08, label="design window (operating)")
            for x in window:
                ax.axvline(x, color="tab:red", lw=1.0, ls="--")
        for values, colour, alpha, label in ((nominal, "tab:blue", 0.7, "nominal"),
                                             (operating, "tab:red", 0.55, "operating")):
            # counted first, drawn as one filled step artist (a bar per bin is one artist each, slow to draw)
            counts = np.histogram(values, bins=bins)[0] if edges is None else \
                np.histogram(0.5 * (edges[1:] + edges[:-1]), bins=bins, weights=values)[0]  # re-binned summaries
            ax.stairs(np.where(counts > 0, counts, np.nan), bins, fill=True, baseline=0.5, color=colour,
                      alpha=alpha, label=label)
        ax.set_yscale("log")
        ax.set_ylabel("bearings")
        ax.set_title(str(name), fontsize=10, loc="left")
    axes[-1].set_xlabel("diametral clearance [µm]")
    axes[0].legend(loc="upper right", fontsize=8, ncols=4)
    fig.suptitle("Nominal clearance against the stated range; operating clearance (press fit, swell, temperature) "
                 "against the design window", fontsize=11)
    return _save(fig, path)


def film_by_bearing(ds, path):
    """Cycle-minimum film and life per main-bearing position and scheme (box plots); PNG.

    The positions carry different loads (the middle bearings of an inline
    engine take the combustion loads of two cylinders), which is why the film
    pooled over positions is multimodal.
    """
    names = list(ds.scheme.values)
    bearings = list(ds.bearing.values)
    fig = Figure(figsize=(WIDTH, 4.2), layout="constrained")
    ax_h, ax_l = fig.subplots(1, 2)
    width = 0.8 / len(names)
    for k, name in enumerate(names):
        i = names.index(name)
        done = converged_engines(ds, i)
        offset = (k - (len(names) - 1) / 2) * width
        # a bearing whose film is not a number (NaN: collapsed, not periodic, failed) has no box point
        h = [numbers(ds.h_min.values[i, done, b] * UM) for b in range(len(bearings))]
        lives = checked_lives(ds.isel(scheme=i), done)  # on the check tier's scale where the study ran it
        life = [numbers(lives[:, b]) for b in range(len(bearings))]
        colour = f"C{k}"
        for ax, values in ((ax_h, h), (ax_l, life)):
            if not done.any():
                continue
            parts = ax.boxplot(values, positions=np.arange(len(bearings)) + offset, widths=0.9 * width,
                               showfliers=False, patch_artist=True, manage_ticks=False)
            for box in parts["boxes"]:
                box.set(facecolor=colour, alpha=0.6)
        ax_h.plot([], [], color=colour, lw=6, alpha=0.6, label=str(name))
    for ax in (ax_h, ax_l):
        ax.set_xticks(np.arange(len(bearings)), [str(b) for b in bearings])
        ax.set_xlabel("main bearing position (1 at the front)")
    _film_and_life_axes(ds, ax_h, ax_l, life_label="bearing life [h]",
                        titles=("Oil film per bearing position (box: quartiles, whiskers: 1.5 IQR)",
                                "Life per bearing position"))
    ax_l.legend(fontsize=8)
    return _save(fig, path)


def _film_and_life_axes(ds, ax_h, ax_l, *, life_label, titles):
    """Labels, titles (film, life) and the film's legend of a figure of films [µm] beside lives [h], the lives on a
    log scale with the engine's life target."""
    ax_l.set_yscale("log")
    ax_l.axhline(float(ds.life_target) / 3600, color="k", ls="--", lw=1, label="life target")
    ax_h.set_ylabel("cycle-minimum film h_min [µm]")
    ax_l.set_ylabel(life_label)
    ax_h.set_title(titles[0], fontsize=10)
    ax_l.set_title(titles[1], fontsize=10)
    ax_h.legend(fontsize=8, ncols=2)


def film_life_by_clearance(ds, path, bins=12):
    """Cycle-minimum film and life against the operating clearance, one colour per main-bearing position; PNG.

    Every scheme's bearings of the mechanical chain together (the schemes
    differ in which clearances they give, not in how a bearing responds to
    one): points, and each position's median in clearance bins with at
    least 10 bearings, so an engineer sees which clearance each position
    prefers. Needs every engine kept (``clearance_operating``); returns None
    from streaming summaries.
    """
    if kept_summaries(ds) or "clearance_operating" not in ds:
        return None
    m = ds.sizes["mech_engine"]
    clearance = ds.clearance_operating.values[:, :m] * UM
    h, life = ds.h_min.values * UM, np.full(ds.life.shape, np.nan)
    done = np.stack([converged_engines(ds, i) for i in range(ds.sizes["scheme"])])[..., None]
    for i in range(ds.sizes["scheme"]):  # lives on the check tier's scale where the study ran it
        life[i, done[i, :, 0]] = checked_lives(ds.isel(scheme=i), done[i, :, 0])
    fig = Figure(figsize=(WIDTH, 4.2), layout="constrained")
    ax_h, ax_l = fig.subplots(1, 2, sharex=True)
    edges = np.linspace(np.nanmin(clearance), np.nanmax(clearance), bins + 1)
    middles = 0.5 * (edges[1:] + edges[:-1])
    for b, bearing in enumerate(ds.bearing.values):
        c = clearance[..., b]
        for ax, values in ((ax_h, h[..., b]), (ax_l, life[..., b])):
            ok = done[..., 0] & np.isfinite(c) & np.isfinite(values)
            ax.scatter(c[ok], values[ok], s=3, alpha=0.15, color=f"C{b}", rasterized=True)
            which = np.digitize(c[ok], edges[1:-1])
            medians = [np.median(values[ok][which == k]) if np.count_nonzero(which == k) >= 10 else np.nan
                       for k in range(bins)]
            ax.plot(middles, medians, color=f"C{b}", lw=2, label=f"bearing {bearing}")
    for ax in (ax_h, ax_l):
        ax.set_xlabel("operating clearance (diametral) [µm]")
    _film_and_life_axes(ds, ax_h, ax_l, life_label="bearing life, Levanov method 1 [h]",
                        titles=("Oil film against clearance per position (lines: medians)",
                                "Life against clearance per position (lines: medians)"))
    return _save(fig, path)


def sensitivity_chart(sensitivity, path):
    """Total and first-order Sobol indices per input, one panel per scheme and output, 95 % intervals; PNG."""
    panels = [(str(o), str(s)) for o in sensitivity.output.values for s in sensitivity.scheme.values
              if np.isfinite(sensitivity.ST.sel(output=o, scheme=s).values).any()]
    columns = min(3, len(panels))
    rows = -(-len(panels) // columns)
    fig = Figure(figsize=(WIDTH, 2.9 * rows + 0.9), layout="constrained")
    axes = np.atleast_2d(fig.subplots(rows, columns, sharex=True, squeeze=False))
    labels = {"clearance_operating": "operating clearance", "h_min": "engine's smallest mid-plane film", "life": "engine life"}
    # every panel on the same rows (the inputs of any panel), so the first column's labels name every row; an
    # input that is not one of a panel's outputs' (misalignment for the clearance) has no bar there
    analysed = np.isfinite(sensitivity.ST.values).any(axis=(0, 1))
    rows_used = np.flatnonzero(analysed)[::-1]
    for k, (output, scheme) in enumerate(panels):
        ax = axes[k // columns, k % columns]
        d = sensitivity.sel(output=output, scheme=scheme).isel(input=rows_used)
        y = np.arange(d.sizes["input"])
        for index, offset, colour in (("ST", 0.2, "tab:blue"), ("S1", -0.2, "tab:orange")):
            value = d[index].values
            err = np.vstack([value - d[f"{index}_lo"].values, d[f"{index}_hi"].values - value]).clip(min=0)
            ax.barh(y + offset, value, height=0.4, xerr=err, color=colour, alpha=0.85,
                    label="total index S_T" if index == "ST" else "first-order index S_1")
        ax.set_yticks(y, [str(i) for i in d.input.values] if k % columns == 0 else [""] * len(y), fontsize=8)
        ax.set_ylim(-0.6, len(y) - 0.4)  # the same rows in every panel, whatever it has bars on
        ax.set_title(f"{scheme}: {labels.get(output, output)}", fontsize=9)
        ax.axvline(0, color="k", lw=0.5)
    for k in range(len(panels), rows * columns):
        axes[k // columns, k % columns].set_axis_off()
    for ax in axes[-1]:
        ax.set_xlabel("share of the output's variance [-]")
    axes[0, 0].legend(fontsize=8, loc="lower right")
    fig.suptitle("What drives the spread: Sobol indices of the root inputs through the assembly chain "
                 "(95 % bootstrap intervals)", fontsize=11)
    return _save(fig, path)


def grade_usage_chart(ds, path):
    """Shells fitted per grade and scheme as shares of the scheme's fitted shells; saved as PNG."""
    usage = grade_usage(ds)
    names = list(ds.scheme.values)
    fig = Figure(figsize=(WIDTH, 3.2), layout="constrained")
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
    axes[0].legend(fontsize=8)
    fig.suptitle("Shell grades fitted and made, per scheme", fontsize=11)
    return _save(fig, path)
