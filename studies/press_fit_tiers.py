"""Press-fit tiers: speed against error, with the finite-element reference as the yardstick.

Over a grid of the design space (housing material, housing OD/ID, shell wall,
shell lining, crush height, operating temperature) every tier is compared with
the ``fe`` reference (bonded steel back and lining for lined shells), and each tier's evaluations per second on one core are measured in
the same run, as ratios to the plain-numpy twin of the closed form.

    python studies/press_fit_tiers.py [--n 2000000] [--repeat 5]

Writes reports/press_fit_tiers.md.
"""

from __future__ import annotations

import argparse
import itertools
import time

import numba
import numpy as np
from _common import best_time, environment, write_report

from stackup import materials
from stackup.fit import press_fit, tiers

BORE = 50.009e-3
CHECK_BORE = 50.000e-3
JOURNAL = 46.009e-3
GRID = {
    "housing_material": ["steel", "grey-cast-iron", "nodular-cast-iron", "aluminium"],
    "ratio": [1.25, 1.5, 2.0],
    "shell_wall": [1.6e-3, 2.0e-3, 3.0e-3],
    "lining": [None, ("copper-lead", 0.3e-3), ("aluminium-tin", 0.3e-3)],
    "crush_height": [0.0, 0.02e-3, 0.08e-3, 0.15e-3],
    "temperature": [20.0, 90.0, 150.0],
}
#: Minimum throughput asked of the production tier on one core [evaluations/s].
TARGET = 20e6


def evaluate(method, case):
    lining = {} if case["lining"] is None else dict(lining_material=case["lining"][0],
                                                    lining_thickness=case["lining"][1])
    return press_fit(housing_bore=BORE, housing_outer=case["ratio"] * BORE, shell_wall=case["shell_wall"],
                     crush_height=case["crush_height"], bearing_width=22e-3,
                     housing_material=case["housing_material"], shell_material="steel-back",
                     temperature=case["temperature"], check_bore=CHECK_BORE, journal_d=JOURNAL, method=method, **lining)


def errors(cases):
    """Largest errors of each tier against ``fe``, for plain and for lined shells."""
    rows, lost = {}, 0
    for lined in (False, True):
        per_method, lost_here = _errors([c for c in cases if (c["lining"] is not None) == lined])
        lost += lost_here
        for method, row in per_method.items():
            rows[(method, "lined" if lined else "plain")] = row
    return rows, lost


def _errors(cases):
    rows = {}
    ref = [evaluate("fe", c) for c in cases]
    for method in ("lame", "thin-ring"):
        got = [evaluate(method, c) for c in cases]
        p_ref = np.array([r.contact_pressure for r in ref])
        s_ref = np.array([r.shell_stress for r in ref])
        in_fit = p_ref > 1e3
        rows[method] = {
            "pressure": np.max(np.abs(np.array([g.contact_pressure for g in got])[in_fit] / p_ref[in_fit] - 1)),
            "stress": np.max(np.abs(np.array([g.shell_stress for g in got])[in_fit] / s_ref[in_fit] - 1)),
            "swell_um": np.max(np.abs(np.array([g.housing_swell - r.housing_swell for g, r in zip(got, ref)]))) * 1e6,
            "clearance_um": np.max(np.abs(np.array([g.clearance - r.clearance for g, r in zip(got, ref)]))) * 1e6,
            "loss_of_fit_agrees": all(bool(g.loss_of_fit) == bool(r.loss_of_fit) for g, r in zip(got, ref)),
        }
    return rows, int(np.count_nonzero([r.loss_of_fit for r in ref]))


def best_rate(fn, n, repeat):
    return n / best_time(fn, repeat)


def speeds(n, repeat):
    rng = np.random.default_rng(0)
    bore = rng.normal(BORE, 2e-6, n)
    wall = rng.normal(1.98e-3, 1e-6, n)
    crush = rng.uniform(0.1e-3, 0.137e-3, n)
    journal = rng.normal(JOURNAL, 2e-6, n)
    kw = dict(housing_bore=bore, housing_outer=90e-3, shell_wall=wall, crush_height=crush, bearing_width=22e-3,
              housing_material="nodular-cast-iron", shell_material="steel-back", temperature=100.0,
              check_bore=CHECK_BORE, journal_d=journal, lining_thickness=0.3e-3, lining_material="aluminium-tin")
    h, s, j, lin = (materials.get(m) for m in ("nodular-cast-iron", "steel-back", "steel", "aluminium-tin"))
    te = tiers.equivalent_wall(wall, 0.3e-3, lin.modulus, s.modulus)
    alpha = tiers.equivalent_expansion(wall, 0.3e-3, lin.modulus, s.modulus, lin.expansion, s.expansion)
    growth = tiers.wall_expansion(wall, 0.3e-3, alpha, s.poisson, lin.poisson, s.expansion, lin.expansion)
    props = dict(housing=(h.modulus, h.poisson, h.expansion), shell=(s.modulus, s.poisson, alpha),
                 journal_expansion=j.expansion, wall_growth=growth)
    out = {
        "lame (numba kernel, via press_fit)": best_rate(lambda: press_fit(**kw), n, repeat),
        "thin-ring (numba kernel, via press_fit)": best_rate(lambda: press_fit(**kw, method="thin-ring"), n, repeat),
        "lame (numpy twin)": best_rate(lambda: tiers.press_fit(bore, 90e-3, wall, te, crush, CHECK_BORE, 100e6, 80.0,
                                                               journal_d=journal, thin=False, **props), n, repeat),
    }
    m = 200
    out["fe (reference)"] = best_rate(lambda: press_fit(**{**kw, "housing_bore": bore[:m], "shell_wall": wall[:m],
                                                          "crush_height": crush[:m], "journal_d": journal[:m]},
                                                        method="fe"), m, 1)
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=2_000_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--out", default="reports/press_fit_tiers.md")
    args = parser.parse_args(argv)
    numba.set_num_threads(1)

    keys = list(GRID)
    cases = [dict(zip(keys, values)) for values in itertools.product(*GRID.values())]
    t0 = time.perf_counter()
    err, lost = errors(cases)
    print(f"errors over {len(cases)} cases in {time.perf_counter() - t0:.1f} s")
    rate = speeds(args.n, args.repeat)
    baseline = rate["lame (numpy twin)"]
    for k, v in rate.items():
        print(f"{k}: {v / 1e6:.3f} M/s")

    lines = [
        "# Press-fit tiers: speed against error",
        "",
        f"{environment()}, one thread.",
        "",
        "## Error against the finite-element reference",
        "",
        f"{len(cases)} cases: housing {', '.join(GRID['housing_material'])}; OD/ID {GRID['ratio']}; shell wall "
        f"{[w * 1e3 for w in GRID['shell_wall']]} mm; plain shells and 0.3 mm copper-lead or aluminium-tin "
        f"linings; crush height {[c * 1e3 for c in GRID['crush_height']]} mm; "
        f"operating temperature {GRID['temperature']} °C (assembly 20 °C); bore {BORE * 1e3} mm, checking block "
        f"{CHECK_BORE * 1e3} mm, steel-back shells, steel journal {JOURNAL * 1e3} mm. The reference meshes shell and "
        f"housing rings with 24 quadratic axisymmetric elements per layer (converged to 1e-8, tested), the lining "
        f"as a bonded layer with its own modulus, Poisson's ratio and expansion, and closes the contact "
        f"with a Lagrange multiplier; {lost} cases lose the fit. Relative errors over the cases with contact; absolute "
        "errors over all.",
        "",
        "| tier | shells | max error contact pressure | max error shell stress | max error swell [µm] | max error clearance [µm] | loss of fit same |",
        "|---|---|---|---|---|---|---|",
        *(f"| {m} | {kind} | {e['pressure']:.2e} | {e['stress']:.2e} | {e['swell_um']:.2e} | {e['clearance_um']:.2e} | "
          f"{'yes' if e['loss_of_fit_agrees'] else 'no'} |" for (m, kind), e in err.items()),
        "",
        "For plain steel shells `lame` is exact within linear plane-stress elasticity (its difference from `fe` is "
        "the reference's discretisation). For lined shells it treats the shell as a steel ring of the "
        "steel-equivalent wall (Kopeliovich's A_calc) growing by the stiffness-weighted expansion of its layers; "
        "the difference from the layered `fe` is that simplification's error. `thin-ring` also ignores the "
        "shell's radial stress and wall thickening, the error a shop formula makes. The default tier is `lame`: it "
        "costs the same as `thin-ring`.",
        "",
        "## Speed",
        "",
        f"{args.n:,} bearings with sampled bore, wall, crush and journal, 0.3 mm aluminium-tin lining (best of "
        f"{args.repeat}); the reference on "
        "200 bearings. Baseline: the plain-numpy twin of the `lame` closed form, in the same run.",
        "",
        "| tier | evaluations per second | ratio to numpy twin |",
        "|---|---|---|",
        *(f"| {k} | {v:,.0f} | {v / baseline:.3g} |" for k, v in rate.items()),
        "",
        f"Target for the production tier: ≥ {TARGET / 1e6:.0f} M evaluations/s on one core: "
        f"{'met' if rate['lame (numba kernel, via press_fit)'] >= TARGET else 'NOT met'} "
        f"({rate['lame (numba kernel, via press_fit)'] / 1e6:.1f} M/s, validation and broadcasting included).",
        "",
        "Reproduce: `python studies/press_fit_tiers.py`.",
    ]
    write_report(args.out, lines)


if __name__ == "__main__":
    main()
