"""Benchmark: bearings per second for sample + measure + grade + pair + clearance, per scheme.

Each scheme's chain (draw the lot's blocks, crankshafts and shells, read them
with the gauges, grade, pair, take shells from stock, nominal clearance) is
timed on the same engines, beside the cost of only drawing the same number of
standard normal variates with numpy in the same run. Ratios, not seconds, are
the result: these machines are shared and noisy.

    python studies/bench_sampling.py [--engines 200000] [--repeat 3]

Writes reports/bench_sampling.md.
"""

from __future__ import annotations

import argparse
import time

from _common import best_time, environment, write_report

from stackup._random import PILOT_KEY, lot_generator, seed_sequence
from stackup.assembly import assemble, shell_demand
from stackup.engines import load_engine
from stackup.parts import draw_lot
from stackup.schemes import load
from stackup.study import ISO_SCHEMES, Study

#: Targets of the foundation issue: chain cost within these multiples of the raw draw.
TARGET = {name: (5.0 if name == "iso13778-6" else 3.0) for name in ISO_SCHEMES}


def chain(engine, scheme, aim, n_engines, seed):
    """The per-scheme chain a Study runs, lot by lot; returns (bearings, normals drawn)."""
    root = seed_sequence(seed)
    lot = engine.shell_wall.lot_engines
    bearings = normals = 0
    for k in range(-(-n_engines // lot)):
        m = min(lot, n_engines - k * lot)
        parts, shell_normals = draw_lot(engine, lot_generator(root, k), m)
        shells = engine.shell_wall.make(scheme, shell_normals, aim)
        result = assemble(scheme, parts, [shells], lot_engines=lot)
        bearings += result.clearance.size
        # blocks and cranks (2 per engine); bores and journals, true and gauge (4 per bearing);
        # shells: wall, gauge, crush (3 each); bore offset and journal eccentricity (4 per bearing)
        normals += 2 * m + 8 * parts.housing_bore.size + 3 * shell_normals.size.size
    return bearings, normals


def raw_draw(normals, lot_count, seed):
    """Draw the same number of standard normals, in as many generator calls per lot."""
    root = seed_sequence(seed)
    per_lot = -(-normals // lot_count)
    for k in range(lot_count):
        lot_generator(root, k).standard_normal(per_lot)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", type=int, default=200_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--out", default="reports/bench_sampling.md")
    args = parser.parse_args(argv)

    engine = load_engine("iso-example")
    pilot, _ = draw_lot(engine, lot_generator(seed_sequence(0), PILOT_KEY), 20_000)
    lots = -(-args.engines // engine.shell_wall.lot_engines)
    chain(engine, load("iso13778-4"), engine.shell_wall.aim_share(load("iso13778-4"), [1, 1, 1, 1, 1]), 2000, 0)  # compile

    rows = []
    for name in ISO_SCHEMES:
        scheme = load(name)
        aim = engine.shell_wall.aim_share(scheme, shell_demand(scheme, pilot))
        bearings, normals = chain(engine, scheme, aim, args.engines, 0)
        t_chain = best_time(lambda: chain(engine, scheme, aim, args.engines, 0), args.repeat)
        t_raw = best_time(lambda: raw_draw(normals, lots, 1), args.repeat)
        rows.append((name, bearings, normals / bearings, bearings / t_chain, bearings / t_raw, t_chain / t_raw, TARGET[name]))
        print(f"{name}: {bearings / t_chain / 1e6:.2f} M bearings/s, {t_chain / t_raw:.2f} x raw draw")

    study = Study(n_engines=args.engines // 4, mechanics_engines=0, progress=False)
    t0 = time.perf_counter()
    ds = study.run()
    t_study = time.perf_counter() - t0
    study_rate = ds.sizes["engine"] * ds.sizes["bearing"] * ds.sizes["scheme"] / t_study

    lines = [
        "# Benchmark: sampling, grading, pairing and clearance",
        "",
        f"{environment()}, one core (numpy and the numba kernel are single-threaded). "
        f"{args.engines:,} engines × {engine.main_bearings} bearings per scheme, best of {args.repeat}.",
        "",
        "The chain is what a study runs per scheme: draw the lot's blocks, crankshafts and shells, read them "
        "with the gauges, grade, pair, take shells from the per-grade stock bins, nominal clearance. "
        "The baseline draws the same number of standard normal variates with numpy (PCG64, one "
        "generator per lot as the chain uses) in the same run.",
        "",
        "| scheme | bearings | normals per bearing | chain [M bearings/s] | raw draw [M bearings/s] | chain / raw draw | target | met |",
        "|---|---|---|---|---|---|---|---|",
        *(f"| {n} | {b:,} | {v:.2f} | {c / 1e6:.2f} | {r / 1e6:.2f} | {x:.2f} | ≤ {t:.0f} | {'yes' if x <= t else 'no'} |"
          for n, b, v, c, r, x, t in rows),
        "",
        f"Whole study (`Study.run()` with the clearance stages: all six schemes, press fit, dataset assembly "
        f"with grade labels included, no crankshaft stage, "
        f"{study.n_engines:,} engines): {study_rate / 1e6:.2f} M bearing-scheme pairs/s.",
        "",
        "Reproduce: `python studies/bench_sampling.py`.",
    ]
    write_report(args.out, lines)


if __name__ == "__main__":
    main()
