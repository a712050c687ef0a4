"""Benchmark of the mechanical chain: one engine's crankshaft cycle, then its five dynamic films and lives.

One sampled engine of ``iso-example`` (misaligned bores and journals within
the drawing's coaxiality and run-out, each bearing at its own clearance):
the crankshaft on the bearing law over 720 crank angles
(``stackup.crank.cycle.engine_cycles``), the journals' tilt at the supports
(``stackup.crank.support_slopes``), the film stage of the study
(``stackup.film.cycle.bearing_films``: heat balance closed on the orbit, then
the orbit of the five main bearings) on each film method, and Levanov's
methods 1 and 2 - the study's ``mechanical_chain`` as a whole and stage by
stage. All on one thread, best of ``--repeat``, in one run, as ratios to the
crankshaft cycle alone (target: crank + films + lives within 4 times the
crank). Then the throughput of a batch of engines on one and on all threads.

    python studies/bench_chain.py [--repeat 7] [--engines 200]

Writes reports/bench_chain.md.
"""

from __future__ import annotations

import argparse
import os

import numba
import numpy as np
from _common import best_time, environment, write_report

from stackup.crank import support_slopes
from stackup.crank.cycle import engine_cycles
from stackup.engines import load_engine
from stackup.film.cycle import FILM_STATUS, bearing_films
from stackup.study.chain import mechanical_chain

TARGET_RATIO = 4.0
METHODS = ("mobility", "mobility-finite", "short", "finite")


def sample_engines(engine, n, rng):
    """Bore offsets and journal eccentricities (n, bearings, 2) within the drawing, and clearances (n, bearings)."""
    spec = engine.crank
    b = engine.main_bearings

    def disc(radius):
        r = radius * np.sqrt(rng.uniform(size=(n, b)))
        a = rng.uniform(0, 2 * np.pi, size=(n, b))
        return np.stack([r * np.cos(a), r * np.sin(a)], axis=-1)

    lo, hi = engine.clearance_window
    return disc(spec.coaxiality / 2), disc(spec.journal_runout / 2), rng.uniform(lo, hi, size=(n, b))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--engines", type=int, default=200)
    parser.add_argument("--out", default="reports/bench_chain.md")
    args = parser.parse_args(argv)

    engine = load_engine("iso-example")
    spec = engine.crank
    angle = np.arange(720.0)
    rng = np.random.default_rng(16)
    bore, journal, clearance = sample_engines(engine, args.engines, rng)
    journal_d = np.full(clearance.shape, 0.5 * (engine.journal_d.lo + engine.journal_d.hi))

    def chain(method, rows=slice(0, 1)):
        return mechanical_chain(engine, clearance=clearance[rows], journal_d=journal_d[rows],
                                bore_offset=bore[rows], journal_eccentricity=journal[rows], crank_angle=angle,
                                crank_method="bearing-law", film_method=method)

    numba.set_num_threads(1)
    for method in METHODS:
        chain(method)  # compile and warm up
    r = engine_cycles(spec, bore_offset=bore[:1], journal_eccentricity=journal[:1], clearance=clearance[:1],
                      crank_angle=angle)
    pins = spec.pin_loads(angle)[None]
    tilt = support_slopes(pins, r.displacements, spans=spec.spans, EI=spec.ei)
    t = {"crank": best_time(lambda: engine_cycles(spec, bore_offset=bore[:1], journal_eccentricity=journal[:1],
                                                  clearance=clearance[:1], crank_angle=angle), args.repeat),
         "tilt": best_time(lambda: support_slopes(pins, r.displacements, spans=spec.spans, EI=spec.ei), args.repeat)}
    for method in METHODS:
        t["film " + method] = best_time(lambda m=method: bearing_films(
            spec, engine.oil_feed, r.reactions, angle, clearance=clearance[:1], journal_d=journal_d[:1], method=m,
            tilt=tilt), args.repeat)
        t["chain " + method] = best_time(lambda m=method: chain(m), args.repeat)
    one = {m: chain(m) for m in METHODS}

    t_batch = {}
    for threads in sorted({1, numba.config.NUMBA_NUM_THREADS}):
        numba.set_num_threads(threads)
        t_batch[threads] = best_time(lambda: chain("mobility-finite", slice(None)), 2)
    batch = chain("mobility-finite", slice(None))

    crank = t["crank"]
    rows = []
    for method in METHODS:
        whole = t["chain " + method]
        lives = whole - crank - t["tilt"] - t["film " + method]
        rows.append(f"| {method} | {1e3 * t['film ' + method] / engine.main_bearings:.2f} | {1e3 * whole:.1f} | "
                    f"{whole / crank:.2f} | {'met' if whole / crank <= TARGET_RATIO else 'NOT met'} | "
                    f"{1e3 * lives:.1f} |")
    status = np.bincount(batch["film_status"].ravel(), minlength=len(FILM_STATUS))
    hm = one["mobility-finite"]
    lines = [
        "# Benchmark: crankshaft, films and lives of one engine",
        "",
        f"{environment()}, {os.cpu_count()} cores. Engine `iso-example`, 720 crank angles, one sampled engine "
        "(bores and journals misaligned within the drawing's coaxiality and run-out, each bearing at its own "
        f"clearance in the {1e6 * engine.clearance_window[0]:.0f}-{1e6 * engine.clearance_window[1]:.0f} µm "
        f"window). One thread, best of {args.repeat}, every stage timed in this run (the machine is shared: "
        "ratios within the run are what counts).",
        "",
        "## One engine: the study's mechanical chain against the crankshaft cycle alone",
        "",
        f"Crankshaft cycle on the bearing law (`engine_cycles`): {1e3 * crank:.2f} ms; journals' tilt at the "
        f"supports (`support_slopes`): {1e3 * t['tilt']:.2f} ms. The film stage (`bearing_films`: heat balance "
        "closed on the film, five bearings' films) per film method, and the whole `mechanical_chain` (crank, tilt, "
        f"films, Levanov's methods 1 and 2) against the crank alone (target ≤ {TARGET_RATIO:.0f}):",
        "",
        "| film method | film stage per bearing [ms] | whole chain [ms] | ratio to the crank | target | "
        "lives and the rest [ms] |",
        "|---|---|---|---|---|---|",
        *rows,
        "",
        "`short` and `finite` are the quasi-static tiers (each crank angle a steady load, their heat balance "
        "quasi-static too); `mobility` and `mobility-finite` the dynamic ones, whose heat balance runs two or "
        "three orbits on every 4th crank angle before the full one.",
        "",
        "That engine on `mobility-finite`: cycle-minimum film "
        f"{', '.join(f'{1e6 * h:.2f}' for h in hm['h_min'][0])} µm, cycle mean "
        f"{', '.join(f'{1e6 * h:.2f}' for h in hm['h_min_mean'][0])} µm, effective temperature "
        f"{', '.join(f'{x:.1f}' for x in hm['film_temperature'][0])} °C; edge film with the beam's tilt "
        f"{', '.join(f'{1e6 * h:.2f}' for h in hm['h_min_edge'][0])} µm (largest tilt "
        f"{', '.join(f'{1e3 * x:.2f}' for x in hm['tilt_max'][0])} mrad).",
        "",
        "## Batch throughput (whole chain, `mobility-finite`)",
        "",
        "| threads | engine chains per second |",
        "|---|---|",
        *(f"| {k} | {args.engines / v:,.0f} |" for k, v in t_batch.items()),
        "",
        f"Over the {args.engines} engines: film status counts ({', '.join(FILM_STATUS)}) = {status.tolist()}; "
        f"median life (method 1, cycle-mean film) {np.median(batch['life']) / 3600:,.0f} h. The edge contacts "
        "come from the tilt the beam's free support rotation gives: the bearing's moment restraint is not in the "
        "beam model, so that tilt is an upper bound (see reports/film_speed_vs_error.md).",
        "",
        "Reproduce: `python studies/bench_chain.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
