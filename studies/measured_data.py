"""Measured data in: fit the (synthetic) measurements, write the engine file, compare schemes on it.

Reads the SYNTHETIC measurement files of ``studies/data/`` (made by
``studies/make_measured_data.py`` from stated true processes) for the ISO
13778 example engine's drawing, and

1. fits the housing bores (per block), journals (per crankshaft) and crush
   heights (in order of manufacture) with :func:`stackup.measure.fit_csv`, and
   the housing's outer diameter to the fitting tests with
   :func:`stackup.measure.calibrate_housing`;
2. writes a copy of the example engine file with the fitted entries, and
   two more with the housing's outer diameter at the ends of its interval;
3. compares the ISO schemes on the measured engine against the assumed one
   (``stackup.compare``, the declared scenarios), and at the interval's ends
   (the model-uncertainty check with the measured interval);
4. measures how often the fits' 95 % intervals hold the truth (Cpk, shared
   share, housing diameter) over seeds of synthetic data, and how often the
   true model is chosen.

    python studies/measured_data.py [--seeds 200] [--engines 20000]

Writes reports/measured_data.md, its figures and engine files in reports/measured_data/, and keeps the
coverage's per-seed records in reports/measured_data/coverage/ (``--coverage-only`` fills them alone; a run
that stops goes on from them).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
from _common import environment, write_report

import stackup
from stackup.measure import calibrate_housing, fit_csv, write_engine
from stackup.measure.coverage import (BORE_LIMITS, GAUGE, GROUPS, PER_GROUP, SHARED, TRUE_PROCESSES, choice_rate,
                                      coverage, synthetic_fitting_tests)
from stackup.tolerances import quantile_cpk

DATA = Path(__file__).parent / "data"
ROOT = Path(__file__).parent.parent
OUT = ROOT / "reports" / "measured_data"
REPORT = ROOT / "reports" / "measured_data.md"
#: Per-seed coverage records (the study's slowest part), kept so that a run can stop and go on.
COVERAGE_CACHE = OUT / "coverage"
#: The files, their column, drawing limits [mm], gauge repeatability [mm], group and sequence columns, and the
#: engine file table each fit goes into.
FILES = (
    ("synthetic_housing_bores.csv", "housing_bore", (50.000, 50.018), 0.0005, "block", None, "housing_bore"),
    ("synthetic_journals.csv", "journal_d", (46.000, 46.018), 0.0005, "crankshaft", None, "journal_d"),
    ("synthetic_crush_heights.csv", "crush_height", (0.065, 0.090), 0.001, None, "sequence", "crush_height"),
)
TESTS = "synthetic_fitting_tests.csv"
CASES = (("normal", True), ("skew-normal", True), ("mixture", True), ("normal", False), ("drift", False))
CHOICE_SIZES = (100, 200, 300, 500)
HOUSING_TESTS = (5, 10, 20, 40)


def fit_files():
    fits = {}
    for name, column, limits, r, group, sequence, _ in FILES:
        fit = fit_csv(DATA / name, column, limits=limits, gauge_repeatability=r, group=group, sequence=sequence)
        fit.figure(label=column).savefig(OUT / f"{column}.png", dpi=100)
        fits[column] = fit
    return fits, calibrate_housing(DATA / TESTS, "iso-example")


def write_engines(fits, housing):
    changes = [c for (_, column, *_rest, table) in FILES for c in fits[column].entries(table)]
    paths = {"estimate": write_engine("iso-example", OUT / "iso-example-measured.toml",
                                      changes + [housing.entry("estimate")], name="iso-example-measured", force=True)}
    for end in ("lower", "upper"):
        if np.isfinite(housing.value(end) if end == "lower" else housing.housing_outer_ci[1]):
            paths[end] = write_engine("iso-example", OUT / f"iso-example-measured-outer-{end}.toml",
                                      changes + [housing.entry(end)], name=f"iso-example-measured-outer-{end}",
                                      force=True)
    return paths


def ranking(engine, n, scenarios=True):
    kwargs = {} if scenarios else {"scenarios": {}}
    result = stackup.compare(engine=str(engine), n_engines=n, design=None, progress=False, **kwargs)
    return stackup.rank(result.dataset, scenarios=result.scenarios or None, tails=result.tails)


def comparison_lines(tables):
    lines = ["| engine | " + " | ".join(f"{s} rank" for s in tables["assumed"].index.sort_values()) + " |",
             "|---|" + "---|" * len(tables["assumed"].index)]
    for label, table in tables.items():
        lines.append(f"| {label} | " + " | ".join(
            f"{int(table.loc[s, 'rank'])} ({table.loc[s, 'clearance_mean_um']:.1f} ± "
            f"{table.loc[s, 'clearance_std_um']:.1f} µm, {table.loc[s, 'outside_window_ppm']:.0f} ppm out)"
            for s in tables["assumed"].index.sort_values()) + " |")
    return lines


def fit_lines(fits, housing):
    lines = ["| dimension | model | process entry (mm) | Cpk (95 % interval) | shared (95 % interval) | "
             "Anderson-Darling p |", "|---|---|---|---|---|---|"]
    for column, fit in fits.items():
        shared = "—" if fit.shared is None else f"{fit.shared:.3f} ({fit.shared_ci[0]:.3f}-{fit.shared_ci[1]:.3f})"
        entry = fit.to_toml().splitlines()[-1 if fit.shared is None else -3].removeprefix("process = ")
        lines.append(f"| {column} | {fit.model} | `{entry}` | {fit.cpk:.2f} ({fit.cpk_ci[0]:.2f}-{fit.cpk_ci[1]:.2f})"
                     f" | {shared} | {fit.goodness_of_fit.p_value:.2f} |")
    lo, hi = housing.housing_outer_ci
    lines += ["", f"Housing: `housing_outer = {housing.housing_outer * 1e3:.1f}` mm, 95 % profile-likelihood interval "
              f"{lo * 1e3:.1f}-{hi * 1e3:.1f} mm from {housing.n_tests} fitting tests (residuals "
              f"{housing.residual_sigma * 1e6:.2f} µm; the engine file assumed {housing.assumed_outer * 1e3:.0f} mm; "
              f"the synthetic truth is 75 mm, {'inside' if lo <= 75e-3 <= hi else 'outside'} this interval: one "
              "sample, which a 95 % interval misses one time in twenty; the share over seeds is under *Coverage*)."]
    return lines


def seed_record(case, grouped, seed):
    """One seed of a coverage case: did the Cpk (and shared) interval hold the truth, its width, the model."""
    r = coverage(case, 1, grouped=grouped, first_seed=seed)
    return {"cpk": r.cpk_hits, "shared": r.shared_hits, "width": r.mean_cpk_width, "model": next(iter(r.chosen))}


def cached_coverage(case, grouped, seeds, *, stored_only=False):
    """Records of seeds 0 .. seeds-1 of a case, computed where ``COVERAGE_CACHE`` lacks them (so a long run can stop
    and go on: every seed is deterministic); the cache is rewritten after every seed. ``stored_only``: the stored
    seeds 0 .. k-1 only (k <= seeds), none computed."""
    path = COVERAGE_CACHE / f"{case}-{'groups' if grouped else 'none'}.json"
    records = json.loads(path.read_text()) if path.exists() else {}
    if stored_only:
        seeds = next((k for k in range(seeds) if str(k) not in records), seeds)
    for seed in range(seeds):
        if str(seed) not in records:
            records[str(seed)] = seed_record(case, grouped, seed)
            COVERAGE_CACHE.mkdir(parents=True, exist_ok=True)
            path.write_text(json.dumps(records, indent=0))
    return [records[str(seed)] for seed in range(seeds)]


def coverage_lines(seeds, stored_only=False):
    lines = [f"| true process | groups | seeds | Cpk interval holds the truth | shared interval holds {SHARED} | "
             "model chosen | mean Cpk interval width |", "|---|---|---|---|---|---|---|"]
    short = False
    for case, grouped in CASES:
        records = cached_coverage(case, grouped, seeds, stored_only=stored_only)
        n = len(records)
        short |= n < seeds
        if not n:
            continue
        cpk_hits = sum(r["cpk"] for r in records)
        shared_hits = sum(r["shared"] for r in records) if grouped else None
        chosen = {}
        for r in records:
            chosen[r["model"]] = chosen.get(r["model"], 0) + 1
        truth = quantile_cpk(TRUE_PROCESSES[case], *BORE_LIMITS)
        shared = "—" if shared_hits is None else f"{shared_hits}/{n} ({shared_hits / n:.1%})"
        chosen = ", ".join(f"{k} {v}" for k, v in sorted(chosen.items(), key=lambda kv: -kv[1]))
        lines.append(f"| {case} (Cpk {truth:.3f}) | {f'{GROUPS} x {PER_GROUP}' if grouped else 'none'} | "
                     f"{n} | {cpk_hits}/{n} ({cpk_hits / n:.1%}) | {shared} | {chosen} | "
                     f"{np.mean([r['width'] for r in records]):.3f} |")
    if short:
        lines += ["", f"Cases with fewer than {seeds} seeds (or missing) were still running when this report was "
                  "written (`--stored-coverage`); `python studies/measured_data.py` goes on from the stored seeds."]
    return lines


def choice_lines(seeds):
    lines = ["| true process | " + " | ".join(f"n = {n}" for n in CHOICE_SIZES) + " |",
             "|---|" + "---|" * len(CHOICE_SIZES)]
    for case in ("normal", "skew-normal", "mixture", "drift"):
        lines.append(f"| {case} | " + " | ".join(f"{choice_rate(case, n, seeds):.0%}" for n in CHOICE_SIZES) + " |")
    return lines


def housing_lines(seeds):
    widths, hits = [], {}
    for n in HOUSING_TESTS:
        count, width = 0, []
        for seed in range(seeds):
            table = synthetic_fitting_tests(n, 75e-3, np.random.default_rng([seed, 37]))
            lo, hi = calibrate_housing(table, "iso-example").housing_outer_ci
            count += lo <= 75e-3 <= hi
            width.append(hi - lo)
        hits[n] = count
        widths.append(np.mean(width))
    return ["| fitting tests | " + " | ".join(str(n) for n in HOUSING_TESTS) + " |",
            "|---|" + "---|" * len(HOUSING_TESTS),
            "| interval holds 75 mm | " + " | ".join(f"{hits[n]}/{seeds} ({hits[n] / seeds:.1%})"
                                                  for n in HOUSING_TESTS) + " |",
            "| mean interval width | " + " | ".join(f"{w * 1e3:.1f} mm" for w in widths) + " |"]


def truth_lines():
    out = []
    for case, process in TRUE_PROCESSES.items():
        out.append(f"- {case}: `{process}` (m)")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=200, help="seeds of each coverage case (default 200)")
    parser.add_argument("--engines", type=int, default=20_000, help="engines of each comparison (default 20000)")
    parser.add_argument("--choice-seeds", type=int, help="seeds of each model-choice cell (default seeds / 2, "
                        "at least 50)")
    parser.add_argument("--housing-seeds", type=int, help="seeds of each housing cell (default seeds)")
    parser.add_argument("--coverage-only", action="store_true", help="only fill the per-seed coverage records "
                        f"({COVERAGE_CACHE.relative_to(ROOT)}); no report")
    parser.add_argument("--stored-coverage", action="store_true", help="report the coverage seeds stored so far "
                        "(up to --seeds) instead of computing the missing ones")
    parser.add_argument("--cases", nargs="+", choices=sorted(TRUE_PROCESSES), help="with --coverage-only: these "
                        "true processes only (to fill them in separate processes)")
    args = parser.parse_args()
    args.choice_seeds = args.choice_seeds or max(50, args.seeds // 2)
    args.housing_seeds = args.housing_seeds or args.seeds
    OUT.mkdir(parents=True, exist_ok=True)
    if args.coverage_only:
        for case, grouped in (c for c in CASES if not args.cases or c[0] in args.cases):
            cached_coverage(case, grouped, args.seeds)
            print(f"coverage {case} ({'groups' if grouped else 'none'}): {args.seeds} seeds", flush=True)
        return
    t0 = time.perf_counter()
    fits, housing = fit_files()
    engines = write_engines(fits, housing)
    print(f"fits and engine files: {time.perf_counter() - t0:.0f} s")
    tables = {"assumed": ranking("iso-example", args.engines), "measured": ranking(engines["estimate"], args.engines)}
    for end in ("lower", "upper"):
        if end in engines:
            tables[f"measured, housing_outer at the {end} end"] = ranking(engines[end], args.engines, scenarios=False)
    print(f"comparisons: {time.perf_counter() - t0:.0f} s")
    cover = coverage_lines(args.seeds, args.stored_coverage)
    choice = choice_lines(args.choice_seeds)
    house = housing_lines(args.housing_seeds)
    print(f"coverage: {time.perf_counter() - t0:.0f} s")
    write_report(REPORT, report(fits, housing, engines, tables, cover, choice, house, args))


def report(fits, housing, engines, tables, cover, choice, house, args):
    measured, assumed = tables["measured"], tables["assumed"]
    best = lambda t: ", ".join(t.index[t["rank"] == t["rank"].min()])  # noqa: E731
    return [
        "# Measured data in: processes and housing stiffness from measurements",
        "",
        "Generated by `studies/measured_data.py`; do not edit by hand. The measurements are SYNTHETIC "
        "(`studies/data/`, made by `studies/make_measured_data.py` from stated true processes), laid on the ISO "
        "13778 example engine's drawing.",
        "",
        "## Verdict",
        "",
        f"On the measured engine the best scheme{'s are' if ',' in best(measured) else ' is'} {best(measured)}; on "
        f"the assumed engine (normal processes of Cpk 1.33, housing ring of 90 mm) {best(assumed)}. The "
        "measured processes are not normal (two boring machines, skewed grinding, a drifting crush height) and the "
        f"housing is softer than assumed ({housing.housing_outer * 1e3:.1f} mm): the tables below give what that "
        "changes. The stated 95 % intervals held the truth in the shares measured under *Coverage*.",
        "",
        "## The fits",
        "",
        *fit_lines(fits, housing),
        "",
        "Figures (histogram with the fitted densities, normal probability plot): "
        + ", ".join(f"`reports/measured_data/{c}.png`" for c in fits) + ".",
        f"Engine files written: {', '.join(f'`{Path(p).relative_to(ROOT)}`' for p in engines.values())}.",
        "",
        f"## Schemes on the measured engine ({args.engines:,} engines, seed 0)",
        "",
        "Rank (clearance mean ± standard deviation, share outside the window). The interval-end rows run without "
        "the declared scenarios: they are the model-uncertainty check with the measured interval of the housing's "
        "outer diameter instead of an assumed range.",
        "",
        *comparison_lines(tables),
        "",
        "## Coverage",
        "",
        f"Synthetic housing bores (drawing {BORE_LIMITS[0] * 1e3:.3f}-{BORE_LIMITS[1] * 1e3:.3f} mm) from these true "
        f"processes, read with a gauge of repeatability {GAUGE.repeatability * 1e6:g} µm and read-out "
        f"{GAUGE.resolution * 1e6:g} µm; grouped samples are {GROUPS} blocks x {PER_GROUP} bores with shared "
        f"share {SHARED}; samples without groups have {GROUPS * PER_GROUP} bores (the drift in order of manufacture).",
        "",
        *truth_lines(),
        "",
        *cover,
        "",
        f"Share of samples (without groups, {args.choice_seeds} seeds) whose least-BIC model is the true one:",
        "",
        *choice,
        "",
        f"Housing calibration on synthetic fitting tests (`stackup.fit.press_fit` at 75 mm plus gauge noise), "
        f"{args.housing_seeds} seeds:",
        "",
        *house,
        "",
        "## Methods",
        "",
        "Model choice by BIC, goodness of fit by Anderson-Darling with a parametric bootstrap, gauge removed per "
        "model, Cpk by the ISO 22514-2 quantile form with a percentile bootstrap interval (whole groups resampled, "
        "every candidate refitted and the model chosen again in each resample), shared share by one-way ANOVA of "
        "normal scores with Searle's interval: `stackup/measure/process.py` and `stackup/measure/shared.py`. "
        "Housing: least squares through `stackup.fit.press_fit`, profile-likelihood interval: "
        "`stackup/measure/housing.py`.",
        "",
        "Why the model is chosen again in each resample (development trials, not rerun by this study: the "
        "skew-normal case above, 120 seeds, 1000 resamples): with 60 blocks x 5 bores the Cpk interval held the "
        "truth in 106/120 seeds when only the chosen model was refitted (percentile), 105/120 with BCa, 110/120 "
        "with the model chosen again; with 100 blocks x 5 bores 107, 105 and 110 of 120. The misses that remain "
        "are mostly samples whose skewness reads low (Cpk read high) or whose least-BIC model is the normal.",
        "",
        f"Environment: {environment()}.",
    ]


if __name__ == "__main__":
    main()
