"""Film tiers: time per bearing-cycle against the h_min error to the Reynolds tier.

Steady tiers (short, finite, reynolds) on a grid of L/D and eccentricity (the
load the Reynolds tier carries at each eccentricity handed to every tier);
the cost of one bearing over a 720-step cycle (quasi-static: one steady
solve per angle; mobility: the orbit with squeeze film to a periodic state) on
the example engine's bearing 2 loads. The default tier is the cheapest within
5 % h_min error.

    python studies/film_speed_vs_error.py

Writes reports/film_speed_vs_error.md.
"""

from __future__ import annotations

import time

import numpy as np
from _common import best_time, environment, write_report

from stackup.crank import reactions
from stackup.engines import load_engine
from stackup.film import BY_COST, ERROR_GRID, cheapest_tier, min_film_thickness, reynolds, tier_errors
from stackup.film.orbit import orbit

DEFAULT_ERROR = 0.05


def errors_by_case():
    rows = []
    for ld in ERROR_GRID["length_over_diameter"]:
        for eps in ERROR_GRID["eccentricity"]:
            field = reynolds.solve_field(eps, 2 * ld)
            load = field.force * 1e6
            h_ref = 1e-3 * (1 - eps)
            errs = {}
            for method in ("short", "finite"):
                f = min_film_thickness(load, diameter=2.0, length=2.0 * ld, clearance=2e-3, viscosity=1.0, speed=1.0,
                                       method=method)
                errs[method] = float(f.h_min) / h_ref - 1
            rows.append((ld, eps, errs["short"], errs["finite"]))
    return rows


def main():
    spec = load_engine("iso-example").crank
    angle = np.arange(720.0)
    r = reactions(spec.pin_loads(angle), spans=spec.spans, EI=spec.ei, law=spec.law(np.full(5, 60e-6)))
    loads = r.reactions[:, 1, :]
    geometry = dict(diameter=0.046, length=spec.bearing_width, clearance=60e-6, viscosity=0.008, speed=spec.speed)

    timing = {}
    for method in ("short", "finite"):
        timing[method] = best_time(lambda: orbit(loads, angle, **geometry, method="quasi-static", steady_method=method), 5)
    magnitude = np.linalg.norm(loads, axis=-1)
    points = np.unique(np.concatenate([np.argsort(magnitude)[-6:], np.linspace(0, 719, 6).astype(int)]))
    t0 = time.perf_counter()
    ref_h = min_film_thickness(np.linalg.norm(loads[points], axis=-1), **{k: v for k, v in geometry.items()},
                               method="reynolds").h_min
    timing["reynolds"] = (time.perf_counter() - t0) / points.size * angle.size
    t0 = time.perf_counter()
    dyn = orbit(loads, angle, **geometry, method="mobility")
    timing["mobility"] = time.perf_counter() - t0
    qs = {m: orbit(loads, angle, **geometry, method="quasi-static", steady_method=m).h_min for m in ("short", "finite")}

    errors = tier_errors()
    default = cheapest_tier(DEFAULT_ERROR)
    cases = errors_by_case()
    lines = [
        "# Film tiers: speed against error",
        "",
        f"{environment()}.",
        "",
        "## Steady tiers against the Reynolds tier",
        "",
        f"Largest relative error of h_min over L/D {list(ERROR_GRID['length_over_diameter'])} and eccentricity "
        f"{list(ERROR_GRID['eccentricity'])} (between the nodes of the finite tier's table), and the time of one "
        "bearing over a 720-step cycle (quasi-static orbit; the Reynolds tier timed on a dozen angles and scaled).",
        "",
        "| tier | worst h_min error | time per bearing-cycle [s] | ratio to short |",
        "|---|---|---|---|",
        *(f"| {m} | {100 * errors[m]:.2f} % | {timing[m]:.4g} | {timing[m] / timing['short']:.3g} |" for m in BY_COST),
        "",
        f"Default steady tier: the cheapest within {100 * DEFAULT_ERROR:.0f} % → **{default}** "
        "(`Study(film_method='auto', film_error=...)` picks it the same way).",
        "",
        "Per case (h_min error of each tier against Reynolds):",
        "",
        "| L/D | eccentricity | short | finite |",
        "|---|---|---|---|",
        *(f"| {ld} | {eps} | {100 * s:+.1f} % | {100 * f:+.3f} % |" for ld, eps, s, f in cases),
        "",
        "## Dynamic load: squeeze film",
        "",
        f"Bearing 2 of the example engine over its cycle (peak {np.linalg.norm(loads, axis=-1).max() / 1e3:.1f} kN, "
        f"L/D {spec.bearing_width / 0.046:.2f}, 60 µm clearance, 8 mPa s). Cycle-minimum film:",
        "",
        "| tier | cycle-minimum h_min [µm] | time per bearing-cycle [s] |",
        "|---|---|---|",
        f"| quasi-static, short | {qs['short'].min() * 1e6:.3f} | {timing['short']:.4g} |",
        f"| quasi-static, finite | {qs['finite'].min() * 1e6:.3f} | {timing['finite']:.4g} |",
        f"| quasi-static, reynolds (at the {points.size} angles incl. the 6 highest loads) | {ref_h.min() * 1e6:.3f} | "
        f"{timing['reynolds']:.4g} |",
        f"| quasi-static, finite at the same angles | {qs['finite'][points].min() * 1e6:.3f} | — |",
        f"| mobility (short-bearing squeeze film, {dyn.cycles} cycles to periodic) | {dyn.h_min.min() * 1e6:.3f} | "
        f"{timing['mobility']:.4g} |",
        "",
        "The mobility tier's film is the short-bearing one: the squeeze film lifts the cycle minimum against the "
        "quasi-static short tier by the ratio of those rows; its finite-length error is that of the short tier "
        "above. No finite-length squeeze-film reference is implemented yet.",
        "",
        "Reproduce: `python studies/film_speed_vs_error.py`.",
    ]
    print(write_report("reports/film_speed_vs_error.md", lines).read_text())


if __name__ == "__main__":
    main()
