"""Monte Carlo error against sample size and time: MC against scrambled Sobol (QMC).

For scheme iso13778-4 on the example engine (clearance stages), each
estimator is run with 10 independent seeds at each size; the error is the
spread of the estimates over seeds (all estimators are unbiased), set beside
the 95 % interval a single run reports for itself, and the mean run time.

    python studies/convergence.py

Writes reports/convergence.md.
"""

from __future__ import annotations

import time

import numpy as np
from _common import environment, write_report

import stackup
from stackup.stats import proportion_ci

SIZES = (1000, 4000, 16000, 64000)
SEEDS = 10
SCHEME = "iso13778-4"


def run(n, seed, sampler):
    t0 = time.perf_counter()
    ds = stackup.Study(n_engines=n, schemes=(SCHEME,), mechanics_engines=0, pilot_engines=20_000, seed=seed,
                       sampler=sampler, progress=False).run()
    elapsed = time.perf_counter() - t0
    d = ds.sel(scheme=SCHEME)
    c = d.clearance_operating.values[d.status.values == 0]
    lo, hi = ds.clearance_window.values
    k = int(np.count_nonzero((c < lo) | (c > hi)))
    share, s_lo, s_hi = proportion_ci(k, c.size)
    return {"mean_um": c.mean() * 1e6, "std_um": c.std(ddof=1) * 1e6, "outside_ppm": share * 1e6,
            "outside_ci_half_ppm": 0.5 * (s_hi - s_lo) * 1e6, "mean_ci_half_um": 1.96 * c.std(ddof=1) / np.sqrt(c.size) * 1e6,
            "time_s": elapsed}


def main():
    rows = []
    for n in SIZES:
        for sampler in ("mc", "qmc"):
            runs = [run(n, seed, sampler) for seed in range(SEEDS)]
            col = {k: np.array([r[k] for r in runs]) for k in runs[0]}
            rows.append((n, sampler, col))
            print(n, sampler, col["mean_um"].std(ddof=1), col["outside_ppm"].std(ddof=1), col["time_s"].mean())
    lines = [
        "# Convergence: Monte Carlo against randomised QMC",
        "",
        f"{environment()}. Scheme {SCHEME}, example engine, clearance stages (no crankshaft stage), "
        f"{SEEDS} seeds per size. Error = standard deviation of the estimate over seeds; 'CI half' = the 95 % "
        "half-width one run reports for itself (for MC it should be about 1.96 × the error).",
        "",
        "| engines | sampler | mean clearance: error [µm] | CI half [µm] | ppm outside window: estimate | error [ppm] | CI half [ppm] | time per run [s] |",
        "|---|---|---|---|---|---|---|---|",
        *(f"| {n:,} | {s} | {c['mean_um'].std(ddof=1):.4f} | {c['mean_ci_half_um'].mean():.4f} | "
          f"{c['outside_ppm'].mean():,.0f} | {c['outside_ppm'].std(ddof=1):,.0f} | {c['outside_ci_half_ppm'].mean():,.0f} | "
          f"{c['time_s'].mean():.2f} |" for n, s, c in rows),
        "",
    ]
    mc = {n: c for n, s, c in rows if s == "mc"}
    q = {n: c for n, s, c in rows if s == "qmc"}
    ratio = [mc[n]["mean_um"].var(ddof=1) / q[n]["mean_um"].var(ddof=1) for n in SIZES]
    slope_mc = np.polyfit(np.log(SIZES), np.log([mc[n]["mean_um"].std(ddof=1) for n in SIZES]), 1)[0]
    slope_q = np.polyfit(np.log(SIZES), np.log([q[n]["mean_um"].std(ddof=1) for n in SIZES]), 1)[0]
    lines += [
        f"Variance ratio MC/QMC of the mean clearance: {', '.join(f'{r:.1f}' for r in ratio)} at "
        f"{', '.join(f'{n:,}' for n in SIZES)} engines; error ∝ n^{slope_mc:.2f} (MC) and n^{slope_q:.2f} (QMC). "
        f"With {SEEDS} seeds each error is known to about ±25 %, so ratios near 1 mean no measurable gain. "
        "QMC here covers the block and crankshaft parts only: the shell walls (about 40 % of the clearance "
        "variance of this scheme) and their assignment from stock stay pseudo-random, each lot of 1000 "
        "engines is an independent scramble, and grading makes the clearance discontinuous in the inputs. "
        "The measured outcome is what a user should expect from `sampler='qmc'` on this pipeline: little or no "
        "gain; plain MC with its reported intervals is the default.",
        "",
    ]
    lines += [
        "The ppm tails by generalized splitting and cross-entropy importance sampling, against plain Monte Carlo "
        "and an established reliability library, are in `reports/tails_vs_peers.md`.",
        "",
        "Reproduce: `python studies/convergence.py`.",
    ]
    write_report("reports/convergence.md", lines)


if __name__ == "__main__":
    main()
