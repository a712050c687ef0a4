"""A scheme designed for the example engine against the six ISO 13778 schemes, on independent samples.

    python studies/design_scheme.py [--n 100000] [--seed 1] [--quick]

1. :func:`stackup.design.design` designs a scheme for the built-in example
   engine and its operating-clearance window (timed: wall and CPU time);
   it is written to reports/design_scheme.toml with its explanation.
2. A :class:`stackup.Study` (its own lots, another seed: parts independent of
   the design sample) runs the designed scheme beside the six ISO schemes,
   nominally and under each declared scenario (same seed, common random
   numbers); :func:`stackup.rank` gives the share outside the window with
   its 95 % interval.
3. The designer's own estimate of each scheme's share outside the window (the
   shells integrated out on a design sample) is set beside the study's: the
   error of the designer's tier against the full chain.
4. Designs with 2 to 5 shell grades on the design sample: what more grades buy.

Writes reports/design_scheme.md; the numbers of the report come from this
script alone, so rerunning it after an engine change regenerates them.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np
from _common import environment, write_report

import stackup
import stackup.design as design_mod
from stackup.design.estimate import outside_share
from stackup.engines import load_engine
from stackup.scenarios import DECLARED

ENGINE = "iso-example"
ISO = design_mod.ISO_SCHEMES
SCHEME_FILE = Path("reports/design_scheme.toml")
#: Fewest bearings a study must count outside the window for its count to decide (as stackup.rank).
MIN_COUNTED = 20
#: Independent design samples and engines per sample of the conditional estimate.
TIER_SAMPLES, TIER_ENGINES = 10, 20_000
#: Shell grade counts compared on the design sample (the issue asks for at most five).
GRADE_COUNTS = (2, 3, 4, 5)
PPM = 1e6


def timed_design(**options):
    """The design and its wall and CPU time [s]."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = design_mod.design(ENGINE, **options)
    return result, time.perf_counter() - wall, time.process_time() - cpu


def study_runs(schemes, n, seed):
    """Label -> ranked table of the study nominally and under each declared scenario (clearance stages)."""
    runs = {}
    for label, change in [("nominal", None), *DECLARED.items()]:
        t0 = time.perf_counter()
        ds = stackup.Study(engine=ENGINE, schemes=tuple(schemes), n_engines=n, seed=seed, keep="summaries",
                           mechanics_engines=0, scenario=change, progress=False).run()
        runs[label] = stackup.rank(ds)
        print(f"study {label}: {time.perf_counter() - t0:.0f} s", flush=True)
    return runs


def fmt_ci(value, ci):
    """A share [ppm] and its interval to the value's precision: whole ppm from 10, tenths from 1, else 2 digits."""
    if value >= 10:
        return f"{value:.0f} [{ci[0]:.0f}, {ci[1]:.0f}]"
    if value >= 1 or value == 0:
        return f"{value:.1f} [{ci[0]:.1f}, {ci[1]:.1f}]"
    digits = max(1, 1 - int(np.floor(np.log10(value))))
    return f"{value:.{digits}f} [{ci[0]:.{digits}f}, {ci[1]:.{digits}f}]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="engines of the validation study")
    parser.add_argument("--seed", type=int, default=1, help="seed of the validation study")
    parser.add_argument("--quick", action="store_true", help="a small run to try the script")
    args = parser.parse_args()
    n = 5000 if args.quick else args.n
    engine = load_engine(ENGINE)
    window = engine.clearance_window
    load_before = os.getloadavg()

    result, wall, cpu = timed_design(log=print)
    designed = result.scheme
    SCHEME_FILE.parent.mkdir(parents=True, exist_ok=True)
    designed.to_toml(SCHEME_FILE)
    print(f"design: {wall:.1f} s wall, {cpu:.1f} s CPU")

    schemes = [str(SCHEME_FILE), *ISO]
    runs = study_runs(schemes, n, args.seed)
    names = [designed.name, *ISO]
    labels = list(runs)

    # the designer's conditional tier on independent design samples, for every run and scheme
    tier = {}
    for label, change in [("nominal", None), *DECLARED.items()]:
        tier[label] = {name: outside_share(engine, scheme, window=window, seed=args.seed, scenario=change,
                                           samples=3 if args.quick else TIER_SAMPLES,
                                           n_engines=2000 if args.quick else TIER_ENGINES)
                       for name, scheme in zip(names, [designed, *ISO])}

    def counted(label, name):
        row = runs[label].loc[name]
        return row["outside_window_ppm"], row["outside_window_ppm_ci"]

    def cell(label, name):
        """The share the ranking rule uses: the study's count from MIN_COUNTED bearings on, else the tier."""
        row = runs[label].loc[name]
        if row["outside_window_ppm"] * row["bearings"] / PPM >= MIN_COUNTED:
            return row["outside_window_ppm"], row["outside_window_ppm_ci"]
        t = tier[label][name]
        return t.outside * PPM, tuple(x * PPM for x in t.outside_interval)

    worst = {}
    for name in names:
        label = max(labels[1:], key=lambda lab: cell(lab, name)[0])
        worst[name] = (label, *cell(label, name))

    # done-when checks
    nominal_hi = cell("nominal", designed.name)[1][1]
    beats_nominal = all(nominal_hi < cell("nominal", k)[1][0] for k in ISO)
    worst_hi = worst[designed.name][2][1]
    beats_worst = all(worst_hi < worst[k][2][0] for k in ISO)
    beats_each = all(cell(lab, designed.name)[1][1] < min(cell(lab, k)[1][0] for k in ISO) for lab in labels)
    best_iso = min(ISO, key=lambda k: cell("nominal", k)[0])
    robust_iso = min(ISO, key=lambda k: worst[k][1])

    counts = []
    for k in GRADE_COUNTS:
        r, w, c = timed_design(shell_grades=k, n_engines=1000 if args.quick else 4000)
        counts.append((k, r, w, c))
        print(f"{k} shell grades: J {r.objective * PPM:.1f} ppm, {w:.0f} s", flush=True)

    order = sorted(names, key=lambda k: runs["nominal"].loc[k, "rank"])
    gauge_label = next(lab for lab, change in DECLARED.items() if "gauge_repeatability" in change)
    lines = [
        "# Scheme designed for the example engine against ISO 13778",
        "",
        f"{environment()}. Engine `{ENGINE}`, operating-clearance window "
        f"{window[0] * PPM:.4g}–{window[1] * PPM:.4g} µm (the engine's). Generated by `studies/design_scheme.py`.",
        "",
        "## Verdict",
        "",
        f"The designed scheme `{designed.name}` ({designed.title.split(': ')[-1]}) keeps "
        f"{fmt_ci(*cell('nominal', designed.name))} ppm of the bearings outside the window, against "
        f"{fmt_ci(*cell('nominal', best_iso))} ppm for {best_iso}, the best ISO scheme on this engine, on parts "
        f"independent of the design sample; under its worst declared scenario ({worst[designed.name][0]}) "
        f"{fmt_ci(*worst[designed.name][1:])} ppm against {fmt_ci(*worst[robust_iso][1:])} ppm for "
        f"{robust_iso} ({worst[robust_iso][0]}), the ISO scheme whose worst scenario is least bad. "
        f"The design took {cpu:.1f} s of CPU time ({wall:.1f} s wall with a load average of "
        f"{load_before[0]:.1f} on {os.cpu_count()} cores when it started).",
        "",
        f"How the shares are known: a study of {n:,} engines × {engine.main_bearings} bearings counts them where "
        f"it finds at least {MIN_COUNTED} bearings outside the window (Clopper–Pearson interval), as "
        "`stackup.rank` does; below that, where a count cannot tell a few ppm from a tenth of one, the "
        f"designer's conditional tier does (`stackup.design.estimate.outside_share`: the shells integrated out "
        f"on {TIER_SAMPLES} independent samples of {TIER_ENGINES:,} engines, Student interval on their "
        "spread). The tier's error against the study's counts is in the last table.",
        "",
        f"What it is fragile to: the gauge. With {gauge_label} the designed scheme's share outside the window "
        f"goes from {fmt_ci(*cell('nominal', designed.name)).split(' [')[0]} to "
        f"{cell(gauge_label, designed.name)[0]:.0f} ppm "
        f"({result.start}: {cell('nominal', result.start)[0]:.1f} to {cell(gauge_label, result.start)[0]:.0f} ppm): "
        "the readings err by a good part of a grade, and the study's plan, which aims shells made to order so "
        "that each grade's bin fills to its demand (`ShellSupply.aim_share`), fills the bins of little-used "
        "grades with shells aimed at their neighbours. The designer weighs the worst scenario in its objective.",
        "",
        "Done-when checks of issue 20 (95 % intervals as above):",
        "",
        f"- at most five shell grades: {len(designed.shell.labels)} — {'yes' if len(designed.shell.labels) <= 5 else 'no'}",
        f"- fewer bearings outside the window than every ISO scheme, intervals apart: "
        f"{'yes' if beats_nominal else 'no'}",
        f"- better under the worst declared scenario (its worst against each ISO scheme's worst, intervals apart): "
        f"{'yes' if beats_worst else 'no'}; better in every scenario, intervals apart: "
        f"{'yes' if beats_each else 'no'}",
        f"- design under a minute on 2 cores: {cpu:.1f} s of CPU time (one core; {wall:.1f} s wall on a machine "
        f"shared with other jobs, load average {load_before[0]:.1f} on {os.cpu_count()} cores) — "
        f"{'yes' if cpu < 60 else 'no'}",
        "",
        "## The designed scheme",
        "",
        f"Written to `{SCHEME_FILE}`; `stackup.schemes.load` reads it like a shipped scheme. Its comments:",
        "",
        "```text",
        *designed.notes,
        "```",
        "",
        "| dimension | grade | limits [mm] |",
        "|---|---|---|",
    ]
    for dim in ("housing", "journal", "shell"):
        for lab, (lo, hi) in designed.grades[dim].items():
            lines.append(f"| {dim} | {lab} | {lo * 1e3:.4f}–{hi * 1e3:.4f} |")
    lines += ["", "Pairing (upper+lower shell grade; rows journal grade, columns housing grade):", "",
              "| journal \\ housing | " + " | ".join(designed.housing.labels) + " |",
              "|---|" + "---|" * len(designed.housing.labels)]
    shell = designed.shell.labels
    for j, jl in enumerate(designed.journal.labels):
        lines.append(f"| {jl} | " + " | ".join(f"{shell[u]}+{shell[l]}" for u, l in designed.cell_pairs[j]) + " |")
    lines += [
        "",
        "## Validation: the study beside the ISO schemes",
        "",
        f"`stackup.Study` with {n:,} engines × {engine.main_bearings} bearings per scheme, seed {args.seed} (its "
        "own production lots and pilot; the design sample is another random stream), clearance stages; each "
        "declared scenario with the same seed. Share of the assembled bearings outside the window, ppm, with "
        "the 95 % interval; ranked by `stackup.rank` on the nominal run.",
        "",
        "| rank | scheme | " + " | ".join(labels) + " | worst scenario | stock-outs [ppm] | surplus [%] |",
        "|---|---|" + "---|" * (len(labels) + 3),
    ]
    for name in order:
        row = runs["nominal"].loc[name]
        lines.append(f"| {int(row['rank'])} | {name} | " + " | ".join(fmt_ci(*cell(lab, name)) for lab in labels)
                     + f" | {worst[name][0]} | {row['stockout_ppm']:.0f} | {row['surplus_pct']:.1f} |")
    lines += [
        "",
        "The misalignment scenario does not change the clearance (it moves bores and journals off the line, "
        "which the crankshaft stage sees): its column equals the nominal one, and the designer leaves it out.",
        "",
        "## Shell supply offered with the grades",
        "",
    ]
    if result.aim_share is not None:
        lines.append("Shells made to order (the engine's supply): share of each lot aimed at each grade centre, "
                     "as the plan aims them for the design's demand: "
                     + ", ".join(f"{lab} {q:.3f}" for lab, q in zip(shell, result.aim_share))
                     + f"; planned surplus {result.surplus.sum():.3f} and shortfall {result.shortfall.sum():.4f} "
                       "shells per bearing.")
        lines.append("")
    lines.append(f"One shell process sorted into the designed grades (`stackup.plan.optimise_supply`, the engine's "
                 f"sorted process): centre it at {result.supply_mean * 1e3:.5f} mm; surplus + 10 × shortfall "
                 f"{result.supply_mean_objective:.0f} shells per {design_mod.SUPPLY_VOLUME:,} engines against "
                 f"{result.supply_centred_objective:.0f} with the process centred on the grades.")
    lines += [
        "",
        "## The designer's estimate against the study",
        "",
        "The designer integrates the shells out (conditional Monte Carlo: each bearing contributes its "
        "probability of ending outside the window with the wall sums of the shells its pair's grades hold) and "
        "takes the operating clearance as linear in the wall sum (within 2 nm of `stackup.fit.press_fit` across "
        f"the window, tested). Here `outside_share` on {TIER_SAMPLES} independent samples of {TIER_ENGINES:,} "
        "engines per run (Student interval) against the study's count (Clopper–Pearson); ppm.",
        "",
        "| run | scheme | tier [95 %] | study count [95 %] | tier / study − 1 | intervals overlap | "
        "study stock-outs [ppm] |",
        "|---|---|---|---|---|---|---|",
    ]
    gaps = {}
    for label in labels:
        for name in order:
            study_ppm, ci = counted(label, name)
            t = tier[label][name]
            t_ppm, t_ci = t.outside * PPM, tuple(x * PPM for x in t.outside_interval)
            stock = runs[label].loc[name, "stockout_ppm"]
            overlap = t_ci[0] <= ci[1] and ci[0] <= t_ci[1]
            gaps[label, name] = (t_ppm / study_ppm - 1 if study_ppm else np.nan, study_ppm, stock, overlap)
            lines.append(f"| {label} | {name} | {fmt_ci(t_ppm, t_ci)} | {fmt_ci(study_ppm, ci)} | "
                         f"{gaps[label, name][0]:+.1%} | {'yes' if overlap else 'no'} | {stock:.0f} |")
    large = [g for g, share, stock, _ in gaps.values() if share >= 1000 and stock < 1000]
    stocked = [(key, g) for key, (g, share, stock, _) in gaps.items() if share >= 100 and stock >= 1000]
    small = [overlap for g, share, stock, overlap in gaps.values() if share < 1000 and stock < 1000]
    apart = [f"{lab}, {name}" for (lab, name), (g, share, stock, overlap) in gaps.items() if not overlap]
    lines += [
        "",
        f"Where the study counts at least 1000 ppm outside the window and has fewer than 1000 ppm stock-outs "
        f"({len(large)} cases), the tier is within {np.nanmax(np.abs(large)):.1%} of the study's count "
        f"(median {np.nanmedian(np.abs(large)):.1%}). Below 1000 ppm (and fewer than 1000 ppm stock-outs) the "
        f"tier's interval overlaps the count's in {sum(small)} of {len(small)} cases. Intervals apart: "
        + ("; ".join(apart) or "none") + ". "
        "Where the study's shells run out for more than 1000 ppm of the bearings, the study leaves those "
        "bearings out of its share while the tier counts them: "
        + ("; ".join(f"{lab}, {name}: {g:+.0%}" for (lab, name), g in stocked) or "no such case") + ". "
        "The other gaps are largest in the gauge scenario, where the bins hold shells aimed at several grades: "
        "the tier draws a bin's shells at random, the study takes them in production order, and a lot is "
        "made grade by grade, so the shells a bin has left over at the end of a lot (the planned surplus) are "
        "always those aimed at the later grades. The tier scores each cell's preferred pair, so the bearings "
        "an ISO scheme assembles with a substitute pair when a bin runs out (fewer than 1000 ppm of them "
        "nominally) are scored as if their preferred shells had been there.",
        "",
    ]
    lines += [
        "## How many shell grades",
        "",
        "Designs with the default options but 2 to 5 shell grades, scored on their design sample "
        "(share outside the window [ppm]; J adds a tenth of the worst scenario and the supply terms).",
        "",
        "| shell grades | nominal | worst scenario | J [ppm] | started from | wall [s] | CPU [s] |",
        "|---|---|---|---|---|---|---|",
    ]
    for k, r, w, c in counts:
        wl = max(list(r.outside)[1:], key=lambda lab: r.outside[lab])
        lines.append(f"| {k} | {r.outside['nominal'] * PPM:.2f} | {r.outside[wl] * PPM:.0f} ({wl}) | "
                     f"{r.objective * PPM:.1f} | {r.start} | {w:.1f} | {c:.1f} |")
    lines += [
        "",
        "## Methods and assumptions",
        "",
        "- Objective: J = P_out + 0.1 × (worst declared scenario's P_out) + 1e-5 × surplus + 1e-4 × shortfall "
        "(planned shells per bearing); `stackup.design.Weights` states the weights. The ISO scheme with the "
        "lowest J on the design sample is the start; its grades seed the search where the counts match.",
        "- Decision variables: housing and journal limits on a 0.1 µm grid, no grade narrower than a gauge "
        "reading of its centre stays inside with probability 0.5; contiguous shell grades, each at least as "
        "wide as holds half of the shells aimed at its centre (process σ and gauge); pairs of a grade with "
        "itself or the next grade (ISO 13778 intermediate pairs).",
        "- Solvers (scipy): differential evolution and exact line searches on the grid for the housing and "
        "journal limits (a whole population scored by prefix sums over the read-out grid); differential "
        "evolution and Nelder–Mead for the shell limits; HiGHS (`scipy.optimize.milp`) for the pairing with "
        "the worst scenario and the supply balance. One design sample (common random numbers) for all of it.",
        "- Shells made to order are aimed as the study aims them (`ShellSupply.aim_share` for each "
        "scenario's own demand), and every design is scored with the aims planned for the demand it makes.",
        f"- Shares from summaries: the study keeps per-scheme counts (`keep='summaries'`), {n:,} engines × "
        f"{engine.main_bearings} bearings per scheme and run, with Clopper–Pearson intervals; where it counts "
        f"fewer than {MIN_COUNTED} bearings outside the window the conditional tier's share and Student interval "
        f"({TIER_SAMPLES} independent samples of {TIER_ENGINES:,} engines) stand in, as in the verdict.",
        "",
    ]
    write_report("reports/design_scheme.md", lines)


if __name__ == "__main__":
    main()
