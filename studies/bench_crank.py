"""Benchmark of the crankshaft stage: one engine cycle, batch throughput, and the error of cheaper tiers.

One engine's full 720-step cycle on the bearing law (one thread), against the
cheapest tier (rigid supports, a matrix product per angle) in the same run
and against the 20 s Bellakhdhar et al. report for their simulation; batch
throughput in engine-cycles per second on one and on all cores; and the
error of rigid supports and linear springs against the law on the same
sampled engines (operating clearances and misalignment from a study).

    python studies/bench_crank.py [--engines 400] [--repeat 7]

Writes reports/bench_crank.md.
"""

from __future__ import annotations

import argparse
import os
import time

import numba
import numpy as np
from _common import best_time, environment, write_report

from stackup.crank import reactions
from stackup.crank.cycle import engine_cycles
from stackup.engines import load_engine
from stackup.study import Study

PAPER_SECONDS = 20.0  # Bellakhdhar et al. 2013, sec. 6.1: one full cycle
TARGET_SECONDS = 2e-3


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", type=int, default=400)
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--out", default="reports/bench_crank.md")
    args = parser.parse_args(argv)

    engine = load_engine("iso-example")
    spec = engine.crank
    angle = np.arange(720.0)
    ds = Study(schemes=("iso13778-4",), n_engines=args.engines, mechanics_engines=0, progress=False).run()
    d = ds.sel(scheme="iso13778-4")
    ok = np.all(d.status.values == 0, axis=1)
    bore = d.bore_offset.values[ok]
    ecc = d.journal_eccentricity.values[ok]
    clearance = d.clearance_operating.values[ok]
    n = bore.shape[0]

    t0 = time.perf_counter()
    loads = spec.pin_loads(angle)[None]  # once per engine type, shared by every sampled engine
    t_loads = time.perf_counter() - t0
    offsets = spec.offsets(bore[:1], ecc[:1], angle)
    law_one = spec.law(clearance[:1, None, :])

    def one():
        return reactions(loads, spans=spec.spans, EI=spec.ei, offsets=offsets, law=law_one)

    numba.set_num_threads(1)
    t_law = best_time(one, args.repeat)
    t_rigid = best_time(lambda: reactions(loads, spans=spec.spans, EI=spec.ei, offsets=offsets), args.repeat)
    t_linear = best_time(lambda: reactions(loads, spans=spec.spans, EI=spec.ei, offsets=offsets, law=0.98e9), args.repeat)
    iterations = one().iterations.mean()

    def batch():
        return engine_cycles(spec, bore_offset=bore, journal_eccentricity=ecc, clearance=clearance, crank_angle=angle)

    t_batch_1 = best_time(batch, 3)
    cores = numba.config.NUMBA_NUM_THREADS
    numba.set_num_threads(cores)
    t_batch_all = best_time(batch, 3)

    law = batch()
    assert law.converged.all()
    peak_law = np.linalg.norm(law.reactions, axis=-1).max(axis=1)
    offsets_all = spec.offsets(bore, ecc, angle)
    tiers = {}
    for name, tier in (("rigid supports", None), ("linear springs k_lv", 0.98e9), ("linear springs k_hv", 1.72e9)):
        r = reactions(loads, spans=spec.spans, EI=spec.ei, offsets=offsets_all, law=tier)
        peak = np.linalg.norm(r.reactions, axis=-1).max(axis=1)
        hist = np.linalg.norm(r.reactions - law.reactions, axis=-1).max(axis=1) / peak_law
        tiers[name] = (np.abs(peak / peak_law - 1).mean(), np.abs(peak / peak_law - 1).max(), hist.mean(), hist.max())

    lines = [
        "# Benchmark: crankshaft beam on nonlinear main bearings",
        "",
        f"{environment()}, {os.cpu_count()} cores. Engine `iso-example` (inline four, "
        f"4000 rpm), 720 crank angles, Bellakhdhar bearing law with each bearing's operating clearance and "
        f"sampled misalignment (coaxiality {spec.coaxiality * 1e6:.0f} µm, run-out {spec.journal_runout * 1e6:.0f} µm) "
        f"of {n} engines assembled with iso13778-4. Best of {args.repeat}.",
        "",
        "## One engine, one thread",
        "",
        "| tier | time per 720-step cycle [ms] | ratio to rigid supports |",
        "|---|---|---|",
        f"| bearing law (Newton, {iterations:.2f} iterations per angle) | {1e3 * t_law:.2f} | {t_law / t_rigid:.1f} |",
        f"| linear springs | {1e3 * t_linear:.2f} | {t_linear / t_rigid:.1f} |",
        f"| rigid supports | {1e3 * t_rigid:.2f} | 1.0 |",
        "",
        f"Times are `stackup.crank.reactions` calls (validation included) with the cycle's pin loads given, "
        f"as in the paper; computing the loads from the pressure model takes {1e3 * t_loads:.1f} ms once per "
        "engine type.",
        "",
        f"Against the {PAPER_SECONDS:.0f} s Bellakhdhar et al. report for one cycle: {PAPER_SECONDS / t_law:,.0f}× faster "
        f"(target ≥ 10,000×, i.e. ≤ {1e3 * TARGET_SECONDS:.0f} ms: {'met' if t_law <= TARGET_SECONDS else 'NOT met'}). "
        "Their figure is from another machine and code; the ratio to rigid supports is measured in this run.",
        "",
        "## Batch throughput",
        "",
        "| threads | engine-cycles per second |",
        "|---|---|",
        f"| 1 | {n / t_batch_1:,.0f} |",
        f"| {cores} | {n / t_batch_all:,.0f} |",
        "",
        "## Error of the cheaper tiers against the bearing law (same engines)",
        "",
        "Cycle-maximum load per bearing (relative error), and the largest difference of the load vector over "
        "the cycle relative to the cycle maximum; mean and worst over engines and bearings.",
        "",
        "| tier | max load: mean error | max load: worst error | load history: mean | load history: worst |",
        "|---|---|---|---|---|",
        *(f"| {k} | {100 * v[0]:.1f} % | {100 * v[1]:.1f} % | {100 * v[2]:.1f} % | {100 * v[3]:.1f} % |" for k, v in tiers.items()),
        "",
        "Reproduce: `python studies/bench_crank.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
