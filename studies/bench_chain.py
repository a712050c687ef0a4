"""Benchmark of the mechanical chain: one engine's crankshaft cycle, then its five dynamic films and lives.

One sampled engine of ``iso-example`` (misaligned bores and journals within
the drawing's coaxiality and run-out, each bearing at its own clearance):
the crankshaft on the bearing law over 720 crank angles
(``stackup.crank.cycle.engine_cycles``), the journals' tilt at the supports
(``stackup.crank.support_slopes``), each bearing's effective viscosity
(isothermal heat balance), the orbit of the five main bearings on each dynamic
tier and Levanov's method 1 on the cycle mean of the minimum film. All on one
thread, best of ``--repeat``, in one run, as ratios to the crankshaft cycle
alone (target: crank + films + lives within 4 times the crank). Then the
throughput of a batch of engines on one and on all threads.

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
from stackup.film import oil as oils
from stackup.film import tiers
from stackup.film.orbit import orbit
from stackup.life import levanov_method1

TARGET_RATIO = 4.0
TIERS = ("mobility", "mobility-finite", "quasi-static-short", "quasi-static-finite")


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


class Chain:
    """The mechanical chain of engines, stage by stage (each a method, so the benchmark can time them apart)."""

    def __init__(self, engine, bore, journal, clearance, angle):
        self.engine, self.spec = engine, engine.crank
        self.bore, self.journal, self.clearance, self.angle = bore, journal, clearance, angle
        self.pins = self.spec.pin_loads(angle)[None]  # once per engine type
        self.diameter = 0.5 * (engine.journal_d.lo + engine.journal_d.hi)

    def crank(self):
        self.r = engine_cycles(self.spec, bore_offset=self.bore, journal_eccentricity=self.journal,
                               clearance=self.clearance, crank_angle=self.angle)
        self.loads = np.moveaxis(self.r.reactions, 1, 2)  # (n, bearings, angles, 2)

    def tilt(self):
        slopes = support_slopes(self.pins, self.r.displacements, spans=self.spec.spans, EI=self.spec.ei)
        self.slopes = np.moveaxis(slopes, 1, 2)

    def heat(self):
        """Effective viscosity by the isothermal heat balance at the cycle-mean load (as film/cycle.py today)."""
        spec = self.spec
        mean_load = np.linalg.norm(self.loads, axis=-1).mean(axis=-1)
        kw = dict(radius=self.diameter / 2, length=spec.bearing_width, radial_clearance=self.clearance / 2,
                  speed=spec.speed)

        def balance(mu):
            eps, phi = tiers.short(mean_load, viscosity=mu, **kw)
            _, torque, flow = tiers.film_quantities(eps, phi, mean_load, viscosity=mu, **kw)
            return torque * spec.speed, flow

        self.mu = oils.effective_temperature(spec.oil, np.full(mean_load.shape, spec.oil_supply_temperature),
                                             balance)[1]

    def film(self, tier):
        self.orbit = orbit(self.loads, self.angle, diameter=self.diameter, length=self.spec.bearing_width,
                           clearance=self.clearance, viscosity=self.mu, speed=self.spec.speed, method=tier,
                           tilt=self.slopes)

    def life(self):
        self.lives = levanov_method1(self.orbit.h_min_mean).life

    def run(self, tier):
        self.crank()
        self.tilt()
        self.heat()
        self.film(tier)
        self.life()
        return self


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
    one = (bore[:1], journal[:1], clearance[:1])

    numba.set_num_threads(1)
    chain = Chain(engine, *one, angle).run("mobility")
    t = {"crank": best_time(chain.crank, args.repeat), "tilt": best_time(chain.tilt, args.repeat),
         "heat": best_time(chain.heat, args.repeat), "life": best_time(chain.life, args.repeat)}
    for tier in TIERS:
        t[tier] = best_time(lambda tier=tier: chain.film(tier), args.repeat)
    chain.film("mobility")
    film = chain.orbit

    t_batch = {}
    batch = Chain(engine, bore, journal, clearance, angle)
    for threads in sorted({1, numba.config.NUMBA_NUM_THREADS}):
        numba.set_num_threads(threads)
        t_batch[threads] = best_time(lambda: batch.run("mobility"), 2)
    lives, batch_film = batch.lives, batch.orbit

    crank = t["crank"]
    rows = []
    for tier in TIERS:
        films = t["tilt"] + t[tier] + t["life"]
        rows.append(f"| {tier} | {1e3 * t[tier] / engine.main_bearings:.2f} | {(crank + films) / crank:.2f} | "
                    f"{'met' if (crank + films) / crank <= TARGET_RATIO else 'NOT met'} | "
                    f"{(crank + films + t['heat']) / crank:.2f} |")
    status = np.bincount(batch_film.status.ravel(), minlength=5)
    lines = [
        "# Benchmark: crankshaft, films and lives of one engine",
        "",
        f"{environment()}, {os.cpu_count()} cores. Engine `iso-example`, 720 crank angles, one sampled engine "
        "(bores and journals misaligned within the drawing's coaxiality and run-out, each bearing at its own "
        f"clearance in the {1e6 * engine.clearance_window[0]:.0f}-{1e6 * engine.clearance_window[1]:.0f} µm "
        f"window). One thread, best of {args.repeat}, every stage timed in this run.",
        "",
        "## One engine: the chain against the crankshaft cycle alone",
        "",
        "| stage | time [ms] | ratio to the crank |",
        "|---|---|---|",
        f"| crankshaft cycle on the bearing law (`engine_cycles`) | {1e3 * crank:.2f} | 1 |",
        f"| journals' tilt at the supports (`support_slopes`) | {1e3 * t['tilt']:.2f} | {t['tilt'] / crank:.2f} |",
        f"| effective viscosity (heat balance of film/cycle.py today) | {1e3 * t['heat']:.2f} | {t['heat'] / crank:.2f} |",
        *(f"| five films, `{tier}` | {1e3 * t[tier]:.2f} | {t[tier] / crank:.2f} |" for tier in TIERS),
        f"| five lives (Levanov method 1 on the cycle-mean film) | {1e3 * t['life']:.3f} | {t['life'] / crank:.3f} |",
        "",
        f"Crank + tilt + films + lives against the crank alone (target ≤ {TARGET_RATIO:.0f}); the last column adds "
        "today's heat balance, which another helper is rewriting:",
        "",
        "| film tier | film per bearing [ms] | ratio | target | ratio with today's heat balance |",
        "|---|---|---|---|---|",
        *rows,
        "",
        f"Films of that engine on `mobility`: cycle minimum {', '.join(f'{1e6 * h:.2f}' for h in film.h_min_cycle[0])} "
        f"µm; edge film with the beam's tilt {', '.join(f'{1e6 * h:.2f}' for h in film.h_min_edge_cycle[0])} µm.",
        "",
        "## Batch throughput (whole chain, `mobility`)",
        "",
        "| threads | engine chains per second |",
        "|---|---|",
        *(f"| {k} | {args.engines / v:,.0f} |" for k, v in t_batch.items()),
        "",
        f"Over the {args.engines} engines: orbit status counts (periodic, not_periodic, collapsed, failed, "
        f"edge_contact) = {status.tolist()}; median life {np.median(lives) / 3600:,.0f} h on the cycle-mean film. "
        "The edge contacts come from the tilt the beam's free support rotation gives: the bearing's moment "
        "restraint is not in the beam model (see reports/film_speed_vs_error.md).",
        "",
        "Reproduce: `python studies/bench_chain.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
