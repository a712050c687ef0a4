"""The heavy diesel's main bearings against Rozhdestvensky et al. (2018), Table 2 (rigid crankcase, coaxial).

``rozhdestvensky-4`` (105 mm × 35 mm main bearings, 103 µm clearance,
219 rad/s, Table 1 of the paper) with bearings and journals coaxial, on every
cycle tier: cycle minimum of the minimum film and the crank angle where it
occurs, its cycle mean, the cycle maximum and mean of the peak pressure and the
mean friction power, beside the paper's values for its rigid crankcase model.

    python studies/rozhdestvensky_table2.py [--workers 2]

Writes reports/rozhdestvensky_table2.md.
"""

from __future__ import annotations

import argparse
import multiprocessing
import time
from concurrent.futures import ProcessPoolExecutor

import numba
import numpy as np
from _common import environment, write_report
from _film_cases import engine_case

from stackup.film.orbit import STATUS, orbit

CLEARANCE = 103e-6  # Table 1, "main bearing clearance": read as diametral (about 1 per mil of 105 mm)
#: Table 2, rigid crankcase model (rows "1)"), bearings 1-4 as printed (2 and 3 repeat the same values):
#: inf h_min [um], its crank angle [deg], h*_min [um], sup p_max [MPa], p*_max [MPa], N* [W].
PAPER = {
    1: (2.89, 70, 11.95, 79, 15, 545),
    2: (2.68, 243, 9.10, 225, 40, 651),
    3: (2.68, 243, 9.10, 225, 40, 651),
    4: (3.64, 609, 11.00, 148, 26, 588),
}
TIERS = ("finite", "mobility", "mobility-finite", "reynolds-transient")


def verdict(rows, ratio):
    """The report's opening, its directions read from the numbers."""
    ref = np.array(rows["reynolds-transient"])

    def span(col, fmt):
        return f"{ref[:, col].min():{fmt}}-{ref[:, col].max():{fmt}}"

    def direction(col, more, less):
        lo, hi = ratio[:, col].min(), ratio[:, col].max()
        word = more if lo > 1 else less if hi < 1 else f"{less} to {more}"
        return f"{word} (ratio {lo:.2f}-{hi:.2f})"

    return (f"The project's reference film (`reynolds-transient`, mass-conserving) puts the heavy diesel's "
            f"cycle-minimum films at {span(0, '.1f')} µm against the paper's 2.7-3.6 µm: "
            f"{direction(0, 'thicker', 'thinner')}; cycle-mean films {span(2, '.1f')} µm against 9.1-12.0 µm: "
            f"{direction(2, 'thicker', 'thinner')}; peak pressures {span(3, '.0f')} MPa against 79-225 MPa: "
            f"{direction(3, 'higher', 'lower')}; mean peak pressures {span(4, '.0f')} MPa against 15-40 MPa: "
            f"{direction(4, 'higher', 'lower')}; friction powers {span(5, '.0f')} W against 545-651 W: "
            f"{direction(5, 'higher', 'lower')}. The films are of the paper's order and the friction power "
            "agrees; the inputs differ (loads, oil, elastic bearing, below) by enough to move the films by tens of "
            "per cent, and this study does not separate them: a check of magnitudes, not a validation.")


DIFFERENCES = [
    "- **Loads.** The engine file's cylinder-pressure model (Wiebe-type, 15 MPa peak), masses, spans and "
    "section inertias are assumptions of typical size (engine file's `source`); the paper uses its measured "
    "pressure trace (Fig. 2) and the FE compliances of its crankshaft and crankcase (Figs. 5-6). The bearing "
    "loads set the film directly.",
    "- **Oil.** The paper's oil is non-Newtonian (shear-thinning index k) with a pressure-viscosity "
    "coefficient (its eq. 3); ours is one viscosity per bearing: at the effective temperature of our heat "
    "balance and the film's mean shear rate (Cross shear thinning), without the pressure term. At 100-225 MPa "
    "the pressure term alone would raise the viscosity several-fold in the loaded zone and thicken the film "
    "there.",
    "- **Elastic bearing.** The paper's film includes the elastic deformation of the bearing (L_p in its eq. 4); "
    "our surfaces are rigid. Elastic flattening spreads the load and lowers the peak pressure - it usually "
    "thins the minimum film slightly.",
    "- **Oil supply and cavitation.** The paper has a groove from 100° to 260° in the bearing and two feed "
    "holes in the journal, with Swift-Stieber conditions; our reference has the same groove (6 mm wide, "
    "0.45 MPa, both assumed) as a fixed-pressure boundary and mass-conserving (Elrod-Adams) cavitation; the "
    "mobility tiers have no groove (the film is complete around the bearing) and the Reynolds condition.",
    "- **Clearance.** Table 1 gives 0.103 mm, read here as the diametral clearance; read as radial, the film "
    "would be thicker still.",
    "- **Journal mass and the crank angle origin.** The paper integrates the journal with its mass and "
    "moments (its eq. 1); ours is massless (mobility). The paper does not state its crank-angle origin, so "
    "the angles of the minimum film are not comparable one to one.",
    "- Table 2 prints the same values for bearings 2 and 3; it is compared as printed.",
]


def paper_ratio_rows(rows):
    """Reference tier over the paper for bearings 1-4 (columns as PAPER)."""
    ours = np.array(rows["reynolds-transient"])[:4]
    return ours / np.array([PAPER[k] for k in (1, 2, 3, 4)], dtype=float)


def row(result, angle, k):
    """The paper's six quantities of bearing k from an Orbit."""
    h = result.h_min[k]
    return (1e6 * h.min(), angle[np.argmin(h)], 1e6 * h.mean(), 1e-6 * result.p_max[k].max(),
            1e-6 * result.p_max[k].mean(), result.friction_power[k].mean())


def _transient(bearing):
    numba.set_num_threads(1)
    case = engine_case("rozhdestvensky-4", clearance=CLEARANCE)
    t0 = time.perf_counter()
    result = orbit(case.loads[bearing:bearing + 1], case.crank_angle, **case.geometry(slice(bearing, bearing + 1)),
                   method="reynolds-transient", feed=case.feed)
    return result, time.perf_counter() - t0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default="reports/rozhdestvensky_table2.md")
    args = parser.parse_args(argv)

    case = engine_case("rozhdestvensky-4", clearance=CLEARANCE)
    n = case.loads.shape[0]
    results = {tier: orbit(case.loads, case.crank_angle, **case.geometry(), method=tier) for tier in TIERS[:-1]}
    with ProcessPoolExecutor(args.workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        transient = list(pool.map(_transient, range(n)))
    rows = {tier: [row(results[tier], case.crank_angle, k) for k in range(n)] for tier in TIERS[:-1]}
    rows["reynolds-transient"] = [row(r, case.crank_angle, 0) for r, _ in transient]
    status = {tier: [STATUS[int(s)] for s in np.atleast_1d(results[tier].status)] for tier in TIERS[:-1]}
    status["reynolds-transient"] = [STATUS[int(r.status[0])] for r, _ in transient]
    peak = np.linalg.norm(case.loads, axis=-1).max(axis=-1)

    lines = [
        "# Heavy diesel main bearings against Rozhdestvensky et al. (2018), Table 2",
        "",
        f"{environment()}.",
        "",
        "## Verdict",
        "",
        verdict(rows, paper_ratio_rows(rows)),
        "",
        "## Set-up",
        "",
        f"`rozhdestvensky-4`: main bearings {1e3 * case.diameter:.0f} mm × {1e3 * case.length:.0f} mm, "
        f"{1e6 * CLEARANCE:.0f} µm diametral clearance, {case.speed:.0f} rad/s (the paper's Table 1); bearings and "
        "journals coaxial, crankshaft as a beam on the engine's bearing law (the paper: rigid crankcase model, "
        "rows 1) of Table 2). Cylinder pressure from the engine file's model (peak "
        "15 MPa; the paper's Fig. 2 trace is not tabulated). Oil SAE 15W-40, effective temperature from the "
        f"study chain's heat balance per bearing (feed groove and side flow, finite tier): {', '.join(f'{t:.0f}' for t in case.temperature)} °C, viscosity "
        f"{', '.join(f'{1e3 * m:.1f}' for m in case.viscosity)} mPa s. Peak bearing loads "
        f"{', '.join(f'{1e-3 * p:.0f}' for p in peak)} kN. Crank angle 0 = firing TDC of cylinder 1 (the paper "
        "does not state its origin).",
        "",
        "## Per bearing",
        "",
        "inf h_min [µm] at crank angle [deg]; h*_min [µm]; sup p_max and p*_max [MPa]; N* [W].",
        "",
        "| bearing | source | inf h_min | at | h*_min | sup p_max | p*_max | N* | status |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for k in range(n):
        if k + 1 in PAPER:
            p = PAPER[k + 1]
            lines.append(f"| {k + 1} | paper (rigid crankcase) | {p[0]:.2f} | {p[1]} | {p[2]:.2f} | {p[3]} | {p[4]} | "
                         f"{p[5]} | — |")
        for tier in TIERS:
            v = rows[tier][k]
            lines.append(f"| {k + 1} | {tier} | {v[0]:.2f} | {v[1]:.0f} | {v[2]:.2f} | {v[3]:.0f} | {v[4]:.0f} | "
                         f"{v[5]:.0f} | {status[tier][k]} |")
    ratio = paper_ratio_rows(rows)
    lines += [
        "",
        "## Ratio of the reference tier (`reynolds-transient`) to the paper, bearings 1-4",
        "",
        "| bearing | inf h_min | h*_min | sup p_max | p*_max | N* |",
        "|---|---|---|---|---|---|",
        *(f"| {k + 1} | {ratio[k, 0]:.2f} | {ratio[k, 2]:.2f} | {ratio[k, 3]:.2f} | {ratio[k, 4]:.2f} | "
          f"{ratio[k, 5]:.2f} |" for k in range(4)),
        "",
        f"Transient tier: {np.mean([t for _, t in transient]):.0f} s per bearing.",
        "",
        "## Why the numbers differ",
        "",
        *DIFFERENCES,
        "",
        "Reproduce: `python studies/rozhdestvensky_table2.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
